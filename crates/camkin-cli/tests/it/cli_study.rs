//! `camkin paper` and `camkin compare`: files produced and well formed, summary contents, JSON
//! keys, bad input.
#![allow(clippy::unwrap_used)]
use crate::common::predicate;
use crate::common::*;
use std::path::Path;

/// A PNG of the expected size (signature and IHDR).
fn assert_png(p: &Path) {
    let b = std::fs::read(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    assert_eq!(&b[..8], b"\x89PNG\r\n\x1a\n", "{}", p.display());
    let w = u32::from_be_bytes(b[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(b[20..24].try_into().unwrap());
    assert_eq!((w, h), (1000, 600), "{}", p.display());
}

/// An SVG document with a title text and at least one drawn line.
fn assert_svg(p: &Path, title: &str) {
    let s = std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    assert!(s.trim_start().starts_with("<svg"), "{}", p.display());
    assert!(s.trim_end().ends_with("</svg>"), "{}", p.display());
    assert!(s.contains(title), "{}: no {title:?}", p.display());
    assert!(
        s.contains("<polyline") || s.contains("<path"),
        "{}",
        p.display()
    );
    assert_eq!(s.matches("<text").count(), s.matches("</text>").count());
}

fn csv(p: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(p).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|v| v.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect();
    (header, rows)
}

#[test]
fn paper_writes_data_plots_and_summary() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("study");
    let assert = run!("paper", "--out", &out).assert().success();
    let stdout = String::from_utf8(assert.get_output().stdout.clone()).unwrap();
    assert!(stdout.contains("| 10000 |"), "{stdout}");
    assert!(
        stdout.contains("Independent check (support function"),
        "{stdout}"
    );
    for cam in ["original", "revised"] {
        let d = out.join(cam);
        for base in ["displacement", "acceleration", "relative_error"] {
            assert_png(&d.join(format!("{base}.png")));
            assert_svg(&d.join(format!("{base}.svg")), "cam angle");
        }
        let (h, rows) = csv(&d.join("displacement.csv"));
        assert_eq!(
            h[..4],
            [
                "angle_deg",
                "position_cm",
                "velocity_cm_s",
                "acceleration_cm_s2"
            ]
        );
        assert_eq!(rows.len(), 7200); // 0.05° grid
        let (h, rows) = csv(&d.join("relative_error.csv"));
        assert_eq!(h, ["angle_deg", "n_100", "n_1000", "n_10000"]);
        // the error falls with N
        let max = |c: usize| rows.iter().map(|r| r[c]).fold(0.0, f64::max);
        assert!(
            max(1) > 5.0 * max(2) && max(2) > 5.0 * max(3),
            "{cam}: {} {} {}",
            max(1),
            max(2),
            max(3)
        );
        let (h, _) = csv(&d.join("acceleration.csv"));
        assert_eq!(
            h,
            [
                "angle_deg",
                "contact_method_cm_s2",
                "interpolated_100_cm_s2",
                "interpolated_1000_cm_s2",
                "interpolated_10000_cm_s2"
            ]
        );
    }
    assert_png(&out.join("revised/relative_error_zoom.png"));
    assert_svg(&out.join("revised/relative_error_zoom.svg"), "5°–10°");
    let original = csv(&out.join("original/displacement.csv")).1;
    assert_eq!(original[0][1], 5.0); // s(0) = 5 cm
    assert!((original[900][1] - 4.448456).abs() < 5e-7); // 45°
    assert!(std::fs::read_to_string(out.join("summary.md"))
        .unwrap()
        .contains("Revised cam"));
}

#[test]
fn paper_json_summary() {
    let dir = tempfile::tempdir().unwrap();
    let out = run!(
        "paper",
        "--step",
        "1",
        "--format",
        "json",
        "--out",
        dir.path()
    )
    .stdout_ok();
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    for cam in ["original", "revised"] {
        for n in ["100", "1000", "10000"] {
            assert!(v[cam]["max_rel_error"][n].as_f64().unwrap() > 0.0);
            assert!(v[cam]["mean_rel_error"][n].as_f64().unwrap() > 0.0);
        }
    }
}

#[test]
fn compare_json_has_errors_keyed_by_n() {
    let out = run!(
        "compare",
        examples().join("paper-revised.toml"),
        "--nodes",
        "100,1000",
        "--step",
        "0.5",
        "--format",
        "json"
    )
    .stdout_ok();
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let m100 = v["max_rel_error"]["100"].as_f64().unwrap();
    let m1000 = v["max_rel_error"]["1000"].as_f64().unwrap();
    assert!(m100 > m1000 && m1000 > 0.0);
    assert!(v["mean_rel_error"]["1000"].as_f64().unwrap() < m1000);
}

#[test]
fn compare_every_example_and_csv_format() {
    for name in [
        "eccentric-roller",
        "ellipse-knife",
        "oscillating-flat",
        "oscillating-roller",
    ] {
        let out = run!(
            "compare",
            examples().join(format!("{name}.toml")),
            "--nodes",
            "50,500",
            "--step",
            "1",
            "--format",
            "csv"
        )
        .stdout_ok();
        let text = String::from_utf8(out).unwrap();
        assert!(text.starts_with("cam,nodes,max_rel_error"), "{text}");
        assert_eq!(text.lines().count(), 3, "{name}");
    }
}

#[test]
fn compare_writes_plots_with_zoom() {
    let dir = tempfile::tempdir().unwrap();
    run!(
        "compare",
        examples().join("oscillating-roller.toml"),
        "--nodes",
        "100",
        "--step",
        "1",
        "--zoom",
        "5:10",
        "--out",
        dir.path()
    )
    .assert()
    .success();
    for base in [
        "displacement",
        "acceleration",
        "relative_error",
        "relative_error_zoom",
    ] {
        assert_png(&dir.path().join(format!("{base}.png")));
        assert_svg(&dir.path().join(format!("{base}.svg")), "cam angle");
    }
    // an arm's angle in degrees by default
    assert!(std::fs::read_to_string(dir.path().join("displacement.svg"))
        .unwrap()
        .contains("displacement (°)"));
}

#[test]
fn study_bad_input_exits_2() {
    let paper = examples().join("paper.toml");
    for (args, needle) in [
        (vec!["--nodes", "2"], "--nodes"),
        (vec!["--nodes", "10,x"], "--nodes"),
        (vec!["--step", "0"], "--step"),
        (vec!["--step", "0.7"], "divide"),
        (vec!["--zoom", "10:5"], "--zoom"),
    ] {
        run!("compare", &paper).args(&args).refused(needle);
    }
    run!("compare", "no-such.toml").refused("cannot read");
    run!("paper", "--step", "-1").assert().code(2);
}

#[test]
fn bench_runs_and_reports_every_key() {
    let out = run!("bench", "--repeats", "1", "--json").stdout_ok();
    let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
    for key in [
        "single_query_ns",
        "sweep_ns_per_angle",
        "parallel_sweep_ns_per_angle",
    ] {
        let v = j[key].as_f64().unwrap_or_else(|| panic!("{key}: {j}"));
        assert!(v.is_finite() && v > 0.0, "{key} = {v}");
    }
    assert_eq!(j["follower"], "translating-flat");
    // the baseline's error falls with the number of nodes; the contact method agrees with the
    // independent support-function check to the guide's figures (docs/checks.md)
    let e = |n: &str| j["baseline_max_rel_error"][n].as_f64().unwrap();
    assert!(e("100") > e("1000") && e("1000") > e("10000"), "{j}");
    let c = &j["independent_check"];
    assert_eq!(c["angles"].as_u64(), Some(360), "{j}");
    assert!(c["position"].as_f64().unwrap() < 2e-14, "{j}");
    assert!(c["velocity"].as_f64().unwrap() < 1e-10, "{j}");
    assert!(c["acceleration"].as_f64().unwrap() < 1e-7, "{j}");
    run!("bench", "--repeats", "0").assert().code(2);
}

/// `bench --instructions` counts a cold query, a warm step and a full-state step under callgrind
/// (scripts/test installs valgrind); without valgrind it refuses before timing anything.
#[test]
fn bench_counts_instructions_with_callgrind() {
    let out = run!("bench", "--repeats", "1", "--json", "--instructions").stdout_ok();
    let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let n = |k: &str| {
        j["instructions"][k]
            .as_u64()
            .unwrap_or_else(|| panic!("instructions.{k}: {j}"))
    };
    let (cold, warm, full) = (n("cold_query"), n("warm_step"), n("warm_step_full_state"));
    // a warm step is one Newton start and the kinematics: cheaper than a search, dearer than
    // a spline evaluation; every output costs more than position, velocity and acceleration
    assert!(warm > 200 && warm < cold && warm < full, "{j}");
    assert!(
        j["single_query_ns"].as_f64().is_some(),
        "the wall-time keys stay: {j}"
    );
    camkin()
        .env("PATH", "")
        .args(["bench", "--repeats", "1", "--instructions"])
        .refused("valgrind was not found");
}

/// Issue 12, class 6: a study estimated at over 30 s, or 1 GB of memory or of files, is
/// refused up front with the estimate and the flag that allows it, and writes nothing.
#[test]
fn studies_that_would_take_minutes_or_gigabytes_ask_first() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("study");
    let many = vec!["1000000"; 40].join(",");
    for (args, needle) in [
        (
            vec!["compare", "MECH", "--nodes", many.as_str()],
            "40000000 interpolation nodes in all would take about",
        ),
        (vec!["compare", "MECH", "--step", "0.00004"], "s and 3.2 GB"),
        (
            vec!["paper", "--step", "0.0001", "--out", "OUT"],
            "GB; pass --large",
        ),
    ] {
        let args: Vec<String> = args
            .iter()
            .map(|a| match *a {
                "MECH" => examples().join("paper.toml").display().to_string(),
                "OUT" => out.display().to_string(),
                a => a.to_string(),
            })
            .collect();
        camkin()
            .args(&args)
            .refused(needle)
            .stderr(predicate::str::contains("--large"));
        assert!(!out.exists(), "{args:?} wrote {}", out.display());
    }
}
