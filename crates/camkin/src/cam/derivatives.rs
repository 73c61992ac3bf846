//! Derivatives of the follower's position in the cam angle by implicit differentiation of the
//! first-touch tangency conditions with Taylor jets (see the `jet` module): the jerk, and a
//! cross-check of the method's velocity and acceleration that shares the search, the profile
//! derivatives and the tangency residual with it (not an independent computation).

use super::follower::Kind as _;
use super::jet::{scale, Jet, Num, V2};
use super::search::solve2;
use super::{CamError, Mechanism, StopReason, Touch};
use crate::body::BodyState;
use crate::geometry::{Rotation, Vec2};

impl Mechanism {
    /// `(dq/dθ, d²q/dθ², d³q/dθ³)` at cam angle `theta` (rad) by implicit differentiation of the
    /// first-touch conditions (see the `jet` module). This is independent of the paper's method
    /// and gives the jerk; `d³q/dθ³` takes the profile's third derivative on the segment that
    /// holds the contact (at a spline node it jumps).
    pub fn angle_derivatives(&self, theta: f64) -> Result<[f64; 3], CamError> {
        let cam = self.cam.state(theta);
        let touch = self.global_touch(theta, &cam.frame())?;
        self.jet_derivatives(theta, &cam, touch)
    }

    pub(crate) fn jet_derivatives(
        &self,
        theta: f64,
        cam: &BodyState,
        touch: Touch,
    ) -> Result<[f64; 3], CamError> {
        let profile = self.cam.profile.as_ref();
        let r = profile.eval(touch.u);
        let s = self.cam.direction.sign();
        let rot0 = Rotation::new(s * theta);
        // R(s ε) as jets: cos(sε) = 1 − ε²/2, sin(sε) = s ε − s ε³/6 (s = ±1)
        let (ce, se) = (Jet([1.0, 0.0, -0.5, 0.0]), Jet([0.0, s, 0.0, -s / 6.0]));
        let j = self.geometry.model.jacobian(
            &cam.eval_curve(profile, touch.u),
            &self.geometry.model.pose(touch.q),
        );
        if !solve2(&j, [1.0, 1.0]).iter().all(|x| x.is_finite()) {
            return Err(CamError::NoConvergence {
                angle_deg: theta.to_degrees(),
                reason: StopReason::SingularJacobian,
            });
        }
        let mut u = [0.0; 4];
        let mut q = [touch.q, 0.0, 0.0, 0.0];
        let world = |x: Jet, y: Jet, origin: Vec2| {
            let (ax, ay) = (ce * x - se * y, se * x + ce * y);
            V2::new(
                Jet::c(origin.x) + scale(ax, rot0.cos_angle()) - scale(ay, rot0.sin_angle()),
                Jet::c(origin.y) + scale(ax, rot0.sin_angle()) + scale(ay, rot0.cos_angle()),
            )
        };
        for k in 1..=3 {
            let dl = Jet([0.0, u[1], u[2], u[3]]);
            let (d2, d3) = (dl * dl, dl * dl * dl);
            let taylor = |c0: f64, c1: f64, c2: f64, c3: f64| {
                Jet::c(c0) + scale(dl, c1) + scale(d2, c2 / 2.0) + scale(d3, c3 / 6.0)
            };
            let x = world(
                taylor(r.p.x, r.d1.x, r.d2.x, r.d3.x),
                taylor(r.p.y, r.d1.y, r.d2.y, r.d3.y),
                self.cam.pivot.coords,
            );
            // ∂x/∂u along the path; the fourth derivative is left out (it does not reach q, see jet.rs)
            let x1 = world(
                taylor(r.d1.x, r.d2.x, r.d3.x, 0.0),
                taylor(r.d1.y, r.d2.y, r.d3.y, 0.0),
                Vec2::zeros(),
            );
            let f = self.geometry.model.residual_value(x, x1, Jet(q));
            [u[k], q[k]] = solve2(&j, [f[0].0[k], f[1].0[k]]);
        }
        Ok([q[1], 2.0 * q[2], 6.0 * q[3]])
    }
}
