//! Mechanisms as plain data: the mechanism-file schema, validated in one place.
//!
//! A [`MechanismSpec`] is what a mechanism file (TOML), a JSON document or a Python dict holds:
//! plain numbers and strings, with the derived `serde` traits behind the `serde` feature. All
//! validation happens in [`MechanismSpec::build`] (and `TryFrom<MechanismSpec> for Mechanism`):
//! kinds, fields that a kind needs or does not take, ranges, points files, the profile's geometry,
//! the follower's reach. Every error names the field by a [`Field`] and carries the value, so a
//! front end places it in its own form (a TOML key's line and column, a Python exception's
//! attributes).
//!
//! Units: lengths in the file's one unit (`length_unit`, which converts them to metres when
//! [`BuildOptions::si`] is set, as a simulation needs), angles in degrees, speeds in rpm.
//!
//! # Example
//!
//! ```
//! # #[cfg(feature = "serde")] {
//! use camkin::cam::Mechanism;
//! use camkin::spec::{Field, FollowerField, MechanismSpec, SpecError};
//!
//! let json = r#"{
//!     "length_unit": "mm",
//!     "cam": { "speed_rpm": 1000.0,
//!              "profile": { "kind": "circle", "center": [0.5, 0.0], "radius": 2.0 } },
//!     "follower": { "kind": "translating-roller", "roller_radius": 0.5 }
//! }"#;
//! let spec: MechanismSpec = serde_json::from_str(json)?;
//! let mech = Mechanism::try_from(spec.clone())?;
//! assert!((mech.analyze(0.0)?.position - 3.0).abs() < 1e-12); // 0.5 + 2 + 0.5
//!
//! let mut bad = spec;
//! bad.follower.roller_radius = Some(-1.0);
//! let err = Mechanism::try_from(bad).unwrap_err();
//! assert!(matches!(err, SpecError::Invalid { field: Field::Follower(FollowerField::RollerRadius), .. }));
//! assert_eq!(err.to_string(), "follower.roller_radius = -1: must be positive and finite");
//! # }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod build;
#[cfg(feature = "serde")]
mod pair;
mod profile;
#[cfg(feature = "text")]
pub mod text;

pub use crate::field::{
    CamField, DynamicsField, Field, FollowerField, Key, ProfileField, SegmentField,
};
pub use build::{BuildOptions, Built, LengthUnit, SpecError, SpecWarning};

use crate::cam::Sense;
use crate::curve::Parameterization;

/// A mechanism: the cam, the follower and, for simulations, the follower's dynamics.
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct MechanismSpec {
    /// the unit of every length: "mm", "cm", "m" or "in" (required: a missing unit is an error);
    /// converted to metres only for simulations ([`BuildOptions::si`])
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub length_unit: Option<String>,
    /// `[cam]`
    pub cam: CamSpec,
    /// `[follower]`
    pub follower: FollowerSpec,
    /// `[dynamics]`, SI units
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub dynamics: Option<DynamicsSpec>,
}

/// `[cam]`: the cam's motion and profile.
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct CamSpec {
    /// speed, revolutions per minute (> 0)
    pub speed_rpm: f64,
    /// direction of rotation (default counter-clockwise)
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub direction: Option<Sense>,
    /// the rotation axis, world (default the origin)
    #[cfg_attr(
        feature = "serde",
        serde(
            default,
            skip_serializing_if = "Option::is_none",
            deserialize_with = "pair::option"
        )
    )]
    pub pivot: Option<[f64; 2]>,
    /// constant angular acceleration, deg/s² (default 0)
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub angular_acceleration_deg_s2: Option<f64>,
    /// `[cam.profile]`
    pub profile: ProfileSpec,
}

/// `[cam.profile]`: every field of every kind; the kind decides which belong.
///
/// Kinds: `spline` (`points`, `parameterization`), `circle` (`center`, `radius`), `ellipse`
/// (`center`, `semi_axes`, `rotation_deg`), `points-file` (`path`, `parameterization`), `motion`
/// (`base_radius`, `segments`).
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
#[allow(missing_docs)]
pub struct ProfileSpec {
    pub kind: String,
    #[cfg_attr(
        feature = "serde",
        serde(
            default,
            skip_serializing_if = "Option::is_none",
            deserialize_with = "pair::option_list"
        )
    )]
    pub points: Option<Vec<[f64; 2]>>,
    /// where the nodes sit in the parameter: `uniform` by default for `spline` (the paper's),
    /// `chord-length` for `points-file`; uneven nodes under `uniform` draw a
    /// [`SpecWarning::UnevenNodes`]
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub parameterization: Option<Parameterization>,
    #[cfg_attr(
        feature = "serde",
        serde(
            default,
            skip_serializing_if = "Option::is_none",
            deserialize_with = "pair::option"
        )
    )]
    pub center: Option<[f64; 2]>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub radius: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(
            default,
            skip_serializing_if = "Option::is_none",
            deserialize_with = "pair::option"
        )
    )]
    pub semi_axes: Option<[f64; 2]>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub rotation_deg: Option<f64>,
    /// a points file, relative to [`BuildOptions::base_dir`]
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub path: Option<String>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub base_radius: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub segments: Option<Vec<SegmentSpec>>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub module: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub teeth: Option<u32>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub pressure_angle_deg: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub addendum: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub dedendum: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub profile_shift: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub backlash: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub fillet_radius: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub tip_relief: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub tip_relief_length: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub tip_relief_shape: Option<crate::curve::ReliefShape>,
    #[cfg_attr(
        feature = "serde",
        serde(
            default,
            skip_serializing_if = "Option::is_none",
            deserialize_with = "pair::option"
        )
    )]
    pub anchor: Option<[f64; 2]>,
    #[cfg_attr(
        feature = "serde",
        serde(
            default,
            skip_serializing_if = "Option::is_none",
            deserialize_with = "pair::option"
        )
    )]
    pub direction: Option<[f64; 2]>,
    #[cfg_attr(
        feature = "serde",
        serde(
            default,
            skip_serializing_if = "Option::is_none",
            deserialize_with = "pair::option"
        )
    )]
    pub at: Option<[f64; 2]>,
}

/// One segment of a `kind = "motion"` profile.
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct SegmentSpec {
    /// the law's name (`dwell`, `cycloidal`, `3-4-5`, …)
    pub law: String,
    /// the rise: a length (translating followers) or degrees of arm angle (oscillating)
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub rise: Option<f64>,
    /// the segment's extent, degrees of cam angle
    pub degrees: f64,
}

/// `[follower]`: every field of every kind; the kind decides which belong.
///
/// Kinds: `translating-flat` (`direction`), `translating-roller` (`direction`, `offset`,
/// `roller_radius`), `translating-knife` (`direction`, `offset`), `oscillating-flat` (`pivot`,
/// `offset`, `closing`, `initial_angle_deg`), `oscillating-roller` (`pivot`, `arm_length`,
/// `roller_radius`, `closing`, `initial_angle_deg`).
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
#[allow(missing_docs)]
pub struct FollowerSpec {
    pub kind: String,
    #[cfg_attr(
        feature = "serde",
        serde(
            default,
            skip_serializing_if = "Option::is_none",
            deserialize_with = "pair::option"
        )
    )]
    pub direction: Option<[f64; 2]>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub offset: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub roller_radius: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(
            default,
            skip_serializing_if = "Option::is_none",
            deserialize_with = "pair::option"
        )
    )]
    pub pivot: Option<[f64; 2]>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub arm_length: Option<f64>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub closing: Option<Sense>,
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub initial_angle_deg: Option<f64>,
    /// the curve a general follower (`translating`, `rotating`) carries, in its own frame
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub profile: Option<Box<ProfileSpec>>,
    /// a second curve on the follower, in the same frame, that touches the cam from the other
    /// side (a conjugate, form-closed follower: the second roller of a yoke or a bell crank);
    /// the first curve sets the position, this one's play is reported
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub conjugate: Option<Box<ProfileSpec>>,
}

/// `[dynamics]`: the follower's mass properties, spring and damper, SI units.
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct DynamicsSpec {
    /// kg, translating followers
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub mass: Option<f64>,
    /// kg·m² about the pivot, oscillating followers
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub inertia: Option<f64>,
    /// N/m (N·m/rad)
    pub spring_stiffness: f64,
    /// N (N·m) at the follower's lowest position
    pub spring_preload: f64,
    /// N·s/m (N·m·s/rad), default 0
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub damping: Option<f64>,
    /// of impacts, 0 to 1, default 0
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub restitution: Option<f64>,
    /// m/s², default none
    #[cfg_attr(
        feature = "serde",
        serde(
            default,
            skip_serializing_if = "Option::is_none",
            deserialize_with = "pair::option"
        )
    )]
    pub gravity: Option<[f64; 2]>,
}
