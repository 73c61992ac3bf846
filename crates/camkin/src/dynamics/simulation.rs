//! A cam-follower simulation: the mechanism's preset system in the one engine where it applies,
//! the one-coordinate model where the contact jumps or the follower is form-closed.

use super::{
    AugmentedLagrangian, DynamicsError, Event, FollowerDynamics, PresetSimulation, Reduced, Sample,
};
use crate::cam::Mechanism;

/// A simulation of a cam (or gear) mechanism's follower with lift-off, impacts and, where the
/// contact jumps, impacts without flight.
///
/// [`Simulation::starting_at`] chooses the model:
/// - [`PresetSimulation`] (the mechanism's preset system, [`crate::cam::CamFollowerSystem`],
///   run by the one engine, [`super::SystemSimulation`], with the paper's eq. 11 as its contact
///   row) for a follower with one curve whose contact never jumps;
/// - [`Reduced`] (the follower's one coordinate, driven exactly along the contact method's first
///   touch) for a follower whose contact jumps (gears at a tooth handover, a flat face across a
///   concave stretch) or that carries a second curve (a conjugate cam, a gear's coast flanks:
///   backlash and rattle).
///
/// Where both apply they agree (`tests/it/dynamics_reduced.rs`).
///
/// ```
/// use camkin::cam::{Cam, Follower, Mechanism, Sense};
/// use camkin::curve::Circle;
/// use camkin::dynamics::{AugmentedLagrangian, FollowerDynamics, Simulation};
/// use camkin::{Point2, Vec2};
/// use std::sync::Arc;
///
/// // an eccentric disc (m) at 300 rpm under a flat face; a stiff, preloaded spring keeps the
/// // follower on the cam, so it follows the kinematic motion s = R + e cos θ
/// let disc = Arc::new(Circle::new(Point2::new(0.005, 0.0), 0.04)?);
/// let cam = Cam::from_rpm(disc, Point2::origin(), Sense::Ccw, 300.0)?;
/// let m = Mechanism::new(cam, Follower::TranslatingFlat { direction: Vec2::x() })?;
/// let params = FollowerDynamics {
///     mass: 0.5,
///     inertia: 0.0,
///     spring_stiffness: 2.0e4,
///     spring_preload: 200.0,
///     damping: 0.0,
///     restitution: 0.0,
///     gravity: Vec2::zeros(),
/// };
/// let mut sim = Simulation::new(&m, params, AugmentedLagrangian::default())?;
/// let h = 1f64.to_radians() / m.cam().speed(); // 1° of cam rotation
/// for _ in 0..90 {
///     assert!(sim.advance(h)?.is_empty(), "no lift-off");
/// }
/// let s = sim.sample()?;
/// let exact = 0.04 + 0.005 * s.cam_angle.cos();
/// assert!(s.in_contact && (s.position - exact).abs() < 1e-8);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
#[allow(clippy::large_enum_variant)]
pub enum Simulation<'a> {
    /// the mechanism's preset system in the one engine
    Preset(PresetSimulation),
    /// the one-coordinate model
    Reduced(Reduced<'a>),
}

impl<'a> Simulation<'a> {
    /// Starts at cam angle 0; see [`Simulation::starting_at`].
    pub fn new(
        mech: &'a Mechanism,
        params: FollowerDynamics,
        al: AugmentedLagrangian,
    ) -> Result<Self, DynamicsError> {
        Self::starting_at(mech, params, al, 0.0)
    }

    /// The simulation of `mech` (lengths in metres) with the follower's `params`, starting at
    /// cam angle `theta0` (rad) at time 0 on the cam at the kinematic position and velocity
    /// (in flight where the contact force there would be tensile: the first
    /// [`Simulation::advance`] then reports a lift-off at time 0). `al` sets the multibody
    /// model's solver.
    pub fn starting_at(
        mech: &'a Mechanism,
        params: FollowerDynamics,
        al: AugmentedLagrangian,
        theta0: f64,
    ) -> Result<Self, DynamicsError> {
        match PresetSimulation::starting_at(mech, params, al, theta0) {
            Ok(m) => Ok(Self::Preset(m)),
            Err(DynamicsError::ContactJumps { .. } | DynamicsError::FormClosed) => {
                Reduced::starting_at(mech, params, theta0).map(Self::Reduced)
            }
            Err(e) => Err(e),
        }
    }

    /// A rough estimate of the seconds `steps` time steps take, for refusing runs of minutes up
    /// front (both front ends refuse over a minute unless asked).
    /// - The preset system: about 25 µs a step (a 1° step counts 49 000 instructions; 100
    ///   revolutions of the paper's cam at 1° steps, 36 000 steps with their output, take
    ///   0.73 s on a 2-core host: 20 µs a step).
    /// - The one-coordinate model searches each of the follower's curves' first touch, warm and
    ///   cold, every step, and by bisection at every event: measured, 4 (an ideal gear pair at
    ///   0.5° steps) to 12 (a gear pair rattling in its backlash at 1° steps) cold searches a
    ///   step and curve. The estimate takes 6 of [`Mechanism::search_seconds_estimate`] a step
    ///   and curve: for hours of work, not for seconds.
    pub fn seconds_estimate(&self, steps: f64) -> f64 {
        match self {
            Self::Preset(_) => steps * 2.5e-5,
            Self::Reduced(r) => steps * r.search_seconds() * 6.0,
        }
    }

    /// Why a step of this model costs more than the preset system's, for the message that
    /// refuses a long run; `None` for the preset system.
    pub fn cost_reason(&self) -> Option<&'static str> {
        match self {
            Self::Preset(_) => None,
            Self::Reduced(_) => Some(
                "its contact jumps or it has a second curve: each step searches every curve's first touch",
            ),
        }
    }

    /// The work of a run of `steps` steps ([`Simulation::seconds_estimate`], with
    /// [`Simulation::cost_reason`]), for the one refusal rule of [`crate::work`].
    pub fn work(&self, steps: f64) -> crate::work::Work {
        let w = crate::work::Work::new(
            format!("{} steps of this mechanism", crate::human::human(steps)),
            self.seconds_estimate(steps),
        );
        match self.cost_reason() {
            Some(why) => w.because(why),
            None => w,
        }
    }

    /// The steps an output interval of `h` s takes, estimated: the one-coordinate model cuts it
    /// into steps of [`super::FollowerDynamics::max_step`]; the preset system's steps are chosen
    /// by its tolerances, each no longer than the interval nor, for long, than its stable step.
    pub fn steps_per_interval(&self, h: f64) -> f64 {
        let longest = match self {
            Self::Preset(m) => m.stable_step(),
            Self::Reduced(r) => r.params().max_step(r.is_rotating()),
        };
        (h / longest).ceil().max(1.0)
    }

    /// The work of a whole run of `mech`: `outputs` output intervals of `h` s
    /// ([`Simulation::work`] of [`Simulation::steps_per_interval`] each), the jump scan at the
    /// start (every 0.25°) and the kinematic motion beside every sample (a sweep of its angles),
    /// about 200 bytes a sample held. What every front end refuses a long run by.
    pub fn run_work(
        &self,
        mech: &crate::cam::Mechanism,
        outputs: usize,
        h: f64,
    ) -> crate::work::Work {
        self.work(outputs as f64 * self.steps_per_interval(h))
            .and(&crate::work::Work::sweep(mech, 1441 + outputs, 1))
            .with_bytes(outputs as f64 * 200.0)
    }

    /// The tolerances of the preset system's steps (refused out of
    /// [`super::Tolerances::RANGE`]); the one-coordinate model steps at its stable step whatever
    /// they are (its flight is exact; its contact follows the kinematics).
    pub fn set_tolerances(&mut self, t: super::Tolerances) -> Result<(), DynamicsError> {
        match self {
            Self::Preset(m) => m.set_tolerances(t),
            Self::Reduced(_) => match t.out_of_range() {
                Some((which, value)) => Err(DynamicsError::Tolerance { which, value }),
                None => Ok(()),
            },
        }
    }

    /// The preset system's integrator ([`super::Scheme`]); the one-coordinate model's flight is
    /// exact whatever it is.
    pub fn set_scheme(&mut self, scheme: super::Scheme) {
        if let Self::Preset(m) = self {
            m.set_scheme(scheme);
        }
    }

    /// The preset system's steps since the start, accepted and rejected; `None` for the
    /// one-coordinate model (its steps are [`Simulation::steps_per_interval`] exactly).
    pub fn steps_taken(&self) -> Option<(usize, usize)> {
        match self {
            Self::Preset(m) => Some(m.steps_taken()),
            Self::Reduced(_) => None,
        }
    }

    /// Advances by `h` seconds; the events located inside the step, in time order.
    pub fn advance(&mut self, h: f64) -> Result<Vec<Event>, DynamicsError> {
        match self {
            Self::Preset(m) => m.advance(h),
            Self::Reduced(r) => r.advance(h),
        }
    }

    /// The state at the current time.
    pub fn sample(&mut self) -> Result<Sample, DynamicsError> {
        match self {
            Self::Preset(m) => m.sample(),
            Self::Reduced(r) => r.sample(),
        }
    }

    /// The current time, s.
    pub fn time(&self) -> f64 {
        match self {
            Self::Preset(m) => m.time(),
            Self::Reduced(r) => r.time(),
        }
    }

    /// The largest `|Φ|` of the active constraints (length or rad); 0 for the one-coordinate
    /// model, which moves on the contact exactly.
    pub fn constraint_residual(&self) -> Result<f64, DynamicsError> {
        match self {
            Self::Preset(m) => m.constraint_residual(),
            Self::Reduced(_) => Ok(0.0),
        }
    }
}
