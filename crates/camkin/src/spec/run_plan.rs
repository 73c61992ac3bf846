//! A simulated system's run over its sweep angle, planned once for every front end: outputs
//! every `step` degrees of the first driver (or the cam), each output interval cut into as many
//! time steps as asked or as the stiffest element needs; and the quasi-static reference run
//! beside it (the same system at a tenth of the speed).

use super::BuiltSystem;
use crate::dynamics::{DynamicsError, SystemSample, SystemSimulation};

/// Most revolutions a run plans.
pub const MAX_REVOLUTIONS: f64 = 1e4;
/// Most time steps an output interval is cut into.
pub const MAX_SUBSTEPS: usize = 1000;
/// The output step's range, degrees of the sweep angle.
pub const STEP_RANGE_DEG: (f64, f64) = (1e-3, 90.0);

/// A run planned: its outputs, the instants of the sweep angle, the time steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunPlan {
    /// the instant at sweep angle 0, s
    pub t0: f64,
    /// one output interval, s
    pub h_out: f64,
    /// the output step, degrees of the sweep angle
    pub step_deg: f64,
    /// output intervals (the samples are one more: the start's)
    pub outputs: usize,
    /// time steps an output interval is cut into
    pub substeps: usize,
}

impl RunPlan {
    /// The time step, s.
    pub fn h(&self) -> f64 {
        self.h_out / self.substeps as f64
    }

    /// Time steps of the whole run.
    pub fn steps(&self) -> usize {
        self.outputs * self.substeps
    }

    /// The sweep angle at the instant `t`, degrees.
    pub fn angle_of(&self, t: f64) -> f64 {
        self.step_deg * (t - self.t0) / self.h_out
    }
}

/// Which setting of a run was refused (each front end names it as its user wrote it: a flag,
/// a keyword, a field).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum PlanField {
    /// the revolutions of the sweep angle
    Revolutions,
    /// the output step, degrees
    Step,
    /// the time steps an output interval is cut into
    Substeps,
}

/// Why a run cannot be planned.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PlanError {
    /// A setting out of its range.
    #[error("{value}: must be {range}")]
    OutOfRange {
        /// the setting
        field: PlanField,
        /// its value as given
        value: String,
        /// its range, in words
        range: &'static str,
    },
    /// The system's outputs are at its first driver's angles, and it has none at a constant
    /// speed.
    #[error("its first driver does not turn an angle at a constant speed: a simulation's outputs are at its angles")]
    NotAnAngle,
    /// The substeps asked leave a time step longer than the stiffest element allows.
    #[error("{element} is too stiff for the time step {} s ({}° of the driver / {substeps} substeps): its rate is {} /s, so the step must be at most {} s; use {need} substeps or more", crate::human::human(*.step), crate::human::human(*.step_deg), crate::human::human(*.rate), crate::human::human(*.max_step))]
    TooStiff {
        /// the stiffest element, named
        element: String,
        /// its rate, 1/s
        rate: f64,
        /// the time step asked, s
        step: f64,
        /// the output step, degrees
        step_deg: f64,
        /// the substeps asked
        substeps: usize,
        /// the longest step it allows, s
        max_step: f64,
        /// the fewest substeps that do
        need: usize,
    },
    /// The system file has no `[dynamics]`: its masses, gravity and forces are not meant for a
    /// simulation (its degrees of freedom are all driven, or it is a kinematic model).
    #[error("it has no [dynamics] table: a system is simulated with it (gravity, restitution; its bodies' masses and its force elements), see docs/systems.md, \"Dynamics of a system\"")]
    NoDynamics,
    /// The system cannot be simulated (its elements, its assembly).
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
}

impl PlanError {
    /// What resolves a [`PlanError::TooStiff`] within the settings' ranges: more substeps (at
    /// most [`MAX_SUBSTEPS`]), else the most substeps and a finer output step (at least
    /// [`STEP_RANGE_DEG`]'s least), else `None`: no output step resolves the element at this
    /// speed (a rate beyond a simulation: a stiffness or a mass off by a unit, most often).
    pub fn stiff_advice(&self) -> Option<crate::dynamics::StepAdvice> {
        use crate::dynamics::StepAdvice;
        let PlanError::TooStiff {
            step_deg,
            substeps,
            need,
            ..
        } = self
        else {
            return None;
        };
        if *need <= MAX_SUBSTEPS {
            return Some(StepAdvice::Substeps(*need));
        }
        // `need` substeps of `step_deg` resolve it: the most substeps, of a step this much finer
        let _ = substeps;
        let finer = step_deg * MAX_SUBSTEPS as f64 / *need as f64;
        // rounded down to two significant digits
        let unit = 10f64.powf(finer.log10().floor() - 1.0);
        let finer = (finer / unit).floor() * unit;
        (finer >= STEP_RANGE_DEG.0).then_some(StepAdvice::FinerStep { step_deg: finer })
    }
}

impl BuiltSystem {
    /// A run of `revolutions` of the sweep angle with outputs every `step_deg`, each output
    /// interval cut into `substeps` time steps (`None`: the fewest the stiffest element
    /// allows), and its simulation started: the plan every front end runs.
    pub fn plan(
        &self,
        revolutions: f64,
        step_deg: f64,
        substeps: Option<usize>,
    ) -> Result<(RunPlan, SystemSimulation<'_>), PlanError> {
        let h = crate::human::human;
        if !self.simulated {
            return Err(PlanError::NoDynamics);
        }
        if !(revolutions > 0.0 && revolutions <= MAX_REVOLUTIONS) {
            return Err(PlanError::OutOfRange {
                field: PlanField::Revolutions,
                value: h(revolutions),
                range: "in (0, 10000]",
            });
        }
        if !(STEP_RANGE_DEG.0..=STEP_RANGE_DEG.1).contains(&step_deg) {
            return Err(PlanError::OutOfRange {
                field: PlanField::Step,
                value: h(step_deg),
                range: "from 0.001 to 90 degrees",
            });
        }
        if let Some(n) = substeps.filter(|n| !(1..=MAX_SUBSTEPS).contains(n)) {
            return Err(PlanError::OutOfRange {
                field: PlanField::Substeps,
                value: n.to_string(),
                range: "from 1 to 1000",
            });
        }
        // outputs at equal steps of the first driver's angle are equal steps of time only at a
        // constant speed
        let steady = self.system.drivers().first().is_some_and(|d| {
            let crate::system::DriverLaw::Quadratic { acceleration, .. } = d.law;
            acceleration == 0.0
        });
        let (true, Some(t0), Some(t1)) = (
            steady,
            self.time_of(0.0),
            self.time_of(step_deg.to_radians()),
        ) else {
            return Err(PlanError::NotAnAngle);
        };
        let sim = SystemSimulation::new(&self.system, self.dynamics.clone())?;
        let h_out = (t1 - t0).abs();
        let need = sim.substeps(h_out);
        let substeps = match substeps {
            None => need,
            Some(n) if h_out / n as f64 <= sim.max_step() => n,
            Some(n) => {
                let (rate, element) = sim.fastest_rate();
                return Err(PlanError::TooStiff {
                    element,
                    rate,
                    step: h_out / n as f64,
                    step_deg,
                    substeps: n,
                    max_step: sim.max_step(),
                    need,
                });
            }
        };
        let plan = RunPlan {
            t0,
            h_out,
            step_deg,
            outputs: (revolutions * 360.0 / step_deg).round().max(1.0) as usize,
            substeps,
        };
        Ok((plan, sim))
    }

    /// The quasi-static reference of a run planned by [`BuiltSystem::plan`]: the samples at
    /// the same sweep angles with the first driver at a tenth of its speed (inertia forces a
    /// hundredth), each output interval in at least as many time steps as the run's and as
    /// many as the stiffest element needs.
    pub fn quasi_static(&self, plan: &RunPlan) -> Result<Vec<SystemSample>, DynamicsError> {
        let mut sys = self.system.clone();
        if let Some(d) = sys.drivers().first().cloned() {
            let crate::system::DriverLaw::Quadratic {
                start,
                rate,
                acceleration,
            } = d.law;
            sys.set_driver_law(
                0,
                crate::system::DriverLaw::Quadratic {
                    start,
                    rate: 0.1 * rate,
                    acceleration: 0.01 * acceleration,
                },
            );
        }
        let mut sim = SystemSimulation::new(&sys, self.dynamics.clone())?;
        let (t0, t1) = (
            self.sweep_angle.time(&sys, 0.0).unwrap_or(0.0),
            self.sweep_angle
                .time(&sys, plan.step_deg.to_radians())
                .unwrap_or(0.0),
        );
        let h_out = (t1 - t0).abs();
        let substeps = sim.substeps(h_out).max(plan.substeps);
        sim.run(plan.outputs, substeps, h_out / substeps as f64, |_| {
            std::ops::ControlFlow::Continue(())
        })
        .map(|r| r.samples)
    }
}

#[cfg(all(test, feature = "text"))]
mod tests {
    use super::*;
    use crate::spec::BuildOptions;

    fn valve_train() -> BuiltSystem {
        let text = include_str!("../../../../examples/valve-train.toml");
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
        let options = BuildOptions {
            base_dir: dir,
            ..BuildOptions::default()
        };
        crate::spec::read_model(text, "valve-train.toml", &options)
            .and_then(crate::spec::ModelFile::into_system)
            .expect("valve train")
    }

    #[test]
    fn a_plan_refuses_each_setting_out_of_range_by_name() {
        let built = valve_train();
        let field = |r: Result<_, PlanError>| match r {
            Err(PlanError::OutOfRange { field, .. }) => Some(field),
            _ => None,
        };
        assert_eq!(
            field(built.plan(0.0, 1.0, None)),
            Some(PlanField::Revolutions)
        );
        assert_eq!(
            field(built.plan(1e4 + 1.0, 1.0, None)),
            Some(PlanField::Revolutions)
        );
        assert_eq!(field(built.plan(1.0, 91.0, None)), Some(PlanField::Step));
        assert_eq!(
            field(built.plan(1.0, 1.0, Some(0))),
            Some(PlanField::Substeps)
        );
        assert_eq!(
            field(built.plan(1.0, 1.0, Some(1001))),
            Some(PlanField::Substeps)
        );
    }

    #[test]
    fn a_plan_takes_the_fewest_substeps_the_stiffest_element_allows() {
        let built = valve_train();
        let (plan, sim) = built.plan(1.0, 1.0, None).expect("plan");
        // one revolution of the camshaft at 1°, each degree too long a step for its springs
        assert_eq!(plan.outputs, 360);
        assert!(plan.substeps >= 2, "{plan:?}");
        assert!(plan.h() <= sim.max_step());
        // one fewer substep would be too long a step, and asked for, it says how many
        assert!(plan.h_out / (plan.substeps - 1) as f64 > sim.max_step());
        match built.plan(1.0, 1.0, Some(plan.substeps - 1)) {
            Err(PlanError::TooStiff { need, .. }) => assert_eq!(need, plan.substeps),
            other => panic!("{other:?}"),
        }
        // the sweep angle of the run's instants: the output step apart
        let t = plan.t0 + 3.0 * plan.h_out;
        assert!((plan.angle_of(t) - 3.0).abs() < 1e-12);
    }
}
