//! The studio on a system file (`[[body]]`, `[[joint]]`, …) whose every degree of freedom is
//! driven: every body and contact drawn at each instant of a revolution of its first driver, the slider turning that driver, and each
//! moving body's main coordinate (the one that moves most) and its acceleration plotted. The
//! page draws it with the cam's code: the frames' shapes are the command's `plot` drawing
//! ([`crate::scene::system::system_scene`]), a body's closed curve kept once in its frame.

use super::answer::{revolution, Analysis, CellTable, Frame, Placed, Series, ShapeOut};
use super::{Limits, StudioError};
use crate::scene::mechanism::Shape;
use crate::scene::system::system_scene;
use camkin::body::Pose;
use camkin::curve::Domain;
use camkin::spec::BuiltSystem;
use camkin::system::{Coordinate, SystemError, SystemState};
use std::time::Instant;

/// A revolution solved: the driver angles (degrees), their instants (s), each instant's state.
type Solved = (Vec<f64>, Vec<f64>, Vec<Result<SystemState, SystemError>>);

/// The instants of a revolution of the first driver at `step_deg`, each solved in turn; the
/// work refused over the limits first.
fn solve(built: &BuiltSystem, step_deg: f64, limits: &Limits) -> Result<Solved, StudioError> {
    let sys = &built.system;
    let angles = revolution(step_deg);
    let work = camkin::work::Work::system(sys, angles.len());
    if let Some(r) = work.refusal_within(limits.max_seconds, camkin::work::BYTES_LIMIT) {
        return Err(StudioError::TooMuch {
            message: format!(
                "{r}, more than the {} s one request may take; use `camkin analyze` for it",
                limits.max_seconds
            ),
        });
    }
    let input = |message: String| StudioError::Input { message, at: None };
    let times = built
        .times(&angles)
        .map_err(|e| input(built.explain_sweep(&e)))?;
    let states: Vec<_> = sys
        .instants(&times)
        .map_err(|e| {
            input(format!(
                "the system cannot be analysed at its first instant: {}",
                built.explain(&e)
            ))
        })?
        .collect();
    Ok((angles, times, states))
}

/// The studio's analysis of a system swept kinematically (every degree of freedom driven),
/// read from `name`.
pub fn analyze(
    built: &BuiltSystem,
    name: &str,
    step_deg: f64,
    limits: &Limits,
) -> Result<Analysis, StudioError> {
    let t0 = Instant::now();
    let sys = &built.system;
    let unit = built.length_unit.name();
    let (angles, _, states) = solve(built, step_deg, limits)?;
    let size = sys.size();
    let scenes = states.iter().map(|s| {
        s.as_ref().ok().map(|s| {
            let poses: Vec<Pose> = s.bodies.iter().map(|b| b.pose).collect();
            (system_scene(sys, s, size), poses)
        })
    });
    let (frames, curves, extent) = scene_frames(sys, scenes);
    let series = body_series(built, &states, unit);
    let failed = states.iter().filter(|s| s.is_err()).count();
    let first_error = states
        .iter()
        .find_map(|s| s.as_ref().err().map(|e| e.to_string()));
    Ok(Analysis {
        failed,
        first_error,
        ..system_analysis(
            built,
            name,
            step_deg,
            (angles, series),
            (frames, curves, extent),
            t0,
        )
    })
}

/// A system's analysis for the page: its drawing, its series, the file's warnings; nothing
/// failed, not simulated, no events (the callers say otherwise).
pub(super) fn system_analysis(
    built: &BuiltSystem,
    name: &str,
    step_deg: f64,
    (angles, series): (Vec<f64>, Vec<Series>),
    (frames, curves, extent): (Vec<Frame>, Vec<Vec<[f64; 2]>>, [f64; 4]),
    t0: Instant,
) -> Analysis {
    Analysis {
        name: name.to_string(),
        length_unit: built.length_unit.name(),
        oscillating: false,
        rpm: built
            .time_of(std::f64::consts::TAU)
            .map_or(0.0, |t| 60.0 / t),
        step_deg,
        angles_deg: angles,
        series,
        frames,
        curves,
        profile: Vec::new(),
        nodes: Vec::new(),
        nodes_editable: false,
        pivot: [0.0, 0.0],
        extent,
        checks: Vec::new(),
        warnings: built
            .warnings
            .iter()
            .map(|w| Placed {
                message: w.to_string(),
                line: None,
                column: None,
            })
            .collect(),
        failed: 0,
        first_error: None,
        dynamics: None,
        gear_loads: None,
        system: true,
        simulated: false,
        events: Vec::new(),
        server_ms: t0.elapsed().as_secs_f64() * 1e3,
    }
}

/// Each instant's scene (its shapes and the bodies' poses; none where it failed) as the page's
/// frames, each contact's closed curves kept once in their bodies' frames, and the extent.
pub(super) fn scene_frames(
    sys: &camkin::system::System,
    scenes: impl Iterator<Item = Option<(Vec<Shape>, Vec<Pose>)>>,
) -> (Vec<Frame>, Vec<Vec<[f64; 2]>>, [f64; 4]) {
    // each contact's closed curves, kept once in their bodies' frames
    let nc = sys.contacts().len();
    let curves: Vec<Vec<[f64; 2]>> = sys
        .contacts()
        .iter()
        .flat_map(|c| [&c.curve_a, &c.curve_b])
        .map(|curve| match curve.domain() {
            Domain::Periodic { period } => (0..720)
                .map(|k| {
                    let p = curve.position(period * f64::from(k) / 720.0);
                    [p.x, p.y]
                })
                .collect(),
            _ => Vec::new(),
        })
        .collect();
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    let mut grow = |p: [f64; 2], r: f64| {
        lo = [lo[0].min(p[0] - r), lo[1].min(p[1] - r)];
        hi = [hi[0].max(p[0] + r), hi[1].max(p[1] + r)];
    };
    let mut frames = Vec::new();
    for scene in scenes {
        let Some((scene, poses)) = scene else {
            frames.push(Frame {
                cam: [0.0, 0.0, 0.0],
                contact: None,
                normal: None,
                follower: Vec::new(),
            });
            continue;
        };
        let shapes: Vec<ShapeOut> = scene
            .into_iter()
            .enumerate()
            .map(|(k, shape)| match shape {
                Shape::Polyline {
                    color,
                    width,
                    closed: true,
                    pts,
                } if k < 2 * nc => {
                    pts.iter().for_each(|p| grow([p.x, p.y], 0.0));
                    let c = &sys.contacts()[k / 2];
                    let id = if k % 2 == 0 { c.a } else { c.b };
                    let pose = id.index().map_or([0.0; 3], |i| {
                        let p = poses[i];
                        [p.origin.x, p.origin.y, p.angle]
                    });
                    ShapeOut::Curve {
                        i: k,
                        pose,
                        color: super::answer::rgb(color),
                        width,
                    }
                }
                other => ShapeOut::from(other),
            })
            .collect();
        for sh in &shapes {
            match sh {
                ShapeOut::Line { pts, .. } => pts.iter().for_each(|p| grow(*p, 0.0)),
                ShapeOut::Circle { c, r, .. } => grow(*c, *r),
                ShapeOut::Dot { p, .. } => grow(*p, 0.0),
                ShapeOut::Curve { .. } => {}
            }
        }
        frames.push(Frame {
            cam: [0.0, 0.0, 0.0],
            contact: None,
            normal: None,
            follower: shapes,
        });
    }
    (frames, curves, [lo[0], lo[1], hi[0], hi[1]])
}

/// Each moving body that no driver moves: its coordinate that moves most over the revolution
/// (an angle counted times the system's size), and that coordinate's acceleration.
fn body_series(
    built: &BuiltSystem,
    states: &[Result<SystemState, SystemError>],
    unit: &'static str,
) -> Vec<Series> {
    let sys = &built.system;
    let size = sys.size();
    let mut out = Vec::new();
    for (i, b) in sys.bodies().iter().enumerate() {
        if sys.drivers().iter().any(|d| d.body.index() == Some(i)) {
            continue;
        }
        let value = |s: &SystemState, c: Coordinate| -> [f64; 2] {
            let st = &s.bodies[i];
            match c {
                Coordinate::X => [st.pose.origin.x, st.acceleration.x],
                Coordinate::Y => [st.pose.origin.y, st.acceleration.y],
                Coordinate::Angle => [st.pose.angle.to_degrees(), st.alpha.to_degrees()],
            }
        };
        let range = |c: Coordinate| {
            let (mut a, mut z) = (f64::INFINITY, f64::NEG_INFINITY);
            for s in states.iter().flatten() {
                let v = value(s, c)[0];
                a = a.min(v);
                z = z.max(v);
            }
            let r = (z - a).max(0.0);
            if c == Coordinate::Angle {
                r.to_radians() * size
            } else {
                r
            }
        };
        let coordinate = [Coordinate::X, Coordinate::Y, Coordinate::Angle]
            .into_iter()
            .max_by(|p, q| range(*p).total_cmp(&range(*q)))
            .unwrap_or(Coordinate::Angle);
        let (u0, u2) = match coordinate {
            Coordinate::Angle => ("°".to_string(), "°/s²".to_string()),
            _ => (unit.to_string(), format!("{unit}/s²")),
        };
        // rounding: a position to 1e-12 of the size (an angle of a revolution), an acceleration
        // to 1e-9 of the driver's ω² times the size (ω² for an angle)
        let w2 = built
            .time_of(1.0)
            .filter(|t| *t != 0.0)
            .map_or(0.0, |t| 1.0 / (t * t));
        let (r0, r2) = match coordinate {
            Coordinate::Angle => (1e-12 * 360.0, 1e-9 * w2.to_degrees()),
            _ => (1e-12 * size, 1e-9 * w2 * size),
        };
        let values = |k: usize| -> Vec<Option<f64>> {
            states
                .iter()
                .map(|s| {
                    s.as_ref()
                        .ok()
                        .map(|s| value(s, coordinate)[k])
                        .filter(|v| v.is_finite())
                })
                .collect()
        };
        let what = match coordinate {
            Coordinate::Angle => "angle",
            Coordinate::X => "x",
            Coordinate::Y => "y",
        };
        out.push(Series {
            key: format!("{}_{what}", b.name),
            label: format!("{} {what}", b.name),
            unit: u0,
            values: values(0),
            resolution: Some(r0),
        });
        out.push(Series {
            key: format!("{}_{what}_acceleration", b.name),
            label: format!("{} {what} acceleration", b.name),
            unit: u2,
            values: values(1),
            resolution: Some(r2),
        });
    }
    out
}

/// The system table at `step_deg` over a revolution: what `camkin analyze FILE --angles
/// 0:360:STEP` writes.
pub fn table(
    built: &BuiltSystem,
    step_deg: f64,
    limits: &Limits,
) -> Result<CellTable, StudioError> {
    let (angles, times, states) = solve(built, step_deg, limits)?;
    let columns = camkin::table::system_columns(built);
    let rows = states
        .iter()
        .enumerate()
        .map(|(k, s)| camkin::table::system_cells(&built.system, angles[k], times[k], s))
        .collect();
    Ok((columns, rows))
}
