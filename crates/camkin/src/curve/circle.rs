//! Circle: `r(u) = c + R (cos u, sin u)`, counter-clockwise, `u` in radians.

use super::{check_point, check_positive, Curve, CurveError, CurveField, Derivs, Domain};
use crate::geometry::{Point2, Vec2};

/// A circle of radius `radius` about `center`, traversed counter-clockwise (`κ = 1/R`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    center: Point2,
    radius: f64,
}

impl Circle {
    /// A circle; `radius` must be positive and finite, `center` finite.
    pub fn new(center: Point2, radius: f64) -> Result<Self, CurveError> {
        Ok(Self {
            center: check_point(CurveField::Center, center)?,
            radius: check_positive(CurveField::Radius, radius)?,
        })
    }
    /// The centre.
    pub fn center(&self) -> Point2 {
        self.center
    }
    /// The radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

impl Curve for Circle {
    fn as_circle(&self) -> Option<&Circle> {
        Some(self)
    }
    fn eval(&self, u: f64) -> Derivs {
        let (s, c) = u.sin_cos();
        let r = self.radius;
        Derivs {
            p: self.center + Vec2::new(r * c, r * s),
            d1: Vec2::new(-r * s, r * c),
            d2: Vec2::new(-r * c, -r * s),
            d3: Vec2::new(r * s, -r * c),
        }
    }
    fn domain(&self) -> Domain {
        Domain::Periodic {
            period: std::f64::consts::TAU,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::test_support::check_derivatives;
    use approx::assert_relative_eq;

    #[test]
    fn curvature_is_inverse_radius_and_normal_points_inward() {
        let c = Circle::new(Point2::new(1.0, -2.0), 2.5).unwrap();
        for k in 0..12 {
            let u = k as f64 * 0.5;
            assert_relative_eq!(c.curvature(u), 0.4, epsilon = 1e-14);
            let inward = (c.center() - c.position(u)) / 2.5;
            assert_relative_eq!(c.normal(u), inward, epsilon = 1e-14);
            check_derivatives(&c, u, 1e-8);
        }
    }

    #[test]
    fn rejects_bad_radius() {
        assert!(matches!(
            Circle::new(Point2::origin(), -1.0),
            Err(CurveError::NonPositive {
                field: CurveField::Radius,
                ..
            })
        ));
        assert!(Circle::new(Point2::origin(), f64::NAN).is_err());
        assert!(Circle::new(Point2::new(f64::INFINITY, 0.0), 1.0).is_err());
    }
}
