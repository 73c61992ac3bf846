//! The general contact search between two closed splines of `N` nodes each, for counting its
//! cost against `Na·Nb` (`scripts/contact-scaling` runs it under `perf stat`).
//!
//! `contact_scaling N MODE REPS`: MODE `full` (indexes built at every query, as
//! `find_contact`), `indexed` (built once, `find_contact_indexed`), or `brute` (every sample pair
//! compared, the search this replaced, for the ratio). Prints the mean wall time per query.

use camkin::body::{BodyState, Pose};
use camkin::contact::{find_contact, find_contact_indexed, CurveIndex, SearchOptions, Surface};
use camkin::curve::{ClosedSpline, Curve};
use camkin::{CurveInFrame, Point2};
use std::hint::black_box;
use std::time::Instant;

fn star(n: usize, r: f64, wobble: f64, lobes: f64) -> ClosedSpline {
    let pts: Vec<Point2> = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            let rr = r * (1.0 + wobble * (lobes * t).sin());
            Point2::new(rr * t.cos(), rr * t.sin())
        })
        .collect();
    ClosedSpline::new(&pts).expect("a star-shaped polygon")
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let mode = args.get(2).map_or("indexed", String::as_str);
    let reps: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(100);
    let (ca, cb) = (star(n, 50.0, 0.1, 3.0), star(n, 20.0, 0.15, 2.0));
    let opts = SearchOptions::for_length_scale(50.0);
    let bodies = |k: usize| {
        let t = k as f64 * 0.01;
        (
            BodyState::at_rest(Pose::new(Point2::origin(), t)),
            BodyState::at_rest(Pose::new(Point2::new(78.0, 3.0), -2.0 * t)),
        )
    };
    let (ia, ib) = (
        CurveIndex::new(&ca, &opts).expect("bounded"),
        CurveIndex::new(&cb, &opts).expect("bounded"),
    );
    let start = Instant::now();
    let mut acc = 0.0;
    for k in 0..reps {
        let (a, b) = bodies(k);
        let (sa, sb) = (Surface::new(&ca, &a), Surface::new(&cb, &b));
        acc += match mode {
            "full" => find_contact(&sa, &sb, &opts).map_or(f64::NAN, |p| p.gap()),
            "indexed" => find_contact_indexed(&sa, Some(&ia), &sb, Some(&ib), &opts)
                .map_or(f64::NAN, |p| p.gap()),
            _ => brute(&ca, &a, &cb, &b, ia.len()),
        };
    }
    let dt = start.elapsed().as_secs_f64() / reps.max(1) as f64;
    println!(
        "N {n} mode {mode}: {:.1} µs per query ({})",
        dt * 1e6,
        black_box(acc)
    );
}

/// The nearest sampled pair by comparing every pair (positions only), as the search did before.
fn brute(ca: &ClosedSpline, a: &BodyState, cb: &ClosedSpline, b: &BodyState, m: usize) -> f64 {
    let (fa, fb) = (a.frame(), b.frame());
    let sample = |c: &ClosedSpline, f: &camkin::Frame| -> Vec<Point2> {
        let period = match c.domain() {
            camkin::curve::Domain::Periodic { period } => period,
            _ => 1.0,
        };
        (0..m)
            .map(|i| f.curve_position(c, period * i as f64 / m as f64))
            .collect()
    };
    let (pa, pb) = (sample(ca, &fa), sample(cb, &fb));
    let mut best = f64::INFINITY;
    for x in &pa {
        for y in &pb {
            best = best.min((x - y).norm_squared());
        }
    }
    best
}
