//! Loads along a gear pair's whole path of contact (issue 48, item 3) against closed forms that
//! share nothing with the report: the normal force `T/r_b`, its equal share where two pairs are in
//! contact, Hertz at the pitch point from the cylinder formula with the pitch radii, and the
//! specific sliding against the exact kinematics' (`camkin mesh`'s) wherever one pair carries.
#![allow(clippy::unwrap_used)]
use camkin::gears::GearPair;
use camkin::report::{GearLoadRequest, GearLoads, Materials};
use camkin::spec::text::{build_placed, parse_toml};
use camkin::spec::BuildOptions;
use std::f64::consts::PI;

fn pair(text: &str) -> (camkin::cam::Mechanism, GearPair) {
    let spec = parse_toml(text, "p.toml").unwrap();
    // in SI units, as the force reports are
    let options = BuildOptions {
        si: true,
        ..BuildOptions::default()
    };
    let m = build_placed(&spec, text, "p.toml", &options)
        .unwrap()
        .0
        .mechanism;
    let p = GearPair::new(&m).unwrap();
    (m, p)
}

const PAIR: &str =
    "length_unit = \"mm\"\n[gear_pair]\nteeth = [20, 42]\nmodule = 2.0\nspeed_rpm = 1000.0\n";

#[test]
fn the_normal_force_is_the_torque_over_the_base_radius_shared_equally() {
    let (m, p) = pair(PAIR);
    let req = GearLoadRequest {
        torque: 50.0,
        face_width: 0.020,
        materials: Materials::default(),
        lubrication: None,
        points: 401,
    };
    let l = GearLoads::new(&p, m.cam().speed(), &req).unwrap();
    let rb1 = 0.020 * (20f64).to_radians().cos();
    assert!((l.normal_force - 50.0 / rb1).abs() < 1e-13 * l.normal_force);
    // the contact ratio of the 20/42 pair: single contact in the middle of the path only
    let eps = (l.path[1] - l.path[0]) / l.base_pitch;
    assert!(eps > 1.5 && eps < 1.7, "{eps}");
    let (mut one, mut two) = (0, 0);
    for q in &l.points {
        // a second pair a base pitch before or after, on the path
        let second =
            q.roll + l.base_pitch <= l.path[1] + 1e-9 || q.roll - l.base_pitch >= l.path[0] - 1e-9;
        if second {
            assert_eq!(q.pairs, 2);
            assert!((q.load - l.normal_force / 2.0).abs() < 1e-13 * l.normal_force);
            two += 1;
        } else {
            assert_eq!(q.pairs, 1);
            assert_eq!(q.load, l.normal_force);
            one += 1;
        }
    }
    // the single-pair zone is (2 − ε) base pitches of the path's ε
    let share = one as f64 / (one + two) as f64;
    assert!(
        (share - (2.0 - eps) / eps).abs() < 0.01,
        "{share} vs {}",
        (2.0 - eps) / eps
    );
}

/// Hertz at the pitch point: two cylinders of the pitch radii (20 and 42 mm) times sin α_w
/// (α_w = 20° for the standard pair), the single pair's whole load, in SI units.
#[test]
fn hertz_at_the_pitch_point_is_the_cylinder_formula() {
    let (m, p) = pair(PAIR);
    let req = GearLoadRequest {
        torque: 80.0,
        face_width: 0.015,
        materials: Materials::default(),
        lubrication: None,
        points: 50,
    };
    let l = GearLoads::new(&p, m.cam().speed(), &req).unwrap();
    let q = l.at_pitch;
    let a = 20f64.to_radians();
    let (r1, r2) = (0.020 * a.sin(), 0.042 * a.sin());
    let e_star = 206e9 / (2.0 * (1.0 - 0.09));
    let f = 80.0 / (0.020 * a.cos());
    assert_eq!(q.pairs, 1);
    let p = (f * e_star * (1.0 / r1 + 1.0 / r2) / (PI * 0.015)).sqrt();
    assert!((q.hertz - p).abs() < 1e-12 * p, "{} vs {p} Pa", q.hertz);
    // no sliding at the pitch point
    assert!(q.sliding.abs() < 1e-12 * q.surface_speeds[0]);
}

/// The specific sliding along the whole path from its closed form, and against the exact
/// kinematics' (`GearPair::mesh`) wherever the mesh's first contact is a single pair on both
/// involutes, at 50 points from root to tip of each gear.
#[test]
fn specific_sliding_along_the_whole_path() {
    let (m, p) = pair(PAIR);
    let w1 = m.cam().speed();
    let req = GearLoadRequest {
        torque: 10.0,
        face_width: 0.010,
        materials: Materials::default(),
        lubrication: None,
        points: 50,
    };
    let l = GearLoads::new(&p, w1, &req).unwrap();
    let (rb1, rb2) = (
        0.020 * 20f64.to_radians().cos(),
        0.042 * 20f64.to_radians().cos(),
    );
    for q in &l.points {
        // the flanks' radii of curvature from the contact's radii: ρ = √(r² − r_b²)
        let rho1 = (q.radius[0].powi(2) - rb1 * rb1).sqrt();
        let rho2 = (q.radius[1].powi(2) - rb2 * rb2).sqrt();
        let (u1, u2) = (w1 * rho1, w1 * (20.0 / 42.0) * rho2);
        let z1 = (u1 - u2) / u1;
        let z2 = (u2 - u1) / u2;
        let s = q.specific_sliding;
        assert!(
            (s[0].unwrap() - z1).abs() < 1e-9 * (1.0 + z1.abs()),
            "{s:?} vs {z1}"
        );
        assert!(
            (s[1].unwrap() - z2).abs() < 1e-9 * (1.0 + z2.abs()),
            "{s:?} vs {z2}"
        );
    }
    // the driver's root (the path's start) slides most
    let first = l.points[0].specific_sliding[0].unwrap();
    assert!(l
        .points
        .iter()
        .all(|q| q.specific_sliding[0].unwrap() >= first - 1e-12));
    // against the exact kinematics
    let mut sweep = m.sweep();
    let mut compared = 0;
    for k in 0..720 {
        let theta = (k as f64 * 0.05).to_radians();
        let s = sweep.step(theta).unwrap();
        let ms = p.mesh(&m, &s);
        if !ms.on_flanks || ms.pairs_in_contact != 1 {
            continue;
        }
        let x = l.pitch_point + ms.line_of_action_position;
        let q = l.at(&p, w1, &req, x).unwrap();
        let exact = ms.specific_sliding_driver.unwrap();
        assert!(
            (q.specific_sliding[0].unwrap() - exact).abs() < 1e-8 * (1.0 + exact.abs()),
            "{x}: {:?} vs {exact}",
            q.specific_sliding
        );
        compared += 1;
    }
    assert!(compared > 100, "{compared}");
}

#[test]
fn bad_loads_are_refused() {
    let (m, p) = pair(PAIR);
    let ok = GearLoadRequest {
        torque: 10.0,
        face_width: 0.010,
        materials: Materials::default(),
        lubrication: None,
        points: 50,
    };
    for bad in [
        GearLoadRequest {
            torque: -1.0,
            ..ok.clone()
        },
        GearLoadRequest {
            torque: f64::NAN,
            ..ok.clone()
        },
        GearLoadRequest {
            face_width: 0.0,
            ..ok.clone()
        },
        GearLoadRequest {
            points: 1,
            ..ok.clone()
        },
    ] {
        assert!(
            GearLoads::new(&p, m.cam().speed(), &bad).is_err(),
            "{bad:?}"
        );
    }
}

fn built(text: &str) -> Result<camkin::spec::Built, String> {
    let spec = parse_toml(text, "p.toml").map_err(|e| e.to_string())?;
    let options = BuildOptions {
        si: true,
        ..BuildOptions::default()
    };
    build_placed(&spec, text, "p.toml", &options)
        .map(|b| b.0)
        .map_err(|e| e.to_string())
}

/// The FZG test gears' load stages (ISO 14635-1, DIN 51354: the pinion torque of each load stage
/// and the nominal Hertz pressure at the pitch point it gives, N/mm², as published). The
/// pressure is tabulated for the A gear's 20 mm face width; the A and C gears share the teeth,
/// the module, the centre distance and the shifts' sum (so the working pressure angle and the
/// pitch radii), and the C gear's pitch point lies in single-tooth contact, where the whole load
/// is on one pair.
const FZG_LOAD_STAGES: [(f64, f64); 12] = [
    (3.3, 146.0),
    (13.7, 295.0),
    (35.3, 474.0),
    (60.8, 621.0),
    (94.1, 773.0),
    (135.5, 927.0),
    (183.4, 1080.0),
    (239.3, 1232.0),
    (302.0, 1386.0),
    (372.6, 1538.0),
    (450.1, 1691.0),
    (534.5, 1841.0),
];

#[test]
fn the_fzg_load_stages_published_hertz_pressures() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/fzg-c.toml"
    ))
    .unwrap();
    let b = built(&text).unwrap();
    let p = GearPair::new(&b.mechanism).unwrap();
    for (torque, published) in FZG_LOAD_STAGES {
        let req = GearLoadRequest {
            torque,
            face_width: 0.020,
            materials: Materials::default(),
            lubrication: None,
            points: 11,
        };
        let l = GearLoads::new(&p, b.mechanism.cam().speed(), &req).unwrap();
        assert_eq!(l.at_pitch.pairs, 1);
        let mpa = l.at_pitch.hertz / 1e6;
        // the table's pressures are rounded to 1 N/mm² and its torques to 0.1 N·m (3.3 N·m:
        // ±1.5 %, ±0.8 % in the pressure)
        let tol = if torque < 5.0 { 0.009 } else { 0.003 };
        assert!(
            (mpa / published - 1.0).abs() < tol,
            "{torque} N·m: {mpa} MPa, published {published}"
        );
    }
    // the C gear's published transverse contact ratio, 1.44 (to its two decimals)
    let l = GearLoads::new(
        &p,
        1.0,
        &GearLoadRequest {
            torque: 1.0,
            face_width: 0.014,
            materials: Materials::default(),
            lubrication: None,
            points: 2,
        },
    )
    .unwrap();
    let eps = (l.path[1] - l.path[0]) / l.base_pitch;
    assert!((eps - 1.44).abs() < 0.005, "{eps}");
}

#[test]
fn the_file_section_and_its_overrides() {
    use camkin::spec::{GivenLoads, LoadInput};
    let with = |extra: &str| built(&format!("{PAIR}{extra}"));
    // a power is a torque at the file's speed: 5.236 kW at 1000 rpm is 50 N·m
    let b = with("[gear_loads]\npower_kw = 5.235987755982989\nface_width = 20.0\n").unwrap();
    let r = b.gear_loads_inputs(&GivenLoads::default()).unwrap();
    assert!((r.torque - 50.0).abs() < 1e-12 * 50.0, "{}", r.torque);
    assert!((r.face_width - 0.020).abs() < 1e-15);
    // each given value replaces the file's
    let r = b
        .gear_loads_inputs(&GivenLoads {
            torque: Some(7.0),
            face_width: Some(10.0),
            ..GivenLoads::default()
        })
        .unwrap();
    assert_eq!((r.torque, r.face_width), (7.0, 0.010));
    // the face width from [lubrication] when [gear_loads] has none
    let b = with("[gear_loads]\ntorque = 3.0\n[lubrication]\noil = \"sae-30@100c\"\nroughness_um = [0.2, 0.2]\nface_width = 12.0\nmaterials = \"steel,bronze\"\n").unwrap();
    let r = b.gear_loads_inputs(&GivenLoads::default()).unwrap();
    assert_eq!(r.face_width, 0.012);
    assert_eq!(r.materials.follower.name, "bronze");
    // refused, naming the input
    let b = with("").unwrap();
    let e = b.gear_loads_inputs(&GivenLoads::default()).unwrap_err();
    assert_eq!(e.input, LoadInput::Torque);
    for (given, input) in [
        (
            GivenLoads {
                torque: Some(-1.0),
                face_width: Some(10.0),
                ..GivenLoads::default()
            },
            LoadInput::Torque,
        ),
        (
            GivenLoads {
                power_kw: Some(0.0),
                face_width: Some(10.0),
                ..GivenLoads::default()
            },
            LoadInput::Power,
        ),
        (
            GivenLoads {
                torque: Some(1.0),
                power_kw: Some(1.0),
                face_width: Some(10.0),
                ..GivenLoads::default()
            },
            LoadInput::Power,
        ),
        (
            GivenLoads {
                torque: Some(1.0),
                ..GivenLoads::default()
            },
            LoadInput::FaceWidth,
        ),
        (
            // 10 m in a millimetre file: a slip
            GivenLoads {
                torque: Some(1.0),
                face_width: Some(1e4 * 1e3),
                ..GivenLoads::default()
            },
            LoadInput::FaceWidth,
        ),
    ] {
        let e = b.gear_loads_inputs(&given).unwrap_err();
        assert_eq!(e.input, input, "{given:?}: {e}");
    }
    // the section's own errors name its keys
    for (extra, key) in [
        ("[gear_loads]\ntorque = 1.0\npower_kw = 1.0\n", "gear_loads.power_kw"),
        ("[gear_loads]\nface_width = 1.0\n", "gear_loads"),
        ("[gear_loads]\ntorque = -2.0\n", "gear_loads.torque"),
        ("[gear_loads]\ntorque = 2.0\nface_width = 0.0\n", "gear_loads.face_width"),
        ("[gear_loads]\ntorque = 2.0\nmaterials = \"rubber,steel\"\n", "gear_loads.materials"),
        (
            "[gear_loads]\ntorque = 2.0\nface_width = 10.0\n[lubrication]\noil = \"sae-30@100c\"\nroughness_um = [0.2, 0.2]\nface_width = 12.0\n",
            "gear_loads.face_width",
        ),
    ] {
        let e = with(extra).unwrap_err();
        assert!(e.contains(key), "{extra}: {e}");
    }
    // a torque on a cam mechanism
    let cam = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100.0\n[cam.profile]\nkind = \"circle\"\ncenter = [5.0, 0.0]\nradius = 20.0\n[follower]\nkind = \"translating-flat\"\n[gear_loads]\ntorque = 5.0\n";
    let e = built(cam).unwrap_err();
    assert!(e.contains("not a gear pair"), "{e}");
}
