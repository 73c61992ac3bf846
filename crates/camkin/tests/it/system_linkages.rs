//! Issue 45: linkages as systems, against their closed-form loop equations: a four-bar
//! crank-rocker and an offset slider-crank, the crank driven at constant speed. Positions from
//! the loop closure (two circles' intersection; a circle and a line), velocities and
//! accelerations by five-point differences of those closed-form positions — no formula shared
//! with the method. Tolerances: positions 1e-12 of the size, velocities 1e-9 and accelerations
//! 1e-7 of their peaks.

use crate::common::system_body as body;
use camkin::system::{
    BodyId, Coordinate, Driver, DriverLaw, Joint, JointKind, System, SystemError,
};
use camkin::{Point2, Vec2};

fn pin(name: &str, a: BodyId, at_a: [f64; 2], b: BodyId, at_b: [f64; 2]) -> Joint {
    Joint {
        name: name.into(),
        kind: JointKind::Revolute {
            a,
            at_a: Point2::new(at_a[0], at_a[1]),
            b,
            at_b: Point2::new(at_b[0], at_b[1]),
        },
    }
}

/// Five-point central differences of `f` at `t`: first and second derivatives.
fn derivatives(f: impl Fn(f64) -> f64, t: f64, h: f64) -> (f64, f64) {
    let (m2, m1, z, p1, p2) = (f(t - 2.0 * h), f(t - h), f(t), f(t + h), f(t + 2.0 * h));
    (
        (m2 - 8.0 * m1 + 8.0 * p1 - p2) / (12.0 * h),
        (-m2 + 16.0 * m1 - 30.0 * z + 16.0 * p1 - p2) / (12.0 * h * h),
    )
}

/// The angle `b` turned to be within π of `a`.
fn near(a: f64, b: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    b + ((a - b) / tau).round() * tau
}

/// Crank 1, coupler 3.5, rocker 2.5, ground 3 (Grashof: the crank turns fully), the crank at
/// 10 rad/s: every angle of the crank over a revolution in 2° steps, swept (warm), and every
/// fifth one also solved cold.
#[test]
fn a_four_bar_follows_its_loop_equations() {
    let (a, b, c, d, w) = (1.0, 3.5, 2.5, 3.0, 10.0);
    // the closed form: the coupler's and the rocker's angles at crank angle θ (the open branch,
    // the coupler's far end above the line of the ground pivots)
    let closed = |th: f64| -> (f64, f64) {
        let pa = Vec2::new(a * th.cos(), a * th.sin());
        let e = Vec2::new(d, 0.0) - pa;
        let l = e.norm();
        let x = (b * b - c * c + l * l) / (2.0 * l);
        let h = (b * b - x * x).sqrt();
        let u = e / l;
        let pb = pa + x * u + h * Vec2::new(-u.y, u.x);
        (
            (pb - pa).y.atan2((pb - pa).x),
            (pb - Vec2::new(d, 0.0)).y.atan2((pb - Vec2::new(d, 0.0)).x),
        )
    };
    let mut sys = System::new();
    let (t3, t4) = closed(0.0);
    let crank = sys.add_body(body("crank", 0.0, 0.0, 0.0));
    // the coupler and the rocker start a little off their assembled poses
    let coupler = sys.add_body(body("coupler", a + 0.05, -0.03, t3 + 0.05));
    let rocker = sys.add_body(body("rocker", d, 0.02, t4 - 0.04));
    let g = BodyId::GROUND;
    sys.add_joint(pin("O2", g, [0.0, 0.0], crank, [0.0, 0.0]));
    sys.add_joint(pin("A", crank, [a, 0.0], coupler, [0.0, 0.0]));
    sys.add_joint(pin("B", coupler, [b, 0.0], rocker, [c, 0.0]));
    sys.add_joint(pin("O4", rocker, [0.0, 0.0], g, [d, 0.0]));
    sys.add_driver(Driver {
        name: "motor".into(),
        body: crank,
        coordinate: Coordinate::Angle,
        law: DriverLaw::linear(0.0, w),
    });
    let mut sweep = sys.sweep().unwrap();
    let size = d + a;
    // peaks of the closed form's rates, for the tolerances
    let (mut vpeak, mut apeak) = (0.0f64, 0.0f64);
    let steps = 180;
    let mut rows = Vec::new();
    for k in 0..steps {
        let t = k as f64 * std::f64::consts::TAU / steps as f64 / w;
        let th = w * t;
        let s = sweep.step(t).unwrap();
        let (e3, e4) = closed(th);
        let angle = |f: &dyn Fn(f64) -> f64| {
            let base = f(t);
            derivatives(|x| near(base, f(x)), t, 1e-4)
        };
        let f3 = |x: f64| closed(w * x).0;
        let f4 = |x: f64| closed(w * x).1;
        let (v3, a3) = angle(&f3);
        let (v4, a4) = angle(&f4);
        vpeak = vpeak.max(v3.abs()).max(v4.abs());
        apeak = apeak.max(a3.abs()).max(a4.abs());
        rows.push((k, s, [e3, e4], [v3, v4], [a3, a4]));
        if k % 5 == 0 {
            let cold = sys.analyze(t).unwrap();
            for i in 0..3 {
                let (p, q) = (&cold.bodies[i].pose, &rows[k].1.bodies[i].pose);
                assert!((p.origin - q.origin).norm() <= 1e-12 * size, "cold at {k}");
            }
        }
    }
    for (k, s, e, v, acc) in rows {
        for (i, id) in [coupler, rocker].iter().enumerate() {
            let b = &s.bodies[id.index().unwrap()];
            let what = format!("body {i} at step {k}");
            assert!(
                (near(e[i], b.pose.angle) - e[i]).abs() * size <= 1e-12 * size,
                "{what}: angle {} against {}",
                b.pose.angle,
                e[i]
            );
            assert!(
                (b.omega - v[i]).abs() <= 1e-9 * vpeak,
                "{what}: ω {} against {}",
                b.omega,
                v[i]
            );
            assert!(
                (b.alpha - acc[i]).abs() <= 1e-7 * apeak,
                "{what}: α {} against {}",
                b.alpha,
                acc[i]
            );
        }
        // the pins hold: the coupler's far end is the rocker's
        let (cb, rb) = (&s.bodies[1], &s.bodies[2]);
        let far = cb.pose.to_world(Point2::new(b, 0.0));
        let tip = rb.pose.to_world(Point2::new(c, 0.0));
        assert!((far - tip).norm() <= 1e-12 * size);
        assert!(s.contacts.is_empty());
    }
}

/// An offset slider-crank (crank 1.2, rod 4, the slider's line 0.5 above the crank's pivot), the
/// crank at 30 rad/s and accelerating at 200 rad/s²: the slider's position
/// `x = a cos θ + √(l² − (a sin θ − e)²)` and its rates by differences in time.
#[test]
fn an_offset_slider_crank_follows_its_closed_form() {
    let (a, l, e, w, al) = (1.2, 4.0, 0.5, 30.0, 200.0);
    let x_of = |t: f64| {
        let th = w * t + 0.5 * al * t * t;
        a * th.cos() + (l * l - (a * th.sin() - e).powi(2)).sqrt()
    };
    let mut sys = System::new();
    let g = BodyId::GROUND;
    let crank = sys.add_body(body("crank", 0.0, 0.0, 0.0));
    let rod = sys.add_body(body("rod", a, 0.0, 0.1));
    let slider = sys.add_body(body("slider", x_of(0.0) + 0.1, e, 0.0));
    sys.add_joint(pin("O", g, [0.0, 0.0], crank, [0.0, 0.0]));
    sys.add_joint(pin("A", crank, [a, 0.0], rod, [0.0, 0.0]));
    sys.add_joint(pin("B", rod, [l, 0.0], slider, [0.0, 0.0]));
    sys.add_joint(Joint {
        name: "guide".into(),
        kind: JointKind::Prismatic {
            a: g,
            at_a: Point2::new(0.0, e),
            axis: Vec2::new(1.0, 0.0),
            b: slider,
            at_b: Point2::origin(),
            angle: 0.0,
        },
    });
    sys.add_driver(Driver {
        name: "motor".into(),
        body: crank,
        coordinate: Coordinate::Angle,
        law: DriverLaw::Quadratic {
            start: 0.0,
            rate: w,
            acceleration: al,
        },
    });
    let mut sweep = sys.sweep().unwrap();
    let mut checked = 0;
    let (mut vpeak, mut apeak) = (0.0f64, 0.0f64);
    let mut rows = Vec::new();
    for k in 0..200 {
        let t = k as f64 * 1e-3;
        let s = sweep.step(t).unwrap();
        let (v, acc) = derivatives(x_of, t, 1e-5);
        vpeak = vpeak.max(v.abs());
        apeak = apeak.max(acc.abs());
        rows.push((s, x_of(t), v, acc));
    }
    for (s, x, v, acc) in rows {
        let b = &s.bodies[slider.index().unwrap()];
        assert!(
            (b.pose.origin.x - x).abs() <= 1e-12 * l,
            "{} {x}",
            b.pose.origin.x
        );
        assert!((b.pose.origin.y - e).abs() <= 1e-12 * l);
        assert!(
            (b.velocity.x - v).abs() <= 1e-9 * vpeak,
            "{} {v}",
            b.velocity.x
        );
        assert!(
            (b.acceleration.x - acc).abs() <= 1e-7 * apeak,
            "{} {acc}",
            b.acceleration.x
        );
        checked += 1;
    }
    assert_eq!(checked, 200);
}

/// A train of three involute gears, 20, 31 and 42 teeth (module 2, 20°), at their standard
/// centre distances on one line, the 31 an idler: the first driven at 100 rad/s. The second
/// turns at −z1/z2 of it, the third at +z1/z3 — the same sense as the first, exactly, with zero
/// angular acceleration (ideal involutes at the standard distance), through every handover of the
/// teeth (the contacts jump to the next pair where the pair followed leaves its flank).
#[test]
fn a_three_gear_train_turns_at_the_tooth_ratios() {
    use camkin::curve::{InvoluteGear, InvoluteGearSpec};
    use camkin::system::Contact;
    use std::f64::consts::PI;
    use std::sync::Arc;
    let (m, alpha) = (2.0, 20f64.to_radians());
    let gear = |z: u32| Arc::new(InvoluteGear::new(InvoluteGearSpec::new(m, z, alpha)).unwrap());
    let (z1, z2, z3) = (20.0, 31.0, 42.0);
    let (a12, a23) = (m * (z1 + z2) / 2.0, m * (z2 + z3) / 2.0);
    let w = 100.0;
    let mut sys = System::new();
    let g = BodyId::GROUND;
    // gear 2's space faces gear 1's tooth 0 (along +x); gear 2 then has a tooth along +x, and
    // gear 3's space faces it
    let (p2, p3) = (PI + PI / z2, PI + PI / z3);
    let b1 = sys.add_body(body("driver", 0.0, 0.0, 0.0));
    let b2 = sys.add_body(body("idler", a12, 0.0, p2));
    let b3 = sys.add_body(body("output", a12 + a23, 0.0, p3));
    sys.add_joint(pin("shaft 1", g, [0.0, 0.0], b1, [0.0, 0.0]));
    sys.add_joint(pin("shaft 2", g, [a12, 0.0], b2, [0.0, 0.0]));
    sys.add_joint(pin("shaft 3", g, [a12 + a23, 0.0], b3, [0.0, 0.0]));
    sys.add_driver(Driver {
        name: "motor".into(),
        body: b1,
        coordinate: Coordinate::Angle,
        law: DriverLaw::linear(0.0, w),
    });
    sys.add_contact(Contact {
        name: "mesh 1-2".into(),
        a: b1,
        curve_a: gear(20),
        b: b2,
        curve_b: gear(31),
    });
    sys.add_contact(Contact {
        name: "mesh 2-3".into(),
        a: b2,
        curve_a: gear(31),
        b: b3,
        curve_b: gear(42),
    });
    let mut sweep = sys.sweep().unwrap();
    let mut jumps = [0, 0];
    let first = sweep.step(0.0).unwrap();
    let (s2, s3) = (first.bodies[1].pose.angle, first.bodies[2].pose.angle);
    // three pitches of gear 1 (54°) in 0.25° steps
    for k in 0..=216 {
        let th = f64::from(k) * 0.25f64.to_radians();
        let s = sweep.step(th / w).unwrap();
        let what = format!("at {:.2}°", th.to_degrees());
        let (o2, o3) = (&s.bodies[1], &s.bodies[2]);
        assert!(
            (o2.omega + z1 / z2 * w).abs() <= 1e-9 * w,
            "{what}: ω2 {}",
            o2.omega
        );
        assert!(
            (o3.omega - z1 / z3 * w).abs() <= 1e-9 * w,
            "{what}: ω3 {}",
            o3.omega
        );
        assert!(o2.alpha.abs() <= 1e-7 * w * w, "{what}: α2 {}", o2.alpha);
        assert!(o3.alpha.abs() <= 1e-7 * w * w, "{what}: α3 {}", o3.alpha);
        assert!(
            (o2.pose.angle - s2 + z1 / z2 * th).abs() <= 1e-12 * 2.0 * PI,
            "{what}: φ2 {} from {s2}, θ {th}",
            o2.pose.angle
        );
        assert!(
            (o3.pose.angle - s3 - z1 / z3 * th).abs() <= 1e-12 * 2.0 * PI,
            "{what}: φ3 {} from {s3}, expected {}",
            o3.pose.angle,
            s3 + z1 / z3 * th
        );
        for (j, c) in s.contacts.iter().enumerate() {
            jumps[j] += usize::from(c.jumped);
        }
    }
    // over three pitches of gear 1 each mesh hands over to the next pair at least twice (once a
    // pitch: a pitch of any of the three gears is 18° of gear 1)
    assert!(jumps[0] >= 2 && jumps[1] >= 2, "{jumps:?}");
    // regression: in 10° steps (more than half a pitch) a prediction carried across a handover
    // lost the mesh (a singular instant at 160°); every instant of a revolution holds the ratios
    let mut coarse = sys.sweep().unwrap();
    for k in 0..36 {
        let th = f64::from(k) * 10f64.to_radians();
        let s = coarse.step(th / w).unwrap();
        assert!((s.bodies[1].omega + z1 / z2 * w).abs() <= 1e-9 * w, "{k}");
        assert!((s.bodies[2].omega - z1 / z3 * w).abs() <= 1e-9 * w, "{k}");
    }
}

/// A cam driving an oscillating arm that is the input link of a four-bar: an eccentric disc
/// (radius 20, eccentricity 4, 300 rpm) under a roller (radius 5) at 20 from the arm's pivot
/// P = (30, 25); a point 12 across the arm drives a coupler (30) to an output rocker (20) pivoted
/// at (65, 30). Reference: the arm's angle by bisection on the roller centre's distance from the
/// disc's centre (`|C(φ) − E(θ)| = 25`), the output's by the four-bar's loop closure (two
/// circles' intersection), rates by five-point differences; to 1e-12, 1e-9 and 1e-7.
#[test]
fn a_cam_drives_a_four_bar_through_its_arm() {
    use camkin::curve::Circle;
    use camkin::system::Contact;
    use std::sync::Arc;
    let (r, e, rr, len) = (20.0, 4.0, 5.0, 20.0);
    let p = Vec2::new(30.0, 25.0);
    let (across, b, c) = (12.0, 30.0, 20.0);
    let o4 = Vec2::new(65.0, 30.0);
    let w = 300.0 * std::f64::consts::TAU / 60.0;
    let arm_point = |phi: f64, q: Vec2| {
        let (s, co) = phi.sin_cos();
        p + Vec2::new(co * q.x - s * q.y, s * q.x + co * q.y)
    };
    // the arm's angle at cam angle θ: near `guess`, the roller centre at r + rr from the disc's
    let arm_angle = |theta: f64, guess: f64| {
        let centre = Vec2::new(e * theta.cos(), e * theta.sin());
        let f = |phi: f64| (arm_point(phi, Vec2::new(len, 0.0)) - centre).norm() - (r + rr);
        let (mut lo, mut hi) = (guess - 0.3, guess + 0.3);
        assert!(f(lo) * f(hi) < 0.0, "no bracket at {theta}");
        for _ in 0..200 {
            let m = 0.5 * (lo + hi);
            if m <= lo || m >= hi {
                break;
            }
            if (f(m) < 0.0) == (f(lo) < 0.0) {
                lo = m;
            } else {
                hi = m;
            }
        }
        0.5 * (lo + hi)
    };
    // the output rocker's angle at arm angle φ (the branch with B below the line A–O4)
    let output = |phi: f64| {
        let a = arm_point(phi, Vec2::new(0.0, across));
        let d = o4 - a;
        let l = d.norm();
        let x = (b * b - c * c + l * l) / (2.0 * l);
        let h = (b * b - x * x).sqrt();
        let u = d / l;
        let bb = a + x * u - h * Vec2::new(-u.y, u.x);
        (bb - o4).y.atan2((bb - o4).x)
    };
    let phi0 = arm_angle(0.0, (-174f64).to_radians());
    let psi0 = output(phi0);
    let mut sys = System::new();
    let g = BodyId::GROUND;
    let cam = sys.add_body(body("cam", 0.0, 0.0, 0.0));
    let arm = sys.add_body(body("arm", p.x, p.y, phi0 + 0.02));
    let a0 = arm_point(phi0, Vec2::new(0.0, across));
    let bb0 = o4 + c * Vec2::new(psi0.cos(), psi0.sin());
    let coupler = sys.add_body(body(
        "coupler",
        a0.x,
        a0.y,
        (bb0 - a0).y.atan2((bb0 - a0).x) - 0.02,
    ));
    let rocker = sys.add_body(body("rocker", o4.x, o4.y, psi0 + 0.01));
    sys.add_joint(pin("camshaft", g, [0.0, 0.0], cam, [0.0, 0.0]));
    sys.add_joint(pin("arm pivot", g, [p.x, p.y], arm, [0.0, 0.0]));
    sys.add_joint(pin("A", arm, [0.0, across], coupler, [0.0, 0.0]));
    sys.add_joint(pin("B", coupler, [b, 0.0], rocker, [c, 0.0]));
    sys.add_joint(pin("O4", g, [o4.x, o4.y], rocker, [0.0, 0.0]));
    sys.add_driver(Driver {
        name: "drive".into(),
        body: cam,
        coordinate: Coordinate::Angle,
        law: DriverLaw::linear(0.0, w),
    });
    sys.add_contact(Contact {
        name: "disc on roller".into(),
        a: cam,
        curve_a: Arc::new(Circle::new(Point2::new(e, 0.0), r).unwrap()),
        b: arm,
        curve_b: Arc::new(Circle::new(Point2::new(len, 0.0), rr).unwrap()),
    });
    let mut sweep = sys.sweep().unwrap();
    let (mut guess, h) = (phi0, 1e-3);
    let mut rows = Vec::new();
    let (mut vpeak, mut apeak) = ([0.0f64; 2], [0.0f64; 2]);
    for k in 0..120 {
        let th = f64::from(k) * 3f64.to_radians();
        let s = sweep.step(th / w).unwrap();
        let phis: Vec<f64> = (-2..=2)
            .map(|j| arm_angle(th + f64::from(j) * h, guess))
            .collect();
        guess = phis[2];
        let psis: Vec<f64> = phis.iter().map(|&f| output(f)).collect();
        let five = |v: &[f64]| {
            (
                (v[0] - 8.0 * v[1] + 8.0 * v[3] - v[4]) / (12.0 * h) * w,
                (-v[0] + 16.0 * v[1] - 30.0 * v[2] + 16.0 * v[3] - v[4]) / (12.0 * h * h) * w * w,
            )
        };
        let (d1, dd1) = five(&phis);
        let (d2, dd2) = five(&psis);
        vpeak = [vpeak[0].max(d1.abs()), vpeak[1].max(d2.abs())];
        apeak = [apeak[0].max(dd1.abs()), apeak[1].max(dd2.abs())];
        rows.push((k, s, [phis[2], d1, dd1], [psis[2], d2, dd2]));
    }
    let turn = std::f64::consts::TAU;
    for (k, s, f, o) in rows {
        for (i, (id, r)) in [(arm, f), (rocker, o)].into_iter().enumerate() {
            let bs = &s.bodies[id.index().unwrap()];
            let angle = bs.pose.angle + ((r[0] - bs.pose.angle) / turn).round() * turn;
            let what = format!("body {i} at {}°", 3 * k);
            assert!(
                (angle - r[0]).abs() <= 1e-12 * 100.0,
                "{what}: {angle} {}",
                r[0]
            );
            assert!(
                (bs.omega - r[1]).abs() <= 1e-9 * vpeak[i],
                "{what}: {} {}",
                bs.omega,
                r[1]
            );
            assert!(
                (bs.alpha - r[2]).abs() <= 1e-7 * apeak[i],
                "{what}: {} {}",
                bs.alpha,
                r[2]
            );
        }
    }
    // the output swings: the four-bar is driven, not at rest
    assert!(vpeak[1] > 0.1 * w, "{vpeak:?}");
}

/// A four-bar driven by its rocker (crank 20, coupler 50, rocker 40, ground 60) cannot turn the
/// rocker past the toggle where crank and coupler fold onto one line, `|O₂B| = 50 − 20`, at the
/// rocker angle `acos(−0.8958…)` = 153.6°: asked beyond it, the sweep stops at the dead point and
/// says so, naming the driver, within 0.01° of that angle; never an answer past it. Both from
/// a sweep in steps and asked at once from the start.
#[test]
fn a_rocker_driven_four_bar_stops_at_its_toggle_and_says_so() {
    let (a, b, c, d) = (20.0, 50.0, 40.0, 60.0);
    let w = std::f64::consts::TAU; // the rocker at 60 rpm
    let start = 100f64.to_radians();
    let mut sys = System::new();
    let crank = sys.add_body(body("crank", 0.0, 0.0, 5f64.to_radians()));
    let coupler = sys.add_body(body("coupler", a, 0.0, 60f64.to_radians()));
    let rocker = sys.add_body(body("rocker", d, 0.0, start));
    let g = BodyId::GROUND;
    sys.add_joint(pin("O2", g, [0.0, 0.0], crank, [0.0, 0.0]));
    sys.add_joint(pin("A", crank, [a, 0.0], coupler, [0.0, 0.0]));
    sys.add_joint(pin("B", coupler, [b, 0.0], rocker, [c, 0.0]));
    sys.add_joint(pin("O4", rocker, [0.0, 0.0], g, [d, 0.0]));
    sys.add_driver(Driver {
        name: "drive rocker".into(),
        body: rocker,
        coordinate: Coordinate::Angle,
        law: DriverLaw::linear(start, w),
    });
    // |B|² = (d + c cos φ)² + (c sin φ)² = (b − a)²
    let toggle = (((b - a) * (b - a) - d * d - c * c) / (2.0 * d * c)).acos();
    let time_at = |deg: f64| (deg.to_radians() - start) / w;
    for from_steps in [true, false] {
        let mut sweep = sys.sweep().unwrap();
        sweep.step(0.0).unwrap();
        if from_steps {
            for deg in [110.0, 130.0, 150.0] {
                sweep.step(time_at(deg)).unwrap();
            }
        }
        let e = sweep.step(time_at(160.0)).unwrap_err();
        match &e {
            SystemError::DeadPoint { time, rows } => {
                let angle = start + w * time;
                assert!(
                    (angle - toggle).abs() <= 0.01f64.to_radians(),
                    "{} against {}",
                    angle.to_degrees(),
                    toggle.to_degrees()
                );
                assert!(rows.contains("drive rocker"), "{rows}");
            }
            other => panic!("{other}"),
        }
        assert!(e.to_string().contains("dead point"), "{e}");
    }
}
