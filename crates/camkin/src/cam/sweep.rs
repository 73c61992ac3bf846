//! Sweeps over cam angles that warm-start each angle from the previous contact.
//!
//! The previous contact `(u, q)` is extrapolated to the new angle to second order (`dq/dθ`,
//! `d²q/dθ²` from the velocity and acceleration, `du/dθ = u̇_A/θ̇` and its difference quotient
//! over the last step) and polished by the same Newton iteration as the global search. A guard then checks that the contact has not jumped to another part of the profile:
//! on a convex profile the first touch is unique and no guard is needed; on a non-convex one the
//! sampled first-touch function is compared with the warm contact, and if another part of the
//! profile touches first the global search is used and the row is marked [`Found::Jump`].

use super::conic::CarriedConic;
use super::first_touch::overtake::Overtaken;
use super::follower::{dispatch, pitch_point, Kind};
use super::pose::Pose;
use super::{CamError, FollowerState, Mechanism, Motion, Touch};
use crate::body::{curve_in, CurveInFrame};
use crate::cam::instant::Instant;
use crate::curve::{ClosedSpline, Curve};
use crate::geometry::{Frame, Rotation};

/// How the contact at an angle was found.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub enum Found {
    /// global bracketing then Newton
    Global,
    /// Newton from the previous angle's contact
    WarmStart,
    /// the contact jumped to another part of the profile since the previous angle (the follower
    /// leaves the profile there: the acceleration is impulsive between the two angles)
    Jump {
        /// the cam parameter the warm start followed
        from_cam_param: f64,
    },
}

/// A warm-started sweep: each angle starts Newton from the previous contact extrapolated to
/// second order; on a non-convex profile a guard compares with the sampled first-touch function
/// and marks jumps of the contact ([`Found::Jump`]).
///
/// ```
/// use camkin::cam::Found;
///
/// // the paper's cam over a revolution in 1° steps: one global search, then warm starts
/// let m = camkin::reference::paper_mechanism(false);
/// let mut sweep = m.sweep();
/// let states: Vec<_> = (0..360)
///     .map(|k| sweep.step(f64::from(k).to_radians()))
///     .collect::<Result<_, _>>()?;
/// assert_eq!(states[0].found, Found::Global);
/// assert!(states[1..].iter().all(|s| s.found == Found::WarmStart));
/// // the same contact as a global search at every angle
/// let cold = m.analyze(100f64.to_radians())?;
/// assert!((states[100].acceleration - cold.acceleration).abs() <= 1e-9 * cold.acceleration.abs());
/// # Ok::<(), camkin::cam::CamError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Sweep<'a> {
    mech: &'a Mechanism,
    /// the cam's profile when it is a spline (the motion-only warm step evaluates it inlined)
    spline: Option<&'a ClosedSpline>,
    /// the cam's profile when it is a circle or an ellipse, its parameter's sine and cosine
    /// carried from one evaluation to the next
    conic: Option<CarriedConic>,
    prev: Option<Prev>,
    /// the last contact found, and `dv/dθ` of a carried curve's parameter
    last: Option<(Touch, f64)>,
    /// the cam's rotation angle (`±θ`) at the last motion-only warm step, for the next by angle
    /// addition
    turn: Option<Pose>,
}

#[derive(Debug, Clone, Copy)]
struct Prev {
    theta: f64,
    u: f64,
    q: f64,
    du_dtheta: f64,
    dq_dtheta: f64,
    /// `d²q/dθ²`, exact from the acceleration
    d2q_dtheta2: f64,
    /// `d²u/dθ²` from the last two rates (0 after a global search)
    d2u_dtheta2: f64,
    /// the position with, for an arm angle, its sine and cosine (after a motion-only warm step)
    pose: Option<Pose>,
}

impl Prev {
    /// The contact extrapolated to second order over `dt` (rad): `(u, q)`, off by O(Δθ³).
    #[inline(always)]
    fn start(&self, dt: f64) -> (f64, f64) {
        (
            self.u + dt * (self.du_dtheta + 0.5 * dt * self.d2u_dtheta2),
            self.q + dt * (self.dq_dtheta + 0.5 * dt * self.d2q_dtheta2),
        )
    }
}

/// Largest angle step (rad) over which the previous contact is used as a start.
pub const MAX_WARM_STEP: f64 = 0.2;

impl<'a> Sweep<'a> {
    pub(crate) fn new(mech: &'a Mechanism) -> Self {
        Self {
            mech,
            spline: mech.touch.cam().profile.as_spline(),
            conic: CarriedConic::of(mech.touch.cam().profile.as_ref()),
            prev: None,
            last: None,
            turn: None,
        }
    }

    /// Analyses the next cam angle `theta` (rad).
    pub fn step(&mut self, theta: f64) -> Result<FollowerState, CamError> {
        let r = self.locate(theta).and_then(|(at, t, f)| {
            self.note(theta, t, f);
            self.mech.kinematics(&at, t, f)
        });
        self.remember(theta, r.as_ref().ok().map(|s| kept(&s.motion())), None);
        r
    }

    /// The follower's position, velocity and acceleration only at the next cam angle `theta`
    /// (rad): the fast path ([`Mechanism::motion`]).
    pub fn step_motion(&mut self, theta: f64) -> Result<Motion, CamError> {
        // the last step by reference: copying it out costs a dozen instructions a step
        let fast = match self.prev {
            Some(ref p) if self.mech.touch.convex() && (theta - p.theta).abs() <= MAX_WARM_STEP => {
                let angle = self.mech.touch.cam().direction.sign() * theta;
                let turn = match self.turn {
                    Some(t) => t.angle_to(angle),
                    None => Pose::angle(angle),
                };
                self.turn = Some(turn);
                let rotation = Rotation::from_cos_sin_unchecked(turn.cos, turn.sin);
                dispatch!(&self.mech.touch.geometry().model, k => self.warm_motion(k, theta, p, rotation))
            }
            _ => None,
        };
        if let Some((s, pose)) = fast {
            self.remember(theta, Some(kept(&s)), pose);
            return Ok(s);
        }
        let r = self.locate(theta).and_then(|(at, t, f)| {
            self.note(theta, t, f);
            self.mech.motion_at(&at, t, f)
        });
        self.remember(theta, r.as_ref().ok().map(kept), None);
        r
    }

    /// The motion-only warm step of a named follower kind `k` on a convex profile: Newton from
    /// the extrapolated contact, the first-touch checks of [`Sweep::warm`], and the kind's
    /// closed-form rates, monomorphised for the kind; also the converged position. `None` where
    /// any of them declines (a carried curve, Newton failing, a touch that is not the first, a
    /// rate's denominator near zero): the general step then decides, from the start.
    #[inline(always)]
    fn warm_motion<K: Kind>(
        &self,
        k: &K,
        theta: f64,
        p: &Prev,
        rotation: Rotation,
    ) -> Option<(Motion, Option<Pose>)> {
        if self.mech.touch.geometry().carried.is_some() {
            return None;
        }
        match (self.spline, &self.conic) {
            // a spline's or a conic's evaluation costs about as much as extrapolating one
            (Some(s), _) => self.warm_motion_on(k, s, theta, p, rotation, false),
            (None, Some(c)) => self.warm_motion_on(k, c, theta, p, rotation, false),
            (None, None) => {
                let profile = self.mech.touch.cam().profile.as_ref();
                self.warm_motion_on(k, profile, theta, p, rotation, true)
            }
        }
    }

    /// [`Sweep::warm_motion`] on the cam's `profile` as its own type or `dyn Curve`, with the
    /// cam's `rotation` at `theta`; `extrapolate`: a roller's profile point from Newton's last
    /// evaluation when its last step was below the tolerance (see
    /// [`FirstTouch::pitch_newton`](super::first_touch::FirstTouch::pitch_newton)).
    #[inline(always)]
    fn warm_motion_on<K: Kind, C: Curve + ?Sized>(
        &self,
        k: &K,
        profile: &C,
        theta: f64,
        p: &Prev,
        rotation: Rotation,
        extrapolate: bool,
    ) -> Option<(Motion, Option<Pose>)> {
        let m = self.mech;
        let cam = m.touch.cam().state(theta);
        // the frame from the rotation carried from the last step (no sin_cos)
        let at = &Instant {
            theta,
            frame: Frame::from_parts(cam.pose.origin.coords.into(), rotation),
            cam,
        };
        let frame = &at.frame;
        let (u0, q0) = p.start(theta - p.theta);
        let (touch, pose, e) = match k.centre_path() {
            // a roller: Newton in the cam parameter alone, the position from its centre
            Some((path, r)) if r > 0.0 => {
                let (u, d) = m
                    .touch
                    .pitch_newton((path, r), profile, at, u0, extrapolate)
                    .ok()?;
                let e = frame.derivs_to_world(&d);
                let near = match p.pose {
                    Some(last) if K::ANGULAR => last,
                    _ => k.pose(q0),
                };
                let (centre, _) = pitch_point((e.p, e.d1, e.d2), r, m.touch.orientation());
                let pose = path.pose(m.touch.cam().pivot, centre, near);
                if !m.touch.convex_warm_touch_with(k, &e, &pose) {
                    return None;
                }
                (
                    Touch {
                        u,
                        q: pose.q,
                        v: 0.0,
                        corner: None,
                    },
                    pose,
                    e,
                )
            }
            _ => {
                let start = match p.pose {
                    Some(from) if K::ANGULAR => k.pose_from(from, q0),
                    _ => k.pose(q0),
                };
                let c = m.touch.newton_with(k, profile, at, u0, start).ok()?;
                if !m.touch.convex_warm_touch_with(k, &c.last, &c.pose) {
                    return None;
                }
                (c.touch, c.pose, curve_in(frame, profile, c.touch.u))
            }
        };
        let found = Found::WarmStart;
        let motion = m.closed_form_motion(k, theta, &at.cam, &e, (touch, pose), found)?;
        Some((motion, K::ANGULAR.then_some(pose)))
    }

    /// Keeps a carried curve's contact parameter and its rate (a difference quotient over the last
    /// step when it was a continuation).
    #[inline(always)]
    fn note(&mut self, theta: f64, t: Touch, found: Found) {
        if self.mech.touch.geometry().carried.is_none() {
            return;
        }
        let rate = match (self.prev, self.last) {
            (Some(p), Some((l, _))) if matches!(found, Found::WarmStart) && theta != p.theta => {
                (t.v - l.v) / (theta - p.theta)
            }
            _ => 0.0,
        };
        self.last = Some((t, rate));
    }

    /// The contact at `theta`: warm-started from the previous angle when there is one.
    #[inline(always)]
    fn locate(&self, theta: f64) -> Result<(Instant, Touch, Found), CamError> {
        let m = self.mech;
        let at = Instant::new(m.cam(), theta);
        let (t, f) = match self.prev {
            Some(p) if (theta - p.theta).abs() <= MAX_WARM_STEP => self.warm(&at, p)?,
            _ => (m.touch.global_touch(&at)?, Found::Global),
        };
        Ok((at, t, f))
    }

    /// Keeps what the next angle's prediction needs: `(u, u̇, q, q̇, q̈, found)`, and the
    /// position as a [`Pose`] when the step has it.
    #[inline(always)]
    fn remember(
        &mut self,
        theta: f64,
        r: Option<(f64, f64, f64, f64, f64, Found)>,
        pose: Option<Pose>,
    ) {
        let m = self.mech;
        self.prev = r.map(|(u, u_rate, q, v, a, found)| {
            let inv_rate = 1.0 / m.touch.cam().speed;
            let du = u_rate * inv_rate;
            // the second derivative of u from the last two rates, when they are close
            let d2u = match self.prev {
                Some(p) if matches!(found, Found::WarmStart) && theta != p.theta => {
                    (du - p.du_dtheta) / (theta - p.theta)
                }
                _ => 0.0,
            };
            Prev {
                theta,
                u,
                q,
                du_dtheta: du,
                dq_dtheta: v * inv_rate,
                d2q_dtheta2: (a - m.touch.cam().angular_acceleration * v * inv_rate)
                    * inv_rate
                    * inv_rate,
                d2u_dtheta2: d2u,
                pose,
            }
        });
    }

    #[inline(always)]
    fn warm(&self, at: &Instant, p: Prev) -> Result<(Touch, Found), CamError> {
        let (theta, frame) = (at.theta, &at.frame);
        let m = self.mech;
        let dt = theta - p.theta;
        // second-order extrapolation: the start is off by O(Δθ³)
        let (u0, q0) = p.start(dt);
        if let (Some(c), Some((last, rate))) = (m.touch.carried(), self.last) {
            let v0 = last.v + dt * rate;
            return m.touch.carried_warm(c, at, (u0, v0, q0), (p.theta, last));
        }
        // on a non-convex profile a knife's crossing can vanish (it merges with its partner where
        // the line of travel grazes the profile) and the tip falls to another crossing: a
        // contact is a continuation only if Newton at the previous angle, started from it, comes
        // back to the previous contact (local rates diverge at the fold, so no step bound works)
        let knife_fold = !m.touch.convex() && m.touch.geometry().is_knife();
        let continues = |t: &Touch| {
            let back = &Instant::new(m.cam(), p.theta);
            m.touch.newton_at(back, t.u, t.q).is_ok_and(|(b, _)| {
                let d = (b.u - p.u).rem_euclid(m.touch.period());
                d.min(m.touch.period() - d) <= 1e-6 * m.touch.period()
            })
        };
        match m.touch.newton_at(at, u0, q0) {
            // on a convex profile the first touch is unique and Newton started next to it: the
            // orientation check is enough (it rejects the cam's back side); a roller's Newton
            // can leap (its residual bends on the scale of the roller's radius, which may be
            // tiny), so its touch must also be the first touch of its cam point
            Ok((t, e))
                if (m.touch.convex() && dispatch!(&m.touch.geometry().model, k => m.touch.convex_warm_touch_with(k, &e, &k.pose(t.q))))
                    // evaluated at the converged point itself: near a cusp the tangent (and
                    // with it the normal) turns over within the last Newton step
                    || (!m.touch.convex() && m.touch.is_first_touch(frame, &t) && (!knife_fold || continues(&t))) =>
            {
                // on a convex profile nothing can overtake the first touch
                if m.touch.convex() {
                    return Ok((t, Found::WarmStart));
                }
                // non-convex: another part of the profile may touch first. A knife's or a
                // roller's reach beside its path can be narrower than the sample spacing, so for
                // them the global search (crossings of the path) decides; for the others the
                // guard bounds the continuous profile and refines the parts that may be ahead
                let threshold = m.touch.oriented(t.q) + m.touch.touch_slack();
                let over = if m.touch.geometry().model.centre_path().is_some() {
                    Overtaken::Sampled
                } else {
                    m.touch.overtaken(at, threshold, t.u)
                };
                let g = match over {
                    Overtaken::No => {
                        m.touch.check_cusps(at, t.q)?;
                        return Ok((t, Found::WarmStart));
                    }
                    Overtaken::By(g) => {
                        m.touch.check_cusps(at, g.q)?;
                        g
                    }
                    Overtaken::Sampled => m.touch.global_touch(at)?,
                };
                if m.touch.oriented(g.q) > threshold {
                    Ok((
                        g,
                        Found::Jump {
                            from_cam_param: t.u,
                        },
                    ))
                } else {
                    Ok((t, Found::WarmStart))
                }
            }
            // the contact followed so far is gone: on a non-convex profile, a contact found
            // elsewhere is a jump
            _ => m.touch.global_touch(at).map(|g| {
                if !m.touch.convex() && !continues(&g) {
                    (g, Found::Jump { from_cam_param: u0 })
                } else {
                    (g, Found::Global)
                }
            }),
        }
    }
}

/// What [`Sweep::remember`] keeps of a motion: `(u, u̇, q, q̇, q̈, found)`.
#[inline(always)]
fn kept(s: &Motion) -> (f64, f64, f64, f64, f64, Found) {
    (
        s.cam_param,
        s.cam_param_rate,
        s.position,
        s.velocity,
        s.acceleration,
        s.found,
    )
}
