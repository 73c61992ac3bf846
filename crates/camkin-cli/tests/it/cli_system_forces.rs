//! Issue 46: `camkin forces` on a system file. An eccentric disc (radius 20 mm, its centre 5 mm
//! off the axis, 600 rpm) lifts a 0.2 kg flat-faced slide held down by a 2 N/mm spring with 20 N
//! of preload, no gravity: its face stays on the disc's top, `y = 20 + e sin θ`, so the contact
//! force is `P + (k e − m e ω²) sin θ` and the camshaft's torque `F e cos θ`, closed forms that
//! share nothing with the simulation; the follower leaves the cam where `m e ω² − k e = P`,
//! at 1654 rpm. The checks exit 3, a flag that is the file's for a system exits 2.

use crate::common::*;
use std::f64::consts::TAU;

const SYSTEM: &str = r#"
length_unit = "mm"

[dynamics]
gravity = [0.0, 0.0]

[[body]]
name = "cam"
mass = 1.0
inertia = 1e-3

[[body]]
name = "face"
position = [0.0, 20.0]
mass = 0.2
inertia = 1e-4

[[joint]]
name = "camshaft"
kind = "revolute"
bodies = ["ground", "cam"]

[[joint]]
name = "guide"
kind = "prismatic"
bodies = ["ground", "face"]
axis = [0.0, 1.0]

[[driver]]
name = "drive"
body = "cam"
coordinate = "angle"
speed_rpm = 600.0

[[contact]]
name = "disc on face"
bodies = ["cam", "face"]
curve_a = { kind = "circle", center = [5.0, 0.0], radius = 20.0 }
curve_b = { kind = "line", anchor = [0.0, 0.0], direction = [1.0, 0.0] }

[[spring]]
name = "return spring"
bodies = ["ground", "face"]
at = [[0.0, -60.0], [0.0, 0.0]]
stiffness = 2.0
free_length = 80.0
preload = 20.0
"#;

fn system() -> (tempfile::TempDir, std::path::PathBuf) {
    let (dir, path) = written("disc.toml", SYSTEM);
    (dir, path)
}

#[test]
fn a_discs_contact_force_and_torque_are_the_closed_forms() {
    let (dir, path) = system();
    let out_dir = dir.path().join("out");
    let out = run!("forces", &path, "--step", "1", "--out", &out_dir)
        .assert()
        .success();
    let (m, e, k, p) = (0.2, 5.0, 2.0, 20.0);
    let w = 600.0 * TAU / 60.0;
    // m e ω² with e in metres: N
    let amplitude = k * e - m * e * 1e-3 * w * w;
    let force = |th: f64| p + amplitude * th.sin();
    let text = std::fs::read_to_string(out_dir.join("forces.csv")).unwrap();
    let (header, rows) = parse_csv(text.as_bytes());
    let col = columns(&header);
    assert_eq!(rows.len(), 361);
    for r in &rows {
        let num = |c: &str| r[col[c]].parse::<f64>().unwrap();
        let th = num("driver_angle_deg").to_radians();
        let f = num("disc_on_face_force_N");
        let torque = num("drive_torque_N_mm");
        assert!(
            (f - force(th)).abs() < 1e-9 * p,
            "at {th} rad: {f} N, closed form {} N",
            force(th)
        );
        let closed = force(th) * e * th.cos();
        assert!(
            (torque - closed).abs() < 1e-9 * p * e,
            "at {th} rad: {torque} N·mm, closed form {closed} N·mm"
        );
    }
    // the summary: the largest force at 90°, the largest torque where (P + A sin θ) cos θ peaks
    let summary = String::from_utf8_lossy(&out.get_output().stdout).to_string();
    let peak = format!("max {} N at 90°", sig4(p + amplitude));
    assert!(summary.contains(&peak), "{peak}: {summary}");
    let best = (0..36000)
        .map(|i| f64::from(i) * 0.01f64.to_radians())
        .map(|th| force(th) * e * th.cos() * 1e-3)
        .fold(f64::MIN, f64::max);
    assert!(
        summary.contains(&format!("driver \"drive\": max {} N·m", sig4(best))),
        "{best}: {summary}"
    );
    for page in ["forces.png", "efforts.png", "forces.svg", "efforts.svg"] {
        assert!(out_dir.join(page).exists(), "{page}");
    }
}

/// 4 significant digits, as the summary prints them.
fn sig4(x: f64) -> String {
    let scale = 10f64.powi(3 - x.abs().log10().floor() as i32);
    camkin::human::human((x * scale).round() / scale)
}

#[test]
fn the_checks_exit_3_and_the_files_flags_exit_2() {
    let (_dir, path) = system();
    // the no-follow speed: m e ω² − k e = P, ω = √((P + k e) / (m e))
    let jump = ((20.0 + 10.0) / (0.2 * 0.005f64)).sqrt() * 60.0 / TAU;
    let out = run!("forces", &path, "--target-rpm", "2000")
        .assert()
        .code(3);
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    let at: f64 = stderr
        .split(" rpm, below")
        .next()
        .and_then(|s| s.rsplit(' ').next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("{stderr}"));
    assert!((at - jump).abs() <= 1.0, "{at} rpm, closed form {jump} rpm");
    run!("forces", &path, "--target-rpm", "1600")
        .assert()
        .success();
    // the force's least, 20 − 6.05 N, under a margin of 15 N
    let out = run!("forces", &path, "--margin", "15").assert().code(3);
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(
        stderr.contains("\"disc on face\"") && stderr.contains("margin 15 N"),
        "{stderr}"
    );
    for (flags, says) in [
        (vec!["--face-width", "8"], "--face-width 8"),
        (vec!["--materials", "steel,bronze"], "--materials"),
    ] {
        let out = run!("forces", &path).args(flags).assert().code(2);
        let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
        assert!(stderr.contains(says), "{stderr}");
    }
    // the sweep's work is in the estimate: refused up front
    let out = run!(
        "forces",
        examples().join("valve-train.toml"),
        "--target-rpm",
        "1000000",
        "--step",
        "0.01"
    )
    .assert()
    .code(2);
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(
        stderr.contains("simulated steps") && stderr.contains("--large"),
        "{stderr}"
    );
    // a system without [dynamics]: its forces come from a simulation
    let out = run!("forces", examples().join("two-followers.toml"))
        .assert()
        .code(2);
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(stderr.contains("[dynamics]"), "{stderr}");
}

/// The disc's lubrication with `[lubrication]` and the contact's face width: along the face the
/// disc's surface passes the contact at `−ωR` and the face's at `eω sin θ` (closed forms), the
/// load per width the closed-form force over 10 mm; `lubrication.csv` has a row per sample; the
/// cam mechanism's lubrication flags are refused for a system, naming the file's keys.
#[test]
fn a_systems_lubrication_against_the_discs_closed_forms() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("disc.toml");
    let text = SYSTEM.replace(
        "curve_b = { kind = \"line\", anchor = [0.0, 0.0], direction = [1.0, 0.0] }\n",
        "curve_b = { kind = \"line\", anchor = [0.0, 0.0], direction = [1.0, 0.0] }\nface_width = 10.0\n",
    ) + "\n[lubrication]\noil = \"sae-30@100c\"\nroughness_um = [0.2, 0.3]\n";
    std::fs::write(&path, text).unwrap();
    let out = run!(
        "forces",
        &path,
        "--step",
        "1",
        "--out",
        dir.path().join("out")
    )
    .assert()
    .success();
    let stdout = String::from_utf8_lossy(&out.get_output().stdout).to_string();
    assert!(
        stdout.contains("lubrication of \"disc on face\": λ min"),
        "{stdout}"
    );
    let (h, rows) =
        parse_csv(&std::fs::read(dir.path().join("out").join("lubrication.csv")).unwrap());
    let c = columns(&h);
    assert_eq!(rows.len(), 361);
    let w = 600.0 * TAU / 60.0;
    let (r, e, m, k, p) = (0.020, 0.005, 0.2, 2000.0, 20.0);
    let x = |row: &Vec<String>, name: &str| -> f64 { row[c[name]].parse().unwrap() };
    let s = -x(&rows[0], "entrainment_m_s").signum();
    for row in &rows {
        let th = x(row, "driver_angle_deg").to_radians();
        let (ua, ub) = (-s * w * r, s * e * w * th.sin());
        let scale = w * r;
        let ent = x(row, "entrainment_m_s");
        assert!((ent - 0.5 * (ua + ub)).abs() < 1e-9 * scale, "{row:?}");
        assert!(
            (x(row, "sliding_m_s") - (ua - ub)).abs() < 1e-9 * scale,
            "{row:?}"
        );
        let f = p + (k * e - m * e * w * w) * th.sin();
        assert!(
            (x(row, "load_N_per_m") - f / 0.010).abs() < 1e-6 * f / 0.010,
            "{row:?}"
        );
        assert_eq!(row[c["contact"]], "disc on face");
    }
    for flag in [["--oil", "sae-30@100c"], ["--roughness", "0.1,0.1"]] {
        let out = run!("forces", &path).args(flag).assert().code(2);
        let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
        assert!(
            stderr.contains(flag[0]) && stderr.contains("[lubrication]"),
            "{stderr}"
        );
    }
}
