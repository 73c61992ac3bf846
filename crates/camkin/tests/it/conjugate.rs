//! Conjugate (form-closed) followers: a second curve on the follower touching the cam from the
//! other side (`Mechanism::with_conjugate`). Its play is checked against closed forms of circle
//! geometry the method does not use (a chord of the pitch circle, the breadth of a circle, the
//! law of cosines about a pivot), and its contact against the motion it did not set.

use crate::common::yoke_spec;
use camkin::cam::{Cam, Follower, FollowerProfile, Mechanism, Sense};
use camkin::curve::{Circle, Curve, Line};

use camkin::spec::{CamSpec, FollowerSpec, MechanismSpec, ProfileSpec, SpecError};
use camkin::{Point2, Vec2};
use std::f64::consts::TAU;
use std::sync::Arc;

/// Cam radius and eccentricity of the circle cam, roller radius.
const R: f64 = 30.0;
const ECC: f64 = 5.0;
const ROLLER: f64 = 10.0;

fn eccentric() -> Cam {
    Cam::from_rpm(
        Arc::new(Circle::new(Point2::new(ECC, 0.0), R).unwrap()),
        Point2::origin(),
        Sense::Ccw,
        600.0,
    )
    .unwrap()
}

fn circle(x: f64, y: f64, r: f64) -> Arc<dyn Curve> {
    Arc::new(Circle::new(Point2::new(x, y), r).unwrap())
}

fn angles() -> impl Iterator<Item = f64> {
    (0..360).map(|k| f64::from(k) * TAU / 360.0)
}

/// The play at every degree, from the sweep (the analysis table's path) and from cold queries,
/// which must agree.
fn plays(m: &Mechanism) -> Vec<f64> {
    let mut sweep = m.sweep();
    let mut conj = m.conjugate_sweep().unwrap();
    angles()
        .map(|t| {
            let s = sweep.step(t).unwrap();
            let warm = conj.play(&s).unwrap();
            let cold = m.conjugate_play(&m.analyze(t).unwrap()).unwrap().unwrap();
            assert!(
                (warm - cold).abs() < 1e-10,
                "{t}: sweep {warm}, cold {cold}"
            );
            warm
        })
        .collect()
}

/// A yoke with two rollers on a slide at offset `e` from the axis, their centres `l` apart:
/// both lie on the line of travel, on the pitch circle (radius R + r about the circle's centre
/// c(θ)) when they touch, so the play is `l` less the chord of that circle along the line,
/// `2 √((R + r)² − (c·p + e)²)` with `p` the line's normal (the offset's direction).
#[test]
fn a_roller_yoke_on_an_eccentric_has_the_play_of_the_chord() {
    for e in [0.0, 7.5, -12.0] {
        for (named, l) in [(true, 79.0), (false, 80.5)] {
            let d = Vec2::new(0.0, 1.0);
            let follower = if named {
                Follower::TranslatingRoller {
                    direction: d,
                    offset: e,
                    roller_radius: ROLLER,
                }
            } else {
                // the same roller carried as a circle: the general path
                Follower::Translating {
                    direction: d,
                    offset: e,
                    profile: FollowerProfile(circle(0.0, 0.0, ROLLER)),
                }
            };
            let m = Mechanism::new(eccentric(), follower)
                .unwrap()
                .with_conjugate(circle(-l, 0.0, ROLLER))
                .unwrap();
            let rho = R + ROLLER;
            for (t, play) in angles().zip(plays(&m)) {
                // c = ECC (cos θ, sin θ); the line of travel is x = −e (rot90(d) = −x)
                let across = ECC * t.cos() + e;
                let chord = 2.0 * (rho * rho - across * across).sqrt();
                assert!(
                    (play - (l - chord)).abs() < 1e-9,
                    "e {e}, named {named}, θ {t}: play {play}, closed form {}",
                    l - chord
                );
            }
        }
    }
}

/// A yoke with two parallel flat faces `b` apart on a circle cam: the breadth of a circle is its
/// diameter, so the play is `b − 2R` at every angle, whatever the eccentricity.
#[test]
fn a_flat_faced_yoke_on_a_circle_has_constant_play() {
    for b in [60.0, 60.3, 59.9] {
        // the second face is the line x = −b in the follower frame, its material below it
        let face: Arc<dyn Curve> =
            Arc::new(Line::new(Point2::new(-b, 0.0), Vec2::new(0.0, 1.0)).unwrap());
        let m = Mechanism::new(
            eccentric(),
            Follower::TranslatingFlat {
                direction: Vec2::new(0.3, 1.0),
            },
        )
        .unwrap()
        .with_conjugate(face)
        .unwrap();
        for (t, play) in angles().zip(plays(&m)) {
            assert!((play - (b - 2.0 * R)).abs() < 1e-9, "b {b}, θ {t}: {play}");
        }
    }
}

/// The same on an arm: an oscillating flat face and a second face `2R` below it in the arm's
/// frame, facing the other way, on a cam turning clockwise. Whatever the arm's angle, the two
/// parallel faces span the circle's breadth, its diameter: the play is 0 at every angle
/// (1e-9 rad), and both faces are reported as contacts.
#[test]
fn a_flat_faced_arm_yoke_on_a_circle_has_no_play_at_its_breadth() {
    let cam = Cam::from_rpm(
        Arc::new(Circle::new(Point2::new(ECC, 0.0), R).unwrap()),
        Point2::origin(),
        Sense::Cw,
        600.0,
    )
    .unwrap();
    let face: Arc<dyn Curve> =
        Arc::new(Line::new(Point2::new(0.0, -2.0 * R), Vec2::new(-1.0, 0.0)).unwrap());
    let m = Mechanism::new(
        cam,
        Follower::OscillatingFlat {
            pivot: Point2::new(-100.0, 40.0),
            face_offset: 0.0,
            closing: Sense::Cw,
            initial_angle: 0.0,
        },
    )
    .unwrap()
    .with_conjugate(face)
    .unwrap();
    for (t, play) in angles().zip(plays(&m)) {
        assert!(play.abs() < 1e-9, "θ {t}: {play}");
        let cs = m.contacts_at(&m.analyze(t).unwrap()).unwrap();
        assert_eq!(cs.iter().filter(|c| c.conjugate).count(), 1, "θ {t}");
    }
}

/// A bell crank: two arms from one pivot, a roller on each, one riding on top of the cam and one
/// underneath. Each roller touches where its centre is `R + r` from the circle's centre: by the
/// law of cosines about the pivot, the arm angles are `atan2(c − O) ± acos((L² + D² − ρ²)/(2LD))`.
/// The top arm closes clockwise, so the play is the second arm's touching angle less the first's.
#[test]
fn a_bell_crank_on_an_eccentric_has_the_play_of_the_law_of_cosines() {
    let o = Point2::new(-90.0, 0.0);
    let (l1, l2, r2) = (98.0, 97.0, 11.0);
    let beta: f64 = -0.84; // the second arm's angle from the first, rad
    for named in [true, false] {
        let follower = if named {
            Follower::OscillatingRoller {
                pivot: o,
                arm_length: l1,
                roller_radius: ROLLER,
                closing: Sense::Cw,
                initial_angle: 0.4,
            }
        } else {
            Follower::Rotating {
                pivot: o,
                closing: Sense::Cw,
                initial_angle: 0.4,
                profile: FollowerProfile(circle(l1, 0.0, ROLLER)),
            }
        };
        let m = Mechanism::new(eccentric(), follower)
            .unwrap()
            .with_conjugate(circle(l2 * beta.cos(), l2 * beta.sin(), r2))
            .unwrap();
        for (t, play) in angles().zip(plays(&m)) {
            let c = Point2::new(ECC * t.cos(), ECC * t.sin());
            let (dd, towards) = ((c - o).norm(), (c.y - o.y).atan2(c.x - o.x));
            let arm = |l: f64, rho: f64| ((l * l + dd * dd - rho * rho) / (2.0 * l * dd)).acos();
            let first = towards + arm(l1, R + ROLLER);
            let second = towards - arm(l2, R + r2) - beta;
            assert!(
                (play - (second - first)).abs() < 1e-9,
                "named {named}, θ {t}: play {play}, closed form {}",
                second - first
            );
        }
    }
}

/// The constant-diameter cam of the example, built from its file's fields (see
/// [`yoke_spec`]), `extra` mm of clearance between the rollers, the cam speeding up at
/// 9000 °/s².
fn constant_diameter(extra: f64) -> Mechanism {
    Mechanism::try_from(yoke_spec(extra, Some(9000.0))).unwrap()
}

fn circle_spec(center: [f64; 2], radius: f64) -> ProfileSpec {
    ProfileSpec {
        kind: "circle".into(),
        center: Some(center),
        radius: Some(radius),
        ..Default::default()
    }
}

/// With no play, both rollers touch at every angle: the second contact's point is a roller's
/// radius from the second roller's centre, on its normal; the motion the first contact set
/// keeps the second closed (zero normal velocity) and satisfies its constraint row (eq. 11 for a
/// contact that did not set it), under angular acceleration too.
#[test]
fn a_constant_diameter_cam_drives_both_rollers() {
    let m = constant_diameter(0.0);
    let omega = m.cam().speed();
    for t in angles() {
        let s = m.analyze(t).unwrap();
        let cs = m.contacts_at(&s).unwrap();
        assert_eq!(cs.len(), 2, "θ {t}");
        assert!(!cs[0].conjugate && cs[1].conjugate);
        let k = &cs[1];
        let centre = Point2::new(0.0, s.position - 120.0);
        let radial = k.point - centre;
        assert!((radial.norm() - ROLLER).abs() < 1e-9, "θ {t}");
        assert!(
            radial.normalize().dot(&k.normal).abs() > 1.0 - 1e-12,
            "θ {t}"
        );
        assert!(k.gap.abs() < 1e-9, "θ {t}: {}", k.gap);
        let scale = omega * omega * 70.0;
        assert!(k.normal_velocity.abs() < 1e-9 * omega * 70.0, "θ {t}");
        assert!(k.residual.abs() < 1e-9 * scale, "θ {t}: {}", k.residual);
        // the row is in the mechanism's coordinates: the follower's own q̈ satisfies it
        let alpha = m.cam().angular_acceleration();
        let row = k.row_cam * alpha + k.row_follower * s.acceleration - k.gamma;
        assert!(row.abs() < 1e-9 * scale, "θ {t}: {row}");
        // and it is not the first contact's row
        assert!((k.row_follower - cs[0].row_follower).abs() > 1.0, "θ {t}");
        // the play of the analysis table's path is zero too
        assert!(m.conjugate_play(&s).unwrap().unwrap().abs() < 1e-9);
    }
}

/// With play the second roller is no contact; with interference it is one, its gap the
/// (negative) play, and its row no longer holds at the motion the first contact set.
#[test]
fn play_and_interference_of_a_constant_diameter_cam() {
    let loose = constant_diameter(0.2);
    let tight = constant_diameter(-0.2);
    for t in angles().step_by(7) {
        let s = loose.analyze(t).unwrap();
        assert_eq!(loose.contacts_at(&s).unwrap().len(), 1);
        assert!((loose.conjugate_play(&s).unwrap().unwrap() - 0.2).abs() < 1e-9);
        let s = tight.analyze(t).unwrap();
        let cs = tight.contacts_at(&s).unwrap();
        assert_eq!(cs.len(), 2);
        assert!((cs[1].gap + 0.2).abs() < 1e-9, "θ {t}: {}", cs[1].gap);
    }
}

/// The second curve is validated like the first, its errors naming `follower.conjugate`.
#[test]
fn conjugate_spec_errors_name_the_field() {
    let with = |conjugate: ProfileSpec| {
        let spec = MechanismSpec {
            length_unit: Some("mm".into()),
            cam: CamSpec {
                speed_rpm: 100.0,
                profile: circle_spec([ECC, 0.0], R),
                ..Default::default()
            },
            follower: FollowerSpec {
                kind: "translating-roller".into(),
                roller_radius: Some(ROLLER),
                conjugate: Some(Box::new(conjugate)),
                ..Default::default()
            },
            ..Default::default()
        };
        Mechanism::try_from(spec).map(|_| ())
    };
    assert!(with(circle_spec([-80.0, 0.0], 10.0)).is_ok());
    let motion = ProfileSpec {
        kind: "motion".into(),
        base_radius: Some(3.0),
        segments: Some(Vec::new()),
        ..Default::default()
    };
    let cases = [
        (
            circle_spec([-80.0, 0.0], -1.0),
            "follower.conjugate.radius = -1",
        ),
        (motion, "follower.conjugate.kind"),
        (
            circle_spec([-80.0, 500.0], 10.0),
            "follower.conjugate: the second curve must touch the cam",
        ),
    ];
    for (c, want) in cases {
        let e: SpecError = with(c).unwrap_err();
        assert!(e.to_string().starts_with(want), "{want}: {e}");
        let path = e.field().to_string();
        assert!(path.starts_with("follower.conjugate"), "{path}");
    }
}

/// The design check of the play: passed for an exact conjugate and a constant clearance (the
/// play's range is within 1e-6 of the cam's size), failed for interference, with the extremes
/// the closed form gives on the eccentric's yoke (`l − chord`: largest where the circle's centre
/// is on the line of travel, at 90° and 270°; smallest at 0° and 180°).
#[test]
fn the_design_check_of_the_play() {
    let thetas: Vec<f64> = angles().collect();
    let check = |extra: f64| {
        constant_diameter(extra)
            .design_checks(&thetas, 30.0)
            .conjugate_play
            .unwrap()
    };
    assert!(check(0.0).passed && check(0.2).passed);
    assert!((check(0.2).min.0 - 0.2).abs() < 1e-9);
    let tight = check(-0.2);
    assert!(!tight.passed && (tight.max.0 + 0.2).abs() < 1e-9);
    let rho = R + ROLLER;
    let l = 2.0 * rho - 0.5;
    let m = Mechanism::new(
        eccentric(),
        Follower::TranslatingRoller {
            direction: Vec2::new(0.0, 1.0),
            offset: 0.0,
            roller_radius: ROLLER,
        },
    )
    .unwrap()
    .with_conjugate(circle(-l, 0.0, ROLLER))
    .unwrap();
    let c = m.design_checks(&thetas, 30.0);
    let p = c.conjugate_play.unwrap();
    let report = camkin::report::DesignReport::new(c, "mm", false);
    assert!(!p.passed && report.failures().contains(&"conjugate play"));
    assert!(
        report.text().contains("the second curve cuts into the cam"),
        "{}",
        report.text()
    );
    let chord_min = 2.0 * (rho * rho - ECC * ECC).sqrt();
    assert!((p.max.0 - (l - chord_min)).abs() < 1e-9, "{p:?}");
    assert!((p.min.0 - (l - 2.0 * rho)).abs() < 1e-9, "{p:?}");
    assert!([0.0, 180.0].contains(&p.max.1.round()), "{p:?}");
    assert!([90.0, 270.0].contains(&p.min.1.round()), "{p:?}");
}
