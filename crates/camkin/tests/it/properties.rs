//! Property tests over random convex spline cams and poses.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Mechanism, Sense};
use camkin::curve::ClosedSpline;
use camkin::geometry::{wrap_angle_near, Rotation};
use camkin::{Point2, Vec2};
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

fn rotate_follower(f: &Follower, r: &Rotation, beta: f64) -> Follower {
    let rp = |p: Point2| r * p;
    match *f {
        Follower::TranslatingFlat { direction } => Follower::TranslatingFlat {
            direction: r * direction,
        },
        Follower::TranslatingRoller {
            direction,
            offset,
            roller_radius,
        } => Follower::TranslatingRoller {
            direction: r * direction,
            offset,
            roller_radius,
        },
        Follower::TranslatingKnife { direction, offset } => Follower::TranslatingKnife {
            direction: r * direction,
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
        _ => unreachable!("the named kinds only"),
    }
}

/// The mirror image `(x, y) → (x, −y)` of a follower: directions and points mirrored, offsets
/// (measured along `rot90(d)` or the arm's normal) and arm angles negated, closing reversed.
fn mirror_follower(f: &Follower) -> Follower {
    let mp = |p: Point2| Point2::new(p.x, -p.y);
    let mv = |v: Vec2| Vec2::new(v.x, -v.y);
    let flip = |s: Sense| {
        if s == Sense::Ccw {
            Sense::Cw
        } else {
            Sense::Ccw
        }
    };
    match *f {
        Follower::TranslatingFlat { direction } => Follower::TranslatingFlat {
            direction: mv(direction),
        },
        Follower::TranslatingRoller {
            direction,
            offset,
            roller_radius,
        } => Follower::TranslatingRoller {
            direction: mv(direction),
            offset: -offset,
            roller_radius,
        },
        Follower::TranslatingKnife { direction, offset } => Follower::TranslatingKnife {
            direction: mv(direction),
            offset: -offset,
        },
        Follower::OscillatingFlat {
            pivot,
            face_offset,
            closing,
            initial_angle,
        } => Follower::OscillatingFlat {
            pivot: mp(pivot),
            face_offset: -face_offset,
            closing: flip(closing),
            initial_angle: -initial_angle,
        },
        Follower::OscillatingRoller {
            pivot,
            arm_length,
            roller_radius,
            closing,
            initial_angle,
        } => Follower::OscillatingRoller {
            pivot: mp(pivot),
            arm_length,
            roller_radius,
            closing: flip(closing),
            initial_angle: -initial_angle,
        },
        _ => unreachable!("the named kinds only"),
    }
}

/// The follower with every length (offsets, radii, arm, pivot) multiplied by `k`.
fn scale_follower(f: &Follower, k: f64) -> Follower {
    let sp = |p: Point2| Point2::from(p.coords * k);
    match *f {
        Follower::TranslatingFlat { direction } => Follower::TranslatingFlat { direction },
        Follower::TranslatingRoller {
            direction,
            offset,
            roller_radius,
        } => Follower::TranslatingRoller {
            direction,
            offset: k * offset,
            roller_radius: k * roller_radius,
        },
        Follower::TranslatingKnife { direction, offset } => Follower::TranslatingKnife {
            direction,
            offset: k * offset,
        },
        Follower::OscillatingFlat {
            pivot,
            face_offset,
            closing,
            initial_angle,
        } => Follower::OscillatingFlat {
            pivot: sp(pivot),
            face_offset: k * face_offset,
            closing,
            initial_angle,
        },
        Follower::OscillatingRoller {
            pivot,
            arm_length,
            roller_radius,
            closing,
            initial_angle,
        } => Follower::OscillatingRoller {
            pivot: sp(pivot),
            arm_length: k * arm_length,
            roller_radius: k * roller_radius,
            closing,
            initial_angle,
        },
        _ => unreachable!("the named kinds only"),
    }
}

/// The five followers of `all_followers` and the mirror images of its two oscillating ones,
/// which close counter-clockwise.
fn seven_followers(pivot: Point2) -> Vec<Follower> {
    let mut f = all_followers(pivot);
    let mirrored_pivot = Point2::new(pivot.x, -pivot.y);
    for k in [3, 4] {
        let m = mirror_follower(&all_followers(mirrored_pivot)[k]);
        f.push(m);
    }
    f
}

/// The random cam `nodes` turning either way (`ccw`) about one pivot with follower number `kind`
/// of [`seven_followers`], when it is convex (the cases below need it): `(pivot, follower,
/// mechanism)`.
fn convex_case(nodes: &[Point2], kind: usize, ccw: bool) -> Option<(Point2, Follower, Mechanism)> {
    let pivot = Point2::new(0.7, -0.4);
    let sense = if ccw { Sense::Ccw } else { Sense::Cw };
    let f = seven_followers(pivot)[kind].clone();
    let m = mechanism(
        Arc::new(ClosedSpline::new(nodes).unwrap()),
        pivot,
        sense,
        1000.0,
        f.clone(),
    );
    m.is_convex().then_some((pivot, f, m))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// For a translating flat-faced follower on a random convex cam, for any direction of
    /// travel, cam direction and axis: velocity and acceleration against differences of position.
    #[test]
    fn flat_face_motion_agrees_with_differences_on_random_convex_cams(
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
        let th = theta.to_radians();
        let s = m.analyze(th).unwrap();
        // against 8th-order differences of the follower's position (the first touch alone, no
        // velocity or acceleration formula), away from spline nodes (where the jerk jumps)
        // a step small enough for the sharply curved stretches of a random cam (the contact can
        // sweep a node spacing in a few degrees; at 5e-4 rad the differences' truncation reached
        // 9e-8 of the velocity on one), large enough for rounding: 1e-4 rad
        let h = 1e-4;
        let (lo, hi) = (m.analyze(th - 4.0 * h).unwrap(), m.analyze(th + 4.0 * h).unwrap());
        prop_assume!(lo.cam_param.floor() == s.cam_param.floor() && hi.cam_param.floor() == s.cam_param.floor());
        let (d1, d2) = fd8(|t| m.position(t).unwrap(), th, h);
        prop_assert!((s.velocity - w * d1).abs() <= 1e-8 * w * m.size(),
            "v = {}, by differences {}", s.velocity, w * d1);
        prop_assert!((s.acceleration - w * w * d2).abs() <= 1e-6 * w * w * m.size(),
            "a = {}, by differences {}", s.acceleration, w * w * d2);
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
        let case = convex_case(&nodes, kind, ccw);
        prop_assume!(case.is_some());
        let (pivot, f, m) = case.unwrap();
        let r = Rotation::new(beta);
        let nodes_r: Vec<Point2> = nodes.iter().map(|p| r * p).collect();
        let mr = Mechanism::new(
            camkin::cam::Cam::from_rpm(Arc::new(ClosedSpline::new(&nodes_r).unwrap()), r * pivot, m.cam().direction(), 1000.0).unwrap(),
            rotate_follower(&f, &r, beta),
        ).unwrap();
        let (a, b) = (m.analyze_deg(theta), mr.analyze_deg(theta));
        // a random cam may leave the follower's reach, but then in both placements alike
        prop_assert_eq!(a.is_ok(), b.is_ok(), "{:?} vs {:?}", a.as_ref().err(), b.as_ref().err());
        prop_assume!(a.is_ok());
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

    /// Mirroring the whole mechanism (`y → −y`) reverses the cam's sense and the closing sense:
    /// the same translating position, arm angles negated, rates alike. A cw cam or a ccw closing
    /// treated as its opposite fails this.
    #[test]
    fn the_mirror_image_moves_as_the_mirror_image(
        nodes in cam_nodes(),
        kind in 0usize..7,
        ccw in any::<bool>(),
        theta in 0.0f64..360.0,
    ) {
        let case = convex_case(&nodes, kind, ccw);
        prop_assume!(case.is_some());
        let (pivot, f, m) = case.unwrap();
        let nodes_m: Vec<Point2> = nodes.iter().map(|p| Point2::new(p.x, -p.y)).collect();
        let other = if ccw { Sense::Cw } else { Sense::Ccw };
        let mm = Mechanism::new(
            camkin::cam::Cam::from_rpm(Arc::new(ClosedSpline::new(&nodes_m).unwrap()), Point2::new(pivot.x, -pivot.y), other, 1000.0).unwrap(),
            mirror_follower(&f),
        ).unwrap();
        let (a, b) = (m.analyze_deg(theta), mm.analyze_deg(theta));
        prop_assert_eq!(a.is_ok(), b.is_ok(), "{:?} vs {:?}", a.as_ref().err(), b.as_ref().err());
        prop_assume!(a.is_ok());
        let (a, b) = (a.unwrap(), b.unwrap());
        let sg = if f.is_oscillating() { -1.0 } else { 1.0 };
        let w = m.cam().speed();
        let scale = m.size() + 10.0;
        let qb = if f.is_oscillating() { wrap_angle_near(-b.position, a.position) } else { b.position };
        prop_assert!((a.position - qb).abs() <= 1e-11 * scale, "q {} vs {}", a.position, qb);
        prop_assert!((a.velocity - sg * b.velocity).abs() <= 1e-10 * w * scale, "v {} vs {}", a.velocity, b.velocity);
        prop_assert!((a.acceleration - sg * b.acceleration).abs() <= 1e-9 * w * w * scale, "a {} vs {}", a.acceleration, b.acceleration);
        prop_assert!((a.contact_world.x - b.contact_world.x).abs() <= 1e-10 * scale);
        prop_assert!((a.contact_world.y + b.contact_world.y).abs() <= 1e-10 * scale);
    }

    /// On random convex cams, every follower (both closing senses) agrees with the support
    /// function at a random angle: position, velocity and acceleration, to the guide's figures.
    #[test]
    fn every_follower_agrees_with_the_support_function_on_random_convex_cams(
        nodes in cam_nodes(),
        kind in 0usize..7,
        ccw in any::<bool>(),
        theta in 0.0f64..360.0,
    ) {
        let case = convex_case(&nodes, kind, ccw);
        prop_assume!(case.is_some());
        let (_, _, m) = case.unwrap();
        let th = theta.to_radians();
        let a = m.analyze(th);
        prop_assume!(a.is_ok());
        let a = a.unwrap();
        // away from a spline node: beside one, the check's stencils are one-sided at its finest
        // steps and their rounding reaches 3e-10 of the peak velocity (the check's limit, not
        // the method's: the method across nodes is checked in `spline_finite_differences`)
        let piece = |t: f64| m.analyze(t).map(|s| s.cam_param.floor()).ok();
        prop_assume!(piece(th - 4e-3) == Some(a.cam_param.floor()) && piece(th + 4e-3) == Some(a.cam_param.floor()));
        let c = m.independent_check(&[th]).unwrap();
        prop_assert_eq!(c.angles, 1, "no stencil on a convex cam: {:?}", c);
        // the guide's claim is relative to the peaks over a revolution (a random cam's sharply
        // curved stretch can carry an acceleration of w² rad, where the differences' rounding
        // limits the check to about 1e-7 of it): the peaks on a 1° grid and at this angle
        let (mut vmax, mut amax) = (a.velocity.abs(), a.acceleration.abs());
        for k in 0..360 {
            if let Ok(s) = m.analyze(f64::from(k).to_radians()) {
                (vmax, amax) = (vmax.max(s.velocity.abs()), amax.max(s.acceleration.abs()));
            }
        }
        let (dv, da) = (c.velocity * a.velocity.abs(), c.acceleration * a.acceleration.abs());
        prop_assert!(c.position <= 2e-14, "{:?}", c);
        prop_assert!(dv <= 1e-10 * vmax, "{:?} at v = {}, peak {vmax}", c, a.velocity);
        prop_assert!(da <= 1e-7 * amax, "{:?} at a = {}, peak {amax}", c, a.acceleration);
    }
    /// Issue 12: scaling every length by any factor from 1e-99 to 1e98 scales positions,
    /// velocities and accelerations by it (arm angles unchanged), in single queries and in a
    /// sweep, for all seven followers: no tolerance, search step or test depends on the unit.
    #[test]
    fn scaling_every_length_scales_the_answers(
        nodes in cam_nodes(),
        exponent in -99.0f64..98.0,
        kind in 0usize..7,
        ccw in any::<bool>(),
        theta0 in 0.0f64..360.0,
    ) {
        let k = 10f64.powf(exponent);
        let case = convex_case(&nodes, kind, ccw);
        prop_assume!(case.is_some());
        let (pivot, f, m) = case.unwrap();
        let scaled: Vec<Point2> = nodes.iter().map(|p| Point2::from(p.coords * k)).collect();
        let ms = Mechanism::new(
            camkin::cam::Cam::from_rpm(Arc::new(ClosedSpline::new(&scaled).unwrap()), Point2::from(pivot.coords * k), m.cam().direction(), 1000.0).unwrap(),
            scale_follower(&f, k),
        ).unwrap();
        let lk = if f.is_oscillating() { 1.0 } else { k };
        let w = m.cam().speed();
        let scale = if f.is_oscillating() { 1.0 } else { m.size() + 10.0 };
        let (mut sw, mut sws) = (m.sweep(), ms.sweep());
        for j in 0..12 {
            let th = (theta0 + 2.0 * j as f64).to_radians();
            let (a, b) = (m.analyze(th), ms.analyze(th));
            prop_assert_eq!(a.is_ok(), b.is_ok(), "{:?} vs {:?}", a.as_ref().err(), b.as_ref().err());
            let (wa, wb) = (sw.step(th), sws.step(th));
            prop_assert_eq!(wa.is_ok(), wb.is_ok(), "{:?} vs {:?}", wa.as_ref().err(), wb.as_ref().err());
            for (a, b) in [(a, b), (wa, wb)] {
                let (Ok(a), Ok(b)) = (a, b) else { continue };
                prop_assert!((a.position - b.position / lk).abs() <= 1e-12 * scale, "q {} vs {} / {lk}", a.position, b.position);
                prop_assert!((a.velocity - b.velocity / lk).abs() <= 1e-11 * w * scale, "v {} vs {}", a.velocity, b.velocity / lk);
                prop_assert!((a.acceleration - b.acceleration / lk).abs() <= 1e-10 * w * w * scale, "a {} vs {}", a.acceleration, b.acceleration / lk);
            }
        }
    }

    /// Issue 12: rollers of any radius from 1e-9 to 3 times the cam's (a roller's reach beside
    /// its path can be far narrower than the profile's sample spacing), translating or
    /// oscillating, agree with the support function (crossings of the roller centre's path with
    /// the offset profile, by bisection) in single queries and in a 1° sweep.
    #[test]
    fn rollers_of_any_size_agree_with_the_support_function(
        nodes in cam_nodes(),
        exponent in -9.0f64..0.5,
        oscillating in any::<bool>(),
        ccw in any::<bool>(),
        theta0 in 0.0f64..360.0,
    ) {
        let r = 3.0 * 10f64.powf(exponent);
        let pivot = Point2::new(0.7, -0.4);
        let sense = if ccw { Sense::Ccw } else { Sense::Cw };
        let f = if oscillating {
            Follower::OscillatingRoller {
                pivot: pivot + Vec2::new(-3.0, 7.0 + r),
                arm_length: 9.0,
                roller_radius: r,
                closing: Sense::Cw,
                initial_angle: (-30f64).to_radians(),
            }
        } else {
            Follower::TranslatingRoller { direction: Vec2::new(0.3, 1.0), offset: 0.5, roller_radius: r }
        };
        let m = mechanism(Arc::new(ClosedSpline::new(&nodes).unwrap()), pivot, sense, 1000.0, f);
        prop_assume!(m.is_convex());
        let scale = if oscillating { 1.0 } else { m.size() + r };
        let mut sweep = m.sweep();
        for j in 0..20 {
            let th = (theta0 + j as f64).to_radians();
            let Some((q, _)) = m.support_position(th) else {
                prop_assert!(m.analyze(th).is_err(), "touches where the support function does not");
                continue;
            };
            let single = m.analyze(th);
            prop_assert!(single.is_ok(), "r = {r} at {}°: {:?}", th.to_degrees(), single.err());
            let warm = sweep.step(th);
            prop_assert!(warm.is_ok(), "r = {r} at {}°: {:?}", th.to_degrees(), warm.err());
            for s in [single.unwrap(), warm.unwrap()] {
                prop_assert!((s.position - q).abs() <= 1e-12 * scale, "r = {r} at {}°: q {} vs {q}", th.to_degrees(), s.position);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// Swapping A and B (a random convex spline cam and an ellipse, both moving) gives the same
    /// contact point and sliding rates, and the same constraint up to its sign.
    #[test]
    fn swapping_a_and_b_gives_same_contact_and_sliding_rates(
        nodes in cam_nodes(),
        ang_a in -3.0f64..3.0, ang_b in -3.0f64..3.0,
        wa in -10.0f64..10.0, wb in -10.0f64..10.0,
        va in (-3.0f64..3.0, -3.0f64..3.0),
        bearing in 0.0f64..std::f64::consts::TAU,
    ) {
        use camkin::body::{BodyState, Pose};
        use camkin::contact::{find_contact, refine, ContactKinematics, SearchOptions, Surface};
        use camkin::curve::{Curve, Ellipse};
        let sp = ClosedSpline::new(&nodes).unwrap();
        let el = Ellipse::new(Point2::new(0.2, -0.1), 1.5, 0.8, 0.3).unwrap();
        let opts = SearchOptions::for_length_scale(4.0);
        let a = BodyState { pose: Pose::new(Point2::origin(), ang_a), velocity: Vec2::new(va.0, va.1), omega: wa, acceleration: Vec2::zeros(), alpha: 0.0 };
        let mut b = BodyState { pose: Pose::new(Point2::new(9.0 * bearing.cos(), 9.0 * bearing.sin()), ang_b), velocity: Vec2::zeros(), omega: wb, acceleration: Vec2::zeros(), alpha: 0.0 };
        let p = find_contact(&Surface::new(&sp, &a), &Surface::new(&el, &b), &opts);
        prop_assume!(p.is_ok());
        let p = p.unwrap().pairing();
        prop_assume!(sp.curvature(p.u_a) > 0.0);
        b.pose.origin += p.gap * *p.normal; // bring B into contact
        let p = refine(&Surface::new(&sp, &a), &Surface::new(&el, &b), p.u_a, p.u_b, &opts).unwrap();
        let vn = p.normal.dot(&(a.velocity_at(p.point_a) - b.velocity_at(p.point_a)));
        b.velocity += vn * *p.normal; // sustained contact
        let (sa, sb) = (Surface::new(&sp, &a), Surface::new(&el, &b));
        let kab = ContactKinematics::new(&sa, &sb, &p, 1e-9).unwrap();
        let q = refine(&sb, &sa, p.u_b, p.u_a, &opts).unwrap();
        let kba = ContactKinematics::new(&sb, &sa, &q, 1e-9).unwrap();
        prop_assert!((q.point_a - p.point_b).norm() < 1e-10);
        let scale = 1.0 + kab.sliding_rate_a.abs() + kab.sliding_rate_b.abs();
        prop_assert!((kba.sliding_rate_a - kab.sliding_rate_b).abs() < 1e-10 * scale);
        prop_assert!((kba.sliding_rate_b - kab.sliding_rate_a).abs() < 1e-10 * scale);
        prop_assert_eq!(kab.sigma, kba.sigma);
        prop_assert!((kab.gamma.abs() - kba.gamma.abs()).abs() < 1e-9 * (1.0 + kab.gamma.abs()));
    }
}
