//! Small dense linear algebra on row-major slices, in buffers that live on the stack for the
//! few coordinates of a cam-follower system (two bodies: six coordinates, six constraint rows),
//! so that a simulated step allocates nothing; larger systems get heap buffers of their size.

use std::ops::{Deref, DerefMut};

/// Stack capacities: a vector of six coordinates and six rows, a 6 × 6 matrix, and the 12 × 12
/// saddle-point matrix of the projection.
pub(crate) const VEC: usize = 12;
pub(crate) const MAT: usize = 36;
pub(crate) const KKT: usize = 144;

/// The cam-follower model's size: six coordinates and at most six rows. A system of this size is
/// solved at compile-time sizes with its rows padded to six by zero rows, so that its loops
/// unroll; a zero row adds exact zeros to every sum, and its multiplier is zero.
pub(crate) const SMALL: usize = 6;

/// Whether `n` coordinates and `m` rows take the compile-time sizes ([`SMALL`]).
pub(crate) fn small(n: usize, m: usize) -> bool {
    n == SMALL && m <= SMALL
}

/// Gives the padded rows `real..m` of the symmetric `m × m` matrix `a` (zero rows and columns:
/// a padded constraint row is zero) a unit diagonal, so that their unknowns come out zero and
/// the rest of the solution is that of the unpadded system, to the bit.
#[inline(always)]
pub(crate) fn unit_padding(a: &mut [f64], m: usize, real: usize) {
    for k in real..m {
        a[k * m + k] = 1.0;
    }
}

/// A buffer of `len` zeros: on the stack up to `N` entries, else on the heap.
#[derive(Debug, Clone)]
pub(crate) enum Buf<const N: usize> {
    Stack([f64; N], usize),
    Heap(Vec<f64>),
}

impl<const N: usize> Buf<N> {
    pub(crate) fn zeros(len: usize) -> Self {
        if len <= N {
            Self::Stack([0.0; N], len)
        } else {
            Self::Heap(vec![0.0; len])
        }
    }

    /// A buffer holding `values`.
    #[cfg(test)]
    pub(crate) fn from_slice(values: &[f64]) -> Self {
        let mut b = Self::zeros(values.len());
        b.copy_from_slice(values);
        b
    }
}

impl<const N: usize> Deref for Buf<N> {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        match self {
            Self::Stack(a, len) => &a[..*len],
            Self::Heap(v) => v,
        }
    }
}

impl<const N: usize> DerefMut for Buf<N> {
    fn deref_mut(&mut self) -> &mut [f64] {
        match self {
            Self::Stack(a, len) => &mut a[..*len],
            Self::Heap(v) => v,
        }
    }
}

/// A dimension: known at compile time ([`Fixed`], for the cam-follower model's six
/// coordinates: its loops unroll and their bounds checks vanish) or at run time (`usize`).
pub(crate) trait Dim: Copy {
    fn get(self) -> usize;
}

impl Dim for usize {
    #[inline(always)]
    fn get(self) -> usize {
        self
    }
}

/// A dimension known at compile time.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Fixed<const N: usize>;

impl<const N: usize> Dim for Fixed<N> {
    #[inline(always)]
    fn get(self) -> usize {
        N
    }
}

/// `Σ a_k b_k`.
#[inline(always)]
pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Overwrites the lower triangle of the symmetric positive definite `n × n` matrix `a` with its
/// Cholesky factor `L` (`a = L Lᵀ`); `false` when `a` is not positive definite.
#[inline(always)]
pub(crate) fn cholesky(a: &mut [f64], n: impl Dim) -> bool {
    let n = n.get();
    let a = &mut a[..n * n];
    for j in 0..n {
        let row_j = &mut a[j * n..(j + 1) * n];
        let d = row_j[j] - dot(&row_j[..j], &row_j[..j]);
        if !(d > 0.0) {
            return false;
        }
        let d = d.sqrt();
        row_j[j] = d;
        for i in j + 1..n {
            // row j lies above row i
            let (upper, lower) = a.split_at_mut(i * n);
            let (lj, row_i) = (&upper[j * n..j * n + j], &mut lower[..n]);
            row_i[j] = (row_i[j] - dot(&row_i[..j], lj)) / d;
        }
    }
    true
}

/// Solves `L Lᵀ x = b` in place (`l` from [`cholesky`]).
#[inline(always)]
pub(crate) fn cholesky_solve(l: &[f64], n: impl Dim, b: &mut [f64]) {
    let n = n.get();
    let (l, b) = (&l[..n * n], &mut b[..n]);
    for i in 0..n {
        let mut s = b[i];
        for k in 0..i {
            s -= l[i * n + k] * b[k];
        }
        b[i] = s / l[i * n + i];
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for k in i + 1..n {
            s -= l[k * n + i] * b[k];
        }
        b[i] = s / l[i * n + i];
    }
}

/// Solves the `n × n` system `a x = b` in place by Gaussian elimination with partial pivoting
/// (`a` is destroyed); `false` when `a` is singular.
pub(crate) fn lu_solve(a: &mut [f64], n: usize, b: &mut [f64]) -> bool {
    let (a, b) = (&mut a[..n * n], &mut b[..n]);
    for j in 0..n {
        // the last of the largest magnitudes in column j at or below the diagonal
        let mut p = j;
        let mut best = a[j * n + j].abs();
        for i in j + 1..n {
            let v = a[i * n + j].abs();
            if v >= best {
                (p, best) = (i, v);
            }
        }
        if !(a[p * n + j] != 0.0 && a[p * n + j].is_finite()) {
            return false;
        }
        if p != j {
            for k in 0..n {
                a.swap(p * n + k, j * n + k);
            }
            b.swap(p, j);
        }
        let inv = 1.0 / a[j * n + j];
        let (upper, lower) = a.split_at_mut((j + 1) * n);
        let row_j = &upper[j * n..];
        let bj = b[j];
        for (ri, bi) in lower.chunks_exact_mut(n).zip(&mut b[j + 1..]) {
            let f = ri[j] * inv;
            if f != 0.0 {
                for (x, y) in ri[j + 1..].iter_mut().zip(&row_j[j + 1..]) {
                    *x -= f * y;
                }
                *bi -= f * bj;
            }
        }
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for k in i + 1..n {
            s -= a[i * n + k] * b[k];
        }
        b[i] = s / a[i * n + i];
    }
    b.iter().all(|x| x.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A symmetric positive definite matrix and a right-hand side, solved by both routines and
    /// checked by the residual `a x − b` (an independent product, not the factorisation).
    #[test]
    fn solves_agree_with_the_product() {
        let n = 5;
        let mut a = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                a[i * n + j] =
                    1.0 / (1.0 + (i as f64 - j as f64).abs()) + if i == j { 2.0 } else { 0.0 };
            }
        }
        let b: Vec<f64> = (0..n).map(|i| (i as f64).sin() + 0.3).collect();
        let residual = |x: &[f64]| {
            (0..n)
                .map(|i| ((0..n).map(|j| a[i * n + j] * x[j]).sum::<f64>() - b[i]).abs())
                .fold(0.0, f64::max)
        };
        let mut l = Buf::<MAT>::from_slice(&a);
        assert!(cholesky(&mut l, n));
        let mut x = Buf::<VEC>::from_slice(&b);
        cholesky_solve(&l, n, &mut x);
        assert!(residual(&x) < 1e-14, "cholesky residual {}", residual(&x));
        let mut m = a.clone();
        let mut y = b.clone();
        assert!(lu_solve(&mut m, n, &mut y));
        assert!(residual(&y) < 1e-14, "LU residual {}", residual(&y));
        // an indefinite matrix is refused by Cholesky, solved by LU; a singular one by neither
        let mut s = vec![0.0, 1.0, 1.0, 0.0];
        assert!(!cholesky(&mut s.clone(), 2));
        let mut r = vec![2.0, 3.0];
        assert!(lu_solve(&mut s, 2, &mut r));
        assert_eq!(r, vec![3.0, 2.0]);
        assert!(!lu_solve(&mut [1.0, 2.0, 2.0, 4.0], 2, &mut [1.0, 1.0]));
        // padded to n + 2 with zero rows and columns and a unit diagonal there: the same
        // solution to the bit, zeros in the padding
        let p = n + 2;
        let mut padded = vec![0.0; p * p];
        for i in 0..n {
            padded[i * p..i * p + n].copy_from_slice(&a[i * n..(i + 1) * n]);
        }
        unit_padding(&mut padded, p, n);
        assert!(cholesky(&mut padded, p));
        let mut z = b.clone();
        z.extend([0.0, 0.0]);
        cholesky_solve(&padded, p, &mut z);
        assert_eq!(&z[..n], &x[..]);
        assert_eq!(&z[n..], &[0.0, 0.0]);
        // a large buffer lives on the heap, a small one on the stack
        assert!(matches!(Buf::<MAT>::zeros(MAT + 1), Buf::Heap(_)));
        assert!(matches!(Buf::<MAT>::zeros(MAT), Buf::Stack(..)));
    }
}
