//! Planar multibody dynamics with the contact acceleration constraint of the paper (eq. 11).
//!
//! Coordinates are absolute: body `i` has `q_i = (x_i, y_i, θ_i)`, its frame's origin and angle
//! (conventions: see the [crate docs](crate#sign-conventions)). Constraints `Φ(q, t) = 0` come with
//! their Jacobian `Φ_q` and the right-hand side `γ` of their acceleration form `Φ_q q̈ = γ`; for a
//! curve-to-curve contact the row and `γ` are those of [`crate::contact::ContactKinematics`]
//! (eq. 11), linear in the accelerations because the sliding rates depend on velocities only.
//!
//! # Formulation
//!
//! The equations of motion `M q̈ + Φ_qᵀ λ = Q`, `Φ_q q̈ = γ` are solved at every evaluation
//! directly by the Schur complement of the rows ([`SystemSimulation`]) or, where rows are
//! dependent, by the augmented Lagrangian method of Bayo, García de Jalón and Serna (1988): with
//! a penalty `α` and, in its general form, Baumgarte-type stabilisation of position and velocity
//! drift (damping `ξ`, frequency `Ω`; the simulations set both to zero, see below),
//!
//! ```text
//! (M + Φ_qᵀ α Φ_q) q̈ = Q − Φ_qᵀ (λ* + α (−γ + 2ξΩ Φ̇ + Ω² Φ))
//! λ* ← λ* + α (Φ_q q̈ − γ + 2ξΩ Φ̇ + Ω² Φ)
//! ```
//!
//! iterated until the stabilised acceleration constraints hold to a tolerance; then
//! `Φ̈ + 2ξΩ Φ̇ + Ω² Φ = 0`, so drift decays instead of growing, and `λ` is recovered from
//! `Φ_qᵀλ = Q − M q̈` (the penalty only sets the speed of the iteration, not the answer).
//!
//! [`SystemSimulation`] (and the cam preset, [`Simulation`]) integrates with the Dormand–Prince
//! 5(4) pair, its steps chosen by [`Tolerances`], and after every step projects positions and
//! velocities mass-orthogonally onto the constraints (Bayo and Ledesma 1996): `min ½ Δqᵀ M Δq`
//! subject to `Φ(q + Δq) = 0` by Newton, then `Φ_q q̇ = −Φ_t`. With it the drift stays at
//! rounding level and the simulated acceleration of a follower in permanent contact equals the
//! contact method's to 1e-13 of its peak.

mod cam;
mod dense;
mod dopri;
mod follower;
mod forces;
mod model;
mod no_follow;
mod projection;
mod reduced;
mod run;
mod sdirk;
mod simulation;
mod solver;
mod stepper;
mod system;

pub use cam::PresetSimulation;
pub use dopri::Tolerances;
pub use follower::{Event, EventKind, FollowerDynamics, Sample, MAX_RATE_STEP, REBOUND_TOLERANCE};
pub use forces::{
    effective_modulus, hertz_line_pressure, surface_speeds, ForceState, ForceSweep, Forces,
    SecondContact,
};
pub(crate) use model::GROUND;
pub use no_follow::{no_follow_speed, NoFollow, SpeedSweep};
pub use reduced::Reduced;
pub use run::Run;
pub use simulation::Simulation;
pub use solver::{AugmentedLagrangian, Evaluation};
pub use stepper::Scheme;
pub use system::{
    AdjusterSample, ContactEvent, ContactHertz, ContactSurface, ElementEnergy, EnergyBalance,
    StartReport, SystemDynamicsOptions, SystemRun, SystemSample, SystemSimulation,
};

/// What went wrong in a dynamic simulation.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DynamicsError {
    /// A contact's kinematics could not be computed.
    #[error("at t = {} s: {source}", crate::human::human(*.time))]
    Contact {
        /// time, s
        time: f64,
        /// the contact error
        source: crate::contact::ContactError,
    },
    /// The augmented mass matrix is not positive definite (a body without mass that no
    /// constraint holds, or a penalty out of range).
    #[error("at t = {} s: the augmented mass matrix is singular", crate::human::human(*.time))]
    Singular {
        /// time, s
        time: f64,
    },
    /// A system's positions cannot be brought back onto its joints, drivers and contacts after a
    /// step: its drivers take it into a dead point (toggle) it cannot pass, or a loop cannot
    /// close. The run stops there rather than go on off the constraints.
    #[error("at t = {} s the positions cannot be kept on the constraints (largest residual {}, in {rows}): the drivers take the system into a dead point (toggle) it cannot be driven past, or a loop cannot close; simulate it up to that instant, or drive it another way", crate::human::human(*.time), crate::human::human(*.residual))]
    Unassembled {
        /// time, s
        time: f64,
        /// the largest residual, in the system's length unit (angles' rows in rad)
        residual: f64,
        /// the rows with the largest residuals, named
        rows: String,
    },
    /// A system's steps shrink to nothing before an instant where its rows become dependent:
    /// its drivers take it into a dead point (toggle) it cannot be driven past.
    #[error("at t = {} s the system reaches a dead point (toggle): its joints' rows become dependent there and {drivers} cannot take it on (its steps shrank to nothing); simulate it up to that instant, or drive it another way", crate::human::human(*.time))]
    DeadPoint {
        /// time, s
        time: f64,
        /// the drivers, named (`driver "drive rocker"`), or the empty string
        drivers: String,
    },
    /// The implicit integrator's Newton iterations did not converge on a step taken again up
    /// to an event.
    #[error("at t = {} s the implicit integrator's Newton iterations did not converge on a step of {} s; simulate with the explicit one (--integrator explicit)", crate::human::human(*.time), crate::human::human(*.step))]
    ImplicitNewton {
        /// time, s
        time: f64,
        /// the step, s
        step: f64,
    },
    /// The multiplier iteration did not converge.
    #[error("at t = {} s: the augmented Lagrangian iteration did not converge ({iterations} iterations, residual {})", crate::human::human(*.time), crate::human::human(*.residual))]
    NoConvergence {
        /// time, s
        time: f64,
        /// iterations done
        iterations: usize,
        /// last constraint residual, 1/s² units of the constraints
        residual: f64,
    },
    /// The kinematic analysis failed during a run.
    #[error("at t = {} s: {source}", crate::human::human(*.time))]
    Analysis {
        /// time, s
        time: f64,
        /// the analysis error
        source: crate::cam::CamError,
    },
    /// The caller stopped the run (its progress callback broke off: an interrupt).
    #[error("stopped by its caller after {done} of {outputs} output intervals")]
    Stopped {
        /// intervals done
        done: usize,
        /// intervals asked for
        outputs: usize,
    },
    /// A conjugate follower's second curve cuts into the cam: a rigid follower cannot be there.
    #[error("follower.conjugate: the second curve cuts {} {unit} into the cam at cam angle {}°: a rigid follower cannot be there; give the second curve clearance (the design checks report its play over a revolution)", crate::human::human(*.depth), crate::human::human(*.angle_deg))]
    Interference {
        /// where it cuts deepest, degrees
        angle_deg: f64,
        /// how deep, in `unit`
        depth: f64,
        /// `m` (a slide) or `rad` (an arm)
        unit: &'static str,
    },
    /// More events than [`MAX_EVENTS_PER_STEP`](self) in one step: the follower chatters.
    #[error("at t = {} s: more than {events} lift-offs and impacts in one step: the follower chatters (restitution near 1 with a rebound that never dies down); use a smaller restitution", crate::human::human(*.time))]
    Chatter {
        /// time, s
        time: f64,
        /// the limit
        events: usize,
    },
    /// The kinematic analysis at the start failed.
    #[error("the starting position cannot be analysed: {source}")]
    Kinematics {
        /// the analysis error
        source: crate::cam::CamError,
    },
    /// The contact jumps across a stretch of the profile the follower cannot follow (a concave
    /// stretch under a flat face, one sharper than the roller, a fold, a knife falling off a
    /// lobe): the dynamics follows one contact point continuously and cannot model the jump.
    #[error("the contact jumps at cam angle {}: the follower cannot follow the profile there (a concave stretch under a flat face, one sharper than the roller, or a fold; the analysis marks those rows as jumps), and the dynamics follows one contact point continuously", fmt_angles(.angles_deg))]
    ContactJumps {
        /// cam angles (degrees, in [0, 360)) of the jumps, sampled every 0.25°
        angles_deg: Vec<f64>,
    },
    /// The follower is conjugate (form-closed, [`crate::cam::Mechanism::with_conjugate`]): its
    /// second curve takes the load where the first would lift off, which the dynamics (one
    /// contact, held on by a spring) does not model.
    #[error("follower.conjugate: the follower is form-closed (its second curve takes the load where the first would lift off) and the dynamics models one contact held on by a spring: not modelled; its kinematics and both contacts are computed by the analysis and the contact listing")]
    FormClosed,
    /// A tolerance out of [`Tolerances::RANGE`].
    #[error("the {which} tolerance {}: must be from 1e-13 to 0.01", crate::human::human(*.value))]
    Tolerance {
        /// `"relative"` or `"absolute"`
        which: &'static str,
        /// its value
        value: f64,
    },
    /// The step the tolerances need fell below the time's rounding: the motion changes faster
    /// than the tolerances can follow (an element far stiffer than the rest, a force that jumps).
    #[error("at t = {} s the step fell to {} s and the error was still above the tolerances (rtol {}, atol {}): the motion changes faster than they can follow (an element far stiffer than the rest, or a force that jumps); loosen them, or check the stiffest element's units", crate::human::human(*.time), crate::human::human(*.step), crate::human::human(*.rtol), crate::human::human(*.atol))]
    StepUnderflow {
        /// time, s
        time: f64,
        /// the last step tried, s
        step: f64,
        /// the relative tolerance
        rtol: f64,
        /// the absolute tolerance
        atol: f64,
    },
    /// A hydraulic lash adjuster left its model during the run: its chamber emptied (the
    /// plunger bottomed) or its pressure fell to absolute zero (cavitation, not modelled).
    #[error("lash adjuster {adjuster:?} at t = {} s: its {what} {} {reason}", crate::human::human(*.time), crate::human::human(*.value))]
    Adjuster {
        /// when, s
        time: f64,
        /// its name
        adjuster: String,
        /// what left the model (`chamber (L)`, `pressure (Pa)`)
        what: &'static str,
        /// its value then
        value: f64,
        /// what happened, and what would help
        reason: &'static str,
    },
    /// An element of a system (a body, a contact) has a dynamic property out of range.
    #[error("{element}: {key} = {}: {reason}", crate::human::human(*.value))]
    Element {
        /// the element, as the system names it (`body "valve"`)
        element: String,
        /// the property
        key: &'static str,
        /// its value
        value: f64,
        /// what it must be
        reason: &'static str,
    },
    /// The system cannot be simulated: an element names a missing body, or the starting
    /// positions cannot be assembled onto the joints and the contacts in touch.
    #[error("{0}")]
    System(#[from] crate::system::SystemError),
    /// A parameter is out of range.
    #[error("{field} = {}: {reason}", crate::human::human(*.value))]
    Invalid {
        /// the parameter
        field: crate::field::Field,
        /// its value
        value: f64,
        /// what it must be
        reason: &'static str,
    },
}

/// `12.5°, 140°, … (7 in all)`
fn fmt_angles(a: &[f64]) -> String {
    let shown: Vec<String> = a
        .iter()
        .take(4)
        .map(|x| format!("{}°", crate::human::human(*x)))
        .collect();
    if a.len() > 4 {
        format!("{}, … ({} in all)", shown.join(", "), a.len())
    } else {
        shown.join(", ")
    }
}
