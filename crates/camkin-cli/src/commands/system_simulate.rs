//! `camkin simulate SYSTEM.toml`: a system's dynamics (`camkin::dynamics::SystemSimulation`),
//! output every `--step` degrees of its first driver's angle: the samples as CSV (stdout, or
//! `time_series.csv` with `--out`), its lift-offs and impacts as a table on stderr (and
//! `events.csv`).

use super::simulate::SimulateArgs;
use crate::output::{write_atomic, write_cell_table, Cell, TableFormat};
use crate::Failure;
use anyhow::anyhow;
use camkin::dynamics::{DynamicsError, SystemSimulation};
use camkin::table::{
    system_event_cells, system_event_columns, system_sample_cells, system_sample_columns,
};

fn bad(m: String) -> Failure {
    Failure::Input(anyhow!(m))
}

/// Input errors (exit 2) and the rest.
fn dyn_err(name: &str, e: DynamicsError) -> Failure {
    match e {
        DynamicsError::Element { .. }
        | DynamicsError::System(_)
        | DynamicsError::SystemStepTooLong { .. }
        | DynamicsError::Chatter { .. } => bad(format!("{name}: {e}")),
        _ => Failure::Internal(anyhow!("{name}: {e}")),
    }
}

/// Simulates the system file `text` (read from `name`) over `outputs` output intervals.
pub fn run(args: &SimulateArgs, name: &str, text: &str, outputs: usize) -> Result<(), Failure> {
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
    let built = super::system::load(&args.mechanism, name, text)?;
    let sys = &built.system;
    let unit = built.length_unit.name();
    let step = args.step.deg();
    let time_of = |deg: f64| built.time_of(deg.to_radians());
    let (Some(t0), Some(t1)) = (time_of(0.0), time_of(step)) else {
        return Err(bad(format!(
            "{name}: its first driver does not turn an angle at a constant speed: a simulation's outputs are at its angles"
        )));
    };
    let h = (t1 - t0).abs() / args.substeps as f64;
    let mut sim =
        SystemSimulation::new(sys, built.dynamics.clone()).map_err(|e| dyn_err(name, e))?;
    let steps = outputs * args.substeps;
    crate::refuse_large(
        &camkin::work::Work::system_simulation(sys, steps, outputs + 1),
        args.work.large,
        ", or simulate fewer --revolutions",
    )?;
    // the stiffest element bounds the step: say how many substeps would do
    let max_step = sim.max_step();
    if h > max_step {
        let (rate, element) = sim.fastest_rate();
        let need = ((t1 - t0).abs() / max_step).ceil();
        return Err(bad(format!(
            "{name}: {element} is too stiff for the time step {} s ({}° of the driver / {} substeps): its rate is {} /s, so the step must be at most {} s; use --substeps {need} or more",
            camkin::human::human(h),
            camkin::human::human(step),
            args.substeps,
            camkin::human::human(rate),
            camkin::human::human(max_step),
        )));
    }
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let angle_of = |t: f64| step * (t - t0) / (t1 - t0);
    let pb = indicatif::ProgressBar::new(outputs as u64);
    let mut rows: Vec<Vec<Cell>> = Vec::with_capacity(outputs + 1);
    let mut events = Vec::new();
    let first = sim.sample().map_err(|e| dyn_err(name, e))?;
    rows.push(system_sample_cells(0.0, &first));
    for k in 1..=outputs {
        for _ in 0..args.substeps {
            let e = sim.advance(h).map_err(|e| dyn_err(name, e))?;
            events.extend(e);
        }
        let s = sim.sample().map_err(|e| dyn_err(name, e))?;
        rows.push(system_sample_cells(step * k as f64, &s));
        if k % 256 == 0 {
            pb.set_position(k as u64);
        }
    }
    pb.finish_and_clear();
    let columns = system_sample_columns(sys, unit);
    let event_columns = system_event_columns(unit);
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
            od.commit().map_err(Failure::output)?;
        }
    }
    // the events, for people
    if events.is_empty() {
        crate::say!("camkin: no lift-off or impact: every contact stays as it started");
    } else {
        crate::say!(
            "{:>9} {:>20} {:>14} {:>18} {:>22}",
            "event",
            "contact",
            "time (s)",
            "driver angle (°)",
            format!("approach speed ({unit}/s)")
        );
        for e in events.iter().take(50) {
            let c = sys
                .contacts()
                .get(e.contact)
                .map_or("?", |c| c.name.as_str());
            crate::say!(
                "{:>9} {:>20} {:>14.9} {:>18.4} {:>22.4}",
                match e.kind {
                    camkin::dynamics::EventKind::LiftOff => "lift-off",
                    _ => "impact",
                },
                c,
                e.time,
                angle_of(e.time),
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
