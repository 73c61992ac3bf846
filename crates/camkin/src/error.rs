//! One error type for everything the library can refuse or fail at: each area's own error
//! converts into it, so code that calls several areas can use `?` throughout.

use crate::cam::CamError;
use crate::contact::ContactError;
use crate::curve::CurveError;
use crate::dynamics::DynamicsError;
use crate::gears::GearError;
use crate::motion::MotionError;
use crate::spec::SpecError;

/// Any error of the library, by area.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// building a curve
    #[error(transparent)]
    Curve(#[from] CurveError),
    /// finding a contact or its kinematics
    #[error(transparent)]
    Contact(#[from] ContactError),
    /// building or analysing a cam mechanism
    #[error(transparent)]
    Cam(#[from] CamError),
    /// a motion program
    #[error(transparent)]
    Motion(#[from] MotionError),
    /// a dynamic simulation
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
    /// a gear pair
    #[error(transparent)]
    Gear(#[from] GearError),
    /// a mechanism specification
    #[error(transparent)]
    Spec(#[from] SpecError),
}
