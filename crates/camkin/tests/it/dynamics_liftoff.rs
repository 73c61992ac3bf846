//! Lift-off of a flat-faced follower on an eccentric circular cam: analytic threshold speed
//! ω² = (F0 + 2 k e)/(m e) and the cam angle where the analytic contact force crosses zero.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Sense};
use camkin::dynamics::{AugmentedLagrangian, EventKind, FollowerDynamics, Simulation};
use camkin::{Point2, Vec2};

const R: f64 = 0.04; // m
const E: f64 = 0.01;
const M: f64 = 0.3; // kg
const K: f64 = 2000.0; // N/m
const F0: f64 = 20.0; // N at the lowest position

fn run(speed_factor: f64) -> (Vec<camkin::dynamics::Event>, f64) {
    let w_crit = ((F0 + 2.0 * K * E) / (M * E)).sqrt();
    let w = speed_factor * w_crit;
    let m = mechanism(
        eccentric_circle(R, E),
        Point2::origin(),
        Sense::Ccw,
        w * 60.0 / std::f64::consts::TAU,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    );
    let p = FollowerDynamics {
        mass: M,
        inertia: 0.0,
        spring_stiffness: K,
        spring_preload: F0,
        damping: 0.0,
        restitution: 0.6,
        gravity: Vec2::zeros(),
    };
    // start where the contact force is largest (θ = 180°) and run one revolution
    let mut sim =
        Simulation::starting_at(&m, p, AugmentedLagrangian::default(), std::f64::consts::PI)
            .unwrap();
    let h = 0.5f64.to_radians() / w;
    let mut events = Vec::new();
    for _ in 0..720 {
        events.extend(sim.advance(h).unwrap());
    }
    (events, w)
}

#[test]
fn no_lift_off_below_the_threshold() {
    let (events, _) = run(0.98);
    assert!(events.is_empty(), "{events:?}");
}

#[test]
fn lift_off_above_the_threshold_where_the_force_crosses_zero() {
    let (events, w) = run(1.02);
    let lift = events
        .iter()
        .find(|e| e.kind == EventKind::LiftOff)
        .expect("a lift-off");
    // F_c(θ) = −m e ω² cos θ + F0 + k e (1 + cos θ) reaches zero first on the way to θ = 360°
    let cos_t = (F0 + K * E) / (M * E * w * w - K * E);
    let theta = std::f64::consts::TAU - cos_t.acos();
    let got = lift.cam_angle.rem_euclid(std::f64::consts::TAU);
    eprintln!(
        "lift-off at {:.6}°, analytic {:.6}°; events {events:?}",
        got.to_degrees(),
        theta.to_degrees()
    );
    assert!(
        (got - theta).to_degrees().abs() < 0.1,
        "lift-off at {}°, analytic {}°",
        got.to_degrees(),
        theta.to_degrees()
    );
    // the follower comes back: an impact, after the lift-off
    assert!(
        events
            .iter()
            .any(|e| e.kind == EventKind::Impact && e.time > lift.time && e.impact_velocity > 0.0),
        "{events:?}"
    );
}
