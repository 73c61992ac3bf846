//! `Mechanism.gear_loads`: a gear pair's loads along its whole path of contact
//! (`camkin forces GEAR.toml --torque`).

use crate::columns::Columns;
use crate::errors;
use crate::forces::{lubrication, materials, real};
use crate::mech::PyMechanism;
use camkin::gears::GearPair;
use camkin::report::{GearLoadRequest, GearLoads, Materials};
use pyo3::prelude::*;
use pyo3::types::PyDict;

#[pymethods]
impl PyMechanism {
    /// gear_loads(*, torque, face_width=None, materials=None, oil=None, roughness_um=None, film=None, friction=None, points=201)
    ///
    /// A gear pair's loads along its whole path of contact, as ``camkin forces --torque``:
    /// ``torque`` (N·m on the driver) puts ``T/r_b1`` along the line of action, shared equally
    /// between the pairs in contact; per point the load (N), Hertz (MPa, with ``face_width`` in
    /// the file's length unit), the flanks' speeds and the specific sliding from the driver's
    /// root to its tip, and with ``oil`` and ``roughness_um`` the film and flash temperature.
    /// Returns ``{"columns": …, "report": …}`` (the columns of ``gear_loads.csv``).
    ///
    /// >>> r = camkin.Mechanism.from_toml("examples/gear-pair-20-42.toml").gear_loads(torque=50, face_width=20)
    /// >>> r["report"]["normal_force"]   # N
    #[pyo3(signature = (*, torque, face_width = None, materials = None, oil = None, roughness_um = None, film = None, friction = None, points = 201))]
    #[allow(clippy::too_many_arguments)]
    fn gear_loads<'py>(
        &self,
        py: Python<'py>,
        torque: &Bound<'py, PyAny>,
        face_width: Option<&Bound<'py, PyAny>>,
        materials: Option<&Bound<'py, PyAny>>,
        oil: Option<&Bound<'py, PyAny>>,
        roughness_um: Option<&Bound<'py, PyAny>>,
        film: Option<&str>,
        friction: Option<&Bound<'py, PyAny>>,
        points: usize,
    ) -> PyResult<Bound<'py, PyDict>> {
        let torque_v = real("torque", torque)?;
        let built = self.built_si_any()?;
        let unit = built.length_unit;
        let mech = &built.mechanism;
        let pair = GearPair::new(mech).map_err(|e| {
            errors::input(
                "torque",
                Some(camkin::human::human(torque_v)),
                format!("torque: the mechanism is not a gear pair ({e}): a cam mechanism's forces come from forces()"),
            )
        })?;
        let file = built.lubrication.clone();
        let width = match face_width {
            Some(w) => real("face_width", w)?,
            None => file.as_ref().map(|f| f.face_width).ok_or_else(|| {
                errors::input(
                    "face_width",
                    None,
                    "face_width: the loads along the path need the teeth's face width (the file's length unit)".into(),
                )
            })?,
        };
        if !(width > 0.0
            && camkin::report::plausible_face_width(width * unit.metres(), mech.size()))
        {
            return Err(errors::input(
                "face_width",
                Some(camkin::human::human(width)),
                format!(
                    "face_width: {} {} must be positive and from 1e-3 to 1e3 times the gears' size",
                    camkin::human::human(width),
                    unit.name()
                ),
            ));
        }
        let materials = match (materials, &file) {
            (Some(m), _) => self::materials(m)?,
            (None, Some(f)) => f.materials.clone(),
            (None, None) => Materials::default(),
        };
        let lubrication =
            lubrication(oil, roughness_um, film, friction, &materials, file.as_ref())?;
        if let Some(l) = &lubrication {
            l.validate()
                .map_err(|e| errors::input("oil", None, format!("oil: {e}")))?;
        }
        let req = GearLoadRequest {
            torque: torque_v,
            face_width: width * unit.metres(),
            materials,
            lubrication,
            points,
        };
        let loads = GearLoads::new(&pair, mech.cam().speed(), &req).map_err(|e| {
            let (field, value) = match e {
                camkin::report::GearLoadError::FaceWidth(_) => ("face_width", width),
                camkin::report::GearLoadError::Points(n) => ("points", n as f64),
                _ => ("torque", torque_v),
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
        Ok(out)
    }
}
