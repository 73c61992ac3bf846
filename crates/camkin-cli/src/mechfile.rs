//! Mechanism files (TOML): the schema of the README, validated and turned into a
//! [`camkin::cam::Mechanism`].
//!
//! Lengths are in any one unit; angles in degrees. Every error names the file, the line and
//! column, the field and the offending value: unknown fields, fields that do not belong to the
//! chosen `kind`, missing fields, wrong types, non-finite or out-of-range numbers, a zero
//! direction, too few or repeated points, a self-intersecting or cusped profile, a follower that
//! cannot reach the cam.

use camkin::cam::synthesis::synthesize;
use camkin::cam::{Cam, CamError, Follower, Mechanism, Sense};
use camkin::curve::{Circle, ClosedSpline, Curve, CurveError, Ellipse, Parameterization};
use camkin::dynamics::FollowerDynamics;
use camkin::motion::{Law, Program, Segment};
use camkin::{Point2, Vec2};
use serde::Deserialize;
use std::ops::Range;
use std::path::Path;
use std::sync::Arc;
use toml::Spanned;

/// Largest mechanism file read, bytes.
pub const MAX_FILE_BYTES: u64 = 8 << 20;
/// Most nodal points of a spline profile (inline or from a points file).
pub const MAX_POINTS: usize = camkin::curve::MAX_POINTS;

/// Bad input, with where it is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InputError {
    /// the message, starting with `file:line:column:` when the place is known
    pub message: String,
}

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for InputError {}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct FileSpec {
    length_unit: Option<Spanned<String>>,
    cam: Spanned<CamSpec>,
    follower: Spanned<FollowerTable>,
    dynamics: Option<Spanned<DynamicsTable>>,
}

/// `[dynamics]`, SI units.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct DynamicsTable {
    mass: Option<Spanned<f64>>,
    inertia: Option<Spanned<f64>>,
    spring_stiffness: Spanned<f64>,
    spring_preload: Spanned<f64>,
    damping: Option<Spanned<f64>>,
    restitution: Option<Spanned<f64>>,
    gravity: Option<Spanned<[f64; 2]>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct CamSpec {
    speed_rpm: Spanned<f64>,
    direction: Option<Spanned<SenseSpec>>,
    pivot: Option<Spanned<[f64; 2]>>,
    angular_acceleration_deg_s2: Option<Spanned<f64>>,
    profile: Spanned<ProfileTable>,
}

#[derive(Debug, Deserialize, Clone, Copy)]
#[serde(rename_all = "lowercase")]
enum SenseSpec {
    Ccw,
    Cw,
}

impl From<SenseSpec> for Sense {
    fn from(s: SenseSpec) -> Self {
        match s {
            SenseSpec::Ccw => Sense::Ccw,
            SenseSpec::Cw => Sense::Cw,
        }
    }
}

#[derive(Debug, Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum ParamSpec {
    Uniform,
    ChordLength,
}

impl From<ParamSpec> for Parameterization {
    fn from(p: ParamSpec) -> Self {
        match p {
            ParamSpec::Uniform => Parameterization::Uniform,
            ParamSpec::ChordLength => Parameterization::ChordLength,
        }
    }
}

/// `[cam.profile]`: every field of every kind; the kind decides which belong.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ProfileTable {
    kind: Spanned<String>,
    points: Option<Spanned<Vec<Spanned<[f64; 2]>>>>,
    parameterization: Option<Spanned<ParamSpec>>,
    center: Option<Spanned<[f64; 2]>>,
    radius: Option<Spanned<f64>>,
    semi_axes: Option<Spanned<[f64; 2]>>,
    rotation_deg: Option<Spanned<f64>>,
    path: Option<Spanned<String>>,
    base_radius: Option<Spanned<f64>>,
    segments: Option<Spanned<Vec<Spanned<SegmentSpec>>>>,
}

/// One segment of a `kind = "motion"` profile.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SegmentSpec {
    law: Spanned<String>,
    #[serde(default)]
    rise: Option<Spanned<f64>>,
    degrees: Spanned<f64>,
}

/// `[follower]`: every field of every kind; the kind decides which belong.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct FollowerTable {
    kind: Spanned<String>,
    direction: Option<Spanned<[f64; 2]>>,
    offset: Option<Spanned<f64>>,
    roller_radius: Option<Spanned<f64>>,
    pivot: Option<Spanned<[f64; 2]>>,
    arm_length: Option<Spanned<f64>>,
    closing: Option<Spanned<SenseSpec>>,
    initial_angle_deg: Option<Spanned<f64>>,
}

/// Places errors in the source text.
struct Ctx<'a> {
    name: &'a str,
    text: &'a str,
    /// metres per length unit of the file (1 when the mechanism is built in file units)
    scale: f64,
}

impl Ctx<'_> {
    fn at(&self, span: Range<usize>, msg: impl std::fmt::Display) -> InputError {
        let start = span.start.min(self.text.len());
        let before = &self.text[..start];
        let line = before.matches('\n').count() + 1;
        let col = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
        InputError {
            message: format!("{}:{line}:{col}: {msg}", self.name),
        }
    }
    /// A point in file units converted to the mechanism's units.
    fn len_point(&self, p: Point2) -> Point2 {
        Point2::new(self.scale * p.x, self.scale * p.y)
    }
    /// A finite number.
    fn finite(&self, field: &str, v: &Spanned<f64>) -> Result<f64, InputError> {
        let x = *v.get_ref();
        if x.is_finite() {
            Ok(x)
        } else {
            Err(self.at(v.span(), format!("{field} = {x}: must be a finite number")))
        }
    }
    /// A positive finite number.
    fn positive(&self, field: &str, v: &Spanned<f64>) -> Result<f64, InputError> {
        let x = *v.get_ref();
        if x.is_finite() && x > 0.0 {
            Ok(x)
        } else {
            Err(self.at(
                v.span(),
                format!("{field} = {x}: must be positive and finite"),
            ))
        }
    }
    fn point(&self, field: &str, v: &Spanned<[f64; 2]>) -> Result<Point2, InputError> {
        let [x, y] = *v.get_ref();
        if x.is_finite() && y.is_finite() {
            Ok(Point2::new(x, y))
        } else {
            Err(self.at(v.span(), format!("{field} = [{x}, {y}]: must be finite")))
        }
    }
    fn direction(&self, field: &str, v: &Spanned<[f64; 2]>) -> Result<Vec2, InputError> {
        let p = self.point(field, v)?;
        if p.coords.norm() > 0.0 {
            Ok(p.coords)
        } else {
            Err(self.at(
                v.span(),
                format!("{field} = [{}, {}]: must be a non-zero direction", p.x, p.y),
            ))
        }
    }
    fn required<'b, T>(
        &self,
        table: &str,
        kind: &Spanned<String>,
        field: &str,
        v: &'b Option<Spanned<T>>,
    ) -> Result<&'b Spanned<T>, InputError> {
        v.as_ref().ok_or_else(|| {
            self.at(
                kind.span(),
                format!("[{table}] kind = {:?} needs `{field}`", kind.get_ref()),
            )
        })
    }
}

/// Errors for fields present that do not belong to the kind.
fn foreign(
    ctx: &Ctx<'_>,
    table: &str,
    kind: &Spanned<String>,
    present: &[(&str, Option<Range<usize>>)],
    allowed: &[&str],
) -> Result<(), InputError> {
    for (name, span) in present {
        if let Some(span) = span {
            if !allowed.contains(name) {
                return Err(ctx.at(
                    span.clone(),
                    format!(
                        "[{table}] kind = {:?} takes no `{name}` (its fields: {})",
                        kind.get_ref(),
                        allowed.join(", ")
                    ),
                ));
            }
        }
    }
    Ok(())
}

fn span_of<T>(v: &Option<Spanned<T>>) -> Option<Range<usize>> {
    v.as_ref().map(Spanned::span)
}

/// Reads a mechanism file's text (at most [`MAX_FILE_BYTES`], a byte-order mark dropped):
/// `(name for messages, text)`.
fn read_text(path: &Path) -> Result<(String, String), InputError> {
    let name = path.display().to_string();
    let cannot = |e: std::io::Error| InputError {
        message: format!("cannot read mechanism file {name}: {e}"),
    };
    let len = std::fs::metadata(path).map_err(cannot)?.len();
    if len > MAX_FILE_BYTES {
        return Err(InputError {
            message: format!(
                "{name}: {len} bytes is more than the {MAX_FILE_BYTES} a mechanism file may have"
            ),
        });
    }
    let text = std::fs::read_to_string(path).map_err(cannot)?;
    let text = text
        .strip_prefix('\u{feff}')
        .map(str::to_string)
        .unwrap_or(text);
    Ok((name, text))
}

/// Reads and builds a mechanism file; every error is bad input (exit code 2).
pub fn load(path: &Path) -> Result<Mechanism, InputError> {
    let (name, text) = read_text(path)?;
    parse(&text, &name, path.parent().unwrap_or(Path::new(".")))
}

/// Reads a mechanism file for a simulation (see [`parse_dynamics`]).
pub fn load_dynamics(path: &Path) -> Result<(Mechanism, FollowerDynamics), InputError> {
    let (name, text) = read_text(path)?;
    parse_dynamics(&text, &name, path.parent().unwrap_or(Path::new(".")))
}

/// Parses and builds a mechanism from the text of a mechanism file called `name` (for messages);
/// `base` resolves a relative points-file path.
pub fn parse(text: &str, name: &str, base: &Path) -> Result<Mechanism, InputError> {
    parse_scaled(text, name, base, false).map(|(m, _)| m)
}

/// Parses a mechanism file for a dynamic simulation: the geometry converted to metres with the
/// file's `length_unit`, and the `[dynamics]` section (required).
pub fn parse_dynamics(
    text: &str,
    name: &str,
    base: &Path,
) -> Result<(Mechanism, FollowerDynamics), InputError> {
    let (m, d) = parse_scaled(text, name, base, true)?;
    Ok((m, d.ok_or_else(|| InputError { message: format!("{name}: a simulation needs a [dynamics] section (mass or inertia, spring_stiffness, spring_preload; damping, restitution, gravity optional)") })?))
}

fn parse_scaled(
    text: &str,
    name: &str,
    base: &Path,
    si: bool,
) -> Result<(Mechanism, Option<FollowerDynamics>), InputError> {
    let spec: FileSpec = toml::from_str(text).map_err(|e| InputError {
        message: format!("{name}: {e}"),
    })?;
    let unit = match &spec.length_unit {
        None => 1.0,
        Some(u) => match u.get_ref().as_str() {
            "m" => 1.0,
            "cm" => 0.01,
            "mm" => 0.001,
            other => {
                let c = Ctx {
                    name,
                    text,
                    scale: 1.0,
                };
                return Err(c.at(
                    u.span(),
                    format!("length_unit = {other:?} is not a unit (mm, cm, m)"),
                ));
            }
        },
    };
    let scale = if si { unit } else { 1.0 };
    let ctx = Ctx { name, text, scale };
    let cam = spec.cam.get_ref();
    let follower = build_follower(&ctx, spec.follower.get_ref())?;
    let sense = cam
        .direction
        .as_ref()
        .map_or(Sense::Ccw, |d| (*d.get_ref()).into());
    let profile = build_profile(&ctx, cam.profile.get_ref(), base, &follower, sense)?;
    let speed = ctx.positive("cam.speed_rpm", &cam.speed_rpm)?;
    let pivot = cam
        .pivot
        .as_ref()
        .map(|p| ctx.point("cam.pivot", p).map(|p| ctx.len_point(p)))
        .transpose()?
        .unwrap_or_else(Point2::origin);
    let alpha = cam
        .angular_acceleration_deg_s2
        .as_ref()
        .map(|a| ctx.finite("cam.angular_acceleration_deg_s2", a))
        .transpose()?
        .unwrap_or(0.0);
    let cam_obj = Cam::from_rpm(profile, pivot, sense, speed)
        .and_then(|c| c.with_angular_acceleration(alpha.to_radians()))
        .map_err(|e| ctx.at(spec.cam.span(), e))?;
    let fspan = spec.follower.span();
    let oscillating = follower.is_oscillating();
    let mech = Mechanism::new(cam_obj, follower).map_err(|e| match e {
        CamError::Cusp { .. } => ctx.at(cam.profile.span(), format!("[cam.profile]: {e}")),
        _ => ctx.at(fspan, e),
    })?;
    let dynamics = spec
        .dynamics
        .as_ref()
        .map(|d| build_dynamics(&ctx, d, oscillating))
        .transpose()?;
    Ok((mech, dynamics))
}

fn build_dynamics(
    ctx: &Ctx<'_>,
    d: &Spanned<DynamicsTable>,
    oscillating: bool,
) -> Result<FollowerDynamics, InputError> {
    let t = d.get_ref();
    let need = |field: &str, v: &Option<Spanned<f64>>| -> Result<f64, InputError> {
        match v {
            Some(v) => ctx.positive(&format!("dynamics.{field}"), v),
            None => Err(ctx.at(
                d.span(),
                format!("[dynamics] needs `{field}` for this follower"),
            )),
        }
    };
    let nonneg = |field: &str, v: &Spanned<f64>| -> Result<f64, InputError> {
        let x = ctx.finite(field, v)?;
        if x >= 0.0 {
            Ok(x)
        } else {
            Err(ctx.at(v.span(), format!("{field} = {x}: must not be negative")))
        }
    };
    let (mass, inertia) = if oscillating {
        if let Some(m) = &t.mass {
            return Err(ctx.at(
                m.span(),
                "[dynamics] of an oscillating follower takes `inertia`, not `mass`",
            ));
        }
        (1.0, need("inertia", &t.inertia)?)
    } else {
        if let Some(i) = &t.inertia {
            return Err(ctx.at(
                i.span(),
                "[dynamics] of a translating follower takes `mass`, not `inertia`",
            ));
        }
        (need("mass", &t.mass)?, 1.0)
    };
    let restitution = t
        .restitution
        .as_ref()
        .map(|r| nonneg("dynamics.restitution", r))
        .transpose()?
        .unwrap_or(0.0);
    if restitution > 1.0 {
        let r = t.restitution.as_ref().map_or(d.span(), Spanned::span);
        return Err(ctx.at(
            r,
            format!("dynamics.restitution = {restitution}: must be from 0 to 1"),
        ));
    }
    let gravity = t
        .gravity
        .as_ref()
        .map(|g| ctx.point("dynamics.gravity", g))
        .transpose()?
        .map_or(Vec2::zeros(), |p| p.coords);
    Ok(FollowerDynamics {
        mass,
        inertia,
        spring_stiffness: nonneg("dynamics.spring_stiffness", &t.spring_stiffness)?,
        spring_preload: nonneg("dynamics.spring_preload", &t.spring_preload)?,
        damping: t
            .damping
            .as_ref()
            .map(|c| nonneg("dynamics.damping", c))
            .transpose()?
            .unwrap_or(0.0),
        restitution,
        gravity,
    })
}

fn build_profile(
    ctx: &Ctx<'_>,
    p: &ProfileTable,
    base: &Path,
    follower: &Follower,
    sense: Sense,
) -> Result<Arc<dyn Curve>, InputError> {
    const T: &str = "cam.profile";
    let present = [
        ("base_radius", span_of(&p.base_radius)),
        ("segments", span_of(&p.segments)),
        ("points", span_of(&p.points)),
        ("parameterization", span_of(&p.parameterization)),
        ("center", span_of(&p.center)),
        ("radius", span_of(&p.radius)),
        ("semi_axes", span_of(&p.semi_axes)),
        ("rotation_deg", span_of(&p.rotation_deg)),
        ("path", span_of(&p.path)),
    ];
    let kind = &p.kind;
    let param = p
        .parameterization
        .as_ref()
        .map_or(Parameterization::Uniform, |v| (*v.get_ref()).into());
    match kind.get_ref().as_str() {
        "spline" => {
            foreign(ctx, T, kind, &present, &["points", "parameterization"])?;
            let pts = ctx.required(T, kind, "points", &p.points)?;
            let list = pts.get_ref();
            if list.len() > MAX_POINTS {
                return Err(ctx.at(pts.span(), format!("cam.profile.points: {} points is more than the {MAX_POINTS} allowed", list.len())));
            }
            let mut nodes = Vec::with_capacity(list.len());
            for (i, q) in list.iter().enumerate() {
                nodes.push(ctx.len_point(ctx.point(&format!("cam.profile.points[{i}]"), q)?));
            }
            let spans: Vec<Range<usize>> = list.iter().map(Spanned::span).collect();
            spline(&nodes, param, |i| ctx.at(spans.get(i).cloned().unwrap_or(pts.span()), ""), "cam.profile.points")
        }
        "circle" => {
            foreign(ctx, T, kind, &present, &["center", "radius"])?;
            let c = ctx.len_point(ctx.point("cam.profile.center", ctx.required(T, kind, "center", &p.center)?)?);
            let r = ctx.scale * ctx.positive("cam.profile.radius", ctx.required(T, kind, "radius", &p.radius)?)?;
            Ok(Arc::new(Circle::new(c, r).map_err(|e| ctx.at(kind.span(), e))?))
        }
        "ellipse" => {
            foreign(ctx, T, kind, &present, &["center", "semi_axes", "rotation_deg"])?;
            let c = ctx.len_point(ctx.point("cam.profile.center", ctx.required(T, kind, "center", &p.center)?)?);
            let ax = ctx.required(T, kind, "semi_axes", &p.semi_axes)?;
            let [a, b] = *ax.get_ref();
            if !(a.is_finite() && a > 0.0 && b.is_finite() && b > 0.0) {
                return Err(ctx.at(ax.span(), format!("cam.profile.semi_axes = [{a}, {b}]: both must be positive and finite")));
            }
            let rot = p.rotation_deg.as_ref().map(|r| ctx.finite("cam.profile.rotation_deg", r)).transpose()?.unwrap_or(0.0);
            Ok(Arc::new(Ellipse::new(c, ctx.scale * a, ctx.scale * b, rot.to_radians()).map_err(|e| ctx.at(kind.span(), e))?))
        }
        "motion" => {
            foreign(ctx, T, kind, &present, &["base_radius", "segments"])?;
            let rb = ctx.scale * ctx.positive("cam.profile.base_radius", ctx.required(T, kind, "base_radius", &p.base_radius)?)?;
            let segs = ctx.required(T, kind, "segments", &p.segments)?;
            // rises: lengths for translating followers, degrees of arm angle for oscillating ones
            let rise_scale = if follower.is_oscillating() { 1f64.to_radians() } else { ctx.scale };
            let mut list = Vec::new();
            for (i, seg) in segs.get_ref().iter().enumerate() {
                let sg = seg.get_ref();
                let law = Law::ALL.iter().copied().find(|l| l.name() == sg.law.get_ref().as_str()).ok_or_else(|| {
                    let names: Vec<&str> = Law::ALL.iter().map(|l| l.name()).collect();
                    ctx.at(sg.law.span(), format!("cam.profile.segments[{i}].law = {:?} is not a law ({})", sg.law.get_ref(), names.join(", ")))
                })?;
                let rise = sg.rise.as_ref().map(|r| ctx.finite(&format!("cam.profile.segments[{i}].rise"), r)).transpose()?.unwrap_or(0.0);
                let degrees = ctx.positive(&format!("cam.profile.segments[{i}].degrees"), &sg.degrees)?;
                list.push(Segment { law, rise: rise * rise_scale, extent: degrees.to_radians() });
            }
            let program = Program::new(0.0, list).map_err(|e| ctx.at(segs.span(), format!("cam.profile.segments: {e}")))?;
            let prof = synthesize(program, rb, follower, sense).map_err(|e| ctx.at(kind.span(), e))?;
            Ok(Arc::new(prof))
        }
        "points-file" => {
            foreign(ctx, T, kind, &present, &["path", "parameterization"])?;
            let path = ctx.required(T, kind, "path", &p.path)?;
            let full = base.join(path.get_ref());
            let file = full.display().to_string();
            let (mut nodes, lines) = camkin::curve::read_points_file(&full).map_err(|e| match e {
                CurveError::PointsFileIo { message, .. } => ctx.at(path.span(), format!("cam.profile.path = {:?}: cannot read {file}: {message}", path.get_ref())),
                CurveError::PointsFileSyntax { line, message, content } => InputError { message: format!("{file}:{line}: {message}: {content:?}") },
                other => ctx.at(path.span(), other),
            })?;
            for n in &mut nodes {
                *n = ctx.len_point(*n);
            }
            spline(
                &nodes,
                param,
                |i| InputError { message: lines.get(i).map_or_else(|| format!("{file}: "), |l| format!("{file}:{l}: ")) },
                &format!("points file {file}"),
            )
        }
        other => Err(ctx.at(kind.span(), format!("cam.profile.kind = {other:?} is not a profile kind (spline, circle, ellipse, points-file, motion)"))),
    }
}

/// A closed spline through `nodes`; `place(i)` locates node `i` for messages.
fn spline(
    nodes: &[Point2],
    param: Parameterization,
    place: impl Fn(usize) -> InputError,
    what: &str,
) -> Result<Arc<dyn Curve>, InputError> {
    let with = |i: usize, msg: String| InputError {
        message: format!("{}{msg}", place(i).message),
    };
    let s = ClosedSpline::with_parameterization(nodes, param).map_err(|e| match e {
        CurveError::TooFewPoints { count } => with(0, format!("{what}: a closed spline needs at least 3 points, got {count}")),
        CurveError::RepeatedPoint { index, next, x, y } => with(next, format!("{what}: points {index} and {next} coincide at ({x}, {y}); consecutive points must differ")),
        CurveError::NonFinitePoint { index, x, y } => with(index, format!("{what}: point {index} = ({x}, {y}) is not finite")),
        other => with(0, format!("{what}: {other}")),
    })?;
    if let Some((ua, ub, p)) = s.self_intersection() {
        let n = nodes.len();
        let (i, j) = (
            (ua.floor() as usize).min(n - 1),
            (ub.floor() as usize).min(n - 1),
        );
        let (i, j) = if param == Parameterization::Uniform {
            (i, j)
        } else {
            (node_of(&s, ua), node_of(&s, ub))
        };
        return Err(with(i, format!("{what}: the spline through the points crosses itself near ({:.6}, {:.6}), between points {i}–{} and {j}–{}", p.x, p.y, (i + 1) % n, (j + 1) % n)));
    }
    Ok(Arc::new(s))
}

/// The node starting the segment that holds parameter `u`.
fn node_of(s: &ClosedSpline, u: f64) -> usize {
    (0..s.segments())
        .rev()
        .find(|&i| s.node_param(i) <= u)
        .unwrap_or(0)
}

fn build_follower(ctx: &Ctx<'_>, f: &FollowerTable) -> Result<Follower, InputError> {
    const T: &str = "follower";
    let present = [
        ("direction", span_of(&f.direction)),
        ("offset", span_of(&f.offset)),
        ("roller_radius", span_of(&f.roller_radius)),
        ("pivot", span_of(&f.pivot)),
        ("arm_length", span_of(&f.arm_length)),
        ("closing", span_of(&f.closing)),
        ("initial_angle_deg", span_of(&f.initial_angle_deg)),
    ];
    let kind = &f.kind;
    let direction = || -> Result<Vec2, InputError> {
        f.direction
            .as_ref()
            .map_or(Ok(Vec2::x()), |d| ctx.direction("follower.direction", d))
    };
    let offset = || -> Result<f64, InputError> {
        f.offset.as_ref().map_or(Ok(0.0), |o| {
            ctx.finite("follower.offset", o).map(|v| ctx.scale * v)
        })
    };
    let closing = f
        .closing
        .as_ref()
        .map_or(Sense::Cw, |c| (*c.get_ref()).into());
    let initial = || -> Result<f64, InputError> {
        Ok(f.initial_angle_deg
            .as_ref()
            .map(|a| ctx.finite("follower.initial_angle_deg", a))
            .transpose()?
            .unwrap_or(0.0)
            .to_radians())
    };
    Ok(match kind.get_ref().as_str() {
        "translating-flat" => {
            foreign(ctx, T, kind, &present, &["direction"])?;
            Follower::TranslatingFlat { direction: direction()? }
        }
        "translating-roller" => {
            foreign(ctx, T, kind, &present, &["direction", "offset", "roller_radius"])?;
            let r = ctx.scale * ctx.positive("follower.roller_radius", ctx.required(T, kind, "roller_radius", &f.roller_radius)?)?;
            Follower::TranslatingRoller { direction: direction()?, offset: offset()?, roller_radius: r }
        }
        "translating-knife" => {
            foreign(ctx, T, kind, &present, &["direction", "offset"])?;
            Follower::TranslatingKnife { direction: direction()?, offset: offset()? }
        }
        "oscillating-flat" => {
            foreign(ctx, T, kind, &present, &["pivot", "offset", "closing", "initial_angle_deg"])?;
            let pivot = ctx.len_point(ctx.point("follower.pivot", ctx.required(T, kind, "pivot", &f.pivot)?)?);
            Follower::OscillatingFlat { pivot, face_offset: offset()?, closing, initial_angle: initial()? }
        }
        "oscillating-roller" => {
            foreign(ctx, T, kind, &present, &["pivot", "arm_length", "roller_radius", "closing", "initial_angle_deg"])?;
            let pivot = ctx.len_point(ctx.point("follower.pivot", ctx.required(T, kind, "pivot", &f.pivot)?)?);
            let l = ctx.scale * ctx.positive("follower.arm_length", ctx.required(T, kind, "arm_length", &f.arm_length)?)?;
            let r = ctx.scale * ctx.positive("follower.roller_radius", ctx.required(T, kind, "roller_radius", &f.roller_radius)?)?;
            Follower::OscillatingRoller { pivot, arm_length: l, roller_radius: r, closing, initial_angle: initial()? }
        }
        other => {
            return Err(ctx.at(
                kind.span(),
                format!("follower.kind = {other:?} is not a follower kind (translating-flat, translating-roller, translating-knife, oscillating-flat, oscillating-roller)"),
            ))
        }
    })
}

/// The paper's mechanism (section 3), the file `examples/paper.toml`.
pub const PAPER_TOML: &str = include_str!("../../../examples/paper.toml");

/// The built-in paper mechanism.
pub fn paper() -> Mechanism {
    camkin::reference::paper_mechanism(false)
}

/// The synthesised profile behind a mechanism built from a `kind = "motion"` file, if it is one.
pub fn synthesized(m: &Mechanism) -> Option<&camkin::cam::synthesis::SynthesizedProfile> {
    let any: &dyn std::any::Any = m.cam().profile();
    any.downcast_ref()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> String {
        parse(text, "m.toml", Path::new("."))
            .map(|_| ())
            .unwrap_err()
            .message
    }

    #[test]
    fn example_file_is_the_built_in_paper_mechanism() {
        let m = parse(PAPER_TOML, "paper.toml", Path::new(".")).unwrap();
        let (a, b) = (m.analyze(0.7).unwrap(), paper().analyze(0.7).unwrap());
        assert_eq!((a.position, a.acceleration), (b.position, b.acceleration));
    }

    #[test]
    fn errors_name_line_field_and_value() {
        let e = err(&PAPER_TOML.replace("direction = [1.0, 0.0]", "roller_radius = 1.0"));
        assert!(
            e.contains("takes no `roller_radius`") && e.contains("m.toml:"),
            "{e}"
        );
        let e = err(&PAPER_TOML.replace("kind = \"spline\"", "kind = \"blob\""));
        assert!(e.contains("\"blob\"") && e.contains("m.toml:9:8:"), "{e}");
        let e = err(&PAPER_TOML.replace("speed_rpm = 1000.0", "speed_rpm = -5.0"));
        assert!(
            e.contains("cam.speed_rpm = -5") && e.contains("m.toml:4:"),
            "{e}"
        );
        let e = err(&PAPER_TOML.replace("speed_rpm = 1000.0", "speed_rpm = \"fast\""));
        assert!(e.contains("line 4") && e.contains("speed_rpm"), "{e}");
    }
}
