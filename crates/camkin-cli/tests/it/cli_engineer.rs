//! Issue 13: the cam engineer's outputs — units on every column, lift, derivatives per degree,
//! forces and spring sizing, manufacturing files, measured profiles — against closed forms and
//! finite differences that share nothing with the method.
use crate::common::predicate;
use crate::common::*;
use std::path::Path;

fn col(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}

fn analyze(args: &[&str]) -> (Vec<String>, Vec<Vec<f64>>) {
    let out = run!("analyze").args(args).stdout_ok();
    let (h, rows) = parse_csv(&out);
    let rows = rows
        .iter()
        .map(|r| r.iter().map(|c| c.parse().unwrap_or(f64::NAN)).collect())
        .collect();
    (h, rows)
}

#[test]
fn a_missing_or_unknown_length_unit_is_refused_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(examples().join("eccentric-roller.toml")).unwrap();
    for (bad, needle) in [
        (
            text.replace("length_unit = \"cm\"\n", ""),
            "length_unit: missing",
        ),
        (
            text.replace("length_unit = \"cm\"", "length_unit = \"furlong\""),
            "length_unit = \"furlong\"",
        ),
    ] {
        let p = dir.path().join("m.toml");
        std::fs::write(&p, bad).unwrap();
        run!("analyze", &p).refused(needle);
    }
}

#[test]
fn every_column_carries_the_files_unit_and_inches_work() {
    let (_dir, p) = written(
        "in.toml",
        std::fs::read_to_string(examples().join("eccentric-roller.toml"))
            .unwrap()
            .replace("length_unit = \"cm\"", "length_unit = \"in\""),
    );
    let (h, _) = analyze(&[p.to_str().unwrap(), "--at", "0"]);
    for c in &h {
        let unitless = [
            "angle_deg",
            "cam_param",
            "normal_x",
            "normal_y",
            "sigma",
            "pressure_angle_deg",
            "at_node",
            "found",
            "error",
        ];
        assert!(
            unitless.contains(&c.as_str()) || c.contains("_in"),
            "{c} has no unit"
        );
    }
    assert_eq!(h[col(&h, "acceleration_in_s2")], "acceleration_in_s2");
}

/// Lift is position minus its lowest over the revolution (0 to 2e for the eccentric disc), and
/// `--per deg` gives the derivatives in the cam angle: central differences of the position
/// column over ±0.01° agree.
#[test]
fn lift_and_derivatives_per_degree() {
    let mech = examples().join("eccentric-roller.toml");
    let (h, rows) = analyze(&[mech.to_str().unwrap(), "--angles", "0:360:0.5"]);
    let lift = col(&h, "lift_cm");
    let lo = rows.iter().map(|r| r[lift]).fold(f64::INFINITY, f64::min);
    let hi = rows.iter().map(|r| r[lift]).fold(0.0, f64::max);
    // the lowest sample, 0.25° at most from the exact lowest: e (1 − cos 0.25°) ≈ 1e-5
    assert!((-1e-12..2e-5).contains(&lo), "{lo}");
    // the roller's centre on a line offset 0.5 from the disc's axis: stroke = √((R+r)² − (x−e)²)…
    // between e = 1 above and below: about 2e = 2
    assert!((hi - 2.0).abs() < 0.05, "{hi}");
    let (h, rows) = analyze(&[
        mech.to_str().unwrap(),
        "--angles",
        "10:370:20",
        "--per",
        "deg",
    ]);
    let (v, a) = (col(&h, "velocity_cm_deg"), col(&h, "acceleration_cm_deg2"));
    let jerk = col(&h, "jerk_cm_deg3");
    for r in &rows {
        let t = r[0];
        let at = |d: f64| {
            let (hh, rr) = analyze(&[mech.to_str().unwrap(), "--at", &format!("{}", t + d)]);
            rr[0][col(&hh, "position_cm")]
        };
        let d = 0.01;
        let (pm, p0, pp) = (at(-d), at(0.0), at(d));
        let fd1 = (pp - pm) / (2.0 * d);
        let fd2 = (pp - 2.0 * p0 + pm) / (d * d);
        assert!((fd1 - r[v]).abs() < 1e-8, "{t}: {fd1} vs {}", r[v]);
        assert!((fd2 - r[a]).abs() < 1e-5, "{t}: {fd2} vs {}", r[a]);
        let (h3, r3) = analyze(&[
            mech.to_str().unwrap(),
            "--at",
            &format!("{},{}", t - d, t + d),
            "--per",
            "deg",
        ]);
        let fd3 = (r3[1][col(&h3, "acceleration_cm_deg2")]
            - r3[0][col(&h3, "acceleration_cm_deg2")])
            / (2.0 * d);
        assert!((fd3 - r[jerk]).abs() < 1e-6, "{t}: {fd3} vs {}", r[jerk]);
        if t >= 100.0 {
            break;
        }
    }
    // an arm's angle is in degrees unless asked for radians
    let osc = examples().join("oscillating-roller.toml");
    let (h, deg) = analyze(&[osc.to_str().unwrap(), "--at", "30"]);
    let (hr, rad) = analyze(&[osc.to_str().unwrap(), "--at", "30", "--angle-unit", "rad"]);
    let q = deg[0][col(&h, "position_deg")];
    assert!((q.to_radians() - rad[0][col(&hr, "position_rad")]).abs() < 1e-12);
    assert!(h.contains(&"acceleration_deg_s2".to_string()));
}

fn forces_csv(dir: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let (h, rows) = parse_csv(&std::fs::read(dir.join("forces.csv")).unwrap());
    (
        h,
        rows.iter()
            .map(|r| r.iter().map(|c| c.parse().unwrap_or(f64::NAN)).collect())
            .collect(),
    )
}

/// `camkin forces` on the eccentric disc under a flat face: the contact force, the camshaft
/// torque and the jump speed of the closed forms; a check that fails exits 3.
#[test]
fn forces_of_the_eccentric_disc_are_the_closed_forms() {
    let dir = tempfile::tempdir().unwrap();
    let mech = examples().join("eccentric-flat-dynamics.toml");
    let slow = dir.path().join("slow.toml");
    std::fs::write(
        &slow,
        std::fs::read_to_string(&mech)
            .unwrap()
            .replace("speed_rpm = 1380.0", "speed_rpm = 1000.0"),
    )
    .unwrap();
    let out = run!(
        "forces",
        &slow,
        "--target-rpm",
        "1000",
        "--face-width",
        "10",
        "--out",
        dir.path().join("out")
    )
    .stdout_ok();
    let report = String::from_utf8(out).unwrap();
    let (m, e, k, f0) = (0.3, 0.01, 2000.0, 20.0);
    let w = 1000.0 * std::f64::consts::TAU / 60.0;
    let (h, rows) = forces_csv(&dir.path().join("out"));
    let (fc, tq) = (col(&h, "contact_force_N"), col(&h, "camshaft_torque_N_m"));
    assert_eq!(rows.len(), 720);
    for r in &rows {
        let phi = r[0].to_radians();
        let force = -m * e * w * w * phi.cos() + f0 + k * e * (1.0 + phi.cos());
        assert!((r[fc] - force).abs() < 1e-9 * 100.0, "{r:?}");
        assert!((r[tq] + force * e * phi.sin()).abs() < 1e-9, "{r:?}");
    }
    let jump = ((f0 + 2.0 * k * e) / (m * e)).sqrt() * 60.0 / std::f64::consts::TAU;
    let printed: f64 = report
        .split("jump speed: ")
        .nth(1)
        .unwrap()
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!((printed - jump).abs() < 1e-3 * jump, "{printed} vs {jump}");
    assert!(report.contains("contact stress (Hertz"), "{report}");
    for f in [
        "force_speed.csv",
        "contact_force.png",
        "camshaft_torque.svg",
        "force_speed.png",
        "contact_stress.png",
    ] {
        assert!(dir.path().join("out").join(f).exists(), "{f}");
    }
    // the force-speed page marks the operating speed and the jump speed (issue 49)
    let svg = std::fs::read_to_string(dir.path().join("out").join("force_speed.svg")).unwrap();
    let jump_label = format!("jump speed {} rpm", camkin_cli::forces_text::num(printed));
    assert!(
        svg.contains("operating speed"),
        "no operating speed in the page"
    );
    assert!(svg.contains(&jump_label), "{jump_label} not in the page");
    // at the file's 1380 rpm the follower leaves the cam: exit 3, with the spring that would do
    run!("forces", &mech)
        .assert()
        .code(3)
        .stdout(predicate::str::contains("preload ≥ "))
        .stderr(predicate::str::contains(
            "the follower leaves the cam at 1350",
        ));
    // an allowable stress below the Hertz stress exits 3; bad materials exit 2
    run!(
        "forces",
        &mech,
        "--target-rpm",
        "100",
        "--face-width",
        "10",
        "--allowable",
        "10"
    )
    .assert()
    .code(3)
    .stderr(predicate::str::contains("exceeds the allowable"));
    run!(
        "forces",
        &mech,
        "--face-width",
        "10",
        "--materials",
        "steel,unobtainium"
    )
    .refused("unobtainium");
    // a file without [dynamics] is refused by name
    run!("forces", examples().join("paper.toml")).refused("[dynamics]");
}

/// Regression (`forces --face-width` on a mushroom follower said "a knife-edge follower has no
/// line contact"): a follower carrying a curve has the curve's radius at the contact. The
/// example's crowned face (a circle of 60 mm) moves as a named roller of 60 mm whose centre is
/// the circle's: the forces and the Hertz stress of the two files agree at every angle (1e-9 of
/// their peaks), the roller's from its closed form.
#[test]
fn forces_face_width_on_a_mushroom_follower_is_not_called_a_knife_edge() {
    let dir = tempfile::tempdir().unwrap();
    let dynamics = "\n[dynamics]\nmass = 0.3\nspring_stiffness = 2000.0\nspring_preload = 100.0\n";
    let text = std::fs::read_to_string(examples().join("mushroom-follower.toml")).unwrap();
    let mushroom = dir.path().join("mushroom.toml");
    std::fs::write(&mushroom, format!("{text}{dynamics}")).unwrap();
    let (head, _) = text.split_once("[follower]").unwrap();
    let roller = dir.path().join("roller.toml");
    std::fs::write(
        &roller,
        format!("{head}[follower]\nkind = \"translating-roller\"\ndirection = [1.0, 0.0]\nroller_radius = 60.0\n{dynamics}"),
    )
    .unwrap();
    let mut tables = Vec::new();
    for (name, file) in [("mushroom", &mushroom), ("roller", &roller)] {
        let out = dir.path().join(name);
        run!("forces", file, "--face-width", "10", "--out", &out)
            .assert()
            .success()
            .stdout(predicate::str::contains(
                "contact stress (Hertz line contact",
            ));
        tables.push(forces_csv(&out));
    }
    let (h, a) = &tables[0];
    let b = &tables[1].1;
    for name in [
        "contact_force_N",
        "contact_stress_MPa",
        "camshaft_torque_N_m",
    ] {
        let c = col(h, name);
        let peak = a.iter().map(|r| r[c].abs()).fold(0.0, f64::max);
        assert!(peak > 0.0, "{name}");
        for (x, y) in a.iter().zip(b) {
            assert!((x[c] - y[c]).abs() <= 1e-9 * peak, "{name}: {x:?} vs {y:?}");
        }
    }
}

/// `camkin profile` on the eccentric disc: the polar table is the disc's radius in polar form,
/// the pitch curve and the cutter path the discs of radius R + r (the offset definition) to 1e-9
/// of the size; the DXF says centimetres and its arcs lie on the exact curves within the stated
/// tolerance; a tool larger than a concave radius exits 3.
#[test]
fn manufacturing_files_follow_their_definitions() {
    let dir = tempfile::tempdir().unwrap();
    run!(
        "profile",
        examples().join("eccentric-roller.toml"),
        "--tool-radius",
        "2.5",
        "--out",
        dir.path()
    )
    .assert()
    .success()
    .stdout(predicate::str::contains("cuts the whole profile"));
    let (rr, e, r) = (4.0f64, 1.0f64, 1.0f64);
    let read = |name: &str| {
        let (h, rows) = parse_csv(&std::fs::read(dir.path().join(name)).unwrap());
        let rows: Vec<Vec<f64>> = rows
            .iter()
            .map(|r| r.iter().map(|c| c.parse().unwrap()).collect())
            .collect();
        (h, rows)
    };
    let (h, polar) = read("polar.csv");
    assert_eq!(h, ["polar_angle_deg", "radius_cm", "x_cm", "y_cm"]);
    assert_eq!(polar.len(), 360);
    for p in &polar {
        let phi = p[0].to_radians();
        let exact = e * phi.cos() + (rr * rr - (e * phi.sin()).powi(2)).sqrt();
        assert!((p[1] - exact).abs() < 1e-9 * rr, "{p:?}");
    }
    for (name, off) in [("pitch.csv", r), ("cutter.csv", 2.5)] {
        let (h, rows) = read(name);
        assert_eq!(h[1], "x_cm");
        for p in &rows {
            let d = (p[1] - e).hypot(p[2]);
            assert!((d - (rr + off)).abs() < 1e-9 * rr, "{name}: {p:?}");
        }
    }
    let dxf = read_dxf(&std::fs::read_to_string(dir.path().join("profile.dxf")).unwrap());
    assert_eq!(dxf.header.get("$INSUNITS").map(String::as_str), Some("5"));
    for (p, off) in dxf.polylines.iter().zip([0.0, r, 2.5]) {
        for (x, y) in polyline_points(p, 5) {
            let d = (x - e).hypot(y);
            assert!((d - (rr + off)).abs() < 1e-6 * 6.0, "{}: {x} {y}", p.layer);
        }
    }
    // the paper's cam: its arcs within the default tolerance (1e-6 of the size) of the spline
    let d2 = dir.path().join("paper");
    run!("profile", examples().join("paper.toml"), "--out", &d2)
        .assert()
        .success();
    let dxf = read_dxf(&std::fs::read_to_string(d2.join("profile.dxf")).unwrap());
    let mech = camkin_cli::mechfile::load(&examples().join("paper.toml")).unwrap();
    let prof = mech.cam().profile();
    let dense: Vec<(f64, f64)> = (0..90_000)
        .map(|k| {
            let p = prof.position(9.0 * k as f64 / 90_000.0);
            (p.x, p.y)
        })
        .collect();
    let pts = polyline_points(&dxf.polylines[0], 3);
    for (x, y) in pts.iter().step_by(7) {
        let dist = dense
            .iter()
            .map(|(a, b)| (a - x).hypot(b - y))
            .fold(f64::INFINITY, f64::min);
        // the dense samples are 2e-3 apart: the nearest lies within 1e-6 of a chord of them
        assert!(dist < 2e-3, "{x} {y}: {dist}");
    }
    // a cutter larger than the paper cam's concave radius cannot cut it: exit 3
    let peanut = dir.path().join("peanut.toml");
    std::fs::write(&peanut, "length_unit = \"mm\"\n[cam]\nspeed_rpm = 1000\n[cam.profile]\nkind = \"spline\"\npoints = [[4.0, 0.0], [3.0, 2.4], [0.5, 1.1], [-2.0, 2.4], [-3.5, 0.1], [-2.2, -2.5], [0.6, -1.0], [3.1, -2.3]]\n[follower]\nkind = \"translating-flat\"\n").unwrap();
    run!(
        "profile",
        &peanut,
        "--tool-radius",
        "3",
        "--out",
        dir.path().join("p")
    )
    .assert()
    .code(3)
    .stdout(predicate::str::contains("UNDERCUT"));
}

/// `camkin deviation`: noisy, unevenly spaced points measured on the eccentric disc. Smoothed
/// within the noise, the acceleration deviates by a few per cent of the peak at most; a spline
/// through the raw points (what a naive analysis does) is off by many times more. A known bump
/// of the radius is reported as it is.
#[test]
fn measured_profiles_are_smoothed_within_the_noise() {
    let dir = tempfile::tempdir().unwrap();
    let (rr, e) = (4.0f64, 1.0f64);
    let mut seed = 12345u64;
    let mut noise = || {
        // uniform in ±√3 σ: RMS σ (an LCG: deterministic)
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0 * 3f64.sqrt()
    };
    let sigma = 5e-4;
    let mut text = String::from("x,y\n");
    for i in 0..500 {
        let t = std::f64::consts::TAU * (i as f64 / 500.0).powf(1.2);
        let (x, y) = (e + rr * t.cos(), rr * t.sin());
        let (rad, ph) = (x.hypot(y) + sigma * noise(), y.atan2(x));
        text += &format!("{},{}\n", rad * ph.cos(), rad * ph.sin());
    }
    let meas = dir.path().join("measured.csv");
    std::fs::write(&meas, &text).unwrap();
    let out = run!(
        "deviation",
        &meas,
        "--against",
        examples().join("eccentric-roller.toml"),
        "--tolerance",
        "0.0006",
        "--out",
        dir.path().join("d")
    )
    .stdout_ok();
    let report = String::from_utf8(out).unwrap();
    let frac = |what: &str| -> f64 {
        let line = report
            .lines()
            .find(|l| l.starts_with(what))
            .unwrap_or_else(|| panic!("{report}"));
        line.split(" of the design")
            .next()
            .unwrap()
            .rsplit('(')
            .next()
            .unwrap()
            .parse()
            .unwrap()
    };
    assert!(frac("acceleration deviation") < 0.02, "{report}");
    // the same points through a spline (a points-file profile): the naive second derivative
    let naive = dir.path().join("naive.toml");
    std::fs::write(
        &naive,
        std::fs::read_to_string(examples().join("eccentric-roller.toml"))
            .unwrap()
            .replace(
                "kind = \"circle\"\ncenter = [1.0, 0.0]\nradius = 4.0",
                "kind = \"points-file\"\npath = \"measured.csv\"",
            ),
    )
    .unwrap();
    let (h, rows) = analyze(&[naive.to_str().unwrap(), "--angles", "0:360:1"]);
    let a = col(&h, "acceleration_cm_s2");
    let w = 600.0 * std::f64::consts::TAU / 60.0;
    let (hd, design) = analyze(&[
        examples().join("eccentric-roller.toml").to_str().unwrap(),
        "--angles",
        "0:360:1",
    ]);
    let ad = col(&hd, "acceleration_cm_s2");
    let peak = design.iter().map(|r| r[ad].abs()).fold(0.0, f64::max);
    let worst = rows
        .iter()
        .zip(&design)
        .map(|(n, d)| (n[a] - d[ad]).abs())
        .fold(0.0, f64::max);
    assert!(
        worst > 10.0 * 0.02 * peak,
        "naive {worst} vs peak {peak} (ω {w})"
    );
    // a known bump of 0.02 cm × cos 3φ, no noise: the radius deviation says it
    let mut text = String::from("x,y\n");
    for i in 0..720 {
        let t = std::f64::consts::TAU * i as f64 / 720.0;
        let (x, y) = (e + rr * t.cos(), rr * t.sin());
        let ph = y.atan2(x);
        let rad = x.hypot(y) + 0.02 * (3.0 * ph).cos();
        text += &format!("{},{}\n", rad * ph.cos(), rad * ph.sin());
    }
    std::fs::write(&meas, &text).unwrap();
    run!(
        "deviation",
        &meas,
        "--against",
        examples().join("eccentric-roller.toml"),
        "--out",
        dir.path().join("b")
    )
    .assert()
    .success();
    let (_, rows) = parse_csv(&std::fs::read(dir.path().join("b/radius.csv")).unwrap());
    for r in &rows {
        let ph: f64 = r[0].parse::<f64>().unwrap().to_radians();
        let d: f64 = r[3].parse().unwrap();
        assert!((d - 0.02 * (3.0 * ph).cos()).abs() < 1e-9, "{r:?}");
    }
}

/// Issue 44: a scan of part of the cam is refused (exit 2) naming the unmeasured stretch, and
/// writes nothing; it used to extrapolate the fit round the cam and report a lift deviation at
/// 257° where nothing was measured.
#[test]
fn deviation_refuses_a_scan_of_part_of_the_cam() {
    let dir = tempfile::tempdir().unwrap();
    let meas = dir.path().join("quarter.csv");
    let (e, rr) = (0.5, 2.0);
    let mut text = String::from("x,y\n");
    for i in 0..=90 {
        let t = (i as f64).to_radians();
        text += &format!("{},{}\n", e + rr * t.cos(), rr * t.sin());
    }
    std::fs::write(&meas, &text).unwrap();
    let out = dir.path().join("out");
    run!(
        "deviation",
        &meas,
        "--against",
        examples().join("eccentric-roller.toml"),
        "--out",
        &out
    )
    .refused("no point measured between polar angles")
    .stderr(predicate::str::contains("measure the whole profile round"))
    .stderr(predicate::str::contains("--tolerance").not());
    assert!(!out.exists());
}

/// Issue 63: a measured profile of huge coordinates is refused at its line (it was "an RMS
/// residual of NaN"), and one of another size than the design's — measured in mm against a
/// design in cm — names both sizes and the unit (it was a fit that found no tolerance).
#[test]
fn deviation_names_huge_points_and_a_profile_of_another_size() {
    let dir = tempfile::tempdir().unwrap();
    let ring = |scale: f64| {
        let mut text = String::from("x,y\n");
        for i in 0..360 {
            let t = f64::from(i).to_radians();
            let r = scale * (4.0 + 0.5 * t.cos());
            text += &format!("{:e},{:e}\n", r * t.cos(), r * t.sin());
        }
        text
    };
    for (name, scale, needles) in [
        (
            "huge.csv",
            1e200,
            vec!["huge.csv: points file line 2", "at most 1e100 in magnitude"],
        ),
        (
            "mm.csv",
            10.0,
            vec![
                "the measured points reach 45 cm from the axis, the design's profile 5 cm",
                "not the same unit",
            ],
        ),
    ] {
        let meas = dir.path().join(name);
        std::fs::write(&meas, ring(scale)).unwrap();
        let mut a = run!(
            "deviation",
            &meas,
            "--against",
            examples().join("eccentric-roller.toml")
        )
        .refused(needles[0]);
        for n in &needles[1..] {
            a = a.stderr(predicate::str::contains(*n));
        }
        let _ = a.stderr(predicate::str::contains("NaN").not());
    }
}

/// Issue 13, item 9: the guide's mechanism-file reference (docs/mechanism-files.md) is a complete file that runs as it is
/// (it used to fail with "takes no `offset`").
#[test]
fn the_readmes_mechanism_file_runs_as_pasted() {
    let readme = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/mechanism-files.md"),
    )
    .unwrap();
    let blocks: Vec<&str> = readme
        .split("```toml\n")
        .skip(1)
        .map(|b| b.split("```").next().unwrap())
        .filter(|b| b.contains("[cam]") && b.contains("[follower]"))
        .collect();
    assert!(!blocks.is_empty());
    let dir = tempfile::tempdir().unwrap();
    for b in blocks {
        let p = dir.path().join("cam.toml");
        std::fs::write(&p, b).unwrap();
        run!("analyze", &p, "--at", "0").assert().success();
    }
}

/// Bad material and load inputs of `forces` are refused before any work, exit 2, naming the flag
/// and the value as written: a modulus typed in GPa where Pa is asked for, an implausible or
/// unknown key, a Poisson's ratio of −1, a face width no cam has, a file in the place of `--out`
/// (which used to compute everything, then exit 1).
#[test]
fn forces_refuses_implausible_materials_widths_and_outputs_up_front() {
    let mech = examples().join("eccentric-flat-dynamics.toml");
    for (args, needles) in [
        (
            vec!["--face-width", "10", "--materials", "E=210:nu=0.3,steel"],
            vec!["--materials", "E=210", "did you mean GPa"],
        ),
        (
            vec!["--face-width", "10", "--materials", "steel,E=210e9:nu=-1"],
            vec!["--materials", "nu = -1"],
        ),
        (
            vec!["--face-width", "10", "--materials", "steel,E=5e-324:nu=0.3"],
            vec!["--materials", "E = 5e-324 Pa"],
        ),
        (
            vec![
                "--face-width",
                "10",
                "--materials",
                "steel,E=210e9:nu=0.3:T=300",
            ],
            vec!["--materials", "unknown key \"T\""],
        ),
        (
            vec![
                "--face-width",
                "10",
                "--materials",
                "steel,E=210e9:nu=0.3:rho=7800",
            ],
            vec![
                "--materials",
                "k is missing (the thermal constants k, rho and c are given together)",
            ],
        ),
        (
            vec!["--face-width", "1e-300"],
            vec!["--face-width", "1e-300 mm", "not plausible"],
        ),
        (vec!["--face-width", "1e9"], vec!["--face-width", "1e9 mm"]),
        (vec!["--face-width", "0"], vec!["--face-width", "0 mm"]),
        (vec!["--allowable", "-5"], vec!["--allowable", "-5 MPa"]),
    ] {
        let out = run!("forces", &mech)
            .args(&args)
            .assert()
            .code(2)
            .get_output()
            .clone();
        let err = String::from_utf8_lossy(&out.stderr).to_string();
        for n in needles {
            assert!(err.contains(n), "{args:?}: {n:?} not in {err}");
        }
        assert!(out.stdout.is_empty(), "{args:?}: refused before any output");
    }
    let (_dir, file) = written("taken", "keep me");
    run!("forces", &mech, "--out", &file).refused("a file, not a folder");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "keep me");
}

/// Issue 49: `[dynamics]` without a spring: `forces` sizes one from the motion alone (the
/// disc's closed form: a constant force of `M + m e ω_t²` holds it, the least at full lift), and
/// says that no speed is safe rather than "leaves the cam at 0 rpm"; the range of stiffnesses
/// and their least preloads ends at the one that needs none.
#[test]
fn forces_sizes_the_spring_from_the_motion_when_the_file_has_none() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(examples().join("eccentric-flat-dynamics.toml"))
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with("spring_"))
        .collect::<Vec<_>>()
        .join("\n");
    let file = dir.path().join("nospring.toml");
    std::fs::write(&file, text).unwrap();
    let out = run!("forces", &file, "--target-rpm", "1000", "--margin", "5")
        .assert()
        .code(3);
    let stdout = String::from_utf8_lossy(&out.get_output().stdout).to_string();
    let stderr = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    // the disc: radius 40 mm, 10 mm off the axis, 0.3 kg; at 1000 rpm, 5 N + m e ω²
    let w: f64 = 1000.0 * std::f64::consts::TAU / 60.0;
    let need = 5.0 + 0.3 * 0.010 * w * w;
    let shown = format!(
        "a constant force of {} N",
        camkin_cli::forces_text::num(need)
    );
    assert!(
        stdout.contains("no spring in the file: the spring from the motion"),
        "{stdout}"
    );
    assert!(stdout.contains(&shown), "{shown} not in {stdout}");
    assert!(stdout.contains("jump speed: none is safe"), "{stdout}");
    assert!(
        stdout.contains("the least preload by stiffness"),
        "{stdout}"
    );
    assert!(
        stderr.contains("even at rest") && !stderr.contains("at 0 rpm"),
        "{stderr}"
    );
}

/// Issue 49: a dwell's constant contact force is named as the stretch it holds over, not as one
/// arbitrary sample of it (the motion program's last 60° dwell on the base circle).
#[test]
fn a_constant_force_over_a_dwell_is_named_as_its_stretch() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(examples().join("motion-roller.toml")).unwrap()
        + "\n[dynamics]\nmass = 0.3\nspring_stiffness = 20000.0\nspring_preload = 50.0\n";
    let file = dir.path().join("dwell.toml");
    std::fs::write(&file, text).unwrap();
    let out = run!("forces", &file).assert().success();
    let stdout = String::from_utf8_lossy(&out.get_output().stdout).to_string();
    assert!(stdout.contains("from 300° to 360° (constant)"), "{stdout}");
}
