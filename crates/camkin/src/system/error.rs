//! What can go wrong assembling or analysing a system: each error names the element (body,
//! joint, driver or contact) as the system names it, and the instant.

use super::Coordinate;

/// Why a system cannot be analysed, or an instant of it cannot be solved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SystemError {
    /// An element names a body the system does not have.
    #[error("{element:?} names a body the system does not have")]
    UnknownBody {
        /// the element's name
        element: String,
    },
    /// A joint or contact joins a body to itself.
    #[error("{element:?} joins {body:?} to itself")]
    SameBody {
        /// the element's name
        element: String,
        /// the body's name
        body: String,
    },
    /// A prismatic joint's axis is not a direction (zero, or not finite).
    #[error("{element:?}: its axis is not a direction (it must be finite and not zero)")]
    Axis {
        /// the joint's name
        element: String,
    },
    /// Two drivers set the same coordinate.
    #[error(
        "{element:?} drives the {coordinate} of {body:?}, which another driver already drives"
    )]
    DrivenTwice {
        /// the second driver's name
        element: String,
        /// the body's name
        body: String,
        /// the coordinate
        coordinate: Coordinate,
    },
    /// The rows cannot determine the coordinates: a kinematic analysis needs as many rows
    /// (joints', drivers', contacts') as coordinates (three a body).
    #[error("the system has {coordinates} coordinates (three a body) and {rows} constraint rows: a kinematic analysis needs one row for each (drive every degree of freedom, or remove a redundant joint)")]
    NotSquare {
        /// three a body
        coordinates: usize,
        /// joints', drivers' and contacts' rows
        rows: usize,
    },
    /// The rows are dependent at this instant: a dead point or toggle, or redundant joints.
    #[error("at t = {} s the constraints are singular (a dead point, a toggle, or redundant joints): {rows}", crate::human::human(*time))]
    Singular {
        /// the instant, s
        time: f64,
        /// the rows involved, named
        rows: String,
    },
    /// A contact whose curves are apart where the joints and drivers hold them: no motion they
    /// allow brings them together (the contact's row depends on theirs), so they never touch.
    #[error("at t = {} s contact {contact:?}: its curves are {} apart and the joints and drivers hold them there ({rows}): no motion they allow brings them together, so they never touch; move a body or a curve", crate::human::human(*time), crate::human::human(*gap))]
    HeldApart {
        /// the instant, s
        time: f64,
        /// the contact, named
        contact: String,
        /// the distance between its curves, in the system's length unit
        gap: f64,
        /// the rows that hold it, named
        rows: String,
    },
    /// The drivers take the system to a dead point (toggle) and no farther: instants were
    /// reached ever closer to the one asked for, and there the rows become dependent.
    #[error("the system reaches a dead point (toggle) at t = {} s and cannot be driven past it: its rows become dependent there ({rows})", crate::human::human(*time))]
    DeadPoint {
        /// the last instant reached, s
        time: f64,
        /// the rows involved, named
        rows: String,
    },
    /// An instant too far from the last solved to follow the assembly to it (through every
    /// instant between), in a system that does not repeat within 8 revolutions of its driver.
    #[error("at t = {} s: following the assembly there from the last instant solved (t = {} s) takes about {} instants between (about {} s), and the system does not repeat within 8 revolutions of its first driver: ask for instants nearer the start", crate::human::human(*time), crate::human::human(*from), crate::human::human(instants.round()), crate::human::human(seconds.round()))]
    TooFar {
        /// the instant asked for, s
        time: f64,
        /// the last instant solved, s
        from: f64,
        /// the instants between that following it would take
        instants: f64,
        /// the seconds they would take ([`super::System::instant_seconds`] each)
        seconds: f64,
    },
    /// Newton on the positions did not converge: the system cannot assemble at this instant
    /// (a closed loop that does not close, a contact lost).
    #[error("at t = {} s the system cannot be assembled: {reason}{}", crate::human::human(*time), residual_note(*residual, row))]
    NoAssembly {
        /// the instant, s
        time: f64,
        /// why Newton stopped
        reason: &'static str,
        /// the largest row residual left
        residual: f64,
        /// that row, named
        row: String,
    },
    /// A contact's pairing or kinematics failed.
    #[error("at t = {} s, contact {contact:?}: {reason}", crate::human::human(*time))]
    Contact {
        /// the instant, s
        time: f64,
        /// the contact's name
        contact: String,
        /// what failed
        reason: String,
    },
    /// The jerk is not defined at this instant (a contact on a breakpoint of its curve, where
    /// the third derivative jumps), or the rows do not determine it (a conformal contact).
    #[error("at t = {} s the jerk is not defined{}: {reason}", crate::human::human(*time), if element.is_empty() { String::new() } else { format!(" (contact {element:?})") })]
    NoJerk {
        /// the instant, s
        time: f64,
        /// the contact's name, or empty
        element: String,
        /// why
        reason: &'static str,
    },
}

/// ` (largest residual R, in ROW)` where Newton left one; nothing where it did not get as far
/// (the rows were dependent before a residual was reduced).
fn residual_note(residual: f64, row: &str) -> String {
    if residual.is_finite() && !row.is_empty() {
        format!(
            " (largest residual {}, in {row})",
            crate::human::human(residual)
        )
    } else if residual.is_finite() {
        format!(" (largest residual {})", crate::human::human(residual))
    } else {
        String::new()
    }
}
