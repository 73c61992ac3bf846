//! Corners of the curves in contact (where the tangent turns: a gear's tip, where a linear tip
//! relief starts) and the exact check that none of them lies inside the other body.
//!
//! A first touch found as a tangency of smooth pieces is accepted on sampled points (see
//! `carried`); a corner of one curve can press into the other between samples (a gear tooth's
//! tip corner entering mesh, by microns). Each corner near the other body is projected onto the
//! other curve (nearest sample, then golden sections on the foot point) and its depth inside the material
//! measured exactly. A contact *at* a corner has no tangency; it is refused with
//! [`StopReason::OnCorner`](super::StopReason::OnCorner), not answered wrongly.

use crate::curve::{Curve, Domain};
use crate::geometry::{rot90, Point2};

/// A curve's corners and sampled points, in its own frame.
#[derive(Debug, Clone, Default)]
pub(crate) struct Corners {
    /// parameter and position of each corner
    pub(crate) at: Vec<(f64, Point2)>,
    /// parameter and position of the samples the foot-point search starts from
    samples: Vec<(f64, Point2)>,
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
        let spacing = samples
            .windows(2)
            .map(|w| (w[1].1 - w[0].1).norm())
            .fold(0.0, f64::max);
        Self {
            at,
            samples,
            period,
            bounds,
            spacing,
        }
    }

    /// How deep the point `x` (this curve's frame) lies inside the material on the curve's
    /// `side` (+1: its left, −1: its right): positive inside, by the distance to the foot point.
    pub(crate) fn depth(&self, curve: &dyn Curve, x: Point2, side: f64) -> f64 {
        let n = self.samples.len();
        let Some(i) = (0..n).min_by(|&a, &b| {
            (self.samples[a].1 - x)
                .norm_squared()
                .total_cmp(&(self.samples[b].1 - x).norm_squared())
        }) else {
            return f64::NEG_INFINITY;
        };
        // the foot point between the nearest sample's neighbours, by golden sections on the
        // distance (no derivatives: robust where the curvature is large)
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
        let dist = |u: f64| (curve.position(u) - x).norm_squared();
        let (u, _) = super::golden::golden_min(dist, lo, hi, 80, |_| false);
        let u = match self.period {
            Some(p) => u.rem_euclid(p),
            None => u.clamp(self.bounds.0, self.bounds.1),
        };
        let d = curve.eval(u);
        side * (x - d.p).dot(&rot90(d.d1.normalize()))
    }
}
