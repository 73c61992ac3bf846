//! The round trip: a profile synthesised exactly from a motion law, analysed by the contact
//! method, returns the law's position, velocity and acceleration, for every law and every
//! follower type.
#![allow(clippy::unwrap_used)]
use camkin::cam::synthesis::{synthesize, SynthesizedProfile};
use camkin::cam::{Cam, Follower, FollowerProfile, Mechanism, Sense};
use camkin::curve::Curve;
use camkin::motion::{Law, Program, Segment};
use camkin::{Point2, Vec2};
use std::sync::Arc;

/// Rise `rise` with `law` over 120°, dwell 60°, return over 120°, dwell 60° (a dwell law: one
/// dwell all round).
fn program(law: Law, rise: f64) -> Program {
    let d = |x: f64| x.to_radians();
    let seg = |law, rise, deg| Segment {
        law,
        rise,
        extent: d(deg),
    };
    let segments = match law {
        Law::Dwell => vec![seg(law, 0.0, 360.0)],
        _ => vec![
            seg(law.clone(), rise, 120.0),
            seg(Law::Dwell, 0.0, 60.0),
            seg(law, -rise, 120.0),
            seg(Law::Dwell, 0.0, 60.0),
        ],
    };
    Program::new(0.0, segments).unwrap()
}

fn translating() -> [Follower; 4] {
    [
        Follower::TranslatingFlat {
            direction: Vec2::new(1.0, 0.2),
        },
        Follower::TranslatingKnife {
            direction: Vec2::new(0.0, 1.0),
            offset: 0.5,
        },
        Follower::TranslatingRoller {
            direction: Vec2::new(-1.0, 0.0),
            offset: -0.4,
            roller_radius: 1.0,
        },
        // a point carried by a general slide, ahead of its frame's origin and to the left
        Follower::Translating {
            direction: Vec2::new(0.6, -0.8),
            offset: 0.2,
            profile: point(-0.7, 0.3),
        },
    ]
}

fn point(x: f64, y: f64) -> FollowerProfile {
    FollowerProfile(Arc::new(
        camkin::curve::PointCurve::new(Point2::new(x, y)).unwrap(),
    ))
}

/// Oscillating followers closing clockwise from above the cam, and their mirror images closing
/// counter-clockwise from below (another branch: the arm near +30° instead of −30°).
fn oscillating() -> [Follower; 6] {
    [
        Follower::OscillatingRoller {
            pivot: Point2::new(-3.0, 7.0),
            arm_length: 9.0,
            roller_radius: 1.0,
            closing: Sense::Cw,
            initial_angle: (-30f64).to_radians(),
        },
        Follower::OscillatingFlat {
            pivot: Point2::new(-3.0, 7.0),
            face_offset: 0.5,
            closing: Sense::Cw,
            initial_angle: (-30f64).to_radians(),
        },
        Follower::OscillatingRoller {
            pivot: Point2::new(-3.0, -7.0),
            arm_length: 9.0,
            roller_radius: 1.0,
            closing: Sense::Ccw,
            initial_angle: 30f64.to_radians(),
        },
        Follower::OscillatingFlat {
            pivot: Point2::new(-3.0, -7.0),
            face_offset: -0.5,
            closing: Sense::Ccw,
            initial_angle: 30f64.to_radians(),
        },
        // a point carried by a general arm: an oscillating knife at a bent arm's end
        Follower::Rotating {
            pivot: Point2::new(-3.0, 7.0),
            closing: Sense::Cw,
            initial_angle: (-30f64).to_radians(),
            profile: point(8.6, -1.5),
        },
        Follower::Rotating {
            pivot: Point2::new(-3.0, -7.0),
            closing: Sense::Ccw,
            initial_angle: 30f64.to_radians(),
            profile: point(8.6, 1.5),
        },
    ]
}

/// Synthesises, analyses over a revolution, and checks position and velocity to `1e-10 q_scale`
/// (times ω for the velocity) and the acceleration to 1e-10 of its peak; the contact must be the
/// synthesised point of each angle.
fn round_trip(f: Follower, law: Law, rise: f64, dir: Sense, q_scale: f64) {
    let name = format!("{} {} {dir:?}", law.name(), f.kind_name());
    let prof = Arc::new(synthesize(program(law.clone(), rise), 4.0, &f, dir).unwrap());
    let m = Mechanism::new(
        Cam::from_rpm(prof.clone(), Point2::origin(), dir, 600.0).unwrap(),
        f,
    )
    .unwrap();
    let w = m.cam().speed();
    let (mut worst, mut amax, mut n): (f64, f64, usize) = (0.0, 0.0, 0);
    for k in 0..360 {
        let deg = k as f64 + 0.5;
        // a constant-velocity law's velocity jumps at its junctions: keep off them
        if law == Law::ConstantVelocity
            && [0.0f64, 120.0, 180.0, 300.0]
                .iter()
                .any(|j| (deg - j).abs() < 1.0)
        {
            continue;
        }
        let th = deg.to_radians();
        let s = m
            .analyze(th)
            .unwrap_or_else(|e| panic!("{name} at {k}: {e}"));
        let exact = prof.follower_motion(th);
        assert!(
            (s.position - exact[0]).abs() < 1e-10 * q_scale,
            "{name} q at {k}: {} vs {}",
            s.position,
            exact[0]
        );
        assert!(
            (s.velocity - w * exact[1]).abs() < 1e-10 * w * q_scale,
            "{name} v at {k}: {} vs {}",
            s.velocity,
            w * exact[1]
        );
        worst = worst.max((s.acceleration - w * w * exact[2]).abs());
        amax = amax.max((w * w * exact[2]).abs());
        assert!(
            (s.cam_param - th).abs() < 1e-9,
            "{name}: contact at {} for θ = {th}",
            s.cam_param
        );
        n += 1;
    }
    let scale = amax.max(w * w);
    assert!(
        worst <= 1e-10 * scale,
        "{name}: acceleration {worst:e} of {scale:e}"
    );
    assert!(n > 300);
}

#[test]
fn every_law_and_translating_follower_round_trips() {
    for law in Law::ALL {
        for f in translating() {
            for dir in [Sense::Ccw, Sense::Cw] {
                round_trip(f.clone(), law.clone(), 1.0, dir, 5.0);
            }
        }
    }
}

#[test]
fn every_law_and_oscillating_follower_round_trips() {
    for law in Law::ALL {
        for f in oscillating() {
            for dir in [Sense::Ccw, Sense::Cw] {
                round_trip(f.clone(), law.clone(), 0.25, dir, 1.0);
            }
        }
    }
}

/// d1, d2, d3 of a synthesised profile against 4th-order differences of the lower derivative,
/// away from the segment junctions.
fn check_derivatives(prof: &SynthesizedProfile, name: &str) {
    let fd = |f: &dyn Fn(f64) -> Vec2, u: f64, h: f64| {
        (f(u - 2.0 * h) - 8.0 * f(u - h) + 8.0 * f(u + h) - f(u + 2.0 * h)) / (12.0 * h)
    };
    for k in 0..36 {
        let deg = k as f64 * 10.0 + 3.3;
        if [0.0f64, 120.0, 180.0, 300.0, 360.0]
            .iter()
            .any(|j| (deg - j).abs() < 1.0)
        {
            continue;
        }
        let u = deg.to_radians();
        let e = prof.eval(u);
        let h = 1e-4;
        let d1 = fd(&|v| prof.eval(v).p.coords, u, h);
        let d2 = fd(&|v| prof.eval(v).d1, u, h);
        let d3 = fd(&|v| prof.eval(v).d2, u, h);
        let sc = 1.0 + e.d1.norm() + e.d2.norm() + e.d3.norm();
        assert!((d1 - e.d1).norm() < 1e-6 * sc, "{name} d1 at {deg}");
        assert!((d2 - e.d2).norm() < 1e-6 * sc, "{name} d2 at {deg}");
        assert!(
            (d3 - e.d3).norm() < 1e-5 * sc,
            "{name} d3 at {deg}: {d3} vs {}",
            e.d3
        );
    }
}

#[test]
fn synthesised_profiles_derivatives_agree_with_differences() {
    for law in Law::ALL {
        for f in translating() {
            check_derivatives(
                &synthesize(program(law.clone(), 1.0), 4.0, &f, Sense::Cw).unwrap(),
                &format!("{} {}", law.name(), f.kind_name()),
            );
        }
        for f in oscillating() {
            check_derivatives(
                &synthesize(program(law.clone(), 0.25), 4.0, &f, Sense::Ccw).unwrap(),
                &format!("{} {}", law.name(), f.kind_name()),
            );
        }
    }
}
