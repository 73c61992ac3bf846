//! `camkin forces GEAR.toml --torque T`: the loads along the whole path of contact, and the
//! torque refused where it does not apply.
use crate::common::*;

/// The 20/42 pair (module 2 mm, 20°) under 50 N·m: the normal force T/r_b1, each row's load the
/// whole of it where one pair carries and half where two do, and the specific sliding over the
/// whole path (the driver's root to its tip), 0 at the pitch point.
#[test]
fn a_torque_loads_the_whole_path_of_contact() {
    let dir = tempfile::tempdir().unwrap();
    let out = run!(
        "forces",
        examples().join("gear-pair-20-42.toml"),
        "--torque",
        "50",
        "--face-width",
        "20",
        "--out",
        dir.path().join("out")
    )
    .stdout_ok();
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
    // the grid's 201 points (its ends A and E) and the named C, and B and D of either side
    assert_eq!(rows.len(), 206);
    let named: Vec<(&str, &str)> = rows
        .iter()
        .filter(|r| !r[c["point"]].is_empty())
        .map(|r| (r[c["point"]].as_str(), r[c["pairs_in_contact"]].as_str()))
        .collect();
    assert_eq!(
        named,
        [
            ("A", "2"),
            ("B", "2"),
            ("B", "1"),
            ("C", "1"),
            ("D", "1"),
            ("D", "2"),
            ("E", "2")
        ]
    );
    for name in ["A", "B", "C", "D", "E"] {
        assert!(text.contains(&format!("\n  {name} ")), "{name}: {text}");
    }
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
    let last = x(&rows[205], "specific_sliding_driver");
    assert!(first < -1.0 && last > 0.0, "{first} {last}");
    assert!(x(&rows[0], "driver_radius_m") < x(&rows[205], "driver_radius_m"));
}

#[test]
fn a_torque_where_it_does_not_apply_is_refused() {
    // (the example, the flags split at spaces, what the refusal says)
    for (file, args, needles) in [
        (
            "paper-dynamics.toml",
            "--torque 5",
            vec!["--torque 5", "not a gear pair"],
        ),
        (
            "gear-pair-20-42.toml",
            "--torque -5 --face-width 20",
            vec!["--torque -5", "positive"],
        ),
        (
            "gear-pair-20-42.toml",
            "--torque 5",
            vec!["--face-width", "face width"],
        ),
        (
            "gear-pair-20-42.toml",
            "--power -2 --face-width 20",
            vec!["--power -2", "positive"],
        ),
        (
            "paper-dynamics.toml",
            "--power 2",
            vec!["--power 2", "not a gear pair"],
        ),
        (
            "fzg-c.toml",
            "--face-width 0.01",
            vec!["--face-width 0.01", "1e-3 to 1e3"],
        ),
        (
            "gear-pair-20-42.toml",
            "--torque 5 --face-width 20 --margin 3",
            vec!["--margin", "--torque"],
        ),
        (
            "gear-pair-20-42.toml",
            "--torque 5 --face-width 20 --oil sae-30@100c",
            vec!["--oil", "--roughness"],
        ),
    ] {
        let args: Vec<&str> = args.split(' ').collect();
        let a = run!("forces", examples().join(file))
            .args(&args)
            .assert()
            .code(2);
        let err = String::from_utf8(a.get_output().stderr.clone()).unwrap();
        for n in needles {
            assert!(err.contains(n), "{args:?}: {n:?} not in {err}");
        }
    }
    // a gear pair without a torque still needs [dynamics] for the forces
    run!("forces", examples().join("gear-pair-20-42.toml")).refused("[dynamics]");
}

/// The file's `[gear_loads]` loads the pair with no flag; `--torque` and `--power` replace it,
/// a power being `P/ω` at the file's speed.
#[test]
fn the_files_gear_loads_and_a_power() {
    let dir = tempfile::tempdir().unwrap();
    let base = std::fs::read_to_string(examples().join("gear-pair-20-42.toml")).unwrap();
    let file = dir.path().join("g.toml");
    std::fs::write(
        &file,
        format!("{base}\n[gear_loads]\ntorque = 50.0\nface_width = 20.0\n"),
    )
    .unwrap();
    let run = |args: &[&str]| {
        let a = run!("forces", &file).args(args).assert().success();
        String::from_utf8(a.get_output().stdout.clone()).unwrap()
    };
    let from_file = run(&[]);
    assert!(from_file.contains("torque 50 N·m"), "{from_file}");
    // 50 N·m at the file's 1000 rpm is 5.236 kW
    let power = 50.0 * 1000.0 * std::f64::consts::PI / 30.0 / 1e3;
    let by_power = run(&["--power", &power.to_string()]);
    assert_eq!(by_power, from_file);
    let other = run(&["--torque", "20"]);
    assert!(other.contains("torque 20 N·m"), "{other}");
    // --torque and --power together: clap's usage error
    run!("forces", &file, "--torque", "2", "--power", "3")
        .assert()
        .code(2);
}
