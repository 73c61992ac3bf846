//! The augmented Lagrangian solve of the equations of motion at one instant.

use super::model::{Row, System};
use super::{Constraint, DynamicsError};
use crate::contact::Pairing;
use nalgebra::{DMatrix, DVector};

/// Parameters of the augmented Lagrangian method (see the [module docs](super)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AugmentedLagrangian {
    /// penalty `α`, relative to the largest mass or inertia (the absolute penalty is this times
    /// that mass)
    pub penalty: f64,
    /// stabilisation damping ratio `ξ`
    pub xi: f64,
    /// stabilisation frequency `Ω`, rad/s
    pub omega: f64,
    /// the iteration stops when the stabilised acceleration residual is below this, relative to
    /// the size of `γ` (plus one)
    pub tolerance: f64,
    /// most iterations
    pub max_iterations: usize,
}

impl Default for AugmentedLagrangian {
    fn default() -> Self {
        Self {
            penalty: 1e8,
            xi: 1.0,
            omega: 10.0,
            tolerance: 1e-13,
            max_iterations: 50,
        }
    }
}

/// The solution at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Evaluation {
    /// accelerations `q̈`
    pub qdd: Vec<f64>,
    /// multipliers `λ`, one per constraint row in order
    pub lambda: Vec<f64>,
    /// `Φ`, one per row
    pub phi: Vec<f64>,
    /// `Φ̇ = Φ_q q̇` (+ `Φ_t` for drivers), one per row
    pub phi_dot: Vec<f64>,
    /// iterations used
    pub iterations: usize,
}

impl System {
    /// Solves for `q̈` and `λ` at `(t, q, q̇)` with the constraints flagged `active`; `pairings`
    /// holds each contact's pairing (updated in place).
    pub fn evaluate(
        &self,
        al: &AugmentedLagrangian,
        t: f64,
        q: &[f64],
        qd: &[f64],
        active: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<Evaluation, DynamicsError> {
        let n = self.dofs();
        let mut rows: Vec<Row> = Vec::new();
        for (k, c) in self.constraints.iter().enumerate() {
            if !active[k] {
                continue;
            }
            let r = self
                .rows(c, t, q, qd, &mut pairings[k])
                .map_err(|source| DynamicsError::Contact { time: t, source })?;
            rows.extend(r);
        }
        let m = rows.len();
        let mut mass = DMatrix::zeros(n, n);
        let mut mmax: f64 = 0.0;
        for (i, b) in self.bodies.iter().enumerate() {
            mass[(3 * i, 3 * i)] = b.mass;
            mass[(3 * i + 1, 3 * i + 1)] = b.mass;
            mass[(3 * i + 2, 3 * i + 2)] = b.inertia;
            mmax = mmax.max(b.mass).max(b.inertia);
        }
        let mut jac = DMatrix::zeros(m, n);
        for (r, row) in rows.iter().enumerate() {
            for &(c, v) in &row.jac {
                jac[(r, c)] += v;
            }
        }
        let qdv = DVector::from_column_slice(qd);
        let mut phi_dot = &jac * &qdv;
        // a driver's Φ_t
        let mut r = 0;
        for (k, c) in self.constraints.iter().enumerate() {
            if !active[k] {
                continue;
            }
            if let Constraint::AngleDriver {
                speed,
                acceleration,
                ..
            } = c
            {
                phi_dot[r] -= speed + acceleration * t;
            }
            r += c.rows();
        }
        let alpha = al.penalty * mmax.max(1e-300);
        let gamma = DVector::from_iterator(m, rows.iter().map(|r| r.gamma));
        let phi = DVector::from_iterator(m, rows.iter().map(|r| r.phi));
        let stab = -&gamma + &phi_dot * (2.0 * al.xi * al.omega) + &phi * (al.omega * al.omega);
        let q_force = DVector::from_vec(self.forces(q, qd));
        let lhs = &mass + jac.transpose() * &jac * alpha;
        let chol = lhs.cholesky().ok_or(DynamicsError::Singular { time: t })?;
        let mut lambda = DVector::zeros(m);
        let scale = 1.0 + gamma.amax();
        for it in 1..=al.max_iterations {
            let rhs = &q_force - jac.transpose() * (&lambda + &stab * alpha);
            let qdd = chol.solve(&rhs);
            let res = &jac * &qdd + &stab;
            lambda += &res * alpha;
            if res.amax() <= al.tolerance * scale {
                // one more solve with the converged multipliers
                let rhs = &q_force - jac.transpose() * (&lambda + &stab * alpha);
                let qdd = chol.solve(&rhs);
                // λ from Φ_qᵀ λ = Q − M q̈ (least squares): the update λ* + α·residual would
                // amplify the residual's rounding by the penalty
                let jjt = &jac * jac.transpose();
                let lambda_final = match jjt.cholesky() {
                    Some(c) => c.solve(&(&jac * (&q_force - &mass * &qdd))),
                    None => lambda.clone() + (&jac * &qdd + &stab) * alpha,
                };
                return Ok(Evaluation {
                    qdd: qdd.as_slice().to_vec(),
                    lambda: lambda_final.as_slice().to_vec(),
                    phi: phi.as_slice().to_vec(),
                    phi_dot: phi_dot.as_slice().to_vec(),
                    iterations: it,
                });
            }
        }
        Err(DynamicsError::NoConvergence {
            time: t,
            iterations: al.max_iterations,
            residual: (&jac
                * chol.solve(&(&q_force - jac.transpose() * (&lambda + &stab * alpha)))
                + &stab)
                .amax(),
        })
    }
}
