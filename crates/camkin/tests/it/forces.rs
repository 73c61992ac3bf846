//! Forces under permanent contact against closed forms that share nothing with the method (the
//! eccentric disc under a flat face: `F = −m e ω² cos φ + F₀ + k e (1 + cos φ)`,
//! `T = −σ F e sin φ`, the jump speed `ω² = (F₀ + 2 k e)/(m e)`), against the dynamic simulation
//! (the multibody solution's contact force, for a flat face, a roller and an oscillating arm of
//! either closing sense), and Hertz's line contact against its half-width form.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Sense};
use camkin::dynamics::{
    effective_modulus, hertz_line_pressure, AugmentedLagrangian, FollowerDynamics, Forces,
    Simulation,
};
use camkin::{Point2, Vec2};
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

const R: f64 = 0.04;
const E: f64 = 0.01;
const M: f64 = 0.3;
const K: f64 = 2000.0;
const F0: f64 = 20.0;

fn params(m: f64, inertia: f64, k: f64, f0: f64, c: f64) -> FollowerDynamics {
    FollowerDynamics {
        mass: m,
        inertia,
        spring_stiffness: k,
        spring_preload: f0,
        damping: c,
        restitution: 0.0,
        gravity: Vec2::zeros(),
    }
}

#[test]
fn eccentric_disc_under_a_flat_face_gives_the_closed_forms() {
    for sense in [Sense::Ccw, Sense::Cw] {
        let s = sense.sign();
        let w = 120.0;
        let disc = Arc::new(camkin::curve::Circle::new(Point2::new(E, 0.0), R).unwrap());
        let mech = mechanism(
            disc,
            Point2::origin(),
            sense,
            w * 60.0 / TAU,
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
        );
        let f = Forces::new(&mech, params(M, 0.0, K, F0, 0.0)).unwrap();
        assert!((f.travel().stroke() - 2.0 * E).abs() < 1e-15);
        for k in 0..72 {
            let theta = k as f64 * 5f64.to_radians();
            let st = f.at(theta).unwrap();
            // the disc's centre is at angle φ = σθ
            let phi = s * theta;
            let force = -M * E * w * w * phi.cos() + F0 + K * E * (1.0 + phi.cos());
            assert_close(st.contact_force, force, 1e-12, 100.0, "contact force");
            let torque = -s * force * E * phi.sin();
            assert_close(st.camshaft_torque, torque, 1e-12, 1.0, "camshaft torque");
            // power: T ω = F q̇ with q̇ = −σ e ω sin φ
            assert_close(
                st.camshaft_torque * w,
                force * (-s * E * w * phi.sin()),
                1e-12,
                100.0,
                "power",
            );
            // the jump speed, the preload and the stiffness for a target speed
            let jump = f.leave_speed(&st, 0.0);
            let c = phi.cos();
            if c > 0.3 {
                // F = 0 at m e ω² c = F0 + k e (1 + c)
                let exact = ((F0 + K * E * (1.0 + c)) / (M * E * c)).sqrt();
                assert_close(jump, exact, 1e-12, exact, "leave speed");
            }
            let target = 200.0;
            let margin = 5.0;
            let preload = f.preload_needed(&st, margin, target);
            let exact = margin + M * E * target * target * c - K * E * (1.0 + c);
            let exact = exact.max(margin - K * E * (1.0 + c));
            assert_close(preload, exact, 1e-12, 100.0, "preload");
        }
        // over the revolution: the smallest speed is at φ = 0
        let worst = (0..720)
            .map(|k| f.leave_speed(&f.at(k as f64 * PI / 360.0).unwrap(), 0.0))
            .fold(f64::INFINITY, f64::min);
        let exact = ((F0 + 2.0 * K * E) / (M * E)).sqrt();
        assert_close(worst, exact, 1e-12, exact, "jump speed");
    }
}

/// The contact force of the multibody simulation in permanent contact (a stiff spring) equals
/// the kinetostatic one at every sampled instant: both cam senses, a flat face, an offset
/// roller, an oscillating roller closing either way.
#[test]
fn kinetostatic_force_equals_the_simulated_one_at_steady_contact() {
    let disc = || Arc::new(camkin::curve::Circle::new(Point2::new(E, 0.003), R).unwrap());
    let cases: Vec<(Follower, FollowerDynamics)> = vec![
        (
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
            params(M, 0.0, K, 60.0, 3.0),
        ),
        (
            Follower::TranslatingRoller {
                direction: Vec2::y(),
                offset: 0.005,
                roller_radius: 0.01,
            },
            params(M, 0.0, K, 60.0, 0.0),
        ),
        (
            Follower::OscillatingRoller {
                pivot: Point2::new(0.02, 0.08),
                arm_length: 0.06,
                roller_radius: 0.01,
                closing: Sense::Cw,
                initial_angle: -1.0,
            },
            params(0.0, 2e-4, 50.0, 3.0, 0.0),
        ),
        (
            Follower::OscillatingRoller {
                pivot: Point2::new(-0.07, 0.05),
                arm_length: 0.06,
                roller_radius: 0.01,
                closing: Sense::Ccw,
                initial_angle: 0.0,
            },
            params(0.0, 2e-4, 50.0, 3.0, 0.01),
        ),
    ];
    for sense in [Sense::Ccw, Sense::Cw] {
        for (follower, p) in &cases {
            let w = 60.0;
            let mech = mechanism(
                disc(),
                Point2::origin(),
                sense,
                w * 60.0 / TAU,
                follower.clone(),
            );
            let f = Forces::new(&mech, *p).unwrap();
            let mut sim =
                Simulation::starting_at(&mech, *p, AugmentedLagrangian::default(), 0.0).unwrap();
            let h = 1f64.to_radians() / w;
            let peak = (0..36)
                .map(|k| f.at(k as f64 * 0.17).unwrap().contact_force.abs())
                .fold(0.0, f64::max);
            for _ in 0..90 {
                for _ in 0..4 {
                    assert!(sim.advance(h / 4.0).unwrap().is_empty(), "{follower:?}");
                }
                let s = sim.sample().unwrap();
                let st = f.at(s.cam_angle).unwrap();
                assert!(st.contact_force > 0.0);
                assert_close(
                    s.contact_force,
                    st.contact_force,
                    1e-8,
                    peak,
                    &format!("{follower:?} {sense:?}"),
                );
                // the simulation's driver torque is the camshaft torque
                assert_close(
                    s.driver_torque * sense.sign(),
                    st.camshaft_torque,
                    1e-8,
                    peak * R,
                    "torque",
                );
            }
        }
    }
}

/// Hertz line contact: `p = √(F E*/(π L R))` against the half-width form of Shigley's
/// Mechanical Engineering Design (eqs. 3-73, 3-74: `b = √(2F/(πl) · Σ(1 − ν²)/E / Σ1/d)`,
/// `p_max = 2F/(π b l)`), written here with diameters, for a roller on a convex cam, on a concave
/// one, and a flat face.
#[test]
fn hertz_line_contact_matches_the_half_width_form() {
    let (e1, nu1, e2, nu2) = (206e9, 0.3, 110e9, 0.34);
    let es = effective_modulus(e1, nu1, e2, nu2);
    for (r1, r2, force, l) in [
        (0.03, 0.01, 800.0, 0.012),
        (-0.05, 0.01, 500.0, 0.02),
        (0.025, f64::INFINITY, 300.0, 0.01),
    ] {
        let (d1, d2) = (2.0 * r1, 2.0 * r2);
        let b = (2.0 * force / (PI * l) * ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2)
            / (1.0 / d1 + 1.0 / d2))
            .sqrt();
        let p = 2.0 * force / (PI * b * l);
        let got = hertz_line_pressure(force, l, r1, r2, es).unwrap();
        assert_close(got, p, 1e-12, p, "p_max");
    }
    // a concave cam as sharp as the roller has no Hertz solution (conformal contact)
    assert!(hertz_line_pressure(100.0, 0.01, -0.01, 0.01, es).is_none());
    // by hand: steel on steel (E 206 GPa, ν 0.3), 1000 N over 10 mm, radii 20 mm and 10 mm:
    // E* = 206/(2 × 0.91) = 113.19 GPa, 1/R = 150 /m, p = √(1000 × 113.19e9 × 150/(π × 0.01))
    // = 735.1 MPa
    let steel = effective_modulus(206e9, 0.3, 206e9, 0.3);
    assert!((steel / 1e9 - 113.187).abs() < 1e-3);
    let p = hertz_line_pressure(1000.0, 0.01, 0.02, 0.01, steel).unwrap();
    assert!((p / 1e6 - 735.14).abs() < 0.01, "{p}");
}

/// Issue 44: with damping the force at an angle is a full quadratic in the speed,
/// `c₂ω² + c₁ω + c₀`, which can fall below the margin between two positive speeds: the follower
/// leaves at the smaller. The jump speed at every angle is checked against a scan of the force
/// upward in speed (bisected where it first falls below the margin), which shares no root
/// formula; the angles with two positive roots are counted, so the case is reached.
#[test]
fn with_damping_the_jump_speed_is_the_smaller_positive_root() {
    let disc = Arc::new(camkin::curve::Circle::new(Point2::new(E, 0.0), R).unwrap());
    let mech = mechanism(
        disc,
        Point2::origin(),
        Sense::Ccw,
        1000.0,
        Follower::TranslatingFlat {
            direction: Vec2::y(),
        },
    );
    let mut two_roots = 0;
    for (c, margin) in [(40.0, 0.0), (15.0, 2.0), (60.0, 5.0)] {
        let f = Forces::new(&mech, params(M, 1.0, K, F0, c)).unwrap();
        for k in 0..180 {
            let s = f.at(k as f64 * 2f64.to_radians()).unwrap();
            let [c2, c1, c0] = f.force_coefficients(&s);
            let c0m = c0 - margin * s.lever;
            if c2 > 0.0 && c1 < 0.0 && c0m > 0.0 && c1 * c1 > 4.0 * c2 * c0m {
                two_roots += 1;
            }
            // the first speed at which the force falls below the margin, by scanning
            let below = |w: f64| f.force_at_speed(&s, w) < margin;
            let expect = if below(0.0) {
                0.0
            } else {
                let mut w = 1e-3;
                while w < 1e7 && !below(w) {
                    w *= 1.001;
                }
                if w >= 1e7 {
                    f64::INFINITY
                } else {
                    let (mut lo, mut hi) = (w / 1.001, w);
                    for _ in 0..200 {
                        let mid = 0.5 * (lo + hi);
                        if below(mid) {
                            hi = mid;
                        } else {
                            lo = mid;
                        }
                    }
                    0.5 * (lo + hi)
                }
            };
            let got = f.leave_speed(&s, margin);
            assert!(
                (got == expect) || (got - expect).abs() <= 1e-9 * expect,
                "c = {c}, at {}°: {got} against {expect}",
                2 * k
            );
        }
    }
    assert!(two_roots > 5, "{two_roots}");
}

/// The spring from the motion alone (issue 49): for the disc, the contact force with a spring
/// `(k, P)` is `P + k e (1 + cos φ) − m e ω² cos φ`; holding at least the margin `M` up to `ω_t`
/// needs `P ≥ M` (at φ = π) and `P + 2 k e ≥ M + m e ω_t²` (at φ = 0, full lift), so the least
/// force at full lift of any spring that holds is `M + m e ω_t²`, reached by a constant force of
/// that size; whatever spring the file has. With no spring in the file, the preload's sizing at
/// the file's stiffness (none) is that same constant force.
#[test]
fn the_spring_from_the_motion_is_the_closed_form() {
    use camkin::report::{ForceReport, ForceRequest};
    let w = 120.0;
    let disc = Arc::new(camkin::curve::Circle::new(Point2::new(E, 0.0), R).unwrap());
    let mech = mechanism(
        disc,
        Point2::origin(),
        Sense::Ccw,
        w * 60.0 / TAU,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    );
    let (margin, target_rpm) = (5.0, 1500.0);
    let wt = target_rpm * TAU / 60.0;
    let need = margin + M * E * wt * wt;
    for (k, f0) in [(K, F0), (0.0, 0.0), (1e5, 300.0)] {
        let req = ForceRequest {
            margin,
            target_rpm: Some(target_rpm),
            ..ForceRequest::default()
        };
        let r = ForceReport::new(&mech, params(M, 0.0, k, f0, 0.0), &req).unwrap();
        let d = r.spring.unwrap().from_motion;
        assert_close(d.force_at_full_lift, need, 1e-9, need, "force at full lift");
        assert_close(d.constant_force, need, 1e-9, need, "constant force");
        assert_close(d.full_lift, 2.0 * E, 1e-12, E, "full lift");
        // it holds: the preload and the stiffness meet both ends' needs
        assert!(d.preload >= margin - 1e-9 * need, "{d:?}");
        assert!(
            d.preload + 2.0 * d.stiffness * E >= need * (1.0 - 1e-9),
            "{d:?}"
        );
        // the range: the least preload at stiffness k is max(M, M + m e ω_t² − 2 k e) (M at
        // φ = π, where there is no lift); more stiffness saves none beyond m ω_t² / 2
        let k_max = M * wt * wt / 2.0;
        assert_close(
            d.trade_off[4][0],
            k_max,
            1e-9,
            k_max,
            "stiffness beyond which none is saved",
        );
        for [kk, p] in d.trade_off {
            let exact = margin.max(need - 2.0 * kk * E);
            assert_close(p, exact, 1e-9, need, "least preload");
        }
    }
}
