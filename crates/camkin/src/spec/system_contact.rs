//! `[[contact]]` of a system file: two bodies' curves that touch, and what its dynamics and
//! lubrication need (restitution, face width, materials, roughness, a rolling roller).

use super::ProfileSpec;

/// `[[contact]]`.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ContactSpec {
    /// its name
    pub name: String,
    /// the bodies carrying curve A and curve B
    #[serde(deserialize_with = "super::pair::names")]
    pub bodies: [String; 2],
    /// curve A in the first body's frame (any curve a follower may carry: spline, circle,
    /// ellipse, points-file, involute-gear, line, point), material on its left
    pub curve_a: ProfileSpec,
    /// curve B in the second body's frame
    pub curve_b: ProfileSpec,
    /// for a `kind = "motion"` curve: the follower its program is written for, as a
    /// mechanism file's `[follower]`, in that curve's body's frame (whose origin is the cam's
    /// axis)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub motion_follower: Option<super::FollowerSpec>,
    /// for a `kind = "motion"` curve: the sense the cam turns in for its program (`ccw` by
    /// default)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub motion_direction: Option<crate::cam::Sense>,
    /// Newton's coefficient of restitution of its impacts, 0 to 1 (for dynamics; default the
    /// `[dynamics]` table's)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub restitution: Option<f64>,
    /// its line contact's face width, length unit: with it the simulation gives its Hertz
    /// pressure (for dynamics)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub face_width: Option<f64>,
    /// its curves' materials, `A,B` (presets or `E=<Pa>:nu=<ratio>`; default `steel,steel`)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub materials: Option<String>,
    /// its curves' RMS roughness, µm (with `[lubrication]`; default that table's)
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "super::pair::option"
    )]
    pub roughness_um: Option<[f64; 2]>,
    /// `"a"` or `"b"`: that curve, a circle, is a roller turning freely on its pin, rolling on
    /// the other without slip (its lubrication; without it a circle slides with its body)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rolls: Option<String>,
    /// `true`: it starts closed whatever its gap at the starting poses, which are assembled onto
    /// it (the distance moved reported); `false`: it starts apart whatever its gap (a lash);
    /// without it a contact starts closed only where its curves are within 1e-3 of the
    /// system's size (for dynamics)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub starts_closed: Option<bool>,
    /// its lash (a valve clearance), the file's length unit: its follower's face (`curve_b`, or
    /// `curve_a` when `curve_b` is the motion cam; a `line` or a `circle`) moved that far into
    /// its material from where the file draws it touching the cam's base circle; it starts
    /// apart (for dynamics; see [`super::BuiltSystem::with_lash`])
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lash: Option<f64>,
}
