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

/// The example with the lash `c` (mm) drawn, not keyed: its `lash` key left out and the bucket,
/// the seat and the spring's anchor moved down by `c` from the base circle.
fn with_lash(c: f64) -> camkin::spec::BuiltSystem {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/bucket-lash.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains("lash = 0.1 ") && text.contains("-20.0]"));
    let text = text
        .replace("lash = 0.1 ", "starts_closed = false ")
        .replace("-20.0]", &format!("{}]", -20.0 - c))
        .replace("-80.0]", &format!("{}]", -80.0 - c))
        .replace("[[0.0, -60.0]", &format!("[[0.0, {}]", -60.0 - c));
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

/// The example as written, its lash keyed (`lash = 0.1` on the cam's contact).
fn keyed() -> camkin::spec::BuiltSystem {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/bucket-lash.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    read_system(&text, "bucket-lash.toml", &BuildOptions::default()).unwrap()
}

/// A revolution's events at 0.25° outputs, as (kind, contact, driver angle °, approach mm/s).
fn events(built: &camkin::spec::BuiltSystem) -> Vec<(EventKind, String, f64, f64)> {
    let (plan, mut sim) = built.plan(1.0, 0.25).unwrap();
    let run = sim
        .run(plan.outputs, plan.h_out, |_| {
            std::ops::ControlFlow::Continue(())
        })
        .unwrap();
    run.events
        .iter()
        .map(|e| {
            (
                e.kind,
                built.system.contacts()[e.contact].name.clone(),
                plan.angle_of(e.time).unwrap(),
                e.approach,
            )
        })
        .collect()
}

/// `lash = c` on the contact (the face moved into the bucket) is the lash drawn (the bucket,
/// seat and spring moved down by `c`, no key): over lashes in the ramps' blend and their
/// constant-velocity part, the same events at the same angles and speeds (to the closed form's
/// tolerances: 1e-8° and 1e-9 of the speed on the constant-velocity part, 1e-7 in a blend); the
/// keyed file's own lash is 0.1 mm.
#[test]
fn the_lash_key_is_the_lash_drawn() {
    let built = keyed();
    assert_eq!(built.lash.len(), 1);
    assert_eq!((built.lash[0].contact, built.lash[0].lash), (0, 0.1));
    for c in [0.02, 0.1, 0.28] {
        let by_key = events(&built.with_lash(c).unwrap());
        let drawn = events(&with_lash(c));
        assert_eq!(by_key.len(), 4, "lash {c}: {by_key:?}");
        assert_eq!(
            by_key.len(),
            drawn.len(),
            "lash {c}: {by_key:?} vs {drawn:?}"
        );
        let (angle_tol, speed_tol) = if in_band(c) {
            (1e-8, 1e-9)
        } else {
            (1e-7, 1e-7)
        };
        for (k, d) in by_key.iter().zip(&drawn) {
            assert_eq!((k.0, &k.1), (d.0, &d.1), "lash {c}");
            assert!((k.2 - d.2).abs() < angle_tol, "lash {c}: {k:?} vs {d:?}");
            assert!(
                (k.3 - d.3).abs() <= speed_tol * d.3.abs().max(1.0),
                "lash {c}: {k:?} vs {d:?}"
            );
        }
    }
}

/// The lash sweep's rows (`camkin simulate --lash`): each lash's take-up on the cam's contact
/// and its seating on the seat, at the closed form's angles (to 1e-8°) and speeds (to 1e-9),
/// the seating at the mirror angle.
#[test]
fn the_lash_sweep_gives_each_take_up_and_seating() {
    let lashes = [0.06, 0.1, 0.2, 0.28];
    let rows = keyed().lash_sweep(&lashes, 1.0, 0.25).unwrap();
    assert_eq!(rows.len(), lashes.len());
    for (row, &c) in rows.iter().zip(&lashes) {
        let (at_deg, speed) = take_up(c);
        let (angle_tol, speed_tol) = if in_band(c) {
            (1e-8, 1e-9)
        } else {
            (1e-7, 1e-7)
        };
        assert_eq!(row.lash, c);
        assert_eq!(row.contact, "cam on bucket");
        assert_eq!(row.seat.as_deref(), Some("seat"), "{row:?}");
        let near = |got: Option<f64>, want: f64, tol: f64| {
            assert!(
                got.is_some_and(|g| (g - want).abs() <= tol),
                "lash {c}: {got:?} vs {want} ({row:?})"
            )
        };
        near(row.take_up_angle_deg, at_deg, angle_tol);
        near(row.seating_angle_deg, TOTAL_DEG - at_deg, angle_tol);
        near(row.take_up_speed, speed, speed_tol * speed);
        near(row.seating_speed, speed, speed_tol * speed);
    }
}

/// A small system: a circle cam of radius 20 mm at the origin on a driven shaft, a follower on
/// a vertical guide carrying `face` (curve B, in its frame) at `at`, the contact's `lash`.
fn face_on_circle(at: [f64; 2], face: &str, lash: &str) -> String {
    format!(
        r#"length_unit = "mm"
[dynamics]
[simulation]
duration = 0.001
interval = 0.001
[[body]]
name = "cam"
mass = 1.0
inertia = 1e-3
[[body]]
name = "follower"
position = [{}, {}]
mass = 0.05
inertia = 1e-6
[[joint]]
name = "bearing"
kind = "revolute"
bodies = ["ground", "cam"]
[[joint]]
name = "guide"
kind = "prismatic"
bodies = ["ground", "follower"]
axis = [0.0, 1.0]
[[driver]]
name = "shaft"
body = "cam"
coordinate = "angle"
speed_rpm = 100.0
[[contact]]
name = "cam on face"
bodies = ["cam", "follower"]
curve_a = {{ kind = "circle", center = [0.0, 0.0], radius = 20.0 }}
curve_b = {face}
{lash}
"#,
        at[0], at[1]
    )
}

/// The lash moves the face into its material whichever way it faces: a flat face above the cam
/// (material above), one below it (its direction reversed, material below) and rollers above
/// and beside it each start apart with a gap equal to the lash along the common normal (to
/// 1e-12 mm), where the file draws them touching.
#[test]
fn a_lash_opens_the_gap_it_names_whichever_way_the_face_looks() {
    let faces = [
        (
            [0.0, 20.0],
            r#"{ kind = "line", anchor = [0.0, 0.0], direction = [1.0, 0.0] }"#,
        ),
        (
            [0.0, -20.0],
            r#"{ kind = "line", anchor = [0.0, 0.0], direction = [-1.0, 0.0] }"#,
        ),
        (
            [0.0, 25.0],
            r#"{ kind = "circle", center = [0.0, 0.0], radius = 5.0 }"#,
        ),
        (
            [0.0, 20.0],
            r#"{ kind = "circle", center = [15.0, 0.0], radius = 5.0 }"#,
        ),
    ];
    for (at, face) in faces {
        for lash in [0.0, 0.07, 0.5] {
            let text = face_on_circle(at, face, &format!("lash = {lash}"));
            let (_, run) = crate::common::run_timed(&text, "face.toml");
            let first = &run.samples[0];
            assert!(lash == 0.0 || !first.in_contact[0], "{face}, lash {lash}");
            assert!(
                (first.gaps[0] - lash).abs() < 1e-12,
                "{face} at {at:?}, lash {lash}: gap {}",
                first.gaps[0]
            );
        }
    }
}

/// A lash that cannot be: negative; on a face that is not a line or a circle (a knife's point);
/// with `starts_closed = true`; not below the roller's radius — each refused when the file is
/// read, naming its key; a sweep of a system with no lash, or beyond a tenth of its size, is
/// refused naming the lash.
#[test]
fn a_lash_that_cannot_be_is_refused_naming_its_key() {
    let line = r#"{ kind = "line", anchor = [0.0, 0.0], direction = [1.0, 0.0] }"#;
    let roller = r#"{ kind = "circle", center = [0.0, 0.0], radius = 5.0 }"#;
    let point = r#"{ kind = "point", at = [0.0, 0.0] }"#;
    for (at, face, lash, key, says) in [
        (
            [0.0, 20.0],
            line,
            "lash = -0.1",
            "contact[0].lash",
            "zero or more",
        ),
        (
            [0.0, 20.0],
            point,
            "lash = 0.1",
            "contact[0].curve_b.kind",
            "\"point\"",
        ),
        (
            [0.0, 20.0],
            line,
            "lash = 0.1\nstarts_closed = true",
            "contact[0].starts_closed",
            "starts apart",
        ),
        (
            [0.0, 25.0],
            roller,
            "lash = 5.0",
            "contact[0].lash",
            "roller's radius 5",
        ),
    ] {
        let text = face_on_circle(at, face, lash);
        let err = match read_system(&text, "face.toml", &BuildOptions::default()) {
            Ok(_) => panic!("{lash} on {face} was accepted"),
            Err(e) => e.to_string(),
        };
        assert!(
            err.contains(key) && err.contains(says),
            "{lash} on {face}: {err}"
        );
    }
    let plain = read_system(
        &face_on_circle([0.0, 20.0], line, ""),
        "face.toml",
        &BuildOptions::default(),
    )
    .unwrap();
    assert_eq!(
        plain.with_lash(0.1).unwrap_err(),
        camkin::spec::LashError::NoLash
    );
    let built = keyed();
    let size = built.system.size();
    for bad in [-0.01, 0.1 * size * 1.01, f64::NAN] {
        let e = built.with_lash(bad).unwrap_err().to_string();
        assert!(e.contains("must be from 0 to"), "{bad}: {e}");
    }
}
