//! Studies over many designs in one call (parallel inside, GIL released; each design's sweep is
//! serial, so results do not depend on the number of threads), and the paper's study.

use crate::columns::angles_from;
use crate::errors;
use crate::model::{revolution_steps, PyMechanism};
use crate::nodes::{check_spline_kind, with_points};
use camkin::cam::Mechanism;
use camkin::geometry::deg_to_rad;
use camkin::table::Units;
use numpy::{PyArray1, PyReadonlyArray3};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

/// One design's summary over the angles.
#[derive(Debug, Clone, Copy)]
struct Summary {
    peak_acceleration: f64,
    peak_acceleration_at: f64,
    min_position: f64,
    max_position: f64,
    peak_pressure_angle: f64,
    min_convex_radius: f64,
    failed: usize,
}

/// The summary of one mechanism: the same sweep as `analyze` (warm-started, degrees reduced as
/// there), so its numbers are the maxima of `analyze`'s columns to the bit.
fn summarize_one(mech: &Mechanism, u: &Units, angles: &[f64]) -> Summary {
    let mut s = Summary {
        peak_acceleration: f64::NAN,
        peak_acceleration_at: f64::NAN,
        min_position: f64::INFINITY,
        max_position: f64::NEG_INFINITY,
        peak_pressure_angle: 0.0,
        min_convex_radius: f64::INFINITY,
        failed: 0,
    };
    let mut sweep = mech.sweep();
    let mut peak = -1.0f64;
    for &a in angles {
        match sweep.step(deg_to_rad(a)) {
            Ok(r) => {
                let m = u.motion(r.position, r.velocity, r.acceleration, r.jerk);
                let (q, acc) = (m[0].unwrap_or(f64::NAN), m[2].unwrap_or(f64::NAN));
                if acc.abs() > peak {
                    peak = acc.abs();
                    s.peak_acceleration = acc;
                    s.peak_acceleration_at = a;
                }
                s.min_position = s.min_position.min(q);
                s.max_position = s.max_position.max(q);
                let pa = r.pressure_angle().to_degrees();
                if pa.abs() > s.peak_pressure_angle.abs() {
                    s.peak_pressure_angle = pa;
                }
                if r.radius_of_curvature > 0.0 {
                    s.min_convex_radius = s.min_convex_radius.min(r.radius_of_curvature);
                }
            }
            Err(_) => s.failed += 1,
        }
    }
    s
}

/// A design that could not be built or analysed: NaN everywhere, and why.
fn failed_summary(angles: usize) -> Summary {
    Summary {
        peak_acceleration: f64::NAN,
        peak_acceleration_at: f64::NAN,
        min_position: f64::NAN,
        max_position: f64::NAN,
        peak_pressure_angle: f64::NAN,
        min_convex_radius: f64::NAN,
        failed: angles,
    }
}

/// `f` over `items` in parallel on `pool`, in batches of four per thread, between which a
/// pending Ctrl-C is raised (`KeyboardInterrupt`): the caller holds no GIL meanwhile.
fn par_batches<T: Sync, R: Send>(
    pool: &rayon::ThreadPool,
    items: &[T],
    f: impl Fn(&T) -> R + Sync + Send,
) -> PyResult<Vec<R>> {
    let batch = 4 * pool.current_num_threads().max(1);
    let mut out = Vec::with_capacity(items.len());
    for b in items.chunks(batch) {
        errors::interrupted()?;
        out.extend(pool.install(|| b.par_iter().map(&f).collect::<Vec<_>>()));
    }
    Ok(out)
}

fn pool(threads: Option<usize>) -> PyResult<rayon::ThreadPool> {
    let n = match threads {
        Some(0) => {
            return Err(errors::input(
                "threads",
                Some("0".into()),
                "threads = 0: at least one thread is needed".into(),
            ))
        }
        Some(n) => n,
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .build()
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))
}

fn study_angles(py: Python<'_>, angles_deg: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<f64>> {
    match angles_deg {
        Some(a) => Ok(angles_from(py, a, "angles_deg")?.0),
        None => Ok((0..360).map(f64::from).collect()),
    }
}

fn check_study(base: &Mechanism, designs: usize, angles: usize, large: bool) -> PyResult<()> {
    let work = camkin::work::Work::new(
        format!("{designs} designs × {angles} angles"),
        base.sweep_seconds_estimate(angles) * designs as f64,
    );
    errors::refuse_large(
        &work,
        large,
        ", or split it (for example over Dask workers)",
    )
}

/// The summaries as a dict of arrays, keys with units.
fn into_dict<'py>(
    py: Python<'py>,
    u: &Units,
    rows: Vec<(Summary, Option<String>)>,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let col = |f: fn(&Summary) -> f64| rows.iter().map(|(s, _)| f(s)).collect::<Vec<f64>>();
    let (k0, k2, l) = (u.motion_key(0), u.motion_key(2), u.len());
    d.set_item(
        format!("peak_acceleration_{k2}"),
        PyArray1::from_vec(py, col(|s| s.peak_acceleration)),
    )?;
    d.set_item(
        "peak_acceleration_angle_deg",
        PyArray1::from_vec(py, col(|s| s.peak_acceleration_at)),
    )?;
    d.set_item(
        format!("min_position_{k0}"),
        PyArray1::from_vec(py, col(|s| s.min_position)),
    )?;
    d.set_item(
        format!("max_position_{k0}"),
        PyArray1::from_vec(py, col(|s| s.max_position)),
    )?;
    d.set_item(
        "peak_pressure_angle_deg",
        PyArray1::from_vec(py, col(|s| s.peak_pressure_angle)),
    )?;
    d.set_item(
        format!("min_convex_radius_{l}"),
        PyArray1::from_vec(py, col(|s| s.min_convex_radius)),
    )?;
    d.set_item(
        "failed_angles",
        PyArray1::from_vec(
            py,
            rows.iter()
                .map(|(s, _)| s.failed as i64)
                .collect::<Vec<i64>>(),
        ),
    )?;
    let errs: Vec<Option<String>> = rows.into_iter().map(|(_, e)| e).collect();
    let np = py.import("numpy")?;
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", np.getattr("object_")?)?;
    d.set_item(
        "error",
        np.call_method(
            "array",
            (pyo3::types::PyList::new(py, errs)?,),
            Some(&kwargs),
        )?,
    )?;
    crate::columns::result(d)
}

/// spline_variants(base, nodes, *, angles_deg=None, threads=None, large=False) -> dict
///
/// Many variants of a spline cam at once: ``nodes`` is a (D, N, 2) array, one set of N nodes
/// (file's length unit) per design, each replacing the base's profile nodes. Every design is
/// analysed at ``angles_deg`` (default 0°, 1°, …, 359°) in parallel on ``threads`` threads
/// (default: all cores), with the GIL released; a design's numbers do not depend on the thread
/// count. Returns arrays of length D: peak acceleration (signed, the largest magnitude) and its
/// angle, the smallest and largest position, the peak pressure angle, the smallest convex radius
/// of curvature, the angles that failed, and ``error`` (why a design could not be built, or None).
///
/// Example::
///
///     base = camkin.paper_cam()
///     nodes = np.array(base.to_dict()["cam"]["profile"]["points"])[None] * [[[1.0, 1.0]], [[1.01, 1.0]]]
///     camkin.spline_variants(base, nodes)["peak_acceleration_cm_s2"]
#[pyfunction]
#[pyo3(signature = (base, nodes, *, angles_deg = None, threads = None, large = false))]
pub fn spline_variants<'py>(
    py: Python<'py>,
    base: PyRef<'py, PyMechanism>,
    nodes: PyReadonlyArray3<'py, f64>,
    angles_deg: Option<&Bound<'py, PyAny>>,
    #[pyo3(from_py_with = crate::errors::count_or_none)] threads: Option<usize>,
    large: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let angles = study_angles(py, angles_deg)?;
    let nodes = nodes.as_array();
    let shape = nodes.shape().to_vec();
    if shape[2] != 2 {
        return Err(errors::input(
            "nodes",
            Some(format!("an array of shape {shape:?}")),
            format!("nodes: a (D, N, 2) array is needed, not one of shape {shape:?}"),
        ));
    }
    // checked here, under the GIL, so that a bad kind is one error rather than D of them
    check_spline_kind(&base.spec)?;
    check_study(base.mech(), shape[0], angles.len(), large)?;
    let u = Units::plain(base.mech(), base.built.length_unit);
    let pool = pool(threads)?;
    let (spec, dir) = (&base.spec, &base.base_dir);
    let owned: Vec<Vec<[f64; 2]>> = nodes
        .outer_iter()
        .map(|d| d.rows().into_iter().map(|r| [r[0], r[1]]).collect())
        .collect();
    let rows = py.detach(|| {
        par_batches(&pool, &owned, |pts| {
            let s = with_points(spec, pts.clone());
            let opts = camkin::spec::BuildOptions {
                base_dir: dir.clone(),
                si: false,
                confine: false,
                limits: crate::model::limits(large),
            };
            match s.build(&opts) {
                Ok(b) => (summarize_one(&b.mechanism, &u, &angles), None),
                Err(e) => (failed_summary(angles.len()), Some(e.to_string())),
            }
        })
    })?;
    into_dict(py, &u, rows)
}

/// summarize(mechanisms, *, angles_deg=None, threads=None, large=False) -> dict
///
/// The same summaries as ``spline_variants`` for a list of mechanisms (base radius × roller
/// radius × law studies built with ``Mechanism.from_dict``), in parallel with the GIL released.
/// The mechanisms must share their length unit and follower motion (translating or arm).
///
/// Example::
///
///     mechs = [camkin.paper_cam(), camkin.Mechanism.from_toml("examples/paper-revised.toml")]
///     camkin.summarize(mechs)["peak_acceleration_cm_s2"]
#[pyfunction]
#[pyo3(signature = (mechanisms, *, angles_deg = None, threads = None, large = false))]
pub fn summarize<'py>(
    py: Python<'py>,
    mechanisms: Vec<PyRef<'py, PyMechanism>>,
    angles_deg: Option<&Bound<'py, PyAny>>,
    #[pyo3(from_py_with = crate::errors::count_or_none)] threads: Option<usize>,
    large: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let angles = study_angles(py, angles_deg)?;
    let mechs: Vec<Mechanism> = mechanisms.iter().map(|m| m.mech().clone()).collect();
    let Some(first) = mechanisms.first() else {
        return Err(errors::input(
            "mechanisms",
            Some("[]".into()),
            "mechanisms: at least one mechanism is needed".into(),
        ));
    };
    for (k, m) in mechanisms.iter().enumerate() {
        if m.built.length_unit != first.built.length_unit
            || m.mech().follower().is_oscillating() != first.mech().follower().is_oscillating()
        {
            return Err(errors::input(
                &format!("mechanisms[{k}]"),
                Some(m.__repr_string()),
                format!("mechanisms[{k}]: its length unit or follower motion differs from mechanisms[0]'s, so their results would not share units"),
            ));
        }
    }
    let u = Units::plain(first.mech(), first.built.length_unit);
    let slowest = mechs
        .iter()
        .map(|m| m.sweep_seconds_estimate(angles.len()))
        .fold(0.0, f64::max);
    let work = camkin::work::Work::new(
        format!("{} designs × {} angles", mechs.len(), angles.len()),
        slowest * mechs.len() as f64,
    );
    errors::refuse_large(
        &work,
        large,
        ", or split it (for example over Dask workers)",
    )?;
    let pool = pool(threads)?;
    let rows = py.detach(|| {
        par_batches(&pool, &mechs, |m| {
            (summarize_one(m, &Units::plain(m, u.length), &angles), None)
        })
    })?;
    into_dict(py, &u, rows)
}

impl PyMechanism {
    fn __repr_string(&self) -> String {
        format!(
            "{} {} in {}",
            self.spec.cam.profile.kind,
            self.spec.follower.kind,
            self.built.length_unit.name()
        )
    }
}

#[pymethods]
impl PyMechanism {
    /// compare(nodes=(100, 1000, 10000), *, step_deg=0.05) -> dict
    ///
    /// The paper's study (section 3): the exact acceleration by the contact method against the
    /// acceleration of a periodic cubic spline through N sampled positions per revolution, on a
    /// grid of ``step_deg``. Returns ``angle_deg``, the exact acceleration (key with its unit),
    /// and for each N the interpolated acceleration, the relative error |a_N − a| / max|a|, and
    /// its largest and mean values.
    ///
    /// Example::
    ///
    ///     s = camkin.paper_cam().compare([100, 1000], step_deg=1.0)
    ///     s["max_rel_error"]
    #[pyo3(signature = (nodes = vec![100, 1000, 10000], *, step_deg = 0.05, large = false))]
    fn compare<'py>(
        &self,
        py: Python<'py>,
        nodes: Vec<usize>,
        #[pyo3(from_py_with = crate::errors::real)] step_deg: f64,
        large: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let n = revolution_steps(step_deg, "step_deg")?;
        if let Some((k, &bad)) = nodes
            .iter()
            .enumerate()
            .find(|(_, &m)| !(4..=10_000_000).contains(&m))
        {
            return Err(errors::input(
                &format!("nodes[{k}]"),
                Some(bad.to_string()),
                format!("nodes[{k}] = {bad}: must be from 4 to 10000000"),
            ));
        }
        self.check_work(n * (1 + nodes.len()), large)?;
        let u = Units::plain(self.mech(), self.built.length_unit);
        let mech = self.mech();
        let angles = camkin::table::AngleGrid::new(0.0, step_deg);
        let grid: Vec<f64> = (0..n).map(|k| angles.at(k)).collect();
        let thetas: Vec<f64> = grid.iter().map(|d| d.to_radians()).collect();
        // the study compares a motion that repeats (a gear pair's does not): bad input for it
        camkin::interp::Interpolated::check_repeats(mech)
            .map_err(|e| errors::input("mechanism", None, e.to_string()))?;
        let out = py.detach(|| -> Result<_, String> {
            let exact: Vec<f64> = mech
                .analyze_all(&thetas)
                .into_iter()
                .zip(&grid)
                .map(|(r, a)| {
                    r.map(|s| s.acceleration)
                        .map_err(|e| format!("contact method at {a}°: {e}"))
                })
                .collect::<Result<_, _>>()?;
            let mut runs = Vec::new();
            for &m in &nodes {
                let it = camkin::interp::Interpolated::new(mech, m).map_err(|e| e.to_string())?;
                let acc: Vec<f64> = thetas.iter().map(|&th| it.acceleration(th)).collect();
                let rel = camkin::interp::relative_errors(&exact, &acc);
                let (max, mean) = camkin::interp::max_and_mean(&rel);
                runs.push((m, acc, rel, max, mean));
            }
            Ok((exact, runs))
        });
        let (exact, runs) = out.map_err(errors::contact)?;
        let conv = |a: f64| u.motion(0.0, 0.0, a, None)[2].unwrap_or(f64::NAN);
        let key = u.motion_key(2);
        let d = PyDict::new(py);
        d.set_item("angle_deg", PyArray1::from_vec(py, grid))?;
        d.set_item(
            format!("contact_method_{key}"),
            PyArray1::from_vec(py, exact.iter().map(|&a| conv(a)).collect::<Vec<_>>()),
        )?;
        let (interp, rel, maxes, means) = (
            PyDict::new(py),
            PyDict::new(py),
            PyDict::new(py),
            PyDict::new(py),
        );
        for (m, acc, r, max, mean) in runs {
            interp.set_item(
                m,
                PyArray1::from_vec(py, acc.iter().map(|&a| conv(a)).collect::<Vec<_>>()),
            )?;
            rel.set_item(m, PyArray1::from_vec(py, r))?;
            maxes.set_item(m, max)?;
            means.set_item(m, mean)?;
        }
        d.set_item(format!("interpolated_{key}"), interp)?;
        d.set_item("rel_error", rel)?;
        d.set_item("max_rel_error", maxes)?;
        d.set_item("mean_rel_error", means)?;
        crate::columns::result(d)
    }
}
