//! Issue 12: thin, elongated and tiny geometry. An ellipse with semi-axes 1000 and 1 under a
//! roller of radius 2 ("does not touch" where the position is 3.0) and of radius 1e-3, against a
//! reference that shares nothing with the method: the roller centre's height as the largest
//! `y + √(r² − x²)` over the ellipse's points within the roller's strip `|x| ≤ r`, whose
//! parameters form two intervals found in closed form, by golden-section search on each.

use crate::common::*;
use camkin::cam::{Follower, Sense};
use camkin::{Point2, Vec2};
use std::f64::consts::TAU;

const A: f64 = 1000.0;
const B: f64 = 1.0;

/// The roller centre's height at cam angle `theta` (ccw cam) for a roller of radius `r`
/// travelling along the y axis (offset 0).
fn reference(theta: f64, r: f64) -> f64 {
    let (s, c) = theta.sin_cos();
    let point = |t: f64| {
        let (x, y) = (A * t.cos(), B * t.sin());
        (c * x - s * y, s * x + c * y)
    };
    let h = |t: f64| {
        let (x, y) = point(t);
        if x.abs() <= r {
            y + (r * r - x * x).sqrt()
        } else {
            f64::NEG_INFINITY
        }
    };
    // x(t) = c A cos t − s B sin t = R cos(t + φ): the strip |x| ≤ r is two intervals of t
    // around t + φ = π/2 and 3π/2, of half-width asin(r/R); h is unimodal on each
    let (ra, phi) = ((c * A).hypot(s * B), (s * B).atan2(c * A));
    let half = (r / ra).min(1.0).asin();
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut best = f64::NEG_INFINITY;
    for centre in [0.25 * TAU, 0.75 * TAU] {
        let (mut lo, mut hi) = (centre - phi - half, centre - phi + half);
        for _ in 0..200 {
            let (m1, m2) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if h(m1) >= h(m2) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        best = best.max(h(0.5 * (lo + hi)));
    }
    best
}

#[test]
fn a_long_thin_ellipse_under_a_small_roller_matches_a_direct_reference() {
    for r in [2.0, 1e-3] {
        let f = Follower::TranslatingRoller {
            direction: Vec2::new(0.0, 1.0),
            offset: 0.0,
            roller_radius: r,
        };
        let m = mechanism(
            ellipse(A, B, Point2::origin(), 0.0),
            Point2::origin(),
            Sense::Ccw,
            60.0,
            f,
        );
        let mut sweep = m.sweep();
        for k in 0..360 {
            let deg = k as f64 + 0.5;
            let th = deg.to_radians();
            let exact = reference(th, r);
            let single = m
                .analyze(th)
                .unwrap_or_else(|e| panic!("r = {r} at {deg}°: {e}"));
            let warm = sweep
                .step(th)
                .unwrap_or_else(|e| panic!("r = {r} sweep at {deg}°: {e}"));
            for (how, s) in [("single", single), ("sweep", warm)] {
                // the reference's golden section is good to ~1e-12 of the size
                assert_close(
                    s.position,
                    exact,
                    1e-11,
                    A,
                    &format!("r = {r} {how} at {deg}°"),
                );
            }
        }
        // at 0° the ellipse lies flat: the roller rests on its top, r above it
        let s = m.analyze(0.0).unwrap();
        assert_close(s.position, B + r, 1e-14, A, &format!("r = {r} at 0°"));
    }
}
