//! The round trip: a profile synthesised exactly from a motion law, analysed by the contact
//! method, returns the law's position, velocity and acceleration (translating followers).
#![allow(clippy::unwrap_used)]
use camkin::cam::synthesis::synthesize;
use camkin::cam::{Cam, Follower, Mechanism, Sense};
use camkin::motion::{Law, Program, Segment};
use camkin::{Point2, Vec2};
use std::sync::Arc;

fn program(law: Law) -> Program {
    let d = |x: f64| x.to_radians();
    match law {
        Law::Dwell => Program::new(
            0.0,
            vec![Segment {
                law,
                rise: 0.0,
                extent: d(360.0),
            }],
        )
        .unwrap(),
        _ => Program::new(
            0.0,
            vec![
                Segment {
                    law,
                    rise: 1.0,
                    extent: d(120.0),
                },
                Segment {
                    law: Law::Dwell,
                    rise: 0.0,
                    extent: d(60.0),
                },
                Segment {
                    law,
                    rise: -1.0,
                    extent: d(120.0),
                },
                Segment {
                    law: Law::Dwell,
                    rise: 0.0,
                    extent: d(60.0),
                },
            ],
        )
        .unwrap(),
    }
}

#[test]
fn every_law_and_translating_follower_round_trips() {
    let followers = [
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
    ];
    for law in Law::ALL {
        for f in followers {
            for dir in [Sense::Ccw, Sense::Cw] {
                let prof = Arc::new(synthesize(program(law), 4.0, &f, dir).unwrap());
                let m = Mechanism::new(
                    Cam::from_rpm(prof.clone(), Point2::origin(), dir, 600.0).unwrap(),
                    f,
                )
                .unwrap();
                let w = m.cam().speed();
                let (mut worst, mut amax, mut n): (f64, f64, usize) = (0.0, 0.0, 0);
                for k in 0..360 {
                    let th = (k as f64 + 0.5).to_radians();
                    // a constant-velocity law's velocity jumps at its junctions: keep off them
                    if law == Law::ConstantVelocity
                        && [0.0f64, 120.0, 180.0, 300.0]
                            .iter()
                            .any(|j| ((k as f64 + 0.5) - j).abs() < 1.0)
                    {
                        continue;
                    }
                    let s = m.analyze(th).unwrap_or_else(|e| {
                        panic!("{} {} {dir:?} at {k}: {e}", law.name(), f.kind_name())
                    });
                    let exact = prof.follower_motion(th);
                    let scale_q = 5.0;
                    assert!(
                        (s.position - exact[0]).abs() < 1e-10 * scale_q,
                        "{} {} {dir:?} q at {k}: {} vs {}",
                        law.name(),
                        f.kind_name(),
                        s.position,
                        exact[0]
                    );
                    assert!(
                        (s.velocity - w * exact[1]).abs() < 1e-10 * w * scale_q,
                        "{} {} v at {k}",
                        law.name(),
                        f.kind_name()
                    );
                    worst = worst.max((s.acceleration - w * w * exact[2]).abs());
                    amax = amax.max((w * w * exact[2]).abs());
                    assert!(
                        (s.cam_param - th).abs() < 1e-9,
                        "{} {}: the contact is the synthesised point of θ",
                        law.name(),
                        f.kind_name()
                    );
                    n += 1;
                }
                let scale = amax.max(w * w);
                assert!(
                    worst <= 1e-10 * scale,
                    "{} {} {dir:?}: acceleration {worst:e} of {scale:e}",
                    law.name(),
                    f.kind_name()
                );
                assert!(n > 300);
            }
        }
    }
}

#[test]
fn synthesised_profiles_derivatives_agree_with_differences() {
    for law in Law::ALL {
        for f in [
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
        ] {
            check_derivatives(
                &synthesize(program(law), 4.0, &f, Sense::Cw).unwrap(),
                &format!("{} {}", law.name(), f.kind_name()),
            );
        }
        for f in [
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
        ] {
            check_derivatives(
                &synthesize(arm_program(law), 4.0, &f, Sense::Ccw).unwrap(),
                &format!("{} {}", law.name(), f.kind_name()),
            );
        }
    }
}

/// d1, d2, d3 of a synthesised profile against 4th-order differences of the lower derivative,
/// away from the segment junctions.
fn check_derivatives(prof: &camkin::cam::synthesis::SynthesizedProfile, name: &str) {
    use camkin::curve::Curve;
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

fn arm_program(law: Law) -> Program {
    let d = |x: f64| x.to_radians();
    match law {
        Law::Dwell => Program::new(
            0.0,
            vec![Segment {
                law,
                rise: 0.0,
                extent: d(360.0),
            }],
        )
        .unwrap(),
        _ => Program::new(
            0.0,
            vec![
                Segment {
                    law,
                    rise: 0.25,
                    extent: d(120.0),
                },
                Segment {
                    law: Law::Dwell,
                    rise: 0.0,
                    extent: d(60.0),
                },
                Segment {
                    law,
                    rise: -0.25,
                    extent: d(120.0),
                },
                Segment {
                    law: Law::Dwell,
                    rise: 0.0,
                    extent: d(60.0),
                },
            ],
        )
        .unwrap(),
    }
}

#[test]
fn every_law_and_oscillating_follower_round_trips() {
    let followers = [
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
    ];
    for law in Law::ALL {
        for f in followers {
            for dir in [Sense::Ccw, Sense::Cw] {
                let prof = Arc::new(synthesize(arm_program(law), 4.0, &f, dir).unwrap());
                let m = Mechanism::new(
                    Cam::from_rpm(prof.clone(), Point2::origin(), dir, 600.0).unwrap(),
                    f,
                )
                .unwrap();
                let w = m.cam().speed();
                let (mut worst, mut amax): (f64, f64) = (0.0, 0.0);
                for k in 0..360 {
                    let deg = k as f64 + 0.5;
                    if law == Law::ConstantVelocity
                        && [0.0f64, 120.0, 180.0, 300.0]
                            .iter()
                            .any(|j| (deg - j).abs() < 1.0)
                    {
                        continue;
                    }
                    let th = deg.to_radians();
                    let s = m.analyze(th).unwrap_or_else(|e| {
                        panic!("{} {} {dir:?} at {k}: {e}", law.name(), f.kind_name())
                    });
                    let exact = prof.follower_motion(th);
                    assert!(
                        (s.position - exact[0]).abs() < 1e-10,
                        "{} {} {dir:?} φ at {k}: {} vs {}",
                        law.name(),
                        f.kind_name(),
                        s.position,
                        exact[0]
                    );
                    assert!(
                        (s.velocity - w * exact[1]).abs() < 1e-10 * w,
                        "{} {} {dir:?} φ̇ at {k}: {} vs {}",
                        law.name(),
                        f.kind_name(),
                        s.velocity,
                        w * exact[1]
                    );
                    worst = worst.max((s.acceleration - w * w * exact[2]).abs());
                    amax = amax.max((w * w * exact[2]).abs());
                    assert!(
                        (s.cam_param - th).abs() < 1e-9,
                        "{} {} {dir:?}: contact at {} for θ = {th}",
                        law.name(),
                        f.kind_name(),
                        s.cam_param
                    );
                }
                let scale = amax.max(w * w);
                assert!(
                    worst <= 1e-10 * scale,
                    "{} {} {dir:?}: acceleration {worst:e} of {scale:e}",
                    law.name(),
                    f.kind_name()
                );
            }
        }
    }
}
