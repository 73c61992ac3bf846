//! Any text given as a points file: parsing, spline building, the self-intersection check and
//! evaluation never panic.
#![no_main]
use camkin::curve::{ClosedSpline, Curve};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok((points, _lines)) = camkin::curve::parse_points_with_lines(text) {
            if let Ok(s) = ClosedSpline::new(&points) {
                let _ = s.self_intersection();
                let _ = s.eval(0.5);
            }
        }
    }
});
