//! The surfaces' speeds at the contact, which lubrication is computed from, against the
//! material velocities of the two bodies and the contact point's own velocity by finite
//! differences of positions (sharing no formula with the paper's sliding rates), for every
//! follower kind on an ellipse and on the paper's cam, both cam senses.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, FollowerCurve, Mechanism, Sense};
use camkin::dynamics::surface_speeds;
use camkin::geometry::rot90;
use camkin::{Point2, Vec2};
use std::f64::consts::TAU;

/// `(u_cam, u_follower)` from positions alone: the contact point's velocity by finite
/// differences of its position in time, the cam's material velocity `ω × (P − C)`, the
/// follower's from the finite difference of its coordinate (a slide: along its direction; an
/// arm: about its pivot).
fn by_positions(m: &Mechanism, follower: &Follower, theta: f64) -> [f64; 2] {
    let cam = m.cam();
    let w = cam.speed();
    let omega = cam.direction().sign() * w;
    let s = m.analyze(theta).unwrap();
    let h = 1e-4;
    let at = |x: f64| m.analyze(x).unwrap();
    let (px, _) = fd8(|x| at(x).contact_world.x, theta, h);
    let (py, _) = fd8(|x| at(x).contact_world.y, theta, h);
    let (dq, _) = fd8(|x| at(x).position, theta, h);
    // d/dt = ω d/dθ at constant speed
    let v_p = Vec2::new(px, py) * w;
    let qdot = dq * w;
    let p = s.contact_world;
    let v_cam = omega * rot90(p - cam.pivot());
    let v_follower = match follower {
        Follower::TranslatingFlat { direction }
        | Follower::TranslatingRoller { direction, .. }
        | Follower::TranslatingKnife { direction, .. } => qdot * direction.normalize(),
        Follower::OscillatingFlat { pivot, .. } | Follower::OscillatingRoller { pivot, .. } => {
            qdot * rot90(p - pivot)
        }
        _ => unreachable!(),
    };
    let t = Vec2::new(s.normal.y, -s.normal.x);
    [(v_cam - v_p).dot(&t), (v_follower - v_p).dot(&t)]
}

#[test]
fn surface_speeds_agree_with_the_bodies_velocities_from_positions() {
    let cams = [
        ellipse(4.0, 3.0, Point2::new(0.3, -0.2), 0.4),
        paper_profile(false),
    ];
    let size = 5.0;
    for profile in cams {
        for sense in [Sense::Ccw, Sense::Cw] {
            for f in all_followers(Point2::origin()) {
                let m = mechanism(profile.clone(), Point2::origin(), sense, 600.0, f.clone());
                let roller = matches!(m.follower_curve(), FollowerCurve::Circle(_));
                let w = m.cam().speed();
                for k in 0..24 {
                    let theta = (f64::from(k) + 0.3) * TAU / 24.0;
                    let s = m.analyze(theta).unwrap();
                    let u = surface_speeds(&m, &s);
                    let r = by_positions(&m, &f, theta);
                    let tol = 1e-8 * size * w;
                    assert_close(u[0], r[0], 1e-8, size * w, "the cam's surface speed");
                    if roller {
                        // rolling without slip: the roller's surface moves with the cam's
                        assert_eq!(u[1], u[0]);
                    } else {
                        assert_close(u[1], r[1], 1e-8, size * w, "the follower's surface speed");
                        // the paper's eq. 6: the follower's sliding rate, up to its tangent's sense
                        assert!(
                            (u[1].abs() - s.sliding_rate_follower.abs()).abs() <= tol,
                            "{f:?} at {theta}: {u:?} vs ṡ_B {}",
                            s.sliding_rate_follower
                        );
                    }
                }
            }
        }
    }
}
