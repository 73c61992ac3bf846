//! Cams of arcs and lines from the command line: the joins reported with their radii, a bad
//! piece refused at its place.
use crate::common::predicate;
use crate::common::*;

/// `camkin profile` on the tangent cam lists its four tangent joins with the radius of
/// curvature either side (20 mm base, 7 mm nose, ∞ on the flanks).
#[test]
fn the_tangent_cams_joins_are_reported_with_their_radii() {
    let dir = tempfile::tempdir().unwrap();
    let out = run!(
        "profile",
        examples().join("tangent-cam.toml"),
        "--out",
        dir.path().join("shop")
    )
    .stdout_ok();
    let text = String::from_utf8(out).unwrap();
    let joins: Vec<&str> = text.lines().filter(|l| l.starts_with("  at (")).collect();
    assert_eq!(joins.len(), 4, "{text}");
    assert!(joins.iter().all(|l| l.ends_with("tangent")), "{text}");
    assert!(
        text.contains("radius 20 mm before, ∞ (a line) after"),
        "{text}"
    );
    assert!(
        text.contains("radius ∞ (a line) before, 7 mm after"),
        "{text}"
    );
}

#[test]
fn a_chain_that_does_not_close_is_refused_at_its_last_piece() {
    let (_dir, file) = written("open.toml", "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100.0\n[cam.profile]\nkind = \"arcs-and-lines\"\nstart = [20.0, 0.0]\npieces = [\n  { to = [-20.0, 0.0], centre = [0.0, 0.0] },\n  { to = [19.0, 0.0] },\n]\n[follower]\nkind = \"translating-flat\"\ndirection = [1.0, 0.0]\n");
    run!("analyze", &file)
        .refused("open.toml:9:")
        .stderr(predicate::str::contains("cam.profile.pieces[1].to"))
        .stderr(predicate::str::contains("does not close"));
}

/// A chain that crosses itself is refused at the later piece, naming the earlier one and the
/// point, in the file's unit: a bow tie whose diagonals cross at the origin, and a line that
/// cuts back through a 270° arc of radius 20 at `t = 10/13` of its way from (0, −20) to
/// (10, 30), i.e. at (100/13, 240/13) = (7.69231, 18.4615) (a regression: a figure of eight was
/// accepted and 17 of 36 angles then failed).
#[test]
fn a_chain_that_crosses_itself_is_refused_where_it_crosses() {
    let head = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100.0\n[cam.profile]\nkind = \"arcs-and-lines\"\n";
    let tail = "[follower]\nkind = \"translating-flat\"\ndirection = [0.0, 1.0]\n";
    let bow = format!("{head}start = [-10.0, -10.0]\npieces = [\n  {{ to = [20.0, 20.0] }},\n  {{ to = [20.0, -20.0] }},\n  {{ to = [-10.0, 10.0] }},\n  {{ to = [-10.0, -10.0] }},\n]\n{tail}");
    let (_dir, file) = written("bow.toml", &bow);
    run!("analyze", &file, "--at", "0")
        .refused("bow.toml:10:")
        .stderr(predicate::str::contains("cam.profile.pieces[2].to"))
        .stderr(predicate::str::contains("meets pieces[0] at [0, 0]"))
        .stderr(predicate::str::contains("crosses or overlaps itself"));
    let cut = format!("{head}start = [20.0, 0.0]\npieces = [\n  {{ to = [0.0, -20.0], centre = [0.0, 0.0] }},\n  {{ to = [10.0, 30.0] }},\n  {{ to = [20.0, 0.0] }},\n]\n{tail}");
    let (_dir, file) = written("cut.toml", &cut);
    run!("analyze", &file, "--at", "0")
        .refused("cut.toml:9:")
        .stderr(predicate::str::contains("cam.profile.pieces[1].to"))
        .stderr(predicate::str::contains(
            "meets pieces[0] at [7.69231, 18.4615]",
        ));
    // the same outline without the cut (a D: a half circle and its chord) is a cam
    let d = format!("{head}start = [20.0, 0.0]\npieces = [\n  {{ to = [-20.0, 0.0], centre = [0.0, 0.0] }},\n  {{ to = [20.0, 0.0] }},\n]\n{tail}");
    let (_dir, file) = written("d.toml", &d);
    run!("analyze", &file, "--at", "0").assert().success();
}
