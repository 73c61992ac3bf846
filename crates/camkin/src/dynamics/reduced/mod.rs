//! The cam solver's dynamics (`spec::Solver::Cam`): a preset's follower as one coordinate
//! driven by the cam through its contacts, where its contact jumps from one part of the curves
//! to another (gears at a tooth handover, a flat face across a concave stretch) or it is
//! form-closed, with or without play (a conjugate cam, gear backlash).
//!
//! # Model
//!
//! The cam's rotation is prescribed, `θ(t) = θ₀ + ω t + ½ α t²`. The follower has one
//! coordinate; write it as the **opening coordinate** `o = a q` (`a = +1` for a slide, minus the
//! closing sense for an arm), which grows away from the cam. Its own curve's first touch
//! `o₁(θ)` (the contact method, exact at every angle) bounds it from below, `o ≥ o₁`; a second
//! curve's first touch `o₂(θ)` bounds it from above, `o ≤ o₂`, and `o₂ − o₁` is the play
//! ([`crate::cam::Mechanism::conjugate_play`]). With `M` the mass (inertia), the spring (preload
//! `F₀` at rest `o_r`, stiffness `k`), damping `c` and gravity `G` along `o`,
//!
//! ```text
//! M ö = −F₀ − k (o − o_r) − c ȯ + G + λ₁ − λ₂,     λ₁, λ₂ ≥ 0
//! ```
//!
//! where `λ₁` (`λ₂`) is the contact's generalized force, nonzero only while that curve touches.
//!
//! - **In contact** the follower moves with the first touch: `o = o_i(θ)`, `ȯ = o_i' θ̇`,
//!   `ö = o_i'' θ̇² + o_i' α` (derivatives in the cam angle from the contact method's velocity
//!   and acceleration), so there is no integration error; the contact force is
//!   `λ₁ = M ö − Q` (`λ₂ = Q − M ö`) with `Q` the applied force, and the follower lifts off
//!   where it would turn tensile (located by bisection). Where both curves touch (no play) the
//!   load passes from one to the other without an event.
//! - **In flight** the equation is linear with constant coefficients and is solved exactly (the
//!   exponential of a 3 × 3 matrix); the gaps `o − o₁` and `o₂ − o` are watched, and where one
//!   closes (located by bisection) the follower hits that curve.
//! - **A jump** of the contact (the warm sweep of the first touch reports
//!   [`Found::Jump`]: another part of the curves, another tooth pair, touches first) is an
//!   impact without flight: the position is continuous (the first touch is the envelope of the
//!   candidates), the flank's velocity is not, and the new part always pushes the follower away
//!   from the cam.
//! - **An impact** reverses the relative velocity times the restitution `e`:
//!   `ȯ⁺ = ȯ_f − e (ȯ⁻ − ȯ_f)`; a rebound slower than [`REBOUND_TOLERANCE`] `· ω · size` keeps the
//!   follower on the curve (as in the multibody model).
//!
//! The driving torque is the contact's reaction, `T = λ₁ o₁'` (`−λ₂ o₂'`) in the cam's sense,
//! so that `T θ̇` is the power the follower receives; the driver's work counts the impulses too
//! (`M Δȯ · ȯ_f` at an impact).
//!
//! The energy balance ([`Reduced::balance`], the [`super::EnergyBalance`] every model reports)
//! holds the follower's kinetic energy, its spring's and gravity's potential, the damper's work
//! (Simpson's rule on each step: in flight with the exact midpoint state), the impacts' losses
//! (`−½ M (1 − e²) u²` each) and the driver's work. In contact the motion is the first touch
//! exactly and the driver's work is what the follower's energy and the damper ask of it; the
//! balance checks the flight (exact motion against the damper's quadrature) and the impacts.

use super::{DynamicsError, Event, EventKind, FollowerDynamics, Sample, REBOUND_TOLERANCE};
use crate::cam::{CamError, Found, Mechanism, Sweep};
use crate::geometry::wrap_angle_near;
use nalgebra::{Matrix3, Vector3};

mod balance;
mod jumps;

/// Which curve of the follower touches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    /// no contact
    Flight,
    /// the follower's own curve (0) or its second curve (1)
    Contact(usize),
}

/// One curve's first touch at a cam angle in the opening coordinate: `o`, `do/dθ`, `d²o/dθ²`.
#[derive(Debug, Clone, Copy)]
struct Kin {
    o: f64,
    d1: f64,
    d2: f64,
    /// the sweep found the contact on another part of the curves than the last angle's
    jumped: bool,
}

/// One of the follower's curves: its mechanism (for the second curve, the conjugate's own) and
/// its warm sweeps.
#[derive(Debug, Clone)]
struct Side<'a> {
    mech: &'a Mechanism,
    /// the opening coordinate per unit of this mechanism's coordinate
    map: f64,
    /// the first touch, stepped to the current time's cam angle
    sweep: Sweep<'a>,
    /// full states for samples and events (stepped forward in time only)
    states: Sweep<'a>,
    /// the first touch at the current time
    at: Kin,
}

impl Reduced<'_> {
    /// The seconds of one cold first-touch search of each of the follower's curves, summed
    /// ([`Mechanism::search_seconds_estimate`]).
    pub(crate) fn search_seconds(&self) -> f64 {
        self.sides
            .iter()
            .map(|s| s.mech.search_seconds_estimate())
            .sum()
    }
}

/// The largest number of events in one step before the run is stopped as chattering.
const MAX_EVENTS_PER_STEP: usize = 1000;

/// A follower driven through its contacts as one coordinate (see the module docs).
#[derive(Debug, Clone)]
pub struct Reduced<'a> {
    sides: Vec<Side<'a>>,
    params: FollowerDynamics,
    /// mass or inertia
    m: f64,
    /// `o = a q`
    a: f64,
    rotating: bool,
    /// the constant part of the applied force along `o`: `−F₀ + k o_r + G`
    f: f64,
    theta0: f64,
    omega: f64,
    alpha: f64,
    /// the cam's sense (+1 ccw)
    cam_sign: f64,
    t: f64,
    o: f64,
    v: f64,
    mode: Mode,
    work: f64,
    /// the follower's joint (its momentum, gravity's potential)
    joint: crate::cam::FollowerJoint,
    /// `o` at the spring's rest (its preload's position)
    o_rest: f64,
    /// `o` and `T + V` at the start
    start: (f64, f64),
    /// the damper's work since the start (≤ 0), J
    damper_work: f64,
    /// the impacts' change of kinetic energy beyond the impulses' work at the flank's velocity
    /// (≤ 0), J
    impacts: f64,
    /// the cam's size (length)
    size: f64,
    /// gap tolerance in `o` (length or rad)
    gap_tol: f64,
    /// force tolerance of the lift-off test, N (N·m)
    force_tol: f64,
    /// two curves closer than this both touch (the touch tolerance), in `o`
    slack: f64,
    pending: Vec<Event>,
}

impl<'a> Reduced<'a> {
    /// The model of `mech` (lengths in metres) with `params`, starting at cam angle `theta0`
    /// (rad) on the follower's own curve, or on its second curve, or in flight (a lift-off at
    /// time 0, reported by the first [`Reduced::advance`]) where the contact force would be
    /// tensile.
    ///
    /// Refused when the second curve cuts into the cam anywhere over a revolution (sampled
    /// every 0.25°): a rigid follower cannot be there.
    pub fn starting_at(
        mech: &'a Mechanism,
        params: FollowerDynamics,
        theta0: f64,
    ) -> Result<Self, DynamicsError> {
        super::follower::check_params(mech, &params)?;
        let cam = mech.cam();
        let travel = mech
            .travel()
            .map_err(|source| DynamicsError::Kinematics { source })?;
        let a = travel.away;
        let joint = mech.follower_joint();
        let (rotating, g) = (joint.is_rotating(), params.gravity_along(&joint));
        let m = params.moving_mass(&joint);
        let o_rest = a * travel.rest;
        let mut sides = vec![Side {
            mech,
            map: a,
            sweep: mech.sweep(),
            states: mech.sweep(),
            at: Kin {
                o: 0.0,
                d1: 0.0,
                d2: 0.0,
                jumped: false,
            },
        }];
        if let Some((second, flip)) = mech.conjugate_side() {
            sides.push(Side {
                mech: second,
                map: a * flip,
                sweep: second.sweep(),
                states: second.sweep(),
                at: sides[0].at,
            });
        }
        let size = mech.size();
        let o_scale = if rotating { 1.0 } else { size };
        let w = cam.speed();
        let k = params.spring_stiffness;
        let mut sim = Self {
            sides,
            params,
            m,
            a,
            rotating,
            f: -params.spring_preload + k * o_rest + g,
            theta0,
            omega: w,
            alpha: cam.angular_acceleration(),
            cam_sign: cam.direction().sign(),
            t: 0.0,
            o: 0.0,
            v: 0.0,
            mode: Mode::Contact(0),
            work: 0.0,
            joint,
            o_rest,
            start: (0.0, 0.0),
            damper_work: 0.0,
            impacts: 0.0,
            size,
            gap_tol: 1e-12 * o_scale,
            force_tol: 1e-9
                * (m * w * w * o_scale
                    + params.spring_preload.abs()
                    + k * o_scale
                    + params.damping * w * o_scale
                    + g.abs()),
            slack: mech.touch.touch_slack(),
            pending: Vec::new(),
        };
        if sim.sides.len() == 2 {
            sim.check_interference()?;
        }
        let first = sim.kin(0, &mut sim.sides[0].sweep.clone(), 0.0, None)?;
        sim.o = first.o;
        let (mut sweeps, kins) = sim.trial(0.0)?;
        for (side, (s, k)) in sim.sides.iter_mut().zip(sweeps.drain(..).zip(kins)) {
            (side.sweep, side.at) = (s, k);
        }
        sim.v = sim.sides[0].at.d1 * w;
        sim.start = (sim.o, 0.0);
        sim.start.1 = sim.follower_energy(sim.o, sim.v);
        sim.mode = sim.settle(0);
        if sim.mode == Mode::Flight {
            sim.pending.push(sim.event(EventKind::LiftOff, 0.0, false));
        }
        Ok(sim)
    }

    /// Refuses a second curve that cuts into the cam anywhere (sampled every 0.25°).
    fn check_interference(&self) -> Result<(), DynamicsError> {
        // the play as the mechanism defines it (`Mechanism::conjugate_play`), swept
        let mech = self.sides[0].mech;
        let mut sweep = mech.sweep();
        let Some(mut second) = mech.conjugate_sweep() else {
            return Ok(());
        };
        let mut worst = (f64::INFINITY, 0.0);
        for k in 0..1440 {
            let theta = f64::from(k) * 0.25f64.to_radians();
            let state = sweep.step(theta).map_err(kinematics)?;
            let play = second.play(&state).map_err(kinematics)?;
            if play < worst.0 {
                worst = (play, theta);
            }
        }
        if worst.0 < -self.slack {
            return Err(DynamicsError::Interference {
                angle_deg: worst.1.to_degrees(),
                depth: -worst.0,
                unit: if self.rotating { "rad" } else { "m" },
            });
        }
        Ok(())
    }

    /// The cam angle at time `t`.
    fn theta(&self, t: f64) -> f64 {
        self.theta0 + self.omega * t + 0.5 * self.alpha * t * t
    }

    /// The cam's speed at time `t`.
    fn rate(&self, t: f64) -> f64 {
        self.omega + self.alpha * t
    }

    /// `x` shifted by whole turns next to `near` (an arm's angle), or `x` (a slide).
    fn unwrap(&self, x: f64, near: f64) -> f64 {
        if self.rotating {
            wrap_angle_near(x, near)
        } else {
            x
        }
    }

    /// Side `i`'s first touch at time `t`, stepping `sweep`; `near` unwraps an angle.
    fn kin(
        &self,
        i: usize,
        sweep: &mut Sweep<'a>,
        t: f64,
        near: Option<f64>,
    ) -> Result<Kin, DynamicsError> {
        let theta = self.theta(t);
        let err = |source| DynamicsError::Analysis {
            time: self.t,
            source,
        };
        let side = &self.sides[i];
        let mut m = sweep.step_motion(theta).map_err(err)?;
        if !matches!(m.found, Found::Jump { .. }) && !side.mech.is_convex() {
            // the sweep's guard sees another part of the profile only once a sample of it
            // leads, up to 5e-4 rad after the parts cross (the peanut of
            // `tests/it/contact_jumps.rs`): the cold search decides, and a lead restarts the
            // sweep on the new part
            let cold = side.mech.motion(theta).map_err(err)?;
            if side.mech.touch.ahead(cold.position, m.position) > side.mech.touch.touch_slack() {
                *sweep = side.mech.sweep();
                m = sweep.step_motion(theta).map_err(err)?;
                m.found = Found::Jump {
                    from_cam_param: m.cam_param,
                };
            }
        }
        let map = self.sides[i].map;
        let d1 = m.velocity / self.omega;
        let d2 = (m.acceleration - d1 * self.alpha) / (self.omega * self.omega);
        let o = map * m.position;
        Ok(Kin {
            o: near.map_or(o, |n| self.unwrap(o, n)),
            d1: map * d1,
            d2: map * d2,
            jumped: matches!(m.found, Found::Jump { .. }),
        })
    }

    /// Every side's sweep cloned and stepped to time `t`, and its first touch there.
    fn trial(&self, t: f64) -> Result<(Vec<Sweep<'a>>, Vec<Kin>), DynamicsError> {
        let mut sweeps = Vec::with_capacity(self.sides.len());
        let mut kins = Vec::with_capacity(self.sides.len());
        for (i, side) in self.sides.iter().enumerate() {
            let mut s = side.sweep.clone();
            kins.push(self.kin(i, &mut s, t, Some(self.o))?);
            sweeps.push(s);
        }
        Ok((sweeps, kins))
    }

    /// The applied force along `o` (spring, damping, gravity), N (N·m).
    fn applied(&self, o: f64, v: f64) -> f64 {
        self.f - self.params.spring_stiffness * o - self.params.damping * v
    }

    /// `(ȯ, ö)` of a first touch at time `t`.
    fn motion(&self, k: &Kin, t: f64) -> (f64, f64) {
        let w = self.rate(t);
        (k.d1 * w, k.d2 * w * w + k.d1 * self.alpha)
    }

    /// The compressive generalized force of side `i` holding the follower on its first touch
    /// `k` at time `t` (negative: tensile, the follower leaves).
    fn lambda(&self, i: usize, k: &Kin, t: f64) -> f64 {
        let (v, acc) = self.motion(k, t);
        let net = self.m * acc - self.applied(k.o, v);
        if i == 0 {
            net
        } else {
            -net
        }
    }

    /// The mode at the current state, on the curve `i` just reached: in contact with it if its
    /// force is compressive, else with the other curve if that touches too (no play) and its
    /// force is compressive, else in flight.
    fn settle(&self, i: usize) -> Mode {
        if self.lambda(i, &self.sides[i].at, self.t) >= -self.force_tol {
            return Mode::Contact(i);
        }
        self.leave(i)
    }

    /// The mode as the follower leaves curve `i`: on the other curve if that touches too (no
    /// play) and its force is compressive, else in flight.
    fn leave(&self, i: usize) -> Mode {
        if self.sides.len() == 2 {
            let j = 1 - i;
            let play = self.sides[1].at.o - self.sides[0].at.o;
            if play <= self.slack && self.lambda(j, &self.sides[j].at, self.t) >= -self.force_tol {
                return Mode::Contact(j);
            }
        }
        Mode::Flight
    }

    /// The free motion from `(o, v)` over `tau` seconds, exact.
    fn flight(&self, o: f64, v: f64, tau: f64) -> (f64, f64) {
        let (k, c) = (self.params.spring_stiffness, self.params.damping);
        let a = Matrix3::new(
            0.0,
            1.0,
            0.0,
            -k / self.m,
            -c / self.m,
            self.f / self.m,
            0.0,
            0.0,
            0.0,
        ) * tau;
        let y = a.exp() * Vector3::new(o, v, 1.0);
        (y.x, y.y)
    }

    /// The gap of side `i` at `o` with its first touch `k` (positive: apart).
    fn gap(&self, i: usize, o: f64, k: &Kin) -> f64 {
        if i == 0 {
            o - k.o
        } else {
            k.o - o
        }
    }

    fn event(&self, kind: EventKind, impact_velocity: f64, conjugate: bool) -> Event {
        Event {
            kind,
            time: self.t,
            cam_angle: self.theta(self.t),
            impact_velocity,
            conjugate,
        }
    }

    /// Moves to time `t` with the sweeps and first touches of [`Reduced::trial`].
    fn commit(&mut self, t: f64, sweeps: Vec<Sweep<'a>>, kins: Vec<Kin>, o: f64, v: f64) {
        for (side, (s, k)) in self.sides.iter_mut().zip(sweeps.into_iter().zip(kins)) {
            (side.sweep, side.at) = (s, k);
        }
        (self.t, self.o, self.v) = (t, o, v);
    }

    /// The kinetic and potential energy of the follower at `(o, v)`, J.
    fn energy(&self, o: f64, v: f64) -> f64 {
        0.5 * self.m * v * v + 0.5 * self.params.spring_stiffness * o * o - self.f * o
    }

    /// Advances by `h` seconds, locating lift-offs, impacts and jumps of the contact inside the
    /// step; a step longer than [`FollowerDynamics::max_step`] is cut into as many equal steps
    /// as it needs.
    pub fn advance(&mut self, h: f64) -> Result<Vec<Event>, DynamicsError> {
        let max = self.params.max_step(self.rotating);
        if h > max {
            let n = (h / max).ceil();
            if !(n <= 1e9) {
                return Err(DynamicsError::Element {
                    element: "the simulation".into(),
                    key: "time step (s)",
                    value: h,
                    reason: "must be positive and finite",
                });
            }
            let mut events = Vec::new();
            for _ in 0..n as usize {
                events.extend(self.advance_within(h / n)?);
            }
            return Ok(events);
        }
        self.advance_within(h)
    }

    /// [`Reduced::advance`] by a step within the stable one.
    fn advance_within(&mut self, h: f64) -> Result<Vec<Event>, DynamicsError> {
        let mut events = std::mem::take(&mut self.pending);
        let end = self.t + h;
        let mut guard = 0;
        while self.t < end - 1e-15 * end.abs().max(1.0) {
            guard += 1;
            if guard > MAX_EVENTS_PER_STEP {
                return Err(DynamicsError::Chatter {
                    time: self.t,
                    events: MAX_EVENTS_PER_STEP,
                });
            }
            match self.mode {
                Mode::Contact(i) => self.contact_step(i, end, &mut events)?,
                Mode::Flight => self.flight_step(end, &mut events)?,
            }
        }
        Ok(events)
    }

    /// In contact with side `i`: to `end`, or to a lift-off, or to a jump of the contact.
    fn contact_step(
        &mut self,
        i: usize,
        end: f64,
        events: &mut Vec<Event>,
    ) -> Result<(), DynamicsError> {
        let (mut sweeps, mut kins) = self.trial(end)?;
        let mut stop = end;
        let mut jump = None;
        let (k0, th0) = (self.sides[i].at, self.theta(self.t));
        if self.broke(&k0, th0, &kins[i], self.theta(end)) {
            // the last angle on the branch followed and the first on the next, by bisection
            let (mut lo, mut hi) = (self.t, end);
            let mut after = (sweeps.clone(), kins.clone());
            let mut before = None;
            while hi - lo > 1e-14 * (1.0 + hi.abs()) {
                let mid = 0.5 * (lo + hi);
                let (s, k) = self.trial(mid)?;
                if self.broke(&k0, th0, &k[i], self.theta(mid)) {
                    (hi, after) = (mid, (s, k));
                } else {
                    (lo, before) = (mid, Some((s, k)));
                }
            }
            // the sweep sees the new part only once it leads by a sample's resolution: the
            // jump is where the two parts' first touches cross, from their Taylor expansions
            let (t_a, ka) = match &before {
                Some((_, k)) => (lo, k[i]),
                None => (self.t, self.sides[i].at),
            };
            let kb = after.1[i];
            let th = Self::crossing(&ka, self.theta(t_a), &kb, self.theta(hi));
            let tc = self.time_at(th).clamp(self.t, hi);
            let th = self.theta(tc);
            let db = th - self.theta(hi);
            let at_b = Kin {
                o: kb.o + db * (kb.d1 + 0.5 * db * kb.d2),
                d1: kb.d1 + db * kb.d2,
                d2: kb.d2,
                jumped: false,
            };
            let da = th - self.theta(t_a);
            let o_a = ka.o + da * (ka.d1 + 0.5 * da * ka.d2);
            let flagged = after.1[i].jumped;
            jump = Some((tc, after.0, at_b, o_a, flagged));
            stop = tc;
            (sweeps, kins) = match self.trial(tc)? {
                (s, k) if !k[i].jumped && tc > self.t => (s, k),
                _ => match before {
                    Some(b) if tc > self.t => b,
                    _ => (vec![], vec![]),
                },
            };
        }
        if !kins.is_empty() && self.lambda(i, &kins[i], stop) < -self.force_tol {
            // the contact force turns tensile: bisection for the zero
            let (mut lo, mut hi) = (self.t, stop);
            let mut at = (sweeps, kins);
            while hi - lo > 1e-14 * (1.0 + hi.abs()) {
                let mid = 0.5 * (lo + hi);
                let (s, k) = self.trial(mid)?;
                if self.lambda(i, &k[i], mid) >= 0.0 {
                    lo = mid;
                } else {
                    (hi, at) = (mid, (s, k));
                }
            }
            self.contact_commit(i, hi, at.0, at.1);
            self.mode = self.leave(i);
            if self.mode == Mode::Flight {
                events.push(self.event(EventKind::LiftOff, 0.0, i == 1));
            }
            return Ok(());
        }
        if !kins.is_empty() {
            self.contact_commit(i, stop, sweeps, kins);
        }
        if let Some((tc, sweep, at_b, o_a, flagged)) = jump {
            // the new part's sweep goes on from where it was found
            self.t = tc;
            self.sides[i].sweep = sweep[i].clone();
            self.sides[i].at = at_b;
            if self.gap(i, o_a, &at_b) > self.slack {
                // the part followed ends (a knife's crossing vanishing at a fold) and the next
                // first touch is behind it: the cam falls away and the follower flies
                self.o = o_a;
                self.mode = Mode::Flight;
                events.push(self.event(EventKind::LiftOff, 0.0, i == 1));
            } else {
                // the parts cross: the position is continuous, the velocity is the followed
                // part's until the impact
                self.o = at_b.o;
                let (vf, _) = self.motion(&at_b, tc);
                let still =
                    (self.v - vf).abs() * self.lever(i)? <= 1e-9 * self.omega.abs() * self.size;
                if !flagged && still {
                    // a bend of the smooth first touch (a node of the profile), not a jump
                    self.v = vf;
                } else {
                    self.impact(i, EventKind::Jump, events)?;
                }
            }
        }
        Ok(())
    }

    /// The time at which the cam reaches `theta` (the driver's `θ(t)` inverted).
    fn time_at(&self, theta: f64) -> f64 {
        let d = theta - self.theta0;
        if self.alpha == 0.0 {
            d / self.omega
        } else {
            2.0 * d / (self.omega + (self.omega * self.omega + 2.0 * self.alpha * d).sqrt())
        }
    }

    /// Moves along side `i`'s first touch to time `t` (the driver's work: the change of the
    /// follower's energy and the damping's loss).
    fn contact_commit(&mut self, i: usize, t: f64, sweeps: Vec<Sweep<'a>>, kins: Vec<Kin>) {
        let k = kins[i];
        let (v, _) = self.motion(&k, t);
        let e0 = self.energy(self.o, self.v);
        let c = self.params.damping;
        let loss = if c > 0.0 {
            // Simpson's rule with the velocity halfway: the first touch's slope there by the
            // cubic through both ends' slopes and curvatures (Hermite, exact to O(Δθ⁴))
            let tm = 0.5 * (self.t + t);
            let ka = self.sides[i].at;
            let (tha, thb) = (self.theta(self.t), self.theta(t));
            let span = thb - tha;
            let x = if span == 0.0 {
                0.5
            } else {
                (self.theta(tm) - tha) / span
            };
            let (x2, x3) = (x * x, x * x * x);
            let d1 = (2.0 * x3 - 3.0 * x2 + 1.0) * ka.d1
                + (x3 - 2.0 * x2 + x) * span * ka.d2
                + (3.0 * x2 - 2.0 * x3) * k.d1
                + (x3 - x2) * span * k.d2;
            let vm = d1 * self.rate(tm);
            c * (t - self.t) / 6.0 * (self.v * self.v + 4.0 * vm * vm + v * v)
        } else {
            0.0
        };
        let o = k.o;
        self.commit(t, sweeps, kins, o, v);
        self.work += self.energy(o, v) - e0 + loss;
        self.damper_work -= loss;
    }

    /// In flight: to `end`, or to the first time a gap closes.
    fn flight_step(&mut self, end: f64, events: &mut Vec<Event>) -> Result<(), DynamicsError> {
        let (o, v) = self.flight(self.o, self.v, end - self.t);
        let (sweeps, kins) = self.trial(end)?;
        // the curve whose gap is most negative, below `-tol`
        let closed = |s: &Self, o: f64, kins: &[Kin], tol: f64| -> Option<usize> {
            let mut worst = None;
            let mut least = 0.0;
            for (i, k) in kins.iter().enumerate() {
                let g = s.gap(i, o, k);
                if g < -tol && g < least {
                    (least, worst) = (g, Some(i));
                }
            }
            worst
        };
        if closed(self, o, &kins, self.gap_tol).is_none() {
            self.damper_work -= self.flight_loss(end - self.t, v);
            self.commit(end, sweeps, kins, o, v);
            return Ok(());
        }
        let (mut lo, mut hi) = (self.t, end);
        let mut at = (sweeps, kins, o, v);
        while hi - lo > 1e-14 * (1.0 + hi.abs()) {
            let mid = 0.5 * (lo + hi);
            let (om, vm) = self.flight(self.o, self.v, mid - self.t);
            let (s, k) = self.trial(mid)?;
            // the zero of the gap (a penetration of `gap_tol` would delay slow landings)
            if closed(self, om, &k, 0.0).is_none() {
                lo = mid;
            } else {
                (hi, at) = (mid, (s, k, om, vm));
            }
        }
        let (s, k, om, vm) = at;
        let i = closed(self, om, &k, 0.0).unwrap_or(0);
        let o = k[i].o;
        self.damper_work -= self.flight_loss(hi - self.t, vm);
        self.commit(hi, s, k, o, vm);
        self.impact(i, EventKind::Impact, events)
    }

    /// |J|: how fast side `i`'s contact point moves along the normal per unit rate of the
    /// follower's coordinate, at the current time.
    fn lever(&mut self, i: usize) -> Result<f64, DynamicsError> {
        let theta = self.theta(self.t);
        let s = self.sides[i]
            .states
            .step(theta)
            .map_err(|source| DynamicsError::Analysis {
                time: self.t,
                source,
            })?;
        Ok(s.follower_motion.dot(&s.normal).abs())
    }

    /// An impact on side `i` at the current state: the velocity relative to its first touch
    /// reverses times the restitution; a negligible rebound keeps the follower on it.
    fn impact(
        &mut self,
        i: usize,
        kind: EventKind,
        events: &mut Vec<Event>,
    ) -> Result<(), DynamicsError> {
        let (vf, _) = self.motion(&self.sides[i].at, self.t);
        let u = self.v - vf;
        let speed = self.lever(i)? * u.abs();
        let e = self.params.restitution;
        let stick = e * speed <= REBOUND_TOLERANCE * self.omega.abs() * self.size;
        let v = if stick { vf } else { vf - e * u };
        // the impulse's work at the flank's velocity; the rest of the change of kinetic energy,
        // −½ M (1 − e²) u², is the impact's loss
        let impulse = self.m * (v - self.v) * vf;
        self.work += impulse;
        self.impacts += 0.5 * self.m * (v * v - self.v * self.v) - impulse;
        self.v = v;
        events.push(self.event(kind, speed, i == 1));
        self.mode = if stick { self.settle(i) } else { Mode::Flight };
        Ok(())
    }

    /// The state at the current time.
    pub fn sample(&mut self) -> Result<Sample, DynamicsError> {
        let (acc, force, torque, side) = match self.mode {
            Mode::Contact(i) => {
                let k = self.sides[i].at;
                let (_, acc) = self.motion(&k, self.t);
                let lam = self.lambda(i, &k, self.t);
                let lever = self.lever(i)?;
                let sense = if i == 0 { lam } else { -lam };
                (acc, lam / lever, self.cam_sign * sense * k.d1, i == 1)
            }
            Mode::Flight => (self.applied(self.o, self.v) / self.m, 0.0, 0.0, false),
        };
        Ok(Sample {
            time: self.t,
            cam_angle: self.theta(self.t),
            position: self.o / self.a,
            velocity: self.v / self.a,
            acceleration: acc / self.a,
            contact_force: force,
            in_contact: self.mode != Mode::Flight,
            on_conjugate: side,
            driver_torque: torque,
            driver_work: self.work,
            balance: self.balance(),
        })
    }

    /// The current time, s.
    pub fn time(&self) -> f64 {
        self.t
    }

    /// The parameters.
    pub fn params(&self) -> &FollowerDynamics {
        &self.params
    }

    /// The follower turns about a pivot.
    pub fn is_rotating(&self) -> bool {
        self.rotating
    }
}

fn kinematics(source: CamError) -> DynamicsError {
    DynamicsError::Kinematics { source }
}
