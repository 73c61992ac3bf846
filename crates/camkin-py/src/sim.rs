//! `Mechanism.simulate` and `System.simulate`: the dynamics with lift-off and impacts, the command's
//! `simulate` as arrays.

use crate::columns::Columns;
use crate::errors;
use crate::model::{PyMechanism, PySystem};
use camkin::dynamics::{AugmentedLagrangian, DynamicsError, Simulation, Tolerances};
use camkin::table::{
    event_cells, event_columns, sample_cells, sample_columns, EventRow, SampleRow, Units,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

fn dyn_err(e: DynamicsError) -> PyErr {
    match e {
        DynamicsError::Invalid { .. }
        | DynamicsError::Unassembled { .. }
        | DynamicsError::DeadPoint { .. }
        | DynamicsError::StepUnderflow { .. }
        | DynamicsError::Chatter { .. } => errors::input("dynamics", None, e.to_string()),
        DynamicsError::FormClosed | DynamicsError::Interference { .. } => {
            errors::input("follower.conjugate", None, e.to_string())
        }
        _ => errors::contact(e.to_string()),
    }
}

/// `integrator` checked, as the keyword names it.
pub(crate) fn scheme(name: &str) -> PyResult<camkin::dynamics::Scheme> {
    camkin::dynamics::Scheme::from_name(name).ok_or_else(|| {
        errors::input(
            "integrator",
            Some(name.to_string()),
            format!(
                "integrator = {name:?}: must be one of {}",
                camkin::dynamics::Scheme::NAMES.join(", ")
            ),
        )
    })
}

/// `rtol` and `atol` checked, as the keywords name them.
pub(crate) fn tolerances(rtol: f64, atol: f64) -> PyResult<Tolerances> {
    let t = Tolerances {
        relative: rtol,
        absolute: atol,
    };
    match t.out_of_range() {
        Some((which, value)) => {
            let key = if which == "relative" { "rtol" } else { "atol" };
            let v = camkin::human::human(value);
            Err(errors::input(
                key,
                Some(v.clone()),
                format!("{key} = {v}: must be from 1e-13 to 0.01"),
            ))
        }
        None => Ok(t),
    }
}

#[pymethods]
impl PyMechanism {
    /// simulate(*, revolutions=1.0, step_deg=1.0, rtol=1e-10, atol=1e-10, start_angle_deg=0.0,
    /// large=False, integrator="auto") -> dict
    ///
    /// The follower's motion under its spring, damping and the cam (the file's ``[dynamics]``,
    /// SI units), with lift-off and impacts, from ``start_angle_deg`` for ``revolutions`` turns,
    /// sampled every ``step_deg`` of cam angle (the integration's steps chosen by the relative
    /// and absolute tolerances ``rtol`` and ``atol``, as ``camkin simulate``'s; ``integrator``
    /// is ``"auto"``, ``"explicit"`` or ``"implicit"``, as its ``--integrator``). Returns
    /// ``{"samples": dict of arrays, "events": list of dicts}`` with the columns of
    /// ``camkin simulate`` (lengths in the file's unit, force in N, time in s), the driver's
    /// torque and work and the follower's energy balance (``kinetic``, ``potential``,
    /// ``damper_work``, ``constraint_work``, ``impact_energy``, ``unexplained``) in N times the
    /// file's unit (docs/dynamics.md, "Energy and work").
    ///
    /// Example::
    ///
    ///     mech = camkin.Mechanism.from_toml("examples/paper-dynamics.toml")
    ///     r = mech.simulate(revolutions=1.0, step_deg=1.0)
    ///     r["events"]
    #[pyo3(signature = (*, revolutions = 1.0, step_deg = 1.0, rtol = 1e-10, atol = 1e-10, start_angle_deg = 0.0, large = false, integrator = "auto"))]
    #[allow(clippy::too_many_arguments)]
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::real)] revolutions: f64,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        #[pyo3(from_py_with = crate::errors::real)] rtol: f64,
        #[pyo3(from_py_with = crate::errors::real)] atol: f64,
        #[pyo3(from_py_with = crate::errors::real)] start_angle_deg: f64,
        large: bool,
        integrator: &str,
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
        let tolerances = tolerances(rtol, atol)?;
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
        sim.set_tolerances(tolerances).map_err(dyn_err)?;
        sim.set_scheme(scheme(integrator)?);
        let h = step_deg.to_radians() / mech.cam().speed();
        errors::refuse_large(
            &sim.run_work(&mech, outputs, h),
            large,
            ", or simulate fewer revolutions",
        )?;
        // Ctrl-C stops the run between output intervals: its KeyboardInterrupt, kept here
        let mut interrupt: Option<PyErr> = None;
        let result = py.detach(|| -> Result<_, DynamicsError> {
            let run = sim.run(outputs, h, |_| match errors::interrupted() {
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
    /// simulate(*, revolutions=None, step_deg=1.0, duration=None, interval=None, rtol=1e-10,
    /// atol=1e-10, large=False, integrator="auto") -> (dict, dict)
    ///
    /// The system's dynamics (a system file with ``[dynamics]``; see docs/systems.md, "Dynamics of a
    /// system"): ``(samples, events)``, two dicts of NumPy arrays keyed by the columns of
    /// ``camkin simulate SYSTEM.toml`` (``time_series.csv`` and ``events.csv``): a sample at the
    /// start and every ``step_deg`` of the first driver, each body's pose, rates and
    /// accelerations, each contact's force (N), gap and whether it is closed, the energy, the
    /// drivers' work and the energy balance (``kinetic``, ``potential``, ``damper_work``,
    /// ``constraint_work``, ``impact_energy`` and ``unexplained``, N·length: see
    /// docs/systems.md, "Energy, work and momentum"); each lift-off and impact with its
    /// contact, instant and approach speed.
    /// A run in time instead (a system without an angle driver: a pendulum, a mechanism
    /// released from rest): ``duration`` seconds with a sample every ``interval`` (by default a
    /// thousandth of it), or the file's ``[simulation]``; its samples have no driver angle.
    /// The integration's steps are chosen by the relative and absolute tolerances ``rtol`` and
    /// ``atol`` (as ``camkin simulate``'s ``--rtol`` and ``--atol``), the samples interpolated
    /// between them; ``integrator`` (``"auto"``, ``"explicit"`` or ``"implicit"``: for a stiff
    /// system, a damper far faster than its motion) as its ``--integrator``. Where the
    /// starting state was changed to fit the joints (the poses assembled, the bodies' ``velocity`` and ``angular_velocity`` projected), a
    /// ``CamkinWarning`` says by how much.
    ///
    /// Example::
    ///
    ///     s = camkin.System.from_toml("examples/valve-train.toml")
    ///     samples, events = s.simulate(revolutions=1.0, step_deg=1.0)
    ///     samples.to_pandas().iloc[:, :4]
    #[pyo3(signature = (*, revolutions = None, step_deg = 1.0, duration = None, interval = None, rtol = 1e-10, atol = 1e-10, large = false, integrator = "auto"))]
    #[allow(clippy::too_many_arguments)]
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::real_or_none)] revolutions: Option<f64>,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        #[pyo3(from_py_with = crate::errors::real_or_none)] duration: Option<f64>,
        #[pyo3(from_py_with = crate::errors::real_or_none)] interval: Option<f64>,
        #[pyo3(from_py_with = crate::errors::real)] rtol: f64,
        #[pyo3(from_py_with = crate::errors::real)] atol: f64,
        large: bool,
        integrator: &str,
    ) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
        let sys = &self.built.system;
        let tolerances = tolerances(rtol, atol)?;
        let scheme = scheme(integrator)?;
        let asked = camkin::spec::RunSettings {
            revolutions,
            step_deg,
            duration,
            interval,
        };
        let (run, plan) = self.run_asked(py, &asked, tolerances, scheme, large)?;
        let timed = plan.step_deg.is_none();
        let unit = self.built.length_unit.name();
        let mut samples = Columns::new(
            camkin::table::system_sample_columns(sys, unit, &self.built.dynamics.hertz, !timed),
            run.samples.len(),
        );
        for (k, s) in run.samples.iter().enumerate() {
            samples.push(camkin::table::system_sample_cells(
                plan.angle_at(k),
                s,
                &self.built.dynamics.hertz,
            ));
        }
        let mut events = Columns::new(
            camkin::table::system_event_columns(unit, !timed),
            run.events.len(),
        );
        for e in &run.events {
            let angle = plan.angle_of(e.time);
            events.push(camkin::table::system_event_cells(sys, e, angle));
        }
        Ok((samples.into_dict(py, false)?, events.into_dict(py, false)?))
    }

    /// Each lash of ``lashes`` (the file's length unit) set on every contact with a ``lash`` key
    /// and run over ``revolutions`` of the first driver (outputs every ``step_deg``), as
    /// ``camkin simulate --lash``: a column table (dict of arrays) with a row per lash and
    /// lashed contact — its take-up's and seating's driver angle (degrees) and approach speed
    /// (length unit per second), and the contact the valve seats on. The lashes run on both
    /// cores.
    ///
    /// Example::
    ///
    ///     s = camkin.System.from_toml("examples/bucket-lash.toml")
    ///     t = s.lash_sweep([0.05, 0.1, 0.2])
    ///     t["seating_speed_mm_s"]
    #[pyo3(signature = (lashes, *, revolutions = 1.0, step_deg = 1.0, large = false))]
    fn lash_sweep<'py>(
        &self,
        py: Python<'py>,
        lashes: Vec<f64>,
        #[pyo3(from_py_with = crate::errors::real)] revolutions: f64,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        large: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        use camkin::spec::LashError;
        let h = camkin::human::human;
        let lash_err = |e: LashError| match e {
            LashError::Plan(e) => plan_err(e),
            LashError::Invalid { value, reason } => errors::input(
                "lashes",
                Some(value.clone()),
                format!("lashes: a lash of {value} {reason}"),
            ),
            e => errors::input("lashes", None, e.to_string()),
        };
        if lashes.is_empty() || lashes.len() > 200 {
            return Err(errors::input(
                "lashes",
                Some(lashes.len().to_string()),
                format!("lashes: give 1 to 200 lashes, not {}", lashes.len()),
            ));
        }
        for &l in &lashes {
            self.built.with_lash(l).map_err(|e| match e {
                LashError::Invalid { reason, .. } => errors::input(
                    "lashes",
                    Some(h(l)),
                    format!("lashes: a lash of {} {reason}", h(l)),
                ),
                e => lash_err(e),
            })?;
        }
        errors::refuse_large(
            &self
                .built
                .lash_sweep_work(lashes.len(), revolutions, step_deg)
                .map_err(lash_err)?,
            large,
            ", or sweep fewer lashes",
        )?;
        let rows = py
            .detach(|| self.built.lash_sweep(&lashes, revolutions, step_deg))
            .map_err(lash_err)?;
        let mut table = Columns::new(
            camkin::table::lash_columns(self.built.length_unit.name()),
            rows.len(),
        );
        for r in &rows {
            table.push(camkin::table::lash_cells(r));
        }
        table.into_dict(py, false)
    }
}

impl PySystem {
    /// A revolution of the first driver in `step_deg` output steps at the default tolerances:
    /// what `forces` and `lubrication` report on.
    pub(crate) fn run_revolution(
        &self,
        py: Python<'_>,
        step_deg: f64,
        large: bool,
    ) -> PyResult<(camkin::dynamics::SystemRun, camkin::spec::RunPlan)> {
        let asked = camkin::spec::RunSettings {
            revolutions: Some(1.0),
            step_deg,
            duration: None,
            interval: None,
        };
        self.run_asked(py, &asked, Tolerances::default(), Default::default(), large)
    }

    /// The simulation `simulate`, `forces` and `lubrication` share: the run `asked` (the
    /// library's plan), with the plan; the start's changes to the state given warned of.
    pub(crate) fn run_asked(
        &self,
        py: Python<'_>,
        asked: &camkin::spec::RunSettings,
        tolerances: Tolerances,
        scheme: camkin::dynamics::Scheme,
        large: bool,
    ) -> PyResult<(camkin::dynamics::SystemRun, camkin::spec::RunPlan)> {
        let dyn_err = |e: camkin::dynamics::DynamicsError| errors::input("", None, e.to_string());
        let (plan, mut sim) = self.built.plan_asked(asked).map_err(plan_err)?;
        sim.set_tolerances(tolerances).map_err(dyn_err)?;
        sim.set_scheme(scheme);
        errors::refuse_large(
            &self.built.run_work(&plan, &sim, false, None),
            large,
            if plan.step_deg.is_none() {
                ", or simulate a shorter duration"
            } else {
                ", or simulate fewer revolutions"
            },
        )?;
        for line in sim
            .start_report()
            .describe(&self.built.system, self.built.length_unit.name())
        {
            errors::warn(py, &line, None, None, None)?;
        }
        let run = py.detach(|| {
            sim.run(plan.outputs, plan.h_out, |k| {
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

/// A run's plan refused, named as `simulate`'s keywords name its settings.
pub(crate) fn plan_err(e: camkin::spec::PlanError) -> PyErr {
    use camkin::spec::{PlanError, PlanField};
    let key = |field| match field {
        PlanField::Revolutions => "revolutions",
        PlanField::Duration => "duration",
        PlanField::Interval => "interval",
        _ => "step_deg",
    };
    match e {
        PlanError::OutOfRange {
            field,
            value,
            range,
        } => errors::input(
            key(field),
            Some(value.clone()),
            format!("{} = {value}: must be {range}", key(field)),
        ),
        PlanError::Both {
            field: PlanField::Interval,
            other: PlanField::Step,
        } => errors::input(
            "interval",
            None,
            "interval is the output interval of a run in time: give duration= (seconds) with it, or [simulation] duration = … in the file".into(),
        ),
        PlanError::Both { field, other } => errors::input(
            key(field),
            None,
            format!("{} with {}: {e}", key(field), key(other)),
        ),
        PlanError::NotAnAngle => errors::input(
            "duration",
            None,
            "its first driver does not turn an angle at a constant speed, so it is not simulated over revolutions: System.simulate(duration=…) runs it for a time (or [simulation] duration = … in the file)".into(),
        ),
        e => errors::input("", None, e.to_string()),
    }
}
