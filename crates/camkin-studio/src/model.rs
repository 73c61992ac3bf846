//! What the studio shows, computed from a mechanism file's text: the analysis over a revolution
//! (the plotted series with their units, the mechanism's drawing at every angle), the design
//! checks placed at their cam angles, the interpolation study, the forces. All numbers come from
//! the library; the page only draws them.

use super::{Limits, StudioError};
use crate::mechtext::{self as mechfile, FromText};
use crate::scene::mechanism::{follower_shapes, Shape};
use camkin::cam::Mechanism;
use camkin::curve::Domain;
use camkin::geometry::deg_to_rad;
use camkin::interp::{max_and_mean, relative_errors, Interpolated};
use camkin::report::{DesignReport, ForceReport, ForceRequest};
use camkin::spec::{BuildOptions, MechanismSpec};
use camkin::table::{AnalysisRow, AnalysisSweep, AngleUnit, Per, Units};
use serde::Serialize;
use std::path::PathBuf;
use std::time::Instant;

/// Where a mechanism's text comes from: its name for messages and the folder its points files
/// may be read from (none for the built-in paper cam).
#[derive(Debug, Clone)]
pub struct Source {
    /// the file's name (`paper.toml`)
    pub name: String,
    /// the folder of the file, the only one read from
    pub folder: Option<PathBuf>,
}

/// How a spec from `source` is built: points files confined to the source's folder (the
/// built-in cam has none, so it may read no file at all).
fn options(
    spec: &MechanismSpec,
    source: &Source,
    si: bool,
    limits: &Limits,
) -> Result<BuildOptions, StudioError> {
    build_options(spec.cam.profile.path.is_some(), source, si, limits)
}

/// How a file from `source` that reads a points file for its cam (`cam_file`) is built.
pub(super) fn build_options(
    cam_file: bool,
    source: &Source,
    si: bool,
    limits: &Limits,
) -> Result<BuildOptions, StudioError> {
    let base_dir = match &source.folder {
        Some(f) => f.clone(),
        None if cam_file => {
            return Err(StudioError::Input {
                message: "cam.profile.path: no folder is open, so no points file can be read; start `camkin serve FILE.toml` to read points files beside FILE.toml".into(),
                at: None,
            });
        }
        None => PathBuf::from("."),
    };
    Ok(BuildOptions {
        base_dir,
        si,
        confine: true,
        limits: camkin::work::Limits {
            seconds: limits.max_seconds,
            bytes: limits.max_request_bytes,
        },
    })
}

/// Builds the mechanism in `text` (in its own units), errors and warnings placed in the text.
pub fn build(text: &str, source: &Source, limits: &Limits) -> Result<FromText, StudioError> {
    let spec = mechfile::parse_spec(text, &source.name)?;
    let options = options(&spec, source, false, limits)?;
    let (built, warnings) = mechfile::build_placed(&spec, text, &source.name, &options)?;
    Ok(FromText {
        spec,
        built,
        warnings,
    })
}

/// A number series over the cam angles, with its name and unit.
#[derive(Debug, Serialize)]
pub struct Series {
    /// short key (`acceleration`)
    pub key: String,
    /// what a person reads (`acceleration`)
    pub label: String,
    /// its unit (`cm/s²`)
    pub unit: String,
    /// one value per angle; `null` where it could not be computed (or is infinite)
    pub values: Vec<Option<f64>>,
    /// magnitudes below this are rounding (an ideal gear's zero acceleration): the page shows
    /// them as 0 and draws the plot on a span that shows them as zero
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resolution: Option<f64>,
}

/// Polylines longer than this, closed, are drawn once in the body frame ([`ShapeOut::Curve`]).
const SHARED_POINTS: usize = 500;

/// A shape of the drawing in world coordinates.
#[derive(Debug, Serialize)]
#[serde(tag = "t", rename_all = "lowercase")]
pub enum ShapeOut {
    /// a polyline
    Line {
        pts: Vec<[f64; 2]>,
        color: String,
        width: u32,
        /// sent only when true (the page reads an absent `closed` as open)
        #[serde(skip_serializing_if = "std::ops::Not::not")]
        closed: bool,
    },
    /// a circle
    Circle {
        c: [f64; 2],
        r: f64,
        color: String,
        width: u32,
    },
    /// a dot of a size in pixels
    Dot { p: [f64; 2], color: String, px: u32 },
    /// a closed curve of the follower, drawn once in its body frame (`Analysis::curves[i]`) and
    /// placed at `pose` (origin and angle, rad) in each frame: a carried gear or spline would
    /// otherwise repeat thousands of points in every frame
    Curve {
        i: usize,
        pose: [f64; 3],
        color: String,
        width: u32,
    },
}

/// A colour as the page's canvas reads it, in its shortest form (`#3c3c3c`).
pub(crate) fn rgb(c: (u8, u8, u8)) -> String {
    format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2)
}

impl From<Shape> for ShapeOut {
    fn from(s: Shape) -> Self {
        match s {
            Shape::Polyline {
                pts,
                color,
                width,
                closed,
            } => ShapeOut::Line {
                pts: pts.iter().map(|p| [p.x, p.y]).collect(),
                color: rgb(color),
                width,
                closed,
            },
            Shape::Circle { c, r, color, width } => ShapeOut::Circle {
                c: [c.x, c.y],
                r,
                color: rgb(color),
                width,
            },
            Shape::Dot { p, color, px } => ShapeOut::Dot {
                p: [p.x, p.y],
                color: rgb(color),
                px,
            },
        }
    }
}

/// The mechanism at one cam angle.
#[derive(Debug, Serialize)]
pub struct Frame {
    /// the cam frame's pose: origin and angle (rad): a cam point `r` is at `origin + R(angle) r`
    pub cam: [f64; 3],
    /// the contact point, world frame (absent where the angle failed)
    pub contact: Option<[f64; 2]>,
    /// the common normal, world frame
    pub normal: Option<[f64; 2]>,
    /// the follower drawn from its model
    pub follower: Vec<ShapeOut>,
}

/// A design check, marked at its cam angles.
#[derive(Debug, Serialize)]
pub struct Check {
    /// which check (`pressure-angle`, `undercut`, `jumps`, `analysed`, `round-trip`, …)
    pub kind: camkin::report::Check,
    /// the check passed (a statement of a value) or failed
    pub ok: bool,
    /// what a person reads
    pub message: String,
    /// cam angles (degrees) to mark
    pub angles_deg: Vec<f64>,
    /// stretches of the profile to mark, cam frame
    pub stretches: Vec<Vec<[f64; 2]>>,
}

/// An event of a simulation (an impact), at its driver angle.
#[derive(Debug, Serialize)]
pub struct Event {
    /// what a person reads
    pub message: String,
    /// the driver's angle, degrees
    pub angle_deg: f64,
}

/// A warning from the file (uneven nodes), placed.
#[derive(Debug, Serialize)]
pub struct Placed {
    /// the message
    pub message: String,
    /// 1-based line and column
    pub line: Option<usize>,
    /// 1-based column
    pub column: Option<usize>,
}

/// Forces under permanent contact at any constant speed: the page evaluates
/// `F = (c2 ω² + c1 ω + c0) / lever` for its speed slider (see
/// [`camkin::report::ForceReport::coefficients`]).
#[derive(Debug, Serialize)]
pub struct DynamicsOut {
    /// the file's cam speed, rpm
    pub rpm: f64,
    /// per angle `[c2, c1, c0, lever]` (SI; `null` where the angle failed)
    pub coefficients: Vec<Option<[f64; 4]>>,
    /// the lowest constant speed at which the contact force reaches zero somewhere, rpm (`null`:
    /// never)
    pub jump_rpm: Option<f64>,
    /// the cam angle where it happens first, degrees
    pub jump_angle_deg: Option<f64>,
    /// the force's unit (`N`)
    pub unit: &'static str,
    /// the lubrication at the file's speed, when the file has `[lubrication]`
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lubrication: Option<LubricationOut>,
}

/// The lubrication the force panel draws (the file's `[lubrication]`, at the file's speed).
#[derive(Debug, Serialize)]
pub struct LubricationOut {
    /// λ per angle (`null` where the contact carries nothing or is not a line contact)
    pub lambda: Vec<Option<f64>>,
    /// the regime per angle: 0 boundary, 1 mixed, 2 full film
    pub regime: Vec<Option<u8>>,
    /// the minimum film per angle, µm
    pub film_minimum_um: Vec<Option<f64>>,
    /// Blok's flash temperature per angle, K
    pub flash_temperature_k: Vec<Option<f64>>,
    /// the angles where the entrainment reverses, degrees
    pub entrainment_reversals_deg: Vec<f64>,
    /// the smallest λ and its angle (degrees)
    pub min_lambda: Option<[f64; 2]>,
    /// the largest flash temperature (K) and its angle (degrees)
    pub max_flash_k: Option<[f64; 2]>,
    /// the friction's mean power, W, and mean torque on the camshaft, N·m
    pub friction: [f64; 2],
}

/// A gear pair's loads along its whole path of contact (the file's `[gear_loads]`, and its
/// `[lubrication]`), over the contact's radius on the driver.
#[derive(Debug, Serialize)]
pub struct GearLoadsOut {
    /// the file's length unit
    pub unit: &'static str,
    /// the torque on the driver, N·m
    pub torque: f64,
    /// the normal force `T/r_b1`, N
    pub normal_force: f64,
    /// the face width, in the file's unit
    pub face_width: f64,
    /// the contact ratio (the path's length over the base pitch)
    pub contact_ratio: f64,
    /// the contact's radius on the driver at each point, the file's unit, its root to its tip
    pub radius: Vec<f64>,
    /// the tooth pairs in contact at each point
    pub pairs: Vec<u32>,
    /// the load on the pair, N
    pub load: Vec<f64>,
    /// Hertz's maximum pressure, MPa
    pub hertz_mpa: Vec<Option<f64>>,
    /// the driver's and the driven gear's specific sliding
    pub specific_sliding: [Vec<Option<f64>>; 2],
    /// λ at each point (with `[lubrication]`)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lambda: Option<Vec<Option<f64>>>,
    /// the regime at each point: 0 boundary, 1 mixed, 2 full film (with `[lubrication]`)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub regime: Option<Vec<Option<u8>>>,
    /// Blok's flash temperature, K (with `[lubrication]`)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flash_temperature_k: Option<Vec<Option<f64>>>,
    /// the pitch point: the driver's radius and the Hertz pressure there (MPa)
    pub pitch: [f64; 2],
    /// the largest Hertz pressure (MPa) and its radius
    pub max_hertz: Option<[f64; 2]>,
    /// the smallest λ and its radius
    pub min_lambda: Option<[f64; 2]>,
    /// the largest flash temperature (K) and its radius
    pub max_flash_k: Option<[f64; 2]>,
}

/// The analysis the studio shows.
#[derive(Debug, Serialize)]
pub struct Analysis {
    /// the file's name
    pub name: String,
    /// the file's length unit
    pub length_unit: &'static str,
    /// the follower swings on an arm (its coordinate is an angle)
    pub oscillating: bool,
    /// cam speed, rpm
    pub rpm: f64,
    /// the cam angle step, degrees
    pub step_deg: f64,
    /// the cam angles, degrees
    pub angles_deg: Vec<f64>,
    /// lift, velocity, acceleration, jerk, pressure angle, radius of curvature
    pub series: Vec<Series>,
    /// the drawing at every angle
    pub frames: Vec<Frame>,
    /// the follower's closed curves in its body frame, which frames place by their pose
    pub curves: Vec<Vec<[f64; 2]>>,
    /// the cam profile in the cam frame, closed polyline
    pub profile: Vec<[f64; 2]>,
    /// the spline's nodes (cam frame): draggable when `nodes_editable`
    pub nodes: Vec<[f64; 2]>,
    /// the nodes are the file's inline `cam.profile.points`
    pub nodes_editable: bool,
    /// the cam's axis, world frame
    pub pivot: [f64; 2],
    /// the drawing's extent over the revolution, `[xmin, ymin, xmax, ymax]`
    pub extent: [f64; 4],
    /// design checks
    pub checks: Vec<Check>,
    /// warnings from the file
    pub warnings: Vec<Placed>,
    /// angles that could not be analysed, and the first reason
    pub failed: usize,
    /// the first failure's message
    pub first_error: Option<String>,
    /// forces, when the file has `[dynamics]`
    pub dynamics: Option<DynamicsOut>,
    /// a gear pair's loads along its path of contact, when the file has `[gear_loads]`
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gear_loads: Option<GearLoadsOut>,
    /// a system file (bodies, joints, contacts): no cam profile, nodes, checks or study
    pub system: bool,
    /// a system simulated (its file has `[dynamics]`): the frames and series are its
    /// simulation's, and `events` its impacts
    pub simulated: bool,
    /// a simulated system's impacts, for people, at their driver angles
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub events: Vec<Event>,
    /// server time for this analysis, ms
    pub server_ms: f64,
}

/// Cam angles of one revolution in steps of `step_deg`.
pub fn revolution(step_deg: f64) -> Vec<f64> {
    let n = (360.0 / step_deg).round() as usize;
    let grid = camkin::table::AngleGrid::new(0.0, step_deg);
    (0..n).map(|k| grid.at(k)).collect()
}

/// Refuses work over the limits: too many angles, a sweep estimated over the time allowed.
pub fn check_work(mech: &Mechanism, angles: usize, limits: &Limits) -> Result<(), StudioError> {
    let work = camkin::work::Work::sweep(mech, angles, 1);
    if let Some(r) = work.refusal_within(limits.max_seconds, camkin::work::BYTES_LIMIT) {
        return Err(StudioError::TooMuch {
            message: format!(
                "{r}, more than the {} s one request may take; use `camkin analyze` for it",
                limits.max_seconds
            ),
        });
    }
    Ok(())
}

/// The analysis of the mechanism in `text` at `step_deg`, checks against `pressure_limit_deg`.
pub fn analyze(
    text: &str,
    source: &Source,
    step_deg: f64,
    pressure_limit_deg: f64,
    limits: &Limits,
) -> Result<Analysis, StudioError> {
    if super::system::is_system(text) {
        return super::system::analyze(text, source, step_deg, limits);
    }
    let t0 = Instant::now();
    let parsed = build(text, source, limits)?;
    let mech = &parsed.built.mechanism;
    let unit = parsed.built.length_unit;
    let angles = revolution(step_deg);
    // three sweeps: the table, the design checks and, with [dynamics], the forces
    let sweeps = if parsed.spec.dynamics.is_some() { 3 } else { 2 };
    check_work(mech, sweeps * angles.len(), limits)?;
    let units = Units::new(mech, unit, AngleUnit::Deg, Per::S);
    let mut sweep = AnalysisSweep::new(mech, &angles, true, angles.len());
    let rows: Vec<AnalysisRow> = sweep.by_ref().flatten().collect();
    let oscillating = units.oscillating;
    let motion: Vec<[Option<f64>; 4]> = rows
        .iter()
        .map(|r| match (r.position, r.velocity, r.acceleration) {
            (Some(q), Some(v), Some(a)) => units.motion(q, v, a, r.jerk),
            _ => [None; 4],
        })
        .collect();
    let finite = |x: Option<f64>| x.filter(|v| v.is_finite());
    let lift: Vec<Option<f64>> = rows
        .iter()
        .map(|r| finite(r.lift.map(|l| units.coord_value(l))))
        .collect();
    let velocity: Vec<Option<f64>> = motion.iter().map(|m| finite(m[1])).collect();
    let acceleration: Vec<Option<f64>> = motion.iter().map(|m| finite(m[2])).collect();
    let jerk: Vec<Option<f64>> = motion.iter().map(|m| finite(m[3])).collect();
    let scales = motion_scales(mech.cam().speed(), [&lift, &velocity, &acceleration, &jerk]);
    // a value under 1e-9 of its motion's scale is rounding (an ideal gear pair's acceleration)
    let resolution = |k: usize| Some(1e-9 * scales[k]).filter(|r| *r > 0.0);
    let series = vec![
        Series {
            key: "lift".into(),
            label: "lift".into(),
            unit: units.motion_symbol(0),
            values: lift,
            resolution: resolution(0),
        },
        Series {
            key: "velocity".into(),
            label: "velocity".into(),
            unit: units.motion_symbol(1),
            values: velocity,
            resolution: resolution(1),
        },
        Series {
            key: "acceleration".into(),
            label: "acceleration".into(),
            unit: units.motion_symbol(2),
            values: acceleration,
            resolution: resolution(2),
        },
        Series {
            key: "jerk".into(),
            label: "jerk".into(),
            unit: units.motion_symbol(3),
            values: jerk,
            resolution: resolution(3),
        },
        Series {
            key: "pressure_angle".into(),
            label: "pressure angle".into(),
            unit: "°".into(),
            values: rows.iter().map(|r| finite(r.pressure_angle_deg)).collect(),
            // an angle below a nanodegree is rounding (a radial flat face's is zero)
            resolution: Some(1e-9),
        },
        Series {
            key: "radius_of_curvature".into(),
            label: "radius of curvature".into(),
            unit: unit.name().into(),
            values: rows.iter().map(|r| finite(r.radius_of_curvature)).collect(),
            resolution: None,
        },
    ];
    // the drawing: the cam's pose and the follower at each angle
    let cam = mech.cam();
    let size = mech.size();
    let mut frames = Vec::with_capacity(rows.len());
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    let mut grow = |p: [f64; 2], r: f64| {
        lo = [lo[0].min(p[0] - r), lo[1].min(p[1] - r)];
        hi = [hi[0].max(p[0] + r), hi[1].max(p[1] + r)];
    };
    let mut curves: Vec<Vec<[f64; 2]>> = Vec::new();
    for (r, &a) in rows.iter().zip(&angles) {
        let pose = cam.state(deg_to_rad(a)).pose;
        let mut shapes = Vec::new();
        let mut body = None;
        if let (Some(q), Some(x), Some(y)) = (r.position, r.contact_x, r.contact_y) {
            follower_shapes(mech, q, camkin::Point2::new(x, y), size, &mut shapes);
            body = Some(mech.follower_body(q).0);
        }
        // a long closed polyline is a carried curve: kept once in the body frame
        let mut k = 0;
        let follower: Vec<ShapeOut> = shapes
            .into_iter()
            .map(|s| match (s, body) {
                (
                    crate::scene::mechanism::Shape::Polyline {
                        pts,
                        color,
                        width,
                        closed: true,
                    },
                    Some(b),
                ) if pts.len() > SHARED_POINTS => {
                    if curves.len() <= k {
                        curves.push(
                            pts.iter()
                                .map(|p| {
                                    let l = b.to_body(*p);
                                    [l.x, l.y]
                                })
                                .collect(),
                        );
                    }
                    pts.iter().for_each(|p| grow([p.x, p.y], 0.0));
                    k += 1;
                    ShapeOut::Curve {
                        i: k - 1,
                        pose: [b.origin.x, b.origin.y, b.angle],
                        color: rgb(color),
                        width,
                    }
                }
                (s, _) => ShapeOut::from(s),
            })
            .collect();
        for s in &follower {
            match s {
                ShapeOut::Line { pts, .. } => pts.iter().for_each(|p| grow(*p, 0.0)),
                ShapeOut::Circle { c, r, .. } => grow(*c, *r),
                ShapeOut::Dot { p, .. } => grow(*p, 0.0),
                ShapeOut::Curve { .. } => {}
            }
        }
        frames.push(Frame {
            cam: [pose.origin.x, pose.origin.y, pose.angle],
            contact: r.contact_x.zip(r.contact_y).map(|(x, y)| [x, y]),
            normal: r.normal_x.zip(r.normal_y).map(|(x, y)| [x, y]),
            follower,
        });
    }
    let profile_curve = cam.profile();
    let (u0, span) = match profile_curve.domain() {
        Domain::Periodic { period } => (0.0, period),
        Domain::Interval { min, max } => (min, max - min),
        _ => (0.0, 0.0),
    };
    let profile: Vec<[f64; 2]> = (0..1440)
        .map(|k| {
            let p = profile_curve.position(u0 + span * k as f64 / 1440.0);
            [p.x, p.y]
        })
        .collect();
    // the cam sweeps a disc about its axis of the profile's largest radius
    let pivot = cam.pivot();
    let reach = profile
        .iter()
        .map(|p| p[0].hypot(p[1]))
        .fold(0.0f64, f64::max);
    grow([pivot.x, pivot.y], reach);
    let (nodes, nodes_editable) = match (
        &parsed.spec.cam.profile.points,
        parsed.spec.cam.profile.kind.as_str(),
    ) {
        (Some(points), "spline") => (points.clone(), true),
        _ => (
            profile_curve
                .breakpoints()
                .into_iter()
                .map(|u| {
                    let p = profile_curve.position(u);
                    [p.x, p.y]
                })
                .collect(),
            false,
        ),
    };
    let checks = checks(
        mech,
        &angles,
        &sweep,
        &rows,
        pressure_limit_deg,
        unit.name(),
    );
    let dynamics = dynamics(text, source, &parsed.spec, &angles, limits)?;
    // loads the file cannot give (no face width, say) leave the kinematics shown, with why
    let (gear_loads, gear_warning) = match gear_loads(text, source, &parsed.spec, limits) {
        Ok(g) => (g, None),
        Err(StudioError::Input { message, .. }) => (None, Some(message)),
        Err(e) => return Err(e),
    };
    let first_error = rows.iter().find_map(|r| r.error.clone());
    Ok(Analysis {
        name: source.name.clone(),
        length_unit: unit.name(),
        oscillating,
        rpm: cam.speed() * 30.0 / std::f64::consts::PI,
        step_deg,
        angles_deg: angles.clone(),
        series,
        frames,
        curves,
        profile,
        nodes,
        nodes_editable,
        pivot: [pivot.x, pivot.y],
        extent: [lo[0], lo[1], hi[0], hi[1]],
        checks,
        warnings: parsed
            .warnings
            .into_iter()
            .map(|w| Placed {
                message: w.message,
                line: w.at.map(|a| a.0),
                column: w.at.map(|a| a.1),
            })
            .chain(gear_warning.map(|message| Placed {
                message,
                line: None,
                column: None,
            }))
            .collect(),
        failed: sweep.failed(),
        first_error,
        dynamics,
        gear_loads,
        system: false,
        simulated: false,
        events: Vec::new(),
        server_ms: t0.elapsed().as_secs_f64() * 1e3,
    })
}

/// The design checks (the library's [`DesignReport`], with the contact's jumps of the sweep),
/// each with the cam angles and profile stretches to mark.
fn checks(
    mech: &Mechanism,
    angles: &[f64],
    sweep: &AnalysisSweep<'_>,
    rows: &[AnalysisRow],
    pressure_limit_deg: f64,
    unit: &str,
) -> Vec<Check> {
    let thetas: Vec<f64> = angles.iter().map(|&a| deg_to_rad(a)).collect();
    let c = mech.design_checks(&thetas, pressure_limit_deg);
    // the time between rows at the cam's speed, for telling a handover from an impulse
    let dt = deg_to_rad(angles.get(1).map_or(1.0, |a| a - angles[0])) / mech.cam().speed().abs();
    let (impulsive, handover) = camkin::report::split_jumps(rows, sweep.jump_at(), dt);
    let report = DesignReport::new(c, unit, mech.follower().is_oscillating())
        .with_jumps(impulsive, handover);
    let profile = mech.cam().profile();
    report
        .verdicts
        .into_iter()
        .map(|v| Check {
            kind: v.check,
            ok: v.passed,
            message: v.message(),
            stretches: v
                .stretches
                .iter()
                .map(|&(a, b)| {
                    (0..=32)
                        .map(|k| {
                            let p = profile.position(a + (b - a) * k as f64 / 32.0);
                            [p.x, p.y]
                        })
                        .collect()
                })
                .collect(),
            angles_deg: v.angles_deg,
        })
        .collect()
}

/// The forces over the revolution when the file has `[dynamics]`.
fn dynamics(
    text: &str,
    source: &Source,
    spec: &MechanismSpec,
    angles: &[f64],
    limits: &Limits,
) -> Result<Option<DynamicsOut>, StudioError> {
    if spec.dynamics.is_none() {
        return Ok(None);
    }
    // the spec already read, built again in SI units
    let options = options(spec, source, true, limits)?;
    let (si, _) = mechfile::build_placed(spec, text, &source.name, &options)?;
    let (Some(params), mech) = (si.dynamics, &si.mechanism) else {
        return Ok(None);
    };
    // the page's force panel is one contact held on by a spring (its jump speed): a
    // form-closed follower's two contacts are `camkin forces`'s
    if mech.is_conjugate() {
        return Ok(None);
    }
    // the library's force report at the page's angles (it fails as a whole where an angle
    // fails: the analysis shows those angles)
    let step_deg = 360.0 / angles.len().max(1) as f64;
    let lub = si.lubrication.as_ref();
    let req = ForceRequest {
        step_deg,
        force_speed: false,
        lubrication: lub.map(|l| l.request),
        face_width: lub.map(|l| l.face_width),
        materials: lub.map(|l| l.materials.clone()).unwrap_or_default(),
        unit: si.length_unit,
        ..ForceRequest::default()
    };
    // a [lubrication] this mechanism cannot take (a knife edge: no line contact) leaves the
    // forces drawn without it (`camkin forces` says why)
    let report = match ForceReport::new(mech, params, &req) {
        Ok(r) => r,
        Err(_) if req.lubrication.is_some() => {
            let plain = ForceRequest {
                lubrication: None,
                face_width: None,
                ..req
            };
            let Ok(r) = ForceReport::new(mech, params, &plain) else {
                return Ok(None);
            };
            r
        }
        Err(_) => return Ok(None),
    };
    let coefficients = report
        .states
        .iter()
        .zip(&report.coefficients)
        .map(|(s, c)| Some([c[0], c[1], c[2], s.lever]))
        .collect();
    let jump = report.jump;
    let rpm = |w: f64| w * 30.0 / std::f64::consts::PI;
    Ok(Some(DynamicsOut {
        rpm: rpm(mech.cam().speed()),
        coefficients,
        jump_rpm: jump.speed.is_finite().then(|| rpm(jump.speed)),
        jump_angle_deg: jump
            .speed
            .is_finite()
            .then(|| angles.get(jump.index).copied())
            .flatten(),
        unit: "N",
        lubrication: report.lubrication.as_ref().map(lubrication_out),
    }))
}

/// Points along a gear pair's path of contact in the studio (as `camkin forces --torque`).
const GEAR_PATH_POINTS: usize = 201;

/// A gear pair's loads when the file has `[gear_loads]` (in SI, drawn in the file's unit).
fn gear_loads(
    text: &str,
    source: &Source,
    spec: &MechanismSpec,
    limits: &Limits,
) -> Result<Option<GearLoadsOut>, StudioError> {
    if spec.gear_loads.is_none() {
        return Ok(None);
    }
    let options = options(spec, source, true, limits)?;
    let (si, _) = mechfile::build_placed(spec, text, &source.name, &options)?;
    let input = |message: String| StudioError::Input { message, at: None };
    let pair = camkin::gears::GearPair::new(&si.mechanism)
        .map_err(|e| input(format!("gear_loads: {e}")))?;
    let resolved = si
        .gear_loads_inputs(&camkin::spec::GivenLoads::default())
        .map_err(|e| input(format!("gear_loads: {e}")))?;
    let lubrication = si.lubrication.as_ref().map(|l| {
        let mut r = l.request;
        // the thermal constants of the materials the loads use
        r.surfaces[0].thermal = resolved.materials.cam.thermal;
        r.surfaces[1].thermal = resolved.materials.follower.thermal;
        r
    });
    let req = camkin::report::GearLoadRequest {
        torque: resolved.torque,
        face_width: resolved.face_width,
        materials: resolved.materials,
        lubrication,
        points: GEAR_PATH_POINTS,
    };
    let l = camkin::report::GearLoads::new(&pair, si.mechanism.cam().speed(), &req)
        .map_err(|e| input(format!("gear_loads: {e}")))?;
    let unit = si.length_unit;
    let len = |x: f64| x / unit.metres();
    let pts = &l.points;
    let lub = req.lubrication.is_some();
    let col = |f: &dyn Fn(&camkin::report::PathPoint) -> Option<f64>| {
        pts.iter().map(f).collect::<Vec<_>>()
    };
    let finite = |x: f64| x.is_finite().then_some(x);
    let at = |i: Option<usize>, v: &dyn Fn(&camkin::report::PathPoint) -> Option<f64>| {
        i.and_then(|i| v(&pts[i]).map(|x| [x, len(pts[i].radius[0])]))
    };
    use camkin::lubrication::Regime;
    Ok(Some(GearLoadsOut {
        unit: unit.name(),
        torque: req.torque,
        normal_force: l.normal_force,
        face_width: len(req.face_width),
        contact_ratio: (l.path[1] - l.path[0]) / l.base_pitch,
        radius: pts.iter().map(|p| len(p.radius[0])).collect(),
        pairs: pts.iter().map(|p| p.pairs).collect(),
        load: pts.iter().map(|p| p.load).collect(),
        hertz_mpa: col(&|p| finite(p.hertz / 1e6)),
        specific_sliding: [
            col(&|p| p.specific_sliding[0]),
            col(&|p| p.specific_sliding[1]),
        ],
        lambda: lub.then(|| col(&|p| p.lambda)),
        regime: lub.then(|| {
            pts.iter()
                .map(|p| {
                    p.regime.map(|r| match r {
                        Regime::Boundary => 0,
                        Regime::Mixed => 1,
                        _ => 2,
                    })
                })
                .collect()
        }),
        flash_temperature_k: lub.then(|| col(&|p| p.flash_temperature)),
        pitch: [len(l.at_pitch.radius[0]), l.at_pitch.hertz / 1e6],
        max_hertz: at(l.max_hertz, &|p| finite(p.hertz / 1e6)),
        min_lambda: at(l.min_lambda, &|p| p.lambda),
        max_flash_k: at(l.max_flash_temperature, &|p| p.flash_temperature),
    }))
}

fn lubrication_out(l: &camkin::report::LubricationReport) -> LubricationOut {
    use camkin::lubrication::Regime;
    let own = |get: &dyn Fn(&camkin::report::LubricationPoint) -> Option<f64>| {
        l.points
            .iter()
            .map(|p| p[0].as_ref().and_then(get))
            .collect()
    };
    let at = |e: camkin::report::Extreme| [e.value, e.cam_angle.to_degrees()];
    LubricationOut {
        lambda: own(&|p| p.lambda),
        regime: l
            .points
            .iter()
            .map(|p| {
                p[0].and_then(|q| q.regime).map(|r| match r {
                    Regime::Boundary => 0,
                    Regime::Mixed => 1,
                    _ => 2,
                })
            })
            .collect(),
        film_minimum_um: own(&|p| p.film.map(|f| f.minimum * 1e6)),
        flash_temperature_k: own(&|p| p.flash_temperature),
        entrainment_reversals_deg: l
            .entrainment_reversals
            .iter()
            .map(|t| t.to_degrees())
            .collect(),
        min_lambda: l.min_lambda.map(at),
        max_flash_k: l.max_flash_temperature.map(at),
        friction: [l.mean_friction_power, l.mean_friction_torque],
    }
}

/// The interpolation study (the paper's section 3) at `step_deg` for node counts `nodes`.
#[derive(Debug, Serialize)]
pub struct Compare {
    /// cam angles, degrees
    pub angles_deg: Vec<f64>,
    /// the acceleration's unit
    pub unit: String,
    /// the exact acceleration
    pub exact: Vec<Option<f64>>,
    /// one run per node count
    pub runs: Vec<CompareRun>,
    /// server time, ms
    pub server_ms: f64,
    /// the acceleration's natural scale (at least ω times the velocity's), in `unit`: the
    /// relative errors' scale when the exact acceleration is zero but for rounding
    pub scale: f64,
    /// why there is no study (a motion that does not repeat every revolution), when there is none
    pub refused: Option<String>,
}

/// One node count of the study.
#[derive(Debug, Serialize)]
pub struct CompareRun {
    /// nodal points per revolution
    pub nodes: usize,
    /// the interpolated acceleration
    pub acceleration: Vec<Option<f64>>,
    /// |a_N − a| / max |a|
    pub rel_error: Vec<Option<f64>>,
    /// largest relative error
    pub max_rel_error: f64,
    /// mean relative error
    pub mean_rel_error: f64,
}

/// The natural scale of the lift and of each of its rates (per second) at the cam speed `omega`
/// (rad/s): each its own largest magnitude, and at least `omega` times the scale of the one
/// before — so that an identically zero rate (an ideal gear pair's acceleration) has the scale of
/// its neighbours, and its rounding noise reads as the zero it is.
pub fn motion_scales(omega: f64, series: [&[Option<f64>]; 4]) -> [f64; 4] {
    let top = |s: &[Option<f64>]| s.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut out = [0.0; 4];
    for k in 0..4 {
        let from_below = if k == 0 {
            0.0
        } else {
            omega.abs() * out[k - 1]
        };
        out[k] = top(series[k]).max(from_below);
    }
    out
}

/// The interpolation study of the mechanism in `text`.
pub fn compare(
    text: &str,
    source: &Source,
    nodes: &[usize],
    step_deg: f64,
    limits: &Limits,
) -> Result<Compare, StudioError> {
    let t0 = Instant::now();
    let parsed = build(text, source, limits)?;
    let mech = &parsed.built.mechanism;
    let angles = revolution(step_deg);
    let total_nodes: usize = nodes.iter().sum();
    check_work(mech, angles.len() + total_nodes, limits)?;
    let units = Units::new(mech, parsed.built.length_unit, AngleUnit::Deg, Per::S);
    let thetas: Vec<f64> = angles.iter().map(|&a| deg_to_rad(a)).collect();
    let states: Vec<_> = mech.analyze_all(&thetas);
    let exact_raw: Vec<f64> = states
        .iter()
        .map(|r| r.as_ref().map_or(f64::NAN, |s| s.acceleration))
        .collect();
    // the paper's relative error is against the largest exact acceleration; an identically zero
    // one (an ideal gear pair's) is measured against its motion's scale instead
    let velocity: Vec<Option<f64>> = states
        .iter()
        .map(|r| r.as_ref().ok().map(|s| s.velocity))
        .collect();
    let position: Vec<Option<f64>> = states
        .iter()
        .map(|r| r.as_ref().ok().map(|s| s.position))
        .collect();
    let accel: Vec<Option<f64>> = exact_raw
        .iter()
        .map(|a| Some(*a).filter(|v| v.is_finite()))
        .collect();
    let scale = motion_scales(mech.cam().speed(), [&position, &velocity, &accel, &[]])[2];
    let top = exact_raw
        .iter()
        .filter(|a| a.is_finite())
        .fold(0.0f64, |m, a| m.max(a.abs()));
    let conv = |a: f64| units.motion(0.0, 0.0, a, None)[2].filter(|v| v.is_finite());
    // a motion that does not repeat (a gear pair's) has no study: the page says why
    if let Err(e) = Interpolated::check_repeats(mech) {
        return Ok(Compare {
            scale: 0.0,
            angles_deg: Vec::new(),
            unit: units.motion_symbol(2),
            exact: Vec::new(),
            runs: Vec::new(),
            server_ms: t0.elapsed().as_secs_f64() * 1e3,
            refused: Some(e.to_string()),
        });
    }
    let mut runs = Vec::new();
    for &n in nodes {
        let it = Interpolated::new(mech, n).map_err(|e| StudioError::Input {
            message: format!("the interpolation with {n} nodes failed: {e}"),
            at: None,
        })?;
        let approx: Vec<f64> = thetas.iter().map(|&t| it.acceleration(t)).collect();
        let mut rel = relative_errors(&exact_raw, &approx);
        if top < 1e-6 * scale {
            rel = exact_raw
                .iter()
                .zip(&approx)
                .map(|(e, a)| (a - e).abs() / scale)
                .collect();
        }
        let (max_rel_error, mean_rel_error) = max_and_mean(&rel);
        runs.push(CompareRun {
            nodes: n,
            acceleration: approx.iter().map(|&a| conv(a)).collect(),
            rel_error: rel
                .iter()
                .map(|&e| Some(e).filter(|v| v.is_finite()))
                .collect(),
            max_rel_error,
            mean_rel_error,
        });
    }
    Ok(Compare {
        refused: None,
        scale: units.motion(0.0, 0.0, scale, None)[2].unwrap_or(0.0).abs(),
        angles_deg: angles,
        unit: units.motion_symbol(2),
        exact: exact_raw.iter().map(|&a| conv(a)).collect(),
        runs,
        server_ms: t0.elapsed().as_secs_f64() * 1e3,
    })
}
