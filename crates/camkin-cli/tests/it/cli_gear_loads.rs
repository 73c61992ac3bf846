//! `camkin forces GEAR.toml --torque T`: the loads along the whole path of contact, and the
//! torque refused where it does not apply.
use crate::common::predicate;
use crate::common::*;

/// The 20/42 pair (module 2 mm, 20°) under 50 N·m: the normal force T/r_b1, each row's load the
/// whole of it where one pair carries and half where two do, and the specific sliding over the
/// whole path (the driver's root to its tip), 0 at the pitch point.
#[test]
fn a_torque_loads_the_whole_path_of_contact() {
    let dir = tempfile::tempdir().unwrap();
    let out = camkin()
        .arg("forces")
        .arg(examples().join("gear-pair-20-42.toml"))
        .args(["--torque", "50", "--face-width", "20", "--out"])
        .arg(dir.path().join("out"))
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    let rb1 = 0.020 * 20f64.to_radians().cos();
    let force = 50.0 / rb1;
    assert!(
        text.contains(&format!(
            "normal force T/r_b1 = {} N",
            camkin::human::human((force).round())
        )),
        "{text}"
    );
    for f in [
        "gear_hertz.png",
        "gear_hertz.svg",
        "gear_specific_sliding.png",
    ] {
        assert!(dir.path().join("out").join(f).exists(), "{f}");
    }
    let (h, rows) =
        parse_csv(&std::fs::read(dir.path().join("out").join("gear_loads.csv")).unwrap());
    let c = columns(&h);
    assert_eq!(rows.len(), 201);
    let x = |r: &Vec<String>, k: &str| -> f64 { r[c[k]].parse().unwrap() };
    let (mut one, mut two) = (0, 0);
    for r in &rows {
        match r[c["pairs_in_contact"]].as_str() {
            "1" => {
                assert!((x(r, "load_N") - force).abs() < 1e-12 * force);
                one += 1;
            }
            "2" => {
                assert!((x(r, "load_N") - force / 2.0).abs() < 1e-12 * force);
                two += 1;
            }
            other => panic!("{other} pairs"),
        }
    }
    assert!(one > 20 && two > 100, "{one} {two}");
    // the driver's root first, its tip last: the driver's specific sliding rises through 0
    let first = x(&rows[0], "specific_sliding_driver");
    let last = x(&rows[200], "specific_sliding_driver");
    assert!(first < -1.0 && last > 0.0, "{first} {last}");
    assert!(x(&rows[0], "driver_radius_m") < x(&rows[200], "driver_radius_m"));
}

#[test]
fn a_torque_where_it_does_not_apply_is_refused() {
    for (file, args, needles) in [
        (
            "paper-dynamics.toml",
            vec!["--torque", "5"],
            vec!["--torque 5", "not a gear pair"],
        ),
        (
            "gear-pair-20-42.toml",
            vec!["--torque", "-5", "--face-width", "20"],
            vec!["--torque -5", "positive"],
        ),
        (
            "gear-pair-20-42.toml",
            vec!["--torque", "5"],
            vec!["--face-width", "face width"],
        ),
        (
            "gear-pair-20-42.toml",
            vec!["--torque", "5", "--face-width", "20", "--margin", "3"],
            vec!["--margin", "--torque"],
        ),
        (
            "gear-pair-20-42.toml",
            vec![
                "--torque",
                "5",
                "--face-width",
                "20",
                "--oil",
                "sae-30@100c",
            ],
            vec!["--oil", "--roughness"],
        ),
    ] {
        let a = camkin()
            .arg("forces")
            .arg(examples().join(file))
            .args(&args)
            .assert()
            .code(2);
        let err = String::from_utf8(a.get_output().stderr.clone()).unwrap();
        for n in needles {
            assert!(err.contains(n), "{args:?}: {n:?} not in {err}");
        }
    }
    // a gear pair without a torque still needs [dynamics] for the forces
    camkin()
        .arg("forces")
        .arg(examples().join("gear-pair-20-42.toml"))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("[dynamics]"));
}
