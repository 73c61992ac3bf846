//! The pruned searches against the scans they replace: every leaf looked at, in order, nothing
//! pruned. Same candidates (bit for bit, ties by the lower parameter), same best sample, same
//! answer to the jump guard, for the five kinds on convex and non-convex cams, rollers larger than
//! a concave radius of curvature (the pitch curve turns back at cusps) included.

use super::*;
use crate::cam::{Cam, Follower, Mechanism, Sense};
use crate::curve::ClosedSpline;
use crate::geometry::Vec2;
use std::sync::Arc;

/// A cam of `n` nodes, radius 40, `lobes` lobes of relative height `a`.
fn lobed(n: usize, lobes: f64, a: f64) -> ClosedSpline {
    let pts: Vec<Point2> = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            let r = 40.0 * (1.0 + a * (lobes * t).sin());
            Point2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    ClosedSpline::new(&pts).unwrap()
}

fn followers() -> Vec<Follower> {
    let arm =
        |pivot: Point2, l: f64, r: f64, closing: Sense, phi0: f64| Follower::OscillatingRoller {
            pivot,
            arm_length: l,
            roller_radius: r,
            closing,
            initial_angle: phi0.to_radians(),
        };
    vec![
        Follower::TranslatingFlat {
            direction: Vec2::y(),
        },
        Follower::TranslatingFlat {
            direction: Vec2::new(1.0, -0.4),
        },
        Follower::TranslatingKnife {
            direction: Vec2::y(),
            offset: 3.0,
        },
        Follower::TranslatingKnife {
            direction: Vec2::new(-0.3, -1.0),
            offset: -11.0,
        },
        Follower::TranslatingRoller {
            direction: Vec2::y(),
            offset: 5.0,
            roller_radius: 8.0,
        },
        // larger than the concave radii of the five-lobed cam: cusps on its pitch curve
        Follower::TranslatingRoller {
            direction: Vec2::new(0.5, 1.0),
            offset: -2.0,
            roller_radius: 30.0,
        },
        Follower::OscillatingFlat {
            pivot: Point2::new(-30.0, 80.0),
            face_offset: 5.0,
            closing: Sense::Cw,
            initial_angle: (-20f64).to_radians(),
        },
        Follower::OscillatingFlat {
            pivot: Point2::new(90.0, 10.0),
            face_offset: -3.0,
            closing: Sense::Ccw,
            initial_angle: 160f64.to_radians(),
        },
        arm(Point2::new(-60.0, 60.0), 75.0, 8.0, Sense::Cw, -20.0),
        arm(Point2::new(80.0, -30.0), 70.0, 25.0, Sense::Ccw, 170.0),
    ]
}

/// Every leaf of `tree` in order: the scan.
fn scan(tree: &CircleTree, v: &mut impl Visit) {
    for n in tree.nodes.iter().filter(|n| n.kids.is_none()) {
        v.leaf(n.lo as usize, n.hi as usize);
    }
}

#[test]
fn pruned_searches_find_what_the_scans_find() {
    let cams = [
        lobed(24, 3.0, 0.15),
        lobed(300, 3.0, 0.15),
        lobed(1000, 5.0, 0.25),
        lobed(64, 2.0, 0.05),
        crate::reference::paper_profile(false),
    ];
    let mut checked = 0;
    let mut pruned_leaves = (0usize, 0usize);
    for (ci, cam) in cams.into_iter().enumerate() {
        let cam = Cam::from_rpm(Arc::new(cam), Point2::origin(), Sense::Ccw, 100.0).unwrap();
        for (fi, f) in followers().into_iter().enumerate() {
            let Ok(m) = Mechanism::new(cam.clone(), f) else {
                continue;
            };
            for k in 0..60 {
                let theta = 0.0137 + f64::from(k) * 0.1049;
                let instant = crate::cam::Instant::new(m.cam(), theta);
                let frame = instant.frame;
                let at = format!("cam {ci}, follower {fi}, angle {k}");
                for s in [&m.touch.index.dense, &m.touch.index.coarse] {
                    let q = || Query::new(&m.touch, &frame, s);
                    let leaves = s.points.nodes.iter().filter(|n| n.kids.is_none()).count();
                    // starts from the crossings of the path
                    if let Some(tree) = &s.path {
                        let (path, r) = m.touch.geometry.model.centre_path().unwrap();
                        let mut a = Candidates::new(4);
                        m.touch.path_starts(&frame, s, &mut a);
                        let mut b = Candidates::new(4);
                        scan(
                            tree,
                            &mut PathStarts {
                                q: q(),
                                tree,
                                path,
                                r,
                                out: &mut b,
                            },
                        );
                        assert_eq!(a.as_slice(), b.as_slice(), "path starts, {at}");
                    } else {
                        // starts from the local maxima of the first-touch function
                        let mut a = Candidates::new(4);
                        let best_a = m.touch.score_starts(&frame, s, &mut a);
                        let mut b = Candidates::new(4);
                        let mut v = ScoreStarts {
                            q: q(),
                            out: &mut b,
                            best: f64::NEG_INFINITY,
                        };
                        scan(&s.points, &mut v);
                        assert_eq!(best_a, v.best, "best sampled score, {at}");
                        assert_eq!(a.as_slice(), b.as_slice(), "score starts, {at}");
                        // how many leaves a pruned search opens
                        let mut count = Counter(
                            0,
                            ScoreStarts {
                                q: q(),
                                out: &mut Candidates::new(4),
                                best: f64::NEG_INFINITY,
                            },
                        );
                        s.points.branch_and_bound(&frame, &mut count);
                        pruned_leaves.0 += count.0;
                        pruned_leaves.1 += leaves;
                    }
                    // the best sample, and the jump guard about it
                    let best = m.touch.best_sample(&frame, s);
                    let mut v = BestSample { q: q(), best: None };
                    scan(&s.points, &mut v);
                    assert_eq!(best, v.best, "best sample, {at}");
                    if let (Some(b), true) = (best, std::ptr::eq(s, &m.touch.index.dense)) {
                        // a sample above the threshold: the global search decides
                        for t in [b.0 - 1e-9, b.0 - 0.01] {
                            assert_eq!(
                                m.touch.overtaken(&instant, t, b.1),
                                super::super::overtake::Overtaken::Sampled,
                                "above {t}, {at}"
                            );
                        }
                    }
                    checked += 1;
                }
            }
        }
    }
    assert!(checked >= 4000, "{checked} queries compared");
    // the flat faces' searches open few leaves
    assert!(
        pruned_leaves.0 * 20 < pruned_leaves.1,
        "{} of {} leaves opened",
        pruned_leaves.0,
        pruned_leaves.1
    );
}

/// Counts the leaves a query opens.
struct Counter<V>(usize, V);

impl<V: Visit> Visit for Counter<V> {
    fn bound(&self, i: usize, c: Point2, r: f64) -> Option<f64> {
        self.1.bound(i, c, r)
    }
    fn floor(&self) -> f64 {
        self.1.floor()
    }
    fn node(&mut self, i: usize) -> bool {
        self.1.node(i)
    }
    fn leaf(&mut self, lo: usize, hi: usize) {
        self.0 += 1;
        self.1.leaf(lo, hi);
    }
}
