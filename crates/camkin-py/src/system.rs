//! `camkin.System`: a planar multibody system read from a system file, analysed over its first
//! driver's angle with the command's columns.

use crate::columns::{angles_from, Columns};
use crate::errors;
use crate::mech::TomlSource;
use camkin::spec::text::read_system;
use camkin::spec::{BuildOptions, BuiltSystem};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A planar multibody system: bodies, joints, drivers and contacts, as a system file describes
/// them (``[[body]]``, ``[[joint]]``, ``[[driver]]``, ``[[contact]]``; see docs/systems.md). Every
/// contact is the paper's exact row. Build one with ``System.from_toml(path_or_text)``.
#[pyclass(frozen, module = "camkin", name = "System")]
#[derive(Debug, Clone)]
pub struct PySystem {
    pub(crate) built: BuiltSystem,
    name: String,
}

#[pymethods]
impl PySystem {
    /// System.from_toml(source, *, large=False) -> System
    ///
    /// A system from a system file (a path, ``str`` or ``os.PathLike``) or its TOML text. A
    /// cam-follower or gear-pair file is its mechanism as a system (bodies ``cam`` and
    /// ``follower``, one contact), analysed at cam angles: ``camkin analyze --system``. Bad
    /// input raises ``camkin.InputError`` naming the element, its key and the value, with the
    /// line and column (``.line``, ``.column``), as the command does.
    ///
    /// Example::
    ///
    ///     s = camkin.System.from_toml("examples/valve-train.toml")
    ///     s.bodies, s.contacts
    #[staticmethod]
    #[pyo3(signature = (source, *, large = false))]
    fn from_toml(py: Python<'_>, source: &Bound<'_, PyAny>, large: bool) -> PyResult<Self> {
        let s = TomlSource::read(py, source, "System.from_toml", "system")?;
        let options = BuildOptions {
            base_dir: s.base,
            si: false,
            confine: false,
            limits: crate::mech::limits(large),
        };
        let built = read_system(&s.text, &s.file, &options).map_err(errors::text)?;
        for w in &built.warnings {
            let field = errors::spec_warning_field(w);
            errors::warn(
                py,
                &format!("{}: {w}", s.file),
                field.as_deref(),
                None,
                None,
            )?;
        }
        Ok(Self {
            built,
            name: s.name,
        })
    }

    /// The bodies' names, in the file's order.
    #[getter]
    fn bodies(&self) -> Vec<String> {
        self.built
            .system
            .bodies()
            .iter()
            .map(|b| b.name.clone())
            .collect()
    }

    /// The contacts' names, in the file's order.
    #[getter]
    fn contacts(&self) -> Vec<String> {
        self.built
            .system
            .contacts()
            .iter()
            .map(|c| c.name.clone())
            .collect()
    }

    /// analyze(angles_deg, *, strict=False, large=False) -> dict
    ///
    /// The system at its first driver's angles (degrees; a number or a 1-D array), swept in
    /// order, each instant warm-started from the last: a dict of NumPy arrays keyed by the
    /// columns of ``camkin analyze SYSTEM.toml`` — each body's ``x``, ``y``, ``angle`` and their
    /// rates and accelerations, each contact's point, gap, sliding rates, ``gamma`` and ``jump``,
    /// and ``error``. An instant that cannot be solved has NaN and its reason in ``error``;
    /// ``strict=True`` raises ``camkin.ContactError`` instead.
    ///
    /// Example::
    ///
    ///     s = camkin.System.from_toml("examples/cam-four-bar.toml")
    ///     r = s.analyze(np.arange(0.0, 360.0, 1.0))  # the first driver's angle, degrees
    ///     r.to_pandas().iloc[:, :6]
    #[pyo3(signature = (angles_deg, *, strict = false, large = false))]
    fn analyze<'py>(
        &self,
        py: Python<'py>,
        angles_deg: &Bound<'py, PyAny>,
        strict: bool,
        large: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (angles, scalar) = angles_from(py, angles_deg, "angles_deg")?;
        let sys = &self.built.system;
        let times = self.built.times(&angles).map_err(|e| match e {
            camkin::spec::SweepError::NeverReached { angle_deg } => errors::input(
                "angles_deg",
                Some(camkin::human::human(angle_deg)),
                e.to_string(),
            ),
            _ => errors::input("driver", None, e.to_string()),
        })?;
        errors::refuse_large(
            &camkin::work::Work::system(sys, angles.len()),
            large,
            ", or use fewer angles",
        )?;
        let (cols, first_error) = py.detach(|| -> PyResult<_> {
            // a system that cannot be analysed at its first instant (a loop that does not
            // close) is bad input, named by its element; the sweep starts there
            let mut instants = sys.instants(&times).map_err(|e| {
                errors::input(
                    "",
                    None,
                    format!(
                        "the system cannot be analysed at its first instant ({}°): {}",
                        camkin::human::human(angles.first().copied().unwrap_or(0.0)),
                        self.built.explain(&e)
                    ),
                )
            })?;
            let mut cols = Columns::new(camkin::table::system_columns(&self.built), angles.len());
            let mut first_error = None;
            for (k, (&a, &t)) in angles.iter().zip(&times).enumerate() {
                if k % 4096 == 0 {
                    errors::interrupted()?;
                }
                let Some(s) = instants.next() else { break };
                if let Err(e) = &s {
                    first_error.get_or_insert((a, e.to_string()));
                }
                cols.push(camkin::table::system_cells(sys, a, t, &s));
            }
            Ok((cols, first_error))
        })?;
        if let (true, Some((a, e))) = (strict, &first_error) {
            return Err(errors::contact(format!(
                "at {} {}°: {e}",
                self.built.angle_name(),
                camkin::human::human(*a)
            )));
        }
        cols.into_dict(py, scalar)
    }

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

    /// lubrication(*, step_deg=1.0, large=False) -> dict
    ///
    /// The lubrication of the system's contacts over a revolution of its first driver, as
    /// ``camkin forces SYSTEM.toml --step STEP`` gives it (its file's ``[lubrication]`` and each
    /// contact's ``face_width``, ``roughness_um`` and ``rolls``): ``{"columns": …, "report": …}``,
    /// the columns of its ``lubrication.csv`` (a row per sample and lubricated contact: the
    /// entrainment and sliding in m/s, the film in µm, λ, the regime, the flash temperature in
    /// K, the friction power in W) and each contact's extremes.
    ///
    /// >>> s = camkin.System.from_toml("examples/valve-train.toml")
    /// >>> r = s.lubrication(step_deg=1.0)
    /// >>> r["report"]["contacts"][0]["min_lambda"]
    #[pyo3(signature = (*, step_deg = 1.0, large = false))]
    fn lubrication<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        large: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let Some(req) = self.built.lubrication.as_ref() else {
            return Err(errors::input(
                "lubrication",
                None,
                "the system's file has no [lubrication] table (its oil and roughness)".into(),
            ));
        };
        let (run, plan) = self.run_revolutions(py, 1.0, step_deg, None, large)?;
        let angle_of = |t: f64| plan.angle_of(t);
        let report =
            camkin::report::SystemLubricationReport::new(&self.built.system, &run, req, angle_of);
        let (names, rows) = report.table();
        let mut cols = Columns::new(names, rows.len());
        for r in rows {
            cols.push(r);
        }
        let out = PyDict::new(py);
        out.set_item("columns", cols.into_dict(py, false)?)?;
        let mut v = serde_json::to_value(&report)
            .map_err(|e| errors::contact(format!("the report cannot be written: {e}")))?;
        if let Some(cs) = v.get_mut("contacts").and_then(|c| c.as_array_mut()) {
            for c in cs {
                if let Some(o) = c.as_object_mut() {
                    o.remove("points");
                }
            }
        }
        if let Some(o) = v.as_object_mut() {
            o.remove("angles_deg");
        }
        let json = py.import("json")?;
        out.set_item("report", json.call_method1("loads", (v.to_string(),))?)?;
        crate::columns::result(out)
    }

    fn __repr__(&self) -> String {
        let s = &self.built.system;
        format!(
            "<camkin.System {:?}: {} bodies, {} joints, {} drivers, {} contacts, lengths in {}>",
            self.name,
            s.bodies().len(),
            s.joints().len(),
            s.drivers().len(),
            s.contacts().len(),
            self.built.length_unit.name()
        )
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
                    element,
                    rate,
                    substeps,
                    need,
                    ..
                } => errors::input(
                    "substeps",
                    Some(substeps.to_string()),
                    format!(
                        "substeps = {substeps}: {element} is too stiff for {substeps} substeps of a {}° step (its rate {} /s): use substeps={need} or more (at most 1000)",
                        h_(step_deg),
                        h_(rate)
                    ),
                ),
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
