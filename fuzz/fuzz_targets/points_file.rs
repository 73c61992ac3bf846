//! Any text given as a points file or a measured profile: parsing, spline building, the
//! self-intersection check, evaluation and the measured profile's fit (coverage rule included)
//! never panic.
#![no_main]
use camkin::curve::{ClosedSpline, Curve};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok((points, _lines)) = camkin::curve::parse_points_with_lines(text) {
            // the measured profile's smoothing (small scans: the fit is cubic in its harmonics)
            if points.len() <= 64 {
                let _ = camkin::measured::FourierRadius::fit(&points, 1e-3);
            }
            if let Ok(s) = ClosedSpline::new(&points) {
                let _ = s.self_intersection();
                let _ = s.eval(0.5);
            }
        }
    }
});
