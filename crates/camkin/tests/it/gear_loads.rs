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
