//! The Schur complement `S = Φ_q M⁻¹ Φ_qᵀ` of a system's rows kept sparse (a row touches at most
//! six coordinates): built over each coordinate's few rows instead of dense products, factored
//! by Cholesky, and the mass-orthogonal corrections it gives (`x0 + M⁻¹ Φ_qᵀ μ`).

use super::super::model::Row;

/// `S` factored (`S = L Lᵀ`), `L` kept row by row within each row's envelope: row `i` from its
/// first nonzero column `first[i]` to the diagonal, at `start[i]` of `l` (a skyline: a chain's
/// rows touch their neighbours only, so `L` holds a few entries a row, not `m²`).
pub(super) struct Schur {
    l: Vec<f64>,
    m: usize,
    /// each row's first nonzero column of `L`
    first: Vec<usize>,
    /// where each row's envelope starts in `l`
    start: Vec<usize>,
}

impl Schur {
    /// Entry `(i, j)` of `L` (`first[i] ≤ j ≤ i`) in `l`.
    #[inline(always)]
    fn at(&self, i: usize, j: usize) -> usize {
        self.start[i] + j - self.first[i]
    }

    /// `S` of `rows` with the inverse masses `inv_mass` (one per coordinate), factored; `None`
    /// where the rows are dependent (a pivot, squared, below 1e-12 of its row's own size). The
    /// factor keeps to each row's envelope (from its first nonzero column): a chain's rows
    /// touch their neighbours only.
    pub(super) fn new(rows: &[Row], inv_mass: &[f64]) -> Option<Self> {
        let m = rows.len();
        let n = inv_mass.len();
        // every entry, bucketed by coordinate (a counting sort): S[a][b] sums over the
        // coordinates rows a and b share
        let mut count = vec![0usize; n + 1];
        for row in rows {
            for &(c, _) in row.jac() {
                count[c + 1] += 1;
            }
        }
        for c in 0..n {
            count[c + 1] += count[c];
        }
        let mut entries = vec![(0usize, 0.0f64); count[n]];
        let mut next = count.clone();
        for (r, row) in rows.iter().enumerate() {
            for &(c, v) in row.jac() {
                entries[next[c]] = (r, v);
                next[c] += 1;
            }
        }
        // each row's first nonzero column: the lowest row it shares a coordinate with (rows
        // are in increasing order within a bucket); the factor's fill stays within it
        let mut first: Vec<usize> = (0..m).collect();
        for c in 0..n {
            let group = &entries[count[c]..count[c + 1]];
            if let Some(&(lowest, _)) = group.first() {
                for &(a, _) in group {
                    first[a] = first[a].min(lowest);
                }
            }
        }
        let mut start = Vec::with_capacity(m + 1);
        let mut size = 0;
        for (i, &f) in first.iter().enumerate() {
            start.push(size);
            size += i + 1 - f;
        }
        let mut schur = Self {
            l: vec![0.0; size],
            m,
            first,
            start,
        };
        for c in 0..n {
            let group = &entries[count[c]..count[c + 1]];
            let w = inv_mass[c];
            for (i, &(a, va)) in group.iter().enumerate() {
                for &(b, vb) in &group[..=i] {
                    let k = schur.at(a, b);
                    schur.l[k] += va * w * vb;
                }
            }
        }
        let diagonal: Vec<f64> = (0..m).map(|a| schur.l[schur.at(a, a)]).collect();
        // Cholesky within the envelope: L[i][j] is zero left of row i's first column
        let Self {
            l, first, start, ..
        } = &mut schur;
        for i in 0..m {
            let (fi, si) = (first[i], start[i]);
            for j in fi..=i {
                let (fj, sj) = (first[j], start[j]);
                let from = fi.max(fj);
                // row i's and row j's entries from `from` to j − 1
                let (ri, rj) = (si + from - fi, sj + from - fj);
                let len = j - from;
                let mut s = l[si + j - fi];
                for (a, b) in l[ri..ri + len].iter().zip(&l[rj..rj + len]) {
                    s -= a * b;
                }
                if j == i {
                    if !(s > 1e-12 * diagonal[i]) {
                        return None;
                    }
                    l[si + i - fi] = s.sqrt();
                } else {
                    l[si + j - fi] = s / l[sj + j - fj];
                }
            }
        }
        Some(schur)
    }

    /// Solves `S μ = b` in place (`L y = b`, then `Lᵀ μ = y`, within the envelope).
    pub(super) fn solve(&self, b: &mut [f64]) {
        let m = self.m;
        for i in 0..m {
            let (f, row) = (self.first[i], self.start[i]);
            let entries = &self.l[row..row + i - f];
            let s = b[i]
                - entries
                    .iter()
                    .zip(&b[f..i])
                    .map(|(l, x)| l * x)
                    .sum::<f64>();
            b[i] = s / self.l[row + i - f];
        }
        for i in (0..m).rev() {
            let (f, row) = (self.first[i], self.start[i]);
            let y = b[i] / self.l[row + i - f];
            b[i] = y;
            for (x, l) in b[f..i].iter_mut().zip(&self.l[row..row + i - f]) {
                *x -= l * y;
            }
        }
    }
}

/// `x0 + M⁻¹ Φ_qᵀ μ` with `S μ = b − Φ_q x0`: the mass-orthogonal projection of `x0` onto
/// `Φ_q x = b`.
pub(super) fn project(
    rows: &[Row],
    inv_mass: &[f64],
    schur: &Schur,
    x0: &[f64],
    b: &[f64],
) -> Vec<f64> {
    let mut mu: Vec<f64> = rows
        .iter()
        .zip(b)
        .map(|(row, &b)| b - row.jac().iter().map(|&(c, v)| v * x0[c]).sum::<f64>())
        .collect();
    schur.solve(&mut mu);
    let mut x = x0.to_vec();
    for (row, &u) in rows.iter().zip(&mu) {
        for &(c, v) in row.jac() {
            x[c] += inv_mass[c] * v * u;
        }
    }
    x
}
