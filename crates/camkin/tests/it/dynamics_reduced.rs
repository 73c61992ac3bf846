//! The one-coordinate model ([`camkin::dynamics::Reduced`]): gear pairs with a load, rattle in
//! the backlash, a form-closed yoke, and agreement with the multibody model, each against what
//! the model must obey and that the test computes itself: the textbook ratio and base radius,
//! straight flights without a load, the restitution rule with velocities from finite differences
//! of the first-touch positions, the cycloid's closed form and the power balance.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Cam, Follower, FollowerProfile, Mechanism, Sense};
use camkin::curve::{InvoluteGear, InvoluteGearSpec, ReliefShape, TipRelief};
use camkin::dynamics::{
    AugmentedLagrangian, DynamicsError, Event, EventKind, FollowerDynamics, Reduced, Sample,
    Simulation,
};
use camkin::spec::BuildOptions;
use camkin::{Point2, Vec2};
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

/// module, m
const MODULE: f64 = 0.002;
const Z1: u32 = 20;
const Z2: u32 = 42;

fn alpha() -> f64 {
    20f64.to_radians()
}

/// The driven gear's base radius, m.
fn base_radius() -> f64 {
    MODULE * f64::from(Z2) / 2.0 * alpha().cos()
}

/// A 20/42 pair (SI) at the standard centre distance, the driver ccw at 1000 rpm, the driven
/// gear closing ccw; `relief` on both gears, `backlash` on the driven one, its coast flanks as a
/// second curve when `coast`.
fn gears(relief: Option<TipRelief>, backlash: f64, coast: bool) -> Mechanism {
    let spec = |z: u32, j: f64| {
        let mut s = InvoluteGearSpec::new(MODULE, z, alpha());
        s.tip_relief = relief;
        s.backlash = j;
        s
    };
    let g1 = InvoluteGear::new(spec(Z1, 0.0)).unwrap();
    let g2 = Arc::new(InvoluteGear::new(spec(Z2, backlash)).unwrap());
    let cam = Cam::from_rpm(Arc::new(g1), Point2::origin(), Sense::Ccw, 1000.0).unwrap();
    let follower = Follower::Rotating {
        pivot: Point2::new(MODULE * f64::from(Z1 + Z2) / 2.0, 0.0),
        closing: Sense::Ccw,
        initial_angle: PI + PI / f64::from(Z2),
        profile: FollowerProfile(g2.clone()),
    };
    let m = Mechanism::new(cam, follower).unwrap();
    if coast {
        m.with_conjugate(g2).unwrap()
    } else {
        m
    }
}

fn relief() -> Option<TipRelief> {
    Some(TipRelief {
        amount: 20e-6,
        length: 5e-3,
        shape: ReliefShape::Parabolic,
    })
}

/// A driven body of inertia `j` (or mass) under a constant load `load` in its closing sense.
fn load(j: f64, load: f64, restitution: f64) -> FollowerDynamics {
    FollowerDynamics {
        mass: j,
        inertia: j,
        spring_stiffness: 0.0,
        spring_preload: load,
        damping: 0.0,
        restitution,
        gravity: Vec2::zeros(),
    }
}

struct Ran {
    samples: Vec<Sample>,
    events: Vec<Event>,
}

fn simulate(m: &Mechanism, p: FollowerDynamics, step_deg: f64, revolutions: f64) -> Ran {
    let mut sim = Simulation::new(m, p, AugmentedLagrangian::default()).unwrap();
    assert!(
        matches!(sim, Simulation::Reduced(_)),
        "the one-coordinate model"
    );
    let outputs = (revolutions * 360.0 / step_deg).round() as usize;
    let h = step_deg.to_radians() / m.cam().speed();
    let run = sim
        .run(outputs, h, |_| std::ops::ControlFlow::Continue(()))
        .unwrap();
    Ran {
        samples: run.samples,
        events: run.events,
    }
}

/// The ideal pair under a load torque never leaves the flank: the driven gear turns at exactly
/// `z1/z2` of the driver's speed, the flank force is the load over the base radius, the driver's
/// torque is the load times `z1/z2` and its work that torque times the angle; the contact hands
/// over to the next tooth pair once per tooth (every 18°) without an impact.
#[test]
fn an_ideal_gear_pair_carries_its_load_at_the_ratio() {
    let m = gears(None, 0.0, false);
    let (j, torque) = (0.002, 10.0);
    let ran = simulate(&m, load(j, torque, 0.5), 1.0, 1.0);
    let w = m.cam().speed();
    let ratio = f64::from(Z1) / f64::from(Z2);
    for s in &ran.samples {
        let at = format!("{:.1}°", s.cam_angle.to_degrees());
        assert!(s.in_contact, "{at}");
        assert_close(s.velocity, -ratio * w, 1e-10, w, &format!("{at}: speed"));
        assert_close(s.acceleration, 0.0, 1e-10, w * w, &format!("{at}: acc"));
        assert_close(
            s.contact_force,
            torque / base_radius(),
            1e-10,
            torque / base_radius(),
            &format!("{at}: flank force"),
        );
        assert_close(
            s.driver_torque,
            torque * ratio,
            1e-10,
            torque,
            &format!("{at}: driver torque"),
        );
    }
    let last = ran.samples.last().unwrap();
    assert_close(
        last.driver_work,
        torque * ratio * TAU,
        1e-10,
        torque * TAU,
        "the driver's work",
    );
    // one handover per tooth: 19 or 20 in a revolution, as the first falls
    assert!(ran.events.len() + 1 >= Z1 as usize, "{:?}", ran.events);
    let pitch_speed = w * MODULE * f64::from(Z1) / 2.0;
    for (k, e) in ran.events.iter().enumerate() {
        assert_eq!(e.kind, EventKind::Jump);
        assert!(e.impact_velocity <= 1e-9 * pitch_speed, "{e:?}");
        if k > 0 {
            let spacing = (e.cam_angle - ran.events[k - 1].cam_angle).to_degrees();
            // both pairs touch around an ideal handover: the jump is seen within 1e-6°
            assert!((spacing - 360.0 / f64::from(Z1)).abs() < 1e-5, "{spacing}°");
        }
    }
}

/// The first touch `o(θ)` of the follower's own curve (`conjugate = false`) or of its second
/// curve, in the follower's coordinate, by cold searches.
fn first_touch(m: &Mechanism, conjugate: bool, theta: f64) -> f64 {
    let s = m.analyze(theta).unwrap();
    if conjugate {
        // the play is measured against the closing sense: for an arm closing ccw, the second
        // curve touches `play` further cw (away from the cam)
        let away = match m.follower_joint() {
            camkin::cam::FollowerJoint::Rotating { closing, .. } => -closing.sign(),
            _ => 1.0,
        };
        s.position + away * m.conjugate_play(&s).unwrap().unwrap()
    } else {
        s.position
    }
}

/// `dq/dt` of a first touch at `theta`, from positions alone, on the branch after it
/// (`side = 1`) or before it (`side = −1`): central differences at `2d` and `4d` to that side,
/// extrapolated linearly to `theta` (clear of a kink, which a jump may have passed by 1e-6 rad).
fn flank_speed(m: &Mechanism, conjugate: bool, theta: f64, side: f64) -> f64 {
    let (h, d) = (1e-6, side * 1e-5);
    let central = |x: f64| {
        let (a, b) = (
            first_touch(m, conjugate, x - h),
            first_touch(m, conjugate, x + h),
        );
        (camkin::geometry::wrap_angle_near(b, a) - a) / (2.0 * h)
    };
    (2.0 * central(theta + 2.0 * d) - central(theta + 4.0 * d)) * m.cam().speed()
}

/// What a run under a constant load (no spring, no damping) must obey, checked from the samples,
/// the events and the kinematic positions alone: the follower stays between its curves' first
/// touches; between events it flies with the constant acceleration `free` (the load over the
/// inertia); at every impact the approach speed is the lever (the base radius, within 2 %: on a
/// relieved tip the normal leaves the base circle's tangent) times the relative speed, and the
/// speed after is the flank's minus `e` times the relative speed. Returns the number of impacts
/// on each curve.
fn check_rattle(m: &Mechanism, ran: &Ran, e: f64, free: f64) -> [usize; 2] {
    let away = m.travel().unwrap().away;
    let w = m.cam().speed();
    let scale = w * f64::from(Z1) / f64::from(Z2);
    for s in &ran.samples {
        let o = away * s.position;
        let o1 = away * first_touch(m, false, s.cam_angle);
        assert!(o - o1 >= -1e-11, "{:?}: {} below the flank", s, o - o1);
        if m.is_conjugate() {
            let o2 = away * first_touch(m, true, s.cam_angle);
            assert!(
                o2 - o >= -1e-11,
                "{:?}: {} beyond the coast flank",
                s,
                o2 - o
            );
        }
        if !s.in_contact {
            assert_close(s.acceleration, free, 1e-12, free.abs(), "free flight");
        }
    }
    let mut hits = [0, 0];
    for (k, pair) in ran.samples.windows(2).enumerate() {
        let (a, b) = (&pair[0], &pair[1]);
        let inside: Vec<&Event> = ran
            .events
            .iter()
            .filter(|ev| ev.time > a.time && ev.time <= b.time)
            .collect();
        if inside.is_empty() && !a.in_contact && !b.in_contact {
            // a flight at constant acceleration
            let dt = b.time - a.time;
            let v = a.velocity + free * dt;
            assert_close(b.velocity, v, 1e-12, scale, &format!("flight {k}"));
            let moved = b.position - a.position;
            assert_close(
                moved,
                a.velocity * dt + 0.5 * free * dt * dt,
                1e-12,
                scale * dt,
                &format!("flight {k}: distance"),
            );
        }
        if let [ev] = inside[..] {
            if ev.kind == EventKind::LiftOff {
                continue;
            }
            hits[usize::from(ev.conjugate)] += 1;
            let before = if ev.kind == EventKind::Jump {
                flank_speed(m, ev.conjugate, ev.cam_angle, -1.0)
            } else {
                assert!(!a.in_contact, "{ev:?} after contact");
                a.velocity + free * (ev.time - a.time)
            };
            let flank = flank_speed(m, ev.conjugate, ev.cam_angle, 1.0);
            let approach = base_radius() * (before - flank).abs();
            assert_close(
                ev.impact_velocity,
                approach,
                0.02,
                approach,
                &format!("{ev:?}: approach speed"),
            );
            if !b.in_contact {
                let after = flank - e * (before - flank) + free * (b.time - ev.time);
                assert_close(b.velocity, after, 1e-6, scale, &format!("{ev:?}: rebound"));
            }
        }
    }
    hits
}

/// The free acceleration of the driven gear (rad/s²) under the load `torque` in its closing
/// sense (ccw).
fn free(torque: f64, j: f64) -> f64 {
    torque / j
}

/// With tip relief and a light load, the driven gear is struck at the handovers, flies off the
/// flank and lands again, by the laws of [`check_rattle`].
#[test]
fn a_lightly_loaded_relieved_pair_rattles_by_the_impact_law() {
    let m = gears(relief(), 0.0, false);
    let (j, torque, e) = (0.002, 0.5, 0.5);
    let ran = simulate(&m, load(j, torque, e), 0.25, 0.5);
    let hits = check_rattle(&m, &ran, e, free(torque, j));
    eprintln!("impacts: {hits:?}; events: {}", ran.events.len());
    assert!(hits[0] >= 9, "{:?}", ran.events);
}

/// With backlash the driven gear flies across it and strikes its coast flanks too (the second
/// curve), by the same laws.
#[test]
fn backlash_lets_the_driven_gear_rattle_between_its_flanks() {
    let m = gears(relief(), 20e-6, true);
    let (j, torque, e) = (0.002, 0.05, 0.9);
    let ran = simulate(&m, load(j, torque, e), 0.25, 0.5);
    let hits = check_rattle(&m, &ran, e, free(torque, j));
    eprintln!("impacts on the drive and coast flanks: {hits:?}");
    assert!(hits[0] >= 3 && hits[1] >= 3, "{:?}", ran.events);
}

/// The constant-diameter cam of `examples/conjugate-yoke.toml` in SI, `extra` m of clearance
/// between the rollers, the cam speeding up at `alpha` °/s².
fn yoke(extra: f64, alpha: Option<f64>) -> Mechanism {
    yoke_spec(1e3 * extra, alpha)
        .build(&BuildOptions {
            si: true,
            ..Default::default()
        })
        .unwrap()
        .mechanism
}

/// The cycloid's lift `s`, `s'`, `s''` (m, per rad) at cam angle `t`: 20 mm over 180° and back.
fn cycloid(t: f64) -> [f64; 3] {
    let (h, b) = (0.02, PI);
    let t = t.rem_euclid(TAU);
    let (phi, sign, base) = if t < b {
        (t, 1.0, 0.0)
    } else {
        (t - b, -1.0, h)
    };
    let x = TAU * phi / b;
    [
        base + sign * h * (phi / b - x.sin() / TAU),
        sign * h / b * (1.0 - x.cos()),
        sign * h * TAU / (b * b) * x.sin(),
    ]
}

/// A form-closed yoke without a spring, the cam speeding up: the yoke follows the cycloid
/// exactly with no event; the roller that carries the load is the one the acceleration presses
/// (the follower's own while `s̈ > 0`, the second while `s̈ < 0`), and the driver's power is the
/// rate of the yoke's kinetic energy, `m s̈ ṡ`.
#[test]
fn a_form_closed_yoke_follows_the_cycloid_and_passes_its_load_between_rollers() {
    let alpha_deg = 9000.0;
    let m = yoke(0.0, Some(alpha_deg));
    let mass = 0.4;
    let ran = simulate(&m, load(mass, 0.0, 0.0), 1.0, 1.0);
    assert!(ran.events.is_empty(), "{:?}", ran.events);
    let (w0, al) = (m.cam().speed(), alpha_deg.to_radians());
    let mut on = [0, 0];
    for s in &ran.samples {
        let t = s.time;
        let (theta, w) = (w0 * t + 0.5 * al * t * t, w0 + al * t);
        assert_close(s.cam_angle, theta, 1e-12, 1.0, "cam angle");
        let [q, d1, d2] = cycloid(theta);
        let (v, acc) = (d1 * w, d2 * w * w + d1 * al);
        let at = format!("{:.1}°", theta.to_degrees());
        assert_close(s.position, 0.05 + q, 1e-12, 0.05, &format!("{at}: s"));
        assert_close(s.velocity, v, 1e-9, 0.02 * w, &format!("{at}: ṡ"));
        assert_close(s.acceleration, acc, 1e-8, 0.02 * w * w, &format!("{at}: s̈"));
        assert!(s.in_contact);
        if acc.abs() > 1e-6 * 0.02 * w * w {
            assert_eq!(s.on_conjugate, acc < 0.0, "{at}: s̈ = {acc}");
            on[usize::from(s.on_conjugate)] += 1;
            assert!(s.contact_force > 0.0, "{at}");
        }
        let power = mass * acc * v;
        assert_close(
            s.driver_torque * w,
            power,
            1e-8,
            mass * 0.02 * 0.02 * w * w * w,
            &format!("{at}: power"),
        );
    }
    assert!(on[0] > 100 && on[1] > 100, "{on:?}");
}

/// A second curve that cuts into the cam is refused, naming it, with the depth (here the
/// interference built in: 0.2 mm).
#[test]
fn a_second_curve_that_cuts_into_the_cam_is_refused() {
    let m = yoke(-0.2e-3, None);
    let e = Simulation::new(&m, load(0.4, 0.0, 0.0), AugmentedLagrangian::default()).unwrap_err();
    let DynamicsError::Interference { depth, unit, .. } = e else {
        panic!("{e}");
    };
    assert_close(depth, 0.2e-3, 1e-9, 1e-3, "depth");
    assert_eq!(unit, "m");
    assert!(e.to_string().starts_with("follower.conjugate"), "{e}");
}

/// Where both models apply (one contact that never jumps) they agree: the paper's cam under a
/// flat face, fast enough to lift off and bounce; the multibody model's RK4 steps are the only
/// difference (the one-coordinate model's flight is exact).
#[test]
fn the_two_models_agree_where_both_apply() {
    let m = mechanism(
        paper_profile(false),
        Point2::origin(),
        Sense::Ccw,
        1000.0,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    );
    // the paper's cam's numbers read as metres: a large cam, a soft spring
    let p = FollowerDynamics {
        mass: 0.5,
        inertia: 0.0,
        spring_stiffness: 500.0,
        spring_preload: 1000.0,
        damping: 5.0,
        restitution: 0.5,
        gravity: Vec2::zeros(),
    };
    let h = 0.25f64.to_radians() / m.cam().speed();
    let mut a = Simulation::new(&m, p, AugmentedLagrangian::default()).unwrap();
    assert!(matches!(a, Simulation::Preset(_)));
    let mut b = Simulation::Reduced(Reduced::starting_at(&m, p, 0.0).unwrap());
    let (mut ea, mut eb) = (Vec::new(), Vec::new());
    let mut worst: f64 = 0.0;
    for _ in 0..1440 {
        ea.extend(a.advance(h).unwrap());
        eb.extend(b.advance(h).unwrap());
        let (sa, sb) = (a.sample().unwrap(), b.sample().unwrap());
        worst = worst.max((sa.position - sb.position).abs() / m.size());
        assert_eq!(sa.in_contact, sb.in_contact, "{sa:?} {sb:?}");
    }
    let period = TAU / m.cam().speed();
    eprintln!(
        "{} events; positions within {worst:.1e} of the cam's size",
        ea.len()
    );
    assert!(ea.len() >= 3, "{ea:?}");
    assert_eq!(ea.len(), eb.len(), "{ea:?}\n{eb:?}");
    for (x, y) in ea.iter().zip(&eb) {
        assert_eq!(x.kind, y.kind);
        assert!((x.time - y.time).abs() < 1e-8 * period, "{x:?} {y:?}");
        assert_close(
            x.impact_velocity,
            y.impact_velocity,
            1e-6,
            y.impact_velocity.max(1e-3),
            "impact speed",
        );
    }
    assert!(worst < 1e-8, "{worst:e}");
}
