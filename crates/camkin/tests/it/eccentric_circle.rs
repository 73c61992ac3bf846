//! Eccentric circular cam (radius R, centre at distance e from the axis in the direction β of the
//! cam's frame) with a translating flat-faced follower moving along x. With φ = σθ + β (σ = +1 ccw,
//! −1 cw), cam speed ω and angular acceleration α (in the cam's direction of motion), exactly:
//!
//! s = R + e cos φ, ṡ = −σ e ω sin φ, s̈ = −e ω² cos φ − σ e α sin φ,
//! jerk = σ e ω³ sin φ − 3 e ω α cos φ, contact point = axis + (R + e cos φ, e sin φ).
//!
//! The centre is off the follower's axis (β ≠ 0), so s(θ) is not even and a cw cam computed as ccw
//! fails these checks.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Cam, Follower, Mechanism, Sense};
use camkin::curve::Circle;
use camkin::{Point2, Vec2};
use std::sync::Arc;

const R: f64 = 4.0;
const E: f64 = 1.25;
const BETA: f64 = 0.6;

fn cam(dir: Sense, pivot: Point2, rpm: f64, alpha: f64) -> Mechanism {
    let disc = Arc::new(Circle::new(Point2::new(E * BETA.cos(), E * BETA.sin()), R).unwrap());
    let cam = Cam::from_rpm(disc, pivot, dir, rpm)
        .unwrap()
        .with_angular_acceleration(alpha)
        .unwrap();
    Mechanism::new(
        cam,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    )
    .unwrap()
}

/// Position, velocity, acceleration, jerk and contact point against the closed forms.
fn check(m: &Mechanism, dir: Sense, pivot: Point2, alpha: f64) {
    let (w, sg) = (m.cam().speed(), dir.sign());
    let scale_a = E * (w * w + alpha.abs());
    for k in 0..72 {
        let th = (k as f64 * 5.0 + 0.37).to_radians();
        let phi = sg * th + BETA;
        let s = m.analyze(th).unwrap();
        let what = |q: &str| format!("{dir:?}, α = {alpha}, θ = {:.2}°: {q}", th.to_degrees());
        assert_close(s.position, R + E * phi.cos(), 1e-12, R + E, &what("s"));
        assert_close(
            s.velocity,
            -sg * E * w * phi.sin(),
            1e-12,
            E * w,
            &what("v"),
        );
        let a = -E * w * w * phi.cos() - sg * E * alpha * phi.sin();
        assert_close(s.acceleration, a, 1e-12, scale_a, &what("a"));
        let j = sg * E * w * w * w * phi.sin() - 3.0 * E * w * alpha * phi.cos();
        let jerk = s.jerk.unwrap_or_else(|| panic!("{}", what("no jerk")));
        assert_close(jerk, j, 1e-12, scale_a * w, &what("jerk"));
        assert_close(
            s.contact_world.x,
            pivot.x + R + E * phi.cos(),
            1e-12,
            R + E,
            &what("x"),
        );
        assert_close(
            s.contact_world.y,
            pivot.y + E * phi.sin(),
            1e-12,
            R + E,
            &what("y"),
        );
        assert_close(s.radius_of_curvature, R, 1e-12, R, &what("ρ"));
    }
}

#[test]
fn flat_follower_matches_closed_form_both_directions() {
    for dir in [Sense::Ccw, Sense::Cw] {
        check(
            &cam(dir, Point2::origin(), 1000.0, 0.0),
            dir,
            Point2::origin(),
            0.0,
        );
    }
}

#[test]
fn cam_axis_anywhere_gives_same_motion() {
    let pivot = Point2::new(-3.0, 12.5);
    for dir in [Sense::Ccw, Sense::Cw] {
        check(&cam(dir, pivot, 1000.0, 0.0), dir, pivot, 0.0);
    }
}

/// With a cam angular acceleration the acceleration gains `σ e α sin φ` and the jerk the
/// `3 θ̇ θ̈ q″` term, `−3 e ω α cos φ`; both directions, both signs of α.
#[test]
fn angular_acceleration_adds_its_terms_to_acceleration_and_jerk() {
    for dir in [Sense::Ccw, Sense::Cw] {
        for alpha in [2.5e4, -9.0e3] {
            let pivot = Point2::new(0.5, -0.25);
            check(&cam(dir, pivot, 300.0, alpha), dir, pivot, alpha);
        }
    }
}

#[test]
fn sliding_rate_coriolis_and_relative_terms() {
    // cam-follower.md / contact-kinematics.md: ṡ_A = −σωR, Coriolis −2ω²R, relative +ω²R
    for dir in [Sense::Ccw, Sense::Cw] {
        let m = cam(dir, Point2::origin(), 600.0, 0.0);
        let w = m.cam().speed();
        for k in 0..12 {
            let s = m.analyze((k as f64 * 30.0 + 7.0).to_radians()).unwrap();
            assert_close(s.sliding_rate_cam, -dir.sign() * w * R, 1e-12, w * R, "ṡ_A");
            assert_close(
                s.normal_acceleration_cam.coriolis,
                -2.0 * w * w * R,
                1e-12,
                w * w * R,
                "Coriolis",
            );
            assert_close(
                s.normal_acceleration_cam.relative,
                w * w * R,
                1e-12,
                w * w * R,
                "relative",
            );
            // along the face (which translates without turning) the contact point moves at
            // d(e sin φ)/dt = σ e ω cos φ in y; the face's parameter runs along −y
            let phi = dir.sign() * (k as f64 * 30.0 + 7.0).to_radians() + BETA;
            assert_close(
                s.sliding_rate_follower,
                -dir.sign() * E * w * phi.cos(),
                1e-12,
                E * w,
                "ṡ_B",
            );
            // a convex disc under a face with material on the other side: tangents opposed
            assert_eq!(s.sigma, -1.0);
        }
    }
}
