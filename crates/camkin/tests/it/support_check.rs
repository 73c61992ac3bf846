//! The contact method against an independent computation: the follower's position as the
//! support function of the cam (extreme over sampled profile points, golden section, no tangency
//! condition), its velocity and acceleration as sixth-order differences in the cam angle.

use super::common::*;
use camkin::cam::{Follower, Sense};
use camkin::{Point2, Vec2};

fn grid(step_deg: f64) -> Vec<f64> {
    let n = (360.0 / step_deg).round() as usize;
    (0..n)
        .map(|k| (k as f64 * step_deg + 0.123).to_radians())
        .collect()
}

/// The claim in the README: the contact method and the support function agree to these
/// fractions (of the profile's size for the position, of the peak for velocity and
/// acceleration).
const POSITION: f64 = 2e-14;
const VELOCITY: f64 = 1e-10;
const ACCELERATION: f64 = 1e-7;

fn check(mech: &camkin::cam::Mechanism, what: &str) -> camkin::cam::IndependentCheck {
    let c = mech.independent_check(&grid(2.0)).unwrap();
    eprintln!("{what}: {c:?}");
    assert!(c.position <= POSITION, "{what}: position {c:?}");
    assert!(c.velocity <= VELOCITY, "{what}: velocity {c:?}");
    assert!(c.acceleration <= ACCELERATION, "{what}: acceleration {c:?}");
    c
}

#[test]
fn every_follower_on_the_paper_cam_agrees_with_the_support_function() {
    for revised in [false, true] {
        for f in all_followers(Point2::origin()) {
            for sense in [Sense::Ccw, Sense::Cw] {
                let m = mechanism(
                    paper_profile(revised),
                    Point2::origin(),
                    sense,
                    60.0,
                    f.clone(),
                );
                let c = check(
                    &m,
                    &format!("{} {sense:?} revised={revised}", f.kind_name()),
                );
                assert_eq!(c.skipped, 0, "{}: a convex cam has no jumps", f.kind_name());
            }
        }
    }
}

#[test]
fn oscillating_followers_closing_either_way_agree_with_the_support_function() {
    let profile = ellipse(5.0, 3.5, Point2::new(0.4, -0.3), 0.3);
    for closing in [Sense::Ccw, Sense::Cw] {
        for (pivot, phi0) in [(Vec2::new(-3.0, 7.0), -30.0), (Vec2::new(8.0, -2.0), 150.0)] {
            let fs = [
                Follower::OscillatingFlat {
                    pivot: Point2::from(pivot),
                    face_offset: 0.5,
                    closing,
                    initial_angle: f64::to_radians(phi0),
                },
                Follower::OscillatingRoller {
                    pivot: Point2::from(pivot),
                    arm_length: 9.0,
                    roller_radius: 1.0,
                    closing,
                    initial_angle: f64::to_radians(phi0),
                },
            ];
            for f in fs {
                let m = mechanism(
                    profile.clone(),
                    Point2::new(0.2, 0.1),
                    Sense::Cw,
                    90.0,
                    f.clone(),
                );
                check(
                    &m,
                    &format!("{} closing {closing:?} at {phi0}°", f.kind_name()),
                );
            }
        }
    }
}

#[test]
fn a_cam_with_angular_acceleration_agrees_with_the_support_function() {
    for f in all_followers(Point2::new(1.0, -2.0)) {
        let cam = camkin::cam::Cam::from_rpm(
            paper_profile(true),
            Point2::new(1.0, -2.0),
            Sense::Cw,
            45.0,
        )
        .unwrap()
        .with_angular_acceleration(-30.0)
        .unwrap();
        let m = camkin::cam::Mechanism::new(cam, f.clone()).unwrap();
        check(&m, &format!("{} with α", f.kind_name()));
    }
}

#[test]
fn the_support_function_itself_matches_closed_forms() {
    // eccentric circle (radius 3, centre (1, 0)): under a flat face along x, s = R + e cos θ; under
    // a centred roller along x, s = e cos θ + √((R + r)² − e² sin² θ)
    let (r, e, rr) = (3.0, 1.0, 0.8);
    let flat = mechanism(
        eccentric_circle(r, e),
        Point2::origin(),
        Sense::Ccw,
        60.0,
        Follower::TranslatingFlat {
            direction: Vec2::new(1.0, 0.0),
        },
    );
    let roller = mechanism(
        eccentric_circle(r, e),
        Point2::origin(),
        Sense::Ccw,
        60.0,
        Follower::TranslatingRoller {
            direction: Vec2::new(1.0, 0.0),
            offset: 0.0,
            roller_radius: rr,
        },
    );
    for th in grid(7.0) {
        let (s, c) = th.sin_cos();
        let q = flat.support_position(th).unwrap().0;
        assert!((q - (r + e * c)).abs() < 1e-14 * r, "flat at {th}: {q}");
        let q = roller.support_position(th).unwrap().0;
        let exact = e * c + ((r + rr).powi(2) - (e * s).powi(2)).sqrt();
        assert!(
            (q - exact).abs() < 1e-14 * r,
            "roller at {th}: {q} vs {exact}"
        );
    }
}
