//! Tolerances and effort of the analysis.

use crate::contact::CONFORMAL_TOLERANCE;

/// Tolerances and effort of the analysis. Lengths are in the problem's unit;
/// [`AnalysisOptions::for_size`] scales them to the cam.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnalysisOptions {
    /// Newton stops when a step moves the contact point and the follower less than this (length).
    pub position_tolerance: f64,
    /// Newton iterations before giving up.
    pub max_iterations: u32,
    /// Bracketing samples per smooth piece of the profile (a spline segment).
    pub samples_per_piece: usize,
    /// Bracketing samples for a profile without breakpoints (circle, ellipse).
    pub samples_per_curve: usize,
    /// Bracketing samples per smooth piece of a convex profile (its first-touch function has a
    /// single maximum, so a coarse scan finds it).
    pub convex_samples_per_piece: usize,
    /// Bracketing samples of a convex profile without breakpoints.
    pub convex_samples_per_curve: usize,
    /// Local maxima of the sampled first-touch function refined by Newton (at most
    /// [`MAX_CANDIDATES`](super::MAX_CANDIDATES)).
    pub candidates: usize,
    /// Relative tolerance on `D` below which contact is conformal.
    pub conformal_tolerance: f64,
    /// The follower is locked when `|cos|` of the pressure angle is below this.
    pub lock_tolerance: f64,
    /// A refined touch counts as the first touch through its cam point when it agrees with that
    /// point's first-touch position within this, and a warm-started touch stands unless a sampled
    /// one is ahead of it by more than this (length).
    pub touch_tolerance: f64,
    /// Largest Newton step in the cam parameter, as a fraction of its period.
    pub max_step_fraction: f64,
    /// The contact is on a node of a spline profile when its parameter is within this fraction
    /// of the period of one.
    pub breakpoint_tolerance: f64,
    /// Compute the jerk (three more orders of implicit differentiation per angle).
    pub jerk: bool,
    /// A bound `C` (1/length) on Newton's quadratic convergence: a step `δ` leaves an error of
    /// about `C δ²`, so a step whose `C δ²` is below [`AnalysisOptions::position_tolerance`] is
    /// accepted without another evaluation. Conservative by default: `10³` over the smallest of
    /// the cam's size, its sharpest radius of curvature and the roller's radius
    /// ([`Mechanism::new`](super::Mechanism::new) sets it; [`AnalysisOptions::for_size`] gives
    /// `10³/size`).
    pub newton_contraction: f64,
}

impl AnalysisOptions {
    /// Options for a cam whose points lie within `size` of its axis.
    pub fn for_size(size: f64) -> Self {
        Self {
            position_tolerance: 1e-13 * size,
            max_iterations: 50,
            samples_per_piece: 16,
            samples_per_curve: 256,
            convex_samples_per_piece: 4,
            convex_samples_per_curve: 32,
            candidates: 4,
            conformal_tolerance: CONFORMAL_TOLERANCE,
            lock_tolerance: 1e-9,
            touch_tolerance: 1e-10 * size,
            max_step_fraction: 0.1,
            breakpoint_tolerance: 1e-9,
            jerk: true,
            newton_contraction: 1e3 / size,
        }
    }
}
