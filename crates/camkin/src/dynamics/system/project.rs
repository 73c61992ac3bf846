//! A simulated system's projection onto its rows (positions by Newton, then velocities), its
//! contacts' gaps.

use super::super::projection::DenseRows;
use super::super::DynamicsError;
use super::eval::Scratch;
use super::SystemSimulation;
use crate::contact::{self, Pairing, Surface};

/// The largest residual (times the system's size, see
/// [`SystemSimulation::unassembled_tolerance`]) the positions may keep
/// after a step's projection: beyond it they are not on the constraints, and the run stops
/// ([`DynamicsError::Unassembled`]) rather than go on off them.
const UNASSEMBLED: f64 = 1e-8;

/// The residual (times the system's size) below which the positions are on the rows: a few
/// ulps. A step's end lies off them by up to its tolerance (1e-10 of the size by default), and
/// one Newton iteration from there lands at rounding; at 1e-14 a drift just under it was left
/// uncorrected, and a follower's acceleration strayed from the kinematics' by 1.4e-13 of its peak.
const ASSEMBLED: f64 = 1e-15;

/// A state a step ends at: positions, rates and pairings (buffers swapped with the
/// simulation's own, so that the state a step started from is kept without a copy).
#[derive(Debug, Clone, Default)]
pub(crate) struct StepEnd {
    pub(super) q: Vec<f64>,
    pub(super) qd: Vec<f64>,
    pub(super) pairings: Vec<Option<Pairing>>,
}

impl SystemSimulation<'_> {
    /// The current state exchanged with `end`'s (buffers swapped, nothing copied).
    pub(super) fn swap_state(&mut self, end: &mut StepEnd) {
        std::mem::swap(&mut self.q, &mut end.q);
        std::mem::swap(&mut self.qd, &mut end.qd);
        std::mem::swap(&mut self.pairings, &mut end.pairings);
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

    /// Sets every body's frame rates `(v_x, v_y, ω)` (L/s and rad/s, three a body in the
    /// system's order) at the current positions, made consistent with the joints, the drivers
    /// and the closed contacts by the mass-orthogonal projection (the least change in the kinetic
    /// energy's metric, `min ½ Δq̇ᵀ M Δq̇` subject to `Φ_q q̇ = −Φ_t`: Bayo and Ledesma 1996); a
    /// closed contact the rates asked part (a body thrown off a surface it rests on), or whose
    /// force they make tensile, leaves at once. Returns the largest change the projection
    /// made to a rate asked (an angle's times the size, in L/s), so that a user sees where what
    /// they asked is not what the constraints allow. The energy balance
    /// ([`SystemSimulation::balance`]) counts from the state set.
    pub fn set_frame_rates(&mut self, rates: &[f64]) -> Result<f64, DynamicsError> {
        if rates.len() != self.qd.len() {
            return Err(DynamicsError::Element {
                element: "the simulation".into(),
                key: "rates",
                value: rates.len() as f64,
                reason: "must be three for each body (v_x, v_y, ω)",
            });
        }
        if let Some(&bad) = rates.iter().find(|r| !r.is_finite()) {
            return Err(DynamicsError::Element {
                element: "the simulation".into(),
                key: "rates",
                value: bad,
                reason: "must be finite",
            });
        }
        // the energy balance starts again from the rates set
        let before = self.energy();
        self.part_by_rates(rates)?;
        // the centres' rates: ẋ_G = ȯ + θ̇ J ρ, J ρ = (−ρ_y, ρ_x)
        let arms = self.arms(&self.q);
        let mut asked = rates.to_vec();
        for (i, r) in arms.iter().enumerate() {
            let w = rates[3 * i + 2];
            asked[3 * i] -= w * r.y;
            asked[3 * i + 1] += w * r.x;
        }
        self.qd.clone_from(&asked);
        self.project()?;
        let change = self
            .qd
            .iter()
            .zip(&asked)
            .enumerate()
            .map(|(i, (a, b))| (a - b).abs() * if i % 3 == 2 { self.size } else { 1.0 })
            .fold(0.0f64, f64::max);
        self.release_pulled()?;
        self.initial_energy += self.energy() - before;
        Ok(change)
    }

    /// Positions by Newton onto the active rows (mass-orthogonal), then velocities onto
    /// `Φ_q q̇ = −Φ_t`.
    pub(super) fn project(&mut self) -> Result<(), DynamicsError> {
        // the evaluations' buffers (none is running now)
        let mut scratch = std::mem::take(self.scratch.get_mut());
        let mut pairings = std::mem::take(&mut self.spare_pairings);
        pairings.clone_from(&self.pairings);
        let modes = std::mem::take(&mut self.in_contact);
        let done = self.project_with(&mut scratch, &modes, &mut pairings);
        self.in_contact = modes;
        *self.scratch.get_mut() = scratch;
        match done? {
            true => {
                std::mem::swap(&mut self.pairings, &mut pairings);
                self.spare_pairings = pairings;
                Ok(())
            }
            false => self.project_dense(),
        }
    }

    /// [`SystemSimulation::project`] with the buffers `s`; `false` where the rows are
    /// dependent (the positions as far as they were moved: the dense projection goes on from
    /// there).
    fn project_with(
        &mut self,
        s: &mut Scratch,
        modes: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<bool, DynamicsError> {
        self.sparse_rows(modes, pairings, s)?;
        for _ in 0..8 {
            if s.phi.iter().all(|p| p.abs() <= ASSEMBLED * self.size) {
                break;
            }
            // (damped where the rows are dependent: Levenberg–Marquardt's step, which still
            // converges where they are consistent, and at a singular pose does not leap)
            if !self.factor_projection(s) {
                return Ok(false);
            }
            // Δq = M⁻¹ Φ_qᵀ μ, S μ = −Φ
            s.lambda.clear();
            s.lambda.extend(s.phi.iter().map(|p| -p));
            s.schur.solve(&mut s.lambda);
            // (summed apart, then added: each coordinate's correction whole)
            s.delta.clear();
            s.delta.resize(self.q.len(), 0.0);
            for (row, &u) in s.rows.iter().zip(&s.lambda) {
                for &(c, v) in row.jac() {
                    s.delta[c] += self.inv_mass[c] * v * u;
                }
            }
            for (q, d) in self.q.iter_mut().zip(&s.delta) {
                *q += d;
            }
            self.sparse_rows(modes, pairings, s)?;
        }
        let tol = self.unassembled_tolerance();
        if !s.phi.iter().all(|p| p.abs() <= tol) {
            // not converged: the dense projection goes on from here, and says so if it fails
            return Ok(false);
        }
        // velocities: q̇ + M⁻¹ Φ_qᵀ μ with S μ = −Φ_t − Φ_q q̇ (the factor is the one the
        // step's check evaluates with next: the same rows)
        if !self.factor_projection(s) {
            return Ok(false);
        }
        self.project_rates(s);
        Ok(true)
    }

    /// The Schur complement of `s.rows` factored for a projection: damped where they are
    /// dependent (Levenberg–Marquardt's step, which still converges where they are consistent,
    /// and at a singular pose does not leap).
    fn factor_projection(&self, s: &mut Scratch) -> bool {
        match self.factor_rows(&mut s.schur, &mut s.geometry, &s.rows) {
            super::singular::Factored::Yes => true,
            _ => s.schur.factor_regularised(&s.rows, &self.inv_mass),
        }
    }

    /// The rates projected onto the rows `s.rows` (their rates `s.rhs`) with the factor
    /// `s.schur`.
    fn project_rates(&mut self, s: &mut Scratch) {
        s.lambda.clear();
        s.lambda.extend(
            s.rows
                .iter()
                .zip(&s.rhs)
                .map(|(row, &b)| b - row.jac().iter().map(|&(c, v)| v * self.qd[c]).sum::<f64>()),
        );
        s.schur.solve(&mut s.lambda);
        for (row, &u) in s.rows.iter().zip(&s.lambda) {
            for &(c, v) in row.jac() {
                self.qd[c] += self.inv_mass[c] * v * u;
            }
        }
    }

    /// The active rows now, sparse, into `s.rows`, with their `Φ` into `s.phi` and the rate
    /// each must have (`−Φ_t`) into `s.rhs`.
    fn sparse_rows(
        &self,
        in_contact: &[bool],
        pairings: &mut [Option<Pairing>],
        s: &mut Scratch,
    ) -> Result<(), DynamicsError> {
        let (q, qd) = (&self.q, &self.qd);
        self.active_into(in_contact, &mut s.active);
        let (qf, qdf) = self.frames(q, qd);
        let arms = self.arms(q);
        s.rows.clear();
        s.phi.clear();
        s.rhs.clear();
        for (k, c) in self.model.constraints.iter().enumerate() {
            if !s.active[k] {
                continue;
            }
            let from = s.rows.len();
            self.model
                .push_rows(c, self.t, &qf, &qdf, &mut pairings[k], &mut s.rows)
                .map_err(|source| DynamicsError::Contact {
                    time: self.t,
                    source,
                })?;
            for row in &mut s.rows[from..] {
                self.row_about_centres(&arms, qd, row);
                s.phi.push(row.phi);
                s.rhs.push(c.target_rate(self.t));
            }
        }
        Ok(())
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
            if rows.phi.iter().all(|p| p.abs() <= ASSEMBLED * self.size) {
                break;
            }
            let b: Vec<f64> = rows.phi.iter().map(|p| -p).collect();
            if !self
                .model
                .project_onto(&rows, &vec![0.0; n], &b[..rows.m], &mut x)
            {
                // dependent rows (a singular pose): the least correction, in least squares
                x = self.pseudo_inverse_correction(&rows, &b);
            }
            for (q, d) in self.q.iter_mut().zip(&x) {
                *q += d;
            }
            rows = self.dense(&self.q, &self.qd, &modes, &mut pairings)?;
        }
        let tol = self.unassembled_tolerance();
        if !rows.phi[..rows.m].iter().all(|p| p.abs() <= tol) {
            return Err(self.unassembled(&rows.phi[..rows.m], &modes));
        }
        if !self
            .model
            .project_onto(&rows, &self.qd, &rows.target, &mut x)
        {
            let r: Vec<f64> = (0..rows.m)
                .map(|i| rows.target[i] - super::super::dense::dot(rows.row(i), &self.qd))
                .collect();
            let dx = self.pseudo_inverse_correction(&rows, &r);
            for ((xi, v), d) in x.iter_mut().zip(&self.qd).zip(&dx) {
                *xi = v + d;
            }
        }
        self.qd.copy_from_slice(&x);
        self.pairings = pairings;
        Ok(())
    }

    /// The largest residual a projection may leave: [`UNASSEMBLED`] times the system's size or
    /// its bodies' farthest coordinate, whichever is larger, and never below 1e-10 (an angle's
    /// row, in rad, where the system is small).
    fn unassembled_tolerance(&self) -> f64 {
        let far = self.q.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        (UNASSEMBLED * self.size.max(far)).max(1e-10)
    }

    /// The positions cannot be brought back onto the rows (residuals `phi`, the active rows of
    /// `modes`): the rows with the largest residuals named.
    fn unassembled(&self, phi: &[f64], modes: &[bool]) -> DynamicsError {
        let sys = &self.sys;
        let fixed = sys.rows() - sys.contacts.len();
        let names: Vec<String> = (0..sys.rows())
            .filter(|&r| r < fixed || modes[r - fixed])
            .map(|r| sys.row_name(r))
            .collect();
        let big = phi.iter().fold(0.0f64, |m, p| m.max(p.abs()));
        let rows = phi
            .iter()
            .zip(&names)
            .filter(|(p, _)| p.abs() >= 0.2 * big || !p.is_finite())
            .map(|(_, n)| n.as_str())
            .collect::<Vec<_>>()
            .join(", ");
        DynamicsError::Unassembled {
            time: self.t,
            residual: big,
            rows,
        }
    }

    /// Each contact's pairing parameters on a closed curve brought back into one period once
    /// they have run a period past it: a cam turning for hundreds of revolutions drives its
    /// parameter on without bound, and at `|u|` of thousands Newton cannot step below the
    /// parameter's own rounding (a run of 330 revolutions stopped so). The pairing stays the same
    /// point; the evaluation kept for the next step is asked again once (rarely).
    pub(super) fn wrap_pairings(&mut self) {
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
}
