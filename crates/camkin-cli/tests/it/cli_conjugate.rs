//! A conjugate (form-closed) follower from the command line: the example's constant-diameter cam
//! drives both rollers (its play column is zero, two contacts at every angle), a second curve's
//! bad field is placed in the file, and `forces` and `simulate` share the load between them.
#![allow(clippy::unwrap_used)]
use crate::common::predicate;
use crate::common::*;

/// The example's rollers are 2 × (40 + 10) + 20 mm apart, the cam's constant diameter across
/// the pitch curve for a motion with `s(θ + 180°) = 20 − s(θ)`: the play is zero at every angle.
#[test]
fn the_examples_second_roller_has_no_play() {
    let out = run!("analyze", examples().join("conjugate-yoke.toml")).stdout_ok();
    let (header, rows) = parse_csv(&out);
    let col = columns(&header);
    assert_eq!(rows.len(), 360);
    for r in &rows {
        let play: f64 = r[col["conjugate_play_mm"]].parse().unwrap();
        assert!(play.abs() < 1e-9, "{r:?}");
        assert!(r[col["error"]].is_empty(), "{r:?}");
    }
}

/// Every angle has the first roller's contact and the second's, named in the `curve` column,
/// each with its row satisfied by the motion (γ and the residual in mm/s²).
#[test]
fn contacts_lists_both_rollers() {
    let out = run!(
        "contacts",
        examples().join("conjugate-yoke.toml"),
        "--angles",
        "0:360:5"
    )
    .assert()
    .success()
    .stderr(predicate::str::contains("144 contacts at 72 cam angles"))
    .get_output()
    .stdout
    .clone();
    let (header, rows) = parse_csv(&out);
    let col = columns(&header);
    assert_eq!(rows.len(), 144);
    for pair in rows.chunks(2) {
        assert_eq!(pair[0][col["curve"]], "follower");
        assert_eq!(pair[1][col["curve"]], "conjugate");
        assert_eq!(pair[0][col["angle_deg"]], pair[1][col["angle_deg"]]);
        for r in pair {
            let gamma: f64 = r[col["gamma_mm_s2"]].parse().unwrap();
            let residual: f64 = r[col["residual_mm_s2"]].parse().unwrap();
            assert!(residual.abs() <= 1e-9 * gamma.abs().max(1.0), "{r:?}");
        }
    }
}

fn with_dynamics() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(examples().join("conjugate-yoke.toml")).unwrap();
    std::fs::write(
        dir.path().join("m.toml"),
        format!("{text}\n[dynamics]\nmass = 0.5\nspring_stiffness = 0.0\nspring_preload = 0.0\n"),
    )
    .unwrap();
    dir
}

/// `forces` on a form-closed follower: the load passes between the rollers where the motion's
/// acceleration changes sign; the load on each roller, one at a time, as the dynamic
/// simulation's contact force on the roller it says touches (at the same angles, 1e-6 of the
/// peak); `--margin` (a spring-held follower's) is refused naming it, nothing written.
/// `simulate` drives it through both rollers: it stays on the cam's motion, the load passing
/// between the rollers (`on_conjugate`), without an event; a second roller that cuts into the cam
/// is refused (exit 2, naming the table, nothing written).
#[test]
fn dynamics_of_a_form_closed_follower() {
    let dir = with_dynamics();
    let mech = dir.path().join("m.toml");
    let out = dir.path().join("f");
    run!("forces", &mech, "--margin", "5", "--out", &out)
        .refused("--margin: the follower is form-closed (follower.conjugate)");
    assert!(!out.exists(), "forces wrote {out:?}");
    run!(
        "forces",
        &mech,
        "--step",
        "2",
        "--face-width",
        "10",
        "--out",
        &out
    )
    .assert()
    .success()
    // the cycloidal rise's and return's accelerations change sign at 90° and 270°
    .stdout(predicate::str::contains(
        "load reversals: 2 a revolution, where the load passes to the other curve (at 90°, 270°)",
    ))
    .stdout(predicate::str::contains("play of the second curve: none"))
    .stdout(predicate::str::contains(
        "contact stress on the second curve",
    ));
    let (fh, frows) = parse_csv(&std::fs::read(out.join("forces.csv")).unwrap());
    let fc = columns(&fh);
    let forces: Vec<(f64, f64, f64)> = frows
        .iter()
        .map(|r| {
            let x = |c: &str| r[fc[c]].parse::<f64>().unwrap();
            (
                x("angle_deg"),
                x("contact_force_N"),
                x("second_contact_force_N"),
            )
        })
        .collect();
    let peak = forces.iter().map(|f| f.1.max(f.2)).fold(0.0, f64::max);
    assert!(peak > 1.0, "{peak}");
    for f in &forces {
        assert!(
            f.1 >= 0.0 && f.2 >= 0.0 && (f.1 == 0.0 || f.2 == 0.0),
            "{f:?}"
        );
    }
    let a = run!("simulate", &mech, "--step", "2")
        .assert()
        .success()
        .stderr(predicate::str::contains("no lift-off"));
    let (header, rows) = parse_csv(&a.get_output().stdout);
    let col = columns(&header);
    let (p, k, on, c) = (
        col["position_mm"],
        col["kinematic_position_mm"],
        col["on_conjugate"],
        col["in_contact"],
    );
    let mut sides = std::collections::BTreeSet::new();
    let mut compared = 0;
    for f in &rows {
        let (x, y): (f64, f64) = (f[p].parse().unwrap(), f[k].parse().unwrap());
        assert!((x - y).abs() <= 1e-9, "{f:?}");
        assert_eq!(f[c], "1", "{f:?}");
        sides.insert(f[on].clone());
        // the kinetostatic force at the same angle, on the roller the simulation says touches
        let angle: f64 = f[col["cam_angle_deg"]].parse().unwrap();
        let force: f64 = f[col["contact_force_N"]].parse().unwrap();
        if let Some(k) = forces
            .iter()
            .find(|g| (g.0 - angle.rem_euclid(360.0)).abs() < 1e-9)
        {
            let expected = if f[on] == "1" { k.2 } else { k.1 };
            assert!((force - expected).abs() <= 1e-6 * peak, "{f:?}: {k:?}");
            compared += 1;
        }
    }
    assert!(compared >= 150, "{compared} angles compared");
    assert_eq!(sides.len(), 2, "the load never passes: {sides:?}");
    let tight = dir.path().join("tight.toml");
    let text = std::fs::read_to_string(&mech)
        .unwrap()
        .replace("center = [-120.0, 0.0]", "center = [-119.8, 0.0]");
    std::fs::write(&tight, text).unwrap();
    let out = dir.path().join("s");
    run!("simulate", &tight, "--out", &out)
        .refused("follower.conjugate: the second curve cuts 0.0002 m into the cam");
    assert!(!out.exists(), "simulate wrote {out:?}");
}

/// A second curve's bad field is named with its line in the file; one that cannot touch the cam
/// from the other side is refused up front.
#[test]
fn a_bad_second_curve_is_placed_in_the_file() {
    let base = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"circle\"\ncenter = [5, 0]\nradius = 30\n[follower]\nkind = \"translating-roller\"\nroller_radius = 10\n[follower.conjugate]\nkind = \"circle\"\n";
    for (tail, needles) in [
        (
            "center = [-80, 0]\nradius = -1\n",
            vec!["follower.conjugate.radius = -1", "m.toml:14:"],
        ),
        (
            "center = [-80, 500]\nradius = 10\n",
            vec!["follower.conjugate: the second curve must touch the cam from the other side"],
        ),
    ] {
        let (_dir, mech) = written("m.toml", format!("{base}{tail}"));
        let a = run!("analyze", &mech).assert().code(2);
        let err = String::from_utf8(a.get_output().stderr.clone()).unwrap();
        for n in needles {
            assert!(err.contains(n), "{n:?} not in {err}");
        }
    }
}

/// `camkin synth` checks the second curve: the example's rollers both touch everywhere; a
/// program whose return is not the rise mirrored (rise over 120°, dwell, return over 180°) loses
/// touch and cuts in, which fails the check with exit code 3 (the files are still written).
#[test]
fn synth_checks_the_conjugate_play() {
    let dir = tempfile::tempdir().unwrap();
    run!(
        "synth",
        examples().join("conjugate-yoke.toml"),
        "--out",
        dir.path().join("ok")
    )
    .assert()
    .success()
    .stdout(predicate::str::contains(
        "conjugate play: none: both curves touch everywhere",
    ));
    let text = std::fs::read_to_string(examples().join("conjugate-yoke.toml")).unwrap();
    let uneven = text.replace(
        "{ law = \"cycloidal\", rise = 20.0, degrees = 180 },",
        "{ law = \"cycloidal\", rise = 20.0, degrees = 120 },\n    { law = \"dwell\", degrees = 60 },",
    );
    assert_ne!(uneven, text);
    let mech = dir.path().join("uneven.toml");
    std::fs::write(&mech, uneven).unwrap();
    run!("synth", &mech, "--out", dir.path().join("bad"))
        .assert()
        .code(3)
        .stdout(predicate::str::contains(
            "the second curve cuts into the cam",
        ))
        .stderr(predicate::str::contains(
            "design checks failed: conjugate play",
        ));
    assert!(dir.path().join("bad").join("checks.txt").exists());
}

/// The studio's checks (here through its one-file report) carry the same words as synth's.
#[test]
fn the_report_checks_the_conjugate_play() {
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("report.html");
    run!(
        "report",
        examples().join("conjugate-yoke.toml"),
        "-o",
        &page
    )
    .assert()
    .success();
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(html.contains("conjugate play: none: both curves touch everywhere"));
}

/// An arm's play is an angle, in degrees in the table (`conjugate_play_deg`): a bell crank with
/// two rollers on an eccentric circle, against the law of cosines about the pivot.
#[test]
fn an_arms_play_is_in_degrees() {
    let dir = tempfile::tempdir().unwrap();
    let mech = dir.path().join("crank.toml");
    let (l1, l2, r, beta) = (98.0f64, 97.0f64, 10.0f64, -0.84f64);
    std::fs::write(
        &mech,
        format!(
            "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"circle\"\ncenter = [5, 0]\nradius = 30\n\
             [follower]\nkind = \"oscillating-roller\"\npivot = [-90, 0]\narm_length = {l1}\nroller_radius = {r}\nclosing = \"cw\"\ninitial_angle_deg = 20\n\
             [follower.conjugate]\nkind = \"circle\"\ncenter = [{}, {}]\nradius = {r}\n",
            l2 * beta.cos(),
            l2 * beta.sin()
        ),
    )
    .unwrap();
    let out = run!("analyze", &mech, "--angles", "0:360:10").stdout_ok();
    let (header, rows) = parse_csv(&out);
    let col = columns(&header);
    assert_eq!(rows.len(), 36);
    for r in &rows {
        let t = r[col["angle_deg"]].parse::<f64>().unwrap().to_radians();
        let (cx, cy) = (5.0 * t.cos() + 90.0, 5.0 * t.sin());
        let (d, towards) = (cx.hypot(cy), cy.atan2(cx));
        let arm = |l: f64| ((l * l + d * d - 40.0 * 40.0) / (2.0 * l * d)).acos();
        let want = (towards - arm(l2) - beta - (towards + arm(l1))).to_degrees();
        let play: f64 = r[col["conjugate_play_deg"]].parse().unwrap();
        assert!((play - want).abs() < 1e-7, "{r:?}: {want}");
    }
}
