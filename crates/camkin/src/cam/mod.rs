//! Cam-follower mechanisms analysed at one instant by the contact method.
//!
//! A [`Cam`] is a closed profile turning about an axis at constant speed (optionally with a
//! constant angular acceleration); a [`Follower`] is one of the five types of `cam-follower.md`.
//! [`Mechanism::analyze`] gives at one cam angle the follower's position (by **first touch**:
//! the follower brought from far away towards the cam stops at the first contact), its velocity
//! and acceleration by the contact method (paper eqs. 5, 6, 11 via [`crate::contact`]), and the
//! contact data an engineer wants beside them. [`Sweep`] reuses the previous contact as a warm
//! start over a range of angles.
//!
//! The cam angle `θ` is how far the cam has turned in its own direction; a counter-clockwise
//! cam's frame is at `+θ`, a clockwise cam's at `−θ`; at `θ = 0` the cam frame is aligned with
//! the world frame with its origin on the rotation axis. Other conventions: see the
//! [crate docs](crate#sign-conventions).

mod build_work;
mod checks;
mod conic;
mod conjugate;
mod contacts;
mod corners;
mod derivatives;
mod error;
mod first_touch;
mod follower;
pub(crate) mod golden;
mod instant;
mod jumps;
mod kinematics;
mod linear;
mod mechanism;
mod options;
mod pose;
mod preset;
mod state;
mod summary;
mod support;
mod sweep;
pub mod synthesis;
mod travel;

pub use build_work::build_work;
pub use checks::{ConjugatePlay, DesignChecks, RoundTrip};
pub use conjugate::ConjugateSweep;
pub use contacts::CamContact;
pub use error::{CamError, StopReason};
pub use first_touch::starts::MAX_CANDIDATES;
pub use follower::{Follower, FollowerCurve, FollowerJoint, FollowerProfile, Sense, LENGTH_RANGE};
pub use jumps::{contact_jumps, contact_jumps_with};
pub use mechanism::SWEEP_CHUNK;
pub use options::AnalysisOptions;
pub use preset::CamFollowerSystem;
pub use state::{Corner, FollowerState, Motion};
pub use support::IndependentCheck;
pub use sweep::{Found, Sweep};
pub use travel::Travel;

pub(crate) use first_touch::search::{bracket_params, bracket_samples, Touch};
pub(crate) use instant::Instant;

use crate::body::BodyState;
use crate::curve::{Curve, Domain};
use crate::field::{CamField, Field};
use crate::geometry::Point2;
use crate::valid::Rule;
use std::sync::Arc;

/// A cam: a closed profile in the cam frame, whose origin is the rotation axis.
#[derive(Debug, Clone)]
pub struct Cam {
    profile: Arc<dyn Curve>,
    pivot: Point2,
    direction: Sense,
    speed: f64,
    angular_acceleration: f64,
    /// the speed as given: its field (`speed` in rad/s or `speed_rpm`) and value, for messages
    speed_given: (CamField, f64),
    /// the angular acceleration as given: its value and the factor to rad/s²
    alpha_given: (f64, f64),
    /// the motion program the profile was synthesised from, when it was
    synthesis: Option<Arc<synthesis::SynthesizedProfile>>,
}

impl Cam {
    /// A cam turning at `speed` rad/s (> 0) in `direction` about the world point `pivot`.
    pub fn new(
        profile: Arc<dyn Curve>,
        pivot: Point2,
        direction: Sense,
        speed: f64,
    ) -> Result<Self, CamError> {
        if !matches!(profile.domain(), Domain::Periodic { .. }) {
            return Err(CamError::OpenProfile);
        }
        Rule::Finite
            .check_point(pivot)
            .map_err(|reason| CamError::InvalidVector {
                field: Field::Cam(CamField::Pivot),
                x: pivot.x,
                y: pivot.y,
                reason,
            })?;
        Rule::Positive
            .check(speed)
            .map_err(|reason| CamError::Invalid {
                field: Field::Cam(CamField::Speed),
                value: speed,
                reason,
            })?;
        Ok(Self {
            profile,
            pivot,
            direction,
            speed,
            angular_acceleration: 0.0,
            speed_given: (CamField::Speed, speed),
            alpha_given: (0.0, 1.0),
            synthesis: None,
        })
    }

    /// As [`Cam::new`] with the speed in revolutions per minute.
    pub fn from_rpm(
        profile: Arc<dyn Curve>,
        pivot: Point2,
        direction: Sense,
        rpm: f64,
    ) -> Result<Self, CamError> {
        Rule::Positive
            .check(rpm)
            .map_err(|reason| CamError::Invalid {
                field: Field::Cam(CamField::SpeedRpm),
                value: rpm,
                reason,
            })?;
        // τ/60 first: rpm · τ would overflow near f64::MAX; a speed that underflows is the rpm's
        if !(rpm * (std::f64::consts::TAU / 60.0) >= LENGTH_RANGE.0) {
            return Err(CamError::Invalid {
                field: Field::Cam(CamField::SpeedRpm),
                value: rpm,
                reason: "is too slow: the speed must be at least 1e-100 rad/s",
            });
        }
        let mut cam = Self::new(
            profile,
            pivot,
            direction,
            rpm * (std::f64::consts::TAU / 60.0),
        )?;
        cam.speed_given = (CamField::SpeedRpm, rpm);
        Ok(cam)
    }

    /// With a constant angular acceleration `θ̈` (rad/s², in the cam's direction of motion); the
    /// speed given is then the speed at the instant analysed.
    pub fn with_angular_acceleration(mut self, alpha: f64) -> Result<Self, CamError> {
        Rule::Finite
            .check(alpha)
            .map_err(|reason| CamError::Invalid {
                field: Field::Cam(CamField::AngularAcceleration),
                value: alpha,
                reason,
            })?;
        self.angular_acceleration = alpha;
        self.alpha_given = (alpha, 1.0);
        Ok(self)
    }

    /// The profile as synthesised from a motion program, when the cam was built from one (by
    /// [`crate::spec::MechanismSpec::build`]).
    pub fn synthesis(&self) -> Option<&synthesis::SynthesizedProfile> {
        self.synthesis.as_deref()
    }

    /// Records that the profile is `s` (which the cam already holds as its curve).
    pub(crate) fn set_synthesis(&mut self, s: Arc<synthesis::SynthesizedProfile>) {
        self.synthesis = Some(s);
    }

    /// The profile.
    pub fn profile(&self) -> &dyn Curve {
        self.profile.as_ref()
    }
    /// The rotation axis (world).
    pub fn pivot(&self) -> Point2 {
        self.pivot
    }
    /// Direction of rotation.
    pub fn direction(&self) -> Sense {
        self.direction
    }
    /// Speed, rad/s (> 0).
    pub fn speed(&self) -> f64 {
        self.speed
    }
    /// Angular acceleration `θ̈`, rad/s².
    pub fn angular_acceleration(&self) -> f64 {
        self.angular_acceleration
    }

    /// Records the angular acceleration as the user gave it (`value · factor` rad/s²), for
    /// messages.
    pub(crate) fn set_alpha_given(&mut self, value: f64, factor: f64) {
        self.alpha_given = (value, factor);
    }

    /// Refuses a speed or an angular acceleration whose outputs on a cam reaching `size` from
    /// its axis would overflow (jerk `~ ω³ size`) or underflow (acceleration `~ ω² size`), naming
    /// the field as given.
    pub(crate) fn check_magnitudes(&self, size: f64) -> Result<(), CamError> {
        const BIG: f64 = 1e290;
        const SMALL: f64 = 1e-290;
        let w = self.speed;
        let (field, value) = self.speed_given;
        let jerk = w * w * w * size;
        let accel = w * w * size;
        if !(jerk.is_finite() && jerk <= BIG) {
            return Err(CamError::Invalid {
                field: Field::Cam(field),
                value,
                reason: "is too fast for this cam: its jerk (~ ω³ × size) would overflow f64",
            });
        }
        if accel.min(jerk) < SMALL {
            return Err(CamError::Invalid {
                field: Field::Cam(field),
                value,
                reason: "is too slow for this cam: its accelerations and jerk (~ ω² × size, ω³ × size) would underflow f64",
            });
        }
        let al = self.angular_acceleration.abs();
        if al > 0.0 && !(al * w * size <= BIG && al * al * size <= BIG) {
            return Err(CamError::Invalid {
                field: Field::Cam(CamField::AngularAcceleration),
                value: self.alpha_given.0,
                reason: "is too large for this cam: its terms in the jerk would overflow f64",
            });
        }
        Ok(())
    }

    /// The cam body's state at cam angle `theta` (rad): angle `±θ`, angular velocity `±ω`.
    pub fn state(&self, theta: f64) -> BodyState {
        let s = self.direction.sign();
        BodyState::rotating(
            self.pivot,
            s * theta,
            s * self.speed,
            s * self.angular_acceleration,
        )
    }
}

/// A cam and its follower, validated, with the precomputed data the analysis needs: the cam,
/// the first-touch engine of its profile and follower, and a form-closed follower's second
/// curve.
#[derive(Debug, Clone)]
pub struct Mechanism {
    /// the first-touch engine: the profile's index, the follower's model, the options
    pub(crate) touch: first_touch::FirstTouch,
    /// a form-closed follower's second curve
    conjugate: Option<Arc<conjugate::Conjugate>>,
}
