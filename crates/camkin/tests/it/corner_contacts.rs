//! Contacts at a corner of a curve (a point of its body, the other curve's normal): a follower's
//! corner on the cam, and a cam's corner on the follower, against closed forms that share nothing
//! with the method (a knife's kinematics, the support function of a gear's tip circle).

use crate::common::{ellipse, flat_face_on, mechanism, paper_profile};
use camkin::cam::{Corner, Follower, FollowerProfile, Sense};
use camkin::curve::{involute_function, Curve, Derivs, Domain, InvoluteGear, InvoluteGearSpec};
use camkin::{Point2, Vec2};
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

/// A wedge: two straight arms of length `len` meeting at the origin, opening along +x at ±`half`
/// (rad), its material between them (on the curve's left: the parameter runs down the upper arm
/// to the tip and out along the lower one).
#[derive(Debug)]
struct Wedge {
    half: f64,
    len: f64,
}

impl Curve for Wedge {
    fn eval(&self, v: f64) -> Derivs {
        let (s, c) = self.half.sin_cos();
        let (p, d1) = if v < 0.0 {
            (Point2::new(-v * c, -v * s), Vec2::new(-c, -s))
        } else {
            (Point2::new(v * c, -v * s), Vec2::new(c, -s))
        };
        Derivs {
            p: Point2::from(p.coords * self.len),
            d1: d1 * self.len,
            d2: Vec2::zeros(),
            d3: Vec2::zeros(),
        }
    }
    fn domain(&self) -> Domain {
        Domain::Interval {
            min: -1.0,
            max: 1.0,
        }
    }
    fn breakpoints(&self) -> Vec<f64> {
        vec![0.0]
    }
}

/// A translating follower carrying a wedge rests on its tip exactly as a knife edge does, while
/// the cam's tangent lies within the wedge's opening (pressure angle below 90° − half-angle); past
/// that an arm touches first and holds the follower further out. Both cams, several directions
/// and offsets, warm steps and cold queries.
#[test]
fn wedge_rests_on_its_tip_as_a_knife() {
    let half = 50f64.to_radians();
    let mut tip_rows = 0;
    let mut arm_rows = 0;
    for profile in [
        paper_profile(false),
        ellipse(4.0, 2.5, Point2::new(0.6, -0.3), 0.4),
    ] {
        for (direction, offset) in [
            (Vec2::x(), 0.0),
            (Vec2::new(0.6, 0.8), 0.8),
            (Vec2::new(-1.0, 0.3), -1.1),
        ] {
            let pivot = Point2::new(0.2, -0.1);
            let knife = mechanism(
                profile.clone(),
                pivot,
                Sense::Ccw,
                600.0,
                Follower::TranslatingKnife { direction, offset },
            );
            let wedge = mechanism(
                profile.clone(),
                pivot,
                Sense::Ccw,
                600.0,
                Follower::Translating {
                    direction,
                    offset,
                    profile: FollowerProfile(Arc::new(Wedge { half, len: 3.0 })),
                },
            );
            let (scale, w) = (knife.size(), knife.cam().speed());
            let (mut a, mut b) = (knife.sweep(), wedge.sweep());
            for k in 0..240 {
                let theta = f64::from(k) * 1.5f64.to_radians();
                let x = a.step(theta).unwrap();
                let y = if k % 7 == 3 {
                    wedge.analyze(theta).unwrap()
                } else {
                    b.step(theta).unwrap()
                };
                let what = format!("{direction:?} at {:.1}°", theta.to_degrees());
                let pressure = x.pressure_angle().abs();
                if pressure < PI / 2.0 - half - 0.01 {
                    tip_rows += 1;
                    assert_eq!(y.corner, Some(Corner::Follower), "{what}");
                    let close = |p: f64, q: f64, tol: f64, name: &str| {
                        assert!((p - q).abs() <= tol, "{what}: {name} {p} against {q}");
                    };
                    close(x.position, y.position, 1e-12 * scale, "position");
                    close(x.velocity, y.velocity, 1e-10 * scale * w, "velocity");
                    close(
                        x.acceleration,
                        y.acceleration,
                        1e-9 * scale * w * w,
                        "acceleration",
                    );
                    close(
                        x.sliding_rate_cam,
                        y.sliding_rate_cam,
                        1e-10 * scale * w,
                        "ṡ_A",
                    );
                    close(y.sliding_rate_follower, 0.0, 0.0, "ṡ_B");
                    close(
                        x.normal_acceleration_cam.total(),
                        y.normal_acceleration_cam.total(),
                        1e-9 * scale * w * w,
                        "a_n",
                    );
                    assert!((x.contact_world - y.contact_world).norm() <= 1e-12 * scale);
                } else if pressure > PI / 2.0 - half + 0.01 {
                    arm_rows += 1;
                    assert_eq!(y.corner, None, "{what}");
                    assert!(y.position > x.position, "{what}: the arm holds it out");
                }
            }
        }
    }
    assert!(
        tip_rows > 1000 && arm_rows > 50,
        "{tip_rows} on the tip, {arm_rows} on an arm"
    );
}

/// The centre angles of a spur gear's tip lands, from its corners on the tip circle (each pair
/// `2ψ_a` apart), and the lands' half-angle `ψ_a = π/2z + inv α − inv α_a` from the gear's own
/// formula.
fn tip_lands(gear: &InvoluteGear, z: u32, alpha: f64) -> (Vec<f64>, f64) {
    let (ra, rb) = (gear.tip_radius(), gear.base_radius());
    let psi_a =
        PI / (2.0 * f64::from(z)) + involute_function(alpha) - involute_function((rb / ra).acos());
    // the tips' centre lines from the curve: each pair of corners on the tip circle within 2ψ_a
    let mut tips: Vec<f64> = gear
        .breakpoints()
        .into_iter()
        .map(|b| gear.position(b))
        .filter(|p| (p.coords.norm() - ra).abs() <= 1e-9 * ra)
        .map(|p| p.y.atan2(p.x))
        .collect();
    tips.sort_by(f64::total_cmp);
    let centres: Vec<f64> = (0..tips.len())
        .filter_map(|i| {
            let (a, b) = (tips[i], tips[(i + 1) % tips.len()]);
            let gap = (b - a).rem_euclid(TAU);
            ((gap - 2.0 * psi_a).abs() <= 1e-9).then_some(a + 0.5 * gap)
        })
        .collect();
    assert_eq!(centres.len(), z as usize, "a land of 2ψ_a per tooth");
    (centres, psi_a)
}

/// A flat face on a 20-tooth spur gear (module 2, 20°) turning at 1000 rpm, with the gear's
/// tooth count, tip radius, speed (rad/s) and tip lands ([`tip_lands`]).
struct Face {
    mech: camkin::cam::Mechanism,
    z: u32,
    ra: f64,
    w: f64,
    centres: Vec<f64>,
    psi_a: f64,
}

fn face_on_a_spur_gear() -> Face {
    let (m, z, alpha) = (2.0, 20u32, 20f64.to_radians());
    let gear = InvoluteGear::new(InvoluteGearSpec::new(m, z, alpha)).unwrap();
    let ra = gear.tip_radius();
    let (centres, psi_a) = tip_lands(&gear, z, alpha);
    let mech = flat_face_on(gear);
    let w = mech.cam().speed();
    Face {
        mech,
        z,
        ra,
        w,
        centres,
        psi_a,
    }
}

/// Regression (`contacts` listed only the first of two contacts when the second rests on a
/// corner): a flat face on a spur gear, at the angle where the face's normal points midway
/// between two tip lands, rests on two tip corners at once, `r_a (cos δ, ± sin δ)` with
/// `δ = π/z − ψ_a`, one arriving and one leaving: their normal velocities differ by
/// `2 ω r_a sin δ`. A hundredth of a degree either side, one corner only.
#[test]
fn a_flat_face_on_two_tip_corners_lists_both() {
    let Face {
        mech,
        z,
        ra,
        w,
        centres,
        psi_a,
    } = face_on_a_spur_gear();
    let delta = PI / f64::from(z) - psi_a;
    for c in &centres[..5] {
        // the face's normal (+x) seen from the gear is at −θ: midway between two lands
        let theta = -(c + PI / f64::from(z));
        let s = mech.analyze(theta).unwrap();
        let what = format!("at {:.3}°", theta.to_degrees());
        assert!(
            (s.position - ra * delta.cos()).abs() <= 1e-12 * ra,
            "{what}"
        );
        let cs = mech.contacts_at(&s).unwrap();
        assert_eq!(cs.len(), 2, "{what}: {cs:?}");
        let mut ys: Vec<f64> = cs.iter().map(|k| k.point.y).collect();
        ys.sort_by(f64::total_cmp);
        for (y, sign) in ys.iter().zip([-1.0, 1.0]) {
            assert!(
                (y - sign * ra * delta.sin()).abs() <= 1e-9 * ra,
                "{what}: {ys:?}"
            );
        }
        for k in &cs {
            assert_eq!(k.corner, Some(Corner::Cam), "{what}");
            assert!((k.point.x - ra * delta.cos()).abs() <= 1e-9 * ra, "{what}");
            assert!(k.gap.abs() <= 1e-9 * ra, "{what}: gap {}", k.gap);
        }
        let dv = (cs[0].normal_velocity - cs[1].normal_velocity).abs();
        assert!(
            (dv - 2.0 * w * ra * delta.sin()).abs() <= 1e-9 * w * ra,
            "{what}: {dv}"
        );
        for side in [-1.0, 1.0] {
            let near = theta + side * 0.01f64.to_radians();
            let s = mech.analyze(near).unwrap();
            assert_eq!(mech.contacts_at(&s).unwrap().len(), 1, "{what} {side}");
        }
    }
}

/// A flat-faced follower on a spur gear rests on a tip corner or on a tip land: its position is
/// the gear's support function, `r_a cos δ` with `δ` the angle from the face's normal to the
/// nearest tip land (0 on a land), so on a corner `q̇ = ∓ω r_a sin δ` and `q̈ = −ω² r_a cos δ`. The
/// lands are where the involute reaches the tip circle, from the gear's own formula
/// (`ψ_a = π/2z + inv α − inv α_a` each side of the tooth's centre line).
#[test]
fn flat_face_on_a_gear_rests_on_its_tip_corners() {
    let face = face_on_a_spur_gear();
    let (mech, ra, w, psi_a) = (face.mech, face.ra, face.w, face.psi_a);
    let centres = face.centres;
    let mut sweep = mech.sweep();
    let (mut on_corner, mut on_land) = (0, 0);
    for k in 0..=1200 {
        let theta = f64::from(k) * 0.03f64.to_radians();
        // the face's normal (+x) seen from the gear: angle −θ; the nearest land's centre
        let (dist, _) = centres
            .iter()
            .map(|&c| {
                let d = (-theta - c + PI).rem_euclid(TAU) - PI;
                (d.abs(), d)
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .unwrap();
        let delta = (dist - psi_a).max(0.0);
        let s = if k % 11 == 4 {
            mech.analyze(theta).unwrap()
        } else {
            sweep.step(theta).unwrap()
        };
        let what = format!("at {:.2}°", theta.to_degrees());
        assert!(
            (s.position - ra * delta.cos()).abs() <= 1e-12 * ra,
            "{what}: {} against {}",
            s.position,
            ra * delta.cos()
        );
        if delta > 1e-6 {
            on_corner += 1;
            assert_eq!(s.corner, Some(Corner::Cam), "{what}");
            assert!(
                (s.velocity.abs() - w * ra * delta.sin()).abs() <= 1e-10 * w * ra,
                "{what}"
            );
            assert!(
                (s.acceleration + w * w * ra * delta.cos()).abs() <= 1e-9 * w * w * ra,
                "{what}: {} against {}",
                s.acceleration,
                -w * w * ra * delta.cos()
            );
            // the corner stays put on the cam, and the contact slides along the face
            assert_eq!(s.cam_param_rate, 0.0, "{what}");
            assert!((s.sliding_rate_follower.abs() - w * ra * delta.cos()).abs() <= 1e-9 * w * ra);
        } else if delta == 0.0 && dist < psi_a - 1e-6 {
            on_land += 1;
            assert_eq!(s.corner, None, "{what}");
            assert!(s.velocity.abs() <= 1e-10 * w * ra, "{what}");
        }
    }
    assert!(
        on_corner > 800 && on_land > 100,
        "{on_corner} on corners, {on_land} on lands"
    );
}

/// Regression (issue 44): at a tip land's edge the face rests on the land (`r_a`) until the
/// face's normal leaves the land, then on its corner (`r_a cos δ`). Just inside the edge the best
/// sample is the corner, and Newton started there wandered down the flank: the named face
/// answered the corner, 1.2e-5 mm below the land, with no warning, and the face carried as a line
/// refused those angles (a joint's rounding hid one tip corner in ten). Both, at every land's
/// two edges, from 0.1° inside to 0.1° outside in steps of 0.001°, against the closed form.
#[test]
fn a_flat_face_at_a_tip_lands_edge_rests_on_the_land_or_the_corner() {
    let face = face_on_a_spur_gear();
    let (ra, psi_a) = (face.ra, face.psi_a);
    let named = mechanism(
        Arc::new(InvoluteGear::new(InvoluteGearSpec::new(2.0, 20, 20f64.to_radians())).unwrap()),
        Point2::origin(),
        Sense::Ccw,
        1000.0,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    );
    let mut checked = 0;
    for (name, mech) in [("named", &named), ("carried", &face.mech)] {
        for c in &face.centres {
            for side in [-1.0, 1.0] {
                for j in -100..=100 {
                    // the face's normal (+x) seen from the gear is at −θ, `dist` from the centre
                    let dist = psi_a + f64::from(j) * 0.001f64.to_radians();
                    let theta = -(c + side * dist);
                    let delta = (dist - psi_a).max(0.0);
                    let s = mech.analyze(theta).unwrap();
                    assert!(
                        (s.position - ra * delta.cos()).abs() <= 1e-12 * ra,
                        "{name} at {:.4}° ({j} thousandths of a degree past the edge): {} \
                         against {}",
                        theta.to_degrees(),
                        s.position,
                        ra * delta.cos()
                    );
                    checked += 1;
                }
            }
        }
    }
    assert_eq!(checked, 2 * 20 * 2 * 201);
}
