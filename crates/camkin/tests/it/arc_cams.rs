//! The textbook arc cams against their closed forms: the tangent cam under a radial roller
//! (on the flank `s = (r_b + r_r)/cos φ`, so `a = ω² (r_b + r_r)` where the flank starts; on the
//! nose `s = d cos φ + √((r_n + r_r)² − d² sin² φ)`), and the circular-arc cam under a flat face
//! (on a flank of radius `R`, `lift = (R − r_b)(1 − cos β)` and `v = ω (R − r_b) sin β`, β the cam
//! angle from the flank's start), each differentiated with hyper-dual numbers; both senses.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Sense};
use camkin::curve::{ArcsAndLines, Piece};
use camkin::{Point2, Vec2};
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

const RB: f64 = 20.0;
const RN: f64 = 8.0;
const LIFT: f64 = 12.0;

/// The cam angle at which a follower along +x sees the cam's direction `phi` (cam frame).
fn theta_of(phi: f64, sense: Sense) -> f64 {
    (-sense.sign() * phi).rem_euclid(TAU)
}

#[test]
fn the_tangent_cam_under_a_radial_roller_is_its_closed_form() {
    let rr = 5.0;
    let d = LIFT + RB - RN;
    let psi = ((RB - RN) / d).acos();
    // where the roller leaves the flank for the nose: the pitch nose's foot's polar angle
    let beta = ((RN + rr) * psi.sin()).atan2(d + (RN + rr) * psi.cos());
    let flank = |phi: HD| HD::c(RB + rr) / (phi + (-psi)).cos();
    let nose = |phi: HD| {
        phi.cos() * HD::c(d)
            + (HD::c((RN + rr) * (RN + rr)) - phi.sin() * phi.sin() * HD::c(d * d)).sqrt()
    };
    for sense in [Sense::Ccw, Sense::Cw] {
        let cam = Arc::new(ArcsAndLines::tangent_cam(RB, RN, LIFT).unwrap());
        let m = mechanism(
            cam,
            Point2::origin(),
            sense,
            1200.0,
            Follower::TranslatingRoller {
                direction: Vec2::x(),
                offset: 0.0,
                roller_radius: rr,
            },
        );
        let w = m.cam().speed();
        let mut checked = [0, 0];
        for k in 1..200 {
            // the follower's direction in the cam's frame, on the upper side (the other mirrors it)
            let phi = psi * f64::from(k) / 200.0;
            let (s, which) = if phi < beta {
                (nose(HD::var(phi)), 1)
            } else {
                (flank(HD::var(phi)), 0)
            };
            if (phi - beta).abs() < 1e-6 {
                continue;
            }
            let st = m.analyze(theta_of(phi, sense)).unwrap();
            // d/dθ = −σ d/dφ
            assert_close(st.position, s.v, 1e-12, RB, "position");
            assert_close(
                st.velocity,
                -sense.sign() * w * s.d1,
                1e-11,
                w * RB,
                "velocity",
            );
            assert_close(
                st.acceleration,
                w * w * s.d2,
                1e-10,
                w * w * RB,
                "acceleration",
            );
            checked[which] += 1;
        }
        assert!(checked[0] > 20 && checked[1] > 20, "{checked:?}");
        // where the flank starts, the textbook's a = ω² (r_b + r_r)
        let st = m.analyze(theta_of(psi - 1e-9, sense)).unwrap();
        assert_close(
            st.acceleration,
            w * w * (RB + rr),
            1e-6,
            w * w * RB,
            "a at the flank's start",
        );
    }
}

#[test]
fn the_circular_arc_cam_under_a_flat_face_is_its_closed_form() {
    let r = 60.0;
    for sense in [Sense::Ccw, Sense::Cw] {
        let cam = ArcsAndLines::circular_arc_cam(RB, RN, LIFT, r).unwrap();
        // the upper flank (the last piece): from the nose to the base circle
        let Piece::Arc {
            start,
            sweep,
            centre,
            ..
        } = cam.pieces()[3]
        else {
            panic!("a flank arc")
        };
        assert!((centre.coords.norm() - (r - RB)).abs() < 1e-12);
        let m = mechanism(
            Arc::new(cam),
            Point2::origin(),
            sense,
            900.0,
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
        );
        let w = m.cam().speed();
        for k in 1..100 {
            // the face's normal in the cam's frame; β from the flank's start at the base circle
            let phi = start + sweep * f64::from(k) / 100.0;
            let beta = start + sweep - phi;
            let st = m.analyze(theta_of(phi, sense)).unwrap();
            let lift = (r - RB) * (1.0 - beta.cos());
            assert_close(st.position - RB, lift, 1e-12, RB, "lift on the flank");
            // v = ω (R − r_b) sin β: turning counter-clockwise the cam brings this flank up
            // from the base circle (a rise), clockwise down from the nose (a return)
            let v = sense.sign() * w * (r - RB) * beta.sin();
            assert_close(st.velocity, v, 1e-11, w * RB, "v on the flank");
            // a = ω² (R − r_b) cos β
            assert_close(
                st.acceleration,
                w * w * (r - RB) * beta.cos(),
                1e-10,
                w * w * RB,
                "a on the flank",
            );
        }
        // on the base circle the follower rests; on the nose it is the nose's support
        let st = m.analyze(theta_of(PI, sense)).unwrap();
        assert_close(st.position, RB, 1e-12, RB, "rest on the base circle");
        let st = m.analyze(theta_of(0.0, sense)).unwrap();
        assert_close(st.position, RB + LIFT, 1e-12, RB, "full lift on the nose");
    }
}
