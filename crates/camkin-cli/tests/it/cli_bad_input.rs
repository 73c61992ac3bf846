//! Bad input: every case exits with code 2 and a message naming the field (or the line of the
//! points file) and the offending value, never a panic, and never a written file.
#![allow(clippy::unwrap_used)]
use crate::common::predicate;
use crate::common::*;

pub(crate) const CIRCLE: &str =
    "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"circle\"\ncenter = [0.5, 0]\nradius = 2\n";
pub(crate) const FLAT: &str = "[follower]\nkind = \"translating-flat\"\n";
pub(crate) const SPLINE_HEAD: &str =
    "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"spline\"\n";

/// Runs `camkin analyze` on `toml` (with extra files) and checks exit code 2, every needle in
/// stderr, no panic and no output file.
pub(crate) fn bad(name: &str, toml: &str, files: &[(&str, &str)], needles: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    for (f, text) in files {
        std::fs::write(dir.path().join(f), text).unwrap();
    }
    let mech = dir.path().join("m.toml");
    std::fs::write(&mech, toml).unwrap();
    let out = dir.path().join("out.csv");
    let a = run!("analyze", &mech, "--at", "0,90", "-o", &out)
        .assert()
        .code(2);
    let err = String::from_utf8(a.get_output().stderr.clone()).unwrap();
    for n in needles {
        assert!(err.contains(n), "{name}: {n:?} not in {err:?}");
    }
    assert!(!err.contains("panicked"), "{name}: {err}");
    assert!(!out.exists(), "{name}: wrote an output file");
}

#[test]
fn missing_and_unknown_fields() {
    bad(
        "missing speed",
        &format!("length_unit = \"mm\"\n[cam]\n[cam.profile]\nkind = \"circle\"\ncenter = [0, 0]\nradius = 1\n{FLAT}"),
        &[],
        &["missing field `speed_rpm`"],
    );
    bad(
        "missing radius",
        &format!("{}\n{FLAT}", CIRCLE.replace("radius = 2\n", "")),
        &[],
        &["needs `radius`", "m.toml:5:"],
    );
    bad(
        "missing follower",
        CIRCLE,
        &[],
        &["missing field `follower`"],
    );
    bad("missing pivot", &format!("{CIRCLE}[follower]\nkind = \"oscillating-roller\"\narm_length = 5\nroller_radius = 1\n"), &[], &["needs `pivot`"]);
    bad(
        "unknown top-level",
        &format!("{CIRCLE}{FLAT}[extra]\nx = 1\n"),
        &[],
        &["unknown field `extra`"],
    );
    bad(
        "unknown field",
        &format!("{CIRCLE}{FLAT}colour = \"red\"\n"),
        &[],
        &["unknown field `colour`"],
    );
    bad(
        "foreign field",
        &format!("{CIRCLE}points = [[0, 0]]\n{FLAT}"),
        &[],
        &["takes no `points`", "m.toml:8:"],
    );
    bad(
        "foreign follower field",
        &format!("{CIRCLE}{FLAT}roller_radius = 1\n"),
        &[],
        &["takes no `roller_radius`"],
    );
    bad(
        "unknown kind",
        &format!("{CIRCLE}[follower]\nkind = \"rocker\"\n"),
        &[],
        &["follower.kind = \"rocker\"", "m.toml:9:"],
    );
}

#[test]
fn wrong_types_and_non_finite_numbers() {
    bad(
        "string speed",
        &format!(
            "{}{FLAT}",
            CIRCLE.replace("speed_rpm = 100", "speed_rpm = \"fast\"")
        ),
        &[],
        &["line 3", "speed_rpm", "\"fast\""],
    );
    bad(
        "string radius",
        &format!("{}{FLAT}", CIRCLE.replace("radius = 2", "radius = \"big\"")),
        &[],
        &["line 7", "\"big\""],
    );
    bad(
        "point arity",
        &format!(
            "{}{FLAT}",
            CIRCLE.replace("center = [0.5, 0]", "center = [0.5]")
        ),
        &[],
        &["line 6"],
    );
    bad(
        "nan radius",
        &format!("{}{FLAT}", CIRCLE.replace("radius = 2", "radius = nan")),
        &[],
        &["cam.profile.radius = NaN", "m.toml:7:"],
    );
    bad(
        "inf speed",
        &format!(
            "{}{FLAT}",
            CIRCLE.replace("speed_rpm = 100", "speed_rpm = inf")
        ),
        &[],
        &["cam.speed_rpm = inf"],
    );
    bad(
        "inf pivot",
        &format!(
            "{}{FLAT}",
            CIRCLE.replace("speed_rpm = 100", "speed_rpm = 100\npivot = [0, -inf]")
        ),
        &[],
        &["cam.pivot = [0, -inf]"],
    );
    bad(
        "nan point",
        &format!("{SPLINE_HEAD}points = [[1, 0], [0, nan], [-1, 0]]\n{FLAT}"),
        &[],
        &["cam.profile.points[1]", "NaN"],
    );
    bad(
        "bad direction string",
        &format!(
            "{}{FLAT}",
            CIRCLE.replace("speed_rpm = 100", "speed_rpm = 100\ndirection = \"up\"")
        ),
        &[],
        &["unknown variant `up`"],
    );
}

#[test]
fn out_of_range_values() {
    bad(
        "zero speed",
        &format!(
            "{}{FLAT}",
            CIRCLE.replace("speed_rpm = 100", "speed_rpm = 0")
        ),
        &[],
        &["cam.speed_rpm = 0", "positive"],
    );
    bad(
        "negative radius",
        &format!("{}{FLAT}", CIRCLE.replace("radius = 2", "radius = -1")),
        &[],
        &["cam.profile.radius = -1", "positive"],
    );
    bad("zero semi-axis", &format!("length_unit = \"mm\"\n[cam]\nspeed_rpm = 1\n[cam.profile]\nkind = \"ellipse\"\ncenter = [0, 0]\nsemi_axes = [2, 0]\n{FLAT}"), &[], &["cam.profile.semi_axes = [2, 0]"]);
    bad(
        "zero direction",
        &format!("{CIRCLE}{FLAT}direction = [0, 0]\n"),
        &[],
        &["follower.direction = [0, 0]", "non-zero"],
    );
    bad(
        "negative roller",
        &format!("{CIRCLE}[follower]\nkind = \"translating-roller\"\nroller_radius = -0.5\n"),
        &[],
        &["follower.roller_radius = -0.5"],
    );
    bad("zero arm", &format!("{CIRCLE}[follower]\nkind = \"oscillating-roller\"\npivot = [0, 8]\narm_length = 0\nroller_radius = 1\n"), &[], &["follower.arm_length = 0"]);
}

#[test]
fn bad_points_inline_and_in_files() {
    bad(
        "two points",
        &format!("{SPLINE_HEAD}points = [[1, 0], [0, 1]]\n{FLAT}"),
        &[],
        &["at least 3 points, got 2"],
    );
    bad(
        "repeated",
        &format!("{SPLINE_HEAD}points = [[1, 0], [0, 1], [0, 1], [-1, 0]]\n{FLAT}"),
        &[],
        &["points 1 and 2 coincide at (0, 1)", "m.toml:6:"],
    );
    bad(
        "repeated across the seam",
        &format!("{SPLINE_HEAD}points = [[1, 0], [0, 1], [-1, 0], [1, 0]]\n{FLAT}"),
        &[],
        &["points 3 and 0 coincide"],
    );
    let pf = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"points-file\"\npath = \"p.csv\"\n[follower]\nkind = \"translating-flat\"\n";
    bad(
        "missing file",
        pf,
        &[],
        &["cam.profile.path = \"p.csv\"", "cannot read"],
    );
    bad(
        "malformed line",
        pf,
        &[("p.csv", "1,0\n0,1\nx,y,z\n-1,0\n")],
        &["p.csv:3:", "expected 2 numbers"],
    );
    bad(
        "non-number",
        pf,
        &[("p.csv", "1,0\n0,one\n-1,0\n")],
        &["p.csv:2:", "\"one\""],
    );
    bad(
        "repeated in file",
        pf,
        &[("p.csv", "# nodes\n1,0\n0,1\n0,1\n-1,0\n")],
        &["p.csv:4:", "points 1 and 2 coincide"],
    );
    bad(
        "too few in file",
        pf,
        &[("p.csv", "1,0\n0,1\n")],
        &["at least 3 points, got 2"],
    );
}

#[test]
fn self_intersecting_profile() {
    // a figure of eight
    let pts: Vec<String> = (0..12)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / 12.0;
            format!("[{}, {}]", 3.0 * t.sin(), 3.0 * t.sin() * t.cos())
        })
        .collect();
    bad(
        "figure of eight",
        &format!("{SPLINE_HEAD}points = [{}]\n{FLAT}", pts.join(", ")),
        &[],
        &["crosses itself near"],
    );
}

#[test]
fn cusped_profile() {
    // back and forth along a line: the tangent vanishes where the spline turns back
    bad(
        "cusp",
        &format!("{SPLINE_HEAD}points = [[0, 0], [2, 0], [0, 0], [-2, 0]]\n{FLAT}"),
        &[],
        &["cusp"],
    );
}

#[test]
fn follower_that_cannot_reach() {
    bad(
        "knife misses",
        &format!("{CIRCLE}[follower]\nkind = \"translating-knife\"\noffset = 3\n"),
        &[],
        &["follower.offset = 3", "misses the cam"],
    );
    bad(
        "roller passes",
        &format!(
            "{CIRCLE}[follower]\nkind = \"translating-roller\"\noffset = -4\nroller_radius = 1\n"
        ),
        &[],
        &["follower.offset = -4", "passes the cam"],
    );
    bad("arm too short", &format!("{CIRCLE}[follower]\nkind = \"oscillating-roller\"\npivot = [0, 10]\narm_length = 3\nroller_radius = 1\n"), &[], &["follower.arm_length = 3", "cannot reach", "(lengths in mm)"]);
    // a carried point: on an arm too short or too long, on the pivot, beside a slide's reach
    let arm = |at: &str| {
        format!("{CIRCLE}[follower]\nkind = \"rotating\"\npivot = [0, 10]\n[follower.profile]\nkind = \"point\"\nat = {at}\n")
    };
    bad(
        "point short of the cam",
        &arm("[3, 0]"),
        &[],
        &[
            "follower.profile.at = 3",
            "stays 7 from the cam axis; the cam reaches 2.5 (lengths in mm)",
        ],
    );
    bad(
        "point beyond the cam",
        &arm("[0, -20]"),
        &[],
        &["follower.profile.at = 20", "stays 10 from"],
    );
    bad(
        "point on the pivot",
        &arm("[0, 0]"),
        &[],
        &["follower.profile.at = [0, 0]", "off its pivot"],
    );
    bad(
        "point beside the slide",
        &format!("{CIRCLE}[follower]\nkind = \"translating\"\noffset = 1\n[follower.profile]\nkind = \"point\"\nat = [0, 2]\n"),
        &[],
        &["follower.offset = 1", "the point's line of travel, 3 from the cam axis, misses the cam, which reaches 2.5"],
    );
    bad(
        "point as a cam",
        "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"point\"\n[follower]\nkind = \"translating-flat\"\n",
        &[],
        &["cam.profile.kind", "a point can only be carried by a follower"],
    );
    bad(
        "point as a second curve",
        &format!("{CIRCLE}[follower]\nkind = \"translating-knife\"\n[follower.conjugate]\nkind = \"point\"\nat = [-5, 0]\n"),
        &[],
        &["follower.conjugate.kind", "cannot be a follower's second curve"],
    );
}

#[test]
fn huge_inputs_are_refused_quickly() {
    // 200 000 points in a points file (under its 16 MiB cap): refused at the points limit,
    // without building a spline through them
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::with_capacity(4 << 20);
    for i in 0..200_000 {
        let t = std::f64::consts::TAU * i as f64 / 2e5;
        text.push_str(&format!("{:.6},{:.6}\n", t.cos(), t.sin()));
    }
    assert!(text.len() < 16 << 20);
    std::fs::write(dir.path().join("big.csv"), &text).unwrap();
    let mech = dir.path().join("m.toml");
    std::fs::write(&mech, "length_unit = \"mm\"\n[cam]\nspeed_rpm = 1\n[cam.profile]\nkind = \"points-file\"\npath = \"big.csv\"\n[follower]\nkind = \"translating-flat\"\n").unwrap();
    run!("analyze", &mech, "--at", "0").refused("more than 100000 points");
}

#[test]
fn mechanism_file_size_limit_is_8_mib_exactly() {
    // a valid file padded with a comment to exactly 8 MiB is read; one byte more is refused
    let dir = tempfile::tempdir().unwrap();
    let head = format!("{CIRCLE}[follower]\nkind = \"translating-flat\"\n#");
    let limit = 8usize << 20;
    let mut text = head.clone();
    text.push_str(&"x".repeat(limit - head.len() - 1));
    text.push('\n');
    assert_eq!(text.len(), limit);
    let at_limit = dir.path().join("at.toml");
    std::fs::write(&at_limit, &text).unwrap();
    run!("analyze", &at_limit, "--at", "0").assert().success();
    text.insert(text.len() - 1, 'x');
    let over = dir.path().join("over.toml");
    std::fs::write(&over, &text).unwrap();
    run!("analyze", &over, "--at", "0").refused("more than 8388608 bytes (8 MiB)");
    // a device has no length in its metadata: the cap is counted while reading
    if std::path::Path::new("/dev/zero").exists() {
        run!("analyze", "/dev/zero", "--at", "0").refused("more than 8388608 bytes");
    }
}

#[test]
fn degenerate_geometry_is_reported_not_hidden() {
    let (_dir, mech) = written("peanut.toml", "length_unit = \"mm\"\n[cam]\nspeed_rpm = 1000\n[cam.profile]\nkind = \"spline\"\npoints = [[4.0, 0.0], [3.0, 2.4], [0.5, 1.1], [-2.0, 2.4], [-3.5, 0.1], [-2.2, -2.5], [0.6, -1.0], [3.1, -2.3]]\n[follower]\nkind = \"translating-flat\"\n");
    let a = run!("analyze", &mech, "--angles", "0:360:2")
        .assert()
        .success();
    let err = String::from_utf8(a.get_output().stderr.clone()).unwrap();
    assert!(err.contains("concave under the flat face"), "{err}");
    assert!(
        err.contains("the contact jumps between cam angles"),
        "{err}"
    );
    let out = String::from_utf8(a.get_output().stdout.clone()).unwrap();
    assert_eq!(
        out.lines().filter(|l| l.contains(",jump,")).count(),
        2,
        "{out}"
    );
    // a roller larger than the dents' radius of curvature
    let roller = mech.with_file_name("roller.toml");
    std::fs::write(
        &roller,
        std::fs::read_to_string(&mech).unwrap().replace(
            "kind = \"translating-flat\"",
            "kind = \"translating-roller\"\nroller_radius = 1.5",
        ),
    )
    .unwrap();
    run!("analyze", &roller, "--angles", "0:360:2")
        .assert()
        .success()
        .stderr(predicate::str::contains("more sharply than the roller"));
}

#[test]
fn bad_motion_profiles() {
    let head = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"motion\"\nbase_radius = 4\n";
    let foll = "[follower]\nkind = \"translating-flat\"\n";
    bad("unknown law", &format!("{head}segments = [{{ law = \"parabolic\", rise = 1, degrees = 180 }}, {{ law = \"dwell\", degrees = 180 }}]\n{foll}"), &[], &["law = \"parabolic\" is not a law", "cycloidal"]);
    bad(
        "not a revolution",
        &format!("{head}segments = [{{ law = \"dwell\", degrees = 300 }}]\n{foll}"),
        &[],
        &["cover 300", "not 360"],
    );
    bad(
        "not closed",
        &format!("{head}segments = [{{ law = \"cycloidal\", rise = 1, degrees = 360 }}]\n{foll}"),
        &[],
        &["does not return"],
    );
    bad(
        "foreign field",
        &format!("{head}radius = 3\nsegments = [{{ law = \"dwell\", degrees = 360 }}]\n{foll}"),
        &[],
        &["takes no `radius`"],
    );
    bad("no base radius", &format!("length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"motion\"\nsegments = [{{ law = \"dwell\", degrees = 360 }}]\n{foll}"), &[], &["needs `base_radius`"]);
}

/// Issue 12, class 1: data that was silently accepted. Every pair of the wrong length, in every
/// place a pair is read, is refused naming its line and value.
#[test]
fn pairs_of_the_wrong_length_are_refused_everywhere() {
    let dynamics = "[dynamics]\nmass = 1\nspring_stiffness = 100\nspring_preload = 10\n";
    let cases: Vec<(&str, String, &str)> = vec![
        ("direction of 3", format!("{CIRCLE}[follower]\nkind = \"translating-flat\"\ndirection = [1.0, 0.0, 7.0]\n"), "found 3 numbers: [1.0, 0.0, 7.0]"),
        ("direction of 1", format!("{CIRCLE}[follower]\nkind = \"translating-flat\"\ndirection = [1.0]\n"), "found 1 number: [1.0]"),
        ("empty direction", format!("{CIRCLE}[follower]\nkind = \"translating-flat\"\ndirection = []\n"), "found 0 numbers"),
        ("cam pivot", format!("{}{FLAT}", CIRCLE.replace("speed_rpm = 100\n", "speed_rpm = 100\npivot = [0, 0, 1]\n")), "found 3 numbers"),
        ("centre", format!("{}{FLAT}", CIRCLE.replace("center = [0.5, 0]", "center = [0.5, 0, 7]")), "[0.5, 0.0, 7.0]"),
        ("semi-axes", format!("length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"ellipse\"\ncenter = [0, 0]\nsemi_axes = [3, 2, 1]\n{FLAT}"), "found 3 numbers"),
        ("a spline point", format!("{SPLINE_HEAD}points = [[5.0, 0.0, 1.0], [0, 5], [-5, 0], [0, -5]]\n{FLAT}"), "point 1: expected a pair"),
        ("a later spline point", format!("{SPLINE_HEAD}points = [[5.0, 0.0], [0, 5], [-5], [0, -5]]\n{FLAT}"), "point 3: expected a pair"),
        ("arm pivot", format!("{CIRCLE}[follower]\nkind = \"oscillating-roller\"\npivot = [-3, 7, 0]\narm_length = 8\nroller_radius = 1\n"), "found 3 numbers"),
        ("gravity", format!("{CIRCLE}{FLAT}{dynamics}gravity = [0, -9.81, 0]\n"), "found 3 numbers"),
    ];
    for (name, toml, needle) in cases {
        bad(name, &toml, &[], &[needle, "m.toml:"]);
    }
}

/// Issue 12, class 1: a points-file row with an empty field, and motion segments whose law and
/// rise disagree.
#[test]
fn empty_fields_and_rises_that_do_not_fit_the_law_are_refused() {
    let pts = format!(
        "{}path = \"p.csv\"\n{FLAT}",
        SPLINE_HEAD.replace("\"spline\"", "\"points-file\"")
    );
    for (row, line) in [
        ("5.0,,0.0", "p.csv:2:"),
        ("5.0,0.0,", "p.csv:2:"),
        ("5.0;;0.0", "p.csv:2:"),
    ] {
        let csv = format!("4,0\n{row}\n0,4\n-4,0\n0,-4\n");
        bad(row, &pts, &[("p.csv", &csv)], &[line, "empty"]);
    }
    let motion = |segs: &str| {
        format!("length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"motion\"\nbase_radius = 40\nsegments = [{segs}]\n[follower]\nkind = \"translating-roller\"\nroller_radius = 5\n")
    };
    bad(
        "rise missing",
        &motion("{ law = \"cycloidal\", degrees = 180 }, { law = \"cycloidal\", rise = -1, degrees = 180 }"),
        &[],
        &["segments[0].rise = none", "needs a rise"],
    );
    bad(
        "rise zero",
        &motion("{ law = \"3-4-5\", rise = 0, degrees = 180 }, { law = \"dwell\", degrees = 180 }"),
        &[],
        &["segments[0].rise = 0", "dwell"],
    );
    bad(
        "dwell with a rise",
        &motion("{ law = \"dwell\", rise = 3, degrees = 360 }"),
        &[],
        &["segments[0].rise = 3", "a dwell has no rise"],
    );
}

/// Issue 12, class 2: speeds whose outputs would overflow or underflow are refused naming the
/// field as given and its value rounded for people; speeds inside the range give finite rows.
#[test]
fn extreme_speeds_are_refused_by_their_own_field() {
    for (rpm, needle) in [
        ("1e200", "cam.speed_rpm = 1e200: is too fast"),
        ("1e308", "cam.speed_rpm = 1e308: is too fast"),
        ("1.7e308", "cam.speed_rpm = 1.7e308: is too fast"),
        ("1e-300", "cam.speed_rpm = 1e-300: is too slow"),
        ("1e-140", "cam.speed_rpm = 1e-140: is too slow"),
    ] {
        bad(
            rpm,
            &format!(
                "{}{FLAT}",
                CIRCLE.replace("speed_rpm = 100", &format!("speed_rpm = {rpm}"))
            ),
            &[],
            &[needle],
        );
    }
    for rpm in ["1e60", "1e-60"] {
        let (_dir, mech) = written(
            "m.toml",
            format!(
                "{}{FLAT}",
                CIRCLE.replace("speed_rpm = 100", &format!("speed_rpm = {rpm}"))
            ),
        );
        let a = run!("analyze", &mech, "--angles", "0:360:7")
            .assert()
            .success();
        let out = String::from_utf8(a.get_output().stdout.clone()).unwrap();
        for line in out.lines().skip(1) {
            for v in line.split(',').take(5) {
                if let Ok(x) = v.parse::<f64>() {
                    assert!(x.is_finite(), "{rpm}: {line}");
                }
            }
            assert!(
                !line.contains("NaN") && !line.contains("inf"),
                "{rpm}: {line}"
            );
        }
    }
}

/// Issue 12, class 4: collinear spline points (a profile with no area) are refused up front, not
/// half the rows failing.
#[test]
fn a_profile_with_no_area_is_refused_up_front() {
    for pts in [
        "[[0, 0], [1, 0], [2, 0], [3, 0]]",
        "[[0, 0], [1, 1], [2, 2], [3, 3], [1.5, 1.5]]",
        "[[1e-9, 0], [2e-9, 0], [3e-9, 0]]",
    ] {
        bad(
            pts,
            &format!("{SPLINE_HEAD}points = {pts}\n{FLAT}"),
            &[],
            &["encloses no area", "collinear"],
        );
    }
}

/// Issue 12, class 2: lengths beyond the range the computation keeps its accuracy in (it squares
/// them) and arm angles beyond ±10 turns are refused by field, with the value; inside the
/// range (1e-100 … 1e100) the answers scale (see the library's scale property test).
#[test]
fn lengths_and_arm_angles_beyond_their_range_are_refused_by_field() {
    let roller = |r: &str| {
        format!("{CIRCLE}[follower]\nkind = \"translating-roller\"\nroller_radius = {r}\n")
    };
    let arm = |extra: &str| {
        format!(
            "{CIRCLE}[follower]\nkind = \"oscillating-roller\"\npivot = [-3, 7]\narm_length = 9\nroller_radius = 1\n{extra}\n"
        )
    };
    for (name, toml, needle) in [
        (
            "huge cam",
            CIRCLE.replace("radius = 2", "radius = 2e100") + FLAT,
            "cam.profile.radius = 2e100: must be from 1e-100 to 1e100",
        ),
        (
            "tiny cam",
            CIRCLE
                .replace("radius = 2", "radius = 2e-101")
                .replace("[0.5, 0]", "[0, 0]")
                + FLAT,
            "cam.profile.radius = 2e-101: must be from 1e-100 to 1e100",
        ),
        (
            "tiny roller",
            roller("1e-101"),
            "follower.roller_radius = 1e-101: must be from 1e-100 to 1e100",
        ),
        (
            "huge roller",
            roller("1e101"),
            "follower.roller_radius = 1e101",
        ),
        (
            "huge offset",
            roller("1").replace("roller_radius", "offset = 1e120\nroller_radius"),
            "follower.offset = 1e120: must be at most 1e100",
        ),
        (
            "far pivot",
            arm("").replace("[-3, 7]", "[-3, 1e101]"),
            "follower.pivot = [-3, 1e101]",
        ),
        (
            "initial angle",
            arm("initial_angle_deg = 1e300"),
            "follower.initial_angle_deg = 1e300: must be finite and within ±3600°",
        ),
        (
            "initial angle 4000",
            arm("initial_angle_deg = -4000"),
            "follower.initial_angle_deg = -4000",
        ),
    ] {
        bad(name, &toml, &[], &[needle]);
    }
}
