//! A circular cam with every follower type against closed forms (differentiated exactly with
//! hyper-dual numbers), for both cam directions and a cam axis away from the origin.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Sense};
use camkin::{Point2, Vec2};

const RC: f64 = 4.0;

/// World centre of the cam circle at cam angle θ: P + R(sθ) c0.
fn centre(theta: HD, pivot: Point2, c0: Vec2, s: f64) -> (HD, HD) {
    let a = s * theta;
    let (c, sn) = (a.cos(), a.sin());
    (
        c0.x * c - c0.y * sn + pivot.x,
        c0.x * sn + c0.y * c + pivot.y,
    )
}

/// The follower position as a closed form of the cam angle.
fn closed_form(f: &Follower, theta: HD, pivot: Point2, c0: Vec2, s: f64) -> HD {
    let (cx, cy) = centre(theta, pivot, c0, s);
    let (yx, yy) = (cx + (-pivot.x), cy + (-pivot.y));
    let translating = |d: Vec2, off: f64, r: f64| {
        let d = d.normalize();
        let p = Vec2::new(-d.y, d.x);
        let a = d.x * yx + d.y * yy;
        let b = p.x * yx + p.y * yy + (-off);
        a + (HD::c((RC + r) * (RC + r)) - b * b).sqrt()
    };
    match *f {
        Follower::TranslatingFlat { direction } => {
            let d = direction.normalize();
            d.x * yx + d.y * yy + RC
        }
        Follower::TranslatingRoller {
            direction,
            offset,
            roller_radius,
        } => translating(direction, offset, roller_radius),
        Follower::TranslatingKnife { direction, offset } => translating(direction, offset, 0.0),
        Follower::OscillatingFlat {
            pivot: o,
            face_offset,
            closing,
            ..
        } => {
            let k = -closing.sign(); // +1 for cw closing: the cam lies on the −n side
            let (wx, wy) = (cx + (-o.x), cy + (-o.y));
            let rho = (wx * wx + wy * wy).sqrt();
            HD::atan2(wy, wx) - (HD::c(face_offset - k * RC) / rho).asin()
        }
        Follower::OscillatingRoller {
            pivot: o,
            arm_length: l,
            roller_radius: r,
            closing,
            ..
        } => {
            let k = -closing.sign();
            let (wx, wy) = (cx + (-o.x), cy + (-o.y));
            let rho2 = wx * wx + wy * wy;
            let rho = rho2.sqrt();
            let c = (rho2 + (l * l - (RC + r) * (RC + r))) / (2.0 * l * rho);
            HD::atan2(wy, wx) + k * c.acos()
        }
        _ => unreachable!("the named kinds only"),
    }
}

/// The five followers, plus the oscillating ones closing counter-clockwise (their arm below the
/// cam, the mirror image of `all_followers`' arms, on the branch near +30°).
fn followers(pivot: Point2) -> Vec<Follower> {
    let mut v = all_followers(pivot);
    v.push(Follower::OscillatingFlat {
        pivot: pivot + Vec2::new(-3.0, -7.0),
        face_offset: 0.5,
        closing: Sense::Ccw,
        initial_angle: 30f64.to_radians(),
    });
    v.push(Follower::OscillatingRoller {
        pivot: pivot + Vec2::new(-3.0, -7.0),
        arm_length: 9.0,
        roller_radius: 1.0,
        closing: Sense::Ccw,
        initial_angle: 30f64.to_radians(),
    });
    v
}

fn check(pivot: Point2, dir: Sense, c0: Vec2) {
    for f in followers(pivot) {
        let m = mechanism(
            std::sync::Arc::new(camkin::curve::Circle::new(Point2::from(c0), RC).unwrap()),
            pivot,
            dir,
            1000.0,
            f.clone(),
        );
        let w = m.cam().speed();
        let mut checked = 0;
        for k in 0..36 {
            let th = (k as f64 * 10.0 + 2.5).to_radians();
            let s = m
                .analyze(th)
                .unwrap_or_else(|e| panic!("{}: {e}", f.kind_name()));
            let cf = closed_form(&f, HD::var(th), pivot, c0, dir.sign());
            let phi = if f.is_oscillating() {
                camkin::geometry::wrap_angle_near(cf.v, s.position)
            } else {
                cf.v
            };
            let name = f.kind_name();
            assert_close(s.position, phi, 1e-12, 10.0, &format!("{name} q at {k}"));
            assert_close(
                s.velocity,
                w * cf.d1,
                1e-11,
                w * 10.0,
                &format!("{name} v at {k}"),
            );
            assert_close(
                s.acceleration,
                w * w * cf.d2,
                1e-11,
                w * w * 10.0,
                &format!("{name} a at {k}"),
            );
            checked += 1;
        }
        assert_eq!(checked, 36);
    }
}

#[test]
fn all_followers_on_eccentric_circle_ccw() {
    check(Point2::origin(), Sense::Ccw, Vec2::new(1.0, 0.0));
}

#[test]
fn all_followers_on_eccentric_circle_cw_axis_elsewhere() {
    check(Point2::new(2.0, -1.0), Sense::Cw, Vec2::new(0.6, -0.8));
}

/// Issue 12 (a paper cam under a 0.01 roller failed at most angles; a thin cam under a small
/// roller "does not touch"): a roller's reach beside its path can be far narrower than the
/// profile's sample spacing. Rollers from 1e-9 to 1e3 times the cam's radius, translating (two
/// offsets) and oscillating, single queries and a 1° sweep, against the closed form.
#[test]
fn tiny_and_huge_rollers_on_an_eccentric_circle_match_the_closed_form() {
    let (pivot, c0) = (Point2::new(0.5, -0.3), Vec2::new(0.6, -0.8));
    for r in [1e-9, 1e-6, 1e-3, 0.05, 1e3] {
        let mut fs = vec![
            Follower::TranslatingRoller {
                direction: Vec2::new(0.0, 1.0),
                offset: 0.0,
                roller_radius: r,
            },
            Follower::TranslatingRoller {
                direction: Vec2::new(1.0, 1.0),
                offset: -0.7 * RC,
                roller_radius: r,
            },
        ];
        if r < 1.0 {
            fs.push(Follower::OscillatingRoller {
                pivot: pivot + Vec2::new(-3.0, 7.0),
                arm_length: 9.0,
                roller_radius: r,
                closing: Sense::Cw,
                initial_angle: (-30f64).to_radians(),
            });
        }
        for f in fs {
            for dir in [Sense::Ccw, Sense::Cw] {
                let m = mechanism(
                    std::sync::Arc::new(camkin::curve::Circle::new(Point2::from(c0), RC).unwrap()),
                    pivot,
                    dir,
                    1000.0,
                    f.clone(),
                );
                let w = m.cam().speed();
                let name = format!("{} r = {r} {dir:?}", f.kind_name());
                let scale = RC + r;
                let mut sweep = m.sweep();
                for k in 0..360 {
                    let th = (k as f64 + 0.25).to_radians();
                    let cf = closed_form(&f, HD::var(th), pivot, c0, dir.sign());
                    let single = m
                        .analyze(th)
                        .unwrap_or_else(|e| panic!("{name} at {k}°: {e}"));
                    let warm = sweep
                        .step(th)
                        .unwrap_or_else(|e| panic!("{name} sweep at {k}°: {e}"));
                    for (how, s) in [("single", single), ("sweep", warm)] {
                        let phi = if f.is_oscillating() {
                            camkin::geometry::wrap_angle_near(cf.v, s.position)
                        } else {
                            cf.v
                        };
                        let what = format!("{name} {how} at {k}°");
                        assert_close(s.position, phi, 1e-12, scale, &format!("{what} q"));
                        assert_close(
                            s.velocity,
                            w * cf.d1,
                            1e-11,
                            w * scale,
                            &format!("{what} v"),
                        );
                        assert_close(
                            s.acceleration,
                            w * w * cf.d2,
                            1e-10,
                            w * w * scale,
                            &format!("{what} a"),
                        );
                    }
                }
            }
        }
    }
}
