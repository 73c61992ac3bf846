//! Where the first-touch search starts Newton: the profile's samples under trees of bounding
//! circles ([`SearchIndex`], built once per mechanism in the cam's frame), searched by branch and
//! bound. A circle is pruned when the follower reaches every point in it later than the starts
//! already kept ([`Kind::score_interval`], [`CentrePath::interval`]): the starts found are the
//! scan's, ties broken by the lower cam parameter, in O(log N) visits where few parts of the
//! profile come near the follower's first touch instead of O(N).

use super::FirstTouch;
use crate::body::CurveInFrame;
use crate::cam::follower::{CentrePath, Kind as _};
use crate::circle_tree::{CircleTree, Visit};
use crate::geometry::{rot90, Frame, Point2};

/// Most start candidates refined by the global search.
pub const MAX_CANDIDATES: usize = 8;

/// The best few start candidates `(oriented score, u, q)`, best first (ties: the lower `u`
/// first), kept without allocating.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Candidates {
    items: [(f64, f64, f64); MAX_CANDIDATES],
    len: usize,
    cap: usize,
}

impl Candidates {
    pub(crate) fn new(cap: usize) -> Self {
        Self {
            items: [(0.0, 0.0, 0.0); MAX_CANDIDATES],
            len: 0,
            cap: cap.clamp(1, MAX_CANDIDATES),
        }
    }
    /// Whether `a` goes before `b`.
    fn before(a: &(f64, f64, f64), b: &(f64, f64, f64)) -> bool {
        a.0 > b.0 || (a.0 == b.0 && a.1 < b.1)
    }
    pub(crate) fn push(&mut self, c: (f64, f64, f64)) {
        if self.len == self.cap {
            if !Self::before(&c, &self.items[self.len - 1]) {
                return;
            }
            self.len -= 1;
        }
        let mut i = self.len;
        while i > 0 && Self::before(&c, &self.items[i - 1]) {
            self.items[i] = self.items[i - 1];
            i -= 1;
        }
        self.items[i] = c;
        self.len += 1;
    }
    /// No candidate scoring below this can enter.
    fn floor(&self) -> f64 {
        if self.len == self.cap {
            self.items[self.len - 1].0
        } else {
            f64::NEG_INFINITY
        }
    }
    pub(crate) fn is_empty(&self) -> bool {
        self.len == 0
    }
    pub(crate) fn as_slice(&self) -> &[(f64, f64, f64)] {
        &self.items[..self.len]
    }
}

/// The samples of one density with their trees.
#[derive(Debug, Clone, Default)]
pub(crate) struct Sampled {
    pub(crate) params: Vec<f64>,
    /// over the profile's points at `params`
    points: CircleTree,
    /// over the points of the path's offset curve (the profile for a knife, the pitch curve for
    /// a roller) at `params`, each grown by its longer neighbouring chord: the continuous curve
    /// between neighbouring samples is taken to stay that close to them, as the scan's
    /// root-finding between samples also assumes; `None` for a flat face
    path: Option<CircleTree>,
    /// for each node of the points' tree, the tangent directions of the profile (cam frame,
    /// `(mid, half width)`, rad) from the sample before its first to the sample after its last;
    /// `None` where they may span a half turn
    turn: Vec<Option<(f64, f64)>>,
    /// the same for the path's tree (it splits the samples alike): the offset curve's tangent is
    /// the profile's, but where the roller is larger than a concave radius of curvature the
    /// offset curve turns back at a cusp, where the distance from the path has an extremum
    /// whatever the tangent: those runs are `None`
    path_turn: Vec<Option<(f64, f64)>>,
    /// for each node of the points' tree, the longest chord from one of its samples to a
    /// neighbouring sample: its circle grown by it holds the continuous curve between the
    /// samples (the jump guard's bound, [`Mechanism::overtaken`])
    pub(super) pad: Vec<f64>,
}

/// The samples of the two densities of the first-touch search: dense (a non-convex profile's
/// global search, the jump guard) and coarse (a convex profile's start).
#[derive(Debug, Clone, Default)]
pub(crate) struct SearchIndex {
    pub(crate) dense: Sampled,
    pub(crate) coarse: Sampled,
}

impl Sampled {
    /// The tree over the profile's points at the samples.
    pub(crate) fn points(&self) -> &CircleTree {
        &self.points
    }

    pub(crate) fn new(m: &FirstTouch, params: Vec<f64>) -> Self {
        let profile = m.cam.profile.as_ref();
        let derivs: Vec<_> = params.iter().map(|&u| profile.eval(u)).collect();
        let points: Vec<Point2> = derivs.iter().map(|d| d.p).collect();
        let path = m.geometry.model.centre_path().map(|(_, r)| {
            let off: Vec<Point2> = params.iter().map(|&u| m.offset_point(u, r)).collect();
            let n = off.len();
            let chord = |k: usize| (off[(k + 1) % n] - off[k]).norm();
            let pad: Vec<f64> = (0..n)
                .map(|k| chord(k).max(chord((k + n - 1) % n)))
                .collect();
            CircleTree::new(&off, Some(&pad))
        });
        let n = points.len();
        let chord = |k: usize| (points[(k + 1) % n] - points[k]).norm();
        let sample_pad: Vec<f64> = (0..n)
            .map(|k| chord(k).max(chord((k + n - 1) % n)))
            .collect();
        let points = CircleTree::new(&points, None);
        let pad = points
            .nodes
            .iter()
            .map(|node| {
                sample_pad[node.lo as usize..node.hi as usize]
                    .iter()
                    .fold(0.0, |a: f64, &b| a.max(b))
            })
            .collect();
        let angles: Vec<Option<f64>> = derivs
            .iter()
            .map(|d| (d.d1.norm_squared() > 0.0).then(|| d.d1.y.atan2(d.d1.x)))
            .collect();
        let turn = tangent_ranges(&points, &angles, |_| true);
        let path_turn = match m.geometry.model.centre_path() {
            Some((_, r)) if r > 0.0 => {
                // the offset curve's speed over the profile's: 1 + r κ (κ > 0 convex)
                let factor: Vec<f64> = derivs
                    .iter()
                    .map(|d| {
                        let speed = d.d1.norm();
                        let kappa = m.orientation * d.d1.perp(&d.d2) / (speed * speed * speed);
                        1.0 + r * kappa
                    })
                    .collect();
                let n = factor.len();
                tangent_ranges(&points, &angles, |k| {
                    factor[k % n] > 0.0 && factor[(k + 1) % n] > 0.0
                })
            }
            _ => turn.clone(),
        };
        Self {
            points,
            params,
            path,
            turn,
            path_turn,
            pad,
        }
    }
}

/// Where the tangent turns by more than this between neighbouring samples, its directions in
/// between are not taken from theirs.
const SPAN_TURN: f64 = std::f64::consts::FRAC_PI_4;

/// The tangent directions over each node of `tree` (see [`Sampled::turn`]) from the tangent
/// angles at the samples (`None` at a cusp). Between two samples the tangent is taken to turn
/// from one's direction to the other's the short way, within half that turn beyond either.
/// Spans that `valid` refuses (by the index of their first sample) count as any direction.
fn tangent_ranges(
    tree: &CircleTree,
    angles: &[Option<f64>],
    valid: impl Fn(usize) -> bool,
) -> Vec<Option<(f64, f64)>> {
    use std::f64::consts::PI;
    let n = angles.len();
    // span k: from sample k to sample k + 1, as an interval [lo, hi] of unwrapped angles
    let span = |k: usize| -> Option<(f64, f64)> {
        if !valid(k) {
            return None;
        }
        let (a, b) = (angles[k % n]?, angles[(k + 1) % n]?);
        let d = crate::geometry::wrap_angle_near(b - a, 0.0);
        if d.abs() > SPAN_TURN {
            return None;
        }
        let (lo, hi) = (a.min(a + d), a.max(a + d));
        let g = 0.5 * (hi - lo) + 1e-9;
        Some((lo - g, hi + g))
    };
    // the union of two overlapping (modulo a turn) intervals; `None` from a half turn on
    let union = |x: Option<(f64, f64)>, y: Option<(f64, f64)>| -> Option<(f64, f64)> {
        let ((x0, x1), (y0, y1)) = (x?, y?);
        let shift = 2.0 * PI * ((0.5 * (x0 + x1 - y0 - y1)) / (2.0 * PI)).round();
        let (lo, hi) = (x0.min(y0 + shift), x1.max(y1 + shift));
        (hi - lo < PI).then_some((lo, hi))
    };
    let mut out = vec![None; tree.nodes.len()];
    for (i, node) in tree.nodes.iter().enumerate().rev() {
        // children come after their parent: reversed, they are done first
        out[i] = match node.kids {
            Some((k0, k1)) => union(out[k0 as usize], out[k1 as usize]),
            None => {
                let (lo, hi) = (node.lo as usize, node.hi as usize);
                // spans from the sample before lo to the sample after hi − 1
                (lo + n - 1..hi + n).fold(span(lo + n - 1), |acc, k| union(acc, span(k)))
            }
        };
    }
    out.into_iter()
        .map(|r| r.map(|(lo, hi)| (0.5 * (lo + hi), 0.5 * (hi - lo))))
        .collect()
}

/// Whether two sets of directions `(mid, half width)` (rad) can share a direction modulo a half
/// turn.
fn may_be_parallel(a: (f64, f64), b: (f64, f64)) -> bool {
    use std::f64::consts::PI;
    let x = a.0 - b.0;
    let d = x - PI * (x / PI).round();
    d.abs() <= a.1 + b.1
}

impl FirstTouch {
    /// The point of the profile's outward offset curve at distance `r` at parameter `u` (cam
    /// frame): the profile itself for `r = 0`.
    #[inline]
    fn offset_point(&self, u: f64, r: f64) -> Point2 {
        let profile = self.cam.profile.as_ref();
        if r == 0.0 {
            return profile.position(u);
        }
        // outward normal −orientation·rot90(r')/|r'|
        let shift = -self.orientation * r;
        let d = profile.eval(u);
        let len = d.d1.norm();
        if len > 0.0 {
            d.p + (shift / len) * rot90(d.d1)
        } else {
            d.p
        }
    }

    /// An upper bound of the oriented first-touch score of the cam points within `r` of `c`.
    #[inline]
    pub(super) fn score_bound(&self, c: Point2, r: f64) -> Option<f64> {
        let interval = self.geometry.model.score_interval(c, r)?;
        Some(self.geometry.joint.oriented_bound(interval))
    }

    /// Start candidates for a knife edge or a roller: the crossings of the path of its tip or
    /// centre with the profile's offset curve at its distance (the profile itself for a knife,
    /// the pitch curve for a roller), sampled at `s` (linear interpolation between samples),
    /// best first. Sign changes find a crossing however thin the roller's reach is beside the
    /// path (a small roller, a long thin cam). Two crossings between neighbouring samples (the
    /// path nearly tangent to the offset curve) show no sign change: where the sampled distance
    /// from the path has a local minimum, its true minimum is located and, when it crosses the
    /// path, both crossings become candidates. Only the samples whose tree circles meet the path
    /// ahead of the candidates kept are looked at, and of those not the runs along which the
    /// distance from the path is monotone and keeps its sign.
    pub(crate) fn path_starts(&self, frame: &Frame, s: &Sampled, out: &mut Candidates) {
        let (Some((path, r)), Some(tree)) = (self.geometry.model.centre_path(), &s.path) else {
            return;
        };
        let mut v = PathStarts {
            q: Query::new(self, frame, s),
            tree,
            path,
            r,
            out,
        };
        tree.branch_and_bound(frame, &mut v);
    }

    /// Start candidates: the local maxima of the first-touch function sampled at `s`, best
    /// first; returns the best sampled score (a lower bound of the true first touch). Runs of
    /// samples along which the function is monotone hold none and are not looked at.
    pub(crate) fn score_starts(&self, frame: &Frame, s: &Sampled, out: &mut Candidates) -> f64 {
        let mut v = ScoreStarts {
            q: Query::new(self, frame, s),
            out,
            best: f64::NEG_INFINITY,
        };
        s.points.branch_and_bound(frame, &mut v);
        v.best
    }

    /// The single best sample of the first-touch function at `s` (`(score, u, q)`; the lowest
    /// `u` among equals).
    pub(crate) fn best_sample(&self, frame: &Frame, s: &Sampled) -> Option<(f64, f64, f64)> {
        let mut v = BestSample {
            q: Query::new(self, frame, s),
            best: None,
        };
        s.points.branch_and_bound(frame, &mut v);
        v.best
    }
}

/// What every query of the samples shares.
pub(super) struct Query<'a> {
    pub(super) m: &'a FirstTouch,
    pub(super) frame: &'a Frame,
    pub(super) s: &'a Sampled,
    /// the cam frame's angle: the samples' tangent directions turned to the world
    angle: f64,
}

impl<'a> Query<'a> {
    pub(super) fn new(m: &'a FirstTouch, frame: &'a Frame, s: &'a Sampled) -> Self {
        Self {
            m,
            frame,
            s,
            angle: frame.rotation.angle(),
        }
    }

    /// The first-touch score of sample `k`.
    #[inline]
    pub(super) fn score(&self, k: usize) -> Option<(f64, f64)> {
        let profile = self.m.cam.profile.as_ref();
        let u = self.s.params[k];
        self.m
            .geometry
            .model
            .score(self.frame.curve_position(profile, u))
    }

    /// Whether node `i`'s tangent directions (from the sample before its first to the sample
    /// after its last; `turn`: the profile's or the path's offset curve's) avoid `dirs`
    /// (world): then what is stationary only at those directions is monotone along those
    /// samples.
    fn avoids(&self, turn: &[Option<(f64, f64)>], i: usize, dirs: Option<(f64, f64)>) -> bool {
        match (turn[i], dirs) {
            (Some((mid, half)), Some(d)) => !may_be_parallel((mid + self.angle, half), d),
            _ => false,
        }
    }

    /// Whether the first-touch score is monotone over node `i` of the points' tree.
    pub(super) fn score_monotone(&self, i: usize, c: Point2, r: f64) -> bool {
        self.avoids(
            &self.s.turn,
            i,
            self.m.geometry.model.stationary_tangents(c, r),
        )
    }
}

/// [`Mechanism::best_sample`]'s query.
struct BestSample<'a> {
    q: Query<'a>,
    best: Option<(f64, f64, f64)>,
}

impl BestSample<'_> {
    fn offer(&mut self, k: usize) {
        let Some((sc, q)) = self.q.score(k) else {
            return;
        };
        let u = self.q.s.params[k];
        if self.best.is_none_or(|b| sc > b.0 || (sc == b.0 && u < b.1)) {
            self.best = Some((sc, u, q));
        }
    }
}

impl Visit for BestSample<'_> {
    fn bound(&self, _i: usize, c: Point2, r: f64) -> Option<f64> {
        self.q.m.score_bound(c, r)
    }
    fn floor(&self) -> f64 {
        self.best.map_or(f64::NEG_INFINITY, |b| b.0)
    }
    fn node(&mut self, i: usize) -> bool {
        let n = self.q.s.points.nodes[i];
        if !self.q.score_monotone(i, self.q.frame * n.c, n.r) {
            return true;
        }
        // monotone: its best sample is at one end
        self.offer(n.lo as usize);
        self.offer(n.hi as usize - 1);
        false
    }
    fn leaf(&mut self, lo: usize, hi: usize) {
        for k in lo..hi {
            self.offer(k);
        }
    }
}

/// [`Mechanism::score_starts`]'s query.
struct ScoreStarts<'a> {
    q: Query<'a>,
    out: &'a mut Candidates,
    best: f64,
}

impl Visit for ScoreStarts<'_> {
    fn bound(&self, i: usize, c: Point2, r: f64) -> Option<f64> {
        // a monotone run holds no local maximum
        if self.q.score_monotone(i, c, r) {
            return None;
        }
        self.q.m.score_bound(c, r)
    }
    fn floor(&self) -> f64 {
        self.out.floor()
    }
    fn leaf(&mut self, lo: usize, hi: usize) {
        let n = self.q.s.params.len();
        let val = |x: Option<(f64, f64)>| x.map_or(f64::NEG_INFINITY, |x| x.0);
        let (mut prev, mut cur) = (self.q.score((lo + n - 1) % n), self.q.score(lo));
        for k in lo..hi {
            let next = self.q.score((k + 1) % n);
            if let Some((sc, q)) = cur {
                self.best = self.best.max(sc);
                if sc >= val(prev) && sc >= val(next) {
                    self.out.push((sc, self.q.s.params[k], q));
                }
            }
            (prev, cur) = (cur, next);
        }
    }
}

/// [`Mechanism::path_starts`]'s query.
struct PathStarts<'a> {
    q: Query<'a>,
    tree: &'a CircleTree,
    path: CentrePath,
    r: f64,
    out: &'a mut Candidates,
}

impl PathStarts<'_> {
    /// The world point of the offset curve at `u`.
    #[inline]
    fn at(&self, u: f64) -> Point2 {
        self.q.frame * self.q.m.offset_point(u, self.r)
    }
    /// The signed distance of `x` from the path.
    #[inline]
    fn lateral_of(&self, x: Point2) -> f64 {
        match self.path {
            CentrePath::Line { p, e, .. } => (x - self.q.m.cam.pivot).dot(&p) - e,
            CentrePath::Circle { o, l, .. } => (x - o).norm() - l,
        }
    }
}

impl Visit for PathStarts<'_> {
    fn bound(&self, i: usize, c: Point2, r: f64) -> Option<f64> {
        let (mid, half) = self.path.interval(self.q.m.cam.pivot, c, r)?;
        let interval = (mid - self.path.lead(), half);
        if self
            .q
            .avoids(&self.q.s.path_turn, i, Some(self.path.tangents(c, r)))
        {
            // the distance from the path is monotone from the sample before the first to the
            // sample after the last: no crossing if it keeps its sign
            let (s, n) = (&self.q.s.params, self.q.s.params.len());
            let node = &self.tree.nodes[i];
            let before = self.lateral_of(self.at(s[(node.lo as usize + n - 1) % n]));
            let after = self.lateral_of(self.at(s[node.hi as usize % n]));
            if (before > 0.0 && after > 0.0) || (before < 0.0 && after < 0.0) {
                return None;
            }
        }
        Some(self.q.m.geometry.joint.oriented_bound(interval))
    }
    fn floor(&self) -> f64 {
        self.out.floor()
    }
    fn leaf(&mut self, lo: usize, hi: usize) {
        let m = self.q.m;
        let (s, n, r, period) = (&self.q.s.params, self.q.s.params.len(), self.r, m.period);
        let (pivot, joint) = (m.cam.pivot, m.geometry.joint);
        let coord = |x: Point2| joint.branch(self.path.coordinate(pivot, x));
        let at = |u: f64| self.at(u);
        let lateral = |u: f64| self.lateral_of(self.at(u));
        // a roller's start must put its centre within a fraction of its radius of the pitch
        // curve, or Newton can settle on the roller's far side (the two are a diameter apart):
        // linear interpolation between samples is not that close for a small roller
        let root = |lo: f64, hi: f64| {
            if r == 0.0 {
                bisect_sign(&lateral, lo, hi)
            } else {
                falsi(&lateral, lo, hi, lateral(lo), lateral(hi), 0.1 * r)
            }
        };
        let mut found = Candidates::new(MAX_CANDIDATES);
        let mut push = |u: f64, x: Point2| {
            let (score, q) = coord(x);
            found.push((score, u.rem_euclid(period), q));
        };
        let mut xa = at(s[lo]);
        let mut la = self.lateral_of(xa);
        let mut l_before = lateral(s[(lo + n - 1) % n]);
        for k in lo..hi {
            let (xb, ub) = if k + 1 < n {
                (at(s[k + 1]), s[k + 1])
            } else {
                (at(s[0]), period)
            };
            let lb = self.lateral_of(xb);
            let ua = if k == 0 { s[n - 1] - period } else { s[k - 1] };
            if (la > 0.0) != (lb > 0.0) && (l_before > 0.0) != (la > 0.0) {
                // two crossings on either side of sample k: the path is nearly tangent there and
                // interpolated starts can both lead Newton to one of them; start from each root
                for (lo, hi) in [(ua, s[k]), (s[k], ub)] {
                    let u0 = root(lo, hi);
                    push(u0, at(u0));
                }
            } else if la == 0.0 || (la > 0.0) != (lb > 0.0) {
                let f = if la == lb { 0.0 } else { la / (la - lb) };
                if r == 0.0 {
                    push(s[k] + f * (ub - s[k]), xa + f * (xb - xa));
                } else {
                    let u0 = falsi(&lateral, s[k], ub, la, lb, 0.1 * r);
                    push(u0, at(u0));
                }
            } else if (l_before > 0.0) == (la > 0.0)
                && la.abs() < l_before.abs()
                && la.abs() <= lb.abs()
            {
                // a local minimum of |distance| at sample k: does the curve cross in between?
                let sign = la.signum();
                // stopping once it crosses: that is all that is needed
                let (um, lm) =
                    crate::cam::golden::golden_min(|u| sign * lateral(u), ua, ub, 60, |v| v < 0.0);
                if lm < 0.0 {
                    for (lo, hi) in [(ua, um), (um, ub)] {
                        let u0 = root(lo, hi);
                        push(u0, at(u0));
                    }
                }
            }
            l_before = la;
            (xa, la) = (xb, lb);
        }
        for &c in found.as_slice() {
            self.out.push(c);
        }
    }
}

/// A root of `f` in `[a, b]` (`fa = f(a)`, `fb = f(b)` of opposite signs, or one zero) by the
/// Illinois variant of regula falsi, stopping once `|f| ≤ tol`: the first step is the linear
/// interpolation, so a root the samples already pin down costs one evaluation.
fn falsi(
    f: &impl Fn(f64) -> f64,
    mut a: f64,
    mut b: f64,
    mut fa: f64,
    mut fb: f64,
    tol: f64,
) -> f64 {
    if fa == 0.0 {
        return a;
    }
    let mut side = 0;
    let mut x = a;
    for _ in 0..100 {
        if fb == 0.0 {
            return b;
        }
        x = (a * fb - b * fa) / (fb - fa);
        if !(x > a.min(b) && x < a.max(b)) {
            x = 0.5 * (a + b);
        }
        let fx = f(x);
        if fx.abs() <= tol || x == a || x == b {
            return x;
        }
        if (fx > 0.0) == (fb > 0.0) {
            (b, fb) = (x, fx);
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            (a, fa) = (x, fx);
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    x
}

/// A point near the sign change of `f` in `[a, b]` (the ends have opposite signs), by 30
/// bisections: a start for Newton.
fn bisect_sign(f: &impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let fa = f(a);
    for _ in 0..30 {
        let m = 0.5 * (a + b);
        if (f(m) > 0.0) == (fa > 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
#[path = "starts_tests.rs"]
mod tests;
