//! The constraints as dense rows and the mass-orthogonal projection onto them (Bayo and Ledesma
//! 1996): what a simulation applies after every step and at impacts.

use super::dense::{
    cholesky, cholesky_solve, dot, lu_solve, small, unit_padding, Buf, Dim, Fixed, KKT, MAT, SMALL,
    VEC,
};
use super::model::Model;
use crate::contact::{ContactError, Pairing};

/// The active constraints as dense rows (`m × n`, row-major, padded with zero rows to six for
/// the cam-follower model: see [`SMALL`]), with `Φ` and each row's target velocity.
pub(crate) struct DenseRows {
    pub(crate) jac: Buf<MAT>,
    pub(crate) phi: Buf<VEC>,
    pub(crate) target: Buf<VEC>,
    /// rows (without the padding)
    pub(crate) m: usize,
    /// coordinates
    n: usize,
}

impl DenseRows {
    /// Row `r` of `Φ_q`.
    pub(crate) fn row(&self, r: usize) -> &[f64] {
        &self.jac[r * self.n..(r + 1) * self.n]
    }
}

impl Model {
    /// The constraints with `active[k]` at `(q, q̇)` and time `t` as dense rows, with `Φ` and the
    /// velocity each row's `Φ_q q̇` must have (`−Φ_t`: a driver's speed, else 0); a contact
    /// follows its pairing in `pairings[k]`.
    pub(crate) fn dense_rows(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        active: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<DenseRows, ContactError> {
        let n = q.len();
        let m = self.active_rows(active);
        let rows = if small(n, m) { SMALL } else { m };
        let mut d = DenseRows {
            jac: Buf::zeros(rows * n),
            phi: Buf::zeros(rows),
            target: Buf::zeros(rows),
            m,
            n,
        };
        let mut r = 0;
        for (k, c) in self.constraints.iter().enumerate() {
            if !active[k] {
                continue;
            }
            for row in self.rows(c, t, q, qd, &mut pairings[k])?.iter() {
                for &(col, v) in row.jac() {
                    d.jac[r * n + col] += v;
                }
                d.phi[r] = row.phi;
                d.target[r] = c.target_rate(t);
                r += 1;
            }
        }
        Ok(d)
    }

    /// Solves `[M Jᵀ; J 0] [x; μ] = [M x0; b]`: the mass-orthogonal projection of `x0` onto
    /// `J x = b` (`rows.jac`), written to `x`; `false` when the system is singular. With every
    /// mass and inertia positive, by the Schur complement: `(J M⁻¹ Jᵀ) μ = b − J x0`,
    /// `x = x0 + M⁻¹ Jᵀ μ` (an `m × m` Cholesky); else (or when that fails) by elimination on the
    /// whole saddle-point matrix.
    pub(crate) fn project_onto(
        &self,
        rows: &DenseRows,
        x0: &[f64],
        b: &[f64],
        x: &mut [f64],
    ) -> bool {
        if small(rows.n, rows.m) {
            self.project_dim(Fixed::<SMALL>, Fixed::<SMALL>, rows, x0, b, x)
        } else {
            self.project_dim(rows.n, rows.m, rows, x0, b, x)
        }
    }

    /// [`System::project_onto`] with the number of coordinates `dim` and `padded` rows (as
    /// many as `rows` holds).
    #[inline(always)]
    fn project_dim(
        &self,
        dim: impl Dim,
        padded: impl Dim,
        rows: &DenseRows,
        x0: &[f64],
        b: &[f64],
        x: &mut [f64],
    ) -> bool {
        let (n, real, m) = (dim.get(), rows.m, padded.get());
        debug_assert!(n == rows.n && real <= m && rows.jac.len() == m * n);
        // the rows and each stack buffer taken as slices once, at their lengths
        let (jac, x0, x): (&[f64], _, _) = (&rows.jac[..m * n], &x0[..n], &mut x[..n]);
        let row = |r: usize| &jac[r * n..(r + 1) * n];
        let mut inv_mass_buf = Buf::<VEC>::zeros(n);
        let inv_mass: &mut [f64] = &mut inv_mass_buf;
        for (i, body) in self.bodies.iter().enumerate() {
            inv_mass[3 * i] = 1.0 / body.mass;
            inv_mass[3 * i + 1] = 1.0 / body.mass;
            inv_mass[3 * i + 2] = 1.0 / body.inertia;
        }
        if inv_mass.iter().all(|w| w.is_finite() && *w > 0.0) {
            let mut s_buf = Buf::<MAT>::zeros(m * m);
            let s: &mut [f64] = &mut s_buf;
            let mut scaled_buf = Buf::<MAT>::zeros(m * n);
            let scaled: &mut [f64] = &mut scaled_buf;
            for r in 0..m {
                for ((o, j), w) in scaled[r * n..(r + 1) * n]
                    .iter_mut()
                    .zip(row(r))
                    .zip(inv_mass.iter())
                {
                    *o = j * w;
                }
            }
            // the lower triangle: all that the factorisation reads
            for a in 0..m {
                for c in 0..a + 1 {
                    s[a * m + c] = dot(&scaled[a * n..(a + 1) * n], row(c));
                }
            }
            // a padded row's multiplier: zero (its row and right-hand side are zero)
            unit_padding(s, m, real);
            if cholesky(s, padded) {
                let mut mu_buf = Buf::<VEC>::zeros(m);
                let mu: &mut [f64] = &mut mu_buf;
                for (r, v) in mu[..real].iter_mut().enumerate() {
                    *v = b[r] - dot(row(r), x0);
                }
                cholesky_solve(s, padded, mu);
                x.copy_from_slice(x0);
                for (r, &u) in mu.iter().enumerate() {
                    for (xi, w) in x.iter_mut().zip(&scaled[r * n..(r + 1) * n]) {
                        *xi += w * u;
                    }
                }
                return x.iter().all(|v| v.is_finite());
            }
        }
        let (m, x0) = (real, &x0[..n]);
        let k = n + m;
        let mut kkt = Buf::<KKT>::zeros(k * k);
        let mut rhs = Buf::<VEC>::zeros(k);
        for (i, body) in self.bodies.iter().enumerate() {
            let d = [body.mass, body.mass, body.inertia];
            for j in 0..3 {
                kkt[(3 * i + j) * k + 3 * i + j] = d[j];
                rhs[3 * i + j] = d[j] * x0[3 * i + j];
            }
        }
        for r in 0..m {
            for (c, &v) in rows.row(r).iter().enumerate() {
                kkt[(n + r) * k + c] = v;
                kkt[c * k + n + r] = v;
            }
            rhs[n + r] = b[r];
        }
        if !lu_solve(&mut kkt, k, &mut rhs) {
            return false;
        }
        x.copy_from_slice(&rhs[..n]);
        true
    }
}
