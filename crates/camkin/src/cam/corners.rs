//! Corners of the curves in contact (where the tangent turns: a gear's tip, where a linear tip
//! relief starts) and the exact check that none of them lies inside the other body.
//!
//! A first touch found as a tangency of smooth pieces is accepted on sampled points (see
//! `carried`); a corner of one curve can press into the other between samples (a gear tooth's
//! tip corner entering mesh, by microns). Each corner near the other body is projected onto the
//! other curve (nearest sample, then golden sections on the foot point) and its depth inside the material
//! measured exactly. A contact *at* a corner has no tangency: see `corner_touch`.

use crate::circle_tree::{CircleTree, Visit};
use crate::curve::{Curve, Domain};
use crate::geometry::{rot90, Point2};

/// A curve's corners and sampled points, in its own frame.
#[derive(Debug, Clone, Default)]
pub(crate) struct Corners {
    /// parameter and position of each corner
    pub(crate) at: Vec<(f64, Point2)>,
    /// parameter and position of the samples the foot-point search starts from
    samples: Vec<(f64, Point2)>,
    /// bounding circles over the samples, for their nearest to a point
    tree: CircleTree,
    period: Option<f64>,
    bounds: (f64, f64),
    /// the longest distance between neighbouring samples
    pub(crate) spacing: f64,
}

/// The tangent turns at a joint by more than this (rad) for the joint to be a corner.
const TURN: f64 = 1e-7;

impl Corners {
    /// The corners of `curve` among its breakpoints, with `samples` (parameters) to search foot
    /// points from.
    pub(crate) fn of(curve: &dyn Curve, samples: &[f64]) -> Self {
        let (period, bounds) = match curve.domain() {
            Domain::Periodic { period } => (Some(period), (0.0, period)),
            Domain::Interval { min, max } => (None, (min, max)),
            Domain::Point => return Self::default(),
        };
        let at: Vec<(f64, Point2)> = curve
            .breakpoints()
            .into_iter()
            .filter(|&b| {
                // a joint belongs to one of its pieces: look just before and just after it
                let (t0, t1) = (curve.tangent(b.next_down()), curve.tangent(b.next_up()));
                crate::geometry::cross(t0, t1).atan2(t0.dot(&t1)).abs() > TURN
            })
            .map(|b| (b, curve.position(b)))
            .collect();
        let samples: Vec<(f64, Point2)> = samples.iter().map(|&u| (u, curve.position(u))).collect();
        let tree = CircleTree::new(&samples.iter().map(|s| s.1).collect::<Vec<_>>(), None);
        let spacing = samples
            .windows(2)
            .map(|w| (w[1].1 - w[0].1).norm())
            .fold(0.0, f64::max);
        Self {
            at,
            samples,
            tree,
            period,
            bounds,
            spacing,
        }
    }

    /// How deep the point `x` (this curve's frame) lies inside the material on the curve's
    /// `side` (+1: its left, −1: its right): positive inside, by the distance to the foot point,
    /// found in `sections` golden sections.
    pub(crate) fn depth_within(
        &self,
        curve: &dyn Curve,
        x: Point2,
        side: f64,
        sections: usize,
    ) -> f64 {
        let Some(u) = self.foot(curve, x, sections) else {
            return f64::NEG_INFINITY;
        };
        depth_at(curve, u, x, side)
    }

    /// The foot point (parameter) of `x` (this curve's frame) and its depth inside the material
    /// on the curve's `side`, when that depth may exceed `tol`; `None` when it is below `tol` by
    /// more than 1e-3 of the samples' spacing.
    ///
    /// Newton on the distance's stationarity from the nearest sample ([`Corners::newton_foot`],
    /// a few evaluations) when it stays in the sample's bracket and ends nearer `x` than the
    /// bracket's three samples; otherwise golden sections, screened in 20 (the 80-section foot
    /// lies in their last bracket, about 1e-4 of the spacing wide; the depth is stationary at
    /// the foot, so the two depths differ by far less than the margin) before the full 80.
    pub(crate) fn deep_foot(
        &self,
        curve: &dyn Curve,
        x: Point2,
        side: f64,
        tol: f64,
    ) -> Option<(f64, f64)> {
        let (lo, i, hi) = self.bracket_of(x)?;
        if let Some(foot) = self.newton_foot(curve, x, (lo, i, hi)) {
            let depth = depth_at(curve, foot, x, side);
            return (depth >= tol - 1e-3 * self.spacing).then_some((foot, depth));
        }
        let quick = self.golden_foot(curve, x, (lo, hi), 20);
        if depth_at(curve, quick, x, side) < tol - 1e-3 * self.spacing {
            return None;
        }
        let foot = self.golden_foot(curve, x, (lo, hi), 80);
        Some((foot, depth_at(curve, foot, x, side)))
    }

    /// The foot point of `x` by Newton on `(p(u) − x)·p'(u) = 0` from the sample `i` (wrapped
    /// into this curve's domain): `None` when a step leaves the bracket `(lo, hi)`, the distance
    /// is not at a minimum there (`p'·p' + (p − x)·p'' ≤ 0`), eight steps do not bring the step
    /// below 1e-12 of the spacing, or the foot is farther from `x` than one of the bracket's
    /// three samples (Newton found a minimum other than the nearest).
    fn newton_foot(
        &self,
        curve: &dyn Curve,
        x: Point2,
        (lo, i, hi): (f64, usize, f64),
    ) -> Option<f64> {
        let n = self.samples.len();
        let mut u = self.samples[i].0;
        let step_tol = 1e-12 * self.spacing.max(f64::MIN_POSITIVE);
        for _ in 0..8 {
            let d = curve.eval(u);
            let r = d.p - x;
            let g = r.dot(&d.d1);
            let h = d.d1.norm_squared() + r.dot(&d.d2);
            if !(h > 0.0) {
                return None;
            }
            let du = -g / h;
            u += du;
            if !(u > lo && u < hi) {
                return None;
            }
            if du.abs() * d.d1.norm() <= step_tol {
                let dist = (curve.position(u) - x).norm_squared();
                let near = |k: usize| (self.samples[k].1 - x).norm_squared();
                let (prev, next) = match self.period {
                    Some(_) => ((i + n - 1) % n, (i + 1) % n),
                    None => (i.saturating_sub(1), (i + 1).min(n - 1)),
                };
                if dist > near(i).min(near(prev)).min(near(next)) {
                    return None;
                }
                return Some(match self.period {
                    Some(p) => u.rem_euclid(p),
                    None => u.clamp(self.bounds.0, self.bounds.1),
                });
            }
        }
        None
    }

    /// The parameter of the foot point of `x` (this curve's frame) on the curve: the point
    /// nearest `x` between the nearest sample's neighbours, in `sections` golden sections.
    pub(crate) fn foot(&self, curve: &dyn Curve, x: Point2, sections: usize) -> Option<f64> {
        let bracket = self.bracket(x)?;
        Some(self.golden_foot(curve, x, bracket, sections))
    }

    /// The parameters of the neighbours of the sample nearest `x`.
    fn bracket(&self, x: Point2) -> Option<(f64, f64)> {
        self.bracket_of(x).map(|(lo, _, hi)| (lo, hi))
    }

    /// The parameters of the neighbours of the sample nearest `x`, and that sample's index.
    fn bracket_of(&self, x: Point2) -> Option<(f64, usize, f64)> {
        let n = self.samples.len();
        let mut near = Nearest {
            samples: &self.samples,
            x,
            best: None,
        };
        self.tree
            .branch_and_bound(&crate::geometry::Frame::identity(), &mut near);
        let (_, i) = near.best?;
        let (lo, hi) = match self.period {
            Some(p) => (
                if i == 0 {
                    self.samples[n - 1].0 - p
                } else {
                    self.samples[i - 1].0
                },
                if i + 1 == n {
                    self.samples[0].0 + p
                } else {
                    self.samples[i + 1].0
                },
            ),
            None => (
                self.samples[i.saturating_sub(1)].0,
                self.samples[(i + 1).min(n - 1)].0,
            ),
        };
        Some((lo, i, hi))
    }

    /// The foot point of `x` within `(lo, hi)` in `sections` golden sections on the distance
    /// (no derivatives: robust where the curvature is large).
    fn golden_foot(
        &self,
        curve: &dyn Curve,
        x: Point2,
        (lo, hi): (f64, f64),
        sections: usize,
    ) -> f64 {
        let dist = |u: f64| (curve.position(u) - x).norm_squared();
        let (u, _) = super::golden::golden_min(dist, lo, hi, sections, |_| false);
        match self.period {
            Some(p) => u.rem_euclid(p),
            None => u.clamp(self.bounds.0, self.bounds.1),
        }
    }
}

/// How deep `x` (the curve's frame) lies inside the material on the curve's `side` (+1: its
/// left), measured from the point at `foot`: positive inside.
pub(crate) fn depth_at(curve: &dyn Curve, foot: f64, x: Point2, side: f64) -> f64 {
    let d = curve.eval(foot);
    side * (x - d.p).dot(&rot90(d.d1.normalize()))
}

/// The sample nearest `x` (the first of equals): `(distance², index)`.
struct Nearest<'a> {
    samples: &'a [(f64, Point2)],
    x: Point2,
    best: Option<(f64, usize)>,
}

impl Visit for Nearest<'_> {
    fn bound(&self, _i: usize, c: Point2, r: f64) -> Option<f64> {
        Some(-((c - self.x).norm() - r).max(0.0))
    }
    fn floor(&self) -> f64 {
        self.best.map_or(f64::NEG_INFINITY, |b| -b.0.sqrt())
    }
    fn leaf(&mut self, lo: usize, hi: usize) {
        for i in lo..hi {
            let d = (self.samples[i].1 - self.x).norm_squared();
            if self.best.is_none_or(|b| d < b.0 || (d == b.0 && i < b.1)) {
                self.best = Some((d, i));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tree's nearest sample is the scan's (the first of equals), far and near the curve.
    #[test]
    fn nearest_sample_is_the_scans() {
        use crate::curve::{InvoluteGear, InvoluteGearSpec};
        let gear = InvoluteGear::new(InvoluteGearSpec::new(2.0, 20, 20f64.to_radians())).unwrap();
        let params: Vec<f64> =
            crate::curve::piece_samples(&gear.breakpoints(), TAU_OF, 16, 256).collect();
        let c = Corners::of(&gear, &params);
        for k in 0..500 {
            let t = f64::from(k) * 0.7;
            let x = Point2::new((5.0 + 0.1 * t) * t.cos(), (5.0 + 0.1 * t) * t.sin());
            let mut near = Nearest {
                samples: &c.samples,
                x,
                best: None,
            };
            c.tree
                .branch_and_bound(&crate::geometry::Frame::identity(), &mut near);
            let scan = (0..c.samples.len())
                .map(|i| ((c.samples[i].1 - x).norm_squared(), i))
                .fold(None, |m: Option<(f64, usize)>, e| {
                    if m.is_none_or(|m| e.0 < m.0) {
                        Some(e)
                    } else {
                        m
                    }
                });
            assert_eq!(near.best, scan, "point {k}");
        }
    }

    /// The screened foot's depth is the 80-section golden one's wherever it is returned, and is
    /// withheld only where the exact depth is below the threshold: points on, just inside and outside a gear's
    /// outline (tips, flanks, fillets), and far off it.
    #[test]
    fn screened_depth_withholds_only_points_below_the_threshold() {
        use crate::curve::{InvoluteGear, InvoluteGearSpec};
        let gear = InvoluteGear::new(InvoluteGearSpec::new(2.0, 20, 20f64.to_radians())).unwrap();
        let params: Vec<f64> =
            crate::curve::piece_samples(&gear.breakpoints(), TAU_OF, 16, 256).collect();
        let c = Corners::of(&gear, &params);
        let (mut kept, mut withheld) = (0, 0);
        for k in 0..4000 {
            // points along the outline, pushed off it along its normal by −0.3 … 0.3 mm
            let u = f64::from(k) * 0.00157;
            let d = gear.eval(u);
            let off = (f64::from(k % 61) - 30.0) * 0.01;
            let x = d.p + off * rot90(d.d1.normalize());
            for tol in [0.0, 1e-9, 0.05] {
                let exact = c
                    .foot(&gear, x, 80)
                    .map(|f| (f, depth_at(&gear, f, x, 1.0)));
                match c.deep_foot(&gear, x, 1.0, tol) {
                    Some(got) => {
                        // Newton's foot or the golden one: the same depth to rounding
                        let e = exact.expect("a foot");
                        assert!(
                            (got.1 - e.1).abs() <= 1e-12 * c.spacing.max(e.1.abs()),
                            "point {k}, tol {tol}: {got:?} against {e:?}"
                        );
                        kept += 1;
                    }
                    None => {
                        assert!(
                            exact.is_none_or(|e| e.1 < tol),
                            "point {k}, tol {tol}: {exact:?}"
                        );
                        withheld += 1;
                    }
                }
            }
        }
        assert!(
            kept > 1000 && withheld > 1000,
            "{kept} kept, {withheld} withheld"
        );
    }

    const TAU_OF: f64 = std::f64::consts::TAU;
}
