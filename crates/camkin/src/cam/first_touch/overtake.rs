//! The sweep's jump guard on a non-convex profile: whether another part of the profile touches
//! the follower before the contact followed so far, decided on the continuous profile, not only
//! at its samples.
//!
//! Where two parts of a profile cross (the follower passes from one lobe to the other), the part
//! taking over has its first touch between samples: its sampled scores lag its true maximum by up
//! to the samples' sagitta, so a guard that compares sampled scores keeps the old part for a
//! window after the crossing (on a cam of size 4 sampled 512 times, for up to 5e-4 rad, off by up
//! to 2.6e-3 in position). Here each circle of the samples' tree is grown by its samples' longer
//! neighbouring chord, so its bound holds the continuous curve; where it still reaches the
//! followed contact's score, every sampled local maximum (other than the followed one) is refined
//! to the exact tangency and compared.

use super::starts::Query;
use super::FirstTouch;
use crate::body::CurveInFrame;
use crate::cam::follower::Kind as _;
use crate::cam::instant::Instant;
use crate::cam::Touch;
use crate::circle_tree::Visit;
use crate::geometry::Point2;

/// What the guard found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Overtaken {
    /// nothing touches before the contact followed
    No,
    /// this exact first touch of another part does (the best of those that do)
    By(Touch),
    /// a sample touches first, or a part does that could not be refined: the global search
    /// decides
    Sampled,
}

impl FirstTouch {
    /// Whether a part of the profile other than the local maximum at cam parameter `own` touches
    /// the follower with an oriented score above `threshold` (the warm contact's, plus the touch
    /// tolerance), on the continuous profile. For the score-based followers (not a knife or a
    /// roller, whose path crossings the global search finds).
    pub(crate) fn overtaken(&self, at: &Instant, threshold: f64, own: f64) -> Overtaken {
        let frame = &at.frame;
        let s = &self.index.dense;
        let mut v = Overtake {
            q: Query::new(self, frame, s),
            at,
            own,
            floor: threshold,
            best: None,
            sampled: false,
        };
        s.points().branch_and_bound(frame, &mut v);
        match (v.sampled, v.best) {
            (true, _) => Overtaken::Sampled,
            (false, Some(t)) => Overtaken::By(t),
            (false, None) => Overtaken::No,
        }
    }
}

/// [`Mechanism::overtaken`]'s query.
struct Overtake<'a> {
    q: Query<'a>,
    at: &'a Instant,
    own: f64,
    /// the threshold, then the best refined touch's score
    floor: f64,
    best: Option<Touch>,
    sampled: bool,
}

impl Overtake<'_> {
    /// The world point of sample `k` (modulo the sample count).
    fn point(&self, k: usize) -> Point2 {
        let s = &self.q.s.params;
        let u = s[k % s.len()];
        self.q
            .frame
            .curve_position(self.q.m.cam.profile.as_ref(), u)
    }

    /// A sample above the floor: the global search decides.
    fn offer(&mut self, score: Option<(f64, f64)>) {
        if score.is_some_and(|(sc, _)| sc > self.floor) {
            self.sampled = true;
        }
    }

    /// Sample `k`'s parameter and its distances to samples `k − 1` and `k + 1`, and whether the
    /// interval between those holds the parameter `x` (modulo the period).
    fn around(&self, k: usize) -> (f64, f64, f64, impl Fn(f64) -> bool) {
        let (s, n, period) = (&self.q.s.params, self.q.s.params.len(), self.q.m.period);
        let u = s[k];
        let ahead = (s[(k + 1) % n] - u).rem_euclid(period);
        let behind = (u - s[(k + n - 1) % n]).rem_euclid(period);
        let holds = move |x: f64| {
            (x - u).rem_euclid(period) <= ahead || (u - x).rem_euclid(period) <= behind
        };
        (u, behind, ahead, holds)
    }

    /// Whether the parameter interval from sample `k − 1` to sample `k + 1` holds `own`.
    fn holds_own(&self, k: usize) -> bool {
        (self.around(k).3)(self.own)
    }

    /// The exact tangency of the sampled local maximum at `k` (its peak lies between samples
    /// `k − 1` and `k + 1`): Newton from the sample, else from the peak of the score there.
    fn refine(&mut self, k: usize, q0: f64) {
        let m = self.q.m;
        let (u, behind, ahead, holds) = self.around(k);
        let frame = self.q.frame;
        let attempt = |u0: f64, q0: f64| {
            m.newton(self.at, u0, q0)
                .ok()
                .filter(|t| holds(t.u) && m.is_first_touch(frame, t))
        };
        let t = attempt(u, q0).or_else(|| {
            let (u1, q1) = m.score_peak(frame, u - behind, u + ahead)?;
            if m.oriented(q1) <= self.floor {
                // the peak is not above: nothing to refine
                return Some(Touch {
                    u: u1,
                    q: q1,
                    v: 0.0,
                    corner: None,
                });
            }
            attempt(u1, q1)
        });
        match t {
            Some(t) if m.oriented(t.q) > self.floor => {
                self.floor = m.oriented(t.q);
                self.best = Some(t);
            }
            Some(_) => {}
            None => self.sampled = true,
        }
    }
}

impl Visit for Overtake<'_> {
    fn bound(&self, i: usize, c: Point2, r: f64) -> Option<f64> {
        self.q.m.score_bound(c, r + self.q.s.pad[i])
    }
    fn floor(&self) -> f64 {
        if self.sampled {
            f64::INFINITY
        } else {
            self.floor
        }
    }
    fn node(&mut self, i: usize) -> bool {
        let n = self.q.s.points().nodes[i];
        let pad = self.q.s.pad[i];
        if !self.q.score_monotone(i, self.q.frame * n.c, n.r + pad) {
            return true;
        }
        // monotone from the sample before its first to the sample after its last: no peak
        // between them, its highest point is an end sample
        self.offer(self.q.score(n.lo as usize));
        self.offer(self.q.score(n.hi as usize - 1));
        false
    }
    fn leaf(&mut self, lo: usize, hi: usize) {
        let m = self.q.m;
        let n = self.q.s.params.len();
        let val = |x: Option<(f64, f64)>| x.map_or(f64::NEG_INFINITY, |x| x.0);
        let score = |p: Point2| m.geometry.model.score(p);
        let mut prev = self.point(lo + n - 1);
        let mut cur = self.point(lo);
        let (mut s_prev, mut s_cur) = (score(prev), score(cur));
        for k in lo..hi {
            if self.sampled {
                return;
            }
            let next = self.point(k + 1);
            let s_next = score(next);
            if let Some((sc, q)) = s_cur {
                if sc > self.floor {
                    self.sampled = true;
                    return;
                }
                // a sampled local maximum whose neighbourhood (the arcs to its neighbours, each
                // within its chord of it) can reach above the floor
                let pad = (next - cur).norm().max((cur - prev).norm());
                if sc >= val(s_prev)
                    && sc >= val(s_next)
                    && !self.holds_own(k)
                    && m.score_bound(cur, pad).is_some_and(|b| b > self.floor)
                {
                    self.refine(k, q);
                }
            }
            (prev, cur, s_prev, s_cur) = (cur, next, s_cur, s_next);
        }
    }
}
