//! A single point: the knife edge.

use super::{check_point, Curve, CurveError, CurveField, Derivs, Domain};
use crate::geometry::{Point2, Vec2};

/// A point fixed in its body (a knife-edge tip). Its domain is [`Domain::Point`]: contact with it
/// is the limit `κ_B → ∞` of eqs. 5–6 (`ṡ_B = 0`, `ṡ_A = w`, `κ_B ṡ_B² → 0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointCurve {
    at: Point2,
}

impl PointCurve {
    /// The point `at` (finite).
    pub fn new(at: Point2) -> Result<Self, CurveError> {
        Ok(Self {
            at: check_point(CurveField::Point, at)?,
        })
    }
    /// Where it is, in its body frame.
    pub fn at(&self) -> Point2 {
        self.at
    }
}

impl Curve for PointCurve {
    fn eval(&self, _u: f64) -> Derivs {
        Derivs {
            p: self.at,
            d1: Vec2::zeros(),
            d2: Vec2::zeros(),
            d3: Vec2::zeros(),
        }
    }
    fn domain(&self) -> Domain {
        Domain::Point
    }
}
