//! A simulation's starting state made consistent with its rows, as an initial-conditions
//! analysis does (Adams' "initial conditions", Chrono's assembly): the poses assembled onto the
//! joints, the drivers and every contact that starts closed (by the mass-orthogonal Newton
//! projection), then the rates the user asked made consistent with them (the mass-orthogonal
//! projection of the velocities, `min ½ Δq̇ᵀ M Δq̇` subject to `Φ_q q̇ = −Φ_t`: Bayo and
//! Ledesma 1996); a closed contact that the asked rates pull apart opens at once. What either
//! projection changed is reported ([`StartReport`]), so that a user sees where the starting
//! state they wrote is not one the constraints allow.

use super::super::follower::EventKind;
use super::super::DynamicsError;
use super::{ContactEvent, SystemSimulation};

/// What the start changed of the state a simulation was given: the distances each body was
/// moved onto the rows and its rates asked against its rates as started.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct StartReport {
    /// how far each body's frame origin was moved by the assembly, L (in the system's order)
    pub moved: Vec<f64>,
    /// how far each body was turned by it, rad
    pub turned: Vec<f64>,
    /// each body's frame rates `(v_x, v_y, ω)` asked (L/s, L/s, rad/s), where the user gave
    /// them (those not given are free: the start finds them)
    pub asked_rates: Vec<[Option<f64>; 3]>,
    /// and as started: consistent with the joints, drivers and closed contacts
    pub rates: Vec<[f64; 3]>,
    /// whether each contact starts closed
    pub closed: Vec<bool>,
    /// the system's size, L: an angular rate's change is weighed at it against a speed's
    pub size: f64,
    /// the contacts assembled closed that open at once: the rates asked part them, or their
    /// force would pull (each a lift-off at the start)
    pub opened: Vec<usize>,
}

impl StartReport {
    /// The body moved farthest by the assembly and the distance, L (`None` without bodies).
    pub fn largest_move(&self) -> Option<(usize, f64)> {
        self.moved
            .iter()
            .copied()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// The body turned most by the assembly and the angle, rad.
    pub fn largest_turn(&self) -> Option<(usize, f64)> {
        self.turned
            .iter()
            .map(|t| t.abs())
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// The body whose rates asked the start changed most, with its change: the largest of its
    /// speed's change (L/s: of the components given) and its angular rate's (rad/s) times the
    /// system's size. `None` where no rate was asked.
    pub fn largest_rate_change(&self) -> Option<(usize, f64)> {
        let size = self.size;
        self.asked_rates
            .iter()
            .zip(&self.rates)
            .enumerate()
            .filter(|(_, (a, _))| a.iter().any(Option::is_some))
            .map(|(i, (a, r))| {
                let d = |c: usize| a[c].map_or(0.0, |a| a - r[c]);
                (i, d(0).hypot(d(1)).max(d(2).abs() * size))
            })
            .max_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// What the start changed, in sentences for people (lengths in `unit`, the bodies and
    /// contacts named from `sys`): the largest move and turn of the assembly where it moved a
    /// body (beyond 1e-9 of the size), the largest change of the rates asked where the user gave
    /// any, and the contacts that open at once.
    pub fn describe(&self, sys: &crate::system::System, unit: &str) -> Vec<String> {
        let h = crate::human::human;
        let body = |i: usize| sys.bodies().get(i).map_or("?", |b| b.name.as_str());
        let contact = |k: usize| sys.contacts().get(k).map_or("?", |c| c.name.as_str());
        let mut lines = Vec::new();
        let (moved, turned) = (self.largest_move(), self.largest_turn());
        if moved.is_some_and(|(_, d)| d > 1e-9 * self.size) || turned.is_some_and(|(_, t)| t > 1e-9)
        {
            let (b, d) = moved.unwrap_or((0, 0.0));
            let (bt, t) = turned.unwrap_or((0, 0.0));
            lines.push(format!(
                "the starting poses were assembled onto the joints, drivers and closed contacts: {:?} moved {} {unit} (the most), {:?} turned {}° (the most)",
                body(b),
                h(d),
                body(bt),
                h(t.to_degrees())
            ));
        }
        let asked = self
            .asked_rates
            .iter()
            .flatten()
            .flatten()
            .fold(0.0f64, |m, r| m.max(r.abs()));
        if let Some((b, change)) = self
            .largest_rate_change()
            .filter(|&(_, c)| c > 1e-12 * asked.max(f64::MIN_POSITIVE))
        {
            lines.push(format!(
                "the starting rates given are not all ones the joints, drivers and closed contacts allow: the nearest that are changed {:?}'s by {} {unit}/s (the most; a turn's rate times the size {} {unit})",
                body(b),
                h(change),
                h(self.size)
            ));
        }
        for &k in &self.opened {
            lines.push(format!(
                "contact {:?} opens at the start: the starting rates part it, or its force would pull",
                contact(k)
            ));
        }
        lines
    }

    /// The contacts closed at the start, in a sentence (the first six named), where the system
    /// has contacts.
    pub fn closed_contacts(&self, sys: &crate::system::System) -> Option<String> {
        let contact = |k: usize| sys.contacts().get(k).map_or("?", |c| c.name.as_str());
        if self.closed.is_empty() {
            return None;
        }
        let closed: Vec<&str> = (0..self.closed.len())
            .filter(|&k| self.closed[k])
            .map(contact)
            .collect();
        let shown = closed
            .iter()
            .take(6)
            .map(|c| format!("{c:?}"))
            .collect::<Vec<_>>();
        Some(format!(
            "{} of {} contacts closed at the start{}{}{}",
            closed.len(),
            self.closed.len(),
            if closed.is_empty() { "" } else { ": " },
            shown.join(", "),
            if closed.len() > 6 { ", …" } else { "" }
        ))
    }
}

impl SystemSimulation<'_> {
    /// How the start changed the state the simulation was given.
    pub fn start_report(&self) -> &StartReport {
        &self.start_report
    }

    /// The frames' coordinates now, three a body.
    pub(super) fn frame_coordinates(&self) -> Vec<f64> {
        self.frames(&self.q, &self.qd).0.into_owned()
    }

    /// The report's moves: each body's frame now against `before` (three a body).
    pub(super) fn note_moves(&mut self, before: &[f64]) {
        let after = self.frame_coordinates();
        let (moved, turned) = before
            .chunks(3)
            .zip(after.chunks(3))
            .map(|(b, a)| ((a[0] - b[0]).hypot(a[1] - b[1]), a[2] - b[2]))
            .unzip();
        self.start_report.moved = moved;
        self.start_report.turned = turned;
        self.start_report.size = self.size;
        self.start_report.closed.clone_from(&self.in_contact);
    }

    /// The rates the options ask for (each body's `(v_x, v_y, ω)` where given) started with: a
    /// closed contact they part opened; the rates not given found so that the rows hold with
    /// the given ones where they can (the least-squares solution, the smallest weighted by the
    /// masses and inertias); then all made consistent with the rows by the mass-orthogonal projection (which
    /// changes a given rate only where the given ones conflict with the rows); then every
    /// closed contact whose force is tensile leaves.
    pub(super) fn start_rates(&mut self) -> Result<(), DynamicsError> {
        let (_, now) = self.frames(&self.q, &self.qd);
        let mut asked = now.into_owned();
        let n = asked.len() / 3;
        let mut given: Vec<[Option<f64>; 3]> = self.opts.initial_rates.clone();
        given.resize(n, [None; 3]);
        given.truncate(n);
        let any = given.iter().flatten().any(Option::is_some);
        for (i, rates) in given.iter().enumerate() {
            for (c, r) in rates.iter().enumerate() {
                if let Some(r) = r {
                    asked[3 * i + c] = *r;
                }
            }
        }
        self.start_report.asked_rates = given.clone();
        let assembled = self.in_contact.clone();
        if any {
            self.part_by_rates(&asked)?;
            let free: Vec<bool> = given.iter().flatten().map(Option::is_none).collect();
            self.fill_free_rates(&mut asked, &free)?;
            self.set_frame_rates(&asked)?;
        } else {
            self.release_pulled()?;
        }
        let (_, rates) = self.frames(&self.q, &self.qd);
        self.start_report.rates = rates.chunks(3).map(|r| [r[0], r[1], r[2]]).collect();
        self.start_report.closed.clone_from(&self.in_contact);
        self.start_report.opened = (0..assembled.len())
            .filter(|&k| assembled[k] && !self.in_contact[k])
            .collect();
        Ok(())
    }

    /// The frame rates `asked` where `free` (one flag a rate) changed so that the active rows'
    /// rates are as they must be with the others held: `min ‖Φ_f δ − r‖` of least
    /// `Σ w δ²` (`w` the masses, and the inertias for the angles; `r` what the rows lack), by
    /// the SVD's least-squares solution.
    fn fill_free_rates(&mut self, asked: &mut [f64], free: &[bool]) -> Result<(), DynamicsError> {
        let cols: Vec<usize> = (0..free.len()).filter(|&c| free[c]).collect();
        if cols.is_empty() {
            return Ok(());
        }
        let (qf, _) = self.frames(&self.q, &self.qd);
        let mut p = self.pairings.clone();
        let rows = self
            .model
            .dense_rows(self.t, &qf, asked, &self.active(&self.in_contact), &mut p)
            .map_err(|source| DynamicsError::Contact {
                time: self.t,
                source,
            })?;
        let m = rows.m;
        if m == 0 {
            return Ok(());
        }
        let weight = |c: usize| {
            let b = &self.model.bodies[c / 3];
            if c % 3 == 2 {
                b.inertia
            } else {
                b.mass
            }
        };
        let a = nalgebra::DMatrix::from_fn(m, cols.len(), |r, j| {
            rows.row(r)[cols[j]] / weight(cols[j]).sqrt()
        });
        let r = nalgebra::DVector::from_fn(m, |r, _| {
            rows.target[r]
                - rows
                    .row(r)
                    .iter()
                    .zip(&*asked)
                    .map(|(j, v)| j * v)
                    .sum::<f64>()
        });
        let eps = 1e-12 * a.amax();
        let Ok(x) = a.svd(true, true).solve(&r, eps) else {
            return Err(DynamicsError::Singular { time: self.t });
        };
        for (j, &c) in cols.iter().enumerate() {
            asked[c] += x[j] / weight(c).sqrt();
        }
        Ok(())
    }

    /// Every closed contact whose gap the frame rates `asked` open (its rate above a
    /// millionth of the system's speed scale) leaves at once: a body thrown off a surface it
    /// rests on.
    pub(super) fn part_by_rates(&mut self, asked: &[f64]) -> Result<(), DynamicsError> {
        // the centres' rates of the frames' asked (as `set_frame_rates` makes them)
        let arms = self.arms(&self.q);
        let mut qd = asked.to_vec();
        for (i, r) in arms.iter().enumerate() {
            let w = asked[3 * i + 2];
            qd[3 * i] -= w * r.y;
            qd[3 * i + 1] += w * r.x;
        }
        let mut p = self.pairings.clone();
        let rows = self.dense(&self.q, &qd, &self.in_contact, &mut p)?;
        // the active contacts' rows are the last, in order
        let closed: Vec<usize> = (0..self.in_contact.len())
            .filter(|&k| self.in_contact[k])
            .collect();
        let first = rows.m - closed.len();
        for (r, &k) in closed.iter().enumerate() {
            let rate: f64 = rows
                .row(first + r)
                .iter()
                .zip(&qd)
                .map(|(j, v)| j * v)
                .sum();
            if self.sense[k] * rate > 1e-6 * self.speed_scale {
                self.open_now(k);
            }
        }
        Ok(())
    }

    /// Contact `k` opens now: a lift-off the next step reports.
    fn open_now(&mut self, k: usize) {
        self.in_contact[k] = false;
        self.pending.push(ContactEvent {
            kind: EventKind::LiftOff,
            time: self.t,
            contact: k,
            approach: 0.0,
        });
    }

    /// Every closed contact whose force is tensile now leaves at once (a lift-off the next
    /// step reports).
    pub(super) fn release_pulled(&mut self) -> Result<(), DynamicsError> {
        let forces = self
            .accel(
                self.t,
                &self.q,
                &self.qd,
                &self.z,
                &self.in_contact.clone(),
                &mut self.pairings.clone(),
            )?
            .forces;
        for (k, &force) in forces.iter().enumerate() {
            if self.in_contact[k] && force < 0.0 {
                self.open_now(k);
            }
        }
        Ok(())
    }
}
