//! The studio on a system file with `[dynamics]` (the valve train): a revolution of its first
//! driver simulated (`camkin::dynamics::SystemSimulation`, as `camkin simulate` does it), each
//! output step drawn from the simulation's poses, and the force panel: each free body's main
//! coordinate and its acceleration (a coil spring's lumped masses left out), each contact's
//! force (those that ever close), its Hertz pressure, and each driver's torque, all on the
//! slider's angle.

use super::answer::{Analysis, CellTable, Event, Series};
use super::kinematic::scene_frames;
use super::{Limits, StudioError};
use crate::scene::system::{scene_at, Touch};
use camkin::body::Pose;
use camkin::dynamics::{EventKind, SystemRun};
use camkin::spec::{BuiltSystem, PlanError, RunPlan};
use std::time::Instant;

/// A revolution of `built` simulated at `step_deg` outputs (the library's plan: the steps
/// chosen by its tolerances); the work refused over the limits first.
pub(super) fn simulate(
    built: &BuiltSystem,
    step_deg: f64,
    limits: &Limits,
) -> Result<(SystemRun, RunPlan), StudioError> {
    let input = |message: String| StudioError::Input { message, at: None };
    let (plan, mut sim) = built.plan(1.0, step_deg).map_err(|e| match e {
        PlanError::NotAnAngle => input(
            "its first driver does not turn an angle at a constant speed: the studio shows a simulated system over its revolution".into(),
        ),
        e => input(format!("the system cannot be simulated: {e}")),
    })?;
    let work = built.run_work(&plan, &sim, false, None);
    if let Some(r) = work.refusal_within(limits.max_seconds, camkin::work::BYTES_LIMIT) {
        return Err(StudioError::TooMuch {
            message: format!(
                "{r}, more than the {} s one request may take; use `camkin simulate` for it",
                limits.max_seconds
            ),
        });
    }
    let run = sim
        .run(plan.outputs, plan.h_out, |_| {
            std::ops::ControlFlow::Continue(())
        })
        .map_err(|e| input(format!("the simulation stopped: {e}")))?;
    Ok((run, plan))
}

/// The studio's analysis of a simulated system (see the module docs).
pub fn analyze(
    built: &BuiltSystem,
    name: &str,
    step_deg: f64,
    limits: &Limits,
) -> Result<Analysis, StudioError> {
    let t0 = Instant::now();
    let sys = &built.system;
    let unit = built.length_unit.name();
    let (run, plan) = simulate(built, step_deg, limits)?;
    let samples = &run.samples;
    let size = sys.size();
    let nb = sys.bodies().len();
    let scenes = samples.iter().map(|s| {
        let poses: Vec<Pose> = (0..nb)
            .map(|i| {
                Pose::new(
                    camkin::Point2::new(s.q[3 * i], s.q[3 * i + 1]),
                    s.q[3 * i + 2],
                )
            })
            .collect();
        let touches: Vec<Touch> = s
            .pairings
            .iter()
            .zip(&s.in_contact)
            .map(|(p, &closed)| {
                p.map_or(
                    Touch {
                        u_a: 0.0,
                        u_b: 0.0,
                        point: camkin::Point2::origin(),
                        normal: camkin::Vec2::x(),
                        closed: false,
                    },
                    |p| Touch {
                        u_a: p.u_a,
                        u_b: p.u_b,
                        point: p.point_a,
                        normal: p.normal.into_inner(),
                        closed,
                    },
                )
            })
            .collect();
        Some((scene_at(sys, &poses, &touches, size), poses))
    });
    let (frames, curves, extent) = scene_frames(sys, scenes);
    let angles: Vec<f64> = (0..samples.len()).map(|k| step_deg * k as f64).collect();
    let mut series = Vec::new();
    // each free body's coordinate that moves most and its acceleration (a coil's lumped masses
    // left out: the panel would be theirs)
    let coil = |name: &str| built.coil_springs.iter().any(|c| name.starts_with(&c.name));
    for (i, b) in sys.bodies().iter().enumerate() {
        if sys.drivers().iter().any(|d| d.body.index() == Some(i)) || coil(&b.name) {
            continue;
        }
        let range = |c: usize| {
            let (lo, hi) = samples
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, z), s| {
                    (a.min(s.q[3 * i + c]), z.max(s.q[3 * i + c]))
                });
            (hi - lo) * if c == 2 { size } else { 1.0 }
        };
        let c = (0..3)
            .max_by(|p, q| range(*p).total_cmp(&range(*q)))
            .unwrap_or(2);
        let what = ["x", "y", "angle"][c];
        let (to, u0, u2) = if c == 2 {
            (
                180.0 / std::f64::consts::PI,
                "°".to_string(),
                "°/s²".to_string(),
            )
        } else {
            (1.0, unit.to_string(), format!("{unit}/s²"))
        };
        let values = |f: &dyn Fn(&camkin::dynamics::SystemSample) -> f64| {
            samples
                .iter()
                .map(|s| Some(f(s)).filter(|v| v.is_finite()))
                .collect()
        };
        // from its start: a plunger's hundredths of a millimetre read as such
        let start = samples.first().map_or(0.0, |s| s.q[3 * i + c]);
        series.push(Series {
            key: format!("{}_{what}", b.name),
            label: format!("{} {what} from its start", b.name),
            unit: u0,
            values: values(&|s| to * (s.q[3 * i + c] - start)),
            resolution: None,
        });
        series.push(Series {
            key: format!("{}_{what}_acceleration", b.name),
            label: format!("{} {what} acceleration", b.name),
            unit: u2,
            values: values(&|s| to * s.qdd[3 * i + c]),
            resolution: None,
        });
    }
    // the force panel
    for (k, c) in sys.contacts().iter().enumerate() {
        if !samples.iter().any(|s| s.in_contact[k]) {
            continue;
        }
        series.push(Series {
            key: format!("{}_force", c.name),
            label: format!("{} force", c.name),
            unit: "N".into(),
            values: samples.iter().map(|s| Some(s.contact_forces[k])).collect(),
            resolution: None,
        });
        if samples.iter().any(|s| s.hertz_pa[k].is_some()) {
            series.push(Series {
                key: format!("{}_hertz", c.name),
                label: format!("{} Hertz pressure", c.name),
                unit: "MPa".into(),
                values: samples
                    .iter()
                    .map(|s| s.hertz_pa[k].map(|p| p * 1e-6))
                    .collect(),
                resolution: None,
            });
        }
    }
    let u = built.dynamics.metres_per_unit;
    for (d, driver) in sys.drivers().iter().enumerate() {
        let (scale, what, unit) = match driver.coordinate {
            camkin::system::Coordinate::Angle => (u, "torque", "N·m"),
            _ => (1.0, "force", "N"),
        };
        series.push(Series {
            key: format!("{}_{what}", driver.name),
            label: format!("{} {what}", driver.name),
            unit: unit.into(),
            values: samples
                .iter()
                .map(|s| s.driver_efforts.get(d).map(|e| e * scale))
                .collect(),
            resolution: None,
        });
    }
    // the impacts, for people: where and how fast
    // a run over the driver's angle (`BuiltSystem::plan`) has one at every instant
    let angle_of = |t: f64| plan.angle_of(t).unwrap_or(f64::NAN);
    let events: Vec<Event> = run
        .events
        .iter()
        .filter(|e| e.kind == EventKind::Impact)
        .map(|e| Event {
            message: format!(
                "impact of {:?} at {}°: {} m/s",
                sys.contacts()
                    .get(e.contact)
                    .map_or("?", |c| c.name.as_str()),
                camkin::human::human((angle_of(e.time) * 100.0).round() / 100.0),
                camkin::human::human((e.approach * u * 1e4).round() / 1e4),
            ),
            angle_deg: angle_of(e.time),
        })
        .collect();
    Ok(Analysis {
        simulated: true,
        events,
        ..super::kinematic::system_analysis(
            built,
            name,
            step_deg,
            (angles, series),
            (frames, curves, extent),
            t0,
        )
    })
}

/// The simulated revolution's time series: what `camkin simulate FILE --step STEP` writes.
pub fn table(
    built: &BuiltSystem,
    step_deg: f64,
    limits: &Limits,
) -> Result<CellTable, StudioError> {
    let (run, _) = simulate(built, step_deg, limits)?;
    let columns = camkin::table::system_sample_columns(
        &built.system,
        built.length_unit.name(),
        &built.dynamics.hertz,
        true,
    );
    let rows = run
        .samples
        .iter()
        .enumerate()
        .map(|(k, s)| {
            camkin::table::system_sample_cells(Some(step_deg * k as f64), s, &built.dynamics.hertz)
        })
        .collect();
    Ok((columns, rows))
}
