//! `camkin simulate`: time series, events, plots, bad dynamics input.
#![allow(clippy::unwrap_used)]
use crate::common::predicate;
use crate::common::*;
use std::path::PathBuf;

fn example(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name)
}

#[test]
fn stiff_spring_stays_on_the_cam_and_follows_the_kinematics() {
    let out = run!(
        "simulate",
        example("paper-dynamics.toml"),
        "--revolutions",
        "1"
    )
    .assert()
    .success()
    .stderr(predicate::str::contains("no lift-off"))
    .get_output()
    .stdout
    .clone();
    let text = String::from_utf8(out).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    assert!(
        header.starts_with(
            "time_s,cam_angle_deg,position_cm,velocity_cm_s,acceleration_cm_s2,contact_force_N,in_contact,kinematic_position_cm,kinematic_acceleration_cm_s2"
        ),
        "{header}"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 361);
    // the paper's cam is in cm (simulated in metres, written in the file's unit): s(0) = 5 cm
    assert!((rows[0][2] - 5.0).abs() < 1e-10, "{}", rows[0][2]);
    let amax = rows.iter().map(|r| r[8].abs()).fold(0.0, f64::max);
    for r in &rows {
        assert_eq!(r[6], 1.0);
        assert!(r[5] > 0.0);
        assert!(
            (r[4] - r[8]).abs() <= 1e-6 * amax,
            "dynamic {} vs kinematic {}",
            r[4],
            r[8]
        );
    }
}

#[test]
fn lift_off_and_impacts_are_reported_and_written() {
    let dir = tempfile::tempdir().unwrap();
    run!(
        "simulate",
        example("eccentric-flat-dynamics.toml"),
        "--start-angle",
        "180",
        "--revolutions",
        "1",
        "--out",
        dir.path()
    )
    .assert()
    .success()
    .stderr(predicate::str::contains("lift-off"))
    .stderr(predicate::str::contains("impact"));
    let events = std::fs::read_to_string(dir.path().join("events.csv")).unwrap();
    assert!(events.starts_with("event,time_s,cam_angle_deg,impact_velocity_mm_s"));
    let lift: f64 = events
        .lines()
        .find(|l| l.starts_with("lift-off"))
        .unwrap()
        .split(',')
        .nth(2)
        .unwrap()
        .parse()
        .unwrap();
    // analytic: cos θ* = (F0 + k e)/(m e ω² − k e) at 1380 rpm
    let w = 1380.0 * std::f64::consts::TAU / 60.0;
    let theta = 360.0
        - ((20.0 + 2000.0 * 0.01) / (0.3 * 0.01 * w * w - 2000.0 * 0.01))
            .acos()
            .to_degrees();
    assert!((lift - theta).abs() < 0.1, "{lift} vs {theta}");
    for f in [
        "time_series.csv",
        "motion.png",
        "motion.svg",
        "acceleration.png",
        "contact_force.png",
        "contact_force.svg",
        "deviation.png",
        "deviation.svg",
    ] {
        assert!(dir.path().join(f).exists(), "{f}");
    }
    // the deviation plot names its quantity and its unit
    let svg = std::fs::read_to_string(dir.path().join("deviation.svg")).unwrap();
    assert!(
        svg.contains("dynamic − kinematic position (mm)"),
        "axis label"
    );
}

#[test]
fn json_has_samples_and_events() {
    let out = run!(
        "simulate",
        example("eccentric-flat-dynamics.toml"),
        "--start-angle",
        "180",
        "--step",
        "2",
        "--format",
        "json"
    )
    .stdout_ok();
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["samples"].as_array().unwrap().len(), 181);
    assert!(v["events"]
        .as_array()
        .unwrap()
        .iter()
        .any(|e| e["event"] == "lift-off"));
}

#[test]
fn bad_dynamics_input_exits_2() {
    let dir = tempfile::tempdir().unwrap();
    let base = std::fs::read_to_string(example("eccentric-flat-dynamics.toml")).unwrap();
    // (what the example says, what the case says instead, what the refusal names)
    let cases = [
        ("mass = 0.3", "mass = -1", "dynamics.mass = -1"),
        ("mass = 0.3", "inertia = 0.1", "takes `mass`, not `inertia`"),
        (
            "restitution = 0.6",
            "restitution = 1.5",
            "dynamics.restitution = 1.5",
        ),
        (
            "length_unit = \"mm\"",
            "length_unit = \"inch\"",
            "length_unit = \"inch\"",
        ),
        (
            "spring_preload = 20.0",
            "spring_preload = nan",
            "dynamics.spring_preload = NaN",
        ),
        (
            "damping = 0.0",
            "damping = 0.0\nfriction = 1",
            "unknown field `friction`",
        ),
        // issue 12, class 2: magnitudes the dynamics cannot compute in are refused by field
        (
            "mass = 0.3",
            "mass = 1e300",
            "dynamics.mass = 1e300: is outside the range",
        ),
        (
            "mass = 0.3",
            "mass = 1e-300",
            "dynamics.mass = 1e-300: is outside the range",
        ),
        (
            "spring_stiffness = ",
            "spring_stiffness = 1e300 #",
            "dynamics.spring_stiffness = 1e300",
        ),
        // issue 64: no step is refused; a damper this stiff needs steps of nanoseconds, and the
        // run's estimate says so
        ("damping = 0.0", "damping = 1e9", "would take about"),
        (
            "damping = 0.0",
            "damping = 0.0\ngravity = [0, -1e308]",
            "dynamics.gravity = [0, -1e308]",
        ),
        // issue 63: a very slow cam's revolution is years of the follower's vibration: its
        // estimate is refused
        (
            "speed_rpm = 1380.0",
            "speed_rpm = 1e-6",
            "steps of this mechanism would take about",
        ),
    ];
    let texts = cases
        .iter()
        .map(|(from, to, needle)| (base.replace(from, to), *needle))
        // no [dynamics] at all
        .chain([(
            base.split("[dynamics]").next().unwrap().to_string(),
            "needs a [dynamics] section",
        )]);
    for (i, (text, needle)) in texts.enumerate() {
        let p = dir.path().join(format!("m{i}.toml"));
        std::fs::write(&p, text).unwrap();
        run!("simulate", &p)
            .refused(needle)
            .stderr(predicate::str::contains("panicked").not());
    }
    run!(
        "simulate",
        example("eccentric-flat-dynamics.toml"),
        "--revolutions",
        "0"
    )
    .assert()
    .code(2);
}

/// Issue 12, class 6: a simulation estimated at hours is refused up front with the estimate and
/// the flag that allows it.
#[test]
fn an_hours_long_simulation_asks_first() {
    let m =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-dynamics.toml");
    run!("simulate", &m, "--revolutions", "10000")
        .refused("3600000 steps")
        // a step a degree at 25 µs, and the kinematic sweep beside the 3.6 million rows at
        // 1 µs an angle
        .stderr(predicate::str::contains("would take about 94 s"))
        .stderr(predicate::str::contains("--large"));
}

/// Issue 16: the one-coordinate model's cost is the library's estimate (six cold searches of 1 ms
/// a step and curve for a carried curve), the same the Python package refuses with: 100
/// revolutions of a gear pair with backlash at 1° are about 432 s, with the kinematic sweep beside
/// the rows about 440 s (its warm step is timed), refused without `--large`.
#[test]
fn a_long_gear_simulation_is_refused_with_the_librarys_estimate() {
    let dir = tempfile::tempdir().unwrap();
    let out = run!(
        "simulate",
        example("gear-pair-backlash.toml"),
        "--revolutions",
        "100",
        "--out",
        dir.path().join("out")
    )
    .assert()
    .code(2);
    let err = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(
        err.contains("36000 steps of this mechanism") && err.contains("--large"),
        "{err}"
    );
    // the library's 432 s of steps and the sweep beside them: 37 441 angles, a carried
    // curve's warm step timed on this machine (0.2 ms: 440 s idle, 462 s beside a build)
    let seconds = err
        .split("would take about ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .and_then(|n| n.parse::<f64>().ok());
    assert!(
        seconds.is_some_and(|s| (430.0..500.0).contains(&s)),
        "{err}"
    );
    assert!(!dir.path().join("out").exists(), "nothing written");
}

/// Issue 16: a concave stretch under a flat face (a dented disc) is simulated: the contact jumps
/// are impacts without flight, written as `jump` rows of `events.csv` and listed on stderr, not a
/// pairing-point search that did not converge (issue 12) nor a refusal.
#[test]
fn a_cam_whose_contact_jumps_is_simulated_with_jump_events() {
    let dir = tempfile::tempdir().unwrap();
    let text = "length_unit = \"m\"\n[cam]\nspeed_rpm = 6.0\n[cam.profile]\nkind = \"spline\"\npoints = [[4.0, 0.0], [3.0, 2.4], [0.5, 1.1], [-2.0, 2.4], [-3.5, 0.1], [-2.2, -2.5], [0.6, -1.0], [3.1, -2.3]]\n[follower]\nkind = \"translating-flat\"\ndirection = [1.0, 0.0]\n[dynamics]\nmass = 0.5\nspring_stiffness = 1000.0\nspring_preload = 500.0\n";
    let p = dir.path().join("m.toml");
    std::fs::write(&p, text).unwrap();
    let out = dir.path().join("run");
    run!("simulate", &p, "--out", &out)
        .assert()
        .success()
        .stderr(predicate::str::contains("jump"))
        .stderr(predicate::str::contains("panicked").not());
    let events = std::fs::read_to_string(out.join("events.csv")).unwrap();
    let jumps = events.lines().filter(|l| l.starts_with("jump,")).count();
    assert_eq!(jumps, 2, "{events}");
}

/// Issue 64: every example with `[dynamics]` simulates with no flags (the flagship valve train
/// once exited 2 asking for `--substeps 2`): its time series on stdout, exit 0.
#[test]
fn every_example_simulates_with_no_flags() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut ran = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        if path.extension().is_none_or(|e| e != "toml") || !text.contains("[dynamics]") {
            continue;
        }
        let out = run!("simulate", &path).stdout_ok();
        assert!(out.len() > 1000, "{}", path.display());
        ran += 1;
    }
    assert!(ran >= 5, "{ran} examples");
}
