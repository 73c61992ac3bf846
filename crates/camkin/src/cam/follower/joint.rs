//! The joint that carries a follower: a slide along a direction or a revolute pair at a pivot.
//! Everything that depends only on how the follower moves (its pose, its velocity at a point, the
//! coordinate's row in the contact constraint, the dynamics' joint and spring) lives here, once
//! for every follower kind.

use super::Sense;
use crate::body::{BodyState, Pose};
use crate::geometry::{rot90, Point2, UnitVec2, Vec2};

/// How a follower moves: one coordinate `q`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum FollowerJoint {
    /// A slide: the follower frame's origin is at `origin + q·direction`, its angle 0; `q` is a
    /// length measured from the cam axis along `direction`.
    Translating {
        /// the frame's origin at `q = 0` (world): the cam axis moved by the offset `e·rot90(d)`
        origin: Point2,
        /// direction of travel `d`, from the cam towards the follower
        direction: UnitVec2,
    },
    /// A revolute pair: the follower frame's origin is the pivot, its angle the arm angle `q`
    /// (rad, counter-clockwise from the world x axis).
    Rotating {
        /// the arm pivot `O` (world)
        pivot: Point2,
        /// the sense in which the spring turns the arm onto the cam
        closing: Sense,
        /// the arm angle is reported within ±180° of this angle, rad
        initial_angle: f64,
        /// the direction from the pivot to the cam's axis, rad (for a carried point, less the
        /// point's polar angle in the arm's frame: the arm angle that points the point at the
        /// cam's axis): the first touch is found among arm angles within ±180° of it, so that
        /// the branch cut lies where the arm points away from the cam and cannot touch it
        toward_cam: f64,
    },
}

impl FollowerJoint {
    /// A slide along `direction` whose frame is at `origin` at `q = 0`.
    pub fn slide(origin: Point2, direction: UnitVec2) -> Self {
        FollowerJoint::Translating { origin, direction }
    }

    /// A revolute pair at `pivot` closed by its spring in the sense `closing`, the arm angle
    /// reported within ±180° of `initial_angle`, its first touch sought within ±180° of
    /// `toward_cam` (see [`FollowerJoint::Rotating`]).
    pub fn arm(pivot: Point2, closing: Sense, initial_angle: f64, toward_cam: f64) -> Self {
        FollowerJoint::Rotating {
            pivot,
            closing,
            initial_angle,
            toward_cam,
        }
    }

    /// The point the joint acts from: a slide's origin (at `q = 0`), an arm's pivot.
    #[inline]
    pub fn origin(&self) -> Point2 {
        match *self {
            FollowerJoint::Translating { origin, .. } => origin,
            FollowerJoint::Rotating { pivot, .. } => pivot,
        }
    }

    /// A slide's direction of travel; `None` for an arm.
    #[inline]
    pub fn direction(&self) -> Option<UnitVec2> {
        match *self {
            FollowerJoint::Translating { direction, .. } => Some(direction),
            FollowerJoint::Rotating { .. } => None,
        }
    }

    /// An arm's initial angle (the reported angle lies within ±180° of it); `None` for a slide.
    #[inline]
    pub fn initial_angle(&self) -> Option<f64> {
        match *self {
            FollowerJoint::Translating { .. } => None,
            FollowerJoint::Rotating { initial_angle, .. } => Some(initial_angle),
        }
    }

    /// The sign of `q` that moves the follower onto the cam: −1 for a slide (decreasing `q`),
    /// an arm's closing sense (+1 counter-clockwise).
    #[inline]
    pub fn closing_sign(&self) -> f64 {
        -self.away()
    }

    /// The difference `a − b` of two coordinates: an arm's taken within ±180°.
    #[inline]
    pub(crate) fn difference(&self, a: f64, b: f64) -> f64 {
        match *self {
            FollowerJoint::Translating { .. } => a - b,
            FollowerJoint::Rotating { .. } => crate::geometry::wrap_angle_near(a - b, 0.0),
        }
    }

    /// Where a point `y` of the follower frame (relative to [`FollowerJoint::origin`] in a frame not
    /// turned) lies along the joint's track: its distance along the slide's direction, or its
    /// polar angle about the pivot. As the follower moves by `Δq`, a point fixed elsewhere moves
    /// along the track by `−Δq`, at its [`FollowerJoint::level`].
    #[inline]
    pub(crate) fn along(&self, y: Vec2) -> f64 {
        match *self {
            FollowerJoint::Translating { direction, .. } => y.dot(&direction),
            FollowerJoint::Rotating { .. } => y.y.atan2(y.x),
        }
    }

    /// The level of `y` on the track (see [`FollowerJoint::along`]): its distance across the slide's
    /// direction, or its radius about the pivot.
    #[inline]
    pub(crate) fn level(&self, y: Vec2) -> f64 {
        match *self {
            FollowerJoint::Translating { direction, .. } => y.dot(&rot90(*direction)),
            FollowerJoint::Rotating { .. } => y.norm(),
        }
    }

    /// The length of a unit of [`FollowerJoint::along`] at `level`: 1 on a slide, the radius on an arm.
    #[inline]
    pub(crate) fn along_length(&self, level: f64) -> f64 {
        match *self {
            FollowerJoint::Translating { .. } => 1.0,
            FollowerJoint::Rotating { .. } => level,
        }
    }

    /// The rate of [`FollowerJoint::velocity_jacobian`] at a point of the follower's curve along the
    /// curve, per unit of its parameter, where the curve's derivative (world) is `t`: zero on a
    /// slide, `k × t` on an arm.
    #[inline]
    pub(crate) fn velocity_jacobian_along(&self, t: Vec2) -> Vec2 {
        match *self {
            FollowerJoint::Translating { .. } => Vec2::zeros(),
            FollowerJoint::Rotating { .. } => rot90(t),
        }
    }

    /// The follower frame at position `q`.
    #[inline]
    pub fn pose(&self, q: f64) -> Pose {
        match *self {
            FollowerJoint::Translating { origin, direction } => {
                Pose::new(origin + q * *direction, 0.0)
            }
            FollowerJoint::Rotating { pivot, .. } => Pose::new(pivot, q),
        }
    }

    /// The follower body's state at position `q`, rate `q̇` and acceleration `q̈`.
    #[inline]
    pub fn body(&self, q: f64, qd: f64, qdd: f64) -> BodyState {
        let pose = self.pose(q);
        match *self {
            FollowerJoint::Translating { direction, .. } => BodyState {
                pose,
                velocity: qd * *direction,
                omega: 0.0,
                acceleration: qdd * *direction,
                alpha: 0.0,
            },
            FollowerJoint::Rotating { .. } => BodyState {
                pose,
                velocity: Vec2::zeros(),
                omega: qd,
                acceleration: Vec2::zeros(),
                alpha: qdd,
            },
        }
    }

    /// This joint as a system's joint between the ground and the follower's body `follower`
    /// (whose frame is the follower frame): a slide along the direction, or a pin at the pivot.
    pub fn system_joint(&self, follower: crate::system::BodyId) -> crate::system::JointKind {
        use crate::system::{BodyId, JointKind};
        match *self {
            FollowerJoint::Translating { origin, direction } => JointKind::Prismatic {
                a: BodyId::GROUND,
                at_a: origin,
                axis: *direction,
                b: follower,
                at_b: Point2::origin(),
                angle: 0.0,
            },
            FollowerJoint::Rotating { pivot, .. } => JointKind::Revolute {
                a: BodyId::GROUND,
                at_a: pivot,
                b: follower,
                at_b: Point2::origin(),
            },
        }
    }

    /// The coordinate `(q, q̇, q̈)` of a follower body's state (the inverse of
    /// [`FollowerJoint::body`]): a slide's travel along its direction from its origin, or an arm's
    /// angle within ±180° of the initial angle.
    pub fn coordinate_of(&self, b: &BodyState) -> [f64; 3] {
        match *self {
            FollowerJoint::Translating { origin, direction } => [
                (b.pose.origin - origin).dot(&direction),
                b.velocity.dot(&direction),
                b.acceleration.dot(&direction),
            ],
            FollowerJoint::Rotating { initial_angle, .. } => {
                let tau = std::f64::consts::TAU;
                let d = (b.pose.angle - initial_angle).rem_euclid(tau);
                let d = if d > std::f64::consts::PI { d - tau } else { d };
                [initial_angle + d, b.omega, b.alpha]
            }
        }
    }

    /// `∂v_B^P/∂q̇` at world point `c`: the velocity of the follower's material point under `c`
    /// per unit rate of the coordinate.
    #[inline]
    pub fn velocity_jacobian(&self, c: Point2) -> Vec2 {
        match *self {
            FollowerJoint::Translating { direction, .. } => *direction,
            FollowerJoint::Rotating { pivot, .. } => rot90(c - pivot),
        }
    }

    /// The coefficient of `q̈` in a contact row `Φ_q = [.., .., .., x_B, y_B, θ_B]` (eq. 11).
    #[inline]
    pub(crate) fn coordinate_coefficient(&self, phi: &[f64; 6]) -> f64 {
        match *self {
            FollowerJoint::Translating { direction: d, .. } => phi[3] * d.x + phi[4] * d.y,
            FollowerJoint::Rotating { .. } => phi[5],
        }
    }

    /// Converts a change of `q` into a length, for tolerances (`size`: the cam's reach from its
    /// axis at `cam_pivot`).
    #[inline]
    pub(crate) fn q_length_scale(&self, size: f64, cam_pivot: Point2) -> f64 {
        match *self {
            FollowerJoint::Translating { .. } => 1.0,
            FollowerJoint::Rotating { pivot, .. } => size + (pivot - cam_pivot).norm(),
        }
    }

    /// `q` oriented so that larger is "touches earlier" (the first touch is the largest).
    #[inline]
    pub(crate) fn oriented(&self, q: f64) -> f64 {
        match *self {
            FollowerJoint::Translating { .. } => q,
            FollowerJoint::Rotating {
                closing,
                toward_cam,
                ..
            } => -closing.sign() * crate::geometry::wrap_angle_near(q, toward_cam),
        }
    }

    /// `(oriented score, reported q)` of a position `q` found as an angle anywhere (a rotating
    /// joint's: the score on the branch about the cam, the angle within ±180° of the initial
    /// angle); `(q, q)` for a slide.
    #[inline]
    pub(crate) fn branch(&self, q: f64) -> (f64, f64) {
        match *self {
            FollowerJoint::Translating { .. } => (q, q),
            FollowerJoint::Rotating { initial_angle, .. } => (
                self.oriented(q),
                crate::geometry::wrap_angle_near(q, initial_angle),
            ),
        }
    }

    /// An upper bound of the oriented score ([`FollowerJoint::oriented`]) of every position within the
    /// interval `(mid, half width)`; +∞ when the interval may cross a rotating joint's branch cut.
    #[inline]
    pub(crate) fn oriented_bound(&self, (mid, half): (f64, f64)) -> f64 {
        match *self {
            FollowerJoint::Translating { .. } => mid + half,
            FollowerJoint::Rotating {
                closing,
                toward_cam,
                ..
            } => {
                let w = crate::geometry::wrap_angle_near(mid, toward_cam);
                if (w - toward_cam).abs() + half >= std::f64::consts::PI {
                    f64::INFINITY
                } else {
                    -closing.sign() * w + half
                }
            }
        }
    }

    /// +1 when `q` is a length (translating), the closing sign's opposite otherwise: the sign
    /// of `q` that moves the follower away from the cam.
    #[inline]
    pub fn away(&self) -> f64 {
        match *self {
            FollowerJoint::Translating { .. } => 1.0,
            FollowerJoint::Rotating { closing, .. } => -closing.sign(),
        }
    }

    /// True for a revolute joint (`q` in rad).
    pub fn is_rotating(&self) -> bool {
        matches!(self, FollowerJoint::Rotating { .. })
    }
}
