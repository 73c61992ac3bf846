//! A cam's manufacturing output and a measured profile's deviation from Python: the library's
//! [`camkin::report::ShopReport`] and [`camkin::report::DeviationReport`], with the columns of
//! `camkin profile`'s and `camkin deviation`'s files (the same numbers, bit for bit).

use crate::errors;
use crate::model::{revolution_steps, PyMechanism};
use camkin::report::{
    DeviationError, DeviationReport, ShopError, ShopField, ShopReport, ShopRequest,
};
use camkin::Point2;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

fn array<'py>(py: Python<'py>, v: Vec<f64>) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_vec(py, v)
}

/// `columns` (name, values) as a dict of arrays.
fn table<'py>(py: Python<'py>, columns: Vec<(String, Vec<f64>)>) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (name, v) in columns {
        d.set_item(name, array(py, v))?;
    }
    Ok(d)
}

#[pymethods]
impl PyMechanism {
    /// shop(*, step_deg=1.0, tool_radius=None, tolerance=None, dxf_path=None) -> dict
    ///
    /// The cam's manufacturing output, as ``camkin profile`` writes it (the same numbers):
    ///
    /// - ``polar``: ``polar_angle_deg``, ``radius_<unit>``, ``x_<unit>``, ``y_<unit>`` every
    ///   ``step_deg`` degrees of the cam frame (``polar.csv``), or None with the reason in
    ///   ``polar_missing`` (a profile a ray from the axis crosses twice);
    /// - ``pitch`` (a roller follower) and ``cutter`` (``tool_radius`` given, the tool's centre):
    ///   ``polar_angle_deg``, ``x_<unit>``, ``y_<unit>``, ``profile_x_<unit>``,
    ///   ``profile_y_<unit>`` (``pitch.csv``, ``cutter.csv``);
    /// - ``cutter_check``: the tool's ``radius``, the ``sharpest_concave`` radius of curvature
    ///   (negative; -inf when convex everywhere), ``undercut`` and, when it is, the polar angles
    ///   ``undercut_from_deg`` to ``undercut_to_deg`` where the tool cannot cut;
    /// - ``dxf``: the DXF's text (``profile.dxf``: arcs within ``tolerance``, default 1e-6 of
    ///   the cam's size, its units set, layers declared, the centre mark and 0° line on
    ///   ``CENTRE``), with ``dxf_arcs``, ``dxf_layers`` and ``dxf_largest_deviation``.
    ///
    /// Lengths in the file's unit. ``dxf_path`` also writes the DXF there (a new file; an
    /// existing one is refused, never replaced).
    ///
    /// Example::
    ///
    ///     s = camkin.Mechanism.from_toml("examples/motion-roller.toml").shop(tool_radius=10.0)
    ///     s["polar"]["radius_mm"].max(), s["cutter_check"]["undercut"]   # mm, bool
    ///     s["polar"].to_pandas().head()
    #[pyo3(signature = (*, step_deg = 1.0, tool_radius = None, tolerance = None, dxf_path = None))]
    fn shop<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        #[pyo3(from_py_with = crate::errors::real_or_none)] tool_radius: Option<f64>,
        #[pyo3(from_py_with = crate::errors::real_or_none)] tolerance: Option<f64>,
        dxf_path: Option<PathBuf>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let n = revolution_steps(step_deg, "step_deg")?;
        self.check_work(n, false)?;
        let unit = self.built.length_unit;
        let l = unit.name();
        let mech = self.mech();
        let req = ShopRequest {
            step_deg,
            tool_radius,
            tolerance,
        };
        let shop = py
            .detach(|| ShopReport::new(mech, unit, &req))
            .map_err(|e| match &e {
                ShopError::Invalid { field, value, .. } => {
                    let name = match field {
                        ShopField::ToolRadius => "tool_radius",
                        ShopField::Tolerance => "tolerance",
                        _ => "step_deg",
                    };
                    errors::input(name, Some(value.clone()), format!("{name} = {e}"))
                }
                _ => errors::contact(e.to_string()),
            })?;
        let d = PyDict::new(py);
        match &shop.polar {
            Ok(p) => {
                let col = |f: &dyn Fn(&[f64; 2]) -> f64| p.points.iter().map(f).collect::<Vec<_>>();
                d.set_item(
                    "polar",
                    table(
                        py,
                        vec![
                            ("polar_angle_deg".into(), p.angle_deg.clone()),
                            (format!("radius_{l}"), col(&|q| q[0].hypot(q[1]))),
                            (format!("x_{l}"), col(&|q| q[0])),
                            (format!("y_{l}"), col(&|q| q[1])),
                        ],
                    )?,
                )?;
                d.set_item("polar_missing", py.None())?;
                for path in &shop.offsets {
                    let c = |j: usize| path.points.iter().map(|q| q[j]).collect::<Vec<_>>();
                    d.set_item(
                        path.name,
                        table(
                            py,
                            vec![
                                ("polar_angle_deg".into(), p.angle_deg.clone()),
                                (format!("x_{l}"), c(0)),
                                (format!("y_{l}"), c(1)),
                                (format!("profile_x_{l}"), col(&|q| q[0])),
                                (format!("profile_y_{l}"), col(&|q| q[1])),
                            ],
                        )?,
                    )?;
                }
            }
            Err(why) => {
                d.set_item("polar", py.None())?;
                d.set_item("polar_missing", why)?;
            }
        }
        for name in ["pitch", "cutter"] {
            if !d.contains(name)? {
                d.set_item(name, py.None())?;
            }
        }
        match &shop.cutter {
            Some(c) => {
                let k = PyDict::new(py);
                k.set_item(format!("radius_{l}"), c.radius)?;
                k.set_item(format!("sharpest_concave_{l}"), c.sharpest_concave)?;
                k.set_item("undercut", c.undercut_deg.is_some())?;
                k.set_item("undercut_from_deg", c.undercut_deg.map(|u| u.0))?;
                k.set_item("undercut_to_deg", c.undercut_deg.map(|u| u.1))?;
                d.set_item("cutter_check", k)?;
            }
            None => d.set_item("cutter_check", py.None())?,
        }
        d.set_item("dxf", &shop.dxf.text)?;
        d.set_item("dxf_arcs", shop.dxf.arcs)?;
        d.set_item("dxf_layers", shop.dxf.layers.clone())?;
        d.set_item(
            format!("dxf_largest_deviation_{l}"),
            shop.dxf.largest_deviation,
        )?;
        if let Some(path) = dxf_path {
            write_new(&path, shop.dxf.text.as_bytes(), "dxf_path")?;
        }
        crate::columns::result(d)
    }

    /// deviation(measured, *, tolerance=None, step_deg=1.0) -> dict
    ///
    /// A profile measured on a coordinate measuring machine against this design, as ``camkin
    /// deviation`` computes it (the same numbers). ``measured``: an (N, 2) array of x, y in the
    /// cam frame (the file's length unit) or the path of such a CSV. The points are smoothed by
    /// a Fourier series of the radius with the fewest harmonics whose RMS residual is within
    /// ``tolerance`` (the measurement's noise; default 1e-4 of the cam's size).
    ///
    /// Returns ``radius`` (``radius.csv``'s columns: ``polar_angle_deg``,
    /// ``measured_radius_<unit>``, ``design_radius_<unit>``, ``deviation_<unit>``,
    /// ``smoothed_radius_<unit>``), ``motion`` (``motion.csv``'s: ``angle_deg`` and the design's,
    /// the measured profile's and the deviation's lift, velocity and acceleration every
    /// ``step_deg``), ``harmonics``, ``rms_residual``, ``tolerance``, ``radius_largest`` and its
    /// ``radius_largest_at_deg``, ``radius_rms``, and per motion ``<name>_largest`` and
    /// ``<name>_largest_at_deg`` (lengths in the file's unit, the motion per second).
    ///
    /// Example::
    ///
    ///     mech = camkin.Mechanism.from_toml("examples/eccentric-roller.toml")
    ///     d = mech.deviation("examples/measured-eccentric.csv", tolerance=0.0006)   # cm
    ///     d["radius_largest"], d["acceleration_largest"]                           # cm, cm/s²
    #[pyo3(signature = (measured, *, tolerance = None, step_deg = 1.0))]
    fn deviation<'py>(
        &self,
        py: Python<'py>,
        measured: &Bound<'py, PyAny>,
        #[pyo3(from_py_with = crate::errors::real_or_none)] tolerance: Option<f64>,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
    ) -> PyResult<Bound<'py, PyDict>> {
        let n = revolution_steps(step_deg, "step_deg")?;
        let pts = measured_points(py, measured)?;
        self.check_work(2 * n, false)?;
        let unit = self.built.length_unit;
        let l = unit.name();
        let opts = camkin::spec::BuildOptions {
            base_dir: self.base_dir.clone(),
            si: false,
            confine: false,
            limits: camkin::work::Limits::default(),
        };
        let (spec, mech) = (&self.spec, self.mech());
        let r = py
            .detach(|| DeviationReport::new(spec, mech, unit, &opts, &pts, tolerance, step_deg))
            .map_err(|e| match &e {
                DeviationError::Tolerance { value, .. } => {
                    errors::input("tolerance", Some(value.clone()), format!("tolerance = {e}"))
                }
                DeviationError::Fit(_) | DeviationError::Polar(_) | DeviationError::Size { .. } => {
                    errors::input("measured", None, format!("measured: {e}"))
                }
                _ => errors::contact(e.to_string()),
            })?;
        let d = PyDict::new(py);
        let rd = &r.radius;
        d.set_item(
            "radius",
            table(
                py,
                vec![
                    ("polar_angle_deg".into(), rd.polar_angle_deg.clone()),
                    (format!("measured_radius_{l}"), rd.measured.clone()),
                    (format!("design_radius_{l}"), rd.design.clone()),
                    (format!("deviation_{l}"), rd.deviation.clone()),
                    (format!("smoothed_radius_{l}"), rd.smoothed.clone()),
                ],
            )?,
        )?;
        let mut cols = vec![("angle_deg".to_string(), r.angle_deg.clone())];
        for mo in &r.motion {
            cols.push((format!("design_{}_{}", mo.name, mo.key), mo.design.clone()));
            cols.push((
                format!("measured_{}_{}", mo.name, mo.key),
                mo.measured.clone(),
            ));
            cols.push((
                format!("deviation_{}_{}", mo.name, mo.key),
                mo.design
                    .iter()
                    .zip(&mo.measured)
                    .map(|(a, b)| b - a)
                    .collect(),
            ));
            d.set_item(format!("{}_largest", mo.name), mo.largest.0)?;
            d.set_item(format!("{}_largest_at_deg", mo.name), mo.largest.1)?;
        }
        d.set_item("motion", table(py, cols)?)?;
        d.set_item("harmonics", r.harmonics)?;
        d.set_item("rms_residual", r.rms_residual)?;
        d.set_item("tolerance", r.tolerance)?;
        d.set_item("radius_largest", r.radius_largest.0)?;
        d.set_item("radius_largest_at_deg", r.radius_largest.1)?;
        d.set_item("radius_rms", r.radius_rms)?;
        d.set_item("length_unit", l)?;
        crate::columns::result(d)
    }
}

/// The measured points: an (N, 2) array (None and non-numbers refused), or a CSV's path.
fn measured_points(py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<Vec<Point2>> {
    let is_path =
        x.extract::<String>().is_ok() || x.is_instance(&py.import("os")?.getattr("PathLike")?)?;
    if is_path {
        let path: PathBuf = py.import("os")?.call_method1("fspath", (x,))?.extract()?;
        let (pts, _) = camkin::curve::read_points_file(&path).map_err(|e| {
            errors::input(
                "measured",
                Some(path.display().to_string()),
                format!("measured: {}: {e}", path.display()),
            )
        })?;
        return Ok(pts);
    }
    let bad = |why: String| errors::input("measured", x.repr().ok().map(|r| r.to_string()), why);
    let np = py.import("numpy")?;
    let arr = np
        .call_method1("asarray", (x,))
        .map_err(|e| bad(format!("measured: not an array of points: {e}")))?;
    let kind: String = arr.getattr("dtype")?.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "f" | "i" | "u") {
        return Err(bad(format!(
            "measured: an (N, 2) array of real numbers (x, y), not one of dtype kind {kind:?}"
        )));
    }
    let arr = arr.call_method1("astype", ("float64",))?;
    let shape: Vec<usize> = arr.getattr("shape")?.extract()?;
    if shape.len() != 2 || shape[1] != 2 {
        return Err(bad(format!(
            "measured: an (N, 2) array of x, y, not of shape {shape:?}"
        )));
    }
    let flat: Vec<f64> = arr
        .call_method0("ravel")?
        .call_method0("tolist")?
        .extract()?;
    if let Some(k) = flat.iter().position(|v| !v.is_finite()) {
        return Err(errors::input(
            &format!("measured[{}]", k / 2),
            Some(flat[k].to_string()),
            format!("measured[{}]: {} is not a finite number", k / 2, flat[k]),
        ));
    }
    Ok(flat.chunks(2).map(|c| Point2::new(c[0], c[1])).collect())
}

/// Writes `bytes` to a new file at `path` (written beside it, then moved into place: no
/// half-written file); an existing file is refused, never replaced.
fn write_new(path: &std::path::Path, bytes: &[u8], field: &str) -> PyResult<()> {
    let shown = path.display().to_string();
    if path.exists() {
        return Err(errors::input(
            field,
            Some(shown.clone()),
            format!("{field} = {shown}: the file exists; camkin writes only new files (remove it first)"),
        ));
    }
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(std::path::Path::new("."));
    let tmp = dir.join(format!(
        ".{}.camkin-{}.tmp",
        path.file_name()
            .map_or_else(|| "out".into(), |n| n.to_string_lossy()),
        std::process::id()
    ));
    let io = |e: std::io::Error| {
        let _ = std::fs::remove_file(&tmp);
        pyo3::exceptions::PyOSError::new_err(format!("{field} = {shown}: {e}"))
    };
    std::fs::write(&tmp, bytes).map_err(io)?;
    // hard_link refuses an existing target, so a file made meanwhile is not replaced either
    std::fs::hard_link(&tmp, path).map_err(io)?;
    let _ = std::fs::remove_file(&tmp);
    Ok(())
}
