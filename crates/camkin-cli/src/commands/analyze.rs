//! `camkin analyze`: the one-instant analysis at a list or range of cam angles, as CSV.

use crate::args::{AngleList, AngleRange};
use crate::output::{write_atomic, write_table, TableFormat};
use crate::{load_mechanism, Failure};
use anyhow::Result;
use camkin::cam::{FollowerState, Mechanism};
use camkin::table::{analysis_rows, FoundBy};
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Mechanism file (TOML); without it, the paper's built-in cam.
    pub mechanism: Option<PathBuf>,
    /// Cam angles in degrees, comma-separated (e.g. 0,45,90).
    #[arg(
        long,
        value_name = "A1,A2,...",
        conflicts_with = "angles",
        allow_hyphen_values = true
    )]
    pub at: Option<AngleList>,
    /// Range of cam angles in degrees: START:STOP:STEP, STOP excluded [default: 0:360:1].
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub angles: Option<AngleRange>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    pub format: TableFormat,
    /// Output file (written atomically); standard output without it.
    #[arg(short = 'o', long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// A warm-started sweep, with a progress bar on a terminal when it is long.
fn analyze_with_progress(
    mech: &camkin::cam::Mechanism,
    thetas: &[f64],
) -> Vec<Result<FollowerState, camkin::cam::CamError>> {
    const CHUNK: usize = 10_000;
    if thetas.len() <= 5 * CHUNK {
        return mech.analyze_all(thetas);
    }
    let pb = indicatif::ProgressBar::new(thetas.len() as u64);
    let mut sweep = mech.sweep();
    let mut out = Vec::with_capacity(thetas.len());
    for chunk in thetas.chunks(CHUNK) {
        out.extend(chunk.iter().map(|&t| sweep.step(t)));
        pb.inc(chunk.len() as u64);
    }
    pb.finish_and_clear();
    out
}

/// Warnings on stderr: profile stretches the follower cannot follow, and where the contact jumps.
fn report_degenerate(mech: &Mechanism, stretches: &[(f64, f64)], angles: &[f64], jumps: &[bool]) {
    let what = match mech.roller_radius() {
        Some(roller_radius) => format!(
            "concave more sharply than the roller (radius of curvature below {roller_radius}), or folds over itself"
        ),
        None => "concave under the flat face, or folds over itself".to_string(),
    };
    let p = mech.cam().profile();
    for &(a, b) in stretches {
        let (pa, pb) = (p.position(a), p.position(b));
        eprintln!(
            "camkin: warning: the cam profile from u = {a:.4} ({:.4}, {:.4}) to u = {b:.4} ({:.4}, {:.4}) is {what}: the follower cannot follow it, the contact jumps across and the acceleration is impulsive there",
            pa.x, pa.y, pb.x, pb.y
        );
    }
    let at: Vec<String> = jumps
        .iter()
        .enumerate()
        .filter(|(_, j)| **j)
        .map(|(k, _)| match k {
            0 => format!("{}°", angles[0]),
            _ => format!("{}°–{}°", angles[k - 1], angles[k]),
        })
        .collect();
    if !at.is_empty() {
        eprintln!("camkin: warning: the contact jumps between cam angles {} (rows marked `jump` in the found column)", at.join(", "));
    }
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let mech = load_mechanism(args.mechanism.as_ref())?;
    let angles = match (&args.at, args.angles) {
        (Some(list), _) => list.0.clone(),
        (None, range) => range.unwrap_or(AngleRange::REVOLUTION).angles(),
    };
    let thetas: Vec<f64> = angles
        .iter()
        .map(|&a| camkin::geometry::deg_to_rad(a))
        .collect();
    let results = analyze_with_progress(&mech, &thetas);
    let failed = results.iter().filter(|r| r.is_err()).count();
    let rows = analysis_rows(&mech, &angles, &results, args.at.is_none());
    let jumps: Vec<bool> = rows
        .iter()
        .map(|r| r.found == Some(FoundBy::Jump))
        .collect();
    report_degenerate(&mech, &mech.unfollowable_stretches(), &angles, &jumps);
    write_atomic(args.output.as_deref(), |w| {
        write_table(w, &rows, args.format)
    })
    .map_err(|e| {
        if args.output.is_some() {
            Failure::output(e)
        } else {
            // standard output that cannot be written is not the user's input
            Failure::Internal(e)
        }
    })?;
    if failed > 0 {
        eprintln!(
            "camkin: {failed} of {} angles could not be analysed; see the error column",
            angles.len()
        );
    }
    Ok(())
}
