//! The spring of a spring-held follower: the least preload with the file's stiffness, the least
//! stiffness with its preload, and the spring from the motion alone (its range, and the one with
//! the least force at full lift).

use crate::dynamics::{FollowerDynamics, ForceState, Forces};
use crate::extreme::best_refined;
use std::f64::consts::TAU;

/// The spring that keeps a spring-held follower on up to the target speed with the margin.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SpringSizing {
    /// the smallest preload with the file's stiffness, N (N·m); at least 0
    pub preload: f64,
    /// the smallest stiffness with the file's preload, N/m (N·m/rad); at least 0. `None`: no
    /// stiffness will do (the follower leaves the cam at its rest position, where only the
    /// preload acts)
    pub stiffness: Option<f64>,
    /// the file's preload
    pub file_preload: f64,
    /// the file's stiffness
    pub file_stiffness: f64,
    /// the spring from the motion alone, whatever the file's
    pub from_motion: SpringDesign,
}

/// The spring from the motion alone: of every stiffness `k` and preload `P` that hold the
/// contact force at least the margin up to the target speed (`P + k s(θ) ≥ r(θ)` at every
/// angle, `s` the lift), the one with the least force at full lift `P + k h` — the spring line
/// tangent to the force the motion needs (a cam designer's construction) — and the softest
/// (`k = 0`, a constant force).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SpringDesign {
    /// its stiffness, N/m (N·m/rad)
    pub stiffness: f64,
    /// its preload at the lowest position, N (N·m)
    pub preload: f64,
    /// its force at full lift `P + k h`, N (N·m)
    pub force_at_full_lift: f64,
    /// the full lift `h`, m (rad)
    pub full_lift: f64,
    /// how far it is compressed at the lowest position, `P/k`, m (rad): its free length is the
    /// installed length plus this (`None` for no stiffness)
    pub preload_deflection: Option<f64>,
    /// the constant force (`k = 0`) that would do, N (N·m)
    pub constant_force: f64,
    /// the range: the least preload at five stiffnesses from none to the one beyond which more
    /// stiffness saves no preload (the preload then only holds the follower at rest), `[k, P]`
    pub trade_off: [[f64; 2]; 5],
}

/// The least `P + k h` over `k ≥ 0` with `P = max(0, max_i (r_i − k s_i))`: convex in `k`,
/// minimised by golden-section search on `[0, k_max]` (beyond `k_max` the preload needed is the
/// one at rest, and the force only grows).
fn spring_from_motion(need: &[(f64, f64)]) -> SpringDesign {
    let h = need.iter().fold(0.0f64, |m, n| m.max(n.1));
    let preload = |k: f64| need.iter().fold(0.0f64, |m, &(r, s)| m.max(r - k * s));
    // at rest (no lift to speak of) only the preload acts: beyond the stiffness that meets
    // every other angle's need with that preload, more stiffness saves no preload
    let rest = 1e-6 * h;
    let at_rest = need
        .iter()
        .filter(|n| n.1 <= rest)
        .fold(0.0f64, |m, n| m.max(n.0));
    let k_max = need
        .iter()
        .filter(|n| n.1 > rest)
        .fold(0.0f64, |m, &(r, s)| m.max((r - at_rest) / s));
    let g = |k: f64| preload(k) + k * h;
    let (mut a, mut b) = (0.0, k_max);
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..200 {
        let (c, d) = (b - phi * (b - a), a + phi * (b - a));
        if g(c) <= g(d) {
            b = d;
        } else {
            a = c;
        }
        if b - a <= 1e-12 * k_max.max(1e-300) {
            break;
        }
    }
    // the search's end, or no stiffness where that does as well (a motion that needs none)
    let k = if g(0.0) <= g(0.5 * (a + b)) {
        0.0
    } else {
        0.5 * (a + b)
    };
    let p = preload(k);
    SpringDesign {
        stiffness: k,
        preload: p,
        force_at_full_lift: p + k * h,
        full_lift: h,
        preload_deflection: (k > 0.0).then(|| p / k),
        constant_force: preload(0.0),
        trade_off: [0.0, 0.25, 0.5, 0.75, 1.0].map(|x| [x * k_max, preload(x * k_max)]),
    }
}

pub(super) fn spring_sizing(
    f: &Forces<'_>,
    states: &[ForceState],
    thetas: &[f64],
    params: &FollowerDynamics,
    margin: f64,
    target: f64,
) -> SpringSizing {
    // the largest need over the revolution, refined between the samples
    let worst = |g: &dyn Fn(&ForceState) -> Option<f64>| {
        let values: Vec<Option<f64>> = states.iter().map(g).collect();
        best_refined(thetas, &values, 1.0, Some(TAU), |t| {
            f.at(t).ok().as_ref().and_then(g)
        })
        .map(|(_, v)| v)
    };
    let preload = worst(&|s| Some(f.preload_needed(s, margin, target))).unwrap_or(0.0);
    let stiffness = worst(&|s| f.stiffness_needed(s, margin, target));
    // where the lift is zero only the preload acts: no stiffness helps if it falls short there
    let possible = states.iter().all(|s| {
        f.stiffness_needed(s, margin, target).is_some()
            || f.preload_needed(s, margin, target) <= params.spring_preload
    });
    // what the motion needs of any spring: `P + k s ≥ r`, `r` the preload needed with no
    // stiffness (the file's taken off)
    let need: Vec<(f64, f64)> = states
        .iter()
        .map(|s| {
            (
                f.preload_needed(s, margin, target) + params.spring_stiffness * s.lift,
                s.lift,
            )
        })
        .collect();
    SpringSizing {
        preload: preload.max(0.0),
        stiffness: possible.then_some(stiffness.unwrap_or(0.0).max(0.0)),
        file_preload: params.spring_preload,
        file_stiffness: params.spring_stiffness,
        from_motion: spring_from_motion(&need),
    }
}
