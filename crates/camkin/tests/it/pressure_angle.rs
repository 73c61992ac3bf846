//! The pressure angle is the textbook's: between the line of the contact force and the direction
//! of motion of the follower's reference point — a roller's centre, not the contact point —
//! signed counter-clockwise from the motion to the force line. Checked against constructions
//! from positions only: the pitch curve (the roller centre's path in the cam's frame) by finite
//! differences, whose normal is the force line; and the eccentric cam's closed form (the force
//! line passes through the disc's centre and the roller's).

use crate::common::*;
use camkin::cam::{Follower, FollowerProfile, Sense};
use camkin::curve::Circle;
use camkin::{Point2, Vec2};
use std::sync::Arc;

fn rot(a: f64, v: Vec2) -> Vec2 {
    let (s, c) = a.sin_cos();
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

fn rot90(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// The signed angle from `m` to the line `n` oriented along `m`.
fn from_motion(m: Vec2, n: Vec2) -> f64 {
    let n = if n.dot(&m) >= 0.0 { n } else { -n };
    (m.x * n.y - m.y * n.x).atan2(m.dot(&n))
}

/// Oscillating rollers on eccentric cams, both cam senses and both closing senses, pivots on
/// either side: the pressure angle against the pitch curve's normal at the roller's centre.
#[test]
fn an_oscillating_rollers_pressure_angle_is_at_its_centre() {
    let (ecc, big_r) = (8.0, 30.0);
    let mut discriminated = 0.0f64;
    for (pivot, arm, roller, closing) in [
        (Point2::new(20.0, 50.0), 45.0, 12.0, Sense::Cw),
        (Point2::new(-25.0, 48.0), 50.0, 15.0, Sense::Ccw),
        (Point2::new(55.0, -10.0), 40.0, 6.0, Sense::Ccw),
    ] {
        for sense in [Sense::Ccw, Sense::Cw] {
            let follower = Follower::OscillatingRoller {
                pivot,
                arm_length: arm,
                roller_radius: roller,
                closing,
                initial_angle: (Point2::origin() - pivot)
                    .y
                    .atan2((Point2::origin() - pivot).x),
            };
            let m = mechanism(
                eccentric_circle(big_r, ecc),
                Point2::origin(),
                sense,
                600.0,
                follower,
            );
            // the roller's centre in the cam's frame at cam angle θ
            let centre = |theta: f64| {
                let phi = m.analyze(theta).unwrap().position;
                let c = pivot + arm * Vec2::new(phi.cos(), phi.sin());
                (c, rot(-sense.sign() * theta, c.coords))
            };
            for k in 0..24 {
                let theta = k as f64 * 15f64.to_radians() + 0.1;
                let s = m.analyze(theta).unwrap();
                let (c, _) = centre(theta);
                // the reference point's motion is the roller centre's
                let mc = rot90(c - pivot);
                assert!(
                    (s.reference_motion - mc).norm() < 1e-9 * mc.norm(),
                    "{:?} {mc:?}",
                    s.reference_motion
                );
                let h = 1e-4;
                let tangent = (centre(theta + h).1 - centre(theta - h).1) / (2.0 * h);
                let normal = rot90(rot(sense.sign() * theta, tangent));
                let expect = from_motion(rot90(c - pivot), normal);
                let got = s.pressure_angle();
                assert!(
                    (got - expect).abs() < 1e-7,
                    "pivot {pivot:?} {sense:?} at {}°: {}° against {}°",
                    theta.to_degrees(),
                    got.to_degrees(),
                    expect.to_degrees()
                );
                // the contact point's direction of motion gives another angle: this geometry
                // tells the two apart
                let at_contact = from_motion(s.follower_motion, *s.normal);
                discriminated = discriminated.max((at_contact - expect).abs());
            }
        }
    }
    assert!(
        discriminated > 5f64.to_radians(),
        "{}",
        discriminated.to_degrees()
    );
}

/// A roller carried by a general arm (a circle on a rotating follower) has the named roller's
/// pressure angle; a knife (a point) keeps its tip's.
#[test]
fn a_carried_circle_is_a_roller_and_a_point_its_tip() {
    let pivot = Point2::new(20.0, 50.0);
    let (arm, roller) = (45.0, 12.0);
    let named = Follower::OscillatingRoller {
        pivot,
        arm_length: arm,
        roller_radius: roller,
        closing: Sense::Cw,
        initial_angle: -1.2,
    };
    let carried = Follower::Rotating {
        pivot,
        closing: Sense::Cw,
        initial_angle: -1.2,
        profile: FollowerProfile(Arc::new(
            Circle::new(Point2::new(arm, 0.0), roller).unwrap(),
        )),
    };
    let a = mechanism(
        eccentric_circle(30.0, 8.0),
        Point2::origin(),
        Sense::Ccw,
        600.0,
        named,
    );
    let b = mechanism(
        eccentric_circle(30.0, 8.0),
        Point2::origin(),
        Sense::Ccw,
        600.0,
        carried,
    );
    for k in 0..36 {
        let theta = k as f64 * 10f64.to_radians();
        let (sa, sb) = (a.analyze(theta).unwrap(), b.analyze(theta).unwrap());
        assert!((sa.pressure_angle() - sb.pressure_angle()).abs() < 1e-9);
    }
    let knife = Follower::Rotating {
        pivot,
        closing: Sense::Cw,
        initial_angle: -1.2,
        profile: FollowerProfile(Arc::new(
            camkin::curve::PointCurve::new(Point2::new(arm, 0.0)).unwrap(),
        )),
    };
    let k = mechanism(
        eccentric_circle(30.0, 8.0),
        Point2::origin(),
        Sense::Ccw,
        600.0,
        knife,
    );
    let s = k.analyze(0.7).unwrap();
    assert!((s.reference_motion - s.follower_motion).norm() < 1e-12);
}

/// Offset translating rollers on an eccentric disc, offsets both ways, both cam senses: the
/// force line joins the disc's centre and the roller's, so the signed angle from the direction
/// of travel to it is known in closed form.
#[test]
fn a_translating_rollers_signed_pressure_angle_has_its_closed_form() {
    let (ecc, big_r, roller) = (6.0, 25.0, 5.0);
    let mut signs = [0usize; 2];
    for offset in [-7.0, 0.0, 9.0] {
        for sense in [Sense::Ccw, Sense::Cw] {
            let d = Vec2::new(0.6, 0.8);
            let follower = Follower::TranslatingRoller {
                direction: d,
                offset,
                roller_radius: roller,
            };
            let m = mechanism(
                eccentric_circle(big_r, ecc),
                Point2::origin(),
                sense,
                300.0,
                follower,
            );
            for k in 0..36 {
                let theta = k as f64 * 10f64.to_radians() + 0.05;
                let s = m.analyze(theta).unwrap();
                let disc = rot(sense.sign() * theta, Vec2::new(ecc, 0.0));
                let centre = offset * rot90(d) + s.position * d;
                let expect = from_motion(d, centre - disc);
                assert!(
                    (s.pressure_angle() - expect).abs() < 1e-12,
                    "offset {offset} {sense:?} at {}°: {} against {}",
                    theta.to_degrees(),
                    s.pressure_angle(),
                    expect
                );
                signs[usize::from(expect > 0.0)] += 1;
            }
        }
    }
    // both signs were reached: a mirrored sign would fail
    assert!(signs[0] > 20 && signs[1] > 20, "{signs:?}");
}

/// A gear carried by an arm is not a roller: its pressure angle is at the contact point, the
/// involute's profile angle there, `cos α = r_b/r` (r: the contact's distance from the driven
/// gear's centre), on both flanks.
#[test]
fn a_gears_pressure_angle_is_its_profile_angle_at_the_contact() {
    use camkin::cam::{Cam, Mechanism};
    use camkin::curve::{InvoluteGear, InvoluteGearSpec};
    let alpha = 20f64.to_radians();
    let g1 = InvoluteGear::new(InvoluteGearSpec::new(2.0, 20, alpha)).unwrap();
    let g2 = InvoluteGear::new(InvoluteGearSpec::new(2.0, 42, alpha)).unwrap();
    let rb2 = g2.base_radius();
    for (driver, closing) in [(Sense::Ccw, Sense::Ccw), (Sense::Cw, Sense::Cw)] {
        let cam = Cam::from_rpm(Arc::new(g1.clone()), Point2::origin(), driver, 1000.0).unwrap();
        let follower = Follower::Rotating {
            pivot: Point2::new(62.0, 0.0),
            closing,
            initial_angle: std::f64::consts::PI + std::f64::consts::PI / 42.0,
            profile: FollowerProfile(Arc::new(g2.clone())),
        };
        let m = Mechanism::new(cam, follower).unwrap();
        let mut checked = 0;
        for k in 0..36 {
            let s = m.analyze(k as f64 * 0.5f64.to_radians()).unwrap();
            if s.corner.is_some() {
                continue;
            }
            let r = (s.contact_world - Point2::new(62.0, 0.0)).norm();
            let expect = (rb2 / r).acos();
            assert!(
                (s.pressure_angle().abs() - expect).abs() < 1e-9,
                "{driver:?}: {} against {}",
                s.pressure_angle(),
                expect
            );
            checked += 1;
        }
        assert!(checked > 30);
    }
}
