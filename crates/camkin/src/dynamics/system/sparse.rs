//! The Schur complement `S = Φ_q M⁻¹ Φ_qᵀ` of a system's rows kept sparse (a row touches at most
//! six coordinates): built over each coordinate's few rows instead of dense products, factored
//! by Cholesky, and the mass-orthogonal corrections it gives (`x0 + M⁻¹ Φ_qᵀ μ`).

use super::super::model::Row;

/// `S` factored (its lower triangle holds `L`, `S = L Lᵀ`).
pub(super) struct Schur {
    l: Vec<f64>,
    m: usize,
    /// each row's first nonzero column of `L`
    first: Vec<usize>,
}

impl Schur {
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
        let mut l = vec![0.0; m * m];
        // each row's first nonzero column: the envelope the factor stays in
        let mut first: Vec<usize> = (0..m).collect();
        for c in 0..n {
            let group = &entries[count[c]..count[c + 1]];
            let w = inv_mass[c];
            // rows in increasing order within a bucket
            for (i, &(a, va)) in group.iter().enumerate() {
                for &(b, vb) in &group[..=i] {
                    l[a * m + b] += va * w * vb;
                    first[a] = first[a].min(b);
                }
            }
        }
        let diagonal: Vec<f64> = (0..m).map(|a| l[a * m + a]).collect();
        // Cholesky within the envelope: L[i][j] is zero left of row i's first column
        for i in 0..m {
            for j in first[i]..=i {
                let from = first[i].max(first[j]);
                let mut s = l[i * m + j];
                for k in from..j {
                    s -= l[i * m + k] * l[j * m + k];
                }
                if j == i {
                    if !(s > 1e-12 * diagonal[i]) {
                        return None;
                    }
                    l[i * m + i] = s.sqrt();
                } else {
                    l[i * m + j] = s / l[j * m + j];
                }
            }
        }
        Some(Self { l, m, first })
    }

    /// Solves `S μ = b` in place (`L y = b`, then `Lᵀ μ = y`, within the envelope).
    pub(super) fn solve(&self, b: &mut [f64]) {
        let (l, m) = (&self.l, self.m);
        for i in 0..m {
            let mut s = b[i];
            for k in self.first[i]..i {
                s -= l[i * m + k] * b[k];
            }
            b[i] = s / l[i * m + i];
        }
        for i in (0..m).rev() {
            let y = b[i] / l[i * m + i];
            b[i] = y;
            for k in self.first[i]..i {
                b[k] -= l[i * m + k] * y;
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
