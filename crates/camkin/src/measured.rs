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
    /// No series within the tolerance with the harmonics the points allow.
    #[error("no fit within the tolerance {tolerance}: the best, with {harmonics} harmonics, leaves an RMS residual of {rms}")]
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
        Ok(best)
    }
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
}
