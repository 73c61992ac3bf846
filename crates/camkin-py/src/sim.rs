//! `Mechanism.simulate` and `System.simulate`: the dynamics with lift-off and impacts, the command's
//! `simulate` as arrays.

use crate::columns::Columns;
use crate::errors;
use crate::model::{PyMechanism, PySystem};
use camkin::dynamics::{AugmentedLagrangian, DynamicsError, Simulation, StepAdvice};
use camkin::table::{
    event_cells, event_columns, sample_cells, sample_columns, EventRow, SampleRow, Units,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

fn dyn_err(e: DynamicsError) -> PyErr {
    match e {
        DynamicsError::Invalid { .. }
        | DynamicsError::StepTooLong { .. }
        | DynamicsError::Unassembled { .. }
        | DynamicsError::Chatter { .. } => errors::input("dynamics", None, e.to_string()),
        DynamicsError::FormClosed | DynamicsError::Interference { .. } => {
            errors::input("follower.conjugate", None, e.to_string())
        }
        _ => errors::contact(e.to_string()),
    }
}

#[pymethods]
impl PyMechanism {
    /// simulate(*, revolutions=1.0, step_deg=1.0, substeps=1, start_angle_deg=0.0, large=False)
    /// -> dict
    ///
    /// The follower's motion under its spring, damping and the cam (the file's ``[dynamics]``,
    /// SI units), with lift-off and impacts, from ``start_angle_deg`` for ``revolutions`` turns,
    /// sampled every ``step_deg`` of cam angle (``substeps`` integration steps each). Returns
    /// ``{"samples": dict of arrays, "events": list of dicts}`` with the columns of
    /// ``camkin simulate`` (lengths in the file's unit, force in N, time in s).
    ///
    /// Example::
    ///
    ///     mech = camkin.Mechanism.from_toml("examples/paper-dynamics.toml")
    ///     r = mech.simulate(revolutions=1.0, step_deg=1.0)
    ///     r["events"]
    #[pyo3(signature = (*, revolutions = 1.0, step_deg = 1.0, substeps = 1, start_angle_deg = 0.0, large = false))]
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::real)] revolutions: f64,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        #[pyo3(from_py_with = crate::errors::count)] substeps: usize,
        #[pyo3(from_py_with = crate::errors::real)] start_angle_deg: f64,
        large: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let bad = |field: &str, v: f64, what: &str| {
            errors::input(
                field,
                Some(camkin::human::human(v)),
                format!("{field} = {}: {what}", camkin::human::human(v)),
            )
        };
        if !(revolutions.is_finite() && revolutions > 0.0 && revolutions <= 1e4) {
            return Err(bad("revolutions", revolutions, "must be in (0, 10000]"));
        }
        if !(step_deg.is_finite() && step_deg > 0.0 && step_deg <= 360.0) {
            return Err(bad("step_deg", step_deg, "must be in (0, 360] degrees"));
        }
        if !(1..=1000).contains(&substeps) {
            return Err(bad("substeps", substeps as f64, "must be from 1 to 1000"));
        }
        if !start_angle_deg.is_finite() {
            return Err(bad("start_angle_deg", start_angle_deg, "must be finite"));
        }
        let outputs = (revolutions * 360.0 / step_deg).round() as usize;
        let (built, params) = self.built_si("simulate")?;
        let mech = built.mechanism;
        let units = Units::plain(&mech, built.length_unit);
        let mut sim = Simulation::starting_at(
            &mech,
            params,
            AugmentedLagrangian::default(),
            camkin::geometry::deg_to_rad(start_angle_deg),
        )
        .map_err(dyn_err)?;
        errors::refuse_large(
            &sim.run_work(&mech, outputs, substeps),
            large,
            ", or simulate fewer revolutions",
        )?;
        let w = mech.cam().speed();
        let h = step_deg.to_radians() / w / substeps as f64;
        if let Some(advice) = sim.step_advice(step_deg, substeps, w, 1000, 360.0 / 1e7) {
            let (rate, field, value) = sim.fastest_rate();
            let hu = camkin::human::human;
            let fix = match advice {
                StepAdvice::Substeps(n) => format!("use substeps={n} or more"),
                StepAdvice::FinerStep { step_deg } => {
                    format!("use substeps=1000 and step_deg={} or finer", hu(step_deg))
                }
                StepAdvice::FasterCam { rpm } => format!(
                    "the cam turns too slowly for outputs by cam angle: raise cam.speed_rpm to at least {} rpm",
                    hu(rpm)
                ),
                _ => "use a finer step_deg".into(),
            };
            return Err(errors::input(
                &field.to_string(),
                Some(hu(value)),
                format!(
                    "{field} = {}: too stiff for the time step {} s; the follower's fastest rate is {} /s: {fix}",
                    hu(value),
                    hu(h),
                    hu(rate)
                ),
            ));
        }
        // Ctrl-C stops the run between output intervals: its KeyboardInterrupt, kept here
        let mut interrupt: Option<PyErr> = None;
        let result = py.detach(|| -> Result<_, DynamicsError> {
            let run = sim.run(outputs, substeps, h, |_| match errors::interrupted() {
                Ok(()) => std::ops::ControlFlow::Continue(()),
                Err(e) => {
                    interrupt = Some(e);
                    std::ops::ControlFlow::Break(())
                }
            })?;
            let thetas: Vec<f64> = run.samples.iter().map(|s| s.cam_angle).collect();
            let kin = mech.analyze_all(&thetas);
            let mut cols = Columns::new(sample_columns(&units), run.samples.len());
            for (s, k) in run.samples.iter().zip(&kin) {
                cols.push(sample_cells(&SampleRow::new(s, k.as_ref().ok()), &units));
            }
            Ok((cols, run.events))
        });
        if let Some(e) = interrupt {
            return Err(e);
        }
        let (samples, events) = result.map_err(dyn_err)?;
        let names = event_columns(&units);
        let ev = PyList::empty(py);
        for e in &events {
            let d = PyDict::new(py);
            for (name, cell) in names.iter().zip(event_cells(&EventRow::from(e), &units)) {
                match cell {
                    camkin::table::Cell::Num(x) => d.set_item(name, x)?,
                    camkin::table::Cell::Int(x) => d.set_item(name, x)?,
                    camkin::table::Cell::Count(x) => d.set_item(name, x)?,
                    camkin::table::Cell::Flag(x) => d.set_item(name, x)?,
                    camkin::table::Cell::Text(x) => d.set_item(name, x)?,
                }
            }
            ev.append(d)?;
        }
        let out = PyDict::new(py);
        out.set_item("samples", samples.into_dict(py, false)?)?;
        out.set_item("events", ev)?;
        crate::columns::result(out)
    }
}

#[pymethods]
impl PySystem {
    /// simulate(*, revolutions=1.0, step_deg=1.0, substeps=None, large=False) -> (dict, dict)
    ///
    /// The system's dynamics (a system file with ``[dynamics]``; see docs/systems.md, "Dynamics of a
    /// system"): ``(samples, events)``, two dicts of NumPy arrays keyed by the columns of
    /// ``camkin simulate SYSTEM.toml`` (``time_series.csv`` and ``events.csv``): a sample at the
    /// start and every ``step_deg`` of the first driver, each body's pose, rates and
    /// accelerations, each contact's force (N), gap and whether it is closed, the energy and the
    /// drivers' work; each lift-off and impact with its contact, instant and approach speed.
    /// ``substeps`` (integration steps per output step) is by default the fewest the stiffest
    /// spring or damper allows; fewer raises ``camkin.InputError`` naming it.
    ///
    /// Example::
    ///
    ///     s = camkin.System.from_toml("examples/valve-train.toml")
    ///     samples, events = s.simulate(revolutions=1.0, step_deg=1.0)
    ///     samples.to_pandas().iloc[:, :4]
    #[pyo3(signature = (*, revolutions = 1.0, step_deg = 1.0, substeps = None, large = false))]
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::real)] revolutions: f64,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        #[pyo3(from_py_with = crate::errors::count_or_none)] substeps: Option<usize>,
        large: bool,
    ) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
        let sys = &self.built.system;
        let (run, plan) = self.run_revolutions(py, revolutions, step_deg, substeps, large)?;
        let unit = self.built.length_unit.name();
        let mut samples = Columns::new(
            camkin::table::system_sample_columns(sys, unit, &self.built.dynamics.hertz),
            run.samples.len(),
        );
        let grid = camkin::table::AngleGrid::new(0.0, step_deg);
        for (k, s) in run.samples.iter().enumerate() {
            samples.push(camkin::table::system_sample_cells(
                grid.at(k),
                s,
                &self.built.dynamics.hertz,
            ));
        }
        let mut events = Columns::new(camkin::table::system_event_columns(unit), run.events.len());
        for e in &run.events {
            let angle = plan.angle_of(e.time);
            events.push(camkin::table::system_event_cells(sys, e, angle));
        }
        Ok((samples.into_dict(py, false)?, events.into_dict(py, false)?))
    }
}

impl PySystem {
    /// The simulation `simulate` and `lubrication` share: `revolutions` of the first driver in
    /// `step_deg` output steps (the library's plan), with the plan.
    pub(crate) fn run_revolutions(
        &self,
        py: Python<'_>,
        revolutions: f64,
        step_deg: f64,
        substeps: Option<usize>,
        large: bool,
    ) -> PyResult<(camkin::dynamics::SystemRun, camkin::spec::RunPlan)> {
        use camkin::spec::{PlanError, PlanField};
        let sys = &self.built.system;
        let h_ = camkin::human::human;
        let dyn_err = |e: camkin::dynamics::DynamicsError| errors::input("", None, e.to_string());
        let (plan, mut sim) = self
            .built
            .plan(revolutions, step_deg, substeps)
            .map_err(|e| match e {
                PlanError::OutOfRange {
                    field,
                    value,
                    range,
                } => {
                    let key = match field {
                        PlanField::Revolutions => "revolutions",
                        PlanField::Step => "step_deg",
                        _ => "substeps",
                    };
                    errors::input(key, Some(value.clone()), format!("{key} = {value}: must be {range}"))
                }
                PlanError::NotAnAngle => errors::input("driver", None, e.to_string()),
                PlanError::TooStiff {
                    ref element,
                    rate,
                    substeps,
                    ..
                } => {
                    let fix = match e.stiff_advice() {
                        Some(camkin::dynamics::StepAdvice::Substeps(n)) => {
                            format!("use substeps={n} or more")
                        }
                        Some(camkin::dynamics::StepAdvice::FinerStep { step_deg }) => format!(
                            "use substeps=1000 and step_deg={} or finer",
                            h_(step_deg)
                        ),
                        _ => format!(
                            "no step_deg from 0.001 with up to 1000 substeps resolves a rate of {} /s at this speed: check the element's stiffness and its bodies' masses (and their units)",
                            h_(rate)
                        ),
                    };
                    errors::input(
                        "substeps",
                        Some(substeps.to_string()),
                        format!(
                            "substeps = {substeps}: {element} is too stiff for {substeps} substeps of a {}° step (its rate {} /s): {fix}",
                            h_(step_deg),
                            h_(rate)
                        ),
                    )
                }
                PlanError::Dynamics(e) => dyn_err(e),
                e => errors::input("", None, e.to_string()),
            })?;
        errors::refuse_large(
            &camkin::work::Work::system_simulation(sys, plan.steps(), plan.outputs + 1),
            large,
            ", or simulate fewer revolutions",
        )?;
        let run = py.detach(|| {
            sim.run(plan.outputs, plan.substeps, plan.h(), |k| {
                if k % 1024 == 0 && errors::interrupted().is_err() {
                    return std::ops::ControlFlow::Break(());
                }
                std::ops::ControlFlow::Continue(())
            })
        });
        let run = match run {
            Ok(r) => r,
            Err(camkin::dynamics::DynamicsError::Stopped { .. }) => {
                errors::interrupted()?;
                return Err(errors::contact("stopped".into()));
            }
            Err(e) => return Err(dyn_err(e)),
        };
        Ok((run, plan))
    }
}
