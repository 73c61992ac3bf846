//! Straight line: `r(u) = p₀ + u d`, `|d| = 1`, `u` is arc length.

use super::{check_point, unit_direction, Curve, CurveError, CurveField, Derivs, Domain};
use crate::geometry::{Point2, Vec2};

/// An infinite straight line through `anchor` along the unit vector `direction` (a flat face).
/// Its left normal is `k × direction`; its curvature is zero.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    anchor: Point2,
    direction: Vec2,
}

impl Line {
    /// A line; `direction` is normalised and must be non-zero.
    pub fn new(anchor: Point2, direction: Vec2) -> Result<Self, CurveError> {
        Ok(Self {
            anchor: check_point(CurveField::Anchor, anchor)?,
            direction: unit_direction(CurveField::Direction, direction)?,
        })
    }
    /// The point at `u = 0`.
    pub fn anchor(&self) -> Point2 {
        self.anchor
    }
    /// The unit direction.
    pub fn direction(&self) -> Vec2 {
        self.direction
    }
    /// The parameter of the foot of the perpendicular from `x`.
    pub fn project(&self, x: Point2) -> f64 {
        (x - self.anchor).dot(&self.direction)
    }
}

impl Curve for Line {
    fn eval(&self, u: f64) -> Derivs {
        Derivs {
            p: self.anchor + u * self.direction,
            d1: self.direction,
            d2: Vec2::zeros(),
            d3: Vec2::zeros(),
        }
    }
    fn domain(&self) -> Domain {
        Domain::Interval {
            min: f64::NEG_INFINITY,
            max: f64::INFINITY,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn straight_with_left_normal() {
        let l = Line::new(Point2::new(1.0, 1.0), Vec2::new(0.0, 2.0)).unwrap();
        assert_eq!(l.curvature(3.0), 0.0);
        assert_relative_eq!(l.normal(0.0), Vec2::new(-1.0, 0.0));
        assert_relative_eq!(l.project(Point2::new(5.0, 4.0)), 3.0);
        assert!(Line::new(Point2::origin(), Vec2::zeros()).is_err());
    }
}
