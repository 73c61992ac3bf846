//! `camkin analyze SYSTEM.toml`: a system of bodies, joints, drivers and contacts, swept over
//! its first driver's angle; one CSV row an instant ([`camkin::table::system_columns`]).
//! `camkin plot SYSTEM.toml`: its drawings at driver angles and an animation of a revolution.

use super::analyze::Args;
use crate::args::AngleRange;
use crate::Failure;
use anyhow::anyhow;
use camkin::spec::text::read_system;
use camkin::spec::{BuildOptions, BuiltSystem};
use camkin::system::{SystemError, SystemState};
use camkin::table::{system_cells, system_columns, Cell};
use std::path::Path;

fn bad(m: String) -> Failure {
    Failure::Input(anyhow!(m))
}

/// The system in `text` (read from `path`, `name` for messages), built; errors at their keys.
/// A cam-follower or gear-pair file is its mechanism as a system.
pub fn load(path: &Path, name: &str, text: &str) -> Result<BuiltSystem, Failure> {
    let options = BuildOptions {
        base_dir: path.parent().unwrap_or(Path::new(".")).to_path_buf(),
        si: false,
        confine: false,
        limits: crate::mechfile::build_limits(),
    };
    let built = read_system(text, name, &options).map_err(|e| bad(e.message))?;
    for w in &built.warnings {
        crate::say!("camkin: warning: {name}: {w}");
    }
    Ok(built)
}

/// The instants at the sweep's angles (degrees): the first driver's, or a cam's.
fn times_of(built: &BuiltSystem, name: &str, angles: &[f64]) -> Result<Vec<f64>, Failure> {
    built
        .times(angles)
        .map_err(|e| bad(format!("{name}: --at, --angles: {e}")))
}

/// The system `built` (read from `name`) swept in order through `angles` (of `--at` or
/// `--angles`), each instant's rows made by `cells` and written 4096 instants at a time under
/// `columns`; the work refused first when it is over the limits. A system that cannot be
/// analysed at its first instant (a loop that does not close, a redundant joint, a driver on a
/// coordinate a joint fixes) is a bad file, named by its element. Warns of the first instant
/// that could not be solved (its rows hold the reason).
fn write_sweep(
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

/// The angles of `--at` or `--angles` (a revolution by default).
fn angles_of(at: &Option<crate::args::AngleList>, range: Option<AngleRange>) -> Vec<f64> {
    match (at, range) {
        (Some(list), _) => list.0.clone(),
        (None, range) => range.unwrap_or(AngleRange::REVOLUTION).angles(),
    }
}

/// Analyses the system `built` (read from `name`).
pub fn analyze(args: &Args, name: &str, built: &BuiltSystem) -> Result<(), Failure> {
    // the cam path's unit flags have no meaning here: refused, not ignored
    if args.units.per != camkin::table::Per::S {
        return Err(bad(
            "--per deg: a system's table gives its rates per second (the columns say so: _mm_s, _deg_s2); drop --per".into(),
        ));
    }
    if args.units.angle_unit.is_some() {
        return Err(bad(
            "--angle-unit rad: a system's table gives its angles in degrees (the columns say so: _deg); drop --angle-unit".into(),
        ));
    }
    let sys = &built.system;
    let angles = angles_of(&args.at, args.angles);
    let mut jumps = Vec::new();
    write_sweep(
        &args.table,
        &args.work,
        name,
        built,
        &angles,
        &system_columns(built),
        |a, t, s| {
            if s.as_ref()
                .is_ok_and(|s| s.contacts.iter().any(|c| c.jumped))
            {
                jumps.push(a);
            }
            vec![system_cells(sys, a, t, s)]
        },
    )?;
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
    Ok(())
}

/// Every contact of the system `built` (read from `name`) at each instant, one row per contact
/// ([`camkin::table::system_contact_columns`]): its point, normal, gap, sliding rates, normal
/// accelerations with their terms and its acceleration constraint row.
pub fn contacts(
    args: &super::contacts::ContactsArgs,
    name: &str,
    built: &BuiltSystem,
) -> Result<(), Failure> {
    use camkin::table::{system_contact_cells, system_contact_columns};
    let sys = &built.system;
    let angles = angles_of(&args.at, args.angles);
    write_sweep(
        &args.table,
        &args.work,
        name,
        built,
        &angles,
        &system_contact_columns(built),
        |a, t, s| system_contact_cells(sys, a, t, s),
    )?;
    let n = sys.contacts().len();
    crate::say!(
        "camkin: {n} contact{} at {} instant{} of {}",
        if n == 1 { "" } else { "s" },
        angles.len(),
        if angles.len() == 1 { "" } else { "s" },
        built.angle_name()
    );
    Ok(())
}

/// Draws the system in `text` at the driver angles `--at` (`drawing_<angle>.svg/png`) and over a
/// revolution in `--frames` frames (`animation.svg`), into `--out`.
pub fn plot(
    args: &super::plot::PlotArgs,
    path: &Path,
    name: &str,
    text: &str,
) -> Result<(), Failure> {
    use crate::draw::mechanism::Shape;
    use crate::draw::system::system_scene;
    let built = load(path, name, text)?;
    let sys = &built.system;
    let angles = args.at.0.clone();
    if angles.len() > 360 || !(1..=3600).contains(&args.frames) {
        return Err(bad(format!(
            "--at: at most 360 drawings, --frames: 1 to 3600 (given {} and {})",
            angles.len(),
            args.frames
        )));
    }
    let frames: Vec<f64> = (0..args.frames)
        .map(|k| 360.0 * k as f64 / args.frames as f64)
        .collect();
    let all: Vec<f64> = angles.iter().chain(&frames).copied().collect();
    crate::refuse_large(
        // the instants drawn and those half a degree apart between them, and the pictures
        &camkin::work::Work::system(sys, all.len() + 720).and(&camkin::work::Work::new(
            "the pictures",
            all.len() as f64 * 5e-3,
        )),
        args.work.large,
        ", or use fewer --frames",
    )?;
    let times = times_of(&built, name, &all)?;
    let size = sys.size();
    // the drawings at --at, then a revolution's frames, from one sweep in order through
    // instants at most half a degree of the driver apart (a contact is followed, not guessed
    // afresh after a long jump: a gear's tooth pairs hand over every pitch)
    let mut scenes: Vec<(f64, Vec<Shape>)> = Vec::new();
    let mut order: Vec<usize> = (0..all.len()).collect();
    order.sort_by(|&i, &j| times[i].total_cmp(&times[j]));
    let mut sweep = sys
        .sweep()
        .map_err(|e| bad(format!("{name}: {}", built.explain(&e))))?;
    let mut by_index: Vec<Option<Vec<Shape>>> = vec![None; all.len()];
    let per_degree =
        built.time_of(1f64.to_radians()).unwrap_or(0.0) - built.time_of(0.0).unwrap_or(0.0);
    let mut at: Option<f64> = None;
    for i in order {
        let to = times[i];
        if let Some(from) = at {
            let n = ((to - from) / (0.5 * per_degree).abs())
                .abs()
                .ceil()
                .min(1e6) as usize;
            for k in 1..n {
                let _ = sweep.step(from + (to - from) * k as f64 / n as f64);
            }
        }
        let s = sweep
            .step(to)
            .map_err(|e| bad(format!("{name}: at {}°: {e}", camkin::human::human(all[i]))))?;
        at = Some(to);
        by_index[i] = Some(system_scene(sys, &s, size));
    }
    for (i, shapes) in by_index.into_iter().enumerate() {
        scenes.push((all[i], shapes.unwrap_or_default()));
    }
    let od = crate::out_dir::OutDir::begin(&args.out, args.force.force)?;
    let what = format!("{} at driver angle", built_name(path));
    let written = super::plot::draw_all(
        od.path(),
        &scenes,
        angles.len(),
        &what,
        built.length_unit.name(),
        "",
    )?;
    od.commit().map_err(Failure::output)?;
    crate::say!(
        "camkin: wrote {} files to {}",
        written.len(),
        args.out.display()
    );
    Ok(())
}

/// The file's name without its folder and extension, for titles.
fn built_name(path: &Path) -> String {
    path.file_stem().map_or_else(
        || path.display().to_string(),
        |s| s.to_string_lossy().into(),
    )
}
