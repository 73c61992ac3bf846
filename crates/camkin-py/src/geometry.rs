//! The general contact API: curves fixed in bodies, bodies with pose, velocity and acceleration,
//! and `contact`, which gives the pairing points, σ, the sliding rates, the normal accelerations
//! and the constraint row Φ_q q̈ = γ (paper eq. 11) — what a multibody solver needs.

use crate::errors;
use camkin::body::{BodyState, Pose};
use camkin::contact::{
    find_contact, pairing_at, refine, ContactKinematics, NormalAcceleration, Pairing,
    SearchOptions, Surface,
};
use camkin::curve::{
    Circle, ClosedSpline, Curve, Domain, Ellipse, Line, Parameterization, PointCurve,
};
use camkin::{Point2, Vec2};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::Arc;

/// A planar curve fixed in a body's frame: build one with ``Spline``, ``Circle``, ``Ellipse``,
/// ``Line`` or ``Point``. Immutable; pickles.
#[pyclass(frozen, module = "camkin", name = "Curve")]
#[derive(Debug, Clone)]
pub struct PyCurve {
    kind: &'static str,
    /// the constructor's numbers, for pickle and repr
    args: Vec<f64>,
    /// spline: chord-length parameterisation
    chord: bool,
    curve: Arc<dyn Curve>,
}

fn curve_err(field: &str, e: camkin::curve::CurveError) -> PyErr {
    errors::input(field, None, format!("{field}: {e}"))
}

fn pair(field: &str, v: &[f64]) -> PyResult<Point2> {
    match v {
        [x, y] if x.is_finite() && y.is_finite() => Ok(Point2::new(*x, *y)),
        _ => Err(errors::input(
            field,
            Some(format!("{v:?}")),
            format!("{field} = {v:?}: two finite numbers (x, y) are needed"),
        )),
    }
}

/// A size the computation takes, as in a mechanism file: from 1e-100 to 1e100.
fn size(field: &str, v: f64) -> PyResult<f64> {
    let (lo, hi) = camkin::cam::LENGTH_RANGE;
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(errors::input(
            field,
            Some(camkin::human::human(v)),
            format!(
                "{field} = {}: must be from 1e-100 to 1e100",
                camkin::human::human(v)
            ),
        ))
    }
}

impl PyCurve {
    fn make(kind: &str, args: &[f64], chord: bool) -> PyResult<Self> {
        let (kind, curve): (&'static str, Arc<dyn Curve>) = match kind {
            "spline" => {
                let pts: Vec<Point2> = args.chunks(2).map(|c| Point2::new(c[0], c[1])).collect();
                let p = if chord {
                    Parameterization::ChordLength
                } else {
                    Parameterization::Uniform
                };
                let s = ClosedSpline::with_parameterization(&pts, p)
                    .map_err(|e| curve_err("points", e))?;
                // the file's rules: points that enclose no area (collinear: the spline runs out
                // and back along a line) and a spline that crosses itself are no profile
                let size = pts.iter().map(|p| p.coords.norm()).fold(0.0, f64::max);
                let area2: f64 = (0..pts.len())
                    .map(|i| {
                        let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
                        a.x * b.y - a.y * b.x
                    })
                    .sum();
                if !(area2.abs() > 1e-9 * size * size) {
                    return Err(errors::input(
                        "points",
                        None,
                        "points: they enclose no area: are they collinear?".into(),
                    ));
                }
                if let Some((_, _, x)) = s.self_intersection() {
                    return Err(errors::input(
                        "points",
                        None,
                        format!(
                            "points: the spline through the points crosses itself near ({}, {})",
                            camkin::human::human(x.x),
                            camkin::human::human(x.y)
                        ),
                    ));
                }
                ("spline", Arc::new(s))
            }
            "circle" => ("circle", {
                size("radius", args[2])?;
                Arc::new(
                    Circle::new(Point2::new(args[0], args[1]), args[2])
                        .map_err(|e| curve_err("radius", e))?,
                )
            }),
            "ellipse" => ("ellipse", {
                size("semi_axes[0]", args[2])?;
                size("semi_axes[1]", args[3])?;
                Arc::new(
                    Ellipse::new(
                        Point2::new(args[0], args[1]),
                        args[2],
                        args[3],
                        args[4].to_radians(),
                    )
                    .map_err(|e| curve_err("semi_axes", e))?,
                )
            }),
            "line" => (
                "line",
                Arc::new(
                    Line::new(Point2::new(args[0], args[1]), Vec2::new(args[2], args[3]))
                        .map_err(|e| curve_err("direction", e))?,
                ),
            ),
            "point" => (
                "point",
                Arc::new(
                    PointCurve::new(Point2::new(args[0], args[1]))
                        .map_err(|e| curve_err("at", e))?,
                ),
            ),
            other => {
                return Err(errors::input(
                    "kind",
                    Some(other.into()),
                    format!("kind = {other:?}: not a curve kind"),
                ))
            }
        };
        Ok(Self {
            kind,
            args: args.to_vec(),
            chord,
            curve,
        })
    }

    /// A length scale of the curve in its body's frame (for tolerances), when bounded.
    fn size(&self) -> Option<f64> {
        let (a, b) = match self.curve.domain() {
            Domain::Periodic { period } => (0.0, period),
            Domain::Interval { min, max } if min.is_finite() && max.is_finite() => (min, max),
            Domain::Point => {
                let p = self.curve.position(0.0);
                return Some(p.coords.norm());
            }
            _ => return None,
        };
        Some(
            (0..64)
                .map(|k| {
                    self.curve
                        .position(a + (b - a) * k as f64 / 64.0)
                        .coords
                        .norm()
                })
                .fold(0.0, f64::max),
        )
    }
}

#[pymethods]
impl PyCurve {
    /// The kind: ``spline``, ``circle``, ``ellipse``, ``line`` or ``point``.
    #[getter]
    fn kind(&self) -> &'static str {
        self.kind
    }

    /// The parameter domain: ``("periodic", 0, period)``, ``("interval", min, max)`` or
    /// ``("point", 0, 0)``.
    #[getter]
    fn domain(&self) -> (&'static str, f64, f64) {
        match self.curve.domain() {
            Domain::Periodic { period } => ("periodic", 0.0, period),
            Domain::Interval { min, max } => ("interval", min, max),
            _ => ("point", 0.0, 0.0),
        }
    }

    /// eval(u) -> dict: position ``r`` and derivatives ``d1``, ``d2``, ``d3`` at parameter ``u``
    /// (body frame), the unit ``tangent``, left ``normal`` and signed ``curvature``.
    ///
    /// Example::
    ///
    ///     c = camkin.Circle((0.0, 0.0), 2.0)
    ///     p = c.eval(0.5)                            # at u = 0.5 (here an angle, rad)
    ///     p["r"], p["curvature"]                     # a point, and 1 / length
    fn eval<'py>(
        &self,
        py: Python<'py>,
        #[pyo3(from_py_with = crate::errors::real)] u: f64,
    ) -> PyResult<Bound<'py, PyDict>> {
        let e = self.curve.eval(u);
        let d = PyDict::new(py);
        let v = |x: f64, y: f64| PyArray1::from_vec(py, vec![x, y]);
        d.set_item("r", v(e.p.x, e.p.y))?;
        d.set_item("d1", v(e.d1.x, e.d1.y))?;
        d.set_item("d2", v(e.d2.x, e.d2.y))?;
        d.set_item("d3", v(e.d3.x, e.d3.y))?;
        let t = self.curve.tangent(u);
        let n = self.curve.normal(u);
        d.set_item("tangent", v(t.x, t.y))?;
        d.set_item("normal", v(n.x, n.y))?;
        d.set_item("curvature", self.curve.curvature(u))?;
        Ok(d)
    }

    /// breakpoints() -> list of parameters where a derivative jumps (spline nodes).
    ///
    /// Example::
    ///
    ///     s = camkin.Spline([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]])
    ///     s.breakpoints()                            # the nodes' parameters
    fn breakpoints(&self) -> Vec<f64> {
        self.curve.breakpoints()
    }

    #[allow(clippy::type_complexity)]
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, (String, Vec<f64>, bool))> {
        let f = py.import("camkin._camkin")?.getattr("_curve_from_state")?;
        Ok((f, (self.kind.to_string(), self.args.clone(), self.chord)))
    }

    fn __repr__(&self) -> String {
        match self.kind {
            "spline" => format!(
                "camkin.Spline(<{} points>{})",
                self.args.len() / 2,
                if self.chord {
                    ", parameterization='chord-length'"
                } else {
                    ""
                }
            ),
            "circle" => format!(
                "camkin.Circle(center=({}, {}), radius={})",
                self.args[0], self.args[1], self.args[2]
            ),
            "ellipse" => format!(
                "camkin.Ellipse(center=({}, {}), semi_axes=({}, {}), rotation_deg={})",
                self.args[0], self.args[1], self.args[2], self.args[3], self.args[4]
            ),
            "line" => format!(
                "camkin.Line(anchor=({}, {}), direction=({}, {}))",
                self.args[0], self.args[1], self.args[2], self.args[3]
            ),
            _ => format!("camkin.Point(at=({}, {}))", self.args[0], self.args[1]),
        }
    }
}

/// For pickle.
#[pyfunction]
pub fn _curve_from_state(kind: &str, args: Vec<f64>, chord: bool) -> PyResult<PyCurve> {
    PyCurve::make(kind, &args, chord)
}

/// Spline(points, parameterization="uniform") -> Curve: the closed C² cubic spline through the
/// nodes (an (N, 2) array, N ≥ 3), node i at u = i, or at the cumulative chord length with
/// ``parameterization="chord-length"``.
///
/// Example::
///
///     cam = camkin.Spline([[5.0, 0.0], [0.0, 4.0], [-5.0, 0.0], [0.0, -4.0]])
///     cam.kind, cam.domain
#[pyfunction]
#[pyo3(name = "Spline", signature = (points, parameterization = "uniform"))]
pub fn spline(points: Vec<Vec<f64>>, parameterization: &str) -> PyResult<PyCurve> {
    let chord = match parameterization {
        "uniform" => false,
        "chord-length" => true,
        other => {
            return Err(errors::input(
                "parameterization",
                Some(other.into()),
                format!("parameterization = {other:?}: \"uniform\" or \"chord-length\""),
            ))
        }
    };
    let mut args = Vec::with_capacity(points.len() * 2);
    for (k, p) in points.iter().enumerate() {
        let p = pair(&format!("points[{k}]"), p)?;
        args.extend([p.x, p.y]);
    }
    if points.len() > camkin::curve::MAX_POINTS {
        return Err(errors::input(
            "points",
            Some(format!("{} points", points.len())),
            format!(
                "points: {} is more than {} points",
                points.len(),
                camkin::curve::MAX_POINTS
            ),
        ));
    }
    PyCurve::make("spline", &args, chord)
}

/// Circle(center, radius) -> Curve: counter-clockwise, u the polar angle (rad) about the centre.
///
/// Example::
///
///     roller = camkin.Circle((0.0, 0.0), 1.5)     # centre and radius, one length unit
///     roller.eval(0.0)["r"]
#[pyfunction]
#[pyo3(name = "Circle")]
pub fn circle(
    #[pyo3(from_py_with = crate::errors::reals)] center: Vec<f64>,
    #[pyo3(from_py_with = crate::errors::real)] radius: f64,
) -> PyResult<PyCurve> {
    let c = pair("center", &center)?;
    PyCurve::make("circle", &[c.x, c.y, radius], false)
}

/// Ellipse(center, semi_axes, rotation_deg=0.0) -> Curve: counter-clockwise, u the eccentric
/// angle (rad); the first semi-axis turned by ``rotation_deg`` from x.
///
/// Example::
///
///     e = camkin.Ellipse((0.0, 0.0), (3.0, 2.0), rotation_deg=30.0)
///     e.eval(0.0)["curvature"]                   # 1 / length
#[pyfunction]
#[pyo3(name = "Ellipse", signature = (center, semi_axes, rotation_deg = 0.0))]
pub fn ellipse(
    #[pyo3(from_py_with = crate::errors::reals)] center: Vec<f64>,
    #[pyo3(from_py_with = crate::errors::reals)] semi_axes: Vec<f64>,
    #[pyo3(from_py_with = crate::errors::real)] rotation_deg: f64,
) -> PyResult<PyCurve> {
    let c = pair("center", &center)?;
    let s = pair("semi_axes", &semi_axes)?;
    PyCurve::make("ellipse", &[c.x, c.y, s.x, s.y, rotation_deg], false)
}

/// Line(anchor, direction) -> Curve: the straight line r(u) = anchor + u·direction/|direction|
/// (material on its left): `u` is the arc length from the anchor, in the length unit of the
/// anchor (any one unit for all the curves of a contact).
///
/// Example::
///
///     face = camkin.Line((0.0, 0.0), (0.0, 1.0))  # through the origin, along +y
///     face.domain
#[pyfunction]
#[pyo3(name = "Line")]
pub fn line(
    #[pyo3(from_py_with = crate::errors::reals)] anchor: Vec<f64>,
    #[pyo3(from_py_with = crate::errors::reals)] direction: Vec<f64>,
) -> PyResult<PyCurve> {
    let a = pair("anchor", &anchor)?;
    let d = pair("direction", &direction)?;
    PyCurve::make("line", &[a.x, a.y, d.x, d.y], false)
}

/// Point(at) -> Curve: a single point (a knife edge), in any one length unit for all the curves
/// of a contact.
///
/// Example::
///
///     knife = camkin.Point((0.0, 0.0))
///     knife.kind
#[pyfunction]
#[pyo3(name = "Point")]
pub fn point(#[pyo3(from_py_with = crate::errors::reals)] at: Vec<f64>) -> PyResult<PyCurve> {
    let p = pair("at", &at)?;
    PyCurve::make("point", &[p.x, p.y], false)
}

/// The state of a rigid body at one instant: origin ``position`` (length), ``angle`` (rad,
/// counter-clockwise), ``velocity`` of the origin (length/s), ``angular_velocity`` (rad/s),
/// ``acceleration`` of the origin (length/s²) and ``angular_acceleration`` (rad/s²). A point r
/// fixed in the body is at position + R(angle) r. Immutable; pickles.
#[pyclass(frozen, module = "camkin", name = "Body")]
#[derive(Debug, Clone)]
pub struct PyBody {
    state: BodyState,
}

#[pymethods]
impl PyBody {
    #[new]
    #[pyo3(signature = (position = vec![0.0, 0.0], angle = 0.0, velocity = vec![0.0, 0.0], angular_velocity = 0.0, acceleration = vec![0.0, 0.0], angular_acceleration = 0.0))]
    fn new(
        #[pyo3(from_py_with = crate::errors::reals)] position: Vec<f64>,
        #[pyo3(from_py_with = crate::errors::real)] angle: f64,
        #[pyo3(from_py_with = crate::errors::reals)] velocity: Vec<f64>,
        #[pyo3(from_py_with = crate::errors::real)] angular_velocity: f64,
        #[pyo3(from_py_with = crate::errors::reals)] acceleration: Vec<f64>,
        #[pyo3(from_py_with = crate::errors::real)] angular_acceleration: f64,
    ) -> PyResult<Self> {
        let p = pair("position", &position)?;
        let v = pair("velocity", &velocity)?;
        let a = pair("acceleration", &acceleration)?;
        for (field, x) in [
            ("angle", angle),
            ("angular_velocity", angular_velocity),
            ("angular_acceleration", angular_acceleration),
        ] {
            if !x.is_finite() {
                return Err(errors::input(
                    field,
                    Some(format!("{x}")),
                    format!("{field} = {x}: must be finite"),
                ));
            }
        }
        Ok(Self {
            state: BodyState {
                pose: Pose::new(p, angle),
                velocity: v.coords,
                omega: angular_velocity,
                acceleration: a.coords,
                alpha: angular_acceleration,
            },
        })
    }

    #[getter]
    fn position(&self) -> (f64, f64) {
        (self.state.pose.origin.x, self.state.pose.origin.y)
    }
    #[getter]
    fn angle(&self) -> f64 {
        self.state.pose.angle
    }
    #[getter]
    fn velocity(&self) -> (f64, f64) {
        (self.state.velocity.x, self.state.velocity.y)
    }
    #[getter]
    fn angular_velocity(&self) -> f64 {
        self.state.omega
    }
    #[getter]
    fn acceleration(&self) -> (f64, f64) {
        (self.state.acceleration.x, self.state.acceleration.y)
    }
    #[getter]
    fn angular_acceleration(&self) -> f64 {
        self.state.alpha
    }

    /// to_world(r) -> (x, y): a point fixed in the body, in the world.
    ///
    /// Example::
    ///
    ///     b = camkin.Body(position=(1.0, 0.0), angle=math.pi / 2)   # angle in rad
    ///     b.to_world((1.0, 0.0))                     # (1.0, 1.0), in the body's length unit
    fn to_world(&self, r: Vec<f64>) -> PyResult<(f64, f64)> {
        let x = self.state.pose.to_world(pair("r", &r)?);
        Ok((x.x, x.y))
    }

    #[allow(clippy::type_complexity)]
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(
        Bound<'py, PyAny>,
        ((f64, f64), f64, (f64, f64), f64, (f64, f64), f64),
    )> {
        let cls = py.import("camkin._camkin")?.getattr("Body")?;
        Ok((
            cls,
            (
                self.position(),
                self.angle(),
                self.velocity(),
                self.angular_velocity(),
                self.acceleration(),
                self.angular_acceleration(),
            ),
        ))
    }

    fn __repr__(&self) -> String {
        format!(
            "camkin.Body(position={:?}, angle={}, velocity={:?}, angular_velocity={}, acceleration={:?}, angular_acceleration={})",
            self.position(),
            self.angle(),
            self.velocity(),
            self.angular_velocity(),
            self.acceleration(),
            self.angular_acceleration()
        )
    }
}

fn terms<'py>(py: Python<'py>, n: &NormalAcceleration) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("material", n.material)?;
    d.set_item("coriolis", n.coriolis)?;
    d.set_item("relative", n.relative)?;
    Ok(d)
}

/// The raw contact: a dict, wrapped by `camkin.contact` into a `Contact`.
#[pyfunction]
#[pyo3(signature = (curve_a, body_a, curve_b, body_b, *, at = None, guess = None, length_scale = None))]
#[allow(clippy::too_many_arguments)]
pub fn _contact<'py>(
    py: Python<'py>,
    curve_a: PyRef<'py, PyCurve>,
    body_a: PyRef<'py, PyBody>,
    curve_b: PyRef<'py, PyCurve>,
    body_b: PyRef<'py, PyBody>,
    at: Option<(f64, f64)>,
    guess: Option<(f64, f64)>,
    #[pyo3(from_py_with = crate::errors::real_or_none)] length_scale: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let (ba, bb) = (body_a.state, body_b.state);
    // a parameter pair must be numbers on the curves (a closed curve's is taken modulo its
    // period; an open one's must be within its ends)
    for (name, pair) in [("at", at), ("guess", guess)] {
        let Some((ua, ub)) = pair else { continue };
        for (k, (u, curve)) in [(ua, &curve_a), (ub, &curve_b)].into_iter().enumerate() {
            let on = match curve.curve.domain() {
                camkin::curve::Domain::Interval { min, max } => u >= min && u <= max,
                _ => u.is_finite(),
            };
            if !(u.is_finite() && on) {
                let which = if k == 0 { "curve_a" } else { "curve_b" };
                return Err(errors::input(
                    name,
                    Some(format!("({ua}, {ub})")),
                    format!(
                        "{name} = ({ua}, {ub}): {u} is not a parameter of {which} (a finite number{})",
                        match curve.curve.domain() {
                            camkin::curve::Domain::Interval { min, max } => format!(" from {min} to {max}"),
                            _ => String::new(),
                        }
                    ),
                ));
            }
        }
    }
    let scale = match length_scale {
        Some(l) if l.is_finite() && l > 0.0 => l,
        Some(l) => {
            return Err(errors::input(
                "length_scale",
                Some(format!("{l}")),
                format!("length_scale = {l}: must be positive and finite"),
            ))
        }
        None => {
            let s = [curve_a.size(), curve_b.size()]
                .into_iter()
                .flatten()
                .fold(0.0, f64::max);
            let d = (ba.pose.origin - bb.pose.origin).norm();
            if s > 0.0 {
                s
            } else if d > 0.0 {
                d
            } else {
                1.0
            }
        }
    };
    let opts = SearchOptions::for_length_scale(scale);
    let (ca, cb) = (curve_a.curve.clone(), curve_b.curve.clone());
    let result = py.detach(|| -> Result<(&'static str, Pairing, Option<ContactKinematics>), camkin::contact::ContactError> {
        let sa = Surface::new(ca.as_ref(), &ba);
        let sb = Surface::new(cb.as_ref(), &bb);
        let p = match (at, guess) {
            (Some((ua, ub)), _) => pairing_at(&sa, &sb, ua, ub),
            (None, Some((ua, ub))) => refine(&sa, &sb, ua, ub, &opts)?,
            (None, None) => find_contact(&sa, &sb, &opts)?.pairing(),
        };
        let status = if p.gap.abs() <= opts.contact_tolerance {
            "touching"
        } else if p.gap < 0.0 {
            "overlapping"
        } else {
            "apart"
        };
        // at a given pairing the kinematics are what was asked for, touching or not
        let k = if status == "touching" || at.is_some() {
            Some(ContactKinematics::new(&sa, &sb, &p, opts.conformal_tolerance)?)
        } else {
            None
        };
        Ok((status, p, k))
    });
    let (status, p, k) = result.map_err(|e| errors::contact(e.to_string()))?;
    let d = PyDict::new(py);
    let v2 = |x: f64, y: f64| PyArray1::from_vec(py, vec![x, y]);
    d.set_item("status", status)?;
    d.set_item("gap", p.gap)?;
    d.set_item("u_a", p.u_a)?;
    d.set_item("u_b", p.u_b)?;
    d.set_item("point_a", v2(p.point_a.x, p.point_a.y))?;
    d.set_item("point_b", v2(p.point_b.x, p.point_b.y))?;
    d.set_item("normal", v2(p.normal.x, p.normal.y))?;
    d.set_item("iterations", p.iterations)?;
    if let Some(k) = k {
        d.set_item("sigma", k.sigma)?;
        d.set_item("kappa_a", k.kappa_a)?;
        d.set_item("kappa_b", k.kappa_b)?;
        d.set_item("metric_a", k.metric_a)?;
        d.set_item("metric_b", k.metric_b)?;
        d.set_item("sliding_rate_a", k.sliding_rate_a)?;
        d.set_item("sliding_rate_b", k.sliding_rate_b)?;
        d.set_item("param_rate_a", k.param_rate_a)?;
        d.set_item("param_rate_b", k.param_rate_b)?;
        d.set_item("normal_velocity", k.normal_velocity)?;
        let (na, nb) = (k.normal_acceleration_a(&ba), k.normal_acceleration_b(&bb));
        d.set_item("normal_acceleration_a", na.total())?;
        d.set_item("normal_acceleration_b", nb.total())?;
        d.set_item("normal_acceleration_a_terms", terms(py, &na)?)?;
        d.set_item("normal_acceleration_b_terms", terms(py, &nb)?)?;
        d.set_item("phi_q", PyArray1::from_vec(py, k.phi_q.to_vec()))?;
        d.set_item("gamma", k.gamma)?;
        d.set_item("acceleration_residual", k.acceleration_residual(&ba, &bb))?;
    }
    Ok(d)
}
