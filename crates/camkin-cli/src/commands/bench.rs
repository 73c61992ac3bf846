//! `camkin bench`: in-process timings of the contact method and of the interpolation baseline,
//! measured in one run so that their ratios mean something on a noisy machine. Each figure is the
//! median of repeated runs. The contact method is timed on its fast path
//! ([`camkin::cam::Mechanism::motion`]): position, velocity and acceleration.

use crate::{load_mechanism, Failure};
use anyhow::anyhow;
use camkin::interp::{max_and_mean, relative_errors, Interpolated};
use rayon::prelude::*;
use serde_json::{json, Map, Value};
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

#[derive(Debug, clap::Args)]
pub struct BenchArgs {
    /// Mechanism file (TOML); without it, the paper's built-in cam.
    pub mechanism: Option<PathBuf>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Repetitions of each measurement (the median is reported).
    #[arg(long, default_value_t = 15)]
    pub repeats: usize,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
    /// Also count the instructions of a cold query, a warm step and a full-state warm step with
    /// valgrind's callgrind (which must be installed: Debian's package `valgrind`); they do not
    /// depend on the machine's load. JSON key `instructions`.
    #[arg(long)]
    pub instructions: bool,
    /// Internal: run only this counted operation (what `--instructions` runs under callgrind).
    #[arg(long, hide = true, value_enum)]
    pub count_operation: Option<Counted>,
    /// Internal: repetitions of the counted operation.
    #[arg(long, hide = true, default_value_t = 1000)]
    pub count_reps: usize,
}

/// The operations `--instructions` counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Counted {
    /// a query at an arbitrary angle (`Mechanism::motion`)
    Cold,
    /// a step of a 0.05° sweep (`Sweep::step_motion`)
    Warm,
    /// a step of a 0.05° sweep with every output but the jerk (`Sweep::step`)
    WarmFull,
}

impl Counted {
    const ALL: [(Counted, &'static str, usize); 3] = [
        (Counted::Cold, "cold_query", 300),
        (Counted::Warm, "warm_step", 2000),
        (Counted::WarmFull, "warm_step_full_state", 2000),
    ];
}

/// Repeats `f` `reps` times: the only function whose instructions callgrind collects.
#[inline(never)]
fn counted_repetitions(reps: usize, mut f: impl FnMut(usize) -> f64) -> f64 {
    let mut acc = 0.0;
    for k in 0..reps {
        acc += f(k);
    }
    black_box(acc)
}

/// Runs `op` `reps` times on `mech` (set-up outside [`counted_repetitions`]).
fn run_counted(mech: &camkin::cam::Mechanism, op: Counted, reps: usize) -> f64 {
    match op {
        Counted::Cold => {
            let th: Vec<f64> = (0..reps)
                .map(|k| (k as f64 * 137.50776405).rem_euclid(360.0).to_radians())
                .collect();
            counted_repetitions(reps, |k| use_motion(mech.motion(th[k])))
        }
        Counted::Warm | Counted::WarmFull => {
            let th: Vec<f64> = (1..=reps)
                .map(|k| (k as f64 * SWEEP_STEP_DEG).to_radians())
                .collect();
            let mut s = mech.sweep();
            let _ = black_box(s.step_motion(0.0));
            counted_repetitions(reps, |k| {
                if op == Counted::Warm {
                    use_motion(s.step_motion(th[k]))
                } else {
                    s.step(th[k]).map_or(0.0, |s| s.acceleration)
                }
            })
        }
    }
}

fn valgrind_missing() -> Failure {
    Failure::Input(anyhow!(
        "--instructions counts with valgrind's callgrind, and valgrind was not found (Debian: apt-get install valgrind)"
    ))
}

/// Fails, before anything is timed, when `--instructions` cannot count.
fn valgrind_present() -> Result<(), Failure> {
    std::process::Command::new("valgrind")
        .arg("--version")
        .output()
        .map(|_| ())
        .map_err(|_| valgrind_missing())
}

/// Instructions per operation of each [`Counted`] operation, counted by running this command
/// under callgrind (collecting only [`counted_repetitions`]).
fn count_instructions(args: &BenchArgs) -> Result<Map<String, Value>, Failure> {
    valgrind_present()?;
    let exe = std::env::current_exe()
        .map_err(|e| Failure::Internal(anyhow!("cannot find this program to count it: {e}")))?;
    let dir = tempfile::tempdir()
        .map_err(|e| Failure::Internal(anyhow!("a temporary directory: {e}")))?;
    let mut out = Map::new();
    for (op, key, reps) in Counted::ALL {
        let file = dir.path().join(format!("{key}.callgrind"));
        let mut cmd = std::process::Command::new("valgrind");
        cmd.arg("--tool=callgrind")
            .arg("--toggle-collect=*counted_repetitions*")
            .arg(format!("--callgrind-out-file={}", file.display()))
            .arg(&exe)
            .arg("bench");
        if let Some(m) = &args.mechanism {
            cmd.arg(m);
        }
        let op_name = clap::ValueEnum::to_possible_value(&op)
            .map_or(String::new(), |v| v.get_name().to_string());
        cmd.args([
            "--count-operation",
            &op_name,
            "--count-reps",
            &reps.to_string(),
        ]);
        let run = cmd.output().map_err(|_| valgrind_missing())?;
        if !run.status.success() {
            return Err(Failure::Internal(anyhow!(
                "counting {key} under callgrind failed: {}",
                String::from_utf8_lossy(&run.stderr)
                    .lines()
                    .last()
                    .unwrap_or("")
            )));
        }
        let text = std::fs::read_to_string(&file)
            .map_err(|e| Failure::Internal(anyhow!("reading callgrind's output: {e}")))?;
        let total: u64 = text
            .lines()
            .find_map(|l| l.strip_prefix("summary:"))
            .and_then(|v| v.trim().parse().ok())
            .ok_or_else(|| Failure::Internal(anyhow!("callgrind wrote no summary for {key}")))?;
        out.insert(
            key.to_string(),
            json!((total as f64 / reps as f64).round() as u64),
        );
    }
    Ok(out)
}

/// What a caller uses of one query: its position, velocity and acceleration, folded into one
/// number so that none of them can be optimised away (the sum is `black_box`ed by the caller).
#[inline]
fn use_motion(r: Result<camkin::cam::Motion, camkin::cam::CamError>) -> f64 {
    r.map_or(0.0, |m| m.position + m.velocity + m.acceleration)
}

/// Median wall time of `f` over `repeats` runs, seconds.
fn median_time(repeats: usize, mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..repeats.max(1))
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

/// Sweep angles: revolutions at 0.05°.
const SWEEP_STEP_DEG: f64 = 0.05;
/// Revolutions swept in one timed run: long enough (about 10 ms) that waking the thread pool's
/// idle workers, slow on a virtual machine, is a small part of it.
const SWEEP_REVOLUTIONS: usize = 10;
const NODES: [usize; 3] = [100, 1000, 10_000];

pub fn run(args: &BenchArgs) -> Result<(), Failure> {
    if !(1..=1000).contains(&args.repeats) {
        return Err(Failure::Input(anyhow!(
            "--repeats: {} must be from 1 to 1000",
            args.repeats
        )));
    }
    let mut mech = load_mechanism(args.mechanism.as_ref())?.mech;
    // the query measured is position, velocity and acceleration (no jerk)
    let mut opts = *mech.options();
    opts.jerk = false;
    mech.set_options(opts);
    if let Some(op) = args.count_operation {
        if !(1..=1_000_000).contains(&args.count_reps) {
            return Err(Failure::Input(anyhow!(
                "--count-reps: {} must be from 1 to 1000000",
                args.count_reps
            )));
        }
        black_box(run_counted(&mech, op, args.count_reps));
        return Ok(());
    }
    if args.instructions {
        valgrind_present()?;
    }
    let r = args.repeats;
    // cold queries and two timed sweeps of SWEEP_REVOLUTIONS revolutions per repetition, one
    // revolution for the baseline's reference, the baseline's nodes twice per repetition
    let per_revolution = (360.0 / SWEEP_STEP_DEG).round() as usize;
    let work = r
        * (1000 + 2 * SWEEP_REVOLUTIONS * per_revolution + 2 * NODES.iter().sum::<usize>())
        + per_revolution;
    crate::check_sweep_time(&mech, work, 1, args.work.large)?;

    // cold queries at scattered angles
    let cold: Vec<f64> = (0..1000)
        .map(|k| (k as f64 * 137.50776405).rem_euclid(360.0).to_radians())
        .collect();
    if let Some(e) = cold.iter().find_map(|&t| mech.motion(t).err()) {
        return Err(Failure::Input(anyhow!(
            "the mechanism cannot be analysed: {e}"
        )));
    }
    let single = median_time(r, || {
        let mut acc = 0.0;
        for &t in &cold {
            acc += use_motion(mech.motion(black_box(t)));
        }
        black_box(acc);
    }) / cold.len() as f64;

    let n = (360.0 / SWEEP_STEP_DEG).round() as usize;
    let thetas: Vec<f64> = (0..n)
        .map(|k| (k as f64 * SWEEP_STEP_DEG).to_radians())
        .collect();
    // each timed run sweeps SWEEP_REVOLUTIONS revolutions in one go, so that a scheduler
    // hiccup or a worker's wake-up is a small part of it
    let long: Vec<f64> = (0..n * SWEEP_REVOLUTIONS)
        .map(|k| (k as f64 * SWEEP_STEP_DEG).to_radians())
        .collect();
    let sweep = median_time(r, || {
        let mut s = mech.sweep();
        let mut acc = 0.0;
        for &t in &long {
            acc += use_motion(s.step_motion(t));
        }
        black_box(acc);
    }) / long.len() as f64;
    let threads = rayon::current_num_threads();
    // the chunks of `Mechanism::analyze_all`: fixed angles, whatever the number of threads
    let parallel = median_time(r, || {
        long.par_chunks(camkin::cam::SWEEP_CHUNK).for_each(|c| {
            let mut s = mech.sweep();
            let mut acc = 0.0;
            for &t in c {
                acc += use_motion(s.step_motion(t));
            }
            black_box(acc);
        });
    }) / long.len() as f64;

    // the interpolation baseline: N position solves, a spline, one evaluation
    let exact: Vec<f64> = mech
        .analyze_all(&thetas)
        .into_iter()
        .map(|s| s.map(|s| s.acceleration).unwrap_or(f64::NAN))
        .collect();
    let mut base_ns = Map::new();
    let mut base_err = Map::new();
    let mut ratio = Map::new();
    for nodes in NODES {
        let reps = if nodes >= 10_000 { r.min(5) } else { r };
        let t = median_time(reps, || {
            let it = Interpolated::new(&mech, nodes).map(|it| it.acceleration(1.234));
            let _ = black_box(it);
        });
        let it = Interpolated::new(&mech, nodes).map_err(|e| Failure::Input(anyhow!("{e}")))?;
        let approx: Vec<f64> = thetas.iter().map(|&t| it.acceleration(t)).collect();
        let (max, _) = max_and_mean(&relative_errors(&exact, &approx));
        base_ns.insert(nodes.to_string(), json!(t * 1e9));
        base_err.insert(nodes.to_string(), json!(max));
        ratio.insert(nodes.to_string(), json!(t / single));
    }
    // the independent check where the contact method answers
    let answered: Vec<f64> = thetas
        .iter()
        .zip(&exact)
        .filter(|(_, a)| a.is_finite())
        .map(|(&t, _)| t)
        .collect();
    let check = mech
        .independent_check(&crate::study::check_angles(&answered))
        .map_err(|e| Failure::Internal(anyhow!("independent check: {e}")))?;
    let instructions = if args.instructions {
        Some(count_instructions(args)?)
    } else {
        None
    };
    let mut out = json!({
        "mechanism": args.mechanism.as_ref().map_or("paper (built in)".to_string(), |p| p.display().to_string()),
        "follower": mech.follower().kind_name(),
        "single_query_ns": single * 1e9,
        "sweep_ns_per_angle": sweep * 1e9,
        "parallel_sweep_ns_per_angle": parallel * 1e9,
        "threads": threads,
        "parallel_speedup": sweep / parallel,
        "baseline_single_query_ns": Value::Object(base_ns.clone()),
        "baseline_max_rel_error": Value::Object(base_err.clone()),
        "baseline_over_single_query": Value::Object(ratio.clone()),
        "independent_check": super::compare::check_json(&check),
        "repeats": r,
    });
    if let Some(i) = &instructions {
        out["instructions"] = Value::Object(i.clone());
    }
    if args.json {
        crate::out!("{out}\n")?;
    } else {
        crate::out!(
            "camkin bench — {} ({}), median of {r} runs\n",
            out["mechanism"].as_str().unwrap_or(""),
            mech.follower().kind_name()
        )?;
        crate::out!(
            "  single cold query (search + velocity + acceleration) {:>12.1} ns\n",
            single * 1e9
        )?;
        crate::out!(
            "  warm sweep, one thread, per angle                   {:>12.1} ns\n",
            sweep * 1e9
        )?;
        crate::out!("  warm sweep, {threads} threads, per angle                  {:>12.1} ns  (speed-up {:.2}×)\n", parallel * 1e9, sweep / parallel)?;
        for nodes in NODES {
            let k = nodes.to_string();
            crate::out!(
                "  interpolation baseline, N = {nodes:>5}: {:>12.0} ns per angle, {:>8.0}× the single query, max relative error {:.2e}\n",
                base_ns[&k].as_f64().unwrap_or(f64::NAN),
                ratio[&k].as_f64().unwrap_or(f64::NAN),
                base_err[&k].as_f64().unwrap_or(f64::NAN)
            )?;
        }
        crate::out!(
            "  independent check (support function, differences in θ) at {} angles: position {:.1e} of the cam's size, velocity {:.1e}, acceleration {:.1e} of their peaks\n",
            check.angles, check.position, check.velocity, check.acceleration
        )?;
        if let Some(i) = &instructions {
            crate::out!(
                "  instructions (callgrind): cold query {}, warm step {}, warm step with every output {}\n",
                i["cold_query"], i["warm_step"], i["warm_step_full_state"]
            )?;
        }
    }
    Ok(())
}
