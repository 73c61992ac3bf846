//! The first touch of a follower carrying any curve (see `follower::carried` for the coverage it
//! starts from): the free gap, Newton on the exact tangency in `(u, v, q)`, and the acceptance
//! test (no sampled cam point inside the follower beyond the polyline's chord error).

use super::follower::carried::{Carried, Crossing, Track};
use super::{CamError, Found, Mechanism, StopReason, Touch};
use crate::body::CurveInFrame;
use crate::geometry::{cross, rot90, wrap_angle_near, Frame, Point2, Vec2};
use std::f64::consts::TAU;

/// A covered stretch of follower positions: `[lo, hi]`, with the cam parameter of the point
/// that covers it and the follower parameter at each end.
#[derive(Debug, Clone, Copy)]
struct Cover {
    lo: f64,
    hi: f64,
    u: f64,
    v_lo: f64,
    v_hi: f64,
    /// converts a change of `q` at this point into a length
    scale: f64,
}

/// Most starts tried by Newton in one global search.
const STARTS: usize = 8;

impl Mechanism {
    pub(crate) fn carried(&self) -> Option<&Carried> {
        self.geometry.carried.as_deref()
    }

    /// `(along, level)` of a world point `x` relative to the follower's joint at `q = 0`, and the
    /// length per unit of `q` there.
    #[inline]
    fn track_of(&self, c: &Carried, x: Point2) -> (f64, f64, f64) {
        match (c.track, self.geometry.joint) {
            (Track::Slide { d, p }, super::Joint::Translating { origin, .. }) => {
                let y = x - origin;
                (y.dot(&d), y.dot(&p), 1.0)
            }
            (_, super::Joint::Rotating { pivot, .. }) => {
                let y = x - pivot;
                let rho = y.norm();
                (y.y.atan2(y.x), rho, rho)
            }
            _ => (f64::NAN, f64::NAN, 1.0),
        }
    }

    /// Every covered stretch of follower positions by the cam's sampled points at `frame`.
    fn covers(&self, c: &Carried, frame: &Frame, out: &mut Vec<Cover>) {
        let profile = self.cam.profile.as_ref();
        let (lo, hi) = c.level_range;
        let mut buf: Vec<Crossing> = Vec::new();
        let mut inside = Vec::new();
        for &u in &self.samples {
            let x = frame.curve_position(profile, u);
            let (along, level, scale) = self.track_of(c, x);
            if !(level >= lo && level <= hi) {
                continue;
            }
            inside.clear();
            c.inside(level, &mut buf, &mut inside);
            for &((a0, v0), (a1, v1)) in &inside {
                // x is inside while along(x) − q ∈ [a0, a1] (slide), ψ − q ∈ [a0, a1] (pivot)
                out.push(Cover {
                    lo: along - a1,
                    hi: along - a0,
                    u,
                    v_lo: v1,
                    v_hi: v0,
                    scale,
                });
            }
        }
    }

    /// The predicted angle of a gear-like follower at cam angle `theta`: the initial angle
    /// continued by the nominal ratio `z_cam/z_follower` (external mesh: opposite senses).
    pub(crate) fn carried_predicted(&self, c: &Carried, theta: f64) -> f64 {
        let super::Joint::Rotating { initial_angle, .. } = self.geometry.joint else {
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
    pub(crate) fn carried_global(
        &self,
        c: &Carried,
        theta: f64,
        frame: &Frame,
    ) -> Result<Touch, CamError> {
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
            super::Joint::Translating { .. } => {
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
            super::Joint::Rotating {
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
                    let d = wrap_angle_near(edge - end, 0.0);
                    starts.push((d.abs() * k.scale, k.u, v, end + d));
                }
            }
        }
        starts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut last = None;
        for &(_, u0, v0, q0) in starts.iter().take(STARTS) {
            match self.carried_newton(c, theta, frame, u0, v0, q0) {
                Ok(t) => match self.carried_accept(c, theta, frame, &t, Some(&covers)) {
                    Ok(()) => return Ok(self.carried_report(c, theta, t)),
                    Err(e) => last = Some(e),
                },
                Err(e) => last = Some(e),
            }
        }
        Err(last.unwrap_or(CamError::NoConvergence {
            angle_deg,
            reason: StopReason::NoCandidate,
        }))
    }

    /// A touch reported on the branch the docs promise: a slide's as found; an arm's angle within
    /// ±180° of its initial angle, a gear-like follower's within half a tooth of the predicted
    /// angle (its contact moved to the tooth that is there).
    fn carried_report(&self, c: &Carried, theta: f64, mut t: Touch) -> Touch {
        if let super::Joint::Rotating { initial_angle, .. } = self.geometry.joint {
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

    /// Newton on the tangency of the cam at `u` and the carried curve at `v` with the follower at
    /// `q`: `x_A(u) = x_B(v, q)` and `x_A' × x_B' = 0`.
    pub(crate) fn carried_newton(
        &self,
        c: &Carried,
        theta: f64,
        frame: &Frame,
        mut u: f64,
        mut v: f64,
        mut q: f64,
    ) -> Result<Touch, CamError> {
        let angle_deg = theta.to_degrees();
        let profile = self.cam.profile.as_ref();
        let tol = self.options.position_tolerance;
        let qs = self.geometry.q_length_scale(self.size);
        let lim = self.options.max_step_fraction * self.period;
        let vlim = self.options.max_step_fraction * (c.bounds.1 - c.bounds.0);
        let joint = self.geometry.joint;
        for _ in 0..self.options.max_iterations {
            let a = frame.curve_at(profile, u);
            let fb = joint.pose(q).frame();
            let b = fb.curve_at(c.curve.as_ref(), v);
            let (dq_x, dq_x1) = match joint {
                super::Joint::Translating { direction, .. } => (*direction, Vec2::zeros()),
                super::Joint::Rotating { pivot, .. } => (rot90(b.p - pivot), rot90(b.d1)),
            };
            let f = [a.p.x - b.p.x, a.p.y - b.p.y, cross(a.d1, b.d1)];
            let j = [
                [a.d1.x, -b.d1.x, -dq_x.x],
                [a.d1.y, -b.d1.y, -dq_x.y],
                [cross(a.d2, b.d1), cross(a.d1, b.d2), cross(a.d1, dq_x1)],
            ];
            let Some([du, dv, dq]) = solve3(j, f) else {
                return Err(CamError::NoConvergence {
                    angle_deg,
                    reason: StopReason::SingularJacobian,
                });
            };
            let (du, dv) = (du.clamp(-lim, lim), dv.clamp(-vlim, vlim));
            u += du;
            v += dv;
            q += dq;
            let step = (du.abs() * a.d1.norm())
                .max(dv.abs() * b.d1.norm())
                .max(dq.abs() * qs);
            if step <= tol {
                let u = u.rem_euclid(self.period);
                let v = match c.period {
                    Some(p) => v.rem_euclid(p),
                    None => v,
                };
                return Ok(Touch { u, q, v });
            }
        }
        Err(CamError::NoConvergence {
            angle_deg,
            reason: StopReason::IterationLimit,
        })
    }

    /// Accepts a converged tangency as the follower's resting contact: on the curve, the two
    /// bodies' material on opposite sides, and no sampled cam point inside the follower by more
    /// than the polyline's chord error (`covers`: the coverage at this angle when known).
    fn carried_accept(
        &self,
        c: &Carried,
        theta: f64,
        frame: &Frame,
        t: &Touch,
        covers: Option<&Vec<Cover>>,
    ) -> Result<(), CamError> {
        let angle_deg = theta.to_degrees();
        let not_first = CamError::NoConvergence {
            angle_deg,
            reason: StopReason::NotFirstTouch,
        };
        if c.period.is_none() && !(t.v >= c.bounds.0 && t.v <= c.bounds.1) {
            return Err(not_first);
        }
        let a = frame.curve_at(self.cam.profile.as_ref(), t.u);
        let b = self
            .geometry
            .joint
            .pose(t.q)
            .frame()
            .curve_at(c.curve.as_ref(), t.v);
        // the cam's outward normal points into the follower's material (on its left)
        let outward = -self.orientation * rot90(a.d1);
        if !(outward.dot(&rot90(b.d1)) > 0.0) {
            return Err(not_first);
        }
        let own;
        let covers = match covers {
            Some(k) => k,
            None => {
                let mut k = Vec::new();
                self.covers(c, frame, &mut k);
                own = k;
                &own
            }
        };
        let slack = 2.0 * c.chord_error + self.options.touch_tolerance;
        let periodic = matches!(self.geometry.joint, super::Joint::Rotating { .. });
        let pitch = TAU / f64::from(c.symmetry);
        for k in covers {
            let q = if periodic {
                // the cover's angle brought next to the contact's, modulo the pitch
                let mid = 0.5 * (k.lo + k.hi);
                let m = wrap_angle_near(mid, t.q);
                let m = m - ((m - t.q) / pitch).round() * pitch;
                t.q + (mid - m)
            } else {
                t.q
            };
            let depth = (q - k.lo).min(k.hi - q) * k.scale;
            if depth > slack {
                return Err(CamError::NoConvergence {
                    angle_deg,
                    reason: StopReason::BehindSample,
                });
            }
        }
        Ok(())
    }

    /// A warm step of a carried curve from the previous contact `(u0, v0, q0)` extrapolated;
    /// `previous`: the previous angle and contact, to tell a jump from a continuation.
    pub(crate) fn carried_warm(
        &self,
        c: &Carried,
        theta: f64,
        frame: &Frame,
        start: (f64, f64, f64),
        previous: (f64, Touch),
    ) -> Result<(Touch, Found), CamError> {
        let (u0, v0, q0) = start;
        let (p_theta, p) = previous;
        let back = self.cam.state(p_theta).frame();
        // a contact continues the previous one when Newton at the previous angle, started from
        // it, comes back to the previous contact (a warm Newton can land on the next tooth pair,
        // or on the same pair a tooth further round, when a large step crosses a handover)
        let continues = |t: &Touch| {
            self.carried_newton(c, p_theta, &back, t.u, t.v, t.q)
                .is_ok_and(|b| {
                    let d = (b.u - p.u).rem_euclid(self.period);
                    d.min(self.period - d) <= 1e-6 * self.period
                        && (b.q - p.q).abs() * self.geometry.q_length_scale(self.size)
                            <= 1e-6 * self.size
                })
        };
        if let Ok(t) = self.carried_newton(c, theta, frame, u0, v0, q0) {
            if self.carried_accept(c, theta, frame, &t, None).is_ok() && continues(&t) {
                return Ok((t, Found::WarmStart));
            }
        }
        let g = self.carried_global(c, theta, frame)?;
        Ok(if continues(&g) {
            (g, Found::Global)
        } else {
            (g, Found::Jump { from_cam_param: u0 })
        })
    }
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

/// `J⁻¹ (−f)` for a 3×3 `J` (nalgebra's LU with partial pivoting), each equation first scaled by
/// its largest coefficient (they mix lengths and lengths squared); `None` when singular.
fn solve3(a: [[f64; 3]; 3], f: [f64; 3]) -> Option<[f64; 3]> {
    let mut m = nalgebra::Matrix3::from_fn(|r, c| a[r][c]);
    let mut b = nalgebra::Vector3::new(-f[0], -f[1], -f[2]);
    for k in 0..3 {
        let s = m.row(k).amax();
        if !(s > 0.0 && s.is_finite()) {
            return None;
        }
        m.row_mut(k).scale_mut(1.0 / s);
        b[k] /= s;
    }
    let x = m.lu().solve(&b)?;
    x.iter().all(|v| v.is_finite()).then(|| [x[0], x[1], x[2]])
}
