//! Eccentric circular cam (radius R, eccentricity e) with a translating flat-faced follower:
//! s = e cos θ + R, ṡ = −e ω sin θ, s̈ = −e ω² cos θ exactly, for both cam directions.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Sense};
use camkin::{Point2, Vec2};

const R: f64 = 4.0;
const E: f64 = 1.25;

#[test]
fn flat_follower_matches_closed_form_both_directions() {
    for dir in [Sense::Ccw, Sense::Cw] {
        let m = mechanism(
            eccentric_circle(R, E),
            Point2::origin(),
            dir,
            1000.0,
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
        );
        let w = m.cam().speed();
        for k in 0..72 {
            let th = (k as f64 * 5.0 + 0.37).to_radians();
            let s = m.analyze(th).unwrap();
            assert_close(s.position, E * th.cos() + R, 1e-12, R + E, "s");
            assert_close(s.velocity, -E * w * th.sin(), 1e-12, E * w, "v");
            assert_close(s.acceleration, -E * w * w * th.cos(), 1e-12, E * w * w, "a");
            assert_close(s.radius_of_curvature, R, 1e-12, R, "rho");
            // the identity s̈ = ω²(ρ − s)
            assert_close(
                s.acceleration,
                w * w * (s.radius_of_curvature - s.position),
                1e-12,
                E * w * w,
                "identity",
            );
        }
    }
}

#[test]
fn sliding_rate_coriolis_and_relative_terms() {
    // cam-follower.md / contact-kinematics.md: ṡ_A = −ωR, Coriolis −2ω²R, relative +ω²R (ccw cam).
    let m = mechanism(
        eccentric_circle(R, E),
        Point2::origin(),
        Sense::Ccw,
        600.0,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    );
    let w = m.cam().speed();
    for k in 0..12 {
        let s = m.analyze((k as f64 * 30.0 + 7.0).to_radians()).unwrap();
        assert_close(s.sliding_rate_cam, -w * R, 1e-12, w * R, "ṡ_A");
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
        // eq. 11: both sides agree
        assert_close(
            s.normal_acceleration_cam.total(),
            s.normal_acceleration_follower.total(),
            1e-12,
            w * w * R,
            "eq. 11",
        );
        // a flat face does not turn: its contact point slides at the speed of the contact point
        assert_eq!(s.sigma.abs(), 1.0);
    }
}

#[test]
fn cam_axis_anywhere_gives_same_motion() {
    let pivot = Point2::new(-3.0, 12.5);
    let m = mechanism(
        eccentric_circle(R, E),
        pivot,
        Sense::Ccw,
        1000.0,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    );
    let w = m.cam().speed();
    for k in 0..24 {
        let th = (k as f64 * 15.0 + 1.0).to_radians();
        let s = m.analyze(th).unwrap();
        assert_close(s.position, E * th.cos() + R, 1e-12, R + E, "s");
        assert_close(s.acceleration, -E * w * w * th.cos(), 1e-12, E * w * w, "a");
        assert_close(
            s.contact_world.x,
            pivot.x + s.position,
            1e-12,
            20.0,
            "contact x on the face",
        );
    }
}

#[test]
fn constant_angular_acceleration_adds_tangential_term() {
    // s(θ) = e cos θ + R: s̈ = θ̈ s'(θ) + θ̇² s''(θ)
    let alpha = 250.0;
    let m = {
        let cam =
            camkin::cam::Cam::from_rpm(eccentric_circle(R, E), Point2::origin(), Sense::Cw, 300.0)
                .unwrap()
                .with_angular_acceleration(alpha)
                .unwrap();
        camkin::cam::Mechanism::new(
            cam,
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
        )
        .unwrap()
    };
    let w = m.cam().speed();
    for k in 0..18 {
        let th = (k as f64 * 20.0 + 3.0).to_radians();
        let s = m.analyze(th).unwrap();
        let expect = alpha * (-E * th.sin()) + w * w * (-E * th.cos());
        assert_close(
            s.acceleration,
            expect,
            1e-12,
            E * (w * w + alpha),
            "a with θ̈",
        );
        // and the identity with the ω̇ term of contact-kinematics.md
        let expect_id = w * w * (s.radius_of_curvature - s.position) + alpha * s.velocity / w;
        assert_close(
            s.acceleration,
            expect_id,
            1e-12,
            E * (w * w + alpha),
            "identity with θ̈",
        );
    }
}
