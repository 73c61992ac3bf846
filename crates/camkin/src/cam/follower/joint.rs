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
pub enum Joint {
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

impl Joint {
    /// The follower frame at position `q`.
    #[inline]
    pub fn pose(&self, q: f64) -> Pose {
        match *self {
            Joint::Translating { origin, direction } => Pose::new(origin + q * *direction, 0.0),
            Joint::Rotating { pivot, .. } => Pose::new(pivot, q),
        }
    }

    /// The follower body's state at position `q`, rate `q̇` and acceleration `q̈`.
    #[inline]
    pub fn body(&self, q: f64, qd: f64, qdd: f64) -> BodyState {
        let pose = self.pose(q);
        match *self {
            Joint::Translating { direction, .. } => BodyState {
                pose,
                velocity: qd * *direction,
                omega: 0.0,
                acceleration: qdd * *direction,
                alpha: 0.0,
            },
            Joint::Rotating { .. } => BodyState {
                pose,
                velocity: Vec2::zeros(),
                omega: qd,
                acceleration: Vec2::zeros(),
                alpha: qdd,
            },
        }
    }

    /// `∂v_B^P/∂q̇` at world point `c`: the velocity of the follower's material point under `c`
    /// per unit rate of the coordinate.
    #[inline]
    pub fn velocity_jacobian(&self, c: Point2) -> Vec2 {
        match *self {
            Joint::Translating { direction, .. } => *direction,
            Joint::Rotating { pivot, .. } => rot90(c - pivot),
        }
    }

    /// The coefficient of `q̈` in a contact row `Φ_q = [.., .., .., x_B, y_B, θ_B]` (eq. 11).
    #[inline]
    pub(crate) fn coordinate_coefficient(&self, phi: &[f64; 6]) -> f64 {
        match *self {
            Joint::Translating { direction: d, .. } => phi[3] * d.x + phi[4] * d.y,
            Joint::Rotating { .. } => phi[5],
        }
    }

    /// Converts a change of `q` into a length, for tolerances (`size`: the cam's reach from its
    /// axis at `cam_pivot`).
    #[inline]
    pub(crate) fn q_length_scale(&self, size: f64, cam_pivot: Point2) -> f64 {
        match *self {
            Joint::Translating { .. } => 1.0,
            Joint::Rotating { pivot, .. } => size + (pivot - cam_pivot).norm(),
        }
    }

    /// `q` oriented so that larger is "touches earlier" (the first touch is the largest).
    #[inline]
    pub(crate) fn oriented(&self, q: f64) -> f64 {
        match *self {
            Joint::Translating { .. } => q,
            Joint::Rotating {
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
            Joint::Translating { .. } => (q, q),
            Joint::Rotating { initial_angle, .. } => (
                self.oriented(q),
                crate::geometry::wrap_angle_near(q, initial_angle),
            ),
        }
    }

    /// An upper bound of the oriented score ([`Joint::oriented`]) of every position within the
    /// interval `(mid, half width)`; +∞ when the interval may cross a rotating joint's branch cut.
    #[inline]
    pub(crate) fn oriented_bound(&self, (mid, half): (f64, f64)) -> f64 {
        match *self {
            Joint::Translating { .. } => mid + half,
            Joint::Rotating {
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
            Joint::Translating { .. } => 1.0,
            Joint::Rotating { closing, .. } => -closing.sign(),
        }
    }

    /// True for a revolute joint (`q` in rad).
    pub fn is_rotating(&self) -> bool {
        matches!(self, Joint::Rotating { .. })
    }
}
