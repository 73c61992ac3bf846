//! Closed (periodic, C²) cubic spline through nodal points: the paper's cam contour.

use super::{Curve, CurveError, Derivs, Domain};
use crate::geometry::{Point2, Vec2};
use crate::periodic::{fit, Knots};

/// The largest coordinate of a spline's node (in magnitude): the chords (up to 2.9e300), their
/// sum over 100 000 nodes and the coefficients stay finite.
pub const MAX_COORDINATE: f64 = 1e300;

/// The chords a chord-length spline takes: its derivatives (the third about size / chord³)
/// stay within f64's normal range.
pub const CHORD_RANGE: (f64, f64) = (1e-150, 1e150);

/// Where the nodes sit in the parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Parameterization {
    /// Node i at `u = i`; `u ∈ [0, n)`. The paper's choice and the default.
    #[default]
    Uniform,
    /// Node i at the cumulative chord length `Σ_{j<i} |P_{j+1} − P_j|`; `u ∈ [0, perimeter of the
    /// node polygon)`. Smoother for unevenly spaced nodes.
    ChordLength,
}

/// A closed cubic spline through `n ≥ 3` nodes: periodic, C² everywhere including the seam
/// between the last node and the first, so no end conditions are needed. The third derivative is
/// constant on each segment and jumps at the nodes ([`Curve::breakpoints`]).
#[derive(Debug, Clone)]
pub struct ClosedSpline {
    nodes: Vec<Point2>,
    knots: Knots,
    /// each segment's start and coefficients side by side (one lookup, one cache line or two)
    pieces: Vec<Piece>,
    parameterization: Parameterization,
}

/// Segment `i` of a closed spline: its start parameter `u_i` and local cubic coefficients
/// `[c0, c1, c2, c3]` for x and y (`x = c0 + c1 t + c2 t² + c3 t³`, `t = u − u_i`), and
/// those of the derivatives, `[2 c2, 3 c3, 6 c3]` (an evaluation multiplies by them only).
#[derive(Debug, Clone, Copy)]
struct Piece {
    start: f64,
    x: [f64; 4],
    y: [f64; 4],
    dx: [f64; 3],
    dy: [f64; 3],
}

/// `[2 c2, 3 c3, 6 c3]` of a cubic's coefficients.
fn derivative_coefficients(c: &[f64; 4]) -> [f64; 3] {
    [2.0 * c[2], 3.0 * c[3], 6.0 * c[3]]
}

/// A cubic's value and first three derivatives at `t`, from its coefficients `c` and its
/// derivatives' `d` ([`derivative_coefficients`]).
#[inline(always)]
fn eval_piece(c: &[f64; 4], d: &[f64; 3], t: f64) -> [f64; 4] {
    [
        c[0] + t * (c[1] + t * (c[2] + t * c[3])),
        c[1] + t * (d[0] + t * d[1]),
        d[0] + t * d[2],
        d[2],
    ]
}

impl ClosedSpline {
    /// The closed spline through `nodes`, uniformly parameterised (node i at `u = i`).
    pub fn new(nodes: &[Point2]) -> Result<Self, CurveError> {
        Self::with_parameterization(nodes, Parameterization::Uniform)
    }

    /// The closed spline through `nodes` with the given parameterisation.
    ///
    /// Errors: fewer than three nodes, a non-finite coordinate or one beyond
    /// [`MAX_COORDINATE`], two consecutive nodes that coincide (the last and the first count as
    /// consecutive), with chord lengths a chord outside [`CHORD_RANGE`].
    pub fn with_parameterization(
        nodes: &[Point2],
        parameterization: Parameterization,
    ) -> Result<Self, CurveError> {
        let n = nodes.len();
        if n < 3 {
            return Err(CurveError::TooFewPoints { count: n });
        }
        for (index, p) in nodes.iter().enumerate() {
            if !(p.x.is_finite() && p.y.is_finite()) {
                return Err(CurveError::NonFinitePoint {
                    index,
                    x: p.x,
                    y: p.y,
                });
            }
            // a chord between nodes near f64's limit, or the sum of the chords, overflows: the
            // curve came out NaN everywhere (chord lengths from 1e160, uniform near 1.7e308)
            if p.x.abs().max(p.y.abs()) > MAX_COORDINATE {
                return Err(CurveError::FarPoint {
                    index,
                    x: p.x,
                    y: p.y,
                });
            }
        }
        for index in 0..n {
            let next = (index + 1) % n;
            if nodes[index] == nodes[next] {
                return Err(CurveError::RepeatedPoint {
                    index,
                    next,
                    x: nodes[index].x,
                    y: nodes[index].y,
                });
            }
        }
        let knots = match parameterization {
            Parameterization::Uniform => Knots::uniform(n, 1.0),
            Parameterization::ChordLength => {
                // hypot: a chord's square overflows from about 1e154
                let h: Vec<f64> = (0..n)
                    .map(|i| {
                        let d = nodes[(i + 1) % n] - nodes[i];
                        d.x.hypot(d.y)
                    })
                    .collect();
                // the third derivative is about (size / chord³): chords from 1e154 left it
                // below f64's normal range, and the curve came out wrong, not NaN
                if let Some(index) = h
                    .iter()
                    .position(|l| !(CHORD_RANGE.0..=CHORD_RANGE.1).contains(l))
                {
                    return Err(CurveError::ChordLength {
                        index,
                        next: (index + 1) % n,
                        length: h[index],
                    });
                }
                Knots::from_lengths(&h)
            }
        };
        let xs: Vec<f64> = nodes.iter().map(|p| p.x).collect();
        let ys: Vec<f64> = nodes.iter().map(|p| p.y).collect();
        let cx = fit(&knots, &xs);
        let cy = fit(&knots, &ys);
        let pieces = (0..n)
            .map(|i| Piece {
                start: knots.u[i],
                x: cx[i],
                y: cy[i],
                dx: derivative_coefficients(&cx[i]),
                dy: derivative_coefficients(&cy[i]),
            })
            .collect();
        Ok(Self {
            nodes: nodes.to_vec(),
            knots,
            pieces,
            parameterization,
        })
    }

    /// The nodes, as given.
    pub fn nodes(&self) -> &[Point2] {
        &self.nodes
    }

    /// The parameter of node `i` (i < n).
    pub fn node_param(&self, i: usize) -> f64 {
        self.knots.u[i]
    }

    /// The parameterisation.
    pub fn parameterization(&self) -> Parameterization {
        self.parameterization
    }

    /// Number of cubic segments (= number of nodes).
    pub fn segments(&self) -> usize {
        self.knots.segments()
    }

    /// Segment `i`: its start parameter, its length in `u`, and its local cubic coefficients
    /// `[c0, c1, c2, c3]` for x and y (`x = c0 + c1 t + c2 t² + c3 t³`, `t = u − start`).
    pub fn segment(&self, i: usize) -> (f64, f64, [f64; 4], [f64; 4]) {
        let c = &self.pieces[i];
        (c.start, self.knots.h(i), c.x, c.y)
    }
}

impl ClosedSpline {
    /// Where the spline crosses itself, if it does: the parameters of the two crossing stretches
    /// and the crossing point. The spline is sampled as a polyline of 8 chords per segment and
    /// the chords are checked pairwise through a uniform grid (expected linear time).
    pub fn self_intersection(&self) -> Option<(f64, f64, Point2)> {
        const PER_SEGMENT: usize = 8;
        let n = self.segments();
        let m = n * PER_SEGMENT;
        let params: Vec<f64> = (0..m)
            .map(|i| {
                let seg = i / PER_SEGMENT;
                self.knots.u[seg]
                    + self.knots.h(seg) * (i % PER_SEGMENT) as f64 / PER_SEGMENT as f64
            })
            .collect();
        let pts: Vec<Point2> = params.iter().map(|&u| self.position(u)).collect();
        let seg = |i: usize| (pts[i], pts[(i + 1) % m]);
        let (mut lo, mut hi) = (pts[0], pts[0]);
        let mut max_len: f64 = 0.0;
        for i in 0..m {
            let (a, b) = seg(i);
            lo = Point2::new(lo.x.min(a.x), lo.y.min(a.y));
            hi = Point2::new(hi.x.max(a.x), hi.y.max(a.y));
            max_len = max_len.max((b - a).norm());
        }
        // the whole test in coordinates scaled to the nodes' extent: a spline near f64's limits
        // (a points file of 1e300s) has a width or chords that overflow, and a grid of them no
        // cells (found by fuzzing: an index out of bounds)
        let extent = self
            .nodes
            .iter()
            .fold(0.0f64, |e, p| e.max(p.x.abs()).max(p.y.abs()));
        if !(extent.is_finite() && extent > 0.0) {
            return None;
        }
        if extent > 1e100 || !(max_len.is_finite() && (hi - lo).norm().is_finite()) {
            let k = 1.0 / extent;
            let scaled: Vec<Point2> = self
                .nodes
                .iter()
                .map(|p| Point2::new(k * p.x, k * p.y))
                .collect();
            let small = ClosedSpline::with_parameterization(&scaled, self.parameterization).ok()?;
            // chord-length parameters scale with the lengths; uniform ones do not
            let u = match self.parameterization {
                Parameterization::ChordLength => extent,
                Parameterization::Uniform => 1.0,
            };
            return small
                .self_intersection()
                .map(|(a, b, p)| (a * u, b * u, Point2::new(p.x * extent, p.y * extent)));
        }
        // cells about as large as the longest chord, at most ~4m of them
        let (w, h) = (hi.x - lo.x, hi.y - lo.y);
        let mut cell = max_len.max(1e-300);
        while (w / cell + 1.0) * (h / cell + 1.0) > 4.0 * m as f64 {
            cell *= 2.0;
        }
        let nx = (w / cell) as usize + 1;
        let ny = (h / cell) as usize + 1;
        let idx = |x: f64, y: f64| {
            (((x - lo.x) / cell) as usize).min(nx - 1)
                + nx * (((y - lo.y) / cell) as usize).min(ny - 1)
        };
        let mut grid: Vec<Vec<u32>> = vec![Vec::new(); nx * ny];
        for i in 0..m {
            let (a, b) = seg(i);
            let (x0, x1) = (a.x.min(b.x), a.x.max(b.x));
            let (y0, y1) = (a.y.min(b.y), a.y.max(b.y));
            let (c0, c1) = (idx(x0, y0), idx(x1, y1));
            for cy in c0 / nx..=c1 / nx {
                for cx in c0 % nx..=c1 % nx {
                    grid[cx + nx * cy].push(i as u32);
                }
            }
        }
        let orient = |p: Point2, q: Point2, r: Point2| crate::geometry::cross(q - p, r - p);
        for cellv in &grid {
            for (k, &i) in cellv.iter().enumerate() {
                for &j in &cellv[k + 1..] {
                    let (i, j) = (i as usize, j as usize);
                    let gap = (i as isize - j as isize).unsigned_abs();
                    if gap <= 1 || gap == m - 1 {
                        continue; // neighbouring chords share an end
                    }
                    let ((a, b), (c, d)) = (seg(i), seg(j));
                    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
                    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
                    if o1 * o2 < 0.0 && o3 * o4 < 0.0 {
                        let t = o1 / (o1 - o2);
                        return Some((params[i], params[j], c + t * (d - c)));
                    }
                }
            }
        }
        None
    }
}

impl ClosedSpline {
    /// The segment holding `u` (modulo the period) and the local coordinate in it.
    #[inline(always)]
    fn piece(&self, u: f64) -> (&Piece, f64) {
        let (i, w) = self.knots.segment_of(u);
        let c = &self.pieces[i];
        (c, w - c.start)
    }
}

impl Curve for ClosedSpline {
    fn as_spline(&self) -> Option<&ClosedSpline> {
        Some(self)
    }

    #[inline(always)]
    fn eval(&self, u: f64) -> Derivs {
        let (c, t) = self.piece(u);
        let x = eval_piece(&c.x, &c.dx, t);
        let y = eval_piece(&c.y, &c.dy, t);
        Derivs {
            p: Point2::new(x[0], y[0]),
            d1: Vec2::new(x[1], y[1]),
            d2: Vec2::new(x[2], y[2]),
            d3: Vec2::new(x[3], y[3]),
        }
    }

    #[inline(always)]
    fn position(&self, u: f64) -> Point2 {
        let (c, t) = self.piece(u);
        let cubic = |c: &[f64; 4]| c[0] + t * (c[1] + t * (c[2] + t * c[3]));
        Point2::new(cubic(&c.x), cubic(&c.y))
    }

    fn domain(&self) -> Domain {
        Domain::Periodic {
            period: self.knots.period(),
        }
    }

    fn breakpoints(&self) -> Vec<f64> {
        self.knots.u[..self.segments()].to_vec()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::test_support::check_derivatives;
    use crate::periodic::eval_local;
    use approx::assert_relative_eq;

    fn paper_nodes() -> Vec<Point2> {
        crate::reference::paper_nodes(false).to_vec()
    }

    #[test]
    fn interpolates_nodes_both_parameterizations() {
        for p in [Parameterization::Uniform, Parameterization::ChordLength] {
            let s = ClosedSpline::with_parameterization(&paper_nodes(), p).unwrap();
            for (i, n) in paper_nodes().iter().enumerate() {
                assert_relative_eq!(s.position(s.node_param(i)), *n, epsilon = 1e-13);
            }
            // u beyond the period wraps
            let period = match s.domain() {
                Domain::Periodic { period } => period,
                _ => unreachable!(),
            };
            assert_relative_eq!(
                s.position(period + s.node_param(2)),
                paper_nodes()[2],
                epsilon = 1e-12
            );
            assert_relative_eq!(
                s.position(-period + s.node_param(3)),
                paper_nodes()[3],
                epsilon = 1e-12
            );
        }
    }

    #[test]
    fn c2_across_every_node_including_seam() {
        for p in [Parameterization::Uniform, Parameterization::ChordLength] {
            let s = ClosedSpline::with_parameterization(&paper_nodes(), p).unwrap();
            let n = s.segments();
            for i in 0..n {
                let (start, h, cx, cy) = s.segment(i);
                let right = s.eval(start + h); // start of the next segment (wraps at the seam)
                let lx = eval_local(&cx, h);
                let ly = eval_local(&cy, h);
                for (k, (l, r)) in [
                    (lx[0], right.p.x),
                    (ly[0], right.p.y),
                    (lx[1], right.d1.x),
                    (ly[1], right.d1.y),
                    (lx[2], right.d2.x),
                    (ly[2], right.d2.y),
                ]
                .into_iter()
                .enumerate()
                {
                    assert!(
                        (l - r).abs() < 1e-12 * (1.0 + r.abs()),
                        "segment {i} quantity {k}: {l} vs {r}"
                    );
                }
            }
        }
    }

    #[test]
    fn derivatives_agree_with_finite_differences() {
        let s = ClosedSpline::new(&paper_nodes()).unwrap();
        for k in 0..40 {
            let u = 0.137 + k as f64 * 0.2234; // avoids the nodes (d3 jumps there)
            if (u - u.round()).abs() > 1e-3 {
                check_derivatives(&s, u, 1e-7);
            }
        }
    }

    #[test]
    fn paper_cam_is_ccw_convex() {
        let s = ClosedSpline::new(&paper_nodes()).unwrap();
        for k in 0..900 {
            assert!(s.curvature(k as f64 * 0.01) > 0.0);
        }
    }

    #[test]
    fn self_intersection_is_found_and_convex_cams_have_none() {
        assert_eq!(
            ClosedSpline::new(&paper_nodes())
                .unwrap()
                .self_intersection(),
            None
        );
        // a figure of eight crosses itself at the origin
        let eight: Vec<Point2> = (0..12)
            .map(|i| {
                let t = std::f64::consts::TAU * i as f64 / 12.0;
                Point2::new(t.sin(), t.sin() * t.cos())
            })
            .collect();
        let (_, _, p) = ClosedSpline::new(&eight)
            .unwrap()
            .self_intersection()
            .expect("crossing");
        assert!(p.coords.norm() < 1e-2, "{p}");
        // the same near f64's limits (found by fuzzing: the grid's width overflowed to an
        // index out of bounds), both parameterisations, the crossing's parameters unscaled
        for param in [Parameterization::Uniform, Parameterization::ChordLength] {
            let (a0, b0, p0) = ClosedSpline::with_parameterization(&eight, param)
                .unwrap()
                .self_intersection()
                .unwrap();
            // as large as each parameterisation takes (CHORD_RANGE, MAX_COORDINATE)
            let big_k = if param == Parameterization::ChordLength {
                4e139
            } else {
                4e299
            };
            let big: Vec<Point2> = eight
                .iter()
                .map(|p| Point2::new(big_k * p.x, big_k * p.y))
                .collect();
            let s = ClosedSpline::with_parameterization(&big, param).unwrap();
            let (a, b, p) = s.self_intersection().expect("crossing");
            assert!((p.coords / big_k - p0.coords).norm() < 1e-9, "{p} {p0}");
            // the same places on the curve: the parameters of the unscaled spline's, scaled
            // with the chord lengths when the parameterisation follows them
            let k = if param == Parameterization::ChordLength {
                big_k
            } else {
                1.0
            };
            assert!(
                (a - k * a0).abs() <= 1e-9 * k * a0.abs().max(1.0),
                "{a} {a0}"
            );
            assert!(
                (b - k * b0).abs() <= 1e-9 * k * b0.abs().max(1.0),
                "{b} {b0}"
            );
        }
        let mut far = paper_nodes();
        far[3] = Point2::new(-4.4e299, 0.6);
        let _ = ClosedSpline::new(&far).map(|s| s.self_intersection());
    }

    /// A spline is finite everywhere and the same curve at any scale its nodes may have: from
    /// 1e-100 to [`MAX_COORDINATE`] uniform, to 1e140 by chord length (chord lengths overflowed
    /// to a NaN curve from 1e160, and the third derivative left f64's normal range; the
    /// uniform fit overflowed near 1.7e308); beyond, refused, naming the node or the chord.
    #[test]
    fn a_spline_is_the_same_curve_at_every_scale_up_to_its_limit() {
        let unit = paper_nodes();
        for param in [Parameterization::Uniform, Parameterization::ChordLength] {
            let s0 = ClosedSpline::with_parameterization(&unit, param).unwrap();
            let Domain::Periodic { period: p0 } = s0.domain() else {
                unreachable!()
            };
            let reach = unit
                .iter()
                .map(|p| p.x.abs().max(p.y.abs()))
                .fold(0.0, f64::max);
            let top = if param == Parameterization::ChordLength {
                140
            } else {
                300
            };
            for e in (-100..=top).step_by(20) {
                // the nodes' largest coordinate is just under 1e{e}
                let k = 0.999 * 10f64.powi(e) / reach;
                let nodes: Vec<Point2> = unit.iter().map(|p| Point2::from(p.coords * k)).collect();
                let s = ClosedSpline::with_parameterization(&nodes, param).unwrap();
                let Domain::Periodic { period } = s.domain() else {
                    unreachable!()
                };
                // the parameter scales with the chords (chord length) or not at all (uniform)
                let ku = if param == Parameterization::ChordLength {
                    k
                } else {
                    1.0
                };
                assert!((period / ku - p0).abs() <= 1e-12 * p0, "1e{e} {param:?}");
                for j in 0..200 {
                    let u = p0 * f64::from(j) / 200.0;
                    let (a, b) = (s0.eval(u), s.eval(u * ku));
                    for (x, y, scale) in [
                        (a.p.coords, b.p.coords, k),
                        (a.d1, b.d1, k / ku),
                        (a.d2, b.d2, k / ku / ku),
                        (a.d3, b.d3, k / ku / ku / ku),
                    ] {
                        let y = y / scale;
                        assert!(
                            y.iter().all(|v| v.is_finite())
                                && (x - y).norm() <= 1e-9 * x.norm().max(1.0),
                            "1e{e} {param:?} at {u}: {x} against {y}"
                        );
                    }
                }
            }
            let mut far = unit.clone();
            far[4] = Point2::new(2.0 * MAX_COORDINATE, 0.0);
            assert!(matches!(
                ClosedSpline::with_parameterization(&far, param),
                Err(CurveError::FarPoint { index: 4, .. })
            ));
            if param == Parameterization::ChordLength {
                for k in [1e-155, 1e155] {
                    let nodes: Vec<Point2> =
                        unit.iter().map(|p| Point2::from(p.coords * k)).collect();
                    assert!(matches!(
                        ClosedSpline::with_parameterization(&nodes, param),
                        Err(CurveError::ChordLength { .. })
                    ));
                }
            }
        }
    }

    #[test]
    fn rejects_bad_nodes() {
        let p = |x, y| Point2::new(x, y);
        assert_eq!(
            ClosedSpline::new(&[p(0.0, 0.0), p(1.0, 0.0)]).unwrap_err(),
            CurveError::TooFewPoints { count: 2 }
        );
        assert!(matches!(
            ClosedSpline::new(&[p(0.0, 0.0), p(1.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)]),
            Err(CurveError::RepeatedPoint {
                index: 1,
                next: 2,
                ..
            })
        ));
        assert!(matches!(
            ClosedSpline::new(&[p(0.0, 0.0), p(1.0, 0.0), p(0.0, 1.0), p(0.0, 0.0)]),
            Err(CurveError::RepeatedPoint {
                index: 3,
                next: 0,
                ..
            })
        ));
        assert!(matches!(
            ClosedSpline::new(&[p(0.0, 0.0), p(f64::NAN, 0.0), p(0.0, 1.0)]),
            Err(CurveError::NonFinitePoint { index: 1, .. })
        ));
    }
}
