//! What can go wrong in building or analysing a mechanism.

use crate::contact::ContactError;
use crate::curve::CurveError;
use crate::field::Field;

/// What went wrong in building or analysing a mechanism.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CamError {
    /// A curve could not be built.
    #[error(transparent)]
    Curve(#[from] CurveError),
    /// A parameter is out of range.
    #[error("{field} = {}: {reason}", crate::human::human(*.value))]
    Invalid {
        /// the field
        field: Field,
        /// the value given
        value: f64,
        /// what it must be
        reason: &'static str,
    },
    /// A point or a vector is out of range.
    #[error("{field} = [{}, {}]: {reason}", crate::human::human(*.x), crate::human::human(*.y))]
    InvalidVector {
        /// the field
        field: Field,
        /// its x
        x: f64,
        /// its y
        y: f64,
        /// what it must be
        reason: &'static str,
    },
    /// Too few nodal points for the interpolation method.
    #[error("the interpolation needs at least 3 nodal points, got {nodes}")]
    TooFewNodes {
        /// the number given
        nodes: usize,
    },
    /// The follower's motion does not repeat every revolution of the cam (a gear pair's driven
    /// gear turns on): a study of a revolution's periodic interpolation does not apply.
    #[error("the follower's motion does not repeat every revolution (its mean velocity is {} of its peak: it turns on, as a gear pair's driven gear does); the interpolation study compares a motion that repeats", crate::human::human(*.moves_on))]
    MotionDoesNotRepeat {
        /// the net motion over a revolution, as a fraction of the peak velocity times a
        /// revolution's time
        moves_on: f64,
    },
    /// The cam profile is not a closed curve.
    #[error("the cam profile must be a closed curve")]
    OpenProfile,
    /// The follower never touches the cam at this angle.
    #[error("at cam angle {}°: the follower does not touch the cam ({reason})", crate::human::human(*.angle_deg))]
    NoTouch {
        /// cam angle, degrees
        angle_deg: f64,
        /// why
        reason: &'static str,
    },
    /// The contact normal is perpendicular to the follower's motion: no velocity solves the
    /// contact condition.
    #[error(
        "at cam angle {angle_deg}°: the follower is locked (pressure angle {pressure_angle_deg}°)"
    )]
    Locked {
        /// cam angle, degrees
        angle_deg: f64,
        /// pressure angle, degrees
        pressure_angle_deg: f64,
    },
    /// The first-touch Newton iteration did not converge.
    #[error("at cam angle {}°: the first-touch search did not converge ({reason})", crate::human::human(*.angle_deg))]
    NoConvergence {
        /// cam angle, degrees
        angle_deg: f64,
        /// why the search stopped
        reason: StopReason,
    },
    /// The follower can never touch the cam.
    #[error("{field} = {}: {reason}", crate::human::human(*.value))]
    Unreachable {
        /// the field
        field: Field,
        /// its value
        value: f64,
        /// why, with the dimensions involved
        reason: String,
    },
    /// The profile encloses no area (collinear points: it runs out and back along a line).
    #[error("the cam profile encloses no area (signed area {}): are its points collinear?", crate::human::human(*.area))]
    NoArea {
        /// the signed area enclosed
        area: f64,
    },
    /// The profile has a cusp: its tangent vanishes, so its normal and curvature are undefined.
    #[error("the cam profile has a cusp (zero-length tangent) at u = {}, ({}, {}) in the cam frame", crate::human::human(*.param), crate::human::human(*.x), crate::human::human(*.y))]
    Cusp {
        /// the profile parameter
        param: f64,
        /// cam-frame x
        x: f64,
        /// cam-frame y
        y: f64,
    },
    /// The contact kinematics could not be computed.
    #[error("at cam angle {}°: {source}", crate::human::human(*.angle_deg))]
    Contact {
        /// cam angle, degrees
        angle_deg: f64,
        /// the contact error
        source: ContactError,
    },
    /// A conjugate follower's second curve cannot be used.
    #[error("{field}: {reason}")]
    Conjugate {
        /// `follower.conjugate`
        field: Field,
        /// why not
        reason: String,
    },
}

/// Why the first-touch search stopped without an answer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum StopReason {
    /// the tangency Jacobian is singular (or not finite) at an iterate
    SingularJacobian,
    /// Newton's iteration limit was reached
    IterationLimit,
    /// Newton converged to a tangency that is not the first touch (the cam's back side, a roller
    /// touching from inside)
    NotFirstTouch,
    /// the bracketing found no start
    NoCandidate,
    /// the refined contact is behind a sampled point of the first-touch function
    BehindSample,
    /// the follower rests on a cusp of a folded profile (a corner: no tangency, no contact
    /// kinematics); the profile folds where the follower cannot follow its motion program
    OnCusp,
    /// the contact is at a corner of a curve (a gear's tip, where a linear tip relief starts)
    /// and the corner's own Newton found no resting place on the other curve there
    OnCorner,
    /// a Newton search for a tangency near a place (a sample within the follower's reach of
    /// touching) travelled farther than the samples' spacing allows without converging
    LeftRegion,
}

impl std::fmt::Display for StopReason {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            StopReason::SingularJacobian => "singular tangency Jacobian",
            StopReason::IterationLimit => "iteration limit reached",
            StopReason::NotFirstTouch => "Newton reached a tangency that is not the first touch",
            StopReason::NoCandidate => "no candidate",
            StopReason::BehindSample => "refined contact is behind a sampled one",
            StopReason::OnCorner => {
                "the contact is at a corner of a curve (a gear's tip, where a linear tip relief starts), and no resting place of that corner on the other curve was found"
            }
            StopReason::LeftRegion => {
                "Newton left the neighbourhood of the place it was started for without converging"
            }
            StopReason::OnCusp => {
                "the follower rests on a cusp of the profile, which folds over itself there (the follower cannot follow the motion program)"
            }
        })
    }
}
