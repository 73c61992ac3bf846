//! Issue 44: every extreme a report gives is where it is, not at the sampling grid. The design
//! checks at 1° steps against closed forms whose extremes lie between the samples: an ellipse's
//! smallest radius of curvature `b²/a` under a flat face, the peak pressure angle of an offset
//! roller on an eccentric disc `asin((|ε| + e)/(R + r))` with its sign, and the face width a flat
//! face needs on an eccentric disc (`2e`).

use crate::common::*;
use camkin::cam::{Follower, Sense};
use camkin::{Point2, Vec2};

fn degrees(step: f64) -> Vec<f64> {
    let n = (360.0 / step).round() as usize;
    (0..n).map(|k| (k as f64 * step).to_radians()).collect()
}

#[test]
fn the_smallest_radius_of_curvature_is_the_ellipses_between_samples() {
    let (a, b, rot) = (40.0, 25.0, 0.37f64);
    for sense in [Sense::Ccw, Sense::Cw] {
        let m = mechanism(
            ellipse(a, b, Point2::origin(), rot.to_radians()),
            Point2::origin(),
            sense,
            100.0,
            Follower::TranslatingFlat {
                direction: Vec2::y(),
            },
        );
        let c = m.design_checks(&degrees(1.0), 30.0);
        let (rho, at) = c.convex_min.unwrap();
        assert!(
            (rho - b * b / a).abs() < 1e-9 * a,
            "{sense:?}: {rho} against {}",
            b * b / a
        );
        // the major axis's end turned to face the follower: 90° − 0.37° ccw (or + for cw), and
        // half a turn later
        let expect = [90.0 - sense.sign() * rot, 270.0 - sense.sign() * rot];
        assert!(
            expect.iter().any(|e| (at - e).abs() < 1e-5),
            "{sense:?}: at {at}°, expected one of {expect:?}"
        );
        // the grid alone would miss it by more than the tolerance
        let grid_best = m
            .analyze_all(&degrees(1.0))
            .into_iter()
            .flatten()
            .map(|s| s.radius_of_curvature)
            .fold(f64::INFINITY, f64::min);
        assert!(grid_best - b * b / a > 1e-6, "{grid_best}");
    }
}

#[test]
fn the_pressure_angles_peak_and_the_face_width_are_the_closed_forms() {
    let (e, big_r, r) = (6.0, 25.0, 5.0);
    let beta = 0.37f64.to_radians();
    let disc = || eccentric_circle_at(big_r, e, beta);
    for offset in [-4.0, 3.0] {
        let m = mechanism(
            disc(),
            Point2::origin(),
            Sense::Ccw,
            100.0,
            Follower::TranslatingRoller {
                direction: Vec2::y(),
                offset,
                roller_radius: r,
            },
        );
        let c = m.design_checks(&degrees(1.0), 30.0);
        let (peak, at) = c.pressure_peak;
        let expect = ((offset.abs() + e) / (big_r + r)).asin().to_degrees();
        assert!(
            (peak.abs() - expect).abs() < 1e-8,
            "offset {offset}: {peak} against {expect}"
        );
        // its sign: the force line from the disc's centre to the roller's, from the travel
        let s = m.analyze(at.to_radians()).unwrap();
        let centre = Point2::new(offset, s.position);
        let disc_centre = Point2::new(
            e * (at.to_radians() + beta).cos(),
            e * (at.to_radians() + beta).sin(),
        );
        let n = centre - disc_centre;
        assert_eq!(
            peak.signum(),
            (-n.x).signum(),
            "offset {offset}: {peak} at {at}"
        );
    }
    let flat = mechanism(
        disc(),
        Point2::origin(),
        Sense::Ccw,
        100.0,
        Follower::TranslatingFlat {
            direction: Vec2::y(),
        },
    );
    let (lo, hi) = flat.design_checks(&degrees(1.0), 30.0).face_range.unwrap();
    assert!((hi - lo - 2.0 * e).abs() < 1e-9, "{lo} {hi}");
}

/// The force report's extremes on an eccentric disc (metres) under a flat face: the contact
/// force `F = F₀ + k e + e (k − m ω²) sin φ`, `φ = θ + β` with `β` = 0.37° off the grid, so
/// its least and greatest, the jump speed `√((F₀ + 2 k e)/(m e))`, the preload the target speed
/// needs, `e m ω_t² − 2 k e`, and the Hertz stress of the largest force on a cylinder of radius
/// `R` against a flat, `√(F E*/(π w R))`, all between the 1° samples.
#[test]
fn the_force_reports_extremes_are_the_closed_forms() {
    use camkin::dynamics::FollowerDynamics;
    use camkin::report::{ForceReport, ForceRequest};
    let (big_r, e, beta) = (0.03, 0.006, 0.37f64.to_radians());
    let (m, k, f0, rpm) = (0.5, 2000.0, 20.0, 1000.0);
    let mech = mechanism(
        eccentric_circle_at(big_r, e, beta),
        Point2::origin(),
        Sense::Ccw,
        rpm,
        Follower::TranslatingFlat {
            direction: Vec2::y(),
        },
    );
    let params = FollowerDynamics {
        mass: m,
        inertia: 1.0,
        spring_stiffness: k,
        spring_preload: f0,
        damping: 0.0,
        restitution: 0.0,
        gravity: Vec2::zeros(),
    };
    let req = ForceRequest {
        step_deg: 1.0,
        target_rpm: Some(1380.0),
        face_width: Some(0.01),
        force_speed: false,
        lubrication: None,
        ..ForceRequest::default()
    };
    let r = ForceReport::new(&mech, params, &req).unwrap();
    let w = rpm * std::f64::consts::TAU / 60.0;
    let (lo, hi) = r.contact_force;
    let expect_lo = f0 + 2.0 * k * e - m * e * w * w;
    let expect_hi = f0 + m * e * w * w;
    assert!(
        (lo.value - expect_lo).abs() < 1e-9 * expect_hi,
        "{} against {expect_lo}",
        lo.value
    );
    assert!(
        (hi.value - expect_hi).abs() < 1e-9 * expect_hi,
        "{} against {expect_hi}",
        hi.value
    );
    assert!(
        (lo.cam_angle.to_degrees() - (90.0 - 0.37)).abs() < 1e-4,
        "{}",
        lo.cam_angle.to_degrees()
    );
    assert!(
        (hi.cam_angle.to_degrees() - (270.0 - 0.37)).abs() < 1e-4,
        "{}",
        hi.cam_angle.to_degrees()
    );
    let jump = ((f0 + 2.0 * k * e) / (m * e)).sqrt();
    assert!(
        (r.jump.speed - jump).abs() < 1e-9 * jump,
        "{} against {jump}",
        r.jump.speed
    );
    let wt = 1380.0 * std::f64::consts::TAU / 60.0;
    let preload = e * m * wt * wt - 2.0 * k * e;
    let spring = r.spring.unwrap();
    assert!(
        (spring.preload - preload).abs() < 1e-9 * preload,
        "{} against {preload}",
        spring.preload
    );
    let h = r.hertz.unwrap();
    let es = h.effective_modulus;
    let p = (expect_hi * es / (std::f64::consts::PI * 0.01 * big_r)).sqrt() / 1e6;
    assert!(
        (h.worst_mpa - p).abs() < 1e-9 * p,
        "{} against {p}",
        h.worst_mpa
    );
}

/// Issue 44: the radius of curvature at the contact carries its sign: negative on a concave
/// stretch. A knife on the polar curve `r = 30 + 6 cos 3φ` (a spline through 1440 of its
/// points) touches where the curve is concave (φ = 60°, `κ = (r² + 2r'² − r r'')/(r² + r'²)^{3/2}`
/// < 0) and convex (φ = 0°): the library's radius against the closed form, with its sign.
#[test]
fn the_radius_of_curvature_is_negative_where_the_profile_is_concave() {
    use camkin::curve::ClosedSpline;
    use std::sync::Arc;
    let r = |p: f64| 30.0 + 6.0 * (3.0 * p).cos();
    let nodes: Vec<Point2> = (0..1440)
        .map(|k| {
            let p = k as f64 * std::f64::consts::TAU / 1440.0;
            Point2::new(r(p) * p.cos(), r(p) * p.sin())
        })
        .collect();
    let profile = Arc::new(ClosedSpline::new(&nodes).unwrap());
    for deg in [60.0f64, 0.0, 180.0] {
        let p = deg.to_radians();
        let (r0, r1, r2) = (r(p), -18.0 * (3.0 * p).sin(), -54.0 * (3.0 * p).cos());
        let kappa = (r0 * r0 + 2.0 * r1 * r1 - r0 * r2) / (r0 * r0 + r1 * r1).powf(1.5);
        let m = mechanism(
            profile.clone(),
            Point2::origin(),
            Sense::Ccw,
            100.0,
            Follower::TranslatingKnife {
                direction: Vec2::new(p.cos(), p.sin()),
                offset: 0.0,
            },
        );
        let s = m.analyze(0.0).unwrap();
        let rho = s.radius_of_curvature;
        assert_eq!(
            rho.signum(),
            kappa.signum(),
            "at {deg}°: {rho} against 1/{kappa}"
        );
        assert!(
            (rho - 1.0 / kappa).abs() < 1e-4 * (1.0 / kappa).abs(),
            "at {deg}°: {rho} against {}",
            1.0 / kappa
        );
    }
}
