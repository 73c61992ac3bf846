//! Ellipse: `r(u) = c + R(φ) (a cos u, b sin u)`, counter-clockwise, `u` the eccentric anomaly.

use super::{
    check_finite, check_point, check_positive, Curve, CurveError, CurveField, Derivs, Domain,
};
use crate::geometry::{Point2, Rotation, Vec2};

/// An ellipse with semi-axis `a` along its own x axis and `b` along its own y axis, that frame
/// rotated by `rotation` (rad, counter-clockwise) about `center`. Traversed counter-clockwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    center: Point2,
    a: f64,
    b: f64,
    rotation: f64,
    rot: Rotation,
}

impl Ellipse {
    /// An ellipse; semi-axes positive and finite, rotation in radians.
    pub fn new(center: Point2, a: f64, b: f64, rotation: f64) -> Result<Self, CurveError> {
        Ok(Self {
            center: check_point(CurveField::Center, center)?,
            a: check_positive(CurveField::SemiAxis(0), a)?,
            b: check_positive(CurveField::SemiAxis(1), b)?,
            rotation: check_finite(CurveField::Rotation, rotation)?,
            rot: Rotation::new(rotation),
        })
    }
    /// Centre.
    pub fn center(&self) -> Point2 {
        self.center
    }
    /// Semi-axes `(a, b)`.
    pub fn semi_axes(&self) -> (f64, f64) {
        (self.a, self.b)
    }
    /// Rotation, rad.
    pub fn rotation(&self) -> f64 {
        self.rotation
    }
}

impl Curve for Ellipse {
    fn as_ellipse(&self) -> Option<&Ellipse> {
        Some(self)
    }
    fn eval(&self, u: f64) -> Derivs {
        let (s, c) = u.sin_cos();
        self.derivs_at(s, c)
    }
    fn domain(&self) -> Domain {
        Domain::Periodic {
            period: std::f64::consts::TAU,
        }
    }
}

impl Ellipse {
    /// The point and derivatives at the parameter whose sine and cosine are `s` and `c` (a
    /// caller carrying them from a nearby parameter needs no `sin_cos`).
    #[inline(always)]
    pub(crate) fn derivs_at(&self, s: f64, c: f64) -> Derivs {
        let (a, b) = (self.a, self.b);
        let r = &self.rot;
        Derivs {
            p: self.center + r * Vec2::new(a * c, b * s),
            d1: r * Vec2::new(-a * s, b * c),
            d2: r * Vec2::new(-a * c, -b * s),
            d3: r * Vec2::new(a * s, -b * c),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::test_support::check_derivatives;
    use approx::assert_relative_eq;

    #[test]
    fn vertex_curvatures_are_closed_form() {
        // At the end of the a axis κ = a/b², at the end of the b axis κ = b/a².
        let e = Ellipse::new(Point2::new(0.5, 0.25), 3.0, 2.0, 0.7).unwrap();
        assert_relative_eq!(e.curvature(0.0), 3.0 / 4.0, epsilon = 1e-14);
        assert_relative_eq!(
            e.curvature(std::f64::consts::FRAC_PI_2),
            2.0 / 9.0,
            epsilon = 1e-14
        );
        let p = e.position(0.0) - e.center();
        assert_relative_eq!(
            p,
            Vec2::new(3.0 * 0.7f64.cos(), 3.0 * 0.7f64.sin()),
            epsilon = 1e-14
        );
        for k in 0..10 {
            check_derivatives(&e, k as f64 * 0.63, 1e-8);
        }
    }
}
