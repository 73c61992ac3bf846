//! `camkin synth`: profile files (the DXF read back by a DXF reader), SVAJ plots, design checks
//! on cams built to violate them, the round trip.
#![allow(clippy::unwrap_used)]
use crate::common::predicate;
use crate::common::*;
use std::path::PathBuf;

#[test]
fn synth_writes_a_profile_a_dxf_reader_opens() {
    let dir = tempfile::tempdir().unwrap();
    let mech = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/motion-roller.toml");
    let out = run!("synth", &mech, "--out", dir.path()).stdout_ok();
    let report = String::from_utf8(out).unwrap();
    assert!(report.contains("round trip"), "{report}");
    // the round trip's acceleration error, as a fraction of the peak, is tiny
    let frac: f64 = report
        .split(" of the peak")
        .next()
        .unwrap()
        .rsplit('(')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(frac < 1e-10, "{report}");
    assert!(
        report.contains("undercut: none") && report.contains("within ±30°"),
        "{report}"
    );
    // the DXF: millimetres, the profile and the roller's pitch curve as closed polylines of
    // arcs; every arc within the stated tolerance of the exact profile (checked at points along
    // the arcs, against the profile's exact radius from the polar table's closed form below)
    let dxf = read_dxf(&std::fs::read_to_string(dir.path().join("profile.dxf")).unwrap());
    assert_eq!(dxf.header.get("$INSUNITS").map(String::as_str), Some("4"));
    let layers: Vec<&str> = dxf.polylines.iter().map(|p| p.layer.as_str()).collect();
    assert_eq!(layers, ["PROFILE", "PITCH"]);
    assert!(dxf.polylines.iter().all(|p| p.closed));
    let (_, polar) = parse_csv(&std::fs::read(dir.path().join("polar.csv")).unwrap());
    assert_eq!(polar.len(), 720);
    for f in [
        "profile.svg",
        "svaj.png",
        "svaj.svg",
        "checks.txt",
        "pitch.csv",
    ] {
        assert!(dir.path().join(f).exists(), "{f}");
    }
    assert!(!dir.path().join("cutter.csv").exists());
}

fn motion_file(
    dir: &std::path::Path,
    follower: &str,
    base: f64,
    rise: f64,
    degrees: f64,
) -> PathBuf {
    let p = dir.join("m.toml");
    std::fs::write(
        &p,
        format!(
            "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"motion\"\nbase_radius = {base}\nsegments = [{{ law = \"cycloidal\", rise = {rise}, degrees = {degrees} }}, {{ law = \"dwell\", degrees = {} }}, {{ law = \"cycloidal\", rise = {}, degrees = {degrees} }}, {{ law = \"dwell\", degrees = {} }}]\n{follower}",
            180.0 - degrees,
            -rise,
            180.0 - degrees
        ),
    )
    .unwrap();
    p
}

#[test]
fn design_checks_catch_cams_built_to_violate_them() {
    let dir = tempfile::tempdir().unwrap();
    // a flat face on a small base circle with a harsh rise: ρ = s + s'' < 0 somewhere
    let m = motion_file(
        dir.path(),
        "[follower]\nkind = \"translating-flat\"\n",
        1.0,
        2.0,
        60.0,
    );
    run!("synth", &m, "--out", dir.path().join("a"))
        .assert()
        .code(3)
        .stderr(predicate::str::contains("design checks failed: round trip"))
        .stdout(predicate::str::contains(
            "the follower cannot follow the profile at",
        ))
        .stdout(predicate::str::contains("round trip FAILED"));
    // a roller larger than the pitch curve's concave radius: undercut
    let m = motion_file(
        dir.path(),
        "[follower]\nkind = \"translating-roller\"\nroller_radius = 3.0\n",
        1.0,
        2.0,
        60.0,
    );
    run!("synth", &m, "--out", dir.path().join("u"))
        .assert()
        .code(3)
        .stderr(predicate::str::contains("undercut"))
        .stdout(predicate::str::contains(
            "undercut: the profile is concave more sharply than the roller",
        ));
    // a roller with a steep rise: the pressure angle goes far beyond 30°
    let m = motion_file(
        dir.path(),
        "[follower]\nkind = \"translating-roller\"\nroller_radius = 0.2\n",
        2.0,
        3.0,
        60.0,
    );
    run!("synth", &m, "--out", dir.path().join("b"))
        .assert()
        .code(3)
        .stderr(predicate::str::contains(
            "design checks failed: pressure angle",
        ))
        .stdout(predicate::str::contains("pressure angle: peak "))
        .stdout(predicate::str::contains("beyond ±30°"));
}

#[test]
fn synth_needs_a_motion_profile() {
    let mech = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper.toml");
    run!("synth", &mech, "--out", tempfile::tempdir().unwrap().path()).refused("kind = \"motion\"");
}

/// Regression (issue 12): a program with no acceleration (constant velocity) was reported as
/// "round trip FAILED … 9.2e297 of the peak": its rounding-level peak was taken as the scale.
#[test]
fn round_trip_of_a_program_without_acceleration_is_not_failed() {
    let (dir, m) = written("cv.toml", "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"motion\"\nbase_radius = 40.0\nsegments = [{ law = \"constant-velocity\", rise = 10.0, degrees = 180 }, { law = \"constant-velocity\", rise = -10.0, degrees = 180 }]\n[follower]\nkind = \"translating-roller\"\nroller_radius = 5\n");
    run!("synth", &m, "--out", dir.path().join("o"))
        .assert()
        .success()
        .stdout(predicate::str::contains("the program has no acceleration"))
        .stdout(predicate::str::contains("FAILED").not());
}

/// Issue 12, class 6: files estimated at over 1 GB are refused up front with the estimate and
/// the flag, and nothing is written.
#[test]
fn a_profile_of_gigabytes_asks_first() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s");
    run!(
        "synth",
        examples().join("motion-roller.toml"),
        "--out",
        &out,
        "--step",
        "0.00004"
    )
    .refused("s and 1.5 GB")
    .stderr(predicate::str::contains("--large"));
    assert!(!out.exists());
}

/// Issue 12, class 3 (regression: "undercut" reported on a roller cam whose concave radii, ≥ 38,
/// are far larger than its roller, 10): a concave stretch a roller fits in is no undercut. The
/// sharpest concave radius reported is checked against the closed form of the pitch curve
/// `r_p(θ) = R_b + r + s(θ)` (cycloidal rise), whose radius of curvature is
/// `(r_p² + r_p'²)^{3/2} / (r_p² + 2 r_p'² − r_p r_p'')`; the profile's is that minus `r`.
#[test]
fn concave_stretches_a_roller_fits_in_are_no_undercut() {
    let dir = tempfile::tempdir().unwrap();
    let (base, rise, beta, roller) = (40.0f64, 30.0f64, 90.0f64, 10.0f64);
    let m = motion_file(
        dir.path(),
        &format!("[follower]\nkind = \"translating-roller\"\ndirection = [0.0, 1.0]\nroller_radius = {roller}\n"),
        base,
        rise,
        beta,
    );
    let a = run!(
        "synth",
        &m,
        "--out",
        dir.path().join("c"),
        "--pressure-limit",
        "35"
    )
    .assert()
    .success()
    .stdout(predicate::str::contains("undercut: none"));
    let out = String::from_utf8(a.get_output().stdout.clone()).unwrap();
    let line = out
        .lines()
        .find(|l| l.starts_with("sharpest concave radius of curvature of the profile: "))
        .unwrap_or_else(|| panic!("{out}"));
    let words: Vec<&str> = line.split_whitespace().collect();
    let rho: f64 = words[8].parse().unwrap();
    let at: f64 = words[11].trim_end_matches('°').parse().unwrap();
    // the pitch curve's radius at program angle `at`: the rise spans 0…β, the return (its
    // mirror, s = rise − rise's s) 180°…180° + β
    let b = beta.to_radians();
    let (x, sign) = if at < beta {
        (at.to_radians(), 1.0)
    } else {
        assert!((180.0..180.0 + beta).contains(&at), "{line}");
        ((at - 180.0).to_radians(), -1.0)
    };
    let k = std::f64::consts::TAU / b;
    let cyc = rise * (x / b - (k * x).sin() / std::f64::consts::TAU);
    let s = if sign > 0.0 { cyc } else { rise - cyc };
    let s1 = sign * rise / b * (1.0 - (k * x).cos());
    let s2 = sign * rise / b * k * (k * x).sin();
    let r = base + roller + s;
    let rho_p = (r * r + s1 * s1).powf(1.5) / (r * r + 2.0 * s1 * s1 - r * s2);
    assert!(rho_p < 0.0 && rho_p.abs() > roller, "{rho_p}");
    assert!(
        (rho - (rho_p - roller)).abs() <= 1e-5 * rho.abs(),
        "{line}: closed form {}",
        rho_p - roller
    );
}

/// Issue 49: `profile.svg` is drawn to scale: its size is in the file's unit (mm here) and equal
/// to its view box, so one user unit is one millimetre; the polygon's farthest point from the
/// axis is the cam's largest radius of `polar.csv`; the centre mark, the 0° line and a scale bar
/// with its length and unit are drawn.
#[test]
fn the_profile_svg_is_drawn_to_scale() {
    let dir = tempfile::tempdir().unwrap();
    run!(
        "synth",
        examples().join("motion-roller.toml"),
        "--out",
        dir.path()
    )
    .assert()
    .success();
    let svg = std::fs::read_to_string(dir.path().join("profile.svg")).unwrap();
    let attr = |name: &str| -> String {
        let at = svg.find(&format!("{name}=\"")).unwrap() + name.len() + 2;
        svg[at..].split('"').next().unwrap().to_string()
    };
    let width = attr("width");
    assert!(width.ends_with("mm"), "{width}");
    let view: Vec<f64> = attr("viewBox")
        .split(' ')
        .map(|v| v.parse().unwrap())
        .collect();
    let w: f64 = width.trim_end_matches("mm").parse().unwrap();
    assert!((w - view[2]).abs() < 1e-9 * w, "{w} vs {view:?}");
    let pts = attr("points");
    let reach = pts
        .split(' ')
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            x.parse::<f64>().unwrap().hypot(y.parse::<f64>().unwrap())
        })
        .fold(0.0f64, f64::max);
    let polar = std::fs::read_to_string(dir.path().join("polar.csv")).unwrap();
    let largest = polar
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(1).unwrap().parse::<f64>().unwrap())
        .fold(0.0f64, f64::max);
    assert!(
        (reach - largest).abs() < 1e-3 * largest,
        "{reach} vs {largest}"
    );
    for mark in ["0°</text>", " mm</text>", "M 0 0 H"] {
        assert!(svg.contains(mark), "{mark}");
    }
}

/// Issue 49: an extreme held over a dwell is named as its stretch on the SVAJ page ("max 12 mm
/// from 120° to 180°"), as `forces` names a constant force; a peak at one angle keeps "at".
#[test]
fn the_svaj_page_names_a_dwells_extreme_as_its_stretch() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("cam");
    run!("synth", examples().join("design-a-cam.toml"), "--out", &out)
        .assert()
        .success();
    let svg = std::fs::read_to_string(out.join("svaj.svg")).unwrap();
    assert!(
        svg.contains("max 12 mm from 120° to 180°"),
        "the lift's dwell at full lift"
    );
    assert!(
        svg.contains("min 0 mm from 300° to 360°"),
        "the dwell at rest, up to 360°"
    );
    assert!(svg.contains("max 1440 mm/s at 60°"), "a peak at one angle");
}
