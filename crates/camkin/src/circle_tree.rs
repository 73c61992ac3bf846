//! A tree of bounding circles over runs of consecutive points of a sampled curve, in the curve's
//! own frame: built once, it moves rigidly with the body that carries the curve (only the centres
//! it visits are moved). The general contact search prunes pairs of circles with it
//! ([`crate::contact::CurveIndex`]); the first-touch search of the named follower kinds prunes
//! circles whose every point the follower reaches later than the best touch found so far
//! ([`CircleTree::branch_and_bound`]).

use crate::geometry::{Frame, Point2};

/// Points per leaf.
pub(crate) const LEAF: usize = 8;

/// A bounding circle over the points `lo..hi`; `kids`: the two halves (none for a leaf).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Node {
    pub(crate) c: Point2,
    pub(crate) r: f64,
    pub(crate) lo: u32,
    pub(crate) hi: u32,
    pub(crate) kids: Option<(u32, u32)>,
}

/// The circles, the root first.
#[derive(Debug, Clone, Default)]
pub(crate) struct CircleTree {
    pub(crate) nodes: Vec<Node>,
}

/// What a branch-and-bound query asks of the tree.
pub(crate) trait Visit {
    /// An upper bound of the quantity sought over every point within `r` of the world point `c`,
    /// the circle of node `i` (`None` when no point there counts).
    fn bound(&self, i: usize, c: Point2, r: f64) -> Option<f64>;
    /// Looks at the inner node `i` (its bound reached the floor): true to go on into its halves.
    /// By default every inner node is opened.
    fn node(&mut self, _i: usize) -> bool {
        true
    }
    /// Circles whose bound is below this hold nothing the query still wants.
    fn floor(&self) -> f64;
    /// Looks at the points `lo..hi` (a leaf whose bound reached the floor).
    fn leaf(&mut self, lo: usize, hi: usize);
}

/// Deepest tree the traversal's fixed stack holds: 2⁶⁰ leaves.
const DEPTH: usize = 60;

impl CircleTree {
    /// The tree over `points`, each grown by its `pad` (a disc about each point: the circles then
    /// hold the continuous curve near the points, not only the points); empty without points.
    pub(crate) fn new(points: &[Point2], pad: Option<&[f64]>) -> Self {
        let mut nodes = Vec::with_capacity(2 * points.len() / LEAF + 2);
        if !points.is_empty() {
            build(points, pad, 0, points.len(), &mut nodes);
        }
        Self { nodes }
    }

    /// Visits the leaves whose bound reaches the floor, the higher bound of two halves first (so
    /// that the floor rises early); a circle is skipped when, by the time it is reached, its bound
    /// is below the floor. A bound equal to the floor is visited: ties are the query's to break.
    pub(crate) fn branch_and_bound(&self, frame: &Frame, v: &mut impl Visit) {
        let Some(root) = self.nodes.first() else {
            return;
        };
        let mut stack = [(0u32, 0.0f64); 2 * DEPTH];
        let mut len = 0;
        if let Some(b) = v.bound(0, frame * root.c, root.r) {
            stack[0] = (0, b);
            len = 1;
        }
        while len > 0 {
            len -= 1;
            let (i, b) = stack[len];
            if b < v.floor() {
                continue;
            }
            let n = &self.nodes[i as usize];
            match n.kids {
                None => v.leaf(n.lo as usize, n.hi as usize),
                Some(_) if !v.node(i as usize) => {}
                Some((k0, k1)) => {
                    let (n0, n1) = (&self.nodes[k0 as usize], &self.nodes[k1 as usize]);
                    let b0 = v.bound(k0 as usize, frame * n0.c, n0.r);
                    let b1 = v.bound(k1 as usize, frame * n1.c, n1.r);
                    // pushed low then high: the higher is popped first
                    let (first, second) =
                        if b0.unwrap_or(f64::NEG_INFINITY) >= b1.unwrap_or(f64::NEG_INFINITY) {
                            ((k1, b1), (k0, b0))
                        } else {
                            ((k0, b0), (k1, b1))
                        };
                    for (k, b) in [first, second] {
                        if let Some(b) = b {
                            if b >= v.floor() {
                                stack[len] = (k, b);
                                len += 1;
                            }
                        }
                    }
                }
            }
        }
    }
}

/// Builds the node of points `lo..hi` (and its subtree) and returns its index.
fn build(
    points: &[Point2],
    pad: Option<&[f64]>,
    lo: usize,
    hi: usize,
    nodes: &mut Vec<Node>,
) -> u32 {
    let at = nodes.len();
    nodes.push(Node {
        c: Point2::origin(),
        r: 0.0,
        lo: lo as u32,
        hi: hi as u32,
        kids: None,
    });
    let (c, r, kids) = if hi - lo <= LEAF {
        let (mut a, mut b) = (points[lo], points[lo]);
        for p in &points[lo..hi] {
            a = a.inf(p);
            b = b.sup(p);
        }
        let c = nalgebra::center(&a, &b);
        let r = (lo..hi)
            .map(|i| (points[i] - c).norm() + pad.map_or(0.0, |w| w[i]))
            .fold(0.0, f64::max);
        (c, r, None)
    } else {
        let mid = lo + (hi - lo) / 2;
        let k0 = build(points, pad, lo, mid, nodes);
        let k1 = build(points, pad, mid, hi, nodes);
        let (n0, n1) = (nodes[k0 as usize], nodes[k1 as usize]);
        // the smallest circle holding both circles
        let d = (n1.c - n0.c).norm();
        let (c, r) = if d + n1.r <= n0.r {
            (n0.c, n0.r)
        } else if d + n0.r <= n1.r {
            (n1.c, n1.r)
        } else {
            let r = 0.5 * (d + n0.r + n1.r);
            (n0.c + (n1.c - n0.c) * ((r - n0.r) / d), r)
        };
        (c, r, Some((k0, k1)))
    };
    // rounding: every point inside by a margin (a pruned circle never holds one at the bound),
    // also of the rounding of moving a far centre
    nodes[at].c = c;
    nodes[at].r = r * (1.0 + 1e-12) + 1e-15 * c.coords.norm() + 1e-300;
    nodes[at].kids = kids;
    at as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Finds the largest `x` of a set of points with bounds `c.x + r`: the same point as the
    /// scan, leaves visited far fewer than all of them.
    struct MaxX<'a> {
        pts: &'a [Point2],
        frame: Frame,
        best: (f64, usize),
        leaves: usize,
    }
    impl Visit for MaxX<'_> {
        fn bound(&self, _i: usize, c: Point2, r: f64) -> Option<f64> {
            Some(c.x + r)
        }
        fn floor(&self) -> f64 {
            self.best.0
        }
        fn leaf(&mut self, lo: usize, hi: usize) {
            self.leaves += 1;
            for i in lo..hi {
                let x = (self.frame * self.pts[i]).x;
                if x > self.best.0 || (x == self.best.0 && i < self.best.1) {
                    self.best = (x, i);
                }
            }
        }
    }

    #[test]
    fn branch_and_bound_finds_the_scans_maximum_visiting_few_leaves() {
        let n = 4096;
        let pts: Vec<Point2> = (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * i as f64 / n as f64;
                let r = 1.0 + 0.2 * (5.0 * t).sin();
                Point2::new(r * t.cos(), r * t.sin())
            })
            .collect();
        let tree = CircleTree::new(&pts, None);
        for k in 0..50 {
            let frame = Frame::new(nalgebra::Vector2::new(3.0, -1.0), 0.13 * f64::from(k));
            let mut v = MaxX {
                pts: &pts,
                frame,
                best: (f64::NEG_INFINITY, 0),
                leaves: 0,
            };
            tree.branch_and_bound(&frame, &mut v);
            let scan = (0..n)
                .map(|i| ((frame * pts[i]).x, i))
                .fold((f64::NEG_INFINITY, 0), |m, e| if e.0 > m.0 { e } else { m });
            assert_eq!(v.best, scan, "pose {k}");
            assert!(
                v.leaves <= 32,
                "{} of {} leaves at pose {k}",
                v.leaves,
                n / LEAF
            );
        }
    }
}
