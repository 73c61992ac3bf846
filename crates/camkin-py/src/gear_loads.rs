//! `Mechanism.gear_loads`: a gear pair's loads along its whole path of contact
//! (`camkin forces GEAR.toml --torque`).

use crate::columns::Columns;
use crate::errors;
use crate::forces::{lubrication, materials, real};
use crate::model::PyMechanism;
use camkin::gears::GearPair;
use camkin::report::{GearLoadRequest, GearLoads};
use camkin::spec::{GivenLoads, LoadInput};
use pyo3::prelude::*;
use pyo3::types::PyDict;

#[pymethods]
impl PyMechanism {
    /// gear_loads(*, torque=None, power_kw=None, face_width=None, materials=None, oil=None, roughness_um=None, film=None, friction=None, points=201)
    ///
    /// A gear pair's loads along its whole path of contact, as ``camkin forces --torque``:
    /// ``torque`` (N·m on the driver; or ``power_kw``, turned into ``P/ω`` at the file's speed)
    /// puts ``T/r_b1`` along the line of action, shared equally between the pairs in contact;
    /// per point the load (N), Hertz (MPa, with ``face_width`` in the file's length unit), the
    /// flanks' speeds and the specific sliding from the driver's root to its tip, and with
    /// ``oil`` and ``roughness_um`` the film and flash temperature. Each keyword replaces the
    /// file's ``[gear_loads]`` (and ``[lubrication]``) value.
    /// Returns ``{"columns": …, "report": …}`` (the columns of ``gear_loads.csv``).
    ///
    /// >>> r = camkin.Mechanism.from_toml("examples/gear-pair-20-42.toml").gear_loads(torque=50, face_width=20)
    /// >>> r["report"]["normal_force"]   # N
    #[pyo3(signature = (*, torque = None, power_kw = None, face_width = None, materials = None, oil = None, roughness_um = None, film = None, friction = None, points = 201))]
    #[allow(clippy::too_many_arguments)]
    fn gear_loads<'py>(
        &self,
        py: Python<'py>,
        torque: Option<&Bound<'py, PyAny>>,
        power_kw: Option<&Bound<'py, PyAny>>,
        face_width: Option<&Bound<'py, PyAny>>,
        materials: Option<&Bound<'py, PyAny>>,
        oil: Option<&Bound<'py, PyAny>>,
        roughness_um: Option<&Bound<'py, PyAny>>,
        film: Option<&str>,
        friction: Option<&Bound<'py, PyAny>>,
        #[pyo3(from_py_with = crate::errors::count)] points: usize,
    ) -> PyResult<Bound<'py, PyDict>> {
        let torque_v = torque.map(|t| real("torque", t)).transpose()?;
        let power_v = power_kw.map(|p| real("power_kw", p)).transpose()?;
        let width_v = face_width.map(|w| real("face_width", w)).transpose()?;
        let given_materials = materials.map(self::materials).transpose()?;
        let built = self.built_si_any()?;
        let mech = &built.mechanism;
        let asked = match (torque_v, power_v) {
            (Some(t), _) => ("torque", Some(camkin::human::human(t))),
            (None, Some(p)) => ("power_kw", Some(camkin::human::human(p))),
            (None, None) => ("torque", None),
        };
        let pair = GearPair::new(mech).map_err(|e| {
            errors::input(
                asked.0,
                asked.1.clone(),
                format!("{}: the mechanism is not a gear pair ({e}): a cam mechanism's forces come from forces()", asked.0),
            )
        })?;
        let given = GivenLoads {
            torque: torque_v,
            power_kw: power_v,
            face_width: width_v,
            materials: given_materials,
        };
        let resolved = built.gear_loads_inputs(&given).map_err(|e| {
            let field = match e.input {
                LoadInput::Torque => "torque",
                LoadInput::Power => "power_kw",
                _ => "face_width",
            };
            errors::input(field, e.value.clone(), format!("{field}: {e}"))
        })?;
        let file = built.lubrication.clone();
        let materials = resolved.materials.clone();
        let lubrication =
            lubrication(oil, roughness_um, film, friction, &materials, file.as_ref())?;
        if let Some(l) = &lubrication {
            l.validate()
                .map_err(|e| errors::input("oil", None, format!("oil: {e}")))?;
        }
        let req = GearLoadRequest {
            torque: resolved.torque,
            face_width: resolved.face_width,
            materials,
            lubrication,
            points,
        };
        let loads = GearLoads::new(&pair, mech.cam().speed(), &req).map_err(|e| {
            let (field, value) = match e {
                camkin::report::GearLoadError::FaceWidth(w) => ("face_width", w),
                camkin::report::GearLoadError::Points(n) => ("points", n as f64),
                _ => ("torque", resolved.torque),
            };
            errors::input(
                field,
                Some(camkin::human::human(value)),
                format!("{field}: {e}"),
            )
        })?;
        let (names, rows) = loads.table();
        let mut cols = Columns::new(names, rows.len());
        for r in rows {
            cols.push(r);
        }
        let out = PyDict::new(py);
        out.set_item("columns", cols.into_dict(py, false)?)?;
        let mut v = serde_json::to_value(&loads)
            .map_err(|e| errors::contact(format!("the report cannot be written: {e}")))?;
        if let Some(o) = v.as_object_mut() {
            o.remove("points");
        }
        let json = py.import("json")?;
        out.set_item("report", json.call_method1("loads", (v.to_string(),))?)?;
        crate::columns::result(out)
    }
}
