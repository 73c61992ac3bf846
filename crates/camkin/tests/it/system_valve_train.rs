//! Issue 45: a single-valve train as a system ([`camkin::reference::single_valve_train`]; the
//! geometry restated here for the reference) — a camshaft (an offset ellipse, 15 × 20 mm, its
//! centre 4 mm below the axis: one lobe) above a roller finger follower pivoting on a lash
//! adjuster's ball, its 6 mm roller on the cam and its pad (a 15 mm arc) on the flat tip of a
//! valve sliding in its guide: three moving bodies, two contacts. Checked against a reference
//! that shares no formula with the method: the finger's angle by bisection on the roller
//! centre's distance from the cam (nearest point by dense sampling and golden-section search),
//! the valve's position from the pad's lowest point, and their rates by five-point differences;
//! the rocker ratio at full lift against the lever arms' closed form.

use camkin::system::SystemState;
use camkin::{Point2, Vec2};
use std::f64::consts::TAU;

/// The lash adjuster's ball: the finger's pivot, world.
const PIVOT: [f64; 2] = [-35.0, -30.0];
/// The roller's centre and radius, finger frame.
const ROLLER: ([f64; 2], f64) = ([35.0, 0.0], 6.0);
/// The pad's centre and radius, finger frame.
const PAD: ([f64; 2], f64) = ([60.0, 12.0], 15.0);
/// The valve's line of travel, x (world).
const VALVE_X: f64 = 25.0;
/// The cam: semi-axes along x and y, and its centre below the axis (cam frame).
const CAM: (f64, f64, f64) = (15.0, 20.0, -4.0);

/// A finger-frame point in the world at finger angle `phi`.
fn on_finger(p: [f64; 2], phi: f64) -> Vec2 {
    let (s, c) = phi.sin_cos();
    Vec2::new(
        PIVOT[0] + c * p[0] - s * p[1],
        PIVOT[1] + s * p[0] + c * p[1],
    )
}

/// The signed distance from world point `x` to the cam turned by `theta` (negative inside):
/// the nearest of 4096 samples of the ellipse, refined by golden-section search.
fn cam_distance(x: Vec2, theta: f64) -> f64 {
    let (s, c) = theta.sin_cos();
    // into the cam's frame
    let p = Vec2::new(c * x.x + s * x.y, -s * x.x + c * x.y);
    let (a, b, yc) = CAM;
    let d = |u: f64| (Vec2::new(a * u.cos(), yc + b * u.sin()) - p).norm();
    let n = 512;
    let k = (0..n)
        .min_by(|&i, &j| d(TAU * i as f64 / n as f64).total_cmp(&d(TAU * j as f64 / n as f64)))
        .unwrap();
    let (mut lo, mut hi) = (
        TAU * (k as f64 - 1.0) / n as f64,
        TAU * (k as f64 + 1.0) / n as f64,
    );
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..80 {
        let (m1, m2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if d(m1) < d(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    let dist = d(0.5 * (lo + hi));
    let inside = (p.x / a).powi(2) + ((p.y - yc) / b).powi(2) < 1.0;
    if inside {
        -dist
    } else {
        dist
    }
}

/// The finger's angle at cam angle `theta`: the roller's centre at its radius from the cam, by
/// bisection (the roller rises into the cam as the finger turns counter-clockwise).
fn finger_angle(theta: f64) -> f64 {
    let f = |phi: f64| cam_distance(on_finger(ROLLER.0, phi), theta) - ROLLER.1;
    let (mut lo, mut hi) = (-0.05, 0.4);
    assert!(f(lo) > 0.0 && f(hi) < 0.0);
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        if m <= lo || m >= hi {
            break;
        }
        if f(m) > 0.0 {
            lo = m;
        } else {
            hi = m;
        }
    }
    0.5 * (lo + hi)
}

/// The valve tip's height at finger angle `phi`: under the pad's lowest point.
fn valve_height(phi: f64) -> f64 {
    on_finger(PAD.0, phi).y - PAD.1
}

/// First and second derivatives from five values at spacing `h` (the middle one's).
fn five_point(v: &[f64], h: f64) -> (f64, f64) {
    let (m2, m1, z, p1, p2) = (v[0], v[1], v[2], v[3], v[4]);
    (
        (m2 - 8.0 * m1 + 8.0 * p1 - p2) / (12.0 * h),
        (-m2 + 16.0 * m1 - 30.0 * z + 16.0 * p1 - p2) / (12.0 * h * h),
    )
}

#[test]
fn a_single_valve_train_follows_its_independent_reference() {
    let w = 3000.0 * TAU / 60.0;
    let (sys, [_, finger, valve]) = camkin::reference::single_valve_train(w);
    let mut sweep = sys.sweep().unwrap();
    let size = 100.0;
    let steps = 180;
    let mut rows: Vec<(f64, SystemState, [f64; 6])> = Vec::new();
    let (mut vpeak, mut apeak) = ([0.0f64; 2], [0.0f64; 2]);
    for k in 0..steps {
        let theta = TAU * f64::from(k) / f64::from(steps);
        let s = sweep.step(theta / w).unwrap();
        // the reference at five instants around this one, in time
        let t = theta / w;
        let h = 1e-3 / w;
        let phis: Vec<f64> = (-2..=2)
            .map(|j| finger_angle(w * (t + f64::from(j) * h)))
            .collect();
        let ys: Vec<f64> = phis.iter().map(|&p| valve_height(p)).collect();
        let (dphi, ddphi) = five_point(&phis, h);
        let (dy, ddy) = five_point(&ys, h);
        vpeak = [vpeak[0].max(dphi.abs()), vpeak[1].max(dy.abs())];
        apeak = [apeak[0].max(ddphi.abs()), apeak[1].max(ddy.abs())];
        rows.push((theta, s, [phis[2], dphi, ddphi, ys[2], dy, ddy]));
    }
    // the valve opens about 16 mm: the lobe's 8 mm over its least reach, times about 2 (the
    // rocker ratio as the finger turns)
    let lift = rows
        .iter()
        .map(|r| r.2[3])
        .fold(f64::NEG_INFINITY, f64::max)
        - rows.iter().map(|r| r.2[3]).fold(f64::INFINITY, f64::min);
    assert!(lift > 12.0 && lift < 20.0, "{lift}");
    for (theta, s, r) in &rows {
        let what = format!("at {:.0}°", theta.to_degrees());
        let f = &s.bodies[finger.index().unwrap()];
        let v = &s.bodies[valve.index().unwrap()];
        assert!(
            (f.pose.angle - r[0]).abs() * size <= 1e-12 * size,
            "{what}: φ {} {}",
            f.pose.angle,
            r[0]
        );
        assert!(
            (f.omega - r[1]).abs() <= 1e-9 * vpeak[0],
            "{what}: φ̇ {} {}",
            f.omega,
            r[1]
        );
        assert!(
            (f.alpha - r[2]).abs() <= 1e-7 * apeak[0],
            "{what}: φ̈ {} {}",
            f.alpha,
            r[2]
        );
        assert!(
            (v.pose.origin.y - r[3]).abs() <= 1e-12 * size,
            "{what}: y {} {}",
            v.pose.origin.y,
            r[3]
        );
        assert!((v.pose.origin.x - VALVE_X).abs() <= 1e-12 * size);
        assert!(
            (v.velocity.y - r[4]).abs() <= 1e-9 * vpeak[1],
            "{what}: ẏ {} {}",
            v.velocity.y,
            r[4]
        );
        assert!(
            (v.acceleration.y - r[5]).abs() <= 1e-7 * apeak[1],
            "{what}: ÿ {} {}",
            v.acceleration.y,
            r[5]
        );
        for c in &s.contacts {
            assert!(c.pairing.gap.abs() <= 1e-12 * size, "{what}");
            assert!(!c.jumped, "{what}");
        }
    }
    // full lift at θ = 0 (the lobe straight down, the finger level): the finger is at rest, so
    // the valve's acceleration over the roller centre's (both vertical) is the lever arms'
    // ratio, 60/35, exactly
    let s = &rows[0].1;
    let f = &s.bodies[finger.index().unwrap()];
    assert!(f.pose.angle.abs() <= 1e-12 && f.omega.abs() <= 1e-9 * vpeak[0]);
    let roller = f.pose.to_world(Point2::new(ROLLER.0[0], ROLLER.0[1]));
    let ratio = s.bodies[valve.index().unwrap()].acceleration.y / f.acceleration_at(roller).y;
    assert!((ratio - 60.0 / 35.0).abs() <= 1e-9, "{ratio}");
}
