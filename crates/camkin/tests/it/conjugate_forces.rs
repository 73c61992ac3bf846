//! Forces on a form-closed (conjugate) follower: where the follower's own curve would leave the
//! cam its second curve carries the load. Checked against the closed forms of an eccentric disc
//! in a flat-faced yoke (no formula of the method), against the energy balance `T ω = M q̇ q̈`
//! (the torque from the two contacts' points and normals, the right side from the motion alone),
//! and against the reduced dynamics' contact force and driving torque, which integrate the
//! motion across the load reversals.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, FollowerProfile, Mechanism, Sense};
use camkin::curve::{Circle, Curve, Ellipse, InvoluteGear, InvoluteGearSpec, Line};
use camkin::dynamics::{AugmentedLagrangian, FollowerDynamics, Forces, Simulation};
use camkin::{Point2, Vec2};
use std::f64::consts::TAU;
use std::sync::Arc;

const R: f64 = 0.04;
const E: f64 = 0.01;
const M: f64 = 0.3;

fn params(m: f64, inertia: f64, k: f64, f0: f64) -> FollowerDynamics {
    FollowerDynamics {
        mass: m,
        inertia,
        spring_stiffness: k,
        spring_preload: f0,
        damping: 0.0,
        restitution: 0.0,
        gravity: Vec2::zeros(),
    }
}

/// An eccentric disc (radius R, eccentricity e) between two flat faces `2R` apart, on a slide
/// along x: the yoke sits at `s = R + e cos φ` (φ = σθ), so along the slide
/// `R = −m e ω² cos φ + F₀ + k e (1 + cos φ)` is what the faces must supply. The near face
/// carries `R` where it is positive and the far face `−R` elsewhere, each at lever 1 (pressure
/// angle 0) on a flat (∞ radius), and the torque is `−σ (F₁ − F₂) e sin φ` (the contacts are at
/// the disc centre's height, on opposite normals). From the spring's preload on, the far face
/// takes load from `ω² = (F₀ + 2 k e)/(m e)`.
#[test]
fn a_flat_faced_yoke_on_an_eccentric_shares_the_load_between_its_faces() {
    for sense in [Sense::Ccw, Sense::Cw] {
        for (k, f0) in [(0.0, 0.0), (2000.0, 20.0)] {
            let s = sense.sign();
            let w = 120.0;
            let far: Arc<dyn Curve> =
                Arc::new(Line::new(Point2::new(-2.0 * R, 0.0), Vec2::new(0.0, 1.0)).unwrap());
            let mech = mechanism(
                eccentric_circle(R, E),
                Point2::origin(),
                sense,
                w * 60.0 / TAU,
                Follower::TranslatingFlat {
                    direction: Vec2::x(),
                },
            )
            .with_conjugate(far)
            .unwrap();
            let f = Forces::new(&mech, params(M, 0.0, k, f0)).unwrap();
            assert!(f.is_form_closed());
            let mut sweep = f.sweep();
            let mut reversals = 0;
            let mut last = None;
            for j in 0..72 {
                let theta = f64::from(j) * 5f64.to_radians() + 0.01;
                let warm = sweep.step(theta).unwrap();
                let st = f.at(theta).unwrap();
                let what = format!("{sense:?} k {k} θ {theta}");
                assert_close(warm.contact_force, st.contact_force, 1e-12, 100.0, &what);
                let phi = s * theta;
                let need = -M * E * w * w * phi.cos() + f0 + k * E * (1.0 + phi.cos());
                let (f1, f2) = (need.max(0.0), (-need).max(0.0));
                let c = st.second.unwrap();
                assert_close(st.contact_force, f1, 1e-12, 100.0, &what);
                assert_close(c.contact_force, f2, 1e-12, 100.0, &what);
                assert_close(c.lever, 1.0, 1e-12, 1.0, &what);
                assert_close(c.pressure_angle, 0.0, 1e-12, 1.0, &what);
                assert_close(c.cam_radius, R, 1e-12, R, &what);
                assert_eq!(c.follower_radius, Some(f64::INFINITY), "{what}");
                assert_eq!(st.follower_radius, Some(f64::INFINITY), "{what}");
                let torque = -s * (f1 - f2) * E * phi.sin();
                assert_close(st.camshaft_torque, torque, 1e-12, 1.0, &what);
                let now = need > 0.0;
                reversals += usize::from(last.is_some_and(|l| l != now));
                last = Some(now);
                if k > 0.0 && phi.cos() > 0.3 {
                    let exact = ((f0 + k * E * (1.0 + phi.cos())) / (M * E * phi.cos())).sqrt();
                    assert_close(f.leave_speed(&st, 0.0), exact, 1e-12, exact, &what);
                }
                if k == 0.0 && phi.cos() > 1e-3 {
                    // no spring: the far face carries at any speed where the yoke decelerates
                    assert_eq!(f.leave_speed(&st, 0.0), 0.0, "{what}");
                }
            }
            // without a spring the load changes face where the acceleration changes sign: at
            // φ = 90° and 270°
            if k == 0.0 {
                assert_eq!(reversals, 2, "{sense:?}");
            }
        }
    }
}

/// Without spring, damping or gravity, the torque that drives the cam at constant speed is the
/// rate of the follower's kinetic energy: `T ω = M q̇ q̈`. The torque comes from each contact's
/// point and normal and the force it carries; the right side from the motion alone. A roller
/// yoke on the constant-diameter cam of the example (the second roller its own contact), and a
/// flat-faced arm yoke on a circle (an inertia, the second face on the arm).
#[test]
fn the_torque_of_a_form_closed_follower_is_its_rate_of_kinetic_energy() {
    let yoke = Mechanism::try_from(yoke_spec(0.0, None)).unwrap();
    let arm = mechanism(
        eccentric_circle(30.0, 5.0),
        Point2::origin(),
        Sense::Cw,
        600.0,
        Follower::OscillatingFlat {
            pivot: Point2::new(-100.0, 40.0),
            face_offset: 0.0,
            closing: Sense::Cw,
            initial_angle: 0.0,
        },
    )
    .with_conjugate(Arc::new(
        Line::new(Point2::new(0.0, -60.0), Vec2::new(-1.0, 0.0)).unwrap(),
    ))
    .unwrap();
    for (name, mech, p) in [
        ("roller yoke", &yoke, params(M, 0.0, 0.0, 0.0)),
        ("arm yoke", &arm, params(0.0, 2e-3, 0.0, 0.0)),
    ] {
        let f = Forces::new(mech, p).unwrap();
        let inertia = p.mass + p.inertia;
        let w = mech.cam().speed();
        let mut sweep = f.sweep();
        let mut carried = [0, 0];
        let peak = (0..360)
            .map(|j| {
                let s = mech.analyze(f64::from(j).to_radians()).unwrap();
                (inertia * s.velocity * s.acceleration).abs()
            })
            .fold(0.0, f64::max);
        for j in 0..360 {
            let theta = (f64::from(j) + 0.3).to_radians();
            let st = sweep.step(theta).unwrap();
            let s = mech.analyze(theta).unwrap();
            let rate = inertia * s.velocity * s.acceleration;
            assert_close(
                st.camshaft_torque * w,
                rate,
                1e-9,
                peak,
                &format!("{name} θ {theta}"),
            );
            let second = st.second.unwrap().contact_force;
            assert!(st.contact_force >= 0.0 && second >= 0.0);
            assert!(st.contact_force == 0.0 || second == 0.0, "one carries");
            carried[usize::from(second > 0.0)] += 1;
        }
        // both curves carry over a revolution
        assert!(carried[0] > 30 && carried[1] > 30, "{name}: {carried:?}");
    }
}

/// The reduced dynamics of the constant-diameter yoke (no play, no spring) follows the cam across
/// its load reversals: its contact force and driving torque are the kinetostatic ones, on the
/// curve the kinetostatics says carries.
#[test]
fn kinetostatic_forces_of_a_yoke_equal_the_simulated_ones() {
    let mech = Mechanism::try_from(yoke_spec(0.0, None)).unwrap();
    let p = params(M, 0.0, 0.0, 0.0);
    let f = Forces::new(&mech, p).unwrap();
    let mut sim = Simulation::starting_at(&mech, p, AugmentedLagrangian::default(), 0.0).unwrap();
    let w = mech.cam().speed();
    let h = 0.25f64.to_radians() / w;
    let peak = (0..360)
        .map(|j| {
            let st = f.at(f64::from(j).to_radians()).unwrap();
            st.contact_force.max(st.second.unwrap().contact_force)
        })
        .fold(0.0, f64::max);
    let mut compared = [0, 0];
    for _ in 0..1440 {
        sim.advance(h).unwrap();
        let s = sim.sample().unwrap();
        let st = f.at(s.cam_angle).unwrap();
        let second = st.second.unwrap().contact_force;
        let expected = st.contact_force.max(second);
        let what = format!("θ {}", s.cam_angle.to_degrees());
        assert_close(s.contact_force, expected, 1e-6, peak, &what);
        assert_close(
            s.driver_torque,
            st.camshaft_torque,
            1e-6,
            peak * 0.07,
            &what,
        );
        if expected > 1e-3 * peak {
            assert_eq!(s.on_conjugate, second > 0.0, "{what}");
            compared[usize::from(s.on_conjugate)] += 1;
        }
    }
    assert!(compared[0] > 300 && compared[1] > 300, "{compared:?}");
}

/// The follower's radius of curvature at the contact, for the Hertz stress: a roller's radius,
/// named or carried as a circle; an ellipse carried on a slide, its radius at the contact point
/// from the point's coordinates in the ellipse's axes, `a² b² (x²/a⁴ + y²/b⁴)^{3/2}` (no
/// derivative of the curve).
#[test]
fn the_follower_radius_at_the_contact() {
    let roller = |named: bool| {
        if named {
            Follower::TranslatingRoller {
                direction: Vec2::y(),
                offset: 0.004,
                roller_radius: 0.012,
            }
        } else {
            Follower::Translating {
                direction: Vec2::y(),
                offset: 0.004,
                profile: FollowerProfile(Arc::new(Circle::new(Point2::origin(), 0.012).unwrap())),
            }
        }
    };
    let (a, b, rot) = (0.02, 0.011, 0.3);
    let egg = Follower::Translating {
        direction: Vec2::y(),
        offset: 0.003,
        profile: FollowerProfile(Arc::new(Ellipse::new(Point2::origin(), a, b, rot).unwrap())),
    };
    for (name, follower) in [
        ("named", roller(true)),
        ("carried", roller(false)),
        ("ellipse", egg),
    ] {
        let mech = mechanism(
            ellipse(0.045, 0.03, Point2::origin(), 0.0),
            Point2::origin(),
            Sense::Ccw,
            300.0,
            follower,
        );
        let f = Forces::new(&mech, params(M, 0.0, 1000.0, 10.0)).unwrap();
        for j in 0..36 {
            let theta = f64::from(j) * 10f64.to_radians() + 0.05;
            let st = f.at(theta).unwrap();
            let rf = st.follower_radius.unwrap();
            if name == "ellipse" {
                let s = mech.analyze(theta).unwrap();
                let (pose, _) = mech.follower_body(s.position);
                // the body frame is world-aligned; the ellipse's axes are turned by the slide's
                // direction (the profile's x axis, here +y) and then by its own rotation
                let x = pose.to_body(s.contact_world);
                let turn = rot + std::f64::consts::FRAC_PI_2;
                let (c, sn) = (turn.cos(), turn.sin());
                let (u, v) = (c * x.x + sn * x.y, -sn * x.x + c * x.y);
                let rho = a * a * b * b * (u * u / a.powi(4) + v * v / b.powi(4)).powf(1.5);
                assert_close(rf, rho, 1e-9, rho, &format!("{name} θ {theta}"));
            } else {
                assert_close(rf, 0.012, 1e-12, 0.012, &format!("{name} θ {theta}"));
            }
        }
    }
}

/// A knife edge has no line contact, nor does a corner: a flat face on a spur gear rests on its
/// tip corners (no radius) and on its tip lands (a flat's ∞).
#[test]
fn a_knife_edge_and_a_corner_have_no_follower_radius() {
    let knife = mechanism(
        eccentric_circle(R, E),
        Point2::origin(),
        Sense::Ccw,
        300.0,
        Follower::TranslatingKnife {
            direction: Vec2::y(),
            offset: 0.0,
        },
    );
    let f = Forces::new(&knife, params(M, 0.0, 1000.0, 10.0)).unwrap();
    assert_eq!(f.at(0.3).unwrap().follower_radius, None);
    let gear = InvoluteGear::new(InvoluteGearSpec::new(0.002, 20, 20f64.to_radians())).unwrap();
    let mech = flat_face_on(gear);
    let f = Forces::new(&mech, params(M, 0.0, 1000.0, 10.0)).unwrap();
    let mut seen = [0, 0];
    for k in 0..120 {
        let theta = f64::from(k) * 0.15f64.to_radians();
        let st = f.at(theta).unwrap();
        if mech.analyze(theta).unwrap().corner.is_some() {
            assert_eq!(st.follower_radius, None, "θ {theta}");
            seen[0] += 1;
        } else {
            assert_eq!(st.follower_radius, Some(f64::INFINITY), "θ {theta}");
            seen[1] += 1;
        }
    }
    assert!(seen[0] > 10 && seen[1] > 10, "{seen:?}");
}
