//! The equations of motion of a simulated system at a state: solved directly by the Schur
//! complement (with one step of iterative refinement), or by the augmented Lagrangian where rows
//! are dependent; the last evaluation kept, and the buffers evaluations reuse.

use super::super::model::{Constraint, Row};
use super::super::DynamicsError;
use super::sparse::Schur;
use super::SystemSimulation;
use crate::contact::Pairing;

/// An evaluation of the equations of motion: `q̈`, each contact's compressive force, the
/// power of each channel of work ([`super::balance`]) and each driver's effort.
#[derive(Debug, Clone, Default)]
pub(crate) struct Accel {
    pub(crate) qdd: Vec<f64>,
    pub(crate) forces: Vec<f64>,
    pub(crate) powers: Vec<f64>,
    pub(crate) efforts: Vec<f64>,
}

impl Accel {
    /// `other` copied in, this one's buffers reused.
    pub(super) fn copy_from(&mut self, other: &Accel) {
        self.qdd.clone_from(&other.qdd);
        self.forces.clone_from(&other.forces);
        self.powers.clone_from(&other.powers);
        self.efforts.clone_from(&other.efforts);
    }
}

/// Buffers a step reuses from one evaluation to the next (nothing of them outlives a call).
#[derive(Debug, Clone, Default)]
pub(crate) struct Scratch {
    /// the active rows, sparse
    pub(super) rows: Vec<Row>,
    /// their stabilised right-hand sides `γ̃` (in a projection, the rates they must have)
    pub(super) rhs: Vec<f64>,
    /// the rows' `Φ` (a projection's)
    pub(super) phi: Vec<f64>,
    /// which constraints hold
    pub(super) active: Vec<bool>,
    /// the multipliers
    pub(super) lambda: Vec<f64>,
    /// the residual of the refinement step
    pub(super) delta: Vec<f64>,
    /// the Schur complement's factor
    pub(super) schur: Schur,
    /// the rows' Schur complement without masses, factored to tell a singular pose
    pub(super) geometry: Schur,
    /// each lash adjuster's power, from the forces the direct solution applied
    pub(super) adjuster_powers: Vec<f64>,
}

/// An evaluation kept: the state and modes it was at, the pairings it started from and ended
/// with, and its answer.
#[derive(Debug, Clone, Default)]
pub(crate) struct Evaluated {
    t: f64,
    q: Vec<f64>,
    qd: Vec<f64>,
    z: Vec<f64>,
    modes: Vec<bool>,
    before: Vec<Option<Pairing>>,
    after: Vec<Option<Pairing>>,
    answer: Accel,
}

impl SystemSimulation<'_> {
    /// The equations of motion at a state (`z` the lash adjusters' pressures) in the modes
    /// `in_contact` (see [`Accel`]): a driver's effort is the force (or torque) it applies
    /// along its coordinate, `−λ`.
    pub(super) fn accel(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        z: &[f64],
        in_contact: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<Accel, DynamicsError> {
        let mut out = Accel::default();
        self.accel_into(t, q, qd, z, in_contact, pairings, &mut out)?;
        Ok(out)
    }

    /// [`SystemSimulation::accel`] written into `out` (its buffers reused).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn accel_into(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        z: &[f64],
        in_contact: &[bool],
        pairings: &mut [Option<Pairing>],
        out: &mut Accel,
    ) -> Result<(), DynamicsError> {
        // the same state, asked again from the pairings it started from or ended with
        // (only the closed contacts' pairings enter it: a flying contact's is followed apart)
        if let Some(e) = self.last.borrow().as_ref() {
            let same = |kept: &[Option<Pairing>]| {
                in_contact
                    .iter()
                    .enumerate()
                    .filter(|(_, &closed)| closed)
                    .all(|(k, _)| {
                        let i = self.first_contact + k;
                        kept[i] == pairings[i]
                    })
            };
            if e.t == t
                && e.q == q
                && e.qd == qd
                && e.z == z
                && e.modes == in_contact
                && (same(&e.before) || same(&e.after))
            {
                for (k, &closed) in in_contact.iter().enumerate() {
                    if closed {
                        let i = self.first_contact + k;
                        pairings[i] = e.after[i];
                    }
                }
                out.copy_from(&e.answer);
                return Ok(());
            }
        }
        // the kept evaluation's buffers are reused: marked stale (its time NaN) until the new
        // one has succeeded
        {
            let mut last = self.last.borrow_mut();
            let e = last.get_or_insert_with(Evaluated::default);
            e.t = f64::NAN;
            e.before.clear();
            e.before.extend_from_slice(pairings);
        }
        self.evaluate(t, q, qd, z, in_contact, pairings, out)?;
        if let Some(e) = self.last.borrow_mut().as_mut() {
            e.t = t;
            e.q.clear();
            e.q.extend_from_slice(q);
            e.qd.clear();
            e.qd.extend_from_slice(qd);
            e.z.clear();
            e.z.extend_from_slice(z);
            e.modes.clear();
            e.modes.extend_from_slice(in_contact);
            e.after.clear();
            e.after.extend_from_slice(pairings);
            e.answer.copy_from(out);
        }
        Ok(())
    }

    /// [`SystemSimulation::accel_into`] computed.
    #[allow(clippy::too_many_arguments)]
    fn evaluate(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        z: &[f64],
        in_contact: &[bool],
        pairings: &mut [Option<Pairing>],
        out: &mut Accel,
    ) -> Result<(), DynamicsError> {
        let (mut active, mut lambda) = {
            let mut s = self.scratch.borrow_mut();
            (std::mem::take(&mut s.active), std::mem::take(&mut s.lambda))
        };
        self.active_into(in_contact, &mut active);
        // (an early return leaves the buffers to be made again)
        let mut singular_pose = false;
        let (mut solved, mut applied) = self.direct(
            t,
            q,
            qd,
            z,
            &active,
            pairings,
            &mut out.qdd,
            &mut lambda,
            false,
            &mut singular_pose,
        )?;
        // whether the scratch's rows are the ones solved (for the constraint forces' power)
        let mut direct = solved;
        if !solved {
            // dependent rows: a redundant joint, which the augmented Lagrangian answers exactly
            // (its matrix stays positive definite there) — but not with forces from tables,
            // applied loads or centres away from the frames, which are not in the model it
            // solves — or a singular pose, where the rows are not consistent and it does not
            // converge: the Schur complement damped there
            let plain = self.sys.table_forces().is_empty()
                && self.sys.loads().is_empty()
                && self.sys.lash_adjusters().is_empty()
                && !self.offset
                && !singular_pose;
            let al = plain.then(|| {
                self.model
                    .evaluate(&self.opts.al, t, q, qd, &active, pairings)
            });
            match al {
                Some(Ok(e)) => (out.qdd, lambda) = (e.qdd, e.lambda),
                None | Some(Err(DynamicsError::NoConvergence { .. })) => {
                    (solved, applied) = self.direct(
                        t,
                        q,
                        qd,
                        z,
                        &active,
                        pairings,
                        &mut out.qdd,
                        &mut lambda,
                        true,
                        &mut singular_pose,
                    )?;
                    if !solved {
                        return Err(DynamicsError::Singular { time: t });
                    }
                    direct = true;
                }
                Some(Err(e)) => return Err(e),
            }
        }
        // λ row by row over the active constraints: a driver's force on its coordinate is −λ,
        // a contact's compressive force −λ (its row is the gap, positive apart)
        out.forces.clear();
        out.forces.resize(in_contact.len(), 0.0);
        out.efforts.clear();
        out.powers.clear();
        out.powers.resize(self.channels(), 0.0);
        // the drivers' power, and the joints' and contacts' `−λ Φ_q q̇` over their rows
        let (mut r, mut drivers, mut constraints) = (0, 0.0, 0.0);
        let s = self.scratch.borrow();
        for (k, c) in self.model.constraints.iter().enumerate() {
            if !active[k] {
                continue;
            }
            if let Constraint::Driver {
                body, coordinate, ..
            } = c
            {
                // the driven coordinate's rate: its frame's
                let rate = match coordinate {
                    crate::system::Coordinate::Angle => qd[3 * body + 2],
                    crate::system::Coordinate::X => self.frame_state(q, qd, *body).velocity.x,
                    crate::system::Coordinate::Y => self.frame_state(q, qd, *body).velocity.y,
                };
                drivers -= lambda[r] * rate;
                out.efforts.push(-lambda[r]);
            } else if direct {
                let span = r..r + c.rows();
                for (row, l) in s.rows[span.clone()].iter().zip(&lambda[span]) {
                    let rate: f64 = row.jac().iter().map(|&(col, v)| v * qd[col]).sum();
                    constraints -= l * rate;
                }
            }
            if k >= self.first_contact {
                let c = k - self.first_contact;
                out.forces[c] = -self.sense[c] * lambda[r];
            }
            r += c.rows();
        }
        drop(s);
        if !direct {
            // the constraint forces' power from `M q̈ − Q` (the augmented Lagrangian's rows are
            // not kept), less the drivers'
            let mut f = vec![0.0; q.len()];
            self.model.forces(q, qd, &mut f);
            let all: f64 = (0..q.len())
                .map(|i| qd[i] * (out.qdd[i] / self.inv_mass[i] - f[i]))
                .sum();
            constraints = all - drivers;
        }
        out.powers[super::balance::DRIVERS] = drivers;
        out.powers[super::balance::APPLIED] = applied;
        out.powers[super::balance::CONSTRAINTS] = constraints;
        self.element_powers(q, qd, &mut out.powers);
        let mut s = self.scratch.borrow_mut();
        // the adjusters' powers (the direct solution, the only one with adjusters, applied
        // their forces), after the force elements' and gravity's channels
        let from = super::balance::ELEMENTS + self.model.forces.len();
        out.powers[from..from + z.len()].copy_from_slice(&s.adjuster_powers);
        (s.active, s.lambda) = (active, lambda);
        Ok(())
    }

    /// The equations of motion `M q̈ + Φ_qᵀ λ = Q`, `Φ_q q̈ = γ − 2ξΩ Φ̇ − Ω² Φ` solved directly
    /// by the Schur complement: `(Φ_q M⁻¹ Φ_qᵀ) λ = Φ_q M⁻¹ Q − γ̃` (Cholesky; a symmetric
    /// diagonal scaling does not change its accuracy, so masses a hundred thousand times apart
    /// cost nothing), `q̈ = M⁻¹ (Q − Φ_qᵀ λ)`, written to `qdd` and `lambda`; whether it was
    /// solved (not where the rows are dependent: `qdd` is then `Q`, the rows and their `γ̃` in
    /// the scratch), and the table forces' and loads' power. `regularise`: `S` damped
    /// (`Schur::factor_regularised`: at a singular pose); `singular_pose` set where it was not
    /// solved because the rows are at one.
    #[allow(clippy::too_many_arguments)]
    fn direct(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        z: &[f64],
        active: &[bool],
        pairings: &mut [Option<Pairing>],
        qdd: &mut Vec<f64>,
        lambda: &mut Vec<f64>,
        regularise: bool,
        singular_pose: &mut bool,
    ) -> Result<(bool, f64), DynamicsError> {
        let n = q.len();
        let al = &self.opts.al;
        let (c1, c2) = (2.0 * al.xi * al.omega, al.omega * al.omega);
        let (qf, qdf) = self.frames(q, qd);
        let arms = self.arms(q);
        // the active rows, sparse (at most six entries each), and their γ̃
        let mut guard = self.scratch.borrow_mut();
        let Scratch {
            rows: sparse,
            rhs,
            delta,
            schur,
            geometry,
            adjuster_powers,
            ..
        } = &mut *guard;
        sparse.clear();
        rhs.clear();
        for (k, c) in self.model.constraints.iter().enumerate() {
            if !active[k] {
                continue;
            }
            let from = sparse.len();
            self.model
                .push_rows(c, t, &qf, &qdf, &mut pairings[k], sparse)
                .map_err(|source| DynamicsError::Contact { time: t, source })?;
            for row in &mut sparse[from..] {
                self.row_about_centres(&arms, qd, row);
                let phi_dot: f64 =
                    row.jac().iter().map(|&(col, v)| v * qd[col]).sum::<f64>() - c.target_rate(t);
                rhs.push(row.gamma - c1 * phi_dot - c2 * row.phi);
            }
        }
        let inv_mass = &self.inv_mass;
        // Q, then q̈ in its place
        let force = qdd;
        force.clear();
        force.resize(n, 0.0);
        self.model.forces(&qf, &qdf, force);
        adjuster_powers.clear();
        adjuster_powers.resize(z.len(), 0.0);
        self.add_adjuster_forces(&qf, &qdf, z, force, adjuster_powers);
        let gas_power = self.add_table_forces(t, &qf, &qdf, force);
        self.forces_about_centres(q, force);
        let factored = if regularise {
            schur.factor_regularised(sparse, inv_mass)
        } else {
            match self.factor_rows(schur, geometry, sparse) {
                super::singular::Factored::Yes => true,
                super::singular::Factored::SingularPose => {
                    *singular_pose = true;
                    false
                }
                super::singular::Factored::Dependent => false,
            }
        };
        if !factored {
            return Ok((false, gas_power));
        }
        // S λ = Φ_q M⁻¹ Q − γ̃
        lambda.clear();
        lambda.extend(sparse.iter().zip(rhs.iter()).map(|(row, &g)| {
            row.jac()
                .iter()
                .map(|&(col, v)| v * inv_mass[col] * force[col])
                .sum::<f64>()
                - g
        }));
        schur.solve(lambda);
        let qdd = force;
        for (row, &l) in sparse.iter().zip(lambda.iter()) {
            for &(col, v) in row.jac() {
                qdd[col] -= v * l;
            }
        }
        for (x, w) in qdd.iter_mut().zip(inv_mass) {
            *x *= w;
        }
        // one step of iterative refinement: `q̈ = M⁻¹ (Q − Φ_qᵀ λ)` is a difference of forces
        // that can be far larger than the accelerations they leave (a stiff spring's force
        // against the contact's), so `Φ_q q̈` misses `γ̃` by their rounding; the residual,
        // solved with the same factor, puts the accelerations on their rows to their own
        // rounding (a follower in contact then moves as the kinematics to 1e-13 of its peak)
        delta.clear();
        delta.extend(
            sparse
                .iter()
                .zip(rhs.iter())
                .map(|(row, &g)| g - row.jac().iter().map(|&(c, v)| v * qdd[c]).sum::<f64>()),
        );
        schur.solve(delta);
        for ((row, &d), l) in sparse.iter().zip(delta.iter()).zip(lambda.iter_mut()) {
            *l -= d;
            for &(col, v) in row.jac() {
                qdd[col] += inv_mass[col] * v * d;
            }
        }
        Ok((true, gas_power))
    }

    /// Adds the forces from tables of the crank angle and the applied loads at `t` to `f`;
    /// their power.
    fn add_table_forces(&self, t: f64, q: &[f64], qd: &[f64], f: &mut [f64]) -> f64 {
        let loads: f64 = self
            .sys
            .loads()
            .iter()
            .map(|l| {
                let s = super::super::model::body_state(q, qd, l.body.0);
                l.add_force(t, s.pose, (s.velocity, s.omega), f)
            })
            .sum();
        let forces = self.sys.table_forces();
        let Some(d) = self.sys.drivers().first() else {
            return loads;
        };
        if forces.is_empty() {
            return loads;
        }
        let [angle, ..] = d.law.at(t);
        let start = d.law.at(0.0)[0];
        let driver_deg = (angle - start).to_degrees();
        loads
            + forces
                .iter()
                .map(|g| {
                    let s = super::super::model::body_state(q, qd, g.body.0);
                    g.add_force(driver_deg, s.pose, (s.velocity, s.omega), f)
                })
                .sum::<f64>()
    }
}
