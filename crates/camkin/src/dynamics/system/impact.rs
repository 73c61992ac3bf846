//! An impact: the jump of the velocities when a contact closes — the mass-orthogonal projection
//! onto the rows held (every joint and driver, every contact in touch, the impacting contact's
//! normal velocity reversed times its restitution) — with a contact whose row conflicts with
//! the impacting one's released (a valve on its seat when the cam takes up its lash), and the
//! impulse split by rows, so that the drivers' share of its work is theirs.

use super::super::follower::REBOUND_TOLERANCE;
use super::super::projection::DenseRows;
use super::super::DynamicsError;
use super::SystemSimulation;
use nalgebra::{DMatrix, DVector};

/// An impact's velocities solved for one set of contacts held.
struct Jump {
    rows: DenseRows,
    active: Vec<bool>,
    /// the impacting contact's normal velocity before, along its row (its magnitude the
    /// approach speed; its sign the row's, not the contact's sense)
    vn: f64,
    /// the rebound is too slow to part the curves: the contact stays closed
    engaged: bool,
    /// the velocities after
    after: Vec<f64>,
}

impl SystemSimulation<'_> {
    /// An impact of contact `k` now: the velocities projected so that its normal velocity
    /// reverses times the restitution, every joint, driver and contact in touch held — but a
    /// contact in touch whose row conflicts with the impacting one's (both hold one body's
    /// coordinate: a valve on its seat when the cam takes up its lash) is released and opens,
    /// the one whose release resolves the conflict with the velocities after parting it. The
    /// approach speed and the contacts released. The contact re-engages when the rebound is
    /// negligible. (Contacts in touch are otherwise held through the impact, its impulse on
    /// them whatever its sign: one pulled lifts off at the next step's check of the forces.)
    pub(super) fn impact(&mut self, k: usize) -> Result<(f64, Vec<usize>), DynamicsError> {
        let mut modes = self.in_contact.clone();
        modes[k] = true;
        let mut released = Vec::new();
        let jump = loop {
            if let Some(j) = self.jump(k, &modes)? {
                break j;
            }
            // the rows conflict: release a contact in touch whose release resolves them and
            // that the velocities after part (or leave at rest), as its impulse would pull
            let mut found = None;
            for j in (0..modes.len()).filter(|&j| j != k && modes[j]) {
                let mut fewer = modes.clone();
                fewer[j] = false;
                if let Some(jump) = self.jump(k, &fewer)? {
                    let parts = self
                        .normal_rate(j, &jump.after)
                        .is_some_and(|v| v >= -1e-9 * jump.vn.abs());
                    if parts {
                        found = Some(j);
                        break;
                    }
                }
            }
            let Some(j) = found else {
                return Err(DynamicsError::Singular { time: self.t });
            };
            modes[j] = false;
            released.push(j);
        };
        self.work[super::balance::DRIVERS] +=
            self.drivers_impulse_work(&jump.rows, &jump.active, &jump.after);
        self.qd = jump.after;
        modes[k] = jump.engaged;
        self.in_contact = modes;
        Ok((jump.vn.abs(), released))
    }

    /// The impact of contact `k` with the contacts `modes` held (`k` among them): its rows and
    /// the velocities after, or `None` where the rows conflict (the projection is singular).
    fn jump(&self, k: usize, modes: &[bool]) -> Result<Option<Jump>, DynamicsError> {
        let mut pairings = self.pairings.clone();
        let rows = self.dense(&self.q, &self.qd, modes, &mut pairings)?;
        let active = self.active(modes);
        let row = self.contact_row(&active, k);
        // the rate of the gap along its row (its sense aside: the rebound reverses it whatever
        // the sense)
        let vn: f64 = rows.row(row).iter().zip(&self.qd).map(|(a, b)| a * b).sum();
        let mut targets = rows.target.to_vec();
        let e = self.opts.restitution.get(k).copied().unwrap_or(0.0);
        // a rebound too slow to part the curves re-engages the contact: the impact is plastic
        // (left at `−e vₙ`, the curves parted at the rebound's speed under a closed contact until
        // the next projection took it away, at a step's end: a jolt to the valve spring's coils
        // that the step's length set)
        let engaged = e * vn.abs() <= REBOUND_TOLERANCE * self.speed_scale;
        targets[row] = if engaged { 0.0 } else { -e * vn };
        let mut after = vec![0.0; self.qd.len()];
        if !self
            .model
            .project_onto(&rows, &self.qd, &targets[..rows.m], &mut after)
        {
            return Ok(None);
        }
        Ok(Some(Jump {
            rows,
            active,
            vn,
            engaged,
            after,
        }))
    }

    /// Contact `j`'s normal rate at the rates `qd` (its gap's rate, in its sense: negative
    /// approaching), from its row with it held; `None` where its row cannot be made.
    fn normal_rate(&self, j: usize, qd: &[f64]) -> Option<f64> {
        let mut modes = vec![false; self.in_contact.len()];
        modes[j] = true;
        let mut pairings = self.pairings.clone();
        let rows = self.dense(&self.q, qd, &modes, &mut pairings).ok()?;
        let row = self.contact_row(&self.active(&modes), j);
        let rate: f64 = rows.row(row).iter().zip(qd).map(|(a, b)| a * b).sum();
        Some(self.sense[j] * rate)
    }

    /// Contact `k`'s row among the rows `active`.
    fn contact_row(&self, active: &[bool], k: usize) -> usize {
        self.model.constraints[..self.first_contact + k]
            .iter()
            .zip(active)
            .filter(|(_, &a)| a)
            .map(|(c, _)| c.rows())
            .sum()
    }

    /// The impulse on each of `rows` that takes the rates from the current ones to `after`:
    /// `Λ` from `Φ_q M⁻¹ Φ_qᵀ Λ = Φ_q Δq̇` (the impulse `M Δq̇ = Φ_qᵀ Λ` split by rows); `None`
    /// where the rows are dependent (a singular pose: the split is not defined).
    fn row_impulses(&self, rows: &DenseRows, after: &[f64]) -> Option<DVector<f64>> {
        let (m, n) = (rows.m, self.qd.len());
        // a point mass's angle has no inertia: its column carries no impulse
        let w: Vec<f64> = self
            .inv_mass
            .iter()
            .map(|&w| if w.is_finite() { w } else { 0.0 })
            .collect();
        let dq: Vec<f64> = (0..n).map(|i| after[i] - self.qd[i]).collect();
        let s = DMatrix::<f64>::from_fn(m, m, |a, b| {
            let (ra, rb) = (rows.row(a), rows.row(b));
            (0..n).map(|i| ra[i] * w[i] * rb[i]).sum::<f64>()
        });
        let rhs = DVector::<f64>::from_fn(m, |a, _| {
            rows.row(a).iter().zip(&dq).map(|(j, d)| j * d).sum()
        });
        s.cholesky().map(|c| c.solve(&rhs))
    }

    /// The work the drivers' impulses do in an impact that takes the rates from the current
    /// ones to `after` under the dense `rows` of the constraints `active`: each driver row's
    /// impulse ([`SystemSimulation::row_impulses`]) times its rate averaged over the impact
    /// (exact: the rates change linearly with the impulse). The driver keeps its speed, so this
    /// is the impulse times it. The rest of the change of kinetic energy is the contact's loss,
    /// `−½ (1 − e²) m u²` for a body of mass `m`. Zero where no driver moves (the impulses are
    /// then not solved for), or where the split is not defined (all of the change counts as the
    /// impact's).
    fn drivers_impulse_work(&self, rows: &DenseRows, active: &[bool], after: &[f64]) -> f64 {
        let mut driven = Vec::new();
        let mut r = 0;
        for (c, _) in self
            .model
            .constraints
            .iter()
            .zip(active)
            .filter(|(_, &a)| a)
        {
            if let super::super::model::Constraint::Driver { .. } = c {
                if c.target_rate(self.t) != 0.0 {
                    driven.push(r);
                }
            }
            r += c.rows();
        }
        if driven.is_empty() {
            return 0.0;
        }
        let Some(lambda) = self.row_impulses(rows, after) else {
            return 0.0;
        };
        let rate =
            |v: &[f64], a: usize| -> f64 { rows.row(a).iter().zip(v).map(|(j, x)| j * x).sum() };
        driven
            .iter()
            .map(|&a| lambda[a] * 0.5 * (rate(&self.qd, a) + rate(after, a)))
            .sum()
    }
}
