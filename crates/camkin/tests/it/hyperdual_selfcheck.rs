//! The test oracle itself: hyper-dual derivatives against known derivatives.
#![allow(clippy::unwrap_used)]
use crate::common::*;

#[test]
fn hyper_dual_derivatives_are_exact() {
    let x = HD::var(0.7);
    // f = sin(x)·sqrt(x) / cos(x): compare with 8th-order finite differences
    let f = |x: f64| x.sin() * x.sqrt() / x.cos();
    let h = (x.sin() * x.sqrt()) / x.cos();
    let (d1, d2) = fd8(f, 0.7, 1e-3);
    assert_close(h.d1, d1, 1e-10, 1.0, "d1");
    assert_close(h.d2, d2, 1e-8, 1.0, "d2");
    let g = HD::atan2(x.sin() + 2.0, x.cos() * x);
    let gf = |t: f64| (t.sin() + 2.0).atan2(t.cos() * t);
    let (d1, d2) = fd8(gf, 0.7, 1e-3);
    assert_close(g.d1, d1, 1e-10, 1.0, "atan2 d1");
    assert_close(g.d2, d2, 1e-8, 1.0, "atan2 d2");
    let a = (0.3 * x).asin() + (0.2 * x).acos();
    let af = |t: f64| (0.3 * t).asin() + (0.2 * t).acos();
    let (d1, d2) = fd8(af, 0.7, 1e-3);
    assert_close(a.d1, d1, 1e-10, 1.0, "asin d1");
    assert_close(a.d2, d2, 1e-8, 1.0, "asin d2");
}
