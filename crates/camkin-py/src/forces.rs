//! `Mechanism.forces`: the library's force report (`camkin forces`) as arrays and a dict.

use crate::columns::Columns;
use crate::errors;
use crate::mech::PyMechanism;
use camkin::report::{ForceField, ForceReport, ForceRequest, Materials, ReportError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The keyword that sets a field of the request.
fn keyword(field: ForceField) -> &'static str {
    match field {
        ForceField::Step => "step_deg",
        ForceField::Margin => "margin",
        ForceField::TargetRpm => "target_rpm",
        ForceField::FaceWidth => "face_width",
        ForceField::Materials => "materials",
        ForceField::Allowable => "allowable_mpa",
        _ => "an argument",
    }
}

fn report_error(e: ReportError, value: Option<String>) -> PyErr {
    match e.field() {
        Some(field) => {
            let name = keyword(field);
            errors::input(name, value, format!("{name}: {e}"))
        }
        None => match e {
            ReportError::Dynamics(_) => errors::input("dynamics", None, e.to_string()),
            _ => errors::contact(e.to_string()),
        },
    }
}

/// Materials from ``"steel,bronze"`` or ``("steel", "E=210e9:nu=0.3")``.
fn materials(x: &Bound<'_, PyAny>) -> PyResult<Materials> {
    let text = if let Ok(s) = x.extract::<String>() {
        s
    } else if let Ok((a, b)) = x.extract::<(String, String)>() {
        format!("{a},{b}")
    } else {
        let shown = x.repr().map(|r| r.to_string()).ok();
        return Err(errors::input(
            "materials",
            shown.clone(),
            format!(
                "materials: {} is not \"CAM,FOLLOWER\" or a pair of material names (e.g. \"steel,steel\")",
                shown.unwrap_or_default()
            ),
        ));
    };
    text.parse::<Materials>()
        .map_err(|e| errors::input("materials", Some(text.clone()), format!("materials: {e}")))
}

#[pymethods]
impl PyMechanism {
    /// forces(*, step_deg=0.5, margin=0.0, target_rpm=None, face_width=None, materials="steel,steel", allowable_mpa=None)
    ///
    /// The forces over a revolution under permanent contact (the file's ``[dynamics]``; friction
    /// neglected), as ``camkin forces`` computes them: the contact force (N), the camshaft torque
    /// (N·m), the jump speed, the spring that keeps the follower on up to ``target_rpm`` with
    /// ``margin`` N to spare, and with ``face_width`` (in the file's length unit) the Hertz stress
    /// (MPa) of ``materials`` (presets or ``E=<Pa>:nu=<ratio>``, cam first).
    ///
    /// Returns ``{"columns": …, "force_speed": …, "report": …}``: the columns of ``forces.csv``
    /// and ``force_speed.csv`` as arrays (the same numbers, bit for bit), and the report's
    /// extremes, checks and sizing as a dict (SI units: angles in rad, speeds in rad/s).
    ///
    /// >>> r = camkin.Mechanism.from_toml("examples/paper-dynamics.toml").forces(face_width=10)
    /// >>> r["report"]["jump"]["speed"] * 60 / (2 * math.pi)   # rpm
    #[pyo3(signature = (*, step_deg = 0.5, margin = 0.0, target_rpm = None, face_width = None, materials = None, allowable_mpa = None))]
    #[allow(clippy::too_many_arguments)]
    fn forces<'py>(
        &self,
        py: Python<'py>,
        step_deg: f64,
        margin: f64,
        target_rpm: Option<f64>,
        face_width: Option<f64>,
        materials: Option<&Bound<'py, PyAny>>,
        allowable_mpa: Option<f64>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let materials = match materials {
            Some(m) => self::materials(m)?,
            None => Materials::default(),
        };
        let (built, params) = self.built_si("forces")?;
        let mech = built.mechanism;
        let req = ForceRequest {
            step_deg,
            margin,
            target_rpm,
            face_width,
            materials,
            allowable_mpa,
            unit: built.length_unit,
            force_speed: true,
            lubrication: None,
        };
        let value_of = |e: &ReportError| {
            match e.field() {
                Some(ForceField::Margin) => Some(margin),
                Some(ForceField::TargetRpm) => target_rpm,
                Some(ForceField::FaceWidth) => face_width,
                Some(ForceField::Allowable) => allowable_mpa,
                Some(ForceField::Step) => Some(step_deg),
                _ => None,
            }
            .map(camkin::human::human)
        };
        req.validate(&mech)
            .map_err(|e| report_error(e.clone(), value_of(&e)))?;
        if let Some(refusal) = req.work(&mech).refusal() {
            return Err(errors::resource(format!(
                "{refusal}; use a coarser step_deg"
            )));
        }
        let report = py
            .detach(|| ForceReport::new(&mech, params, &req))
            .map_err(|e| report_error(e.clone(), value_of(&e)))?;
        let table = |(names, rows): (Vec<String>, Vec<Vec<camkin::table::Cell>>)| {
            let mut cols = Columns::new(names, rows.len());
            for r in rows {
                cols.push(r);
            }
            cols.into_dict(py, false)
        };
        let out = PyDict::new(py);
        out.set_item("columns", table(report.table())?)?;
        out.set_item("force_speed", table(report.force_speed_table())?)?;
        // the rest of the report (its tables are the columns above)
        let mut v = serde_json::to_value(&report)
            .map_err(|e| errors::contact(format!("the report cannot be written: {e}")))?;
        if let Some(o) = v.as_object_mut() {
            for k in ["states", "stress_mpa", "force_speed", "coefficients"] {
                o.remove(k);
            }
        }
        let json = py.import("json")?;
        out.set_item("report", json.call_method1("loads", (v.to_string(),))?)?;
        Ok(out)
    }
}
