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

pub(super) fn bad(m: String) -> Failure {
    Failure::Input(anyhow!(m))
}

/// Input errors (exit 2) and the rest.
pub(super) fn dyn_err(name: &str, e: DynamicsError) -> Failure {
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
    if let Some(range) = &args.no_follow {
        if built.time_of(0.0).is_none() {
            return Err(plan_err(name, camkin::spec::PlanError::NotAnAngle));
        }
        return no_follow(args, name, &built, range);
    }
    let (plan, mut sim) = built
        .plan(args.revolutions, step, Some(args.substeps))
        .map_err(|e| plan_err(name, e))?;
    // with --out, the pages' reference run at a tenth of the speed: ten times the steps at
    // least (its time step is as the stiffest element needs)
    let reference = if args.out.is_some() { 11 } else { 1 };
    crate::refuse_large(
        &camkin::work::Work::system_simulation(sys, plan.steps() * reference, outputs + 1),
        args.work.large,
        ", or simulate fewer --revolutions",
    )?;
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let angle_of = |t: f64| plan.angle_of(t);
    let pb = indicatif::ProgressBar::new(outputs as u64);
    let run = sim
        .run(plan.outputs, plan.substeps, plan.h(), |k| {
            if k % 256 == 0 {
                pb.set_position(k as u64);
            }
            std::ops::ControlFlow::Continue(())
        })
        .map_err(|e| dyn_err(name, e))?;
    let (samples, events) = (run.samples, run.events);
    pb.finish_and_clear();
    let grid = camkin::table::AngleGrid::new(0.0, step);
    let rows: Vec<Vec<Cell>> = samples
        .iter()
        .enumerate()
        .map(|(k, s)| system_sample_cells(grid.at(k), s, &built.dynamics.hertz))
        .collect();
    let columns = system_sample_columns(sys, unit, &built.dynamics.hertz);
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
            // the same system at a tenth of the speed: its motion nearly quasi-static (inertia
            // forces a hundredth), the reference of the deviation plot
            let slow = built.quasi_static(&plan).map_err(|e| dyn_err(name, e))?;
            let impacts: Vec<f64> = events
                .iter()
                .filter(|e| e.kind == camkin::dynamics::EventKind::Impact)
                .map(|e| angle_of(e.time))
                .collect();
            super::system_pages::write(&dir, name, &built, &samples, &slow, step, &impacts)
                .map_err(Failure::output)?;
            od.commit().map_err(Failure::output)?;
        }
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

/// A run's plan refused, as the command's flags name it.
pub(super) fn plan_err(name: &str, e: camkin::spec::PlanError) -> Failure {
    use camkin::spec::{PlanError, PlanField};
    let h = camkin::human::human;
    match e {
        PlanError::OutOfRange {
            field,
            value,
            range,
        } => {
            let flag = match field {
                PlanField::Revolutions => "--revolutions",
                PlanField::Step => "--step",
                _ => "--substeps",
            };
            bad(format!("{flag}: {value} must be {range}"))
        }
        PlanError::TooStiff {
            element,
            rate,
            step,
            step_deg,
            substeps,
            max_step,
            need,
        } => bad(format!(
            "{name}: {element} is too stiff for the time step {} s ({}° of the driver / {substeps} substeps): its rate is {} /s, so the step must be at most {} s; use --substeps {need} or more",
            h(step),
            h(step_deg),
            h(rate),
            h(max_step),
        )),
        PlanError::Dynamics(e) => dyn_err(name, e),
        e => bad(format!("{name}: {e}")),
    }
}

/// `--no-follow FROM:TO:STEP`: the speed sweep, its answer printed.
fn no_follow(
    args: &SimulateArgs,
    name: &str,
    built: &camkin::spec::BuiltSystem,
    range: &str,
) -> Result<(), Failure> {
    let parts: Vec<&str> = range.split(':').collect();
    let nums: Vec<f64> = parts.iter().filter_map(|p| p.trim().parse().ok()).collect();
    let [from, to, step] = nums[..] else {
        return Err(bad(format!(
            "--no-follow {range}: give FROM:TO:STEP in rpm (e.g. 1000:6000:250)"
        )));
    };
    if parts.len() != 3 || !(from > 0.0 && to > from && step > 0.0 && to.is_finite()) {
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
        revolutions: args.revolutions,
        after_impact_deg: 5.0,
    };
    // the steps of the speeds tried and the bisection's, each a run at its speed (the fastest's
    // time step the stiffest element's)
    let sys = &built.system;
    let runs = ((to - from) / step).ceil() + (step.max(1.0)).log2().ceil() + 1.0;
    let sim = SystemSimulation::new(sys, built.dynamics.clone()).map_err(|e| dyn_err(name, e))?;
    let per_rev_steps = {
        let w = to * std::f64::consts::TAU / 60.0;
        let h_out = args.step.deg().to_radians() / w;
        (360.0 / args.step.deg()) * sim.substeps(h_out) as f64
    };
    let steps = (runs * per_rev_steps * args.revolutions) as usize;
    crate::refuse_large(
        &camkin::work::Work::system_simulation(sys, steps, 0),
        args.work.large,
        ", or sweep fewer speeds (a larger STEP, a narrower FROM:TO)",
    )?;
    let found = camkin::dynamics::no_follow_speed(sys, &built.dynamics, &sweep)
        .map_err(|e| dyn_err(name, e))?;
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
                h(args.revolutions),
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
