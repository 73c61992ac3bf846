//! The two model classes and how they are read: `camkin.Mechanism`, a cam-follower mechanism from
//! the mechanism-file schema (TOML text or file, or a dict; immutable, pickles as its spec), and
//! `camkin.System`, a planar multibody system from a system file (or a mechanism file as its
//! system). What each computes lives in the file of its query (`analyze.rs`, `contacts.rs`,
//! `forces.rs`, `sim.rs`, …), both classes' beside each other.

use crate::errors;
use camkin::cam::Mechanism;
use camkin::spec::{BuildOptions, Built, BuiltSystem, MechanismSpec};
use camkin::table::{AngleUnit, Per, Units};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::path::{Path, PathBuf};

/// Rows of an analysis computed per chunk (the GIL is released for the whole computation).
pub(crate) const CHUNK: usize = 65_536;
/// Most angles in one call without `large=True`: the library's memory limit at about 200
/// bytes each in the result ([`camkin::work::BYTES_LIMIT`]).
pub const MAX_ANGLES: usize = (camkin::work::BYTES_LIMIT / 200.0) as usize;

/// A cam-follower mechanism: a cam turning at constant speed (or constant angular acceleration)
/// and a follower, as a mechanism file describes them. Lengths are in the file's
/// ``length_unit``, angles in degrees, speeds in rpm; every result names its unit.
///
/// Build one with ``Mechanism.from_toml(path_or_text)``, ``Mechanism.from_dict(d)`` or
/// ``camkin.paper_cam()``. Immutable; pickles (for multiprocessing, Dask, Ray).
#[pyclass(frozen, module = "camkin", name = "Mechanism")]
#[derive(Debug, Clone)]
pub struct PyMechanism {
    pub spec: MechanismSpec,
    /// the folder a relative points-file path is read from
    pub base_dir: PathBuf,
    pub built: Built,
    /// a name for titles (the file's stem, or `paper`)
    pub name: String,
    /// the follower's travel and the profile's unfollowable stretches, found at the first sweep
    /// (a search that costs about a thousand warm steps) and kept
    pub(crate) parts: std::sync::OnceLock<SweepParts>,
    /// where each of `built.warnings` is in the mechanism's text, when it was read from text
    places: Vec<Option<(usize, usize)>>,
}

type SweepParts = (
    Result<camkin::cam::Travel, camkin::cam::CamError>,
    Vec<(f64, f64)>,
);

impl PyMechanism {
    /// Builds a spec in its own units.
    /// `large`: build a profile whose search index is over the library's limits.
    pub fn build(
        spec: MechanismSpec,
        base_dir: PathBuf,
        name: String,
        large: bool,
    ) -> PyResult<Self> {
        let built = spec
            .build(&BuildOptions {
                base_dir: base_dir.clone(),
                si: false,
                confine: false,
                limits: limits(large),
            })
            .map_err(|e| errors::spec(&e))?;
        Ok(Self::of(spec, base_dir, built, name))
    }

    /// Builds a spec read from mechanism `text` (called `file` in messages): an error is placed
    /// at its key's line and column (`InputError.line`, `.column`), as the command's.
    pub fn build_text(
        spec: MechanismSpec,
        text: &str,
        file: &str,
        base_dir: PathBuf,
        name: String,
        large: bool,
    ) -> PyResult<Self> {
        let options = BuildOptions {
            base_dir: base_dir.clone(),
            si: false,
            confine: false,
            limits: limits(large),
        };
        let (built, placed) =
            camkin::spec::text::build_placed(&spec, text, file, &options).map_err(errors::text)?;
        let mut m = Self::of(spec, base_dir, built, name);
        m.places = placed.iter().map(|w| w.at).collect();
        Ok(m)
    }

    fn of(spec: MechanismSpec, base_dir: PathBuf, built: Built, name: String) -> Self {
        Self {
            spec,
            base_dir,
            built,
            name,
            parts: std::sync::OnceLock::new(),
            places: Vec::new(),
        }
    }

    /// The mechanism built again in SI units (lengths in metres).
    pub fn built_si_any(&self) -> PyResult<Built> {
        self.spec
            .build(&BuildOptions {
                base_dir: self.base_dir.clone(),
                si: true,
                confine: false,
                // built once already, within the limits or with large=True
                limits: camkin::work::Limits::NONE,
            })
            .map_err(|e| errors::spec(&e))
    }

    /// The mechanism built again in SI units with its `[dynamics]`, for `what` (`simulate`,
    /// `forces`) that needs them.
    pub fn built_si(&self, what: &str) -> PyResult<(Built, camkin::dynamics::FollowerDynamics)> {
        let built = self.built_si_any()?;
        let params = built.dynamics.ok_or_else(|| {
            errors::input(
                "dynamics",
                None,
                format!("{what} needs a [dynamics] section (mass or inertia; spring_stiffness and spring_preload, default 0, damping, restitution, gravity optional)"),
            )
        })?;
        Ok((built, params))
    }

    pub fn mech(&self) -> &Mechanism {
        &self.built.mechanism
    }

    pub(crate) fn units(&self, per: &str, angle_unit: &str) -> PyResult<Units> {
        let per: Per = per.parse().map_err(|e: camkin::table::UnknownUnit| {
            errors::input("per", Some(per.into()), e.to_string())
        })?;
        let angle: AngleUnit = angle_unit
            .parse()
            .map_err(|e: camkin::table::UnknownUnit| {
                errors::input("angle_unit", Some(angle_unit.into()), e.to_string())
            })?;
        Ok(Units::new(self.mech(), self.built.length_unit, angle, per))
    }

    /// Refuses a sweep of `angles` over the library's limits ([`camkin::work`]): its time (a
    /// large non-convex profile searches its samples at every step) and the results held, about
    /// 200 bytes an angle.
    pub fn check_work(&self, angles: usize, large: bool) -> PyResult<()> {
        errors::refuse_large(
            &camkin::work::Work::sweep(self.mech(), angles, 1).with_bytes(angles as f64 * 200.0),
            large,
            ", or use fewer angles",
        )
    }

    /// Warns (Python's `warnings`, category `camkin.errors.CamkinWarning`).
    pub fn warn(py: Python<'_>, message: &str, field: Option<&str>) -> PyResult<()> {
        errors::warn(py, message, field, None, None)
    }
}

/// Parses TOML text into a spec (the library's reader): errors name the key path and carry
/// toml's line and column.
pub fn parse_toml(text: &str, name: &str) -> PyResult<MechanismSpec> {
    camkin::spec::text::parse_toml(text, name).map_err(errors::text)
}

/// TOML given to a `from_toml`: its text, its name for messages, the folder relative paths in it
/// are read from, and a name for titles.
pub struct TomlSource {
    pub text: String,
    pub file: String,
    pub base: PathBuf,
    pub name: String,
}

impl TomlSource {
    /// `source` as text (a str with a line break, or a line of TOML that names no file: a path
    /// may hold `=`, so `a=b/cam.toml` is a path, read or refused as one) or as a path (str or
    /// os.PathLike) read with the library's bound; `what` names the caller in messages and
    /// `default` is the title of text.
    pub fn read(
        py: Python<'_>,
        source: &Bound<'_, PyAny>,
        what: &str,
        default: &str,
    ) -> PyResult<Self> {
        let is_text = source
            .extract::<String>()
            .map(|s| {
                s.contains('\n')
                    || (s.contains('=')
                        && !Path::new(&s).exists()
                        && s.parse::<toml::Table>().is_ok())
            })
            .unwrap_or(false);
        if is_text {
            return Ok(Self {
                text: source.extract()?,
                file: "<text>".into(),
                base: PathBuf::from("."),
                name: default.into(),
            });
        }
        let path: PathBuf = py
            .import("os")?
            .call_method1("fspath", (source,))
            .and_then(|p| p.extract())
            .map_err(|_| {
                errors::input(
                    "source",
                    source.repr().ok().map(|r| r.to_string()),
                    format!("{what} takes a path (str or os.PathLike) or TOML text"),
                )
            })?;
        let (file, text) = camkin::spec::text::read_file(&path).map_err(errors::text)?;
        let base = path
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_else(|| PathBuf::from("."));
        let base = std::fs::canonicalize(&base).unwrap_or(base);
        let name = path
            .file_stem()
            .map_or_else(|| default.into(), |s| s.to_string_lossy().into_owned());
        Ok(Self {
            text,
            file,
            base,
            name,
        })
    }
}

/// Parses JSON text (a dict dumped by Python's json) into a spec; errors name the key path (the
/// JSON's own lines and columns are not the user's: the user wrote a dict).
pub fn parse_json(text: &str) -> PyResult<MechanismSpec> {
    camkin::spec::text::parse_json(text, "mechanism dict").map_err(|mut e| {
        e.at = None;
        errors::text(e)
    })
}

fn json_module(py: Python<'_>) -> PyResult<Bound<'_, PyModule>> {
    py.import("json")
}

/// The built-in paper cam's file.
pub const PAPER_TOML: &str = include_str!("../../../examples/paper.toml");

#[pymethods]
impl PyMechanism {
    /// Mechanism.from_toml(source, *, large=False) -> Mechanism
    ///
    /// A mechanism from a mechanism file (a path, ``str`` or ``os.PathLike``) or from TOML text
    /// (a ``str`` with a line break, or with ``=`` that names no file: a path may hold ``=``). A
    /// relative points-file path is read from the file's folder (the current folder for text).
    /// Bad input raises ``camkin.InputError`` naming the field, the value, and the line and
    /// column in the text (``.line``, ``.column``), as the command does. A profile whose search
    /// index would take over 1 GB or 30 s to build raises ``camkin.ResourceError`` with the
    /// estimate, unless ``large=True``.
    ///
    /// Example::
    ///
    ///     mech = camkin.Mechanism.from_toml("examples/paper.toml")
    ///     mech.length_unit, mech.speed_rpm          # "cm", 1000.0 rpm
    #[staticmethod]
    #[pyo3(signature = (source, *, large = false))]
    fn from_toml(py: Python<'_>, source: &Bound<'_, PyAny>, large: bool) -> PyResult<Self> {
        let s = TomlSource::read(py, source, "Mechanism.from_toml", "mechanism")?;
        let spec = parse_toml(&s.text, &s.file)?;
        let m = Self::build_text(spec, &s.text, &s.file, s.base, s.name, large)?;
        m.warn_spec(py)?;
        Ok(m)
    }

    /// Mechanism.from_dict(d, base_dir=".", *, large=False) -> Mechanism
    ///
    /// A mechanism from a dict with the mechanism file's schema (``length_unit``, ``cam``,
    /// ``follower``, optional ``dynamics``). ``base_dir`` resolves a relative points-file path;
    /// ``large`` as in ``from_toml``.
    ///
    /// Example::
    ///
    ///     d = camkin.paper_cam().to_dict()
    ///     d["cam"]["speed_rpm"] = 1500.0            # rpm
    ///     faster = camkin.Mechanism.from_dict(d)
    #[staticmethod]
    #[pyo3(signature = (d, base_dir = None, *, large = false))]
    fn from_dict(
        py: Python<'_>,
        d: &Bound<'_, PyAny>,
        base_dir: Option<PathBuf>,
        large: bool,
    ) -> PyResult<Self> {
        if !d.is_instance_of::<PyDict>() {
            return Err(errors::input(
                "",
                d.repr().ok().map(|r| r.to_string()),
                "Mechanism.from_dict takes a dict with the mechanism file's schema".into(),
            ));
        }
        let value = crate::dict::to_value(d, "", 0)?;
        let spec = camkin::spec::text::from_value(value, "mechanism dict").map_err(errors::text)?;
        let m = Self::build(
            spec,
            base_dir.unwrap_or_else(|| PathBuf::from(".")),
            "mechanism".into(),
            large,
        )?;
        m.warn_spec(py)?;
        Ok(m)
    }

    /// to_dict() -> dict: the mechanism's spec, as ``from_dict`` takes it.
    ///
    /// Example::
    ///
    ///     d = camkin.paper_cam().to_dict()
    ///     d["cam"]["profile"]["points"][:2]         # in the file's length unit (cm)
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let text = serde_json::to_string(&self.spec)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        json_module(py)?.call_method1("loads", (text,))
    }

    /// to_toml() -> str: the mechanism file's text.
    ///
    /// Example::
    ///
    ///     text = camkin.paper_cam().to_toml()
    ///     again = camkin.Mechanism.from_toml(text)
    fn to_toml(&self) -> PyResult<String> {
        toml::to_string(&self.spec)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))
    }

    /// For pickle: rebuilt from its spec (and the folder its points file is read from).
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, (String, String, String))> {
        let f = py
            .import("camkin._camkin")?
            .getattr("_mechanism_from_json")?;
        let text = serde_json::to_string(&self.spec)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        Ok((
            f,
            (text, self.base_dir.display().to_string(), self.name.clone()),
        ))
    }

    fn __repr__(&self) -> String {
        format!(
            "<camkin.Mechanism {:?}: {} cam at {} rpm, {} follower, lengths in {}>",
            self.name,
            self.spec.cam.profile.kind,
            camkin::human::human(self.spec.cam.speed_rpm),
            self.spec.follower.kind,
            self.built.length_unit.name()
        )
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .extract::<PyRef<'_, PyMechanism>>()
            .map(|o| o.spec == self.spec && o.base_dir == self.base_dir)
            .unwrap_or(false)
    }

    /// The length unit of every length in and out: ``"mm"``, ``"cm"``, ``"m"`` or ``"in"``.
    #[getter]
    fn length_unit(&self) -> &'static str {
        self.built.length_unit.name()
    }

    /// The cam's speed, rpm.
    #[getter]
    fn speed_rpm(&self) -> f64 {
        self.spec.cam.speed_rpm
    }

    /// The follower's kind (``"translating-flat"``, ``"oscillating-roller"``, …).
    #[getter]
    fn follower_kind(&self) -> String {
        self.spec.follower.kind.clone()
    }

    /// The follower coordinate is an arm angle (its position in degrees).
    #[getter]
    fn oscillating(&self) -> bool {
        self.mech().follower().is_oscillating()
    }

    /// The name used in titles (the file's stem).
    #[getter]
    fn name(&self) -> String {
        self.name.clone()
    }

    /// The folder a relative points-file path is read from (the file's folder; ``"."`` for
    /// text and dicts unless ``base_dir`` was given).
    #[getter]
    fn base_dir(&self) -> String {
        self.base_dir.display().to_string()
    }

    /// The file has a ``[dynamics]`` section (``simulate`` needs one).
    #[getter]
    fn has_dynamics(&self) -> bool {
        self.spec.dynamics.is_some()
    }

    /// travel() -> dict: the follower's rest (nearest the cam) and farthest positions over a
    /// revolution, their cam angles (degrees) and the stroke; positions in the file's length
    /// unit, an arm's in degrees. Keys carry the units.
    ///
    /// Example::
    ///
    ///     t = camkin.paper_cam().travel()
    ///     t                                          # lowest, highest, lift: cm
    fn travel<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let t = self
            .mech()
            .travel()
            .map_err(|e| errors::contact(format!("the follower's travel: {e}")))?;
        let u = Units::plain(self.mech(), self.built.length_unit);
        let k = u.motion_key(0);
        let d = PyDict::new(py);
        d.set_item(format!("rest_{k}"), u.coord_value(t.rest))?;
        d.set_item("rest_angle_deg", t.rest_angle.to_degrees())?;
        d.set_item(format!("peak_{k}"), u.coord_value(t.peak))?;
        d.set_item("peak_angle_deg", t.peak_angle.to_degrees())?;
        d.set_item(format!("stroke_{k}"), u.coord_value(t.stroke()))?;
        crate::columns::result(d)
    }

    /// checks(*, step_deg=0.5, pressure_limit_deg=30.0) -> dict
    ///
    /// The design checks of ``camkin synth`` at every ``step_deg`` of a revolution: ``passed``
    /// and ``failures`` (names of the failed checks), the round trip of a synthesised profile
    /// (contact method against its motion law), radii of curvature at the contact (smallest
    /// convex, sharpest concave, with their cam angles), undercut angles, the pressure angle's
    /// peak and the angles beyond the limit, the face width a flat face needs. Lengths in the
    /// file's unit (an arm's motion in rad), angles in degrees. ``verdicts`` lists each check's
    /// ``check``, ``passed``, ``lines`` (the words of ``camkin synth``'s ``checks.txt``, which
    /// ``text`` holds whole), ``angles_deg`` and ``stretches``.
    ///
    /// Example::
    ///
    ///     c = camkin.Mechanism.from_toml("examples/motion-roller.toml").checks()
    ///     print(c["text"])
    ///     c["passed"], c["failures"]
    #[pyo3(signature = (*, step_deg = 0.5, pressure_limit_deg = 30.0))]
    fn checks<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        #[pyo3(from_py_with = crate::errors::real)] pressure_limit_deg: f64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let n = revolution_steps(step_deg, "step_deg")?;
        if !(pressure_limit_deg.is_finite()
            && pressure_limit_deg > 0.0
            && pressure_limit_deg < 90.0)
        {
            return Err(errors::input(
                "pressure_limit_deg",
                Some(camkin::human::human(pressure_limit_deg)),
                format!("pressure_limit_deg = {pressure_limit_deg}: must be in (0, 90) degrees"),
            ));
        }
        self.check_work(n, false)?;
        let grid = camkin::table::AngleGrid::new(0.0, step_deg);
        let thetas: Vec<f64> = (0..n).map(|k| grid.at(k).to_radians()).collect();
        let mech = self.mech();
        let checks = py.detach(|| mech.design_checks(&thetas, pressure_limit_deg));
        let report = camkin::report::DesignReport::new(
            checks,
            self.built.length_unit.name(),
            mech.follower().is_oscillating(),
        );
        let undercut = report.checks.undercut();
        let text = serde_json::to_string(&report.checks)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        let d = json_module(py)?.call_method1("loads", (text,))?;
        let verdicts = serde_json::to_string(&report.verdicts)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        d.set_item(
            "verdicts",
            json_module(py)?.call_method1("loads", (verdicts,))?,
        )?;
        d.set_item("text", report.text())?;
        d.set_item("passed", report.passed())?;
        d.set_item("failures", PyList::new(py, report.failures())?)?;
        d.set_item("undercut", undercut)?;
        d.set_item("length_unit", self.built.length_unit.name())?;
        Ok(crate::columns::result(d.cast_into::<PyDict>()?)?.into_any())
    }

    /// profile(n=720) -> numpy.ndarray, shape (n, 2): points of the cam profile in the cam's
    /// frame (file's length unit), evenly spaced in the profile parameter.
    ///
    /// Example::
    ///
    ///     xy = camkin.paper_cam().profile(360)      # (360, 2): x, y in cm
    ///     xy.min(axis=0), xy.max(axis=0)
    #[pyo3(signature = (n = 720))]
    fn profile<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::count)] n: usize,
    ) -> PyResult<Bound<'py, numpy::PyArray2<f64>>> {
        if !(3..=10_000_000).contains(&n) {
            return Err(errors::input(
                "n",
                Some(n.to_string()),
                format!("n = {n}: must be from 3 to 10000000"),
            ));
        }
        let p = self.mech().cam().profile();
        let (a, b) = match p.domain() {
            camkin::curve::Domain::Periodic { period } => (0.0, period),
            camkin::curve::Domain::Interval { min, max } => (min, max),
            _ => (0.0, 1.0),
        };
        let rows: Vec<Vec<f64>> = (0..n)
            .map(|k| {
                let x = p.position(a + (b - a) * k as f64 / n as f64);
                vec![x.x, x.y]
            })
            .collect();
        numpy::PyArray2::from_vec2(py, &rows)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))
    }

    /// with_nodes(points) -> Mechanism: the same mechanism with the spline profile's nodes
    /// replaced (an (N, 2) array in the file's length unit); validated as a file would be
    /// (``large`` as in ``from_toml``).
    ///
    /// Example::
    ///
    ///     mech = camkin.paper_cam()
    ///     nodes = np.array(mech.to_dict()["cam"]["profile"]["points"])
    ///     bigger = mech.with_nodes(1.1 * nodes)      # cm
    #[pyo3(signature = (points, *, large = false))]
    fn with_nodes(&self, points: numpy::PyReadonlyArray2<'_, f64>, large: bool) -> PyResult<Self> {
        let spec = crate::nodes::spec_with_nodes(&self.spec, points.as_array())?;
        Self::build(spec, self.base_dir.clone(), self.name.clone(), large)
    }
}

impl PyMechanism {
    fn warn_spec(&self, py: Python<'_>) -> PyResult<()> {
        for (k, w) in self.built.warnings.iter().enumerate() {
            let field = errors::spec_warning_field(w);
            let at = self.places.get(k).copied().flatten();
            errors::warn(py, &w.to_string(), field.as_deref(), None, at)?;
        }
        Ok(())
    }
}

/// The number of steps of `step_deg` in a revolution; `step_deg` must divide it evenly enough.
pub fn revolution_steps(step_deg: f64, field: &str) -> PyResult<usize> {
    if !(step_deg.is_finite() && step_deg > 0.0 && step_deg <= 360.0) {
        return Err(errors::input(
            field,
            Some(camkin::human::human(step_deg)),
            format!("{field} = {step_deg}: must be in (0, 360] degrees"),
        ));
    }
    let n = (360.0 / step_deg).round();
    if n > 1e8 {
        return Err(errors::resource(format!(
            "{field} = {step_deg}: {n} angles per revolution is more than 100000000"
        )));
    }
    Ok(n as usize)
}

/// The work limits of building a mechanism: the library's, or none with `large=True`.
pub(crate) fn limits(large: bool) -> camkin::work::Limits {
    if large {
        camkin::work::Limits::NONE
    } else {
        camkin::work::Limits::default()
    }
}

/// For pickle: a mechanism rebuilt from its spec's JSON.
#[pyfunction]
pub fn _mechanism_from_json(text: &str, base_dir: &str, name: &str) -> PyResult<PyMechanism> {
    let spec = parse_json(text)?;
    // it was built once, within the limits or with large=True
    PyMechanism::build(spec, PathBuf::from(base_dir), name.into(), true)
}

/// For the widget: a mechanism from a mechanism file's text, its errors placed in the text
/// (``file`` names it), points files read from ``base_dir``.
#[pyfunction]
pub fn _mechanism_from_text(
    py: Python<'_>,
    text: &str,
    base_dir: &str,
    name: &str,
    file: &str,
) -> PyResult<PyMechanism> {
    let spec = parse_toml(text, file)?;
    let m = PyMechanism::build_text(
        spec,
        text,
        file,
        PathBuf::from(base_dir),
        name.into(),
        false,
    )?;
    m.warn_spec(py)?;
    Ok(m)
}

/// paper_cam() -> Mechanism: the paper's cam (section 3; ``examples/paper.toml``): a 9-node
/// closed spline cam at 1000 rpm under a translating flat-faced follower, lengths in cm.
///
/// Example::
///
///     mech = camkin.paper_cam()
///     mech.analyze(90.0)["lift_cm"]
#[pyfunction]
pub fn paper_cam() -> PyResult<PyMechanism> {
    let spec = parse_toml(PAPER_TOML, "paper.toml")?;
    PyMechanism::build(spec, PathBuf::from("."), "paper".into(), false)
}

/// `camkin.ContactError` for the first row that could not be computed, `(angle, reason)`, if any
/// (`what`: whose angle, "cam" or "driver").
pub fn raise_first(first_error: Option<(f64, String)>, what: &str) -> PyResult<()> {
    match first_error {
        Some((a, e)) => Err(errors::contact(format!(
            "at {what} angle {}°: {e}",
            camkin::human::human(a)
        ))),
        None => Ok(()),
    }
}

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
            limits: crate::model::limits(large),
        };
        let built = camkin::spec::read_model(&s.text, &s.file, &options)
            .and_then(camkin::spec::ModelFile::into_system)
            .map_err(errors::text)?;
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
