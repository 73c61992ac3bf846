//! Sweeps over cam angles that warm-start each angle from the previous contact.
//!
//! The previous contact `(u, q)` is extrapolated to the new angle with its rates
//! (`du/dθ = u̇_A/θ̇`, `dq/dθ = q̇/θ̇`) and polished by the same Newton iteration as the global
//! search. A guard then checks that the contact has not jumped to another part of the profile:
//! on a convex profile the first touch is unique and no guard is needed; on a non-convex one the
//! sampled first-touch function is compared with the warm contact, and if another part of the
//! profile touches first the global search is used and the row is marked [`Found::Jump`].

use super::{CamError, FollowerState, Mechanism, Touch};
use crate::body::Frame;

/// How the contact at an angle was found.
#[derive(Debug, Clone, Copy, PartialEq)]
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

/// A warm-started sweep; see the [module docs](self).
#[derive(Debug, Clone)]
pub struct Sweep<'a> {
    mech: &'a Mechanism,
    prev: Option<Prev>,
}

#[derive(Debug, Clone, Copy)]
struct Prev {
    theta: f64,
    u: f64,
    q: f64,
    du_dtheta: f64,
    dq_dtheta: f64,
}

/// Largest angle step (rad) over which the previous contact is used as a start.
pub const MAX_WARM_STEP: f64 = 0.2;

impl<'a> Sweep<'a> {
    pub(crate) fn new(mech: &'a Mechanism) -> Self {
        Self { mech, prev: None }
    }

    /// Analyses the next cam angle `theta` (rad).
    pub fn step(&mut self, theta: f64) -> Result<FollowerState, CamError> {
        let m = self.mech;
        let cam = m.cam.state(theta);
        let frame = cam.frame();
        let found = match self.prev {
            Some(p) if (theta - p.theta).abs() <= MAX_WARM_STEP => self.warm(theta, &frame, p),
            _ => m.global_touch(theta, &frame).map(|t| (t, Found::Global)),
        };
        let result = found.and_then(|(t, f)| m.kinematics(theta, &cam, &frame, t, f));
        self.prev = match &result {
            Ok(s) => {
                let rate = m.cam.speed;
                Some(Prev {
                    theta,
                    u: s.cam_param,
                    q: s.position,
                    du_dtheta: s.sliding_rate_cam
                        / m.cam.profile().eval(s.cam_param).d1.norm()
                        / rate,
                    dq_dtheta: s.velocity / rate,
                })
            }
            Err(_) => None,
        };
        result
    }

    fn warm(&self, theta: f64, frame: &Frame, p: Prev) -> Result<(Touch, Found), CamError> {
        let m = self.mech;
        let dt = theta - p.theta;
        let u0 = p.u + p.du_dtheta * dt;
        let q0 = p.q + p.dq_dtheta * dt;
        match m.newton(theta, frame, u0, q0) {
            Ok(t) if m.is_first_touch(frame, &t) => {
                // on a convex profile the first touch is unique: nothing can overtake it
                if m.convex {
                    return Ok((t, Found::WarmStart));
                }
                // non-convex: another part of the profile touches first if a sample does (a
                // sampled score is an exact first touch of that point)
                let ahead = if m.geometry.is_knife() {
                    true
                } else {
                    m.best_sampled_score(frame) > m.oriented(t.q) + m.touch_slack()
                };
                if !ahead {
                    return Ok((t, Found::WarmStart));
                }
                let g = m.global_touch(theta, frame)?;
                if m.oriented(g.q) > m.oriented(t.q) + m.touch_slack() {
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
            _ => m.global_touch(theta, frame).map(|t| (t, Found::Global)),
        }
    }
}
