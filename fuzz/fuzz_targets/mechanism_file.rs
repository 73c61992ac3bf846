//! Any text given as a mechanism file: parsing and validation never panic, and a mechanism that
//! is accepted can be analysed — single queries, a warm-started sweep, the jump scan, the
//! independent support function, and (with `[dynamics]`) a few simulation steps (errors are
//! fine, panics are not).
#![no_main]
use camkin::dynamics::{AugmentedLagrangian, Simulation};
use libfuzzer_sys::fuzz_target;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let base = Path::new("/nonexistent");
    if let Ok(m) = camkin_cli::mechfile::parse(text, "fuzz.toml", base) {
        for k in 0..3 {
            let _ = m.analyze(k as f64 * 2.1);
        }
        let mut sweep = m.sweep();
        for k in 0..8 {
            let _ = sweep.step(k as f64 * 0.05);
        }
        let _ = m.unfollowable_stretches();
        let _ = m.jump_angles(45.0);
        let _ = m.support_position(0.7);
    }
    if let Ok((m, params)) = camkin_cli::mechfile::parse_dynamics(text, "fuzz.toml", base) {
        if let Ok(mut sim) = Simulation::starting_at(&m, params, AugmentedLagrangian::default(), 0.3) {
            let h = (1f64.to_radians() / m.cam().speed()).min(sim.max_step());
            for _ in 0..3 {
                if sim.advance(h).is_err() || sim.sample().is_err() {
                    break;
                }
            }
        }
    }
});
