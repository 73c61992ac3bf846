//! Lift-off, free flight and re-contact of a flat-faced follower on an eccentric circular cam,
//! against closed forms that share nothing with the simulation: the follower's kinematic motion
//! `s = R + e cos φ` (φ = σθ + β), the analytic contact force, the harmonic free flight under the
//! spring, and the restitution rule. Both cam directions, the disc's centre off the follower's
//! axis (so that a cw cam treated as ccw would fail). Each closed form checks both models: the
//! multibody one and the one-coordinate one ([`camkin::dynamics::Reduced`]).
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Mechanism, Sense};
use camkin::dynamics::{
    AugmentedLagrangian, Event, EventKind, FollowerDynamics, Reduced, Sample, Simulation,
    REBOUND_TOLERANCE,
};
use camkin::{Point2, Vec2};
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

const R: f64 = 0.04; // m
const E: f64 = 0.01;
const M: f64 = 0.3; // kg
const K: f64 = 2000.0; // N/m
const F0: f64 = 20.0; // N at the lowest position
const REST: f64 = 0.6;

/// The analytic threshold speed: the contact force `−m e ω² cos φ + F0 + k e (1 + cos φ)` first
/// reaches zero at `φ = 0`.
fn w_crit() -> f64 {
    ((F0 + 2.0 * K * E) / (M * E)).sqrt()
}

struct Run {
    m: Mechanism,
    w: f64,
    sigma: f64,
    beta: f64,
    theta0: f64,
    events: Vec<Event>,
    last: Sample,
}

impl Run {
    /// φ at time t.
    fn phi(&self, t: f64) -> f64 {
        self.sigma * (self.theta0 + self.w * t) + self.beta
    }
    /// The cam's support along x (the flat face's kinematic position) and its rate at time t.
    fn cam(&self, t: f64) -> (f64, f64) {
        let p = self.phi(t);
        (R + E * p.cos(), -E * self.sigma * self.w * p.sin())
    }
    /// The analytic contact force in permanent contact at time t.
    fn force(&self, t: f64) -> f64 {
        let p = self.phi(t);
        -M * E * self.w * self.w * p.cos() + F0 + K * E * (1.0 + p.cos())
    }
}

/// The eccentric disc (centre at `E` in direction `beta`) turning at `w` rad/s in `sense` under
/// a flat face travelling along x.
fn eccentric_flat(w: f64, sense: Sense, beta: f64) -> Mechanism {
    let disc = Arc::new(
        camkin::curve::Circle::new(Point2::new(E * beta.cos(), E * beta.sin()), R).unwrap(),
    );
    mechanism(
        disc,
        Point2::origin(),
        sense,
        w * 60.0 / TAU,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    )
}

/// The follower: mass `M` on the spring `K`, `F0`, with damping `c` (N·s/m).
fn follower(c: f64) -> FollowerDynamics {
    FollowerDynamics {
        mass: M,
        inertia: 0.0,
        spring_stiffness: K,
        spring_preload: F0,
        damping: c,
        restitution: REST,
        gravity: Vec2::zeros(),
    }
}

/// The simulation of `m` from `theta0` in the multibody model, or in the one-coordinate model.
fn start(m: &Mechanism, p: FollowerDynamics, theta0: f64, reduced: bool) -> Simulation<'_> {
    let sim = if reduced {
        Simulation::Reduced(Reduced::starting_at(m, p, theta0).unwrap())
    } else {
        Simulation::starting_at(m, p, AugmentedLagrangian::default(), theta0).unwrap()
    };
    assert_eq!(matches!(sim, Simulation::Reduced(_)), reduced);
    sim
}

/// Both models, named.
const MODELS: [(bool, &str); 2] = [(false, "multibody"), (true, "one coordinate")];

fn run(speed_factor: f64, sense: Sense, beta: f64, reduced: bool) -> Run {
    let w = speed_factor * w_crit();
    let m = eccentric_flat(w, sense, beta);
    let p = follower(0.0);
    // start where the contact force is largest (φ = π) and run one revolution
    let sigma = sense.sign();
    let theta0 = sigma * (PI - beta);
    let (events, last) = {
        let mut sim = start(&m, p, theta0, reduced);
        let h = 0.5f64.to_radians() / w;
        let mut events = Vec::new();
        for _ in 0..720 {
            events.extend(sim.advance(h).unwrap());
        }
        (events, sim.sample().unwrap())
    };
    Run {
        m,
        w,
        sigma,
        beta,
        theta0,
        events,
        last,
    }
}

/// The first root of `f` after `t0` (f(t0⁺) > 0), by scanning in steps of `dt` and bisecting.
fn first_root(f: impl Fn(f64) -> f64, t0: f64, dt: f64, t_max: f64) -> Option<f64> {
    let mut a = t0;
    while a < t_max {
        let b = a + dt;
        if f(b) <= 0.0 {
            let (mut lo, mut hi) = (a, b);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if f(mid) > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            return Some(0.5 * (lo + hi));
        }
        a = b;
    }
    None
}

#[test]
fn no_lift_off_below_the_threshold() {
    for (sense, beta) in [(Sense::Ccw, 0.0), (Sense::Cw, 0.7)] {
        for (reduced, model) in MODELS {
            let r = run(0.98, sense, beta, reduced);
            assert!(r.events.is_empty(), "{model}: {:?}", r.events);
        }
    }
}

/// Lift-off where the analytic force crosses zero; free flight under the spring is harmonic, so
/// each landing time and approach speed follows from the state after the previous event; each
/// impact reverses the normal velocity times the restitution; once a rebound is slower than
/// `REBOUND_TOLERANCE · ω · size` the follower stays on the cam and follows the kinematic motion.
#[test]
fn lift_off_flight_impacts_and_re_engagement_follow_closed_forms() {
    for ((sense, beta), (reduced, model)) in [(Sense::Ccw, 0.0), (Sense::Cw, 0.7)]
        .into_iter()
        .flat_map(|c| MODELS.map(|m| (c, m)))
    {
        let r = run(1.02, sense, beta, reduced);
        let period = TAU / r.w;
        let name = format!("{model}, {sense:?}, β = {}", r.beta);
        // lift-off: the first zero of the analytic contact force
        let t_lift = first_root(|t| r.force(t), 0.0, period / 3600.0, period).unwrap();
        let lift = &r.events[0];
        assert_eq!(lift.kind, EventKind::LiftOff, "{name}: {:?}", r.events);
        let d_angle = (lift.time - t_lift) * r.w;
        eprintln!(
            "{name}: lift-off at {:.7}°, analytic {:.7}° (Δ = {:.1e}°)",
            lift.cam_angle.to_degrees(),
            (r.theta0 + r.w * t_lift).to_degrees(),
            d_angle.to_degrees()
        );
        assert!(
            d_angle.to_degrees().abs() < 1e-9,
            "{name}: Δ = {d_angle:e} rad"
        );

        // the flights, from the analytic state at lift-off
        let omega = (K / M).sqrt();
        let low = R - E;
        let (mut t0, mut x0, mut v0) = {
            let (x, v) = r.cam(t_lift);
            (t_lift, x, v)
        };
        let threshold = REBOUND_TOLERANCE * r.w * r.m.size();
        let mut impacts = 0;
        let mut worst_t: f64 = 0.0;
        let mut worst_v: f64 = 0.0;
        loop {
            // x(τ) about the spring's equilibrium low − F0/k, harmonic with Ω = √(k/m)
            let y0 = x0 - (low - F0 / K);
            let x = |t: f64| {
                let tau = t - t0;
                (low - F0 / K) + y0 * (omega * tau).cos() + v0 / omega * (omega * tau).sin()
            };
            let v = |t: f64| {
                let tau = t - t0;
                -y0 * omega * (omega * tau).sin() + v0 * (omega * tau).cos()
            };
            let gap = |t: f64| x(t) - r.cam(t).0;
            let t_land = first_root(gap, t0 + 1e-7 * period, period / 20_000.0, t0 + period)
                .unwrap_or_else(|| panic!("{name}: no landing predicted"));
            let approach = r.cam(t_land).1 - v(t_land);
            impacts += 1;
            let ev = r
                .events
                .get(impacts)
                .unwrap_or_else(|| panic!("{name}: impact {impacts} missing: {:?}", r.events));
            assert_eq!(ev.kind, EventKind::Impact, "{name}");
            worst_t = worst_t.max(((ev.time - t_land) / period).abs());
            worst_v = worst_v.max(((ev.impact_velocity - approach) / approach).abs());
            let rebound = REST * approach;
            if rebound <= threshold {
                break;
            }
            // after the impact: on the cam, moving away with the relative speed e·v
            t0 = t_land;
            x0 = r.cam(t_land).0;
            v0 = r.cam(t_land).1 + rebound;
        }
        eprintln!(
            "{name}: {impacts} impacts; landing times within {worst_t:.1e} of a revolution, approach speeds within {worst_v:.1e} relative"
        );
        assert_eq!(r.events.len(), impacts + 1, "{name}: {:?}", r.events);
        // the one-coordinate model's flight is exact (the multibody one integrates it by RK4)
        let (tol_t, tol_v) = if reduced { (1e-11, 1e-9) } else { (1e-9, 1e-7) };
        assert!(worst_t < tol_t, "{name}: landing times off by {worst_t:e}");
        assert!(
            worst_v < tol_v,
            "{name}: approach speeds off by {worst_v:e}"
        );
        // re-engaged: in contact at the end of the revolution, on the kinematic motion
        let t_end = r.last.time;
        assert!(r.last.in_contact, "{name}");
        assert!(
            (r.last.position - r.cam(t_end).0).abs() < 1e-9 * R,
            "{name}: {} vs {}",
            r.last.position,
            r.cam(t_end).0
        );
    }
}

/// Regression (`simulate examples/eccentric-flat-dynamics.toml` started in contact carrying a
/// tensile force of −2.65 N): above the jump speed, a start at the top of the stroke (φ = 0, where
/// the analytic contact force is negative) is in flight from time 0: the first sample carries no
/// force and the spring's acceleration `−(F0 + 2 k e)/m`, and the first step reports a lift-off at
/// time 0, for both cam senses.
#[test]
fn a_start_with_a_tensile_contact_force_is_in_flight_from_time_zero() {
    for sense in [Sense::Ccw, Sense::Cw] {
        let beta: f64 = 0.3;
        let sigma = sense.sign();
        let w = 1.02 * w_crit();
        let m = eccentric_flat(w, sense, beta);
        let p = follower(0.0);
        // φ = σθ + β = 0 at the start: the top of the stroke
        let theta0 = -sigma * beta;
        let analytic_force = -M * E * w * w + F0 + 2.0 * K * E;
        assert!(analytic_force < 0.0, "the case must start tensile");
        for (reduced, model) in MODELS {
            let mut sim = start(&m, p, theta0, reduced);
            let s0 = sim.sample().unwrap();
            assert!(!s0.in_contact, "{model}, {sense:?}: starts in contact");
            assert_eq!(s0.contact_force, 0.0);
            assert_close(s0.position, R + E, 1e-12, R, "start position");
            let spring_accel = -(F0 + 2.0 * K * E) / M;
            assert_close(
                s0.acceleration,
                spring_accel,
                1e-9,
                spring_accel.abs(),
                "free-flight acceleration",
            );
            let events = sim.advance(0.5f64.to_radians() / w).unwrap();
            assert!(
                matches!(events.first(), Some(e) if e.kind == EventKind::LiftOff && e.time == 0.0),
                "{model}, {sense:?}: {events:?}"
            );
        }
    }
}

/// Issue 12 and issue 64: a time step longer than the follower's fastest rate allows is not
/// refused: the steps inside it are chosen by the tolerances. An overdamped follower (where a
/// fixed step 1.7 times RK4's limit once gave impacts of 9–18 m/s for the resolved run's 1 m/s)
/// asked for outputs ten times its stable step apart stays on the run asked for outputs at a
/// sixteenth of that, to 1e-6 of the eccentricity.
#[test]
fn an_output_step_longer_than_the_damping_allows_is_cut_by_the_tolerances_not_refused() {
    let beta: f64 = 0.0;
    let w = 1.2 * w_crit();
    let m = eccentric_flat(w, Sense::Ccw, beta);
    let c = 2000.0; // N·s/m: c/m = 6667 /s, far above √(k/m) = 82 /s
    let p = follower(c);
    let mut sim = Simulation::starting_at(&m, p, AugmentedLagrangian::default(), 0.0).unwrap();
    let (cm, km) = (c / M, K / M);
    let rate = 0.5 * (cm + (cm * cm - 4.0 * km).sqrt());
    let h = 10.0 * 2.0 / rate;
    let mut fine = Simulation::starting_at(&m, p, AugmentedLagrangian::default(), 0.0).unwrap();
    let mut worst = 0.0f64;
    for _ in 0..100 {
        sim.advance(h).unwrap();
        for _ in 0..16 {
            fine.advance(h / 16.0).unwrap();
        }
        let (a, b) = (sim.sample().unwrap(), fine.sample().unwrap());
        assert!(a.position.is_finite() && a.velocity.is_finite(), "{a:?}");
        worst = worst.max((a.position - b.position).abs());
    }
    assert!(
        worst <= 1e-6 * E,
        "the long output step departs from the short one by {worst:e} m"
    );
}
