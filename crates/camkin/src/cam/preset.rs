//! A cam-follower mechanism as a [`System`]: the cam a body pinned to the ground at its axis and
//! driven at its speed, the follower a body on a slide or a pin, the profile and the follower's
//! curve one contact between them. The system's kinematic analysis then answers what
//! [`Mechanism::analyze`] answers by its own fast path (one coordinate, closed forms per
//! follower kind); the tests hold the two to 1e-12 of the size on every example.
//!
//! The cam path stays the front ends' route for `[cam]` files: it is exact, about 60× cheaper a
//! step, and gives what the system does not (design checks, a form-closed follower's play,
//! jerk on every follower kind). The preset is how a cam-follower becomes part of a larger
//! mechanism (a cam driving a linkage) and how the two routes check each other.

use super::{CamError, FollowerJoint, Mechanism};
use crate::body::Pose;
use crate::geometry::Point2;
use crate::system::{
    Body, BodyId, Contact, Coordinate, Driver, DriverLaw, JointKind, System, SystemState,
};

/// A cam-follower mechanism as a system, with its bodies' ids.
#[derive(Debug, Clone)]
pub struct CamFollowerSystem {
    /// the system: bodies `cam` and `follower`, joints `camshaft` and `follower joint`, driver
    /// `cam drive`, contact `cam on follower`
    pub system: System,
    /// the cam
    pub cam: BodyId,
    /// the follower
    pub follower: BodyId,
    /// the follower's joint, to read its coordinate back from a body's state
    pub joint: FollowerJoint,
    /// the cam's speed at `t = 0`, rad/s
    pub speed: f64,
    /// the cam's angular acceleration, rad/s², in its own direction
    pub angular_acceleration: f64,
    /// +1 counter-clockwise, −1 clockwise
    pub sense: f64,
    /// the cam angle at `t = 0`, rad, in the cam's direction
    pub start_angle: f64,
}

impl CamFollowerSystem {
    /// The follower's coordinate `(q, q̇, q̈)` as the cam path reports it (a slide's travel from
    /// the cam axis along its direction, or an arm's angle within ±180° of the cam path's
    /// reference angle), from a solved instant.
    pub fn follower_coordinate(&self, state: &SystemState) -> [f64; 3] {
        match self.follower.index() {
            Some(i) => self.joint.coordinate_of(&state.bodies[i]),
            None => [f64::NAN; 3],
        }
    }

    /// The instant at which the cam is at angle `theta` (rad, in its own direction):
    /// `θ − θ₀ = ω t + α t²/2` (NaN when a decelerating cam never gets there).
    pub fn time_of(&self, theta: f64) -> f64 {
        self.sweep_angle()
            .time(&self.system, theta - self.start_angle)
            .unwrap_or(f64::NAN)
    }

    /// The sweep angle of the preset: the cam angle.
    pub fn sweep_angle(&self) -> crate::spec::SweepAngle {
        crate::spec::SweepAngle::Cam {
            speed: self.speed,
            angular_acceleration: self.angular_acceleration,
        }
    }
}

impl CamFollowerSystem {
    /// The mechanism `m` as a [`System`] (see the module docs of `cam::preset`). The follower starts where
    /// the cam path's first touch puts it at cam angle 0, so that both routes follow the same
    /// contact. The cam turns from angle 0 at `t = 0` at its speed, accelerating at its angular
    /// acceleration (the cam path analyses each angle at the speed given instead: the two agree
    /// when it is zero). A form-closed follower's second curve is left out: with it the follower's one
    /// degree of freedom would have two rows, and the system's kinematic analysis needs one
    /// row a coordinate.
    pub fn of(m: &Mechanism) -> Result<CamFollowerSystem, CamError> {
        Self::starting_at(m, 0.0)
    }

    /// As [`CamFollowerSystem::of`], with the cam at angle `theta0` (rad, in its own direction)
    /// at `t = 0` and the follower where the cam path's first touch puts it there.
    pub fn starting_at(m: &Mechanism, theta0: f64) -> Result<CamFollowerSystem, CamError> {
        let cam = m.cam();
        let start = m.analyze(theta0)?;
        let sense = cam.direction().sign();
        let mut system = System::new();
        let cam_body = system.add_body(Body {
            name: "cam".into(),
            mass: 0.0,
            inertia: 0.0,
            pose: Pose::new(cam.pivot(), sense * theta0),
            centre_of_mass: crate::geometry::Point2::origin(),
        });
        let joint = m.follower_joint();
        let (pose, curve) = m.follower_body(start.position);
        let follower = system.add_body(Body {
            name: "follower".into(),
            mass: 0.0,
            inertia: 0.0,
            pose,
            centre_of_mass: crate::geometry::Point2::origin(),
        });
        system.add_joint(crate::system::Joint {
            name: "camshaft".into(),
            kind: JointKind::Revolute {
                a: BodyId::GROUND,
                at_a: cam.pivot(),
                b: cam_body,
                at_b: Point2::origin(),
            },
        });
        system.add_joint(crate::system::Joint {
            name: "follower joint".into(),
            kind: joint.system_joint(follower),
        });
        system.add_driver(Driver {
            name: "cam drive".into(),
            body: cam_body,
            coordinate: Coordinate::Angle,
            law: DriverLaw::Quadratic {
                start: sense * theta0,
                rate: sense * cam.speed(),
                acceleration: sense * cam.angular_acceleration(),
            },
        });
        system.add_contact(Contact {
            name: "cam on follower".into(),
            a: cam_body,
            curve_a: m.profile_arc(),
            b: follower,
            curve_b: curve,
        });
        Ok(CamFollowerSystem {
            system,
            cam: cam_body,
            follower,
            joint,
            speed: cam.speed(),
            angular_acceleration: cam.angular_acceleration(),
            sense,
            start_angle: theta0,
        })
    }
}
