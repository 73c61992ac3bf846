//! Planar curves fixed in a body frame.
//!
//! One small trait, [`Curve`]: position and derivatives at a parameter, plus the parameter domain;
//! tangent, left normal and signed curvature are provided methods. Conventions (left normal,
//! curvature sign, metric factor `g = |r'|`): see the [crate docs](crate#sign-conventions).
//!
//! | type | curve | parameter |
//! |---|---|---|
//! | [`ClosedSpline`] | periodic C² cubic spline through nodes (the paper's cam) | node i at `u = i` (or cumulative chord length) |
//! | [`Circle`] | circle | angle from the +x axis, rad |
//! | [`Ellipse`] | ellipse with semi-axes and rotation | eccentric anomaly, rad |
//! | [`InvoluteGear`] | external involute spur gear: flanks, tip, root fillet, tip relief | arc length along each piece |
//! | [`Line`] | infinite straight line | arc length from its anchor point |
//! | [`PointCurve`] | a single point (knife edge) | none |

mod arcs_and_lines;
mod circle;
mod ellipse;
mod involute_gear;
mod line;
mod piece_crossings;
mod point;
mod points_file;
mod spline;

pub use arcs_and_lines::{ArcsAndLines, ArcsError, Join, Piece};
pub use circle::Circle;
pub use ellipse::Ellipse;
pub use involute_gear::{
    involute_function, FlankPoint, FlankSide, InvoluteGear, InvoluteGearSpec, ReliefShape,
    TipRelief,
};
pub use line::Line;
pub use point::PointCurve;
pub use points_file::{
    parse_points, parse_points_with_lines, read_points_file, MAX_FILE_BYTES, MAX_POINTS,
};
pub use spline::{ClosedSpline, Parameterization, CHORD_RANGE, MAX_COORDINATE};

use crate::geometry::{cross, rot90, Point2, Vec2};
use crate::valid::Rule;

/// Position and derivatives of a curve at one parameter value, in the curve's (body) frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Derivs {
    /// `r(u)`, length
    pub p: Point2,
    /// `r'(u) = dr/du`
    pub d1: Vec2,
    /// `r''(u)`
    pub d2: Vec2,
    /// `r'''(u)`; for a cubic spline the value on the segment that starts at or before `u`
    /// (it jumps at the nodes, see [`Curve::breakpoints`]).
    pub d3: Vec2,
}

impl Derivs {
    /// Metric factor `g = |r'|` (the paper's `dξ/dα`).
    #[inline]
    pub fn metric(&self) -> f64 {
        self.d1.norm()
    }
    /// Unit tangent `r'/|r'|`.
    #[inline]
    pub fn tangent(&self) -> Vec2 {
        self.d1 * (1.0 / self.d1.norm())
    }
    /// Left normal `k × t`.
    #[inline]
    pub fn normal(&self) -> Vec2 {
        rot90(self.tangent())
    }
    /// Signed curvature `κ = (r' × r'')/|r'|³`, 1/length; positive where the curve turns left.
    #[inline]
    pub fn curvature(&self) -> f64 {
        let g = self.d1.norm();
        cross(self.d1, self.d2) / (g * g * g)
    }
    /// Derivative of the signed curvature with respect to arc length, `dκ/ds`, 1/length².
    pub fn curvature_slope(&self) -> f64 {
        let g2 = self.d1.norm_squared();
        let g = g2.sqrt();
        let c = cross(self.d1, self.d2);
        let dc = cross(self.d1, self.d3);
        let dg = self.d1.dot(&self.d2) / g;
        // κ = c / g³, dκ/du = (dc g³ − 3 c g² dg)/g⁶; ds = g du
        (dc * g - 3.0 * c * dg) / (g2 * g2 * g)
    }
}

/// The parameter domain of a curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Domain {
    /// A closed curve: `u ∈ [0, period)`, any `u` is taken modulo the period.
    Periodic {
        /// length of the parameter period
        period: f64,
    },
    /// An open curve over `[min, max]`; the bounds may be infinite (a straight line).
    Interval {
        /// lower bound
        min: f64,
        /// upper bound
        max: f64,
    },
    /// The curve is a single point (a knife edge): the parameter is ignored and tangent, normal
    /// and curvature are undefined (NaN); contact code treats it as the limit `κ → ∞`.
    Point,
}

/// A regular planar curve `r(u)` fixed in a body frame.
///
/// Implementors provide [`eval`](Curve::eval) and [`domain`](Curve::domain); everything else is
/// derived. A curve must be regular (`r' ≠ 0`) except a [`Domain::Point`] curve.
pub trait Curve: std::fmt::Debug + Send + Sync {
    /// Position and first three derivatives at `u`.
    fn eval(&self, u: f64) -> Derivs;

    /// The parameter domain.
    fn domain(&self) -> Domain;

    /// Parameters where the curve is only C² (its curvature has a corner and the third
    /// derivative jumps): a cubic spline's nodes. Empty for analytic curves.
    fn breakpoints(&self) -> Vec<f64> {
        Vec::new()
    }

    /// The order of the curve's rotational symmetry about its frame's origin: `z` for a gear of
    /// `z` teeth (it looks the same turned by `2π/z`), 1 for a curve without such symmetry.
    fn symmetry(&self) -> u32 {
        1
    }

    /// The curve as a closed cubic spline, when it is one: the typed hook a fast path asks (the
    /// spline's warm step reads its pieces directly), as kurbo's `as_circle`.
    fn as_spline(&self) -> Option<&ClosedSpline> {
        None
    }

    /// The curve as an involute gear, when it is one (a gear pair is read as gears).
    fn as_involute_gear(&self) -> Option<&InvoluteGear> {
        None
    }

    /// The curve as a circle, when it is one (a circle on a follower is a roller: the pressure
    /// angle is taken at its centre).
    fn as_circle(&self) -> Option<&Circle> {
        None
    }

    /// The curve as an ellipse, when it is one (a sweep carries its parameter's sine and cosine).
    fn as_ellipse(&self) -> Option<&Ellipse> {
        None
    }

    /// The curve as a chain of arcs and lines, when it is one (its joins are reported).
    fn as_arcs_and_lines(&self) -> Option<&ArcsAndLines> {
        None
    }

    /// `r(u)`.
    fn position(&self, u: f64) -> Point2 {
        self.eval(u).p
    }
    /// Unit tangent at `u`.
    fn tangent(&self, u: f64) -> Vec2 {
        self.eval(u).tangent()
    }
    /// Left normal at `u` (see the [crate docs](crate#sign-conventions)).
    fn normal(&self, u: f64) -> Vec2 {
        self.eval(u).normal()
    }
    /// Signed curvature at `u`, 1/length.
    fn curvature(&self, u: f64) -> f64 {
        self.eval(u).curvature()
    }
}

/// A field of the data a curve is built from, named by enum; its `Display` is the key of the
/// mechanism-file schema where there is one (`semi_axes[0]`, `tip_relief.length`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum CurveField {
    /// a circle's or an ellipse's centre
    Center,
    /// a circle's radius
    Radius,
    /// an ellipse's semi-axis (0 or 1)
    SemiAxis(usize),
    /// an ellipse's rotation
    Rotation,
    /// a point curve's place
    Point,
    /// a line's anchor
    Anchor,
    /// a line's direction
    Direction,
    /// a gear's module
    Module,
    /// a gear's number of teeth
    Teeth,
    /// a gear's pressure angle
    PressureAngle,
    /// a gear's addendum factor
    Addendum,
    /// a gear's dedendum factor
    Dedendum,
    /// a gear's profile shift coefficient
    ProfileShift,
    /// a gear's backlash
    Backlash,
    /// a gear's root fillet radius
    FilletRadius,
    /// a gear's tip relief at the tip
    TipReliefAmount,
    /// the length of a gear's tip relief
    TipReliefLength,
}

impl std::fmt::Display for CurveField {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CurveField::SemiAxis(i) => write!(f, "semi_axes[{i}]"),
            other => f.write_str(match other {
                CurveField::Center => "center",
                CurveField::Radius => "radius",
                CurveField::Rotation => "rotation",
                CurveField::Point => "point",
                CurveField::Anchor => "anchor",
                CurveField::Direction => "direction",
                CurveField::Module => "module",
                CurveField::Teeth => "teeth",
                CurveField::PressureAngle => "pressure_angle_deg",
                CurveField::Addendum => "addendum",
                CurveField::Dedendum => "dedendum",
                CurveField::ProfileShift => "profile_shift",
                CurveField::Backlash => "backlash",
                CurveField::FilletRadius => "fillet_radius",
                CurveField::TipReliefAmount => "tip_relief.amount",
                CurveField::TipReliefLength => "tip_relief.length",
                CurveField::SemiAxis(_) => unreachable!("written above"),
            }),
        }
    }
}

/// What is wrong with the data a curve was asked to be built from.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CurveError {
    /// A closed spline needs at least three nodes.
    #[error("a closed spline needs at least 3 points, got {count}")]
    TooFewPoints {
        /// number of points given
        count: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("point {index} is not finite: ({}, {})", crate::human::human(*.x), crate::human::human(*.y))]
    NonFinitePoint {
        /// index of the point (0-based)
        index: usize,
        /// its x
        x: f64,
        /// its y
        y: f64,
    },
    /// A node too far from the origin for the spline's arithmetic.
    #[error("point {index} = ({}, {}) is too far out: a spline's coordinates must be at most 1e300 in magnitude (its chords and coefficients must stay finite)", crate::human::human(*.x), crate::human::human(*.y))]
    FarPoint {
        /// the point's index
        index: usize,
        /// its x
        x: f64,
        /// its y
        y: f64,
    },
    /// A chord of a chord-length spline outside the range its derivatives can be represented
    /// in (the third derivative grows as 1/chord²).
    #[error("points {index} and {next} are {} apart: a chord-length spline needs chords from 1e-150 to 1e150", crate::human::human(*.length))]
    ChordLength {
        /// the first point's index
        index: usize,
        /// the next point's index
        next: usize,
        /// the distance between them
        length: f64,
    },
    /// Two consecutive nodes coincide (the last and the first count as consecutive).
    #[error("points {index} and {next} coincide at ({}, {})", crate::human::human(*.x), crate::human::human(*.y))]
    RepeatedPoint {
        /// index of the first of the two
        index: usize,
        /// index of the second
        next: usize,
        /// x of the repeated point
        x: f64,
        /// y of the repeated point
        y: f64,
    },
    /// A size (radius, semi-axis) is not positive and finite.
    #[error("{field} must be positive and finite, got {}", crate::human::human(*.value))]
    NonPositive {
        /// the field
        field: CurveField,
        /// the value given
        value: f64,
    },
    /// A number that must be finite is not.
    #[error("{field} must be finite, got {}", crate::human::human(*.value))]
    NonFinite {
        /// the field
        field: CurveField,
        /// the value given
        value: f64,
    },
    /// A direction vector has zero (or non-finite) length.
    #[error("{field} must be a non-zero finite vector, got ({}, {})", crate::human::human(*.x), crate::human::human(*.y))]
    ZeroDirection {
        /// the field
        field: CurveField,
        /// x of the vector
        x: f64,
        /// y of the vector
        y: f64,
    },
    /// A points file could not be read.
    #[error("cannot read points file {path}: {message}")]
    PointsFileIo {
        /// the path as given
        path: String,
        /// the operating system's message
        message: String,
    },
    /// A line of a points file is malformed.
    #[error("points file line {line}: {message}: {content:?}")]
    PointsFileSyntax {
        /// 1-based line number
        line: usize,
        /// what is wrong
        message: String,
        /// the line's text
        content: String,
    },
    /// A gear that cannot be made from the data given.
    #[error("{field} = {}: {reason}", crate::human::human(*.value))]
    Gear {
        /// the field
        field: CurveField,
        /// the value given
        value: f64,
        /// why not
        reason: String,
    },
}

/// Sample parameters over one period of a closed curve, in increasing order within `[0,
/// period)`: `per_piece` evenly in every smooth piece between consecutive `breakpoints`
/// (the last piece going round the end of the period to the first breakpoint, its samples past
/// the end brought to the start), or `per_curve` evenly over the period when there are none.
/// A curve whose pieces repeat (a gear's teeth) gets samples that repeat with them.
pub(crate) fn piece_samples(
    breakpoints: &[f64],
    period: f64,
    per_piece: usize,
    per_curve: usize,
) -> impl Iterator<Item = f64> + '_ {
    let n = breakpoints.len();
    let piece = move |i: usize| -> (f64, f64, usize) {
        if n == 0 {
            (0.0, period, per_curve)
        } else {
            let s = breakpoints[i];
            let e = breakpoints
                .get(i + 1)
                .copied()
                .unwrap_or(breakpoints[0] + period);
            (s, e, per_piece)
        }
    };
    let at = move |(s, e, k): (f64, f64, usize), j: usize| s + (e - s) * j as f64 / k as f64;
    // the last piece's samples past the period's end, brought to its start
    let (last, wrapped_from) = match n {
        0 => ((0.0, period, per_curve), per_curve),
        _ => {
            let p = piece(n - 1);
            (p, (0..p.2).find(|&j| at(p, j) >= period).unwrap_or(p.2))
        }
    };
    let wrapped = (wrapped_from..last.2).map(move |j| at(last, j) - period);
    let pieces = (0..n.max(1)).flat_map(move |i| {
        let p = piece(i);
        let k = if i + 1 == n.max(1) { wrapped_from } else { p.2 };
        (0..k).map(move |j| at(p, j))
    });
    wrapped.chain(pieces)
}

impl CurveError {
    /// The field at fault, with the value given, where the error names one.
    pub fn field(&self) -> Option<(CurveField, f64)> {
        match *self {
            CurveError::NonPositive { field, value }
            | CurveError::NonFinite { field, value }
            | CurveError::Gear { field, value, .. } => Some((field, value)),
            _ => None,
        }
    }
}

pub(crate) fn check_positive(field: CurveField, value: f64) -> Result<f64, CurveError> {
    Rule::Positive
        .check(value)
        .map_err(|_| CurveError::NonPositive { field, value })
}

pub(crate) fn check_finite(field: CurveField, value: f64) -> Result<f64, CurveError> {
    Rule::Finite
        .check(value)
        .map_err(|_| CurveError::NonFinite { field, value })
}

pub(crate) fn check_point(field: CurveField, p: Point2) -> Result<Point2, CurveError> {
    check_finite(field, p.x)?;
    check_finite(field, p.y)?;
    Ok(p)
}

/// The unit vector along `v`, or an error naming `field` when `v` is zero or not finite.
pub fn unit_direction(field: CurveField, v: Vec2) -> Result<Vec2, CurveError> {
    let n = v.norm();
    if n.is_finite() && n > 0.0 {
        Ok(v / n)
    } else {
        Err(CurveError::ZeroDirection {
            field,
            x: v.x,
            y: v.y,
        })
    }
}

#[cfg(test)]
pub(crate) mod test_support {
    //! Derivative checks shared by the curve tests.
    use super::*;
    use crate::geometry::Vec2;

    /// Fourth-order central difference of `f` at `u` with step `h`.
    pub(crate) fn central(f: impl Fn(f64) -> Vec2, u: f64, h: f64) -> Vec2 {
        (f(u - 2.0 * h) - 8.0 * f(u - h) + 8.0 * f(u + h) - f(u + 2.0 * h)) / (12.0 * h)
    }

    /// Asserts that d1, d2, d3 agree with finite differences of the lower derivative at `u`.
    pub(crate) fn check_derivatives(c: &dyn Curve, u: f64, tol: f64) {
        let h = 1e-4;
        let e = c.eval(u);
        let d1 = central(|v| c.eval(v).p.coords, u, h);
        let d2 = central(|v| c.eval(v).d1, u, h);
        let d3 = central(|v| c.eval(v).d2, u, h);
        let scale = 1.0 + e.d1.norm() + e.d2.norm() + e.d3.norm();
        assert!(
            (d1 - e.d1).norm() < tol * scale,
            "d1 at {u}: {d1} vs {}",
            e.d1
        );
        assert!(
            (d2 - e.d2).norm() < tol * scale,
            "d2 at {u}: {d2} vs {}",
            e.d2
        );
        assert!(
            (d3 - e.d3).norm() < tol * scale,
            "d3 at {u}: {d3} vs {}",
            e.d3
        );
    }
}

#[cfg(test)]
mod tests {
    use super::piece_samples;

    /// Samples cover the period in increasing order, `per_piece` in every piece including the
    /// one round the end (which used to end at the period, leaving the stretch before the first
    /// breakpoint a single chord), and repeat with pieces that repeat.
    #[test]
    fn piece_samples_cover_the_period_and_repeat_with_the_pieces() {
        // three "teeth" of length 2, joints at 0.3 and 1.1 of each
        let bp: Vec<f64> = (0..3)
            .flat_map(|k| [2.0 * f64::from(k) + 0.3, 2.0 * f64::from(k) + 1.1])
            .collect();
        let s: Vec<f64> = piece_samples(&bp, 6.0, 4, 100).collect();
        assert_eq!(s.len(), 6 * 4);
        assert!(
            s.windows(2).all(|w| w[0] < w[1]) && s[0] >= 0.0 && s[23] < 6.0,
            "{s:?}"
        );
        // the stretch from 0 to the first joint is sampled: the piece from 5.1 to 6.3 has its
        // fourth sample at 6.0, brought to 0
        assert!(s[0].abs() <= 1e-12 && (s[1] - 0.3).abs() <= 1e-12, "{s:?}");
        for i in 0..16 {
            assert!((s[i + 8] - s[i] - 2.0).abs() <= 1e-12, "{i}: {s:?}");
        }
        // joints from 0 (a spline's nodes): as before, nothing wraps
        let s: Vec<f64> = piece_samples(&[0.0, 1.0, 2.5], 4.0, 2, 100).collect();
        assert_eq!(s, vec![0.0, 0.5, 1.0, 1.75, 2.5, 3.25]);
        // no joints
        let s: Vec<f64> = piece_samples(&[], 1.0, 2, 4).collect();
        assert_eq!(s, vec![0.0, 0.25, 0.5, 0.75]);
    }
}
