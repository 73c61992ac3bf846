//! `camkin plot`: figures, drawings and the animation are produced and well formed.
#![allow(clippy::unwrap_used)]
use crate::common::predicate;
use crate::common::*;
use std::path::Path;

fn png_size(p: &Path) -> (u32, u32) {
    let b = std::fs::read(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    assert_eq!(&b[..8], b"\x89PNG\r\n\x1a\n", "{}", p.display());
    (
        u32::from_be_bytes(b[16..20].try_into().unwrap()),
        u32::from_be_bytes(b[20..24].try_into().unwrap()),
    )
}

/// Every element opened is closed, in order (a small well-formedness check).
fn assert_well_formed_svg(p: &Path) -> String {
    let s = std::fs::read_to_string(p).unwrap();
    let mut stack: Vec<String> = Vec::new();
    let mut rest = s.as_str();
    while let Some(i) = rest.find('<') {
        let j = rest[i..]
            .find('>')
            .unwrap_or_else(|| panic!("{}: unclosed tag", p.display()))
            + i;
        let tag = &rest[i + 1..j];
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop().as_deref(), Some(name.trim()), "{}", p.display());
        } else if !tag.ends_with('/') && !tag.starts_with('?') && !tag.starts_with('!') {
            stack.push(tag.split_whitespace().next().unwrap().to_string());
        }
        rest = &rest[j + 1..];
    }
    assert!(stack.is_empty(), "{}: unclosed {stack:?}", p.display());
    assert!(s.trim_start().starts_with("<svg"));
    s
}

#[test]
fn plot_every_follower_type() {
    for name in [
        "paper",
        "eccentric-roller",
        "ellipse-knife",
        "oscillating-flat",
        "oscillating-roller",
    ] {
        let dir = tempfile::tempdir().unwrap();
        run!(
            "plot",
            examples().join(format!("{name}.toml")),
            "--step",
            "2",
            "--frames",
            "12",
            "--at",
            "0,45",
            "--out",
            dir.path()
        )
        .assert()
        .success();
        let d = dir.path();
        assert_eq!(png_size(&d.join("kinematics.png")), (1400, 1300));
        let k = assert_well_formed_svg(&d.join("kinematics.svg"));
        for title in [
            "lift (",
            "velocity (",
            "acceleration",
            "jerk",
            "pressure angle",
            "radius of curvature",
        ] {
            assert!(k.contains(title), "{name}: {title}");
        }
        // the SVAJ page: four panels, each axis with its unit, peaks annotated
        assert_eq!(png_size(&d.join("svaj.png")), (1200, 1500));
        let svaj = assert_well_formed_svg(&d.join("svaj.svg"));
        let (len, coord) = match name {
            "oscillating-flat" | "oscillating-roller" => ("cm", "°"),
            _ => ("cm", "cm"),
        };
        for label in [
            format!("lift ({coord})"),
            format!("velocity ({coord}/s)"),
            format!("acceleration ({coord}/s²)"),
            format!("jerk ({coord}/s³)"),
            "cam angle (°)".into(),
            "max ".into(),
            "rpm".into(),
        ] {
            assert!(svaj.contains(&label), "{name}: {label}");
        }
        assert!(
            k.contains(&format!("radius of curvature ({len})")),
            "{name}"
        );
        assert!(!svaj.contains("e-1"), "{name}: a tick of rounding noise");
        for a in ["0", "45"] {
            let (w, h) = png_size(&d.join(format!("drawing_{a}.png")));
            assert_eq!(w, 800);
            assert!(h > 200);
            assert!(assert_well_formed_svg(&d.join(format!("drawing_{a}.svg")))
                .contains(&format!("cam angle {a}°")));
        }
        let anim = assert_well_formed_svg(&d.join("animation.svg"));
        assert_eq!(anim.matches("<animate ").count(), 12, "{name}");
        assert!(anim.contains("repeatCount=\"indefinite\""));
    }
}

#[test]
fn plot_defaults_to_the_paper_cam() {
    let dir = tempfile::tempdir().unwrap();
    run!("plot", "--step", "5", "--frames", "4", "--out", dir.path())
        .assert()
        .success()
        .stderr(predicate::str::contains("paper"));
    // four default drawings, kinematics (2), the SVAJ page (2), animation, and the list of
    // the files camkin wrote there
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 14);
    assert!(dir.path().join(".camkin-results").exists());
}

#[test]
fn plot_bad_input_exits_2() {
    for (args, needle) in [
        (vec!["--at", "x"], "--at"),
        (vec!["--frames", "0"], "--frames"),
        (vec!["--step", "0"], "--step"),
    ] {
        let dir = tempfile::tempdir().unwrap();
        run!("plot")
            .args(&args)
            .arg("--out")
            .arg(dir.path())
            .refused(needle);
    }
}

/// Regression (issue 12): `plot --at 0,0.5` wrote one drawing (`drawing_0.svg` held the 0.5° one:
/// `.5` was taken for an extension), and `--at 1e300` would name a file with 301 digits.
#[test]
fn drawings_are_named_by_their_whole_angle_modulo_360() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("p");
    run!(
        "plot",
        "--frames",
        "2",
        "--at",
        "0,0.5,1e300,280,1e20",
        "--out",
        &out
    )
    .assert()
    .success();
    let mut names: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with("drawing_"))
        .collect();
    names.sort();
    // 1e300 ≡ 0 and 1e20 ≡ 280 (mod 360): the same drawings as 0° and 280°
    assert_eq!(
        names,
        [
            "drawing_0.5.png",
            "drawing_0.5.svg",
            "drawing_0.png",
            "drawing_0.svg",
            "drawing_280.png",
            "drawing_280.svg"
        ]
    );
    let half = std::fs::read_to_string(out.join("drawing_0.5.svg")).unwrap();
    assert!(
        half.contains("cam angle 0.5°"),
        "the 0.5° drawing is the 0.5° one"
    );
}

/// Issue 49: a drawing says it is to scale and in which unit, has a scale bar with its length and
/// a legend of what is drawn (the cam's sense of rotation among it).
#[test]
fn drawings_carry_their_scale_and_legend() {
    let dir = tempfile::tempdir().unwrap();
    run!(
        "plot",
        examples().join("paper.toml"),
        "--at",
        "30",
        "--frames",
        "4",
        "--out",
        dir.path().join("p")
    )
    .assert()
    .success();
    let svg = std::fs::read_to_string(dir.path().join("p").join("drawing_30.svg")).unwrap();
    assert!(svg.contains("to scale, lengths in cm"), "no unit");
    assert!(svg.contains("sense of rotation"), "no legend");
    assert!(svg.contains("\n2 cm\n</text>"), "no scale bar label");
}
