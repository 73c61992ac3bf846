//! `Mechanism.forces` and `System.forces`: the library's force reports (`camkin forces`) as
//! arrays and a dict — a mechanism's ([`camkin::report::ForceReport`]), and a simulated
//! system's over a revolution of its first driver ([`camkin::report::SystemForces`]: the columns
//! of its `forces.csv`, bit for bit, and its report and checks); and their lubrication
//! (`Mechanism.lubrication` through the same request, `System.lubrication`).

use crate::columns::Columns;
use crate::errors;
use crate::model::{PyMechanism, PySystem};
use camkin::lubrication::{FilmFormula, Friction, Lubricant, LubricantError, SurfaceProperties};
use camkin::report::{
    ForceField, ForceReport, ForceRequest, LubricationRequest, Materials, ReportError,
};
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
        ForceField::Viscosity | ForceField::PressureViscosity => "oil",
        ForceField::Roughness => "roughness_um",
        ForceField::Thermal => "materials",
        ForceField::Friction => "friction",
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
pub(crate) fn materials(x: &Bound<'_, PyAny>) -> PyResult<Materials> {
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

/// The `repr` of a Python value, for messages.
fn shown(x: &Bound<'_, PyAny>) -> String {
    x.repr().map(|r| r.to_string()).unwrap_or_default()
}

/// A real number from `x` (an int or a float; not a string, a bool or a complex), named `name`.
pub(crate) fn real(name: &str, x: &Bound<'_, PyAny>) -> PyResult<f64> {
    let refuse = || {
        let v = shown(x);
        errors::input(
            name,
            Some(v.clone()),
            format!("{name}: {v} is not a number"),
        )
    };
    if x.is_instance_of::<pyo3::types::PyBool>() || x.is_instance_of::<pyo3::types::PyString>() {
        return Err(refuse());
    }
    x.extract::<f64>().map_err(|_| refuse())
}

/// The lubrication the keywords and the file's `[lubrication]` ask for, each keyword replacing
/// the file's value: `None` without an oil in either; a roughness needed with one, and not given
/// without one.
pub(crate) fn lubrication(
    oil: Option<&Bound<'_, PyAny>>,
    roughness_um: Option<&Bound<'_, PyAny>>,
    film: Option<&str>,
    friction: Option<&Bound<'_, PyAny>>,
    materials: &Materials,
    file: Option<&camkin::spec::BuiltLubrication>,
) -> PyResult<Option<LubricationRequest>> {
    // the file's [lubrication] is the default of every keyword: one given replaces its value
    let from_file = file.map(|f| f.request);
    let lubricant = match oil {
        Some(oil) => {
            let text = oil.extract::<String>().map_err(|_| {
                let v = shown(oil);
                errors::input(
                    "oil",
                    Some(v.clone()),
                    format!("oil: {v} is not a lubricant's name or \"eta=<Pa·s>:alpha=<1/Pa>\""),
                )
            })?;
            Some(text.parse::<Lubricant>().map_err(|e: LubricantError| {
                errors::input("oil", Some(text.clone()), format!("oil: {e}"))
            })?)
        }
        None => from_file.map(|f| f.lubricant),
    };
    let Some(lubricant) = lubricant else {
        if let Some(r) = roughness_um {
            return Err(errors::input(
                "roughness_um",
                Some(shown(r)),
                "roughness_um: the surfaces' roughness is for the film's λ; give the lubricant with oil= (e.g. oil=\"sae-30@100c\")".into(),
            ));
        }
        return Ok(None);
    };
    let (rq, formula, friction) = lubrication_keywords(roughness_um, film, friction)?;
    let rq = match (rq, from_file) {
        (Some(rq), _) => rq,
        (None, Some(f)) => f.surfaces.map(|s| s.roughness),
        (None, None) => {
            return Err(errors::input(
                "roughness_um",
                None,
                "oil: λ needs each surface's RMS roughness: give roughness_um=(CAM, FOLLOWER) in µm, e.g. (0.2, 0.3)".into(),
            ))
        }
    };
    let thermal = [materials.cam.thermal, materials.follower.thermal];
    Ok(Some(LubricationRequest {
        lubricant,
        formula: formula.or(from_file.map(|f| f.formula)).unwrap_or_default(),
        surfaces: [0, 1].map(|i| SurfaceProperties {
            roughness: rq[i],
            thermal: thermal[i],
        }),
        friction: friction
            .or(from_file.map(|f| f.friction))
            .unwrap_or(camkin::spec::DEFAULT_FRICTION),
    }))
}

/// The roughness (m), film formula and friction keywords, each as given (`None`: not given).
#[allow(clippy::type_complexity)]
fn lubrication_keywords(
    roughness_um: Option<&Bound<'_, PyAny>>,
    film: Option<&str>,
    friction: Option<&Bound<'_, PyAny>>,
) -> PyResult<(Option<[f64; 2]>, Option<FilmFormula>, Option<Friction>)> {
    let rq = match roughness_um {
        None => None,
        Some(r) => {
            let pair = r
                .extract::<(Bound<'_, PyAny>, Bound<'_, PyAny>)>()
                .map_err(|_| {
                    let v = shown(r);
                    errors::input(
                        "roughness_um",
                        Some(v.clone()),
                        format!("roughness_um: {v} is not a pair (CAM, FOLLOWER) in µm, e.g. (0.2, 0.3)"),
                    )
                })?;
            let mut rq = [0.0; 2];
            for (slot, x) in rq.iter_mut().zip([&pair.0, &pair.1]) {
                let v = real("roughness_um", x)?;
                *slot = camkin::lubrication::roughness_from_um(v).ok_or_else(|| {
                    errors::input(
                        "roughness_um",
                        Some(shown(x)),
                        format!(
                            "roughness_um: {} µm {}",
                            shown(x),
                            camkin::lubrication::ROUGHNESS_RULE
                        ),
                    )
                })?;
            }
            Some(rq)
        }
    };
    let formula = match film {
        None => None,
        Some(film) => Some(
            FilmFormula::ALL
                .into_iter()
                .find(|f| f.name() == film)
                .ok_or_else(|| {
                    errors::input(
                        "film",
                        Some(film.to_string()),
                        format!(
                            "film: {film:?} is not a film formula: {}",
                            FilmFormula::ALL.map(FilmFormula::name).join(" or ")
                        ),
                    )
                })?,
        ),
    };
    let friction = match friction {
        None => None,
        Some(f) => Some(
            if let Ok((b, full)) = f.extract::<(Bound<'_, PyAny>, Bound<'_, PyAny>)>() {
                Friction::Mixed {
                    boundary: real("friction", &b)?,
                    full_film: real("friction", &full)?,
                }
            } else {
                Friction::Constant(real("friction", f)?)
            },
        ),
    };
    Ok((rq, formula, friction))
}

#[pymethods]
impl PyMechanism {
    /// forces(*, step_deg=0.5, margin=0.0, target_rpm=None, face_width=None, materials="steel,steel", allowable_mpa=None, oil=None, roughness_um=None, film=None, friction=None)
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
    /// With ``oil`` (a preset such as ``"sae-30@100c"``, or ``"eta=<Pa·s>:alpha=<1/Pa>"``),
    /// ``roughness_um`` (the cam's and the follower's RMS roughness, µm) and ``face_width``, the
    /// lubrication too: ``"lubrication"`` holds the columns of ``lubrication.csv`` (entrainment
    /// and sliding m/s, film µm, λ, regime, friction, flash temperature K, friction power W) and
    /// the report's ``"lubrication"`` its summary (smallest λ, entrainment reversals in rad,
    /// flash temperature, friction power). ``film`` is ``"dowson-higginson"`` (default) or
    /// ``"hamrock"``; ``friction`` a coefficient or ``(boundary, full_film)`` (linear in λ from 1
    /// to 3; default ``(0.1, 0.03)``). A file's ``[lubrication]`` section gives every one of
    /// these (and ``face_width``, ``materials``) that is not passed.
    ///
    /// >>> r = camkin.Mechanism.from_toml("examples/paper-dynamics.toml").forces(face_width=10)
    /// >>> r["report"]["jump"]["speed"] * 60 / (2 * math.pi)   # rpm
    #[pyo3(signature = (*, step_deg = 0.5, margin = 0.0, target_rpm = None, face_width = None, materials = None, allowable_mpa = None, oil = None, roughness_um = None, film = None, friction = None))]
    #[allow(clippy::too_many_arguments)]
    fn forces<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        #[pyo3(from_py_with = crate::errors::real)] margin: f64,
        #[pyo3(from_py_with = crate::errors::real_or_none)] target_rpm: Option<f64>,
        #[pyo3(from_py_with = crate::errors::real_or_none)] face_width: Option<f64>,
        materials: Option<&Bound<'py, PyAny>>,
        #[pyo3(from_py_with = crate::errors::real_or_none)] allowable_mpa: Option<f64>,
        oil: Option<&Bound<'py, PyAny>>,
        roughness_um: Option<&Bound<'py, PyAny>>,
        film: Option<&str>,
        friction: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (built, params) = self.built_si("forces")?;
        // the file's [lubrication] gives what the keywords leave out
        let file = built.lubrication.clone();
        let materials = match (materials, &file) {
            (Some(m), _) => self::materials(m)?,
            (None, Some(f)) => f.materials.clone(),
            (None, None) => Materials::default(),
        };
        let face_width = face_width.or(file.as_ref().map(|f| f.face_width));
        let lubrication =
            lubrication(oil, roughness_um, film, friction, &materials, file.as_ref())?;
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
            lubrication,
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
        if let Some(l) = &report.lubrication {
            out.set_item("lubrication", table(l.table())?)?;
        }
        // the rest of the report (its tables are the columns above)
        let mut v = serde_json::to_value(&report)
            .map_err(|e| errors::contact(format!("the report cannot be written: {e}")))?;
        if let Some(o) = v.as_object_mut() {
            for k in ["states", "stress_mpa", "force_speed", "coefficients"] {
                o.remove(k);
            }
            if let Some(l) = o.get_mut("lubrication").and_then(|l| l.as_object_mut()) {
                for k in ["points", "cam_angles"] {
                    l.remove(k);
                }
            }
        }
        let json = py.import("json")?;
        out.set_item("report", json.call_method1("loads", (v.to_string(),))?)?;
        crate::columns::result(out)
    }
}

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
        // the library's checks, as a cam's forces take them
        if let Err(e) = camkin::report::check_limits(margin, allowable_mpa) {
            let (key, value) = match e.field() {
                Some(ForceField::Allowable) => ("allowable_mpa", allowable_mpa.unwrap_or(f64::NAN)),
                _ => ("margin", margin),
            };
            return Err(errors::input(
                key,
                Some(h(value)),
                format!("{key} = {}: {e}", h(value)),
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
            let (steps, samples) = sw.work(&sim);
            errors::refuse_large(
                &camkin::work::Work::system_simulation(sys, steps, samples, outputs + 1),
                large,
                ", or use a coarser step_deg",
            )?;
        }
        let (run, plan) = self.run_revolution(py, step_deg, large)?;
        // a run over the driver's angle (`BuiltSystem::plan`) has one at every instant
        let angle_of = |t: f64| plan.angle_of(t).unwrap_or(f64::NAN);
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

#[pymethods]
impl PySystem {
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
        let (run, plan) = self.run_revolution(py, step_deg, large)?;
        // a run over the driver's angle (`BuiltSystem::plan`) has one at every instant
        let angle_of = |t: f64| plan.angle_of(t).unwrap_or(f64::NAN);
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
}
