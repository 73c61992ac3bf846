//! A cam-follower mechanism's dynamics in the one engine: the mechanism's preset system
//! ([`crate::cam::CamFollowerSystem`]: the cam pinned to the ground and driven, the follower on
//! its slide or pin, the profile and the follower's curve one contact) with the follower's mass,
//! spring, damper and gravity as the system's own bodies and force elements, run by
//! [`SystemSimulation`] and read back in the follower's coordinate.
//!
//! The follower's spring is the system's elements:
//! - on a slide, a compression spring seated on the ground on the slide's axis, `D = 100` cam
//!   sizes beyond the follower's rest position (`ref`), with stiffness `k`, free length
//!   `D − ref` and preload `−F₀` (a tension): its force on the follower is
//!   `−(F₀ + k (s − ref)) d` while the follower is on the axis below the seat, the slide's spring
//!   exactly; the damper between the same points gives `−c ṡ d`;
//! - on a pin, a torsion spring from the ground with free angle `ref` and preload `−σ F₀` (`σ`
//!   the closing sense), whose torque on the arm is `σ F₀ − k (θ − ref)`, and a torsion damper
//!   `−c ω`.
//!
//! The cam's mass and inertia (1 kg, 1 kg·m²) do not change the follower's motion: the cam is
//! driven. The samples leave them out: the driving torque is what the cam passes on to the
//! follower (the driver's less `1 kg·m² · α`), its work and the energy balance are the
//! follower's (the cam's kinetic energy and the gravity of the masses held at pivots taken
//! away), as in the one-coordinate model.

use super::follower::{check_params, Event, EventKind, FollowerDynamics, Sample};
use super::system::{ContactEvent, SystemDynamicsOptions, SystemSimulation};
use super::{AugmentedLagrangian, DynamicsError};
use crate::cam::{CamFollowerSystem, FollowerJoint, Mechanism};
use crate::system::{BodyId, ForceElement, ForceKind};

/// How far beyond the follower's rest position a slide's spring is seated, in cam sizes: the
/// follower never flies this far (a spring with the follower beyond its seat would pull).
const SEAT: f64 = 100.0;

/// A cam-follower mechanism simulated as its preset system (see the module docs);
/// [`super::Simulation`] chooses it for a follower with one contact that never jumps.
#[derive(Debug, Clone)]
pub struct PresetSimulation {
    sim: SystemSimulation<'static>,
    joint: FollowerJoint,
    /// the follower's body index
    follower: usize,
    /// the cam's body index
    cam: usize,
    /// the cam's kinetic energy at the start, J (its 1 kg·m²: the driver's, not the follower's)
    cam_kinetic0: f64,
    /// gravity's potential of the bodies' masses held at their pivots (the cam's 1 kg; an arm's
    /// mass), constant, J
    held: f64,
    theta0: f64,
    speed: f64,
    /// the cam's angular acceleration, rad/s²
    alpha: f64,
}

impl PresetSimulation {
    /// The preset of `mech` (lengths in metres) with the follower's `params`, starting at cam
    /// angle `theta0` (rad) at time 0 at the kinematic position and velocity, in contact unless
    /// the contact force there would be tensile (then the first advance reports a lift-off at
    /// time 0). `al` solves dependent rows (it is not used where the rows are independent).
    ///
    /// Refused with [`DynamicsError::ContactJumps`] where the contact jumps and
    /// [`DynamicsError::FormClosed`] for a conjugate follower: [`super::Simulation`] takes
    /// the one-coordinate model there.
    pub fn starting_at(
        mech: &Mechanism,
        params: FollowerDynamics,
        al: AugmentedLagrangian,
        theta0: f64,
    ) -> Result<Self, DynamicsError> {
        check_params(mech, &params)?;
        if mech.is_conjugate() {
            return Err(DynamicsError::FormClosed);
        }
        let jumps = mech.jump_angles(0.25);
        if !jumps.is_empty() {
            return Err(DynamicsError::ContactJumps { angles_deg: jumps });
        }
        let kinematics = |source| DynamicsError::Kinematics { source };
        let preset = CamFollowerSystem::starting_at(mech, theta0).map_err(kinematics)?;
        let rest = mech.travel().map_err(kinematics)?.rest;
        let CamFollowerSystem {
            mut system,
            cam,
            follower,
            joint,
            ..
        } = preset;
        let (Some(ic), Some(fi)) = (cam.index(), follower.index()) else {
            unreachable!("the preset's cam and follower are bodies")
        };
        let rotating = joint.is_rotating();
        {
            let bodies = &mut system.bodies;
            (bodies[ic].mass, bodies[ic].inertia) = (1.0, 1.0);
            // an arm's mass sits at its pivot, a slide does not turn: the other entry is 1
            (bodies[fi].mass, bodies[fi].inertia) = if rotating {
                (1.0, params.inertia)
            } else {
                (params.mass, 1.0)
            };
        }
        let (k, f0, c) = (
            params.spring_stiffness,
            params.spring_preload,
            params.damping,
        );
        let mut element = |name: &str, kind| {
            system.add_force(ForceElement {
                name: name.into(),
                kind,
            })
        };
        match joint {
            FollowerJoint::Translating { origin, direction } => {
                let d = SEAT * mech.size() + rest.abs();
                let seat = origin + (rest + d) * *direction;
                let at_b = crate::Point2::origin();
                element(
                    "follower spring",
                    ForceKind::Spring {
                        a: BodyId::GROUND,
                        at_a: seat,
                        b: follower,
                        at_b,
                        stiffness: k,
                        free_length: d,
                        preload: -f0,
                    },
                );
                if c != 0.0 {
                    element(
                        "follower damper",
                        ForceKind::Damper {
                            a: BodyId::GROUND,
                            at_a: seat,
                            b: follower,
                            at_b,
                            damping: c,
                        },
                    );
                }
            }
            FollowerJoint::Rotating { closing, .. } => {
                element(
                    "follower spring",
                    ForceKind::TorsionSpring {
                        a: BodyId::GROUND,
                        b: follower,
                        stiffness: k,
                        free_angle: rest,
                        preload: -closing.sign() * f0,
                    },
                );
                if c != 0.0 {
                    element(
                        "follower damper",
                        ForceKind::TorsionDamper {
                            a: BodyId::GROUND,
                            b: follower,
                            damping: c,
                        },
                    );
                }
            }
        }
        let opts = SystemDynamicsOptions {
            metres_per_unit: 1.0,
            gravity: params.gravity,
            restitution: vec![params.restitution],
            al,
            hertz: Vec::new(),
            start_touching: Vec::new(),
            initial_rates: Vec::new(),
            tolerances: super::Tolerances::default(),
            scheme: super::Scheme::Auto,
        };
        let sim = SystemSimulation::owning(system, opts)?;
        let (cs, fs) = (sim.state(ic), sim.state(fi));
        let g = params.gravity;
        let mut held = -g.dot(&cs.pose.origin.coords);
        if rotating {
            held -= g.dot(&fs.pose.origin.coords);
        }
        Ok(Self {
            sim,
            joint,
            follower: fi,
            cam: ic,
            cam_kinetic0: 0.5 * cs.omega * cs.omega,
            held,
            theta0,
            speed: mech.cam().speed(),
            alpha: mech.cam().angular_acceleration(),
        })
    }

    /// The tolerances of its steps ([`SystemSimulation::set_tolerances`]).
    pub fn set_tolerances(&mut self, t: super::Tolerances) -> Result<(), DynamicsError> {
        self.sim.set_tolerances(t)
    }

    /// The integrator of its steps ([`SystemSimulation::set_scheme`]).
    pub fn set_scheme(&mut self, scheme: super::Scheme) {
        self.sim.set_scheme(scheme);
    }

    /// The steps taken since the start: accepted and rejected
    /// ([`SystemSimulation::steps_taken`]).
    pub fn steps_taken(&self) -> (usize, usize) {
        self.sim.steps_taken()
    }

    /// The longest step its integration is stable at, s
    /// ([`SystemSimulation::stable_step`]).
    pub fn stable_step(&self) -> f64 {
        self.sim.stable_step()
    }

    /// The cam angle at time `t`, rad (`θ₀ + ω t + ½ α t²`: the driver's).
    fn cam_angle(&self, t: f64) -> f64 {
        self.theta0 + self.speed * t + 0.5 * self.alpha * t * t
    }

    /// The follower's event of a contact event.
    fn event(&self, e: &ContactEvent) -> Event {
        Event {
            kind: e.kind,
            time: e.time,
            cam_angle: self.cam_angle(e.time),
            impact_velocity: match e.kind {
                EventKind::Impact => e.approach,
                _ => 0.0,
            },
            conjugate: false,
        }
    }

    /// Advances by `h` seconds, locating lift-off and impact events inside the step.
    pub fn advance(&mut self, h: f64) -> Result<Vec<Event>, DynamicsError> {
        let events = self.sim.advance(h)?;
        Ok(events.iter().map(|e| self.event(e)).collect())
    }

    /// The follower's state at the current time.
    pub fn sample(&mut self) -> Result<Sample, DynamicsError> {
        let (i, c) = (3 * self.follower, 3 * self.cam + 2);
        let (body, force, torque) = self.sim.motion(|q, qd, a| {
            let body = crate::BodyState {
                pose: crate::Pose::new(crate::Point2::new(q[i], q[i + 1]), q[i + 2]),
                velocity: crate::Vec2::new(qd[i], qd[i + 1]),
                omega: qd[i + 2],
                acceleration: crate::Vec2::new(a.qdd[i], a.qdd[i + 1]),
                alpha: a.qdd[i + 2],
            };
            // the torque the cam passes on: the driver's less its own 1 kg·m² times α
            (body, a.forces[0], a.efforts[0] - a.qdd[c])
        })?;
        let [position, velocity, acceleration] = match self.joint {
            // the arm's angle as integrated (not wrapped)
            FollowerJoint::Rotating { .. } => [body.pose.angle, body.omega, body.alpha],
            FollowerJoint::Translating { .. } => self.joint.coordinate_of(&body),
        };
        let t = self.sim.time();
        Ok(Sample {
            time: t,
            cam_angle: self.cam_angle(t),
            position,
            velocity,
            acceleration,
            contact_force: force,
            in_contact: self.sim.in_contact(0),
            on_conjugate: false,
            driver_torque: torque,
            driver_work: self.sim.driver_work() - self.cam_kinetic_change(),
            balance: self.balance(),
        })
    }

    /// The cam's kinetic energy's change since the start, J: the driver's work on the cam's
    /// own 1 kg·m² (where it accelerates), not on the follower.
    fn cam_kinetic_change(&self) -> f64 {
        let w = self.sim.state(self.cam).omega;
        0.5 * w * w - self.cam_kinetic0
    }

    /// The follower's energy balance ([`Sample::balance`]): the system's, less the cam's
    /// kinetic energy and angular momentum and the driver's work on them, less gravity's
    /// constant potential of the masses held at their pivots.
    fn balance(&self) -> super::EnergyBalance {
        let mut b = self.sim.balance();
        let w = self.sim.state(self.cam).omega;
        b.kinetic -= 0.5 * w * w;
        b.initial -= self.cam_kinetic0 + self.held;
        b.drivers -= self.cam_kinetic_change();
        b.gravity.potential -= self.held;
        b.angular_momentum -= w;
        b
    }

    /// The largest `|Φ|` of the active constraints at the current state (length or rad).
    pub fn constraint_residual(&self) -> Result<f64, DynamicsError> {
        self.sim.constraint_residual()
    }

    /// The current time, s.
    pub fn time(&self) -> f64 {
        self.sim.time()
    }
}
