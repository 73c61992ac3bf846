//! The augmented Lagrangian solve of the equations of motion at one instant.

use super::dense::{
    cholesky, cholesky_solve, dot, small, unit_padding, Buf, Dim, Fixed, MAT, SMALL, VEC,
};
use super::model::Model;
use super::DynamicsError;
use crate::contact::Pairing;

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

/// Where [`System::evaluate_into`] writes its solution: `q̈` (one per coordinate) and, one per
/// active constraint row in order, `λ`, `Φ` and `Φ̇` (each at least as long as the rows).
pub(crate) struct Solution<'a> {
    pub(crate) qdd: &'a mut [f64],
    pub(crate) lambda: &'a mut [f64],
    pub(crate) phi: &'a mut [f64],
    pub(crate) phi_dot: &'a mut [f64],
}

impl Model {
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
        let m = self.active_rows(active);
        let mut e = Evaluation {
            qdd: vec![0.0; self.dofs()],
            lambda: vec![0.0; m],
            phi: vec![0.0; m],
            phi_dot: vec![0.0; m],
            iterations: 0,
        };
        e.iterations = self.evaluate_into(
            al,
            t,
            q,
            qd,
            active,
            pairings,
            Solution {
                qdd: &mut e.qdd,
                lambda: &mut e.lambda,
                phi: &mut e.phi,
                phi_dot: &mut e.phi_dot,
            },
        )?;
        Ok(e)
    }

    /// The number of rows of the constraints flagged `active`.
    pub(crate) fn active_rows(&self, active: &[bool]) -> usize {
        self.constraints
            .iter()
            .zip(active)
            .filter(|(_, &a)| a)
            .map(|(c, _)| c.rows())
            .sum()
    }

    /// [`System::evaluate`] into `out`, without allocating for a system of up to six coordinates
    /// and six rows; the iterations used.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn evaluate_into(
        &self,
        al: &AugmentedLagrangian,
        t: f64,
        q: &[f64],
        qd: &[f64],
        active: &[bool],
        pairings: &mut [Option<Pairing>],
        out: Solution<'_>,
    ) -> Result<usize, DynamicsError> {
        let m = self.active_rows(active);
        // the cam-follower model at compile-time sizes, its rows padded to six: its loops unroll
        if small(self.dofs(), m) {
            self.evaluate_dim(
                Fixed::<SMALL>,
                Fixed::<SMALL>,
                m,
                al,
                t,
                q,
                qd,
                active,
                pairings,
                out,
            )
        } else {
            self.evaluate_dim(self.dofs(), m, m, al, t, q, qd, active, pairings, out)
        }
    }

    /// [`System::evaluate_into`] with the number of coordinates `dim`, the `m` active rows and
    /// `padded` rows (at least `m`; the rest are zero rows, whose multipliers are zero).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn evaluate_dim(
        &self,
        dim: impl Dim,
        padded: impl Dim,
        m: usize,
        al: &AugmentedLagrangian,
        t: f64,
        q: &[f64],
        qd: &[f64],
        active: &[bool],
        pairings: &mut [Option<Pairing>],
        out: Solution<'_>,
    ) -> Result<usize, DynamicsError> {
        let n = dim.get();
        let rows = padded.get();
        debug_assert!(m <= rows);
        // Φ_q (rows × n, row-major), γ, Φ and Φ̇ (with a driver's Φ_t)
        // each buffer taken as a slice once (not through the buffer at every access)
        let mut jac_buf = Buf::<MAT>::zeros(rows * n);
        let jac: &mut [f64] = &mut jac_buf;
        let mut gamma_buf = Buf::<VEC>::zeros(rows);
        let gamma: &mut [f64] = &mut gamma_buf;
        let phi = &mut out.phi[..m];
        let phi_dot = &mut out.phi_dot[..m];
        let mut r = 0;
        for (k, c) in self.constraints.iter().enumerate() {
            if !active[k] {
                continue;
            }
            let rows = self
                .rows(c, t, q, qd, &mut pairings[k])
                .map_err(|source| DynamicsError::Contact { time: t, source })?;
            for row in rows.iter() {
                for &(col, v) in row.jac() {
                    jac[r * n + col] += v;
                }
                gamma[r] = row.gamma;
                phi[r] = row.phi;
                phi_dot[r] = dot(&jac[r * n..(r + 1) * n], qd) - c.target_rate(t);
                r += 1;
            }
        }
        let mut mass_buf = Buf::<VEC>::zeros(n);
        let mass: &mut [f64] = &mut mass_buf;
        let mut mmax: f64 = 0.0;
        for (i, b) in self.bodies.iter().enumerate() {
            mass[3 * i] = b.mass;
            mass[3 * i + 1] = b.mass;
            mass[3 * i + 2] = b.inertia;
            mmax = mmax.max(b.mass).max(b.inertia);
        }
        let alpha = al.penalty * mmax.max(1e-300);
        let (c1, c2) = (2.0 * al.xi * al.omega, al.omega * al.omega);
        let mut stab_buf = Buf::<VEC>::zeros(rows);
        let stab: &mut [f64] = &mut stab_buf;
        for i in 0..m {
            stab[i] = -gamma[i] + phi_dot[i] * c1 + phi[i] * c2;
        }
        let mut q_force_buf = Buf::<VEC>::zeros(n);
        let q_force: &mut [f64] = &mut q_force_buf;
        self.forces(q, qd, q_force);
        let inputs = Inputs {
            n,
            m,
            jac,
            gamma,
            mass,
            stab,
            q_force,
            alpha,
        };
        let mut lambda_buf = Buf::<VEC>::zeros(rows);
        let lambda: &mut [f64] = &mut lambda_buf;
        let iterations = al_iterate(&inputs, dim, padded, al, t, lambda, out.qdd)?;
        out.lambda[..m].copy_from_slice(&lambda[..m]);
        Ok(iterations)
    }
}

/// What the augmented Lagrangian iteration works on: `n` coordinates, `m` rows (padded with zero
/// rows to the iteration's row count), `Φ_q` (`jac`, rows × `n`, row-major), `γ`, the mass diagonal, the stabilised right-hand side `stab`, the
/// forces `Q` and the penalty `α`.
struct Inputs<'a> {
    n: usize,
    m: usize,
    jac: &'a [f64],
    gamma: &'a [f64],
    mass: &'a [f64],
    stab: &'a [f64],
    q_force: &'a [f64],
    alpha: f64,
}

/// The augmented Lagrangian iteration (see the [module docs](super)): `λ` and `q̈` written, the
/// iterations used.
#[inline(always)]
fn al_iterate(
    inputs: &Inputs<'_>,
    dim: impl Dim,
    padded: impl Dim,
    al: &AugmentedLagrangian,
    t: f64,
    lambda: &mut [f64],
    qdd: &mut [f64],
) -> Result<usize, DynamicsError> {
    let &Inputs {
        n,
        m,
        jac,
        gamma,
        mass,
        stab,
        q_force,
        alpha,
    } = inputs;
    debug_assert_eq!(n, dim.get());
    let (n, real, m) = (dim.get(), m, padded.get());
    // the slices at their lengths (so that the loops over `n` need no bounds checks)
    let (jac, mass, q_force, qdd) = (&jac[..m * n], &mass[..n], &q_force[..n], &mut qdd[..n]);
    let (gamma, stab, lambda) = (&gamma[..m], &stab[..m], &mut lambda[..m]);
    let row = |r: usize| &jac[r * n..(r + 1) * n];
    // M + α Φ_qᵀ Φ_q, its lower triangle (all that the factorisation reads), factorised
    let mut lhs_buf = Buf::<MAT>::zeros(n * n);
    let lhs: &mut [f64] = &mut lhs_buf[..n * n];
    for r in 0..m {
        let jr = row(r);
        for i in 0..n {
            let a = jr[i];
            if a != 0.0 {
                for j in 0..i + 1 {
                    lhs[i * n + j] += a * jr[j];
                }
            }
        }
    }
    for i in 0..n {
        for j in 0..i + 1 {
            lhs[i * n + j] *= alpha;
        }
        lhs[i * n + i] += mass[i];
    }
    if !cholesky(lhs, dim) {
        return Err(DynamicsError::Singular { time: t });
    }
    let lhs: &[f64] = lhs;
    lambda.fill(0.0);
    let amax = |v: &[f64]| v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    debug_assert_eq!(lambda.len(), m);
    let scale = 1.0 + amax(gamma);
    // q̈ from Q − Φ_qᵀ (λ + α stab)
    let solve = |lambda: &[f64], qdd: &mut [f64]| {
        qdd.copy_from_slice(q_force);
        for r in 0..m {
            let w = lambda[r] + stab[r] * alpha;
            for (x, a) in qdd.iter_mut().zip(row(r)) {
                *x -= a * w;
            }
        }
        cholesky_solve(lhs, dim, qdd);
    };
    let residual = |qdd: &[f64], res: &mut [f64]| {
        for (r, x) in res.iter_mut().enumerate() {
            *x = dot(row(r), qdd) + stab[r];
        }
    };
    let mut res_buf = Buf::<VEC>::zeros(m);
    let res: &mut [f64] = &mut res_buf;
    for it in 1..=al.max_iterations {
        solve(lambda, qdd);
        residual(qdd, res);
        for (l, x) in lambda.iter_mut().zip(res.iter()) {
            *l += x * alpha;
        }
        if amax(res) <= al.tolerance * scale {
            // one more solve with the converged multipliers
            solve(lambda, qdd);
            // λ from Φ_qᵀ λ = Q − M q̈ (least squares): the update λ* + α·residual would
            // amplify the residual's rounding by the penalty
            // (its lower triangle: all that the factorisation reads)
            let mut jjt = Buf::<MAT>::zeros(m * m);
            for (a, ja) in jjt.chunks_exact_mut(m).enumerate() {
                for (b, x) in ja[..=a].iter_mut().enumerate() {
                    *x = dot(row(a), row(b));
                }
            }
            // a padded row's multiplier: zero (its row and right-hand side are zero)
            unit_padding(&mut jjt, m, real);
            if cholesky(&mut jjt, padded) {
                // Q − M q̈, then Φ_q times it
                let mut f = Buf::<VEC>::zeros(n);
                for (j, x) in f.iter_mut().enumerate() {
                    *x = q_force[j] - mass[j] * qdd[j];
                }
                let mut rhs = Buf::<VEC>::zeros(m);
                for (r, x) in rhs.iter_mut().enumerate() {
                    *x = dot(row(r), &f);
                }
                cholesky_solve(&jjt, padded, &mut rhs);
                lambda.copy_from_slice(&rhs);
            } else {
                residual(qdd, res);
                for (l, x) in lambda.iter_mut().zip(res.iter()) {
                    *l += x * alpha;
                }
            }
            return Ok(it);
        }
    }
    solve(lambda, qdd);
    residual(qdd, res);
    Err(DynamicsError::NoConvergence {
        time: t,
        iterations: al.max_iterations,
        residual: amax(res),
    })
}

#[cfg(test)]
mod tests {
    //! The augmented Lagrangian on its own: closed-form motions under an applied torque and
    //! gravity.
    use super::super::model::{Constraint, Load, Model, RigidBody};
    use super::AugmentedLagrangian;
    use crate::system::{BodyId, ForceKind, JointKind};
    use crate::{Point2, Vec2};

    fn pinned(body: RigidBody, at: Point2, ground: Point2, force: Load) -> Model {
        Model {
            bodies: vec![body],
            constraints: vec![Constraint::Joint(JointKind::Revolute {
                a: BodyId::GROUND,
                at_a: ground,
                b: BodyId(0),
                at_b: at,
            })],
            forces: vec![force],
            search: crate::contact::SearchOptions::default(),
        }
    }

    #[test]
    fn applied_torque_on_a_pinned_disc() {
        // a disc pinned at its centre under a torque of 3 (a torsion spring of no stiffness
        // whose preload −3 turns its second body counter-clockwise): θ̈ = τ / I, and the pin
        // carries no force
        let s = pinned(
            RigidBody {
                mass: 2.0,
                inertia: 0.5,
            },
            Point2::origin(),
            Point2::new(1.0, 2.0),
            Load::Element(ForceKind::TorsionSpring {
                a: BodyId::GROUND,
                b: BodyId(0),
                stiffness: 0.0,
                free_angle: 0.0,
                preload: -3.0,
            }),
        );
        let e = s
            .evaluate(
                &AugmentedLagrangian::default(),
                0.0,
                &[1.0, 2.0, 0.3],
                &[0.0, 0.0, 4.0],
                &[true],
                &mut [None],
            )
            .expect("solved");
        assert!((e.qdd[2] - 6.0).abs() < 1e-12, "{:?}", e.qdd);
        assert!(e.qdd[0].abs() < 1e-12 && e.qdd[1].abs() < 1e-12);
        assert!(e.lambda.iter().all(|l| l.abs() < 1e-9), "{:?}", e.lambda);
    }

    #[test]
    fn pendulum_under_gravity() {
        // a point mass m on a massless arm of length l pinned at the origin, angle θ from +x:
        // θ̈ = −(g/l) cos θ (gravity −y); the body frame at the mass, the pin at (−l, 0) in it
        let (m, l, g) = (1.5, 0.8, 9.81);
        let s = pinned(
            RigidBody {
                mass: m,
                inertia: 1e-12,
            },
            Point2::new(-l, 0.0),
            Point2::origin(),
            Load::Gravity(Vec2::new(0.0, -g)),
        );
        for (th, w) in [(0.3f64, 1.0f64), (-1.0, -2.0), (2.0, 0.5)] {
            let q = [l * th.cos(), l * th.sin(), th];
            let qd = [-l * w * th.sin(), l * w * th.cos(), w];
            let e = s
                .evaluate(
                    &AugmentedLagrangian::default(),
                    0.0,
                    &q,
                    &qd,
                    &[true],
                    &mut [None],
                )
                .expect("solved");
            let expect = -(g / l) * th.cos();
            assert!(
                (e.qdd[2] - expect).abs() < 1e-6 * expect.abs().max(1.0),
                "θ̈ {} vs {expect}",
                e.qdd[2],
            );
        }
    }
}
