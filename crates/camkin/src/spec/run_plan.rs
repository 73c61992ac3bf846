//! A simulated system's run over its sweep angle, planned once for every front end: outputs
//! every `step` degrees of the first driver (or the cam), the time steps between them chosen by
//! the tolerances; and the quasi-static reference run beside it (the same system at a tenth of
//! the speed).

use super::BuiltSystem;
use crate::dynamics::{DynamicsError, SystemSample, SystemSimulation};

/// Most revolutions a run plans.
pub const MAX_REVOLUTIONS: f64 = 1e4;
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
}

impl RunPlan {
    /// The run's duration, s.
    pub fn duration(&self) -> f64 {
        self.h_out * self.outputs as f64
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
    /// The system file has no `[dynamics]`: its masses, gravity and forces are not meant for a
    /// simulation (its degrees of freedom are all driven, or it is a kinematic model).
    #[error("it has no [dynamics] table: a system is simulated with it (gravity, restitution; its bodies' masses and its force elements), see docs/systems.md, \"Dynamics of a system\"")]
    NoDynamics,
    /// The system cannot be simulated (its elements, its assembly).
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
}

impl BuiltSystem {
    /// A run of `revolutions` of the sweep angle with outputs every `step_deg`, and its
    /// simulation started: the plan every front end runs.
    pub fn plan(
        &self,
        revolutions: f64,
        step_deg: f64,
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
        let plan = RunPlan {
            t0,
            h_out,
            step_deg,
            outputs: (revolutions * 360.0 / step_deg).round().max(1.0) as usize,
        };
        Ok((plan, sim))
    }

    /// The work of a run planned by [`BuiltSystem::plan`] (its steps estimated by
    /// [`SystemSimulation::steps_estimate`], its samples made and held), with the quasi-static
    /// reference run beside it where `reference` (ten times as long:
    /// [`BuiltSystem::quasi_static`]) and a speed sweep's runs where given: what every front end
    /// refuses a long run by.
    pub fn run_work(
        &self,
        plan: &RunPlan,
        sim: &SystemSimulation<'_>,
        reference: bool,
        sweep: Option<&crate::dynamics::SpeedSweep>,
    ) -> crate::work::Work {
        let mut steps = sim.steps_estimate(plan.duration(), plan.h_out);
        let mut samples = (plan.outputs + 1) as f64;
        if reference {
            steps += sim.steps_estimate(10.0 * plan.duration(), 10.0 * plan.h_out);
            samples *= 2.0;
        }
        if let Some(s) = sweep {
            let (more, sampled) = s.work(sim);
            steps += more;
            samples += sampled;
        }
        let work =
            crate::work::Work::system_simulation(&self.system, steps, samples, plan.outputs + 1);
        // where the stiffest element sets the steps, it is named
        let stable = sim.stable_step();
        if stable < plan.h_out {
            let (rate, element) = sim.fastest_rate();
            let h = crate::human::human;
            work.because(format!(
                "{element} moves at up to {} /s, so its steps are at most {} s",
                h(rate),
                h(stable)
            ))
        } else {
            work
        }
    }

    /// The quasi-static reference of a run planned by [`BuiltSystem::plan`]: the samples at
    /// the same sweep angles with the first driver at a tenth of its speed (inertia forces a
    /// hundredth).
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
        sim.run(plan.outputs, h_out, |_| std::ops::ControlFlow::Continue(()))
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
        assert_eq!(field(built.plan(0.0, 1.0)), Some(PlanField::Revolutions));
        assert_eq!(
            field(built.plan(1e4 + 1.0, 1.0)),
            Some(PlanField::Revolutions)
        );
        assert_eq!(field(built.plan(1.0, 91.0)), Some(PlanField::Step));
        let (plan, _) = built.plan(1.0, 1.0).expect("plan");
        // one revolution of the camshaft at 1°; the sweep angle of the run's instants
        assert_eq!(plan.outputs, 360);
        let t = plan.t0 + 3.0 * plan.h_out;
        assert!((plan.angle_of(t) - 3.0).abs() < 1e-12);
    }
}
