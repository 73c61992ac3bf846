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
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod arcs;
mod build;
mod built_system;
mod coil_spring;
mod gear_loads;
mod gear_pair;
mod kinds;
mod lash;
mod lift_table;
mod lubrication;
#[cfg(feature = "text")]
mod model_file;
mod pair;
mod profile;
mod run_plan;
mod system;
mod system_adjuster;
mod system_contact;
mod system_driver;
mod system_dynamics;
mod system_elements;
mod system_lubrication;
#[cfg(feature = "text")]
pub mod text;
mod warning;

pub use crate::field::{
    CamField, DynamicsField, Field, FollowerField, GearPairField, Key, ProfileField, SegmentField,
    SystemField, SystemKey, SystemTable,
};
pub use build::{BuildOptions, Built, LengthUnit, SpecError};
pub use built_system::{BuiltSystem, SweepAngle, SweepError};
pub use coil_spring::CoilSpringSpec;
pub use gear_loads::{
    torque_from_power, BuiltGearLoads, GearLoadsSpec, GivenLoads, LoadInput, LoadInputError,
    ResolvedLoads,
};
pub use gear_pair::{GearPairFile, GearPairSpec};
pub use kinds::{DriverCoordinate, FollowerKind, JointKindName, ProfileKind};
pub use lash::{LashCycle, LashError, Lashed};
pub use lubrication::{BuiltLubrication, FrictionSpec, LubricationSpec, DEFAULT_FRICTION};
#[cfg(feature = "text")]
pub use model_file::{read_model, ModelFile, Preset, Solver};
pub use run_plan::{
    PlanError, PlanField, RunPlan, RunSettings, TimedRun, MAX_DURATION, MAX_OUTPUTS,
    MAX_REVOLUTIONS, STEP_RANGE_DEG,
};
pub use system::{BodySpec, DriverSpec, JointSpec, SystemSpec};
pub use system_adjuster::LashAdjusterSpec;
pub use system_contact::ContactSpec;
pub use system_dynamics::{GasForceSpec, LoadSpec, SimulationSpec, SystemDynamicsSpec};
pub use system_elements::{DamperSpec, SpringSpec, TorsionSpringSpec};
pub use system_lubrication::SystemLubricationSpec;
pub use warning::SpecWarning;

use crate::cam::Sense;
use crate::curve::Parameterization;

/// A mechanism: the cam, the follower and, for simulations, the follower's dynamics. Two specs
/// are equal when they describe the same mechanism (whether it was read from a `[gear_pair]`
/// only changes how errors are named).
#[derive(Debug, Clone, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MechanismSpec {
    /// the unit of every length: "mm", "cm", "m" or "in" (required: a missing unit is an error);
    /// converted to metres only for simulations ([`BuildOptions::si`])
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub length_unit: Option<String>,
    /// `[cam]`
    pub cam: CamSpec,
    /// `[follower]`
    pub follower: FollowerSpec,
    /// `[dynamics]`, SI units
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dynamics: Option<DynamicsSpec>,
    /// `[lubrication]`: the force report's lubrication
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lubrication: Option<LubricationSpec>,
    /// `[gear_loads]`: a gear pair's torque and face width
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gear_loads: Option<GearLoadsSpec>,
    /// read from a `[gear_pair]` file ([`GearPairFile::to_mechanism`]): errors then name the
    /// `gear_pair` keys
    #[serde(skip)]
    pub from_gear_pair: bool,
}

impl PartialEq for MechanismSpec {
    fn eq(&self, other: &Self) -> bool {
        self.length_unit == other.length_unit
            && self.cam == other.cam
            && self.follower == other.follower
            && self.dynamics == other.dynamics
            && self.lubrication == other.lubrication
            && self.gear_loads == other.gear_loads
    }
}

impl MechanismSpec {
    /// The points files the spec reads (`kind = "points-file"`), as written: relative to
    /// [`BuildOptions::base_dir`] unless absolute.
    pub fn files(&self) -> Vec<&str> {
        let follower = [&self.follower.profile, &self.follower.conjugate];
        std::iter::once(&self.cam.profile)
            .chain(follower.into_iter().flatten().map(|b| b.as_ref()))
            .flat_map(ProfileSpec::files)
            .collect()
    }
}

impl ProfileSpec {
    /// The files it reads, as written: a points file's `path`, each lift table's `file`.
    pub fn files(&self) -> impl Iterator<Item = &str> {
        self.path.as_deref().into_iter().chain(
            self.segments
                .iter()
                .flatten()
                .filter_map(|s| s.file.as_deref()),
        )
    }
}

/// `[cam]`: the cam's motion and profile.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CamSpec {
    /// speed, revolutions per minute (> 0)
    pub speed_rpm: f64,
    /// direction of rotation (default counter-clockwise)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub direction: Option<Sense>,
    /// the rotation axis, world (default the origin)
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "pair::option"
    )]
    pub pivot: Option<[f64; 2]>,
    /// constant angular acceleration, deg/s² (default 0)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub angular_acceleration_deg_s2: Option<f64>,
    /// `[cam.profile]`
    pub profile: ProfileSpec,
}

/// Declares a table of the schema whose `kind` decides which keys belong: each optional key
/// written once, with the [`Field`] variant that names it in errors (`present` lists which are
/// given; [`ProfileKind::fields`] and [`FollowerKind::fields`] which each kind takes), then the
/// keys that every kind takes.
macro_rules! spec_table {
    (
        $(#[$sm:meta])*
        pub struct $name:ident by $fe:ident {
            $(#[$km:meta])*
            pub kind: String,
            $( $(#[$m:meta])* $f:ident: $t:ty => $v:ident, )*
            $( ; every kind $( $(#[$am:meta])* $af:ident: $at:ty, )* )?
        }
    ) => {
        $(#[$sm])*
        #[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
        #[serde(deny_unknown_fields)]
        pub struct $name {
            $(#[$km])*
            pub kind: String,
            $(
                $(#[$m])*
                #[serde(default, skip_serializing_if = "Option::is_none")]
                pub $f: Option<$t>,
            )*
            $($(
                $(#[$am])*
                #[serde(default, skip_serializing_if = "Option::is_none")]
                pub $af: Option<$at>,
            )*)?
        }
        impl $name {
            /// Each optional key by its field, and whether it is given.
            pub(crate) fn present(&self) -> Vec<($fe, bool)> {
                vec![$(($fe::$v, self.$f.is_some())),*]
            }
        }
    };
}

spec_table! {
    /// `[cam.profile]` (and a follower's `profile` or `conjugate`): every key of every kind; the
    /// kind ([`ProfileKind`], by its name) decides which belong.
    pub struct ProfileSpec by ProfileField {
        /// the kind's name: `spline`, `circle`, `ellipse`, `points-file`, `motion`,
        /// `tangent-cam`, `circular-arc-cam`, `involute-gear`, or a follower's `line` or `point`
        pub kind: String,
        /// `spline`: the nodes, cam frame
        #[serde(deserialize_with = "pair::option_list")]
        points: Vec<[f64; 2]> => Points,
        /// where the nodes sit in the parameter: `uniform` by default for `spline` (the paper's),
        /// `chord-length` for `points-file`; uneven nodes under `uniform` draw a
        /// [`SpecWarning::UnevenNodes`]
        parameterization: Parameterization => Parameterization,
        /// `circle`, `ellipse`: the centre
        #[serde(deserialize_with = "pair::option")]
        center: [f64; 2] => Center,
        /// `circle`: the radius
        radius: f64 => Radius,
        /// `ellipse`: the semi-axes along its own x and y
        #[serde(deserialize_with = "pair::option")]
        semi_axes: [f64; 2] => SemiAxes,
        /// `ellipse`: its turn, degrees counter-clockwise (default 0)
        rotation_deg: f64 => RotationDeg,
        /// `points-file`: a points file, relative to [`BuildOptions::base_dir`]
        path: String => Path,
        /// `motion`, `tangent-cam`, `circular-arc-cam`: the base circle's radius
        base_radius: f64 => BaseRadius,
        /// `motion`: the program's segments
        segments: Vec<SegmentSpec> => Segments,
        /// `tangent-cam`, `circular-arc-cam`: the nose circle's radius
        nose_radius: f64 => NoseRadius,
        /// `tangent-cam`, `circular-arc-cam`: the lift, the nose's farthest point less the base
        /// radius
        lift: f64 => Lift,
        /// `circular-arc-cam`: the flanks' radius
        flank_radius: f64 => FlankRadius,
        /// `arcs-and-lines`: where the chain starts
        #[serde(deserialize_with = "pair::option")]
        start: [f64; 2] => Start,
        /// `arcs-and-lines`: the chain, counter-clockwise round the cam
        pieces: Vec<PieceSpec> => Pieces,
        /// `involute-gear`: the module
        module: f64 => Module,
        /// `involute-gear`: the number of teeth
        teeth: u32 => Teeth,
        /// `involute-gear`: the pressure angle, degrees
        pressure_angle_deg: f64 => PressureAngle,
        /// `involute-gear`: the addendum coefficient (default 1)
        addendum: f64 => Addendum,
        /// `involute-gear`: the dedendum coefficient (default 1.25)
        dedendum: f64 => Dedendum,
        /// `involute-gear`: the profile shift coefficient (default 0)
        profile_shift: f64 => ProfileShift,
        /// `involute-gear`: the backlash, a length along the pitch circle (default 0)
        backlash: f64 => Backlash,
        /// `involute-gear`: the root fillet's radius (default the rack's)
        fillet_radius: f64 => FilletRadius,
        /// `involute-gear`: tip relief, the amount at the tip
        tip_relief: f64 => TipRelief,
        /// `involute-gear`: tip relief, its length along the line of action
        tip_relief_length: f64 => TipReliefLength,
        /// `involute-gear`: tip relief, its shape (default linear)
        tip_relief_shape: crate::curve::ReliefShape => TipReliefShape,
        /// `line`: a point on it (default the origin)
        #[serde(deserialize_with = "pair::option")]
        anchor: [f64; 2] => Anchor,
        /// `line`: its direction, the follower's material on its left
        #[serde(deserialize_with = "pair::option")]
        direction: [f64; 2] => Direction,
        /// `point`: where it is (default the origin)
        #[serde(deserialize_with = "pair::option")]
        at: [f64; 2] => At,
    }
}

/// One piece of a `kind = "arcs-and-lines"` profile: a line to `to`, or with `centre` an arc
/// about it to `to` (counter-clockwise unless `clockwise`), from where the piece before ends.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PieceSpec {
    /// where the piece ends
    #[serde(deserialize_with = "pair::exact")]
    pub to: [f64; 2],
    /// an arc's centre
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "pair::option"
    )]
    pub centre: Option<[f64; 2]>,
    /// an arc turning clockwise (concave on a counter-clockwise profile); default false
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub clockwise: Option<bool>,
}

/// One segment of a `kind = "motion"` profile.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SegmentSpec {
    /// the law's name (`dwell`, `cycloidal`, `3-4-5`, …)
    pub law: String,
    /// the rise: a length (translating followers) or degrees of arm angle (oscillating)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rise: Option<f64>,
    /// the segment's extent, degrees of cam angle (every law but a table's)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub degrees: Option<f64>,
    /// `table`: a file of `angle_deg, lift` rows, relative to [`BuildOptions::base_dir`]
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    /// `table`: the step of inline lifts, degrees
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub step_deg: Option<f64>,
    /// `table`: the lifts inline, every `step_deg` from the segment's start
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lift: Option<Vec<f64>>,
}

spec_table! {
    /// `[follower]`: every key of every kind; the kind ([`FollowerKind`], by its name) decides
    /// which belong.
    pub struct FollowerSpec by FollowerField {
        /// the kind's name: `translating`, `rotating` (carrying `profile`), or one of the named
        /// kinds `translating-flat`, `translating-roller`, `translating-knife`,
        /// `oscillating-flat`, `oscillating-roller`
        pub kind: String,
        /// a slide's direction of travel (default the x axis)
        #[serde(deserialize_with = "pair::option")]
        direction: [f64; 2] => Direction,
        /// a slide's offset from the cam axis, or a flat arm's face offset from its pivot
        offset: f64 => Offset,
        /// a roller's radius
        roller_radius: f64 => RollerRadius,
        /// an arm's pivot, world
        #[serde(deserialize_with = "pair::option")]
        pivot: [f64; 2] => Pivot,
        /// an arm's length to the roller's centre
        arm_length: f64 => ArmLength,
        /// the sense in which the load turns an arm onto the cam (default clockwise)
        closing: Sense => Closing,
        /// the arm angle is reported within ±180° of it, degrees (default 0)
        initial_angle_deg: f64 => InitialAngle,
        /// the curve a general follower (`translating`, `rotating`) carries, in its own frame
        profile: Box<ProfileSpec> => Profile,
        ; every kind
        /// a second curve on the follower, in the same frame, that touches the cam from the other
        /// side (a conjugate, form-closed follower: the second roller of a yoke or a bell crank);
        /// the first curve sets the position, this one's play is reported
        conjugate: Box<ProfileSpec>,
    }
}

/// `[dynamics]`: the follower's mass properties, spring and damper, SI units.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DynamicsSpec {
    /// kg, translating followers
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass: Option<f64>,
    /// kg·m² about the pivot, oscillating followers
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inertia: Option<f64>,
    /// N/m (N·m/rad); default 0: no spring (`camkin forces` sizes one from the motion)
    #[serde(default)]
    pub spring_stiffness: f64,
    /// N (N·m) at the follower's lowest position; default 0
    #[serde(default)]
    pub spring_preload: f64,
    /// N·s/m (N·m·s/rad), default 0
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping: Option<f64>,
    /// of impacts, 0 to 1, default 0
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub restitution: Option<f64>,
    /// m/s², default none
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "pair::option"
    )]
    pub gravity: Option<[f64; 2]>,
}
