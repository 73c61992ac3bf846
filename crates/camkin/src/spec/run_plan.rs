//! A simulated system's run, planned once for every front end: over its sweep angle, outputs
//! every `step` degrees of the first driver (or the cam), or over a duration, outputs every
//! `interval` seconds (a system without an angle driver: a pendulum, a mechanism released from
//! rest); the time steps between them chosen by the tolerances; and the quasi-static reference
//! run beside a sweep (the same system at a tenth of the speed).

use super::BuiltSystem;
use crate::dynamics::{DynamicsError, SystemSample, SystemSimulation};

/// Most revolutions a run plans.
pub const MAX_REVOLUTIONS: f64 = 1e4;
/// The output step's range, degrees of the sweep angle.
pub const STEP_RANGE_DEG: (f64, f64) = (1e-3, 90.0);

/// Longest duration of a run in time, s.
pub const MAX_DURATION: f64 = 1e6;
/// Most output intervals a run has.
pub const MAX_OUTPUTS: f64 = 1e7;

/// A run planned: its outputs, the instants of the sweep angle, the time steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunPlan {
    /// the instant of the first sample (sweep angle 0), s
    pub t0: f64,
    /// one output interval, s
    pub h_out: f64,
    /// the output step, degrees of the sweep angle; `None` for a run in time
    /// ([`BuiltSystem::plan_timed`])
    pub step_deg: Option<f64>,
    /// output intervals (the samples are one more: the start's)
    pub outputs: usize,
}

impl RunPlan {
    /// The run's duration, s.
    pub fn duration(&self) -> f64 {
        self.h_out * self.outputs as f64
    }

    /// The sweep angle at the instant `t`, degrees (`None` for a run in time).
    pub fn angle_of(&self, t: f64) -> Option<f64> {
        self.step_deg.map(|step| step * (t - self.t0) / self.h_out)
    }

    /// Sample `k`'s sweep angle, degrees, as a round number of the step's decimals (`None`
    /// for a run in time).
    pub fn angle_at(&self, k: usize) -> Option<f64> {
        self.step_deg
            .map(|step| crate::table::AngleGrid::new(0.0, step).at(k))
    }
}

/// What a front end's user asked of a run, each setting left out where they gave none (see
/// [`BuiltSystem::plan_asked`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunSettings {
    /// revolutions of the first driver
    pub revolutions: Option<f64>,
    /// the output step over them, degrees
    pub step_deg: f64,
    /// a run in time's duration, s
    pub duration: Option<f64>,
    /// its output interval, s
    pub interval: Option<f64>,
}

/// A run in time: `[simulation]` of a system file, or a front end's duration.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct TimedRun {
    /// how long, s
    pub duration: f64,
    /// the output interval, s
    pub interval: f64,
}

impl TimedRun {
    /// A run of `duration` seconds with outputs every `interval` (by default a thousandth of
    /// the duration), or the setting out of its range: the duration in (0, 1e6] s, the
    /// interval in (0, duration] with at most 1e7 outputs.
    pub fn new(duration: f64, interval: Option<f64>) -> Result<Self, PlanError> {
        let h = crate::human::human;
        if !(duration > 0.0 && duration <= MAX_DURATION) {
            return Err(PlanError::OutOfRange {
                field: PlanField::Duration,
                value: h(duration),
                range: "in (0, 1000000] s",
            });
        }
        let interval = interval.unwrap_or(duration / 1000.0);
        if !(interval > 0.0 && interval <= duration && duration / interval <= MAX_OUTPUTS) {
            return Err(PlanError::OutOfRange {
                field: PlanField::Interval,
                value: h(interval),
                range: "in (0, duration] s, with at most 10000000 outputs in the duration",
            });
        }
        Ok(Self { duration, interval })
    }

    /// Its output intervals: as many as the interval fits in the duration (rounded to the
    /// nearest whole number within 1e-9 of it, else up: the interval shortened to divide the
    /// duration), at least one.
    pub fn outputs(&self) -> usize {
        let n = self.duration / self.interval;
        (if (n - n.round()).abs() <= 1e-9 * n {
            n.round()
        } else {
            n.ceil()
        })
        .max(1.0) as usize
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
    /// a run in time's duration, s
    Duration,
    /// a run in time's output interval, s
    Interval,
}

/// Why a run cannot be planned.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PlanError {
    /// Two settings that cannot go together (a duration with revolutions; an interval without
    /// a duration, with revolutions or a step).
    #[error("a run is either in revolutions of the first driver (with its output step in degrees) or in time (a duration, with its output interval in seconds), not both")]
    Both {
        /// the setting refused
        field: PlanField,
        /// the one it cannot go with
        other: PlanField,
    },
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
    /// speed (and no duration was given).
    #[error("its first driver does not turn an angle at a constant speed, so its run is not in revolutions: give it a duration ([simulation] duration = … s in the file, or the front end's duration)")]
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
            step_deg: Some(step_deg),
            outputs: (revolutions * 360.0 / step_deg).round().max(1.0) as usize,
        };
        Ok((plan, sim))
    }

    /// A run in time from `t = 0` and its simulation started: any system with `[dynamics]`,
    /// with or without drivers. Where the interval does not divide the duration, it is
    /// shortened to the next that does ([`TimedRun::outputs`] intervals), so that the last
    /// output is at the duration's end.
    pub fn plan_timed(&self, run: TimedRun) -> Result<(RunPlan, SystemSimulation<'_>), PlanError> {
        if !self.simulated {
            return Err(PlanError::NoDynamics);
        }
        let sim = SystemSimulation::new(&self.system, self.dynamics.clone())?;
        let outputs = run.outputs();
        let plan = RunPlan {
            t0: 0.0,
            h_out: run.duration / outputs as f64,
            step_deg: None,
            outputs,
        };
        Ok((plan, sim))
    }

    /// The run a front end's settings ask for (every one its user may leave out): a
    /// `duration` (outputs every `interval`, by default a thousandth of it); else the file's
    /// `[simulation]` (its interval replaced by `interval` where given) unless `revolutions`
    /// are given; else `revolutions` (default 1) of the first driver in `step_deg` output
    /// steps. A duration with revolutions, or an interval with neither duration, are refused
    /// naming the setting.
    pub fn plan_asked(
        &self,
        asked: &RunSettings,
    ) -> Result<(RunPlan, SystemSimulation<'_>), PlanError> {
        match (asked.duration, self.timed_run, asked.revolutions) {
            (Some(_), _, Some(_)) => Err(PlanError::Both {
                field: PlanField::Duration,
                other: PlanField::Revolutions,
            }),
            (Some(d), _, None) => self.plan_timed(TimedRun::new(d, asked.interval)?),
            (None, Some(file), None) => self.plan_timed(TimedRun::new(
                file.duration,
                Some(asked.interval.unwrap_or(file.interval)),
            )?),
            (None, _, _) if asked.interval.is_some() => Err(PlanError::Both {
                field: PlanField::Interval,
                other: if asked.revolutions.is_some() {
                    PlanField::Revolutions
                } else {
                    PlanField::Step
                },
            }),
            (None, _, revolutions) => self.plan(revolutions.unwrap_or(1.0), asked.step_deg),
        }
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
        if stable < plan.h_out && !sim.implicit() {
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
        let Some(step_deg) = plan.step_deg else {
            return Err(DynamicsError::Element {
                element: "the run".into(),
                key: "duration",
                value: plan.duration(),
                reason: "is in time: its quasi-static reference is of a sweep of the first driver",
            });
        };
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
                .time(&sys, step_deg.to_radians())
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
        assert!((plan.angle_of(t).unwrap() - 3.0).abs() < 1e-12);
    }

    /// A run in time's settings refused by name out of range; its interval shortened to divide
    /// the duration (0.5 s in 0.2 s intervals: 3 of 1/6 s), kept where it divides it within
    /// rounding (0.3 s in 0.1 s: 3, not 4).
    #[test]
    fn a_run_in_time_is_refused_by_name_and_ends_at_its_duration() {
        let field = |r: Result<TimedRun, PlanError>| match r {
            Err(PlanError::OutOfRange { field, .. }) => Some(field),
            _ => None,
        };
        assert_eq!(field(TimedRun::new(0.0, None)), Some(PlanField::Duration));
        assert_eq!(
            field(TimedRun::new(f64::NAN, None)),
            Some(PlanField::Duration)
        );
        assert_eq!(field(TimedRun::new(2e6, None)), Some(PlanField::Duration));
        assert_eq!(
            field(TimedRun::new(1.0, Some(0.0))),
            Some(PlanField::Interval)
        );
        assert_eq!(
            field(TimedRun::new(1.0, Some(2.0))),
            Some(PlanField::Interval)
        );
        assert_eq!(
            field(TimedRun::new(1.0, Some(1e-8))),
            Some(PlanField::Interval)
        );
        assert_eq!(TimedRun::new(0.5, Some(0.2)).unwrap().outputs(), 3);
        assert_eq!(TimedRun::new(0.3, Some(0.1)).unwrap().outputs(), 3);
        assert_eq!(TimedRun::new(2.0, None).unwrap().outputs(), 1000);
        let built = valve_train();
        let (plan, _) = built
            .plan_timed(TimedRun::new(0.5, Some(0.2)).unwrap())
            .unwrap();
        assert_eq!((plan.outputs, plan.step_deg), (3, None));
        assert!((plan.duration() - 0.5).abs() < 1e-15);
        assert_eq!(plan.angle_of(0.1), None);
    }

    /// The settings a front end passes: a duration with revolutions, or an interval with
    /// neither a duration nor a file's `[simulation]`, refused naming both; a duration alone
    /// runs in time, revolutions alone over the driver.
    #[test]
    fn a_run_is_in_revolutions_or_in_time_not_both() {
        let built = valve_train();
        let asked = |revolutions, duration, interval| RunSettings {
            revolutions,
            step_deg: 1.0,
            duration,
            interval,
        };
        let both = |r: Result<(RunPlan, SystemSimulation<'_>), PlanError>| match r {
            Err(PlanError::Both { field, other }) => Some((field, other)),
            _ => None,
        };
        assert_eq!(
            both(built.plan_asked(&asked(Some(1.0), Some(0.1), None))),
            Some((PlanField::Duration, PlanField::Revolutions))
        );
        assert_eq!(
            both(built.plan_asked(&asked(None, None, Some(0.1)))),
            Some((PlanField::Interval, PlanField::Step))
        );
        let (plan, _) = built.plan_asked(&asked(None, Some(0.01), None)).unwrap();
        assert_eq!((plan.step_deg, plan.outputs), (None, 1000));
        let (plan, _) = built.plan_asked(&asked(Some(0.5), None, None)).unwrap();
        assert_eq!((plan.step_deg, plan.outputs), (Some(1.0), 180));
    }
}
