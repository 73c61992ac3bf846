//! Design checks of a cam over a revolution, as an engineer reviews a profile before it goes to
//! the shop: the round trip of a synthesised profile (the contact method against its motion law),
//! the profile's radii of curvature at the contact, undercut (a roller that does not fit a
//! concave stretch, a concave stretch under a flat face), the pressure angle against a limit, the
//! face width a flat follower needs.
//!
//! The checks are data; [`crate::report::DesignReport`] gives each its verdict and its words,
//! which every front end prints.

use super::{CamError, FollowerCurve, FollowerState, Mechanism, StopReason};

/// The round trip of a synthesised profile: the follower's motion by the contact method against
/// the motion law it was synthesised from, largest differences over the checked angles.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RoundTrip {
    /// largest |Δ position|, length (rad for an arm)
    pub position: f64,
    /// largest |Δ velocity|, length/s (rad/s)
    pub velocity: f64,
    /// largest |Δ acceleration|, length/s² (rad/s²)
    pub acceleration: f64,
    /// the program's peak acceleration, length/s² (rad/s²)
    pub peak_acceleration: f64,
    /// what `acceleration` is measured against: the program's peak acceleration, or ω² times the
    /// cam's size (ω² × 1 rad for an arm) when the program has none (constant velocity, dwells)
    pub scale: f64,
    /// the program has an acceleration (its peak is more than 1e-9 of ω² × size)
    pub has_peak: bool,
    /// `acceleration ≤ 1e-6 scale` and every angle analysed
    pub passed: bool,
}

/// The design checks of a mechanism at a list of cam angles ([`Mechanism::design_checks`]).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DesignChecks {
    /// the pressure-angle limit checked against, degrees
    pub pressure_limit_deg: f64,
    /// cam angles checked
    pub angles: usize,
    /// angles that could not be analysed
    pub failed: usize,
    /// the cam angles (degrees) that could not be analysed, with the first one's reason
    pub failed_deg: Vec<f64>,
    /// why the first of them could not be analysed
    pub first_failure: Option<String>,
    /// the round trip, for a synthesised (`kind = "motion"`) profile
    pub round_trip: Option<RoundTrip>,
    /// the smallest convex radius of curvature of the profile at a contact (length) and its cam
    /// angle (degrees)
    pub convex_min: Option<(f64, f64)>,
    /// the sharpest concave radius of curvature at a contact (negative, length) and its angle
    pub concave_sharpest: Option<(f64, f64)>,
    /// the roller's radius (a roller follower)
    pub roller_radius: Option<f64>,
    /// the follower is a flat face
    pub flat_face: bool,
    /// where the contact lies along a flat face, smallest and largest (length): the face width
    /// needed is their difference
    pub face_range: Option<(f64, f64)>,
    /// the pressure angle of largest magnitude (degrees, signed) and its cam angle
    pub pressure_peak: (f64, f64),
    /// cam angles (degrees) where |pressure angle| exceeds the limit
    pub pressure_over_deg: Vec<f64>,
    /// cam angles (degrees) where the follower cannot follow the profile: concave more sharply
    /// than the roller, concave under a flat face, or resting on a cusp of a folded profile
    pub undercut_deg: Vec<f64>,
    /// the profile's stretches (parameter intervals) the follower cannot follow
    pub stretches: Vec<(f64, f64)>,
    /// a conjugate follower's play over the checked angles
    pub conjugate_play: Option<ConjugatePlay>,
}

/// A conjugate follower's play over the checked angles ([`Mechanism::conjugate_play`]): in
/// units of the follower's position (length, or rad for an arm), angles in degrees.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ConjugatePlay {
    /// the smallest play (negative: interference) and its cam angle
    pub min: (f64, f64),
    /// the largest play and its cam angle
    pub max: (f64, f64),
    /// angles where the play could not be computed
    pub failed: usize,
    /// what the play is measured against: 1e-6 of the cam's size (of 1 rad for an arm)
    pub tolerance: f64,
    /// the second curve neither cuts into the cam (`min ≥ −tolerance`) nor loses touch with it
    /// (`max − min ≤ tolerance`: a constant clearance passes, a varying one does not: the
    /// program does not suit the conjugate), and every angle was computed
    pub passed: bool,
}

impl DesignChecks {
    /// The follower cannot follow the profile somewhere (undercut, or a concave stretch under a
    /// flat face).
    pub fn undercut(&self) -> bool {
        !self.stretches.is_empty() || !self.undercut_deg.is_empty()
    }

    /// The smallest convex radius of curvature of the pitch curve (the roller centre's path,
    /// `ρ + r`), for a roller; `∞` when the profile has no convex contact.
    pub fn pitch_convex_min(&self) -> Option<f64> {
        self.roller_radius
            .map(|r| self.convex_min.map_or(f64::INFINITY, |(rho, _)| rho + r))
    }
}

/// The body of [`Mechanism::design_checks`] (documented there).
pub(crate) fn design_checks(
    mech: &Mechanism,
    thetas: &[f64],
    pressure_limit_deg: f64,
) -> DesignChecks {
    let states = mech.analyze_all(thetas);
    let synth = mech.cam().synthesis();
    let w = mech.cam().speed();
    let (mut eq, mut ev, mut ea, mut amax) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let mut failed = 0;
    let (mut failed_deg, mut first_failure) = (Vec::new(), None);
    let mut over = Vec::new();
    let mut folded = Vec::new();
    // the profile at the contact concave more sharply than the follower can follow (a flat
    // face: any concave stretch, ρ ≤ 0; a roller of radius r: −r < ρ ≤ 0; a knife any)
    let (concave_limit, roller_radius, flat_face) = match mech.follower_curve() {
        FollowerCurve::Circle(roller) => (-roller.radius(), Some(roller.radius()), false),
        FollowerCurve::Line(_) => (0.0, None, true),
        _ => (f64::NEG_INFINITY, None, false),
    };
    for (t, s) in thetas.iter().zip(&states) {
        if let Some(synth) = synth {
            // the program's peak over every angle, not only those analysed
            let m = synth.follower_motion(*t);
            amax = amax.max((w * w * m[2]).abs());
        }
        let s = match s {
            Ok(s) => s,
            Err(e) => {
                failed += 1;
                failed_deg.push(t.to_degrees());
                first_failure.get_or_insert_with(|| e.to_string());
                // resting on a cusp of a folded profile: the follower cannot follow it
                if matches!(
                    e,
                    CamError::NoConvergence {
                        reason: StopReason::OnCusp,
                        ..
                    }
                ) {
                    folded.push(t.to_degrees());
                }
                continue;
            }
        };
        if let Some(synth) = synth {
            let m = synth.follower_motion(*t);
            eq = eq.max((s.position - m[0]).abs());
            ev = ev.max((s.velocity - w * m[1]).abs());
            ea = ea.max((s.acceleration - w * w * m[2]).abs());
        }
        let pa = s.pressure_angle().to_degrees();
        if pa.abs() > pressure_limit_deg {
            over.push(t.to_degrees());
        }
        let rho = s.radius_of_curvature;
        if concave_limit > f64::NEG_INFINITY && !(rho > 0.0 || rho < concave_limit) {
            folded.push(t.to_degrees());
        }
    }
    // the extremes where they are, refined between the samples on the exact curve
    let period = crate::extreme::is_revolution(thetas).then_some(std::f64::consts::TAU);
    let best = |g: &dyn Fn(&FollowerState) -> Option<f64>, sign: f64| {
        let values: Vec<Option<f64>> = states.iter().map(|s| s.as_ref().ok().and_then(g)).collect();
        crate::extreme::best_refined(thetas, &values, sign, period, |t| {
            mech.analyze(t).ok().as_ref().and_then(g)
        })
        .map(|(t, v)| (v, t.rem_euclid(std::f64::consts::TAU).to_degrees()))
    };
    let convex_min = best(&|s| Some(s.radius_of_curvature).filter(|&r| r > 0.0), -1.0);
    let concave_sharpest = best(&|s| Some(s.radius_of_curvature).filter(|&r| r < 0.0), 1.0);
    let pa_peak = best(&|s| Some(s.pressure_angle().abs()), 1.0).map_or((0.0, 0.0), |(_, at)| {
        // the signed angle at the refined peak
        let signed = mech
            .analyze(at.to_radians())
            .map_or(f64::NAN, |s| s.pressure_angle().to_degrees());
        (signed, at)
    });
    let face_range = if flat_face {
        let lo = best(&|s| Some(s.follower_param), -1.0);
        let hi = best(&|s| Some(s.follower_param), 1.0);
        lo.zip(hi).map(|((a, _), (b, _))| (a, b))
    } else {
        None
    };
    let round_trip = synth.map(|_| {
        let natural = if mech.follower().is_oscillating() {
            w * w
        } else {
            w * w * mech.size()
        };
        // a program's "peak" below 1e-9 of the natural scale is rounding
        let has_peak = amax > 1e-9 * natural;
        let scale = if has_peak { amax } else { natural };
        RoundTrip {
            position: eq,
            velocity: ev,
            acceleration: ea,
            peak_acceleration: amax,
            scale,
            has_peak,
            passed: ea <= 1e-6 * scale && failed == 0,
        }
    });
    DesignChecks {
        pressure_limit_deg,
        angles: thetas.len(),
        failed,
        failed_deg,
        first_failure,
        round_trip,
        convex_min,
        concave_sharpest,
        roller_radius,
        flat_face,
        face_range,
        pressure_peak: pa_peak,
        pressure_over_deg: over,
        undercut_deg: folded,
        stretches: mech.unfollowable_stretches(),
        conjugate_play: conjugate_play_over(mech, &states),
    }
}

/// The play of a conjugate follower's second curve at the analysed states.
fn conjugate_play_over(
    mech: &Mechanism,
    states: &[Result<super::FollowerState, CamError>],
) -> Option<ConjugatePlay> {
    let mut sweep = mech.conjugate_sweep()?;
    let (mut min, mut max) = ((f64::INFINITY, 0.0), (f64::NEG_INFINITY, 0.0));
    let mut failed = 0;
    for s in states.iter().flatten() {
        match sweep.play(s) {
            Ok(p) => {
                let at = s.cam_angle.to_degrees();
                if p < min.0 {
                    min = (p, at);
                }
                if p > max.0 {
                    max = (p, at);
                }
            }
            Err(_) => failed += 1,
        }
    }
    let tolerance = 1e-6
        * if mech.follower().is_oscillating() {
            1.0
        } else {
            mech.size()
        };
    Some(ConjugatePlay {
        min,
        max,
        failed,
        tolerance,
        passed: failed == 0 && min.0 >= -tolerance && max.0 - min.0 <= tolerance,
    })
}
