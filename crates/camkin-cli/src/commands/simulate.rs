//! `camkin simulate`: a mechanism's dynamics with lift-off and impacts: a cam-follower file's
//! follower ([`camkin::dynamics::Simulation`]), a system file's bodies
//! ([`camkin::dynamics::SystemSimulation`], output every `--step` degrees of its first driver's
//! angle, or every `--interval` seconds of a `--duration` or its file's `[simulation]`).

use crate::args::RevolutionStep;
use crate::draw::chart::{self, Chart, Series};
use crate::mechfile::{self, BySolver};
use crate::output::{write_atomic, write_cell_table, Cell, Keyed, TableFormat};
use crate::Failure;
use anyhow::anyhow;
use camkin::dynamics::{
    AugmentedLagrangian, DynamicsError, Event, Sample, Simulation, SystemSimulation,
};
use camkin::table::Units;
use camkin::table::{
    event_cells, event_columns, sample_cells, sample_columns, system_event_cells,
    system_event_columns, system_sample_cells, system_sample_columns, EventRow, SampleRow,
};
use rayon::prelude::*;
use std::io::Write;
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub struct SimulateArgs {
    /// Mechanism file (TOML) with a `[dynamics]` section, or a system file (`[[body]]`, `[[joint]]`,
    /// …) with one (see docs/systems.md, "Dynamics of a system").
    pub mechanism: PathBuf,
    /// Cam revolutions to simulate (a system: its first driver's) [default: 1; a system file
    /// with `[simulation]`: its duration instead].
    #[arg(long, value_name = "N", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub revolutions: Option<f64>,
    /// A system file: simulate this many seconds from t = 0 (outputs every --interval), with or
    /// without drivers; instead of its `[simulation]` duration or --revolutions.
    #[arg(long, value_name = "S", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub duration: Option<f64>,
    /// A run in time's output interval, seconds [default: its file's, or a thousandth of the
    /// duration].
    #[arg(long, value_name = "S", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub interval: Option<f64>,
    /// Output interval, degrees of cam angle (a system: of its first driver); the integration's
    /// steps are chosen by --rtol and --atol, the outputs interpolated between them.
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
    /// Relative tolerance of the integration: each step's error is kept below RTOL times each
    /// coordinate's size plus ATOL times its scale (the steps are chosen by it).
    #[arg(long, value_name = "RTOL", default_value = "1e-10", value_parser = crate::args::real)]
    pub rtol: f64,
    /// Absolute tolerance of the integration, as a fraction of each coordinate's scale (a
    /// length's: the mechanism's size; an angle's: a radian; a rate's: those over its time
    /// scale).
    #[arg(long, value_name = "ATOL", default_value = "1e-10", value_parser = crate::args::real)]
    pub atol: f64,
    /// The integrator: `explicit` (Dormand–Prince 5(4)), `implicit` (SDIRK 4(3), L-stable: for
    /// stiff systems, a damper far faster than the motion), or `auto` (implicit where the
    /// fastest rate is a damper's decay over ten times the fastest vibration's and the
    /// motion's).
    #[arg(long, value_name = "SCHEME", default_value = "auto", value_parser = clap::builder::PossibleValuesParser::new(camkin::dynamics::Scheme::NAMES))]
    pub integrator: String,
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
    /// With --no-follow: revolutions simulated at each speed before those judged, so that they
    /// start from the settled periodic state at that speed (a spring's surge set going by the
    /// start has run its course).
    #[arg(long, value_name = "N", default_value_t = 1.0, value_parser = crate::args::real)]
    pub settle: f64,
    /// A system file whose contacts have a `lash`: every lashed contact's lash set to FROM, then
    /// up by STEP to TO (the file's length unit), a run of --revolutions at each; each one's
    /// take-up and seating angle and speed printed instead of the time series (with --out:
    /// lash.csv and the speeds against the lash, lash.svg and lash.png).
    #[arg(long, value_name = "FROM:TO:STEP", allow_hyphen_values = true)]
    pub lash: Option<String>,
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
        | DynamicsError::Unassembled { .. }
        | DynamicsError::DeadPoint { .. }
        | DynamicsError::StepUnderflow { .. }
        | DynamicsError::ImplicitNewton { .. }
        | DynamicsError::Adjuster { .. } => Failure::Input(anyhow!("{e}")),
        _ => Failure::Internal(anyhow!("{e}")),
    }
}

/// `--rtol` and `--atol` checked, as the flags name them.
pub(super) fn tolerances(rtol: f64, atol: f64) -> Result<camkin::dynamics::Tolerances, Failure> {
    let t = camkin::dynamics::Tolerances {
        relative: rtol,
        absolute: atol,
    };
    match t.out_of_range() {
        Some((which, value)) => Err(Failure::Input(anyhow!(
            "--{}: {} must be from 1e-13 to 0.01",
            if which == "relative" { "rtol" } else { "atol" },
            camkin::human::human(value)
        ))),
        None => Ok(t),
    }
}

pub fn run(args: &SimulateArgs) -> Result<(), Failure> {
    let revolutions = args.revolutions.unwrap_or(1.0);
    if !(revolutions.is_finite() && revolutions > 0.0 && revolutions <= 1e4) {
        return Err(Failure::Input(anyhow!(
            "--revolutions: {} must be in (0, 10000]",
            camkin::human::human(revolutions)
        )));
    }
    let step = args.step.deg();
    let tolerances = tolerances(args.rtol, args.atol)?;
    let scheme =
        camkin::dynamics::Scheme::from_name(&args.integrator).expect("clap keeps to Scheme::NAMES");
    let outputs = (revolutions * 360.0 / step).round() as usize;
    if outputs > 10_000_000 {
        return Err(Failure::Input(anyhow!(
            "{outputs} output rows is more than 10000000"
        )));
    }
    // the model picks its solver: a system file ([[body]], [[joint]], …, [dynamics]) is
    // simulated as a system, a cam preset in metres by its one-coordinate model
    let model = mechfile::load_model(Some(&args.mechanism), true)?;
    for (flag, given) in [("--no-follow", &args.no_follow), ("--lash", &args.lash)] {
        if given.is_some() && model.model.preset().is_some() {
            return Err(Failure::Input(anyhow!(
                "{flag}: for a system file ([[body]], [[joint]], …, [dynamics]); {} is a mechanism file",
                model.model.name()
            )));
        }
    }
    let (preset, name) = match model.by_solver(false)? {
        BySolver::General {
            name, mut built, ..
        } => {
            built.dynamics.tolerances = tolerances;
            built.dynamics.scheme = scheme;
            return run_system(args, &name, &built);
        }
        BySolver::Cam { preset, name, .. } => (preset, name),
    };
    if args.duration.is_some() || args.interval.is_some() {
        return Err(Failure::Input(anyhow!(
            "--{}: a run in time is for a system file ([[body]], [[joint]], …, [dynamics]); {name} is a cam-follower file, simulated over --revolutions of its cam",
            if args.duration.is_some() { "duration" } else { "interval" }
        )));
    }
    let unit = preset.built.length_unit;
    let params = mechfile::dynamics_of(&preset.built, &name)?;
    let mech = preset.built.mechanism;
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
    sim.set_tolerances(tolerances).map_err(dyn_err)?;
    sim.set_scheme(scheme);
    let h = step.to_radians() / mech.cam().speed();
    crate::refuse_large(
        &sim.run_work(&mech, outputs, h),
        args.work.large,
        ", or simulate fewer --revolutions",
    )?;
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let pb = indicatif::ProgressBar::new(outputs as u64);
    let run = sim
        .run(outputs, h, |k| {
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
    if let Some(last) = samples.last() {
        // the balance in the file's unit (the run's is in J)
        let b = last.balance.scaled(1.0 / unit.metres());
        crate::say!("camkin: {}", b.describe(unit.name()));
    }
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
    let motion = Chart::new(
        "follower position: dynamic and kinematic",
        "cam angle (°)",
        format!("position ({pu})"),
        vec![
            Series::line("dynamic", pts(&|k| c(samples[k].position))),
            Series::dashed(
                "kinematic (contact method)",
                pts(&|k| c(rows[k].kinematic_position)),
            ),
        ],
    );
    chart::save(&motion, &dir.join("motion"))?;
    // the two positions differ by microns where they differ at all: their difference, drawn
    let deviation = Chart::new(
        "follower position less the kinematic one (lift-off, play)",
        "cam angle (°)",
        format!("dynamic − kinematic position ({pu})"),
        vec![Series::line(
            "dynamic − kinematic",
            pts(&|k| c(samples[k].position) - c(rows[k].kinematic_position)),
        )],
    );
    chart::save(&deviation, &dir.join("deviation"))?;
    let acc = Chart::new(
        "follower acceleration: dynamic and kinematic",
        "cam angle (°)",
        format!("acceleration ({au})"),
        vec![
            Series::line("dynamic", pts(&|k| c(samples[k].acceleration))),
            Series::dashed(
                "kinematic (contact method)",
                pts(&|k| c(rows[k].kinematic_acceleration)),
            ),
        ],
    );
    chart::save(&acc, &dir.join("acceleration"))?;
    let force = Chart::new(
        "contact force (0 while the follower is off the cam)",
        "cam angle (°)",
        "contact force (N)",
        vec![
            Series::line("contact force", pts(&|k| samples[k].contact_force)),
            Series::dashed("zero", pts(&|_| 0.0)),
        ],
    );
    chart::save(&force, &dir.join("contact_force"))?;
    Ok(())
}

pub(super) fn bad(m: String) -> Failure {
    Failure::Input(anyhow!(m))
}

/// Input errors (exit 2) and the rest.
pub(super) fn system_err(name: &str, e: DynamicsError) -> Failure {
    match e {
        DynamicsError::Element { .. }
        | DynamicsError::System(_)
        | DynamicsError::Unassembled { .. }
        | DynamicsError::DeadPoint { .. }
        | DynamicsError::StepUnderflow { .. }
        | DynamicsError::Tolerance { .. }
        | DynamicsError::Adjuster { .. }
        | DynamicsError::Chatter { .. } => bad(format!("{name}: {e}")),
        _ => Failure::Internal(anyhow!("{name}: {e}")),
    }
}

/// Simulates the system `built` (read from `name`) over `outputs` output intervals:
/// the samples as CSV (stdout, or `time_series.csv` with `--out`), its lift-offs and impacts as
/// a table on stderr (and `events.csv`), the pages of its motion and forces.
fn run_system(
    args: &SimulateArgs,
    name: &str,
    built: &camkin::spec::BuiltSystem,
) -> Result<(), Failure> {
    if args.start_angle != 0.0 {
        return Err(bad(format!(
            "--start-angle: {}: a system starts where its file puts it (its bodies' poses, at driver angle 0)",
            camkin::human::human(args.start_angle)
        )));
    }
    if args.format != TableFormat::Csv {
        return Err(bad(
            "--format json: a system's time series is written as CSV".into(),
        ));
    }
    let sys = &built.system;
    let unit = built.length_unit.name();
    let step = args.step.deg();
    if let Some(range) = &args.lash {
        return super::lash_sweep::run(args, name, built, range);
    }
    if let Some(range) = &args.no_follow {
        if args.duration.is_some() || args.interval.is_some() {
            return Err(bad(format!(
                "--no-follow {range}: a speed sweep simulates revolutions of the first driver, not a --duration"
            )));
        }
        if built.time_of(0.0).is_none() {
            return Err(plan_err(name, camkin::spec::PlanError::NotAnAngle));
        }
        return no_follow(args, name, built, range);
    }
    let (plan, mut sim) = built
        .plan_asked(&camkin::spec::RunSettings {
            revolutions: args.revolutions,
            step_deg: step,
            duration: args.duration,
            interval: args.interval,
        })
        .map_err(|e| plan_err(name, e))?;
    // with --out, the pages' reference run at a tenth of the speed (of a sweep)
    let timed = plan.step_deg.is_none();
    crate::refuse_large(
        &built.run_work(&plan, &sim, args.out.is_some() && !timed, None),
        args.work.large,
        if timed {
            ", or simulate a shorter --duration"
        } else {
            ", or simulate fewer --revolutions"
        },
    )?;
    let start = sim.start_report();
    for line in start
        .describe(sys, unit)
        .iter()
        .chain(&start.closed_contacts(sys))
    {
        crate::say!("camkin: {line}");
    }
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let angle_of = |t: f64| plan.angle_of(t);
    let pb = indicatif::ProgressBar::new(plan.outputs as u64);
    let run = sim
        .run(plan.outputs, plan.h_out, |k| {
            if k % 256 == 0 {
                pb.set_position(k as u64);
            }
            std::ops::ControlFlow::Continue(())
        })
        .map_err(|e| system_err(name, e))?;
    let (samples, events) = (run.samples, run.events);
    pb.finish_and_clear();
    let rows: Vec<Vec<Cell>> = samples
        .iter()
        .enumerate()
        .map(|(k, s)| system_sample_cells(plan.angle_at(k), s, &built.dynamics.hertz))
        .collect();
    let columns = system_sample_columns(sys, unit, &built.dynamics.hertz, !timed);
    let event_columns = system_event_columns(unit, !timed);
    let event_rows: Vec<Vec<Cell>> = events
        .iter()
        .map(|e| system_event_cells(sys, e, angle_of(e.time)))
        .collect();
    let series =
        |w: &mut dyn std::io::Write| write_cell_table(w, TableFormat::Csv, &columns, rows.clone());
    match od {
        None => write_atomic(None, series).map_err(Failure::Internal)?,
        Some(od) => {
            let dir = od.path().to_path_buf();
            write_atomic(Some(&dir.join("time_series.csv")), series).map_err(Failure::output)?;
            write_atomic(Some(&dir.join("events.csv")), |w| {
                write_cell_table(w, TableFormat::Csv, &event_columns, event_rows.clone())
            })
            .map_err(Failure::output)?;
            // the energy balance element by element
            let gravity = built.dynamics.gravity != camkin::Vec2::zeros();
            let energy_rows: Vec<Vec<Cell>> = samples
                .iter()
                .enumerate()
                .map(|(k, s)| camkin::table::system_energy_cells(plan.angle_at(k), s, gravity))
                .collect();
            let energy_columns = camkin::table::system_energy_columns(sys, unit, gravity, !timed);
            write_atomic(Some(&dir.join("energy.csv")), |w| {
                write_cell_table(w, TableFormat::Csv, &energy_columns, energy_rows.clone())
            })
            .map_err(Failure::output)?;
            let impacts = events
                .iter()
                .filter(|e| e.kind == camkin::dynamics::EventKind::Impact);
            if timed {
                crate::draw::simulation::write_timed(&dir, name, built, &samples, impacts.count())
                    .map_err(Failure::output)?;
            } else {
                // the same system at a tenth of the speed: its motion nearly quasi-static
                // (inertia forces a hundredth), the reference of the deviation plot
                let slow = built.quasi_static(&plan).map_err(|e| system_err(name, e))?;
                let impacts: Vec<f64> = impacts.filter_map(|e| angle_of(e.time)).collect();
                crate::draw::simulation::write(&dir, name, built, &samples, &slow, step, &impacts)
                    .map_err(Failure::output)?;
            }
            od.commit().map_err(Failure::output)?;
        }
    }
    // the energy balance at the end, for people
    if let Some(last) = samples.last() {
        crate::say!("camkin: {}", last.balance.describe(unit));
    }
    // each coil spring's surge, for people
    for c in &built.coil_springs {
        let f = c.surge_frequencies(built.dynamics.metres_per_unit);
        if f.is_empty() {
            continue;
        }
        let shown: Vec<String> = f
            .iter()
            .take(4)
            .map(|x| camkin::human::human(x.round()))
            .collect();
        crate::say!(
            "camkin: {:?}: surge frequencies {}{} Hz ({} lumped masses, both ends held)",
            c.name,
            shown.join(", "),
            if f.len() > 4 { ", …" } else { "" },
            c.masses
        );
    }
    // each hydraulic lash adjuster's chamber over the run, for people
    for (k, h) in sys.lash_adjusters().iter().enumerate() {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for x in &samples {
            lo = lo.min(x.adjusters[k].pressure);
            hi = hi.max(x.adjusters[k].pressure);
        }
        if let (Some(first), Some(last)) = (samples.first(), samples.last()) {
            // to a millionth of its chamber's drawn height (the integration's rounding below)
            let q = 1e-6 * h.adjuster.chamber;
            let grown = ((last.adjusters[k].chamber - first.adjusters[k].chamber) / q).round() * q;
            crate::say!(
                "camkin: lash adjuster {:?}: pressure {} to {} bar; its chamber {} {unit} longer at the end than at the start",
                h.name,
                crate::forces_text::num(lo / 1e5),
                crate::forces_text::num(hi / 1e5),
                crate::forces_text::num(grown)
            );
        }
    }
    // each lashed contact's take-up and seating, for people
    for l in &built.lash {
        crate::say!(
            "camkin: {}",
            super::lash_sweep::describe(built, l, &events, |t| plan.angle_of(t))
        );
    }
    // the events, for people
    if events.is_empty() && !sys.contacts().is_empty() {
        crate::say!("camkin: no lift-off or impact: every contact stays as it started");
    } else if !events.is_empty() {
        crate::say!(
            "{:>9} {:>20} {:>14} {:>18} {:>22}",
            "event",
            "contact",
            "time (s)",
            if timed { "" } else { "driver angle (°)" },
            format!("approach speed ({unit}/s)")
        );
        for e in events.iter().take(50) {
            let c = sys
                .contacts()
                .get(e.contact)
                .map_or("?", |c| c.name.as_str());
            crate::say!(
                "{:>9} {:>20} {:>14.9} {:>18} {:>22.4}",
                match e.kind {
                    camkin::dynamics::EventKind::LiftOff => "lift-off",
                    _ => "impact",
                },
                c,
                e.time,
                angle_of(e.time).map_or(String::new(), |a| format!("{a:.4}")),
                e.approach
            );
        }
        if events.len() > 50 {
            crate::say!(
                "… {} events in all (see events.csv with --out)",
                events.len()
            );
        }
    }
    Ok(())
}

/// The flag of a run's setting.
fn flag_of(field: camkin::spec::PlanField) -> &'static str {
    use camkin::spec::PlanField;
    match field {
        PlanField::Revolutions => "--revolutions",
        PlanField::Duration => "--duration",
        PlanField::Interval => "--interval",
        _ => "--step",
    }
}

/// A run's plan refused, as the command's flags name it.
pub(super) fn plan_err(name: &str, e: camkin::spec::PlanError) -> Failure {
    use camkin::spec::{PlanError, PlanField};
    match e {
        PlanError::OutOfRange {
            field,
            value,
            range,
        } => bad(format!("{}: {value} must be {range}", flag_of(field))),
        PlanError::Both {
            field: PlanField::Interval,
            other: PlanField::Step,
        } => bad(
            "--interval: is the output interval of a run in time: give --duration SECONDS with it (or [simulation] duration = … in the file)".into(),
        ),
        PlanError::Both { field, other } => {
            bad(format!("{} with {}: {e}", flag_of(field), flag_of(other)))
        }
        PlanError::Dynamics(e) => system_err(name, e),
        PlanError::NotAnAngle => bad(format!(
            "{name}: its first driver does not turn an angle at a constant speed, so it is not simulated over revolutions: simulate it for a time (camkin simulate --duration SECONDS, or [simulation] duration = … in the file)"
        )),
        e => bad(format!("{name}: {e}")),
    }
}

/// `FROM:TO:STEP` given to `flag` as its three numbers, or refused saying how to write it
/// (`how`: its unit and an example).
pub(super) fn from_to_step(flag: &str, range: &str, how: &str) -> Result<[f64; 3], Failure> {
    let parts: Vec<&str> = range.split(':').collect();
    let nums: Vec<f64> = parts.iter().filter_map(|p| p.trim().parse().ok()).collect();
    match (&nums[..], parts.len()) {
        (&[from, to, step], 3) => Ok([from, to, step]),
        _ => Err(bad(format!("{flag} {range}: give FROM:TO:STEP {how}"))),
    }
}

/// `--no-follow FROM:TO:STEP`: the speed sweep, its answer printed.
fn no_follow(
    args: &SimulateArgs,
    name: &str,
    built: &camkin::spec::BuiltSystem,
    range: &str,
) -> Result<(), Failure> {
    let [from, to, step] = from_to_step("--no-follow", range, "in rpm (e.g. 1000:6000:250)")?;
    if !(from > 0.0 && to > from && step > 0.0 && to.is_finite()) {
        return Err(bad(format!(
            "--no-follow {range}: FROM, TO and STEP must be positive rpm with TO above FROM"
        )));
    }
    let sweep = camkin::dynamics::SpeedSweep {
        from_rpm: from,
        to_rpm: to,
        step_rpm: step,
        tolerance_rpm: 1.0,
        step_deg: args.step.deg(),
        revolutions: args.revolutions.unwrap_or(1.0),
        after_impact_deg: 5.0,
        settle_revolutions: args.settle,
    };
    // the speeds tried and the bisection's, each a run at its speed
    let sys = &built.system;
    let sim =
        SystemSimulation::new(sys, built.dynamics.clone()).map_err(|e| system_err(name, e))?;
    let (steps, samples) = sweep.work(&sim);
    crate::refuse_large(
        &camkin::work::Work::system_simulation(sys, steps, samples, 0),
        args.work.large,
        ", or sweep fewer speeds (a larger STEP, a narrower FROM:TO)",
    )?;
    let found = camkin::dynamics::no_follow_speed(sys, &built.dynamics, &sweep)
        .map_err(|e| system_err(name, e))?;
    let h = camkin::human::human;
    match found {
        Some(nf) => {
            let contact = sys
                .contacts()
                .get(nf.contact)
                .map_or("?", |c| c.name.as_str());
            println!(
                "no-follow speed: {} rpm ({} rpm follows): contact {contact:?} opens at {}° of the driver",
                h((nf.speed_rpm * 10.0).round() / 10.0),
                h((nf.following_rpm * 10.0).round() / 10.0),
                h((nf.angle_deg * 10.0).round() / 10.0),
            );
            println!(
                "found by simulating {} revolution(s) at speeds from {} rpm in {} rpm steps and bisecting to 1 rpm ({} simulations)",
                h(args.revolutions.unwrap_or(1.0)),
                h(from),
                h(step),
                nf.simulations
            );
        }
        None => println!(
            "no contact that stays closed at {} rpm opens up to {} rpm",
            h(from),
            h(to)
        ),
    }
    Ok(())
}
