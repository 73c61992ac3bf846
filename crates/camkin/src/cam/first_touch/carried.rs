//! The first touch of a follower carrying any curve (see `follower::carried` for the coverage it
//! starts from): the free gap, Newton on the exact tangency in `(u, v, q)`, and the acceptance
//! test (no sampled cam point inside the follower beyond the polyline's chord error).

use super::FirstTouch;
use crate::body::{CurveInFrame, WorldDerivs};
use crate::cam::follower::carried::{Carried, Crossing};
use crate::cam::instant::Instant;
use crate::cam::linear::solve3;
use crate::cam::{CamError, Found, StopReason, Touch};
use crate::geometry::{cross, rot90, wrap_angle_near, Frame, Point2, Vec2};
use std::f64::consts::TAU;

/// A covered stretch of follower positions: `[lo, hi]`, with the cam parameter of the point
/// that covers it and the follower parameter at each end.
#[derive(Debug, Clone, Copy)]
pub(super) struct Cover {
    pub(super) lo: f64,
    pub(super) hi: f64,
    pub(super) u: f64,
    /// the index of the cam's sample
    pub(super) k: usize,
    pub(super) v_lo: f64,
    pub(super) v_hi: f64,
    /// converts a change of `q` at this point into a length
    pub(super) scale: f64,
}

/// How the bodies meet at a touch.
pub(super) struct Sides {
    /// the contact point (world)
    pub(super) contact: Point2,
    /// the cam's outward normal points into the follower's material (on its left); at a corner,
    /// the corner's pieces lie outside the other body
    pub(super) opposite: bool,
    /// the follower moving in its closing sense moves its point at the contact into the cam
    pub(super) approaching: bool,
}

/// [`Mechanism::covers`]' walk over the cam's samples.
struct CoverSamples<'a> {
    m: &'a FirstTouch,
    c: &'a Carried,
    frame: &'a Frame,
    out: &'a mut Vec<Cover>,
    buf: Vec<Crossing>,
    inside: Vec<((f64, f64), (f64, f64))>,
    /// only the samples within this circle (world: centre, radius)
    near: Option<(Point2, f64)>,
}

impl crate::circle_tree::Visit for CoverSamples<'_> {
    fn bound(&self, _i: usize, x: Point2, r: f64) -> Option<f64> {
        // whether the circle meets the band of levels (a slab, or an annulus about the pivot)
        let (lo, hi) = self.c.level_range;
        let joint = &self.m.geometry.joint;
        let level = joint.level(x - joint.origin());
        // grown by the longest chord: a band narrower than the samples' spacing may be crossed
        // between a leaf's last sample and the next leaf's first
        let slack = (r + self.m.sample_chord) * (1.0 + 1e-12);
        let near = self
            .near
            .is_none_or(|(o, reach)| (x - o).norm() <= reach + slack);
        (near && level + slack >= lo && level - slack <= hi).then_some(0.0)
    }
    fn floor(&self) -> f64 {
        f64::NEG_INFINITY
    }
    fn leaf(&mut self, first: usize, last: usize) {
        let (m, c) = (self.m, self.c);
        let joint = &m.geometry.joint;
        let (lo, hi) = c.level_range;
        let params = &m.index.dense.params[first..last];
        let all = &m.index.dense.params;
        for (k, (&u, &y)) in params.iter().zip(&m.sample_points[first..last]).enumerate() {
            let x = self.frame * y;
            // the level first: most points of a large driver are beyond an arm's reach (and an
            // arm's `along` is an arctangent)
            let mut y = x - joint.origin();
            let mut level = joint.level(y);
            let mut u = u;
            if !(level >= lo && level <= hi) {
                // a band narrower than the samples' spacing (a tiny carried curve) may fall
                // between this sample and the next: the cam's own point within it, by bisection
                // on the chord's stretch of the profile
                let next = first + k + 1;
                let (un, yn) = match (all.get(next), m.sample_points.get(next)) {
                    (Some(&un), Some(&yn)) => (un, yn),
                    _ if !all.is_empty() => (all[0] + m.period, m.sample_points[0]),
                    _ => continue,
                };
                let ln = joint.level(self.frame * yn - joint.origin());
                if !((level < lo && ln > hi) || (level > hi && ln < lo)) {
                    continue;
                }
                let profile = m.cam.profile.as_ref();
                let at = |t: f64| joint.level(self.frame * profile.position(t) - joint.origin());
                let (mut a, mut b, rising) = (u, un, level < lo);
                let mut found = None;
                for _ in 0..80 {
                    let mid = 0.5 * (a + b);
                    let l = at(mid);
                    if l >= lo && l <= hi {
                        found = Some((mid, l));
                        break;
                    }
                    if (l < lo) == rising {
                        a = mid;
                    } else {
                        b = mid;
                    }
                }
                let Some((um, lm)) = found else { continue };
                (u, level) = (um.rem_euclid(m.period), lm);
                y = self.frame * profile.position(u) - joint.origin();
            }
            let (along, scale) = (joint.along(y), joint.along_length(level));
            self.inside.clear();
            c.inside(level, &mut self.buf, &mut self.inside);
            for &((a0, v0), (a1, v1)) in &self.inside {
                // x is inside while along(x) − q ∈ [a0, a1] (slide), ψ − q ∈ [a0, a1] (pivot)
                self.out.push(Cover {
                    lo: along - a1,
                    hi: along - a0,
                    u,
                    k: first + k,
                    v_lo: v1,
                    v_hi: v0,
                    scale,
                });
            }
        }
    }
}

/// A cover's depth at a follower position: see `FirstTouch::cover_depths`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Tie<'a> {
    pub(super) depth: f64,
    pub(super) q: f64,
    pub(super) cover: &'a Cover,
}

/// Newton's tolerance (length), the follower coordinate's length scale, and the largest steps
/// of the cam's and the carried curve's parameters and of the follower's coordinate.
pub(super) struct Limits {
    pub(super) tol: f64,
    pub(super) qs: f64,
    pub(super) lim: f64,
    pub(super) vlim: f64,
    pub(super) qlim: f64,
}

/// Most starts tried by Newton in one global search.
const STARTS: usize = 8;

impl FirstTouch {
    pub(crate) fn carried(&self) -> Option<&Carried> {
        self.geometry.carried.as_deref()
    }

    /// Every covered stretch of follower positions by the cam's sampled points at `frame`, in
    /// the samples' order. Only the samples whose tree circles meet the band of levels the
    /// follower's curve spans are looked at (a large driver has most points beyond its reach).
    pub(super) fn covers(&self, c: &Carried, frame: &Frame, out: &mut Vec<Cover>) {
        self.covers_within(c, frame, None, out);
    }

    /// [`FirstTouch::covers`] that can matter with the follower at `q`: of a closed curve, only
    /// the samples within `window` of its bounding circle there (a sample farther away is
    /// outside the follower by more than `window`: the follower must move at least that far to
    /// take it in, so its cover's depth is below `−window`).
    pub(super) fn covers_at(
        &self,
        c: &Carried,
        frame: &Frame,
        q: f64,
        window: f64,
        out: &mut Vec<Cover>,
    ) {
        let near = c.hull.map(|(o, r)| {
            let o = self.geometry.joint.pose(q).frame() * o;
            (o, r + window + self.options.touch_tolerance)
        });
        self.covers_within(c, frame, near, out);
    }

    fn covers_within(
        &self,
        c: &Carried,
        frame: &Frame,
        near: Option<(Point2, f64)>,
        out: &mut Vec<Cover>,
    ) {
        let mut v = CoverSamples {
            m: self,
            c,
            frame,
            out,
            buf: Vec::new(),
            inside: Vec::new(),
            near,
        };
        self.index.dense.points().branch_and_bound(frame, &mut v);
    }

    /// The predicted angle of a gear-like follower at cam angle `theta`: the initial angle
    /// continued by the nominal ratio `z_cam/z_follower` (external mesh: opposite senses).
    pub(crate) fn carried_predicted(&self, c: &Carried, theta: f64) -> f64 {
        let Some(initial_angle) = self.geometry.joint.initial_angle() else {
            return 0.0;
        };
        let z1 = self.cam.profile.symmetry();
        if z1 > 1 && c.symmetry > 1 {
            initial_angle
                - self.cam.direction.sign() * f64::from(z1) / f64::from(c.symmetry) * theta
        } else {
            initial_angle
        }
    }

    /// The global first touch of a carried curve at cam angle `theta`.
    pub(crate) fn carried_global(&self, c: &Carried, at: &Instant) -> Result<Touch, CamError> {
        let (theta, frame) = (at.theta, &at.frame);
        let angle_deg = theta.to_degrees();
        let no_touch = |reason| CamError::NoTouch { angle_deg, reason };
        let mut covers = Vec::new();
        self.covers(c, frame, &mut covers);
        if covers.is_empty() {
            return Err(no_touch("the follower's curve cannot reach the cam"));
        }
        // the resting position (sampled) and the starts nearest it: (distance, u, v, q)
        let mut starts: Vec<(f64, f64, f64, f64)> = Vec::new();
        match self.geometry.joint {
            crate::cam::FollowerJoint::Translating { .. } => {
                let top = covers
                    .iter()
                    .map(|k| k.hi)
                    .fold(f64::NEG_INFINITY, f64::max);
                if top == f64::INFINITY {
                    return Err(no_touch(
                        "the follower's curve covers the cam however far it moves away: its material must be on its left, away from the cam",
                    ));
                }
                for k in &covers {
                    starts.push(((top - k.hi) * k.scale, k.u, k.v_hi, k.hi));
                }
            }
            crate::cam::FollowerJoint::Rotating {
                closing,
                toward_cam,
                initial_angle,
                ..
            } => {
                let periodic = c.symmetry > 1;
                let period = TAU / f64::from(c.symmetry);
                // a gear-like curve rests in the gap nearest its predicted angle; an arm in the
                // gap that holds it pointing away from the cam, or when that is covered (a face
                // reaching past the pivot), the gap nearest its initial angle
                let gap = if periodic {
                    free_gap(&covers, self.carried_predicted(c, theta), period, true)
                } else {
                    free_gap(&covers, toward_cam + std::f64::consts::PI, period, false)
                        .or_else(|| free_gap(&covers, initial_angle, period, true))
                };
                let gap = gap.ok_or_else(|| {
                    no_touch(if periodic {
                        "the gears overlap at every angle: the centre distance is too short"
                    } else {
                        "the follower overlaps the cam at every angle"
                    })
                })?;
                let ccw = closing.sign() > 0.0;
                // the follower turns in its closing sense until it touches: the gap's end
                let end = if ccw { gap.1 } else { gap.0 };
                for k in &covers {
                    let (edge, v) = if ccw { (k.lo, k.v_lo) } else { (k.hi, k.v_hi) };
                    let start = match c.sector {
                        // one tooth's cover: started with that tooth there, ranked by the
                        // nearest tooth's distance (the report brings the contact to it)
                        Some((turn, _)) => {
                            let d = edge - end;
                            (d - (d / turn).round() * turn, edge)
                        }
                        None => {
                            let d = wrap_angle_near(edge - end, 0.0);
                            (d, end + d)
                        }
                    };
                    starts.push((start.0.abs() * k.scale, k.u, v, start.1));
                }
            }
        }
        starts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut last = None;
        let corner = |e: &CamError| {
            matches!(
                e,
                CamError::NoConvergence {
                    reason: StopReason::OnCorner,
                    ..
                }
            )
        };
        // a converged touch settled and reported; the follower closing runs into it (a pair
        // without backlash touches on both flanks: the one behind is not where it comes to rest)
        let settled = |t: Result<Touch, CamError>| {
            t.and_then(|t| self.carried_settle(c, at, t, Some(&covers)))
                .and_then(|t| {
                    if self
                        .carried_sides(c, frame, &t)
                        .is_some_and(|s| s.approaching)
                    {
                        Ok(t)
                    } else {
                        Err(CamError::NoConvergence {
                            angle_deg,
                            reason: StopReason::NotFirstTouch,
                        })
                    }
                })
                .map(|t| self.carried_report(c, theta, t))
        };
        // a corner found in the way is the reason to give
        let keep = |e: CamError, last: &mut Option<CamError>| {
            if !last.as_ref().is_some_and(corner) {
                *last = Some(e);
            }
        };
        for &(_, u0, v0, q0) in starts.iter().take(STARTS) {
            match settled(self.carried_newton(c, at, u0, v0, q0)) {
                Ok(t) => return Ok(t),
                Err(e) => keep(e, &mut last),
            }
            // a curve small beside the cam's samples: its crossing's parameter can be far
            // round it from the tangency, and Newton reaches the wrong side; started again where
            // the curve's tangent faces the cam's
            let small = c.hull.is_some_and(|(_, r)| r <= 4.0 * self.corners.spacing);
            if let Some(v1) = small.then(|| self.facing_start(c, frame, u0, q0)).flatten() {
                if v1 != v0 {
                    match settled(self.carried_newton(c, at, u0, v1, q0)) {
                        Ok(t) => return Ok(t),
                        Err(e) => keep(e, &mut last),
                    }
                }
            }
        }
        // no tangency near a corner: the resting contact is at the corner
        if !last.as_ref().is_some_and(corner) {
            if let Some(&(_, u0, v0, q0)) = starts.first() {
                let near = 3.0 * self.corners.spacing.max(c.corners.spacing);
                let xa = frame * profile_point(self, u0);
                let xb = self.geometry.joint.pose(q0).frame() * c.curve.position(v0);
                for k in self.corners_near(c, frame, q0, (xa, xb), near) {
                    match settled(self.corner_from(c, at, &k, q0)) {
                        Ok(t) => return Ok(t),
                        Err(e) => keep(e, &mut last),
                    }
                }
                if !last.as_ref().is_some_and(corner) && !c.corners.at.is_empty() {
                    last = Some(CamError::NoConvergence {
                        angle_deg,
                        reason: StopReason::OnCorner,
                    });
                }
            }
        }
        Err(last.unwrap_or(CamError::NoConvergence {
            angle_deg,
            reason: StopReason::NoCandidate,
        }))
    }

    /// The carried curve's parameter facing the cam at `u` with the follower at `q`: within four
    /// of the cam's sample spacings of the cam's point, the curve's tangent most nearly opposite
    /// the cam's in the sense that puts the bodies' material on opposite sides
    /// ([`Carried::facing`]).
    fn facing_start(&self, c: &Carried, frame: &Frame, u: f64, q: f64) -> Option<f64> {
        let a = frame.curve_at(self.cam.profile.as_ref(), u);
        let fb = self.geometry.joint.pose(q).frame();
        let near = fb.inverse_transform_point(&a.p).coords;
        // opposite sides: o (x_A' · x_B') < 0
        let direction = fb.rotation.inverse() * (-self.orientation * a.d1);
        c.facing(direction, near, 4.0 * self.corners.spacing)
    }

    /// A touch reported on the branch the docs promise: a slide's as found; an arm's angle within
    /// ±180° of its initial angle, a gear-like follower's within half a tooth of the predicted
    /// angle (its contact moved to the tooth that is there).
    fn carried_report(&self, c: &Carried, theta: f64, mut t: Touch) -> Touch {
        if let Some(initial_angle) = self.geometry.joint.initial_angle() {
            if c.symmetry > 1 {
                let pitch = TAU / f64::from(c.symmetry);
                let k = ((t.q - self.carried_predicted(c, theta)) / pitch).round();
                if k != 0.0 {
                    t.q -= k * pitch;
                    if let Some(period) = c.period {
                        t.v = (t.v + k * period / f64::from(c.symmetry)).rem_euclid(period);
                    }
                }
            } else {
                let q = wrap_angle_near(t.q, initial_angle);
                t.q = q;
            }
        }
        t
    }

    /// Newton's tolerance and step bounds for a carried curve.
    pub(super) fn carried_limits(&self, c: &Carried) -> Limits {
        let fraction = self.options.max_step_fraction;
        let qs = self.geometry.q_length_scale(self.size);
        Limits {
            tol: self.options.position_tolerance,
            qs,
            lim: fraction * self.period,
            vlim: fraction * (c.bounds.1 - c.bounds.0),
            // the follower moves its point by at most the fraction of the cam's size a step (an
            // angle's step unbounded sent tries that do not converge beyond 1e8 rad)
            qlim: fraction * self.size / qs,
        }
    }

    /// The cam at `u` and the carried curve at `v` with the follower at `q` (world), and the
    /// motion of the follower's point there per unit of `q`.
    #[inline]
    pub(super) fn carried_points(
        &self,
        c: &Carried,
        frame: &Frame,
        (u, v, q): (f64, f64, f64),
    ) -> (WorldDerivs, WorldDerivs, Vec2) {
        let joint = self.geometry.joint;
        let a = frame.curve_at(self.cam.profile.as_ref(), u);
        let b = joint.pose(q).frame().curve_at(c.curve.as_ref(), v);
        let dq_x = joint.velocity_jacobian(b.p);
        (a, b, dq_x)
    }

    /// The tangency conditions of the cam at `u` and the carried curve at `v` with the follower
    /// at `q`, `F = (x_A(u) − x_B(v, q), x_A' × x_B')`, and their Jacobian in `(u, v, q)`; with
    /// the two curves' points (world).
    #[inline]
    pub(crate) fn carried_system(
        &self,
        c: &Carried,
        frame: &Frame,
        (u, v, q): (f64, f64, f64),
    ) -> (WorldDerivs, WorldDerivs, [f64; 3], [[f64; 3]; 3]) {
        let (a, b, dq_x) = self.carried_points(c, frame, (u, v, q));
        let dq_x1 = self.geometry.joint.velocity_jacobian_along(b.d1);
        let f = [a.p.x - b.p.x, a.p.y - b.p.y, cross(a.d1, b.d1)];
        let j = [
            [a.d1.x, -b.d1.x, -dq_x.x],
            [a.d1.y, -b.d1.y, -dq_x.y],
            [cross(a.d2, b.d1), cross(a.d1, b.d2), cross(a.d1, dq_x1)],
        ];
        (a, b, f, j)
    }

    /// Newton on the tangency of the cam at `u` and the carried curve at `v` with the follower at
    /// `q`: `x_A(u) = x_B(v, q)` and `x_A' × x_B' = 0`.
    pub(crate) fn carried_newton(
        &self,
        c: &Carried,
        at: &Instant,
        u: f64,
        v: f64,
        q: f64,
    ) -> Result<Touch, CamError> {
        self.carried_newton_within(c, at, (u, v, q), f64::INFINITY)
    }

    /// [`FirstTouch::carried_newton`] for a tangency near its start: it gives up
    /// ([`StopReason::LeftRegion`]) once the steps in either curve's point or the follower's
    /// have travelled more than `reach` (length).
    pub(super) fn carried_newton_within(
        &self,
        c: &Carried,
        at: &Instant,
        (mut u, mut v, mut q): (f64, f64, f64),
        reach: f64,
    ) -> Result<Touch, CamError> {
        let (theta, frame) = (at.theta, &at.frame);
        let angle_deg = theta.to_degrees();
        let Limits {
            tol,
            qs,
            lim,
            vlim,
            qlim,
        } = self.carried_limits(c);
        let mut travel = [0.0f64; 3];
        for _ in 0..self.options.max_iterations {
            let (a, b, f, j) = self.carried_system(c, frame, (u, v, q));
            let Some([du, dv, dq]) = solve3(j, f) else {
                return Err(CamError::NoConvergence {
                    angle_deg,
                    reason: StopReason::SingularJacobian,
                });
            };
            let (du, dv, dq) = (
                du.clamp(-lim, lim),
                dv.clamp(-vlim, vlim),
                dq.clamp(-qlim, qlim),
            );
            u += du;
            v += dv;
            q += dq;
            let moved = [
                du.abs() * a.d1.norm(),
                dv.abs() * b.d1.norm(),
                dq.abs() * qs,
            ];
            let step = moved[0].max(moved[1]).max(moved[2]);
            if step <= tol {
                let u = u.rem_euclid(self.period);
                let v = match c.period {
                    Some(p) => v.rem_euclid(p),
                    None => v,
                };
                return Ok(Touch {
                    u,
                    q,
                    v,
                    corner: None,
                });
            }
            for (t, m) in travel.iter_mut().zip(moved) {
                *t += m;
            }
            if travel.iter().any(|&t| t > reach) {
                return Err(CamError::NoConvergence {
                    angle_deg,
                    reason: StopReason::LeftRegion,
                });
            }
        }
        Err(CamError::NoConvergence {
            angle_deg,
            reason: StopReason::IterationLimit,
        })
    }

    /// The other tangencies that touch the cam with the follower at `t` (within the touch
    /// tolerance, the bodies' material on opposite sides), appended to `out` (one per place).
    pub(crate) fn carried_touching(
        &self,
        c: &Carried,
        at: &Instant,
        t: &Touch,
        out: &mut Vec<Touch>,
    ) {
        let frame = &at.frame;
        let mut covers = Vec::new();
        let (_, window) = self.tie_window(c);
        self.covers_at(c, frame, t.q, window, &mut covers);
        let mut ties: Vec<_> = self
            .cover_depths(c, t, &covers)
            .filter(|d| d.depth > -window)
            .collect();
        let Some(sides) = self.carried_sides(c, frame, t) else {
            return;
        };
        let tol = self.options.touch_tolerance;
        let close = 1e-6 * self.size;
        let place = |t: &Touch| frame * profile_point(self, t.u);
        // a contact may close either way (gears without backlash touch on both flanks); one
        // found again from another place does not count as found there
        let every = (8, true);
        self.near_tangencies(c, at, t, sides.contact, &mut ties, every, |t2, gain| {
            let new = !out.iter().any(|o| (place(o) - place(&t2)).norm() <= close);
            let opposite = self
                .carried_sides(c, frame, &t2)
                .is_some_and(|s| s.opposite);
            if new && gain.abs() <= tol && opposite {
                out.push(t2);
                Some(false)
            } else {
                None
            }
        });
        // corners resting on the other curve (the caller keeps one contact per place)
        self.corners_touching(c, frame, t, out);
    }

    /// The accepted touch from `t`: moved to an earlier tangency while one is found (a few
    /// times at most).
    fn carried_settle(
        &self,
        c: &Carried,
        at: &Instant,
        mut t: Touch,
        covers: Option<&Vec<Cover>>,
    ) -> Result<Touch, CamError> {
        let theta = at.theta;
        for _ in 0..4 {
            match self.carried_accept(c, at, &t, covers)? {
                None => return Ok(t),
                Some(t2) => t = t2,
            }
        }
        Err(CamError::NoConvergence {
            angle_deg: theta.to_degrees(),
            reason: StopReason::NotFirstTouch,
        })
    }

    /// A tangency with the bodies' material on opposite sides, on the curve, that the follower
    /// moving in its closing sense runs into.
    pub(super) fn carried_proper(&self, c: &Carried, frame: &Frame, t: &Touch) -> bool {
        self.carried_sides(c, frame, t)
            .is_some_and(|s| s.opposite && s.approaching)
    }

    /// How the bodies meet at a touch; `None` when it is off an open curve's bounds.
    pub(super) fn carried_sides(&self, c: &Carried, frame: &Frame, t: &Touch) -> Option<Sides> {
        if t.corner.is_some() {
            return self.corner_sides(c, frame, t);
        }
        if c.period.is_none() && !(t.v >= c.bounds.0 && t.v <= c.bounds.1) {
            return None;
        }
        let a = frame.curve_at(self.cam.profile.as_ref(), t.u);
        let b = self
            .geometry
            .joint
            .pose(t.q)
            .frame()
            .curve_at(c.curve.as_ref(), t.v);
        let outward = -self.orientation * rot90(a.d1);
        let joint = &self.geometry.joint;
        let (dx, closing) = (joint.velocity_jacobian(b.p), joint.closing_sign());
        Some(Sides {
            contact: a.p,
            opposite: outward.dot(&rot90(b.d1)) > 0.0,
            approaching: closing * dx.dot(&outward) < 0.0,
        })
    }

    /// A warm step of a carried curve from the previous contact `(u0, v0, q0)` extrapolated;
    /// `previous`: the previous angle and contact, to tell a jump from a continuation.
    pub(crate) fn carried_warm(
        &self,
        c: &Carried,
        at: &Instant,
        start: (f64, f64, f64),
        previous: (f64, Touch),
    ) -> Result<(Touch, Found), CamError> {
        let (u0, v0, q0) = start;
        let (p_theta, p) = previous;
        let back = &Instant::new(&self.cam, p_theta);
        // Newton of the kind of `corner`: on a tangency, or on a corner resting on a curve
        let newton = |at: &Instant, (u, v, q): (f64, f64, f64), corner| match corner {
            None => self.carried_newton(c, at, u, v, q),
            Some(side) => self.corner_newton(c, at, side, u, v, q),
        };
        let near = 4.0 * self.corners.spacing.max(c.corners.spacing);
        // a contact continues the previous one when Newton at the previous angle, started from
        // it, comes back to the previous contact (a warm Newton can land on the next tooth pair,
        // or on the same pair a tooth further round, when a large step crosses a handover); one
        // that reached a corner or left it, when it moved less than a few samples on each curve
        let continues = |t: &Touch| {
            if t.corner != p.corner {
                return self.corner_continues(c, (&p, t), near);
            }
            newton(back, (t.u, t.v, t.q), t.corner).is_ok_and(|b| {
                let d = (b.u - p.u).rem_euclid(self.period);
                d.min(self.period - d) <= 1e-6 * self.period
                    && (b.q - p.q).abs() * self.geometry.q_length_scale(self.size)
                        <= 1e-6 * self.size
            })
        };
        if let Ok(t) = newton(at, (u0, v0, q0), p.corner) {
            if let Ok(t) = self.carried_settle(c, at, t, None) {
                if continues(&t) {
                    return Ok((t, Found::WarmStart));
                }
            }
        }
        let g = self.carried_global(c, at)?;
        Ok(if continues(&g) {
            (g, Found::Global)
        } else {
            (g, Found::Jump { from_cam_param: u0 })
        })
    }
}

pub(super) fn profile_point(m: &FirstTouch, u: f64) -> Point2 {
    m.cam.profile.position(u)
}

/// The free gap (between covered stretches) to rest in, as `(from, to)` angles with
/// `from ≤ to`: for a periodic follower the gap nearest `reference` on a circle of circumference
/// `period`, otherwise the gap that holds `reference`.
fn free_gap(covers: &[Cover], reference: f64, period: f64, periodic: bool) -> Option<(f64, f64)> {
    // stretches relative to the reference, their starts in [0, period)
    let mut arcs: Vec<(f64, f64)> = Vec::with_capacity(covers.len() + 8);
    for k in covers {
        let w = k.hi - k.lo;
        if !(w < period) {
            return None;
        }
        let lo = (k.lo - reference).rem_euclid(period);
        arcs.push((lo, lo + w));
        if lo + w > period {
            arcs.push((lo - period, lo + w - period));
        }
    }
    arcs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut merged: Vec<(f64, f64)> = Vec::new();
    for (lo, hi) in arcs {
        match merged.last_mut() {
            Some(m) if lo <= m.1 => m.1 = m.1.max(hi),
            _ => merged.push((lo, hi)),
        }
    }
    // the gaps on the circle [0, period): between merged stretches, and round the end
    let mut gaps: Vec<(f64, f64)> = merged.windows(2).map(|w| (w[0].1, w[1].0)).collect();
    let (first, last) = (merged.first()?, merged.last()?);
    if last.1 < first.0 + period {
        gaps.push((last.1, first.0 + period));
    }
    let gaps: Vec<(f64, f64)> = gaps.into_iter().filter(|g| g.1 > g.0).collect();
    // the reference is at 0 (and at `period`)
    let distance = |g: &(f64, f64)| -> f64 {
        let holds = |x: f64| g.0 <= x && x <= g.1;
        if holds(0.0) || holds(period) || holds(-period) {
            0.0
        } else {
            [g.0, g.1]
                .iter()
                .map(|&e| {
                    let d = e.rem_euclid(period);
                    d.min(period - d)
                })
                .fold(f64::INFINITY, f64::min)
        }
    };
    let best = gaps
        .iter()
        .copied()
        .min_by(|a, b| distance(a).total_cmp(&distance(b)))?;
    if !periodic && distance(&best) > 0.0 {
        return None;
    }
    // back to angles, the gap placed next to the reference
    let shift = if best.0 > period / 2.0 { -period } else { 0.0 };
    Some((reference + best.0 + shift, reference + best.1 + shift))
}
