//! `camkin simulate`: the cam-follower mechanism's dynamics with lift-off and impacts.

use crate::args::RevolutionStep;
use crate::draw::chart::{self, Chart, Series};
use crate::mechfile;
use crate::output::{write_atomic, write_cell_table, Cell, Keyed, TableFormat};
use crate::Failure;
use anyhow::anyhow;
use camkin::dynamics::{AugmentedLagrangian, DynamicsError, Event, Sample, Simulation, StepAdvice};
use camkin::table::Units;
use camkin::table::{
    event_cells, event_columns, sample_cells, sample_columns, EventRow, SampleRow,
};
use rayon::prelude::*;
use std::io::Write;
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub struct SimulateArgs {
    /// Mechanism file (TOML) with a `[dynamics]` section, or a system file (`[[body]]`, `[[joint]]`,
    /// …) with one (see docs/systems.md, "Dynamics of a system").
    pub mechanism: PathBuf,
    /// Cam revolutions to simulate (a system: its first driver's).
    #[arg(long, value_name = "N", default_value_t = 1.0, value_parser = crate::args::real, allow_negative_numbers = true)]
    pub revolutions: f64,
    /// Output interval, degrees of cam angle (a system: of its first driver).
    #[arg(long, value_name = "DEG", default_value = "1")]
    pub step: RevolutionStep,
    /// Cam angle at time 0, degrees (the follower starts on the cam there).
    #[arg(
        long,
        value_name = "DEG",
        default_value_t = 0.0,
        value_parser = crate::args::real,
        allow_negative_numbers = true
    )]
    pub start_angle: f64,
    /// Integration steps per output interval.
    #[arg(long, value_name = "K", default_value_t = 1)]
    pub substeps: usize,
    /// Directory for the time series, the events and the plots; the time series goes to stdout
    /// without it.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Format of the time series.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    pub format: TableFormat,
    /// A system file's no-follow speed: its driver's speed raised from FROM to TO rpm in steps of
    /// STEP (a revolution simulated at each) until a contact that stays closed at FROM opens,
    /// then bisected to 1 rpm; printed instead of the time series.
    #[arg(long, value_name = "FROM:TO:STEP")]
    pub no_follow: Option<String>,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
    #[command(flatten)]
    pub force: crate::out_dir::ForceArg,
}

fn dyn_err(e: DynamicsError) -> Failure {
    match e {
        DynamicsError::Invalid { .. }
        | DynamicsError::Kinematics { .. }
        | DynamicsError::ContactJumps { .. }
        | DynamicsError::FormClosed
        | DynamicsError::Interference { .. }
        | DynamicsError::Chatter { .. }
        | DynamicsError::StepTooLong { .. } => Failure::Input(anyhow!("{e}")),
        _ => Failure::Internal(anyhow!("{e}")),
    }
}

pub fn run(args: &SimulateArgs) -> Result<(), Failure> {
    if !(args.revolutions.is_finite() && args.revolutions > 0.0 && args.revolutions <= 1e4) {
        return Err(Failure::Input(anyhow!(
            "--revolutions: {} must be in (0, 10000]",
            camkin::human::human(args.revolutions)
        )));
    }
    let step = args.step.deg();
    if !(1..=1000).contains(&args.substeps) {
        return Err(Failure::Input(anyhow!(
            "--substeps: {} must be from 1 to 1000",
            args.substeps
        )));
    }
    let outputs = (args.revolutions * 360.0 / step).round() as usize;
    if outputs > 10_000_000 {
        return Err(Failure::Input(anyhow!(
            "{outputs} output rows is more than 10000000"
        )));
    }
    let steps = outputs as f64 * args.substeps as f64;
    // a system file ([[body]], [[joint]], …, [dynamics]) is simulated as a system
    let (name, text) =
        crate::mechfile::read_text(&args.mechanism).map_err(|e| Failure::Input(anyhow!(e)))?;
    if camkin::spec::text::is_system(&text) {
        return super::system_simulate::run(args, &name, &text, outputs);
    }
    if args.no_follow.is_some() {
        return Err(Failure::Input(anyhow!(
            "--no-follow: for a system file ([[body]], [[joint]], …, [dynamics]); {} is a mechanism file",
            name
        )));
    }
    let (mech, params, unit) =
        mechfile::load_dynamics(&args.mechanism).map_err(|e| Failure::Input(anyhow!(e)))?;
    let units = Units::plain(&mech, unit);
    // the simulation computes in metres: lengths back to the file's unit
    let k_len = if units.oscillating {
        1.0
    } else {
        1.0 / unit.metres()
    };
    if !args.start_angle.is_finite() {
        return Err(Failure::Input(anyhow!(
            "--start-angle: {} must be finite",
            args.start_angle
        )));
    }
    let mut sim = Simulation::starting_at(
        &mech,
        params,
        AugmentedLagrangian::default(),
        camkin::geometry::deg_to_rad(args.start_angle),
    )
    .map_err(dyn_err)?;
    // the model chosen (the one-coordinate model searches every curve's first touch each
    // step), the jump scan at the start (every 0.25°) and the kinematic motion beside every row
    // (about 200 bytes a row held)
    crate::refuse_large(
        &sim.work(steps)
            .and(&camkin::work::Work::sweep(&mech, 1441 + outputs, 1))
            .with_bytes(outputs as f64 * 200.0),
        args.work.large,
        ", or simulate fewer --revolutions",
    )?;
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let w = mech.cam().speed();
    let h = step.to_radians() / w / args.substeps as f64;
    // the damping and the spring must be resolved by the time step (the library refuses a longer
    // one): say what would do it, within the flags' ranges
    if let Some(advice) = sim.step_advice(step, args.substeps, w, 1000, RevolutionStep::MIN_DEG) {
        let (rate, field, value) = sim.fastest_rate();
        let h_ = camkin::human::human;
        let fix = match advice {
            StepAdvice::Substeps(n) => format!("use --substeps {n} or more"),
            StepAdvice::FinerStep { step_deg } => {
                format!("use --substeps 1000 and --step {}° or finer", h_(step_deg))
            }
            StepAdvice::FasterCam { rpm } => format!(
                "the cam turns too slowly for outputs by cam angle (at most 1000 substeps of a {}° step): raise cam.speed_rpm to at least {} rpm",
                h_(RevolutionStep::MIN_DEG),
                h_(rpm)
            ),
            _ => "use a finer --step".into(),
        };
        return Err(Failure::Input(anyhow!(
            "{field} = {}: too stiff for the time step {} s ({}° / ω / {} substeps): the follower's fastest rate is {} /s (c/m = {} /s, √(k/m) = {} /s); {fix}",
            h_(value),
            h_(h),
            h_(step),
            args.substeps,
            h_(rate),
            h_(params.damping / params.moving_mass(&mech.follower_joint())),
            h_((params.spring_stiffness / params.moving_mass(&mech.follower_joint())).sqrt()),
        )));
    }
    let pb = indicatif::ProgressBar::new(outputs as u64);
    let run = sim
        .run(outputs, args.substeps, h, |k| {
            pb.set_position(k as u64);
            std::ops::ControlFlow::Continue(())
        })
        .map_err(dyn_err)?;
    let (samples, events) = (run.samples, run.events);
    pb.finish_and_clear();
    // the kinematic motion at the same cam angles (the contact method)
    let thetas: Vec<f64> = samples.iter().map(|s| s.cam_angle).collect();
    let kin = mech.analyze_all(&thetas);
    let rows: Vec<SampleRow> = samples
        .iter()
        .zip(&kin)
        .map(|(s, k)| SampleRow::new(s, k.as_ref().ok()))
        .collect();
    let event_rows: Vec<EventRow> = events.iter().map(EventRow::from).collect();
    let sample_columns = sample_columns(&units);
    let sample_cells: Vec<Vec<Cell>> = rows.par_iter().map(|r| sample_cells(r, &units)).collect();
    let event_columns = event_columns(&units);
    let event_cells: Vec<Vec<Cell>> = event_rows.iter().map(|e| event_cells(e, &units)).collect();
    let series = |w: &mut dyn Write| -> anyhow::Result<()> {
        match args.format {
            TableFormat::Json => {
                let samples: Vec<Keyed<'_>> = sample_cells
                    .iter()
                    .map(|c| Keyed(&sample_columns, c))
                    .collect();
                let events: Vec<Keyed<'_>> = event_cells
                    .iter()
                    .map(|c| Keyed(&event_columns, c))
                    .collect();
                #[derive(serde::Serialize)]
                struct Series<'a> {
                    samples: &'a [Keyed<'a>],
                    events: &'a [Keyed<'a>],
                }
                serde_json::to_writer(
                    &mut *w,
                    &Series {
                        samples: &samples,
                        events: &events,
                    },
                )?;
                writeln!(w)?;
                Ok(())
            }
            TableFormat::Csv => {
                write_cell_table(w, TableFormat::Csv, &sample_columns, sample_cells.clone())
            }
        }
    };
    match od {
        None => write_atomic(None, series).map_err(Failure::Internal)?,
        Some(od) => {
            let dir = &od.path().to_path_buf();
            let ext = if args.format == TableFormat::Json {
                "json"
            } else {
                "csv"
            };
            write_atomic(Some(&dir.join(format!("time_series.{ext}"))), series)
                .map_err(Failure::output)?;
            write_atomic(Some(&dir.join("events.csv")), |w| {
                write_cell_table(w, TableFormat::Csv, &event_columns, event_cells.clone())
            })
            .map_err(Failure::output)?;
            plot(&samples, &rows, dir, &units, k_len).map_err(Failure::output)?;
            od.commit().map_err(Failure::output)?;
        }
    }
    report(&events, unit, mech.is_conjugate());
    Ok(())
}

/// The events as a table on stderr.
fn report(events: &[Event], unit: camkin::spec::LengthUnit, conjugate: bool) {
    if events.is_empty() {
        crate::say!("camkin: no lift-off: the follower stays on the cam");
        return;
    }
    crate::say!(
        "{:>9} {:>14} {:>15} {:>18}{}",
        "event",
        "time (s)",
        "cam angle (°)",
        format!("impact speed ({}/s)", unit.name()),
        if conjugate { "  curve" } else { "" }
    );
    for e in events.iter().take(50) {
        let row = EventRow::from(e);
        crate::say!(
            "{:>9} {:>14.9} {:>15.6} {:>18.6}{}",
            row.event,
            e.time,
            e.cam_angle.to_degrees(),
            e.impact_velocity / unit.metres(),
            if conjugate {
                format!("  {}", row.curve)
            } else {
                String::new()
            }
        );
    }
    if events.len() > 50 {
        crate::say!(
            "… {} events in all (see events.csv with --out)",
            events.len()
        );
    }
}

fn plot(
    samples: &[Sample],
    rows: &[SampleRow],
    dir: &std::path::Path,
    u: &Units,
    k_len: f64,
) -> anyhow::Result<()> {
    let (pu, au) = (u.motion_symbol(0), u.motion_symbol(2));
    let c = |x: f64| u.coord_value(k_len * x);
    let pts = |f: &dyn Fn(usize) -> f64| -> Vec<(f64, f64)> {
        samples
            .iter()
            .enumerate()
            .map(|(k, s)| (s.cam_angle.to_degrees(), f(k)))
            .collect()
    };
    let motion = Chart {
        title: "follower position: dynamic and kinematic".into(),
        x_label: "cam angle (°)".into(),
        y_label: format!("position ({pu})"),
        series: vec![
            Series {
                name: "dynamic".into(),
                points: pts(&|k| c(samples[k].position)),
                dashed: false,
            },
            Series {
                name: "kinematic (contact method)".into(),
                points: pts(&|k| c(rows[k].kinematic_position)),
                dashed: true,
            },
        ],
        log_y: false,
        x_range: None,
    };
    chart::save(&motion, &dir.join("motion"))?;
    // the two positions differ by microns where they differ at all: their difference, drawn
    let deviation = Chart {
        title: "follower position less the kinematic one (lift-off, play)".into(),
        x_label: "cam angle (°)".into(),
        y_label: format!("dynamic − kinematic position ({pu})"),
        series: vec![Series {
            name: "dynamic − kinematic".into(),
            points: pts(&|k| c(samples[k].position) - c(rows[k].kinematic_position)),
            dashed: false,
        }],
        log_y: false,
        x_range: None,
    };
    chart::save(&deviation, &dir.join("deviation"))?;
    let acc = Chart {
        title: "follower acceleration: dynamic and kinematic".into(),
        x_label: "cam angle (°)".into(),
        y_label: format!("acceleration ({au})"),
        series: vec![
            Series {
                name: "dynamic".into(),
                points: pts(&|k| c(samples[k].acceleration)),
                dashed: false,
            },
            Series {
                name: "kinematic (contact method)".into(),
                points: pts(&|k| c(rows[k].kinematic_acceleration)),
                dashed: true,
            },
        ],
        log_y: false,
        x_range: None,
    };
    chart::save(&acc, &dir.join("acceleration"))?;
    let force = Chart {
        title: "contact force (0 while the follower is off the cam)".into(),
        x_label: "cam angle (°)".into(),
        y_label: "contact force (N)".into(),
        series: vec![
            Series {
                name: "contact force".into(),
                points: pts(&|k| samples[k].contact_force),
                dashed: false,
            },
            Series {
                name: "zero".into(),
                points: pts(&|_| 0.0),
                dashed: true,
            },
        ],
        log_y: false,
        x_range: None,
    };
    chart::save(&force, &dir.join("contact_force"))?;
    Ok(())
}
