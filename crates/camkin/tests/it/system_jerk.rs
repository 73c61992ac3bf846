//! Issue 45: a system's jerk (`System::jerk`: the rows differentiated three times in time, each
//! contact as its pairing conditions) against five-point differences in time of the
//! accelerations the analysis gives (the paper's rows with `γ`) — a computation that shares no
//! formula with it — at every system example, at 24 instants of a driver revolution. Where the
//! jerk is not defined (a contact on a spline node) it must say so, not answer.
//!
//! Tolerance: 1e-9 of the example's largest jerk (or of `ω³ × size` where that is larger: a gear
//! train of ideal involutes has none, and its jerk must be zero to 1e-12 of that) (the differences' truncation, `h⁴` with the
//! driver turning 1e-3 rad a step, and their round-off, `ε q̈ / h`, are below it: 2e-11 measured).

use crate::common::read_system;
use camkin::spec::text::is_system;
use camkin::spec::BuildOptions;
use camkin::system::SystemError;
use std::path::Path;

fn system_examples() -> Vec<(String, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let path = e.unwrap().path();
        if path.extension().and_then(|x| x.to_str()) != Some("toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        // the kinematic examples (a file with [dynamics] is simulated)
        if is_system(&text) && !text.contains("[dynamics]") {
            out.push((path.to_string_lossy().into_owned(), text));
        }
    }
    out.sort();
    assert!(out.len() >= 5, "{} system examples", out.len());
    out
}

#[test]
fn every_system_examples_jerk_is_the_derivative_of_its_accelerations() {
    for (name, text) in system_examples() {
        let options = BuildOptions {
            base_dir: Path::new(&name).parent().unwrap().to_path_buf(),
            ..BuildOptions::default()
        };
        let built = read_system(&text, &name, &options).unwrap();
        let sys = &built.system;
        let nb = sys.bodies().len();
        // the driver's rate: a revolution's period and the step
        let period = built.time_of(std::f64::consts::TAU).unwrap() - built.time_of(0.0).unwrap();
        let h = 1e-3 / std::f64::consts::TAU * period.abs();
        let mut sweep = sys.sweep().unwrap();
        let (mut worst, mut peak, mut undefined, mut compared) = (0.0f64, 0.0f64, 0, 0);
        let mut largest = 0.0f64;
        let size = sys.size();
        for k in 0..24 {
            let t = built
                .time_of((15.0 * f64::from(k) + 7.0).to_radians())
                .unwrap();
            // q̈ at t − 2h … t + 2h, in order (warm), and the instant itself
            let mut acc = Vec::new();
            let mut at = None;
            for i in -2..=2 {
                let s = sweep.step(t + f64::from(i) * h).unwrap();
                acc.push(
                    s.bodies
                        .iter()
                        .flat_map(|b| [b.acceleration.x, b.acceleration.y, b.alpha * size])
                        .collect::<Vec<_>>(),
                );
                if i == 0 {
                    at = Some(s);
                }
            }
            let s = at.unwrap();
            // a contact that moved to another pair of points near t has no derivative there
            if s.contacts.iter().any(|c| c.jumped) {
                continue;
            }
            match sys.jerk(&s) {
                Ok(j) => {
                    compared += 1;
                    for b in 0..nb {
                        let mine = [j[b].linear.x, j[b].linear.y, j[b].angular * size];
                        for c in 0..3 {
                            let a = |i: usize| acc[i][3 * b + c];
                            let fd = (a(0) - 8.0 * a(1) + 8.0 * a(3) - a(4)) / (12.0 * h);
                            worst = worst.max((mine[c] - fd).abs());
                            largest = largest.max(mine[c].abs());
                            peak = peak.max(fd.abs());
                        }
                    }
                }
                Err(SystemError::NoJerk { .. }) => undefined += 1,
                Err(e) => panic!("{name} at instant {k}: {e}"),
            }
        }
        // a gear train of ideal involutes has none: its scale is then the driver's ω³ × size
        let w = std::f64::consts::TAU / period.abs();
        let scale = peak.max(w * w * w * size);
        eprintln!(
            "{name}: jerk against differences of the accelerations: {:.1e} of {scale:.3e} (its peak {peak:.3e}, angles as size × rad/s³); {compared} instants, {undefined} at a breakpoint",
            worst / scale
        );
        assert!(compared >= 20, "{name}: only {compared} instants compared");
        assert!(
            worst <= 1e-9 * scale,
            "{name}: jerk off by {worst:e} of {scale:e}"
        );
        // ideal involutes turn each other at constant ratios: no jerk at all
        if name.ends_with("gear-train.toml") {
            assert!(largest <= 1e-12 * scale, "{name}: jerk {largest:e}");
        }
    }
}
