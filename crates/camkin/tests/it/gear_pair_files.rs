//! Issue 45: a gear pair in a gear engineer's words (`[gear_pair]`: teeth, module, pressure angle,
//! shifts, centre distance, backlash). It is read as the cam-follower mechanism the gear examples
//! spell out by hand — the same answers — and its errors name the `gear_pair` key written, at
//! its line.

use camkin::spec::text::{build_placed, parse_toml};
use camkin::spec::BuildOptions;
use std::f64::consts::TAU;

fn mechanism(text: &str) -> camkin::cam::Mechanism {
    let spec = parse_toml(text, "p.toml").unwrap();
    build_placed(&spec, text, "p.toml", &BuildOptions::default())
        .unwrap()
        .0
        .mechanism
}

fn error(text: &str) -> camkin::spec::text::TextError {
    match parse_toml(text, "p.toml") {
        Err(e) => e,
        Ok(spec) => build_placed(&spec, text, "p.toml", &BuildOptions::default())
            .map(|_| ())
            .unwrap_err(),
    }
}

const PAIR: &str =
    "length_unit = \"mm\"\n[gear_pair]\nteeth = [20, 42]\nmodule = 2.0\nspeed_rpm = 1000.0\n";

#[test]
fn a_gear_pair_is_the_hand_written_pair() {
    for (pair, by_hand) in [
        (PAIR.to_string(), "gear-pair-20-42.toml"),
        (
            format!("{PAIR}backlash = 0.02\n"),
            "gear-pair-backlash.toml",
        ),
    ] {
        let text = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../examples")
                .join(by_hand),
        )
        .unwrap()
        // the backlash example's [dynamics] is not part of the geometry compared
        .split("[dynamics]")
        .next()
        .unwrap()
        .to_string();
        let (a, b) = (mechanism(&pair), mechanism(&text));
        for k in 0..180 {
            let th = f64::from(k) * 0.2f64.to_radians();
            let (x, y) = (a.analyze(th).unwrap(), b.analyze(th).unwrap());
            assert!(
                (x.position - y.position).abs() <= 1e-12 * TAU,
                "{by_hand} at {k}"
            );
            assert!(
                (x.velocity - y.velocity).abs() <= 1e-12 * y.velocity.abs(),
                "{by_hand}"
            );
        }
        assert_eq!(a.conjugate_curve().is_some(), b.conjugate_curve().is_some());
    }
}

/// Shifted gears at their default centre distance, the tight mesh for the shifts: they turn at
/// the tooth ratio exactly (zero angular acceleration), at a distance above the standard one.
#[test]
fn shifted_gears_mesh_at_their_tight_distance_by_default() {
    let text = PAIR.replace(
        "module = 2.0\n",
        "module = 2.0\nprofile_shift = [0.3, 0.1]\n",
    );
    let m = mechanism(&text);
    let a = m.follower_joint().origin().x;
    assert!(a > 62.0 + 0.5 && a < 62.0 + 2.0 * 0.4, "{a}");
    let w = m.cam().speed();
    for k in 0..90 {
        let s = m.analyze(f64::from(k) * 0.2f64.to_radians()).unwrap();
        assert!(
            (s.velocity + 20.0 / 42.0 * w).abs() <= 1e-9 * w,
            "{k}: {}",
            s.velocity
        );
        assert!(
            s.acceleration.abs() <= 1e-7 * w * w,
            "{k}: {}",
            s.acceleration
        );
    }
}

#[test]
fn a_gear_pairs_errors_name_its_keys() {
    let line_of =
        |text: &str, needle: &str| text.lines().position(|l| l.contains(needle)).unwrap() + 1;
    for (what, text, needles, at) in [
        (
            "a gear of two teeth",
            PAIR.replace("[20, 42]", "[20, 2]"),
            vec!["gear_pair.teeth[1]", "2"],
            "teeth",
        ),
        (
            "a negative module",
            PAIR.replace("module = 2.0", "module = -2.0"),
            vec!["gear_pair.module", "-2"],
            "module",
        ),
        (
            "gears too close",
            format!("{PAIR}centre_distance = 58.0\n"),
            vec!["gear_pair.centre_distance", "58"],
            "centre_distance",
        ),
        (
            "a misspelled key",
            PAIR.replace("module", "modul"),
            vec!["modul"],
            "modul",
        ),
    ] {
        let e = error(&text);
        for n in needles {
            assert!(e.message.contains(n), "{what}: {}", e.message);
        }
        assert_eq!(
            e.at.map(|a| a.0),
            Some(line_of(&text, at)),
            "{what}: {}",
            e.message
        );
    }
}
