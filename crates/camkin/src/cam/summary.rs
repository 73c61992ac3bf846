//! The profile summary that [`Mechanism::new`](super::Mechanism::new) computes once: size,
//! orientation, convexity and cusps, in one streaming pass over a dense sampling (nothing stored,
//! so a 100 000-node profile needs no more memory than a small one).

use super::{bracket_params, CamError};
use crate::curve::Curve;
use crate::field::{Field, ProfileField};
use crate::geometry::{cross, Point2};

/// What the analysis needs to know of a closed profile.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ProfileSummary {
    /// largest distance of a profile point from the cam axis
    pub(crate) size: f64,
    /// +1 counter-clockwise, −1 clockwise (shoelace)
    pub(crate) orientation: f64,
    /// the curvature has one sign all round
    pub(crate) convex: bool,
    /// the mean length of the tangent `|r'|` over the samples
    pub(crate) mean_speed: f64,
    /// the parameters of the cusps of a folded profile (where the tangent reverses)
    pub(crate) cusps: Vec<f64>,
    /// the smallest radius of curvature over the samples
    pub(crate) min_radius: f64,
}

impl ProfileSummary {
    /// Summarises `profile` (period `period`, smooth pieces between `breakpoints`); refuses a
    /// profile of no or infinite size and one with a cusp (a vanishing tangent).
    pub(crate) fn of(
        profile: &dyn Curve,
        breakpoints: &[f64],
        period: f64,
    ) -> Result<Self, CamError> {
        let (mut size, mut area2, mut kmin, mut kmax, mut gsum, mut count) =
            (0.0f64, 0.0, f64::INFINITY, f64::NEG_INFINITY, 0.0, 0usize);
        let mut gmin = (f64::INFINITY, 0.0, Point2::origin());
        let (mut first, mut prev): (Option<Point2>, Option<Point2>) = (None, None);
        // a fold (a swallowtail between two cusps, as an envelope makes where the follower cannot
        // follow the program): the tangent reverses between neighbouring samples while the
        // curvature keeps its sign, so the curvature alone calls it convex
        let mut prev_d1: Option<(f64, crate::geometry::Vec2)> = None;
        let mut cusps = Vec::new();
        for u in bracket_params(breakpoints, period, 64, 1024) {
            let e = profile.eval(u);
            if let Some((up, d)) = prev_d1 {
                if d.dot(&e.d1) < 0.0 {
                    cusps.push(cusp_between(profile, up, u));
                }
            }
            prev_d1 = Some((u, e.d1));
            size = size.max(e.p.coords.norm());
            match prev {
                Some(p) => area2 += cross(p.coords, e.p.coords),
                None => first = Some(e.p),
            }
            prev = Some(e.p);
            let g = e.d1.norm();
            if !(g >= gmin.0) {
                gmin = (g, u, e.p);
            }
            gsum += g;
            count += 1;
            let k = e.curvature();
            kmin = kmin.min(k);
            kmax = kmax.max(k);
        }
        if !(size.is_finite() && size > 0.0) {
            return Err(CamError::Invalid {
                field: Field::Profile(ProfileField::Table),
                value: size,
                reason: "profile must have a finite, non-zero size",
            });
        }
        if let (Some(f), Some(l)) = (first, prev) {
            area2 += cross(l.coords, f.coords);
        }
        let orientation = if area2 >= 0.0 { 1.0 } else { -1.0 };
        // a cusp: the tangent vanishes (relative to its mean length)
        let mean_g = gsum / count.max(1) as f64;
        if !(gmin.0 > 1e-9 * mean_g) {
            return Err(CamError::Cusp {
                param: gmin.1,
                x: gmin.2.x,
                y: gmin.2.y,
            });
        }
        if let Some((up, d)) = prev_d1 {
            let e = profile.eval(period);
            if d.dot(&e.d1) < 0.0 {
                cusps.push(cusp_between(profile, up, period) % period);
            }
        }
        // (after the cusp check, which names the point) a profile that encloses no area (collinear points: it runs out and back along a line)
        // is no cam; refused up front rather than failing at every angle
        if !(area2.abs() > 1e-9 * size * size) {
            return Err(CamError::NoArea { area: area2 / 2.0 });
        }
        let convex = cusps.is_empty()
            && if orientation > 0.0 {
                kmin > 0.0
            } else {
                kmax < 0.0
            };
        Ok(Self {
            size,
            orientation,
            convex,
            mean_speed: mean_g,
            cusps,
            min_radius: 1.0 / kmin.abs().max(kmax.abs()),
        })
    }
}

/// The cusp between `a` and `b` (where the tangent reverses): the minimum of `|r'|`.
fn cusp_between(profile: &dyn Curve, a: f64, b: f64) -> f64 {
    super::golden::golden_min(|u| profile.eval(u).d1.norm(), a, b, 80, |_| false).0
}
