//! Where the contact jumps: rows of a sweep flagged by the warm start's guard, or whose contact
//! passed over a stretch the follower cannot follow.

use super::{CamError, FollowerState, Found, Mechanism};
use crate::curve::Domain;

/// Rows whose contact jumped since the previous row: flagged by the sweep, or (for contiguous
/// angles) the contact parameter passed over a stretch the follower cannot follow, which it can
/// only do by jumping.
pub fn contact_jumps(
    mech: &Mechanism,
    results: &[Result<FollowerState, CamError>],
    contiguous: bool,
) -> Vec<bool> {
    contact_jumps_with(mech, &mech.unfollowable_stretches(), results, contiguous)
}

/// [`contact_jumps`] with the mechanism's [`Mechanism::unfollowable_stretches`] computed once by
/// the caller (a long run in chunks).
pub fn contact_jumps_with(
    mech: &Mechanism,
    stretches: &[(f64, f64)],
    results: &[Result<FollowerState, CamError>],
    contiguous: bool,
) -> Vec<bool> {
    let period = match mech.cam().profile().domain() {
        Domain::Periodic { period } => period,
        _ => 1.0,
    };
    let mut out = vec![false; results.len()];
    for k in 0..results.len() {
        let Ok(s) = &results[k] else { continue };
        if matches!(s.found, Found::Jump { .. }) {
            out[k] = true;
            continue;
        }
        let Some(Ok(p)) = k.checked_sub(1).map(|i| &results[i]) else {
            continue;
        };
        if !contiguous || stretches.is_empty() {
            continue;
        }
        // the arc from the previous contact to this one, in the direction the contact moves
        let dir = if p.cam_param_rate >= 0.0 { 1.0 } else { -1.0 };
        let arc = (dir * (s.cam_param - p.cam_param)).rem_euclid(period);
        let inside = |u: f64| {
            let d = (dir * (u - p.cam_param)).rem_euclid(period);
            d > 0.0 && d < arc
        };
        out[k] = stretches.iter().any(|&(a, b)| inside(a) && inside(b));
    }
    out
}

/// The body of [`Mechanism::jump_angles`] (documented there).
pub(crate) fn jump_angles(mech: &Mechanism, step_deg: f64) -> Vec<f64> {
    // on a convex profile the first touch moves continuously: nothing to scan
    if mech.touch.convex() {
        return Vec::new();
    }
    let n = (360.0 / step_deg).ceil().max(1.0) as usize;
    let angles: Vec<f64> = (0..=n).map(|k| k as f64 * 360.0 / n as f64).collect();
    let mut sweep = mech.sweep();
    let results: Vec<_> = angles.iter().map(|&a| sweep.step(a.to_radians())).collect();
    contact_jumps(mech, &results, true)
        .into_iter()
        .zip(&angles)
        .filter(|(j, _)| *j)
        .map(|(_, &a)| a % 360.0)
        .collect()
}
