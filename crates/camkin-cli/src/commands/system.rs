//! `camkin analyze SYSTEM.toml`: a system of bodies, joints, drivers and contacts, swept over
//! its first driver's angle; one CSV row an instant ([`camkin::table::system_columns`]).

use super::analyze::Args;
use crate::args::AngleRange;
use crate::Failure;
use anyhow::anyhow;
use camkin::spec::text::{build_system_placed, parse_system_toml};
use camkin::spec::BuildOptions;
use camkin::table::{system_cells, system_columns};
use std::path::Path;

/// Seconds an instant takes, about (a warm instant of the valve train: 47 000 instructions),
/// with a margin for larger systems and their searches.
const SECONDS_PER_INSTANT: f64 = 1e-4;

/// Analyses the system in `text` (read from `path`, `name` for messages).
pub fn analyze(args: &Args, path: &Path, name: &str, text: &str) -> Result<(), Failure> {
    args.table.check()?;
    let bad = |m: String| Failure::Input(anyhow!(m));
    let spec = parse_system_toml(text, name).map_err(|e| bad(e.message))?;
    let options = BuildOptions {
        base_dir: path.parent().unwrap_or(Path::new(".")).to_path_buf(),
        si: false,
        confine: false,
        limits: crate::mechfile::build_limits(),
    };
    let built = build_system_placed(&spec, text, name, &options).map_err(|e| bad(e.message))?;
    let sys = &built.system;
    let angles = match (&args.at, args.angles) {
        (Some(list), _) => list.0.clone(),
        (None, range) => range.unwrap_or(AngleRange::REVOLUTION).angles(),
    };
    let times: Vec<f64> = angles
        .iter()
        .map(|a| {
            sys.driver_time(a.to_radians()).ok_or_else(|| {
                bad(format!(
                    "{name}: a system is swept over its first driver's angle (--at, --angles): [[driver]] number 1 must drive an angle at a constant speed_rpm"
                ))
            })
        })
        .collect::<Result<_, _>>()?;
    crate::refuse_large(
        &camkin::work::Work::new(
            format!("{} instants of this system", angles.len()),
            angles.len() as f64 * SECONDS_PER_INSTANT,
        )
        .with_bytes(angles.len() as f64 * 40.0 * (sys.bodies().len() * 9 + 8) as f64),
        args.work.large,
        ", or use fewer angles",
    )?;
    let mut sweep = sys.sweep().map_err(|e| bad(format!("{name}: {e}")))?;
    // a system that cannot be analysed at its first instant (a loop that does not close, a
    // redundant joint, a driver on a coordinate a joint fixes) is a bad file, named by its
    // element
    if let Some(&t0) = times.first() {
        if let Err(e) = sys.analyze(t0) {
            return Err(bad(format!(
                "{name}: the system cannot be analysed at its first instant ({}°): {e}",
                camkin::human::human(angles[0])
            )));
        }
    }
    let unit = built.length_unit.name();
    let columns = system_columns(sys, unit);
    let mut jumps = Vec::new();
    let mut failed = None;
    let mut k = 0;
    let mut next_chunk = || {
        if k >= angles.len() {
            return None;
        }
        let end = (k + 4096).min(angles.len());
        let rows = (k..end)
            .map(|i| {
                let s = sweep.step(times[i]);
                match &s {
                    Ok(state) => {
                        if state.contacts.iter().any(|c| c.jumped) {
                            jumps.push(angles[i]);
                        }
                    }
                    Err(e) => {
                        failed.get_or_insert((angles[i], e.to_string()));
                    }
                }
                system_cells(sys, angles[i], times[i], &s)
            })
            .collect();
        k = end;
        Some(rows)
    };
    args.table.write(&columns, &mut next_chunk)?;
    if !jumps.is_empty() {
        let h = camkin::human::human;
        let shown: Vec<String> = jumps
            .iter()
            .take(5)
            .map(|a| format!("{}°", h(*a)))
            .collect();
        crate::say!(
            "camkin: warning: a contact moved to another pair of points at {} instant{} ({}{}): rows marked true in its jump column",
            jumps.len(),
            if jumps.len() == 1 { "" } else { "s" },
            shown.join(", "),
            if jumps.len() > 5 { ", …" } else { "" }
        );
    }
    if let Some((a, e)) = failed {
        crate::say!(
            "camkin: warning: some instants could not be solved (the first at {}°: {e}); their rows hold the reason in the error column",
            camkin::human::human(a)
        );
    }
    Ok(())
}
