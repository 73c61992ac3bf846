//! Dynamics with permanent contact: the simulated follower reproduces the kinematic motion of
//! the contact method, and the contact force balances the follower's equation of motion.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Sense};
use camkin::dynamics::{AugmentedLagrangian, FollowerDynamics, Simulation};
use camkin::{Point2, Vec2};

fn params(oscillating: bool) -> FollowerDynamics {
    FollowerDynamics {
        mass: 0.5,
        inertia: 0.02,
        spring_stiffness: if oscillating { 200.0 } else { 2.0e4 },
        spring_preload: if oscillating { 50.0 } else { 800.0 },
        damping: if oscillating { 0.5 } else { 20.0 },
        restitution: 0.5,
        gravity: Vec2::zeros(),
    }
}

#[test]
fn permanent_contact_reproduces_kinematics_for_every_follower() {
    for (dir, f) in [Sense::Ccw, Sense::Cw].into_iter().flat_map(|d| {
        all_followers(Point2::origin())
            .into_iter()
            .map(move |f| (d, f))
    }) {
        let osc = f.is_oscillating();
        let m = mechanism(
            paper_profile(false),
            Point2::origin(),
            dir,
            100.0,
            f.clone(),
        );
        let p = params(osc);
        let mut sim = Simulation::new(&m, p, AugmentedLagrangian::default()).unwrap();
        let sign = match *m.follower() {
            Follower::OscillatingFlat { closing, .. }
            | Follower::OscillatingRoller { closing, .. } => closing.sign(),
            _ => -1.0,
        };
        let low = extreme(&m, -sign);
        let w = m.cam().speed();
        let h = 0.25f64.to_radians() / w;
        let mut amax: f64 = 0.0;
        let mut worst_a: f64 = 0.0;
        let mut worst_f: f64 = 0.0;
        let mut fmax: f64 = 0.0;
        for _ in 0..1440 {
            let events = sim.advance(h).unwrap();
            assert!(events.is_empty(), "{}: {events:?}", f.kind_name());
            let s = sim.sample().unwrap();
            let k = m.analyze(s.cam_angle).unwrap();
            amax = amax.max(k.acceleration.abs());
            worst_a = worst_a.max((s.acceleration - k.acceleration).abs());
            // the force balance along the follower's motion
            let lhs = s.contact_force * k.normal.dot(&k.follower_motion).abs()
                / if osc { 1.0 } else { k.follower_motion.norm() };
            let rhs = if osc {
                // torque about the pivot: I φ̈ + spring torque (against the closing sense) + c φ̇
                p.inertia * s.acceleration - spring_torque(&p, sign, low, s.position)
                    + p.damping * s.velocity
            } else {
                p.mass * s.acceleration + spring_force(&p, low, s.position) + p.damping * s.velocity
            };
            worst_f = worst_f.max((lhs - rhs).abs());
            fmax = fmax.max(rhs.abs());
            assert!(
                s.contact_force > 0.0,
                "{}: force {}",
                f.kind_name(),
                s.contact_force
            );
        }
        eprintln!(
            "{} {dir:?}: |Δa|/max|a| = {:e}, force balance |Δ|/max = {:e}",
            f.kind_name(),
            worst_a / amax,
            worst_f / fmax
        );
        assert!(
            // the guide claims 3e-14 of the peak
            worst_a <= 1e-13 * amax,
            "{}: {}",
            f.kind_name(),
            worst_a / amax
        );
        assert!(
            // the guide claims 2e-10 of the largest force
            worst_f <= 1e-9 * fmax,
            "{}: {}",
            f.kind_name(),
            worst_f / fmax
        );
    }
}

/// The extreme position over a revolution (`sense` +1: smallest, −1: largest): a 0.1° sampling
/// refined by the parabola through the three samples around the extreme (error O(Δθ⁴)).
fn extreme(m: &camkin::cam::Mechanism, sense: f64) -> f64 {
    let n = 3600;
    let pos: Vec<f64> = (0..n)
        .map(|k| sense * m.position((k as f64 * 0.1).to_radians()).unwrap())
        .collect();
    let k = (0..n).min_by(|&a, &b| pos[a].total_cmp(&pos[b])).unwrap();
    let (a, b, c) = (pos[(k + n - 1) % n], pos[k], pos[(k + 1) % n]);
    // vertex of the parabola through (−1, a), (0, b), (1, c)
    let vertex = b - (c - a) * (c - a) / (8.0 * (a - 2.0 * b + c));
    sense * vertex
}

/// Spring force along +d (positive: pushing onto the cam) at position `s`, the lowest position
/// being `low`.
fn spring_force(p: &FollowerDynamics, low: f64, s: f64) -> f64 {
    p.spring_preload + p.spring_stiffness * (s - low)
}

/// Spring torque (ccw positive) on the arm at angle `phi`, turning it in the sense `sign`, the
/// lowest position being `low`.
fn spring_torque(p: &FollowerDynamics, sign: f64, low: f64, phi: f64) -> f64 {
    sign * (p.spring_preload + p.spring_stiffness * (-sign * (phi - low)))
}

/// No damping, permanent contact, 100 revolutions: the driving torque's work equals the gain in
/// kinetic plus spring energy (the guide claims 2.6e-7 of the energy exchanged with 0.25° steps),
/// and the constraints do not drift (the guide claims 5e-14 of the cam's size).
#[test]
fn energy_balance_and_no_drift_over_a_hundred_revolutions() {
    let m = mechanism(
        paper_profile(false),
        Point2::origin(),
        Sense::Ccw,
        100.0,
        Follower::TranslatingRoller {
            direction: Vec2::y(),
            offset: 0.7,
            roller_radius: 1.2,
        },
    );
    let p = FollowerDynamics {
        damping: 0.0,
        ..params(false)
    };
    let mut sim = Simulation::new(&m, p, AugmentedLagrangian::default()).unwrap();
    let low = extreme(&m, 1.0);
    let energy = |s: &camkin::dynamics::Sample| {
        0.5 * p.mass * s.velocity * s.velocity
            + p.spring_preload * (s.position - low)
            + 0.5 * p.spring_stiffness * (s.position - low).powi(2)
    };
    let s0 = sim.sample().unwrap();
    let e0 = energy(&s0);
    let w = m.cam().speed();
    let h = 0.25f64.to_radians() / w;
    let (mut worst, mut swing, mut drift): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for k in 0..144_000 {
        assert!(sim.advance(h).unwrap().is_empty());
        if k % 40 == 0 {
            let s = sim.sample().unwrap();
            let de = energy(&s) - e0;
            swing = swing.max(de.abs());
            worst = worst.max((s.driver_work - de).abs());
            drift = drift.max(sim.constraint_residual().unwrap());
        }
    }
    eprintln!(
        "energy: |W − ΔE| ≤ {worst:e} against swings of {swing:e}; drift {drift:e} (size {})",
        m.size()
    );
    assert!(worst <= 5e-7 * swing, "{worst} vs {swing}");
    assert!(drift <= 2e-13 * m.size(), "{drift}");
}
