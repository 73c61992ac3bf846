//! Contacts at a corner of a carried follower's curve or of the cam's profile: where one curve's
//! tangent turns (a gear's tip, where a linear tip relief starts) and that corner rests on the
//! other curve.
//!
//! There is no tangency there. The corner is a point of its body (a knife edge): its curvature is
//! infinite, its sliding rate zero, and the normal is the other curve's. Such a contact holds
//! while the other curve's tangent lies within the corner's turn: both pieces that meet at the
//! corner stay outside the other body. It is found when a corner lies inside the other body at a
//! tangency (the corner touches first), or when no tangency is found near a corner, and refined
//! by Newton on `x_A(u) = x_B(v, q)` in the smooth curve's parameter and `q`, the corner's
//! parameter fixed at its joint.

use super::carried::{Limits, Sides};
use super::FirstTouch;
use crate::body::CurveInFrame;
use crate::cam::follower::carried::Carried;
use crate::cam::instant::Instant;
use crate::cam::{CamError, Corner, StopReason, Touch};
use crate::curve::Curve;
use crate::geometry::{cross, rot90, Frame, Point2, Vec2};

/// A corner that lies inside the other body at a touch: which curve's, its parameter, the foot
/// point's parameter on the other curve, and how deep it is (length).
#[derive(Debug, Clone, Copy)]
pub(super) struct Inside {
    pub(super) side: Corner,
    pub(super) param: f64,
    pub(super) foot: f64,
    pub(super) depth: f64,
}

/// How far (cosine of the angle) a piece at a corner may lean into the other body and the
/// contact still be at the corner: rounding, not geometry (a piece leaning in by `δ` rad moves
/// the true contact, a tangency on that piece, by `O(δ²)` of its radius of curvature).
const LEAN: f64 = 1e-9;

impl FirstTouch {
    /// The corner of `side`'s curve nearest the parameter `param` (within `1e-9` of the period
    /// or of the bounds): its exact parameter.
    pub(super) fn corner_param(&self, c: &Carried, side: Corner, param: f64) -> Option<f64> {
        let (at, span, period) = match side {
            Corner::Cam => (&self.corners.at, self.period, Some(self.period)),
            Corner::Follower => (&c.corners.at, c.bounds.1 - c.bounds.0, c.period),
        };
        let gap = |b: f64| match period {
            Some(p) => {
                let d = (b - param).rem_euclid(p);
                d.min(p - d)
            }
            None => (b - param).abs(),
        };
        at.iter()
            .map(|&(b, _)| (gap(b), b))
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .filter(|&(d, _)| d <= 1e-9 * span)
            .map(|(_, b)| b)
    }

    /// Newton on the corner of `side`'s curve (at `u` for the cam's, at `v` for the follower's)
    /// resting on the other curve: `x_A(u) = x_B(v, q)` in the other curve's parameter and `q`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn corner_newton(
        &self,
        c: &Carried,
        at: &Instant,
        side: Corner,
        mut u: f64,
        mut v: f64,
        mut q: f64,
    ) -> Result<Touch, CamError> {
        let (theta, frame) = (at.theta, &at.frame);
        let angle_deg = theta.to_degrees();
        let fail = |reason| CamError::NoConvergence { angle_deg, reason };
        match side {
            Corner::Cam => {
                u = self
                    .corner_param(c, side, u)
                    .ok_or(fail(StopReason::OnCorner))?
            }
            Corner::Follower => {
                v = self
                    .corner_param(c, side, v)
                    .ok_or(fail(StopReason::OnCorner))?
            }
        }
        let l: Limits = self.carried_limits(c);
        for _ in 0..self.options.max_iterations {
            let (a, b, dq_x) = self.carried_points(c, frame, (u, v, q));
            // the smooth curve's parameter moves its point; q moves the follower's
            let col = match side {
                Corner::Follower => a.d1,
                Corner::Cam => -b.d1,
            };
            let f = a.p - b.p;
            let Some((ds, dq)) = solve2(col, -dq_x, -f) else {
                return Err(fail(StopReason::SingularJacobian));
            };
            let moved = match side {
                Corner::Follower => {
                    let d = ds.clamp(-l.lim, l.lim);
                    u += d;
                    d.abs() * a.d1.norm()
                }
                Corner::Cam => {
                    let d = ds.clamp(-l.vlim, l.vlim);
                    v += d;
                    d.abs() * b.d1.norm()
                }
            };
            let dq = dq.clamp(-l.qlim, l.qlim);
            q += dq;
            if moved.max(dq.abs() * l.qs) <= l.tol {
                return Ok(Touch {
                    u: u.rem_euclid(self.period),
                    q,
                    v: c.period.map_or(v, |p| v.rem_euclid(p)),
                    corner: Some(side),
                });
            }
        }
        Err(fail(StopReason::IterationLimit))
    }

    /// How the bodies meet at the corner touch `t`: `opposite` when the corner's body is a
    /// convex wedge there with both its pieces outside the other body; `None` off an open
    /// curve's bounds or away from a corner.
    pub(super) fn corner_sides(&self, c: &Carried, frame: &Frame, t: &Touch) -> Option<Sides> {
        let side = t.corner?;
        if c.period.is_none() && !(t.v >= c.bounds.0 && t.v <= c.bounds.1) {
            return None;
        }
        let fb = self.geometry.joint.pose(t.q).frame();
        let profile = self.cam.profile.as_ref();
        let o = self.orientation;
        // the smooth body's outward normal, the corner's tangents either side of its joint
        // (world), the corner's material side (+1: left), and the normal from cam to follower
        let (contact, out, (t_in, t_out), material, toward_follower) = match side {
            Corner::Follower => {
                let a = frame.curve_at(profile, t.u);
                let out = -o * rot90(a.d1.normalize());
                let v = self.corner_param(c, side, t.v)?;
                let (ti, to) = either_side(c.curve.as_ref(), v, c.period);
                let r = fb.rotation;
                (a.p, out, (r * ti, r * to), 1.0, out)
            }
            Corner::Cam => {
                let b = fb.curve_at(c.curve.as_ref(), t.v);
                // the follower's material is on its curve's left
                let out = -rot90(b.d1.normalize());
                let u = self.corner_param(c, side, t.u)?;
                let (ti, to) = either_side(profile, u, Some(self.period));
                let r = frame.rotation;
                (b.p, out, (r * ti, r * to), o, -out)
            }
        };
        let convex = material * cross(t_in, t_out) > 0.0;
        let outside = out.dot(&-t_in) >= -LEAN && out.dot(&t_out) >= -LEAN;
        let joint = &self.geometry.joint;
        let (dx, closing) = (joint.velocity_jacobian(contact), joint.closing_sign());
        Some(Sides {
            contact,
            opposite: convex && outside,
            approaching: closing * dx.dot(&toward_follower) < 0.0,
        })
    }

    /// From a corner touch `t` one of whose pieces leans into the other body: the tangency on
    /// that piece next to the corner (where the contact is once it has left the corner, or
    /// before it reaches it), by Newton started just off the joint on that piece.
    pub(super) fn off_corner(&self, c: &Carried, at: &Instant, t: &Touch) -> Option<Touch> {
        let frame = &at.frame;
        let side = t.corner?;
        let fb = self.geometry.joint.pose(t.q).frame();
        let profile = self.cam.profile.as_ref();
        let (out, b, (t_in, t_out), span) = match side {
            Corner::Follower => {
                let a = frame.curve_at(profile, t.u);
                let b = self.corner_param(c, side, t.v)?;
                let (ti, to) = either_side(c.curve.as_ref(), b, c.period);
                let span = c.bounds.1 - c.bounds.0;
                (
                    -self.orientation * rot90(a.d1.normalize()),
                    b,
                    (fb.rotation * ti, fb.rotation * to),
                    span,
                )
            }
            Corner::Cam => {
                let e = fb.curve_at(c.curve.as_ref(), t.v);
                let b = self.corner_param(c, side, t.u)?;
                let (ti, to) = either_side(profile, b, Some(self.period));
                (
                    -rot90(e.d1.normalize()),
                    b,
                    (frame.rotation * ti, frame.rotation * to),
                    self.period,
                )
            }
        };
        // the piece that leans in the more: before the joint (−1) or after it (+1)
        let (lean_in, lean_out) = (out.dot(&-t_in), out.dot(&t_out));
        let way = if lean_in < lean_out { -1.0 } else { 1.0 };
        if lean_in.min(lean_out) >= -LEAN {
            return None;
        }
        [1e-9, 1e-6, 1e-3].into_iter().find_map(|nudge| {
            let p = b + way * nudge * span;
            let (u, v) = match side {
                Corner::Cam => (p.rem_euclid(self.period), t.v),
                Corner::Follower => (t.u, c.period.map_or(p, |per| p.rem_euclid(per))),
            };
            let t2 = self.carried_newton(c, at, u, v, t.q).ok()?;
            // on that piece, near the corner
            let q = match side {
                Corner::Cam => t2.u,
                Corner::Follower => t2.v,
            };
            let d = match (side, c.period) {
                (Corner::Follower, None) => q - b,
                (Corner::Follower, Some(per)) => (q - b + 0.5 * per).rem_euclid(per) - 0.5 * per,
                (Corner::Cam, _) => {
                    (q - b + 0.5 * self.period).rem_euclid(self.period) - 0.5 * self.period
                }
            };
            (d * way > 0.0).then_some(t2)
        })
    }

    /// The corner of either curve deepest inside the other body at `t`, deeper than the touch
    /// tolerance (`t`'s own corner aside).
    pub(super) fn corner_inside(&self, c: &Carried, frame: &Frame, t: &Touch) -> Option<Inside> {
        let tol = self.options.touch_tolerance;
        let mut deepest: Option<Inside> = None;
        self.corners_deeper(c, frame, t, tol, |k| {
            if k.depth > tol && deepest.is_none_or(|d| k.depth > d.depth) {
                deepest = Some(k);
            }
        });
        deepest
    }

    /// The corners of either curve that rest on the other at `t`'s position (within the touch
    /// tolerance, both pieces meeting there outside the other body), `t`'s own corner aside, as
    /// corner touches appended to `out`: a tooth's tip on the mating flank beside the first
    /// contact, a flat face on two tip corners at once.
    pub(crate) fn corners_touching(
        &self,
        c: &Carried,
        frame: &Frame,
        t: &Touch,
        out: &mut Vec<Touch>,
    ) {
        let tol = self.options.touch_tolerance;
        let mut found = Vec::new();
        self.corners_deeper(c, frame, t, -tol, |k| {
            if k.depth.abs() <= tol {
                found.push(k);
            }
        });
        for k in found {
            let (u, v) = match k.side {
                Corner::Cam => (k.param, k.foot),
                Corner::Follower => (k.foot, k.param),
            };
            let t2 = Touch {
                u,
                v,
                q: t.q,
                corner: Some(k.side),
            };
            if self
                .carried_sides(c, frame, &t2)
                .is_some_and(|s| s.opposite)
            {
                out.push(t2);
            }
        }
    }

    /// Every corner of either curve (`t`'s own aside) within reach of the other body whose depth
    /// inside it, with the follower at `t`'s position, may exceed `threshold`
    /// ([`crate::cam::corners::Corners::deep_foot`]), handed to `visit` with its exact depth.
    fn corners_deeper(
        &self,
        c: &Carried,
        frame: &Frame,
        t: &Touch,
        threshold: f64,
        mut visit: impl FnMut(Inside),
    ) {
        let tol = self.options.touch_tolerance;
        let fb = self.geometry.joint.pose(t.q).frame();
        let profile = self.cam.profile.as_ref();
        let own = |side: Corner, b: f64| {
            t.corner == Some(side)
                && match side {
                    Corner::Cam => b == t.u,
                    Corner::Follower => self.corner_param(c, side, t.v) == Some(b),
                }
        };
        // the follower's corners within the cam's reach, inside the cam
        for &(b, y) in &c.corners.at {
            let x = fb * y;
            if (x - self.cam.pivot).norm() > self.size + tol || own(Corner::Follower, b) {
                continue;
            }
            let local = frame.inverse_transform_point(&x);
            if let Some((foot, depth)) =
                self.corners
                    .deep_foot(profile, local, self.orientation, threshold)
            {
                visit(Inside {
                    side: Corner::Follower,
                    param: b,
                    foot,
                    depth,
                });
            }
        }
        // the cam's corners inside the follower (an arm's curve reaches no further from its
        // pivot than its sampled levels)
        let reach = c
            .joint
            .is_rotating()
            .then(|| (c.joint.origin(), c.level_range.1));
        for &(b, y) in &self.corners.at {
            let x = frame * y;
            if reach.is_some_and(|(o, r)| (x - o).norm() > r + c.chord_error + tol)
                || own(Corner::Cam, b)
            {
                continue;
            }
            let local = fb.inverse_transform_point(&x);
            if let Some((foot, depth)) =
                c.corners.deep_foot(c.curve.as_ref(), local, 1.0, threshold)
            {
                visit(Inside {
                    side: Corner::Cam,
                    param: b,
                    foot,
                    depth,
                });
            }
        }
    }

    /// The corner touch of the corner `k` found inside the other body with the follower at `q`.
    pub(super) fn corner_from(
        &self,
        c: &Carried,
        at: &Instant,
        k: &Inside,
        q: f64,
    ) -> Result<Touch, CamError> {
        let (u, v) = match k.side {
            Corner::Cam => (k.param, k.foot),
            Corner::Follower => (k.foot, k.param),
        };
        self.corner_newton(c, at, k.side, u, v, q)
    }

    /// The corners of either curve within `near` of the cam point `xa` or the follower point
    /// `xb` (world) with the follower at `q`: each as the corner inside the other body it would
    /// be, for [`Mechanism::corner_from`] (its depth not measured).
    pub(super) fn corners_near(
        &self,
        c: &Carried,
        frame: &Frame,
        q: f64,
        (xa, xb): (Point2, Point2),
        near: f64,
    ) -> Vec<Inside> {
        let fb = self.geometry.joint.pose(q).frame();
        let profile = self.cam.profile.as_ref();
        let mut out = Vec::new();
        for &(b, y) in &c.corners.at {
            let x = fb * y;
            if (x - xb).norm() <= near {
                let local = frame.inverse_transform_point(&x);
                if let Some(foot) = self.corners.foot(profile, local, 80) {
                    out.push(Inside {
                        side: Corner::Follower,
                        param: b,
                        foot,
                        depth: 0.0,
                    });
                }
            }
        }
        for &(b, y) in &self.corners.at {
            let x = frame * y;
            if (x - xa).norm() <= near {
                let local = fb.inverse_transform_point(&x);
                if let Some(foot) = c.corners.foot(c.curve.as_ref(), local, 80) {
                    out.push(Inside {
                        side: Corner::Cam,
                        param: b,
                        foot,
                        depth: 0.0,
                    });
                }
            }
        }
        out
    }

    /// Whether the touch `t` continues `p` (at the previous angle) where one of them is at a
    /// corner and the other not: the contact reached the corner, or left it onto a piece that
    /// meets there. It does when the contact's place on each curve moved less than `near`.
    pub(super) fn corner_continues(
        &self,
        c: &Carried,
        (p, t): (&Touch, &Touch),
        near: f64,
    ) -> bool {
        let profile = self.cam.profile.as_ref();
        let curve = c.curve.as_ref();
        (profile.position(p.u) - profile.position(t.u)).norm() <= near
            && (curve.position(p.v) - curve.position(t.v)).norm() <= near
    }
}

/// The unit tangents of `curve` just before and just after its joint at `b` (a periodic curve's
/// joint at 0 is also its joint at the period).
fn either_side(curve: &dyn Curve, b: f64, period: Option<f64>) -> (Vec2, Vec2) {
    let before = match period {
        Some(p) if b <= 0.0 => p.next_down(),
        _ => b.next_down(),
    };
    (curve.tangent(before), curve.tangent(b.next_up()))
}

/// `(s, q)` with `s a + q b = f`, by Cramer's rule; `None` when `a` and `b` are parallel (to
/// rounding).
fn solve2(a: Vec2, b: Vec2, f: Vec2) -> Option<(f64, f64)> {
    let det = cross(a, b);
    if !(det.abs() > 1e-14 * a.norm() * b.norm()) {
        return None;
    }
    Some((cross(f, b) / det, cross(a, f) / det))
}
