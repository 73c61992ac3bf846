//! What every dynamic model of the follower shares: its properties, the samples and events of
//! a run, the checks of the properties and the fastest rate the time step must resolve.

use super::DynamicsError;
use crate::cam::Mechanism;
use crate::field::{DynamicsField, Field};
use crate::geometry::Vec2;

/// Dynamic properties of the follower (SI units, lengths in the mechanism's unit converted by the
/// caller).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FollowerDynamics {
    /// mass of a translating follower, kg
    pub mass: f64,
    /// moment of inertia of an oscillating follower about its pivot, kg·m²
    pub inertia: f64,
    /// spring stiffness, N/m (translating) or N·m/rad (oscillating)
    pub spring_stiffness: f64,
    /// spring force (torque) at the follower's lowest position over a revolution, pushing it
    /// onto the cam, N (N·m)
    pub spring_preload: f64,
    /// viscous damping, N·s/m (N·m·s/rad)
    pub damping: f64,
    /// coefficient of restitution of impacts, 0 to 1
    pub restitution: f64,
    /// gravity, m/s²
    pub gravity: Vec2,
}

impl FollowerDynamics {
    /// What moves with the follower's coordinate: a slide's mass (kg), an arm's moment of
    /// inertia about its pivot (kg·m²).
    pub fn moving_mass(&self, joint: &crate::cam::FollowerJoint) -> f64 {
        if joint.is_rotating() {
            self.inertia
        } else {
            self.mass
        }
    }

    /// Gravity's force along a slide's coordinate, N (`m g·d`); 0 on an arm, whose mass is taken
    /// at its pivot (no gravity torque).
    pub fn gravity_along(&self, joint: &crate::cam::FollowerJoint) -> f64 {
        joint
            .direction()
            .map_or(0.0, |d| self.mass * self.gravity.dot(&d))
    }
}

/// The follower's state at one instant of a simulation.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Sample {
    /// time, s
    pub time: f64,
    /// cam angle, rad
    pub cam_angle: f64,
    /// position (as in [`crate::cam::FollowerState`])
    pub position: f64,
    /// velocity
    pub velocity: f64,
    /// acceleration
    pub acceleration: f64,
    /// contact force along the common normal, N, compressive positive; 0 in free flight
    pub contact_force: f64,
    /// the follower touches the cam
    pub in_contact: bool,
    /// the touching curve is the follower's second curve (a conjugate follower, a gear's coast
    /// flank)
    pub on_conjugate: bool,
    /// the torque driving the cam, N·m
    pub driver_torque: f64,
    /// the work done by the driving torque since time 0, J
    pub driver_work: f64,
    /// the follower's energy balance, J: its kinetic energy, its spring's (and gravity's)
    /// potential, its damper's and the driver's work, the impacts' losses, and what is left
    /// unexplained (the cam, driven, is not in it: its kinetic energy is the driver's)
    pub balance: super::EnergyBalance,
}

/// What happened at an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum EventKind {
    /// the contact force reached zero: the follower leaves the cam
    LiftOff,
    /// the follower hits the cam again
    Impact,
    /// the contact jumps to another part of the curves (another tooth pair): an impact without
    /// flight, at the speed the new part approaches the follower (0 for an ideal involute
    /// handover)
    Jump,
}

/// A located event.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Event {
    /// lift-off, impact or jump
    pub kind: EventKind,
    /// time, s
    pub time: f64,
    /// cam angle, rad
    pub cam_angle: f64,
    /// normal approach speed at an impact (0 at a lift-off), m/s
    pub impact_velocity: f64,
    /// on the follower's second curve (a conjugate follower, a gear's coast flank)
    pub conjugate: bool,
}

/// A rebound slower than this times the cam's surface speed scale (`ω · size`) ends the bouncing:
/// the impact is taken as plastic and the contact re-engaged (a sequence of bounces with
/// restitution below 1 would otherwise never end).
pub const REBOUND_TOLERANCE: f64 = 1e-3;

/// The longest step times the follower's fastest rate ([`FollowerDynamics::max_step`]).
pub const MAX_RATE_STEP: f64 = 2.0;

/// Checks the follower's properties for `mech`: a positive mass (inertia for an arm), a
/// restitution from 0 to 1.
pub(crate) fn check_params(
    mech: &Mechanism,
    params: &FollowerDynamics,
) -> Result<(), DynamicsError> {
    let positive = |field: Field, v: f64| {
        if v.is_finite() && v > 0.0 {
            Ok(())
        } else {
            Err(DynamicsError::Invalid {
                field,
                value: v,
                reason: "must be positive and finite",
            })
        }
    };
    if mech.follower_joint().is_rotating() {
        positive(Field::Dynamics(DynamicsField::Inertia), params.inertia)?;
    } else {
        positive(Field::Dynamics(DynamicsField::Mass), params.mass)?;
    }
    if !(0.0..=1.0).contains(&params.restitution) {
        return Err(DynamicsError::Invalid {
            field: Field::Dynamics(DynamicsField::Restitution),
            value: params.restitution,
            reason: "must be from 0 to 1",
        });
    }
    Ok(())
}

impl FollowerDynamics {
    /// The mass (`rotating = false`) or the inertia.
    pub fn inertial(&self, rotating: bool) -> f64 {
        if rotating {
            self.inertia
        } else {
            self.mass
        }
    }

    /// The follower's fastest free rate (1/s) and the parameter that sets it: the larger root of
    /// `λ² + (c/m) λ + k/m = 0` in magnitude (`c/m` for a heavily damped follower, `√(k/m)` for a
    /// lightly damped one; `m` is the inertia for an arm).
    pub fn fastest_rate(&self, rotating: bool) -> (f64, Field, f64) {
        let m = self.inertial(rotating);
        let (c, k) = (self.damping / m, self.spring_stiffness / m);
        let disc = c * c - 4.0 * k;
        if disc >= 0.0 {
            (
                0.5 * (c + disc.sqrt()),
                Field::Dynamics(DynamicsField::Damping),
                self.damping,
            )
        } else {
            (
                k.sqrt(),
                Field::Dynamics(DynamicsField::SpringStiffness),
                self.spring_stiffness,
            )
        }
    }

    /// The longest time step, s: [`MAX_RATE_STEP`] over the fastest rate (the classical
    /// Runge–Kutta method is stable to 2.78 on the negative real axis and 2.83 on the imaginary
    /// one; measured on an overdamped follower, steps of 3.3 / rate ran but gave impacts of
    /// 9–18 m/s where the resolved run gives 1 m/s). The one-coordinate model's flight is exact,
    /// but it finds an impact from the gaps at the ends of a step, so it keeps the same bound.
    pub fn max_step(&self, rotating: bool) -> f64 {
        let rate = self.fastest_rate(rotating).0;
        if rate > 0.0 {
            MAX_RATE_STEP / rate
        } else {
            f64::INFINITY
        }
    }
}
