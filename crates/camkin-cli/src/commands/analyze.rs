//! `camkin analyze`: the one-instant analysis at a list or range of cam angles, as CSV.

use crate::mechfile::BySolver;
use crate::output::TableFormat;
use crate::Failure;
use anyhow::Result;
use camkin::cam::Mechanism;
use camkin::table::AnalysisSweep;
use camkin::table::Units;
use camkin::table::{analysis_cells, analysis_columns};
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Mechanism file (TOML); without it, the paper's built-in cam. A system file (arrays of
    /// tables `body`, `joint`, `driver`, `contact`: see examples/valve-train-kinematics.toml) is swept over
    /// its first driver's angle, one row an instant with every body and contact.
    pub mechanism: Option<PathBuf>,
    #[command(flatten)]
    pub sweep: crate::args::AngleArgs,
    /// Analyse a cam or gear-pair file as a system of bodies (the cam and the follower, jointed
    /// to the ground, one contact): each body's pose, velocity and acceleration and the
    /// contact's terms, the columns of a system file, at each cam angle. The motion is the one
    /// the cam path gives (to 1e-12 of the size); the cam path has more columns and is faster.
    #[arg(long)]
    pub system: bool,
    #[command(flatten)]
    pub units: crate::args::MotionUnitArgs,
    #[command(flatten)]
    pub table: crate::args::TableArgs,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
}

/// Warnings on stderr: profile stretches the follower cannot follow, and where the contact jumps
/// (`jump_at`: the first rows that jumped, of `total`).
fn report_degenerate(
    mech: &Mechanism,
    unit: &str,
    stretches: &[(f64, f64)],
    angles: &[f64],
    jump_at: &[usize],
    total: usize,
) {
    let what = match mech.roller_radius() {
        Some(roller_radius) => format!(
            "concave more sharply than the roller (radius of curvature below {} {unit}), or folds over itself",
            camkin::human::human(roller_radius)
        ),
        None => "concave under the flat face, or folds over itself".to_string(),
    };
    let p = mech.cam().profile();
    for &(a, b) in stretches {
        let (pa, pb) = (p.position(a), p.position(b));
        crate::say!(
            "camkin: warning: the cam profile from u = {a:.4} ({:.4}, {:.4}) {unit} to u = {b:.4} ({:.4}, {:.4}) {unit} is {what}: the follower cannot follow it, the contact jumps across and the acceleration is impulsive there",
            pa.x, pa.y, pb.x, pb.y
        );
    }
    let at: Vec<String> = jump_at
        .iter()
        .map(|&k| {
            let h = camkin::human::human;
            match k {
                0 => format!("{}°", h(angles[0])),
                _ => format!("{}°–{}°", h(angles[k - 1]), h(angles[k])),
            }
        })
        .collect();
    if !at.is_empty() {
        let more = if total > at.len() {
            format!(" and {} more", total - at.len())
        } else {
            String::new()
        };
        crate::say!("camkin: warning: the contact jumps between cam angles {}{more} (rows marked `jump` in the found column)", at.join(", "));
    }
}

/// Rows computed and written per chunk: the memory a run holds whatever its length.
const CHUNK: usize = 65_536;
/// Bytes of output per row, about (CSV; JSON is about twice): for the size estimate.
const BYTES_PER_ROW: f64 = 380.0;

pub fn run(args: &Args) -> Result<(), Failure> {
    // the model picks its solver (--system: the general one on a cam's preset too)
    let model = crate::mechfile::load_model(args.mechanism.as_ref(), false)?;
    let loaded = match model.by_solver(args.system)? {
        BySolver::General { name, built, .. } => return analyze_system(args, &name, &built),
        BySolver::Cam { preset, stem, .. } => crate::Loaded::of(*preset, stem),
    };
    args.table.check()?;
    let mech = &loaded.mech;
    let units = Units::new(
        mech,
        loaded.unit,
        args.units.angle_unit_for(mech)?,
        args.units.per,
    );
    let columns = analysis_columns(&units);
    let angles = args.sweep.or_revolution();
    let per_row = match args.table.format {
        TableFormat::Csv => BYTES_PER_ROW,
        TableFormat::Json => 2.0 * BYTES_PER_ROW,
    };
    // the bytes written (memory stays bounded: rows are written CHUNK at a time)
    crate::refuse_large(
        &camkin::work::Work::sweep(mech, angles.len(), 1).with_bytes(angles.len() as f64 * per_row),
        args.work.large,
        ", or use fewer angles",
    )?;
    let contiguous = args.sweep.contiguous();
    let mut rows = AnalysisSweep::new(mech, &angles, contiguous, CHUNK);
    // lift is measured from the lowest position over the revolution
    if let Err(e) = rows.travel() {
        crate::say!("camkin: warning: no lift column: the lowest position over the revolution could not be found ({e})");
    }
    let pb = if angles.len() > 5 * CHUNK {
        indicatif::ProgressBar::new(angles.len() as u64)
    } else {
        indicatif::ProgressBar::hidden()
    };
    let next_chunk = || {
        let chunk = rows.next()?;
        pb.inc(chunk.len() as u64);
        Some(chunk)
    };
    args.table
        .write_rows(&columns, next_chunk, |r| analysis_cells(r, &units))?;
    pb.finish_and_clear();
    report_degenerate(
        mech,
        loaded.unit.name(),
        rows.stretches(),
        &angles,
        rows.jump_at(),
        rows.jumps(),
    );
    let failed = rows.failed();
    if failed > 0 {
        crate::say!(
            "camkin: {failed} of {} angles could not be analysed; see the error column",
            angles.len()
        );
    }
    Ok(())
}

/// Analyses the system `built` (read from `name`).
fn analyze_system(
    args: &Args,
    name: &str,
    built: &camkin::spec::BuiltSystem,
) -> Result<(), Failure> {
    // the cam path's unit flags have no meaning here: refused, not ignored
    if args.units.per != camkin::table::Per::S {
        return Err(Failure::Input(anyhow::anyhow!(
            "--per deg: a system's table gives its rates per second (the columns say so: _mm_s, _deg_s2); drop --per"
        )));
    }
    if args.units.angle_unit.is_some() {
        return Err(Failure::Input(anyhow::anyhow!(
            "--angle-unit rad: a system's table gives its angles in degrees (the columns say so: _deg); drop --angle-unit"
        )));
    }
    let sys = &built.system;
    let angles = args.sweep.or_revolution();
    let mut jumps = Vec::new();
    crate::sweep::write_sweep(
        &args.table,
        &args.work,
        name,
        built,
        &angles,
        &camkin::table::system_columns(built),
        |a, t, s| {
            if s.as_ref()
                .is_ok_and(|s| s.contacts.iter().any(|c| c.jumped))
            {
                jumps.push(a);
            }
            vec![camkin::table::system_cells(sys, a, t, s)]
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
