//! Bad numbers and unbounded work: every sweeping command refuses minutes or gigabytes up front
//! with one sentence; numeric flags take a sign and refuse a unit; extreme numbers are never
//! printed digit by digit; errors name the key and value the user wrote; an index beyond the
//! memory limit is refused before it is built. Exit 2, never a panic, never a written file (as
//! the bad files of `cli_bad_input`).

use crate::cli_bad_input::{bad, CIRCLE, FLAT, SPLINE_HEAD};
use crate::common::predicate;
use crate::common::*;

/// Issue 44, class 4 (unbounded work): every command that sweeps the cam refuses, before it
/// writes anything, a step that would take minutes or gigabytes — with the library's one
/// sentence (`would take about … s and … GB`), exit 2, and the flag that allows it.
#[test]
fn every_sweeping_command_refuses_gigabytes_up_front_with_one_sentence() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let out = out.to_str().unwrap();
    let ecc = examples().join("eccentric-roller.toml");
    let ecc = ecc.to_str().unwrap();
    let measured = examples().join("measured-eccentric.csv");
    let measured = measured.to_str().unwrap();
    let motion = examples().join("motion-roller.toml");
    let motion = motion.to_str().unwrap();
    let paper_dynamics = examples().join("paper-dynamics.toml");
    let paper_dynamics = paper_dynamics.to_str().unwrap();
    for args in [
        vec!["plot", "--step", "0.000036", "--out", out],
        vec![
            "profile",
            "--step",
            "0.000036",
            "--tool-radius",
            "0.5",
            "--out",
            out,
        ],
        vec![
            "deviation",
            measured,
            "--against",
            ecc,
            "--step",
            "0.000036",
            "--out",
            out,
        ],
        vec!["synth", motion, "--step", "0.00004", "--out", out],
        vec!["analyze", "--angles", "0:1e7:1", "-o", out],
        // issue 63: the force report's states held for 1e7 angles (2.4 GB before it was
        // counted)
        vec!["forces", paper_dynamics, "--step", "0.000036", "--out", out],
    ] {
        camkin()
            .args(&args)
            .refused("would take about ")
            .stderr(predicate::str::contains(" GB"))
            .stderr(predicate::str::contains("pass --large to run it anyway"));
        assert!(
            !std::path::Path::new(out).exists(),
            "{args:?}: nothing written"
        );
    }
}

/// Issue 63: a system's size is in its estimate. 3 000 driven wheels (a 9 000 × 9 000 dense
/// Jacobian, 648 MB a copy) are refused at one instant for their memory (they reached 2.5 GB);
/// the gear train asked 200 000° away, which it must reach through every instant between
/// (it does not repeat), is refused with its seconds (its gear contacts' pairings cost 2e-4 to
/// 6e-4 s an instant; 35 000 instants at 1e5° took 13 to 21 s where the estimate said 3.5).
#[test]
fn a_systems_size_and_its_far_instants_are_estimated() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("length_unit = \"mm\"\n");
    for i in 0..3000 {
        text += &format!("[[body]]\nname = \"w{i}\"\nposition = [{i}.0, 0.0]\n[[joint]]\nname = \"p{i}\"\nkind = \"revolute\"\nbodies = [\"ground\", \"w{i}\"]\nat = [[{i}.0, 0.0], [0.0, 0.0]]\n[[driver]]\nname = \"d{i}\"\nbody = \"w{i}\"\ncoordinate = \"angle\"\nspeed_rpm = 60.0\n");
    }
    let wheels = dir.path().join("wheels.toml");
    std::fs::write(&wheels, text).unwrap();
    for cmd in ["analyze", "contacts"] {
        run!(cmd, &wheels, "--at", "0")
            .refused("1 instant of this system would take about ")
            .stderr(predicate::str::contains(" GB"));
    }
    run!("analyze", examples().join("gear-train.toml"), "--at", "2e5")
        .refused("takes about 69813 instants between (about ")
        .stderr(predicate::str::contains("does not repeat"));
}

/// Issue 49, item 5 (a class): every numeric option takes a leading minus as a sign (the option's
/// own check then names it, not "unexpected argument") and refuses a unit typed with the number,
/// saying so; exit 2 either way.
#[test]
fn numeric_options_take_a_sign_and_refuse_a_unit_in_the_number() {
    let dynamics = examples().join("eccentric-flat-dynamics.toml");
    let dynamics = dynamics.to_str().unwrap();
    let motion = examples().join("motion-roller.toml");
    let motion = motion.to_str().unwrap();
    let measured = examples().join("measured-eccentric.csv");
    let measured = measured.to_str().unwrap();
    let ecc = examples().join("eccentric-roller.toml");
    let ecc = ecc.to_str().unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["forces", dynamics], "--margin"),
        (vec!["forces", dynamics], "--target-rpm"),
        (vec!["forces", dynamics], "--face-width"),
        (vec!["forces", dynamics], "--allowable"),
        (vec!["simulate", dynamics], "--revolutions"),
        (vec!["synth", motion], "--pressure-limit"),
        (vec!["synth", motion], "--tool-radius"),
        (vec!["profile", ecc], "--tool-radius"),
        (vec!["profile", ecc], "--tolerance"),
        (vec!["deviation", measured, "--against", ecc], "--tolerance"),
    ];
    // the refusal's stderr of `head flag value` (exit 2)
    let refused = |head: &[&str], flag: &str, value: &str| {
        let out = camkin()
            .args(head)
            .args([flag, value])
            .assert()
            .code(2)
            .get_output()
            .clone();
        String::from_utf8_lossy(&out.stderr).to_string()
    };
    for (head, flag) in &cases {
        let err = refused(head, flag, "12mm");
        assert!(
            err.contains("write the number alone (12)") && err.contains(flag),
            "{flag} 12mm: {err}"
        );
        let err = refused(head, flag, "-7");
        assert!(
            !err.contains("unexpected argument") && err.contains(flag) && err.contains("-7"),
            "{flag} -7: {err}"
        );
    }
}

/// Issue 44: a number in a message is the user's or rounded for people: every numeric flag of
/// every command, given extreme values, answers (or refuses) without a run of 25 digits (1e300
/// printed as 301 of them) and without a panic.
#[test]
fn extreme_numbers_are_never_printed_digit_by_digit() {
    let e = examples();
    let ex = |f: &str| e.join(f).display().to_string();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o").display().to_string();
    let html = dir.path().join("r.html").display().to_string();
    let cases: Vec<Vec<String>> = vec![
        vec![
            "plot".into(),
            ex("paper.toml"),
            "--out".into(),
            out.clone(),
            "--force".into(),
            "--at".into(),
        ],
        vec![
            "simulate".into(),
            ex("eccentric-flat-dynamics.toml"),
            "--revolutions".into(),
        ],
        vec![
            "simulate".into(),
            ex("eccentric-flat-dynamics.toml"),
            "--start-angle".into(),
        ],
        vec![
            "profile".into(),
            ex("paper.toml"),
            "--out".into(),
            out.clone(),
            "--force".into(),
            "--tool-radius".into(),
        ],
        vec![
            "profile".into(),
            ex("paper.toml"),
            "--out".into(),
            out.clone(),
            "--force".into(),
            "--tolerance".into(),
        ],
        vec![
            "synth".into(),
            ex("motion-roller.toml"),
            "--out".into(),
            out.clone(),
            "--force".into(),
            "--pressure-limit".into(),
        ],
        vec![
            "deviation".into(),
            ex("measured-eccentric.csv"),
            "--against".into(),
            ex("eccentric-roller.toml"),
            "--tolerance".into(),
        ],
        vec![
            "report".into(),
            ex("paper.toml"),
            "-o".into(),
            html,
            "--pressure-limit".into(),
        ],
        vec![
            "forces".into(),
            ex("eccentric-flat-dynamics.toml"),
            "--margin".into(),
        ],
        vec![
            "forces".into(),
            ex("eccentric-flat-dynamics.toml"),
            "--face-width".into(),
        ],
        vec![
            "forces".into(),
            ex("eccentric-flat-dynamics.toml"),
            "--target-rpm".into(),
        ],
        vec!["analyze".into(), ex("paper.toml"), "--at".into()],
        vec![
            "plot".into(),
            ex("paper.toml"),
            "--out".into(),
            out,
            "--force".into(),
            "--step".into(),
        ],
    ];
    for c in &cases {
        for v in ["1e300", "-1e300", "1e-300", "-1e-300"] {
            let o = camkin().args(c).arg(v).output_of();
            let err = String::from_utf8_lossy(&o.stderr);
            assert_ne!(o.status.code(), Some(101), "{c:?} {v}: {err}");
            let run = err
                .as_bytes()
                .split(|b| !b.is_ascii_digit())
                .map(<[u8]>::len)
                .max()
                .unwrap_or(0);
            assert!(run < 25, "{c:?} {v}: {err}");
        }
    }
}

/// Issue 44: each error names the key the user wrote, on its line, with the value the user
/// wrote: a gear's negative tip relief at `tip_relief` (it was placed at `kind`), a module of
/// 1e300 at `module` (it was "cam.profile = 0"), a speed of 5e-324 rpm at `speed_rpm` (it was
/// "cam.speed = 0"), a radius of 1e200 at `radius` (it was "cam.profile = inf"), a motion
/// program of 1001 segments at `segments`; and `[1e-300, 0]` is the x axis, as the library takes
/// it.
#[test]
fn errors_name_the_key_and_value_the_user_wrote() {
    let gear = std::fs::read_to_string(examples().join("gear-pair-20-42.toml")).unwrap();
    let relief = gear.replacen(
        "pressure_angle_deg = 20.0\n",
        "pressure_angle_deg = 20.0\ntip_relief = -0.02\ntip_relief_length = 1.0\n",
        1,
    );
    bad(
        "relief",
        &relief,
        &[],
        &["m.toml:18:14: cam.profile.tip_relief = -0.02: must be positive"],
    );
    bad(
        "module",
        &gear.replacen("module = 2.0", "module = 1e300", 1),
        &[],
        &["m.toml:15:10: cam.profile.module = 1e300: must be from 1e-100 to 1e100"],
    );
    bad(
        "slow",
        &gear.replace("speed_rpm = 1000.0", "speed_rpm = 5e-324"),
        &[],
        &["cam.speed_rpm = 5e-324: is too slow"],
    );
    bad(
        "huge radius",
        &format!("{}{FLAT}", CIRCLE.replace("radius = 2", "radius = 1e200")),
        &[],
        &["m.toml:7:10: cam.profile.radius = 1e200: must be from 1e-100 to 1e100"],
    );
    // issue 63: a size derived from what the user wrote is named at what they wrote
    for (module, distance) in [("1e300", "3.1e301"), ("1e99", "3.1e100")] {
        bad(
            "gear pair module",
            &format!("length_unit = \"mm\"\n[gear_pair]\nteeth = [20, 42]\nmodule = {module}\nspeed_rpm = 1000.0\n"),
            &[],
            &[&format!("m.toml:4:10: gear_pair.module = {module}: gives a centre distance of {distance}")],
        );
    }
    bad(
        "huge rise",
        "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"motion\"\nbase_radius = 40\nsegments = [{ law = \"cycloidal\", rise = 1e300, degrees = 180 }, { law = \"cycloidal\", rise = -1e300, degrees = 180 }]\n[follower]\nkind = \"translating-roller\"\nroller_radius = 5\n",
        &[],
        &["cam.profile.segments[0].rise = 1e300: must be at most 1e100 in magnitude"],
    );
    let segs: String = (0..1001)
        .map(|_| "[[cam.profile.segments]]\nlaw = \"dwell\"\ndegrees = 0.3\n".to_string())
        .collect();
    bad(
        "segments",
        &format!("length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"motion\"\nbase_radius = 40\n{segs}[follower]\nkind = \"translating-roller\"\nroller_radius = 5\n"),
        &[],
        &["cam.profile.segments: 1001 segments is more than the 1000"],
    );
    let (_dir, m) = written(
        "m.toml",
        format!("{CIRCLE}[follower]\nkind = \"translating-flat\"\ndirection = [1e-300, 0]\n"),
    );
    run!("analyze", &m, "--at", "0").assert().success();
}

/// Issue 44: a mechanism whose search indexes would hold more than the library's memory limit
/// (a 100 000-node spline cam carrying a 100 000-node spline follower: about 1.4 GB) is refused
/// before they are built, at the cam's profile, with the estimate and `--large`, for every
/// command that reads a mechanism; the studio's report refuses it too.
#[test]
fn a_mechanism_too_large_to_index_is_refused_before_it_is_built() {
    let n = 100_000;
    let ring = |r: f64, x: f64| -> String {
        (0..n)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / n as f64;
                format!("[{:.6},{:.6}]", x + r * t.cos(), 0.8 * r * t.sin())
            })
            .collect::<Vec<_>>()
            .join(",")
    };
    let toml = format!(
        "{SPLINE_HEAD}points = [{}]\n[follower]\nkind = \"translating\"\ndirection = [1.0, 0.0]\n\
         offset = 0.0\n[follower.profile]\nkind = \"spline\"\npoints = [{}]\n",
        ring(40.0, 0.0),
        ring(2.0, 3.0)
    );
    bad(
        "two 100 000-node splines",
        &toml,
        &[],
        &["cam.profile", "would take about", "GB", "--large"],
    );
    let (dir, mech) = written("m.toml", &toml);
    for args in [
        vec!["report", "-o"],
        vec!["plot", "--out"],
        vec!["forces", "--out"],
    ] {
        let out = dir.path().join("out");
        let a = run!(args[0], &mech, args[1], &out).assert().code(2);
        let err = String::from_utf8(a.get_output().stderr.clone()).unwrap();
        assert!(
            err.contains("would take about") && err.contains("--large"),
            "{}: {err}",
            args[0]
        );
        assert!(!out.exists(), "{}", args[0]);
    }
}
