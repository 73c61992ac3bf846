//! Property tests over random convex spline cams and poses.
#![allow(clippy::unwrap_used)]
mod common;
use camkin::cam::{Follower, Mechanism, Sense};
use camkin::curve::ClosedSpline;
use camkin::geometry::{wrap_angle_near, Rot};
use camkin::{Point2, Vec2};
use common::*;
use proptest::prelude::*;
use std::sync::Arc;

/// Nodes on a jittered circle of radius ≈ 3 (most such splines are convex).
fn cam_nodes() -> impl Strategy<Value = Vec<Point2>> {
    (5usize..12).prop_flat_map(|n| {
        prop::collection::vec((-0.25f64..0.25, -0.3f64..0.3), n).prop_map(move |j| {
            j.iter()
                .enumerate()
                .map(|(i, &(da, dr))| {
                    let a = (i as f64 + da) * std::f64::consts::TAU / n as f64;
                    let r = 3.0 + dr;
                    Point2::new(r * a.cos() + 0.4, r * a.sin() - 0.2)
                })
                .collect()
        })
    })
}

fn rotate_follower(f: &Follower, r: &Rot, beta: f64) -> Follower {
    let rp = |p: Point2| Point2::from(r.apply(p.coords));
    match *f {
        Follower::TranslatingFlat { direction } => Follower::TranslatingFlat {
            direction: r.apply(direction),
        },
        Follower::TranslatingRoller {
            direction,
            offset,
            roller_radius,
        } => Follower::TranslatingRoller {
            direction: r.apply(direction),
            offset,
            roller_radius,
        },
        Follower::TranslatingKnife { direction, offset } => Follower::TranslatingKnife {
            direction: r.apply(direction),
            offset,
        },
        Follower::OscillatingFlat {
            pivot,
            face_offset,
            closing,
            initial_angle,
        } => Follower::OscillatingFlat {
            pivot: rp(pivot),
            face_offset,
            closing,
            initial_angle: initial_angle + beta,
        },
        Follower::OscillatingRoller {
            pivot,
            arm_length,
            roller_radius,
            closing,
            initial_angle,
        } => Follower::OscillatingRoller {
            pivot: rp(pivot),
            arm_length,
            roller_radius,
            closing,
            initial_angle: initial_angle + beta,
        },
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// For a translating flat-faced follower on a convex cam, s̈ = ω² (ρ − s) (an identity that
    /// is not the method), for any direction of travel, cam direction and axis.
    #[test]
    fn flat_face_identity_on_random_convex_cams(
        nodes in cam_nodes(),
        dir_angle in 0.0f64..std::f64::consts::TAU,
        ccw in any::<bool>(),
        theta in 0.0f64..360.0,
        px in -5.0f64..5.0, py in -5.0f64..5.0,
    ) {
        let profile = Arc::new(ClosedSpline::new(&nodes).unwrap());
        let sense = if ccw { Sense::Ccw } else { Sense::Cw };
        let m = mechanism(profile, Point2::new(px, py), sense, 1000.0,
            Follower::TranslatingFlat { direction: Vec2::new(dir_angle.cos(), dir_angle.sin()) });
        prop_assume!(m.is_convex());
        let w = m.cam().speed();
        let s = m.analyze_deg(theta).unwrap();
        let expect = w * w * (s.radius_of_curvature - s.position);
        prop_assert!((s.acceleration - expect).abs() <= 1e-10 * w * w * m.size(),
            "a = {}, ω²(ρ − s) = {}", s.acceleration, expect);
    }

    /// Rotating the whole mechanism (cam axis, profile, follower) about the world origin changes
    /// nothing relative: same translating position, arm angle shifted by the rotation, same rates.
    #[test]
    fn rotating_the_whole_mechanism_changes_nothing_relative(
        nodes in cam_nodes(),
        beta in -3.0f64..3.0,
        kind in 0usize..5,
        ccw in any::<bool>(),
        theta in 0.0f64..360.0,
    ) {
        let pivot = Point2::new(0.7, -0.4);
        let sense = if ccw { Sense::Ccw } else { Sense::Cw };
        let f = all_followers(pivot)[kind];
        let m = mechanism(Arc::new(ClosedSpline::new(&nodes).unwrap()), pivot, sense, 1000.0, f);
        prop_assume!(m.is_convex());
        let r = Rot::new(beta);
        let nodes_r: Vec<Point2> = nodes.iter().map(|p| Point2::from(r.apply(p.coords))).collect();
        let mr = Mechanism::new(
            camkin::cam::Cam::from_rpm(Arc::new(ClosedSpline::new(&nodes_r).unwrap()), Point2::from(r.apply(pivot.coords)), sense, 1000.0).unwrap(),
            rotate_follower(&f, &r, beta),
        ).unwrap();
        let (a, b) = (m.analyze_deg(theta), mr.analyze_deg(theta));
        prop_assume!(a.is_ok()); // a random cam may leave the follower's reach
        let (a, b) = (a.unwrap(), b.unwrap());
        let w = m.cam().speed();
        let qb = if f.is_oscillating() { wrap_angle_near(b.position - beta, a.position) } else { b.position };
        let scale = m.size() + 10.0;
        prop_assert!((a.position - qb).abs() <= 1e-11 * scale, "q {} vs {}", a.position, qb);
        prop_assert!((a.velocity - b.velocity).abs() <= 1e-10 * w * scale, "v {} vs {}", a.velocity, b.velocity);
        prop_assert!((a.acceleration - b.acceleration).abs() <= 1e-9 * w * w * scale, "a {} vs {}", a.acceleration, b.acceleration);
        prop_assert!((a.sliding_rate_cam - b.sliding_rate_cam).abs() <= 1e-9 * w * scale);
        prop_assert!((a.cam_param - b.cam_param).abs() <= 1e-9);
    }
}
