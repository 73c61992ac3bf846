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
        self.a.extend_from_slice(&m[..n * n]);
        self.perm.clear();
        self.perm.extend(0..n);
        let a = &mut self.a[..];
        let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
        for k in 0..n {
            // the largest entry of column k at or below the diagonal
            let mut p = k;
            let mut big = a[k * n + k].abs();
            for i in k + 1..n {
                let v = a[i * n + k].abs();
                if v > big {
                    (p, big) = (i, v);
                }
            }
            if p != k {
                let (top, bottom) = a.split_at_mut(p * n);
                top[k * n..k * n + n].swap_with_slice(&mut bottom[..n]);
                self.perm.swap(k, p);
            }
            let d = a[k * n + k];
            lo = lo.min(d.abs());
            hi = hi.max(d.abs());
            if d == 0.0 || !d.is_finite() {
                lo = 0.0;
                continue;
            }
            // rows below k less multiples of row k (the Jacobian is sparse: most are skipped)
            let (top, rest) = a.split_at_mut((k + 1) * n);
            let pivot_row = &top[k * n + k + 1..k * n + n];
            for row in rest.chunks_exact_mut(n) {
                let f = row[k] / d;
                row[k] = f;
                if f != 0.0 {
                    for (x, &y) in row[k + 1..].iter_mut().zip(pivot_row) {
                        *x -= f * y;
                    }
                }
            }
        }
        self.pivots = (lo, hi);
    }

    /// Solves `A x = b` into `x` (`b` permuted, then the two triangles).
    pub(crate) fn solve(&self, b: &[f64], x: &mut Vec<f64>) {
        let (n, a) = (self.n, &self.a[..]);
        x.clear();
        x.extend(self.perm.iter().map(|&p| b[p]));
        for (i, row) in a.chunks_exact(n).enumerate() {
            let s = x[i] - dot(&row[..i], &x[..i]);
            x[i] = s;
        }
        for (i, row) in a.chunks_exact(n).enumerate().rev() {
            let s = x[i] - dot(&row[i + 1..], &x[i + 1..]);
            x[i] = s / row[i];
        }
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(p, q)| p * q).sum()
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
