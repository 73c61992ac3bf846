//! Derivatives of the follower's position in the cam angle by implicit differentiation of the
//! first-touch tangency conditions with Taylor jets (see the `jet` module): the jerk, and a
//! cross-check of the method's velocity and acceleration that shares the search, the profile
//! derivatives and the tangency residual with it (not an independent computation).

use super::follower::carried::Carried;
use super::follower::Kind as _;
use super::linear::{solve2, solve3};
use super::{CamError, FollowerJoint, Mechanism, StopReason, Touch};
use crate::body::BodyState;
use crate::cam::instant::Instant;
use crate::curve::Derivs;
use crate::geometry::Rotation;
use crate::jet::{curve_jets, scale, turned, Jet, Num, V2};

/// The body of [`Mechanism::angle_derivatives`] (documented there).
pub(crate) fn angle_derivatives(mech: &Mechanism, theta: f64) -> Result<[f64; 3], CamError> {
    let at = &Instant::new(mech.cam(), theta);
    let touch = mech.touch.global_touch(at)?;
    match mech.touch.carried() {
        Some(c) => carried_jet_derivatives(mech, c, at, touch),
        None => jet_derivatives(mech, theta, &at.cam, touch),
    }
}

/// The cam's point and tangent at `u + dl` (world) as jets in the cam angle `θ + ε`.
fn cam_jets(mech: &Mechanism, r: &Derivs, theta: f64, dl: Jet) -> (V2<Jet>, V2<Jet>) {
    let s = mech.touch.cam().direction.sign();
    let rot0 = Rotation::new(s * theta);
    // R(θ + ε) = R(θ) R(s ε) as jets: cos(sε) = 1 − ε²/2, sin(sε) = s ε − s ε³/6 (s = ±1)
    let (ce, se) = (Jet([1.0, 0.0, -0.5, 0.0]), Jet([0.0, s, 0.0, -s / 6.0]));
    let (c0, s0) = (rot0.cos_angle(), rot0.sin_angle());
    let rot = (scale(ce, c0) - scale(se, s0), scale(se, c0) + scale(ce, s0));
    let (x, x1) = curve_jets(r, dl);
    (
        turned(rot, x) + V2::c(mech.touch.cam().pivot.coords),
        turned(rot, x1),
    )
}

/// [`Mechanism::angle_derivatives`] at a converged touch of a named follower kind.
pub(crate) fn jet_derivatives(
    mech: &Mechanism,
    theta: f64,
    cam: &BodyState,
    touch: Touch,
) -> Result<[f64; 3], CamError> {
    let profile = mech.touch.cam().profile.as_ref();
    let r = profile.eval(touch.u);
    let j = mech.touch.geometry().model.jacobian(
        &cam.eval_curve(profile, touch.u),
        &mech.touch.geometry().model.pose(touch.q),
    );
    if !solve2(&j, [1.0, 1.0]).iter().all(|x| x.is_finite()) {
        return Err(CamError::NoConvergence {
            angle_deg: theta.to_degrees(),
            reason: StopReason::SingularJacobian,
        });
    }
    let mut u = [0.0; 4];
    let mut q = [touch.q, 0.0, 0.0, 0.0];
    for k in 1..=3 {
        let (x, x1) = cam_jets(mech, &r, theta, Jet([0.0, u[1], u[2], u[3]]));
        let f = mech.touch.geometry().model.residual_value(x, x1, Jet(q));
        [u[k], q[k]] = solve2(&j, [f[0].0[k], f[1].0[k]]);
    }
    Ok([q[1], 2.0 * q[2], 6.0 * q[3]])
}

/// [`Mechanism::angle_derivatives`] at a converged tangency of the carried curve `c`: the
/// unknowns are the cam's parameter `u`, the carried curve's `v` and the position `q`, the
/// conditions those of Newton's (`x_A(u, θ) = x_B(v, q)`, `x_A' × x_B' = 0`). The curves'
/// fourth derivatives would enter the tangency row at order 3 only, and the `q`-row of `J⁻¹`
/// has a zero there (with the tangents parallel, the first two rows alone fix `q`, by their
/// component along the normal), so they are left out. `frame` is the cam's at `theta`.
pub(crate) fn carried_jet_derivatives(
    mech: &Mechanism,
    c: &Carried,
    at: &Instant,
    touch: Touch,
) -> Result<[f64; 3], CamError> {
    let (theta, frame) = (at.theta, &at.frame);
    let singular = || CamError::NoConvergence {
        angle_deg: theta.to_degrees(),
        reason: StopReason::SingularJacobian,
    };
    let (a, b) = (
        mech.touch.cam().profile.eval(touch.u),
        c.curve.eval(touch.v),
    );
    let (.., j) = mech
        .touch
        .carried_system(c, frame, (touch.u, touch.v, touch.q));
    solve3(j, [1.0, 1.0, 1.0]).ok_or_else(singular)?;
    let (mut u, mut v, mut q) = ([0.0; 4], [0.0; 4], [touch.q, 0.0, 0.0, 0.0]);
    for k in 1..=3 {
        let (xa, xa1) = cam_jets(mech, &a, theta, Jet([0.0, u[1], u[2], u[3]]));
        let (y, y1) = curve_jets(&b, Jet([0.0, v[1], v[2], v[3]]));
        // the follower's frame at q: a slide's keeps its angle 0 (the curve was turned to
        // the world's axes when it was carried), an arm's turns by q
        let (xb, xb1) = match mech.touch.geometry().joint {
            FollowerJoint::Translating { origin, direction } => (
                V2::c(origin.coords) + V2::c(*direction).scale(Jet(q)) + y,
                y1,
            ),
            FollowerJoint::Rotating { pivot, .. } => {
                let (sin, cos) = Jet(q).sin_cos();
                (
                    turned((cos, sin), y) + V2::c(pivot.coords),
                    turned((cos, sin), y1),
                )
            }
        };
        let f = [xa.x - xb.x, xa.y - xb.y, xa1.x * xb1.y - xa1.y * xb1.x];
        [u[k], v[k], q[k]] = solve3(j, [f[0].0[k], f[1].0[k], f[2].0[k]]).ok_or_else(singular)?;
    }
    Ok([q[1], 2.0 * q[2], 6.0 * q[3]])
}
