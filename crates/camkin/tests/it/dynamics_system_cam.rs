//! Issue 46: a cam-follower simulated as a system (`SystemSimulation` on the preset of
//! `Mechanism::to_system`, its spring a point spring along the slide built here by hand) against
//! the cam-follower simulation (`Simulation`: the library's own preset with the follower's
//! mass, spring and damper, issue 62) and the closed forms of
//! `dynamics_liftoff`: an eccentric disc under a flat face, below the lift-off speed (the
//! follower on the cam: `s = R + e cos θ`, the contact force in closed form) and above it (the
//! lift-off's instant, each landing's instant and approach speed, both models).

use crate::common::*;
use camkin::body::{BodyState, Pose};
use camkin::cam::{Follower, Mechanism, Sense};
use camkin::dynamics::{
    AugmentedLagrangian, EventKind, FollowerDynamics, Simulation, SystemDynamicsOptions,
    SystemSimulation,
};
use camkin::system::{BodyId, ForceElement, ForceKind};
use camkin::{Point2, Vec2};
use std::f64::consts::TAU;
use std::sync::Arc;

const R: f64 = 0.04; // m
const E: f64 = 0.01;
const M: f64 = 0.3; // kg
const K: f64 = 2000.0; // N/m
const F0: f64 = 20.0; // N at the lowest position
const REST: f64 = 0.6;

fn w_crit() -> f64 {
    ((F0 + 2.0 * K * E) / (M * E)).sqrt()
}

fn eccentric_flat(w: f64) -> Mechanism {
    let disc = Arc::new(camkin::curve::Circle::new(Point2::new(E, 0.0), R).unwrap());
    mechanism(
        disc,
        Point2::origin(),
        Sense::Ccw,
        w * 60.0 / TAU,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    )
}

/// The mechanism's preset system with the follower's mass and spring: a point spring from a
/// ground point on the slide's line 1 m beyond the lowest position, free length 1 m and a
/// tension of −F0 there, so that it pushes the follower onto the cam with `F0 + K (s − low)`.
fn as_system(m: &Mechanism) -> (camkin::cam::CamFollowerSystem, f64) {
    let mut preset = m.to_system().unwrap();
    let f = preset.follower.index().unwrap();
    // as today's model has them: the cam's (driven) 1 and 1, the slide's mass and inertia 1
    let mut bodies = preset.system.bodies().to_vec();
    for b in &mut bodies {
        (b.mass, b.inertia) = (1.0, 1.0);
    }
    bodies[f].mass = M;
    let low = R - E;
    let p0 = bodies[f].pose.origin;
    let s0 = preset
        .joint
        .coordinate_of(&BodyState::at_rest(bodies[f].pose))[0];
    let ground_end = p0 + (low + 1.0 - s0) * Vec2::x();
    let mut sys = camkin::system::System::new();
    for b in bodies {
        sys.add_body(b);
    }
    for j in preset.system.joints() {
        sys.add_joint(j.clone());
    }
    for d in preset.system.drivers() {
        sys.add_driver(d.clone());
    }
    for c in preset.system.contacts() {
        sys.add_contact(c.clone());
    }
    sys.add_force(ForceElement {
        name: "spring".into(),
        kind: ForceKind::Spring {
            a: BodyId::GROUND,
            at_a: ground_end,
            b: preset.follower,
            at_b: Point2::origin(),
            stiffness: K,
            free_length: 1.0,
            preload: -F0,
        },
    });
    preset.system = sys;
    (preset, p0.x - s0)
}

fn params() -> FollowerDynamics {
    FollowerDynamics {
        mass: M,
        inertia: 0.0,
        spring_stiffness: K,
        spring_preload: F0,
        damping: 0.0,
        restitution: REST,
        gravity: Vec2::zeros(),
    }
}

/// Below the lift-off speed both follow `s = R + e cos θ` and push with
/// `F0 + K e (1 + cos θ) − M e ω² cos θ`; the camshaft's torque is `−F e sin θ`, and the energy
/// changes by the drive's work.
#[test]
fn below_lift_off_the_system_path_follows_the_closed_form_and_todays_model() {
    let w = 0.8 * w_crit();
    let m = eccentric_flat(w);
    let (preset, _) = as_system(&m);
    let opts = SystemDynamicsOptions {
        restitution: vec![REST],
        ..SystemDynamicsOptions::default()
    };
    let mut sys_sim = SystemSimulation::new(&preset.system, opts).unwrap();
    let mut cam_sim = Simulation::new(&m, params(), AugmentedLagrangian::default()).unwrap();
    let h = 0.5f64.to_radians() / w;
    let f = preset.follower.index().unwrap();
    let (mut dq, mut dv, mut df, mut dm) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let (mut dt, mut de) = (0.0f64, 0.0f64);
    let e0 = sys_sim.sample().unwrap().energy;
    for _ in 0..720 {
        assert!(sys_sim.advance(h).unwrap().is_empty());
        assert!(cam_sim.advance(h).unwrap().is_empty());
        let s = sys_sim.sample().unwrap();
        let c = cam_sim.sample().unwrap();
        let th = w * s.time;
        let body = BodyState {
            pose: Pose::new(Point2::new(s.q[3 * f], s.q[3 * f + 1]), s.q[3 * f + 2]),
            velocity: Vec2::new(s.qd[3 * f], s.qd[3 * f + 1]),
            omega: s.qd[3 * f + 2],
            acceleration: Vec2::new(s.qdd[3 * f], s.qdd[3 * f + 1]),
            alpha: s.qdd[3 * f + 2],
        };
        let [q, v, _] = preset.joint.coordinate_of(&body);
        let force = F0 + K * E * (1.0 + th.cos()) - M * E * w * w * th.cos();
        dq = dq.max((q - (R + E * th.cos())).abs() / E);
        dv = dv.max((v + E * w * th.sin()).abs() / (E * w));
        df = df.max((s.contact_forces[0] - force).abs() / force);
        dm = dm.max((s.contact_forces[0] - c.contact_force).abs() / force);
        dm = dm.max((q - c.position).abs() / E);
        // the camshaft's torque: the face pushes the disc back along −x at height e sin θ, so
        // the drive supplies −F e sin θ (its power the follower's F·ṡ)
        let torque = -force * E * th.sin();
        dt = dt.max((s.driver_efforts[0] - torque).abs() / (force * E));
        // no damping, no impact: the energy changes by the drive's work alone
        de = de.max((s.energy - e0 - s.driver_work).abs() / (K * E * E));
    }
    eprintln!("camshaft torque {dt:.1e} of F e; energy less work {de:.1e} of k e²");
    assert!(dt < 1e-9 && de < 1e-9, "{dt:e} {de:e}");
    eprintln!(
        "closed form: position {dq:.1e}, velocity {dv:.1e}, force {df:.1e}; today's model {dm:.1e}"
    );
    assert!(
        dq < 1e-12 && dv < 1e-10 && df < 1e-9,
        "{dq:e} {dv:e} {df:e}"
    );
    assert!(dm < 1e-9, "{dm:e}");
}

/// Above it: the lift-off where the force crosses zero and every landing, in both models (a
/// regression test too: the flying contact's pairing was not followed from step to step, and
/// Newton from the pairing at lift-off found the disc's far side, an impact 8 ms early).
#[test]
fn above_lift_off_the_system_path_flies_and_lands_as_todays_model_does() {
    let w = 1.3 * w_crit();
    let m = eccentric_flat(w);
    let (preset, _) = as_system(&m);
    let opts = SystemDynamicsOptions {
        restitution: vec![REST],
        ..SystemDynamicsOptions::default()
    };
    let mut sys_sim = SystemSimulation::new(&preset.system, opts).unwrap();
    let mut cam_sim = Simulation::new(&m, params(), AugmentedLagrangian::default()).unwrap();
    let h = 0.5f64.to_radians() / w;
    let (mut mine, mut theirs) = (Vec::new(), Vec::new());
    for _ in 0..720 {
        mine.extend(sys_sim.advance(h).unwrap());
        theirs.extend(cam_sim.advance(h).unwrap());
    }
    let period = TAU / w;
    assert!(mine.len() >= 3, "{mine:?}");
    assert_eq!(mine.len(), theirs.len(), "{mine:?}\n{theirs:?}");
    let (mut dt, mut dv) = (0.0f64, 0.0f64);
    for (a, b) in mine.iter().zip(&theirs) {
        assert_eq!(a.kind, b.kind);
        dt = dt.max((a.time - b.time).abs() / period);
        if a.kind == EventKind::Impact {
            dv = dv.max((a.approach - b.impact_velocity).abs() / (E * w));
        }
    }
    eprintln!(
        "{} events; times within {dt:.1e} of a revolution, approach speeds within {dv:.1e} of e ω",
        mine.len()
    );
    assert!(dt < 1e-10 && dv < 1e-10, "{dt:e} {dv:e}");
}

/// Regression (issue 62): a cam simulated for hundreds of revolutions. The contact's parameter
/// on the disc ran on without bound (−2048 after 327 revolutions of
/// `eccentric-flat-dynamics.toml`), where Newton could not step below its rounding and the run
/// stopped with "pairing-point search did not converge". A disc turning slowly under a follower
/// held by gravity alone (no spring: steps of 10°) for 400 revolutions stays on the closed form
/// `s = R + e cos θ`.
#[test]
fn hundreds_of_revolutions_keep_the_contact() {
    let w = 10.0; // rad/s: e ω² = 1 m/s², under gravity's 9.81: no lift-off
    let m = eccentric_flat(w);
    let p = FollowerDynamics {
        mass: M,
        inertia: 0.0,
        spring_stiffness: 0.0,
        spring_preload: 0.0,
        damping: 0.0,
        restitution: 0.0,
        gravity: Vec2::new(-9.81, 0.0),
    };
    let mut sim = Simulation::new(&m, p, AugmentedLagrangian::default()).unwrap();
    let h = 10f64.to_radians() / w;
    for _ in 0..400 * 36 {
        let events = sim.advance(h).unwrap();
        assert!(events.is_empty(), "{events:?}");
    }
    let s = sim.sample().unwrap();
    let miss = (s.position - (R + E * s.cam_angle.cos())).abs();
    assert!(s.in_contact && miss < 1e-9 * R, "{miss:e}");
}
