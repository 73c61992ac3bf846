//! The constraints as dense rows and the mass-orthogonal projection onto them (Bayo and Ledesma
//! 1996): what a simulation applies after every step and at impacts.

use super::model::{Constraint, System};
use crate::contact::{ContactError, Pairing};
use nalgebra::{DMatrix, DVector};

/// The active constraints as dense rows, with `Φ` and each row's target velocity.
pub(crate) struct DenseRows {
    pub(crate) rows: Vec<Vec<f64>>,
    pub(crate) phi: Vec<f64>,
    pub(crate) target: Vec<f64>,
}

impl System {
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
        let (mut rows, mut phi, mut target) = (Vec::new(), Vec::new(), Vec::new());
        for (k, c) in self.constraints.iter().enumerate() {
            if !active[k] {
                continue;
            }
            for row in self.rows(c, t, q, qd, &mut pairings[k])? {
                let mut j = vec![0.0; n];
                for (col, v) in &row.jac {
                    j[*col] += v;
                }
                rows.push(j);
                phi.push(row.phi);
                target.push(match c {
                    Constraint::AngleDriver {
                        speed,
                        acceleration,
                        ..
                    } => speed + acceleration * t,
                    _ => 0.0,
                });
            }
        }
        Ok(DenseRows { rows, phi, target })
    }

    /// Solves `[M Jᵀ; J 0] [x; μ] = [M x0; b]`: the mass-orthogonal projection of `x0` onto
    /// `J x = b`; `None` when the system is singular.
    pub(crate) fn project_onto(
        &self,
        rows: &[Vec<f64>],
        x0: &[f64],
        b: &[f64],
    ) -> Option<Vec<f64>> {
        let n = x0.len();
        let m = rows.len();
        let mut kkt = DMatrix::zeros(n + m, n + m);
        let mut rhs = DVector::zeros(n + m);
        for (i, body) in self.bodies.iter().enumerate() {
            let d = [body.mass, body.mass, body.inertia];
            for k in 0..3 {
                kkt[(3 * i + k, 3 * i + k)] = d[k];
                rhs[3 * i + k] = d[k] * x0[3 * i + k];
            }
        }
        for (r, j) in rows.iter().enumerate() {
            for c in 0..n {
                kkt[(n + r, c)] = j[c];
                kkt[(c, n + r)] = j[c];
            }
            rhs[n + r] = b[r];
        }
        let sol = kkt.lu().solve(&rhs)?;
        Some(sol.rows(0, n).iter().copied().collect())
    }
}
