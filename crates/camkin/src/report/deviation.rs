//! A profile measured on a coordinate measuring machine against the design, computed once for
//! every front end (`camkin deviation`, Python's `Mechanism.deviation()`): the deviation in
//! radius at the measured points, and in the follower's lift, velocity and acceleration over a
//! revolution.
//!
//! The measured points (x, y in the cam frame, the design's length unit) are smoothed by a
//! least-squares Fourier series of the radius in the polar angle with the fewest harmonics whose
//! RMS residual is within the tolerance (the measurement's noise); the smoothed profile (a
//! chord-length spline through 1440 of its points) drives the design's follower.

use crate::cam::Mechanism;
use crate::measured::{FourierRadius, MeasuredError};
use crate::spec::{BuildOptions, LengthUnit, MechanismSpec, ProfileSpec};
use crate::table::Units;
use crate::Point2;
use std::f64::consts::TAU;

/// Why a deviation report was not made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DeviationError {
    /// the tolerance is out of its range
    #[error("{value} {unit} must be positive and below 0.1 of the cam's size ({size} {unit})")]
    Tolerance {
        /// the value given, rounded for people
        value: String,
        /// the size of the cam, rounded for people
        size: String,
        /// the length unit
        unit: &'static str,
    },
    /// the measured points are not the design's size: another cam, or another unit
    #[error("the measured points reach {measured} {unit} from the axis, the design's profile {design} {unit}: not the same cam, or not the same unit (the points are read in the design's unit, {unit})")]
    Size {
        /// the points' farthest distance from the axis, rounded for people
        measured: String,
        /// the design's, rounded for people
        design: String,
        /// the length unit
        unit: &'static str,
    },
    /// the points could not be smoothed
    #[error("{0}")]
    Fit(MeasuredError),
    /// the design has no polar table (its profile is not star-shaped about the axis)
    #[error("{0}")]
    Polar(String),
    /// the smoothed measured profile could not be built
    #[error("the smoothed measured profile: {0}")]
    Smoothed(String),
    /// a follower's motion could not be computed
    #[error("{0}")]
    Analysis(String),
}

/// The deviation in radius at each measured point.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct RadiusDeviation {
    /// the points' polar angles, degrees in [0, 360)
    pub polar_angle_deg: Vec<f64>,
    /// the measured radius
    pub measured: Vec<f64>,
    /// the design's radius at the same polar angle
    pub design: Vec<f64>,
    /// measured − design
    pub deviation: Vec<f64>,
    /// the smoothed (Fourier) radius there
    pub smoothed: Vec<f64>,
}

/// One of the follower's motions (lift, velocity, acceleration) by the design and by the
/// smoothed measured profile.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct MotionDeviation {
    /// `"lift"`, `"velocity"` or `"acceleration"`
    pub name: &'static str,
    /// the column key's unit part (`"mm"`, `"mm_s"`, `"mm_s2"`; an arm's in degrees)
    pub key: String,
    /// the unit for people (`"mm/s"`)
    pub symbol: String,
    /// the design's
    pub design: Vec<f64>,
    /// the measured profile's
    pub measured: Vec<f64>,
    /// the largest deviation (signed) and the cam angle where, degrees
    pub largest: (f64, f64),
    /// the design's peak magnitude
    pub design_peak: f64,
}

/// A measured profile against the design.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DeviationReport {
    /// the length unit
    pub length_unit: &'static str,
    /// the measured points
    pub points: usize,
    /// the smoothing's harmonics
    pub harmonics: usize,
    /// the smoothing's RMS residual
    pub rms_residual: f64,
    /// the tolerance it met
    pub tolerance: f64,
    /// the radius's deviation at the measured points
    pub radius: RadiusDeviation,
    /// the largest radius deviation (signed) and its polar angle, degrees
    pub radius_largest: (f64, f64),
    /// the radius deviation's RMS
    pub radius_rms: f64,
    /// the cam angles of the motion's comparison, degrees
    pub angle_deg: Vec<f64>,
    /// lift, velocity and acceleration
    pub motion: Vec<MotionDeviation>,
}

impl DeviationReport {
    /// `points` measured against `design` (built from `spec` with `options`, lengths in
    /// `unit`), smoothed within `tolerance` (default 1e-4 of the cam's size), the motion compared
    /// every `step_deg`.
    pub fn new(
        spec: &MechanismSpec,
        design: &Mechanism,
        unit: LengthUnit,
        options: &BuildOptions,
        points: &[Point2],
        tolerance: Option<f64>,
        step_deg: f64,
    ) -> Result<Self, DeviationError> {
        let h = crate::human::human;
        let l = unit.name();
        let size = design.size();
        let tol = tolerance.unwrap_or(1e-4 * size);
        if !(tol.is_finite() && tol > 0.0 && tol < 0.1 * size) {
            return Err(DeviationError::Tolerance {
                value: h(tol),
                size: h(size),
                unit: l,
            });
        }
        // a worn or misground cam is within a few per cent of its design; twice or half its
        // size is another cam or another unit (a fit to it would be measured against nothing)
        let reach = points.iter().fold(0.0f64, |m, p| m.max(p.coords.norm()));
        if !(reach <= 2.0 * size && reach >= 0.5 * size) {
            return Err(DeviationError::Size {
                measured: h(reach),
                design: h(size),
                unit: l,
            });
        }
        let fit = FourierRadius::fit(points, tol).map_err(DeviationError::Fit)?;
        let phis: Vec<f64> = points
            .iter()
            .map(|p| p.y.atan2(p.x).rem_euclid(TAU))
            .collect();
        let profile = design.cam().profile();
        let us = super::shop::polar_params(profile, &phis).map_err(DeviationError::Polar)?;
        let mut radius = RadiusDeviation::default();
        let (mut dmax, mut dmax_at, mut sq) = (0.0f64, 0.0f64, 0.0f64);
        for ((p, &phi), &u) in points.iter().zip(&phis).zip(&us) {
            let design_r = profile.position(u).coords.norm();
            let r = p.coords.norm();
            let d = r - design_r;
            sq += d * d;
            if d.abs() > dmax.abs() {
                (dmax, dmax_at) = (d, phi);
            }
            radius.polar_angle_deg.push(phi.to_degrees());
            radius.measured.push(r);
            radius.design.push(design_r);
            radius.deviation.push(d);
            radius.smoothed.push(fit.radius(phi));
        }
        let radius_rms = (sq / points.len() as f64).sqrt();
        // the smoothed profile driving the design's follower
        let n = 1440;
        let smooth: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let p = fit.point(TAU * k as f64 / n as f64);
                [p.x, p.y]
            })
            .collect();
        let mut sspec = spec.clone();
        sspec.cam.profile = ProfileSpec {
            kind: "spline".into(),
            points: Some(smooth),
            parameterization: Some(crate::curve::Parameterization::ChordLength),
            ..ProfileSpec::default()
        };
        let measured = sspec
            .build(options)
            .map_err(|e| DeviationError::Smoothed(e.to_string()))?
            .mechanism;
        let u = Units::plain(design, unit);
        let m = (360.0 / step_deg).round() as usize;
        let grid = crate::table::AngleGrid::new(0.0, step_deg);
        let angle_deg: Vec<f64> = (0..m).map(|k| grid.at(k)).collect();
        let thetas: Vec<f64> = angle_deg.iter().map(|a| a.to_radians()).collect();
        let sweep = |mm: &Mechanism| -> Result<Vec<[f64; 3]>, DeviationError> {
            let t = mm
                .travel()
                .map_err(|e| DeviationError::Analysis(format!("the follower's travel: {e}")))?;
            mm.analyze_all(&thetas)
                .into_iter()
                .map(|r| {
                    r.map(|s| {
                        let c = u.motion(s.position, s.velocity, s.acceleration, None);
                        [
                            u.coord_value(t.lift(s.position)),
                            c[1].unwrap_or(f64::NAN),
                            c[2].unwrap_or(f64::NAN),
                        ]
                    })
                    .map_err(|e| DeviationError::Analysis(format!("analysis: {e}")))
                })
                .collect()
        };
        let d = sweep(design)?;
        let g = sweep(&measured)?;
        let motion = ["lift", "velocity", "acceleration"]
            .iter()
            .enumerate()
            .map(|(j, name)| {
                let design: Vec<f64> = d.iter().map(|r| r[j]).collect();
                let measured: Vec<f64> = g.iter().map(|r| r[j]).collect();
                let design_peak = design.iter().map(|v| v.abs()).fold(0.0, f64::max);
                let (mut worst, mut at) = (0.0f64, 0.0);
                for (k, (a, b)) in design.iter().zip(&measured).enumerate() {
                    if (b - a).abs() > worst.abs() {
                        (worst, at) = (b - a, angle_deg[k]);
                    }
                }
                MotionDeviation {
                    name,
                    key: u.motion_key(j),
                    symbol: u.motion_symbol(j).to_string(),
                    design,
                    measured,
                    largest: (worst, at),
                    design_peak,
                }
            })
            .collect();
        Ok(Self {
            length_unit: l,
            points: points.len(),
            harmonics: fit.harmonics(),
            rms_residual: fit.rms_residual,
            tolerance: tol,
            radius,
            radius_largest: (dmax, dmax_at.to_degrees()),
            radius_rms,
            angle_deg,
            motion,
        })
    }
}
