//! What a follower kind implements: [`Kind`] (joint, curve, first-touch geometry, the tangency
//! residual Newton solves) with [`Rates`] (closed-form rates) and [`Synthesis`] (the envelope a
//! motion program is synthesised through); and the one enum of the kinds with its dispatch.

use super::*;

/// A kind's rates in closed form: the motion-only path of a warm step.
pub(crate) trait Rates {
    /// The follower's velocity `q̇`, acceleration `q̈` and the cam parameter's rate `u̇`, as
    /// `[q̇, q̈, u̇]`, at the converged first touch `c` at position `q`, in closed form from the
    /// tangency conditions differentiated in time (see the `rates` module): the motion-only
    /// path. `None` for a kind without them, or where a denominator is within `refuse` of zero
    /// (the caller then runs the paper's method, which refuses with its reason or answers).
    fn rates(&self, _c: &CamPoint, _q: &Pose, _refuse: &Refusals) -> Option<[f64; 3]> {
        None
    }
}

/// What a kind gives the synthesis of a profile from a motion program.
pub(crate) trait Synthesis {
    /// Synthesis: the follower's position `q₀` (length, or arm angle) where it rests on the base
    /// circle of radius `base_radius` (the program's zero).
    fn synthesis_start(&self, base_radius: f64) -> Result<f64, CamError>;
    /// Synthesis: the profile point touching the follower at cam angle `u`, with `s` the
    /// program's value and four derivatives (`s₀` added to the value), `σ` the cam's sense and
    /// `rot = R(−σu)`.
    fn envelope(&self, s: &[f64; 5], s0: f64, u: f64, sigma: f64, rot: &Rotation) -> Envelope;
}

/// What each follower kind implements, once, in its own file: its joint and curve, the
/// first-touch geometry (the score of a cam point, its bounds for pruning, the tangency residual
/// Newton solves and its Jacobian), with its closed-form rates and its synthesis envelope as the
/// supertraits [`Rates`] and [`Synthesis`].
pub(crate) trait Kind: Rates + Synthesis {
    /// The joint that carries the follower.
    fn joint(&self) -> FollowerJoint;
    /// The contact curve in the follower's frame, oriented material-on-the-left.
    fn curve(&self) -> FollowerCurve;
    /// The position at which the follower's boundary first passes through the world cam point
    /// `x`, oriented so that larger is "touches earlier" (the first touch is the maximum), or
    /// `None` when the follower never touches `x`. Returns `(oriented score, q)`.
    fn score(&self, x: Point2) -> Option<(f64, f64)>;
    /// The position is an angle whose sine and cosine [`Kind::pose`] keeps (a sweep then
    /// carries them from step to step); else a length.
    const ANGULAR: bool = false;
    /// The position `q` as a [`Pose`]: with its sine and cosine for an arm angle (the methods
    /// below read them there instead of calling `sin_cos`), without for a length.
    #[inline(always)]
    fn pose(&self, q: f64) -> Pose {
        if Self::ANGULAR {
            Pose::angle(q)
        } else {
            Pose::length(q)
        }
    }
    /// The position `q` reached from `from` (a Newton step, a sweep's step): for an arm angle its
    /// sine and cosine carried by angle addition where the step is small.
    #[inline(always)]
    fn pose_from(&self, from: Pose, q: f64) -> Pose {
        if Self::ANGULAR {
            from.angle_to(q)
        } else {
            Pose::length(q)
        }
    }
    /// Whether a converged tangency at world cam point `x` and position `q` is the follower's
    /// first touch through `x` (the position of [`Kind::score`], within `slack`), not its
    /// boundary's later crossing of `x`. A kind may answer by a cheaper equivalent test.
    #[inline(always)]
    fn is_first_through(&self, x: Point2, q: &Pose, slack: f64) -> bool {
        matches!(self.score(x), Some((_, qs)) if (qs - q.q).abs() <= slack)
    }
    /// An interval `(mid, half width)` of positions holding the `q` of [`Kind::score`] at every
    /// world point within `r` of `c` (rounding included), for pruning the first-touch search;
    /// `None` when the follower touches none of them. The default bounds nothing.
    fn score_interval(&self, _c: Point2, _r: f64) -> Option<(f64, f64)> {
        Some((0.0, f64::INFINITY))
    }
    /// The world tangent directions `(mid, half width)`, rad, modulo a half turn, at which the
    /// score of a curve passing within `r` of `c` can be stationary (the follower's contact
    /// tangent there): along a piece of curve whose tangent avoids them the score is monotone.
    /// `None` when any direction can be.
    fn stationary_tangents(&self, _c: Point2, _r: f64) -> Option<(f64, f64)> {
        None
    }
    /// Residual of the tangency conditions at world cam point `x` (with `x1 = ∂x/∂u`) and
    /// position `q`: two equations, zero at a touch. Generic so that the jerk can be computed by
    /// differentiating it with jets.
    fn residual_value<T: Num>(&self, x: V2<T>, x1: V2<T>, q: T) -> [T; 2];
    /// [`Kind::residual_value`] at cam point `e` and position `q` (Newton's).
    #[inline(always)]
    fn residual(&self, e: &WorldDerivs, q: &Pose) -> [f64; 2] {
        self.residual_value(V2::c(e.p.coords), V2::c(e.d1), q.q)
    }
    /// `∂(residual)/∂(u, q)` at cam point `e` and position `q`.
    fn jacobian(&self, e: &WorldDerivs, q: &Pose) -> [[f64; 2]; 2];
    /// Newton's step `(δu, δq)` at cam point `e` and position `q`: `J δ = −residual`, non-finite
    /// where `J` is singular. A kind whose `J` has a zero may solve it by substitution.
    #[inline(always)]
    fn newton_step(&self, e: &WorldDerivs, q: &Pose) -> [f64; 2] {
        crate::cam::linear::solve2(&self.jacobian(e, q), self.residual(e, q))
    }
    /// A direction from the contact point `c` into the follower at position `q`: along it the
    /// cam's outward normal must point at a genuine touch (the cam's back side, or a roller
    /// touching from inside, fail this).
    fn toward_follower(&self, c: Point2, q: &Pose) -> Vec2;
    /// Refuses a follower that can never touch a cam reaching `size` from its axis.
    fn check_reach(&self, _size: f64) -> Result<(), CamError> {
        Ok(())
    }
    /// The signed curvature (of a counter-clockwise profile) below which the follower cannot
    /// follow the profile: 0 under a flat face, `−1/r` under a roller; `None` for a point.
    fn concave_limit(&self) -> Option<f64>;
    /// The path of the follower's reference point (a knife's tip, a roller's centre) and its
    /// distance from the cam's boundary at a touch (0, the roller's radius): the first touch is
    /// the extreme crossing of that path with the profile's outward offset curve at that
    /// distance (the pitch curve), found by sign changes whatever the roller's size. `None` for
    /// a flat face.
    fn centre_path(&self) -> Option<(CentrePath, f64)> {
        None
    }
    /// The roller's radius.
    fn roller_radius(&self) -> Option<f64> {
        None
    }
}

/// A follower kind with its derived data: one variant per kind.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Model {
    TranslatingFlat(TranslatingFlat),
    TranslatingRoller(TranslatingRoller),
    TranslatingKnife(TranslatingKnife),
    OscillatingFlat(OscillatingFlat),
    OscillatingRoller(OscillatingRoller),
    OscillatingKnife(OscillatingKnife),
    Carried(carried::CarriedJoint),
}

/// Calls `$body` with `$k` bound to the kind inside a `Model`.
macro_rules! dispatch {
    ($model:expr, $k:ident => $body:expr) => {
        match $model {
            $crate::cam::follower::Model::TranslatingFlat($k) => $body,
            $crate::cam::follower::Model::TranslatingRoller($k) => $body,
            $crate::cam::follower::Model::TranslatingKnife($k) => $body,
            $crate::cam::follower::Model::OscillatingFlat($k) => $body,
            $crate::cam::follower::Model::OscillatingRoller($k) => $body,
            $crate::cam::follower::Model::OscillatingKnife($k) => $body,
            $crate::cam::follower::Model::Carried($k) => $body,
        }
    };
}

pub(crate) use dispatch;

impl Kind for Model {
    // some kinds are: a sweep through `Model` keeps the pose
    const ANGULAR: bool = true;
    fn joint(&self) -> FollowerJoint {
        dispatch!(self, k => k.joint())
    }
    fn curve(&self) -> FollowerCurve {
        dispatch!(self, k => k.curve())
    }
    #[inline]
    fn score(&self, x: Point2) -> Option<(f64, f64)> {
        dispatch!(self, k => k.score(x))
    }
    #[inline]
    fn score_interval(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        dispatch!(self, k => k.score_interval(c, r))
    }
    fn stationary_tangents(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        dispatch!(self, k => k.stationary_tangents(c, r))
    }
    #[inline]
    fn pose(&self, q: f64) -> Pose {
        dispatch!(self, k => k.pose(q))
    }
    #[inline]
    fn pose_from(&self, from: Pose, q: f64) -> Pose {
        dispatch!(self, k => k.pose_from(from, q))
    }
    #[inline]
    fn is_first_through(&self, x: Point2, q: &Pose, slack: f64) -> bool {
        dispatch!(self, k => k.is_first_through(x, q, slack))
    }
    fn residual_value<T: Num>(&self, x: V2<T>, x1: V2<T>, q: T) -> [T; 2] {
        dispatch!(self, k => k.residual_value(x, x1, q))
    }
    #[inline]
    fn residual(&self, e: &WorldDerivs, q: &Pose) -> [f64; 2] {
        dispatch!(self, k => k.residual(e, q))
    }
    #[inline]
    fn jacobian(&self, e: &WorldDerivs, q: &Pose) -> [[f64; 2]; 2] {
        dispatch!(self, k => k.jacobian(e, q))
    }
    #[inline]
    fn newton_step(&self, e: &WorldDerivs, q: &Pose) -> [f64; 2] {
        dispatch!(self, k => k.newton_step(e, q))
    }
    #[inline]
    fn toward_follower(&self, c: Point2, q: &Pose) -> Vec2 {
        dispatch!(self, k => k.toward_follower(c, q))
    }
    fn check_reach(&self, size: f64) -> Result<(), CamError> {
        dispatch!(self, k => k.check_reach(size))
    }
    fn concave_limit(&self) -> Option<f64> {
        dispatch!(self, k => k.concave_limit())
    }
    fn centre_path(&self) -> Option<(CentrePath, f64)> {
        dispatch!(self, k => k.centre_path())
    }
    fn roller_radius(&self) -> Option<f64> {
        dispatch!(self, k => k.roller_radius())
    }
}

impl Rates for Model {
    #[inline(always)]
    fn rates(&self, c: &CamPoint, q: &Pose, refuse: &Refusals) -> Option<[f64; 3]> {
        dispatch!(self, k => k.rates(c, q, refuse))
    }
}

impl Synthesis for Model {
    fn synthesis_start(&self, base_radius: f64) -> Result<f64, CamError> {
        dispatch!(self, k => k.synthesis_start(base_radius))
    }
    #[inline]
    fn envelope(&self, s: &[f64; 5], s0: f64, u: f64, sigma: f64, rot: &Rotation) -> Envelope {
        dispatch!(self, k => k.envelope(s, s0, u, sigma, rot))
    }
}
