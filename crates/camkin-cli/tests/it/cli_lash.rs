//! `camkin simulate --lash FROM:TO:STEP` on `examples/bucket-lash.toml` (issue 65, lash and
//! ramps): each lash's take-up and seating against the ramp's closed form, the table and chart
//! written with `--out`, and every bad range refused naming `--lash` with nothing written.

use crate::common::{examples, run};

/// The ramp's closed form (docs/valve-train.md#lash-and-ramps): a lash `c` between 0.05 and
/// 0.25 mm of the 0.3 mm, 30° ramp is taken up at `30° (1/4 + 3/4 (c/0.3 − 1/6))` at
/// `ω · 4h/3β` = 120 mm/s at 1500 rpm, and the valve seats at the mirror angle `260° − that`.
fn closed_form(c: f64) -> (f64, f64) {
    (30.0 * (0.25 + 0.75 * (c / 0.3 - 1.0 / 6.0)), 120.0)
}

/// The sweep prints a row a lash, and `--out` writes `lash.csv` (round-trip numbers: the
/// closed form's angles to 1e-8° and speed to 1e-9 of it on the ramps' constant-velocity part)
/// and the chart; a plain run prints the lashed contact's take-up and seating.
#[test]
fn the_lash_sweep_prints_and_writes_each_take_up_and_seating() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("lash");
    let text = run!(
        "simulate",
        examples().join("bucket-lash.toml"),
        "--lash",
        "0.05:0.25:0.05",
        "--out",
        &out
    )
    .stdout_ok();
    let text = String::from_utf8(text).unwrap();
    assert!(
        text.contains("0.1        cam on bucket        11.25              120       248.75              120         seat"),
        "{text}"
    );
    let csv = std::fs::read_to_string(out.join("lash.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("lash_mm,contact,take_up_angle_deg,take_up_speed_mm_s,seat,seating_angle_deg,seating_speed_mm_s")
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 5, "{csv}");
    for (k, r) in rows.iter().enumerate() {
        let c = 0.05 * (k + 1) as f64;
        let num = |i: usize| r[i].parse::<f64>().unwrap();
        assert!((num(0) - c).abs() < 1e-12, "{r:?}");
        let (at, speed) = closed_form(c);
        assert_eq!((r[1], r[4]), ("cam on bucket", "seat"));
        assert!((num(2) - at).abs() < 1e-8, "{r:?} vs {at}");
        assert!((num(5) - (260.0 - at)).abs() < 1e-8, "{r:?} vs {at}");
        assert!((num(3) - speed).abs() < 1e-9 * speed, "{r:?}");
        assert!((num(6) - speed).abs() < 1e-9 * speed, "{r:?}");
    }
    for f in ["lash.svg", "lash.png"] {
        assert!(std::fs::metadata(out.join(f)).unwrap().len() > 1000, "{f}");
    }
    let plain = run!(
        "simulate",
        examples().join("bucket-lash.toml"),
        "--step",
        "1"
    )
    .assert()
    .success();
    let err = String::from_utf8_lossy(&plain.get_output().stderr).to_string();
    assert!(
        err.contains("\"cam on bucket\", lash 0.1 mm: taken up at 11.25°, 120 mm/s; seated on \"seat\" at 248.75°, 120 mm/s"),
        "{err}"
    );
}

/// Every bad range or file is refused (exit 2) naming `--lash` and the value as written, and
/// the `--out` folder is not made.
#[test]
fn a_bad_lash_sweep_is_refused_naming_the_flag() {
    let bucket = examples().join("bucket-lash.toml");
    let valve = examples().join("valve-train.toml");
    let paper = examples().join("paper.toml");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("never");
    for (file, range, says) in [
        (
            &bucket,
            "0.4:0.1:0.05",
            "--lash 0.4:0.1:0.05: FROM must be 0 or more",
        ),
        (
            &bucket,
            "-0.1:0.1:0.05",
            "--lash -0.1:0.1:0.05: FROM must be 0 or more",
        ),
        (&bucket, "0.1:0.2", "--lash 0.1:0.2: give FROM:TO:STEP"),
        (&bucket, "a:b:c", "--lash a:b:c: give FROM:TO:STEP"),
        (
            &bucket,
            "0:1:1e-6",
            "--lash 0:1:1e-6: 1000001 lashes is more than 200",
        ),
        (
            &bucket,
            "0:20:10",
            "--lash 0:20:10: a lash of 10 mm must be from 0 to",
        ),
        (&valve, "0.1:0.2:0.05", "no contact has a lash"),
        (&paper, "0.1:0.2:0.05", "--lash: for a system file"),
    ] {
        run!("simulate", file, "--lash", range, "--out", &out).refused(says);
        assert!(!out.exists(), "{range}");
    }
    run!(
        "simulate",
        &bucket,
        "--lash",
        "0.1:0.2:0.05",
        "--no-follow",
        "1000:2000:500"
    )
    .refused("--lash 0.1:0.2:0.05: a lash sweep simulates revolutions");
}
