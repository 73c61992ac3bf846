//! The dynamics of any [`crate::system::System`]: its bodies' masses, its joints and drivers as
//! bilateral rows, its contacts as unilateral rows (the paper's eq. 11 with its exact `γ`), its
//! springs, dampers and torsion springs, and gravity.
//!
//! The equations of motion `M q̈ + Φ_qᵀ λ = Q`, `Φ_q q̈ = γ` are solved at every evaluation by the
//! augmented Lagrangian (see the [module docs](super)), integrated by the classical Runge–Kutta
//! method, and after every step positions and velocities are projected mass-orthogonally onto
//! the active rows (Bayo and Ledesma 1996). A body's frame origin is its centre of mass (`M` is
//! diagonal: mass, mass, inertia about the origin).
//!
//! A contact is unilateral:
//! - in contact, its row holds while its force (`−λ`) is compressive; where it would turn
//!   tensile inside a step, the instant is located by bisection on the force and the contact
//!   leaves (a lift-off);
//! - in flight, its gap (along the common normal of the nearest points) is watched; where it
//!   closes inside a step, the instant is located by bisection on the gap, and the impact
//!   reverses the normal velocity times the restitution (Newton's law) by a mass-orthogonal
//!   projection of the velocities with every joint, driver and contact in touch held; a rebound
//!   below [`REBOUND_TOLERANCE`] of the system's speed scale re-engages the contact.
//!
//! Units: lengths in the system's unit `L` (its curves' and joints'), masses in kg and inertias
//! in kg·m² (converted with the unit's size in metres), forces in N, stiffnesses in N/L, gravity
//! in m/s²; energies are reported in N·L.

use super::follower::{EventKind, REBOUND_TOLERANCE};
use super::model::{Constraint, ForceElement, RigidBody, System};
use super::projection::DenseRows;
use super::{AugmentedLagrangian, DynamicsError};
use crate::contact::{self, Pairing, Proximity, SearchOptions, Surface};
use crate::geometry::Vec2;
use crate::system::SystemError;

/// How a system is simulated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SystemDynamicsOptions {
    /// the system's length unit in metres (1e-3 for mm)
    pub metres_per_unit: f64,
    /// gravity in the world, m/s²
    pub gravity: Vec2,
    /// Newton's coefficient of restitution of every contact, 0 to 1
    pub restitution: f64,
    /// the augmented Lagrangian's parameters; by default its penalty is 1e4 of the largest mass
    /// (see [`SystemDynamicsOptions::default`])
    pub al: AugmentedLagrangian,
}

impl Default for SystemDynamicsOptions {
    /// No gravity, lengths in metres, no rebound, and the augmented Lagrangian with a penalty
    /// of 1e4 of the largest mass (not the cam model's 1e8): the matrix `M + α Φ_qᵀ Φ_q` it
    /// factors has a condition number of about the penalty, which costs the free motion that
    /// many ulps — at 1e8 a pendulum's energy wandered by 3e-9 of itself whatever the step, at
    /// 1e4 by RK4's `h⁴` alone (2e-12 at 0.25 ms steps), in a few more iterations.
    fn default() -> Self {
        Self {
            metres_per_unit: 1.0,
            gravity: Vec2::zeros(),
            restitution: 0.0,
            al: AugmentedLagrangian {
                penalty: 1e4,
                ..AugmentedLagrangian::default()
            },
        }
    }
}

/// A lift-off or an impact of a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactEvent {
    /// lift-off or impact
    pub kind: EventKind,
    /// when, s
    pub time: f64,
    /// which contact, in the system's order
    pub contact: usize,
    /// an impact's approach speed along the normal (L/s; 0 for a lift-off)
    pub approach: f64,
}

/// The state of a simulated system at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct SystemSample {
    /// s
    pub time: f64,
    /// every body's `(x, y, θ)`, in the system's order
    pub q: Vec<f64>,
    /// their rates
    pub qd: Vec<f64>,
    /// their accelerations
    pub qdd: Vec<f64>,
    /// each contact's compressive force, N (0 in flight)
    pub contact_forces: Vec<f64>,
    /// each contact's gap along its common normal, L (0 in contact)
    pub gaps: Vec<f64>,
    /// whether each contact is in touch
    pub in_contact: Vec<bool>,
    /// kinetic plus potential energy (springs, torsion springs, gravity), N·L
    pub energy: f64,
    /// the work the drivers have done since the start, N·L
    pub driver_work: f64,
}

/// A simulation of a [`crate::system::System`] (see the module docs).
#[derive(Debug, Clone)]
pub struct SystemSimulation<'a> {
    sys: &'a crate::system::System,
    model: System,
    opts: SystemDynamicsOptions,
    /// the model's constraint index of contact 0 (joints, then drivers, then contacts)
    first_contact: usize,
    size: f64,
    /// a speed of the system (its drivers' rates times the size, or `√(g size)`), for the
    /// rebound that re-engages a contact
    speed_scale: f64,
    t: f64,
    q: Vec<f64>,
    qd: Vec<f64>,
    in_contact: Vec<bool>,
    pairings: Vec<Option<Pairing>>,
    work: f64,
    pending: Vec<ContactEvent>,
}

/// Most events in one call of [`SystemSimulation::advance`].
const MAX_EVENTS: usize = 64;

/// A contact whose curves are this close (times the size) at the starting poses starts in touch
/// (the positions are then assembled onto it).
const STARTS_IN_TOUCH: f64 = 1e-3;

impl<'a> SystemSimulation<'a> {
    /// Starts `sys` at time 0 from its bodies' poses (assembled onto the joints and drivers and
    /// every contact whose curves are within 1e-3 of the size there), at rest but for the
    /// drivers' rates. A contact whose force would be tensile at the start lifts off at once
    /// (the first [`SystemSimulation::advance`] reports it).
    pub fn new(
        sys: &'a crate::system::System,
        opts: SystemDynamicsOptions,
    ) -> Result<Self, DynamicsError> {
        sys.check_elements()?;
        let u = opts.metres_per_unit;
        if !(u > 0.0 && u.is_finite()) {
            return Err(DynamicsError::Element {
                element: "the system".into(),
                key: "length unit (m)",
                value: u,
                reason: "must be positive",
            });
        }
        if !(0.0..=1.0).contains(&opts.restitution) {
            return Err(DynamicsError::Element {
                element: "every contact".into(),
                key: "restitution",
                value: opts.restitution,
                reason: "must be from 0 to 1",
            });
        }
        let mut bodies = Vec::with_capacity(sys.bodies().len());
        for b in sys.bodies() {
            for (key, v) in [("mass", b.mass), ("inertia", b.inertia)] {
                if !(v > 0.0 && v.is_finite()) {
                    return Err(DynamicsError::Element {
                        element: format!("body {:?}", b.name),
                        key,
                        value: v,
                        reason: "must be positive for a simulation",
                    });
                }
            }
            // kg → N·s²/L, kg·m² → N·L·s²
            bodies.push(RigidBody {
                mass: b.mass * u,
                inertia: b.inertia / u,
            });
        }
        let mut constraints: Vec<Constraint> = sys
            .joints()
            .iter()
            .map(|j| Constraint::Joint(j.kind))
            .collect();
        constraints.extend(sys.drivers().iter().map(|d| Constraint::Driver {
            body: d.body.0,
            coordinate: d.coordinate,
            law: d.law,
        }));
        let first_contact = constraints.len();
        constraints.extend(sys.contacts().iter().map(|c| Constraint::Contact {
            a: c.a.0,
            curve_a: c.curve_a.clone(),
            b: c.b.0,
            curve_b: c.curve_b.clone(),
        }));
        let gravity = opts.gravity / u;
        let mut forces: Vec<ForceElement> = sys
            .forces()
            .iter()
            .map(|f| ForceElement::Element(f.kind))
            .collect();
        if gravity != Vec2::zeros() {
            forces.push(ForceElement::Gravity(gravity));
        }
        let size = sys.size();
        let model = System {
            bodies,
            constraints,
            forces,
            search: SearchOptions::for_length_scale(size),
        };
        let rates = sys
            .drivers()
            .iter()
            .map(|d| {
                let r = d.law.at(0.0)[1].abs();
                match d.coordinate {
                    crate::system::Coordinate::Angle => r * size,
                    _ => r,
                }
            })
            .fold(0.0f64, f64::max);
        let speed_scale = rates.max((gravity.norm() * size).sqrt()).max(1e-300);
        let q: Vec<f64> = sys
            .bodies()
            .iter()
            .flat_map(|b| [b.pose.origin.x, b.pose.origin.y, b.pose.angle])
            .collect();
        let nc = sys.contacts().len();
        let mut sim = Self {
            sys,
            model,
            opts,
            first_contact,
            size,
            speed_scale,
            t: 0.0,
            qd: vec![0.0; q.len()],
            q,
            in_contact: vec![false; nc],
            pairings: vec![None; first_contact + nc],
            work: 0.0,
            pending: Vec::new(),
        };
        // each contact's nearest (or deepest) pair of points, globally
        for k in 0..nc {
            let c = &sys.contacts()[k];
            let (sa, sb) = (sim.state(c.a.0), sim.state(c.b.0));
            let found = contact::find_contact(
                &Surface::new(c.curve_a.as_ref(), &sa),
                &Surface::new(c.curve_b.as_ref(), &sb),
                &sim.model.search,
            )
            .map_err(|e| SystemError::Contact {
                time: 0.0,
                contact: c.name.clone(),
                reason: e.to_string(),
            })?;
            let (Proximity::Apart(p) | Proximity::Touching(p) | Proximity::Overlapping(p)) = found;
            sim.in_contact[k] = p.gap <= STARTS_IN_TOUCH * size;
            sim.pairings[first_contact + k] = Some(p);
        }
        sim.project().map_err(|e| match e {
            DynamicsError::Singular { .. } => DynamicsError::System(SystemError::NoAssembly {
                time: 0.0,
                reason: "the starting poses cannot be assembled onto the joints, drivers and contacts in touch (their rows are dependent)",
                residual: f64::NAN,
                row: String::new(),
            }),
            e => e,
        })?;
        let residual = sim.constraint_residual()?;
        if residual > 1e-9 * size {
            return Err(SystemError::NoAssembly {
                time: 0.0,
                reason: "the starting poses cannot be assembled onto the joints, drivers and contacts in touch",
                residual,
                row: String::new(),
            }
            .into());
        }
        // a contact pulled at the start leaves at once
        let (_, forces, _) = sim.accel(
            0.0,
            &sim.q,
            &sim.qd,
            &sim.in_contact.clone(),
            &mut sim.pairings.clone(),
        )?;
        for (k, &force) in forces.iter().enumerate() {
            if sim.in_contact[k] && force < 0.0 {
                sim.in_contact[k] = false;
                sim.pending.push(ContactEvent {
                    kind: EventKind::LiftOff,
                    time: 0.0,
                    contact: k,
                    approach: 0.0,
                });
            }
        }
        Ok(sim)
    }

    /// Body `i`'s state now (the ground's for [`super::GROUND`]).
    fn state(&self, i: usize) -> crate::body::BodyState {
        super::model::body_state(&self.q, &self.qd, i)
    }

    /// The rows that hold in the modes `in_contact`: joints and drivers always.
    fn active(&self, in_contact: &[bool]) -> Vec<bool> {
        let mut a = vec![true; self.first_contact];
        a.extend_from_slice(in_contact);
        a
    }

    /// `(q̈, each contact's compressive force, the drivers' power)` at a state in the modes
    /// `in_contact`.
    fn accel(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        in_contact: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<(Vec<f64>, Vec<f64>, f64), DynamicsError> {
        let active = self.active(in_contact);
        let e = self
            .model
            .evaluate(&self.opts.al, t, q, qd, &active, pairings)?;
        // λ row by row over the active constraints: a driver's force on its coordinate is −λ,
        // a contact's compressive force −λ (its row is the gap, positive apart)
        let mut forces = vec![0.0; in_contact.len()];
        let (mut r, mut power) = (0, 0.0);
        for (k, c) in self.model.constraints.iter().enumerate() {
            if !active[k] {
                continue;
            }
            if let Constraint::Driver {
                body, coordinate, ..
            } = c
            {
                power -= e.lambda[r] * qd[3 * body + coordinate.index()];
            }
            if k >= self.first_contact {
                forces[k - self.first_contact] = -e.lambda[r];
            }
            r += c.rows();
        }
        Ok((e.qdd, forces, power))
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
        let (a1, _, w1) = self.accel(t, q, qd, modes, &mut p)?;
        let (q2, v2) = (add(q, qd, 0.5 * h), add(qd, &a1, 0.5 * h));
        let (a2, _, w2) = self.accel(t + 0.5 * h, &q2, &v2, modes, &mut p)?;
        let (q3, v3) = (add(q, &v2, 0.5 * h), add(qd, &a2, 0.5 * h));
        let (a3, _, w3) = self.accel(t + 0.5 * h, &q3, &v3, modes, &mut p)?;
        let (q4, v4) = (add(q, &v3, h), add(qd, &a3, h));
        let (a4, _, w4) = self.accel(t + h, &q4, &v4, modes, &mut p)?;
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
    fn gap(
        &self,
        q: &[f64],
        qd: &[f64],
        k: usize,
        pairings: &mut [Option<Pairing>],
    ) -> Result<f64, DynamicsError> {
        let c = &self.sys.contacts()[k];
        let (sa, sb) = (
            super::model::body_state(q, qd, c.a.0),
            super::model::body_state(q, qd, c.b.0),
        );
        let slot = &mut pairings[self.first_contact + k];
        let p0 = slot.expect("every contact has a pairing from the start");
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
        Ok(p.gap)
    }

    /// The active rows at `(q, q̇)` as dense rows.
    fn dense(
        &self,
        q: &[f64],
        qd: &[f64],
        in_contact: &[bool],
        pairings: &mut [Option<Pairing>],
    ) -> Result<DenseRows, DynamicsError> {
        self.model
            .dense_rows(self.t, q, qd, &self.active(in_contact), pairings)
            .map_err(|source| DynamicsError::Contact {
                time: self.t,
                source,
            })
    }

    /// Positions by Newton onto the active rows (mass-orthogonal), then velocities onto
    /// `Φ_q q̇ = −Φ_t`.
    fn project(&mut self) -> Result<(), DynamicsError> {
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

    /// The largest `|Φ|` of the active rows now, L (angles' rows in rad): the drift.
    pub fn constraint_residual(&self) -> Result<f64, DynamicsError> {
        let mut p = self.pairings.clone();
        let rows = self.dense(&self.q, &self.qd, &self.in_contact, &mut p)?;
        Ok(rows.phi.iter().fold(0.0f64, |m, x| m.max(x.abs())))
    }

    /// The current time, s.
    pub fn time(&self) -> f64 {
        self.t
    }

    /// Kinetic plus potential energy at the current state, N·L.
    fn energy(&self) -> f64 {
        let mut e = 0.0;
        for (i, b) in self.model.bodies.iter().enumerate() {
            let v = &self.qd[3 * i..3 * i + 3];
            e += 0.5 * (b.mass * (v[0] * v[0] + v[1] * v[1]) + b.inertia * v[2] * v[2]);
        }
        for f in &self.model.forces {
            match f {
                ForceElement::Element(kind) => {
                    e += kind.potential(|id| self.state(id.0));
                }
                ForceElement::Gravity(g) => {
                    for (i, b) in self.model.bodies.iter().enumerate() {
                        e -= b.mass * (g.x * self.q[3 * i] + g.y * self.q[3 * i + 1]);
                    }
                }
                _ => {}
            }
        }
        e
    }

    /// The sample at the current state.
    pub fn sample(&self) -> Result<SystemSample, DynamicsError> {
        let mut p = self.pairings.clone();
        let (qdd, contact_forces, _) =
            self.accel(self.t, &self.q, &self.qd, &self.in_contact, &mut p)?;
        let mut gaps = vec![0.0; self.in_contact.len()];
        for (k, g) in gaps.iter_mut().enumerate() {
            if !self.in_contact[k] {
                *g = self.gap(&self.q, &self.qd, k, &mut p)?;
            }
        }
        Ok(SystemSample {
            time: self.t,
            q: self.q.clone(),
            qd: self.qd.clone(),
            qdd,
            contact_forces,
            gaps,
            in_contact: self.in_contact.clone(),
            energy: self.energy(),
            driver_work: self.work,
        })
    }

    /// Advances by `h` seconds, locating every lift-off and impact inside the step.
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
            let (_, forces, _) = self.accel(self.t, &self.q, &self.qd, &self.in_contact, &mut p)?;
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
        let vn: f64 = rows.row(r).iter().zip(&self.qd).map(|(a, b)| a * b).sum();
        let mut targets = rows.target.to_vec();
        targets[r] = -self.opts.restitution * vn;
        let mut x = vec![0.0; self.qd.len()];
        if !self
            .model
            .project_onto(&rows, &self.qd, &targets[..rows.m], &mut x)
        {
            return Err(DynamicsError::Singular { time: self.t });
        }
        self.qd = x;
        let approach = vn.abs();
        self.in_contact[k] =
            self.opts.restitution * approach <= REBOUND_TOLERANCE * self.speed_scale;
        Ok(approach)
    }
}
