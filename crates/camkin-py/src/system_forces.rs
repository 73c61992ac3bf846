//! A simulated system's forces from Python: the library's [`camkin::report::SystemForces`] over
//! a revolution of its first driver, as `camkin forces SYSTEM.toml` gives them (the columns of
//! its `forces.csv`, bit for bit, and its report and checks).

use crate::columns::Columns;
use crate::errors;
use crate::system::PySystem;
use pyo3::prelude::*;
use pyo3::types::PyDict;

#[pymethods]
impl PySystem {
    /// forces(*, step_deg=1.0, margin=0.0, allowable_mpa=None, target_rpm=None, large=False) -> dict
    ///
    /// The forces of the system over a revolution of its first driver, simulated as
    /// ``camkin forces SYSTEM.toml --step STEP`` simulates it (the file's ``[dynamics]``, the
    /// time step the stiffest element needs):
    ///
    /// - ``columns``: its ``forces.csv`` (``driver_angle_deg``, ``time_s``, each contact's
    ///   ``<name>_force_N`` and, with a face width, ``<name>_hertz_MPa``, each driver's torque
    ///   ``…_torque_N_m`` or force), bit for bit;
    /// - ``report``: each contact's largest force (N), smallest force while closed, whether it
    ///   stays closed and its largest Hertz pressure (MPa), each driver's largest, smallest,
    ///   mean and RMS effort (N·m or N), each impact (its angle in degrees, approach speed m/s);
    /// - ``failures``: the checks that fail — a contact closed all the revolution whose force
    ///   falls under ``margin`` N, a contact whose Hertz pressure exceeds ``allowable_mpa`` MPa,
    ///   and with ``target_rpm`` a contact closed at the sweep's slowest speed that opens below
    ///   the target (the no-follow speed, swept from a quarter of the lower of the target and the
    ///   file's speed in eight steps, bisected to 1 rpm) — the command's ``--margin``,
    ///   ``--allowable``, ``--target-rpm`` (exit code 3 there).
    ///
    /// The lubrication of its contacts is ``lubrication()``.
    ///
    /// Example::
    ///
    ///     s = camkin.System.from_toml("examples/valve-train.toml")
    ///     f = s.forces(margin=50.0)
    ///     f["report"]["drivers"][0]["max"], f["failures"]
    #[pyo3(signature = (*, step_deg = 1.0, margin = 0.0, allowable_mpa = None, target_rpm = None, large = false))]
    fn forces<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        #[pyo3(from_py_with = crate::errors::real)] margin: f64,
        #[pyo3(from_py_with = crate::errors::real_or_none)] allowable_mpa: Option<f64>,
        #[pyo3(from_py_with = crate::errors::real_or_none)] target_rpm: Option<f64>,
        large: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let h = camkin::human::human;
        if !margin.is_finite() {
            return Err(errors::input(
                "margin",
                Some(h(margin)),
                format!("margin = {}: must be a finite force, N", h(margin)),
            ));
        }
        if let Some(a) = allowable_mpa.filter(|a| !(a.is_finite() && *a > 0.0)) {
            return Err(errors::input(
                "allowable_mpa",
                Some(h(a)),
                format!("allowable_mpa = {}: must be a positive pressure, MPa", h(a)),
            ));
        }
        if let Some(t) = target_rpm.filter(|t| !(t.is_finite() && *t > 0.0 && *t <= 1e6)) {
            return Err(errors::input(
                "target_rpm",
                Some(h(t)),
                format!(
                    "target_rpm = {}: must be a positive speed up to 1e6, rpm",
                    h(t)
                ),
            ));
        }
        if !self.built.simulated {
            return Err(errors::input(
                "dynamics",
                None,
                "a system's forces come from its simulation: its file needs a [dynamics] table"
                    .into(),
            ));
        }
        let sys = &self.built.system;
        let sweep = target_rpm.map(|t| camkin::dynamics::SpeedSweep::to_target(sys, t, step_deg));
        if let Some(sw) = &sweep {
            let sim = camkin::dynamics::SystemSimulation::new(sys, self.built.dynamics.clone())
                .map_err(|e| errors::input("dynamics", None, e.to_string()))?;
            let outputs = (360.0 / step_deg).round().max(1.0) as usize;
            errors::refuse_large(
                &camkin::work::Work::system_simulation(
                    sys,
                    sw.steps(outputs, |h| sim.substeps(h)),
                    outputs + 1,
                ),
                large,
                ", or use a coarser step_deg",
            )?;
        }
        let (run, plan) = self.run_revolutions(py, 1.0, step_deg, None, large)?;
        let angle_of = |t: f64| plan.angle_of(t);
        let report = camkin::report::SystemForces::new(
            sys,
            &run,
            self.built.dynamics.metres_per_unit,
            angle_of,
        );
        let (names, rows) = camkin::table::system_force_table(
            sys,
            &run.samples,
            self.built.length_unit.name(),
            &self.built.dynamics.hertz,
            step_deg,
        );
        let mut cols = Columns::new(names, rows.len());
        for r in rows {
            cols.push(r);
        }
        let json = py.import("json")?;
        let loads = |v: Result<String, serde_json::Error>| -> PyResult<Bound<'py, PyAny>> {
            let text =
                v.map_err(|e| errors::contact(format!("the report cannot be written: {e}")))?;
            json.call_method1("loads", (text,))
        };
        let out = PyDict::new(py);
        out.set_item("columns", cols.into_dict(py, false)?)?;
        out.set_item("report", loads(serde_json::to_string(&report))?)?;
        let mut failures = report.failures(margin, allowable_mpa);
        if let Some(sw) = &sweep {
            let dynamics = &self.built.dynamics;
            let found = py
                .detach(|| camkin::dynamics::no_follow_speed(sys, dynamics, sw))
                .map_err(|e| errors::input("target_rpm", None, e.to_string()))?;
            if let Some(nf) = found {
                failures.push(camkin::report::SystemForceFailure::no_follow(sys, &nf, sw));
            }
        }
        out.set_item("failures", loads(serde_json::to_string(&failures))?)?;
        crate::columns::result(out)
    }
}
