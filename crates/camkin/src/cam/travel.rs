//! The follower's travel over a revolution: its rest position (nearest the cam: the lowest of a
//! translating follower) and its farthest, with the cam angles where it reaches them, from which
//! cam tools measure **lift**: how far the follower has moved away from its rest position.

use super::{CamError, Mechanism};

/// The follower's extreme positions over one revolution of the cam.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Travel {
    /// the rest position, nearest the cam (length, or arm angle in rad): the origin of lift
    pub rest: f64,
    /// a cam angle where it is reached, rad in `[0, 2π)`
    pub rest_angle: f64,
    /// the position farthest from the cam
    pub peak: f64,
    /// a cam angle where it is reached, rad
    pub peak_angle: f64,
    /// the sign of a change of position away from the cam (+1 for a translating follower; for an
    /// arm, the opposite of its closing sense)
    pub away: f64,
}

impl Travel {
    /// The lift at position `q`: how far it is from rest, away from the cam (≥ 0).
    pub fn lift(&self, q: f64) -> f64 {
        self.away * (q - self.rest)
    }
    /// The stroke: the largest lift.
    pub fn stroke(&self) -> f64 {
        self.lift(self.peak)
    }
}

/// Samples per revolution of the coarse scan.
const SAMPLES: usize = 720;

/// The body of [`Mechanism::travel`] (documented there).
pub(crate) fn travel(mech: &Mechanism) -> Result<Travel, CamError> {
    let step = std::f64::consts::TAU / SAMPLES as f64;
    let mut sweep = mech.sweep();
    let mut q = Vec::with_capacity(SAMPLES);
    for k in 0..SAMPLES {
        q.push(sweep.step_motion(k as f64 * step)?.position);
    }
    let away = mech.follower_joint().away();
    let (mut lo, mut hi) = (0usize, 0usize);
    for k in 1..SAMPLES {
        if away * q[k] < away * q[lo] {
            lo = k;
        }
        if away * q[k] > away * q[hi] {
            hi = k;
        }
    }
    let (rest_angle, rest) = refine_extreme(mech, lo, step, q[lo], -away)?;
    let (peak_angle, peak) = refine_extreme(mech, hi, step, q[hi], away)?;
    Ok(Travel {
        rest,
        rest_angle,
        peak,
        peak_angle,
        away,
    })
}

/// The extreme near sample `k` (`sign` −1 for a minimum, +1 for a maximum): bisection on
/// the velocity between the neighbouring samples, kept only when it improves on the sample.
/// One sweep steps through the bisection (every point within two samples of the last: warm
/// starts), not a cold search at each point (a gear pair's cold search costs 500 of its warm
/// steps).
fn refine_extreme(
    mech: &Mechanism,
    k: usize,
    step: f64,
    qk: f64,
    sign: f64,
) -> Result<(f64, f64), CamError> {
    let t = k as f64 * step;
    let wrap = |a: f64| a.rem_euclid(std::f64::consts::TAU);
    let (mut a, mut b) = (t - step, t + step);
    let mut sweep = mech.sweep();
    let mut motion = |x: f64| sweep.step_motion(x);
    let (va, vb) = (motion(a)?.velocity, motion(b)?.velocity);
    // at a minimum the velocity goes from negative to positive (at a maximum, the reverse)
    if !(sign * va > 0.0 && sign * vb < 0.0) {
        return Ok((wrap(t), qk));
    }
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        if sign * motion(m)?.velocity > 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    let m = 0.5 * (a + b);
    let qm = motion(m)?.position;
    if sign * (qm - qk) >= 0.0 {
        Ok((wrap(m), qm))
    } else {
        Ok((wrap(t), qk))
    }
}
