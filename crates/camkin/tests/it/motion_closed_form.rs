//! The motion-only path (`Mechanism::motion`, `Sweep::step_motion`) computes the follower's
//! velocity and acceleration and the cam parameter's rate by closed forms of each named kind
//! (the tangency conditions differentiated in time), sharing no formula with the paper's method
//! that `analyze` and `Sweep::step` use. The two must agree to 1e-13 of each quantity's scale
//! (size·ωᵏ, or ωᵏ for an arm's angle) at every angle, cold and warm, in both senses, with the
//! cam speeding up, on convex and non-convex cams.

use super::common::{all_followers, eccentric_circle, ellipse, paper_profile};
use camkin::cam::{Cam, Follower, Mechanism, Motion, Sense};
use camkin::curve::{ClosedSpline, Curve};
use camkin::Point2;
use std::sync::Arc;

/// A three-lobed cam, concave between the lobes (the flat faces and rollers skip the hollows).
fn lobed() -> Arc<dyn Curve> {
    let pts: Vec<Point2> = (0..60)
        .map(|i| {
            let t = std::f64::consts::TAU * f64::from(i) / 60.0;
            let r = 4.0 * (1.0 + 0.12 * (3.0 * t).sin());
            Point2::new(r * t.cos() + 0.3, r * t.sin() - 0.2)
        })
        .collect();
    Arc::new(ClosedSpline::new(&pts).unwrap())
}

fn cams() -> Vec<(&'static str, Arc<dyn Curve>)> {
    vec![
        ("paper", paper_profile(false)),
        ("paper revised", paper_profile(true)),
        ("eccentric circle", eccentric_circle(4.0, 1.25)),
        ("ellipse", ellipse(4.5, 3.0, Point2::new(0.4, -0.3), 0.3)),
        ("lobed", lobed()),
    ]
}

/// `|motion − analyze| ≤ 1e-13 · scale` for the rates (the position and the cam parameter are
/// the same numbers: the same contact).
fn assert_agree(m: &Mechanism, got: &Motion, want: &camkin::cam::FollowerState, what: &str) {
    let w = m.cam().speed();
    let len = if m.follower().is_oscillating() {
        1.0
    } else {
        m.size()
    };
    let checks = [
        ("position", got.position, want.position, len),
        ("velocity", got.velocity, want.velocity, len * w),
        (
            "acceleration",
            got.acceleration,
            want.acceleration,
            len * w * w,
        ),
        ("cam parameter", got.cam_param, want.cam_param, m.size()),
    ];
    for (name, a, b, scale) in checks {
        assert!(
            (a - b).abs() <= 1e-13 * scale,
            "{what}: {name} {a} (closed form) vs {b} (paper's method), |diff| = {:e}, allowed {:e}",
            (a - b).abs(),
            1e-13 * scale
        );
    }
    // the parameter's rate: relative to the largest it can be, ω times the cam's length over
    // its parameter range near the contact (|u̇| ≤ ω·size/|x'| would be loose on a slow spot)
    let scale = want.cam_param_rate.abs().max(w);
    assert!(
        (got.cam_param_rate - want.cam_param_rate).abs() <= 1e-12 * scale,
        "{what}: cam parameter rate {} vs {}",
        got.cam_param_rate,
        want.cam_param_rate
    );
    assert_eq!(got.found, want.found, "{what}: found");
}

/// Both paths answer and agree ([`assert_agree`]), or both refuse with the same error; true
/// when they answered.
fn agree_or_refuse_alike(
    m: &Mechanism,
    motion: Result<Motion, camkin::cam::CamError>,
    state: Result<camkin::cam::FollowerState, camkin::cam::CamError>,
    what: &str,
) -> bool {
    match (motion, state) {
        (Ok(a), Ok(b)) => {
            assert_agree(m, &a, &b, what);
            true
        }
        (Err(a), Err(b)) => {
            assert_eq!(a.to_string(), b.to_string(), "{what}");
            false
        }
        (a, b) => panic!("{what}: {a:?} vs {b:?}"),
    }
}

#[test]
fn motion_closed_forms_agree_with_the_papers_method() {
    let mut compared = 0;
    for (cam_name, profile) in cams() {
        for sense in [Sense::Ccw, Sense::Cw] {
            for f in all_followers(Point2::origin()) {
                let cam = Cam::from_rpm(profile.clone(), Point2::origin(), sense, 600.0)
                    .unwrap()
                    .with_angular_acceleration(40.0)
                    .unwrap();
                let kind = f.kind_name();
                let Ok(m) = Mechanism::new(cam, f) else {
                    panic!("{cam_name}, {kind}: refused");
                };
                // warm: a sweep in 0.5° steps, both paths side by side
                let (mut fast, mut full) = (m.sweep(), m.sweep());
                for k in 0..720 {
                    let th = (f64::from(k) * 0.5).to_radians();
                    let what = format!(
                        "{cam_name}, {sense:?}, {kind}, warm at {:.1}°",
                        th.to_degrees()
                    );
                    compared += usize::from(agree_or_refuse_alike(
                        &m,
                        fast.step_motion(th),
                        full.step(th),
                        &what,
                    ));
                }
                // cold: irregular angles
                for k in 0..90 {
                    let th = (f64::from(k) * 4.123).to_radians();
                    let what = format!(
                        "{cam_name}, {sense:?}, {kind}, cold at {:.3}°",
                        th.to_degrees()
                    );
                    compared += usize::from(agree_or_refuse_alike(
                        &m,
                        m.motion(th),
                        m.analyze(th),
                        &what,
                    ));
                }
            }
        }
    }
    // every row is a contact: 5 cams, 2 senses, 5 kinds, 720 warm and 90 cold angles
    assert_eq!(compared, 40_500, "rows compared");
}

/// Near a lock the rates grow without bound and both paths lose digits to the same
/// ill-conditioning: a roller whose line of travel grazes an eccentric circle at 30°, where the
/// contact normal is perpendicular to the travel. The closed forms decline within 4× the lock
/// tolerance and leave the refusal to the method; elsewhere both agree to 1e-13 of the rates'
/// own size times the conditioning `1 / cos(pressure angle)`.
#[test]
fn motion_near_a_lock_agrees_or_refuses_alike() {
    // circle radius 3 about (1, 0) on the cam; roller radius 0.5 on the line y = 4: at 30° the
    // circle's centre is at height 0.5 and its top at 3.5 below the roller's line
    let m = Mechanism::new(
        Cam::from_rpm(
            eccentric_circle(3.0, 1.0),
            Point2::origin(),
            Sense::Ccw,
            60.0,
        )
        .unwrap(),
        Follower::TranslatingRoller {
            direction: camkin::Vec2::x(),
            offset: 4.0,
            roller_radius: 0.5,
        },
    )
    .unwrap();
    let (mut compared, mut refused, mut worst) = (0, 0, 0.0f64);
    // from a radian past the lock down to it (the roller meets the circle from 30° to 150°)
    for j in 0..=64 {
        let th = 30f64.to_radians() + 10f64.powf(-f64::from(j) / 4.0);
        match (m.motion(th), m.analyze(th)) {
            (Ok(a), Ok(b)) => {
                let cond = 1.0 / b.pressure_angle().cos().abs();
                let w = m.cam().speed();
                for (name, x, y, s) in [
                    ("velocity", a.velocity, b.velocity, m.size() * w),
                    (
                        "acceleration",
                        a.acceleration,
                        b.acceleration,
                        m.size() * w * w,
                    ),
                ] {
                    // the contact's position is good to about ε·size; near the lock the
                    // rates' relative sensitivity to it is about the conditioning
                    let tol = (1e-13 + 1e-14 * cond) * (y.abs() + s);
                    assert!(
                        (x - y).abs() <= tol,
                        "{name} at {th} rad: {x} vs {y}, cond {cond:e}"
                    );
                    worst = worst.max((x - y).abs() / (y.abs() + s) / cond);
                }
                compared += 1;
            }
            (Err(a), Err(b)) => {
                assert_eq!(a.to_string(), b.to_string());
                refused += 1;
            }
            (a, b) => panic!("at {th} rad: {a:?} vs {b:?}"),
        }
    }
    eprintln!("near the lock: {compared} compared, {refused} refused alike, worst difference {worst:e} × conditioning");
    assert!(compared >= 30, "{compared}");
}
