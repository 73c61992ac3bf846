//! The acceptance test of a carried curve's first touch: a converged tangency is the follower's
//! resting contact when it is on the curve, the bodies' material lies on opposite sides, no
//! corner is inside the other body, and no sampled cam point is inside the follower beyond the
//! polyline's chord error; a tangency elsewhere within the samples' resolution may stop the
//! follower first.

use super::FirstTouch;
use crate::cam::follower::carried::Carried;
use crate::cam::instant::Instant;
use crate::cam::{CamError, StopReason, Touch};

use crate::geometry::{wrap_angle_near, Frame, Point2};
use std::f64::consts::TAU;

use super::carried::{profile_point, Cover, Tie};

impl FirstTouch {
    /// Accepts a converged tangency as the follower's resting contact: on the curve, the two
    /// bodies' material on opposite sides, no corner inside the other body, and no sampled cam
    /// point inside the follower by more than the polyline's chord error (`covers`: the coverage
    /// at this angle when known). `Ok(Some(t2))`: a tangency elsewhere, within the samples'
    /// resolution of this one, stops the follower first.
    pub(super) fn carried_accept(
        &self,
        c: &Carried,
        at: &Instant,
        t: &Touch,
        covers: Option<&Vec<Cover>>,
    ) -> Result<Option<Touch>, CamError> {
        let (theta, frame) = (at.theta, &at.frame);
        let angle_deg = theta.to_degrees();
        let not_first = CamError::NoConvergence {
            angle_deg,
            reason: StopReason::NotFirstTouch,
        };
        let Some(sides) = self.carried_sides(c, frame, t) else {
            return Err(not_first);
        };
        if !sides.opposite {
            // a corner with a piece leaning into the other body: the contact is on that piece
            return match self.off_corner(c, at, t) {
                Some(t2) => Ok(Some(t2)),
                None => Err(not_first),
            };
        }
        let own;
        let covers = match covers {
            Some(k) => k,
            None => {
                let mut k = Vec::new();
                self.covers_at(c, frame, t.q, self.tie_window(c).1, &mut k);
                own = k;
                &own
            }
        };
        if let Some(k) = self.corner_inside(c, frame, t) {
            // the corner touches first: the contact is there (or, when it is not found, refused)
            return match self.corner_from(c, at, &k, t.q) {
                Ok(t2) if t2 != *t => Ok(Some(t2)),
                _ => Err(CamError::NoConvergence {
                    angle_deg,
                    reason: StopReason::OnCorner,
                }),
            };
        }
        let (slack, window) = self.tie_window(c);
        let mut ties: Vec<Tie<'_>> = Vec::new();
        for tie in self.cover_depths(c, t, covers) {
            if tie.depth > slack {
                return Err(CamError::NoConvergence {
                    angle_deg,
                    reason: StopReason::BehindSample,
                });
            }
            // a near tie elsewhere on the cam: the samples cannot tell which touches first (a
            // sample can miss an overlap shallower than its spacing's sagitta), the exact
            // tangency there can (a gear's next tooth pair, by a fraction of a micron)
            if tie.depth > -window {
                ties.push(tie);
            }
        }
        let tol = self.options.touch_tolerance;
        let mut earlier = None;
        let once = (8, false);
        self.near_tangencies(c, at, t, sides.contact, &mut ties, once, |t2, gain| {
            if gain > tol && gain <= 2.0 * window && self.carried_proper(c, frame, &t2) {
                earlier = Some(t2);
                Some(true)
            } else {
                None
            }
        });
        Ok(earlier)
    }

    /// How deep a sampled cam point may lie inside the follower at an accepted touch (the
    /// polyline's chord error, both ways, and the touch tolerance), and how near to touching a
    /// cover must be to be looked at as a possible tangency (that, or the samples' spacing).
    pub(super) fn tie_window(&self, c: &Carried) -> (f64, f64) {
        let slack = 2.0 * c.chord_error + self.options.touch_tolerance;
        (slack, slack.max(self.corners.spacing.max(c.chord_error)))
    }

    /// How deep each cover's cam point is inside the follower at `t`'s position, length
    /// (negative: outside), with the cover's position brought next to `t`'s (modulo a turn for
    /// an arm: every tooth of a gear has its own covers, and its own parameter `v`).
    pub(super) fn cover_depths<'a>(
        &self,
        c: &Carried,
        t: &Touch,
        covers: &'a [Cover],
    ) -> impl Iterator<Item = Tie<'a>> + 'a {
        let periodic = self.geometry.joint.is_rotating();
        let sector = c.sector;
        let tq = t.q;
        covers.iter().map(move |k| {
            let mid = 0.5 * (k.lo + k.hi);
            let q = match (periodic, sector) {
                // one tooth's covers: the tooth that is there
                (true, Some((turn, _))) => tq + ((mid - tq) / turn).round() * turn,
                (true, None) => tq + (mid - wrap_angle_near(mid, tq)),
                (false, _) => tq,
            };
            Tie {
                depth: (q - k.lo).min(k.hi - q) * k.scale,
                q,
                cover: k,
            }
        })
    }

    /// Whether the sample of cam parameter index `k` is the sampled peak of a part of the cam
    /// other than the contact's at `own`: at least as deep as both neighbouring samples and not
    /// next to `own`. `depths`: each tie's sample and depth, sorted (a sample that is not a tie
    /// is shallower than every tie).
    fn other_peak(&self, depths: &[(usize, f64)], k: usize, own: f64) -> bool {
        let params = &self.index.dense.params;
        let n = params.len();
        if n < 3 {
            return false;
        }
        let depth_of = |k: usize| {
            let i = depths.partition_point(|d| d.0 < k);
            depths[i..]
                .iter()
                .take_while(|d| d.0 == k)
                .map(|d| d.1)
                .fold(f64::NEG_INFINITY, f64::max)
        };
        let here = depth_of(k);
        let u = params[k];
        let ahead = (params[(k + 1) % n] - u).rem_euclid(self.period);
        let behind = (u - params[(k + n - 1) % n]).rem_euclid(self.period);
        let holds_own = (own - u).rem_euclid(self.period) <= ahead
            || (u - own).rem_euclid(self.period) <= behind;
        here >= depth_of((k + 1) % n) && here >= depth_of((k + n - 1) % n) && !holds_own
    }

    /// Newton on the tangency near each of `ties` (`(depth, q, cover)`, sorted here deepest
    /// first), one per place at least four sample spacings from `contact` (or nearer, at the
    /// sampled peak of another part of the cam) and from the places tried before, `places` at
    /// most, started at the cover's edge the closing sense reaches
    /// (with `both_edges`, also at its other edge, and when neither gives a tangency there, from
    /// the cam point deepest inside the follower near the sample). Each tangency found is
    /// brought to `t`'s configuration modulo the curve's symmetry (the contact moved to the
    /// tooth that is there, as `carried_report` does) and handed to `f` with its gain: how far
    /// before `t`, in the closing sense, it stops the follower (length; negative: after). `f`
    /// returns `None` when it does not take the tangency, else whether to stop.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn near_tangencies(
        &self,
        c: &Carried,
        at: &Instant,
        t: &Touch,
        contact: Point2,
        ties: &mut [Tie<'_>],
        (places, both_edges): (usize, bool),
        mut f: impl FnMut(Touch, f64) -> Option<bool>,
    ) {
        let frame = &at.frame;
        let periodic = self.geometry.joint.is_rotating();
        let pitch = TAU / f64::from(c.symmetry);
        // a slide closes towards the cam (decreasing q), an arm in its closing sense
        let closing = self.geometry.joint.closing_sign();
        let spacing = self.corners.spacing.max(c.chord_error);
        let joint = self.geometry.joint;
        // the tangency near a tie lies within a sample or two of it (a deeper neighbour would be
        // the tie); a Newton going farther is after another place, which has a tie of its own
        let reach = 16.0 * spacing;
        let mut tried: Vec<Point2> = Vec::new();
        let mut depths: Vec<(usize, f64)> = ties.iter().map(|d| (d.cover.k, d.depth)).collect();
        depths.sort_unstable_by_key(|d| d.0);
        ties.sort_by(|a, b| b.depth.total_cmp(&a.depth));
        for &Tie { q, cover: k, .. } in ties.iter() {
            if tried.len() >= places {
                break;
            }
            let x = frame * self.cam.profile.position(k.u);
            // a place within a few samples of one looked at is the same place; near the
            // contact, unless its sample is the peak of another part of the cam (two parts
            // crossing: the one taking over touches first by less than the samples can tell)
            if ((x - contact).norm() <= 4.0 * spacing && !self.other_peak(&depths, k.k, t.u))
                || tried.iter().any(|y| (x - y).norm() <= 4.0 * spacing)
            {
                continue;
            }
            tried.push(x);
            let closing_edge = if closing > 0.0 {
                (k.lo, k.v_lo)
            } else {
                (k.hi, k.v_hi)
            };
            let other_edge = if closing > 0.0 {
                (k.hi, k.v_hi)
            } else {
                (k.lo, k.v_lo)
            };
            // a tangency from a start, handed to `f`: `Some((stop, here))` when `f` took it,
            // `here` when it is at this place (Newton may go to another)
            let mut attempt = |u0: f64, q0: f64, v: f64| -> Option<(bool, bool)> {
                let mut t2 = self.carried_newton_within(c, at, (u0, v, q0), reach).ok()?;
                let n = if periodic {
                    ((t2.q - t.q) / pitch).round()
                } else {
                    0.0
                };
                let d = t2.q - t.q - n * pitch;
                t2.q = t.q + d;
                if let (Some(period), true) = (c.period, n != 0.0) {
                    t2.v = (t2.v + n * period / f64::from(c.symmetry)).rem_euclid(period);
                }
                let here = (frame * self.cam.profile.position(t2.u) - x).norm() <= 4.0 * spacing;
                f(t2, -closing * d * k.scale).map(|stop| (stop, here))
            };
            let edges = [Some(closing_edge), both_edges.then_some(other_edge)];
            let mut taken = false;
            for (edge, v) in edges.into_iter().flatten() {
                // at the edge with the cover's tooth there: one tooth's cover is that tooth's,
                // a whole turn's is brought next to `t`
                let q0 = if c.sector.is_some() {
                    edge
                } else {
                    t.q + (edge - q)
                };
                match attempt(k.u, q0, v) {
                    Some((true, _)) => return,
                    Some((false, true)) => {
                        taken = true;
                        break;
                    }
                    _ => {}
                }
            }
            // a contact that closes either way and was not found from the edges: from the cam
            // point deepest into the follower near the sample and its foot point, with the
            // follower where it is (a tangency close to where a flank begins or ends is missed
            // from the edges: a sample on the radial flank below a gear's base circle, an edge
            // beyond the tooth's tip corner)
            if both_edges && !taken {
                if let Some((u0, v)) = self.deepest_near(c, frame, &joint.pose(t.q).frame(), k.u) {
                    if attempt(u0, t.q, v).is_some_and(|(stop, _)| stop) {
                        return;
                    }
                }
            }
        }
    }

    /// The cam point between the dense samples either side of `u` that lies deepest inside the
    /// follower (at `fb`), by golden sections on its depth, and its foot point on the
    /// follower's curve: `(u, v)`. A start for Newton, so found to a few digits.
    fn deepest_near(&self, c: &Carried, frame: &Frame, fb: &Frame, u: f64) -> Option<(f64, f64)> {
        let params = &self.index.dense.params;
        let n = params.len();
        if n < 2 {
            return None;
        }
        let i = params.partition_point(|&p| p < u);
        let lo = if i >= 1 {
            params[i - 1]
        } else {
            params[n - 1] - self.period
        };
        let hi = if i + 1 < n {
            params[i + 1]
        } else {
            params[i + 1 - n] + self.period
        };
        let local = |u: f64| fb.inverse_transform_point(&(frame * profile_point(self, u)));
        let curve = c.curve.as_ref();
        let (u, _) = crate::cam::golden::golden_min(
            |u| -c.corners.depth_within(curve, local(u), 1.0, 30),
            lo,
            hi,
            30,
            |_| false,
        );
        Some((
            u.rem_euclid(self.period),
            c.corners.foot(curve, local(u), 60)?,
        ))
    }
}
