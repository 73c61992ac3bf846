//! A simulated system's steps: the Dormand–Prince 5(4) pair ([`super::super::dopri`]) over the
//! equations of motion ([`super::eval`]) with its step chosen by the tolerances, each step's end
//! projected onto the rows, the events inside a step located on its interpolant (lift-offs by
//! bisection on the force, impacts on the gap), and outputs inside a step interpolated and
//! projected.

use super::super::dopri::{starting_step, Controller};
use super::super::follower::EventKind;
use super::super::stepper::Stepper;
use super::super::DynamicsError;
use super::eval::Accel;
use super::project::StepEnd;
use super::{ContactEvent, SystemRun, SystemSimulation, MAX_EVENTS};
use crate::contact::Pairing;

/// The integrator's state between steps: the stages and interpolant of the last step, its
/// controller, the next step it proposes, and the span, modes and starting pairings the
/// interpolant holds for.
#[derive(Debug, Clone, Default)]
pub(crate) struct Integrator {
    dopri: Stepper,
    /// a step taken again to an event inside the last one
    redo: Stepper,
    control: Controller,
    /// the next step proposed (`None` before the first: estimated)
    next: Option<f64>,
    /// the instants the last step's interpolant holds between (its start, and its end or the
    /// event that cut it)
    span: (f64, f64),
    /// the contacts closed over that span, and every contact's pairing at its start
    modes: Vec<bool>,
    start_pairings: Vec<Option<Pairing>>,
    /// the energy the impacts and projections had changed at its start (a sample inside it
    /// is of the motion before the event or the projection that ended it)
    start_jumps: (f64, f64),
    /// buffers: a state, the stages' pairings, an evaluation
    y: Vec<f64>,
    pairings: Vec<Option<Pairing>>,
    accel: Accel,
    /// the next step the controller asked for after the last accepted one
    next_from_error: f64,
    /// steps accepted and rejected since the start
    pub(crate) accepted: usize,
    pub(crate) rejected: usize,
}

impl SystemSimulation<'_> {
    /// The error scale of component `i` of the state `(q, q̇, p, W)` (see
    /// [`crate::dynamics::Tolerances`]): `atol` times a length's scale (the size), an angle's (a
    /// radian), a rate's (those over the time scale), plus `rtol` times the larger size of the
    /// component at the step's ends; the work `W` is not measured (a quadrature of the powers
    /// on the steps the motion takes).
    fn error_scale(&self, i: usize, y0: f64, y1: f64) -> f64 {
        if i >= 2 * self.q.len() + self.adjusters() {
            return f64::INFINITY;
        }
        let tol = self.opts.tolerances;
        tol.absolute * self.typical(i) + tol.relative * y0.max(y1)
    }

    /// The size of component `i` of the state `(q, q̇, p, W)`: a length's the system's size, an
    /// angle's a radian, a rate's those over the time scale, a lash adjuster's pressure its
    /// supply's (or a bar), a work's 1.
    fn typical(&self, i: usize) -> f64 {
        let n = self.q.len();
        let length = if i % 3 == 2 { 1.0 } else { self.size };
        if i < n {
            length
        } else if i < 2 * n {
            length * self.speed_scale / self.size
        } else if i < 2 * n + self.adjusters() {
            // a chamber's pressure: its supply's, or a bar
            let h = &self.sys.lash_adjusters()[i - 2 * n].adjuster;
            h.supply.abs().max(1e5)
        } else {
            1.0
        }
    }

    /// The longest step a run with outputs every `h_out` s takes: the output interval, or one
    /// degree of the first driver's angle where that is longer, so that a contact that opens
    /// and closes again inside a step (unseen at its ends) is not missed at coarse outputs.
    pub(super) fn longest_step(&self, h_out: f64) -> f64 {
        h_out.max(self.degree_time())
    }

    /// The time the first driver takes to turn a degree now, s (0 where it drives no angle or
    /// stands still).
    pub(super) fn degree_time(&self) -> f64 {
        self.sys
            .drivers()
            .first()
            .filter(|d| d.coordinate == crate::system::Coordinate::Angle)
            .map(|d| d.law.at(self.t)[1].abs())
            .filter(|w| *w > 0.0)
            .map_or(0.0, |w| 1f64.to_radians() / w)
    }

    /// One step from the current state, no longer than `h_max` and ending no later than
    /// `limit`, tried until its error is within the tolerances; its end (projected onto the
    /// rows) becomes the current state, or the first lift-off or impact inside it does (the
    /// event pushed to `events`). The step's interpolant is kept for the outputs inside it.
    pub(super) fn step(
        &mut self,
        limit: f64,
        h_max: f64,
        events: &mut Vec<ContactEvent>,
    ) -> Result<(), DynamicsError> {
        self.wrap_pairings();
        // a step ends at the next corner of an applied load's profile (its force's slope jumps
        // there: a step across it would lose its order)
        let limit = self
            .sys
            .loads()
            .iter()
            .flat_map(|l| l.profile.iter().map(|p| p.0))
            .filter(|&t| t > self.t)
            .fold(limit, f64::min);
        let mut it = std::mem::take(&mut self.integrator);
        let done = self.step_with(&mut it, limit, h_max, events);
        self.integrator = it;
        done
    }

    /// [`SystemSimulation::step`] with the integrator `it` (taken out of the simulation).
    fn step_with(
        &mut self,
        it: &mut Integrator,
        limit: f64,
        h_max: f64,
        events: &mut Vec<ContactEvent>,
    ) -> Result<(), DynamicsError> {
        let (n, m) = (self.q.len(), self.adjusters());
        let t0 = self.t;
        it.y.clear();
        it.y.extend_from_slice(&self.q);
        it.y.extend_from_slice(&self.qd);
        it.y.extend_from_slice(&self.z);
        it.y.extend_from_slice(&self.work);
        let implicit = self.implicit();
        if it.dopri.is_implicit() != implicit {
            it.dopri = Stepper::new(implicit);
            it.control = Controller::of_order(it.dopri.error_order());
        }
        if it.modes != self.in_contact {
            it.dopri.invalidate();
        }
        it.modes.clone_from(&self.in_contact);
        it.start_pairings.clone_from(&self.pairings);
        it.start_jumps = (self.impacts, self.projections);
        let room = limit - t0;
        // the smallest step that still moves the time
        let floor = 1e-14 * t0.abs().max(h_max).max(1e-300);
        // the most a step's end may lie off the rows (a step's drift is of its tolerance): a
        // step beyond a dead point or one that ran away is taken again, shorter
        let tol = self.opts.tolerances;
        let off = 10.0 * tol.relative.max(tol.absolute).max(1e-4);
        // whether a stage's rows were dependent or a step's end could not be put back on them
        // (a dead point ahead, where the drivers cannot take the system on)
        let mut dependent = false;
        let mut shorter: Option<f64> = None;
        loop {
            let h = self.attempt(it, t0, room, h_max, floor, shorter, &mut dependent)?;
            // the end, projected onto the rows
            let y1 = it.dopri.y1();
            self.q.copy_from_slice(&y1[..n]);
            self.qd.copy_from_slice(&y1[n..2 * n]);
            self.z.copy_from_slice(&y1[2 * n..2 * n + m]);
            self.work.copy_from_slice(&y1[2 * n + m..]);
            self.pairings.clone_from(&it.pairings);
            self.t = if h >= room { limit } else { t0 + h };
            let unprojected = self.energy();
            let moved = match self.project() {
                Ok(()) => (0..n)
                    .map(|i| {
                        let scale = if i % 3 == 2 { 1.0 } else { self.size };
                        (self.q[i] - y1[i]).abs() / scale
                    })
                    .fold(0.0f64, f64::max),
                Err(DynamicsError::Unassembled { .. } | DynamicsError::Singular { .. }) => {
                    f64::INFINITY
                }
                Err(e) => return Err(e),
            };
            if moved <= off {
                it.next = Some(it.next_from_error);
                self.projections += self.energy() - unprojected;
                break;
            }
            // back to the start, a fifth of the step
            dependent = true;
            it.accepted -= 1;
            it.rejected += 1;
            self.q.copy_from_slice(&it.y[..n]);
            self.qd.copy_from_slice(&it.y[n..2 * n]);
            self.z.copy_from_slice(&it.y[2 * n..2 * n + m]);
            self.work.copy_from_slice(&it.y[2 * n + m..]);
            self.pairings.clone_from(&it.start_pairings);
            self.t = t0;
            shorter = Some(0.2 * h);
        }
        it.dopri.interpolant();
        // what ended the step: a contact pulled, or a gap closed
        let crossing = self.crossings()?;
        if crossing.is_empty() {
            it.span = (t0, self.t);
            return Ok(());
        }
        // the first crossing on the interpolant, each located by bisection on its own quantity
        let mut first = (f64::INFINITY, 0);
        for &k in &crossing {
            let theta = self.locate(it, k)?;
            if theta < first.0 {
                first = (theta, k);
            }
        }
        let (theta, k) = first;
        // the step's end is given up for the event's instant: its projection's energy with it
        self.projections = it.start_jumps.1;
        self.set_by_step(it, theta)?;
        it.span = (t0, self.t);
        if self.in_contact[k] {
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
            let before = self.energy();
            self.project()?;
            let projected = self.energy();
            self.projections += projected - before;
            // the drivers' impulses' work is theirs: the rest of the change is the impact's loss
            let drivers = self.work[super::balance::DRIVERS];
            let (approach, released) = self.impact(k)?;
            self.impacts +=
                self.energy() - projected - (self.work[super::balance::DRIVERS] - drivers);
            events.push(ContactEvent {
                kind: EventKind::Impact,
                time: self.t,
                contact: k,
                approach,
            });
            // the contacts the impact pulled apart leave at its instant
            for j in released {
                events.push(ContactEvent {
                    kind: EventKind::LiftOff,
                    time: self.t,
                    contact: j,
                    approach: 0.0,
                });
            }
        }
        Ok(())
    }

    /// The system at `t` cannot be taken on: its steps shrank to nothing with stages whose rows
    /// were dependent (a dead point).
    fn dead_point(&self, t: f64) -> DynamicsError {
        let drivers: Vec<String> = self
            .sys
            .drivers()
            .iter()
            .map(|d| format!("driver {:?}", d.name))
            .collect();
        DynamicsError::DeadPoint {
            time: t,
            drivers: drivers.join(", "),
        }
    }

    /// Steps from the state `it.y` at `t0` tried until one's error is within the tolerances
    /// (its stages and end in `it.dopri`, its pairings in `it.pairings`, the next step the
    /// controller asks for in `it.next_from_error`): the step's length. The first try is
    /// `shorter` where given (a step whose end could not be projected, taken again).
    #[allow(clippy::too_many_arguments)]
    fn attempt(
        &self,
        it: &mut Integrator,
        t0: f64,
        room: f64,
        h_max: f64,
        floor: f64,
        shorter: Option<f64>,
        dependent: &mut bool,
    ) -> Result<f64, DynamicsError> {
        let (n, m) = (self.q.len(), self.adjusters());
        let Integrator {
            dopri,
            control,
            y,
            pairings,
            accel,
            modes,
            start_pairings,
            ..
        } = it;
        // the stages' pairings, set back to the step's start before each try
        let stage_pairings = std::cell::RefCell::new(std::mem::take(pairings));
        let mut f = |t: f64, y: &[f64], dy: &mut Vec<f64>| {
            self.derivative(t, y, modes, &mut stage_pairings.borrow_mut(), accel, dy)
        };
        // k₁: the evaluation that ended the last step (kept), or the start's
        let mut k1 = std::mem::take(dopri.first());
        stage_pairings.borrow_mut().clone_from(start_pairings);
        f(t0, y, &mut k1)?;
        let proposed = match it.next {
            Some(h) => h,
            None => {
                let norm = |v: &[f64]| {
                    let s: f64 = (0..2 * n + m)
                        .map(|i| (v[i] / self.error_scale(i, y[i].abs(), y[i].abs())).powi(2))
                        .sum();
                    (s / (2 * n + m) as f64).sqrt()
                };
                let y0 = y.clone();
                starting_step(t0, &y0, &k1, &mut f, norm)?
            }
        };
        let mut h = shorter.unwrap_or(proposed).min(h_max);
        // whether the step was cut to end at the limit
        let mut clipped;
        loop {
            // a step that would end within a hundredth of itself of the limit ends at it (a
            // sliver of a step left before the limit would be below the time's rounding)
            clipped = h >= 0.99 * room;
            if clipped {
                h = room;
            }
            if !(h > floor) {
                if *dependent {
                    return Err(self.dead_point(t0));
                }
                return Err(DynamicsError::StepUnderflow {
                    time: t0,
                    step: h,
                    rtol: self.opts.tolerances.relative,
                    atol: self.opts.tolerances.absolute,
                });
            }
            dopri.first().clone_from(&k1);
            stage_pairings.borrow_mut().clone_from(start_pairings);
            let err = match dopri.attempt(
                t0,
                y,
                h,
                2 * n + m,
                &mut f,
                |i, a, b| self.error_scale(i, a, b),
                |i| self.typical(i),
            ) {
                Ok(err) => err,
                // a stage past a dead point: the step is too long
                Err(DynamicsError::Singular { .. } | DynamicsError::NoConvergence { .. }) => {
                    *dependent = true;
                    f64::INFINITY
                }
                Err(e) => return Err(e),
            };
            let (ok, next) = control.judge(h, err);
            if ok {
                it.accepted += 1;
                it.next_from_error = next;
                break;
            }
            it.rejected += 1;
            h = next;
        }
        *dopri.first() = k1;
        *pairings = stage_pairings.into_inner();
        // a step cut short to end at the limit leaves the controller's proposal
        it.next_from_error = if clipped && h < proposed {
            it.next_from_error.max(proposed)
        } else {
            it.next_from_error
        };
        Ok(h)
    }

    /// The contacts whose force (closed) or gap (open) has crossed zero at the current state.
    fn crossings(&mut self) -> Result<Vec<usize>, DynamicsError> {
        let mut p = std::mem::take(&mut self.spare_pairings);
        p.clone_from(&self.pairings);
        let mut a = std::mem::take(&mut self.sampled.get_mut().1);
        self.accel_into(
            self.t,
            &self.q,
            &self.qd,
            &self.z,
            &self.in_contact,
            &mut p,
            &mut a,
        )?;
        let mut crossing = Vec::new();
        for (k, &force) in a.forces.iter().enumerate() {
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
            std::mem::swap(&mut self.pairings, &mut p);
        }
        self.spare_pairings = p;
        self.sampled.get_mut().1 = a;
        Ok(crossing)
    }

    /// The fraction `θ ∈ (0, 1]` of the last step at which contact `k`'s force (closed) or
    /// gap (open) crosses zero on its interpolant, to 1e-14 of the time.
    fn locate(&self, it: &Integrator, k: usize) -> Result<f64, DynamicsError> {
        let (n, m) = (self.q.len(), self.adjusters());
        let d = &it.dopri;
        let mut y = Vec::new();
        let mut p = Vec::new();
        let value = |theta: f64, y: &mut Vec<f64>, p: &mut Vec<Option<Pairing>>| {
            d.at(theta, y);
            p.clone_from(&it.start_pairings);
            let (q, v, z) = (&y[..n], &y[n..2 * n], &y[2 * n..2 * n + m]);
            if it.modes[k] {
                Ok::<f64, DynamicsError>(
                    self.accel(d.t0() + theta * d.h(), q, v, z, &it.modes, p)?
                        .forces[k],
                )
            } else {
                Ok(self.gap(q, v, k, p)? + 1e-12 * self.size)
            }
        };
        // crossed only once projected: at the step's end
        if value(1.0, &mut y, &mut p)? >= 0.0 {
            return Ok(1.0);
        }
        let (mut lo, mut hi) = (0.0, 1.0);
        let precision = 1e-14 * (1.0 + d.t0().abs()) / d.h();
        while hi - lo > precision {
            let mid = 0.5 * (lo + hi);
            if value(mid, &mut y, &mut p)? >= 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(hi)
    }

    /// The derivative of the state `y = (q, q̇, W)` at `t` in the modes `modes`: `(q̇, q̈, P)`,
    /// `P` the power of each channel of work ([`super::balance`]); the evaluation left in
    /// `accel`.
    fn derivative(
        &self,
        t: f64,
        y: &[f64],
        modes: &[bool],
        pairings: &mut [Option<Pairing>],
        accel: &mut Accel,
        dy: &mut Vec<f64>,
    ) -> Result<(), DynamicsError> {
        let (n, m) = (self.q.len(), self.adjusters());
        let (q, v, z) = (&y[..n], &y[n..2 * n], &y[2 * n..2 * n + m]);
        self.accel_into(t, q, v, z, modes, pairings, accel)?;
        dy.clear();
        dy.extend_from_slice(v);
        dy.extend_from_slice(&accel.qdd);
        self.adjuster_rates(t, q, v, z, dy)?;
        dy.extend_from_slice(&accel.powers);
        Ok(())
    }

    /// The current state set to the end of a step of `θ` of the last one, taken again from its
    /// start in its modes (the fifth-order solution, not the interpolant's fourth: an event's
    /// state starts all that follows it), projected.
    fn set_by_step(&mut self, it: &mut Integrator, theta: f64) -> Result<(), DynamicsError> {
        let (n, m) = (self.q.len(), self.adjusters());
        let (t0, h) = (it.dopri.t0(), theta * it.dopri.h());
        let mut p = it.start_pairings.clone();
        let mut accel = Accel::default();
        let mut redo = std::mem::take(&mut it.redo);
        it.dopri.prepare_redo(&mut redo);
        let this = &*self;
        let mut f = |t: f64, y: &[f64], dy: &mut Vec<f64>| {
            this.derivative(t, y, &it.modes, &mut p, &mut accel, dy)
        };
        let done = redo.attempt(
            t0,
            it.dopri.y0(),
            h,
            2 * n,
            &mut f,
            |i, a, b| this.error_scale(i, a, b),
            |i| this.typical(i),
        );
        match done {
            Err(e) => {
                it.redo = redo;
                return Err(e);
            }
            // the implicit method's Newton did not converge on the shorter step
            Ok(err) if err.is_infinite() && redo.is_implicit() => {
                it.redo = redo;
                return Err(DynamicsError::ImplicitNewton { time: t0, step: h });
            }
            Ok(_) => {}
        }
        let y1 = redo.y1();
        self.q.copy_from_slice(&y1[..n]);
        self.qd.copy_from_slice(&y1[n..2 * n]);
        self.z.copy_from_slice(&y1[2 * n..2 * n + m]);
        self.work.copy_from_slice(&y1[2 * n + m..]);
        it.redo = redo;
        self.pairings = p;
        self.in_contact.clone_from(&it.modes);
        self.t = t0 + h;
        self.project_counted()
    }

    /// The current state set to the last step's interpolant at `θ`, in its modes, projected.
    fn set_from_interpolant(&mut self, it: &Integrator, theta: f64) -> Result<(), DynamicsError> {
        let (n, m) = (self.q.len(), self.adjusters());
        let mut y = Vec::new();
        it.dopri.at(theta, &mut y);
        self.q.copy_from_slice(&y[..n]);
        self.qd.copy_from_slice(&y[n..2 * n]);
        self.z.copy_from_slice(&y[2 * n..2 * n + m]);
        self.work.copy_from_slice(&y[2 * n + m..]);
        self.pairings.clone_from(&it.start_pairings);
        self.in_contact.clone_from(&it.modes);
        self.t = it.dopri.t0() + theta * it.dopri.h();
        self.project_counted()
    }

    /// [`SystemSimulation::project`], the energy it changed counted in the balance.
    fn project_counted(&mut self) -> Result<(), DynamicsError> {
        let before = self.energy();
        self.project()?;
        self.projections += self.energy() - before;
        Ok(())
    }

    /// The tolerances of the steps from now on (see [`crate::dynamics::Tolerances`]); refused
    /// out of [`crate::dynamics::Tolerances::RANGE`].
    pub fn set_tolerances(
        &mut self,
        tolerances: crate::dynamics::Tolerances,
    ) -> Result<(), DynamicsError> {
        if let Some((which, value)) = tolerances.out_of_range() {
            return Err(DynamicsError::Tolerance { which, value });
        }
        self.opts.tolerances = tolerances;
        Ok(())
    }

    /// The integrator of the steps from now on ([`crate::dynamics::Scheme`]).
    pub fn set_scheme(&mut self, scheme: crate::dynamics::Scheme) {
        self.opts.scheme = scheme;
    }

    /// The steps taken since the start: accepted, and rejected (their error above the
    /// tolerances, or a stage past a dead point).
    pub fn steps_taken(&self) -> (usize, usize) {
        (self.integrator.accepted, self.integrator.rejected)
    }

    /// The integrator its steps take: [`crate::dynamics::Scheme::Explicit`] or
    /// [`crate::dynamics::Scheme::Implicit`] (the options' choice, or the one
    /// [`crate::dynamics::Scheme::Auto`] made from the system's rates).
    pub fn scheme_in_use(&self) -> crate::dynamics::Scheme {
        if self.implicit() {
            crate::dynamics::Scheme::Implicit
        } else {
            crate::dynamics::Scheme::Explicit
        }
    }

    /// Advances by `h` seconds in steps chosen by the tolerances (the last cut to end at
    /// `t + h`), locating every lift-off and impact inside.
    pub fn advance(&mut self, h: f64) -> Result<Vec<ContactEvent>, DynamicsError> {
        if !(h > 0.0 && h.is_finite()) {
            return Err(DynamicsError::Element {
                element: "the simulation".into(),
                key: "time step (s)",
                value: h,
                reason: "must be positive",
            });
        }
        let mut events = std::mem::take(&mut self.pending);
        let stop = self.t + h;
        let h_max = self.longest_step(h);
        while self.t < stop {
            if events.len() > MAX_EVENTS {
                return Err(DynamicsError::Chatter {
                    time: self.t,
                    events: MAX_EVENTS,
                });
            }
            self.step(stop, h_max, &mut events)?;
        }
        Ok(events)
    }

    /// `outputs` output intervals of `h_out` s, sampled at the start and at the end of each
    /// (where a step passes an output, its interpolant there, projected onto the rows);
    /// `progress(k)` after the `k`-th (breaking off stops the run with
    /// [`DynamicsError::Stopped`]).
    pub fn run(
        &mut self,
        outputs: usize,
        h_out: f64,
        mut progress: impl FnMut(usize) -> std::ops::ControlFlow<()>,
    ) -> Result<SystemRun, DynamicsError> {
        if !(h_out > 0.0 && h_out.is_finite()) {
            return Err(DynamicsError::Element {
                element: "the simulation".into(),
                key: "output interval (s)",
                value: h_out,
                reason: "must be positive",
            });
        }
        let mut samples = Vec::with_capacity(outputs + 1);
        let mut events = std::mem::take(&mut self.pending);
        samples.push(self.sample()?);
        let start = self.t;
        let end = start + outputs as f64 * h_out;
        let h_max = self.longest_step(h_out);
        let mut k = 1;
        let mut since = events.len();
        let implicit = self.implicit();
        while k <= outputs {
            // the implicit method's steps end at the outputs (its interpolant's end slopes carry a
            // stiff component's error times its rate)
            let limit = if implicit && k < outputs {
                start + k as f64 * h_out
            } else {
                end
            };
            self.step(limit, h_max, &mut events)?;
            if events.len() - since > MAX_EVENTS {
                return Err(DynamicsError::Chatter {
                    time: self.t,
                    events: MAX_EVENTS,
                });
            }
            let reached = self.integrator.span.1;
            while k <= outputs {
                let tk = if k == outputs {
                    end
                } else {
                    start + k as f64 * h_out
                };
                if tk > reached {
                    break;
                }
                samples.push(if tk == self.t {
                    self.sample()?
                } else {
                    self.sample_between(tk)?
                });
                since = events.len();
                if progress(k).is_break() {
                    return Err(DynamicsError::Stopped { done: k, outputs });
                }
                k += 1;
            }
        }
        Ok(SystemRun { samples, events })
    }

    /// The sample at `t` inside the last step: its interpolant there in its modes, projected
    /// onto the rows; the current state is kept.
    fn sample_between(&mut self, t: f64) -> Result<SystemSample, DynamicsError> {
        let it = std::mem::take(&mut self.integrator);
        let theta = (t - it.dopri.t0()) / it.dopri.h();
        // the current state kept aside
        let mut kept = StepEnd {
            q: self.q.clone(),
            qd: self.qd.clone(),
            pairings: self.pairings.clone(),
        };
        let (t_now, work, modes) = (self.t, self.work.clone(), self.in_contact.clone());
        let z = self.z.clone();
        let jumps = (self.impacts, self.projections);
        (self.impacts, self.projections) = it.start_jumps;
        let sampled = self
            .set_from_interpolant(&it, theta.clamp(0.0, 1.0))
            .and_then(|()| {
                self.t = t;
                self.sample()
            });
        self.swap_state(&mut kept);
        (self.t, self.work, self.in_contact) = (t_now, work, modes);
        self.z = z;
        (self.impacts, self.projections) = jumps;
        self.integrator = it;
        sampled
    }
}

use super::SystemSample;
