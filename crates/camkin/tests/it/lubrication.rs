//! The surfaces' speeds at the contact, which lubrication is computed from, against the
//! material velocities of the two bodies and the contact point's own velocity by finite
//! differences of positions (sharing no formula with the paper's sliding rates), for every
//! follower kind on an ellipse and on the paper's cam, both cam senses.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, FollowerCurve, Mechanism, Sense};
use camkin::curve::Circle;
use camkin::dynamics::{surface_speeds, FollowerDynamics};
use camkin::geometry::rot90;
use camkin::lubrication::{FilmFormula, Friction, Lubricant, SurfaceProperties, Thermal};
use camkin::report::{ForceReport, ForceRequest, LubricationRequest, Materials};
use camkin::{Point2, Vec2};
use std::f64::consts::TAU;
use std::sync::Arc;

/// `(u_cam, u_follower)` from positions alone: the contact point's velocity by finite
/// differences of its position in time, the cam's material velocity `ω × (P − C)`, the
/// follower's from the finite difference of its coordinate (a slide: along its direction; an
/// arm: about its pivot).
fn by_positions(m: &Mechanism, follower: &Follower, theta: f64) -> [f64; 2] {
    let cam = m.cam();
    let w = cam.speed();
    let omega = cam.direction().sign() * w;
    let s = m.analyze(theta).unwrap();
    let h = 1e-4;
    let at = |x: f64| m.analyze(x).unwrap();
    let (px, _) = fd8(|x| at(x).contact_world.x, theta, h);
    let (py, _) = fd8(|x| at(x).contact_world.y, theta, h);
    let (dq, _) = fd8(|x| at(x).position, theta, h);
    // d/dt = ω d/dθ at constant speed
    let v_p = Vec2::new(px, py) * w;
    let qdot = dq * w;
    let p = s.contact_world;
    let v_cam = omega * rot90(p - cam.pivot());
    let v_follower = match follower {
        Follower::TranslatingFlat { direction }
        | Follower::TranslatingRoller { direction, .. }
        | Follower::TranslatingKnife { direction, .. } => qdot * direction.normalize(),
        Follower::OscillatingFlat { pivot, .. } | Follower::OscillatingRoller { pivot, .. } => {
            qdot * rot90(p - pivot)
        }
        _ => unreachable!(),
    };
    let t = Vec2::new(s.normal.y, -s.normal.x);
    [(v_cam - v_p).dot(&t), (v_follower - v_p).dot(&t)]
}

#[test]
fn surface_speeds_agree_with_the_bodies_velocities_from_positions() {
    let cams = [
        ellipse(4.0, 3.0, Point2::new(0.3, -0.2), 0.4),
        paper_profile(false),
    ];
    let size = 5.0;
    for profile in cams {
        for sense in [Sense::Ccw, Sense::Cw] {
            for f in all_followers(Point2::origin()) {
                let m = mechanism(profile.clone(), Point2::origin(), sense, 600.0, f.clone());
                let roller = matches!(m.follower_curve(), FollowerCurve::Circle(_));
                let w = m.cam().speed();
                for k in 0..24 {
                    let theta = (f64::from(k) + 0.3) * TAU / 24.0;
                    let s = m.analyze(theta).unwrap();
                    let u = surface_speeds(&m, &s);
                    let r = by_positions(&m, &f, theta);
                    let tol = 1e-8 * size * w;
                    assert_close(u[0], r[0], 1e-8, size * w, "the cam's surface speed");
                    if roller {
                        // rolling without slip: the roller's surface moves with the cam's
                        assert_eq!(u[1], u[0]);
                    } else {
                        assert_close(u[1], r[1], 1e-8, size * w, "the follower's surface speed");
                        // the paper's eq. 6: the follower's sliding rate, up to its tangent's sense
                        assert!(
                            (u[1].abs() - s.sliding_rate_follower.abs()).abs() <= tol,
                            "{f:?} at {theta}: {u:?} vs ṡ_B {}",
                            s.sliding_rate_follower
                        );
                    }
                }
            }
        }
    }
}

fn oil_request(friction: Friction) -> LubricationRequest {
    let steel = SurfaceProperties {
        roughness: 0.2e-6,
        thermal: Some(Thermal {
            conductivity: 46.0,
            density: 7800.0,
            specific_heat: 470.0,
        }),
    };
    LubricationRequest {
        lubricant: Lubricant {
            viscosity: 0.012,
            pressure_viscosity: 1.8e-8,
        },
        formula: FilmFormula::DowsonHigginson,
        surfaces: [
            steel,
            SurfaceProperties {
                roughness: 0.3e-6,
                ..steel
            },
        ],
        friction,
    }
}

fn spring(m: f64, k: f64, f0: f64) -> FollowerDynamics {
    FollowerDynamics {
        mass: m,
        inertia: 0.0,
        spring_stiffness: k,
        spring_preload: f0,
        damping: 0.0,
        restitution: 0.0,
        gravity: Vec2::zeros(),
    }
}

/// The eccentric disc (radius R, eccentricity e) under a flat face, in closed form: the contact
/// is the disc's point farthest along the face's normal, so the cam's surface moves past it at
/// `σ ω R` and the face's at `−σ ω e cos φ` (the contact's slide along the face); the reduced
/// radius is `R`, the load `F = −m e ω² cos φ + F₀ + k e (1 + cos φ)` over the face width. The
/// film by Dowson and Higginson's formula in its dimensional form, λ, the friction power and
/// Blok's temperature, each written out here, against the report at every angle (1e-12).
#[test]
fn the_eccentric_disc_under_a_flat_face_has_the_closed_form_film() {
    let (r, e, m, k, f0) = (0.02, 0.005, 0.2, 4000.0, 30.0);
    let width = 0.01;
    for sense in [Sense::Ccw, Sense::Cw] {
        let disc = Arc::new(Circle::new(Point2::new(e, 0.0), r).unwrap());
        let mech = mechanism(
            disc,
            Point2::origin(),
            sense,
            1000.0,
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
        );
        let w = mech.cam().speed();
        let req = ForceRequest {
            step_deg: 5.0,
            face_width: Some(width),
            lubrication: Some(oil_request(Friction::Constant(0.05))),
            force_speed: false,
            ..ForceRequest::default()
        };
        let report = ForceReport::new(&mech, spring(m, k, f0), &req).unwrap();
        let lub = report.lubrication.as_ref().unwrap();
        let e_prime = 2.0 * Materials::default().effective_modulus();
        let o = req.lubrication.unwrap();
        let sigma = (0.2e-6f64.powi(2) + 0.3e-6f64.powi(2)).sqrt();
        let beta = (46.0f64 * 7800.0 * 470.0).sqrt();
        assert!(lub.entrainment_reversals.is_empty());
        for (s, p) in report.states.iter().zip(&lub.points) {
            let phi = sense.sign() * s.cam_angle;
            // along the cam profile's tangent, which the sense of rotation does not turn
            let (u1, u2) = (sense.sign() * w * r, -sense.sign() * w * e * phi.cos());
            let force = -m * e * w * w * phi.cos() + f0 + k * e * (1.0 + phi.cos());
            let p = p[0].as_ref().unwrap();
            let ue = 0.5 * (u1 + u2);
            assert_close(p.entrainment, ue, 1e-12, w * r, "entrainment");
            assert_close(p.sliding, u1 - u2, 1e-12, w * r, "sliding");
            assert_close(p.reduced_radius.unwrap(), r, 1e-12, r, "reduced radius");
            let load = force / width;
            let h_min = 2.65
                * o.lubricant.pressure_viscosity.powf(0.54)
                * (o.lubricant.viscosity * ue.abs()).powf(0.70)
                * r.powf(0.43)
                / (e_prime.powf(0.03) * load.powf(0.13));
            let film = p.film.unwrap();
            assert_close(film.minimum, h_min, 1e-12, h_min, "minimum film");
            assert_close(p.lambda.unwrap(), h_min / sigma, 1e-12, h_min / sigma, "λ");
            assert_close(
                p.friction_power,
                0.05 * force * (u1 - u2).abs(),
                1e-12,
                force * w * r,
                "friction power",
            );
            let a = (8.0 * load * r / (std::f64::consts::PI * e_prime)).sqrt();
            let blok = 1.11 * 0.05 * load * (u1 - u2).abs()
                / (beta * (u1.abs().sqrt() + u2.abs().sqrt()) * (2.0 * a).sqrt());
            // √|u| is ill-conditioned at 0: a speed within δ = 1e-12 ω R moves √|u| by up to √δ
            let carry = u1.abs().sqrt() + u2.abs().sqrt();
            let tol = 1e-12 + (1e-12 * w * r).sqrt() / carry;
            assert_close(
                p.flash_temperature.unwrap(),
                blok,
                tol,
                blok,
                "flash temperature",
            );
        }
        // the friction power's mean by the closed form's own mean: μ ω (R F̄ + e ⟨F cos φ⟩)
        let n = report.states.len() as f64;
        let mean: f64 = report
            .states
            .iter()
            .map(|s| {
                let c = (sense.sign() * s.cam_angle).cos();
                let force = -m * e * w * w * c + f0 + k * e * (1.0 + c);
                0.05 * force * w * (r + e * c).abs()
            })
            .sum::<f64>()
            / n;
        assert_close(
            lub.mean_friction_power,
            mean,
            1e-12,
            mean,
            "mean friction power",
        );
        assert_close(
            lub.mean_friction_torque * w,
            mean,
            1e-12,
            mean,
            "friction torque",
        );
    }
}

/// An ellipse (semi-axes A > √2 B) turning about its centre under a flat face: with `p(φ)` its
/// support function, the cam's surface moves past the contact at `ω (p + p'')` and the face's
/// at `ω p''`, so the entrainment changes sign where `p + 2p'' = 0` — four angles a turn. Those
/// angles, found by bisection on `p` and `p''` evaluated with hyper-dual numbers (no formula of
/// the library), against the report's (to 1e-9°), both senses. Over the same revolution, a
/// second check of the mixed friction model (its unit test the first): each point's
/// coefficient from its own λ by the documented rule written out, and its friction power
/// `μ F |u₁ − u₂|` (a quadratic blend put in the model's place fails it).
#[test]
fn the_entrainment_reverses_where_the_support_function_says() {
    let (a, b) = (0.05, 0.02);
    let support = |phi: HD| {
        let (c, s) = (phi.cos(), phi.sin());
        (c * c * HD::c(a * a) + s * s * HD::c(b * b)).sqrt()
    };
    let g = |phi: f64| {
        let p = support(HD::var(phi));
        p.v + 2.0 * p.d2
    };
    // the reference: every sign change of p + 2p'' on a fine grid, bisected
    let mut reference = Vec::new();
    let n = 3600;
    for k in 0..n {
        let (mut lo, mut hi) = (TAU * k as f64 / n as f64, TAU * (k + 1) as f64 / n as f64);
        if g(lo) * g(hi) < 0.0 {
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if g(mid) * g(lo) > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            reference.push(0.5 * (lo + hi));
        }
    }
    assert_eq!(reference.len(), 4);
    for sense in [Sense::Ccw, Sense::Cw] {
        let mech = mechanism(
            ellipse(a, b, Point2::origin(), 0.0),
            Point2::origin(),
            sense,
            1500.0,
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
        );
        let req = ForceRequest {
            step_deg: 1.0,
            face_width: Some(0.01),
            lubrication: Some(oil_request(Friction::Mixed {
                boundary: 0.1,
                full_film: 0.03,
            })),
            force_speed: false,
            ..ForceRequest::default()
        };
        let report = ForceReport::new(&mech, spring(0.1, 5000.0, 50.0), &req).unwrap();
        let lub = report.lubrication.as_ref().unwrap();
        // a second check of the mixed friction model, from the report's own λ: the coefficient
        // is the boundary's 0.1 to λ = 1, the full film's 0.03 from λ = 3, linear between, and
        // the friction power is μ F |u₁ − u₂| (written out here, not the library's function)
        let mut mixed = 0;
        for p in lub.points.iter().filter_map(|p| p[0]) {
            let mu = match p.lambda {
                Some(l) if l >= 3.0 => 0.03,
                Some(l) if l > 1.0 => {
                    mixed += 1;
                    0.1 + (l - 1.0) / 2.0 * (0.03 - 0.1)
                }
                _ => 0.1,
            };
            assert!((p.friction_coefficient - mu).abs() < 1e-15, "{p:?}");
            let power = mu * p.load_per_width.max(0.0) * 0.01 * p.sliding.abs();
            assert!(
                (p.friction_power - power).abs() <= 1e-12 * power.max(1e-12),
                "{p:?}"
            );
        }
        assert!(mixed > 10, "{mixed} points in the mixed regime");
        let found = &lub.entrainment_reversals;
        // the face's normal in the cam's frame is at φ = −σθ
        let mut expected: Vec<f64> = reference
            .iter()
            .map(|&phi| (-sense.sign() * phi).rem_euclid(TAU))
            .collect();
        expected.sort_by(f64::total_cmp);
        assert_eq!(found.len(), 4, "{found:?}");
        for (f, x) in found.iter().zip(&expected) {
            assert!(
                (f - x).abs() < 1e-9f64.to_radians(),
                "{sense:?}: {f} vs {x} rad ({:e}°)",
                (f - x).abs().to_degrees()
            );
        }
    }
}
