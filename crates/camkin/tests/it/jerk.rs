//! Jerk, and the implicit-differentiation derivatives it comes from.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Mechanism, Sense};
use camkin::{Point2, Vec2};

/// Two independent methods: implicit differentiation of the first-touch conditions and the
/// paper's contact method (eqs. 5, 6, 11) give the same velocity and acceleration.
#[test]
fn implicit_differentiation_agrees_with_contact_method_for_every_follower() {
    for (revised, dir, pivot) in [
        (false, Sense::Ccw, Point2::origin()),
        (true, Sense::Cw, Point2::new(-1.0, 2.0)),
    ] {
        for f in all_followers(pivot) {
            let m = mechanism(paper_profile(revised), pivot, dir, 1000.0, f);
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

#[test]
fn jerk_agrees_with_differences_of_acceleration_for_every_follower() {
    for f in all_followers(Point2::origin()) {
        let m = mechanism(
            paper_profile(false),
            Point2::origin(),
            Sense::Ccw,
            1000.0,
            f,
        );
        assert!(check_jerk_by_differences(&m, f.kind_name(), true) >= 30);
        let m = mechanism(
            ellipse(5.0, 3.5, Point2::new(0.4, 0.2), 0.3),
            Point2::origin(),
            Sense::Cw,
            700.0,
            f,
        );
        assert_eq!(check_jerk_by_differences(&m, f.kind_name(), false), 60);
    }
}

#[test]
fn jerk_is_absent_exactly_at_a_spline_node() {
    // θ = 0 on the paper cam: the contact is node 0, where the curvature has a corner
    let s = paper_mechanism(false).analyze(0.0).unwrap();
    assert!(s.at_breakpoint);
    assert_eq!(s.jerk, None);
}

/// With a cam angular acceleration θ̈: q̈ = θ̇² q'' + θ̈ q' (contact method against implicit
/// differentiation), for every follower type and both directions.
#[test]
fn angular_acceleration_for_every_follower() {
    for dir in [Sense::Ccw, Sense::Cw] {
        for f in all_followers(Point2::origin()) {
            let cam =
                camkin::cam::Cam::from_rpm(paper_profile(false), Point2::origin(), dir, 400.0)
                    .unwrap()
                    .with_angular_acceleration(-900.0)
                    .unwrap();
            let m = Mechanism::new(cam, f).unwrap();
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
                if let Some(j) = s.jerk {
                    assert_close(
                        j,
                        w * w * w * d[2] + 3.0 * w * al * d[1],
                        1e-12,
                        scale * w,
                        "jerk",
                    );
                }
            }
        }
    }
}
