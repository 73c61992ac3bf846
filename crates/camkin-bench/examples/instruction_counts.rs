//! Runs one counted scenario (`scripts/instruction-counts` runs it under callgrind, collecting
//! only `scenarios::counted_repetitions`).
//!
//! `instruction_counts --list`: the scenarios, one per line (`name<TAB>repetitions<TAB>operation`).
//! `instruction_counts NAME [REPS]`: sets NAME up and repeats its operation REPS times.

use camkin_bench::scenarios;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    match args.get(1).map(String::as_str) {
        Some("--list") | None => {
            for s in scenarios::all() {
                println!("{}\t{}\t{}", s.name, s.reps, s.operation);
            }
        }
        Some(name) => {
            let reps = match args.get(2) {
                Some(r) => r.parse().unwrap_or_else(|_| {
                    eprintln!("instruction_counts: REPS must be a count, not {r:?}");
                    std::process::exit(2)
                }),
                None => scenarios::all()
                    .into_iter()
                    .find(|s| s.name == name)
                    .map_or(1, |s| s.reps),
            };
            match scenarios::run(name, reps) {
                Some(acc) => println!("{name}: {reps} repetitions, checksum {acc}"),
                None => {
                    eprintln!("instruction_counts: no scenario {name:?} (see --list)");
                    std::process::exit(2)
                }
            }
        }
    }
}
