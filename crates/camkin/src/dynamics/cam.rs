//! A cam-follower mechanism as a multibody system, simulated with unilateral contact.
//!
//! Body 0 is the cam, driven about its axis (a revolute joint and an angle driver at the cam's
//! speed); body 1 the follower, on a translational joint (translating followers) or a revolute
//! joint at its pivot (oscillating). While in contact the contact row of eq. 11 is active; when
//! the contact force would turn tensile the follower lifts off (located by bisection on the force),
//! the signed gap is monitored in free flight, and re-contact (located by bisection on the gap) is
//! an impact with a coefficient of restitution, after which the contact is re-engaged once the
//! bouncing has died down.

use super::follower::{Event, EventKind, FollowerDynamics, Sample, REBOUND_TOLERANCE};
use super::model::{body_state, Constraint, ForceElement, RigidBody, System};
use super::projection::DenseRows;
use super::solver::{AugmentedLagrangian, Solution};
use super::DynamicsError;
use crate::cam::{Joint, Mechanism};
use crate::contact::{refine, Pairing, SearchOptions, Surface};
use crate::field::Field;
use crate::geometry::Vec2;

/// A cam-follower simulation as a multibody system (see the module docs); [`super::Simulation`]
/// chooses it for a follower with one contact that never jumps.
#[derive(Debug, Clone)]
pub struct Multibody {
    sys: System,
    al: AugmentedLagrangian,
    params: FollowerDynamics,
    oscillating: bool,
    axis: Vec2,
    axis_origin: crate::Point2,
    orientation: f64,
    speed: f64,
    /// the cam's angular acceleration, rad/s²
    alpha: f64,
    theta0: f64,
    work: f64,
    t: f64,
    q: State,
    qd: State,
    in_contact: bool,
    pairings: Pairings,
    size: f64,
    /// events found at the start (a tensile force there: lift-off at time 0), returned by the
    /// first [`Multibody::advance`]
    pending: Vec<Event>,
    /// the last evaluation at the current state ([`Multibody::here`]): a step's force check,
    /// then the sample, then the next step's first stage share it
    last: std::cell::Cell<Option<Here>>,
}

/// An evaluation at a state: `q̈`, the contact force and the driver's torque, with the state,
/// mode and contact pairing it was taken at and the contact pairing after it (only the contact
/// has a pairing: the joints' entries stay `None`).
#[derive(Debug, Clone, Copy)]
struct Here {
    t: f64,
    q: State,
    qd: State,
    contact: bool,
    before: Option<Pairing>,
    after: Option<Pairing>,
    qdd: State,
    force: f64,
    torque: f64,
}

const CONTACT: usize = 3;
/// The coordinates of the cam and the follower (`x, y, θ` each).
const DOFS: usize = 6;
/// The constraint rows: the cam's revolute joint (2), its driver (1), the follower's joint (2),
/// the contact (1).
const ROWS: usize = 6;
type State = [f64; DOFS];
type Pairings = [Option<Pairing>; 4];
/// The driver's row among the constraint rows (after the cam's revolute joint).
const DRIVER_ROW: usize = 2;

impl Multibody {
    /// Builds the multibody model of `mech` with the follower's `params`, starting at cam angle
    /// 0 at the kinematic position and velocity, in contact unless the contact force there would
    /// be tensile (then it starts in flight, and the first [`Multibody::advance`] reports a
    /// lift-off at time 0).
    ///
    /// ```
    /// use camkin::cam::{Cam, Follower, Mechanism, Sense};
    /// use camkin::curve::Circle;
    /// use camkin::dynamics::{AugmentedLagrangian, FollowerDynamics, Multibody};
    /// use camkin::{Point2, Vec2};
    /// use std::sync::Arc;
    ///
    /// // an eccentric disc (m) at 300 rpm under a flat face; a stiff, preloaded spring keeps the
    /// // follower on the cam, so it follows the kinematic motion s = R + e cos θ
    /// let disc = Arc::new(Circle::new(Point2::new(0.005, 0.0), 0.04)?);
    /// let cam = Cam::from_rpm(disc, Point2::origin(), Sense::Ccw, 300.0)?;
    /// let m = Mechanism::new(cam, Follower::TranslatingFlat { direction: Vec2::x() })?;
    /// let params = FollowerDynamics {
    ///     mass: 0.5,
    ///     inertia: 0.0,
    ///     spring_stiffness: 2.0e4,
    ///     spring_preload: 200.0,
    ///     damping: 0.0,
    ///     restitution: 0.0,
    ///     gravity: Vec2::zeros(),
    /// };
    /// let mut sim = Multibody::new(&m, params, AugmentedLagrangian::default())?;
    /// let h = 1f64.to_radians() / m.cam().speed(); // 1° of cam rotation
    /// for _ in 0..90 {
    ///     assert!(sim.advance(h)?.is_empty(), "no lift-off");
    /// }
    /// let s = sim.sample()?;
    /// let exact = 0.04 + 0.005 * s.cam_angle.cos();
    /// assert!(s.in_contact && (s.position - exact).abs() < 1e-8);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn new(
        mech: &Mechanism,
        params: FollowerDynamics,
        al: AugmentedLagrangian,
    ) -> Result<Self, DynamicsError> {
        Self::starting_at(mech, params, al, 0.0)
    }

    /// As [`Multibody::new`], starting at cam angle `theta0` (rad) at time 0.
    pub fn starting_at(
        mech: &Mechanism,
        params: FollowerDynamics,
        al: AugmentedLagrangian,
        theta0: f64,
    ) -> Result<Self, DynamicsError> {
        super::follower::check_params(mech, &params)?;
        let oscillating = mech.follower_joint().is_rotating();
        if mech.is_conjugate() {
            return Err(DynamicsError::FormClosed);
        }
        let jumps = mech.jump_angles(0.25);
        if !jumps.is_empty() {
            return Err(DynamicsError::ContactJumps { angles_deg: jumps });
        }
        let cam = mech.cam();
        let s0 = mech
            .analyze(theta0)
            .map_err(|source| DynamicsError::Kinematics { source })?;
        let (pose_b, curve_b) = mech.follower_body(s0.position);
        let sign = cam.direction().sign();
        let (follower_joint, axis, axis_origin, spring) = match mech.follower_joint() {
            Joint::Translating { origin, direction } => {
                let low = mech
                    .travel()
                    .map_err(|source| DynamicsError::Kinematics { source })?
                    .rest;
                (
                    Constraint::Translational {
                        body: 1,
                        through: origin,
                        axis: *direction,
                        angle: 0.0,
                    },
                    *direction,
                    cam.pivot(),
                    ForceElement::AxialSpring {
                        body: 1,
                        origin: cam.pivot(),
                        axis: *direction,
                        stiffness: params.spring_stiffness,
                        preload: params.spring_preload,
                        reference: low,
                        damping: params.damping,
                    },
                )
            }
            Joint::Rotating { pivot, closing, .. } => {
                // the spring turns the arm onto the cam (sense `closing`); lowest = nearest the cam
                let cs = closing.sign();
                let low = mech
                    .travel()
                    .map_err(|source| DynamicsError::Kinematics { source })?
                    .rest;
                (
                    Constraint::Revolute {
                        body: 1,
                        local: crate::Point2::origin(),
                        ground: pivot,
                    },
                    Vec2::zeros(),
                    pivot,
                    ForceElement::TorsionSpring {
                        body: 1,
                        sign: cs,
                        stiffness: params.spring_stiffness,
                        preload: params.spring_preload,
                        reference: low,
                        damping: params.damping,
                    },
                )
            }
        };
        let mut forces = vec![spring];
        if params.gravity != Vec2::zeros() {
            forces.push(ForceElement::Gravity(params.gravity));
        }
        let follower_mass = if oscillating {
            RigidBody {
                mass: 1.0,
                inertia: params.inertia,
            }
        } else {
            RigidBody {
                mass: params.mass,
                inertia: 1.0,
            }
        };
        let sys = System {
            // the cam is driven: its mass properties do not change the follower's motion
            bodies: vec![
                RigidBody {
                    mass: 1.0,
                    inertia: 1.0,
                },
                follower_mass,
            ],
            constraints: vec![
                Constraint::Revolute {
                    body: 0,
                    local: crate::Point2::origin(),
                    ground: cam.pivot(),
                },
                Constraint::AngleDriver {
                    body: 0,
                    angle0: sign * theta0,
                    speed: sign * cam.speed(),
                    acceleration: sign * cam.angular_acceleration(),
                },
                follower_joint,
                Constraint::Contact {
                    a: 0,
                    curve_a: mech.profile_arc(),
                    b: 1,
                    curve_b,
                },
            ],
            forces,
            search: SearchOptions::for_length_scale(mech.size()),
        };
        let body_b = mech.follower_body(s0.position).0;
        let q = [
            cam.pivot().x,
            cam.pivot().y,
            sign * theta0,
            pose_b.origin.x,
            pose_b.origin.y,
            body_b.angle,
        ];
        let fv = if oscillating {
            Vec2::zeros()
        } else {
            s0.velocity * axis
        };
        let qd = [
            0.0,
            0.0,
            sign * cam.speed(),
            fv.x,
            fv.y,
            if oscillating { s0.velocity } else { 0.0 },
        ];
        let pairing = Pairing {
            u_a: s0.cam_param,
            u_b: s0.follower_param,
            point_a: s0.contact_world,
            point_b: s0.contact_world,
            normal: s0.normal,
            gap: 0.0,
            iterations: 0,
        };
        let mut sim = Self {
            sys,
            al,
            params,
            oscillating,
            axis,
            axis_origin,
            orientation: mech.orientation(),
            speed: cam.speed(),
            alpha: cam.angular_acceleration(),
            theta0,
            work: 0.0,
            t: 0.0,
            q,
            qd,
            in_contact: true,
            pairings: [None, None, None, Some(pairing)],
            size: mech.size(),
            pending: Vec::new(),
            last: std::cell::Cell::new(None),
        };
        // The kinematic start is in contact; a tensile force there means the spring cannot hold
        // the follower on the cam at this angle and speed: it leaves at once.
        let (q0, qd0) = (sim.q, sim.qd);
        let mut p = sim.pairings;
        let (_, f, _) = sim.accel(0.0, &q0, &qd0, true, &mut p)?;
        if f < 0.0 {
            sim.in_contact = false;
            sim.pending.push(Event {
                kind: EventKind::LiftOff,
                time: 0.0,
                cam_angle: theta0,
                impact_velocity: 0.0,
                conjugate: false,
            });
        }
        Ok(sim)
    }

    /// The follower's fastest free rate (see [`FollowerDynamics::fastest_rate`]).
    pub fn fastest_rate(&self) -> (f64, Field, f64) {
        self.params.fastest_rate(self.oscillating)
    }

    /// The longest step [`Multibody::advance`] accepts, s ([`FollowerDynamics::max_step`]).
    pub fn max_step(&self) -> f64 {
        self.params.max_step(self.oscillating)
    }

    /// The cam angle now, rad (`θ₀ + ω t + ½ α t²`: the driver's).
    fn cam_angle(&self) -> f64 {
        self.theta0 + self.speed * self.t + 0.5 * self.alpha * self.t * self.t
    }

    /// The multibody system (for inspection).
    pub fn system(&self) -> &System {
        &self.sys
    }

    fn active(&self, contact: bool) -> [bool; 4] {
        [true, true, true, contact]
    }

    /// `(q̈, compressive contact force, driving torque)` at a state.
    fn accel(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        contact: bool,
        pairings: &mut [Option<Pairing>],
    ) -> Result<(State, f64, f64), DynamicsError> {
        let (mut qdd, mut lambda, mut phi, mut phi_dot) =
            ([0.0; DOFS], [0.0; ROWS], [0.0; ROWS], [0.0; ROWS]);
        self.sys.evaluate_into(
            &self.al,
            t,
            q,
            qd,
            &self.active(contact),
            pairings,
            Solution {
                qdd: &mut qdd,
                lambda: &mut lambda,
                phi: &mut phi,
                phi_dot: &mut phi_dot,
            },
        )?;
        // the contact is the last row
        let f = if contact {
            -self.orientation * lambda[ROWS - 1]
        } else {
            0.0
        };
        // the driver is row 2 (after the cam's revolute joint); its force on θ is −λ
        Ok((qdd, f, -lambda[DRIVER_ROW]))
    }

    /// The evaluation at the current state in mode `contact`, from the current pairings:
    /// remembered, so that asking again at the same state and mode, with the pairings it
    /// started from or ended with, evaluates once (a step's force check, the sample after it
    /// and the next step's first stage are one evaluation).
    fn here(&self, contact: bool) -> Result<Here, DynamicsError> {
        if let Some(h) = self.last.get() {
            if h.t == self.t
                && h.q == self.q
                && h.qd == self.qd
                && h.contact == contact
                && (h.before == self.pairings[CONTACT] || h.after == self.pairings[CONTACT])
            {
                return Ok(h);
            }
        }
        let mut after = self.pairings;
        let (qdd, force, torque) = self.accel(self.t, &self.q, &self.qd, contact, &mut after)?;
        let h = Here {
            t: self.t,
            q: self.q,
            qd: self.qd,
            contact,
            before: self.pairings[CONTACT],
            after: after[CONTACT],
            qdd,
            force,
            torque,
        };
        self.last.set(Some(h));
        Ok(h)
    }

    /// RK4's first stage at the current state in the given mode (`q̈` and the driver's torque)
    /// and the pairings after it ([`Multibody::here`]).
    fn first_stage(&self, contact: bool) -> Result<((State, f64), Pairings), DynamicsError> {
        let h = self.here(contact)?;
        let mut after = self.pairings;
        after[CONTACT] = h.after;
        Ok(((h.qdd, h.torque), after))
    }

    /// One RK4 step of length `h` from the current state in the given mode, from its `first`
    /// stage ([`Multibody::first_stage`]); `pairings` are those after the first stage.
    fn rk4(
        &self,
        h: f64,
        contact: bool,
        (a1, t1): (State, f64),
        pairings: &mut [Option<Pairing>],
    ) -> Result<(State, State, f64), DynamicsError> {
        let (t, q, qd) = (self.t, &self.q, &self.qd);
        let add =
            |a: &[f64], b: &[f64], s: f64| -> State { std::array::from_fn(|i| a[i] + s * b[i]) };
        let (q2, v2) = (add(q, qd, 0.5 * h), add(qd, &a1, 0.5 * h));
        let (a2, _, t2) = self.accel(t + 0.5 * h, &q2, &v2, contact, pairings)?;
        let (q3, v3) = (add(q, &v2, 0.5 * h), add(qd, &a2, 0.5 * h));
        let (a3, _, t3) = self.accel(t + 0.5 * h, &q3, &v3, contact, pairings)?;
        let (q4, v4) = (add(q, &v3, h), add(qd, &a3, h));
        let (a4, _, t4) = self.accel(t + h, &q4, &v4, contact, pairings)?;
        let qn: State =
            std::array::from_fn(|i| q[i] + h / 6.0 * (qd[i] + 2.0 * v2[i] + 2.0 * v3[i] + v4[i]));
        let vn: State =
            std::array::from_fn(|i| qd[i] + h / 6.0 * (a1[i] + 2.0 * a2[i] + 2.0 * a3[i] + a4[i]));
        // the driving torque's work over the step, integrated with the same stages
        let w = 2; // θ of the cam
        let dw = h / 6.0 * (t1 * qd[w] + 2.0 * t2 * v2[w] + 2.0 * t3 * v3[w] + t4 * v4[w]);
        Ok((qn, vn, dw))
    }

    /// Signed gap (positive apart) at a state, following the pairing.
    fn gap(
        &self,
        q: &[f64],
        qd: &[f64],
        pairing: &mut Option<Pairing>,
    ) -> Result<f64, DynamicsError> {
        let Constraint::Contact {
            curve_a, curve_b, ..
        } = &self.sys.constraints[CONTACT]
        else {
            unreachable!("constraint 3 is the contact")
        };
        let (sa, sb) = (body_state(q, qd, 0), body_state(q, qd, 1));
        let p0 = pairing.unwrap_or(Pairing {
            u_a: 0.0,
            u_b: 0.0,
            point_a: crate::Point2::origin(),
            point_b: crate::Point2::origin(),
            normal: crate::UnitVec2::new_unchecked(Vec2::x()),
            gap: 0.0,
            iterations: 0,
        });
        let p = refine(
            &Surface::new(curve_a.as_ref(), &sa),
            &Surface::new(curve_b.as_ref(), &sb),
            p0.u_a,
            p0.u_b,
            &self.sys.search,
        )
        .map_err(|source| DynamicsError::Contact {
            time: self.t,
            source,
        })?;
        *pairing = Some(p);
        Ok(self.orientation * p.gap)
    }

    /// The sample at the current state.
    pub fn sample(&mut self) -> Result<Sample, DynamicsError> {
        let Here {
            qdd,
            force: f,
            torque,
            after,
            ..
        } = self.here(self.in_contact)?;
        self.pairings[CONTACT] = after;
        let (position, velocity, acceleration) = if self.oscillating {
            (self.q[5], self.qd[5], qdd[5])
        } else {
            let p = crate::Point2::new(self.q[3], self.q[4]);
            (
                (p - self.axis_origin).dot(&self.axis),
                Vec2::new(self.qd[3], self.qd[4]).dot(&self.axis),
                Vec2::new(qdd[3], qdd[4]).dot(&self.axis),
            )
        };
        Ok(Sample {
            time: self.t,
            cam_angle: self.cam_angle(),
            position,
            velocity,
            acceleration,
            contact_force: f,
            in_contact: self.in_contact,
            on_conjugate: false,
            driver_torque: torque,
            driver_work: self.work,
        })
    }

    /// The largest `|Φ|` of the active constraints at the current state (length or rad):
    /// the drift from the constraint manifold.
    pub fn constraint_residual(&self) -> Result<f64, DynamicsError> {
        let mut p = self.pairings;
        let rows = self.dense_rows(&self.q, &self.qd, self.in_contact, &mut p)?;
        Ok(rows.phi.iter().fold(0.0f64, |m, x| m.max(x.abs())))
    }

    /// The current time, s.
    pub fn time(&self) -> f64 {
        self.t
    }

    /// Advances by `h` seconds, locating lift-off and impact events inside the step.
    pub fn advance(&mut self, h: f64) -> Result<Vec<Event>, DynamicsError> {
        self.params.check_step(self.oscillating, h)?;
        let mut events = std::mem::take(&mut self.pending);
        let end = self.t + h;
        let mut guard = 0;
        while self.t < end - 1e-15 * end.abs().max(1.0) && guard < 64 {
            guard += 1;
            let dt = end - self.t;
            let (first, mut pairings) = self.first_stage(self.in_contact)?;
            let (qn, vn, dw) = self.rk4(dt, self.in_contact, first, &mut pairings)?;
            if self.in_contact {
                // the step's end, projected: the contact force there decides (its evaluation
                // is the sample's and the next step's first stage)
                let before = (self.q, self.qd, self.pairings, self.t, self.work);
                (self.q, self.qd, self.pairings, self.t) = (qn, vn, pairings, end);
                self.work += dw;
                self.project()?;
                if self.here(true)?.force >= 0.0 {
                    continue;
                }
                (self.q, self.qd, self.pairings, self.t, self.work) = before;
                // the force crosses zero inside: bisection on the sub-step
                let tau = self.bisect(
                    dt,
                    |s, t, q, v, p| s.accel(t, q, v, true, p).map(|(_, f, _)| f),
                    true,
                )?;
                self.commit(tau, true)?;
                self.in_contact = false;
                events.push(Event {
                    kind: EventKind::LiftOff,
                    time: self.t,
                    cam_angle: self.cam_angle(),
                    impact_velocity: 0.0,
                    conjugate: false,
                });
            } else {
                let mut p = pairings[CONTACT];
                let g = self.gap(&qn, &vn, &mut p)?;
                if g >= -1e-12 * self.size {
                    pairings[CONTACT] = p;
                    (self.q, self.qd, self.pairings, self.t) = (qn, vn, pairings, end);
                    self.work += dw;
                    self.project()?;
                    continue;
                }
                let tau = self.bisect(dt, |s, _t, q, v, p| s.gap(q, v, &mut p[CONTACT]), false)?;
                self.commit(tau, false)?;
                let vn_before = self.impact()?;
                events.push(Event {
                    kind: EventKind::Impact,
                    time: self.t,
                    cam_angle: self.cam_angle(),
                    impact_velocity: vn_before,
                    conjugate: false,
                });
            }
        }
        Ok(events)
    }

    /// The sub-step `τ ∈ (0, dt]` where `f` (evaluated at the end of an RK4 step of length `τ`)
    /// crosses zero; `contact` is the mode integrated in.
    fn bisect(
        &self,
        dt: f64,
        f: impl Fn(&Self, f64, &[f64], &[f64], &mut [Option<Pairing>]) -> Result<f64, DynamicsError>,
        contact: bool,
    ) -> Result<f64, DynamicsError> {
        let (mut lo, mut hi) = (0.0, dt);
        // every trial step starts from the current state
        let (first, after) = self.first_stage(contact)?;
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            let mut p = after;
            let (q, v, _) = self.rk4(mid, contact, first, &mut p)?;
            let val = f(self, self.t + mid, &q, &v, &mut p)?;
            if val >= 0.0 {
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

    fn commit(&mut self, tau: f64, contact: bool) -> Result<(), DynamicsError> {
        let (first, mut p) = self.first_stage(contact)?;
        let (q, v, dw) = self.rk4(tau, contact, first, &mut p)?;
        let mut pc = p[CONTACT];
        let _ = self.gap(&q, &v, &mut pc)?;
        p[CONTACT] = pc;
        (self.q, self.qd, self.pairings, self.t) = (q, v, p, self.t + tau);
        self.work += dw;
        Ok(())
    }

    /// The active constraints at `(q, q̇)` as dense rows (see [`System::dense_rows`]).
    fn dense_rows(
        &self,
        q: &[f64],
        qd: &[f64],
        contact: bool,
        pairings: &mut [Option<Pairing>],
    ) -> Result<DenseRows, DynamicsError> {
        self.sys
            .dense_rows(self.t, q, qd, &self.active(contact), pairings)
            .map_err(|source| DynamicsError::Contact {
                time: self.t,
                source,
            })
    }

    /// The mass-orthogonal projection of `x0` onto `J x = b` (see [`System::project_onto`]).
    fn project_onto(
        &self,
        rows: &DenseRows,
        x0: &[f64],
        b: &[f64],
    ) -> Result<State, DynamicsError> {
        let mut x = [0.0; DOFS];
        if self.sys.project_onto(rows, x0, b, &mut x) {
            Ok(x)
        } else {
            Err(DynamicsError::Singular { time: self.t })
        }
    }

    /// Mass-orthogonal projection of the state onto the constraints (Bayo and Ledesma 1996):
    /// positions by Newton on `Φ(q) = 0`, then velocities onto `Φ_q q̇ = −Φ_t`.
    fn project(&mut self) -> Result<(), DynamicsError> {
        let mut pairings = self.pairings;
        let mut rows = self.dense_rows(&self.q, &self.qd, self.in_contact, &mut pairings)?;
        for _ in 0..4 {
            if rows.phi.iter().all(|p| p.abs() <= 1e-14 * self.size) {
                break;
            }
            let zero = [0.0; DOFS];
            let mut b = [0.0; ROWS];
            for (b, p) in b.iter_mut().zip(rows.phi.iter()) {
                *b = -p;
            }
            let dq = self.project_onto(&rows, &zero, &b[..rows.m])?;
            for (q, d) in self.q.iter_mut().zip(&dq) {
                *q += d;
            }
            // the rows at the corrected positions (the velocity projection uses the last)
            rows = self.dense_rows(&self.q, &self.qd, self.in_contact, &mut pairings)?;
        }
        self.qd = self.project_onto(&rows, &self.qd, &rows.target)?;
        self.pairings = pairings;
        Ok(())
    }

    /// An impact at the current state: velocities projected so that the normal velocity reverses
    /// times the restitution (joints and driver held); returns the approach speed. Re-engages the
    /// contact when the rebound is negligible.
    fn impact(&mut self) -> Result<f64, DynamicsError> {
        let mut pairings = self.pairings;
        let rows = self.dense_rows(&self.q, &self.qd, true, &mut pairings)?;
        let mut targets = rows.target.clone();
        let m = rows.m;
        let vn_before = rows
            .row(m - 1)
            .iter()
            .zip(&self.qd)
            .map(|(a, b)| a * b)
            .sum::<f64>();
        let approach = (self.orientation * vn_before).abs();
        targets[m - 1] = -self.params.restitution * vn_before;
        self.qd = self.project_onto(&rows, &self.qd, &targets)?;
        // a negligible rebound: the follower stays on the cam
        let rebound = self.params.restitution * approach;
        self.in_contact = rebound <= REBOUND_TOLERANCE * self.speed * self.size;
        Ok(approach)
    }
}
