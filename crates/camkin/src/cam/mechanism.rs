//! Building a mechanism (validation, the profile summary, the bracketing samples) and its public
//! queries.

use super::follower::{Geometry, Kind as _};
use super::instant::Instant;
use super::summary::ProfileSummary;
use super::{
    bracket_samples, AnalysisOptions, Cam, CamContact, CamError, DesignChecks, Follower,
    FollowerCurve, FollowerJoint, FollowerState, Found, IndependentCheck, Mechanism, Motion, Sweep,
    Travel,
};
use crate::curve::{Curve, Domain};
use crate::field::{Field, ProfileField};
use std::sync::Arc;

/// Angles per chunk of [`Mechanism::analyze_all`]: each chunk is one warm-started sweep (a
/// global search, then about 1 µs a step), so a chunk is a few milliseconds of work.
pub const SWEEP_CHUNK: usize = 2048;

impl Mechanism {
    /// Validates and prepares a mechanism.
    pub fn new(cam: Cam, follower: Follower) -> Result<Self, CamError> {
        let profile = cam.profile.as_ref();
        let period = match profile.domain() {
            Domain::Periodic { period } => period,
            _ => return Err(CamError::OpenProfile),
        };
        let breakpoints = profile.breakpoints();
        let samples = bracket_samples(&breakpoints, period, 16, 256);
        let summary = ProfileSummary::of(profile, &breakpoints, period)?;
        let size = summary.size;
        if !(super::LENGTH_RANGE.0..=super::LENGTH_RANGE.1).contains(&size) {
            return Err(CamError::Invalid {
                field: Field::Profile(ProfileField::Table),
                value: size,
                reason: "the cam's size (its greatest reach from its axis) must be from 1e-100 to 1e100 length units",
            });
        }
        let geometry = Geometry::new(follower, cam.pivot, size)?;
        geometry.model.check_reach(size)?;
        cam.check_magnitudes(size)?;
        let mut options = AnalysisOptions::for_size(size);
        // Newton's error after a step δ is about δ²/ρ for the smallest radius ρ in play: the
        // profile's sharpest curvature, a small roller (a 1e-9 roller accepted a step of 1e-8
        // that left an error of 1e-7)
        let sharpest = size
            .min(summary.min_radius)
            .min(geometry.model.roller_radius().unwrap_or(f64::INFINITY));
        options.newton_contraction = 1e3 / sharpest;
        let corners = std::sync::Arc::new(super::corners::Corners::of(profile, &samples));
        Ok(Self {
            touch: super::first_touch::FirstTouch::new(
                cam,
                geometry,
                summary,
                period,
                breakpoints,
                corners,
                options,
            ),
            conjugate: None,
        })
    }

    /// Replaces the analysis options.
    pub fn set_options(&mut self, options: AnalysisOptions) {
        self.touch.set_options(options);
    }

    /// The analysis options in force.
    pub fn options(&self) -> &AnalysisOptions {
        self.touch.options()
    }

    /// The cam.
    pub fn cam(&self) -> &Cam {
        self.touch.cam()
    }

    /// The follower.
    pub fn follower(&self) -> &Follower {
        &self.touch.geometry().follower
    }

    /// The joint that carries the follower.
    pub fn follower_joint(&self) -> FollowerJoint {
        self.touch.geometry().joint
    }

    /// The follower's contact curve in its own frame (see [`Mechanism::follower_body`]).
    pub fn follower_curve(&self) -> FollowerCurve {
        self.touch.geometry().curve.clone()
    }

    /// The radius of a roller follower.
    pub fn roller_radius(&self) -> Option<f64> {
        self.touch.geometry().model.roller_radius()
    }

    /// Largest distance of a profile point from the cam axis (the length scale of tolerances).
    pub fn size(&self) -> f64 {
        self.touch.size()
    }

    /// A rough estimate of the seconds a warm-started sweep over `angles` cam angles takes, for
    /// refusing work of minutes up front: about a microsecond a step on a convex profile; on a
    /// non-convex one every step also searches the profile's dense samples (16 a spline piece)
    /// for a contact elsewhere, by branch and bound over their tree, in about 2 µs per doubling
    /// of their number (at most 41 µs a step measured on a 100 000-node profile, 1.6 million
    /// samples, 2-core host); a follower carrying a curve checks its acceptance against the
    /// cam's samples within its reach and its corners, about 0.2 ms a step (twice what the
    /// 20/42 gear pair measured).
    pub fn sweep_seconds_estimate(&self, angles: usize) -> f64 {
        angles as f64 * self.step_seconds_estimate(angles)
    }

    /// Seconds a step of a warm-started sweep of `angles` angles over a revolution takes (for a
    /// carried curve, timed here: see [`Mechanism::sweep_seconds_estimate`]).
    pub fn step_seconds_estimate(&self, angles: usize) -> f64 {
        if self.touch.carried().is_some() {
            // a carried curve's cost depends on both curves' sizes, over orders of magnitude:
            // measured, on this machine, by a few steps at the spacing asked (the first cold)
            let step = std::f64::consts::TAU / angles.clamp(8, 1 << 20) as f64;
            2e-4f64.max(self.measured_step_seconds(step))
        } else if self.touch.convex() {
            1e-6
        } else {
            2e-6 + 2e-6 * (self.touch.index().dense.params.len().max(2) as f64).log2()
        }
    }

    /// Seconds a step of a sweep at `step` (rad) takes here: six steps timed, the first cold.
    fn measured_step_seconds(&self, step: f64) -> f64 {
        let t0 = std::time::Instant::now();
        let mut sweep = self.sweep();
        for k in 0..6 {
            let _ = sweep.step_motion(f64::from(k) * step);
        }
        t0.elapsed().as_secs_f64() / 6.0
    }

    /// Why a sweep of this mechanism costs more than a microsecond a step, for the sentence that
    /// refuses a long one ([`crate::work::Work::sweep`]); `None` for a convex profile under a
    /// named follower.
    pub fn search_cost_reason(&self) -> Option<String> {
        if self.touch.carried().is_some() {
            Some("the follower carries a curve: every angle checks the cam's samples within its reach".into())
        } else if self.touch.convex() {
            None
        } else {
            Some(format!(
                "it is not convex, so every angle searches its {} samples for a contact elsewhere",
                self.sample_count()
            ))
        }
    }

    /// A rough estimate of the seconds one cold first-touch search takes (a global search, no
    /// warm start), for refusing work of minutes up front: ten warm steps' worth for the named
    /// kinds (a cold query counts 4 800–13 000 instructions, about 5 µs, against 600–870 for a
    /// warm step); 1 ms for a follower carrying a curve (twice the 0.5 ms the 20/42 gear pair
    /// measured).
    pub fn search_seconds_estimate(&self) -> f64 {
        if self.touch.carried().is_some() {
            // a cold query, timed (at least the 1 ms the 20/42 gear pair's took twice over)
            let t0 = std::time::Instant::now();
            let _ = self.motion(0.37);
            1e-3f64.max(t0.elapsed().as_secs_f64())
        } else {
            10.0 * self.sweep_seconds_estimate(1)
        }
    }

    /// A rough estimate of the seconds [`Mechanism::travel`] takes (every table's lift column
    /// needs it): a warm sweep of 720 angles and about 130 cold searches refining the rest and
    /// peak positions.
    pub fn travel_seconds_estimate(&self) -> f64 {
        self.travel_seconds_with(self.step_seconds_estimate(720))
    }

    /// [`Mechanism::travel_seconds_estimate`] with a warm step's seconds already known (a
    /// carried curve's are timed: once is enough).
    pub(crate) fn travel_seconds_with(&self, step_seconds: f64) -> f64 {
        720.0 * step_seconds + 130.0 * self.search_seconds_estimate()
    }

    /// The number of dense samples of the profile the global search looks among.
    pub fn sample_count(&self) -> usize {
        self.touch.index().dense.params.len()
    }

    /// True when the follower carries a curve whose first touch is found by the coverage search
    /// (a general follower's curve other than a point: a point is a knife edge, computed by the
    /// knife's closed forms).
    pub fn carries_curve(&self) -> bool {
        self.touch.carried().is_some()
    }

    /// True when the profile's curvature has one sign all round (sampled densely).
    pub fn is_convex(&self) -> bool {
        self.touch.convex()
    }

    /// Parameter ranges `(from, to)` of the profile that the follower cannot follow: concave
    /// stretches under a flat face, stretches concave more sharply than the roller (radius of
    /// curvature below the roller radius), the backward branch of a fold (a profile that crosses
    /// itself between two cusps, as an envelope does where the follower cannot follow its
    /// motion program). The follower bridges them: the contact jumps across
    /// and the acceleration is impulsive there. Found on a dense sampling of the profile; empty
    /// for a knife edge and for convex profiles.
    pub fn unfollowable_stretches(&self) -> Vec<(f64, f64)> {
        let Some(limit) = self.touch.geometry().model.concave_limit() else {
            return Vec::new();
        };
        let profile = self.touch.cam().profile.as_ref();
        let u = bracket_samples(self.touch.breakpoints(), self.touch.period(), 64, 2048);
        let mut bad: Vec<bool> = u
            .iter()
            .map(|&v| self.touch.orientation() * profile.curvature(v) < limit)
            .collect();
        // a folded profile (a swallowtail between two cusps, found once by the summary): the
        // branch between the cusps runs backwards and the follower cannot follow it whatever its
        // curvature says; the tangent reverses at each cusp, the shorter alternate branches are
        // the reversed ones
        let n = u.len();
        if self.touch.cusps().len() >= 2 {
            let mut reversed: Vec<bool> = u
                .iter()
                .map(|&v| self.touch.cusps().iter().filter(|&&c| c <= v).count() % 2 == 1)
                .collect();
            if reversed.iter().filter(|&&r| r).count() * 2 > n {
                reversed.iter_mut().for_each(|r| *r = !*r);
            }
            for k in 0..n {
                bad[k] |= reversed[k];
            }
        }
        let mut out = Vec::new();
        let Some(start) = (0..n).find(|&k| !bad[k]) else {
            return vec![(0.0, self.touch.period())];
        };
        let mut k = start;
        for _ in 0..n {
            let j = (k + 1) % n;
            if !bad[k] && bad[j] {
                let mut e = j;
                while bad[(e + 1) % n] {
                    e = (e + 1) % n;
                }
                out.push((u[j], u[e]));
            }
            k = j;
        }
        out
    }

    /// The follower's body frame at position `q` (translating: origin at `pivot + e·rot90(d) +
    /// q·d`, angle 0; oscillating: origin at the arm pivot, angle `q`) and its contact curve in that
    /// frame (face: a line, roller: a circle, knife: a point; oriented material-on-the-left).
    pub fn follower_body(&self, q: f64) -> (crate::body::Pose, Arc<dyn Curve>) {
        (
            self.touch.geometry().joint.pose(q),
            self.touch.geometry().curve.clone().to_arc(),
        )
    }

    /// This mechanism as a system of bodies, joints, a driver and a contact
    /// ([`super::CamFollowerSystem::of`]).
    pub fn to_system(&self) -> Result<super::CamFollowerSystem, CamError> {
        super::CamFollowerSystem::of(self)
    }

    /// The shared profile.
    pub fn profile_arc(&self) -> Arc<dyn Curve> {
        self.touch.cam().profile.clone()
    }

    /// +1 when the profile runs counter-clockwise, −1 when clockwise.
    pub fn orientation(&self) -> f64 {
        self.touch.orientation()
    }

    /// The follower's motion at cam angle `theta` (rad) with the cam's own speed and
    /// angular acceleration. The contact is found by a global search.
    ///
    /// ```
    /// use camkin::cam::{Cam, Follower, Mechanism, Sense};
    /// use camkin::curve::Circle;
    /// use camkin::{Point2, Vec2};
    /// use std::sync::Arc;
    ///
    /// // an eccentric circle (radius 4, centre 1.25 off the axis) under a flat face moving
    /// // along x: s = R + e cos θ, s̈ = −e ω² cos θ exactly
    /// let (r, e) = (4.0, 1.25);
    /// let disc = Arc::new(Circle::new(Point2::new(e, 0.0), r)?);
    /// let cam = Cam::from_rpm(disc, Point2::origin(), Sense::Ccw, 1000.0)?;
    /// let m = Mechanism::new(cam, Follower::TranslatingFlat { direction: Vec2::x() })?;
    /// let (theta, w) = (0.3_f64, m.cam().speed());
    /// let s = m.analyze(theta)?;
    /// assert!((s.position - (r + e * theta.cos())).abs() < 1e-12);
    /// assert!((s.acceleration + e * w * w * theta.cos()).abs() < 1e-9 * e * w * w);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn analyze(&self, theta: f64) -> Result<FollowerState, CamError> {
        let at = &Instant::new(self.cam(), theta);
        let touch = self.touch.global_touch(at)?;
        self.kinematics(at, touch, Found::Global)
    }

    /// The follower's position, velocity and acceleration only at cam angle `theta` (rad): the
    /// same contact as [`Mechanism::analyze`], with the five named kinds' rates in closed form
    /// (the tangency conditions differentiated in time, agreeing with the paper's method to
    /// 1e-13 of each quantity's scale); a follower carrying a curve uses the paper's method.
    pub fn motion(&self, theta: f64) -> Result<Motion, CamError> {
        let at = &Instant::new(self.cam(), theta);
        let touch = self.touch.global_touch(at)?;
        self.motion_at(at, touch, Found::Global)
    }

    /// As [`Mechanism::analyze`] with the angle in degrees.
    pub fn analyze_deg(&self, theta_deg: f64) -> Result<FollowerState, CamError> {
        self.analyze(crate::geometry::deg_to_rad(theta_deg))
    }

    /// The follower's position only, at cam angle `theta` (rad), by first touch.
    pub fn position(&self, theta: f64) -> Result<f64, CamError> {
        Ok(self.touch.global_touch(&Instant::new(self.cam(), theta))?.q)
    }

    /// A sweep that warm-starts each angle from the previous contact.
    pub fn sweep(&self) -> Sweep<'_> {
        Sweep::new(self)
    }

    /// The states at the cam angles `angles_deg` (degrees): warm-started sweeps
    /// ([`Mechanism::analyze_all`]) when `contiguous` (the angles trace the motion), else a cold
    /// query at each.
    pub fn analyze_deg_each(
        &self,
        angles_deg: &[f64],
        contiguous: bool,
    ) -> Vec<Result<FollowerState, CamError>> {
        if contiguous {
            let thetas: Vec<f64> = angles_deg.iter().map(|a| a.to_radians()).collect();
            self.analyze_all(&thetas)
        } else {
            angles_deg
                .iter()
                .map(|a| self.analyze(a.to_radians()))
                .collect()
        }
    }

    /// Analyses every angle of `thetas` (rad) in order with warm-started [`Sweep`]s, one for
    /// each chunk of [`SWEEP_CHUNK`] angles, on several threads (feature `parallel`, on by
    /// default). The chunks are fixed by the angles' positions, not by the number of threads,
    /// and each starts from a global search at the angle before its first (so the jump guard
    /// sees the step into it, as a single sweep would): the results do not depend on the number
    /// of threads, bit for bit, and differ from one sweep through every angle only by rounding
    /// (the warm start's extrapolation restarts at each chunk).
    pub fn analyze_all(&self, thetas: &[f64]) -> Vec<Result<FollowerState, CamError>> {
        self.analyze_all_after(None, thetas)
    }

    /// [`Mechanism::analyze_all`] of the angles `thetas` that follow the angle `before` (rad):
    /// the first chunk also starts from a global search there. `analyze_all` of a long list is
    /// the same, bit for bit, as this of its consecutive slices of a multiple of [`SWEEP_CHUNK`]
    /// angles, each after the angle before it (what a front end writing rows in bounded memory
    /// does).
    pub fn analyze_all_after(
        &self,
        before: Option<f64>,
        thetas: &[f64],
    ) -> Vec<Result<FollowerState, CamError>> {
        let chunk = |c: usize| -> Vec<Result<FollowerState, CamError>> {
            let start = c * SWEEP_CHUNK;
            let end = (start + SWEEP_CHUNK).min(thetas.len());
            let mut s = self.sweep();
            // the previous angle's contact, as the sweep reaching it would have it
            let lead = if start > 0 {
                Some(thetas[start - 1])
            } else {
                before
            };
            if let Some(t) = lead {
                let _ = s.step(t);
            }
            thetas[start..end].iter().map(|&t| s.step(t)).collect()
        };
        let chunks = thetas.len().div_ceil(SWEEP_CHUNK);
        #[cfg(feature = "parallel")]
        {
            use rayon::prelude::*;
            (0..chunks)
                .into_par_iter()
                .map(chunk)
                .collect::<Vec<_>>()
                .into_iter()
                .flatten()
                .collect()
        }
        #[cfg(not(feature = "parallel"))]
        {
            (0..chunks).flat_map(chunk).collect()
        }
    }

    /// Cam angles (degrees, in `[0, 360)`) at which the contact jumps over a revolution sampled
    /// every `step_deg` degrees: the end angle of every step across which the contact left one
    /// part of the profile for another (see [`contact_jumps`](super::contact_jumps)). Empty for a follower that stays
    /// on the profile all round.
    pub fn jump_angles(&self, step_deg: f64) -> Vec<f64> {
        super::jumps::jump_angles(self, step_deg)
    }

    /// The rest and farthest positions of the follower over a revolution, each located to
    /// rounding: a scan at 0.5° steps, then the zero of the velocity (exact, by the contact
    /// method) between the neighbours of the extreme sample, by bisection. Where the velocity
    /// does not change sign there (a dwell, or an extreme at a jump of the contact) the extreme
    /// sample stands. The scan is a warm-started sweep: the cost is about that of analysing
    /// 720 angles plus some 100 global searches.
    pub fn travel(&self) -> Result<Travel, CamError> {
        super::travel::travel(self)
    }

    /// The design checks at cam angles `thetas` (rad), the pressure angle against
    /// `pressure_limit_deg`.
    pub fn design_checks(&self, thetas: &[f64], pressure_limit_deg: f64) -> DesignChecks {
        super::checks::design_checks(self, thetas, pressure_limit_deg)
    }

    /// The follower's position at cam angle `theta` (rad) computed independently of the contact
    /// method (the support function: see [`Mechanism::independent_check`]) and the profile
    /// parameter of the cam point realising it, or `None` when the follower touches no cam point.
    pub fn support_position(&self, theta: f64) -> Option<(f64, f64)> {
        super::support::support_position(self, theta)
    }

    /// Compares the contact method's position, velocity and acceleration at `thetas` (rad) with
    /// an independent computation: the follower's position as the cam's *support function* (for
    /// every cam point, the coordinate at which the follower's boundary passes through it,
    /// entering the follower in its closing sense; the extreme of that over the profile, by
    /// sampling and golden-section search; a knife edge's over the crossings of its path, by
    /// bisection), its velocity and acceleration by seven-point differences in the cam angle.
    /// No tangency condition, Newton solve or curvature is involved. Fails only when the contact
    /// method fails.
    pub fn independent_check(&self, thetas: &[f64]) -> Result<IndependentCheck, CamError> {
        super::support::independent_check(self, thetas)
    }

    /// Every contact at cam angle `theta` (rad): the first touch of [`Mechanism::analyze`]
    /// first, then each other place where the follower's curve touches the cam at that position
    /// (see [`Mechanism::contacts_at`]).
    pub fn contacts(&self, theta: f64) -> Result<Vec<CamContact>, CamError> {
        super::contacts::contacts(self, theta)
    }

    /// About how many seconds finding every contact at `angles` cam angles takes: the sweep,
    /// and per angle one more search (about 1.5 ms for a follower carrying a curve, twice what
    /// the 20/42 gear pair measured; 50 µs for a named kind, a cold query's cost at 100 000
    /// nodes).
    pub fn contacts_seconds_estimate(&self, angles: usize) -> f64 {
        super::contacts::contacts_seconds_estimate(self, angles)
    }

    /// Every contact with the follower at the state `s` (from [`Mechanism::analyze`] or a
    /// [`Sweep`]): its own contact first, then the other tangencies (in the order of
    /// the cam's parameter) within the
    /// touch tolerance of its position, found from the same starts as the first-touch search (the
    /// local maxima of the sampled first-touch function; a carried curve's covered cam samples)
    /// and refined by Newton, then a conjugate follower's second curve where its play is within
    /// the touch tolerance or negative. Each has its kinematics at the state's velocity and
    /// acceleration.
    pub fn contacts_at(&self, s: &FollowerState) -> Result<Vec<CamContact>, CamError> {
        super::contacts::contacts_at(self, s)
    }

    /// `(dq/dθ, d²q/dθ², d³q/dθ³)` at cam angle `theta` (rad) by implicit differentiation of the
    /// first-touch conditions (see the `jet` module). This is independent of the paper's method
    /// and gives the jerk; `d³q/dθ³` takes the profile's third derivative on the segment that
    /// holds the contact (at a spline node it jumps).
    pub fn angle_derivatives(&self, theta: f64) -> Result<[f64; 3], CamError> {
        super::derivatives::angle_derivatives(self, theta)
    }
}
