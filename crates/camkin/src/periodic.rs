//! Periodic (closed, C²) cubic spline interpolation in one variable: the piece shared by the
//! closed spline curve ([`crate::curve::ClosedSpline`]) and the paper's comparison method
//! ([`crate::interp`]).
//!
//! Knots `0 = u_0 < u_1 < … < u_{n−1} < u_n = P` (the period), values `y_0 … y_{n−1}` with
//! `y_n = y_0`. The second derivatives `M_i` at the knots solve the cyclic tridiagonal system
//!
//! ```text
//! h_{i−1} M_{i−1} + 2 (h_{i−1} + h_i) M_i + h_i M_{i+1} = 6 (Δ_i − Δ_{i−1}),   Δ_i = (y_{i+1} − y_i)/h_i
//! ```
//!
//! (indices mod n), which is strictly diagonally dominant and solved by the Thomas algorithm with
//! a Sherman–Morrison correction for the two corner entries. Each segment is stored in local form
//! `y = c0 + c1 t + c2 t² + c3 t³`, `t = u − u_i ∈ [0, h_i)`.

/// Knot vector of a periodic spline, with the segment lookup.
#[derive(Debug, Clone)]
pub(crate) struct Knots {
    /// `n + 1` knots from 0 to the period.
    pub(crate) u: Vec<f64>,
    /// `Some(1/h)` when the knots are `i h` (segment lookup by multiplication).
    pub(crate) uniform: Option<f64>,
    /// the period (the last knot) and the last segment's index, kept beside `u` so that a
    /// lookup reads neither `u`'s length nor its last element (a warm step looks up twice)
    period: f64,
    last: usize,
}

impl Knots {
    pub(crate) fn uniform(n: usize, h: f64) -> Self {
        let u: Vec<f64> = (0..=n).map(|i| i as f64 * h).collect();
        Self {
            period: u[n],
            last: n - 1,
            u,
            uniform: Some(1.0 / h),
        }
    }

    /// From the segment lengths `h_0 … h_{n−1}` (all > 0).
    pub(crate) fn from_lengths(h: &[f64]) -> Self {
        let mut u = Vec::with_capacity(h.len() + 1);
        let mut acc = 0.0;
        u.push(0.0);
        for &hi in h {
            acc += hi;
            u.push(acc);
        }
        Self {
            period: acc,
            last: h.len() - 1,
            u,
            uniform: None,
        }
    }

    pub(crate) fn segments(&self) -> usize {
        self.u.len() - 1
    }

    pub(crate) fn period(&self) -> f64 {
        self.period
    }

    pub(crate) fn h(&self, i: usize) -> f64 {
        self.u[i + 1] - self.u[i]
    }

    /// The segment holding `u` (taken modulo the period) and the local coordinate in it.
    #[inline]
    pub(crate) fn locate(&self, u: f64) -> (usize, f64) {
        let (i, w) = self.segment_of(u);
        (i, w - self.u[i])
    }

    /// The segment holding `u` and `u` taken modulo the period.
    #[inline(always)]
    pub(crate) fn segment_of(&self, u: f64) -> (usize, f64) {
        let p = self.period;
        let w = if (0.0..p).contains(&u) {
            u
        } else {
            u.rem_euclid(p)
        };
        let i = match self.uniform {
            // through u32 (fewer instructions than a saturating cast to usize): the index
            // is below the segment count, far below 2³², and a NaN `u` gives 0
            Some(inv_h) => (((w * inv_h) as u32) as usize).min(self.last),
            None => {
                // last knot index ≤ w
                let k = self.u.partition_point(|&k| k <= w);
                k.saturating_sub(1).min(self.last)
            }
        };
        (i, w)
    }
}

/// Local cubic coefficients `[c0, c1, c2, c3]` of each segment of the periodic spline through
/// `values` at `knots`.
pub(crate) fn fit(knots: &Knots, values: &[f64]) -> Vec<[f64; 4]> {
    let n = knots.segments();
    debug_assert_eq!(values.len(), n);
    debug_assert!(n >= 3);
    let h: Vec<f64> = (0..n).map(|i| knots.h(i)).collect();
    let delta: Vec<f64> = (0..n)
        .map(|i| (values[(i + 1) % n] - values[i]) / h[i])
        .collect();
    // Row i: sub[i] M_{i−1} + diag[i] M_i + sup[i] M_{i+1} = rhs[i], every row divided by a
    // power of two near the longest segment: the elimination multiplies coefficients in pairs,
    // which overflowed for segments from about 1e154 (chord lengths of a spline 1e160 across);
    // a power of two changes no bit of the solution
    let longest = h.iter().fold(0.0f64, |a, &b| a.max(b));
    let scale = if longest > 0.0 && longest.is_finite() {
        2f64.powi(longest.log2().round() as i32)
    } else {
        1.0
    };
    let sub: Vec<f64> = (0..n).map(|i| h[(i + n - 1) % n] / scale).collect();
    let sup: Vec<f64> = h.iter().map(|&x| x / scale).collect();
    let diag: Vec<f64> = (0..n).map(|i| 2.0 * (sub[i] + sup[i])).collect();
    let rhs: Vec<f64> = (0..n)
        .map(|i| 6.0 * (delta[i] - delta[(i + n - 1) % n]) / scale)
        .collect();
    let m = solve_cyclic_tridiagonal(&sub, &diag, &sup, &rhs);
    (0..n)
        .map(|i| {
            let j = (i + 1) % n;
            let hi = h[i];
            [
                values[i],
                delta[i] - hi * (2.0 * m[i] + m[j]) / 6.0,
                0.5 * m[i],
                (m[j] - m[i]) / (6.0 * hi),
            ]
        })
        .collect()
}

/// Solves the cyclic tridiagonal system whose row i is
/// `sub[i] x_{i−1} + diag[i] x_i + sup[i] x_{i+1} = rhs[i]` (indices mod n, n ≥ 3), assuming
/// strict diagonal dominance (no pivoting).
pub(crate) fn solve_cyclic_tridiagonal(
    sub: &[f64],
    diag: &[f64],
    sup: &[f64],
    rhs: &[f64],
) -> Vec<f64> {
    let n = diag.len();
    // Corners: A[0][n−1] = sub[0] (beta), A[n−1][0] = sup[n−1] (alpha).
    let alpha = sup[n - 1];
    let beta = sub[0];
    let gamma = -diag[0];
    let mut b = diag.to_vec();
    b[0] -= gamma;
    b[n - 1] -= alpha * beta / gamma;
    let x = solve_tridiagonal(sub, &b, sup, rhs);
    let mut u = vec![0.0; n];
    u[0] = gamma;
    u[n - 1] = alpha;
    let z = solve_tridiagonal(sub, &b, sup, &u);
    let fact = (x[0] + beta * x[n - 1] / gamma) / (1.0 + z[0] + beta * z[n - 1] / gamma);
    x.iter().zip(&z).map(|(xi, zi)| xi - fact * zi).collect()
}

/// Thomas algorithm; `sub[0]` and `sup[n−1]` are ignored.
fn solve_tridiagonal(sub: &[f64], diag: &[f64], sup: &[f64], rhs: &[f64]) -> Vec<f64> {
    let n = diag.len();
    let mut c = vec![0.0; n];
    let mut d = vec![0.0; n];
    c[0] = sup[0] / diag[0];
    d[0] = rhs[0] / diag[0];
    for i in 1..n {
        let m = diag[i] - sub[i] * c[i - 1];
        c[i] = if i + 1 < n { sup[i] / m } else { 0.0 };
        d[i] = (rhs[i] - sub[i] * d[i - 1]) / m;
    }
    let mut x = vec![0.0; n];
    x[n - 1] = d[n - 1];
    for i in (0..n - 1).rev() {
        x[i] = d[i] - c[i] * x[i + 1];
    }
    x
}

/// Value and first three derivatives of the local cubic `c` at `t`.
#[inline]
pub(crate) fn eval_local(c: &[f64; 4], t: f64) -> [f64; 4] {
    [
        c[0] + t * (c[1] + t * (c[2] + t * c[3])),
        c[1] + t * (2.0 * c[2] + t * 3.0 * c[3]),
        2.0 * c[2] + t * 6.0 * c[3],
        6.0 * c[3],
    ]
}

/// A scalar periodic cubic spline (used by the comparison method of the paper).
#[derive(Debug, Clone)]
pub(crate) struct ScalarSpline {
    knots: Knots,
    coef: Vec<[f64; 4]>,
}

impl ScalarSpline {
    /// Uniform knots `i · period / n` through `values` (n ≥ 3).
    pub(crate) fn uniform(values: &[f64], period: f64) -> Self {
        let knots = Knots::uniform(values.len(), period / values.len() as f64);
        let coef = fit(&knots, values);
        Self { knots, coef }
    }

    /// Value and first three derivatives at `u` (taken modulo the period).
    pub(crate) fn eval(&self, u: f64) -> [f64; 4] {
        let (i, t) = self.knots.locate(u);
        eval_local(&self.coef[i], t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn cyclic_solver_matches_dense_product() {
        let sub = [1.0, 0.5, 2.0, 0.25, 1.5];
        let sup = [0.75, 1.0, 0.5, 2.0, 1.25];
        let diag: Vec<f64> = (0..5).map(|i| 4.0 + sub[i] + sup[i]).collect();
        let rhs = [1.0, -2.0, 3.0, 0.5, -1.0];
        let x = solve_cyclic_tridiagonal(&sub, &diag, &sup, &rhs);
        for i in 0..5 {
            let lhs = sub[i] * x[(i + 4) % 5] + diag[i] * x[i] + sup[i] * x[(i + 1) % 5];
            assert_relative_eq!(lhs, rhs[i], epsilon = 1e-13);
        }
    }

    #[test]
    fn cyclic_solver_three_unknowns() {
        let sub = [1.0, 2.0, 3.0];
        let sup = [0.5, 0.25, 1.0];
        let diag = [5.0, 6.0, 7.0];
        let rhs = [1.0, 2.0, 3.0];
        let x = solve_cyclic_tridiagonal(&sub, &diag, &sup, &rhs);
        for i in 0..3 {
            let lhs = sub[i] * x[(i + 2) % 3] + diag[i] * x[i] + sup[i] * x[(i + 1) % 3];
            assert_relative_eq!(lhs, rhs[i], epsilon = 1e-13);
        }
    }

    #[test]
    fn periodic_spline_reproduces_sine_to_fourth_order() {
        // Error of a periodic cubic spline is O(h⁴) in value, O(h²) in second derivative.
        let err = |n: usize| {
            let p = std::f64::consts::TAU;
            let v: Vec<f64> = (0..n).map(|i| (p * i as f64 / n as f64).sin()).collect();
            let s = ScalarSpline::uniform(&v, p);
            (0..997)
                .map(|k| {
                    let u = p * k as f64 / 997.0;
                    (s.eval(u)[0] - u.sin()).abs()
                })
                .fold(0.0, f64::max)
        };
        let (e1, e2) = (err(20), err(40));
        assert!(e1 < 1e-4, "{e1}");
        let order = (e1 / e2).log2();
        assert!((order - 4.0).abs() < 0.3, "order {order}");
    }

    #[test]
    fn spline_is_c2_across_every_knot_including_seam() {
        let knots = Knots::from_lengths(&[1.0, 0.5, 2.0, 1.3]);
        let values = [0.0, 1.0, -0.5, 2.0];
        let c = fit(&knots, &values);
        let n = 4;
        for i in 0..n {
            let end = eval_local(&c[i], knots.h(i));
            let start = eval_local(&c[(i + 1) % n], 0.0);
            for d in 0..3 {
                assert_relative_eq!(end[d], start[d], epsilon = 1e-12, max_relative = 1e-12);
            }
            assert_relative_eq!(start[0], values[(i + 1) % n]);
        }
    }
}
