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
