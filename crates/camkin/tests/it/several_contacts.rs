//! Every contact at an instant (`Mechanism::contacts`): two gear tooth pairs while the contact
//! ratio is above one, and a roller bridging a notch, checked against closed forms the contact
//! method does not use (the line of action, the involute's roll lengths, the constant ratio of
//! ideal involutes, mirror symmetry).

use crate::common::base_pitches_inside;
use camkin::cam::{Cam, CamContact, Follower, FollowerProfile, Mechanism, Sense};
use camkin::curve::{Circle, ClosedSpline, Curve, InvoluteGear, InvoluteGearSpec, Line};
use camkin::{Point2, Vec2};
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

const M: f64 = 2.0;

/// A standard `z1`/`z2` pair, 20°, module 2, at the standard centre distance, the driver at
/// 1000 rpm speeding up at `alpha`; each tooth thinned by `backlash` on its pitch circle.
fn gears(z1: u32, z2: u32, alpha: f64, backlash: f64) -> Mechanism {
    let spec = |z| InvoluteGearSpec {
        backlash,
        ..InvoluteGearSpec::new(M, z, 20f64.to_radians())
    };
    let (g1, g2) = (
        InvoluteGear::new(spec(z1)).unwrap(),
        InvoluteGear::new(spec(z2)).unwrap(),
    );
    let cam = Cam::from_rpm(Arc::new(g1), Point2::origin(), Sense::Ccw, 1000.0)
        .unwrap()
        .with_angular_acceleration(alpha)
        .unwrap();
    let follower = Follower::Rotating {
        pivot: Point2::new(M * f64::from(z1 + z2) / 2.0, 0.0),
        closing: Sense::Ccw,
        initial_angle: PI + PI / f64::from(z2),
        profile: FollowerProfile(Arc::new(g2)),
    };
    Mechanism::new(cam, follower).unwrap()
}

/// Three mesh cycles of three pairs under angular acceleration, without and with backlash.
/// Every contact lies on a line of action: the driving one (through the pitch point, tangent to
/// the base circles below the line of centres) and, without backlash, the coast one (its mirror
/// image in the line of centres: the back flanks touch too). On each line there are as many
/// contacts as the line holds (the first one's place moved by whole base pitches, inside the
/// line's ends). Each slides along its flanks at the rates the involute's roll lengths give
/// (`ṡ₁ = ρ₁ ω₁`, `ṡ₂ = ρ₂ ω₂`), and each row holds at the ideal motion `q̈ = −(z1/z2) θ̈`
/// written here, not the one the method solved.
#[test]
fn ideal_gears_report_every_tooth_pair_in_contact() {
    // 18 teeth: the fewest a standard 20° rack cuts without undercut (17 is cut slightly, its
    // flank's foot a corner the mate's tip touches)
    for (z1, z2) in [(20, 42), (18, 60), (25, 31)] {
        for backlash in [0.0, 0.1] {
            mesh_cycles(z1, z2, backlash);
        }
    }
}

fn mesh_cycles(teeth1: u32, teeth2: u32, backlash: f64) {
    let alpha = 2000.0;
    let mech = gears(teeth1, teeth2, alpha, backlash);
    let (z1, z2) = (f64::from(teeth1), f64::from(teeth2));
    let a_w = 20f64.to_radians();
    let (r1, r2) = (M * z1 / 2.0, M * z2 / 2.0);
    let (rb1, rb2) = (r1 * a_w.cos(), r2 * a_w.cos());
    let (ra1, ra2) = (r1 + M, r2 + M);
    let a = r1 + r2;
    let pb = TAU * rb1 / z1;
    let pitch = Point2::new(r1, 0.0);
    // the lines of action: T₁ on the driver's base circle, the unit vector along the line, its
    // ends measured from the pitch point where the tip circles cross it
    let lines = [-1.0, 1.0].map(|side: f64| {
        let t1 = Point2::new(rb1 * a_w.cos(), side * rb1 * a_w.sin());
        (t1, (pitch - t1).normalize())
    });
    let (start, end) = (
        a * a_w.sin() - (ra2 * ra2 - rb2 * rb2).sqrt() - rb1 * a_w.tan(),
        (ra1 * ra1 - rb1 * rb1).sqrt() - rb1 * a_w.tan(),
    );
    let w1 = mech.cam().speed();
    let w2 = w1 * z1 / z2;
    let qdd = -z1 / z2 * alpha;
    let mut sweep = mech.sweep();
    let mut double = 0usize;
    // three mesh cycles
    let n = 360;
    for k in 0..n {
        let theta = f64::from(k) / f64::from(n) * 3.0 * TAU / z1;
        let s = sweep.step(theta).unwrap();
        let cs = mech.contacts_at(&s).unwrap();
        let what = format!(
            "{teeth1}/{teeth2}, backlash {backlash} mm, θ = {:.2}°",
            theta.to_degrees()
        );
        // the first contact is the state's own; the others in the order of the cam parameter
        assert_eq!(cs[0].point, s.contact_world, "{what}");
        assert!(
            cs[1..].windows(2).all(|w| w[0].cam_param < w[1].cam_param),
            "{what}"
        );
        let mut on_line = [Vec::new(), Vec::new()];
        for c in &cs {
            // on the line, the normal along it (both lines pass through the pitch point)
            let which = lines.iter().position(|(t1, e)| {
                let across = Vec2::new(-e.y, e.x);
                (c.point - t1).dot(&across).abs() <= 1e-10 * a
                    && c.normal.dot(&across).abs() <= 1e-10
            });
            let Some(i) = which else {
                panic!("{what}: {} on no line of action", c.point);
            };
            on_line[i].push(c);
            assert!(c.gap.abs() <= 1e-10 * a, "{what}: gap {}", c.gap);
            assert!(c.normal_velocity.abs() <= 1e-10 * w1 * a, "{what}");
            // sliding rates from the roll lengths
            let (t1, e) = lines[i];
            let rho1 = (c.point - t1).dot(&e);
            let rho2 = a * a_w.sin() - rho1;
            assert!(
                (c.sliding_rate_cam.abs() - rho1 * w1).abs() <= 1e-9 * w1 * a,
                "{what}: ṡ₁ {} against {}",
                c.sliding_rate_cam,
                rho1 * w1
            );
            assert!(
                (c.sliding_rate_follower.abs() - rho2 * w2).abs() <= 1e-9 * w1 * a,
                "{what}: ṡ₂ {} against {}",
                c.sliding_rate_follower,
                rho2 * w2
            );
            // the row, with the ideal accelerations
            let lhs = c.row_cam * alpha + c.row_follower * qdd;
            let scale = c.gamma.abs() + (c.row_cam * alpha).abs();
            assert!(
                (lhs - c.gamma).abs() <= 1e-9 * scale,
                "{what}: row gives {lhs} against γ = {}",
                c.gamma
            );
            assert!(c.residual.abs() <= 1e-9 * scale, "{what}");
        }
        assert!(on_line[0].iter().any(|c| c.point == s.contact_world));
        // the coast flanks touch when there is no backlash, and only then
        assert_eq!(on_line[1].is_empty(), backlash > 0.0, "{what}");
        for (i, line) in on_line.iter().enumerate() {
            let Some(first) = line.first() else { continue };
            let x = |c: &CamContact| (c.point - pitch).dot(&lines[i].1);
            for c in line {
                let j = (x(c) - x(first)) / pb;
                assert!((j - j.round()).abs() <= 1e-10, "{what}: {j} base pitches");
            }
            let (inside, near_end) = base_pitches_inside(x(first), pb, start, end);
            if !near_end {
                assert_eq!(line.len(), inside.len(), "{what}: line {i}, at {inside:?}");
            }
        }
        double += usize::from(on_line[0].len() == 2);
    }
    // the fraction of time with two pairs driving is ε − 1 (ε = 1.6398 for 20/42)
    let eps =
        ((ra1 * ra1 - rb1 * rb1).sqrt() + (ra2 * ra2 - rb2 * rb2).sqrt() - a * a_w.sin()) / pb;
    let frac = double as f64 / f64::from(n);
    assert!(
        (frac - (eps - 1.0)).abs() <= 2.0 / f64::from(n),
        "two pairs {frac} of the time, ε = {eps}"
    );
}

/// A 10-tooth pinion cut by a standard rack is undercut: its involute starts above the base
/// circle, where the rack's tip round crossed it. Meshing with 40 teeth it still transmits the
/// exact ratio (no contact on the fillet: the mate's tip reaches less deep than the rack's), but
/// over a shorter path: the time with two pairs in contact, counted from the contacts at each
/// angle, is `ε − 1` with `ε` from the form circle (1.09), not the textbook's tip-circle
/// formula (1.54), which assumes the involute down to the base circle.
#[test]
fn undercut_pinion_meshes_over_its_shortened_path_of_contact() {
    let mech = gears(10, 40, 0.0, 0.0);
    let gear = |z| InvoluteGear::new(InvoluteGearSpec::new(M, z, 20f64.to_radians())).unwrap();
    let (g1, g2) = (gear(10), gear(40));
    let a = M * 50.0 / 2.0;
    let eps = camkin::gears::contact_ratio(&g1, &g2, a).unwrap();
    let (rb1, rb2, ra1, ra2) = (
        g1.base_radius(),
        g2.base_radius(),
        g1.tip_radius(),
        g2.tip_radius(),
    );
    let pb = TAU * rb1 / 10.0;
    let textbook = ((ra1 * ra1 - rb1 * rb1).sqrt() + (ra2 * ra2 - rb2 * rb2).sqrt()
        - a * 20f64.to_radians().sin())
        / pb;
    assert!(
        g1.form_radius() > rb1 && eps < textbook - 0.4,
        "ε {eps}, textbook {textbook}"
    );
    let w = mech.cam().speed();
    let n = 720;
    let mut sweep = mech.sweep();
    let mut double = 0;
    for k in 0..n {
        let theta = f64::from(k) / f64::from(n) * 2.0 * TAU / 10.0;
        let s = sweep.step(theta).unwrap();
        assert!(
            (s.velocity + 0.25 * w).abs() <= 1e-10 * w,
            "{k}: ratio {}",
            -s.velocity / w
        );
        let cs = mech.contacts_at(&s).unwrap();
        // the driving flanks' contacts, their normal along the driving line of action (the
        // coast flanks touch too, without backlash, along its mirror image)
        let along = Vec2::new(20f64.to_radians().sin(), 20f64.to_radians().cos());
        let driving = cs
            .iter()
            .filter(|c| c.normal.dot(&along).abs() >= 1.0 - 1e-9)
            .count();
        double += usize::from(driving == 2);
    }
    let frac = double as f64 / f64::from(n);
    assert!(
        (frac - (eps - 1.0)).abs() <= 2.0 / f64::from(n),
        "two pairs {frac} of the time, ε = {eps}"
    );
}

/// A cam mirror-symmetric about the y axis with a notch at the top, narrower than the roller:
/// `r(φ) = 40 − 4 exp(−((φ − 90°)/8°)²)` through nodes every 5°.
fn notched() -> Arc<ClosedSpline> {
    let nodes: Vec<Point2> = (0..72)
        .map(|i| {
            let phi = (90.0 + 5.0 * f64::from(i)).to_radians();
            let d = (phi - PI / 2.0 + PI).rem_euclid(TAU) - PI;
            let r = 40.0 - 4.0 * (-(d / 8f64.to_radians()).powi(2)).exp();
            Point2::new(r * phi.cos(), r * phi.sin())
        })
        .collect();
    Arc::new(ClosedSpline::new(&nodes).unwrap())
}

fn on_notch(follower: Follower) -> Mechanism {
    let cam = Cam::from_rpm(notched(), Point2::origin(), Sense::Ccw, 600.0).unwrap();
    Mechanism::new(cam, follower).unwrap()
}

/// A roller over the notch, or a flat face on it, rests on both shoulders at θ = 0: two contacts,
/// mirror images of each other; at the mirror the second contact's own motion is the first's
/// reversed, so the motion (set by the first) opens it at `ν·(v_A − v_B) = −2 q̇ (ν·d)`. The same
/// through the named kinds and through their curves carried by the general follower.
#[test]
fn roller_or_face_on_a_notch_touches_both_shoulders() {
    let d = Vec2::new(0.0, 1.0);
    let roller = (
        Follower::TranslatingRoller {
            direction: d,
            offset: 0.0,
            roller_radius: 10.0,
        },
        Arc::new(Circle::new(Point2::origin(), 10.0).unwrap()) as Arc<dyn Curve>,
    );
    // the face x·d = s: in the frame along d, the line through the origin along −y
    let face = (
        Follower::TranslatingFlat { direction: d },
        Arc::new(Line::new(Point2::origin(), Vec2::new(0.0, -1.0)).unwrap()) as Arc<dyn Curve>,
    );
    for (named, curve) in [roller, face] {
        let general = Follower::Translating {
            direction: d,
            offset: 0.0,
            profile: FollowerProfile(curve),
        };
        on_both_shoulders(&on_notch(named), &on_notch(general), d);
    }
}

fn on_both_shoulders(named: &Mechanism, general: &Mechanism, d: Vec2) {
    let mut found: Vec<Vec<CamContact>> = Vec::new();
    for m in [named, general] {
        let s = m.analyze(0.0).unwrap();
        let cs = m.contacts_at(&s).unwrap();
        assert_eq!(cs.len(), 2, "{cs:?}");
        let (p, q) = (cs[0].point, cs[1].point);
        assert!(
            p.x.abs() > 1.0,
            "on a shoulder, not the notch's bottom: {p}"
        );
        assert!((p.x + q.x).abs() <= 1e-9 * 40.0, "{p} and {q}");
        assert!((p.y - q.y).abs() <= 1e-9 * 40.0, "{p} and {q}");
        assert!((cs[0].normal.x + cs[1].normal.x).abs() <= 1e-9);
        assert!(cs[1].gap.abs() <= 1e-9 * 40.0);
        assert!(
            s.velocity.abs() > 1.0,
            "the shoulders move: q̇ = {}",
            s.velocity
        );
        assert!(cs[0].normal_velocity.abs() <= 1e-9 * s.velocity.abs());
        let want = -2.0 * s.velocity * cs[1].normal.dot(&d);
        assert!(
            (cs[1].normal_velocity - want).abs() <= 1e-9 * want.abs(),
            "{} against {want}",
            cs[1].normal_velocity
        );
        found.push(cs);
    }
    // the named roller and the carried circle: the same two contacts
    for (a, b) in found[0].iter().zip(&found[1]) {
        assert!((a.point - b.point).norm() <= 1e-9 * 40.0);
        assert!((a.row_follower - b.row_follower).abs() <= 1e-9 * a.row_follower.abs());
        assert!((a.gamma - b.gamma).abs() <= 1e-9 * a.gamma.abs().max(1.0));
    }
    // off the mirror the roller rests on one shoulder
    for m in [named, general] {
        assert_eq!(m.contacts(0.05).unwrap().len(), 1);
    }
}

/// Wherever the first touch passes from one shoulder of the notch to the other (found by
/// bisection on which side the contact is), the follower touches both: two contacts there, one
/// on each shoulder, both touching. For an offset roller, an oscillating roller, a flat face and
/// a circle carried by an arm: the named kinds' search and the carried curve's.
#[test]
fn every_kind_touches_both_shoulders_where_its_contact_crosses_the_notch() {
    let pivot = Point2::new(60.0, 60.0);
    // the arm from the pivot to above the notch, turned counter-clockwise onto the cam
    let (arm, phi0) = (
        (Point2::new(0.0, 50.0) - pivot).norm(),
        (-10.0f64).atan2(-60.0).rem_euclid(TAU),
    );
    let followers = [
        Follower::TranslatingRoller {
            direction: Vec2::new(0.0, 1.0),
            offset: 3.0,
            roller_radius: 10.0,
        },
        Follower::TranslatingFlat {
            direction: Vec2::new(0.2, 1.0),
        },
        Follower::OscillatingRoller {
            pivot,
            arm_length: arm,
            roller_radius: 10.0,
            closing: Sense::Ccw,
            initial_angle: phi0,
        },
        Follower::Rotating {
            pivot,
            closing: Sense::Ccw,
            initial_angle: phi0,
            profile: FollowerProfile(Arc::new(Circle::new(Point2::new(arm, 0.0), 10.0).unwrap())),
        },
    ];
    for f in followers {
        let what = format!("{f:?}");
        let m = on_notch(f);
        let period = 72.0;
        let side = |theta: f64| {
            let u = m.analyze(theta).unwrap().cam_param;
            (u + period / 2.0).rem_euclid(period) > period / 2.0
        };
        // the crossing: a change of side between neighbouring angles, then bisection
        let steps: Vec<f64> = (0..=120).map(|k| -0.6 + 0.01 * f64::from(k)).collect();
        let k = steps
            .windows(2)
            .position(|w| side(w[0]) != side(w[1]))
            .unwrap_or_else(|| panic!("{what}: the contact never crosses the notch"));
        let (mut a, mut b) = (steps[k], steps[k + 1]);
        let sa = side(a);
        for _ in 0..60 {
            let mid = 0.5 * (a + b);
            if side(mid) == sa {
                a = mid;
            } else {
                b = mid;
            }
        }
        let s = m.analyze(a).unwrap();
        let cs = m.contacts_at(&s).unwrap();
        assert_eq!(cs.len(), 2, "{what} at θ = {a}: {cs:?}");
        let sides: Vec<bool> = cs
            .iter()
            .map(|c| (c.cam_param + period / 2.0).rem_euclid(period) > period / 2.0)
            .collect();
        assert_ne!(sides[0], sides[1], "{what}: both on one shoulder");
        assert!(cs.iter().all(|c| c.gap.abs() <= 1e-9 * 40.0), "{what}");
    }
}
