//! `camkin contacts`: every contact at each angle, one row each, with units in the column names;
//! two to four contacts of the 20/42 gear pair (both lines of action: no backlash), one of the
//! paper's cam; JSON with the CSV's columns; refusals with exit code 2.
#![allow(clippy::unwrap_used)]
use crate::common::predicate;
use crate::common::*;
use std::collections::HashMap;

/// Over one mesh cycle of the ideal 20/42 pair the driving line of action holds one or two
/// contacts, ε on average (the contact ratio, written here from m, z and α), and so does the
/// coast line (no backlash): 2ε contacts per angle on average. Every row's constraint holds at
/// the ideal motion (the driver at constant speed and the driven gear at the constant ratio:
/// both accelerations zero, so `gamma` is zero).
#[test]
fn gear_pair_has_two_to_four_contacts_each_with_its_row() {
    let pair = examples().join("gear-pair-20-42.toml");
    let out = run!("contacts", &pair, "--angles", "0:18:0.25")
        .assert()
        .success()
        .stderr(predicate::str::contains("at most 4 at once"))
        .get_output()
        .stdout
        .clone();
    let (header, rows) = parse_csv(&out);
    let col = columns(&header);
    for name in [
        "angle_deg",
        "contact",
        "x_mm",
        "gap_mm",
        "sliding_rate_cam_mm_s",
        "row_cam_mm_per_rad",
        "row_follower_mm_per_rad",
        "gamma_mm_s2",
        "residual_mm_s2",
    ] {
        assert!(col.contains_key(name), "no column {name} in {header:?}");
    }
    let num = |r: &Vec<String>, n: &str| r[col[n]].parse::<f64>().unwrap();
    let mut per_angle: HashMap<String, usize> = HashMap::new();
    for r in &rows {
        *per_angle.entry(r[col["angle_deg"]].clone()).or_default() += 1;
        assert!(num(r, "gap_mm").abs() <= 1e-9, "{r:?}");
        // the driver at constant speed: θ̈ = 0, and the driven gear's q̈ = 0 (ideal ratio)
        assert!(num(r, "gamma_mm_s2").abs() <= 1e-6, "{r:?}");
        assert!(num(r, "residual_mm_s2").abs() <= 1e-6, "{r:?}");
    }
    assert_eq!(per_angle.len(), 72);
    assert!(
        per_angle.values().all(|&n| (2..=4).contains(&n)),
        "{per_angle:?}"
    );
    let alpha = 20f64.to_radians();
    let (r1, r2) = (20.0, 42.0);
    let roll = |r: f64| ((r + 2.0f64).powi(2) - (r * alpha.cos()).powi(2)).sqrt();
    let eps = (roll(r1) + roll(r2) - (r1 + r2) * alpha.sin())
        / (std::f64::consts::PI * 2.0 * alpha.cos());
    let mean = rows.len() as f64 / 72.0;
    // each line's count changes at two instants per cycle: up to two samples off on each
    assert!(
        (mean - 2.0 * eps).abs() <= 4.0 / 72.0,
        "{mean} contacts on average, ε = {eps}"
    );
}

#[test]
fn json_has_the_csv_columns_and_the_paper_cam_one_contact() {
    let out = run!("contacts", "--at", "0,33", "--format", "json").stdout_ok();
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 2);
    for r in rows {
        assert_eq!(r["contact"], 0);
        assert!(r["row_follower_cm_per_cm"].as_f64().unwrap() > 0.0);
        assert!(r["error"].is_null());
    }
}

#[test]
fn refusals_name_the_value_and_exit_2() {
    run!("contacts", "--angles", "0:10").refused("0:10");
    run!("contacts", "no-such-file.toml").refused("no-such-file.toml");
    // 3.6 million angles of a gear pair: hours of searching, refused with the estimate
    run!(
        "contacts",
        examples().join("gear-pair-20-42.toml"),
        "--angles",
        "0:360:0.0001"
    )
    .refused("would take about");
}
