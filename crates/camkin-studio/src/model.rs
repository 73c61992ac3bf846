//! What the studio shows of a cam-follower or gear-pair file: the analysis over a revolution
//! (the plotted series with their units, the mechanism's drawing at every angle), the design
//! checks placed at their cam angles, the interpolation study, the forces. All numbers come from
//! the library; the page only draws them.

use super::answer::{
    revolution, rgb, Analysis, Check, Compare, CompareRun, DynamicsOut, Frame, GearLoadsOut,
    LubricationOut, Placed, Series, ShapeOut, SHARED_POINTS,
};
use super::source::{build, options_for, Source};
use super::{Limits, StudioError};
use crate::mechtext as mechfile;
use crate::scene::mechanism::follower_shapes;
use camkin::cam::Mechanism;
use camkin::curve::Domain;
use camkin::geometry::deg_to_rad;
use camkin::interp::{max_and_mean, relative_errors, Interpolated};
use camkin::report::{DesignReport, ForceReport, ForceRequest};
use camkin::spec::{MechanismSpec, Preset};
use camkin::table::{AnalysisRow, AnalysisSweep, AngleUnit, Per, Units};
use std::time::Instant;

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

/// The analysis of the mechanism (a cam-follower or gear-pair file) in `text` at `step_deg`,
/// checks against `pressure_limit_deg`.
pub fn analyze_mechanism(
    text: &str,
    parsed: &Preset,
    source: &Source,
    step_deg: f64,
    pressure_limit_deg: f64,
    limits: &Limits,
) -> Result<Analysis, StudioError> {
    let t0 = Instant::now();
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
            .iter()
            .map(|w| Placed {
                message: w.message.clone(),
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
    let options = options_for(spec, source, true, limits)?;
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
    let options = options_for(spec, source, true, limits)?;
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
    let at = |p: &Option<camkin::report::PathPoint>,
              v: &dyn Fn(&camkin::report::PathPoint) -> Option<f64>| {
        p.as_ref().and_then(|p| v(p).map(|x| [x, len(p.radius[0])]))
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
        max_hertz: at(&l.max_hertz, &|p| finite(p.hertz / 1e6)),
        min_lambda: at(&l.min_lambda, &|p| p.lambda),
        max_flash_k: at(&l.max_flash_temperature, &|p| p.flash_temperature),
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
    compare_preset(&build(text, source, limits)?, nodes, step_deg, limits)
}

/// The interpolation study of the cam `parsed`.
pub fn compare_preset(
    parsed: &Preset,
    nodes: &[usize],
    step_deg: f64,
    limits: &Limits,
) -> Result<Compare, StudioError> {
    let t0 = Instant::now();
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
