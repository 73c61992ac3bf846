//! Warm-started sweeps: same answers as the global search at every angle; jumps of the contact on
//! non-convex cams are noticed and flagged.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Found, Mechanism, Sense};
use camkin::curve::ClosedSpline;
use camkin::{Point2, Vec2};
use std::sync::Arc;

/// Returns (warm starts, jumps flagged by the sweep, jumps of the global contact parameter).
fn compare_with_global(m: &Mechanism, step_deg: f64) -> (usize, usize, usize) {
    let n = (360.0 / step_deg) as usize;
    let thetas: Vec<f64> = (0..n).map(|k| (k as f64 * step_deg).to_radians()).collect();
    let rows = m.analyze_all(&thetas);
    let (mut warm, mut jumps, mut global_jumps) = (0, 0, 0);
    let mut prev_u: Option<f64> = None;
    let w = m.cam().speed();
    for (t, r) in thetas.iter().zip(rows) {
        let s = r.unwrap();
        let g = m.analyze(*t).unwrap();
        if let Some(pu) = prev_u {
            // the parameter moves by well under a segment per step unless the contact jumps
            let du = (g.cam_param - pu).abs();
            if du > 0.5 && du < 7.5 {
                global_jumps += 1;
            }
        }
        prev_u = Some(g.cam_param);
        assert_close(s.position, g.position, 1e-12, m.size() + 10.0, "position");
        // at a tie (two parts of the profile touch at once) either contact is a first touch
        if (s.contact_world - g.contact_world).norm() < 1e-6 {
            assert_close(
                s.acceleration,
                g.acceleration,
                1e-9,
                w * w * m.size(),
                "acceleration",
            );
        }
        match s.found {
            Found::WarmStart => warm += 1,
            Found::Jump { .. } => jumps += 1,
            Found::Global => {}
        }
    }
    (warm, jumps, global_jumps)
}

#[test]
fn sweep_matches_global_for_every_follower_on_paper_cam() {
    for f in all_followers(Point2::origin()) {
        let m = mechanism(
            paper_profile(false),
            Point2::origin(),
            Sense::Ccw,
            1000.0,
            f.clone(),
        );
        let (warm, jumps, _) = compare_with_global(&m, 1.0);
        assert_eq!(jumps, 0, "{}", f.kind_name());
        assert!(warm >= 359, "{}: only {warm} warm starts", f.kind_name());
    }
}

/// A cam with two dents (non-convex): a flat face bridges each dent, so the contact jumps from one
/// lobe to the next each time the face passes a dent.
fn peanut() -> Arc<ClosedSpline> {
    let pts = [
        (4.0, 0.0),
        (3.0, 2.4),
        (0.5, 1.1),
        (-2.0, 2.4),
        (-3.5, 0.1),
        (-2.2, -2.5),
        (0.6, -1.0),
        (3.1, -2.3),
    ];
    Arc::new(
        ClosedSpline::new(
            &pts.iter()
                .map(|&(x, y)| Point2::new(x, y))
                .collect::<Vec<_>>(),
        )
        .unwrap(),
    )
}

#[test]
fn jumps_on_non_convex_cam_are_detected_and_match_global() {
    let m = mechanism(
        peanut(),
        Point2::origin(),
        Sense::Ccw,
        1000.0,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    );
    assert!(!m.is_convex());
    let (warm, jumps, global_jumps) = compare_with_global(&m, 0.5);
    // the face bridges each dent once per revolution (when it is parallel to the hull edge over it)
    assert_eq!(global_jumps, 2, "jumps of the global contact");
    assert_eq!(jumps, global_jumps, "jumps flagged by the sweep");
    assert!(warm > 600, "warm starts: {warm}");
}

#[test]
fn roller_on_non_convex_cam_jumps_too() {
    let f = Follower::TranslatingRoller {
        direction: Vec2::y(),
        offset: 0.0,
        roller_radius: 2.0,
    };
    let m = mechanism(peanut(), Point2::origin(), Sense::Cw, 500.0, f);
    let (_, jumps, global_jumps) = compare_with_global(&m, 0.5);
    assert!(global_jumps >= 2, "global jumps {global_jumps}");
    assert_eq!(jumps, global_jumps, "jumps flagged by the sweep");
}

/// The motion-only path finds the same contact as the full analysis: bit for bit cold, within
/// the position tolerance warm (its rates are closed forms, compared with the paper's method
/// in `motion_closed_form`).
#[test]
fn motion_fast_path_finds_the_same_contact() {
    for f in all_followers(Point2::origin()) {
        let m = mechanism(
            paper_profile(true),
            Point2::origin(),
            Sense::Cw,
            800.0,
            f.clone(),
        );
        let mut full = m.sweep();
        let mut fast = m.sweep();
        for k in 0..720 {
            let th = (k as f64 * 0.5).to_radians();
            let (a, b) = (full.step(th).unwrap(), fast.step_motion(th).unwrap());
            // warm, the two extrapolate from rates that differ by rounding
            assert_eq!(a.found, b.found, "{}", f.kind_name());
            assert!(
                (a.position - b.position).abs() <= 1e-13 * m.size()
                    && (a.cam_param - b.cam_param).abs() <= 1e-13 * m.size(),
                "{}: {a:?} vs {b:?}",
                f.kind_name()
            );
            let c = m.motion(th).unwrap();
            let d = m.analyze(th).unwrap();
            assert_eq!((c.position, c.cam_param), (d.position, d.cam_param));
        }
    }
}

/// Regression (issue 12): a motion program too fast for its base circle folds the synthesised
/// profile (a swallowtail between two cusps, while the curvature keeps one sign); the profile was
/// taken as convex and the warm-started sweep followed the fold's backward branch over a dwell
/// (s = 27.67 → 21.71 where it is 28) without a flag. Now the fold makes the profile non-convex,
/// it is reported as a stretch the follower cannot follow, and every answer of a sweep equals
/// the single query's and the independent support function's.
#[test]
fn warm_sweep_on_a_folded_motion_profile_agrees_with_single_queries() {
    use camkin::cam::synthesis::synthesize;
    use camkin::motion::{Law, Program, Segment};
    for (base, sense) in [
        (8.0, Sense::Ccw),
        (8.0, Sense::Cw),
        (6.0, Sense::Ccw),
        (5.0, Sense::Cw),
    ] {
        let seg = |law, rise, deg: f64| Segment {
            law,
            rise,
            extent: deg.to_radians(),
        };
        let program = Program::new(
            0.0,
            vec![
                seg(Law::Cycloidal, 20.0, 120.0),
                seg(Law::Dwell, 0.0, 60.0),
                seg(Law::Polynomial345, -20.0, 120.0),
                seg(Law::Dwell, 0.0, 60.0),
            ],
        )
        .unwrap();
        let f = Follower::TranslatingFlat {
            direction: Vec2::x(),
        };
        let prof = Arc::new(synthesize(program, base, &f, sense).unwrap());
        let m = mechanism(prof, Point2::origin(), sense, 1000.0, f);
        let what = format!("base {base} {sense:?}");
        assert!(!m.is_convex(), "{what}: a folded profile is not convex");
        assert!(
            !m.unfollowable_stretches().is_empty(),
            "{what}: the fold is reported"
        );
        let thetas: Vec<f64> = (0..360).map(|k| (k as f64 + 0.5).to_radians()).collect();
        let (mut answered, mut dwell) = (0, 0);
        for (t, r) in thetas.iter().zip(m.analyze_all(&thetas)) {
            let Ok(s) = r else { continue };
            answered += 1;
            let g = m
                .analyze(*t)
                .unwrap_or_else(|e| panic!("{what} at {t}: sweep answered, single query: {e}"));
            assert!(
                (s.position - g.position).abs() < 1e-9,
                "{what} at {:.1}°: sweep {} vs single {}",
                t.to_degrees(),
                s.position,
                g.position
            );
            let (q, _) = m.support_position(*t).unwrap();
            assert!(
                (s.position - q).abs() < 1e-9,
                "{what} at {:.1}°: sweep {} vs support {q}",
                t.to_degrees(),
                s.position
            );
            let deg = t.to_degrees();
            if (125.0..175.0).contains(&deg) {
                assert!(
                    (s.position - (base + 20.0)).abs() < 1e-9,
                    "{what}: the dwell at {deg}° reads {}",
                    s.position
                );
                dwell += 1;
            }
        }
        assert!(answered > 200, "{what}: {answered} answers");
        assert!(
            dwell >= 40,
            "{what}: {dwell} of the dwell's 50 angles answered"
        );
    }
}

/// Issue 17: a sweep of many angles runs in fixed chunks on rayon's threads. On 1, 2 and 3
/// threads the rows are the same bit for bit (the chunks do not depend on the thread count), and
/// they agree with one sweep through every angle to rounding, with the same rows flagged as
/// jumps (each chunk starts at the angle before its first), for every follower on the paper's
/// cam and on a cam with dents.
#[test]
fn analyze_all_does_not_depend_on_the_thread_count() {
    use camkin::cam::SWEEP_CHUNK;
    let n = 4 * SWEEP_CHUNK + 123;
    // 0.11° steps: four chunk boundaries, and several revolutions' jumps on the dented cam
    let thetas: Vec<f64> = (0..n).map(|k| (k as f64 * 0.11).to_radians()).collect();
    let bits = |r: &Result<camkin::cam::FollowerState, camkin::cam::CamError>| {
        r.as_ref()
            .map(|s| {
                (
                    s.position.to_bits(),
                    s.velocity.to_bits(),
                    s.acceleration.to_bits(),
                    matches!(s.found, Found::Jump { .. }),
                )
            })
            .map_err(|e| e.to_string())
    };
    let mut jumps = 0;
    for profile in [
        paper_profile(false),
        peanut() as Arc<dyn camkin::curve::Curve>,
    ] {
        for f in all_followers(Point2::origin()) {
            let m = mechanism(profile.clone(), Point2::origin(), Sense::Ccw, 600.0, f);
            let on = |threads: usize| {
                rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap()
                    .install(|| m.analyze_all(&thetas))
            };
            let one: Vec<_> = on(1).iter().map(bits).collect();
            for threads in [2, 3] {
                let other: Vec<_> = on(threads).iter().map(bits).collect();
                assert!(
                    one == other,
                    "{}: {threads} threads differ from one",
                    m.follower().kind_name()
                );
            }
            // one sweep through every angle
            let mut s = m.sweep();
            let serial: Vec<_> = thetas.iter().map(|&t| s.step(t)).collect();
            let chunked = on(2);
            let peak = serial
                .iter()
                .filter_map(|r| r.as_ref().ok())
                .fold(0.0f64, |p, s| p.max(s.acceleration.abs()));
            for (k, (a, b)) in serial.iter().zip(&chunked).enumerate() {
                let what = format!("{} row {k}", m.follower().kind_name());
                let (a, b) = match (a, b) {
                    (Ok(a), Ok(b)) => (a, b),
                    (Err(x), Err(y)) => {
                        assert_eq!(x.to_string(), y.to_string(), "{what}");
                        continue;
                    }
                    _ => panic!("{what}: one sweep {a:?}, the chunks {b:?}"),
                };
                assert!(
                    (a.position - b.position).abs() <= 1e-13 * m.size(),
                    "{what}: position"
                );
                assert!(
                    (a.acceleration - b.acceleration).abs() <= 1e-11 * peak,
                    "{what}: acceleration"
                );
                assert_eq!(
                    matches!(a.found, Found::Jump { .. }),
                    matches!(b.found, Found::Jump { .. }),
                    "{what}: jump flag"
                );
                jumps += usize::from(matches!(a.found, Found::Jump { .. }));
            }
        }
    }
    assert!(jumps > 0, "the dented cam's jumps are compared too");
}
