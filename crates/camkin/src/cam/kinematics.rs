//! The contact method at a converged first touch: the follower's velocity from the velocity
//! constraint, the sliding rates (paper eqs. 5, 6), the normal accelerations (eqs. 1, 2) and the
//! follower's acceleration from the acceleration constraint (eq. 11).

use super::follower::carried::Carried;
use super::follower::rates::CamPoint;
use super::follower::{dispatch, Kind};
use super::pose::Pose;
use super::state::pressure_angle;
use super::{CamError, Corner, FollowerState, Found, Mechanism, Motion, Touch};
use crate::body::{curve_in, BodyState, CurveInFrame, WorldDerivs};
use crate::cam::instant::Instant;
use crate::contact::{ContactKinematics, Pairing, Surface};
use crate::curve::PointCurve;
use crate::geometry::{UnitVec2, Vec2};

/// The shared part of an analysis at a converged touch.
struct Core {
    body_a: crate::curve::Derivs,
    ea: WorldDerivs,
    nu: Vec2,
    jb: Vec2,
    qd: f64,
    qdd: f64,
    u_b: f64,
    k: ContactKinematics,
}

impl Mechanism {
    #[inline(always)]
    pub(crate) fn motion_at(
        &self,
        at: &Instant,
        touch: Touch,
        found: Found,
    ) -> Result<Motion, CamError> {
        let (theta, cam, frame) = (at.theta, &at.cam, &at.frame);
        // a named kind: the closed-form rates at the contact (no normal, body states or
        // constraint row); declined near a refusal, where the paper's method says why
        if self.touch.geometry().carried.is_none() && touch.corner.is_none() {
            let profile = self.touch.cam().profile.as_ref();
            let fast = dispatch!(&self.touch.geometry().model, k => {
                let at = curve_in(frame, profile, touch.u);
                self.closed_form_motion(k, theta, cam, &at, (touch, k.pose(touch.q)), found)
            });
            if let Some(m) = fast {
                return Ok(m);
            }
        }
        let c = self.core(at, touch)?;
        Ok(Motion {
            cam_angle: theta,
            position: touch.q,
            velocity: c.qd,
            acceleration: c.qdd,
            cam_param: touch.u,
            cam_param_rate: c.k.param_rate_a,
            found,
        })
    }

    /// The motion at a converged first touch (with the follower's position as a [`Pose`]) at
    /// the cam point `e` by the closed-form rates of the follower kind `k` (see
    /// [`Kind::rates`]); `None` where they decline.
    #[inline(always)]
    pub(crate) fn closed_form_motion<K: Kind>(
        &self,
        k: &K,
        theta: f64,
        cam: &BodyState,
        e: &WorldDerivs,
        (touch, pose): (Touch, Pose),
        found: Found,
    ) -> Option<Motion> {
        let at = CamPoint::new(e, self.touch.cam().pivot, cam.omega, cam.alpha);
        let [qd, qdd, ud] = k.rates(&at, &pose, &self.touch.prepared().refuse)?;
        Some(Motion {
            cam_angle: theta,
            position: touch.q,
            velocity: qd,
            acceleration: qdd,
            cam_param: touch.u,
            cam_param_rate: ud,
            found,
        })
    }

    /// Velocity, acceleration and contact data at a converged touch (paper eqs. 5, 6, 1, 2, 11).
    /// The contact method at a converged touch: velocity from the velocity constraint, sliding
    /// rates (eqs. 5, 6) and acceleration from the acceleration constraint (eq. 11).
    #[inline(always)]
    fn core(&self, at: &Instant, touch: Touch) -> Result<Core, CamError> {
        let (theta, cam, frame) = (at.theta, &at.cam, &at.frame);
        let g = &self.touch.geometry();
        let profile = self.touch.cam().profile.as_ref();
        let angle_deg = theta.to_degrees();
        let body_a = profile.eval(touch.u);
        let ea = frame.derivs_to_world(&body_a);
        let c = ea.p;
        let nu = self.contact_normal(&ea, &touch);
        let jb = g.joint.velocity_jacobian(c);
        // velocity constraint Φ_q q̇ = 0: ν·v_A^P = q̇ ν·J_B
        let den = nu.dot(&jb);
        if !(den.abs() > self.touch.options().lock_tolerance * jb.norm()) {
            return Err(CamError::Locked {
                angle_deg,
                pressure_angle_deg: pressure_angle(jb, nu).to_degrees(),
            });
        }
        let qd = nu.dot(&cam.velocity_at(c)) / den;
        let body_b = g.joint.body(touch.q, qd, 0.0);
        let (u_b, k) = self.pair_kinematics(theta, cam, &ea, &body_b, touch)?;
        // acceleration constraint Φ_q q̈ = γ (eq. 11), cam accelerations known
        let phi = &k.phi_q;
        let known = phi[2] * cam.alpha;
        let coef = g.joint.coordinate_coefficient(phi);
        let qdd = (k.gamma - known) / coef;
        Ok(Core {
            body_a,
            ea,
            nu,
            jb,
            qd,
            qdd,
            u_b,
            k,
        })
    }

    /// The contact method's kinematics (eqs. 5, 6, 1, 2, 11) at the touch `t`, the cam point
    /// `ea` (world) paired with the follower's curve on `body_b`: the follower curve's parameter
    /// there and the kinematics.
    #[inline(always)]
    pub(crate) fn pair_kinematics(
        &self,
        theta: f64,
        cam: &BodyState,
        ea: &WorldDerivs,
        body_b: &BodyState,
        t: Touch,
    ) -> Result<(f64, ContactKinematics), CamError> {
        let g = &self.touch.geometry();
        let c = ea.p;
        let nu = self.contact_normal(ea, &t);
        let (u_b, mut eb) = g.curve.world_at(&body_b.frame(), c, t.v);
        let pairing = Pairing {
            u_a: t.u,
            u_b,
            point_a: c,
            point_b: eb.p,
            normal: UnitVec2::new_unchecked(nu),
            gap: nu.dot(&(c - eb.p)),
            iterations: 0,
        };
        let tol = self.touch.options().conformal_tolerance;
        let k = match (t.corner, self.touch.carried()) {
            // the cam's corner is a point of the cam resting on the follower's curve
            (Some(Corner::Cam), Some(carried)) => {
                let corner = PointCurve::new(self.touch.cam().profile.position(t.u))?;
                let a = Surface::new(&corner, cam);
                let b = Surface::new(carried.curve.as_ref(), body_b);
                ContactKinematics::new(&a, &b, &pairing, tol)
            }
            // a named follower resting on a corner of the cam: the corner is a point of the cam
            (Some(Corner::Cam), None) => {
                let corner = PointCurve::new(self.touch.cam().profile.position(t.u))?;
                let curve = g.curve.clone().to_arc();
                let a = Surface::new(&corner, cam);
                let b = Surface::new(curve.as_ref(), body_b);
                ContactKinematics::new(&a, &b, &pairing, tol)
            }
            (corner, _) => {
                // the follower's corner is a point of the follower (a knife edge)
                let point = corner == Some(Corner::Follower);
                if point {
                    (eb.d1, eb.d2, eb.d3) = (Vec2::zeros(), Vec2::zeros(), Vec2::zeros());
                }
                ContactKinematics::from_geometry(
                    cam,
                    ea,
                    body_b,
                    &eb,
                    point || g.is_knife(),
                    &pairing,
                    tol,
                )
            }
        }
        .map_err(|source| CamError::Contact {
            angle_deg: theta.to_degrees(),
            source,
        })?;
        Ok((u_b, k))
    }

    /// The common normal at the touch `t`: the cam profile's left normal at the cam point `ea`
    /// (world); at a corner of the cam, which has none, the follower curve's right normal there
    /// (the normal the contact method reports with the cam's corner a point).
    #[inline(always)]
    pub(crate) fn contact_normal(&self, ea: &WorldDerivs, t: &Touch) -> Vec2 {
        if t.corner == Some(Corner::Cam) {
            let fb = self.touch.geometry().joint.pose(t.q).frame();
            let (_, eb) = self.touch.geometry().curve.world_at(&fb, ea.p, t.v);
            -eb.as_derivs().normal()
        } else {
            ea.as_derivs().normal()
        }
    }

    pub(crate) fn kinematics(
        &self,
        at: &Instant,
        touch: Touch,
        found: Found,
    ) -> Result<FollowerState, CamError> {
        let (theta, cam) = (at.theta, &at.cam);
        let Core {
            body_a,
            ea,
            nu,
            jb,
            qd,
            qdd,
            u_b,
            k,
        } = self.core(at, touch)?;
        let g = &self.touch.geometry();
        let c = ea.p;
        let body_b = g.joint.body(touch.q, qd, qdd);
        // a roller's centre (a circle on the follower turns on its pin: the force passes through
        // it), else the contact point
        let reference_motion = match g.curve.circle() {
            Some(r) => g.joint.velocity_jacobian(body_b.pose.to_world(r.center())),
            None => jb,
        };
        let kappa_conv = self.touch.orientation() * k.kappa_a;
        let at_breakpoint = self.at_breakpoint(touch.u);
        // none where a curve's third derivative jumps (a spline node, a piece joint of the
        // carried curve) or the contact sits on a corner
        let dq = match self.touch.carried() {
            _ if at_breakpoint || !self.touch.options().jerk || touch.corner.is_some() => None,
            Some(c) if self.carried_at_breakpoint(c, touch.v) => None,
            Some(c) => Some(super::derivatives::carried_jet_derivatives(
                self, c, at, touch,
            )?),
            None => Some(super::derivatives::jet_derivatives(
                self, theta, cam, touch,
            )?),
        };
        let jerk = dq.map(|dq| {
            let (w, al) = (
                self.touch.cam().speed,
                self.touch.cam().angular_acceleration,
            );
            w * w * w * dq[2] + 3.0 * w * al * dq[1]
        });
        Ok(FollowerState {
            cam_angle: theta,
            position: touch.q,
            velocity: qd,
            acceleration: qdd,
            jerk,
            contact_world: c,
            contact_cam: body_a.p,
            cam_param: touch.u,
            cam_param_rate: k.param_rate_a,
            follower_param: u_b,
            sliding_rate_cam: k.sliding_rate_a,
            sliding_rate_follower: k.sliding_rate_b,
            normal_acceleration_cam: k.normal_acceleration_a(cam),
            normal_acceleration_follower: k.normal_acceleration_b(&body_b),
            normal: UnitVec2::new_unchecked(nu),
            sigma: k.sigma,
            follower_motion: jb,
            reference_motion,
            radius_of_curvature: 1.0 / kappa_conv,
            at_breakpoint,
            corner: touch.corner,
            found,
        })
    }

    /// Whether the carried curve's parameter `v` is on one of its breakpoints (within the
    /// breakpoint tolerance of its parameter span).
    fn carried_at_breakpoint(&self, c: &Carried, v: f64) -> bool {
        let span = c.period.unwrap_or(c.bounds.1 - c.bounds.0);
        let tol = self.touch.options().breakpoint_tolerance * span;
        let bp = &c.breakpoints;
        let i = bp.partition_point(|&b| b <= v);
        let near = |k: usize| bp.get(k).is_some_and(|&b| (b - v).abs() <= tol);
        // a closed curve's parameter wraps: its first breakpoint is also at period + first
        let wrapped = c.period.is_some_and(|p| {
            bp.first().is_some_and(|&b| (b + p - v).abs() <= tol)
                || bp.last().is_some_and(|&b| (v + p - b).abs() <= tol)
        });
        (i > 0 && near(i - 1)) || near(i) || wrapped
    }

    /// True when `u` is within the breakpoint tolerance of a node of the profile.
    fn at_breakpoint(&self, u: f64) -> bool {
        let bp = &self.touch.breakpoints();
        if bp.is_empty() {
            return false;
        }
        let tol = self.touch.options().breakpoint_tolerance * self.touch.period();
        let i = bp.partition_point(|&b| b <= u);
        let below = if i == 0 {
            bp[bp.len() - 1] - self.touch.period()
        } else {
            bp[i - 1]
        };
        let above = if i < bp.len() {
            bp[i]
        } else {
            bp[0] + self.touch.period()
        };
        u - below < tol || above - u < tol
    }
}
