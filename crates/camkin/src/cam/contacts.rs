//! Every contact at an instant. The follower rests at its first touch; wherever else its curve
//! touches the cam at that position (the next tooth pair of two gears while the contact ratio
//! is above one, a roller bridging a notch, a flat face on two equal lobes) is a contact too,
//! with its own sliding rates, normal accelerations and acceleration constraint row.
//!
//! Each [`CamContact`]'s row is eq. 11 in the mechanism's two coordinates, the cam angle `θ` (in
//! the cam's own direction, as everywhere in [`crate::cam`]) and the follower's `q`:
//!
//! ```text
//! Φ_θ θ̈ + Φ_q q̈ = γ        Φ_θ = ±Φ_θA,  Φ_q = Φ_pB·d (slide) or Φ_θB (pivot)
//! ```
//!
//! with `Φ_θA`, `Φ_pB`, `Φ_θB` the entries of [`ContactKinematics::phi_q`](crate::contact::ContactKinematics::phi_q) for the cam's and the
//! follower's body coordinates. The first contact's row is the one the follower's acceleration
//! is solved from; another contact's row holds at the same motion only if the two contacts agree
//! (ideal involutes do; a worn tooth would not): its [`CamContact::residual`] says by how much, and
//! its [`CamContact::normal_velocity`] whether the motion opens or closes it.

use super::follower::Kind as _;
use super::{CamError, FollowerState, Mechanism, Touch};
use crate::body::CurveInFrame;
use crate::cam::instant::Instant;
use crate::contact::NormalAcceleration;
use crate::geometry::{Point2, UnitVec2};

/// One contact between the cam and the follower at an instant. World frame; lengths in the
/// mechanism's unit, time in s; `q` in length (slide) or rad (pivot).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct CamContact {
    /// the cam angle `θ`, rad
    pub cam_angle: f64,
    /// the cam-profile parameter at the contact
    pub cam_param: f64,
    /// the follower curve's parameter at the contact
    pub follower_param: f64,
    /// the contact point (on the cam), world frame
    pub point: Point2,
    /// the common normal `ν_A` (the cam profile's left normal), world frame
    pub normal: UnitVec2,
    /// how far the follower would move in its closing sense before this contact alone touches,
    /// length (zero within the touch tolerance: 0 for the first contact); for the second curve
    /// of a conjugate follower, its play (negative: it cuts into the cam)
    pub gap: f64,
    /// `ν_A·(v_A^P − v_B^P)` with the follower's velocity, length/s: zero where the motion keeps
    /// this contact closed
    pub normal_velocity: f64,
    /// `ṡ_A`: sliding rate along the cam profile, relative to the cam, length/s (eq. 5)
    pub sliding_rate_cam: f64,
    /// `ṡ_B`: sliding rate along the follower's curve, relative to the follower, length/s (eq. 6)
    pub sliding_rate_follower: f64,
    /// normal acceleration seen from the cam (eq. 1), along `normal`, length/s²
    pub normal_acceleration_cam: NormalAcceleration,
    /// normal acceleration seen from the follower (eq. 2), with the follower's acceleration,
    /// along `normal`, length/s²
    pub normal_acceleration_follower: NormalAcceleration,
    /// `Φ_θ`, the row's coefficient of the cam's angular acceleration, length/rad
    pub row_cam: f64,
    /// `Φ_q`, the row's coefficient of the follower's acceleration, length per unit of `q`
    pub row_follower: f64,
    /// `γ`, the row's right-hand side, length/s²
    pub gamma: f64,
    /// `Φ_θ θ̈ + Φ_q q̈ − γ` at the motion of the state, length/s² (zero for the first contact;
    /// for another, zero where the contacts agree)
    pub residual: f64,
    /// the contact is the second curve's of a conjugate follower ([`Mechanism::with_conjugate`]);
    /// `follower_param` is then that curve's parameter
    pub conjugate: bool,
    /// the contact is at a corner of this curve, not a tangency (see [`FollowerState::corner`])
    pub corner: Option<super::Corner>,
}

/// The body of [`Mechanism::contacts`] (documented there).
pub(crate) fn contacts(mech: &Mechanism, theta: f64) -> Result<Vec<CamContact>, CamError> {
    contacts_at(mech, &mech.analyze(theta)?)
}

/// The body of [`Mechanism::contacts_seconds_estimate`] (documented there).
pub(crate) fn contacts_seconds_estimate(mech: &Mechanism, angles: usize) -> f64 {
    let per_angle = if mech.touch.carried().is_some() {
        // every contact of a carried curve searched: timed once here (it grows with both curves)
        let t0 = std::time::Instant::now();
        if let Ok(s) = mech.analyze(0.37) {
            let _ = contacts_at(mech, &s);
        }
        1.5e-3f64.max(t0.elapsed().as_secs_f64())
    } else {
        5e-5
    };
    mech.sweep_seconds_estimate(angles) + angles as f64 * per_angle
}

/// The body of [`Mechanism::contacts_at`] (documented there).
pub(crate) fn contacts_at(
    mech: &Mechanism,
    s: &FollowerState,
) -> Result<Vec<CamContact>, CamError> {
    let at = &Instant::new(mech.cam(), s.cam_angle);
    let frame = &at.frame;
    let first = Touch {
        u: s.cam_param,
        q: s.position,
        v: s.follower_param,
        corner: s.corner,
    };
    let mut touches = vec![first];
    match mech.touch.carried() {
        Some(c) => mech.touch.carried_touching(c, at, &first, &mut touches),
        None => named_touching(mech, at, &first, &mut touches),
    }
    // one contact per place
    let close = 1e-6 * mech.touch.size();
    let mut places: Vec<Point2> = Vec::new();
    let mut out = Vec::with_capacity(touches.len());
    for t in &touches {
        let x = frame.curve_position(mech.touch.cam().profile.as_ref(), t.u);
        if places.iter().any(|y| (x - y).norm() <= close) {
            continue;
        }
        places.push(x);
        out.push(contact(mech, at, t, s)?);
    }
    // the others in the order of the cam's parameter, whatever order the search found them in
    out[1..].sort_by(|a, b| a.cam_param.total_cmp(&b.cam_param));
    if let Some(c) = mech.conjugate_contact(s)? {
        out.push(c);
    }
    Ok(out)
}

/// The named kinds' other tangencies at `t`'s position: Newton from each start of the
/// global search, kept when it is a first touch within the touch tolerance of `t`.
fn named_touching(mech: &Mechanism, at: &Instant, t: &Touch, out: &mut Vec<Touch>) {
    let frame = &at.frame;
    let mut starts = super::first_touch::starts::Candidates::new(super::MAX_CANDIDATES);
    if mech.touch.geometry().model.centre_path().is_some() {
        mech.touch
            .path_starts(frame, &mech.touch.index().dense, &mut starts);
    } else {
        mech.touch
            .score_starts(frame, &mech.touch.index().dense, &mut starts);
    }
    let slack = mech.touch.touch_slack();
    for &(_, u0, q0) in starts.as_slice() {
        if let Ok(t2) = mech.touch.newton(at, u0, q0) {
            if mech.touch.ahead(t.q, t2.q).abs() <= slack && mech.touch.is_first_touch(frame, &t2) {
                out.push(t2);
            }
        }
    }
}

/// The kinematics of the contact `t` with the follower at the state `s`'s position,
/// velocity and acceleration.
pub(crate) fn contact(
    mech: &Mechanism,
    at: &Instant,
    t: &Touch,
    s: &FollowerState,
) -> Result<CamContact, CamError> {
    let (theta, cam, frame) = (at.theta, &at.cam, &at.frame);
    let g = &mech.touch.geometry();
    let ea = frame.derivs_to_world(&mech.touch.cam().profile.eval(t.u));
    let (c, nu) = (ea.p, mech.contact_normal(&ea, t));
    let body_b = g.joint.body(s.position, s.velocity, s.acceleration);
    let (u_b, k) = mech.pair_kinematics(theta, cam, &ea, &body_b, *t)?;
    let row_cam = k.phi_q[2] * mech.touch.cam().direction.sign();
    let row_follower = g.joint.coordinate_coefficient(&k.phi_q);
    Ok(CamContact {
        cam_angle: theta,
        cam_param: t.u,
        follower_param: u_b,
        point: c,
        normal: UnitVec2::new_unchecked(nu),
        gap: mech.touch.ahead(s.position, t.q) * g.q_length_scale(mech.touch.size()),
        normal_velocity: k.normal_velocity,
        sliding_rate_cam: k.sliding_rate_a,
        sliding_rate_follower: k.sliding_rate_b,
        normal_acceleration_cam: k.normal_acceleration_a(cam),
        normal_acceleration_follower: k.normal_acceleration_b(&body_b),
        row_cam,
        row_follower,
        gamma: k.gamma,
        residual: row_cam * mech.touch.cam().angular_acceleration + row_follower * s.acceleration
            - k.gamma,
        conjugate: false,
        corner: t.corner,
    })
}
