//! The first-touch search: Newton on the tangency residual, the test that a tangency is the
//! first touch, and the global search (bracketing samples of the first-touch function, the best
//! local maxima refined by Newton).

use super::follower::Kind as _;
use super::{CamError, Mechanism, StopReason};
use crate::body::{CurveInFrame, WorldDerivs};
use crate::geometry::Frame;

/// A converged first touch: cam parameter and follower position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Touch {
    pub(crate) u: f64,
    pub(crate) q: f64,
}

impl Mechanism {
    fn q_scale(&self) -> f64 {
        self.geometry.q_length_scale(self.size)
    }

    /// [`AnalysisOptions::touch_tolerance`] in units of the follower coordinate.
    pub(crate) fn touch_slack(&self) -> f64 {
        self.options.touch_tolerance / self.q_scale()
    }

    /// Newton on the tangency residual from `(u, q)`.
    pub(crate) fn newton(
        &self,
        theta: f64,
        frame: &Frame,
        u: f64,
        q: f64,
    ) -> Result<Touch, CamError> {
        self.newton_at(theta, frame, u, q).map(|(t, _)| t)
    }

    /// Newton on the tangency residual from `(u, q)`; also returns the cam point of the last
    /// iterate (within the position tolerance of the converged one).
    #[inline]
    pub(crate) fn newton_at(
        &self,
        theta: f64,
        frame: &Frame,
        mut u: f64,
        mut q: f64,
    ) -> Result<(Touch, WorldDerivs), CamError> {
        let profile = self.cam.profile.as_ref();
        let tol = self.options.position_tolerance;
        let tol2 = tol * tol;
        // C² δ⁴ ≤ tol²: the next step would be below the tolerance
        let c2 = self.options.newton_contraction * self.options.newton_contraction;
        let qs = self.q_scale();
        let lim = self.options.max_step_fraction * self.period;
        for _ in 0..self.options.max_iterations {
            let e = frame.curve_at(profile, u);
            let (f, j) = self.geometry.residual(&e, q);
            let inv_det = 1.0 / (j[0][0] * j[1][1] - j[0][1] * j[1][0]);
            let du = (-f[0] * j[1][1] + f[1] * j[0][1]) * inv_det;
            let dq = (-j[0][0] * f[1] + j[1][0] * f[0]) * inv_det;
            if !(du.is_finite() && dq.is_finite()) {
                return Err(CamError::NoConvergence {
                    angle_deg: theta.to_degrees(),
                    reason: StopReason::SingularJacobian,
                });
            }
            // a step stays within a fraction of the period (safeguard against wild steps)
            let du = du.clamp(-lim, lim);
            u += du;
            q += dq;
            let step2 = (du * du * e.d1.norm_squared()).max(dq * dq * qs * qs);
            if step2 <= tol2 || c2 * step2 * step2 <= tol2 {
                let u = if (0.0..self.period).contains(&u) {
                    u
                } else {
                    u.rem_euclid(self.period)
                };
                return Ok((Touch { u, q }, e));
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
        if !self.faces_follower(e, q) {
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
        match self.geometry.model.score(e.p) {
            Some((_, qs)) => (qs - q).abs() <= self.touch_slack(),
            None => false,
        }
    }

    /// Fails with [`StopReason::OnCusp`] when a cusp of a folded profile touches the follower
    /// before the contact at position `q`: the follower then rests on that corner.
    pub(crate) fn check_cusps(&self, theta: f64, frame: &Frame, q: f64) -> Result<(), CamError> {
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
    #[inline]
    pub(crate) fn faces_follower(&self, e: &WorldDerivs, q: f64) -> bool {
        // outward normal ∝ −orientation · k × r'
        let outward = -self.orientation * crate::geometry::rot90(e.d1);
        outward.dot(&self.geometry.model.toward_follower(e.p, q)) > 0.0
    }

    /// Oriented score of a position (larger is an earlier touch).
    pub(crate) fn oriented(&self, q: f64) -> f64 {
        self.geometry.joint.oriented(q)
    }

    /// Start candidates for a knife edge: the crossings of its line of travel with the profile
    /// sampled at `s` (linear interpolation between samples), best first. Two crossings between
    /// neighbouring samples (the line nearly tangent to the profile) show no sign change: where
    /// the sampled distance from the line has a local minimum, its true minimum is located and,
    /// when it crosses the line, both crossings become candidates.
    fn knife_starts(&self, frame: &Frame, s: &[f64], out: &mut Candidates) {
        let Some((d, p, e)) = self.geometry.model.knife_line() else {
            return;
        };
        let profile = self.cam.profile.as_ref();
        let n = s.len();
        let at = |u: f64| frame.curve_position(profile, u) - self.cam.pivot;
        let y = |k: usize| at(s[k]);
        let lateral = |u: f64| at(u).dot(&p) - e;
        let (y0, mut ya) = (y(0), y(0));
        let mut la = ya.dot(&p) - e;
        let mut l_before = lateral(s[n - 1]);
        for k in 0..n {
            let (yb, ub) = if k + 1 < n {
                (y(k + 1), s[k + 1])
            } else {
                (y0, self.period)
            };
            let lb = yb.dot(&p) - e;
            let ua = if k == 0 {
                s[n - 1] - self.period
            } else {
                s[k - 1]
            };
            if (la > 0.0) != (lb > 0.0) && (l_before > 0.0) != (la > 0.0) {
                // two crossings on either side of sample k: the line is nearly tangent there and
                // interpolated starts can both lead Newton to one of them; start from each root
                for (lo, hi) in [(ua, s[k]), (s[k], ub)] {
                    let u0 = bisect_sign(&lateral, lo, hi);
                    let q0 = at(u0).dot(&d);
                    out.push((q0, u0.rem_euclid(self.period), q0));
                }
            } else if la == 0.0 || (la > 0.0) != (lb > 0.0) {
                let f = if la == lb { 0.0 } else { la / (la - lb) };
                let q0 = ya.dot(&d) * (1.0 - f) + yb.dot(&d) * f;
                out.push((q0, s[k] + f * (ub - s[k]), q0));
            } else if (l_before > 0.0) == (la > 0.0)
                && la.abs() < l_before.abs()
                && la.abs() <= lb.abs()
            {
                // a local minimum of |distance| at sample k: does the profile cross in between?
                let sign = la.signum();
                // stopping once it crosses: that is all that is needed
                let (um, lm) =
                    super::golden::golden_min(|u| sign * lateral(u), ua, ub, 60, |v| v < 0.0);
                if lm < 0.0 {
                    for (lo, hi) in [(ua, um), (um, ub)] {
                        let u0 = bisect_sign(&lateral, lo, hi);
                        let q0 = at(u0).dot(&d);
                        out.push((q0, u0.rem_euclid(self.period), q0));
                    }
                }
            }
            l_before = la;
            (ya, la) = (yb, lb);
        }
    }

    /// Start candidates: the local maxima of the first-touch function sampled at `s`, best
    /// first; returns the best sampled score (a lower bound of the true first touch).
    fn score_starts(&self, frame: &Frame, s: &[f64], out: &mut Candidates) -> f64 {
        let profile = self.cam.profile.as_ref();
        let n = s.len();
        let score = |u: f64| self.geometry.model.score(frame.curve_position(profile, u));
        let val = |x: Option<(f64, f64)>| x.map_or(f64::NEG_INFINITY, |x| x.0);
        let first = score(s[0]);
        let (mut prev, mut cur) = (score(s[n - 1]), first);
        let mut best = f64::NEG_INFINITY;
        for (k, &u) in s.iter().enumerate() {
            let next = s.get(k + 1).map_or(first, |&v| score(v));
            if let Some((sc, q)) = cur {
                best = best.max(sc);
                if sc >= val(prev) && sc >= val(next) {
                    out.push((sc, u, q));
                }
            }
            (prev, cur) = (cur, next);
        }
        best
    }

    /// The peak of the first-touch function on `[a, b]` by golden-section search: `(u, q)`.
    fn score_peak(&self, frame: &Frame, a: f64, b: f64) -> Option<(f64, f64)> {
        let profile = self.cam.profile.as_ref();
        let score = |u: f64| {
            self.geometry
                .model
                .score(frame.curve_position(profile, u))
                .map_or(f64::NEG_INFINITY, |s| s.0)
        };
        let (u, _) = super::golden::golden_min(|u| -score(u), a, b, 60, |_| false);
        let (_, q) = self
            .geometry
            .model
            .score(frame.curve_position(profile, u))?;
        Some((u.rem_euclid(self.period), q))
    }

    /// The single best sample of the first-touch function at `s` (a convex profile has one
    /// maximum).
    fn best_sample(&self, frame: &Frame, s: &[f64]) -> Option<(f64, f64, f64)> {
        let profile = self.cam.profile.as_ref();
        let mut best: Option<(f64, f64, f64)> = None;
        for &u in s {
            if let Some((sc, q)) = self.geometry.model.score(frame.curve_position(profile, u)) {
                if best.is_none_or(|b| sc > b.0) {
                    best = Some((sc, u, q));
                }
            }
        }
        best
    }

    /// Global first touch. A convex profile's first-touch function has one maximum: its best
    /// coarse sample (for a knife edge, the outer crossing found by the coarse scan) is refined by
    /// Newton. Otherwise, or when that start fails, the best local maxima of the densely sampled
    /// function (the crossings, for a knife edge) are refined and the best first touch among them
    /// is kept.
    pub(crate) fn global_touch(&self, theta: f64, frame: &Frame) -> Result<Touch, CamError> {
        let knife = self.geometry.is_knife();
        if self.convex {
            // a knife's line crosses a convex profile twice: the coarse scan finds the outer
            // crossing unless the line only grazes the profile (then the dense scan below)
            let start = if knife {
                let mut c = Candidates::new(1);
                self.knife_starts(frame, &self.coarse, &mut c);
                c.as_slice().first().copied()
            } else {
                self.best_sample(frame, &self.coarse)
            };
            if let Some((_, u0, q0)) = start {
                if let Ok(t) = self.newton(theta, frame, u0, q0) {
                    if self.is_first_touch(frame, &t) {
                        return Ok(t);
                    }
                }
            }
        }
        let mut starts = Candidates::new(self.options.candidates);
        let best_sample = if knife {
            self.knife_starts(frame, &self.samples, &mut starts);
            f64::NEG_INFINITY // a knife's interpolated crossings are not exact touches
        } else {
            self.score_starts(frame, &self.samples, &mut starts)
        };
        if starts.is_empty() {
            let reason = if knife {
                "the knife edge's line of travel misses the cam"
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
        let spacing = self.period / self.samples.len().max(1) as f64;
        for &(_, u0, q0) in starts.as_slice() {
            // a start from which Newton wanders (the profile turning sharply near it) is first
            // moved to the sampled maximum's peak by golden-section search on the score
            let refined = || {
                let (u1, q1) = self.score_peak(frame, u0 - spacing, u0 + spacing)?;
                self.newton(theta, frame, u1, q1).ok()
            };
            let attempt = match self.newton(theta, frame, u0, q0) {
                Err(
                    e @ CamError::NoConvergence {
                        reason: StopReason::IterationLimit | StopReason::SingularJacobian,
                        ..
                    },
                ) if !knife => refined().ok_or(e),
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
        let best = best.ok_or_else(|| {
            last_err.unwrap_or(CamError::NoConvergence {
                angle_deg: theta.to_degrees(),
                reason: StopReason::NoCandidate,
            })
        })?;
        self.check_cusps(theta, frame, best.q)?;
        // the refined touch can only be later than (or equal to) a sampled one
        if self.oriented(best.q) < best_sample - self.touch_slack() {
            return Err(CamError::NoConvergence {
                angle_deg: theta.to_degrees(),
                reason: StopReason::BehindSample,
            });
        }
        Ok(best)
    }

    /// The best sampled first-touch score over the dense samples (the sweep's jump guard).
    pub(crate) fn best_sampled_score(&self, frame: &Frame) -> f64 {
        self.best_sample(frame, &self.samples)
            .map_or(f64::NEG_INFINITY, |b| b.0)
    }
}

/// Most start candidates refined by the global search.
pub const MAX_CANDIDATES: usize = 8;

/// The best few start candidates `(oriented score, u, q)`, best first, kept without allocating.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Candidates {
    items: [(f64, f64, f64); MAX_CANDIDATES],
    len: usize,
    cap: usize,
}

impl Candidates {
    pub(crate) fn new(cap: usize) -> Self {
        Self {
            items: [(0.0, 0.0, 0.0); MAX_CANDIDATES],
            len: 0,
            cap: cap.clamp(1, MAX_CANDIDATES),
        }
    }
    pub(crate) fn push(&mut self, c: (f64, f64, f64)) {
        if self.len == self.cap {
            if !(c.0 > self.items[self.len - 1].0) {
                return;
            }
            self.len -= 1;
        }
        let mut i = self.len;
        while i > 0 && self.items[i - 1].0 < c.0 {
            self.items[i] = self.items[i - 1];
            i -= 1;
        }
        self.items[i] = c;
        self.len += 1;
    }
    pub(crate) fn is_empty(&self) -> bool {
        self.len == 0
    }
    pub(crate) fn as_slice(&self) -> &[(f64, f64, f64)] {
        &self.items[..self.len]
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

/// A point near the sign change of `f` in `[a, b]` (the ends have opposite signs), by 30
/// bisections: a start for Newton.
fn bisect_sign(f: &impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let fa = f(a);
    for _ in 0..30 {
        let m = 0.5 * (a + b);
        if (f(m) > 0.0) == (fa > 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::*;
    fn paper() -> Mechanism {
        crate::reference::paper_mechanism(false)
    }

    #[test]
    fn back_side_stationary_point_is_not_a_first_touch() {
        let m = paper();
        let frame = m.cam.state(0.0).frame();
        // Newton from the far side converges to the leftmost point, a stationary point of x·d
        let back = m.newton(0.0, &frame, 4.5, -2.8).unwrap();
        assert!(back.q < 0.0);
        assert!(!m.is_first_touch(&frame, &back));
        let front = m.newton(0.0, &frame, 0.1, 4.9).unwrap();
        assert!(m.is_first_touch(&frame, &front));
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
