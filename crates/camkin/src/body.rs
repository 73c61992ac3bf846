//! Planar rigid bodies: pose, velocity and acceleration, and curves seen in the world frame.
//!
//! Conventions: see the [crate docs](crate#sign-conventions).

use crate::curve::{Curve, Derivs};
use crate::geometry::{rot90, Frame, Point2, Rotation, Vec2};

/// Where a body is: origin `p` (length) and angle `θ` (rad, counter-clockwise).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Pose {
    /// the body frame's origin in the world
    pub origin: Point2,
    /// the body frame's angle, rad
    pub angle: f64,
}

impl Pose {
    /// A pose.
    pub fn new(origin: Point2, angle: f64) -> Self {
        Self { origin, angle }
    }
    /// A body point `r` in the world: `p + R(θ) r`.
    pub fn to_world(&self, r: Point2) -> Point2 {
        self.frame() * r
    }
    /// A world point in the body frame: `R(θ)ᵀ (x − p)`.
    pub fn to_body(&self, x: Point2) -> Point2 {
        self.frame().inverse_transform_point(&x)
    }
    /// The body frame as an isometry (its rotation's cosine and sine computed once).
    #[inline]
    pub fn frame(&self) -> Frame {
        // a translating body's angle is exactly 0: skip the sin_cos
        let rotation = if self.angle == 0.0 {
            Rotation::identity()
        } else {
            Rotation::new(self.angle)
        };
        Frame::from_parts(self.origin.coords.into(), rotation)
    }
}

/// The state of a planar rigid body at one instant.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct BodyState {
    /// pose
    pub pose: Pose,
    /// `ṗ`, velocity of the origin (length/s)
    pub velocity: Vec2,
    /// `ω`, angular velocity (rad/s, counter-clockwise)
    pub omega: f64,
    /// `p̈`, acceleration of the origin (length/s²)
    pub acceleration: Vec2,
    /// `ω̇`, angular acceleration (rad/s²)
    pub alpha: f64,
}

/// A curve point and its parameter derivatives expressed in the world frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorldDerivs {
    /// world position `x(u)`
    pub p: Point2,
    /// `R r'`
    pub d1: Vec2,
    /// `R r''`
    pub d2: Vec2,
    /// `R r'''`
    pub d3: Vec2,
}

impl WorldDerivs {
    /// As [`Derivs`] (for its tangent, normal and curvature helpers).
    pub fn as_derivs(&self) -> Derivs {
        Derivs {
            p: self.p,
            d1: self.d1,
            d2: self.d2,
            d3: self.d3,
        }
    }
}

impl BodyState {
    /// A body at rest at `pose`.
    pub fn at_rest(pose: Pose) -> Self {
        Self {
            pose,
            velocity: Vec2::zeros(),
            omega: 0.0,
            acceleration: Vec2::zeros(),
            alpha: 0.0,
        }
    }

    /// A body turning about its fixed origin with angular velocity `omega` and angular
    /// acceleration `alpha`.
    pub fn rotating(origin: Point2, angle: f64, omega: f64, alpha: f64) -> Self {
        Self {
            pose: Pose::new(origin, angle),
            velocity: Vec2::zeros(),
            omega,
            acceleration: Vec2::zeros(),
            alpha,
        }
    }

    /// Velocity of the material point of this body at world point `x`: `ṗ + ω k × (x − p)`.
    #[inline]
    pub fn velocity_at(&self, x: Point2) -> Vec2 {
        self.velocity + self.omega * rot90(x - self.pose.origin)
    }

    /// Acceleration of the material point at world point `x`:
    /// `p̈ + ω̇ k × (x − p) − ω² (x − p)`.
    #[inline]
    pub fn acceleration_at(&self, x: Point2) -> Vec2 {
        let r = x - self.pose.origin;
        self.acceleration + self.alpha * rot90(r) - self.omega * self.omega * r
    }

    /// The curve at `u`, in the world frame.
    #[inline]
    pub fn eval_curve(&self, curve: &dyn Curve, u: f64) -> WorldDerivs {
        self.frame().curve_at(curve, u)
    }

    /// The body frame with its rotation computed once, for evaluating many curve points.
    #[inline]
    pub fn frame(&self) -> Frame {
        self.pose.frame()
    }
}

/// [`CurveInFrame::curve_at`] for a curve of a type known at compile time (its evaluation
/// inlined, what the caller does not read left out) or `dyn Curve`.
#[inline(always)]
pub(crate) fn curve_in<C: Curve + ?Sized>(frame: &Frame, curve: &C, u: f64) -> WorldDerivs {
    frame.derivs_to_world(&curve.eval(u))
}

/// Curves seen through a body [`Frame`].
pub trait CurveInFrame {
    /// Body-frame derivatives expressed in the world frame.
    fn derivs_to_world(&self, d: &Derivs) -> WorldDerivs;
    /// The curve at `u`, in the world frame.
    fn curve_at(&self, curve: &dyn Curve, u: f64) -> WorldDerivs;
    /// Only the world position of the curve at `u`.
    fn curve_position(&self, curve: &dyn Curve, u: f64) -> Point2;
}

impl CurveInFrame for Frame {
    #[inline(always)]
    fn derivs_to_world(&self, d: &Derivs) -> WorldDerivs {
        let r = &self.rotation;
        WorldDerivs {
            p: self * d.p,
            d1: r * d.d1,
            d2: r * d.d2,
            d3: r * d.d3,
        }
    }

    #[inline(always)]
    fn curve_at(&self, curve: &dyn Curve, u: f64) -> WorldDerivs {
        curve_in(self, curve, u)
    }

    #[inline]
    fn curve_position(&self, curve: &dyn Curve, u: f64) -> Point2 {
        self * curve.position(u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn material_point_motion_matches_finite_differences() {
        // A body point followed in time under constant p̈ and ω̇.
        let (p0, v0, a0) = (
            Vec2::new(1.0, 2.0),
            Vec2::new(0.3, -0.2),
            Vec2::new(0.05, 0.1),
        );
        let (th0, w0, al) = (0.4, 1.3, -0.7);
        let r = Vec2::new(0.8, -1.5);
        let x = |t: f64| {
            let p = p0 + v0 * t + 0.5 * a0 * t * t;
            let th = th0 + w0 * t + 0.5 * al * t * t;
            p + crate::geometry::Rotation::new(th) * r
        };
        let b = BodyState {
            pose: Pose::new(Point2::from(p0), th0),
            velocity: v0,
            omega: w0,
            acceleration: a0,
            alpha: al,
        };
        let xw = Point2::from(x(0.0));
        let h = 1e-3;
        let v_fd = (x(h) - x(-h)) / (2.0 * h);
        let a_fd = (x(h) - 2.0 * x(0.0) + x(-h)) / (h * h);
        assert_relative_eq!(b.velocity_at(xw), v_fd, epsilon = 1e-6);
        assert_relative_eq!(b.acceleration_at(xw), a_fd, epsilon = 1e-5);
        assert_relative_eq!(
            b.pose.to_body(b.pose.to_world(Point2::from(r))),
            Point2::from(r),
            epsilon = 1e-14
        );
    }
}
