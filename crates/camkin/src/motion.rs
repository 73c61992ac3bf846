//! Follower motion laws and motion programs (the first half of cam design: the law; the profile
//! synthesised from it comes in a later step).
//!
//! A law is given in normalised form `y(x)`, `x ∈ [0, 1]`, rising from `y(0) = 0` to `y(1) = 1`,
//! with its first three derivatives in `x`. A segment of a program scales it to a rise `h` over an
//! extent `β` of cam angle: `s = s₀ + h y((θ − θ₀)/β)`, `s' = h y'/β`, `s'' = h y''/β²`,
//! `s''' = h y'''/β³` (derivatives in the cam angle, rad).

use crate::lift_table::LiftTable;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

/// A motion law.
#[derive(Debug, Clone, PartialEq)]
pub enum Law {
    /// no motion (the rise of a dwell segment must be 0)
    Dwell,
    /// `y = (1 − cos πx)/2`: finite acceleration jumps at the ends
    SimpleHarmonic,
    /// `y = x − sin(2πx)/(2π)`: zero velocity and acceleration at both ends
    Cycloidal,
    /// `y = 10x³ − 15x⁴ + 6x⁵`: zero velocity and acceleration at both ends
    Polynomial345,
    /// `y = 35x⁴ − 84x⁵ + 70x⁶ − 20x⁷`: zero velocity, acceleration and jerk at both ends
    Polynomial4567,
    /// acceleration: sine ramps over the first and last eighth of each half, constant between
    ModifiedTrapezoid,
    /// acceleration: a short sine quarter over the first and last eighth, a long cosine between
    ModifiedSine,
    /// `y = x`: constant velocity
    ConstantVelocity,
    /// A valve train's clearance ramp: constant velocity `y' = 4/3` over its middle half, reached
    /// from rest over its first quarter and left to rest over its last by cycloidal blends of the
    /// velocity (`y' = V (u − sin 2πu / 2π)`, `u = 4x`): its velocity, acceleration and jerk are
    /// continuous and zero at both ends, so it meets a dwell and a lift from rest; its height
    /// is `1/6` at the constant part's start and `5/6` at its end. A ramp of rise `h` over `β`
    /// moves at `4h / 3β` (length per rad) there: a clearance between those heights is taken up,
    /// and a valve seats, at that speed times the cam's.
    Ramp,
    /// A lift table interpolated by a quintic spline ([`LiftTable`]): its segment moves by the
    /// table's lifts less its first (its rise is the table's last lift less its first), over
    /// the table's span; its normalised form is that over its largest excursion.
    Table(Arc<LiftTable>),
}

/// The fraction of a [`Law::Ramp`] each blend takes.
const RAMP_BLEND: f64 = 0.25;

/// [`Law::Ramp`]'s value and four derivatives over its first half, `x ∈ [0, 1/2]`.
fn ramp_first_half(x: f64) -> [f64; 5] {
    let (b, v) = (RAMP_BLEND, 1.0 / (1.0 - RAMP_BLEND));
    if x >= b {
        return [v * (0.5 * b + (x - b)), v, 0.0, 0.0, 0.0];
    }
    let u = x / b;
    let (s, c) = (TAU * u).sin_cos();
    [
        v * b * (0.5 * u * u + (c - 1.0) / (TAU * TAU)),
        v * (u - s / TAU),
        v * (1.0 - c) / b,
        v * TAU * s / (b * b),
        v * TAU * TAU * c / (b * b * b),
    ]
}

/// One piece of a piecewise acceleration `A sin(ω x + φ) + B` on `[x0, x1]`, with the velocity
/// and displacement constants that make the integrals continuous.
#[derive(Debug, Clone, Copy)]
struct Piece {
    x0: f64,
    a: f64,
    w: f64,
    phi: f64,
    b: f64,
    v0: f64,
    s0: f64,
}

impl Piece {
    /// `[y, y', y'', y''']` at `x` (relative to the piece's start for the constants).
    fn eval(&self, x: f64) -> [f64; 4] {
        let e = self.eval5(x);
        [e[0], e[1], e[2], e[3]]
    }

    /// `[y, y', y'', y''', y'''']` at `x`: [`Piece::eval`] and the snap from one sine.
    fn eval5(&self, x: f64) -> [f64; 5] {
        let t = x - self.x0;
        let (a, w, b) = (self.a, self.w, self.b);
        if w == 0.0 {
            return [
                self.s0 + self.v0 * t + 0.5 * b * t * t,
                self.v0 + b * t,
                b,
                0.0,
                0.0,
            ];
        }
        let (sn, cs) = (self.w * x + self.phi).sin_cos();
        let (sn0, cs0) = (self.w * self.x0 + self.phi).sin_cos();
        // v = v0 + ∫ a = v0 − A/ω (cos − cos0) + B t ; s = s0 + ∫ v
        let v = self.v0 - a / w * (cs - cs0) + b * t;
        let s = self.s0 + (self.v0 + a / w * cs0) * t - a / (w * w) * (sn - sn0) + 0.5 * b * t * t;
        [s, v, a * sn + b, a * w * cs, -a * w * w * sn]
    }
}

/// A law whose acceleration is piecewise `A sin(ωx + φ) + B`, integrated exactly from rest and
/// scaled so that `y(1) = 1`.
fn piecewise(shape: &[(f64, f64, f64, f64, f64)]) -> Vec<Piece> {
    // shape: (x0, A, ω, φ, B) for unit peak acceleration; integrate, then scale
    let mut pieces: Vec<Piece> = Vec::new();
    let (mut v, mut s) = (0.0, 0.0);
    for (k, &(x0, a, w, phi, b)) in shape.iter().enumerate() {
        let p = Piece {
            x0,
            a,
            w,
            phi,
            b,
            v0: v,
            s0: s,
        };
        let x1 = shape.get(k + 1).map_or(1.0, |n| n.0);
        let e = p.eval(x1);
        (s, v) = (e[0], e[1]);
        pieces.push(p);
    }
    let scale = 1.0 / s;
    for p in &mut pieces {
        p.a *= scale;
        p.b *= scale;
        p.v0 *= scale;
        p.s0 *= scale;
    }
    pieces
}

fn modified_trapezoid() -> &'static [Piece] {
    static P: std::sync::OnceLock<Vec<Piece>> = std::sync::OnceLock::new();
    P.get_or_init(|| {
        let w = 4.0 * PI;
        piecewise(&[
            (0.0, 1.0, w, 0.0, 0.0),      // sin ramp up to the peak at 1/8
            (0.125, 0.0, 0.0, 0.0, 1.0),  // constant
            (0.375, 1.0, w, -PI, 0.0),    // cos(4π(x − 3/8)) = sin(4πx − π): 1 at 3/8 to −1 at 5/8
            (0.625, 0.0, 0.0, 0.0, -1.0), // constant negative
            (0.875, 1.0, w, 0.0, 0.0),    // −cos(4π(x − 7/8)) = sin(4πx): −1 at 7/8 to 0 at 1
        ])
    })
}

fn modified_sine() -> &'static [Piece] {
    static P: std::sync::OnceLock<Vec<Piece>> = std::sync::OnceLock::new();
    P.get_or_init(|| {
        piecewise(&[
            (0.0, 1.0, 4.0 * PI, 0.0, 0.0), // sin(4πx): peak 1 at 1/8
            (0.125, 1.0, 4.0 * PI / 3.0, PI / 2.0 - PI / 6.0, 0.0), // cos(4π/3 (x − 1/8)) = sin(4πx/3 + π/3)
            (0.875, 1.0, 4.0 * PI, 0.0, 0.0), // −cos(4π(x − 7/8)) = sin(4πx): −1 at 7/8 to 0 at 1
        ])
    })
}

fn eval_pieces(pieces: &[Piece], x: f64) -> [f64; 5] {
    let k = pieces.iter().rposition(|p| p.x0 <= x).unwrap_or(0);
    pieces[k].eval5(x)
}

impl Law {
    /// `[y, y', y'', y''']` at `x ∈ [0, 1]` (outside, the end values).
    pub fn normalized(&self, x: f64) -> [f64; 4] {
        let y = self.normalized5(x);
        [y[0], y[1], y[2], y[3]]
    }

    /// `y''''` at `x ∈ [0, 1]` (the fourth derivative, for the third derivative of synthesised
    /// profiles).
    pub fn snap(&self, x: f64) -> f64 {
        self.normalized5(x)[4]
    }

    /// `[y, y', y'', y''', y'''']` at `x ∈ [0, 1]` (outside, the end values): one sine and
    /// cosine for all five.
    pub fn normalized5(&self, x: f64) -> [f64; 5] {
        let x = x.clamp(0.0, 1.0);
        match self {
            Law::Dwell => [0.0; 5],
            Law::ConstantVelocity => [x, 1.0, 0.0, 0.0, 0.0],
            Law::SimpleHarmonic => {
                let (s, c) = (PI * x).sin_cos();
                [
                    0.5 * (1.0 - c),
                    0.5 * PI * s,
                    0.5 * PI * PI * c,
                    -0.5 * PI * PI * PI * s,
                    -0.5 * PI.powi(4) * c,
                ]
            }
            Law::Cycloidal => {
                let (s, c) = (TAU * x).sin_cos();
                [
                    x - s / TAU,
                    1.0 - c,
                    TAU * s,
                    TAU * TAU * c,
                    -TAU.powi(3) * s,
                ]
            }
            Law::Polynomial345 => {
                let (x2, x3) = (x * x, x * x * x);
                [
                    x3 * (10.0 - 15.0 * x + 6.0 * x2),
                    x2 * (30.0 - 60.0 * x + 30.0 * x2),
                    x * (60.0 - 180.0 * x + 120.0 * x2),
                    60.0 - 360.0 * x + 360.0 * x2,
                    -360.0 + 720.0 * x,
                ]
            }
            Law::Polynomial4567 => {
                let (x2, x3) = (x * x, x * x * x);
                [
                    x2 * x2 * (35.0 - 84.0 * x + 70.0 * x2 - 20.0 * x3),
                    x3 * (140.0 - 420.0 * x + 420.0 * x2 - 140.0 * x3),
                    x2 * (420.0 - 1680.0 * x + 2100.0 * x2 - 840.0 * x3),
                    x * (840.0 - 5040.0 * x + 8400.0 * x2 - 4200.0 * x3),
                    840.0 - 10080.0 * x + 25200.0 * x * x - 16800.0 * x * x * x,
                ]
            }
            Law::ModifiedTrapezoid => eval_pieces(modified_trapezoid(), x),
            Law::ModifiedSine => eval_pieces(modified_sine(), x),
            Law::Ramp => {
                if x <= 0.5 {
                    ramp_first_half(x)
                } else {
                    // symmetric about its middle: y(x) = 1 − y(1 − x)
                    let y = ramp_first_half(1.0 - x);
                    [1.0 - y[0], y[1], -y[2], y[3], -y[4]]
                }
            }
            Law::Table(t) => {
                let (b, l) = (t.span(), t.excursion());
                let l = if l > 0.0 { l } else { 1.0 };
                let y = t.eval5(x * b);
                [
                    (y[0] - t.ends().0) / l,
                    y[1] * b / l,
                    y[2] * b * b / l,
                    y[3] * b * b * b / l,
                    y[4] * b * b * b * b / l,
                ]
            }
        }
    }

    /// The name used in mechanism files.
    pub fn name(&self) -> &'static str {
        match self {
            Law::Dwell => "dwell",
            Law::SimpleHarmonic => "simple-harmonic",
            Law::Cycloidal => "cycloidal",
            Law::Polynomial345 => "3-4-5",
            Law::Polynomial4567 => "4-5-6-7",
            Law::ModifiedTrapezoid => "modified-trapezoid",
            Law::ModifiedSine => "modified-sine",
            Law::ConstantVelocity => "constant-velocity",
            Law::Ramp => "ramp",
            Law::Table(_) => "table",
        }
    }

    /// Every named law (a [`Law::Table`] is made from its table).
    pub const ALL: [Law; 9] = [
        Law::Dwell,
        Law::SimpleHarmonic,
        Law::Cycloidal,
        Law::Polynomial345,
        Law::Polynomial4567,
        Law::ModifiedTrapezoid,
        Law::ModifiedSine,
        Law::ConstantVelocity,
        Law::Ramp,
    ];
}

/// One segment of a motion program.
#[derive(Debug, Clone, PartialEq)]
pub struct Segment {
    /// the law
    pub law: Law,
    /// the rise (negative: a return), length or rad
    pub rise: f64,
    /// the extent in cam angle, rad
    pub extent: f64,
}

impl Segment {
    /// How far it moves: its rise's size, a table's largest excursion.
    pub fn size(&self) -> f64 {
        match &self.law {
            Law::Table(t) => t.excursion().max(self.rise.abs()),
            _ => self.rise.abs(),
        }
    }
}

/// Where two consecutive segments (or the last and the first) break continuity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Discontinuity {
    /// cam angle of the junction, rad
    pub at: f64,
    /// index of the segment that starts there
    pub segment: usize,
    /// the lowest derivative that jumps: 0 position, 1 velocity, 2 acceleration, 3 jerk
    pub order: usize,
    /// the jump, in units of that derivative per rad^order
    pub jump: f64,
}

/// What is wrong with a motion program.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MotionError {
    /// No segments.
    #[error("a motion program needs at least one segment")]
    Empty,
    /// A segment's extent is not positive and finite.
    #[error("segment {index}: extent {} rad must be positive and finite", crate::human::human(*.extent))]
    Extent {
        /// the segment
        index: usize,
        /// its extent
        extent: f64,
    },
    /// A rise is not finite, or a dwell rises.
    #[error("segment {index}: rise {rise} ({reason})")]
    Rise {
        /// the segment
        index: usize,
        /// its rise
        rise: f64,
        /// why
        reason: &'static str,
    },
    /// The extents do not add up to one revolution.
    #[error("the segments cover {}°, not 360°", crate::human::human(*.total_deg))]
    NotARevolution {
        /// their total, degrees
        total_deg: f64,
    },
    /// The rises do not add up to zero: the motion would not close.
    #[error("the rises add up to {}, not 0: the motion does not return to its start", crate::human::human(*.total))]
    NotClosed {
        /// their sum
        total: f64,
    },
}

/// A motion program: segments covering one revolution from a base position.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    segments: Vec<Segment>,
    starts: Vec<f64>,
    levels: Vec<f64>,
    base: f64,
}

/// Tolerance on the revolution and closure sums, relative.
const CLOSURE_TOLERANCE: f64 = 1e-9;

impl Program {
    /// A program starting at position `base` at cam angle 0.
    pub fn new(base: f64, segments: Vec<Segment>) -> Result<Self, MotionError> {
        if segments.is_empty() {
            return Err(MotionError::Empty);
        }
        let (mut t, mut lvl) = (0.0, base);
        let (mut starts, mut levels) = (Vec::new(), Vec::new());
        let mut scale: f64 = 0.0;
        for (index, s) in segments.iter().enumerate() {
            if !(s.extent.is_finite() && s.extent > 0.0) {
                return Err(MotionError::Extent {
                    index,
                    extent: s.extent,
                });
            }
            if !s.rise.is_finite() {
                return Err(MotionError::Rise {
                    index,
                    rise: s.rise,
                    reason: "must be finite",
                });
            }
            if s.law == Law::Dwell && s.rise != 0.0 {
                return Err(MotionError::Rise {
                    index,
                    rise: s.rise,
                    reason: "a dwell does not rise",
                });
            }
            if let Law::Table(table) = &s.law {
                let (first, last) = table.ends();
                if (s.extent - table.span()).abs() > CLOSURE_TOLERANCE * table.span()
                    || (s.rise - (last - first)).abs()
                        > CLOSURE_TOLERANCE * table.excursion().max(f64::MIN_POSITIVE)
                {
                    return Err(MotionError::Rise {
                        index,
                        rise: s.rise,
                        reason:
                            "a table's segment rises by its last lift less its first, over its span",
                    });
                }
            }
            starts.push(t);
            levels.push(lvl);
            t += s.extent;
            lvl += s.rise;
            scale = scale.max(s.size());
        }
        if (t - TAU).abs() > CLOSURE_TOLERANCE * TAU {
            return Err(MotionError::NotARevolution {
                total_deg: t.to_degrees(),
            });
        }
        if (lvl - base).abs() > CLOSURE_TOLERANCE * scale.max(f64::MIN_POSITIVE) {
            return Err(MotionError::NotClosed { total: lvl - base });
        }
        Ok(Self {
            segments,
            starts,
            levels,
            base,
        })
    }

    /// The segments.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// `[s, s', s'', s''']` at cam angle `theta` (rad, taken modulo one revolution); derivatives
    /// in the cam angle.
    pub fn eval(&self, theta: f64) -> [f64; 4] {
        let t = theta.rem_euclid(TAU);
        // the starts are increasing: a binary search (a linear scan made a 100 000-segment program
        // quadratic to synthesise)
        let k = self.starts.partition_point(|&s| s <= t).saturating_sub(1);
        self.eval_segment(k, t)
    }

    fn eval_segment(&self, k: usize, t: f64) -> [f64; 4] {
        let e = self.eval_segment5(k, t);
        [e[0], e[1], e[2], e[3]]
    }

    /// [`Program::eval_segment`] and the fourth derivative.
    fn eval_segment5(&self, k: usize, t: f64) -> [f64; 5] {
        let s = &self.segments[k];
        if let Law::Table(table) = &s.law {
            // the table's own lifts, from its first
            let y = table.eval5(t - self.starts[k]);
            return [
                self.levels[k] + y[0] - table.ends().0,
                y[1],
                y[2],
                y[3],
                y[4],
            ];
        }
        let b = s.extent;
        let y = s.law.normalized5((t - self.starts[k]) / b);
        [
            self.levels[k] + s.rise * y[0],
            s.rise * y[1] / b,
            s.rise * y[2] / (b * b),
            s.rise * y[3] / (b * b * b),
            s.rise * y[4] / (b * b * b * b),
        ]
    }

    /// The junctions where the motion is not smooth: for each, the lowest derivative that jumps
    /// (by more than `tolerance` relative to the program's scale of that derivative, the largest
    /// `|rise| / extent^order` of its segments).
    pub fn discontinuities(&self, tolerance: f64) -> Vec<Discontinuity> {
        let n = self.segments.len();
        let ends: Vec<[f64; 4]> = (0..n)
            .map(|k| self.eval_segment(k, self.starts[k] + self.segments[k].extent))
            .collect();
        let begins: Vec<[f64; 4]> = (0..n)
            .map(|k| self.eval_segment(k, self.starts[k]))
            .collect();
        // the program's own scale of each derivative: |rise| / extent^d
        let mut scale = [0.0f64; 4];
        for seg in &self.segments {
            for (d, sc) in scale.iter_mut().enumerate() {
                *sc = sc.max(seg.size() / seg.extent.powi(d as i32));
            }
        }
        let mut out = Vec::new();
        for (k, &b) in begins.iter().enumerate() {
            let a = ends[(k + n - 1) % n];
            if let Some(order) =
                (0..4).find(|&d| (a[d] - b[d]).abs() > tolerance * scale[d].max(1e-300))
            {
                out.push(Discontinuity {
                    at: self.starts[k],
                    segment: k,
                    order,
                    jump: b[order] - a[order],
                });
            }
        }
        out
    }

    /// `[s, s', s'', s''', s'''']` at cam angle `theta` (rad).
    pub fn eval5(&self, theta: f64) -> [f64; 5] {
        // within a turn already (as a sweep's angles mostly are): the same value without the
        // division's cost
        let t = if (0.0..TAU).contains(&theta) {
            theta
        } else {
            theta.rem_euclid(TAU)
        };
        // the starts are increasing: a binary search (a linear scan made a 100 000-segment program
        // quadratic to synthesise)
        let k = self.starts.partition_point(|&s| s <= t).saturating_sub(1);
        self.eval_segment5(k, t)
    }

    /// Cam angles where segments start (rad).
    pub fn starts(&self) -> &[f64] {
        &self.starts
    }

    /// The base position (at cam angle 0).
    pub fn base(&self) -> f64 {
        self.base
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fd(f: impl Fn(f64) -> f64, x: f64, h: f64) -> f64 {
        (f(x - 2.0 * h) - 8.0 * f(x - h) + 8.0 * f(x + h) - f(x + 2.0 * h)) / (12.0 * h)
    }

    #[test]
    fn every_law_rises_from_0_to_1_and_its_derivatives_agree_with_differences() {
        for law in Law::ALL {
            if law == Law::Dwell {
                assert_eq!(law.normalized(0.3), [0.0; 4]);
                continue;
            }
            let y0 = law.normalized(0.0);
            let y1 = law.normalized(1.0);
            assert!(
                y0[0].abs() < 1e-14 && (y1[0] - 1.0).abs() < 1e-12,
                "{}: {y0:?} {y1:?}",
                law.name()
            );
            for k in 1..40 {
                let x = (k as f64 + 0.37) / 41.0;
                // the piecewise laws' jerk jumps at the eighths: keep the stencil off them
                if matches!(law, Law::ModifiedTrapezoid | Law::ModifiedSine)
                    && ((x * 8.0) - (x * 8.0).round()).abs() < 1e-2
                {
                    continue;
                }
                let e = law.normalized(x);
                for d in 0..3 {
                    let num = fd(|t| law.normalized(t)[d], x, 1e-4);
                    let scale = 1.0 + e[d + 1].abs();
                    assert!(
                        (num - e[d + 1]).abs() < 1e-6 * scale,
                        "{} d{} at {x}: {num} vs {}",
                        law.name(),
                        d + 1,
                        e[d + 1]
                    );
                }
            }
        }
    }

    /// The clearance ramp: at rest (velocity, acceleration and jerk zero) at both ends, its
    /// height 1 at the end, its velocity 4/3 and nothing else over its middle half, where its
    /// height runs from 1/6 to 5/6 (what a clearance taken up at its constant speed must lie
    /// between).
    #[test]
    fn the_ramp_is_constant_velocity_between_blends_from_rest() {
        let r = |x: f64| Law::Ramp.normalized5(x);
        for d in 1..4 {
            assert!(
                r(0.0)[d].abs() < 1e-15 && r(1.0)[d].abs() < 1e-15,
                "derivative {d}"
            );
        }
        assert!(r(0.0)[0].abs() < 1e-15 && (r(1.0)[0] - 1.0).abs() < 1e-15);
        assert!((r(0.25)[0] - 1.0 / 6.0).abs() < 1e-15 && (r(0.75)[0] - 5.0 / 6.0).abs() < 1e-15);
        for k in 0..=100 {
            let x = 0.25 + 0.5 * k as f64 / 100.0;
            let y = r(x);
            assert!((y[1] - 4.0 / 3.0).abs() < 1e-14, "{x}: {y:?}");
            assert!(y[2].abs() < 1e-12 && y[3].abs() < 1e-10, "{x}: {y:?}");
            assert!((y[0] - (1.0 / 6.0 + 4.0 / 3.0 * (x - 0.25))).abs() < 1e-14);
        }
    }

    #[test]
    fn snap_is_the_derivative_of_jerk() {
        for law in Law::ALL {
            for k in 1..40 {
                let x = (k as f64 + 0.37) / 41.0;
                if matches!(law, Law::ModifiedTrapezoid | Law::ModifiedSine)
                    && ((x * 8.0) - (x * 8.0).round()).abs() < 1e-2
                {
                    continue;
                }
                let num = fd(|t| law.normalized(t)[3], x, 1e-4);
                let e = law.snap(x);
                assert!(
                    (num - e).abs() < 1e-5 * (1.0 + e.abs()),
                    "{} at {x}: {num} vs {e}",
                    law.name()
                );
            }
        }
    }

    #[test]
    fn boundary_values_define_the_laws() {
        let zero = |law: &Law, d: usize| {
            let (a, b) = (law.normalized(0.0)[d], law.normalized(1.0)[d]);
            a.abs() < 1e-10 && b.abs() < 1e-10
        };
        for law in [
            Law::Cycloidal,
            Law::Polynomial345,
            Law::Polynomial4567,
            Law::ModifiedTrapezoid,
            Law::ModifiedSine,
        ] {
            assert!(
                zero(&law, 1) && zero(&law, 2),
                "{}: velocity and acceleration vanish at both ends",
                law.name()
            );
        }
        assert!(zero(&Law::Polynomial4567, 3), "4-5-6-7: jerk vanishes too");
        assert!(
            zero(&Law::SimpleHarmonic, 1) && !zero(&Law::SimpleHarmonic, 2),
            "harmonic: velocity vanishes, acceleration does not"
        );
        // known peak accelerations (normalised): cycloidal 2π, 3-4-5 5.7735, mod. trapezoid 4.8881, mod. sine 5.5280
        let peak = |law: Law| {
            (0..=10000)
                .map(|k| law.normalized(k as f64 / 1e4)[2].abs())
                .fold(0.0, f64::max)
        };
        assert!((peak(Law::Cycloidal) - TAU).abs() < 1e-6);
        assert!((peak(Law::Polynomial345) - 10.0 / 3f64.sqrt()).abs() < 1e-6);
        assert!(
            (peak(Law::ModifiedTrapezoid) - 4.8881).abs() < 1e-3,
            "{}",
            peak(Law::ModifiedTrapezoid)
        );
        assert!(
            (peak(Law::ModifiedSine) - 5.5280).abs() < 1e-3,
            "{}",
            peak(Law::ModifiedSine)
        );
        // the piecewise laws are C² inside (continuous acceleration)
        for law in [Law::ModifiedTrapezoid, Law::ModifiedSine] {
            for &x in &[0.125, 0.375, 0.625, 0.875] {
                let (a, b) = (law.normalized(x - 1e-9)[2], law.normalized(x + 1e-9)[2]);
                assert!(
                    (a - b).abs() < 1e-6,
                    "{} acceleration at {x}: {a} vs {b}",
                    law.name()
                );
            }
        }
    }

    #[test]
    fn program_covers_a_revolution_and_reports_junctions() {
        let d = |x: f64| x.to_radians();
        let p = Program::new(
            0.0,
            vec![
                Segment {
                    law: Law::Cycloidal,
                    rise: 1.2,
                    extent: d(120.0),
                },
                Segment {
                    law: Law::Dwell,
                    rise: 0.0,
                    extent: d(60.0),
                },
                Segment {
                    law: Law::SimpleHarmonic,
                    rise: -1.2,
                    extent: d(120.0),
                },
                Segment {
                    law: Law::Dwell,
                    rise: 0.0,
                    extent: d(60.0),
                },
            ],
        )
        .unwrap();
        assert!((p.eval(d(120.0))[0] - 1.2).abs() < 1e-12);
        assert!((p.eval(d(60.0))[1] - 1.2 * 2.0 / d(120.0)).abs() < 1e-12); // cycloidal mid-velocity 2h/β
        let j = p.discontinuities(1e-9);
        // cycloidal joins dwells smoothly up to acceleration (jerk jumps); harmonic jumps in acceleration
        let at = |deg: f64| {
            j.iter()
                .find(|x| (x.at - d(deg)).abs() < 1e-12)
                .map(|x| x.order)
        };
        assert_eq!(at(0.0), Some(3));
        assert_eq!(at(120.0), Some(3));
        assert_eq!(at(180.0), Some(2));
        assert_eq!(at(300.0), Some(2));
        assert!(matches!(
            Program::new(
                0.0,
                vec![Segment {
                    law: Law::Cycloidal,
                    rise: 1.0,
                    extent: TAU
                }]
            ),
            Err(MotionError::NotClosed { .. })
        ));
        assert!(matches!(
            Program::new(
                0.0,
                vec![Segment {
                    law: Law::Dwell,
                    rise: 0.0,
                    extent: 3.0
                }]
            ),
            Err(MotionError::NotARevolution { .. })
        ));
    }

    #[test]
    fn the_segment_search_finds_the_segment_of_every_angle() {
        // 1000 segments, alternately rising and returning: at every angle the binary search
        // picks the segment a linear scan picks, ends and starts included
        let n = 1000;
        let segments: Vec<Segment> = (0..n)
            .map(|i| Segment {
                law: Law::Cycloidal,
                rise: if i % 2 == 0 { 0.5 } else { -0.5 },
                extent: TAU / n as f64,
            })
            .collect();
        let p = Program::new(0.0, segments).unwrap();
        for k in 0..=20_000 {
            let t = (k as f64 * TAU / 20_000.0).rem_euclid(TAU);
            let linear = p.starts.iter().rposition(|&s| s <= t).unwrap_or(0);
            assert_eq!(p.eval(t), p.eval_segment(linear, t), "at {t}");
        }
    }
}
