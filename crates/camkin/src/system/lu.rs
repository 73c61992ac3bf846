//! A dense LU factorisation with partial pivoting on buffers kept between instants: a system's
//! `Φ_q` is small (three columns a body) and factored two or three times an instant, where
//! allocating a matrix each time cost more than the arithmetic.

/// `P A = L U` of an `n × n` matrix, row-major, in place.
#[derive(Debug, Clone, Default)]
pub(crate) struct Lu {
    n: usize,
    a: Vec<f64>,
    perm: Vec<usize>,
    /// the smallest and largest pivot magnitudes
    pub(crate) pivots: (f64, f64),
}

impl Lu {
    /// Factors the row-major `n × n` matrix `m`.
    pub(crate) fn factor(&mut self, m: &[f64], n: usize) {
        self.n = n;
        self.a.clear();
        self.a.extend_from_slice(m);
        self.perm.clear();
        self.perm.extend(0..n);
        let a = &mut self.a;
        let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
        for k in 0..n {
            // the largest entry of column k at or below the diagonal
            let mut p = k;
            for i in k + 1..n {
                if a[i * n + k].abs() > a[p * n + k].abs() {
                    p = i;
                }
            }
            if p != k {
                for j in 0..n {
                    a.swap(k * n + j, p * n + j);
                }
                self.perm.swap(k, p);
            }
            let d = a[k * n + k];
            lo = lo.min(d.abs());
            hi = hi.max(d.abs());
            if d == 0.0 || !d.is_finite() {
                lo = 0.0;
                continue;
            }
            for i in k + 1..n {
                let f = a[i * n + k] / d;
                a[i * n + k] = f;
                if f != 0.0 {
                    for j in k + 1..n {
                        a[i * n + j] -= f * a[k * n + j];
                    }
                }
            }
        }
        self.pivots = (lo, hi);
    }

    /// Solves `A x = b` into `x` (`b` permuted, then the two triangles).
    pub(crate) fn solve(&self, b: &[f64], x: &mut Vec<f64>) {
        let (n, a) = (self.n, &self.a);
        x.clear();
        x.extend(self.perm.iter().map(|&p| b[p]));
        for i in 0..n {
            let mut s = x[i];
            for j in 0..i {
                s -= a[i * n + j] * x[j];
            }
            x[i] = s;
        }
        for i in (0..n).rev() {
            let mut s = x[i];
            for j in i + 1..n {
                s -= a[i * n + j] * x[j];
            }
            x[i] = s / a[i * n + i];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against nalgebra's LU on a matrix that needs pivoting, and the pivots of a singular one.
    #[test]
    fn solves_as_nalgebra_does_and_sees_a_singular_matrix() {
        let m = [
            0.0, 2.0, 1.0, -1.0, //
            3.0, 1.0, 0.0, 2.0, //
            1.0, -2.0, 4.0, 0.5, //
            2.0, 0.0, -1.0, 3.0,
        ];
        let b = [1.0, -2.0, 0.5, 4.0];
        let mut lu = Lu::default();
        lu.factor(&m, 4);
        let mut x = Vec::new();
        lu.solve(&b, &mut x);
        let reference = nalgebra::DMatrix::from_row_slice(4, 4, &m)
            .lu()
            .solve(&nalgebra::DVector::from_column_slice(&b))
            .unwrap();
        for i in 0..4 {
            assert!((x[i] - reference[i]).abs() < 1e-14, "{x:?} {reference}");
        }
        // a row that is the sum of two others
        let mut s = m;
        for j in 0..4 {
            s[12 + j] = s[j] + s[4 + j];
        }
        lu.factor(&s, 4);
        assert!(lu.pivots.0 <= 1e-15 * lu.pivots.1, "{:?}", lu.pivots);
    }
}
