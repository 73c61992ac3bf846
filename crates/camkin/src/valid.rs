//! The one validation vocabulary: what a number (or a point) given by a user must be, and the
//! words that say why not. The spec, the follower, the cam and the curves check their inputs by
//! these rules, each wrapping a refusal into its own error with the field it names.

use crate::Point2;

/// Largest length the computation takes in magnitude (it squares lengths): see
/// [`LENGTH_RANGE`].
pub const BIG: f64 = 1e100;

/// The lengths the computation keeps full accuracy for, in any unit: a cam's size and a
/// follower's lengths from `1e-100` to `1e100` (lengths are squared inside, and squares of
/// lengths beyond overflow or underflow `f64`).
pub const LENGTH_RANGE: (f64, f64) = (1e-100, BIG);

/// What a number must be.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Rule {
    /// any finite number
    Finite,
    /// finite and greater than zero
    Positive,
    /// finite and at least zero
    NonNegative,
    /// a length or coordinate the computation takes: finite, at most [`BIG`] in magnitude
    Bounded,
    /// a size the computation takes: within [`LENGTH_RANGE`]
    Size,
    /// an angle of an arm, rad: finite and within ±3600°
    ArmAngle,
}

impl Rule {
    /// `v` when it keeps the rule, else why not (the words every error says).
    pub(crate) fn check(self, v: f64) -> Result<f64, &'static str> {
        let ok = v.is_finite()
            && match self {
                Rule::Finite => true,
                Rule::Positive => v > 0.0,
                Rule::NonNegative => v >= 0.0,
                Rule::Bounded => v.abs() <= BIG,
                Rule::Size => (LENGTH_RANGE.0..=LENGTH_RANGE.1).contains(&v),
                Rule::ArmAngle => v.abs() <= 20.0 * std::f64::consts::PI,
            };
        if ok {
            return Ok(v);
        }
        Err(match self {
            Rule::Finite => "must be finite",
            Rule::Positive => "must be positive and finite",
            Rule::NonNegative => "must be finite and ≥ 0",
            Rule::Bounded if v.is_finite() => "must be at most 1e100 in magnitude",
            Rule::Bounded => "must be finite",
            Rule::Size if v.is_finite() && v > 0.0 => "must be from 1e-100 to 1e100",
            Rule::Size => "must be positive and finite",
            Rule::ArmAngle => "must be finite and within ±3600°",
        })
    }

    /// `p` when both its coordinates keep the rule, else why not.
    pub(crate) fn check_point(self, p: Point2) -> Result<Point2, &'static str> {
        self.check(p.x)?;
        self.check(p.y)?;
        Ok(p)
    }
}

#[cfg(test)]
mod tests {
    use super::Rule::*;

    #[test]
    fn each_rule_takes_its_edges_and_refuses_past_them() {
        assert_eq!(Finite.check(-1e308), Ok(-1e308));
        assert_eq!(Finite.check(f64::NAN), Err("must be finite"));
        assert_eq!(Positive.check(5e-324), Ok(5e-324));
        assert_eq!(Positive.check(0.0), Err("must be positive and finite"));
        assert_eq!(
            Positive.check(f64::INFINITY),
            Err("must be positive and finite")
        );
        assert_eq!(NonNegative.check(0.0), Ok(0.0));
        assert!(NonNegative.check(-1e-300).is_err());
        assert_eq!(Bounded.check(-1e100), Ok(-1e100));
        assert_eq!(
            Bounded.check(1.1e100),
            Err("must be at most 1e100 in magnitude")
        );
        assert_eq!(Bounded.check(f64::NEG_INFINITY), Err("must be finite"));
        assert_eq!(Size.check(1e-100), Ok(1e-100));
        assert_eq!(Size.check(1e-101), Err("must be from 1e-100 to 1e100"));
        assert_eq!(Size.check(-1.0), Err("must be positive and finite"));
        let turn = std::f64::consts::TAU;
        assert_eq!(ArmAngle.check(-10.0 * turn), Ok(-10.0 * turn));
        assert!(ArmAngle.check(10.0 * turn + 1e-9).is_err());
        assert!(Finite
            .check_point(crate::Point2::new(0.0, f64::NAN))
            .is_err());
    }
}
