//! The first-touch search of the five named follower kinds on a non-convex cam of `N` spline
//! nodes, for counting its cost against `N` (`scripts/first-touch-scaling` runs it under
//! callgrind).
//!
//! `first_touch_scaling N KIND MODE REPS`: KIND one of `translating-flat`, `translating-roller`,
//! `translating-knife`, `oscillating-flat`, `oscillating-roller`; MODE `cold` (a query at an
//! arbitrary cam angle, `Mechanism::motion`) or `warm` (a step of a 0.05° sweep,
//! `Sweep::step_motion`). Prints the mean wall time per query and a checksum of the positions.

use camkin::cam::{Cam, Mechanism, Sense};
use camkin::Point2;
use std::hint::black_box;
use std::sync::Arc;
use std::time::Instant;

use camkin_bench::scenarios::{lobed, lobed_follower};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let kind = args.get(2).map_or("translating-flat", String::as_str);
    let mode = args.get(3).map_or("cold", String::as_str);
    let reps: usize = args.get(4).and_then(|s| s.parse().ok()).unwrap_or(100);
    let cam = Cam::from_rpm(Arc::new(lobed(n)), Point2::origin(), Sense::Ccw, 100.0).expect("cam");
    let mut m = Mechanism::new(
        cam,
        lobed_follower(kind).unwrap_or_else(|| panic!("unknown follower kind {kind}")),
    )
    .expect("mechanism");
    let mut o = *m.options();
    o.jerk = false;
    m.set_options(o);
    let mut sweep = m.sweep();
    // the warm sweep starts with one cold query, not counted per step
    if mode == "warm" {
        let _ = black_box(sweep.step_motion(0.0));
    }
    let start = Instant::now();
    let mut acc = 0.0;
    for k in 0..reps {
        let q = match mode {
            "warm" => sweep.step_motion(((k + 1) as f64 * 0.05).to_radians()),
            _ => m.motion(0.1 + k as f64 * 0.37),
        };
        acc += q.map_or(f64::NAN, |q| q.position);
    }
    let dt = start.elapsed().as_secs_f64() / reps.max(1) as f64;
    println!(
        "N {n} {kind} {mode}: {:.2} µs per query (sum of positions {})",
        dt * 1e6,
        black_box(acc)
    );
}
