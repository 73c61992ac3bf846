//! Benchmarks of camkin's hot paths: `cargo bench -p camkin-bench` (criterion, wall times), and
//! the scenarios whose instructions `scripts/instruction-counts` counts with callgrind
//! ([`scenarios`]). They live in their own package so that `cargo test --workspace` never
//! compiles criterion.

pub mod scenarios;
