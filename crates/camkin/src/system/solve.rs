//! The kinematic analysis of a [`System`] at one instant: positions by Newton on `Φ = 0` (each
//! contact's pairing re-solved at every step), then velocities and accelerations by one linear
//! solve each with the same `Φ_q`. A [`SystemSweep`] warm-starts each instant from the last
//! (positions predicted by the last velocities and accelerations, pairings by their rates).

use super::bending::bending;
use super::newton::{fill_states, iamax, Scratch};
use super::{System, SystemError};
use crate::body::BodyState;
use crate::contact::{ContactKinematics, CurveIndex, Pairing, SearchOptions};
use crate::geometry::Vec2;

/// A converged instant whose rows are still off by more than this times the size did not
/// assemble.
const RESIDUAL_TOLERANCE: f64 = 1e-9;

/// One contact at an instant: its pairing points and its kinematics (sliding rates, normal
/// acceleration terms, the row and `γ`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactState {
    /// the pairing (gap 0 at a solved instant)
    pub pairing: Pairing,
    /// the paper's kinematics at it
    pub kinematics: ContactKinematics,
    /// the contact moved to another pair of points since the last instant (the pair it
    /// followed would have let the curves overlap elsewhere: a gear's next tooth, a cam's
    /// concave stretch bridged); the acceleration is impulsive there
    pub jumped: bool,
}

/// Every body's pose, velocity and acceleration and every contact's kinematics at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct SystemState {
    /// the instant, s
    pub time: f64,
    /// the bodies, in the system's order
    pub bodies: Vec<BodyState>,
    /// the contacts, in the system's order
    pub contacts: Vec<ContactState>,
    /// Newton iterations on the positions
    pub iterations: u32,
}

impl Solved {
    /// The farthest any body moves in `dt` from this instant by its rates and accelerations:
    /// its origin's move plus its angle's times `size`.
    fn predicted_move(&self, dt: f64, size: f64) -> f64 {
        let mut far: f64 = 0.0;
        for i in 0..self.q.len() / 3 {
            let (v, a) = (&self.qd[3 * i..3 * i + 3], &self.qdd[3 * i..3 * i + 3]);
            let linear = v[0].hypot(v[1]) * dt.abs() + 0.5 * a[0].hypot(a[1]) * dt * dt;
            let angular = size * (v[2].abs() * dt.abs() + 0.5 * a[2].abs() * dt * dt);
            far = far.max(linear + angular);
        }
        far
    }
}

/// What solving the positions keeps for the next instant.
#[derive(Debug, Clone, Default)]
struct Solved {
    time: f64,
    q: Vec<f64>,
    qd: Vec<f64>,
    qdd: Vec<f64>,
    pairings: Vec<(f64, f64)>,
    rates: Vec<(f64, f64)>,
    /// each contact's sliding rates along A and B, length/s
    slides: Vec<(f64, f64)>,
    /// the coordinates' third derivative, from this instant's accelerations and the last's
    /// (zero at the first): the predictor's cubic term
    qddd: Vec<f64>,
}

/// The farthest any body may move between two instants that Newton joins, as a fraction of the
/// system's size (an angle counts times the size), predicted from the last instant's rates and
/// accelerations: a longer step is taken through instants between, so that Newton stays on the
/// assembly it follows. One step of 90° of the valve train's cam converged on another assembly
/// (the finger 68° up where it is 15.6°), which only the contact's jump flag showed; at this
/// bound the step is a few degrees of a cam, and a sweep at 0.25° never divides one.
const MAX_MOVE: f64 = 0.05;

/// The smallest pivot of the rows below this times the largest, at the last instant reached
/// before one that cannot be solved (and four times below where the step began), is a dead
/// point: the rows at a toggle are dependent, and an instant 1/4096 of a step before it is
/// within this (a four-bar driven by its rocker: 1e-3 there, 4e-5 nearer).
const DEAD_POINT: f64 = 1e-2;

/// Most instants between two asked for.
const MAX_SUBSTEPS: f64 = 65_536.0;

/// The longest an instant far away may take to reach through the instants between, s (the work
/// limit every entry point refuses beyond, [`crate::work::SECONDS_LIMIT`]).
const FAR_SECONDS: f64 = 30.0;

/// An instant farther from the last than this many instants between is reached through the
/// system's period where it repeats ([`super::period`]).
const FAR_INSTANTS: f64 = 2048.0;

/// Most times one instant moves its contacts to other pairs of points.
const MAX_JUMPS: usize = 8;

/// Instants of a system in order, each warm-started from the last.
#[derive(Debug)]
pub struct SystemSweep<'a> {
    pub(super) sys: &'a System,
    pub(super) opts: SearchOptions,
    pub(super) size: f64,
    last: Option<Solved>,
    /// the instant before the last's vectors, reused for the next
    spare: Option<Solved>,
    /// each contact's curves' search indexes, for the check that no other pair of points
    /// overlaps
    pub(super) indexes: Vec<(Option<CurveIndex>, Option<CurveIndex>)>,
    /// whether each contact's curves are both convex (a closed convex curve, a line, a point):
    /// two convex bodies touching at a point overlap nowhere else, so the check is not needed
    pub(super) convex: Vec<bool>,
    /// the smallest radius of curvature of the contacts' curves (sampled; at most the size)
    pub(super) sharpest: f64,
    /// the contacts that jumped in any instant solved on the way to the one asked for
    jumps: Vec<bool>,
    /// buffers an instant reuses
    scratch: Scratch,
    /// after how long the system repeats, once an instant far away asked for it (`Some(None)`:
    /// it does not within [`super::period::MAX_REVOLUTIONS`] revolutions)
    period: Option<Option<super::period::Period>>,
}

impl System {
    /// The system at time `t` (s), solved from the bodies' starting poses (each contact's
    /// pairing found by a global search first).
    pub fn analyze(&self, t: f64) -> Result<SystemState, SystemError> {
        self.sweep()?.step(t)
    }

    /// A sweep: instants solved in turn, each from the last.
    pub fn sweep(&self) -> Result<SystemSweep<'_>, SystemError> {
        self.check()?;
        let size = self.size();
        let opts = SearchOptions::for_length_scale(size);
        let indexes = self
            .contacts
            .iter()
            .map(|c| {
                (
                    CurveIndex::new(c.curve_a.as_ref(), &opts),
                    CurveIndex::new(c.curve_b.as_ref(), &opts),
                )
            })
            .collect();
        // each contact's curves, sampled once: both convex (no overlap check needed) and the
        // sharpest radius of curvature (Newton's one-step rule)
        let mut convex = Vec::with_capacity(self.contacts.len());
        let mut sharpest = size;
        for c in &self.contacts {
            let (ca, ra) = bending(c.curve_a.as_ref(), size);
            let (cb, rb) = bending(c.curve_b.as_ref(), size);
            convex.push(ca && cb);
            sharpest = sharpest.min(ra).min(rb);
        }
        Ok(SystemSweep {
            sys: self,
            opts,
            size,
            last: None,
            spare: None,
            indexes,
            convex,
            sharpest,
            jumps: vec![false; self.contacts.len()],
            scratch: Scratch::default(),
            period: None,
        })
    }
}

/// A system's instants at given times, in order, each warm-started from the last: what every
/// front end sweeps. The first is solved when the sweep is made ([`System::instants`]), so that
/// a system that cannot be analysed there (a loop that does not close, a redundant joint, a
/// driver on a coordinate a joint fixes) is an error before any answer; a later instant that
/// fails is its own item.
#[derive(Debug)]
pub struct Instants<'a> {
    sweep: SystemSweep<'a>,
    first: Option<SystemState>,
    times: std::slice::Iter<'a, f64>,
}

impl System {
    /// The instants at `times` (s), in order (see [`Instants`]); the first instant's error if
    /// it cannot be solved.
    pub fn instants<'a>(&'a self, times: &'a [f64]) -> Result<Instants<'a>, SystemError> {
        let mut sweep = self.sweep()?;
        let mut times = times.iter();
        let first = match times.next() {
            Some(&t) => Some(sweep.step(t)?),
            None => None,
        };
        Ok(Instants {
            sweep,
            first,
            times,
        })
    }
}

impl Iterator for Instants<'_> {
    type Item = Result<SystemState, SystemError>;

    fn next(&mut self) -> Option<Self::Item> {
        if let Some(s) = self.first.take() {
            return Some(Ok(s));
        }
        let &t = self.times.next()?;
        Some(self.sweep.step(t))
    }
}

impl SystemSweep<'_> {
    /// The system at time `t`, warm-started from the last instant solved. The first instant is
    /// reached from the bodies' starting poses, which are a guess at `t = 0` (each contact's
    /// pairing found there by a global search). An instant too far from the last for Newton
    /// (the drivers moved a long way) is reached through instants between: the answer is the
    /// assembly continuously connected to the start, on its branch.
    pub fn step(&mut self, t: f64) -> Result<SystemState, SystemError> {
        let first = self.last.is_none();
        if first && t != 0.0 {
            self.step_once(0.0)?;
        }
        self.jumps.iter_mut().for_each(|j| *j = false);
        if let Some(s) = self.far(t)? {
            return Ok(s);
        }
        let mut s = self.step_reached(t)?;
        // a jump in an instant between (the continuation's) is this step's
        for (c, &j) in s.contacts.iter_mut().zip(&self.jumps) {
            c.jumped = j && !first;
        }
        Ok(s)
    }

    /// An instant more than [`FAR_INSTANTS`] instants between from the last: where the system
    /// repeats, the instant that many whole periods nearer the start, reached from the start
    /// and turned on by the periods' turns (this sweep goes on from there); where it does not
    /// and more than [`MAX_SUBSTEPS`] instants, or [`FAR_SECONDS`] by
    /// [`System::instant_seconds`](super::System::instant_seconds), would be needed, refused
    /// ([`SystemError::TooFar`]);
    /// `None` for the instants between.
    fn far(&mut self, t: f64) -> Result<Option<SystemState>, SystemError> {
        let Some(last) = &self.last else {
            return Ok(None);
        };
        let from = last.time;
        let n = last.predicted_move(t - from, self.size) / (MAX_MOVE * self.size);
        if !(n > FAR_INSTANTS) {
            return Ok(None);
        }
        if self.period.is_none() {
            self.period = Some(self.sys.period()?);
        }
        match self.period.clone().flatten() {
            Some(p) => {
                let periods = (t / p.time).floor();
                let mut near = self.sys.sweep()?;
                let state = near.step(t - periods * p.time)?;
                let Some(mut last) = near.last.take() else {
                    return Ok(None);
                };
                last.time += periods * p.time;
                for (b, turn) in p.turns.iter().enumerate() {
                    last.q[3 * b + 2] += periods * turn;
                }
                self.last = Some(last);
                self.spare = None;
                Ok(Some(p.shift(state, periods)))
            }
            None if n > MAX_SUBSTEPS || n * self.sys.instant_seconds() > FAR_SECONDS => {
                Err(SystemError::TooFar {
                    time: t,
                    from,
                    instants: n,
                    seconds: n * self.sys.instant_seconds(),
                })
            }
            None => Ok(None),
        }
    }

    /// `t` from the last instant, through instants between where the bodies would move far
    /// (see [`MAX_MOVE`]) or Newton needs them.
    fn step_reached(&mut self, t: f64) -> Result<SystemState, SystemError> {
        if let Some(last) = &self.last {
            let (from, dt) = (last.time, t - last.time);
            let size = self.size;
            let n = (last.predicted_move(dt, size) / (MAX_MOVE * size)).ceil();
            if n > 1.0 && n.is_finite() {
                let n = n.min(MAX_SUBSTEPS) as usize;
                for k in 1..n {
                    self.step_continued(from + dt * k as f64 / n as f64)?;
                }
            }
        }
        self.step_continued(t)
    }

    /// `t` from the last instant, through instants between where Newton fails.
    fn step_continued(&mut self, t: f64) -> Result<SystemState, SystemError> {
        match self.step_once(t) {
            Ok(s) => Ok(s),
            Err(
                e @ (SystemError::NoAssembly { .. }
                | SystemError::Contact { .. }
                | SystemError::Singular { .. }
                | SystemError::HeldApart { .. }),
            ) => {
                let Some(from) = self.last.as_ref().map(|l| l.time) else {
                    return Err(e);
                };
                let before = self.conditioning(false).map(|c| c.0);
                self.continue_to(from, t, 0)
                    .map_err(|_| self.dead_point(before).unwrap_or(e))
            }
            Err(e) => Err(e),
        }
    }

    /// The last instant's rows: how far from dependent they are (the smallest pivot over the
    /// largest) and, when they are nearly dependent, which; `None` where they cannot be
    /// assembled.
    fn conditioning(&mut self, name: bool) -> Option<(f64, f64, String)> {
        let last = self.last.as_ref()?;
        let (time, q, mut pairings) = (last.time, last.q.clone(), last.pairings.clone());
        let nb = self.sys.bodies.len();
        let mut w = std::mem::take(&mut self.scratch);
        fill_states(&q, None, nb, &mut w.st);
        let mut flags = vec![false; self.sys.contacts.len()];
        let found = match self.assemble(time, &w.st, &mut pairings, &mut flags, false, &mut w.asm) {
            Ok(()) => {
                w.lu.factor(&w.asm.jac, 3 * nb);
                let (lo, hi) = w.lu.pivots;
                let rows = if name {
                    self.dependent_rows(&w.asm.jac)
                } else {
                    String::new()
                };
                Some((lo / hi, time, rows))
            }
            Err(_) => None,
        };
        self.scratch = w;
        found
    }

    /// After instants were reached ever closer to one that cannot be solved: a dead point
    /// (toggle) the drivers cannot take the system past, when the rows at the last instant
    /// reached are nearly dependent and were at least four times less so where the step began (`before`, their
    /// conditioning there); `None` where the failure is another (a contact lost, a loop that
    /// does not close).
    fn dead_point(&mut self, before: Option<f64>) -> Option<SystemError> {
        let before = before?;
        let (now, time, rows) = self.conditioning(true)?;
        (now < DEAD_POINT && now < 0.25 * before).then_some(SystemError::DeadPoint { time, rows })
    }

    /// Reaches `t` from the last instant (at `from`) through the midpoint, halving again where
    /// that fails, to a depth of 12 (4096 instants).
    fn continue_to(&mut self, from: f64, t: f64, depth: u32) -> Result<SystemState, SystemError> {
        if depth >= 12 {
            return self.step_once(t);
        }
        let mid = 0.5 * (from + t);
        let saved = self.last.clone();
        let reached = match self.step_once(mid) {
            Ok(_) => Ok(()),
            Err(_) => {
                self.last = saved.clone();
                self.continue_to(from, mid, depth + 1).map(|_| ())
            }
        };
        reached?;
        match self.step_once(t) {
            Ok(s) => Ok(s),
            Err(_) => self.continue_to(mid, t, depth + 1),
        }
    }

    /// One instant from the last, with no continuation (its buffers taken for the instant).
    fn step_once(&mut self, t: f64) -> Result<SystemState, SystemError> {
        let mut w = std::mem::take(&mut self.scratch);
        let r = self.instant(t, &mut w);
        self.scratch = w;
        r
    }

    fn instant(&mut self, t: f64, w: &mut Scratch) -> Result<SystemState, SystemError> {
        let sys = self.sys;
        let nb = sys.bodies.len();
        let nc = sys.contacts.len();
        let size = self.size;
        // this instant's vectors: the last but one's, reused
        let mut next = self.spare.take().unwrap_or_default();
        next.time = t;
        match &self.last {
            Some(s) => {
                let dt = t - s.time;
                // a cubic prediction: Newton then needs one iteration (its step about dt⁴)
                next.q.clear();
                next.q.extend((0..s.q.len()).map(|i| {
                    s.q[i] + dt * (s.qd[i] + dt * (0.5 * s.qdd[i] + dt * s.qddd[i] / 6.0))
                }));
                next.pairings.clear();
                next.pairings.extend(
                    s.pairings
                        .iter()
                        .zip(&s.rates)
                        .map(|(&(ua, ub), &(ra, rb))| (ua + ra * dt, ub + rb * dt)),
                );
            }
            None => {
                next.q = sys
                    .bodies
                    .iter()
                    .flat_map(|b| [b.pose.origin.x, b.pose.origin.y, b.pose.angle])
                    .collect();
                next.pairings = self.global_pairings(t, &next.q)?;
            }
        };
        w.q0.clear();
        w.q0.extend_from_slice(&next.q);
        let mut jumped = std::mem::take(&mut w.jumped);
        jumped.clear();
        jumped.resize(nc, false);
        let q = &mut next.q;
        let pairings = &mut next.pairings;
        let mut iterations = self.positions(t, q, pairings, &mut jumped, w)?;
        // a contact is unilateral: where the curves overlap at another pair of points, that pair
        // is the contact (the one followed has left), and the instant is solved again with it
        for _ in 0..MAX_JUMPS {
            let moved = self.overlaps(t, q, pairings, &mut jumped)?;
            if !moved {
                break;
            }
            iterations += self.positions(t, q, pairings, &mut jumped, w)?;
        }
        // positions are continuous in time even where a contact jumps (its rates jump): an
        // assembly farther from the prediction than twice the step's whole move is another one
        // (a gear turned by a tooth, another branch), and the step is taken in halves instead
        if let Some(last) = &self.last {
            let allowed = 2.0 * last.predicted_move(t - last.time, size) + 1e-4 * size;
            let (mut off, mut at) = (0.0f64, 0);
            for i in 0..nb {
                let q0 = &w.q0;
                let d = (q[3 * i] - q0[3 * i]).hypot(q[3 * i + 1] - q0[3 * i + 1])
                    + size * (q[3 * i + 2] - q0[3 * i + 2]).abs();
                if d > off {
                    (off, at) = (d, i);
                }
            }
            if off > allowed {
                return Err(SystemError::NoAssembly {
                    time: t,
                    reason: "the assembly found is farther from the last instant's than the bodies' rates allow (a gear turned by a tooth, another branch)",
                    residual: off,
                    row: format!("body {:?}", sys.bodies[at].name),
                });
            }
        }
        // velocities: Φ_q q̇ = −Φ_t (the drivers' rates)
        // the first instant's pairings are where the search started, not a jump
        if self.last.is_none() {
            jumped.iter_mut().for_each(|j| *j = false);
        }
        let mut still = std::mem::take(&mut w.still);
        still.clear();
        still.resize(nc, false);
        fill_states(q, None, nb, &mut w.st);
        self.assemble(t, &w.st, pairings, &mut still, false, &mut w.asm)?;
        let r = iamax(&w.asm.phi);
        let residual = w.asm.phi.get(r).map_or(0.0, |v| v.abs());
        if residual > RESIDUAL_TOLERANCE * size {
            return Err(SystemError::NoAssembly {
                time: t,
                reason: "the rows are not met where Newton stopped",
                residual,
                row: sys.row_name(r),
            });
        }
        self.factor(t, &w.asm.jac, &mut w.lu)?;
        // the angle columns were scaled by the size
        let unscale = |v: &mut Vec<f64>, x: &[f64]| {
            v.clear();
            v.extend_from_slice(x);
            for i in 0..nb {
                v[3 * i + 2] /= size;
            }
        };
        w.lu.solve(&w.asm.rate, &mut w.x);
        unscale(&mut next.qd, &w.x);
        // accelerations: Φ_q q̈ = γ, every contact's γ from its exact sliding rates
        fill_states(&next.q, Some(&next.qd), nb, &mut w.st);
        self.assemble(t, &w.st, &mut next.pairings, &mut still, true, &mut w.asm)?;
        w.lu.solve(&w.asm.gamma, &mut w.x);
        unscale(&mut next.qdd, &w.x);
        let qdd = &next.qdd;
        let b = &w.asm;
        let bodies: Vec<BodyState> = (0..nb)
            .map(|i| {
                let mut s = w.st[i];
                s.acceleration = Vec2::new(qdd[3 * i], qdd[3 * i + 1]);
                s.alpha = qdd[3 * i + 2];
                s
            })
            .collect();
        // a contact point that moved along its curve much farther than its sliding rates at
        // both ends say (their mean times the step: third-order accurate) went to another pair
        // of points that was touching too (a gear's next tooth pair)
        if let Some(last) = &self.last {
            let dt = t - last.time;
            for (k, c) in sys.contacts.iter().enumerate() {
                let Some(now) = b.contacts[k].1 else { continue };
                let (was, slid) = (last.pairings[k], last.slides[k]);
                // parameters that moved as their rates say (within a quarter) moved along the
                // curves as the sliding rates say: no chord to measure
                let (ra, rb) = last.rates[k];
                let as_rates = |from: f64, to: f64, r0: f64, r1: f64| {
                    let expected = 0.5 * (r0 + r1) * dt;
                    (to - from - expected).abs() <= 0.25 * expected.abs()
                };
                if as_rates(was.0, next.pairings[k].0, ra, now.param_rate_a)
                    && as_rates(was.1, next.pairings[k].1, rb, now.param_rate_b)
                {
                    continue;
                }
                let moved = |curve: &dyn crate::curve::Curve, a: f64, b: f64, rates: (f64, f64)| {
                    let chord = (curve.position(b) - curve.position(a)).norm();
                    let expected = (0.5 * (rates.0 + rates.1) * dt).abs();
                    chord > 2.0 * expected + 1e-3 * size
                };
                if moved(
                    c.curve_a.as_ref(),
                    was.0,
                    next.pairings[k].0,
                    (slid.0, now.sliding_rate_a),
                ) || moved(
                    c.curve_b.as_ref(),
                    was.1,
                    next.pairings[k].1,
                    (slid.1, now.sliding_rate_b),
                ) {
                    jumped[k] = true;
                }
            }
        }
        for (all, &j) in self.jumps.iter_mut().zip(&jumped) {
            *all |= j;
        }
        let contacts: Vec<ContactState> = b
            .contacts
            .iter()
            .zip(&jumped)
            .filter_map(|((p, k), &jumped)| {
                k.map(|k| ContactState {
                    pairing: *p,
                    kinematics: k,
                    jumped,
                })
            })
            .collect();
        next.rates.clear();
        next.rates.extend(
            contacts
                .iter()
                .map(|c| (c.kinematics.param_rate_a, c.kinematics.param_rate_b)),
        );
        next.slides.clear();
        next.slides.extend(
            contacts
                .iter()
                .map(|c| (c.kinematics.sliding_rate_a, c.kinematics.sliding_rate_b)),
        );
        // the third derivative, for the next prediction: not across a jump of a contact (the
        // accelerations change there at once)
        next.qddd.clear();
        match &self.last {
            Some(l) if t != l.time && l.qdd.len() == qdd.len() && !jumped.iter().any(|&j| j) => {
                let h = t - l.time;
                next.qddd
                    .extend(qdd.iter().zip(&l.qdd).map(|(a, b)| (a - b) / h));
            }
            _ => next.qddd.resize(qdd.len(), 0.0),
        };
        w.jumped = jumped;
        w.still = still;
        self.spare = self.last.replace(next);
        Ok(SystemState {
            time: t,
            bodies,
            contacts,
            iterations,
        })
    }
}
