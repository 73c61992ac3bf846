//! The global bracketing of [`find_contact`](super::find_contact) without comparing every sample
//! pair: each curve's samples (in its own frame) under a tree of bounding circles over runs of
//! consecutive samples, and a dual traversal that prunes pairs of circles farther apart than the
//! nearest pairs found so far.
//!
//! The search answers exactly what the brute force answered: for each sample of A its nearest
//! sample of B, and the `k` samples of A nearest to B (ties broken by the lower index, as a
//! stable sort of the brute force's list would). A circle tree is rigid: it moves with its body
//! by moving its centres, so it is built once per curve ([`CurveIndex`]) and queried at any pose.

use crate::circle_tree::{CircleTree, Node, LEAF};
use crate::curve::{Curve, Domain};
use crate::geometry::{Frame, Point2};

/// A curve's samples (parameters and points in the curve's own frame) with a tree of bounding
/// circles over them: built once, queried at any pose of the body that carries the curve.
#[derive(Debug, Clone)]
pub struct CurveIndex {
    params: Vec<f64>,
    points: Vec<Point2>,
    tree: CircleTree,
}

impl CurveIndex {
    /// The index of `curve` sampled at `params` (the search's samples: see
    /// [`SearchOptions`](super::SearchOptions)); `None` when there are none.
    pub(crate) fn from_params(curve: &dyn Curve, params: Vec<f64>) -> Option<Self> {
        if params.is_empty() {
            return None;
        }
        let points: Vec<Point2> = params.iter().map(|&u| curve.position(u)).collect();
        let tree = CircleTree::new(&points, None);
        Some(Self {
            params,
            points,
            tree,
        })
    }

    /// The index of a bounded curve with the search's samples; `None` for an unbounded curve (a
    /// line), which the search projects onto instead.
    pub fn new(curve: &dyn Curve, opts: &super::SearchOptions) -> Option<Self> {
        Self::from_params(curve, super::sample_params(curve, opts)?)
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether there are no samples (never, for an index that was built).
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Whether this is an index of `curve`: bounded, and its first and last samples on it.
    pub(crate) fn samples(&self, curve: &dyn Curve) -> bool {
        bounded(curve)
            && [0, self.points.len() - 1].iter().all(|&i| {
                let (p, q) = (curve.position(self.params[i]), self.points[i]);
                (p - q).norm() <= 1e-12 * (1.0 + q.coords.norm())
            })
    }

    pub(crate) fn param(&self, i: usize) -> f64 {
        self.params[i]
    }

    /// For a closed curve, whether the point `x` (in the curve's own frame) is inside the
    /// polygon of its samples (even-odd rule), and the longest side of that polygon (within
    /// which of the curve the polygon's answer may differ from the curve's); `None` for an open
    /// curve.
    pub(crate) fn polygon_contains(&self, closed: bool, x: Point2) -> Option<(bool, f64)> {
        if !closed || self.points.len() < 3 {
            return None;
        }
        let n = self.points.len();
        let mut inside = false;
        let mut longest: f64 = 0.0;
        for i in 0..n {
            let (p, q) = (self.points[i], self.points[(i + 1) % n]);
            longest = longest.max((q - p).norm());
            if (p.y > x.y) != (q.y > x.y) {
                let at = p.x + (x.y - p.y) / (q.y - p.y) * (q.x - p.x);
                if x.x < at {
                    inside = !inside;
                }
            }
        }
        Some((inside, longest))
    }

    /// The sampled points at a pose (world frame).
    #[cfg(test)]
    pub(crate) fn world_points(&self, frame: &Frame) -> Vec<Point2> {
        self.points.iter().map(|p| frame * p).collect()
    }
}

/// The `k` samples of A nearest to B's samples, each with its nearest sample of B, as
/// `(distance², index on A, index on B)` sorted by distance then index on A: the brute force's
/// answer, with far pairs of circles pruned.
pub(crate) fn nearest_pairs(
    a: &CurveIndex,
    fa: &Frame,
    b: &CurveIndex,
    fb: &Frame,
    k: usize,
) -> Vec<(f64, usize, usize)> {
    let mut q = Query {
        a,
        b,
        fa,
        fb,
        nn: vec![(f64::INFINITY, 0); a.len()],
        top: Vec::with_capacity(k + 1),
        k: k.max(1),
    };
    let g = q.gap(0, 0);
    q.visit(0, 0, g);
    q.top.iter().map(|&(d, i)| (d, i, q.nn[i].1)).collect()
}

/// A query's state; points and centres are moved to the world frame where they are visited (most
/// never are).
struct Query<'t> {
    a: &'t CurveIndex,
    b: &'t CurveIndex,
    fa: &'t Frame,
    fb: &'t Frame,
    /// each sample of A: its nearest distance² so far and the sample of B
    nn: Vec<(f64, usize)>,
    /// the `k` samples of A nearest so far: (distance², index), sorted
    top: Vec<(f64, usize)>,
    k: usize,
}

impl Query<'_> {
    /// No pair farther apart than this can enter the answer.
    fn bound(&self) -> f64 {
        if self.top.len() == self.k {
            self.top[self.k - 1].0
        } else {
            f64::INFINITY
        }
    }

    /// The distance between the circles of nodes `i` (A) and `j` (B): negative where they
    /// overlap (then no bound, but still an order: the deeper overlap first).
    fn gap(&self, i: u32, j: u32) -> f64 {
        let (ni, nj) = (
            &self.a.tree.nodes[i as usize],
            &self.b.tree.nodes[j as usize],
        );
        (self.fa * ni.c - self.fb * nj.c).norm() - ni.r - nj.r
    }

    /// Whether the circles at distance `g` are too far apart to hold a pair of the answer.
    fn pruned(&self, g: f64) -> bool {
        g > 0.0 && g * g > self.bound()
    }

    fn visit(&mut self, i: u32, j: u32, g: f64) {
        if self.pruned(g) {
            return;
        }
        let (ni, nj) = (self.a.tree.nodes[i as usize], self.b.tree.nodes[j as usize]);
        match (ni.kids, nj.kids) {
            (None, None) => self.leaves(&ni, &nj),
            // split the larger circle; the nearer half first, so the bound tightens early
            (Some((i0, i1)), _) if nj.kids.is_none() || ni.r >= nj.r => {
                let (g0, g1) = (self.gap(i0, j), self.gap(i1, j));
                if g0 <= g1 {
                    self.visit(i0, j, g0);
                    self.visit(i1, j, g1);
                } else {
                    self.visit(i1, j, g1);
                    self.visit(i0, j, g0);
                }
            }
            (_, Some((j0, j1))) => {
                let (g0, g1) = (self.gap(i, j0), self.gap(i, j1));
                if g0 <= g1 {
                    self.visit(i, j0, g0);
                    self.visit(i, j1, g1);
                } else {
                    self.visit(i, j1, g1);
                    self.visit(i, j0, g0);
                }
            }
            (Some(_), None) => unreachable!("handled by the arm above"),
        }
    }

    fn leaves(&mut self, ni: &Node, nj: &Node) {
        let (lo, hi) = (nj.lo as usize, nj.hi as usize);
        let mut pb = [Point2::origin(); LEAF];
        for (y, p) in pb.iter_mut().zip(&self.b.points[lo..hi]) {
            *y = self.fb * p;
        }
        for ia in ni.lo as usize..ni.hi as usize {
            let x = self.fa * self.a.points[ia];
            let (mut best, mut at) = self.nn[ia];
            for (ib, y) in (lo..hi).zip(&pb) {
                let d = (x - y).norm_squared();
                // the lowest index among equals, as the brute force's first minimum
                if d < best || (d == best && ib < at) {
                    best = d;
                    at = ib;
                }
            }
            if (best, at) != self.nn[ia] {
                self.nn[ia] = (best, at);
                self.offer(best, ia);
            }
        }
    }

    /// A sample of A whose nearest distance² fell to `d`: kept when among the `k` nearest.
    fn offer(&mut self, d: f64, ia: usize) {
        if let Some(p) = self.top.iter().position(|&(_, i)| i == ia) {
            self.top.remove(p);
        }
        let at = self.top.partition_point(|&(e, i)| (e, i) < (d, ia));
        if at < self.k {
            self.top.insert(at, (d, ia));
            self.top.truncate(self.k);
        }
    }
}

/// Whether a curve is bounded (it can be indexed).
pub(crate) fn bounded(c: &dyn Curve) -> bool {
    !matches!(c.domain(), Domain::Interval { min, max } if !(min.is_finite() && max.is_finite()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::ClosedSpline;

    /// Against the brute force it replaces: the same `k` nearest samples of A, the same partners,
    /// on curves of 3 to 40 nodes at many poses (ties included: a circle-like spline facing a
    /// copy of itself).
    #[test]
    fn nearest_pairs_match_the_brute_force() {
        let star = |n: usize, r: f64, wob: f64| {
            let pts: Vec<Point2> = (0..n)
                .map(|i| {
                    let t = std::f64::consts::TAU * i as f64 / n as f64;
                    let rr = r * (1.0 + wob * (3.0 * t).sin());
                    Point2::new(rr * t.cos(), rr * t.sin())
                })
                .collect();
            ClosedSpline::new(&pts).unwrap()
        };
        for (na, nb) in [(3, 3), (5, 17), (40, 12), (24, 24)] {
            let (ca, cb) = (star(na, 2.0, 0.2), star(nb, 1.0, 0.1));
            let opts = super::super::SearchOptions::default();
            let (ia, ib) = (
                CurveIndex::new(&ca, &opts).unwrap(),
                CurveIndex::new(&cb, &opts).unwrap(),
            );
            for pose in 0..40 {
                let t = f64::from(pose);
                let fa = Frame::new(nalgebra::Vector2::new(0.1 * t, -0.05 * t), 0.3 * t);
                let fb = Frame::new(nalgebra::Vector2::new(3.0 - 0.07 * t, 0.2), -0.2 * t);
                let (pa, pb) = (ia.world_points(&fa), ib.world_points(&fb));
                let mut brute: Vec<(f64, usize, usize)> = pa
                    .iter()
                    .enumerate()
                    .map(|(i, x)| {
                        let (j, d) = pb
                            .iter()
                            .enumerate()
                            .map(|(j, y)| (j, (x - y).norm_squared()))
                            .fold((0, f64::INFINITY), |m, e| if e.1 < m.1 { e } else { m });
                        (d, i, j)
                    })
                    .collect();
                brute.sort_by(|x, y| x.0.total_cmp(&y.0));
                brute.truncate(6);
                assert_eq!(
                    nearest_pairs(&ia, &fa, &ib, &fb, 6),
                    brute,
                    "{na}/{nb} at pose {pose}"
                );
            }
        }
    }
}
