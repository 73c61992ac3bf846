//! Elliptical cam centred on its axis with a flat-faced follower: s(θ) = √(a² cos²θ + b² sin²θ)
//! (the ellipse's support function), differentiated exactly.
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

#[test]
fn rotated_offset_ellipse_satisfies_flat_identity() {
    let m = mechanism(
        ellipse(4.0, 2.5, Point2::new(0.8, -0.3), 0.6),
        Point2::new(1.0, 1.0),
        Sense::Ccw,
        1000.0,
        Follower::TranslatingFlat {
            direction: Vec2::new(0.0, -1.0),
        },
    );
    let w = m.cam().speed();
    for k in 0..72 {
        let st = m.analyze_deg(k as f64 * 5.0).unwrap();
        assert_close(
            st.acceleration,
            w * w * (st.radius_of_curvature - st.position),
            1e-11,
            w * w * 5.0,
            "s̈ = ω²(ρ − s)",
        );
    }
}
