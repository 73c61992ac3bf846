//! `camkin mesh`: a gear pair's table with units, the handover where the line of action says, the
//! summary on stderr, the plot, refusals of what is not a gear pair.
#![allow(clippy::unwrap_used)]
use crate::common::predicate;
use crate::common::*;
use std::collections::HashMap;

fn table(out: &[u8]) -> (HashMap<String, usize>, Vec<Vec<String>>) {
    let (header, rows) = parse_csv(out);
    let col = header
        .iter()
        .enumerate()
        .map(|(i, h)| (h.clone(), i))
        .collect();
    (col, rows)
}

fn num(r: &[String], col: &HashMap<String, usize>, name: &str) -> f64 {
    r[col[name]].parse().unwrap_or(f64::NAN)
}

/// The built-in 20/42 pair over two mesh cycles: the nominal ratio and no transmission error at
/// every row, and a handover a mesh cycle, each where the reported pair reaches the end of the path of contact
/// (the driver's tip circle on the line of action: `√(r_a1² − r_b1²) − r_b1 tan α` from the pitch
/// point), written here from m, z and α alone.
#[test]
fn default_is_the_ideal_pair_with_its_handover_where_the_line_of_action_ends() {
    let out = run!("mesh")
        .assert()
        .success()
        .stderr(predicate::str::contains("contact ratio 1.6399"))
        .stderr(predicate::str::contains(
            "2 handovers to another tooth pair",
        ))
        .get_output()
        .stdout
        .clone();
    let (col, rows) = table(&out);
    for name in [
        "angle_deg",
        "driven_angle_deg",
        "transmission_error_urad",
        "transmission_error_mm",
        "line_of_action_mm",
        "sliding_velocity_mm_s",
        "specific_sliding_driver",
        "pairs_in_contact",
    ] {
        assert!(col.contains_key(name), "no column {name}");
    }
    assert_eq!(rows.len(), 720);
    let alpha = 20f64.to_radians();
    let (rb1, ra1) = (20.0 * alpha.cos(), 22.0);
    let end = (ra1 * ra1 - rb1 * rb1).sqrt() - rb1 * alpha.tan();
    let mut jumps = 0;
    for (k, r) in rows.iter().enumerate() {
        assert!(
            (num(r, &col, "speed_ratio") + 20.0 / 42.0).abs() <= 1e-10,
            "{r:?}"
        );
        assert!(
            num(r, &col, "transmission_error_urad").abs() <= 1e-6,
            "{r:?}"
        );
        if r[col["found"]] == "jump" {
            jumps += 1;
            // the previous row's pair, moved on by r_b1 per radian, has left the path
            let prev = &rows[k - 1];
            let x = num(prev, &col, "line_of_action_mm");
            let step = (num(r, &col, "angle_deg") - num(prev, &col, "angle_deg")).to_radians();
            assert!(x <= end + 1e-9 && x + rb1 * step > end - 1e-9, "{x} {end}");
            // and the new pair is a base pitch behind
            let pb = std::f64::consts::TAU * rb1 / 20.0;
            let x_new = num(r, &col, "line_of_action_mm");
            assert!((x_new - (x + rb1 * step - pb)).abs() <= 1e-9, "{x_new}");
        }
    }
    assert_eq!(jumps, 2);
}

/// Tip relief: the table's columns agree with each other in their units (µrad and mm along the
/// line of action, `r_b2 = 42 cos 20°`), the error is never negative (relief only lets the
/// driven gear lag), the page of plots is written, and cold queries at listed angles give the
/// sweep's rows.
#[test]
fn tip_relief_table_units_plot_and_cold_queries_agree() {
    let dir = tempfile::tempdir().unwrap();
    let file = examples().join("gear-pair-tip-relief.toml");
    let out = run!("mesh", &file, "--angles", "0:18:0.25", "--plot", dir.path())
        .assert()
        .success()
        .stderr(predicate::str::contains("peak to peak"))
        .get_output()
        .stdout
        .clone();
    let (col, rows) = table(&out);
    assert_eq!(rows.len(), 72);
    let rb2 = 42.0 * 20f64.to_radians().cos();
    let mut most: f64 = 0.0;
    for r in &rows {
        let (urad, mm) = (
            num(r, &col, "transmission_error_urad"),
            num(r, &col, "transmission_error_mm"),
        );
        assert!((urad * 1e-6 * rb2 - mm).abs() <= 1e-12 * rb2, "{r:?}");
        assert!(mm >= -1e-12, "{r:?}");
        most = most.max(mm);
    }
    // 20 µm of relief on each gear: the driven gear lags by less than both together
    assert!(most > 1e-3 && most < 0.04, "{most}");
    for f in ["mesh.svg", "mesh.png"] {
        let bytes = std::fs::read(dir.path().join(f)).unwrap();
        assert!(bytes.len() > 10_000, "{f}: {} bytes", bytes.len());
    }
    // cold queries at some of the same angles
    let at = "0.25,3.75,7.5,12.75";
    let cold = run!("mesh", &file, "--at", at).stdout_ok();
    let (c2, cold) = table(&cold);
    for r in &cold {
        let a = num(r, &c2, "angle_deg");
        let w = rows
            .iter()
            .find(|w| (num(w, &col, "angle_deg") - a).abs() < 1e-9)
            .unwrap();
        for name in [
            "driven_angle_deg",
            "transmission_error_mm",
            "line_of_action_mm",
        ] {
            let (x, y) = (num(r, &c2, name), num(w, &col, name));
            assert!(
                (x - y).abs() <= 1e-9 * (1.0 + y.abs()),
                "{name} at {a}: {x} {y}"
            );
        }
        assert_eq!(r[c2["driver_tooth"]], w[col["driver_tooth"]]);
    }
}

#[test]
fn json_keeps_counts_and_flags_as_numbers_and_booleans() {
    let out = run!("mesh", "--at", "0,9", "--format", "json").stdout_ok();
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let r = &v[1];
    assert!(r["on_flanks"].is_boolean(), "{r}");
    assert!(r["pairs_in_contact"].is_u64(), "{r}");
    assert!(r["driver_tooth"].is_u64(), "{r}");
    assert_eq!(r["driver_flank"], "ccw");
}

/// A cam that is not a gear: exit 2 naming what is missing, and no output file written.
#[test]
fn not_a_gear_pair_is_refused_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("mesh.csv");
    run!("mesh", examples().join("paper.toml"), "-o", &out)
        .refused("not a gear pair")
        .stderr(predicate::str::contains(
            "cam.profile.kind = \"involute-gear\"",
        ));
    assert!(!out.exists());
}

/// Issue 44: gears whose teeth overlap (closer than the tight mesh: the FZG C pair at its
/// nominal 91.5 mm) or never meet on their involutes are refused by every command that reads
/// the file (exit 2, at `follower.pivot`, naming the distance that would work), not analysed
/// with failures about tip corners or a negative contact ratio; a ratio below 1 is warned of.
#[test]
fn interfering_or_distant_gears_are_refused_naming_the_distance() {
    let (dir, fzg) = written("fzg.toml", "length_unit = \"mm\"\n[cam]\nspeed_rpm = 1000.0\n[cam.profile]\nkind = \"involute-gear\"\nmodule = 4.5\nteeth = 16\npressure_angle_deg = 20.0\nprofile_shift = 0.1817\n[follower]\nkind = \"rotating\"\npivot = [91.5, 0.0]\nclosing = \"ccw\"\ninitial_angle_deg = 187.5\n[follower.profile]\nkind = \"involute-gear\"\nmodule = 4.5\nteeth = 24\npressure_angle_deg = 20.0\nprofile_shift = 0.1715\n");
    for cmd in ["analyze", "mesh", "contacts"] {
        run!(cmd, &fzg)
            .refused("fzg.toml:12:9: follower.pivot")
            .stderr(predicate::str::contains(
                "tight-mesh (zero-backlash) distance 91.500078596",
            ))
            .stderr(predicate::str::contains("overlap by 6.000e-5"));
    }
    let text = std::fs::read_to_string(examples().join("gear-pair-20-42.toml")).unwrap();
    let far = dir.path().join("far.toml");
    std::fs::write(
        &far,
        text.replace("pivot = [62.0, 0.0]", "pivot = [70.0, 0.0]"),
    )
    .unwrap();
    run!("mesh", &far)
        .refused("no path of contact")
        .stderr(predicate::str::contains("at most 63.3917"));
    let low = dir.path().join("low.toml");
    std::fs::write(
        &low,
        text.replace("pivot = [62.0, 0.0]", "pivot = [64.0, 0.0]"),
    )
    .unwrap();
    run!("mesh", &low, "--angles", "0:18:1")
        .assert()
        .success()
        .stderr(predicate::str::contains(
            "warning: contact ratio 0.745 is below 1",
        ));
}
