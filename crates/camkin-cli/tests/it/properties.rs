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
            "[cam]\nspeed_rpm = {rpm}\ndirection = \"{}\"\n\n[cam.profile]\n{p}\n[follower]\n{f}",
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
}
