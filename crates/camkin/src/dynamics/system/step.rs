//! A simulated system's steps: the equations of motion at a state (solved directly, or by the
//! augmented Lagrangian where rows are dependent), RK4, the projection onto the rows, and the
//! events inside a step (lift-offs by bisection on the force, impacts by bisection on the gap).

use super::super::follower::{EventKind, REBOUND_TOLERANCE};
use super::super::model::{Constraint, Row};
use super::super::projection::DenseRows;
use super::super::DynamicsError;
use super::sparse::{self, Schur};
use super::{ContactEvent, SystemSimulation, MAX_EVENTS};
use crate::contact::{self, Pairing, Surface};

/// `(q̈, each contact's compressive force, the drivers' power, each driver's effort)`.
type Accel = (Vec<f64>, Vec<f64>, f64, Vec<f64>);

/// Buffers a step reuses from one evaluation to the next (nothing of them outlives a call).
#[derive(Debug, Clone, Default)]
pub(crate) struct Scratch {
    /// the active rows, sparse
    rows: Vec<Row>,
    /// their stabilised right-hand sides `γ̃`
    rhs: Vec<f64>,
    /// which constraints hold
    active: Vec<bool>,
    /// the residual of the refinement step
    delta: Vec<f64>,
    /// the Schur complement's factor
    schur: Schur,
}

/// An evaluation kept: the state and modes it was at, the pairings it started from and ended
/// with, and its answer.
#[derive(Debug, Clone, Default)]
pub(crate) struct Evaluated {
    t: f64,
    q: Vec<f64>,
    qd: Vec<f64>,
    modes: Vec<bool>,
    before: Vec<Option<Pairing>>,
    after: Vec<Option<Pairing>>,
    answer: Accel,
}

impl SystemSimulation<'_> {
    /// `(q̈, each contact's compressive force, the drivers' power, each driver's effort)` at a
    /// state in the modes `in_contact`: a driver's effort is the force (or torque) it applies
    /// along its coordinate, `−λ`.
    pub(super) fn accel(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        in_contact: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<Accel, DynamicsError> {
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
                && e.modes == in_contact
                && (same(&e.before) || same(&e.after))
            {
                for (k, &closed) in in_contact.iter().enumerate() {
                    if closed {
                        let i = self.first_contact + k;
                        pairings[i] = e.after[i];
                    }
                }
                return Ok(e.answer.clone());
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
        let answer = self.evaluate(t, q, qd, in_contact, pairings)?;
        if let Some(e) = self.last.borrow_mut().as_mut() {
            e.t = t;
            e.q.clear();
            e.q.extend_from_slice(q);
            e.qd.clear();
            e.qd.extend_from_slice(qd);
            e.modes.clear();
            e.modes.extend_from_slice(in_contact);
            e.after.clear();
            e.after.extend_from_slice(pairings);
            e.answer.0.clone_from(&answer.0);
            e.answer.1.clone_from(&answer.1);
            e.answer.2 = answer.2;
            e.answer.3.clone_from(&answer.3);
        }
        Ok(answer)
    }

    /// [`SystemSimulation::accel`] computed.
    fn evaluate(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        in_contact: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<Accel, DynamicsError> {
        let mut active = std::mem::take(&mut self.scratch.borrow_mut().active);
        self.active_into(in_contact, &mut active);
        // (an early return leaves the buffer to be made again)
        let (qdd, lambda, gas_power) = match self.direct(t, q, qd, &active, pairings)? {
            Some(x) => x,
            // forces from tables of the crank angle are not in the model the augmented
            // Lagrangian solves: dependent rows with them are refused, not answered without them
            None if !self.sys.table_forces().is_empty() => {
                return Err(DynamicsError::Singular { time: t });
            }
            // nor are centres of mass away from the frames' origins
            None if self.offset => return Err(DynamicsError::Singular { time: t }),
            // dependent rows (a redundant joint): the augmented Lagrangian, whose matrix stays
            // positive definite there
            None => {
                let e = self
                    .model
                    .evaluate(&self.opts.al, t, q, qd, &active, pairings)?;
                (e.qdd, e.lambda, 0.0)
            }
        };
        // λ row by row over the active constraints: a driver's force on its coordinate is −λ,
        // a contact's compressive force −λ (its row is the gap, positive apart)
        let mut forces = vec![0.0; in_contact.len()];
        let mut efforts = Vec::with_capacity(self.sys.drivers().len());
        // the drivers' power and the table forces' (their work is the drivers' column's too)
        let (mut r, mut power) = (0, gas_power);
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
                power -= lambda[r] * rate;
                efforts.push(-lambda[r]);
            }
            if k >= self.first_contact {
                let c = k - self.first_contact;
                forces[c] = -self.sense[c] * lambda[r];
            }
            r += c.rows();
        }
        self.scratch.borrow_mut().active = active;
        Ok((qdd, forces, power, efforts))
    }

    /// The equations of motion `M q̈ + Φ_qᵀ λ = Q`, `Φ_q q̈ = γ − 2ξΩ Φ̇ − Ω² Φ` solved directly
    /// by the Schur complement: `(Φ_q M⁻¹ Φ_qᵀ) λ = Φ_q M⁻¹ Q − γ̃` (Cholesky; a symmetric
    /// diagonal scaling does not change its accuracy, so masses a hundred thousand times apart
    /// cost nothing), `q̈ = M⁻¹ (Q − Φ_qᵀ λ)`. `None` where the rows are dependent.
    #[allow(clippy::type_complexity)]
    fn direct(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        active: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<Option<(Vec<f64>, Vec<f64>, f64)>, DynamicsError> {
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
            ..
        } = &mut *guard;
        sparse.clear();
        rhs.clear();
        for (k, c) in self.model.constraints.iter().enumerate() {
            if !active[k] {
                continue;
            }
            let rows = self
                .model
                .rows(c, t, &qf, &qdf, &mut pairings[k])
                .map_err(|source| DynamicsError::Contact { time: t, source })?;
            for row in rows.iter() {
                let mut row = *row;
                self.row_about_centres(&arms, qd, &mut row);
                let phi_dot: f64 =
                    row.jac().iter().map(|&(col, v)| v * qd[col]).sum::<f64>() - c.target_rate(t);
                rhs.push(row.gamma - c1 * phi_dot - c2 * row.phi);
                sparse.push(row);
            }
        }
        let inv_mass = &self.inv_mass;
        let mut force = vec![0.0; n];
        self.model.forces(&qf, &qdf, &mut force);
        let gas_power = self.add_table_forces(t, &qf, &qdf, &mut force);
        self.forces_about_centres(q, &mut force);
        if !schur.factor(sparse, inv_mass) {
            return Ok(None);
        }
        // S λ = Φ_q M⁻¹ Q − γ̃
        let mut lambda: Vec<f64> = sparse
            .iter()
            .zip(rhs.iter())
            .map(|(row, &g)| {
                row.jac()
                    .iter()
                    .map(|&(col, v)| v * inv_mass[col] * force[col])
                    .sum::<f64>()
                    - g
            })
            .collect();
        schur.solve(&mut lambda);
        let mut qdd = force;
        for (row, &l) in sparse.iter().zip(&lambda) {
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
        Ok(Some((qdd, lambda, gas_power)))
    }

    /// One RK4 step of `h` from the current state in the current modes: the state at its end,
    /// the pairings there and the drivers' work over it.
    #[allow(clippy::type_complexity)]
    fn rk4(
        &self,
        h: f64,
    ) -> Result<(Vec<f64>, Vec<f64>, Vec<Option<Pairing>>, f64), DynamicsError> {
        let (t, q, qd, modes) = (self.t, &self.q, &self.qd, &self.in_contact);
        let mut p = self.pairings.clone();
        let add = |a: &[f64], b: &[f64], s: f64| -> Vec<f64> {
            a.iter().zip(b).map(|(x, y)| x + s * y).collect()
        };
        let (a1, _, w1, _) = self.accel(t, q, qd, modes, &mut p)?;
        let (q2, v2) = (add(q, qd, 0.5 * h), add(qd, &a1, 0.5 * h));
        let (a2, _, w2, _) = self.accel(t + 0.5 * h, &q2, &v2, modes, &mut p)?;
        let (q3, v3) = (add(q, &v2, 0.5 * h), add(qd, &a2, 0.5 * h));
        let (a3, _, w3, _) = self.accel(t + 0.5 * h, &q3, &v3, modes, &mut p)?;
        let (q4, v4) = (add(q, &v3, h), add(qd, &a3, h));
        let (a4, _, w4, _) = self.accel(t + h, &q4, &v4, modes, &mut p)?;
        let n = q.len();
        let qn = (0..n)
            .map(|i| q[i] + h / 6.0 * (qd[i] + 2.0 * v2[i] + 2.0 * v3[i] + v4[i]))
            .collect();
        let vn = (0..n)
            .map(|i| qd[i] + h / 6.0 * (a1[i] + 2.0 * a2[i] + 2.0 * a3[i] + a4[i]))
            .collect();
        Ok((qn, vn, p, h / 6.0 * (w1 + 2.0 * w2 + 2.0 * w3 + w4)))
    }

    /// Contact `k`'s gap at the state `(q, q̇)` along the common normal of its nearest points
    /// (Newton from its pairing, kept).
    pub(super) fn gap(
        &self,
        q: &[f64],
        qd: &[f64],
        k: usize,
        pairings: &mut [Option<Pairing>],
    ) -> Result<f64, DynamicsError> {
        let c = &self.sys.contacts()[k];
        let (sa, sb) = (
            self.frame_state(q, qd, c.a.0),
            self.frame_state(q, qd, c.b.0),
        );
        let slot = &mut pairings[self.first_contact + k];
        // every contact's pairing is found when the simulation starts
        let p0 = slot.ok_or(DynamicsError::Contact {
            time: self.t,
            source: crate::contact::ContactError::Unsupported("a contact without a pairing"),
        })?;
        let p = contact::refine(
            &Surface::new(c.curve_a.as_ref(), &sa),
            &Surface::new(c.curve_b.as_ref(), &sb),
            p0.u_a,
            p0.u_b,
            &self.model.search,
        )
        .map_err(|source| DynamicsError::Contact {
            time: self.t,
            source,
        })?;
        *slot = Some(p);
        Ok(self.sense[k] * p.gap)
    }

    /// The active rows at `(q, q̇)` as dense rows.
    pub(super) fn dense(
        &self,
        q: &[f64],
        qd: &[f64],
        in_contact: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<DenseRows, DynamicsError> {
        let (qf, qdf) = self.frames(q, qd);
        let mut rows = self
            .model
            .dense_rows(self.t, &qf, &qdf, &self.active(in_contact), pairings)
            .map_err(|source| DynamicsError::Contact {
                time: self.t,
                source,
            })?;
        self.dense_about_centres(q, &mut rows);
        Ok(rows)
    }

    /// Positions by Newton onto the active rows (mass-orthogonal), then velocities onto
    /// `Φ_q q̇ = −Φ_t`.
    pub(super) fn project(&mut self) -> Result<(), DynamicsError> {
        let mut pairings = self.pairings.clone();
        let modes = self.in_contact.clone();
        // the factor's buffers are the evaluations' (none is running now)
        let mut schur = std::mem::take(&mut self.scratch.get_mut().schur);
        let done = self.project_with(&mut schur, &modes, &mut pairings);
        self.scratch.get_mut().schur = schur;
        match done? {
            true => {
                self.pairings = pairings;
                Ok(())
            }
            false => self.project_dense(),
        }
    }

    /// [`SystemSimulation::project`] with `schur`'s buffers; `false` where the rows are
    /// dependent (the positions as far as they were moved: the dense projection goes on from
    /// there).
    fn project_with(
        &mut self,
        schur: &mut Schur,
        modes: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<bool, DynamicsError> {
        let (mut rows, mut phi, mut target) =
            self.sparse_rows(&self.q, &self.qd, modes, pairings)?;
        for _ in 0..8 {
            if phi.iter().all(|p| p.abs() <= 1e-14 * self.size) {
                break;
            }
            if !schur.factor(&rows, &self.inv_mass) {
                return Ok(false);
            }
            let b: Vec<f64> = phi.iter().map(|p| -p).collect();
            let dq = sparse::project(&rows, &self.inv_mass, schur, &vec![0.0; self.q.len()], &b);
            for (q, d) in self.q.iter_mut().zip(&dq) {
                *q += d;
            }
            (rows, phi, target) = self.sparse_rows(&self.q, &self.qd, modes, pairings)?;
        }
        if !schur.factor(&rows, &self.inv_mass) {
            return Ok(false);
        }
        self.qd = sparse::project(&rows, &self.inv_mass, schur, &self.qd, &target);
        Ok(true)
    }

    /// Adds the forces from tables of the crank angle at `t` to `f`; their power.
    fn add_table_forces(&self, t: f64, q: &[f64], qd: &[f64], f: &mut [f64]) -> f64 {
        let forces = self.sys.table_forces();
        let Some(d) = self.sys.drivers().first() else {
            return 0.0;
        };
        if forces.is_empty() {
            return 0.0;
        }
        let [angle, ..] = d.law.at(t);
        let start = d.law.at(0.0)[0];
        let driver_deg = (angle - start).to_degrees();
        forces
            .iter()
            .map(|g| {
                let s = super::super::model::body_state(q, qd, g.body.0);
                g.add_force(driver_deg, s.pose, (s.velocity, s.omega), f)
            })
            .sum()
    }

    /// How many rows the constraints `active` hold.
    fn active_rows(&self, active: &[bool]) -> usize {
        self.model
            .constraints
            .iter()
            .zip(active)
            .filter(|(_, &a)| a)
            .map(|(c, _)| c.rows())
            .sum()
    }

    /// The active rows at `(q, q̇)`, sparse, with `Φ` and the rate each must have (`−Φ_t`).
    #[allow(clippy::type_complexity)]
    fn sparse_rows(
        &self,
        q: &[f64],
        qd: &[f64],
        in_contact: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<(Vec<Row>, Vec<f64>, Vec<f64>), DynamicsError> {
        let active = self.active(in_contact);
        let (qf, qdf) = self.frames(q, qd);
        let arms = self.arms(q);
        let m = self.active_rows(&active);
        let (mut rows, mut phi, mut target) = (
            Vec::with_capacity(m),
            Vec::with_capacity(m),
            Vec::with_capacity(m),
        );
        for (k, c) in self.model.constraints.iter().enumerate() {
            if !active[k] {
                continue;
            }
            let rs = self
                .model
                .rows(c, self.t, &qf, &qdf, &mut pairings[k])
                .map_err(|source| DynamicsError::Contact {
                    time: self.t,
                    source,
                })?;
            for row in rs.iter() {
                let mut row = *row;
                self.row_about_centres(&arms, qd, &mut row);
                phi.push(row.phi);
                target.push(c.target_rate(self.t));
                rows.push(row);
            }
        }
        Ok((rows, phi, target))
    }

    /// [`SystemSimulation::project`] on the whole saddle-point matrix, where the rows are
    /// dependent and the Schur complement cannot be factored.
    fn project_dense(&mut self) -> Result<(), DynamicsError> {
        let n = self.q.len();
        let mut pairings = self.pairings.clone();
        let modes = self.in_contact.clone();
        let mut rows = self.dense(&self.q, &self.qd, &modes, &mut pairings)?;
        let mut x = vec![0.0; n];
        for _ in 0..8 {
            if rows.phi.iter().all(|p| p.abs() <= 1e-14 * self.size) {
                break;
            }
            let b: Vec<f64> = rows.phi.iter().map(|p| -p).collect();
            if !self
                .model
                .project_onto(&rows, &vec![0.0; n], &b[..rows.m], &mut x)
            {
                return Err(DynamicsError::Singular { time: self.t });
            }
            for (q, d) in self.q.iter_mut().zip(&x) {
                *q += d;
            }
            rows = self.dense(&self.q, &self.qd, &modes, &mut pairings)?;
        }
        if !self
            .model
            .project_onto(&rows, &self.qd, &rows.target, &mut x)
        {
            return Err(DynamicsError::Singular { time: self.t });
        }
        self.qd.copy_from_slice(&x);
        self.pairings = pairings;
        Ok(())
    }

    /// Advances by `h` seconds, locating every lift-off and impact inside the step. A step
    /// longer than [`SystemSimulation::max_step`] is refused, naming the stiffest element.
    pub fn advance(&mut self, h: f64) -> Result<Vec<ContactEvent>, DynamicsError> {
        if !(h > 0.0 && h.is_finite()) {
            return Err(DynamicsError::Element {
                element: "the simulation".into(),
                key: "time step (s)",
                value: h,
                reason: "must be positive",
            });
        }
        let max_step = self.max_step();
        if h > max_step * (1.0 + 1e-12) {
            let (rate, element) = self.fastest_rate();
            return Err(DynamicsError::SystemStepTooLong {
                element,
                step: h,
                rate,
                max_step,
            });
        }
        self.wrap_pairings();
        let mut events = std::mem::take(&mut self.pending);
        let end = self.t + h;
        while self.t < end - 1e-15 * end.abs().max(1.0) {
            if events.len() > MAX_EVENTS {
                return Err(DynamicsError::Chatter {
                    time: self.t,
                    events: MAX_EVENTS,
                });
            }
            let dt = end - self.t;
            let saved = (
                self.q.clone(),
                self.qd.clone(),
                self.pairings.clone(),
                self.t,
                self.work,
            );
            let (qn, vn, pn, dw) = self.rk4(dt)?;
            (self.q, self.qd, self.pairings, self.t) = (qn, vn, pn, end);
            self.work += dw;
            self.project()?;
            // what ended the step: a contact pulled, or a gap closed
            let mut p = self.pairings.clone();
            let (_, forces, _, _) =
                self.accel(self.t, &self.q, &self.qd, &self.in_contact, &mut p)?;
            let mut crossing = Vec::new();
            for (k, &force) in forces.iter().enumerate() {
                if self.in_contact[k] {
                    if force < 0.0 {
                        crossing.push(k);
                    }
                } else if self.gap(&self.q, &self.qd, k, &mut p)? < -1e-12 * self.size {
                    crossing.push(k);
                }
            }
            if crossing.is_empty() {
                // the pairings followed to this state: a flying contact's from its last, so that
                // Newton stays on the nearest pair of points (from the pairing at lift-off, a
                // disc's far side under a flat face was found once the follower had flown)
                self.pairings = p;
                continue;
            }
            (self.q, self.qd, self.pairings, self.t, self.work) = saved;
            // the first crossing, each located by bisection on its own quantity
            let mut first = (f64::INFINITY, 0);
            for &k in &crossing {
                let tau = self.bisect(dt, k)?;
                if tau < first.0 {
                    first = (tau, k);
                }
            }
            let (tau, k) = first;
            let (qn, vn, pn, dw) = self.rk4(tau)?;
            (self.q, self.qd, self.pairings) = (qn, vn, pn);
            self.t += tau;
            self.work += dw;
            if self.in_contact[k] {
                self.project()?;
                self.in_contact[k] = false;
                events.push(ContactEvent {
                    kind: EventKind::LiftOff,
                    time: self.t,
                    contact: k,
                    approach: 0.0,
                });
            } else {
                let mut p = self.pairings.clone();
                self.gap(&self.q.clone(), &self.qd.clone(), k, &mut p)?;
                self.pairings = p;
                self.project()?;
                let approach = self.impact(k)?;
                events.push(ContactEvent {
                    kind: EventKind::Impact,
                    time: self.t,
                    contact: k,
                    approach,
                });
            }
        }
        Ok(events)
    }

    /// Each contact's pairing parameters on a closed curve brought back into one period once
    /// they have run a period past it: a cam turning for hundreds of revolutions drives its
    /// parameter on without bound, and at `|u|` of thousands Newton cannot step below the
    /// parameter's own rounding (a run of 330 revolutions stopped so). The pairing stays the same
    /// point; the evaluation kept for the next step is asked again once (rarely).
    fn wrap_pairings(&mut self) {
        for (k, c) in self.sys.contacts().iter().enumerate() {
            let Some(p) = self.pairings[self.first_contact + k].as_mut() else {
                continue;
            };
            for (u, curve) in [(&mut p.u_a, &c.curve_a), (&mut p.u_b, &c.curve_b)] {
                if let crate::curve::Domain::Periodic { period } = curve.domain() {
                    if !(-period..=2.0 * period).contains(u) {
                        *u = u.rem_euclid(period);
                    }
                }
            }
        }
    }

    /// The sub-step `τ ∈ (0, dt]` at whose end contact `k`'s force (in touch) or gap (in flight)
    /// crosses zero, integrating in the current modes.
    fn bisect(&self, dt: f64, k: usize) -> Result<f64, DynamicsError> {
        let (mut lo, mut hi) = (0.0, dt);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            let (q, v, mut p, _) = self.rk4(mid)?;
            let value = if self.in_contact[k] {
                self.accel(self.t + mid, &q, &v, &self.in_contact, &mut p)?
                    .1[k]
            } else {
                self.gap(&q, &v, k, &mut p)? + 1e-12 * self.size
            };
            if value >= 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo <= 1e-14 * (1.0 + self.t) {
                break;
            }
        }
        Ok(0.5 * (lo + hi))
    }

    /// An impact of contact `k` now: the velocities projected so that its normal velocity
    /// reverses times the restitution, every joint, driver and contact in touch held; the
    /// approach speed. The contact re-engages when the rebound is negligible.
    fn impact(&mut self, k: usize) -> Result<f64, DynamicsError> {
        let mut modes = self.in_contact.clone();
        modes[k] = true;
        let mut pairings = self.pairings.clone();
        let rows = self.dense(&self.q, &self.qd, &modes, &mut pairings)?;
        // the impacting contact's row among the active rows
        let active = self.active(&modes);
        let r: usize = self.model.constraints[..self.first_contact + k]
            .iter()
            .zip(&active)
            .filter(|(_, &a)| a)
            .map(|(c, _)| c.rows())
            .sum();
        // the gap's rate (its row times q̇), negative approaching in the contact's sense
        let vn: f64 = rows.row(r).iter().zip(&self.qd).map(|(a, b)| a * b).sum();
        let mut targets = rows.target.to_vec();
        let e = self.opts.restitution.get(k).copied().unwrap_or(0.0);
        targets[r] = -e * vn;
        let mut x = vec![0.0; self.qd.len()];
        if !self
            .model
            .project_onto(&rows, &self.qd, &targets[..rows.m], &mut x)
        {
            return Err(DynamicsError::Singular { time: self.t });
        }
        self.qd = x;
        let approach = vn.abs();
        self.in_contact[k] = e * approach <= REBOUND_TOLERANCE * self.speed_scale;
        Ok(approach)
    }
}
