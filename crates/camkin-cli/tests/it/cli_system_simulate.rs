//! Issue 46: `camkin simulate` on a system file. The valve train of
//! `examples/valve-train.toml` at a low speed, where the valve follows the cam, seats
//! at the closing ramp's speed where it lands: the cycloidal ramp's finger rate there times the pad's
//! lever arm (55 mm), a closed form that shares nothing with the simulation; its lift peaks at
//! the program's 9.85° of the finger through the pad's circle. Bad dynamics input exits 2
//! naming the element and its value.

use crate::common::*;
use std::f64::consts::TAU;

/// The example with its camshaft at `rpm` and its valve spring massless.
fn valve_train_at(rpm: f64) -> (tempfile::TempDir, std::path::PathBuf) {
    let text = std::fs::read_to_string(examples().join("valve-train.toml")).unwrap();
    // its valve spring massless: the ramp's closed form has no coils to carry
    let text = text
        .replace("speed_rpm = 3000.0", &format!("speed_rpm = {rpm:?}"))
        .replace("masses = 8", "masses = 0")
        .replace("damping_ratio = 0.03", "");
    let (dir, path) = written("vt.toml", text);
    (dir, path)
}

#[test]
fn a_slow_valve_train_seats_at_its_ramps_speed_and_lifts_as_its_program_says() {
    let rpm = 300.0;
    let (_dir, path) = valve_train_at(rpm);
    let out = run!("simulate", &path, "--step", "0.25").assert().success();
    let (header, rows) = parse_csv(&out.get_output().stdout);
    let col = columns(&header);
    assert_eq!(rows.len(), 1441);
    let num = |r: &Vec<String>, c: &str| r[col[c]].parse::<f64>().unwrap();
    // the lift: the pad's lowest point, the finger turned 9.85° down about its pivot
    let th = (-9.85f64).to_radians();
    let closed = -((55.0 * th.sin() + 10.0 * th.cos()) - 10.0);
    let lift = rows
        .iter()
        .map(|r| -28.0 - num(r, "valve_y_mm"))
        .fold(f64::MIN, f64::max);
    // less the lash adjuster's squeeze (its 20 000 N/mm under a few hundred N)
    assert!(
        (lift - closed).abs() < 0.03,
        "lift {lift} mm, the program's {closed} mm"
    );
    // the seating: an impact of "seat" at the closing ramp's speed where it lands, the
    // cycloid `s' = h/β (1 − cos 2πx)` (h = −0.15°, β = 20°, from 140°) on the pad's 55 mm lever
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    let seat: Vec<f64> = stderr
        .lines()
        .find(|l| l.contains("impact") && l.contains("seat"))
        .unwrap_or_else(|| panic!("no seating impact: {stderr}"))
        .split_whitespace()
        .skip(2)
        .map(|x| x.parse().unwrap())
        .collect();
    let (angle, speed) = (seat[1], seat[2]);
    assert!(
        angle > 140.0 && angle < 160.0,
        "seats at {angle}°: {stderr}"
    );
    let w = rpm * TAU / 60.0;
    let x = (angle - 140.0) / 20.0;
    let ramp = 0.15 / 20.0 * (1.0 - (TAU * x).cos()) * w * 55.0;
    assert!(
        (speed - ramp).abs() < 0.002 * ramp,
        "seating at {speed} mm/s at {angle}°, the ramp's {ramp} mm/s"
    );
    // the seat carries the spring's 250 N less the pad's push while closed
    let last = rows.last().unwrap();
    assert_eq!(last[col["seat_in_contact"]], "true");
    let seat_force = num(last, "seat_force_N");
    assert!(seat_force > 200.0 && seat_force < 250.0, "{seat_force}");
}

#[test]
fn bad_dynamics_input_exits_2_naming_the_element_and_its_value() {
    let text = std::fs::read_to_string(examples().join("valve-train.toml")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    for (from, to, says) in [
        (
            "restitution = 0.3",
            "restitution = 1.5",
            "contact[2].restitution = 1.5",
        ),
        ("mass = 0.045", "mass = 0.0", "body[3].mass = 0"),
        ("mass = 0.045", "mass = -0.045", "body[3].mass = -0.045"),
        (
            "gravity = [0.0, -9.81]",
            "gravity = [0.0, 1e400]",
            "gravity",
        ),
        (
            "materials = \"steel,aisi-52100\"",
            "materials = \"steel\"",
            "contact[1].materials",
        ),
        (
            "face_width = 8.0",
            "face_width = -8.0",
            "contact[1].face_width = -8",
        ),
        (
            "centre_of_mass = [15.0, 0.0]",
            "centre_of_mass = [15.0, nan]",
            "body[2].centre_of_mass = [15, NaN]",
        ),
    ] {
        let path = dir.path().join("bad.toml");
        std::fs::write(&path, text.replacen(from, to, 1)).unwrap();
        let out = run!("simulate", &path).assert().code(2);
        let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
        assert!(stderr.contains(says), "{to}: {stderr}");
    }
    // a constant-velocity ramp leaves a corner on the cam where it meets the dwell: refused
    // for dynamics, naming the segment where the velocity jumps
    let path = dir.path().join("bad.toml");
    std::fs::write(
        &path,
        text.replacen(
            "{ law = \"cycloidal\", rise = -0.15",
            "{ law = \"constant-velocity\", rise = -0.15",
            1,
        ),
    )
    .unwrap();
    let out = run!("simulate", &path).assert().code(2);
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(
        stderr.contains("contact[0].curve_a.segments[3].law")
            && stderr.contains("velocity jumps")
            && stderr.contains("140"),
        "{stderr}"
    );
    // a spring with no ends: its `bodies` and `at` left out, named at its table
    let path = dir.path().join("bad.toml");
    std::fs::write(
        &path,
        format!("{text}\n[[spring]]\nname = \"loose\"\nstiffness = 1.0\nfree_length = 1.0\n"),
    )
    .unwrap();
    let out = run!("simulate", &path).assert().code(2);
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(
        stderr.contains("spring") && stderr.contains("bodies"),
        "{stderr}"
    );
    // a four-bar driven by its rocker into the toggle it cannot pass (crank 20, coupler 50,
    // rocker 40, ground 60 mm; at 153.6°, 0.1489 s from 100° at 60 rpm): simulate and forces
    // stop there, naming the dead point, exit 2 (an internal error "the augmented mass matrix
    // is singular" half a second later, before)
    let path = dir.path().join("toggle.toml");
    std::fs::write(&path, FOUR_BAR_INTO_ITS_TOGGLE).unwrap();
    for cmd in ["simulate", "forces"] {
        let out = run!(cmd, &path).assert().code(2);
        let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
        assert!(stderr.contains("at t = 0.1489"), "{cmd}: {stderr}");
        assert!(stderr.contains("dead point (toggle)"), "{cmd}: {stderr}");
    }
    // work over the limit: refused up front with its estimate
    let out = run!(
        "simulate",
        examples().join("valve-train.toml"),
        "--revolutions",
        "5000",
        "--step",
        "0.25"
    )
    .assert()
    .code(2);
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(
        stderr.contains("simulated steps") && stderr.contains("--large"),
        "{stderr}"
    );
    // the flags a system has no use for are refused, not ignored
    for (flags, says) in [
        (["--start-angle", "10"], "--start-angle"),
        (["--format", "json"], "--format json"),
    ] {
        let out = run!("simulate", examples().join("valve-train.toml"))
            .args(flags)
            .assert()
            .code(2);
        let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
        assert!(stderr.contains(says), "{stderr}");
    }
    // no step is refused: a coarse output step runs, its steps chosen by the tolerances, and
    // the valve train's no flags (the flagship example) run too
    run!(
        "simulate",
        examples().join("valve-train.toml"),
        "--step",
        "2"
    )
    .stdout_ok();
    run!("simulate", examples().join("valve-train.toml")).stdout_ok();
    // the tolerances out of range are named as the flags are
    for (flag, value) in [("--rtol", "0"), ("--atol", "0.5"), ("--rtol", "1e-14")] {
        run!("simulate", examples().join("valve-train.toml"), flag, value)
            .refused(format!("{flag}: {value} must be from 1e-13 to 0.01"));
    }
    // the integrator is named as the flag is, with its choices
    run!(
        "simulate",
        examples().join("valve-train.toml"),
        "--integrator",
        "stiff"
    )
    .refused("'stiff' for '--integrator <SCHEME>'");
}

/// `--integrator implicit` runs the valve train to the explicit pair's outputs (the library's
/// `dynamics_stiff` measures the two against closed forms): its events at the same instants
/// to 1e-9 s and its valve lift within 1e-6 mm at every output.
#[test]
fn the_implicit_integrator_runs_the_valve_train_as_the_explicit_one() {
    let column = |out: &str, name: &str| -> Vec<f64> {
        let mut lines = out.lines();
        let head: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
        let j = head
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("{name}"));
        lines
            .map(|l| {
                l.split(',')
                    .nth(j)
                    .and_then(|x| x.parse().ok())
                    .unwrap_or(f64::NAN)
            })
            .collect()
    };
    let mut runs = Vec::new();
    for scheme in ["explicit", "implicit"] {
        let out = run!(
            "simulate",
            examples().join("valve-train.toml"),
            "--revolutions",
            "0.5",
            "--integrator",
            scheme
        )
        .assert()
        .success();
        runs.push(String::from_utf8_lossy(&out.get_output().stdout).to_string());
    }
    let (a, b) = (
        column(&runs[0], "valve_y_mm"),
        column(&runs[1], "valve_y_mm"),
    );
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() < 1e-6, "{x} vs {y}");
    }
}

/// `--no-follow` sweeps the speed and prints where the finger leaves its cam (with the valve
/// spring massless, the reduced model's 4145 rpm less the lash adjuster's give: see the
/// library's `dynamics_valve_train`; with its coils' mass, lower);
/// `--out` writes the time series, the events and the lift, force and deviation pages.
#[test]
fn the_no_follow_speed_and_the_pages() {
    let out = run!(
        "simulate",
        examples().join("valve-train.toml"),
        "--no-follow",
        "1000:6000:500",
        "--step",
        "0.5"
    )
    .assert()
    .success();
    let text = String::from_utf8_lossy(&out.get_output().stdout).to_string();
    let rpm: f64 = text
        .split("no-follow speed: ")
        .nth(1)
        .and_then(|t| t.split(" rpm").next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("{text}"));
    // below 3892 rpm, the reduced model's with a third of the coils' mass on the valve (the
    // quasi-static share): the coils surge (their first mode at 574 Hz, the cam's tenth
    // harmonic at 3444 rpm) and the finger leaves sooner
    assert!(rpm > 3000.0 && rpm < 3892.0, "{text}");
    assert!(text.contains("\"cam on roller\""), "{text}");
    let dir = tempfile::tempdir().unwrap();
    let pages = dir.path().join("vt");
    run!(
        "simulate",
        examples().join("valve-train.toml"),
        "--step",
        "0.5",
        "--out",
        &pages
    )
    .assert()
    .success();
    for f in [
        "time_series.csv",
        "events.csv",
        "lift.svg",
        "lift.png",
        "forces.png",
        "deviation.png",
    ] {
        let len = std::fs::metadata(pages.join(f))
            .map(|m| m.len())
            .unwrap_or(0);
        assert!(len > 200, "{f}: {len} bytes");
    }
    let events = std::fs::read_to_string(pages.join("events.csv")).unwrap();
    assert!(events.contains("impact,seat"), "{events}");
}

/// The cam's Hertz pressure on the roller while the valve is shut: the base circle (20 mm) on
/// the roller (8 mm) over its 12 mm face, steel on steel, `p = √(F E* (1/R₁ + 1/R₂) / (π L))`
/// with the force of the same row — the curvatures' signs (a cam synthesised clockwise) and the
/// millimetres in it.
#[test]
fn the_cams_hertz_pressure_on_its_base_circle_is_the_closed_forms() {
    let out = run!(
        "simulate",
        examples().join("valve-train.toml"),
        "--step",
        "0.5"
    )
    .assert()
    .success();
    let (header, rows) = parse_csv(&out.get_output().stdout);
    let col = columns(&header);
    let e_star = 206e9 / (2.0 * (1.0 - 0.3 * 0.3));
    let mut checked = 0;
    for r in &rows {
        let angle: f64 = r[col["driver_angle_deg"]].parse().unwrap();
        if !(200.0..=350.0).contains(&angle) {
            continue;
        }
        let f: f64 = r[col["cam_on_roller_force_N"]].parse().unwrap();
        let p: f64 = r[col["cam_on_roller_hertz_MPa"]].parse().unwrap();
        let closed = (f * e_star * (1.0 / 0.020 + 1.0 / 0.008) / (std::f64::consts::PI * 0.012))
            .sqrt()
            / 1e6;
        assert!(
            (p - closed).abs() <= 1e-9 * closed,
            "at {angle}°: {p} MPa, {closed} MPa"
        );
        checked += 1;
    }
    assert!(checked > 200);
}

/// A gas force from a table of the crank angle on the valve (`[[gas_force]]`): 50 N pushing it
/// open at crank 0° takes 50 N off the seat's force there (the first row: statics alone); an
/// unsorted table exits 2 naming it.
#[test]
fn a_gas_force_table_pushes_the_valve() {
    let text = std::fs::read_to_string(examples().join("valve-train.toml")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let seat_at_start = |extra: &str| {
        let path = dir.path().join("gas.toml");
        std::fs::write(&path, format!("{text}\n{extra}")).unwrap();
        let out = run!("simulate", &path, "--step", "0.25", "--revolutions", "0.01")
            .assert()
            .success();
        let (header, rows) = parse_csv(&out.get_output().stdout);
        rows[0][columns(&header)["seat_force_N"]]
            .parse::<f64>()
            .unwrap()
    };
    let without = seat_at_start("");
    let with = seat_at_start(
        "[[gas_force]]\nname = \"cylinder\"\nbody = \"valve\"\nat = [0.0, -60.0]\ndirection = [0.0, -1.0]\ntable = [[0.0, 50.0], [360.0, 50.0]]\n",
    );
    assert!((without - with - 50.0).abs() < 1e-9, "{without} {with}");
    let path = dir.path().join("bad.toml");
    std::fs::write(
        &path,
        format!("{text}\n[[gas_force]]\nname = \"cylinder\"\nbody = \"valve\"\ndirection = [0.0, -1.0]\ntable = [[360.0, 50.0], [10.0, 5.0]]\n"),
    )
    .unwrap();
    let out = run!("simulate", &path).assert().code(2);
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(stderr.contains("gas_force[0].table"), "{stderr}");
}

/// A four-bar driven by its rocker past its toggle (see
/// `bad_dynamics_input_exits_2_naming_the_element_and_its_value`).
const FOUR_BAR_INTO_ITS_TOGGLE: &str = r#"length_unit = "mm"
[dynamics]
gravity = [0.0, 0.0]
[[body]]
name = "crank"
mass = 0.1
inertia = 1e-5
angle_deg = 5.0
[[body]]
name = "coupler"
mass = 0.1
inertia = 1e-5
position = [20.0, 0.0]
angle_deg = 50.0
[[body]]
name = "rocker"
mass = 0.1
inertia = 1e-5
position = [60.0, 0.0]
angle_deg = 100.0
[[joint]]
name = "O2"
kind = "revolute"
bodies = ["ground", "crank"]
[[joint]]
name = "A"
kind = "revolute"
bodies = ["crank", "coupler"]
at = [[20.0, 0.0], [0.0, 0.0]]
[[joint]]
name = "B"
kind = "revolute"
bodies = ["coupler", "rocker"]
at = [[50.0, 0.0], [40.0, 0.0]]
[[joint]]
name = "O4"
kind = "revolute"
bodies = ["rocker", "ground"]
at = [[0.0, 0.0], [60.0, 0.0]]
[[driver]]
name = "drive rocker"
body = "rocker"
coordinate = "angle"
speed_rpm = 60.0
start = 100.0
"#;

/// Issue 64: a system without a driver is simulated for a time. A pendulum (a bar pinned at
/// one end, in mm, started 3 mm off its pin and turning at 2 rad/s): with no flags it exits 2
/// naming `--duration`; `--duration 2 --interval 0.25` writes 9 samples in time (no driver
/// angle column), its energy constant to 1e-8 of its swing's (`m g L` scale), the start's
/// assembly said on stderr; `--out` draws its motion and energy; a duration with revolutions,
/// an interval alone, and a duration on a cam-follower file exit 2 naming the flags.
#[test]
fn a_driverless_system_runs_for_a_duration() {
    let text = "length_unit = \"mm\"\n[dynamics]\ngravity = [0.0, -9.81]\n[[body]]\nname = \"bar\"\nmass = 2.0\ninertia = 0.06\nposition = [300.0, 3.0]\nangular_velocity = 2.0\n[[joint]]\nname = \"pin\"\nkind = \"revolute\"\nbodies = [\"ground\", \"bar\"]\nat = [[0.0, 0.0], [-300.0, 0.0]]\n";
    let (dir, path) = written("pendulum.toml", text);
    run!("simulate", &path).refused("--duration SECONDS");
    let out = run!("simulate", &path, "--duration", "2", "--interval", "0.25")
        .assert()
        .success();
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert!(
        stderr.contains("assembled onto the joints") && stderr.contains("\"bar\" turned"),
        "{stderr}"
    );
    let (header, rows) = parse_csv(&out.get_output().stdout);
    assert_eq!(header[0], "time_s");
    assert!(!header.iter().any(|h| h.contains("driver_angle")));
    assert_eq!(rows.len(), 9);
    let col = columns(&header);
    let num = |r: &Vec<String>, c: &str| r[col[c]].parse::<f64>().unwrap();
    assert_eq!(num(&rows[8], "time_s"), 2.0);
    let scale = 2.0 * 9.81 * 300.0; // N·mm
    let e0 = num(&rows[0], "energy_N_mm");
    for r in &rows {
        let drift = (num(r, "energy_N_mm") - e0).abs() / scale;
        assert!(drift < 1e-8, "energy drifts by {drift:e} of m g L");
    }
    let pages = dir.path().join("pages");
    run!("simulate", &path, "--duration", "1", "--out", &pages)
        .assert()
        .success();
    for f in [
        "time_series.csv",
        "events.csv",
        "energy.csv",
        "motion.svg",
        "energy.svg",
    ] {
        assert!(pages.join(f).exists(), "{f}");
    }
    // the balance by element: gravity's work, integrated with the motion, is minus its
    // potential's change, computed from the positions; the pin does no work
    let (header, rows) = parse_csv(&std::fs::read(pages.join("energy.csv")).unwrap());
    assert_eq!(&header[..2], ["time_s", "kinetic_N_mm"]);
    let col = columns(&header);
    let num = |r: &Vec<String>, c: &str| r[col[c]].parse::<f64>().unwrap();
    let v0 = num(&rows[0], "gravity_potential_N_mm");
    for r in &rows {
        let work = num(r, "gravity_work_N_mm");
        let change = num(r, "gravity_potential_N_mm") - v0;
        assert!((work + change).abs() < 1e-8 * scale, "{work} {change}");
        assert!(num(r, "constraint_work_N_mm").abs() < 1e-8 * scale);
        assert!(num(r, "unexplained_N_mm").abs() < 1e-8 * scale);
    }
    run!("simulate", &path, "--duration", "1", "--revolutions", "1")
        .refused("--duration with --revolutions");
    run!("simulate", &path, "--interval", "0.1")
        .refused("--interval: is the output interval of a run in time");
    run!("simulate", &path, "--duration", "0").refused("--duration: 0 must be in (0, 1000000] s");
    run!("simulate", examples().join("paper.toml"), "--duration", "1")
        .refused("--duration: a run in time is for a system file");
}
