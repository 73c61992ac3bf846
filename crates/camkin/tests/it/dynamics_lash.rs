//! Issue 65, "lash and ramps": `examples/bucket-lash.toml`, a rigid bucket on its valve with a
//! lash `c` below a cam whose clearance ramps (`law = "ramp"`, rise `h` over `β`) take it up,
//! against the ramp's closed form: its lift `h y(x)` with `y = 1/6 + 4/3 (x − 1/4)` over its
//! middle half and `y = V b (u²/2 + (cos 2πu − 1)/4π²)` (`u = x/b`, `b = 1/4`, `V = 4/3`) in its
//! first blend, its rate `h y'(x)/β`. The cam meets the bucket where the ramp's lift is `c`, at
//! the cam's speed times the ramp's rate there; the valve seats at the mirror angle at the same
//! speed; the seat lets go at the take-up and the cam at the seating.

use crate::common::read_system;
use camkin::dynamics::EventKind;
use camkin::spec::BuildOptions;
use std::f64::consts::{PI, TAU};

/// The ramp: rise (mm) and extent (rad); the lift's whole extent before the closing ramp ends
/// (ramps, rise and return: 260°); the cam's speed (rad/s).
const H: f64 = 0.3;
const BETA_DEG: f64 = 30.0;
const TOTAL_DEG: f64 = 260.0;
const RPM: f64 = 1500.0;

/// The ramp's normalised lift and rate at `x ∈ [0, 1]` (symmetric about its middle:
/// `y(x) = 1 − y(1 − x)`).
fn ramp(x: f64) -> (f64, f64) {
    if x > 0.5 {
        let (y, v) = ramp(1.0 - x);
        return (1.0 - y, v);
    }
    let (b, v) = (0.25, 4.0 / 3.0);
    if x >= b {
        (1.0 / 6.0 + v * (x - b), v)
    } else {
        let u = x / b;
        (
            v * b * (0.5 * u * u + ((TAU * u).cos() - 1.0) / (TAU * TAU)),
            v * (u - (TAU * u).sin() / TAU),
        )
    }
}

/// The cam angle (°) at which the ramp's lift is `c` (bisection on the closed form) and the
/// take-up speed there, mm/s.
fn take_up(c: f64) -> (f64, f64) {
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if H * ramp(mid).0 < c {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let x = 0.5 * (lo + hi);
    let beta = BETA_DEG.to_radians();
    let w = RPM * TAU / 60.0;
    (x * BETA_DEG, w * H * ramp(x).1 / beta)
}

/// Whether the lash `c` (mm) is taken up on the ramps' constant-velocity part.
fn in_band(c: f64) -> bool {
    (H / 6.0..=5.0 * H / 6.0).contains(&c)
}

/// The example with the lash `c` (mm): the bucket, the seat and the spring's anchor moved down
/// by `c` from the base circle.
fn with_lash(c: f64) -> camkin::spec::BuiltSystem {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/bucket-lash.toml");
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("-20.1]", &format!("{}]", -20.0 - c))
        .replace("-80.1]", &format!("{}]", -80.0 - c))
        .replace("-60.1]", &format!("{}]", -60.0 - c));
    read_system(&text, "bucket-lash.toml", &BuildOptions::default()).unwrap()
}

/// Over a lash sweep — in the ramps' constant-velocity band (1/6 to 5/6 of 0.3 mm) and in their
/// blends, before and after it — a revolution at 0.25° outputs takes up each lash where the closed form puts it
/// (to 1e-8°) at the closed form's speed (to 1e-9 of it: `ω h V / β` = 120 mm/s in the band;
/// in a blend both to 1e-7), the seat letting go at that instant, and seats the valve at the
/// mirror angle at the same speed, the cam letting go there; nothing else happens.
#[test]
fn the_ramps_take_up_the_lash_and_seat_the_valve_at_their_speed() {
    let w = RPM * TAU / 60.0;
    let band = w * H * (4.0 / 3.0) / BETA_DEG.to_radians();
    assert!((band - 120.0).abs() < 1e-9, "{band}");
    for c in [0.02, 0.06, 0.1, 0.15, 0.2, 0.24, 0.28] {
        let (at_deg, speed) = take_up(c);
        let built = with_lash(c);
        let (plan, mut sim) = built.plan(1.0, 0.25).unwrap();
        let run = sim
            .run(plan.outputs, plan.h_out, |_| {
                std::ops::ControlFlow::Continue(())
            })
            .unwrap();
        let name = |k: usize| built.system.contacts()[k].name.as_str();
        let seen: Vec<(EventKind, &str, f64, f64)> = run
            .events
            .iter()
            .map(|e| (e.kind, name(e.contact), e.time * w * 180.0 / PI, e.approach))
            .collect();
        eprintln!("lash {c} mm: take-up at {at_deg:.6}°, {speed:.6} mm/s; {seen:?}");
        assert_eq!(seen.len(), 4, "{seen:?}");
        let expect = [
            (EventKind::Impact, "cam on bucket", at_deg, speed),
            (EventKind::LiftOff, "seat", at_deg, 0.0),
            (EventKind::Impact, "seat", TOTAL_DEG - at_deg, speed),
            (EventKind::LiftOff, "cam on bucket", TOTAL_DEG - at_deg, 0.0),
        ];
        // a contact is located where its gap is 1e-12 of the system's size (80 mm) past zero:
        // 6e-9° late on the constant-velocity part; in a blend the valve's speed changes with
        // the angle and the seating is located on the integrated motion (its tolerance, 1e-10)
        let (angle_tol, speed_tol) = if in_band(c) {
            (1e-8, 1e-9)
        } else {
            (1e-7, 1e-7)
        };
        for (got, want) in seen.iter().zip(&expect) {
            assert_eq!((got.0, got.1), (want.0, want.1), "lash {c}: {got:?}");
            assert!(
                (got.2 - want.2).abs() < angle_tol,
                "lash {c}: {got:?} vs {want:?}"
            );
            assert!(
                (got.3 - want.3).abs() <= speed_tol * speed,
                "lash {c}: {got:?} vs {want:?}"
            );
        }
        if in_band(c) {
            assert!((speed - band).abs() < 1e-12 * band);
        }
    }
}

/// A lift too steep for the flat face (8 mm over 60° above a 20 mm base circle: `R + s + s''`
/// reaches −18 mm near the nose) gives a cam that folds back on itself: refused when the file
/// is read, naming the contact's base radius and the angle (before, a run stopped in a contact
/// search that "did not converge", reported as an internal error).
#[test]
fn a_cam_that_folds_back_under_its_flat_face_is_refused() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/bucket-lash.toml");
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("rise = 8.0, degrees = 100", "rise = 8.0, degrees = 60")
        .replace("rise = -8.0, degrees = 100", "rise = -8.0, degrees = 60")
        .replace(
            "{ law = \"dwell\", degrees = 100 }",
            "{ law = \"dwell\", degrees = 180 }",
        );
    let err = match read_system(&text, "folded.toml", &BuildOptions::default()) {
        Ok(_) => panic!("a folded cam was accepted"),
        Err(e) => e.to_string(),
    };
    assert!(
        err.contains("contact[0].curve_a.base_radius") && err.contains("folds back"),
        "{err}"
    );
}
