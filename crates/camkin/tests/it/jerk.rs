//! Jerk, and the implicit-differentiation derivatives it comes from.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Mechanism, Sense};
use camkin::{Point2, Vec2};

/// The contact method (eqs. 5, 6, 11) against a second derivation: implicit differentiation of the
/// first-touch conditions. Not independent (both use the global search, the profile's derivatives
/// and the residual of the Newton solve); it checks the method's formulas, not the contact.
#[test]
fn implicit_differentiation_agrees_with_contact_method_for_every_follower() {
    for (revised, dir, pivot) in [
        (false, Sense::Ccw, Point2::origin()),
        (true, Sense::Cw, Point2::new(-1.0, 2.0)),
    ] {
        for f in all_followers(pivot) {
            let m = mechanism(paper_profile(revised), pivot, dir, 1000.0, f.clone());
            let w = m.cam().speed();
            for k in 0..72 {
                let th = (k as f64 * 5.0 + 0.3).to_radians();
                let s = m.analyze(th).unwrap();
                let d = m.angle_derivatives(th).unwrap();
                let name = f.kind_name();
                assert_close(
                    s.velocity,
                    w * d[0],
                    1e-11,
                    w * m.size(),
                    &format!("{name} v at {k}"),
                );
                assert_close(
                    s.acceleration,
                    w * w * d[1],
                    1e-10,
                    w * w * m.size(),
                    &format!("{name} a at {k}"),
                );
            }
        }
    }
}

#[test]
fn eccentric_circle_flat_follower_jerk_is_closed_form() {
    for dir in [Sense::Ccw, Sense::Cw] {
        let m = mechanism(
            eccentric_circle(4.0, 1.25),
            Point2::new(0.5, 0.5),
            dir,
            1000.0,
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
        );
        let w = m.cam().speed();
        for k in 0..36 {
            let th = (k as f64 * 10.0 + 1.0).to_radians();
            let j = m.analyze(th).unwrap().jerk.unwrap();
            assert_close(
                j,
                1.25 * w * w * w * th.sin(),
                1e-12,
                1.25 * w * w * w,
                "jerk",
            );
        }
    }
}

/// `spline`: skip stencils that cross a node (integer parameter) of the spline profile.
fn check_jerk_by_differences(m: &Mechanism, name: &str, spline: bool) -> usize {
    let w = m.cam().speed();
    let h = 2e-3;
    let mut n = 0;
    for k in 0..60 {
        let th = (k as f64 * 6.0 + 0.9).to_radians();
        let s = m.analyze(th).unwrap();
        let (lo, hi) = (
            m.analyze(th - 4.0 * h).unwrap(),
            m.analyze(th + 4.0 * h).unwrap(),
        );
        if spline
            && (lo.cam_param.floor() != s.cam_param.floor()
                || hi.cam_param.floor() != s.cam_param.floor())
        {
            continue;
        }
        let (da, _) = fd8(|t| m.analyze(t).unwrap().acceleration, th, h);
        let j = s
            .jerk
            .unwrap_or_else(|| panic!("{name}: no jerk away from nodes"));
        assert_close(
            j,
            w * da,
            1e-7,
            w * w * w * m.size(),
            &format!("{name} jerk at {k}"),
        );
        n += 1;
    }
    n
}

/// [`check_jerk_by_differences`] on an ellipse cam (no nodes: every one of its 60 angles).
fn check_jerk_on_the_ellipse_cam(f: &Follower, name: &str) {
    let m = mechanism(
        ellipse(5.0, 3.5, Point2::new(0.4, 0.2), 0.3),
        Point2::origin(),
        Sense::Cw,
        700.0,
        f.clone(),
    );
    assert_eq!(check_jerk_by_differences(&m, name, false), 60, "{name}");
}

#[test]
fn jerk_agrees_with_differences_of_acceleration_for_every_follower() {
    for f in all_followers(Point2::origin()) {
        let m = mechanism(
            paper_profile(false),
            Point2::origin(),
            Sense::Ccw,
            1000.0,
            f.clone(),
        );
        assert!(check_jerk_by_differences(&m, f.kind_name(), true) >= 30);
        check_jerk_on_the_ellipse_cam(&f, f.kind_name());
    }
}

/// A follower carrying a curve: its jerk (jets of the three tangency conditions in the cam's
/// and the carried curve's parameters and the position) against 8th-order differences of the
/// acceleration, which the paper's method computes (no jets): an ellipse on an arm and on a
/// slide, a crowned (circular) face on a slide, on an ellipse cam and on the paper's spline cam.
#[test]
fn carried_curve_jerk_agrees_with_differences_of_acceleration() {
    use camkin::cam::FollowerProfile;
    use camkin::curve::{Circle, Ellipse};
    use std::sync::Arc;
    let egg = || Ellipse::new(Point2::new(0.0, 0.0), 1.5, 0.8, 0.3).unwrap();
    let followers = [
        Follower::Rotating {
            pivot: Point2::new(2.0, 9.0),
            closing: Sense::Cw,
            initial_angle: -1.3,
            profile: FollowerProfile(Arc::new(
                Ellipse::new(Point2::new(6.0, 0.0), 1.5, 0.8, 0.3).unwrap(),
            )),
        },
        Follower::Translating {
            direction: Vec2::new(0.0, 1.0),
            offset: 0.5,
            profile: FollowerProfile(Arc::new(egg())),
        },
        Follower::Translating {
            direction: Vec2::new(0.6, 0.8),
            offset: -0.3,
            profile: FollowerProfile(Arc::new(Circle::new(Point2::new(9.0, 0.0), 9.0).unwrap())),
        },
    ];
    for f in followers {
        let name = format!("{f:?}");
        check_jerk_on_the_ellipse_cam(&f, &name);
        let m = mechanism(
            paper_profile(false),
            Point2::origin(),
            Sense::Ccw,
            1000.0,
            f,
        );
        assert!(check_jerk_by_differences(&m, &name, true) >= 30, "{name}");
    }
}

#[test]
fn jerk_is_absent_exactly_at_a_spline_node() {
    // θ = 0 on the paper cam: the contact is node 0, where the curvature has a corner
    let s = paper_mechanism(false).analyze(0.0).unwrap();
    assert!(s.at_breakpoint);
    assert_eq!(s.jerk, None);
}

/// With a cam angular acceleration θ̈: q̈ = θ̇² q'' + θ̈ q' (the contact method against the
/// implicit-differentiation derivatives, which share the search and the residual with it), for
/// every follower type and both directions.
#[test]
fn angular_acceleration_for_every_follower() {
    for dir in [Sense::Ccw, Sense::Cw] {
        for f in all_followers(Point2::origin()) {
            let cam =
                camkin::cam::Cam::from_rpm(paper_profile(false), Point2::origin(), dir, 400.0)
                    .unwrap()
                    .with_angular_acceleration(-900.0)
                    .unwrap();
            let m = Mechanism::new(cam, f.clone()).unwrap();
            let (w, al): (f64, f64) = (m.cam().speed(), -900.0);
            for k in 0..36 {
                let th = (k as f64 * 10.0 + 0.4).to_radians();
                let s = m.analyze(th).unwrap();
                let d = m.angle_derivatives(th).unwrap();
                let scale = (w * w + al.abs()) * m.size();
                assert_close(
                    s.acceleration,
                    w * w * d[1] + al * d[0],
                    1e-11,
                    scale,
                    f.kind_name(),
                );
            }
        }
    }
}

/// Velocity, acceleration and jerk with a cam angular acceleration against time differences along
/// the trajectory θ(t) = θ₀ + ω₀t + αt²/2, ω(t) = ω₀ + αt: each instant is a separate analysis (a cam
/// with that instant's speed), so the `3 θ̇ θ̈ q″` term of the jerk and the `θ̈ q′` term of the
/// acceleration are checked against the method's own lower derivatives, differenced in time, for
/// every follower type and both directions (a smooth ellipse cam: no nodes in the stencils).
#[test]
fn angular_acceleration_terms_agree_with_time_differences_for_every_follower() {
    let profile = ellipse(5.0, 3.5, Point2::new(0.4, 0.2), 0.3);
    for dir in [Sense::Ccw, Sense::Cw] {
        for f in all_followers(Point2::origin()) {
            let (w0, al) = (40.0_f64, 3.0e3_f64);
            let at = |t: f64| {
                let cam =
                    camkin::cam::Cam::new(profile.clone(), Point2::origin(), dir, w0 + al * t)
                        .unwrap()
                        .with_angular_acceleration(al)
                        .unwrap();
                let m = Mechanism::new(cam, f.clone()).unwrap();
                let th = 0.7 + w0 * t + 0.5 * al * t * t;
                m.analyze(th).unwrap()
            };
            let size = 5.0;
            for k in 0..12 {
                let t0 = k as f64 * 0.55 / w0;
                let s = at(t0);
                let w = w0 + al * t0;
                let h = 0.3f64.to_radians() / w;
                let (v, _) = fd8(|t| at(t).position, t0, h);
                let (a, _) = fd8(|t| at(t).velocity, t0, h);
                let (j, _) = fd8(|t| at(t).acceleration, t0, h);
                let name = format!("{} {dir:?} at t = {t0:.4} s", f.kind_name());
                assert_close(s.velocity, v, 1e-8, w * size, &format!("{name}: v"));
                let sa = (w * w + al) * size;
                assert_close(s.acceleration, a, 1e-8, sa, &format!("{name}: a"));
                let jerk = s.jerk.expect("jerk on a smooth cam");
                assert_close(jerk, j, 1e-7, sa * w, &format!("{name}: jerk"));
            }
        }
    }
}
