//! What the Newton iteration on a system's positions works with: its tolerances, the buffers
//! an instant reuses (the assembly of the rows, the factorisation, the solutions), and the
//! bodies' states from the coordinate vectors.

use super::joint::RowEval;
use super::lu::Lu;
use super::BodyId;
use crate::body::{BodyState, Pose};
use crate::contact::{ContactKinematics, Pairing};
use crate::geometry::{Point2, Vec2};

/// Newton iterations on the positions before giving up.
pub(super) const MAX_ITERATIONS: u32 = 50;

/// Newton stops when no coordinate moves more than this times the system's size (angles times
/// the size).
pub(super) const STEP_TOLERANCE: f64 = 1e-13;

/// The LU's smallest pivot below this times its largest is a singular matrix (the angle columns
/// scaled by the size, so that every entry is of order one).
pub(super) const SINGULAR: f64 = 1e-10;

/// A contact's gap beyond this times the size, at a Newton step, has the global search check
/// that no nearer pair of points is the contact (a warm-started step predicts gaps far smaller).
pub(super) const SUSPECT_GAP: f64 = 1e-6;

/// The rows of `Φ` at the states, their gradients (row-major, columns `(x, y, size·θ)` of each
/// body) and `γ`, the drivers' rates, and every contact's pairing (refined from the pairing
/// followed) with its kinematics when the states carry velocities. Kept between instants.
#[derive(Debug, Default)]
pub(super) struct Assembly {
    pub(super) phi: Vec<f64>,
    pub(super) jac: Vec<f64>,
    pub(super) gamma: Vec<f64>,
    pub(super) rate: Vec<f64>,
    pub(super) contacts: Vec<(Pairing, Option<ContactKinematics>)>,
    pub(super) rows: Vec<RowEval>,
}

/// Buffers an instant reuses: the assembly, the factorisation, the solutions, the bodies'
/// states, the positions predicted, the contacts' flags.
#[derive(Debug, Default)]
pub(super) struct Scratch {
    pub(super) asm: Assembly,
    pub(super) lu: Lu,
    pub(super) x: Vec<f64>,
    pub(super) neg: Vec<f64>,
    pub(super) st: Vec<BodyState>,
    pub(super) q0: Vec<f64>,
    pub(super) jumped: Vec<bool>,
    pub(super) still: Vec<bool>,
}

/// The index of the largest magnitude (0 for none).
pub(super) fn iamax(v: &[f64]) -> usize {
    (0..v.len()).fold(0, |b, i| if v[i].abs() > v[b].abs() { i } else { b })
}

/// Body `i`'s state from the coordinate vectors (`qd`, `qdd` optional).
pub(super) fn state_of(q: &[f64], qd: Option<&[f64]>, i: usize) -> BodyState {
    let k = 3 * i;
    let mut s = BodyState::at_rest(Pose::new(Point2::new(q[k], q[k + 1]), q[k + 2]));
    if let Some(v) = qd {
        s.velocity = Vec2::new(v[k], v[k + 1]);
        s.omega = v[k + 2];
    }
    s
}

/// The states of every body, and the ground's (at rest at the world's origin).
pub(super) fn states(q: &[f64], qd: Option<&[f64]>, n: usize) -> Vec<BodyState> {
    (0..n).map(|i| state_of(q, qd, i)).collect()
}

/// [`states`] into a buffer kept between instants.
pub(super) fn fill_states(q: &[f64], qd: Option<&[f64]>, n: usize, out: &mut Vec<BodyState>) {
    out.clear();
    out.extend((0..n).map(|i| state_of(q, qd, i)));
}

pub(super) fn ground() -> BodyState {
    BodyState::at_rest(Pose::new(Point2::origin(), 0.0))
}

pub(super) fn get(states: &[BodyState], id: BodyId) -> BodyState {
    id.index().map_or_else(ground, |i| states[i])
}
