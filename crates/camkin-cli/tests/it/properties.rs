//! Property tests of the mechanism-file parser over random valid and invalid mechanisms: parsing
//! never panics, a valid file builds a mechanism whose analysis gives finite numbers or a typed
//! error, and every rejection says where (file:line:column or the missing field).
#![allow(clippy::unwrap_used)]
use camkin_cli::mechfile::parse;
use proptest::prelude::*;
use std::path::Path;

fn profile() -> impl Strategy<Value = String> {
    prop_oneof![
        (1.0f64..5.0, -1.0f64..1.0).prop_map(|(r, e)| format!("kind = \"circle\"\ncenter = [{e}, 0.0]\nradius = {r}\n")),
        (2.0f64..5.0, 1.0f64..2.0, -90.0f64..90.0).prop_map(|(a, b, rot)| format!("kind = \"ellipse\"\ncenter = [0.2, 0.1]\nsemi_axes = [{a}, {b}]\nrotation_deg = {rot}\n")),
        (5usize..14, prop::collection::vec(-0.2f64..0.2, 14)).prop_map(|(n, j)| {
            let pts: Vec<String> = (0..n)
                .map(|i| {
                    let t = std::f64::consts::TAU * i as f64 / n as f64;
                    let r = 3.0 + j[i];
                    format!("[{}, {}]", r * t.cos(), r * t.sin())
                })
                .collect();
            format!("kind = \"spline\"\npoints = [{}]\n", pts.join(", "))
        }),
    ]
}

fn follower() -> impl Strategy<Value = String> {
    prop_oneof![
        (0.0f64..6.3).prop_map(|a| format!("kind = \"translating-flat\"\ndirection = [{}, {}]\n", a.cos(), a.sin())),
        (0.0f64..6.3, -1.0f64..1.0, 0.2f64..2.0).prop_map(|(a, e, r)| format!("kind = \"translating-roller\"\ndirection = [{}, {}]\noffset = {e}\nroller_radius = {r}\n", a.cos(), a.sin())),
        (0.0f64..6.3, -0.8f64..0.8).prop_map(|(a, e)| format!("kind = \"translating-knife\"\ndirection = [{}, {}]\noffset = {e}\n", a.cos(), a.sin())),
        (-0.5f64..0.5).prop_map(|e| format!("kind = \"oscillating-flat\"\npivot = [-3.0, 7.0]\noffset = {e}\nclosing = \"cw\"\ninitial_angle_deg = -30.0\n")),
        (0.5f64..1.5).prop_map(|r| format!("kind = \"oscillating-roller\"\npivot = [-3.0, 7.0]\narm_length = 9.0\nroller_radius = {r}\nclosing = \"cw\"\ninitial_angle_deg = -30.0\n")),
    ]
}

fn mechanism() -> impl Strategy<Value = String> {
    (1.0f64..5000.0, any::<bool>(), profile(), follower()).prop_map(|(rpm, ccw, p, f)| {
        format!(
            "length_unit = \"mm\"\n[cam]\nspeed_rpm = {rpm}\ndirection = \"{}\"\n\n[cam.profile]\n{p}\n[follower]\n{f}",
            if ccw { "ccw" } else { "cw" }
        )
    })
}

/// A random edit of a valid file: a line dropped, a value replaced, a field added, a kind changed.
fn mutate(text: &str, what: usize, at: usize, token: &str) -> String {
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let k = at % lines.len();
    match what % 4 {
        0 => {
            lines.remove(k);
        }
        1 => {
            if let Some(eq) = lines[k].find('=') {
                lines[k] = format!("{}= {token}", &lines[k][..eq]);
            }
        }
        2 => lines.insert(k, format!("extra_field = {token}")),
        _ => {
            if let Some(l) = lines.iter_mut().find(|l| l.starts_with("kind")) {
                *l = format!("kind = \"{token}\"");
            }
        }
    }
    lines.join("\n")
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    #[test]
    fn valid_mechanisms_parse_and_analyse(text in mechanism(), theta in 0.0f64..6.3) {
        let m = parse(&text, "m.toml", Path::new("."));
        prop_assert!(m.is_ok(), "{}\n{}", text, m.err().map(|e| e.message).unwrap_or_default());
        let m = m.unwrap();
        match m.analyze(theta) {
            Ok(s) => prop_assert!(s.position.is_finite() && s.velocity.is_finite() && s.acceleration.is_finite()),
            // a generated follower may miss a generated cam: that is geometry, said as such; a
            // numerical failure of the solver is not acceptable here
            Err(e) => prop_assert!(
                matches!(e, camkin::cam::CamError::NoTouch { .. } | camkin::cam::CamError::Unreachable { .. }),
                "{text}\n{e:?}"
            ),
        }
    }

    #[test]
    fn invalid_mechanisms_are_rejected_with_a_place(
        text in mechanism(),
        what in 0usize..4,
        at in 0usize..40,
        token in prop_oneof![Just("nan"), Just("-1"), Just("0"), Just("1e400"), Just("\"x\""), Just("[0, 0]"), Just("[]"), Just("inf"), Just("blob"), Just("1e-320")],
    ) {
        let bad = mutate(&text, what, at, token);
        match parse(&bad, "m.toml", Path::new(".")) {
            Ok(m) => {
                // some edits leave a valid file; it must still analyse without panicking
                let _ = m.analyze(0.3);
            }
            Err(e) => {
                let msg = e.message;
                prop_assert!(msg.starts_with("m.toml:") || msg.contains("m.toml: TOML parse error"), "{msg}");
                prop_assert!(msg.len() < 2000);
            }
        }
    }

    /// Issue 12, class 1: a pair of any length but two (`direction`, `pivot`, `center`,
    /// `semi_axes`, a spline point, `gravity`) is refused, naming the field, never read as its
    /// first two numbers.
    #[test]
    fn pairs_of_any_other_length_are_refused_naming_the_field(
        which in 0usize..6,
        values in prop::collection::vec(-5.0f64..5.0, 0..7),
    ) {
        prop_assume!(values.len() != 2);
        let list = format!("[{}]", values.iter().map(|v| format!("{v:.3}")).collect::<Vec<_>>().join(", "));
        let circle = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"circle\"\ncenter = [0.5, 0]\nradius = 2\n";
        let (text, field) = match which {
            0 => (format!("{circle}[follower]\nkind = \"translating-flat\"\ndirection = {list}\n"), "follower.direction"),
            1 => (format!("{circle}[follower]\nkind = \"oscillating-flat\"\npivot = {list}\n"), "follower.pivot"),
            2 => (format!("{}[follower]\nkind = \"translating-flat\"\n", circle.replace("[0.5, 0]", &list)), "cam.profile.center"),
            3 => (format!("length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"ellipse\"\ncenter = [0, 0]\nsemi_axes = {list}\n[follower]\nkind = \"translating-flat\"\n"), "cam.profile.semi_axes"),
            4 => (format!("length_unit = \"mm\"\n[cam]\nspeed_rpm = 100\n[cam.profile]\nkind = \"spline\"\npoints = [[3, 0], [0, 3], {list}, [0, -3]]\n[follower]\nkind = \"translating-flat\"\n"), "cam.profile.points"),
            _ => (format!("{circle}[follower]\nkind = \"translating-flat\"\n[dynamics]\nmass = 1\nspring_stiffness = 100\nspring_preload = 10\ngravity = {list}\n"), "dynamics.gravity"),
        };
        let err = parse(&text, "m.toml", Path::new(".")).err();
        let msg = err.map(|e| e.message);
        prop_assert!(msg.as_ref().is_some_and(|m| m.contains(field) && m.starts_with("m.toml:")), "{text}\n{msg:?}");
    }

    /// Issue 12, class 2: any magnitude of speed (1e-300 … 1e300 rpm) and of every length
    /// (1e-150 … 1e150) is either computed, with finite numbers, or refused naming its field.
    #[test]
    fn any_magnitude_is_computed_finite_or_refused_by_field(
        speed_exp in -300.0f64..300.0,
        length_exp in -150.0f64..150.0,
        theta in 0.0f64..6.3,
        roller in any::<bool>(),
    ) {
        let (w, k) = (10f64.powf(speed_exp), 10f64.powf(length_exp));
        let follower = if roller {
            format!("kind = \"translating-roller\"\ndirection = [0, 1]\noffset = {:e}\nroller_radius = {:e}\n", 0.3 * k, 0.8 * k)
        } else {
            "kind = \"translating-flat\"\n".to_string()
        };
        let text = format!(
            "length_unit = \"mm\"\n[cam]\nspeed_rpm = {w:e}\n[cam.profile]\nkind = \"circle\"\ncenter = [{:e}, 0]\nradius = {:e}\n[follower]\n{follower}",
            0.5 * k,
            2.0 * k
        );
        match parse(&text, "m.toml", Path::new(".")) {
            Ok(m) => {
                let s = m.analyze(theta);
                prop_assert!(s.is_ok(), "{text}\n{:?}", s.err());
                let s = s.unwrap();
                prop_assert!(s.position.is_finite() && s.velocity.is_finite() && s.acceleration.is_finite() && s.jerk.is_none_or(f64::is_finite), "{text}\n{s:?}");
                // and scaled: the flat face's position is R + e cos θ
                if !roller {
                    prop_assert!((s.position / k - (2.0 + 0.5 * theta.cos())).abs() < 1e-12, "{text}\n{s:?}");
                }
            }
            Err(e) => {
                let msg = e.message;
                prop_assert!(
                    msg.starts_with("m.toml:") && (msg.contains("cam.speed_rpm") || msg.contains("cam.profile") || msg.contains("follower.")),
                    "{text}\n{msg}"
                );
            }
        }
    }
}
