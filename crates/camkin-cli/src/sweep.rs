//! A system swept over its angle (the first driver's, or a cam's) by `camkin analyze` and
//! `camkin contacts`: the instants of the angles asked, the work refused first, the rows written
//! 4096 instants at a time.

use crate::Failure;
use anyhow::anyhow;
use camkin::spec::BuiltSystem;
use camkin::system::{SystemError, SystemState};
use camkin::table::Cell;

fn bad(m: String) -> Failure {
    Failure::Input(anyhow!(m))
}

/// The instants at the sweep's angles (degrees): the first driver's, or a cam's.
pub fn times_of(built: &BuiltSystem, name: &str, angles: &[f64]) -> Result<Vec<f64>, Failure> {
    built.times(angles).map_err(|e| {
        bad(format!(
            "{name}: --at, --angles: {}",
            built.explain_sweep(&e)
        ))
    })
}

/// The system `built` (read from `name`) swept in order through `angles` (of `--at` or
/// `--angles`), each instant's rows made by `cells` and written 4096 instants at a time under
/// `columns`; the work refused first when it is over the limits. A system that cannot be
/// analysed at its first instant (a loop that does not close, a redundant joint, a driver on a
/// coordinate a joint fixes) is a bad file, named by its element. Warns of the first instant
/// that could not be solved (its rows hold the reason).
pub fn write_sweep(
    table: &crate::args::TableArgs,
    work: &crate::args::WorkArgs,
    name: &str,
    built: &BuiltSystem,
    angles: &[f64],
    columns: &[String],
    mut cells: impl FnMut(f64, f64, &Result<SystemState, SystemError>) -> Vec<Vec<Cell>>,
) -> Result<(), Failure> {
    table.check()?;
    let sys = &built.system;
    let times = times_of(built, name, angles)?;
    crate::refuse_large(
        &camkin::work::Work::system(sys, angles.len()),
        work.large,
        ", or use fewer angles",
    )?;
    let mut instants = sys.instants(&times).map_err(|e| {
        bad(format!(
            "{name}: the system cannot be analysed at its first instant ({}°): {}",
            camkin::human::human(angles.first().copied().unwrap_or(0.0)),
            built.explain(&e)
        ))
    })?;
    let mut failed = None;
    let mut k = 0;
    let mut next_chunk = || {
        if k >= angles.len() {
            return None;
        }
        let end = (k + 4096).min(angles.len());
        let mut rows = Vec::new();
        for i in k..end {
            let s = instants.next()?;
            if let Err(e) = &s {
                failed.get_or_insert((angles[i], e.to_string()));
            }
            rows.extend(cells(angles[i], times[i], &s));
        }
        k = end;
        Some(rows)
    };
    table.write(columns, &mut next_chunk)?;
    if let Some((a, e)) = failed {
        crate::say!(
            "camkin: warning: some instants could not be solved (the first at {}°: {e}); their rows hold the reason in the error column",
            camkin::human::human(a)
        );
    }
    Ok(())
}
