//! Issue 45: `camkin analyze` on a system file. The valve train's table holds every body's pose,
//! velocity and acceleration and every contact's row, equal (to the last bit printed) to the
//! library's answer at the same instants; a bad system file exits 2 naming the element and its
//! line.

use crate::common::*;
use std::f64::consts::TAU;

#[test]
fn the_valve_train_file_is_analysed_as_a_system() {
    let out = run!(
        "analyze",
        examples().join("valve-train-kinematics.toml"),
        "--angles",
        "0:360:15"
    )
    .assert()
    .success();
    let text = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    // two leading columns, twelve a body, thirteen a contact, the error
    assert_eq!(header.len(), 2 + 12 * 3 + 13 * 2 + 1);
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (vy, vay, fa, vjy) = (
        col("valve_y_mm"),
        col("valve_ay_mm_s2"),
        col("finger_angle_deg"),
        col("valve_jerk_y_mm_s3"),
    );
    let w = 3000.0 * TAU / 60.0;
    let (sys, [_, finger, valve]) = camkin::reference::single_valve_train(w);
    let mut sweep = sys.sweep().unwrap();
    let mut n = 0;
    for (k, line) in lines.enumerate() {
        let cells: Vec<&str> = line.split(',').collect();
        let s = sweep.step((15.0 * k as f64).to_radians() / w).unwrap();
        let (f, v) = (
            &s.bodies[finger.index().unwrap()],
            &s.bodies[valve.index().unwrap()],
        );
        let num = |i: usize| cells[i].parse::<f64>().unwrap();
        assert!((num(vy) - v.pose.origin.y).abs() <= 1e-12 * 100.0, "{line}");
        assert!(
            (num(fa) - f.pose.angle.to_degrees()).abs() <= 1e-10,
            "{line}"
        );
        assert!(
            (num(vay) - v.acceleration.y).abs() <= 1e-9 * v.acceleration.y.abs().max(1.0),
            "{line}"
        );
        let j = sys.jerk(&s).unwrap()[valve.index().unwrap()].linear.y;
        // the valve's jerk peaks near 3e9 mm/s³; at rest on the base circle it is zero to
        // rounding, which differs between the file's system and the reference's
        assert!((num(vjy) - j).abs() <= 1e-9 * j.abs().max(1e6), "{line}");
        assert_eq!(*cells.last().unwrap(), "", "{line}");
        // each contact's row holds: a_n on A is a_n on B (eq. 11), to rounding
        for c in ["cam_on_roller", "pad_on_valve"] {
            let r = num(col(&format!("{c}_residual_mm_s2")));
            let terms = [
                "normal_acceleration",
                "coriolis_a",
                "relative_a",
                "coriolis_b",
                "relative_b",
            ]
            .iter()
            .map(|t| num(col(&format!("{c}_{t}_mm_s2"))).abs())
            .fold(1.0, f64::max);
            assert!(
                r.abs() <= 1e-14 * terms,
                "{c}: residual {r} against terms of {terms}"
            );
        }
        n += 1;
    }
    assert_eq!(n, 24);
}

#[test]
fn a_bad_system_file_exits_2_naming_the_element() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("s.toml");
    let text = std::fs::read_to_string(examples().join("valve-train-kinematics.toml"))
        .unwrap()
        .replace(
            "bodies = [\"finger\", \"valve\"]",
            "bodies = [\"finger\", \"vlave\"]",
        );
    std::fs::write(&f, &text).unwrap();
    let line = text.lines().position(|l| l.contains("\"vlave\"")).unwrap() + 1;
    run!("analyze", &f)
        .refused(format!("s.toml:{line}:"))
        .stderr(predicate::str::contains("contact[1].bodies"))
        .stderr(predicate::str::contains("\"vlave\""));
}

/// Issue 45's bad system files: a closed loop that cannot assemble (a four-bar whose coupler is
/// too short to reach its rocker) and a spring with both ends at one point of one body exit 2
/// naming the element.
#[test]
fn a_loop_that_cannot_close_and_a_spring_on_one_point_exit_2() {
    let four_bar = |coupler: f64| {
        format!(
            r#"length_unit = "mm"
[[body]]
name = "crank"
[[body]]
name = "coupler"
position = [10.0, 0.0]
[[body]]
name = "rocker"
position = [40.0, 0.0]
angle_deg = 90.0
[[joint]]
name = "O2"
kind = "revolute"
bodies = ["ground", "crank"]
[[joint]]
name = "A"
kind = "revolute"
bodies = ["crank", "coupler"]
at = [[10.0, 0.0], [0.0, 0.0]]
[[joint]]
name = "B"
kind = "revolute"
bodies = ["coupler", "rocker"]
at = [[{coupler}, 0.0], [25.0, 0.0]]
[[joint]]
name = "O4"
kind = "revolute"
bodies = ["ground", "rocker"]
at = [[40.0, 0.0], [0.0, 0.0]]
[[driver]]
name = "motor"
body = "crank"
coordinate = "angle"
speed_rpm = 60.0
"#
        )
    };
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("s.toml");
    // it closes with a coupler of 35 (10 + 35 > 30 + 25 > …)
    std::fs::write(&f, four_bar(35.0)).unwrap();
    run!("analyze", &f, "--at", "0,90").assert().success();
    std::fs::write(&f, four_bar(3.0)).unwrap();
    run!("analyze", &f, "--at", "0,90")
        .refused("cannot be")
        .stderr(predicate::str::contains("joint \""));
    let spring = format!(
        "{}[[spring]]\nname = \"return spring\"\nbodies = [\"rocker\", \"rocker\"]\nat = [[5.0, 0.0], [5.0, 0.0]]\nstiffness = 10.0\nfree_length = 20.0\n",
        four_bar(35.0)
    );
    std::fs::write(&f, &spring).unwrap();
    let line = spring
        .lines()
        .position(|l| l.starts_with("bodies = [\"rocker\", \"rocker\"]"))
        .unwrap()
        + 1;
    run!("analyze", &f)
        .refused(format!("s.toml:{line}:"))
        .stderr(predicate::str::contains("spring[0].bodies"))
        .stderr(predicate::str::contains("joins \"rocker\" to itself"));
}

/// A rocker on an eccentric held by a torsion spring, for dynamics (issue 63's examples).
const ROCKER: &str = r#"length_unit = "mm"
[dynamics]
gravity = [0.0, -9.81]
[[body]]
name = "cam"
mass = 1.0
inertia = 1e-3
[[body]]
name = "rocker"
position = [-50.0, 45.0]
angle_deg = -4.78
mass = 0.05
inertia = 2e-5
[[joint]]
name = "camshaft"
kind = "revolute"
bodies = ["ground", "cam"]
[[joint]]
name = "pivot"
kind = "revolute"
bodies = ["ground", "rocker"]
at = [[-50.0, 45.0], [0.0, 0.0]]
[[driver]]
name = "drive"
body = "cam"
coordinate = "angle"
speed_rpm = 1000.0
[[contact]]
name = "cam on roller"
bodies = ["cam", "rocker"]
curve_a = { kind = "circle", center = [10.0, 0.0], radius = 30.0 }
curve_b = { kind = "circle", center = [60.0, 0.0], radius = 10.0 }
face_width = 10.0
[[torsion_spring]]
name = "return spring"
bodies = ["ground", "rocker"]
stiffness = 200.0
free_angle_deg = -90.0
preload = 0.0
"#;

/// Issue 63, class "invalid models accepted silently": each change to a valid system file is
/// refused (exit 2) at its key with what the user wrote — names used twice (their columns would
/// appear twice), a list of three where two are meant, an element joining a body to itself, a
/// gas force on the ground, magnitudes beyond the range the dynamics is computed in, a face
/// width whose Hertz pressure is infinite.
#[test]
fn invalid_system_models_are_refused_at_their_key() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("s.toml");
    std::fs::write(&f, ROCKER).unwrap();
    run!("simulate", &f, "--revolutions", "0.1")
        .assert()
        .success();
    let contact =
        &ROCKER[ROCKER.find("[[contact]]").unwrap()..ROCKER.find("[[torsion_spring]]").unwrap()];
    let gas = "[[gas_force]]\nname = \"gas\"\nbody = \"ground\"\ndirection = [0.0, 1.0]\ntable = [[0.0, 10.0], [360.0, 20.0]]\n";
    let coil = "[[coil_spring]]\nname = \"coil\"\nbodies = [\"ground\", \"rocker\"]\nat = [[-50.0, 100.0], [0.0, 0.0]]\nstiffness = 1.0\nfree_length = 60.0\nmass = 1e300\nmasses = 4\n";
    let cases: Vec<(String, &str)> = vec![
        (format!("{ROCKER}{contact}"), "contact[1].name: \"cam on roller\": contact[0] has this name already"),
        (ROCKER.replace("name = \"return spring\"", "name = \"cam\""), "torsion_spring[0].name: \"cam\": body[0] has this name already"),
        (format!("{ROCKER}[[driver]]\nname = \"drive\"\nbody = \"rocker\"\ncoordinate = \"angle\"\nspeed_rpm = 1.0\n"), "driver[1].name: \"drive\": driver[0] has this name already"),
        (ROCKER.replace("bodies = [\"ground\", \"cam\"]", "bodies = [\"ground\", \"cam\", \"rocker\"]"), "expected two bodies' names"),
        (ROCKER.replace("gravity = [0.0, -9.81]", "gravity = [0.0, -9.81, 0.0]"), "dynamics.gravity"),
        (ROCKER.replace("bodies = [\"ground\", \"rocker\"]\nstiffness", "bodies = [\"rocker\", \"rocker\"]\nstiffness"), "joins \"rocker\" to itself"),
        (format!("{ROCKER}{gas}"), "gas_force[0].body: the ground does not move"),
        (ROCKER.replace("mass = 0.05", "mass = 1e12"), "body[1].mass = 1e12: is outside the range"),
        (ROCKER.replace("inertia = 2e-5", "inertia = 1e-20"), "body[1].inertia = 1e-20: is outside the range"),
        (ROCKER.replace("gravity = [0.0, -9.81]", "gravity = [0.0, -1e7]"), "dynamics.gravity = [0, -10000000]: is outside the range the dynamics is computed in (at most 1e6 m/s²)"),
        (ROCKER.replace("preload = 0.0", "preload = 1e300"), "torsion_spring[0].preload = 1e300: is outside the range"),
        (ROCKER.replace("free_angle_deg = -90.0", "free_angle_deg = 1e300"), "torsion_spring[0].free_angle_deg = 1e300: is outside the range"),
        (ROCKER.replace("speed_rpm = 1000.0", "speed_rpm = 1e300"), "driver[0].speed_rpm = 1e300: is outside the range"),
        (ROCKER.replace("face_width = 10.0", "face_width = 1e-300"), "contact[0].face_width = 1e-300"),
        (format!("{ROCKER}{coil}"), "coil_spring[0].mass = 1e300: is outside the range"),
        // it was "largest residual NaN, in )"
        (format!("{ROCKER}{}", coil.replace("mass = 1e300", "mass = 0.02\nsolid_length = 70.0")), "coil_spring[0].solid_length = 70: must be below the free length 60"),
        // an oil no contact takes (the rocker's contact has no face width): ignored, before
        (format!("{}[lubrication]\noil = \"sae-30@100c\"\n", ROCKER.replace("face_width = 10.0\n", "")), "lubrication: no contact takes this oil"),
    ];
    for (text, needle) in cases {
        std::fs::write(&f, &text).unwrap();
        for command in ["simulate", "analyze"] {
            run!(command, &f)
                .refused(needle)
                .stderr(predicate::str::contains("panicked").not());
        }
    }
}

/// `camkin plot` on a system file draws it at the driver angles asked (SVG and PNG) and over a
/// revolution (an animation), following its contacts through half-degree instants between.
#[test]
fn a_system_is_drawn_at_its_driver_angles() {
    let dir = tempfile::tempdir().unwrap();
    for example in ["valve-train-kinematics.toml", "gear-train.toml"] {
        let out = dir.path().join(example);
        run!(
            "plot",
            examples().join(example),
            "--out",
            &out,
            "--at",
            "0,90",
            "--frames",
            "8"
        )
        .assert()
        .success();
        for f in [
            "drawing_0.svg",
            "drawing_0.png",
            "drawing_90.svg",
            "drawing_90.png",
            "animation.svg",
        ] {
            let p = out.join(f);
            assert!(
                std::fs::metadata(&p).is_ok_and(|m| m.len() > 1000),
                "{example}: {f}"
            );
        }
        let svg = std::fs::read_to_string(out.join("drawing_90.svg")).unwrap();
        assert!(svg.contains("driver angle 90°"), "{example}");
    }
}

/// A cam file analysed with `--system`: the cam and the follower as bodies of a system. For
/// each follower kind (the translating flat face of the paper, an oscillating roller, a
/// clockwise cam under an offset roller) the follower's coordinate read from its body's columns
/// is the cam path's `position`, `velocity` and `acceleration` in the same run's other table, to
/// 1e-12 of the size (ω × size, ω² × size), at the cam angles asked; the sweep's column is the
/// cam angle.
#[test]
fn a_cam_file_as_a_system_gives_the_cam_paths_motion() {
    let table = |file: &str, system: bool| -> Vec<std::collections::HashMap<String, f64>> {
        let mut cmd = camkin();
        cmd.arg("analyze")
            .arg(examples().join(file))
            .args(["--angles", "0:360:7.5"]);
        if system {
            cmd.arg("--system");
        }
        let out = cmd.assert().success();
        let text = String::from_utf8(out.get_output().stdout.clone()).unwrap();
        let mut lines = text.lines();
        let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
        lines
            .map(|l| {
                header
                    .iter()
                    .cloned()
                    .zip(l.split(',').map(|c| c.parse::<f64>().unwrap_or(f64::NAN)))
                    .collect()
            })
            .collect()
    };
    // (file, its length unit, the follower's coordinate from its body's columns, size, rpm)
    type Coordinate = fn(&std::collections::HashMap<String, f64>, &str) -> [f64; 4];
    let slide_x: Coordinate = |r, u| {
        [
            r[&format!("follower_x_{u}")],
            r[&format!("follower_vx_{u}_s")],
            r[&format!("follower_ax_{u}_s2")],
            r[&format!("follower_jerk_x_{u}_s3")],
        ]
    };
    let slide_y: Coordinate = |r, u| {
        [
            r[&format!("follower_y_{u}")],
            r[&format!("follower_vy_{u}_s")],
            r[&format!("follower_ay_{u}_s2")],
            r[&format!("follower_jerk_y_{u}_s3")],
        ]
    };
    let arm: Coordinate = |r, _| {
        [
            r["follower_angle_deg"],
            r["follower_omega_deg_s"],
            r["follower_alpha_deg_s2"],
            r["follower_jerk_angle_deg_s3"],
        ]
    };
    for (file, unit, coordinate, size, rpm) in [
        ("paper.toml", "cm", slide_x, 5.0, 1000.0),
        ("oscillating-roller.toml", "cm", arm, 360.0, 1000.0),
        ("eccentric-roller.toml", "cm", slide_y, 5.0, 600.0),
    ] {
        let (sys, cam) = (table(file, true), table(file, false));
        assert_eq!(sys.len(), 48, "{file}");
        let w: f64 = rpm * TAU / 60.0;
        // the cam body turns at the cam's speed in its own sense
        assert!((sys[0]["cam_omega_deg_s"].abs().to_radians() - w).abs() <= 1e-12 * w);
        for (s, c) in sys.iter().zip(&cam) {
            assert_eq!(s["angle_deg"], c["angle_deg"], "{file}");
            let [q, v, a, j] = coordinate(s, unit);
            let (cq, cv, ca, cj) = if file.starts_with("oscillating") {
                (
                    c["position_deg"],
                    c["velocity_deg_s"],
                    c["acceleration_deg_s2"],
                    c["jerk_deg_s3"],
                )
            } else {
                (
                    c[&format!("position_{unit}")],
                    c[&format!("velocity_{unit}_s")],
                    c[&format!("acceleration_{unit}_s2")],
                    c[&format!("jerk_{unit}_s3")],
                )
            };
            // the jerk: empty (NaN here) in both where the contact is on a spline node
            assert_eq!(j.is_nan(), cj.is_nan(), "{file}: jerk {j} {cj}");
            if !j.is_nan() {
                assert!(
                    (j - cj).abs() <= 1e-12 * w * w * w * size,
                    "{file}: {j} {cj}"
                );
            }
            // the eccentric roller travels along +y from x = -0.5: its y is its position
            assert!((q - cq).abs() <= 1e-12 * size, "{file}: {q} {cq}");
            assert!((v - cv).abs() <= 1e-12 * w * size, "{file}: {v} {cv}");
            assert!((a - ca).abs() <= 1e-12 * w * w * size, "{file}: {a} {ca}");
        }
    }
}

/// A cam synthesised from a motion program drives a rocker whose other arm drives a slider
/// through a rod (`examples/cam-rocker-slider.toml`), checked through the command against a
/// reference that shares no formula with the method: the rocker's angle is the program's
/// (`φ₀ + s(θ)`, the textbook cycloidal and 3-4-5 laws and their derivatives written out here,
/// `φ₀` where the roller centre meets the prime circle), and the slider's height is the rod's
/// loop closed by hand, `y = P_y − √(l² − (x_g − P_x)²)`, differentiated by five-point
/// differences. Positions to 1e-12 of the size, velocities to 1e-9 and accelerations to 1e-7
/// of their peaks.
#[test]
fn a_cam_rocker_and_slider_against_the_program_and_the_loop() {
    use std::f64::consts::PI;
    let out = run!(
        "analyze",
        examples().join("cam-rocker-slider.toml"),
        "--angles",
        "0:360:1.5"
    )
    .assert()
    .success();
    let (header, rows) = parse_csv(&out.get_output().stdout);
    let col = columns(&header);
    let w = 600.0 * TAU / 60.0;
    // the program, in degrees of arm angle against degrees of cam angle: (s, s', s'') in rad
    let program = |th: f64| -> [f64; 3] {
        let deg = th.to_degrees().rem_euclid(360.0);
        let b = 120f64.to_radians();
        let h = 15f64.to_radians();
        if deg < 120.0 {
            let x = deg / 120.0;
            [
                h * (x - (2.0 * PI * x).sin() / (2.0 * PI)),
                h / b * (1.0 - (2.0 * PI * x).cos()),
                2.0 * PI * h / (b * b) * (2.0 * PI * x).sin(),
            ]
        } else if deg < 180.0 {
            [h, 0.0, 0.0]
        } else if deg < 300.0 {
            let x = (deg - 180.0) / 120.0;
            let p = 10.0 * x.powi(3) - 15.0 * x.powi(4) + 6.0 * x.powi(5);
            let dp = 30.0 * x * x - 60.0 * x.powi(3) + 30.0 * x.powi(4);
            let ddp = 60.0 * x - 180.0 * x * x + 120.0 * x.powi(3);
            [h * (1.0 - p), -h / b * dp, -h / (b * b) * ddp]
        } else {
            [0.0, 0.0, 0.0]
        }
    };
    // φ₀: the roller centre (60 mm from the pivot at (−60, 40)) on the prime circle (38 mm),
    // the branch nearest 0°
    let (ox, oy, arm, prime): (f64, f64, f64, f64) = (-60.0, 40.0, 60.0, 38.0);
    let d = ox.hypot(oy);
    let a = (prime * prime - arm * arm + d * d) / (2.0 * d);
    let hh = (prime * prime - a * a).sqrt();
    let (ux, uy) = (ox / d, oy / d);
    let phi0 = [1.0, -1.0]
        .map(|s| {
            let (cx, cy) = (a * ux - s * hh * uy, a * uy + s * hh * ux);
            (cy - oy).atan2(cx - ox)
        })
        .into_iter()
        .min_by(|p, q| p.abs().total_cmp(&q.abs()))
        .unwrap();
    // the slider's height at cam angle θ: the rod (30 mm) from the rocker's pin (−30, 10) in
    // its frame to the guide x = −100, the slider below the pin
    let slider = |th: f64| -> f64 {
        let phi = phi0 + program(th)[0];
        let (c, s) = (phi.cos(), phi.sin());
        let (px, py) = (ox + c * -30.0 - s * 10.0, oy + s * -30.0 + c * 10.0);
        py - (30.0f64 * 30.0 - (-100.0 - px).powi(2)).sqrt()
    };
    let num = |r: &Vec<String>, k: &str| r[col[k]].parse::<f64>().unwrap();
    let (mut peak_v, mut peak_a) = (0.0f64, 0.0f64);
    let mut worst = [0.0f64; 5];
    let mut worst_a = 0.0f64;
    let size = 100.0;
    for r in &rows {
        let th = num(r, "driver_angle_deg").to_radians();
        assert_eq!(r[col["error"]], "", "{r:?}");
        let [s, ds, dds] = program(th);
        worst[0] = worst[0].max((num(r, "rocker_angle_deg").to_radians() - phi0 - s).abs());
        worst[1] = worst[1].max((num(r, "rocker_omega_deg_s").to_radians() - ds * w).abs() / w);
        worst[2] = worst[2]
            .max((num(r, "rocker_alpha_deg_s2").to_radians() - dds * w * w).abs() / (w * w));
        // the slider: its height, and five-point differences in θ away from the program's
        // joins (where the 3-4-5 law's acceleration, and so the slider's, has a corner)
        let y = slider(th);
        worst[3] = worst[3].max((num(r, "slider_y_mm") - y).abs() / size);
        let deg = th.to_degrees();
        let near_join = [0.0, 120.0, 180.0, 300.0, 360.0]
            .iter()
            .any(|j| (deg - j).abs() < 0.5);
        if !near_join {
            let e = 1e-3;
            let f = |k: f64| slider(th + k * e);
            let d1 = (f(-2.0) - 8.0 * f(-1.0) + 8.0 * f(1.0) - f(2.0)) / (12.0 * e) * w;
            let d2 = (-f(-2.0) + 16.0 * f(-1.0) - 30.0 * f(0.0) + 16.0 * f(1.0) - f(2.0))
                / (12.0 * e * e)
                * w
                * w;
            peak_v = peak_v.max(d1.abs());
            peak_a = peak_a.max(d2.abs());
            worst[4] = worst[4].max((num(r, "slider_vy_mm_s") - d1).abs());
            worst_a = worst_a.max((num(r, "slider_ay_mm_s2") - d2).abs());
        }
    }
    eprintln!("rocker {:.1e} rad, {:.1e}, {:.1e}; slider {:.1e} of the size, velocity {:.1e} mm/s of {peak_v:.0}, acceleration {worst_a:.1e} mm/s² of {peak_a:.0}", worst[0], worst[1], worst[2], worst[3], worst[4]);
    assert!(
        worst[0] <= 1e-12 && worst[1] <= 1e-12 && worst[2] <= 1e-12,
        "{worst:?}"
    );
    assert!(worst[3] <= 1e-12, "{worst:?}");
    assert!(worst[4] <= 1e-9 * peak_v, "{worst:?} {peak_v}");
    assert!(worst_a <= 1e-7 * peak_a, "{worst_a} {peak_a}");
    assert!(peak_a > 1e4, "{peak_a}");
}

/// `camkin contacts SYSTEM.toml`: one row per contact per instant, whose acceleration
/// constraint row, applied to the two bodies' accelerations that `analyze` gives at the same
/// instants, is its `gamma` (eq. 11), and whose normal is the row's `x`, `y` entries of its
/// first body (the gap's gradient).
#[test]
fn a_systems_contacts_are_rows_that_the_accelerations_meet() {
    let file = examples().join("valve-train-kinematics.toml");
    let run = |cmd: &str| {
        let out = run!(cmd, &file, "--angles", "0:360:10").assert().success();
        parse_csv(&out.get_output().stdout)
    };
    let (ch, crows) = run("contacts");
    let (ah, arows) = run("analyze");
    let (c, a) = (columns(&ch), columns(&ah));
    assert_eq!(crows.len(), 2 * arows.len());
    let num = |r: &Vec<String>, col: &std::collections::HashMap<&str, usize>, k: &str| {
        r[col[k]].parse::<f64>().unwrap()
    };
    let mut worst: f64 = 0.0;
    for (k, r) in crows.iter().enumerate() {
        let instant = &arows[k / 2];
        assert_eq!(
            num(r, &c, "driver_angle_deg"),
            num(instant, &a, "driver_angle_deg")
        );
        assert_eq!(r[c["error"]], "");
        let body = |which: &str| r[c[&format!("body_{which}")[..]]].clone();
        let accel = |b: &str| -> [f64; 3] {
            if b == "ground" {
                return [0.0; 3];
            }
            [
                num(instant, &a, &format!("{b}_ax_mm_s2")),
                num(instant, &a, &format!("{b}_ay_mm_s2")),
                num(instant, &a, &format!("{b}_alpha_deg_s2")).to_radians(),
            ]
        };
        let (qa, qb) = (accel(&body("a")), accel(&body("b")));
        let row = [
            "row_x_a",
            "row_y_a",
            "row_angle_a_mm",
            "row_x_b",
            "row_y_b",
            "row_angle_b_mm",
        ]
        .map(|k| num(r, &c, k));
        let lhs: f64 = (0..3).map(|i| row[i] * qa[i] + row[3 + i] * qb[i]).sum();
        let gamma = num(r, &c, "gamma_mm_s2");
        let scale = num(r, &c, "normal_accel_a_mm_s2").abs().max(1.0);
        worst = worst.max((lhs - gamma).abs() / scale);
        // the row's x and y entries of body A are the common normal
        assert!((row[0] - num(r, &c, "normal_x")).abs() <= 1e-12, "{r:?}");
        assert!((row[1] - num(r, &c, "normal_y")).abs() <= 1e-12, "{r:?}");
        assert!(num(r, &c, "gap_mm").abs() <= 1e-12 * 100.0);
    }
    assert!(worst <= 1e-9, "{worst:e}");
}

/// The cam path's unit flags mean nothing to a system's table (its rates are per second, its
/// angles in degrees, as its columns say): given with a system file or `--system`, they are
/// refused with exit 2 naming the flag and the value, not ignored.
#[test]
fn unit_flags_a_system_cannot_honour_are_refused() {
    for (file, extra, flag) in [
        (
            "valve-train-kinematics.toml",
            vec!["--per", "deg"],
            "--per deg",
        ),
        (
            "valve-train-kinematics.toml",
            vec!["--angle-unit", "rad"],
            "--angle-unit rad",
        ),
        ("paper.toml", vec!["--system", "--per", "deg"], "--per deg"),
        (
            "oscillating-roller.toml",
            vec!["--system", "--angle-unit", "rad"],
            "--angle-unit rad",
        ),
    ] {
        let out = run!("analyze", examples().join(file))
            .args(&extra)
            .args(["--at", "0"])
            .assert()
            .code(2);
        let err = String::from_utf8(out.get_output().stderr.clone()).unwrap();
        assert!(err.contains(flag), "{file} {extra:?}: {err}");
        assert!(out.get_output().stdout.is_empty(), "{file}: wrote a table");
    }
}

/// A form-closed follower read as a system (`--system`) leaves its second curve out, and says
/// so on stderr; the table still holds the first contact.
#[test]
fn a_form_closed_follower_as_a_system_says_its_second_curve_is_left_out() {
    let out = run!(
        "analyze",
        examples().join("conjugate-yoke.toml"),
        "--system",
        "--at",
        "0,90"
    )
    .assert()
    .success();
    let err = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(
        err.contains("warning") && err.contains("second curve is left out"),
        "{err}"
    );
    let (header, rows) = parse_csv(&out.get_output().stdout);
    assert_eq!(rows.len(), 2);
    assert!(header
        .iter()
        .any(|h| h == "cam_on_follower_gamma_mm_s2" || h.starts_with("cam_on_follower_gamma")));
}

/// Issue 63 and issue 64: no step is refused; an element too stiff for a simulation in
/// reasonable time (√(1e12 N·m / 2e-5 kg·m²) = 2.236e8 /s) is named by the run's estimate, which
/// is refused without `--large`.
#[test]
fn a_stiff_element_is_named_by_the_runs_estimate() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("s.toml");
    let stiff = ROCKER.replace("stiffness = 200.0", "stiffness = 1e15");
    std::fs::write(&f, &stiff).unwrap();
    run!("simulate", &f)
        .refused("would take about")
        .stderr(predicate::str::contains(
            "torsion spring \"return spring\" moves at up to 223606798 /s",
        ))
        .stderr(predicate::str::contains("--large"))
        .stderr(predicate::str::contains("--substeps").not());
}

/// A wheel turning about its centre carries a circle of radius 10 whose centre is 50 above a
/// slider's line: the joints hold the curves 50 − 10 = 40 apart at every instant. That is said
/// as it is, naming the contact, the gap and the rows that hold it (a regression: "the
/// constraints are singular (a dead point, a toggle, or redundant joints)").
#[test]
fn curves_the_joints_hold_apart_are_said_to_never_touch() {
    let text = r#"length_unit = "mm"
[[body]]
name = "slider"
[[joint]]
name = "guide"
kind = "prismatic"
bodies = ["ground", "slider"]
axis = [1.0, 0.0]
[[body]]
name = "wheel"
position = [0.0, 50.0]
[[joint]]
name = "pin"
kind = "revolute"
bodies = ["ground", "wheel"]
at = [[0.0, 50.0], [0.0, 0.0]]
[[driver]]
name = "turn"
body = "wheel"
coordinate = "angle"
speed_rpm = 60.0
[[contact]]
name = "never"
bodies = ["wheel", "slider"]
curve_a = { kind = "circle", center = [0.0, 0.0], radius = 10.0 }
curve_b = { kind = "line", anchor = [0.0, 0.0], direction = [1.0, 0.0] }
"#;
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("apart.toml");
    std::fs::write(&f, text).unwrap();
    for cmd in ["analyze", "contacts"] {
        let out = run!(cmd, &f, "--at", "0").assert().code(2);
        let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
        assert!(
            stderr.contains("contact \"never\": its curves are 40 apart")
                && stderr.contains("joint \"guide\"")
                && stderr.contains("never touch")
                && !stderr.contains("singular"),
            "{cmd}: {stderr}"
        );
    }
}
