//! The paper's comparison method on its cams: the interpolation error of the acceleration falls
//! with the number of nodal points N, and the paper's figure (max relative error about 0.05 % at
//! N = 10 000 for the original cam) is of the same order.
//!
//! The maximum error falls only like 1/N: the follower's displacement is C² but its third
//! derivative jumps wherever the contact crosses a node of the cam's spline, and next to such a
//! kink the interpolated second derivative is first-order accurate.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::interp::{max_and_mean, relative_errors, Interpolated};

fn study(revised: bool, n: usize, grid: usize) -> (f64, f64) {
    let m = paper_mechanism(revised);
    let thetas: Vec<f64> = (0..grid)
        .map(|k| std::f64::consts::TAU * k as f64 / grid as f64)
        .collect();
    let exact: Vec<f64> = m
        .analyze_all(&thetas)
        .into_iter()
        .map(|r| r.unwrap().acceleration)
        .collect();
    let it = Interpolated::new(&m, n).unwrap();
    let approx: Vec<f64> = thetas.iter().map(|&t| it.acceleration(t)).collect();
    max_and_mean(&relative_errors(&exact, &approx))
}

#[test]
fn interpolation_error_falls_with_nodes() {
    for revised in [false, true] {
        let e: Vec<f64> = [100, 1000, 10_000]
            .iter()
            .map(|&n| study(revised, n, 3600).0)
            .collect();
        eprintln!(
            "revised={revised}: N=100 {:e}, N=1000 {:e}, N=10000 {:e}",
            e[0], e[1], e[2]
        );
        for w in e.windows(2) {
            let ratio = w[0] / w[1];
            // at least first order, at most second order (a cubic spline's s'' cannot do better)
            assert!((5.0..=100.0).contains(&ratio), "revised={revised}: {:?}", e);
        }
        assert!(
            e[0] > 1e-2,
            "the coarse interpolation must show a visible error: {}",
            e[0]
        );
    }
}

#[test]
fn paper_figure_order_of_magnitude_at_ten_thousand_nodes() {
    let (max, mean) = study(false, 10_000, 7200);
    eprintln!("original N=10000: max {max:e} mean {mean:e}");
    // the paper reports a maximum of about 0.05 %
    assert!(max > 5e-5 && max < 5e-3, "max relative error {max}");
}
