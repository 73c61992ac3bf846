//! Benchmarks of camkin's hot paths: `cargo bench -p camkin-bench`. They live in their own
//! package so that `cargo test --workspace` never compiles criterion.
