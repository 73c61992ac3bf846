//! Issue 48, item 1 for the multibody systems: a system file's `[lubrication]` gives each
//! closed contact with a face width its entrainment, sliding, film, λ and flash temperature at
//! every sample of its simulation. Checked against the closed forms of an eccentric disc (radius
//! R, eccentricity e, turning at ω) under a flat face sliding on a slide: along the face, the
//! disc's material passes the contact at `ωR` and the face's at `−eω cos θ` — sharing nothing
//! with the report's route (the contact's sliding rates at the simulated state).
#![allow(clippy::unwrap_used)]
use crate::common::read_system;
use camkin::dynamics::SystemSimulation;
use camkin::report::SystemLubricationReport;
use camkin::spec::BuildOptions;

const DISC: &str = r#"length_unit = "mm"
[dynamics]

[[body]]
name = "cam"
mass = 1.0
inertia = 1.0

[[body]]
name = "slider"
mass = 0.3
inertia = 1.0

[[joint]]
name = "bearing"
kind = "revolute"
bodies = ["ground", "cam"]

[[joint]]
name = "slide"
kind = "prismatic"
bodies = ["ground", "slider"]
at = [[0.0, 0.0], [0.0, 0.0]]
axis = [1.0, 0.0]

[[driver]]
name = "motor"
body = "cam"
coordinate = "angle"
speed_rpm = 300.0

[[contact]]
name = "disc on face"
bodies = ["cam", "slider"]
curve_a = { kind = "circle", center = [10.0, 0.0], radius = 40.0 }
curve_b = { kind = "line", anchor = [50.0, 0.0], direction = [0.0, -1.0] }
face_width = 10.0
ROLLS

[[spring]]
name = "spring"
bodies = ["ground", "slider"]
at = [[1000.0, 0.0], [0.0, 0.0]]
stiffness = 2.0
free_length = 1030.0
preload = 0.0

[lubrication]
oil = "sae-30@100c"
roughness_um = [0.2, 0.3]
"#;

fn simulate(text: &str) -> (camkin::spec::BuiltSystem, camkin::dynamics::SystemRun) {
    let built = read_system(text, "disc.toml", &BuildOptions::default()).unwrap();
    let mut sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
    // a revolution at 300 rpm (0.2 s) in 2° steps
    let h_out = 0.2 / 180.0;
    let run = sim
        .run(180, h_out, |_| std::ops::ControlFlow::Continue(()))
        .unwrap();
    (built, run)
}

#[test]
fn an_eccentric_disc_under_a_flat_face_against_its_closed_forms() {
    let (built, run) = simulate(&DISC.replace("ROLLS", ""));
    let w = 300.0 * std::f64::consts::TAU / 60.0;
    let (r, e): (f64, f64) = (0.040, 0.010);
    let req = built.lubrication.as_ref().unwrap();
    let rep = SystemLubricationReport::new(&built.system, &run, req, |t| w * t.to_degrees());
    assert_eq!(rep.contacts.len(), 1);
    let c = &rep.contacts[0];
    let sigma = (0.2f64.powi(2) + 0.3f64.powi(2)).sqrt() * 1e-6;
    assert!((c.composite_roughness - sigma).abs() < 1e-18);
    // the sign of A's tangent along the face: the first sample's
    let first = c.points[0].unwrap();
    let s = first.entrainment.signum() * (r - e).signum();
    let mut n = 0;
    for (k, p) in c.points.iter().enumerate() {
        let p = p.expect("the disc holds the face all the revolution");
        let th = w * run.samples[k].time;
        let (ua, ub) = (s * w * r, -s * e * w * th.cos());
        let scale = w * r;
        assert!(
            (p.entrainment - 0.5 * (ua + ub)).abs() < 1e-12 * scale,
            "{k}: {p:?}"
        );
        assert!((p.sliding - (ua - ub)).abs() < 1e-12 * scale, "{k}: {p:?}");
        // a disc on a flat: the reduced radius is the disc's
        assert!((p.reduced_radius.unwrap() - r).abs() < 1e-12 * r);
        assert!((p.lambda.unwrap() - p.film.unwrap().minimum / sigma).abs() < 1e-12);
        // the load per width is the sample's force over 10 mm
        let f = run.samples[k].contact_forces[0];
        assert!((p.load_per_width - f / 0.010).abs() < 1e-9 * f / 0.010);
        n += 1;
    }
    assert_eq!(n, 181);
    // the entrainment (ωR − eω cos θ)/2 never reverses with R > e
    assert!(c.entrainment_reversals_deg.is_empty());
    // its sliding never stops: friction dissipates all the revolution
    assert!(c.mean_friction_power > 0.0);
    let (names, rows) = rep.table();
    assert_eq!(names[0], "driver_angle_deg");
    assert_eq!(rows.len(), 181);
}

/// A disc rolling on the face (`rolls = "a"`: the disc is a roller on its pin) has nothing
/// sliding and the face's speed twice over; a face larger than the disc's eccentricity makes the
/// entrainment reverse twice a revolution (where `e cos θ = R`, with `e > R`: a disc of radius
/// 5 mm 10 mm off the axis).
#[test]
fn a_roller_rolls_and_an_entrainment_that_reverses_is_found_between_samples() {
    let (built, run) = simulate(&DISC.replace("ROLLS", "rolls = \"a\""));
    let w = 300.0 * std::f64::consts::TAU / 60.0;
    let req = built.lubrication.as_ref().unwrap();
    let rep = SystemLubricationReport::new(&built.system, &run, req, |t| w * t.to_degrees());
    let e = 0.010;
    for (k, p) in rep.contacts[0].points.iter().enumerate() {
        let p = p.expect("the disc holds the face all the revolution");
        assert_eq!(p.sliding, 0.0);
        // the entrainment is the face's surface speed past the contact, −eω cos θ, value by
        // value (the roller's own ωR would be 0.4/0.1 = 4 times the largest)
        let th = w * run.samples[k].time;
        let face = e * w * th.cos();
        assert!(
            (p.entrainment.abs() - face.abs()).abs() < 1e-12 * w * e,
            "{k}: {} vs {face}",
            p.entrainment
        );
    }
    assert_eq!(rep.contacts[0].mean_friction_power, 0.0);
    // a roller on the follower (`rolls = "b"`, radius 10 mm on the slider, its centre on the
    // slide's line through the axis) rolling on the disc: the entrainment is the disc's surface
    // speed past the contact point, R (ω − ψ̇), ψ the common normal's angle, here
    // ψ = −asin(e sin θ / (R + r)): R ω (1 + e cos θ / √((R + r)² − e² sin² θ)) (the roller's
    // own material speed would be the slider's, at most eω)
    let roller = DISC.replace("ROLLS", "rolls = \"b\"").replace(
        "curve_b = { kind = \"line\", anchor = [50.0, 0.0], direction = [0.0, -1.0] }",
        "curve_b = { kind = \"circle\", center = [60.0, 0.0], radius = 10.0 }",
    );
    let (built, run) = simulate(&roller);
    let rep = SystemLubricationReport::new(
        &built.system,
        &run,
        built.lubrication.as_ref().unwrap(),
        |t| w * t.to_degrees(),
    );
    let (r, reach) = (0.040, 0.050);
    for (k, p) in rep.contacts[0].points.iter().enumerate() {
        let p = p.expect("the roller holds the disc all the revolution");
        let th = w * run.samples[k].time;
        let disc = r * w * (1.0 + e * th.cos() / (reach * reach - (e * th.sin()).powi(2)).sqrt());
        assert!(
            (p.entrainment.abs() - disc).abs() < 1e-9 * disc,
            "{k}: {} vs {disc}",
            p.entrainment
        );
        assert_eq!(p.sliding, 0.0);
    }
    // the disc smaller than its eccentricity: its surface passes at ωR, the face's at −eω cos θ
    let small = DISC
        .replace("ROLLS", "")
        .replace(
            "center = [10.0, 0.0], radius = 40.0",
            "center = [10.0, 0.0], radius = 5.0",
        )
        .replace("anchor = [50.0, 0.0]", "anchor = [15.0, 0.0]");
    let (built, run) = simulate(&small);
    let rep = SystemLubricationReport::new(
        &built.system,
        &run,
        built.lubrication.as_ref().unwrap(),
        |t| w * t.to_degrees(),
    );
    let rev = &rep.contacts[0].entrainment_reversals_deg;
    // ωR = eω cos θ at cos θ = 1/2: 60° and 300°, to the 2° samples' linear interpolation
    assert_eq!(rev.len(), 2, "{rev:?}");
    for (got, want) in rev.iter().zip([60.0, 300.0]) {
        assert!((got - want).abs() < 0.1, "{rev:?}");
    }
}

#[test]
fn bad_lubrication_in_a_system_file_names_its_key() {
    let base = DISC.replace("ROLLS", "");
    for (text, key) in [
        (DISC.replace("ROLLS", "rolls = \"b\""), "contact[0].rolls"),
        (DISC.replace("ROLLS", "rolls = \"c\""), "contact[0].rolls"),
        (
            DISC.replace("ROLLS", "roughness_um = [0.0, 0.2]"),
            "contact[0].roughness_um[0]",
        ),
        (base.replace("sae-30@100c", "sae-99"), "lubrication.oil"),
        (
            base.replace("roughness_um = [0.2, 0.3]\n", ""),
            "contact[0].face_width",
        ),
        (
            base.replace(
                "[lubrication]\noil = \"sae-30@100c\"\nroughness_um = [0.2, 0.3]\n",
                "",
            )
            .replace("face_width = 10.0\n", "face_width = 10.0\nrolls = \"a\"\n"),
            "contact[0].rolls",
        ),
        (
            base.replace("face_width = 10.0\n", "roughness_um = [0.2, 0.2]\n"),
            "contact[0].roughness_um",
        ),
        (base.replace("[dynamics]\n", ""), "lubrication"),
        (
            base.replace(
                "roughness_um = [0.2, 0.3]\n",
                "roughness_um = [0.2, 0.3]\nface_width = 3.0\n",
            ),
            "face_width",
        ),
    ] {
        let e = read_system(&text, "disc.toml", &BuildOptions::default())
            .err()
            .unwrap_or_else(|| panic!("accepted: {key}"))
            .to_string();
        assert!(e.contains(key), "{key}: {e}");
    }
}
