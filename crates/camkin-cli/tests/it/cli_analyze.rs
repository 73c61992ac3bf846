//! `camkin analyze`: output format, examples, exit codes, atomic output, error messages.
#![allow(clippy::unwrap_used)]
use crate::common::predicate;
use crate::common::*;
use std::path::PathBuf;

#[test]
fn default_runs_the_paper_cam_over_a_revolution() {
    let out = run!("analyze").stdout_ok();
    let (header, rows) = parse_csv(&out);
    // the paper's cam is in cm: every column says so
    assert_eq!(
        &header[..6],
        [
            "angle_deg",
            "position_cm",
            "lift_cm",
            "velocity_cm_s",
            "acceleration_cm_s2",
            "jerk_cm_s3"
        ]
    );
    assert_eq!(rows.len(), 360);
    for r in &rows {
        assert_eq!(r.len(), header.len());
    }
    // θ = 0: s = 5 cm, a = −26 961.97 cm/s² (cam-follower.md)
    let s: f64 = rows[0][1].parse().unwrap();
    let a: f64 = rows[0][4].parse().unwrap();
    assert!(
        (s - 5.0).abs() < 1e-12 && (a + 26_961.97).abs() < 0.01,
        "{s} {a}"
    );
}

#[test]
fn at_list_and_numbers_round_trip() {
    let out = run!("analyze", "--at", "45,-10").stdout_ok();
    let (_, rows) = parse_csv(&out);
    assert_eq!(rows.len(), 2);
    // the angle column echoes the angle asked for, exactly
    assert_eq!(rows[0][0].parse::<f64>().unwrap(), 45.0);
    assert_eq!(rows[1][0].parse::<f64>().unwrap(), -10.0);
    let s: f64 = rows[0][1].parse().unwrap();
    assert!((s - 4.448456).abs() < 5e-7);
}

#[test]
fn every_example_file_analyses_without_errors() {
    let mut n = 0;
    for entry in std::fs::read_dir(examples()).unwrap() {
        let p = entry.unwrap().path();
        let text = std::fs::read_to_string(&p).unwrap_or_default();
        // a system with [dynamics] and free degrees of freedom is simulated: analysing it says so
        if text.contains("[[body]]") && text.contains("[dynamics]") {
            let out = run!("analyze", &p, "--angles", "0:360:10").assert().code(2);
            let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
            assert!(stderr.contains("camkin simulate"), "{stderr}");
            continue;
        }
        if p.extension().is_some_and(|e| e == "toml") {
            let out = run!("analyze", &p, "--angles", "0:360:10").stdout_ok();
            let (header, rows) = parse_csv(&out);
            assert_eq!(rows.len(), 36, "{}", p.display());
            let err = header.iter().position(|h| h == "error").unwrap();
            for r in rows {
                assert!(r[err].is_empty(), "{}: {:?}", p.display(), r[err]);
            }
            n += 1;
        }
    }
    assert!(n >= 6);
}

#[test]
fn output_file_is_written_and_failed_runs_leave_existing_file_alone() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.csv");
    run!("analyze", "--angles", "0:10:1", "-o", &out)
        .assert()
        .success()
        .stdout("");
    let good = std::fs::read_to_string(&out).unwrap();
    assert_eq!(good.lines().count(), 11);
    // bad input: exit 2, the good file untouched, no temporary left behind
    run!("analyze", "--angles", "0:10:0", "-o", &out).refused("STEP");
    assert_eq!(std::fs::read_to_string(&out).unwrap(), good);
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
}

#[test]
fn bad_input_exits_2_with_a_message_naming_the_problem() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let paper = std::fs::read_to_string(examples().join("paper.toml")).unwrap();
    let cases: Vec<(PathBuf, &str)> = vec![
        (dir.path().join("missing.toml"), "cannot read"),
        (write("syntax.toml", "[cam\nspeed_rpm = 1"), "line 1"),
        (write("unknown.toml", &paper.replace("direction = [1.0, 0.0]", "roller_radius = 2.0")), "roller_radius"),
        (write("kind.toml", &paper.replace("kind = \"spline\"", "kind = \"blob\"")), "blob"),
        (write("speed.toml", &paper.replace("speed_rpm = 1000.0", "speed_rpm = -5.0")), "speed_rpm"),
        (write("few.toml", &paper.replace("points = [[5.0, 0.0], [3.4, 2.8], [0.6, 3.4], [-1.5, 2.6], [-2.8, 1.0],\n          [-2.8, -1.0], [-1.5, -2.6], [0.6, -3.4], [3.4, -2.8]]", "points = [[1.0, 0.0], [0.0, 1.0]]")), "at least 3"),
        (write("radius.toml", "length_unit = \"mm\"\n[cam]\nspeed_rpm = 10\n[cam.profile]\nkind = \"circle\"\ncenter = [0, 0]\nradius = -1\n[follower]\nkind = \"translating-flat\"\n"), "radius"),
        (write("pfile.toml", "length_unit = \"mm\"\n[cam]\nspeed_rpm = 10\n[cam.profile]\nkind = \"points-file\"\npath = \"nope.csv\"\n[follower]\nkind = \"translating-flat\"\n"), "nope.csv"),
    ];
    for (path, needle) in cases {
        run!("analyze", &path, "--at", "0")
            .refused(needle)
            .stderr(predicate::str::contains("panicked").not());
    }
}

#[test]
fn follower_that_never_touches_is_bad_input() {
    let (_dir, p) = written("far.toml", "length_unit = \"mm\"\n[cam]\nspeed_rpm = 10\n[cam.profile]\nkind = \"circle\"\ncenter = [0, 0]\nradius = 1\n[follower]\nkind = \"translating-knife\"\noffset = 5.0\n");
    run!("analyze", &p, "--at", "0")
        .refused("follower.offset = 5")
        .stderr(predicate::str::contains("misses the cam"));
}

#[test]
fn rows_where_the_follower_misses_carry_the_error() {
    // an eccentric circle (axis distances 0.2 to 1.8) and a knife line at 1.5: it touches only
    // while the cam's far side passes
    let (_dir, p) = written("some.toml", "length_unit = \"mm\"\n[cam]\nspeed_rpm = 10\n[cam.profile]\nkind = \"circle\"\ncenter = [0.8, 0]\nradius = 1\n[follower]\nkind = \"translating-knife\"\noffset = 1.5\n");
    let out = run!("analyze", &p, "--at", "0,90")
        .assert()
        .success()
        .stderr(predicate::str::contains("could not be analysed"))
        .get_output()
        .stdout
        .clone();
    let (_, rows) = parse_csv(&out);
    assert!(
        rows[0].last().unwrap().contains("misses the cam"),
        "{:?}",
        rows[0]
    );
    assert!(rows[1].last().unwrap().is_empty(), "{:?}", rows[1]);
}

#[test]
fn help_shows_examples_for_every_subcommand() {
    for cmd in [
        "analyze", "paper", "compare", "plot", "bench", "simulate", "synth",
    ] {
        run!(cmd, "--help")
            .assert()
            .success()
            .stdout(predicate::str::contains("Examples:"))
            .stdout(predicate::str::contains("Exit codes"));
    }
    run!("--help")
        .assert()
        .success()
        .stdout(predicate::str::contains("Exit codes"));
}

#[test]
fn json_format_has_the_csv_columns_as_keys() {
    let out = run!("analyze", "--at", "0,45", "--format", "json").stdout_ok();
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[0]["position_cm"], 5.0);
    assert!((rows[1]["acceleration_cm_s2"].as_f64().unwrap() + 6291.918).abs() < 1e-3);
    assert!(rows[0]["jerk_cm_s3"].is_null()); // θ = 0 sits on a spline node
    assert!(rows[1]["jerk_cm_s3"].is_number());
}

/// Regression (issue 12): angles are reduced modulo 360° in degrees before conversion, so an
/// angle and any angle congruent to it give the same row (1e20 ≡ 280, −90 ≡ 270).
#[test]
fn congruent_angles_give_the_same_row() {
    let a = run!("analyze", "--at", "280,1e20,270,-90,0.5,720.5")
        .assert()
        .success();
    let out = String::from_utf8(a.get_output().stdout.clone()).unwrap();
    let rows: Vec<Vec<&str>> = out
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    // every number the same to round-off (a warm start and a global search may differ in the
    // last bits); only `found` (global or warm) may differ
    let numbers = |r: &[&str]| -> Vec<f64> {
        r[1..r.len() - 2]
            .iter()
            .map(|v| v.parse().unwrap())
            .collect()
    };
    for (i, j) in [(0, 1), (2, 3), (4, 5)] {
        let (a, b) = (numbers(&rows[i]), numbers(&rows[j]));
        for (k, (x, y)) in a.iter().zip(&b).enumerate() {
            assert!(
                (x - y).abs() <= 1e-12 * x.abs().max(y.abs()).max(1.0),
                "{} vs {}: column {k}: {x} vs {y}",
                rows[i][0],
                rows[j][0]
            );
        }
    }
}

/// Issue 12, class 7: valid files are accepted — TOML dotted keys at the top level, and a
/// points-file header whose words hold `inf` or `nan` (`x_info,y_info`).
#[test]
fn dotted_keys_and_wordy_headers_are_valid() {
    let (dir, m) = written("dotted.toml", "length_unit = \"mm\"\ncam.speed_rpm = 1000.0\ncam.profile.kind = \"points-file\"\ncam.profile.path = \"p.csv\"\nfollower.kind = \"translating-flat\"\n");
    std::fs::write(
        dir.path().join("p.csv"),
        "x_info,y_info\n4,0\n0,4\n-4,0\n0,-4\n",
    )
    .unwrap();
    run!("analyze", &m, "--at", "10").assert().success();
}

/// Issue 12, class 6: a long run is written in chunks (bounded memory) with the same rows as the
/// library gives for all the angles at once, jumps across chunk seams included; output over
/// 1 GiB is refused up front with the estimate unless `--large`.
#[test]
fn long_runs_stream_the_same_rows_and_huge_ones_ask_first() {
    let (dir, m) = written("peanut.toml", "length_unit = \"mm\"\n[cam]\nspeed_rpm = 1000\n[cam.profile]\nkind = \"spline\"\npoints = [[4.0, 0.0], [3.0, 2.4], [0.5, 1.1], [-2.0, 2.4], [-3.5, 0.1], [-2.2, -2.5], [0.6, -1.0], [3.1, -2.3]]\n[follower]\nkind = \"translating-flat\"\n");
    let out = dir.path().join("rows.csv");
    // 0.005° over a revolution: 72 000 rows, two chunks
    run!("analyze", &m, "--angles", "0:360:0.005", "-o", &out)
        .assert()
        .success();
    let mech = camkin_cli::mechfile::load(&m).unwrap();
    // the range's angles as the command computes them: the decimals typed (0.015, not
    // 0.015000000000000001)
    let grid = camkin::table::AngleGrid::new(0.0, 0.005);
    let angles: Vec<f64> = (0..72_000).map(|k| grid.at(k)).collect();
    let thetas: Vec<f64> = angles
        .iter()
        .map(|&a| camkin::geometry::deg_to_rad(a))
        .collect();
    let results = mech.analyze_all(&thetas);
    let rows = camkin::table::analysis_rows(&mech, &angles, &results, true);
    let units = camkin::table::Units::plain(&mech, camkin::spec::LengthUnit::Mm);
    let travel = mech.travel().unwrap();
    let cells = rows
        .iter()
        .map(|r| camkin::table::analysis_cells(&r.clone().with_lift(&travel), &units))
        .collect();
    let mut expected = Vec::new();
    camkin_cli::output::write_cell_table(
        &mut expected,
        camkin_cli::output::TableFormat::Csv,
        &camkin::table::analysis_columns(&units),
        cells,
    )
    .unwrap();
    let got = std::fs::read(&out).unwrap();
    assert!(
        got == expected,
        "streamed rows differ from the rows computed at once"
    );
    assert_eq!(
        rows.iter()
            .filter(|r| r.found == Some(camkin::table::FoundBy::Jump))
            .count(),
        2
    );

    run!("analyze", "--angles", "0:1e7:1").refused(
            "10000000 cam angles on this profile, with the follower's travel, would take about 11 s and 3.8 GB",
        ).stderr(predicate::str::contains("--large"));
}

/// Issue 12, class 3 (regressions): an oscillating roller with `initial_angle_deg = 120` failed
/// at every angle (the branch cut fell inside the arm angles that touch the cam); the paper's
/// cam under a 0.01 roller failed to converge at most angles. Every row is computed now, and the
/// initial angle changes only the multiple of 360° the arm angle is reported in.
#[test]
fn any_initial_angle_and_a_small_roller_analyse_every_angle() {
    let dir = tempfile::tempdir().unwrap();
    let base = std::fs::read_to_string(examples().join("oscillating-roller.toml")).unwrap();
    let run = |text: &str| {
        let p = dir.path().join("m.toml");
        std::fs::write(&p, text).unwrap();
        // an arm's angle in radians (a slide refuses the unit: its coordinate is a length)
        let unit: &[&str] = if text.contains("oscillating") {
            &["--angle-unit", "rad"]
        } else {
            &[]
        };
        let a = run!("analyze", &p, "--angles", "0:360:1")
            .args(unit)
            .assert()
            .success();
        let (header, rows) = parse_csv(&a.get_output().stdout);
        assert!(["position_rad", "position_cm"].contains(&header[1].as_str()));
        let error = header.iter().position(|h| h == "error").unwrap();
        assert_eq!(rows.len(), 360);
        assert!(rows.iter().all(|r| r[error].is_empty()), "{text}");
        rows.iter()
            .map(|r| r[1].parse::<f64>().unwrap())
            .collect::<Vec<_>>()
    };
    let reference = run(&base);
    for angle in ["120.0", "170.0", "-200.0", "400.0"] {
        let q = run(&base.replace(
            "initial_angle_deg = -30.0",
            &format!("initial_angle_deg = {angle}"),
        ));
        let phi0 = angle.parse::<f64>().unwrap().to_radians();
        for (a, b) in reference.iter().zip(&q) {
            let turns = ((b - a) / std::f64::consts::TAU).round();
            assert!(
                (b - a - turns * std::f64::consts::TAU).abs() < 1e-12,
                "{angle}: {a} vs {b}"
            );
            assert!(
                (b - phi0).abs() <= std::f64::consts::PI + 1e-12,
                "{angle}: {b}"
            );
        }
    }
    let small = std::fs::read_to_string(examples().join("paper.toml"))
        .unwrap()
        .replace(
            "kind = \"translating-flat\"",
            "kind = \"translating-roller\"\nroller_radius = 0.01",
        );
    assert!(small.contains("roller_radius = 0.01"));
    run(&small);
}

/// Issue 12, class 4: unevenly spaced points under the uniform parameterisation draw a warning
/// naming `chord-length` (inline points and a points file that asks for uniform); a points
/// file is parameterised by chord length by default (the same rows as asking for it), silently.
#[test]
fn uneven_points_under_uniform_parameterisation_warn_and_files_default_to_chord_length() {
    let dir = tempfile::tempdir().unwrap();
    // a circle of 24 points at alternating angular steps a, 3a
    let a = std::f64::consts::TAU / 48.0;
    let (mut t, mut pts) = (0.0f64, Vec::new());
    for k in 0..24 {
        pts.push((0.5 + 3.0 * t.cos(), 3.0 * t.sin()));
        t += if k % 2 == 0 { a } else { 3.0 * a };
    }
    let csv: String = pts.iter().map(|(x, y)| format!("{x},{y}\n")).collect();
    std::fs::write(dir.path().join("p.csv"), csv).unwrap();
    let inline: Vec<String> = pts.iter().map(|(x, y)| format!("[{x}, {y}]")).collect();
    let head = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 60\n[cam.profile]\n";
    let flat = "[follower]\nkind = \"translating-flat\"\n";
    let run = |name: &str, text: String| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        let a = run!("analyze", &p, "--angles", "0:360:5")
            .assert()
            .success();
        let o = a.get_output();
        (
            String::from_utf8(o.stdout.clone()).unwrap(),
            String::from_utf8(o.stderr.clone()).unwrap(),
        )
    };
    let warned = |err: &str| err.contains("unevenly spaced") && err.contains("chord-length");
    let (_, err) = run(
        "inline.toml",
        format!(
            "{head}kind = \"spline\"\npoints = [{}]\n{flat}",
            inline.join(", ")
        ),
    );
    assert!(warned(&err), "{err}");
    assert!(err.contains("cam.profile.points"), "{err}");
    let (_, err) = run(
        "uniform.toml",
        format!("{head}kind = \"points-file\"\npath = \"p.csv\"\nparameterization = \"uniform\"\n{flat}"),
    );
    assert!(warned(&err) && err.contains("cam.profile.path"), "{err}");
    let (default_rows, err) = run(
        "default.toml",
        format!("{head}kind = \"points-file\"\npath = \"p.csv\"\n{flat}"),
    );
    assert!(!err.contains("warning"), "{err}");
    let (chord_rows, _) = run(
        "chord.toml",
        format!("{head}kind = \"points-file\"\npath = \"p.csv\"\nparameterization = \"chord-length\"\n{flat}"),
    );
    assert_eq!(default_rows, chord_rows);
    // and chord length follows the circle: the flat face's acceleration −e ω² cos θ (e = 0.5)
    // to the spline's own approximation of it
    let (_, rows) = parse_csv(default_rows.as_bytes());
    let w = std::f64::consts::TAU;
    for r in &rows {
        let th = r[0].parse::<f64>().unwrap().to_radians();
        let acc = r[4].parse::<f64>().unwrap();
        assert!(
            (acc + 0.5 * w * w * th.cos()).abs() < 0.2 * 0.5 * w * w,
            "{r:?}"
        );
    }
}

/// Issue 12, class 6: on a large non-convex profile every angle searches the profile's samples for
/// a contact elsewhere; a run estimated at over 30 s is refused up front with the estimate and
/// the flag (100 000 nodes: 1.6 million samples, about 44 µs an angle, 1.8 million angles).
#[test]
fn sweeps_of_minutes_on_a_large_non_convex_profile_ask_first() {
    let dir = tempfile::tempdir().unwrap();
    let n = 100_000;
    let csv: String = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            let r = 3.0 + 0.8 * (2.0 * t).cos();
            format!("{},{}\n", r * t.cos(), r * t.sin())
        })
        .collect();
    std::fs::write(dir.path().join("p.csv"), csv).unwrap();
    let m = dir.path().join("m.toml");
    std::fs::write(
        &m,
        "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"points-file\"\npath = \"p.csv\"\n[follower]\nkind = \"translating-roller\"\nroller_radius = 0.5\n",
    )
    .unwrap();
    for args in [
        vec!["analyze", "M", "--angles", "0:360:0.0002"],
        vec!["plot", "M", "--out", "OUT", "--step", "0.0002"],
    ] {
        let out = dir.path().join("plots");
        let args: Vec<String> = args
            .iter()
            .map(|a| match *a {
                "M" => m.display().to_string(),
                "OUT" => out.display().to_string(),
                a => a.to_string(),
            })
            .collect();
        camkin()
            .args(&args)
            .refused("would take about")
            .stderr(predicate::str::contains("--large"));
        assert!(!out.exists());
    }
}

/// The mushroom example (a translating follower carrying a circle of radius R through its origin)
/// is a roller of radius R whose centre is R further along the line of travel: the same motion,
/// its position R less — the general follower against a named kind's closed form.
#[test]
fn mushroom_follower_is_a_roller_shifted_by_its_radius() {
    let file = examples().join("mushroom-follower.toml");
    let text = std::fs::read_to_string(&file).unwrap();
    let cut = text.find("[follower.profile]").unwrap();
    let roller = text[..cut].replace(
        "kind = \"translating\"\n",
        "kind = \"translating-roller\"\nroller_radius = 60.0\n",
    );
    let (_dir, rfile) = written("roller.toml", roller);
    let run = |f: &std::path::Path| {
        let out = run!("analyze", f, "--angles", "0:360:5").stdout_ok();
        parse_csv(&out).1
    };
    let (m, r) = (run(&file), run(&rfile));
    assert_eq!(m.len(), 72);
    for (a, b) in m.iter().zip(&r) {
        let x = |row: &Vec<String>, i: usize| row[i].parse::<f64>().unwrap();
        assert!(
            (x(a, 1) + 60.0 - x(b, 1)).abs() <= 1e-10 * 110.0,
            "{a:?} {b:?}"
        );
        for i in [3, 4] {
            assert!(
                (x(a, i) - x(b, i)).abs() <= 1e-9 * (1.0 + x(b, i).abs()),
                "{i}: {a:?} {b:?}"
            );
        }
    }
}
