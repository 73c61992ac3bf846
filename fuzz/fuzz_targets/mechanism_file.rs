//! Any text given as a mechanism file: parsing and validation never panic, and a mechanism that
//! is accepted can be analysed (errors are fine, panics are not).
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(m) = camkin_cli::mechfile::parse(text, "fuzz.toml", std::path::Path::new("/nonexistent")) {
            for k in 0..3 {
                let _ = m.analyze(k as f64 * 2.1);
            }
            let _ = m.unfollowable_stretches();
        }
    }
});
