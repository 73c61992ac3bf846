//! A simulated system at a singular pose: where its rows are dependent and not consistent (the
//! N-four-bar mechanism with its cranks flat on the ground line has, for an instant, N + 1
//! degrees of freedom where it has one), the accelerations and projections by the
//! Moore–Penrose pseudo-inverse — the equations of motion of Udwadia and Kalaba (1992, *Proc.
//! R. Soc. A* 439, "A new perspective on constrained motion"): `q̈ = a + W (Φ_q W)⁺ (γ̃ − Φ_q a)`,
//! `a = M⁻¹ Q`, `W = M^{-1/2}`, the motion nearest to the unconstrained one in the kinetic
//! energy's metric (Gauss's principle) that meets the rows in the least-squares sense, and the
//! corrections of positions and velocities the least ones in that metric (`Δx = W (Φ_q W)⁺ r`).
//! Away from singular poses both equal the direct solution.

use super::super::model::Row;
use super::super::projection::DenseRows;
use super::sparse::{Schur, SINGULAR};
use super::SystemSimulation;
use nalgebra::{DMatrix, DVector};

/// Singular values below this times the largest are taken as zero (the rows' dependent
/// directions).
const RANK: f64 = 1e-3;

/// `B⁺` of the rows weighted by `W = M^{-1/2}` (`m × n` scaled to `n × m`).
fn weighted_pinv(b: DMatrix<f64>) -> DMatrix<f64> {
    let svd = b.svd(true, true);
    let largest = svd.singular_values.max();
    svd.pseudo_inverse(RANK * largest.max(f64::MIN_POSITIVE))
        .unwrap_or_else(|_| DMatrix::zeros(0, 0))
}

/// How the rows' Schur complement factored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Factored {
    /// factored
    Yes,
    /// dependent in the mass metric (a redundant joint, or exactly at a singular pose)
    Dependent,
    /// nearly dependent by their geometry: a singular pose being passed
    SingularPose,
}

impl SystemSimulation<'_> {
    /// `rows`' Schur complement factored into `schur` (in the mass metric), told apart from a
    /// singular pose by `geometry` where its pivots are small (see [`SINGULAR`]).
    pub(super) fn factor_rows(
        &self,
        schur: &mut Schur,
        geometry: &mut Schur,
        rows: &[Row],
    ) -> Factored {
        if !schur.factor(rows, &self.inv_mass) {
            return Factored::Dependent;
        }
        if schur.worst_pivot() < SINGULAR && geometry.singular(rows, &self.geometry) {
            return Factored::SingularPose;
        }
        Factored::Yes
    }

    /// The least correction `x` (in the kinetic energy's metric) with `Φ_q x = r` in the
    /// least-squares sense, for the dense `rows` (`x = W (Φ_q W)⁺ r`).
    pub(super) fn pseudo_inverse_correction(&self, rows: &DenseRows, r: &[f64]) -> Vec<f64> {
        let n = self.inv_mass.len();
        let m = rows.m;
        let w: Vec<f64> = self.inv_mass.iter().map(|x| x.sqrt()).collect();
        let mut b = DMatrix::<f64>::zeros(m, n);
        for i in 0..m {
            for (c, (v, wc)) in rows.row(i).iter().zip(&w).enumerate() {
                b[(i, c)] = v * wc;
            }
        }
        let pinv = weighted_pinv(b);
        if pinv.nrows() != n {
            return vec![0.0; n];
        }
        let y = pinv * DVector::from_column_slice(&r[..m]);
        y.iter().zip(&w).map(|(yi, wi)| yi * wi).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The weighted pseudo-inverse of a matrix with a dependent row solves a consistent system
    /// exactly and gives the least-norm answer (a row repeated: `x = (1/2, 1/2)` for
    /// `x₁ + x₂ = 1` twice).
    #[test]
    fn the_pseudo_inverse_of_repeated_rows_gives_the_least_answer() {
        let b = DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, 1.0]);
        let p = weighted_pinv(b);
        let x = p * DVector::from_column_slice(&[1.0, 1.0]);
        assert!(
            (x[0] - 0.5).abs() < 1e-15 && (x[1] - 0.5).abs() < 1e-15,
            "{x}"
        );
    }
}
