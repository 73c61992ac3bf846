//! The analysis state: what the contact method reports at one cam angle.

use super::Found;
use crate::contact::NormalAcceleration;
use crate::geometry::{cross, Point2, UnitVec2, Vec2};

/// The follower's motion and the contact at one cam angle.
///
/// Position, velocity, acceleration and jerk are of the follower's coordinate: translating
/// followers in length, length/s, length/s², length/s³ (measured from the cam axis along `d`);
/// oscillating followers in rad, rad/s, rad/s², rad/s³ (absolute arm angle).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FollowerState {
    /// cam angle `θ`, rad
    pub cam_angle: f64,
    /// position `q`
    pub position: f64,
    /// velocity `q̇`
    pub velocity: f64,
    /// acceleration `q̈` by the contact method (eq. 11)
    pub acceleration: f64,
    /// jerk `d³q/dt³ = θ̇³ q‴ + 3 θ̇ θ̈ q″` (derivatives in θ by implicit differentiation, see
    /// [`Mechanism::angle_derivatives`](super::Mechanism::angle_derivatives)); `None` when the contact sits on a node of a spline
    /// profile, where the curvature has a corner and the jerk jumps, or when
    /// [`AnalysisOptions::jerk`](super::AnalysisOptions::jerk) is off
    pub jerk: Option<f64>,
    /// contact point, world frame
    pub contact_world: Point2,
    /// contact point, cam frame
    pub contact_cam: Point2,
    /// the cam-profile parameter at the contact, in `[0, period)`
    pub cam_param: f64,
    /// `u̇_A = ṡ_A/g_A`: rate of the cam parameter at the contact, relative to the cam, 1/s
    /// (eq. 7)
    pub cam_param_rate: f64,
    /// the follower-curve parameter at the contact (line: arc length; roller: angle in the
    /// follower frame; knife: 0)
    pub follower_param: f64,
    /// `ṡ_A`: sliding rate of the contact point along the cam profile, relative to the cam,
    /// length/s (eq. 5)
    pub sliding_rate_cam: f64,
    /// `ṡ_B`: sliding rate along the follower's curve, relative to the follower, length/s (eq. 6)
    pub sliding_rate_follower: f64,
    /// normal acceleration of the contact point seen from the cam (eq. 1), along `normal`
    pub normal_acceleration_cam: NormalAcceleration,
    /// normal acceleration seen from the follower (eq. 2), along `normal`
    pub normal_acceleration_follower: NormalAcceleration,
    /// the common normal `ν_A` (cam profile's left normal), world frame
    pub normal: UnitVec2,
    /// `σ`
    pub sigma: f64,
    /// direction of motion of the follower's material point under the contact per unit rate of
    /// its coordinate (`∂v_B^P/∂q̇`: `d` for translating followers, `k × (c − O)` for
    /// oscillating ones), world frame: what the contact force does work along
    pub follower_motion: Vec2,
    /// direction of motion of the follower's reference point per unit rate of its coordinate,
    /// world (`d` for translating followers, `k × (R − O)` for oscillating ones): the reference
    /// point is a roller's centre (the follower's curve is a circle, named or carried: it turns
    /// on its pin, and the force passes through it), else the contact point (a knife's tip, a
    /// flat or curved face, a gear's flank); see [`FollowerState::pressure_angle`]
    pub reference_motion: Vec2,
    /// radius of curvature of the cam profile at the contact, positive where convex (∞ on a
    /// straight stretch), length
    pub radius_of_curvature: f64,
    /// the contact sits on a node of the profile (its curvature has a corner there: the jerk
    /// jumps)
    pub at_breakpoint: bool,
    /// the contact is at a corner of one curve (where its tangent turns: a gear's tip, where a
    /// linear tip relief starts), not a tangency: that curve is a point there (its curvature
    /// infinite, its sliding rate zero) and the normal is the other curve's
    pub corner: Option<Corner>,
    /// how the contact was found
    pub found: Found,
}

/// Which curve has a corner at a contact ([`FollowerState::corner`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Corner {
    /// a corner of the cam's profile touches the follower's curve
    Cam,
    /// a corner of the follower's curve touches the cam's profile
    Follower,
}

impl Corner {
    /// `cam` or `follower`.
    pub fn name(self) -> &'static str {
        match self {
            Corner::Cam => "cam",
            Corner::Follower => "follower",
        }
    }
}

/// The follower's motion at one cam angle: position, velocity and acceleration with nothing
/// else computed (the fast path for sweeps and dynamics; see [`crate::cam::Mechanism::motion`]).
/// Units as in [`FollowerState`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// cam angle `θ`, rad
    pub cam_angle: f64,
    /// position `q`
    pub position: f64,
    /// velocity `q̇`
    pub velocity: f64,
    /// acceleration `q̈`
    pub acceleration: f64,
    /// the cam-profile parameter at the contact
    pub cam_param: f64,
    /// its rate `u̇_A` relative to the cam, 1/s
    pub cam_param_rate: f64,
    /// how the contact was found
    pub found: Found,
}

/// The angle from the direction of motion `jb` of the follower's point to the contact normal
/// `nu` oriented towards the follower, rad, counter-clockwise positive.
pub(super) fn pressure_angle(jb: Vec2, nu: Vec2) -> f64 {
    let npush = if nu.dot(&jb) >= 0.0 { nu } else { -nu };
    cross(jb, npush).atan2(jb.dot(&npush))
}

impl FollowerState {
    /// The motion part of the state (what [`crate::cam::Mechanism::motion`] returns).
    #[inline]
    pub fn motion(&self) -> Motion {
        Motion {
            cam_angle: self.cam_angle,
            position: self.position,
            velocity: self.velocity,
            acceleration: self.acceleration,
            cam_param: self.cam_param,
            cam_param_rate: self.cam_param_rate,
            found: self.found,
        }
    }

    /// Pressure angle, the textbook's: from the direction of motion of the follower's
    /// reference point ([`FollowerState::reference_motion`]: a roller's centre, else the contact
    /// point — a knife's tip, a face, a gear's flank, where it is the involute's profile angle
    /// `cos α = r_b/r`) to the line of the contact force (the common normal, which passes
    /// through a roller's centre), oriented along the motion; rad, counter-clockwise positive.
    /// For a translating follower every point moves along `d`, so the reference does not
    /// matter; on an arm the roller's centre and the contact point move in different directions
    /// (Norton, *Cam Design and Manufacturing Handbook*, ch. 7; Rothbart, *Cam Design
    /// Handbook*, ch. 5).
    pub fn pressure_angle(&self) -> f64 {
        pressure_angle(self.reference_motion, *self.normal)
    }
}
