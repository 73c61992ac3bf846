//! Contact jumps on a non-convex cam are flagged where they happen: every flagged step brackets
//! an independently located jump angle and every such angle is flagged, for all five followers.
//! The jump angles come from the convex hull (a flat face jumps when it lies along a hull edge
//! bridging a dent) and, for every follower, from the support function of the cam
//! (`Mechanism::support_position`'s maximiser switching branch), which shares no code with the
//! search or the sweep.

use super::common::*;
use camkin::cam::{Follower, Mechanism, Sense};
use camkin::curve::{ClosedSpline, Curve};
use camkin::table::contact_jumps;
use camkin::{Point2, Vec2};
use std::f64::consts::TAU;
use std::sync::Arc;

/// A cam with two dents.
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
    Arc::new(ClosedSpline::new(&pts.map(|(x, y)| Point2::new(x, y))).unwrap())
}

fn followers() -> Vec<Follower> {
    vec![
        Follower::TranslatingFlat {
            direction: Vec2::new(1.0, 0.3),
        },
        Follower::TranslatingRoller {
            direction: Vec2::new(0.0, 1.0),
            offset: 0.4,
            roller_radius: 1.5,
        },
        Follower::TranslatingKnife {
            direction: Vec2::new(-1.0, 0.2),
            offset: 1.6,
        },
        Follower::OscillatingFlat {
            pivot: Point2::new(-3.0, 8.0),
            face_offset: 0.5,
            closing: Sense::Cw,
            initial_angle: (-30f64).to_radians(),
        },
        Follower::OscillatingRoller {
            pivot: Point2::new(9.0, 3.0),
            arm_length: 8.0,
            roller_radius: 1.2,
            closing: Sense::Ccw,
            initial_angle: 200f64.to_radians(),
        },
    ]
}

const PERIOD: f64 = 8.0; // the peanut's parameter period (8 nodes)

/// Parameter distance on the closed profile.
fn du(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(PERIOD);
    d.min(PERIOD - d)
}

/// The jump angles of the support function over a revolution: where its maximiser moves by more
/// than a tenth of a node spacing between neighbouring angles 0.05° apart (a steady contact moves
/// by a few hundredths at most), located by bisection to 1e-12 rad.
fn support_jumps(m: &Mechanism) -> Vec<f64> {
    let u = |t: f64| m.support_position(t).unwrap().1;
    let n = 7200;
    let mut out = Vec::new();
    for k in 0..n {
        let (mut a, mut b) = (k as f64 * TAU / n as f64, (k + 1) as f64 * TAU / n as f64);
        let (ua, ub) = (u(a), u(b));
        if du(ua, ub) < 0.1 {
            continue;
        }
        while b - a > 1e-12 {
            let mid = 0.5 * (a + b);
            let um = u(mid);
            if du(um, ua) < du(um, ub) {
                a = mid;
            } else {
                b = mid;
            }
        }
        out.push(0.5 * (a + b));
    }
    out
}

/// The angles at which a flat face along `d` lies along a hull edge bridging a dent: the edge's
/// outward normal, turned with the cam, points along `d`.
fn hull_jumps(profile: &dyn Curve, d: Vec2, sense: Sense) -> Vec<f64> {
    let n = 20_000;
    let mut pts: Vec<Point2> = (0..n)
        .map(|k| profile.position(k as f64 * PERIOD / n as f64))
        .collect();
    pts.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    // Andrew's monotone chain, counter-clockwise
    let cross = |o: Point2, a: Point2, b: Point2| (a - o).perp(&(b - o));
    let mut hull: Vec<Point2> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        let it: Box<dyn Iterator<Item = &Point2>> = if pass == 0 {
            Box::new(pts.iter())
        } else {
            Box::new(pts.iter().rev())
        };
        for &p in it {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    let spacing = 20.0 * 30.0 / n as f64; // well above the samples' spacing (perimeter < 30)
    let mut out = Vec::new();
    for i in 0..hull.len() {
        let (a, b) = (hull[i], hull[(i + 1) % hull.len()]);
        let e = b - a;
        if e.norm() > spacing {
            // outward normal of a ccw hull; the cam frame turns by σθ: R(σθ) n = d
            let normal = Vec2::new(e.y, -e.x);
            let theta = sense.sign() * (d.y.atan2(d.x) - normal.y.atan2(normal.x));
            out.push(theta.rem_euclid(TAU));
        }
    }
    out
}

/// The flagged steps `(θ_prev, θ)` of a sweep at `step_deg` (what `camkin analyze` reports).
fn flagged(m: &Mechanism, step_deg: f64) -> Vec<(f64, f64)> {
    let n = (360.0 / step_deg).round() as usize;
    let thetas: Vec<f64> = (0..=n)
        .map(|k| (k as f64 * step_deg + 0.01).to_radians())
        .collect();
    let rows = m.analyze_all(&thetas);
    assert!(
        rows.iter().all(|r| r.is_ok()),
        "{}",
        m.follower().kind_name()
    );
    let jumps = contact_jumps(m, &rows, true);
    (1..thetas.len())
        .filter(|&k| jumps[k])
        .map(|k| (thetas[k - 1], thetas[k]))
        .collect()
}

/// Each flagged step holds exactly one of `angles` and each angle is in a flagged step.
fn assert_located(what: &str, steps: &[(f64, f64)], angles: &[f64]) {
    let inside = |&(a, b): &(f64, f64), t: f64| {
        let t = a + (t - a).rem_euclid(TAU);
        t > a && t <= b
    };
    for s in steps {
        let hits = angles.iter().filter(|&&t| inside(s, t)).count();
        assert_eq!(
            hits,
            1,
            "{what}: flagged step {:.3}°–{:.3}° holds {hits} jump angles of {angles:?}",
            s.0.to_degrees(),
            s.1.to_degrees()
        );
    }
    for &t in angles {
        assert!(
            steps.iter().any(|s| inside(s, t)),
            "{what}: the jump at {:.4}° is not flagged (flagged: {steps:?})",
            t.to_degrees()
        );
    }
}

#[test]
fn jumps_are_flagged_where_the_support_function_switches_branch_for_every_follower() {
    let mut jumping = Vec::new();
    for f in followers() {
        for sense in [Sense::Ccw, Sense::Cw] {
            let m = mechanism(peanut(), Point2::origin(), sense, 600.0, f.clone());
            assert!(!m.is_convex());
            let angles = support_jumps(&m);
            let what = format!("{} {sense:?}", f.kind_name());
            for step in [1.0, 0.25] {
                assert_located(&format!("{what} at {step}°"), &flagged(&m, step), &angles);
            }
            if !angles.is_empty() {
                jumping.push(f.kind_name());
            }
        }
    }
    // the test means something only where there are jumps: all five kinds jump on this cam
    jumping.dedup();
    assert_eq!(jumping.len(), 5, "kinds that jump: {jumping:?}");
}

#[test]
fn a_flat_face_jumps_where_it_lies_along_a_hull_edge_bridging_a_dent() {
    let d = Vec2::new(1.0, 0.3);
    for sense in [Sense::Ccw, Sense::Cw] {
        let m = mechanism(
            peanut(),
            Point2::origin(),
            sense,
            600.0,
            Follower::TranslatingFlat { direction: d },
        );
        let hull = hull_jumps(peanut().as_ref(), d, sense);
        assert_eq!(hull.len(), 2, "two dents, two bridging edges: {hull:?}");
        // the support function switches branch at the same angles (the hull is sampled: 1e-6 rad)
        let support = support_jumps(&m);
        assert_eq!(support.len(), 2);
        for t in &hull {
            assert!(
                support
                    .iter()
                    .any(|s| (s - t).abs().min(TAU - (s - t).abs()) < 1e-6),
                "hull {t} vs support {support:?}"
            );
        }
        for step in [2.0, 0.5, 0.05] {
            assert_located(
                &format!("flat {sense:?} at {step}°"),
                &flagged(&m, step),
                &hull,
            );
        }
    }
}

/// Regression: a knife edge whose crossing merges with its partner and vanishes (the line of
/// travel grazes a lobe) falls to another crossing; the sweep followed Newton there and called it
/// a warm start, so the fall was not flagged.
#[test]
fn knife_falling_off_a_lobe_is_flagged_as_a_jump() {
    let m = mechanism(
        peanut(),
        Point2::origin(),
        Sense::Cw,
        600.0,
        followers()[2].clone(),
    );
    let thetas: Vec<f64> = [31.01f64, 32.01, 33.01].map(f64::to_radians).to_vec();
    let rows = m.analyze_all(&thetas);
    let jumps = contact_jumps(&m, &rows, true);
    assert_eq!(jumps, [false, false, true]);
    let fall = rows[1].as_ref().unwrap().position - rows[2].as_ref().unwrap().position;
    assert!(fall > 3.0, "the tip falls by {fall}");
}

/// Regression: near a grazing line of travel the two crossings lie between neighbouring samples
/// (or on either side of one sample) and the global search converged to the wrong one or missed
/// both, answering a lower crossing: it must agree with the support function.
#[test]
fn knife_global_search_finds_crossings_near_tangency() {
    let m = mechanism(
        peanut(),
        Point2::origin(),
        Sense::Cw,
        600.0,
        followers()[2].clone(),
    );
    // the top crossing pair vanishes at about 32.1516°
    for k in 0..40 {
        let th = (32.10 + k as f64 * 0.0013).to_radians();
        let (q, _) = m.support_position(th).unwrap();
        let g = m.analyze(th).unwrap();
        assert!(
            (g.position - q).abs() < 1e-9,
            "at {:.4}°: global search {} vs support {q}",
            th.to_degrees(),
            g.position
        );
    }
}

/// Regression (`simulate` on a concave stretch under a flat face ended in "pairing-point search
/// did not converge", an internal error): the multibody model, which follows one contact point,
/// refuses a cam whose contact jumps up front with the jump angles, and those angles are the
/// independently located jumps (each one at most a 0.25° sample after it), for every follower
/// and both senses; [`Simulation`](camkin::dynamics::Simulation) then takes the one-coordinate
/// model, which has jumps as impacts.
#[test]
fn simulation_across_a_contact_jump_is_refused_with_the_jump_angles() {
    use camkin::dynamics::{
        AugmentedLagrangian, DynamicsError, FollowerDynamics, PresetSimulation, Simulation,
    };
    for f in followers() {
        for sense in [Sense::Ccw, Sense::Cw] {
            let m = mechanism(peanut(), Point2::origin(), sense, 600.0, f.clone());
            let located: Vec<f64> = support_jumps(&m)
                .iter()
                .map(|t| t.to_degrees().rem_euclid(360.0))
                .collect();
            let what = format!("{} {sense:?}", f.kind_name());
            let params = FollowerDynamics {
                mass: 0.5,
                inertia: 0.01,
                spring_stiffness: 1000.0,
                spring_preload: 50.0,
                damping: 0.0,
                restitution: 0.5,
                gravity: Vec2::zeros(),
            };
            let r = PresetSimulation::starting_at(&m, params, AugmentedLagrangian::default(), 0.0);
            let chosen = Simulation::new(&m, params, AugmentedLagrangian::default()).unwrap();
            assert_eq!(
                matches!(chosen, Simulation::Reduced(_)),
                !located.is_empty(),
                "{what}: the model chosen"
            );
            if located.is_empty() {
                assert!(r.is_ok(), "{what}: {:?}", r.err());
                continue;
            }
            let Err(DynamicsError::ContactJumps { angles_deg }) = r else {
                panic!("{what}: not refused with the jumps: {:?}", r.err());
            };
            assert_eq!(
                angles_deg.len(),
                located.len(),
                "{what}: {angles_deg:?} vs {located:?}"
            );
            for t in &located {
                assert!(
                    angles_deg
                        .iter()
                        .any(|a| (a - t).rem_euclid(360.0) <= 0.25 + 1e-9),
                    "{what}: the jump at {t}° is not among {angles_deg:?}"
                );
            }
        }
    }
}

/// Every follower across the peanut's dents, simulated: each jump of the contact is an event at
/// the independently located jump angle (the support function's, within 1e-6°): an impact
/// without flight where two parts of the profile cross, a lift-off where the part followed ends
/// (a knife falling off a lobe; a jump while it flies, as a knife does from just before its fold,
/// is none); the follower is never inside the cam (never closer than the
/// support position). For the flat face (its normal is its line of travel: the lever is 1) the
/// approach speed is `ω |Δs'|` of the kink in the support function, its slopes on either side by
/// finite differences of support positions, and with no restitution and a strong spring the face
/// stays on the cam. Both senses.
#[test]
fn a_follower_across_the_dents_is_struck_at_each_jump() {
    use camkin::dynamics::{AugmentedLagrangian, EventKind, FollowerDynamics, Simulation};
    let params = FollowerDynamics {
        mass: 0.5,
        inertia: 0.05,
        spring_stiffness: 1000.0,
        spring_preload: 500.0,
        damping: 0.0,
        restitution: 0.0,
        gravity: Vec2::zeros(),
    };
    for f in followers() {
        for sense in [Sense::Ccw, Sense::Cw] {
            let what = format!("{} {sense:?}", f.kind_name());
            let flat = matches!(f, Follower::TranslatingFlat { .. });
            let m = mechanism(peanut(), Point2::origin(), sense, 6.0, f.clone());
            let w = m.cam().speed();
            let located = support_jumps(&m);
            if located.is_empty() {
                continue;
            }
            let mut sim = Simulation::new(&m, params, AugmentedLagrangian::default()).unwrap();
            assert!(matches!(sim, Simulation::Reduced(_)));
            let run = sim
                .run(720, 0.5f64.to_radians() / w, |_| {
                    std::ops::ControlFlow::Continue(())
                })
                .unwrap();
            let s = |t: f64| m.support_position(t).unwrap().0;
            let away = m.travel().unwrap().away;
            for x in &run.samples {
                let gap = away * (x.position - s(x.cam_angle));
                assert!(gap >= -1e-9, "{what}: inside the cam by {gap:e} at {x:?}");
            }
            let jumps: Vec<_> = run
                .events
                .iter()
                .filter(|e| e.kind != EventKind::Impact)
                .collect();
            for &t in &located {
                // a jump while the follower flies (after a knife's fall) is no event
                let flying = run
                    .events
                    .iter()
                    .rev()
                    .find(|e| e.cam_angle < t - 1e-8)
                    .is_some_and(|e| e.kind == EventKind::LiftOff);
                if flying {
                    continue;
                }
                let near = jumps
                    .iter()
                    .map(|e| (e.cam_angle - t).to_degrees().abs())
                    .fold(f64::INFINITY, f64::min);
                assert!(near < 1e-6, "{what}: no event within {near:e}° of {t} rad");
            }
            if !flat {
                continue;
            }
            // the slope of the support position from one side, clear of the kink
            let slope = |t: f64, side: f64| {
                let (h, d) = (1e-6, side * 1e-5);
                let c = |x: f64| (s(x + h) - s(x - h)) / (2.0 * h);
                2.0 * c(t + 2.0 * d) - c(t + 4.0 * d)
            };
            assert_eq!(run.events.len(), located.len(), "{what}: {:?}", run.events);
            for (e, &t) in run.events.iter().zip(&located) {
                assert_eq!(e.kind, EventKind::Jump, "{what}");
                let want = w * (slope(t, 1.0) - slope(t, -1.0)).abs();
                assert_close(e.impact_velocity, want, 1e-6, want, "approach speed");
            }
            assert!(run.samples.iter().all(|x| x.in_contact), "{what}");
        }
    }
}

/// Regression (the sweep guard lagged after two parts crossed): the warm sweep's guard compared
/// sampled first-touch scores, which lag the true maximum of the part taking over (it lies
/// between samples), so for a window after the crossing the sweep kept the old part: a flat face
/// on this cam was off by up to 2.6e-3 (cam size 4) for up to 5e-4 rad, an oscillating flat face
/// by 4.8e-4 rad, and the jump was flagged late. Every follower, both senses, two more face
/// directions: fine sweeps through each jump of the independent support function agree with it
/// at every step, and the step that holds the jump is the one flagged. The same followers as
/// general ones carrying their contact curves (their own search; not the knife, a point is not
/// carried): the carried search skipped possible ties within four sample spacings of the
/// contact, so a roller on an arm kept the old part 3.7e-6 rad after the crossing (1.25e-6 rad
/// off) and the jump was flagged a step late.
#[test]
fn sweep_guard_lag_after_parts_cross() {
    use camkin::cam::Found;
    let mut fs = followers();
    fs.push(Follower::TranslatingFlat {
        direction: Vec2::new(1.0, 0.0),
    });
    fs.push(Follower::TranslatingFlat {
        direction: Vec2::new(0.0, 1.0),
    });
    let mut crossings = [0, 0];
    for f in fs {
        for sense in [Sense::Ccw, Sense::Cw] {
            let m = mechanism(peanut(), Point2::origin(), sense, 600.0, f.clone());
            // the same follower as a general one carrying its contact curve (its own search;
            // a point is not carried: a knife is only named)
            let general = (!matches!(f, Follower::TranslatingKnife { .. }))
                .then(|| Mechanism::new(m.cam().clone(), general_of(&m)).unwrap());
            for t0 in support_jumps(&m) {
                for (path, swept) in
                    std::iter::once(("named", &m)).chain(general.as_ref().map(|g| ("general", g)))
                {
                    for h in [1e-5, 1e-4, 1e-3] {
                        let what = format!(
                            "{} ({path}) {sense:?}, jump at {t0:.6} rad, step {h:e} rad",
                            f.kind_name()
                        );
                        let mut sweep = swept.sweep();
                        // 80 steps either side, the crossing 0.37 of a step before a sample
                        let thetas: Vec<f64> = (0..=160)
                            .map(|k| t0 + (f64::from(k) - 80.0 + 0.37) * h)
                            .collect();
                        let mut flagged = Vec::new();
                        for (k, &th) in thetas.iter().enumerate() {
                            let s = sweep.step(th).unwrap();
                            let (q, _) = m.support_position(th).unwrap();
                            assert!(
                            (s.position - q).abs() <= 1e-9,
                            "{what}: at {:+.2e} rad from the jump the sweep gives {} ({:?}), the support function {q}",
                            th - t0,
                            s.position,
                            s.found
                        );
                            if matches!(s.found, Found::Jump { .. }) {
                                flagged.push(k);
                            }
                        }
                        assert_eq!(flagged, vec![80], "{what}: flagged steps");
                        crossings[usize::from(path == "general")] += 1;
                    }
                }
            }
        }
    }
    // named and general (no knife) sweeps through jumps
    assert!(
        crossings[0] >= 3 * 28 && crossings[1] >= 3 * 24,
        "{crossings:?} sweeps through jumps"
    );
}
