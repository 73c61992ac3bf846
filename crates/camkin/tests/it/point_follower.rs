//! A point carried by a general follower is a knife edge. On an arm (an oscillating knife):
//! against the closed form of an eccentric circular cam, the tip where its circle about the pivot
//! meets the cam's circle, its velocity and acceleration by implicit differentiation of that
//! meeting (no tangency condition, no Newton, no formula of the method); and against the support
//! function on the paper's cam. On a slide: the named translating knife on the point's line of
//! travel, its position moved by the point's lead. And what is refused, naming the field.

use crate::common::{eccentric_circle, mechanism, paper_profile};
use camkin::cam::{CamError, Follower, FollowerProfile, Mechanism, Sense};
use camkin::curve::PointCurve;
use camkin::{Point2, Vec2};
use std::f64::consts::PI;
use std::sync::Arc;

fn point(x: f64, y: f64) -> FollowerProfile {
    FollowerProfile(Arc::new(PointCurve::new(Point2::new(x, y)).unwrap()))
}

fn rot90(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// An arm about `o` carrying the point `tip` (arm frame) on a circle of radius `r` whose centre is
/// `(e, 0)` in the cam's frame, the cam about `p` turning in `sense`: the arm angle of first touch
/// at cam angle `theta` and its first two derivatives in `theta`. The tip `T = O + L t(φ + β)`
/// lies on the cam's circle: `g = |T − C(θ)|² − r² = 0`, `C = p + R(σθ)(e, 0)`. Of the two
/// meetings, the one the arm reaches first turning in its closing sense `κ` enters the circle
/// there (`κ ∂g/∂φ < 0`). Then `φ' = −g_θ/g_φ`, `φ'' = −(g_φφ φ'² + 2 g_φθ φ' + g_θθ)/g_φ`.
struct Arm {
    o: Point2,
    tip: Vec2,
    closing: Sense,
    phi0: f64,
}

fn arm_closed_form(
    arm: &Arm,
    (p, e, r): (Point2, f64, f64),
    sense: Sense,
    theta: f64,
) -> (f64, f64, f64) {
    let sigma = sense.sign();
    let (s, c) = (sigma * theta).sin_cos();
    let centre = p + Vec2::new(c * e, s * e);
    let l = arm.tip.norm();
    let beta = arm.tip.y.atan2(arm.tip.x);
    let kappa = arm.closing.sign();
    // circle–circle meeting: along the line of centres a from o, h across
    let dv = centre - arm.o;
    let d = dv.norm();
    let a = (l * l - r * r + d * d) / (2.0 * d);
    let h = (l * l - a * a).sqrt();
    let ex = dv / d;
    let c1 = centre - p; // C − p
    let dc = sigma * rot90(c1); // C'
    let ddc = -c1; // C''
    let mut best = None;
    for sgn in [1.0, -1.0] {
        let x = arm.o + a * ex + sgn * h * rot90(ex);
        let t = (x - arm.o) / l;
        let n = rot90(t);
        let w = x - centre;
        let g_phi = 2.0 * l * w.dot(&n);
        if kappa * g_phi >= 0.0 {
            continue;
        }
        let g_theta = -2.0 * w.dot(&dc);
        let g_pp = 2.0 * (l * l - l * w.dot(&t));
        let g_pt = -2.0 * l * dc.dot(&n);
        let g_tt = 2.0 * (dc.norm_squared() - w.dot(&ddc));
        let d1 = -g_theta / g_phi;
        let d2 = -(g_pp * d1 * d1 + 2.0 * g_pt * d1 + g_tt) / g_phi;
        let psi = t.y.atan2(t.x) - beta;
        let phi = arm.phi0 + (psi - arm.phi0 + PI).rem_euclid(2.0 * PI) - PI;
        best = Some((phi, d1, d2));
    }
    best.expect("the arm's circle meets the cam")
}

#[test]
fn oscillating_knife_on_an_eccentric_circle_matches_the_circles_meeting() {
    let (p, e, r) = (Point2::new(0.4, -0.2), 1.3, 4.0);
    let arms = [
        // a bent arm closing clockwise from above, the same mirrored closing counter-clockwise
        // from below, a straight one, and a point behind the pivot (an arm reaching back)
        Arm {
            o: Point2::new(-3.0, 8.0),
            tip: Vec2::new(8.6, -1.5),
            closing: Sense::Cw,
            phi0: -0.6,
        },
        Arm {
            o: Point2::new(-3.0, -8.0),
            tip: Vec2::new(8.6, 1.5),
            closing: Sense::Ccw,
            phi0: 0.6,
        },
        Arm {
            o: Point2::new(9.0, 1.0),
            tip: Vec2::new(8.0, 0.0),
            closing: Sense::Ccw,
            phi0: PI,
        },
        Arm {
            o: Point2::new(2.0, 9.5),
            tip: Vec2::new(-1.0, -8.5),
            closing: Sense::Ccw,
            phi0: 0.0,
        },
    ];
    let mut rows = 0;
    for arm in &arms {
        for sense in [Sense::Ccw, Sense::Cw] {
            let f = Follower::Rotating {
                pivot: arm.o,
                closing: arm.closing,
                initial_angle: arm.phi0,
                profile: point(arm.tip.x, arm.tip.y),
            };
            let m = mechanism(eccentric_circle(r, e), p, sense, 600.0, f);
            assert!(
                !m.carries_curve(),
                "a point is a knife edge, not a carried curve"
            );
            let w = m.cam().speed();
            let thetas: Vec<f64> = (0..720)
                .map(|k| f64::from(k) * 0.5f64.to_radians())
                .collect();
            let exact: Vec<_> = thetas
                .iter()
                .map(|&t| arm_closed_form(arm, (p, e, r), sense, t))
                .collect();
            let vmax = exact.iter().map(|x| (w * x.1).abs()).fold(0.0, f64::max);
            let amax = exact
                .iter()
                .map(|x| (w * w * x.2).abs())
                .fold(0.0, f64::max);
            let mut sweep = m.sweep();
            for (i, (&t, &(q, d1, d2))) in thetas.iter().zip(&exact).enumerate() {
                let warm = sweep.step(t).unwrap();
                let cold = (i % 10 == 3).then(|| m.analyze(t).unwrap());
                for s in [Some(warm), cold].into_iter().flatten() {
                    let what = format!("{:?} {sense:?} at {:.1}°", arm.o, t.to_degrees());
                    // the arm angle times its reach: a length, against the cam's size
                    let reach = arm.tip.norm();
                    assert!(
                        (s.position - q).abs() * reach <= 1e-12 * m.size(),
                        "{what}: φ {} vs {q}",
                        s.position
                    );
                    assert!(
                        (s.velocity - w * d1).abs() <= 1e-10 * vmax,
                        "{what}: φ̇ {} vs {}",
                        s.velocity,
                        w * d1
                    );
                    assert!(
                        (s.acceleration - w * w * d2).abs() <= 1e-9 * amax,
                        "{what}: φ̈ {} vs {}",
                        s.acceleration,
                        w * w * d2
                    );
                    // the contact is the tip, on the cam's circle
                    let (sn, cs) = s.position.sin_cos();
                    let tip = arm.o
                        + Vec2::new(
                            cs * arm.tip.x - sn * arm.tip.y,
                            sn * arm.tip.x + cs * arm.tip.y,
                        );
                    assert!(
                        (s.contact_world - tip).norm() <= 1e-11 * m.size(),
                        "{what}: contact"
                    );
                    rows += 1;
                }
            }
        }
    }
    assert_eq!(rows, 4 * 2 * (720 + 72));
}

/// The paper's cam (a spline, not a closed form) under an oscillating knife: the method against
/// the support function (the extreme crossing of the tip's circle with the profile by bisection,
/// velocity and acceleration by differences in the cam angle), both closing senses. The third arm
/// (its tip 95° off the arm's axis) was refused at 108° before the knife search took the path's
/// polar angle less the tip's for the arm angle.
#[test]
fn oscillating_knife_on_the_paper_cam_agrees_with_the_support_function() {
    for (o, tip, closing, phi0) in [
        (
            Point2::new(-3.0, 7.0),
            Vec2::new(8.6, -1.5),
            Sense::Cw,
            -0.5,
        ),
        // examples/oscillating-knife.toml
        (
            Point2::new(-8.0, 5.0),
            Vec2::new(8.6, -1.5),
            Sense::Cw,
            -0.5,
        ),
        (
            Point2::new(-3.0, -7.0),
            Vec2::new(8.6, 1.5),
            Sense::Ccw,
            0.5,
        ),
        (Point2::new(7.5, 0.5), Vec2::new(-0.5, 6.0), Sense::Ccw, 1.5),
    ] {
        let f = Follower::Rotating {
            pivot: o,
            closing,
            initial_angle: phi0,
            profile: point(tip.x, tip.y),
        };
        let m = mechanism(
            paper_profile(false),
            Point2::origin(),
            Sense::Ccw,
            1000.0,
            f,
        );
        let thetas: Vec<f64> = (0..180).map(|k| f64::from(k) * 2f64.to_radians()).collect();
        let check = m.independent_check(&thetas).unwrap();
        assert!(check.angles >= 150, "{check:?}");
        assert!(check.position <= 1e-12, "{o:?}: {check:?}");
        assert!(check.velocity <= 1e-9, "{o:?}: {check:?}");
        assert!(check.acceleration <= 1e-7, "{o:?}: {check:?}");
    }
}

/// A point at `(a, b)` on a slide (along the direction of travel, and to its left) is the named
/// knife on the line of travel offset by `e + b`, its frame's position `a` behind the tip's.
#[test]
fn translating_point_is_the_named_knife_moved_by_its_lead() {
    let profile = paper_profile(false);
    for (d, e, (a, b)) in [
        (Vec2::new(1.0, 0.0), 0.0, (0.0, 0.0)),
        (Vec2::new(-1.0, 0.2), -0.4, (1.5, 0.3)),
        (Vec2::new(0.3, 1.0), 0.7, (-2.0, -1.1)),
    ] {
        let general = Follower::Translating {
            direction: d,
            offset: e,
            profile: point(a, b),
        };
        let named = Follower::TranslatingKnife {
            direction: d,
            offset: e + b,
        };
        let (g, n) = (
            mechanism(
                profile.clone(),
                Point2::new(0.2, -0.1),
                Sense::Cw,
                600.0,
                general,
            ),
            mechanism(
                profile.clone(),
                Point2::new(0.2, -0.1),
                Sense::Cw,
                600.0,
                named,
            ),
        );
        let w = n.cam().speed();
        let (mut sg, mut sn) = (g.sweep(), n.sweep());
        for k in 0..360 {
            let t = f64::from(k).to_radians();
            let (x, y) = (sg.step(t).unwrap(), sn.step(t).unwrap());
            let what = format!("{d:?} ({a}, {b}) at {k}°");
            assert!(
                (x.position + a - y.position).abs() <= 1e-12 * n.size(),
                "{what}: s"
            );
            assert!(
                (x.velocity - y.velocity).abs() <= 1e-10 * w * n.size(),
                "{what}: v"
            );
            assert!(
                (x.acceleration - y.acceleration).abs() <= 1e-9 * w * w * n.size(),
                "{what}: a"
            );
            assert!(
                (x.contact_world - y.contact_world).norm() <= 1e-12 * n.size(),
                "{what}"
            );
        }
    }
}

/// A point on the pivot never moves; a point whose circle cannot reach the cam never touches it:
/// both refused, naming `follower.profile.at`.
#[test]
fn a_point_that_cannot_move_or_reach_is_refused_naming_its_field() {
    let arm = |tip: Vec2| Follower::Rotating {
        pivot: Point2::new(-3.0, 7.0),
        closing: Sense::Cw,
        initial_angle: 0.0,
        profile: point(tip.x, tip.y),
    };
    for tip in [Vec2::zeros(), Vec2::new(0.5, 0.0), Vec2::new(30.0, 0.0)] {
        let cam =
            camkin::cam::Cam::from_rpm(paper_profile(false), Point2::origin(), Sense::Ccw, 600.0)
                .unwrap();
        let err = Mechanism::new(cam, arm(tip)).unwrap_err();
        assert!(
            matches!(
                &err,
                CamError::InvalidVector { .. } | CamError::Unreachable { .. }
            ) && err.to_string().contains("follower.profile.at"),
            "{tip:?}: {err}"
        );
    }
}
