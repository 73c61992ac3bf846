//! What the closed-form rates of a named follower kind share ([`super::Kind::rates`]).
//!
//! At a converged first touch the tangency conditions `F(u, q) = 0` hold at every instant, so
//! their time derivatives vanish too. The cam point `x(u, t)` turns with the cam: with `y = x −
//! cam axis` and `J` the quarter turn, `ẏ = ω J y + u̇ x'` and `ẍ = b + ü x'`, where
//!
//! `b = α J y − ω² y + 2 ω u̇ J x' + u̇² x''`.
//!
//! Each kind solves the first derivative of its two conditions for `(u̇, q̇)` and the second for
//! `q̈`, in which `ü` drops out (its coefficient is a tangency condition). These are the
//! follower's velocity and acceleration without the paper's general machinery (normals, sliding
//! rates, body states, the constraint row), for [`crate::cam::Motion`]: the motion-only fast path.
//! They share no formula with the paper's method, which [`crate::cam::Mechanism::analyze`] keeps
//! using; the two agree to rounding (tested in `tests/it/motion_closed_form.rs`).

use crate::body::WorldDerivs;
use crate::geometry::{rot90, Point2, Vec2};

/// A converged contact point on the cam, world frame, and the cam's motion.
#[derive(Debug, Clone, Copy)]
pub(crate) struct CamPoint {
    /// the point `x`
    pub(crate) x: Point2,
    /// `x − cam axis`
    pub(crate) y: Vec2,
    /// `∂x/∂u`
    pub(crate) x1: Vec2,
    /// `∂²x/∂u²`
    pub(crate) x2: Vec2,
    /// the cam's angular velocity `ω` (counter-clockwise positive), rad/s
    pub(crate) w: f64,
    /// the cam's angular acceleration `α`, rad/s²
    pub(crate) a: f64,
}

impl CamPoint {
    #[inline(always)]
    pub(crate) fn new(e: &WorldDerivs, cam_axis: Point2, w: f64, a: f64) -> Self {
        Self {
            x: e.p,
            y: e.p - cam_axis,
            x1: e.d1,
            x2: e.d2,
            w,
            a,
        }
    }

    /// The velocity `ω J y` of the cam's material point at `x`.
    #[inline(always)]
    pub(crate) fn material_velocity(&self) -> Vec2 {
        self.w * rot90(self.y)
    }

    /// `b = α J y − ω² y + 2 ω u̇ J x' + u̇² x''`: the contact point's acceleration but its
    /// `ü x'` term, for the cam parameter's rate `ud`.
    #[inline(always)]
    pub(crate) fn acceleration_but_tangential(&self, ud: f64) -> Vec2 {
        let w = self.w;
        self.a * rot90(self.y) - (w * w) * self.y
            + (2.0 * w * ud) * rot90(self.x1)
            + (ud * ud) * self.x2
    }
}

/// The tolerances the paper's method refuses a contact by, which the closed forms decline by
/// (with a margin, so that a contact the method would refuse always reaches it and gets its
/// error): a follower locked by a normal perpendicular to its motion, conformal curvatures.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Refusals {
    /// [`crate::cam::AnalysisOptions::lock_tolerance`] times the margin
    pub(crate) lock: f64,
    /// [`crate::cam::AnalysisOptions::conformal_tolerance`] times the margin
    pub(crate) conformal: f64,
}

impl Refusals {
    /// How much wider than the method's own tolerances the closed forms decline.
    const MARGIN: f64 = 4.0;

    pub(crate) fn new(lock_tolerance: f64, conformal_tolerance: f64) -> Self {
        Self {
            lock: Self::MARGIN * lock_tolerance,
            conformal: Self::MARGIN * conformal_tolerance,
        }
    }
}

/// `Some(rates)` when all three are finite (and their sum does not overflow, beyond 1.8e308:
/// declined, the general step then computes them).
#[inline(always)]
pub(crate) fn finite(r: [f64; 3]) -> Option<[f64; 3]> {
    // a sum holding an infinity or a NaN is one (∞ − ∞ is NaN): one test for the three, half
    // the instructions of three `is_finite`
    (r[0] + r[1] + r[2]).is_finite().then_some(r)
}

/// The roller's relative-curvature denominator `D = x''·m + |x'|²` (`m = x − roller centre`),
/// or `None` where the cam's curvature matches the roller's within the tolerance (the paper's
/// `|κ_b − σ κ_a| ≤ tol (|κ_a| + |κ_b|)`: with `m ⟂ x'`, `x''·m = ±κ_a r |x'|²`).
#[inline(always)]
pub(crate) fn roller_denominator(c: &CamPoint, m: Vec2, refuse: &Refusals) -> Option<f64> {
    let (x2m, g) = (c.x2.dot(&m), c.x1.norm_squared());
    let den = x2m + g;
    (den.abs() > refuse.conformal * (g + x2m.abs())).then_some(den)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cam::follower::{Follower, Kind, Rates as _, Sense};

    /// One test for three rates declines any infinity or NaN among them, wherever it sits,
    /// and keeps finite ones of any sign and size (short of a sum beyond 1.8e308).
    #[test]
    fn finite_declines_any_infinity_or_nan() {
        let bad = [f64::INFINITY, f64::NEG_INFINITY, f64::NAN];
        let good = [0.0, -0.0, 1e-300, -3.5, 1e300, -1e300];
        for &b in &bad {
            for &g in &good {
                for k in 0..3 {
                    let mut r = [g, -g, g];
                    r[k] = b;
                    assert_eq!(finite(r), None, "{r:?}");
                }
            }
        }
        assert_eq!(finite([f64::INFINITY, f64::NEG_INFINITY, 1.0]), None);
        for &a in &good {
            for &b in &good {
                assert_eq!(finite([a, b, -a]), Some([a, b, -a]));
            }
        }
    }

    fn at(x: [f64; 2], x1: [f64; 2], x2: [f64; 2]) -> CamPoint {
        let e = WorldDerivs {
            p: Point2::new(x[0], x[1]),
            d1: Vec2::new(x1[0], x1[1]),
            d2: Vec2::new(x2[0], x2[1]),
            d3: Vec2::zeros(),
        };
        CamPoint::new(&e, Point2::origin(), 3.0, 0.5)
    }

    /// Each kind declines where the paper's method refuses (locked, conformal) and answers
    /// next to it.
    #[test]
    fn closed_forms_decline_where_the_method_refuses() {
        let refuse = Refusals::new(1e-9, 1e-9);
        // each kind at its position `q`: (contact point, x', x'', answers)
        type Case = ([f64; 2], [f64; 2], [f64; 2], bool);
        let check = |f: Follower, q: f64, cases: &[Case]| {
            let model = f.model(Point2::origin()).unwrap();
            for &(p, d1, d2, answers) in cases {
                let got = model.rates(&at(p, d1, d2), &model.pose(q), &refuse);
                assert_eq!(got.is_some(), answers, "{f:?} at {p:?}, {d1:?}, {d2:?}");
            }
        };
        // a flat face along y on a cam straight at the contact (x'' ∥ the face): conformal
        check(
            Follower::TranslatingFlat {
                direction: Vec2::y(),
            },
            2.0,
            &[
                ([0.0, 2.0], [1.0, 0.0], [1.0, 0.0], false),
                ([0.0, 2.0], [1.0, 0.0], [0.0, -1.0], true),
            ],
        );
        // a roller of radius 1 on the y axis, centre at the origin (q = 0): the normal along x,
        // perpendicular to the travel, is locked; below the roller, curved as the roller
        // (concave, radius 1), conformal
        check(
            Follower::TranslatingRoller {
                direction: Vec2::y(),
                offset: 0.0,
                roller_radius: 1.0,
            },
            0.0,
            &[
                ([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], false),
                ([0.0, -1.0], [1.0, 0.0], [0.0, 1.0], false),
                ([0.0, -1.0], [1.0, 0.0], [0.0, 0.5], true),
            ],
        );
        // a knife along y whose profile runs along its line of travel: locked
        check(
            Follower::TranslatingKnife {
                direction: Vec2::y(),
                offset: 0.0,
            },
            2.0,
            &[
                ([0.0, 2.0], [0.0, 1.0], [1.0, 0.0], false),
                ([0.0, 2.0], [1.0, 0.2], [0.0, -1.0], true),
            ],
        );
        // an arm pivoted at (−3, 2), face offset 0, at φ = 0 (the face is the line y = 2): the
        // contact right under the pivot is locked
        check(
            Follower::OscillatingFlat {
                pivot: Point2::new(-3.0, 2.0),
                face_offset: 0.0,
                closing: Sense::Cw,
                initial_angle: 0.0,
            },
            0.0,
            &[
                ([-3.0, 2.0], [1.0, 0.0], [0.0, -1.0], false),
                ([0.5, 2.0], [1.0, 0.0], [0.0, -1.0], true),
            ],
        );
        // an arm of length 3 pivoted at (−3, 0), roller radius 1 centred at the origin: a
        // contact on the arm's line has its normal through the pivot (locked); below it as the
        // translating roller
        check(
            Follower::OscillatingRoller {
                pivot: Point2::new(-3.0, 0.0),
                arm_length: 3.0,
                roller_radius: 1.0,
                closing: Sense::Cw,
                initial_angle: 0.0,
            },
            0.0,
            &[
                ([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], false),
                ([0.0, -1.0], [1.0, 0.0], [0.0, 0.5], true),
                ([0.0, -1.0], [1.0, 0.0], [0.0, 1.0], false),
            ],
        );
    }
}
