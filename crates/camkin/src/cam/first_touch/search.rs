//! The first-touch search: Newton on the tangency residual, the test that a tangency is the
//! first touch, and the global search (bracketing samples of the first-touch function, the best
//! local maxima refined by Newton).

use super::starts::Candidates;
use super::FirstTouch;
use crate::body::{curve_in, CurveInFrame, WorldDerivs};
use crate::cam::follower::rates::Refusals;
use crate::cam::follower::{dispatch, pitch_point, CentrePath, Kind};
use crate::cam::instant::Instant;
use crate::cam::pose::Pose;
use crate::cam::{CamError, StopReason};
use crate::curve::{Curve, Derivs};
use crate::geometry::{Frame, Point2};

/// A converged first touch: cam parameter and follower position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Touch {
    pub(crate) u: f64,
    pub(crate) q: f64,
    /// the follower curve's parameter at the contact (a carried curve's; 0 for the named kinds,
    /// whose contact curve gives it in closed form)
    pub(crate) v: f64,
    /// the contact is at a corner of this curve (its parameter there is exact), not a tangency
    pub(crate) corner: Option<crate::cam::Corner>,
}

/// What Newton converged to: the touch, the position as a [`Pose`], and the cam point of
/// the last iterate (within the position tolerance of the converged one).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Converged {
    pub(crate) touch: Touch,
    pub(crate) pose: Pose,
    pub(crate) last: WorldDerivs,
}

/// Newton's constants and the first-touch slack, prepared from the options once
/// ([`Mechanism::set_options`]): a warm step reads them.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Prepared {
    /// `1 / position tolerance`
    inv_tol: f64,
    /// `(newton_contraction · tolerance)²`
    c2: f64,
    /// the follower coordinate's length scale over the tolerance
    q_over_tol: f64,
    /// the largest step of the cam parameter (a fraction of the period)
    lim: f64,
    /// [`AnalysisOptions::touch_tolerance`] in units of the follower coordinate
    touch_slack: f64,
    /// where the closed-form rates decline
    pub(crate) refuse: Refusals,
}

impl Prepared {
    /// Newton's test on a step whose squared length, in units of the tolerance, is `step2`:
    /// `δ ≤ tol`, or `C δ² ≤ tol` (the next step would be below the tolerance).
    #[inline(always)]
    fn accepts(&self, step2: f64) -> bool {
        step2 <= 1.0 || self.c2 * step2 * step2 <= 1.0
    }

    pub(crate) fn new(options: &crate::cam::AnalysisOptions, q_scale: f64, period: f64) -> Self {
        let tol = options.position_tolerance;
        let ct = options.newton_contraction * tol;
        Self {
            inv_tol: 1.0 / tol,
            c2: ct * ct,
            q_over_tol: q_scale / tol,
            lim: options.max_step_fraction * period,
            touch_slack: options.touch_tolerance / q_scale,
            refuse: Refusals::new(options.lock_tolerance, options.conformal_tolerance),
        }
    }
}

impl FirstTouch {
    /// The follower coordinate's length scale: 1 for a length; for an arm angle the cam's size
    /// plus the pivot's distance from the cam's axis (the farthest a contact can be from the pivot).
    pub(crate) fn q_scale(&self) -> f64 {
        self.geometry.q_length_scale(self.size)
    }

    /// The cam parameter `u` taken into `[0, period)` (no division when it is there already).
    #[inline(always)]
    fn in_period(&self, u: f64) -> f64 {
        if (0.0..self.period).contains(&u) {
            u
        } else {
            u.rem_euclid(self.period)
        }
    }

    /// [`AnalysisOptions::touch_tolerance`] in units of the follower coordinate.
    #[inline(always)]
    pub(crate) fn touch_slack(&self) -> f64 {
        self.prepared.touch_slack
    }

    /// Newton on the tangency residual from `(u, q)`.
    pub(crate) fn newton(&self, at: &Instant, u: f64, q: f64) -> Result<Touch, CamError> {
        self.newton_at(at, u, q).map(|(t, _)| t)
    }

    /// Newton on the tangency residual from `(u, q)`; also returns the cam point of the last
    /// iterate (within the position tolerance of the converged one).
    #[inline]
    pub(crate) fn newton_at(
        &self,
        at: &Instant,
        u: f64,
        q: f64,
    ) -> Result<(Touch, WorldDerivs), CamError> {
        let profile = self.cam.profile.as_ref();
        dispatch!(&self.geometry.model, k => self
            .newton_with(k, profile, at, u, k.pose(q))
            .map(|c| (c.touch, c.last)))
    }

    /// [`Mechanism::newton_at`] for the follower kind `k` (the mechanism's own) on the cam's
    /// `profile` (as its own type or `dyn Curve`): monomorphised, so that a warm step inlines
    /// the kind's residual and Jacobian and, on a spline, the spline's evaluation. Starts from
    /// the position `pose` (an arm angle's sine and cosine are carried along the steps).
    #[inline(always)]
    pub(crate) fn newton_with<K: Kind, C: Curve + ?Sized>(
        &self,
        k: &K,
        profile: &C,
        at: &Instant,
        mut u: f64,
        mut pose: Pose,
    ) -> Result<Converged, CamError> {
        let (theta, frame) = (at.theta, &at.frame);
        // in units of the tolerance (squares of lengths could underflow at extreme sizes):
        // a step δ is accepted when δ ≤ tol, or when C δ² ≤ tol (the next step would be below
        // the tolerance): (δ/tol)² ≤ 1 or (C tol)² (δ/tol)⁴ ≤ 1
        let Prepared {
            inv_tol,
            q_over_tol,
            lim,
            ..
        } = self.prepared;
        for _ in 0..self.options.max_iterations {
            let e = curve_in(frame, profile, u);
            let [du, dq] = k.newton_step(&e, &pose);
            if !(du.is_finite() && dq.is_finite()) {
                return Err(CamError::NoConvergence {
                    angle_deg: theta.to_degrees(),
                    reason: StopReason::SingularJacobian,
                });
            }
            // a step stays within a fraction of the period (safeguard against wild steps)
            let du = du.clamp(-lim, lim);
            u += du;
            pose = k.pose_from(pose, pose.q + dq);
            let (su, sq) = (du * inv_tol, dq * q_over_tol);
            let step2 = (su * su * e.d1.norm_squared()).max(sq * sq);
            if self.prepared.accepts(step2) {
                let touch = Touch {
                    u: self.in_period(u),
                    q: pose.q,
                    v: 0.0,
                    corner: None,
                };
                return Ok(Converged {
                    touch,
                    pose,
                    last: e,
                });
            }
        }
        Err(CamError::NoConvergence {
            angle_deg: theta.to_degrees(),
            reason: StopReason::IterationLimit,
        })
    }

    /// A roller's warm Newton (radius `r > 0`, centre on `path`) in the cam parameter alone,
    /// from `u`: the roller's centre is the profile's pitch point ([`pitch_point`]) where
    /// that crosses the path, so the path's residual at the pitch point is one equation in
    /// `u`, whose derivative is `(1 + r κ)` times the gradient's component along `x'`. No
    /// arm angle is carried through the iterations; the caller takes the position from the
    /// converged pitch point ([`CentrePath::pose`]). Steps are accepted as by
    /// [`Mechanism::newton_with`], the centre's displacement measured both as a length and
    /// as the follower coordinate. Returns the converged `u` and the profile there (with
    /// `extrapolate`, from the last evaluation by Taylor series when the last step was below
    /// the tolerance: for a profile whose evaluation is costly).
    #[inline(always)]
    pub(crate) fn pitch_newton<C: Curve + ?Sized>(
        &self,
        (path, r): (CentrePath, f64),
        profile: &C,
        at: &Instant,
        mut u: f64,
        extrapolate: bool,
    ) -> Result<(f64, Derivs), CamError> {
        let (theta, frame) = (at.theta, &at.frame);
        let Prepared {
            inv_tol,
            q_over_tol,
            lim,
            ..
        } = self.prepared;
        // the larger by a comparison, not `max` (its NaN handling costs instructions; both are
        // set up finite)
        let along = q_over_tol * path.per_length();
        let per_tol = if along > inv_tol { along } else { inv_tol };
        // in the cam's frame: the path turned once, not the curve's three derivatives each
        // iteration (the pitch point's offset and stretch do not depend on the frame)
        let body = path.in_body(self.cam.pivot, frame);
        for _ in 0..self.options.max_iterations {
            let e = profile.eval(u);
            let (c, stretch) = pitch_point((e.p, e.d1, e.d2), r, self.orientation);
            let (f, g) = body.residual(Point2::origin(), c);
            let du = -f / (stretch * g.dot(&e.d1));
            if !du.is_finite() {
                return Err(CamError::NoConvergence {
                    angle_deg: theta.to_degrees(),
                    reason: StopReason::SingularJacobian,
                });
            }
            // clamped by comparisons (`du` is finite here): no NaN handling to pay for
            let du = if du > lim {
                lim
            } else if du < -lim {
                -lim
            } else {
                du
            };
            u += du;
            let s = du * stretch * per_tol;
            let step2 = s * s * e.d1.norm_squared();
            if extrapolate && step2 <= 1.0 {
                // a step below the tolerance: the curve at the new `u` by Taylor series from
                // this evaluation, not another evaluation (one of a synthesised profile costs
                // 900 instructions). The terms left out are `du` times the tolerance relative
                // to the size, and smaller for `p` and `d1`.
                let d = Derivs {
                    p: e.p + du * (e.d1 + (0.5 * du) * e.d2),
                    d1: e.d1 + du * e.d2,
                    d2: e.d2 + du * e.d3,
                    d3: e.d3,
                };
                return Ok((self.in_period(u), d));
            }
            if self.prepared.accepts(step2) {
                let u = self.in_period(u);
                return Ok((u, profile.eval(u)));
            }
        }
        Err(CamError::NoConvergence {
            angle_deg: theta.to_degrees(),
            reason: StopReason::IterationLimit,
        })
    }

    /// True when `(u, q)` is the follower's first touch through that cam point (not another
    /// tangency such as the cam's back side or a roller touching from inside).
    pub(crate) fn is_first_touch(&self, frame: &Frame, t: &Touch) -> bool {
        self.is_first_touch_at(&frame.curve_at(self.cam.profile.as_ref(), t.u), t.q)
    }

    /// [`Mechanism::is_first_touch`] with the cam point already evaluated.
    #[inline]
    pub(crate) fn is_first_touch_at(&self, e: &WorldDerivs, q: f64) -> bool {
        dispatch!(&self.geometry.model, k => self.is_first_touch_with(k, e, &k.pose(q)))
    }

    /// [`Mechanism::is_first_touch_at`] for the follower kind `k` (the mechanism's own).
    #[inline(always)]
    pub(crate) fn is_first_touch_with<K: Kind>(&self, k: &K, e: &WorldDerivs, q: &Pose) -> bool {
        if !self.faces_follower_with(k, e, q) {
            return false;
        }
        // on a cusp of a folded profile the tangency conditions hold trivially (r' = 0): the
        // follower rests on a corner there, which the contact method cannot describe
        if !self.convex && e.d1.norm_squared() < (1e-6 * self.mean_speed).powi(2) {
            return false;
        }
        if self.geometry.is_knife() {
            return true;
        }
        k.is_first_through(e.p, q, self.touch_slack())
    }

    /// A warm contact on a convex profile is the first touch: its normal faces the follower,
    /// and a roller's touch is the first of its cam point (a roller's Newton can leap: its
    /// residual bends on the scale of the roller's radius, which may be tiny).
    #[inline(always)]
    pub(crate) fn convex_warm_touch_with<K: Kind>(&self, k: &K, e: &WorldDerivs, q: &Pose) -> bool {
        self.faces_follower_with(k, e, q) && (!self.roller || self.is_first_touch_with(k, e, q))
    }

    /// Fails with [`StopReason::OnCusp`] when a cusp of a folded profile touches the follower
    /// before the contact at position `q`: the follower then rests on that corner.
    pub(crate) fn check_cusps(&self, at: &Instant, q: f64) -> Result<(), CamError> {
        let (theta, frame) = (at.theta, &at.frame);
        for &u in &self.cusps {
            let p = frame.curve_position(self.cam.profile.as_ref(), u);
            if let Some((score, _)) = self.geometry.model.score(p) {
                if score > self.oriented(q) + self.touch_slack() {
                    return Err(CamError::NoConvergence {
                        angle_deg: theta.to_degrees(),
                        reason: StopReason::OnCusp,
                    });
                }
            }
        }
        Ok(())
    }

    /// The cam's outward normal at `e` faces the follower at position `q` (the cam's back side
    /// and a roller touching from inside fail this). Only a sign: no normalisation.
    #[inline(always)]
    pub(crate) fn faces_follower_with<K: Kind>(&self, k: &K, e: &WorldDerivs, q: &Pose) -> bool {
        // outward normal ∝ −orientation · k × r'
        let outward = -self.orientation * crate::geometry::rot90(e.d1);
        outward.dot(&k.toward_follower(e.p, q)) > 0.0
    }

    /// Oriented score of a position (larger is an earlier touch).
    pub(crate) fn oriented(&self, q: f64) -> f64 {
        self.geometry.joint.oriented(q)
    }

    /// The peak of the first-touch function on `[a, b]` by golden-section search: `(u, q)`.
    pub(super) fn score_peak(&self, frame: &Frame, a: f64, b: f64) -> Option<(f64, f64)> {
        let profile = self.cam.profile.as_ref();
        let score = |u: f64| {
            self.geometry
                .model
                .score(frame.curve_position(profile, u))
                .map_or(f64::NEG_INFINITY, |s| s.0)
        };
        let (u, _) = crate::cam::golden::golden_min(|u| -score(u), a, b, 60, |_| false);
        let (_, q) = self
            .geometry
            .model
            .score(frame.curve_position(profile, u))?;
        Some((u.rem_euclid(self.period), q))
    }

    /// Global first touch. A convex profile's first-touch function has one maximum: its best
    /// coarse sample (for a knife edge, the outer crossing found by the coarse scan) is refined by
    /// Newton. Otherwise, or when that start fails, the best local maxima of the densely sampled
    /// function (the crossings, for a knife edge) are refined and the best first touch among them
    /// is kept.
    pub(crate) fn global_touch(&self, at: &Instant) -> Result<Touch, CamError> {
        let (theta, frame) = (at.theta, &at.frame);
        if let Some(c) = self.carried() {
            return self.carried_global(c, at);
        }
        let knife = self.geometry.is_knife();
        let on_path = self.geometry.model.centre_path().is_some();
        if self.convex {
            // a knife's or a roller's path crosses a convex (offset) profile twice: the coarse
            // scan finds the outer crossing unless the path only grazes it (then the dense scan)
            let start = if on_path {
                let mut c = Candidates::new(1);
                self.path_starts(frame, &self.index.coarse, &mut c);
                c.as_slice().first().copied()
            } else {
                self.best_sample(frame, &self.index.coarse)
            };
            if let Some((_, u0, q0)) = start {
                if let Ok(t) = self.newton(at, u0, q0) {
                    if self.is_first_touch(frame, &t) {
                        return Ok(t);
                    }
                }
            }
        }
        let mut starts = Candidates::new(self.options.candidates);
        let best_sample = if on_path {
            // starts from the crossings; a roller's sampled scores (exact first touches of the
            // points it reaches) still bound the result from below
            self.path_starts(frame, &self.index.dense, &mut starts);
            if self.roller {
                self.best_sample(frame, &self.index.dense)
                    .map_or(f64::NEG_INFINITY, |b| b.0)
            } else {
                f64::NEG_INFINITY
            }
        } else {
            self.score_starts(frame, &self.index.dense, &mut starts)
        };
        if starts.is_empty() {
            let reason = if knife && self.geometry.joint.is_rotating() {
                "the knife edge's circle about the pivot misses the cam"
            } else if knife {
                "the knife edge's line of travel misses the cam"
            } else if on_path {
                "the roller's path misses the cam"
            } else {
                "the follower cannot reach the cam"
            };
            return Err(CamError::NoTouch {
                angle_deg: theta.to_degrees(),
                reason,
            });
        }
        let mut best: Option<Touch> = None;
        let mut last_err = None;
        let spacing = self.period / self.index.dense.params.len().max(1) as f64;
        for &(score, u0, q0) in starts.as_slice() {
            // a start from which Newton wanders (the profile turning sharply near it, or a
            // corner next to a tangency) is first moved to the sampled maximum's peak by
            // golden-section search on the score. A wander shows as a failure or as a tangency
            // behind the sample it started from (a local maximum is never below its samples)
            let refined = || {
                let (u1, q1) = self.score_peak(frame, u0 - spacing, u0 + spacing)?;
                self.newton(at, u1, q1).ok()
            };
            let attempt = match self.newton(at, u0, q0) {
                Err(
                    e @ CamError::NoConvergence {
                        reason: StopReason::IterationLimit | StopReason::SingularJacobian,
                        ..
                    },
                ) if !on_path => refined().ok_or(e),
                Ok(t) if !on_path && self.oriented(t.q) < score - self.touch_slack() => {
                    Ok(refined().unwrap_or(t))
                }
                other => other,
            };
            match attempt {
                Ok(t) if self.is_first_touch(frame, &t) => {
                    if best.is_none_or(|b| self.oriented(t.q) > self.oriented(b.q)) {
                        best = Some(t);
                    }
                }
                Ok(_) => {
                    last_err = Some(CamError::NoConvergence {
                        angle_deg: theta.to_degrees(),
                        reason: StopReason::NotFirstTouch,
                    })
                }
                Err(e) => last_err = Some(e),
            }
        }
        // a corner of the cam (a gear's tip, a relief's start) on which the follower rests has
        // no tangency: it is the first touch when it is ahead of every tangency found and of
        // every sample (the first-touch function peaks at it)
        let corner = self.best_corner(frame).filter(|c| {
            let ahead = self.oriented(c.q) + self.touch_slack();
            ahead >= best_sample
                && best.is_none_or(|b| self.oriented(c.q) > self.oriented(b.q) + self.touch_slack())
        });
        if let Some(c) = corner {
            return Ok(c);
        }
        let best = best.ok_or_else(|| {
            last_err.unwrap_or(CamError::NoConvergence {
                angle_deg: theta.to_degrees(),
                reason: StopReason::NoCandidate,
            })
        })?;
        self.check_cusps(at, best.q)?;
        // the refined touch can only be later than (or equal to) a sampled one
        if self.oriented(best.q) < best_sample - self.touch_slack() {
            return Err(CamError::NoConvergence {
                angle_deg: theta.to_degrees(),
                reason: StopReason::BehindSample,
            });
        }
        Ok(best)
    }

    /// The cam corner a named follower touches first, as a touch at that corner (the follower's
    /// first-touch position through the corner's point).
    fn best_corner(&self, frame: &Frame) -> Option<Touch> {
        let mut best: Option<(f64, Touch)> = None;
        for &(u, p) in &self.corners.at {
            let world = frame * p;
            if let Some((score, q)) = self.geometry.model.score(world) {
                if best.as_ref().is_none_or(|b| score > b.0) {
                    best = Some((
                        score,
                        Touch {
                            u,
                            q,
                            v: 0.0,
                            corner: Some(crate::cam::Corner::Cam),
                        },
                    ));
                }
            }
        }
        best.map(|b| b.1)
    }
}

/// The same parameters as [`bracket_samples`], without storing them.
pub(crate) use crate::curve::piece_samples as bracket_params;

/// Parameters for bracketing: `per_piece` per smooth piece, or `per_curve` over the period.
pub(crate) fn bracket_samples(
    breakpoints: &[f64],
    period: f64,
    per_piece: usize,
    per_curve: usize,
) -> Vec<f64> {
    bracket_params(breakpoints, period, per_piece, per_curve).collect()
}

#[cfg(test)]
mod tests {
    use crate::cam::Mechanism;
    use crate::cam::*;
    fn paper() -> Mechanism {
        crate::reference::paper_mechanism(false)
    }

    #[test]
    fn back_side_stationary_point_is_not_a_first_touch() {
        let m = paper();
        let at = &crate::cam::Instant::new(m.cam(), 0.0);
        let frame = at.frame;
        // Newton from the far side converges to the leftmost point, a stationary point of x·d
        let back = m.touch.newton(at, 4.5, -2.8).unwrap();
        assert!(back.q < 0.0);
        assert!(!m.touch.is_first_touch(&frame, &back));
        let front = m.touch.newton(at, 0.1, 4.9).unwrap();
        assert!(m.touch.is_first_touch(&frame, &front));
        assert!((front.q - 5.0).abs() < 1e-14);
    }

    #[test]
    fn bracket_samples_cover_each_piece() {
        let s = bracket_samples(&[0.0, 1.0, 3.0], 4.0, 2, 5);
        assert_eq!(s, vec![0.0, 0.5, 1.0, 2.0, 3.0, 3.5]);
        assert_eq!(bracket_samples(&[], 1.0, 2, 4), vec![0.0, 0.25, 0.5, 0.75]);
        assert_eq!(
            bracket_params(&[0.0, 1.0, 3.0], 4.0, 2, 5).collect::<Vec<_>>(),
            s
        );
        assert_eq!(
            bracket_params(&[], 1.0, 2, 4).collect::<Vec<_>>(),
            vec![0.0, 0.25, 0.5, 0.75]
        );
    }
}
