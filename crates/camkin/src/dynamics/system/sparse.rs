//! The Schur complement `S = Φ_q M⁻¹ Φ_qᵀ` of a system's rows kept sparse (a row touches at most
//! six coordinates): built over each coordinate's few rows instead of dense products, factored
//! by Cholesky, and the mass-orthogonal corrections it gives (`x0 + M⁻¹ Φ_qᵀ μ`).

use super::super::model::Row;

/// Up to this many rows `S` is built whole from the rows' entries (a cam and its follower have
/// six): cheaper than bucketing the entries by coordinate.
const DENSE_ROWS: usize = 12;

/// A pivot of the Schur complement, squared, below this times its row's own size marks the rows
/// dependent (a redundant joint).
const DEPENDENT: f64 = 1e-12;

/// Rows whose geometry alone (the Schur complement with unit weights, an angle's times the
/// size: no masses) has a pivot, squared, below this times its row's size are at a singular
/// pose (the sine of the angle between a row and the others' below 1e-3): there the direct
/// solution would amplify the rows' rounding by its inverse square, and the Schur complement is
/// damped by it instead ([`Schur::factor_regularised`]). A point mass's rows are as dependent
/// in the mass metric, but not in this one.
pub(super) const SINGULAR: f64 = 1e-6;

/// `S` factored (`S = L Lᵀ`), `L` kept row by row within each row's envelope: row `i` from its
/// first nonzero column `first[i]` to the diagonal, at `start[i]` of `l` (a skyline: a chain's
/// rows touch their neighbours only, so `L` holds a few entries a row, not `m²`). Its buffers
/// are kept from one factorisation to the next ([`Schur::factor`]): a simulation's step
/// allocates nothing for it.
#[derive(Debug, Clone, Default)]
pub(crate) struct Schur {
    l: Vec<f64>,
    m: usize,
    /// each row's first nonzero column of `L`
    first: Vec<usize>,
    /// where each row's envelope starts in `l`
    start: Vec<usize>,
    /// the rows' entries bucketed by coordinate, with the buckets' bounds and fill positions
    entries: Vec<(usize, f64)>,
    count: Vec<usize>,
    next: Vec<usize>,
    diagonal: Vec<f64>,
    /// `Φ_q M⁻¹` dense, for a few rows
    weighted: Vec<f64>,
    /// the rows of the factor held, where it succeeded: asked again for the same rows (a
    /// projection's rates, then the step's check at the same positions) it is kept
    factored: Vec<Row>,
    /// the regularisation of the factor held (0: `S` itself)
    factored_mu: f64,
    /// the regularisation being factored
    mu: f64,
    /// the smallest pivot, squared, over its row's size, that the factor in progress accepts
    floor: f64,
    /// the smallest it met
    worst: f64,
    /// the rows in the order factored (reverse Cuthill–McKee: a narrow envelope whatever order
    /// the file wrote its joints in), and each row's place in it
    order: Vec<usize>,
    place: Vec<usize>,
    /// the rows' pattern that order is of (each row's length, then its columns), and the one
    /// being factored: a step's rows keep their pattern, and their order with it
    pattern: Vec<usize>,
    asked: Vec<usize>,
    /// a right-hand side in that order
    permuted: std::cell::RefCell<Vec<f64>>,
}

impl Schur {
    /// Factors `S` of `rows` with the inverse masses `inv_mass` in place, reusing the buffers;
    /// `false` where the rows are dependent (a pivot, squared, below 1e-12 of its row's own
    /// size). The factor keeps to each row's envelope (from its first nonzero column): a
    /// chain's rows touch their neighbours only.
    pub(super) fn factor(&mut self, rows: &[Row], inv_mass: &[f64]) -> bool {
        self.factor_with(rows, inv_mass, 0.0, DEPENDENT)
    }

    /// [`Schur::factor`] of `S + μ D` (`D` its diagonal, `μ` [`SINGULAR`]): at a singular
    /// pose, where `S` is nearly singular, the least-squares answer damped in the rows'
    /// dependent directions (Levenberg–Marquardt's damping; the augmented Lagrangian's penalty
    /// `1/μ`), which elsewhere changes the answer by `μ` of it; it fails only on a row of zeros.
    pub(super) fn factor_regularised(&mut self, rows: &[Row], inv_mass: &[f64]) -> bool {
        self.factor_with(rows, inv_mass, SINGULAR, 0.0)
    }

    /// Whether `rows` are at a singular pose: their Schur complement with the weights
    /// `geometry` (no masses) has a pivot, squared, below [`SINGULAR`] of its row's size.
    pub(super) fn singular(&mut self, rows: &[Row], geometry: &[f64]) -> bool {
        !self.factor_with(rows, geometry, 0.0, SINGULAR)
    }

    /// The smallest pivot, squared, over its row's size, of the last factor.
    pub(super) fn worst_pivot(&self) -> f64 {
        self.worst
    }

    fn factor_with(&mut self, rows: &[Row], inv_mass: &[f64], mu: f64, floor: f64) -> bool {
        // (the last rows first: contacts' rows come last and move most, joints' are often fixed)
        let same = self.factored_mu == mu
            && self.floor == floor
            && self.factored.len() == rows.len()
            && self
                .factored
                .iter()
                .rev()
                .zip(rows.iter().rev())
                .all(|(a, b)| a.jac() == b.jac());
        if same {
            return true;
        }
        self.factored.clear();
        (self.mu, self.floor, self.worst) = (mu, floor, f64::INFINITY);
        if !self.factor_anew(rows, inv_mass) {
            return false;
        }
        self.factored.extend_from_slice(rows);
        self.factored_mu = mu;
        true
    }

    /// [`Schur::factor`] computed.
    fn factor_anew(&mut self, rows: &[Row], inv_mass: &[f64]) -> bool {
        let m = rows.len();
        let n = inv_mass.len();
        self.m = m;
        if m <= DENSE_ROWS {
            self.fill_dense(rows, inv_mass);
            return self.cholesky_dense();
        }
        // every entry, bucketed by coordinate (a counting sort): S[a][b] sums over the
        // coordinates rows a and b share
        let count = &mut self.count;
        count.clear();
        count.resize(n + 1, 0);
        for row in rows {
            for &(c, _) in row.jac() {
                count[c + 1] += 1;
            }
        }
        for c in 0..n {
            count[c + 1] += count[c];
        }
        let entries = &mut self.entries;
        entries.clear();
        entries.resize(count[n], (0, 0.0));
        // the rows renumbered by reverse Cuthill–McKee (found again only where their pattern
        // changed: a contact closed or opened), and bucketed in that order
        self.asked.clear();
        for row in rows {
            self.asked.push(row.jac().len());
            self.asked.extend(row.jac().iter().map(|&(c, _)| c));
        }
        if self.asked != self.pattern || self.order.len() != m {
            self.next.clear();
            self.next.extend_from_slice(count);
            for (r, row) in rows.iter().enumerate() {
                for &(c, v) in row.jac() {
                    entries[self.next[c]] = (r, v);
                    self.next[c] += 1;
                }
            }
            reverse_cuthill_mckee(rows, count, entries, &mut self.order);
            self.place.clear();
            self.place.resize(m, 0);
            for (i, &r) in self.order.iter().enumerate() {
                self.place[r] = i;
            }
            std::mem::swap(&mut self.pattern, &mut self.asked);
        }
        self.next.clear();
        self.next.extend_from_slice(count);
        for &r in &self.order {
            for &(c, v) in rows[r].jac() {
                entries[self.next[c]] = (self.place[r], v);
                self.next[c] += 1;
            }
        }
        // each row's first nonzero column: the lowest row it shares a coordinate with (rows
        // are in increasing order within a bucket); the factor's fill stays within it
        let first = &mut self.first;
        first.clear();
        first.extend(0..m);
        for c in 0..n {
            let group = &entries[count[c]..count[c + 1]];
            if let Some(&(lowest, _)) = group.first() {
                for &(a, _) in group {
                    first[a] = first[a].min(lowest);
                }
            }
        }
        let start = &mut self.start;
        start.clear();
        let mut size = 0;
        for (i, &f) in first.iter().enumerate() {
            start.push(size);
            size += i + 1 - f;
        }
        let l = &mut self.l;
        l.clear();
        l.resize(size, 0.0);
        for c in 0..n {
            let group = &entries[count[c]..count[c + 1]];
            let w = inv_mass[c];
            for (i, &(a, va)) in group.iter().enumerate() {
                for &(b, vb) in &group[..=i] {
                    l[start[a] + b - first[a]] += va * w * vb;
                }
            }
        }
        self.cholesky()
    }

    /// `S` of a few rows whole (every row's envelope from column 0): `Φ_q M⁻¹` scattered dense
    /// (`m × n`), each entry of `S` its row's dot product with another row's (at most six)
    /// entries.
    fn fill_dense(&mut self, rows: &[Row], inv_mass: &[f64]) {
        let (m, n) = (rows.len(), inv_mass.len());
        self.first.clear();
        self.first.resize(m, 0);
        self.start.clear();
        self.start.extend((0..m).map(|i| i * (i + 1) / 2));
        self.l.clear();
        self.l.resize(m * (m + 1) / 2, 0.0);
        let weighted = &mut self.weighted;
        weighted.clear();
        weighted.resize(m * n, 0.0);
        for (a, ra) in rows.iter().enumerate() {
            for &(c, v) in ra.jac() {
                weighted[a * n + c] += v * inv_mass[c];
            }
        }
        for (a, wa) in weighted.chunks_exact(n).enumerate() {
            for (b, rb) in rows[..=a].iter().enumerate() {
                self.l[self.start[a] + b] = rb.jac().iter().map(|&(c, v)| wa[c] * v).sum();
            }
        }
    }

    /// Cholesky of `S` filled whole in `l` (row `i` at `i(i+1)/2`): the envelope's, without
    /// its bookkeeping.
    fn cholesky_dense(&mut self) -> bool {
        let (mu, floor) = (self.mu, self.floor);
        let l = &mut self.l;
        let mut ri = 0;
        for i in 0..self.m {
            let (done, rest) = l.split_at_mut(ri);
            let row = &mut rest[..=i];
            let mut rj = 0;
            for j in 0..i {
                let lj = &done[rj..=rj + j];
                let s = row[j] - dot(&row[..j], &lj[..j]);
                row[j] = s / lj[j];
                rj += j + 1;
            }
            let diagonal = row[i] * (1.0 + mu);
            row[i] = diagonal;
            let s = diagonal - dot(&row[..i], &row[..i]);
            self.worst = self.worst.min(s / diagonal);
            if !(s > floor * diagonal) {
                return false;
            }
            row[i] = s.sqrt();
            ri += i + 1;
        }
        true
    }

    /// Cholesky of `S` (filled in `l`) within the envelope: `false` where a pivot, squared,
    /// falls below 1e-12 of its row's own size (dependent rows).
    fn cholesky(&mut self) -> bool {
        let m = self.m;
        let Self {
            l,
            first,
            start,
            diagonal,
            mu,
            floor,
            worst,
            ..
        } = self;
        diagonal.clear();
        for a in 0..m {
            let d = &mut l[start[a] + a - first[a]];
            *d *= 1.0 + *mu;
            diagonal.push(*d);
        }
        let floor = *floor;
        // L[i][j] is zero left of row i's first column
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
                    *worst = worst.min(s / diagonal[i]);
                    if !(s > floor * diagonal[i]) {
                        return false;
                    }
                    l[si + i - fi] = s.sqrt();
                } else {
                    l[si + j - fi] = s / l[sj + j - fj];
                }
            }
        }
        true
    }

    /// Solves `S μ = b` in place (`L y = b`, then `Lᵀ μ = y`, within the envelope, in the
    /// order factored).
    pub(super) fn solve(&self, b: &mut [f64]) {
        let m = self.m;
        if m <= DENSE_ROWS {
            return self.solve_dense(&mut b[..m]);
        }
        let mut permuted = self.permuted.borrow_mut();
        permuted.clear();
        permuted.extend(self.order.iter().map(|&r| b[r]));
        self.solve_ordered(&mut permuted);
        for (&r, &x) in self.order.iter().zip(permuted.iter()) {
            b[r] = x;
        }
    }

    /// [`Schur::solve`] of a right-hand side in the order factored.
    fn solve_ordered(&self, b: &mut [f64]) {
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

    /// [`Schur::solve`] with `L` whole (row `i` at `i(i+1)/2`).
    fn solve_dense(&self, b: &mut [f64]) {
        let m = b.len();
        let l = &self.l[..m * (m + 1) / 2];
        let mut ri = 0;
        for i in 0..m {
            let row = &l[ri..=ri + i];
            let mut s = b[i];
            for (x, y) in row[..i].iter().zip(b.iter()) {
                s -= x * y;
            }
            b[i] = s / row[i];
            ri += i + 1;
        }
        for i in (0..m).rev() {
            ri -= i + 1;
            let row = &l[ri..=ri + i];
            let y = b[i] / row[i];
            b[i] = y;
            for (x, l) in b.iter_mut().zip(&row[..i]) {
                *x -= l * y;
            }
        }
    }
}

/// `Σ aᵢ bᵢ`.
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
/// The reverse Cuthill–McKee order of `rows` (two rows neighbours where they share a
/// coordinate; `count` and `entries`: the rows' entries bucketed by coordinate) into `order`:
/// from a row of fewest neighbours, breadth first, each row's new neighbours fewest first, then
/// reversed (George and Liu, *Computer Solution of Large Sparse Positive Definite Systems*,
/// 1981, §4.3): a chain's rows come out along it, whatever order they were written in, so that
/// each row's envelope holds its few neighbours.
fn reverse_cuthill_mckee(
    rows: &[Row],
    count: &[usize],
    entries: &[(usize, f64)],
    order: &mut Vec<usize>,
) {
    let m = rows.len();
    let neighbours = |r: usize| {
        rows[r]
            .jac()
            .iter()
            .flat_map(move |&(c, _)| entries[count[c]..count[c + 1]].iter().map(|e| e.0))
    };
    let degree: Vec<usize> = (0..m).map(|r| neighbours(r).count()).collect();
    let mut seen = vec![false; m];
    order.clear();
    let mut fresh = Vec::new();
    while order.len() < m {
        let Some(start) = (0..m).filter(|&r| !seen[r]).min_by_key(|&r| degree[r]) else {
            break;
        };
        seen[start] = true;
        let mut head = order.len();
        order.push(start);
        while head < order.len() {
            let r = order[head];
            head += 1;
            fresh.clear();
            for a in neighbours(r) {
                if !seen[a] {
                    seen[a] = true;
                    fresh.push(a);
                }
            }
            fresh.sort_by_key(|&a| (degree[a], a));
            order.extend_from_slice(&fresh);
        }
    }
    order.reverse();
}
