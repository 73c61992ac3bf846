//! `camkin simulate SYSTEM.toml --lash FROM:TO:STEP`: the lash sweep
//! ([`camkin::spec::BuiltSystem::lash_sweep`]): each lash run over the file's revolutions, each
//! lashed contact's take-up and seating angles and speeds printed, and with `--out` the table
//! (`lash.csv`) and the speeds against the lash (`lash.svg`, `lash.png`).

use super::simulate::{bad, plan_err, SimulateArgs};
use crate::draw::chart::{self, Chart, Series};
use crate::forces_text::num;
use crate::output::{write_atomic, write_cell_table, TableFormat};
use crate::Failure;
use camkin::spec::{BuiltSystem, LashError};
use camkin::table::{lash_cells, lash_columns, Cell, LashRow};

/// The most lashes a sweep runs.
const MAX_LASHES: usize = 200;

/// The lashes of `FROM:TO:STEP` (the file's length unit): FROM, FROM + STEP, … up to TO.
fn lashes(range: &str) -> Result<Vec<f64>, Failure> {
    let [from, to, step] = super::simulate::from_to_step(
        "--lash",
        range,
        "in the file's length unit (e.g. 0.1:0.4:0.05)",
    )?;
    if !(from >= 0.0 && to >= from && step > 0.0 && to.is_finite()) {
        return Err(bad(format!(
            "--lash {range}: FROM must be 0 or more, TO no less than FROM and STEP positive"
        )));
    }
    // the count first: a tiny STEP would make millions
    let n = ((to - from) / step * (1.0 + 1e-9)).floor() + 1.0;
    if n > MAX_LASHES as f64 {
        return Err(bad(format!(
            "--lash {range}: {} lashes is more than {MAX_LASHES} (a larger STEP)",
            camkin::human::human(n)
        )));
    }
    // each a round number of the step's decimals (0.15, not 0.15000000000000002)
    Ok((0..n as usize)
        .map(|k| {
            let x = from + k as f64 * step;
            (x * 1e12).round() / 1e12
        })
        .collect())
}

/// Runs the sweep of `range` over `built` (read from `name`) and prints it.
pub fn run(
    args: &SimulateArgs,
    name: &str,
    built: &BuiltSystem,
    range: &str,
) -> Result<(), Failure> {
    if args.no_follow.is_some() || args.duration.is_some() || args.interval.is_some() {
        return Err(bad(format!(
            "--lash {range}: a lash sweep simulates revolutions of the first driver at the file's speed: leave out --no-follow, --duration and --interval"
        )));
    }
    let lashes = lashes(range)?;
    let revolutions = args.revolutions.unwrap_or(1.0);
    let step = args.step.deg();
    let unit = built.length_unit.name();
    let lash_err = |e: LashError| match e {
        LashError::Plan(e) => plan_err(name, e),
        LashError::Invalid { value, reason } => {
            bad(format!("--lash {range}: a lash of {value} {unit} {reason}"))
        }
        e @ LashError::NoLash => bad(format!("--lash {range}: {name}: {e}")),
        e => Failure::Internal(anyhow::anyhow!("{name}: {e}")),
    };
    // every lash is checked before any runs
    for &l in &lashes {
        built.with_lash(l).map_err(lash_err)?;
    }
    crate::refuse_large(
        &built
            .lash_sweep_work(lashes.len(), revolutions, step)
            .map_err(lash_err)?,
        args.work.large,
        ", or sweep fewer lashes (a larger STEP)",
    )?;
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let rows = built
        .lash_sweep(&lashes, revolutions, step)
        .map_err(lash_err)?;
    if let Some(od) = od {
        let dir = od.path().to_path_buf();
        let cells: Vec<Vec<Cell>> = rows.iter().map(lash_cells).collect();
        write_atomic(Some(&dir.join("lash.csv")), |w| {
            write_cell_table(w, TableFormat::Csv, &lash_columns(unit), cells.clone())
        })
        .map_err(Failure::output)?;
        chart::save(&speeds_chart(&rows, name, unit), &dir.join("lash"))
            .map_err(Failure::output)?;
        od.commit().map_err(Failure::output)?;
    }
    print(&rows, unit, revolutions, built.system.first_driver_rpm());
    Ok(())
}

/// The take-up and seating speeds against the lash, a line for each lashed contact.
fn speeds_chart(rows: &[LashRow], name: &str, unit: &str) -> Chart {
    let mut contacts: Vec<&str> = Vec::new();
    for r in rows {
        if !contacts.contains(&r.contact.as_str()) {
            contacts.push(&r.contact);
        }
    }
    let mut series = Vec::new();
    for c in contacts {
        let of = |f: fn(&LashRow) -> Option<f64>| -> Vec<(f64, f64)> {
            rows.iter()
                .filter(|r| r.contact == c)
                .filter_map(|r| f(r).map(|v| (r.lash, v)))
                .collect()
        };
        series.push(Series::line(
            format!("{c}: seating speed"),
            of(|r| r.seating_speed),
        ));
        series.push(Series::dashed(
            format!("{c}: take-up speed"),
            of(|r| r.take_up_speed),
        ));
    }
    Chart::new(
        format!("{name}: seating and take-up speed against the lash"),
        format!("lash ({unit})"),
        format!("approach speed ({unit}/s)"),
        series,
    )
}

/// The rows for people: angles to 0.01°, speeds to four significant digits.
fn print(rows: &[LashRow], unit: &str, revolutions: f64, rpm: f64) {
    let h = camkin::human::human;
    let angle = |a: Option<f64>| a.map_or("—".into(), |a| format!("{:.2}", a));
    let speed = |v: Option<f64>| v.map_or("—".into(), num);
    println!(
        "lash sweep at {} rpm, {} revolution(s) each: take-up (the cam's contact closing) and seating (the valve on its seat)",
        num(rpm),
        h(revolutions)
    );
    println!(
        "{:>10} {:>20} {:>12} {:>16} {:>12} {:>16} {:>12}",
        format!("lash ({unit})"),
        "contact",
        "take-up (°)",
        format!("speed ({unit}/s)"),
        "seating (°)",
        format!("speed ({unit}/s)"),
        "seat"
    );
    for r in rows {
        println!(
            "{:>10} {:>20} {:>12} {:>16} {:>12} {:>16} {:>12}",
            h(r.lash),
            r.contact,
            angle(r.take_up_angle_deg),
            speed(r.take_up_speed),
            angle(r.seating_angle_deg),
            speed(r.seating_speed),
            r.seat.as_deref().unwrap_or("—")
        );
    }
}

/// A lashed contact's take-up and seating among a run's `events`, in words (`angle_of`: the
/// driver's angle at an instant, none in a run in time).
pub fn describe(
    built: &BuiltSystem,
    l: &camkin::spec::Lashed,
    events: &[camkin::dynamics::ContactEvent],
    angle_of: impl Fn(f64) -> Option<f64>,
) -> String {
    let unit = built.length_unit.name();
    let name = |k: usize| built.system.contacts()[k].name.as_str();
    let at = |e: &camkin::dynamics::ContactEvent| {
        let when = match angle_of(e.time) {
            Some(a) => format!("{:.2}°", a),
            None => format!("{} s", num(e.time)),
        };
        format!("at {when}, {} {unit}/s", num(e.approach))
    };
    let head = format!(
        "{:?}, lash {} {unit}:",
        name(l.contact),
        camkin::human::human(l.lash)
    );
    match camkin::spec::LashCycle::find(events, l.contact) {
        None => format!("{head} never taken up"),
        Some(c) => match c.seating {
            Some(s) => format!(
                "{head} taken up {}; seated on {:?} {}",
                at(&c.take_up),
                name(s.contact),
                at(&s)
            ),
            None => format!("{head} taken up {}; no seating follows", at(&c.take_up)),
        },
    }
}
