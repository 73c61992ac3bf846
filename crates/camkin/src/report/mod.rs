//! Reports an engineer reads, computed once for every front end: each a `Serialize` type (with
//! the `serde` feature) that the command prints and writes, the Python package returns and the
//! studio draws. The front ends only word them.
//!
//! - [`ForceReport`]: forces, torque, jump speed, spring sizing and Hertz stress over a
//!   revolution under permanent contact (`camkin forces`, `Mechanism.forces()` in Python).
//! - [`DesignReport`]: each design check of a revolution with its verdict and its words
//!   (`camkin synth`'s `checks.txt`, the studio's checks, `Mechanism.checks()` in Python).
//! - [`SystemForces`]: a simulated system's contact forces, Hertz pressures, drivers' efforts
//!   (a camshaft's torque) and impacts (`camkin forces SYSTEM.toml`).
//! - [`ShopReport`]: a cam's manufacturing output: polar table, pitch and cutter paths, the
//!   cutter's undercut check and a DXF of arcs (`camkin profile`, `Mechanism.shop()`).
//! - [`DeviationReport`]: a measured profile against the design, in radius and in the
//!   follower's motion (`camkin deviation`, `Mechanism.deviation()`).
//! - [`Materials`]: elastic constants for the Hertz stress, presets and `E=…:nu=…`, checked for
//!   plausibility.

mod design;
mod deviation;
pub mod dxf;
mod forces;
mod gear_loads;
mod lubrication;
mod materials;
pub mod shop;
mod spring;
mod system_forces;
mod system_lubrication;

pub use design::{split_jumps, Check, DesignReport, Verdict};
pub use deviation::{DeviationError, DeviationReport, MotionDeviation, RadiusDeviation};
pub use forces::{
    check_limits, plausible_face_width, rpm, ForceCheck, ForceReport, ForceRequest, FormClosed,
    HertzReport, HertzSide, Jump,
};
pub use gear_loads::{GearLoadError, GearLoadRequest, GearLoads, PathPoint};
pub use lubrication::{LubricationPoint, LubricationReport, LubricationRequest};
pub use materials::{Material, MaterialError, Materials, MODULUS_RANGE_PA, POISSON_RANGE, PRESETS};
pub use shop::{
    CutterCheck, OffsetPath, PolarTable, ShopError, ShopField, ShopReport, ShopRequest,
};
pub use spring::{SpringDesign, SpringSizing};
pub use system_forces::{
    AtAngle, ContactForces, DriverEffort, Impact, SystemForceFailure, SystemForces,
};
pub use system_lubrication::{
    ContactLubrication, ContactLubricationReport, SystemLubricationReport, SystemLubricationRequest,
};

use crate::cam::CamError;
use crate::dynamics::DynamicsError;
use std::fmt;

/// A value of a report and the cam angle where it is.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Extreme {
    /// the value (in the report's unit for it)
    pub value: f64,
    /// the cam angle, rad
    pub cam_angle: f64,
}

/// The inputs of a force report, named by enum: each front end words them its own way (the
/// command's `--face-width`, Python's `face_width`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ForceField {
    /// the cam-angle step
    Step,
    /// the contact force that must remain
    Margin,
    /// the speed up to which the follower must stay on
    TargetRpm,
    /// the face width of the contact
    FaceWidth,
    /// the materials
    Materials,
    /// the allowable contact stress
    Allowable,
    /// the lubricant's viscosity
    Viscosity,
    /// the lubricant's pressure–viscosity coefficient
    PressureViscosity,
    /// a surface's roughness
    Roughness,
    /// a body's thermal properties (conductivity, density, specific heat)
    Thermal,
    /// the friction coefficients
    Friction,
}

impl ForceField {
    /// Every field, for front ends that map them all.
    pub const ALL: [ForceField; 11] = [
        ForceField::Step,
        ForceField::Margin,
        ForceField::TargetRpm,
        ForceField::FaceWidth,
        ForceField::Materials,
        ForceField::Allowable,
        ForceField::Viscosity,
        ForceField::PressureViscosity,
        ForceField::Roughness,
        ForceField::Thermal,
        ForceField::Friction,
    ];
}

/// Why a report could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ReportError {
    /// An input is out of its range: `value` as given, in `unit`.
    #[error("{} {unit} {reason}", crate::human::human(*.value))]
    Invalid {
        /// the input
        field: ForceField,
        /// its value
        value: f64,
        /// its unit
        unit: &'static str,
        /// what it must be
        reason: &'static str,
    },
    /// An input that does not apply to this mechanism.
    #[error("{reason}")]
    NotApplicable {
        /// the input
        field: ForceField,
        /// why
        reason: &'static str,
    },
    /// The dynamics' parameters do not fit the mechanism.
    #[error("{0}")]
    Dynamics(DynamicsError),
    /// The kinematics failed at an angle.
    #[error("the forces cannot be computed: {0}")]
    Kinematics(CamError),
    /// The second curve's play failed at an angle.
    #[error("the second curve's play cannot be computed: {0}")]
    Play(CamError),
}

impl ReportError {
    /// The input the error is about, when it is about one.
    pub fn field(&self) -> Option<ForceField> {
        match self {
            ReportError::Invalid { field, .. } | ReportError::NotApplicable { field, .. } => {
                Some(*field)
            }
            _ => None,
        }
    }
}

impl fmt::Display for ForceField {
    /// The field's name in the library's words (front ends use their own: a flag, a keyword).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ForceField::Step => "step",
            ForceField::Margin => "margin",
            ForceField::TargetRpm => "target speed",
            ForceField::FaceWidth => "face width",
            ForceField::Materials => "materials",
            ForceField::Allowable => "allowable stress",
            ForceField::Viscosity => "viscosity",
            ForceField::PressureViscosity => "pressure-viscosity coefficient",
            ForceField::Roughness => "roughness",
            ForceField::Thermal => "thermal properties",
            ForceField::Friction => "friction coefficient",
        })
    }
}
