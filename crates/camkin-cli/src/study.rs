//! The paper's study (section 3): exact acceleration by the contact method against the
//! acceleration of a periodic cubic spline through N sampled positions, over one revolution.

use anyhow::{anyhow, Result};
use camkin::cam::{FollowerState, Mechanism};
use camkin::interp::{max_and_mean, relative_errors, Interpolated};
use indicatif::{ProgressBar, ProgressStyle};
use std::time::Instant;

/// One interpolation run of the study.
#[derive(Debug)]
pub struct NodeRun {
    /// nodal points per revolution
    pub nodes: usize,
    /// interpolated acceleration on the grid
    pub acceleration: Vec<f64>,
    /// relative error on the grid, |a_N − a| / max|a|
    pub rel_error: Vec<f64>,
    pub max_rel_error: f64,
    pub mean_rel_error: f64,
    /// wall time: N position solves, spline, evaluation on the whole grid (s)
    pub total_seconds: f64,
    /// wall time to answer one angle: N position solves, spline, one evaluation (s)
    pub single_seconds: f64,
}

pub use camkin::cam::IndependentCheck;

#[derive(Debug)]
pub struct Study {
    pub grid_deg: Vec<f64>,
    pub exact: Vec<FollowerState>,
    pub max_abs_acceleration: f64,
    pub runs: Vec<NodeRun>,
    /// contact method on the whole grid (s)
    pub contact_total_seconds: f64,
    /// contact method, one cold query at an arbitrary angle (median, s)
    pub contact_single_seconds: f64,
    /// the contact method against the support function, on at most 360 of the grid's angles
    pub check: IndependentCheck,
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn progress(len: u64, msg: &str) -> ProgressBar {
    let pb = ProgressBar::new(len);
    if let Ok(style) = ProgressStyle::with_template("{msg:>28} [{bar:30}] {pos}/{len} ({elapsed})")
    {
        pb.set_style(style.progress_chars("=> "));
    }
    pb.set_message(msg.to_string());
    pb
}

/// Runs the study on a grid of `step_deg` over one revolution for each of `nodes`.
/// Estimated `(seconds, bytes)` of a study with these node counts and grid step on this
/// machine class (measured on the paper's cam, 2-core host: a grid angle costs about 0.7 µs and
/// 300 bytes, and 16 more bytes per run; a node about 1.6 µs, the interpolation being built twice
/// for its timing, and 160 bytes while its run lasts).
pub fn estimate(nodes: &[usize], step_deg: f64) -> (f64, f64) {
    let grid = (360.0 / step_deg).round();
    let runs = nodes.len() as f64;
    let total: f64 = nodes.iter().map(|&n| n as f64).sum();
    let largest = nodes.iter().copied().max().unwrap_or(0) as f64;
    let seconds = grid * 0.7e-6 + total * 1.6e-6 + grid * runs * 0.02e-6;
    let bytes = grid * (300.0 + 16.0 * runs) + 2.0 * largest * 160.0;
    (seconds, bytes)
}

/// Refuses, with the estimate and the flag that allows it, a study estimated at over a minute
/// or 2 GiB of memory, or whose files (when `writes`) would pass 1 GiB (`studies` of them run
/// one after the other; measured: about 90 bytes per grid angle and 60 more per run, the
/// paper's three runs at 0.0001° wrote 2 GB).
pub fn check_bounds(
    nodes: &[usize],
    step_deg: f64,
    studies: usize,
    writes: bool,
    large: bool,
) -> Result<()> {
    let (seconds, bytes) = estimate(nodes, step_deg);
    let seconds = seconds * studies as f64;
    let grid = (360.0 / step_deg).round();
    let written = if writes {
        grid * (90.0 + 60.0 * nodes.len() as f64) * studies as f64
    } else {
        0.0
    };
    let work = camkin::work::Work::new(
        format!(
            "{grid} grid angles and {} interpolation nodes in all",
            nodes.iter().sum::<usize>() * studies
        ),
        seconds,
    )
    // memory held, or files written (whichever is larger)
    .with_bytes(bytes.max(written));
    if let Some(r) = work.refusal().filter(|_| !large) {
        anyhow::bail!(
            "{r}; pass --large to run it anyway, or use a coarser --step or fewer --nodes"
        );
    }
    Ok(())
}

pub fn run(mech: &Mechanism, nodes: &[usize], step_deg: f64, label: &str) -> Result<Study> {
    let count = (360.0 / step_deg).round() as usize;
    let grid = camkin::table::AngleGrid::new(0.0, step_deg);
    let grid_deg: Vec<f64> = (0..count).map(|k| grid.at(k)).collect();
    let thetas: Vec<f64> = grid_deg.iter().map(|d| d.to_radians()).collect();
    let pb = progress(2 + nodes.len() as u64, label);

    let t0 = Instant::now();
    let exact = mech
        .analyze_all(&thetas)
        .into_iter()
        .zip(&grid_deg)
        .map(|(r, a)| r.map_err(|e| anyhow!("contact method at {a}°: {e}")))
        .collect::<Result<Vec<_>>>()?;
    let contact_total_seconds = t0.elapsed().as_secs_f64();
    let contact_single_seconds = median(
        (0..101)
            .map(|k| {
                let th = (k as f64 * 3.567 + 0.1).to_radians();
                let t = Instant::now();
                let _ = std::hint::black_box(mech.analyze(th));
                t.elapsed().as_secs_f64()
            })
            .collect(),
    );
    pb.inc(1);
    let a: Vec<f64> = exact.iter().map(|s| s.acceleration).collect();
    let max_abs_acceleration = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));

    Interpolated::check_repeats(mech)?;
    let mut runs = Vec::with_capacity(nodes.len());
    for &n in nodes {
        pb.set_message(format!("{label}: N = {n}"));
        let t = Instant::now();
        let it = Interpolated::new(mech, n)?;
        let acceleration: Vec<f64> = thetas.iter().map(|&th| it.acceleration(th)).collect();
        let total_seconds = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let one = Interpolated::new(mech, n)?;
        let _ = std::hint::black_box(one.acceleration(std::f64::consts::FRAC_PI_4));
        let single_seconds = t.elapsed().as_secs_f64();
        let rel_error = relative_errors(&a, &acceleration);
        let (max_rel_error, mean_rel_error) = max_and_mean(&rel_error);
        runs.push(NodeRun {
            nodes: n,
            acceleration,
            rel_error,
            max_rel_error,
            mean_rel_error,
            total_seconds,
            single_seconds,
        });
        pb.inc(1);
    }

    // the contact method against an independent computation
    let check = mech.independent_check(&check_angles(&thetas))?;
    pb.inc(1);
    pb.finish_and_clear();
    Ok(Study {
        grid_deg,
        exact,
        max_abs_acceleration,
        runs,
        contact_total_seconds,
        contact_single_seconds,
        check,
    })
}

/// At most 360 of `thetas`, evenly spread: the angles of the independent check (about 1 ms
/// each).
pub fn check_angles(thetas: &[f64]) -> Vec<f64> {
    let stride = thetas.len().div_ceil(360).max(1);
    thetas.iter().step_by(stride).copied().collect()
}
