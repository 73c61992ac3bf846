//! Measured profiles: points of a cam measured on a coordinate measuring machine, noisy and
//! unevenly spaced, smoothed before they are differentiated.
//!
//! The smoothing is a least-squares **periodic Fourier series of the radius in the polar angle**
//! about the cam axis, `r(φ) = a₀ + Σₖ₌₁ᴷ (aₖ cos kφ + bₖ sin kφ)`, with the fewest harmonics `K`
//! whose RMS residual is within the stated tolerance (the measurement's noise). Noise of RMS σ
//! on points a distance `h` apart puts an error of about `σ/h²` into a curvature taken from the
//! points themselves (a spline through them); the series averages it over the whole revolution.
//! The profile must be star-shaped about the cam axis (every ray from it crosses the profile
//! once), as a cam's is.

use crate::Point2;
use nalgebra::{DMatrix, DVector};
use std::f64::consts::TAU;

/// The most harmonics a fit uses (a profile detail of 1°: 2π/360 … 3° here).
pub const MAX_HARMONICS: usize = 120;

/// The widest stretch of polar angle without a measured point that a fit accepts, degrees. The
/// series is periodic: across a gap it is not measured but extrapolated from both sides, and a
/// deviation reported there would describe nothing that was measured. A fit with `K` harmonics
/// also needs a point every `180°/K` (half the period of its highest harmonic), or the
/// harmonic is free inside the gap; the smaller of the two limits applies.
pub const MAX_GAP_DEG: f64 = 10.0;

/// A smooth radius function fitted to measured points.
#[derive(Debug, Clone, PartialEq)]
pub struct FourierRadius {
    /// `a₀, a₁, b₁, …, a_K, b_K`
    pub coefficients: Vec<f64>,
    /// RMS of the fit's residuals, length
    pub rms_residual: f64,
}

/// Why measured points could not be fitted.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MeasuredError {
    /// Too few points for any fit.
    #[error("{count} points: a fit needs at least 8")]
    TooFew {
        /// points given
        count: usize,
    },
    /// A point at the cam axis (no polar angle).
    #[error("point {index} is at the cam axis")]
    AtAxis {
        /// 0-based
        index: usize,
    },
    /// The points leave a stretch of the profile unmeasured (see [`MAX_GAP_DEG`]).
    #[error("no point measured between polar angles {from_deg:.1}° and {to_deg:.1}° (a gap of {gap_deg:.1}°; the most a fit takes is {limit_deg:.1}°): measure the whole profile round")]
    Gap {
        /// where the gap starts, degrees counter-clockwise from the cam frame's x axis
        from_deg: f64,
        /// where it ends
        to_deg: f64,
        /// its width, degrees
        gap_deg: f64,
        /// the widest accepted, degrees
        limit_deg: f64,
    },
    /// No series within the tolerance with the harmonics the points allow.
    #[error("no fit within the tolerance {}: the best, with {harmonics} harmonics, leaves an RMS residual of {}", crate::human::human(*.tolerance), crate::human::human(*.rms))]
    NoFit {
        /// asked for
        tolerance: f64,
        /// the most tried
        harmonics: usize,
        /// its residual
        rms: f64,
    },
}

impl FourierRadius {
    /// The number of harmonics `K`.
    pub fn harmonics(&self) -> usize {
        (self.coefficients.len() - 1) / 2
    }

    /// `r(φ)`.
    pub fn radius(&self, phi: f64) -> f64 {
        let c = &self.coefficients;
        let mut r = c[0];
        for k in 1..=self.harmonics() {
            let (s, co) = (k as f64 * phi).sin_cos();
            r += c[2 * k - 1] * co + c[2 * k] * s;
        }
        r
    }

    /// The point of the smoothed profile at polar angle `phi`.
    pub fn point(&self, phi: f64) -> Point2 {
        let r = self.radius(phi);
        Point2::new(r * phi.cos(), r * phi.sin())
    }

    /// The least-squares series with `k` harmonics through `(φᵢ, rᵢ)`.
    pub fn fit_harmonics(phi: &[f64], r: &[f64], k: usize) -> Option<Self> {
        let n = phi.len();
        let m = 2 * k + 1;
        let mut a = DMatrix::<f64>::zeros(n, m);
        for (i, &p) in phi.iter().enumerate() {
            a[(i, 0)] = 1.0;
            for j in 1..=k {
                let (s, c) = (j as f64 * p).sin_cos();
                a[(i, 2 * j - 1)] = c;
                a[(i, 2 * j)] = s;
            }
        }
        let b = DVector::from_column_slice(r);
        // normal equations by Cholesky (the columns are near-orthogonal for points all round)
        let ata = a.transpose() * &a;
        let atb = a.transpose() * &b;
        let x = ata.cholesky()?.solve(&atb);
        let res = &a * &x - b;
        Some(Self {
            coefficients: x.iter().copied().collect(),
            rms_residual: (res.norm_squared() / n as f64).sqrt(),
        })
    }

    /// The series with the fewest harmonics whose RMS residual is within `tolerance`, fitted to
    /// points in the cam frame (the cam axis at the origin). At most `min(n/4, MAX_HARMONICS)` harmonics.
    pub fn fit(points: &[Point2], tolerance: f64) -> Result<Self, MeasuredError> {
        if points.len() < 8 {
            return Err(MeasuredError::TooFew {
                count: points.len(),
            });
        }
        let mut phi = Vec::with_capacity(points.len());
        let mut r = Vec::with_capacity(points.len());
        for (i, p) in points.iter().enumerate() {
            let rr = p.coords.norm();
            if !(rr > 0.0) {
                return Err(MeasuredError::AtAxis { index: i });
            }
            phi.push(p.y.atan2(p.x).rem_euclid(TAU));
            r.push(rr);
        }
        let gap = widest_gap(&phi);
        let refuse = |limit_deg: f64| {
            if gap.2 > limit_deg.to_radians() {
                Err(MeasuredError::Gap {
                    from_deg: gap.0.to_degrees(),
                    to_deg: gap.1.to_degrees(),
                    gap_deg: gap.2.to_degrees(),
                    limit_deg,
                })
            } else {
                Ok(())
            }
        };
        refuse(MAX_GAP_DEG)?;
        let kmax = (points.len() / 4).clamp(1, MAX_HARMONICS);
        let fit = |k: usize| Self::fit_harmonics(&phi, &r, k);
        // doubling to a fit within the tolerance, then bisection for the fewest harmonics
        let (mut lo, mut hi) = (0usize, 1usize);
        let mut good: Option<Self> = None;
        let mut last: Option<Self> = None;
        loop {
            let k = hi.min(kmax);
            match fit(k) {
                Some(f) if f.rms_residual <= tolerance => {
                    hi = k;
                    good = Some(f);
                    break;
                }
                Some(f) => {
                    lo = k;
                    last = Some(f);
                }
                None => break,
            }
            if k == kmax {
                break;
            }
            hi *= 2;
        }
        let Some(mut best) = good else {
            return Err(match last {
                Some(f) => MeasuredError::NoFit {
                    tolerance,
                    harmonics: f.harmonics(),
                    rms: f.rms_residual,
                },
                None => MeasuredError::TooFew {
                    count: points.len(),
                },
            });
        };
        while hi - lo > 1 {
            let m = (lo + hi) / 2;
            match fit(m) {
                Some(f) if f.rms_residual <= tolerance => {
                    hi = m;
                    best = f;
                }
                _ => lo = m,
            }
        }
        refuse(MAX_GAP_DEG.min(180.0 / best.harmonics().max(1) as f64))?;
        Ok(best)
    }
}

/// The widest stretch of polar angle between neighbouring angles of `phi` (each in `[0, 2π)`),
/// round the full turn: `(from, to, width)`, rad, `to` reduced to `[0, 2π)`.
fn widest_gap(phi: &[f64]) -> (f64, f64, f64) {
    let mut s = phi.to_vec();
    s.sort_by(f64::total_cmp);
    let mut best = (0.0, 0.0, -1.0);
    for (i, &a) in s.iter().enumerate() {
        let b = if i + 1 < s.len() {
            s[i + 1]
        } else {
            s[0] + TAU
        };
        if b - a > best.2 {
            best = (a, b.rem_euclid(TAU), b - a);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_radius_of_three_harmonics_is_recovered_from_uneven_points() {
        let truth = |p: f64| 40.0 + 3.0 * p.cos() - 1.5 * (2.0 * p).sin() + 0.4 * (3.0 * p).cos();
        // uneven angles, no noise
        let pts: Vec<Point2> = (0..200)
            .map(|i| {
                let p = TAU * (i as f64 / 200.0).powf(1.3);
                Point2::new(truth(p) * p.cos(), truth(p) * p.sin())
            })
            .collect();
        let f = FourierRadius::fit(&pts, 1e-9).unwrap();
        assert_eq!(f.harmonics(), 3);
        for k in 0..50 {
            let p = k as f64 * 0.13;
            assert!((f.radius(p) - truth(p)).abs() < 1e-9);
        }
    }

    /// Points on part of the profile only: refused, naming the unmeasured stretch, wherever it
    /// is (across the x axis too), and a gap just inside the limit is taken.
    #[test]
    fn a_gap_in_the_scan_is_refused_naming_it() {
        let on = |deg: f64| {
            let p = deg.to_radians();
            Point2::new(40.0 * p.cos(), 40.0 * p.sin())
        };
        // a quarter of the cam measured
        let quarter: Vec<Point2> = (0..=90).map(|d| on(d as f64)).collect();
        match FourierRadius::fit(&quarter, 1e-6) {
            Err(MeasuredError::Gap {
                from_deg,
                to_deg,
                gap_deg,
                ..
            }) => {
                assert!((from_deg - 90.0).abs() < 1e-9 && to_deg.abs() < 1e-9);
                assert!((gap_deg - 270.0).abs() < 1e-9);
            }
            other => panic!("{other:?}"),
        }
        // everything but 350°…20° (across the x axis)
        let most: Vec<Point2> = (20..=350).map(|d| on(d as f64)).collect();
        let e = FourierRadius::fit(&most, 1e-6).unwrap_err();
        assert!(e.to_string().contains("350.0° and 20.0°"), "{e}");
        // every 9.5°: within the 10° limit (a circle: no harmonic needed)
        let sparse: Vec<Point2> = (0..38).map(|k| on(k as f64 * 9.5)).collect();
        assert!(FourierRadius::fit(&sparse, 1e-6).is_ok());
    }

    /// A fit whose highest harmonic has a half period shorter than the widest gap is refused:
    /// that harmonic is free inside the gap.
    #[test]
    fn a_gap_wider_than_the_highest_harmonic_resolves_is_refused() {
        let truth = |p: f64| 40.0 + 0.5 * (25.0 * p).cos();
        // 2.5° spacing everywhere, 9° across one stretch: within 10°, beyond 180°/25 = 7.2°
        let mut angles: Vec<f64> = (0..144)
            .map(|k| k as f64 * 2.5)
            .filter(|d| !(101.0..=109.0).contains(d))
            .collect();
        angles.push(109.0);
        let pts: Vec<Point2> = angles
            .iter()
            .map(|d| {
                let p = d.to_radians();
                Point2::new(truth(p) * p.cos(), truth(p) * p.sin())
            })
            .collect();
        match FourierRadius::fit(&pts, 1e-6) {
            Err(MeasuredError::Gap { limit_deg, .. }) => assert!(limit_deg < 7.3, "{limit_deg}"),
            other => panic!("{other:?}"),
        }
    }
}
