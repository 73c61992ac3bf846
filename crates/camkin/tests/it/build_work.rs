//! Issue 44: the memory a mechanism's search indexes hold is estimated before they are built
//! ([`camkin::cam::build_work`]), and that estimate is checked here against the bytes actually
//! allocated while building, counted by this test binary's allocator on the building thread:
//! large spline cams under a named follower and under a carried curve, a carried spline, a gear
//! pair. The estimate must not be below the measurement, nor more than three times it.

use crate::common::eccentric_circle;
use crate::general_follower::gear_pair;
use camkin::cam::{Cam, Follower, FollowerProfile, Mechanism, Sense};
use camkin::curve::{Circle, ClosedSpline, Curve};
use camkin::{Point2, Vec2};
use peakmem_alloc::{PeakMemAlloc, PeakMemAllocTrait, INSTRUMENTED_SYSTEM};
use std::alloc::System;
use std::sync::Arc;

/// The system allocator, counting the most bytes held since the last reset (every thread's:
/// the measurement runs in a process of its own, see below).
#[global_allocator]
static ALLOCATOR: &PeakMemAlloc<System> = &INSTRUMENTED_SYSTEM;

/// The most bytes held at once while `f` runs, above what was held before.
fn peak_bytes<T>(f: impl FnOnce() -> T) -> (T, f64) {
    ALLOCATOR.reset_peak_memory();
    let out = f();
    (out, ALLOCATOR.get_peak_memory() as f64)
}

fn ellipse_spline(n: usize, a: f64, b: f64, centre: Vec2) -> Arc<dyn Curve> {
    let nodes: Vec<Point2> = (0..n)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / n as f64;
            Point2::from(centre + Vec2::new(a * t.cos(), b * t.sin()))
        })
        .collect();
    Arc::new(ClosedSpline::new(&nodes).unwrap())
}

/// Runs the measurement below alone, in a process of its own (this test binary again, one test,
/// one thread), so that no other test's allocations are counted.
#[test]
fn build_estimates_bound_the_measured_memory() {
    let out = std::process::Command::new(std::env::current_exe().unwrap())
        .args([
            "build_work::measured_alone",
            "--exact",
            "--ignored",
            "--test-threads=1",
            "--nocapture",
        ])
        .output()
        .unwrap();
    let text =
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{text}");
    assert!(text.contains("1 passed"), "{text}");
}

#[test]
#[ignore = "run alone by build_estimates_bound_the_measured_memory"]
fn measured_alone() {
    let big_cam = || {
        Cam::from_rpm(
            ellipse_spline(20_000, 50.0, 40.0, Vec2::zeros()),
            Point2::origin(),
            Sense::Ccw,
            1000.0,
        )
        .unwrap()
    };
    let small_cam = || {
        Cam::from_rpm(
            eccentric_circle(20.0, 5.0),
            Point2::origin(),
            Sense::Ccw,
            1000.0,
        )
        .unwrap()
    };
    let crowned = Follower::Translating {
        direction: Vec2::x(),
        offset: 0.0,
        profile: FollowerProfile(Arc::new(Circle::new(Point2::new(60.0, 0.0), 60.0).unwrap())),
    };
    let carried_spline = Follower::Translating {
        direction: Vec2::x(),
        offset: 0.0,
        profile: FollowerProfile(ellipse_spline(20_000, 8.0, 5.0, Vec2::new(8.0, 0.0))),
    };
    let roller = Follower::TranslatingRoller {
        direction: Vec2::x(),
        offset: 3.0,
        roller_radius: 10.0,
    };
    let (gears, _) = gear_pair(20, 42);
    let cases: Vec<(&str, Cam, Follower)> = vec![
        ("20 000-node spline cam, roller", big_cam(), roller),
        ("20 000-node spline cam, carried circle", big_cam(), crowned),
        (
            "eccentric cam, carried 20 000-node spline",
            small_cam(),
            carried_spline,
        ),
        (
            "20/42 gear pair",
            gears.cam().clone(),
            gears.follower().clone(),
        ),
    ];
    for (name, cam, follower) in cases {
        let estimate = camkin::cam::build_work(&cam, &follower, None).bytes;
        let (m, measured) = peak_bytes(|| Mechanism::new(cam, follower).unwrap());
        drop(m);
        println!("{name}: estimated {estimate:.3e} bytes, measured {measured:.3e}");
        assert!(
            estimate >= measured && estimate <= 3.0 * measured,
            "{name}: estimated {estimate:.3e} bytes, measured {measured:.3e}"
        );
    }
}
