//! What a valid spec probably did not mean: the warnings a front end shows.

use crate::field::Field;

/// A valid spec that is probably not what was meant.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SpecWarning {
    /// Unevenly spaced nodes under the uniform parameterisation, which puts them at equal
    /// parameter steps and bends the spline between them.
    #[error("{field}: the points are unevenly spaced (the longest chord between neighbours is {} times the shortest) and parameterization = \"uniform\" puts them at equal parameter steps, which bends the spline between them: its accelerations can be off by many times their peak (measured: 17 times at a ratio of 1.5 on a circle); write parameterization = \"chord-length\" unless the profile is defined this way", crate::human::human(*.ratio))]
    UnevenNodes {
        /// `points` or `path`
        field: Field,
        /// longest over shortest chord
        ratio: f64,
    },
    /// A form-closed follower read as a system: its second curve is left out (the follower's
    /// one degree of freedom takes one row; the second contact is the cam path's check).
    #[error("follower.conjugate: the form-closed follower's second curve is left out of the system (one row for its one degree of freedom): the system follows the first contact; `camkin analyze` without --system checks the second")]
    ConjugateLeftOut,
    /// A lift table whose noise (rounding, measurement) its interpolant turns into an
    /// acceleration noise over 1 % of its peak acceleration: nothing is smoothed.
    #[error("{field}: the table's lifts carry noise of about {} (their sixth differences' RMS over √924, in the rise's unit), which its interpolating spline turns into acceleration noise of {} % of its peak acceleration: the cam's acceleration, curvature and forces carry it; smooth the table (or measure it finer) first", crate::human::human(*.sigma), crate::human::human((*.fraction * 1000.0).round() / 10.0))]
    NoisyTable {
        /// the table's `file` or `lift`
        field: Field,
        /// the lifts' noise, the rise's unit
        sigma: f64,
        /// its acceleration noise over its peak acceleration
        fraction: f64,
    },
}
