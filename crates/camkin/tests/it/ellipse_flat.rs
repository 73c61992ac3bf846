//! Elliptical cam centred on its axis with a flat-faced follower: s(θ) = √(a² cos²θ + b² sin²θ)
//! (the ellipse's support function), differentiated exactly; an ellipse off its axis and turned,
//! against its support function too.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Sense};
use camkin::{Point2, Vec2};

#[test]
fn ellipse_support_function_both_directions() {
    let (a, b) = (5.0, 3.0);
    for dir in [Sense::Ccw, Sense::Cw] {
        let m = mechanism(
            ellipse(a, b, Point2::origin(), 0.0),
            Point2::origin(),
            dir,
            1000.0,
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
        );
        let w = m.cam().speed();
        for k in 0..90 {
            let th = (k as f64 * 4.0 + 0.1).to_radians();
            let t = HD::var(th);
            let (c, s) = (t.cos(), t.sin());
            let cf = (HD::c(a * a) * c * c + HD::c(b * b) * s * s).sqrt();
            let st = m.analyze(th).unwrap();
            assert_close(st.position, cf.v, 1e-13, a, "s");
            assert_close(st.velocity, w * cf.d1, 1e-12, w * a, "v");
            assert_close(st.acceleration, w * w * cf.d2, 1e-12, w * w * a, "a");
        }
    }
}

/// An ellipse off its axis and turned: its support function in the face's direction `d`,
/// `s(θ) = (R c)·d + √(a² (R e₁·d)² + b² (R e₂·d)²)` with `R = R(σθ)`, differentiated exactly.
#[test]
fn rotated_offset_ellipse_against_its_support_function() {
    let (a, b, c, rot) = (4.0, 2.5, Point2::new(0.8, -0.3), 0.6f64);
    for dir in [Sense::Ccw, Sense::Cw] {
        let m = mechanism(
            ellipse(a, b, c, rot),
            Point2::origin(),
            dir,
            1000.0,
            Follower::TranslatingFlat {
                direction: Vec2::new(0.0, -1.0),
            },
        );
        let w = m.cam().speed();
        let sg = dir.sign();
        for k in 0..72 {
            let th = (k as f64 * 5.0 + 0.7).to_radians();
            // the cam frame's angle and the direction d = (0, −1) seen in it: R(−σθ) d
            let phi = HD::var(th) * HD::c(sg);
            let (sp, cp) = (phi.sin(), phi.cos());
            // R(−φ)(0, −1) = (−sin φ, −cos φ)
            let (dx, dy) = (HD::c(0.0) - sp, HD::c(0.0) - cp);
            let (e1, e2) = ((rot.cos(), rot.sin()), (-rot.sin(), rot.cos()));
            let p1 = dx * HD::c(e1.0) + dy * HD::c(e1.1);
            let p2 = dx * HD::c(e2.0) + dy * HD::c(e2.1);
            let sf = dx * HD::c(c.x)
                + dy * HD::c(c.y)
                + (HD::c(a * a) * p1 * p1 + HD::c(b * b) * p2 * p2).sqrt();
            let st = m.analyze(th).unwrap();
            assert_close(st.position, sf.v, 1e-13, a, "s");
            assert_close(st.velocity, w * sf.d1, 1e-12, w * a, "v");
            assert_close(st.acceleration, w * w * sf.d2, 1e-12, w * w * a, "a");
        }
    }
}
