//! Cam-follower mechanisms analysed at one instant by the contact method.
//!
//! A [`Cam`] is a closed profile turning about an axis at constant speed (optionally with a
//! constant angular acceleration); a [`Follower`] is one of the five types of `cam-follower.md`.
//! [`Mechanism::analyze`] gives at one cam angle the follower's position (by **first touch**:
//! the follower brought from far away towards the cam stops at the first contact), its velocity
//! and acceleration by the contact method (paper eqs. 5, 6, 11 via [`crate::contact`]), and the
//! contact data an engineer wants beside them. [`Sweep`] reuses the previous contact as a warm
//! start over a range of angles.
//!
//! The cam angle `θ` is how far the cam has turned in its own direction; a counter-clockwise
//! cam's frame is at `+θ`, a clockwise cam's at `−θ`; at `θ = 0` the cam frame is aligned with
//! the world frame with its origin on the rotation axis. Other conventions: see the
//! [crate docs](crate#sign-conventions).

mod checks;
mod follower;
mod jet;
mod sweep;
pub mod synthesis;

pub use checks::Check;
pub use follower::{Follower, FollowerCurve, Joint, Sense};
pub use sweep::{Found, Sweep};

use crate::body::{BodyState, Frame, WorldDerivs};
use crate::contact::{
    ContactError, ContactKinematics, NormalAcceleration, Pairing, CONFORMAL_TOLERANCE,
};
use crate::curve::{Curve, CurveError, Domain};
use crate::geometry::{cross, Point2, Rot, Vec2};
use follower::{Geometry, Kind as _};
use jet::{scale, Jet, Num, V2};
use std::sync::Arc;

/// A cam: a closed profile in the cam frame, whose origin is the rotation axis.
#[derive(Debug, Clone)]
pub struct Cam {
    profile: Arc<dyn Curve>,
    pivot: Point2,
    direction: Sense,
    speed: f64,
    angular_acceleration: f64,
}

impl Cam {
    /// A cam turning at `speed` rad/s (> 0) in `direction` about the world point `pivot`.
    pub fn new(
        profile: Arc<dyn Curve>,
        pivot: Point2,
        direction: Sense,
        speed: f64,
    ) -> Result<Self, CamError> {
        if !matches!(profile.domain(), Domain::Periodic { .. }) {
            return Err(CamError::OpenProfile);
        }
        if !(pivot.x.is_finite() && pivot.y.is_finite()) {
            return Err(CamError::Invalid {
                field: "cam.pivot",
                value: if pivot.x.is_finite() {
                    pivot.y
                } else {
                    pivot.x
                },
                reason: "must be finite",
            });
        }
        if !(speed.is_finite() && speed > 0.0) {
            return Err(CamError::Invalid {
                field: "cam.speed",
                value: speed,
                reason: "must be positive and finite",
            });
        }
        Ok(Self {
            profile,
            pivot,
            direction,
            speed,
            angular_acceleration: 0.0,
        })
    }

    /// As [`Cam::new`] with the speed in revolutions per minute.
    pub fn from_rpm(
        profile: Arc<dyn Curve>,
        pivot: Point2,
        direction: Sense,
        rpm: f64,
    ) -> Result<Self, CamError> {
        if !(rpm.is_finite() && rpm > 0.0) {
            return Err(CamError::Invalid {
                field: "cam.speed_rpm",
                value: rpm,
                reason: "must be positive and finite",
            });
        }
        Self::new(
            profile,
            pivot,
            direction,
            rpm * std::f64::consts::TAU / 60.0,
        )
    }

    /// With a constant angular acceleration `θ̈` (rad/s², in the cam's direction of motion); the
    /// speed given is then the speed at the instant analysed.
    pub fn with_angular_acceleration(mut self, alpha: f64) -> Result<Self, CamError> {
        if !alpha.is_finite() {
            return Err(CamError::Invalid {
                field: "cam.angular_acceleration",
                value: alpha,
                reason: "must be finite",
            });
        }
        self.angular_acceleration = alpha;
        Ok(self)
    }

    /// The profile.
    pub fn profile(&self) -> &dyn Curve {
        self.profile.as_ref()
    }
    /// The rotation axis (world).
    pub fn pivot(&self) -> Point2 {
        self.pivot
    }
    /// Direction of rotation.
    pub fn direction(&self) -> Sense {
        self.direction
    }
    /// Speed, rad/s (> 0).
    pub fn speed(&self) -> f64 {
        self.speed
    }
    /// Angular acceleration `θ̈`, rad/s².
    pub fn angular_acceleration(&self) -> f64 {
        self.angular_acceleration
    }

    /// The cam body's state at cam angle `theta` (rad): angle `±θ`, angular velocity `±ω`.
    pub fn state(&self, theta: f64) -> BodyState {
        let s = self.direction.sign();
        BodyState::rotating(
            self.pivot,
            s * theta,
            s * self.speed,
            s * self.angular_acceleration,
        )
    }
}

/// Tolerances and effort of the analysis. Lengths are in the problem's unit;
/// [`AnalysisOptions::for_size`] scales them to the cam.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnalysisOptions {
    /// Newton stops when a step moves the contact point and the follower less than this (length).
    pub position_tolerance: f64,
    /// Newton iterations before giving up.
    pub max_iterations: u32,
    /// Bracketing samples per smooth piece of the profile (a spline segment).
    pub samples_per_piece: usize,
    /// Bracketing samples for a profile without breakpoints (circle, ellipse).
    pub samples_per_curve: usize,
    /// Bracketing samples per smooth piece of a convex profile (its first-touch function has a
    /// single maximum, so a coarse scan finds it).
    pub convex_samples_per_piece: usize,
    /// Bracketing samples of a convex profile without breakpoints.
    pub convex_samples_per_curve: usize,
    /// Local maxima of the sampled first-touch function refined by Newton (at most
    /// [`MAX_CANDIDATES`]).
    pub candidates: usize,
    /// Relative tolerance on `D` below which contact is conformal.
    pub conformal_tolerance: f64,
    /// The follower is locked when `|cos|` of the pressure angle is below this.
    pub lock_tolerance: f64,
    /// A refined touch counts as the first touch through its cam point when it agrees with that
    /// point's first-touch position within this, and a warm-started touch stands unless a sampled
    /// one is ahead of it by more than this (length).
    pub touch_tolerance: f64,
    /// Largest Newton step in the cam parameter, as a fraction of its period.
    pub max_step_fraction: f64,
    /// The contact is on a node of a spline profile when its parameter is within this fraction
    /// of the period of one.
    pub breakpoint_tolerance: f64,
    /// Compute the jerk (three more orders of implicit differentiation per angle).
    pub jerk: bool,
    /// A bound `C` (1/length) on Newton's quadratic convergence: a step `δ` leaves an error of
    /// about `C δ²`, so a step whose `C δ²` is below [`AnalysisOptions::position_tolerance`] is
    /// accepted without another evaluation. Conservative by default (`10³/size`).
    pub newton_contraction: f64,
}

impl AnalysisOptions {
    /// Options for a cam whose points lie within `size` of its axis.
    pub fn for_size(size: f64) -> Self {
        Self {
            position_tolerance: 1e-13 * size,
            max_iterations: 50,
            samples_per_piece: 16,
            samples_per_curve: 256,
            convex_samples_per_piece: 4,
            convex_samples_per_curve: 32,
            candidates: 4,
            conformal_tolerance: CONFORMAL_TOLERANCE,
            lock_tolerance: 1e-9,
            touch_tolerance: 1e-10 * size,
            max_step_fraction: 0.1,
            breakpoint_tolerance: 1e-9,
            jerk: true,
            newton_contraction: 1e3 / size,
        }
    }
}

/// What went wrong in building or analysing a mechanism.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CamError {
    /// A curve could not be built.
    #[error(transparent)]
    Curve(#[from] CurveError),
    /// A parameter is out of range.
    #[error("{field} = {value}: {reason}")]
    Invalid {
        /// the field, as in mechanism files
        field: &'static str,
        /// the value given
        value: f64,
        /// what it must be
        reason: &'static str,
    },
    /// The cam profile is not a closed curve.
    #[error("the cam profile must be a closed curve")]
    OpenProfile,
    /// The follower never touches the cam at this angle.
    #[error("at cam angle {angle_deg}°: the follower does not touch the cam ({reason})")]
    NoTouch {
        /// cam angle, degrees
        angle_deg: f64,
        /// why
        reason: &'static str,
    },
    /// The contact normal is perpendicular to the follower's motion: no velocity solves the
    /// contact condition.
    #[error(
        "at cam angle {angle_deg}°: the follower is locked (pressure angle {pressure_angle_deg}°)"
    )]
    Locked {
        /// cam angle, degrees
        angle_deg: f64,
        /// pressure angle, degrees
        pressure_angle_deg: f64,
    },
    /// The first-touch Newton iteration did not converge.
    #[error("at cam angle {angle_deg}°: the first-touch search did not converge ({reason})")]
    NoConvergence {
        /// cam angle, degrees
        angle_deg: f64,
        /// the stopping reason
        reason: &'static str,
    },
    /// The follower can never touch the cam.
    #[error("{field} = {value}: {reason}")]
    Unreachable {
        /// the field, as in mechanism files
        field: &'static str,
        /// its value
        value: f64,
        /// why, with the dimensions involved
        reason: String,
    },
    /// The profile has a cusp: its tangent vanishes, so its normal and curvature are undefined.
    #[error("the cam profile has a cusp (zero-length tangent) at u = {param}, ({x}, {y}) in the cam frame")]
    Cusp {
        /// the profile parameter
        param: f64,
        /// cam-frame x
        x: f64,
        /// cam-frame y
        y: f64,
    },
    /// The contact kinematics could not be computed.
    #[error("at cam angle {angle_deg}°: {source}")]
    Contact {
        /// cam angle, degrees
        angle_deg: f64,
        /// the contact error
        source: ContactError,
    },
}

/// A cam and its follower, validated, with the precomputed data the analysis needs.
#[derive(Debug, Clone)]
pub struct Mechanism {
    cam: Cam,
    geometry: Geometry,
    options: AnalysisOptions,
    samples: Vec<f64>,
    coarse: Vec<f64>,
    period: f64,
    size: f64,
    orientation: f64,
    convex: bool,
    breakpoints: Vec<f64>,
}

/// The follower's motion and the contact at one cam angle.
///
/// Position, velocity, acceleration and jerk are of the follower's coordinate: translating
/// followers in length, length/s, length/s², length/s³ (measured from the cam axis along `d`);
/// oscillating followers in rad, rad/s, rad/s², rad/s³ (absolute arm angle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FollowerState {
    /// cam angle `θ`, rad
    pub cam_angle: f64,
    /// position `q`
    pub position: f64,
    /// velocity `q̇`
    pub velocity: f64,
    /// acceleration `q̈` by the contact method (eq. 11)
    pub acceleration: f64,
    /// jerk `d³q/dt³ = θ̇³ q‴ + 3 θ̇ θ̈ q″` (derivatives in θ by implicit differentiation, see
    /// [`Mechanism::angle_derivatives`]); `None` when the contact sits on a node of a spline
    /// profile, where the curvature has a corner and the jerk jumps, or when
    /// [`AnalysisOptions::jerk`] is off
    pub jerk: Option<f64>,
    /// contact point, world frame
    pub contact_world: Point2,
    /// contact point, cam frame
    pub contact_cam: Point2,
    /// the cam-profile parameter at the contact, in `[0, period)`
    pub cam_param: f64,
    /// `u̇_A = ṡ_A/g_A`: rate of the cam parameter at the contact, relative to the cam, 1/s
    /// (eq. 7)
    pub cam_param_rate: f64,
    /// the follower-curve parameter at the contact (line: arc length; roller: angle in the
    /// follower frame; knife: 0)
    pub follower_param: f64,
    /// `ṡ_A`: sliding rate of the contact point along the cam profile, relative to the cam,
    /// length/s (eq. 5)
    pub sliding_rate_cam: f64,
    /// `ṡ_B`: sliding rate along the follower's curve, relative to the follower, length/s (eq. 6)
    pub sliding_rate_follower: f64,
    /// normal acceleration of the contact point seen from the cam (eq. 1), along `normal`
    pub normal_acceleration_cam: NormalAcceleration,
    /// normal acceleration seen from the follower (eq. 2), along `normal`
    pub normal_acceleration_follower: NormalAcceleration,
    /// the common normal `ν_A` (cam profile's left normal), world frame
    pub normal: Vec2,
    /// `σ`
    pub sigma: f64,
    /// direction of motion of the follower's material point under the contact per unit rate of
    /// its coordinate (`∂v_B^P/∂q̇`: `d` for translating followers, `k × (c − O)` for
    /// oscillating ones), world frame; see [`FollowerState::pressure_angle`]
    pub follower_motion: Vec2,
    /// radius of curvature of the cam profile at the contact, positive where convex (∞ on a
    /// straight stretch), length
    pub radius_of_curvature: f64,
    /// the contact sits on a node of the profile (its curvature has a corner there: the jerk
    /// jumps)
    pub at_breakpoint: bool,
    /// how the contact was found
    pub found: Found,
}

/// The follower's motion at one cam angle: position, velocity and acceleration by the contact
/// method with nothing else computed (the fast path for sweeps and dynamics). Units as in
/// [`FollowerState`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// cam angle `θ`, rad
    pub cam_angle: f64,
    /// position `q`
    pub position: f64,
    /// velocity `q̇`
    pub velocity: f64,
    /// acceleration `q̈` (eq. 11)
    pub acceleration: f64,
    /// the cam-profile parameter at the contact
    pub cam_param: f64,
    /// its rate `u̇_A` relative to the cam, 1/s
    pub cam_param_rate: f64,
    /// how the contact was found
    pub found: Found,
}

/// The shared part of an analysis at a converged touch.
struct Core {
    body_a: crate::curve::Derivs,
    ea: WorldDerivs,
    nu: Vec2,
    jb: Vec2,
    qd: f64,
    qdd: f64,
    u_b: f64,
    k: ContactKinematics,
}

/// A converged first touch: cam parameter and follower position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Touch {
    pub(crate) u: f64,
    pub(crate) q: f64,
}

impl Mechanism {
    /// Validates and prepares a mechanism.
    pub fn new(cam: Cam, follower: Follower) -> Result<Self, CamError> {
        let geometry = Geometry::new(follower, cam.pivot)?;
        let profile = cam.profile.as_ref();
        let period = match profile.domain() {
            Domain::Periodic { period } => period,
            _ => return Err(CamError::OpenProfile),
        };
        let breakpoints = profile.breakpoints();
        let samples = bracket_samples(&breakpoints, period, 16, 256);
        // size, orientation (shoelace) and convexity from a dense sampling
        // one streaming pass over a dense sampling: size, orientation (shoelace), convexity, cusps
        let (mut size, mut area2, mut kmin, mut kmax, mut gsum, mut count) =
            (0.0f64, 0.0, f64::INFINITY, f64::NEG_INFINITY, 0.0, 0usize);
        let mut gmin = (f64::INFINITY, 0.0, Point2::origin());
        let (mut first, mut prev): (Option<Point2>, Option<Point2>) = (None, None);
        for u in bracket_params(&breakpoints, period, 64, 1024) {
            let e = profile.eval(u);
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
                field: "cam.profile",
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
        let convex = if orientation > 0.0 {
            kmin > 0.0
        } else {
            kmax < 0.0
        };
        geometry.model.check_reach(size)?;
        let options = AnalysisOptions::for_size(size);
        let mut m = Self {
            cam,
            geometry,
            options,
            coarse: samples.clone(),
            samples,
            period,
            size,
            orientation,
            convex,
            breakpoints,
        };
        m.set_options(options);
        Ok(m)
    }

    /// Replaces the analysis options.
    pub fn set_options(&mut self, options: AnalysisOptions) {
        self.samples = bracket_samples(
            &self.breakpoints,
            self.period,
            options.samples_per_piece.max(2),
            options.samples_per_curve.max(8),
        );
        self.coarse = bracket_samples(
            &self.breakpoints,
            self.period,
            options.convex_samples_per_piece.max(2),
            options.convex_samples_per_curve.max(8),
        );
        self.options = options;
    }

    /// The analysis options in force.
    pub fn options(&self) -> &AnalysisOptions {
        &self.options
    }
    /// The cam.
    pub fn cam(&self) -> &Cam {
        &self.cam
    }
    /// The follower.
    pub fn follower(&self) -> &Follower {
        &self.geometry.follower
    }
    /// The joint that carries the follower.
    pub fn follower_joint(&self) -> Joint {
        self.geometry.joint
    }
    /// The follower's contact curve in its own frame (see [`Mechanism::follower_body`]).
    pub fn follower_curve(&self) -> FollowerCurve {
        self.geometry.curve
    }
    /// The radius of a roller follower.
    pub fn roller_radius(&self) -> Option<f64> {
        self.geometry.model.roller_radius()
    }
    /// Largest distance of a profile point from the cam axis (the length scale of tolerances).
    pub fn size(&self) -> f64 {
        self.size
    }
    /// True when the profile's curvature has one sign all round (sampled densely).
    pub fn is_convex(&self) -> bool {
        self.convex
    }
    /// Parameter ranges `(from, to)` of the profile that the follower cannot follow: concave
    /// stretches under a flat face, stretches concave more sharply than the roller (radius of
    /// curvature below the roller radius). The follower bridges them: the contact jumps across
    /// and the acceleration is impulsive there. Found on a dense sampling of the profile; empty
    /// for a knife edge and for convex profiles.
    pub fn unfollowable_stretches(&self) -> Vec<(f64, f64)> {
        let Some(limit) = self.geometry.model.concave_limit() else {
            return Vec::new();
        };
        let profile = self.cam.profile.as_ref();
        let u = bracket_samples(&self.breakpoints, self.period, 64, 2048);
        let bad: Vec<bool> = u
            .iter()
            .map(|&v| self.orientation * profile.curvature(v) < limit)
            .collect();
        let mut out = Vec::new();
        let n = u.len();
        let Some(start) = (0..n).find(|&k| !bad[k]) else {
            return vec![(0.0, self.period)];
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

    /// The follower's body frame at position `q` (translating: origin at `pivot + e·perp(d) +
    /// q·d`, angle 0; oscillating: origin at the arm pivot, angle `q`) and its contact curve in that
    /// frame (face: a line, roller: a circle, knife: a point; oriented material-on-the-left).
    pub fn follower_body(&self, q: f64) -> (crate::body::Pose, Arc<dyn Curve>) {
        (self.geometry.joint.pose(q), self.geometry.curve.to_arc())
    }

    /// The shared profile.
    pub fn profile_arc(&self) -> Arc<dyn Curve> {
        self.cam.profile.clone()
    }

    /// +1 when the profile runs counter-clockwise, −1 when clockwise.
    pub fn orientation(&self) -> f64 {
        self.orientation
    }

    /// The follower's motion at cam angle `theta` (rad) with the cam's own speed and
    /// angular acceleration. The contact is found by a global search.
    pub fn analyze(&self, theta: f64) -> Result<FollowerState, CamError> {
        let cam = self.cam.state(theta);
        let frame = cam.frame();
        let touch = self.global_touch(theta, &frame)?;
        self.kinematics(theta, &cam, &frame, touch, Found::Global)
    }

    /// The follower's position, velocity and acceleration only at cam angle `theta` (rad): the
    /// same contact method as [`Mechanism::analyze`] without the other outputs.
    pub fn motion(&self, theta: f64) -> Result<Motion, CamError> {
        let cam = self.cam.state(theta);
        let frame = cam.frame();
        let touch = self.global_touch(theta, &frame)?;
        self.motion_at(theta, &cam, &frame, touch, Found::Global)
    }

    #[inline(always)]
    pub(crate) fn motion_at(
        &self,
        theta: f64,
        cam: &BodyState,
        frame: &Frame,
        touch: Touch,
        found: Found,
    ) -> Result<Motion, CamError> {
        let c = self.core(theta, cam, frame, touch)?;
        Ok(Motion {
            cam_angle: theta,
            position: touch.q,
            velocity: c.qd,
            acceleration: c.qdd,
            cam_param: touch.u,
            cam_param_rate: c.k.param_rate_a,
            found,
        })
    }

    /// As [`Mechanism::analyze`] with the angle in degrees.
    pub fn analyze_deg(&self, theta_deg: f64) -> Result<FollowerState, CamError> {
        self.analyze(theta_deg.to_radians())
    }

    /// The follower's position only, at cam angle `theta` (rad), by first touch.
    pub fn position(&self, theta: f64) -> Result<f64, CamError> {
        let frame = self.cam.state(theta).frame();
        Ok(self.global_touch(theta, &frame)?.q)
    }

    /// A sweep that warm-starts each angle from the previous contact.
    pub fn sweep(&self) -> Sweep<'_> {
        Sweep::new(self)
    }

    /// Analyses every angle of `thetas` (rad) in order with a warm-started [`Sweep`].
    pub fn analyze_all(&self, thetas: &[f64]) -> Vec<Result<FollowerState, CamError>> {
        let mut s = self.sweep();
        thetas.iter().map(|&t| s.step(t)).collect()
    }

    fn q_scale(&self) -> f64 {
        self.geometry.q_length_scale(self.size)
    }

    /// [`AnalysisOptions::touch_tolerance`] in units of the follower coordinate.
    pub(crate) fn touch_slack(&self) -> f64 {
        self.options.touch_tolerance / self.q_scale()
    }

    /// Newton on the tangency residual from `(u, q)`.
    pub(crate) fn newton(
        &self,
        theta: f64,
        frame: &Frame,
        u: f64,
        q: f64,
    ) -> Result<Touch, CamError> {
        self.newton_at(theta, frame, u, q).map(|(t, _)| t)
    }

    /// Newton on the tangency residual from `(u, q)`; also returns the cam point of the last
    /// iterate (within the position tolerance of the converged one).
    #[inline]
    pub(crate) fn newton_at(
        &self,
        theta: f64,
        frame: &Frame,
        mut u: f64,
        mut q: f64,
    ) -> Result<(Touch, WorldDerivs), CamError> {
        let profile = self.cam.profile.as_ref();
        let tol = self.options.position_tolerance;
        let tol2 = tol * tol;
        // C² δ⁴ ≤ tol²: the next step would be below the tolerance
        let c2 = self.options.newton_contraction * self.options.newton_contraction;
        let qs = self.q_scale();
        let lim = self.options.max_step_fraction * self.period;
        for _ in 0..self.options.max_iterations {
            let e = frame.eval(profile, u);
            let (f, j) = self.geometry.residual(&e, q);
            let inv_det = 1.0 / (j[0][0] * j[1][1] - j[0][1] * j[1][0]);
            let du = (-f[0] * j[1][1] + f[1] * j[0][1]) * inv_det;
            let dq = (-j[0][0] * f[1] + j[1][0] * f[0]) * inv_det;
            if !(du.is_finite() && dq.is_finite()) {
                return Err(CamError::NoConvergence {
                    angle_deg: theta.to_degrees(),
                    reason: "singular tangency Jacobian",
                });
            }
            // a step stays within a fraction of the period (safeguard against wild steps)
            let du = du.clamp(-lim, lim);
            u += du;
            q += dq;
            let step2 = (du * du * e.d1.norm_squared()).max(dq * dq * qs * qs);
            if step2 <= tol2 || c2 * step2 * step2 <= tol2 {
                let u = if (0.0..self.period).contains(&u) {
                    u
                } else {
                    u.rem_euclid(self.period)
                };
                return Ok((Touch { u, q }, e));
            }
        }
        Err(CamError::NoConvergence {
            angle_deg: theta.to_degrees(),
            reason: "iteration limit reached",
        })
    }

    /// True when `(u, q)` is the follower's first touch through that cam point (not another
    /// tangency such as the cam's back side or a roller touching from inside).
    pub(crate) fn is_first_touch(&self, frame: &Frame, t: &Touch) -> bool {
        self.is_first_touch_at(&frame.eval(self.cam.profile.as_ref(), t.u), t.q)
    }

    /// [`Mechanism::is_first_touch`] with the cam point already evaluated.
    #[inline]
    pub(crate) fn is_first_touch_at(&self, e: &WorldDerivs, q: f64) -> bool {
        if !self.faces_follower(e, q) {
            return false;
        }
        if self.geometry.is_knife() {
            return true;
        }
        match self.geometry.model.score(e.p) {
            Some((_, qs)) => (qs - q).abs() <= self.touch_slack(),
            None => false,
        }
    }

    /// The cam's outward normal at `e` faces the follower at position `q` (the cam's back side
    /// and a roller touching from inside fail this). Only a sign: no normalisation.
    #[inline]
    pub(crate) fn faces_follower(&self, e: &WorldDerivs, q: f64) -> bool {
        // outward normal ∝ −orientation · k × r'
        let outward = -self.orientation * crate::geometry::perp(e.d1);
        outward.dot(&self.geometry.model.toward_follower(e.p, q)) > 0.0
    }

    /// Oriented score of a position (larger is an earlier touch).
    pub(crate) fn oriented(&self, q: f64) -> f64 {
        self.geometry.joint.oriented(q)
    }

    /// Start candidates for a knife edge: the crossings of its line of travel with the profile
    /// sampled at `s` (linear interpolation between samples), best first.
    fn knife_starts(&self, frame: &Frame, s: &[f64], out: &mut Candidates) {
        let Some((d, p, e)) = self.geometry.model.knife_line() else {
            return;
        };
        let profile = self.cam.profile.as_ref();
        let n = s.len();
        let y = |k: usize| frame.position(profile, s[k]) - self.cam.pivot;
        let (y0, mut ya) = (y(0), y(0));
        let mut la = ya.dot(&p) - e;
        for k in 0..n {
            let (yb, ub) = if k + 1 < n {
                (y(k + 1), s[k + 1])
            } else {
                (y0, self.period)
            };
            let lb = yb.dot(&p) - e;
            if la == 0.0 || (la > 0.0) != (lb > 0.0) {
                let f = if la == lb { 0.0 } else { la / (la - lb) };
                let q0 = ya.dot(&d) * (1.0 - f) + yb.dot(&d) * f;
                out.push((q0, s[k] + f * (ub - s[k]), q0));
            }
            (ya, la) = (yb, lb);
        }
    }

    /// Start candidates: the local maxima of the first-touch function sampled at `s`, best
    /// first; returns the best sampled score (a lower bound of the true first touch).
    fn score_starts(&self, frame: &Frame, s: &[f64], out: &mut Candidates) -> f64 {
        let profile = self.cam.profile.as_ref();
        let n = s.len();
        let score = |u: f64| self.geometry.model.score(frame.position(profile, u));
        let val = |x: Option<(f64, f64)>| x.map_or(f64::NEG_INFINITY, |x| x.0);
        let first = score(s[0]);
        let (mut prev, mut cur) = (score(s[n - 1]), first);
        let mut best = f64::NEG_INFINITY;
        for (k, &u) in s.iter().enumerate() {
            let next = s.get(k + 1).map_or(first, |&v| score(v));
            if let Some((sc, q)) = cur {
                best = best.max(sc);
                if sc >= val(prev) && sc >= val(next) {
                    out.push((sc, u, q));
                }
            }
            (prev, cur) = (cur, next);
        }
        best
    }

    /// The single best sample of the first-touch function at `s` (a convex profile has one
    /// maximum).
    fn best_sample(&self, frame: &Frame, s: &[f64]) -> Option<(f64, f64, f64)> {
        let profile = self.cam.profile.as_ref();
        let mut best: Option<(f64, f64, f64)> = None;
        for &u in s {
            if let Some((sc, q)) = self.geometry.model.score(frame.position(profile, u)) {
                if best.is_none_or(|b| sc > b.0) {
                    best = Some((sc, u, q));
                }
            }
        }
        best
    }

    /// Global first touch. A convex profile's first-touch function has one maximum: its best
    /// coarse sample (for a knife edge, the outer crossing found by the coarse scan) is refined by
    /// Newton. Otherwise, or when that start fails, the best local maxima of the densely sampled
    /// function (the crossings, for a knife edge) are refined and the best first touch among them
    /// is kept.
    pub(crate) fn global_touch(&self, theta: f64, frame: &Frame) -> Result<Touch, CamError> {
        let knife = self.geometry.is_knife();
        if self.convex {
            // a knife's line crosses a convex profile twice: the coarse scan finds the outer
            // crossing unless the line only grazes the profile (then the dense scan below)
            let start = if knife {
                let mut c = Candidates::new(1);
                self.knife_starts(frame, &self.coarse, &mut c);
                c.as_slice().first().copied()
            } else {
                self.best_sample(frame, &self.coarse)
            };
            if let Some((_, u0, q0)) = start {
                if let Ok(t) = self.newton(theta, frame, u0, q0) {
                    if self.is_first_touch(frame, &t) {
                        return Ok(t);
                    }
                }
            }
        }
        let mut starts = Candidates::new(self.options.candidates);
        let best_sample = if knife {
            self.knife_starts(frame, &self.samples, &mut starts);
            f64::NEG_INFINITY // a knife's interpolated crossings are not exact touches
        } else {
            self.score_starts(frame, &self.samples, &mut starts)
        };
        if starts.is_empty() {
            let reason = if knife {
                "the knife edge's line of travel misses the cam"
            } else {
                "the follower cannot reach the cam"
            };
            return Err(CamError::NoTouch {
                angle_deg: theta.to_degrees(),
                reason,
            });
        }
        let mut best: Option<Touch> = None;
        let mut last_err = None;
        for &(_, u0, q0) in starts.as_slice() {
            match self.newton(theta, frame, u0, q0) {
                Ok(t) if self.is_first_touch(frame, &t) => {
                    if best.is_none_or(|b| self.oriented(t.q) > self.oriented(b.q)) {
                        best = Some(t);
                    }
                }
                Ok(_) => {
                    last_err = Some(CamError::NoConvergence {
                        angle_deg: theta.to_degrees(),
                        reason: "Newton reached a tangency that is not the first touch",
                    })
                }
                Err(e) => last_err = Some(e),
            }
        }
        let best = best.ok_or_else(|| {
            last_err.unwrap_or(CamError::NoConvergence {
                angle_deg: theta.to_degrees(),
                reason: "no candidate",
            })
        })?;
        // the refined touch can only be later than (or equal to) a sampled one
        if self.oriented(best.q) < best_sample - self.touch_slack() {
            return Err(CamError::NoConvergence {
                angle_deg: theta.to_degrees(),
                reason: "refined contact is behind a sampled one",
            });
        }
        Ok(best)
    }

    /// The best sampled first-touch score over the dense samples (the sweep's jump guard).
    pub(crate) fn best_sampled_score(&self, frame: &Frame) -> f64 {
        self.best_sample(frame, &self.samples)
            .map_or(f64::NEG_INFINITY, |b| b.0)
    }

    /// `(dq/dθ, d²q/dθ², d³q/dθ³)` at cam angle `theta` (rad) by implicit differentiation of the
    /// first-touch conditions (see the `jet` module). This is independent of the paper's method
    /// and gives the jerk; `d³q/dθ³` takes the profile's third derivative on the segment that
    /// holds the contact (at a spline node it jumps).
    pub fn angle_derivatives(&self, theta: f64) -> Result<[f64; 3], CamError> {
        let cam = self.cam.state(theta);
        let touch = self.global_touch(theta, &cam.frame())?;
        self.jet_derivatives(theta, &cam, touch)
    }

    pub(crate) fn jet_derivatives(
        &self,
        theta: f64,
        cam: &BodyState,
        touch: Touch,
    ) -> Result<[f64; 3], CamError> {
        let profile = self.cam.profile.as_ref();
        let r = profile.eval(touch.u);
        let s = self.cam.direction.sign();
        let rot0 = Rot::new(s * theta);
        // R(s ε) as jets: cos(sε) = 1 − ε²/2, sin(sε) = s ε − s ε³/6 (s = ±1)
        let (ce, se) = (Jet([1.0, 0.0, -0.5, 0.0]), Jet([0.0, s, 0.0, -s / 6.0]));
        let j = self
            .geometry
            .model
            .jacobian(&cam.eval_curve(profile, touch.u), touch.q);
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if !(det.abs() > 0.0 && det.is_finite()) {
            return Err(CamError::NoConvergence {
                angle_deg: theta.to_degrees(),
                reason: "singular tangency Jacobian",
            });
        }
        let mut u = [0.0; 4];
        let mut q = [touch.q, 0.0, 0.0, 0.0];
        let world = |x: Jet, y: Jet, origin: Vec2| {
            let (ax, ay) = (ce * x - se * y, se * x + ce * y);
            V2::new(
                Jet::c(origin.x) + scale(ax, rot0.cos) - scale(ay, rot0.sin),
                Jet::c(origin.y) + scale(ax, rot0.sin) + scale(ay, rot0.cos),
            )
        };
        for k in 1..=3 {
            let dl = Jet([0.0, u[1], u[2], u[3]]);
            let (d2, d3) = (dl * dl, dl * dl * dl);
            let taylor = |c0: f64, c1: f64, c2: f64, c3: f64| {
                Jet::c(c0) + scale(dl, c1) + scale(d2, c2 / 2.0) + scale(d3, c3 / 6.0)
            };
            let x = world(
                taylor(r.p.x, r.d1.x, r.d2.x, r.d3.x),
                taylor(r.p.y, r.d1.y, r.d2.y, r.d3.y),
                self.cam.pivot.coords,
            );
            // ∂x/∂u along the path; the fourth derivative is left out (it does not reach q, see jet.rs)
            let x1 = world(
                taylor(r.d1.x, r.d2.x, r.d3.x, 0.0),
                taylor(r.d1.y, r.d2.y, r.d3.y, 0.0),
                Vec2::zeros(),
            );
            let f = self.geometry.model.residual_value(x, x1, Jet(q));
            let (f0, f1) = (f[0].0[k], f[1].0[k]);
            u[k] = (-f0 * j[1][1] + f1 * j[0][1]) / det;
            q[k] = (-j[0][0] * f1 + j[1][0] * f0) / det;
        }
        Ok([q[1], 2.0 * q[2], 6.0 * q[3]])
    }

    /// Velocity, acceleration and contact data at a converged touch (paper eqs. 5, 6, 1, 2, 11).
    /// The contact method at a converged touch: velocity from the velocity constraint, sliding
    /// rates (eqs. 5, 6) and acceleration from the acceleration constraint (eq. 11).
    #[inline]
    fn core(
        &self,
        theta: f64,
        cam: &BodyState,
        frame: &Frame,
        touch: Touch,
    ) -> Result<Core, CamError> {
        let g = &self.geometry;
        let profile = self.cam.profile.as_ref();
        let angle_deg = theta.to_degrees();
        let body_a = profile.eval(touch.u);
        let ea = frame.to_world(&body_a);
        let c = ea.p;
        let nu = ea.as_derivs().normal();
        let jb = g.joint.velocity_jacobian(c);
        // velocity constraint Φ_q q̇ = 0: ν·v_A^P = q̇ ν·J_B
        let den = nu.dot(&jb);
        if !(den.abs() > self.options.lock_tolerance * jb.norm()) {
            return Err(CamError::Locked {
                angle_deg,
                pressure_angle_deg: pressure_angle(jb, nu).to_degrees(),
            });
        }
        let qd = nu.dot(&cam.velocity_at(c)) / den;
        let body_b = g.joint.body(touch.q, qd, 0.0);
        let (u_b, eb) = g.curve.world_at(&body_b.frame(), c);
        let pairing = Pairing {
            u_a: touch.u,
            u_b,
            point_a: c,
            point_b: eb.p,
            normal: nu,
            gap: nu.dot(&(c - eb.p)),
            iterations: 0,
        };
        let k = ContactKinematics::from_geometry(
            cam,
            &ea,
            &body_b,
            &eb,
            g.is_knife(),
            &pairing,
            self.options.conformal_tolerance,
        )
        .map_err(|source| CamError::Contact { angle_deg, source })?;
        // acceleration constraint Φ_q q̈ = γ (eq. 11), cam accelerations known
        let phi = &k.phi_q;
        let known = phi[2] * cam.alpha;
        let coef = g.joint.coordinate_coefficient(phi);
        let qdd = (k.gamma - known) / coef;
        Ok(Core {
            body_a,
            ea,
            nu,
            jb,
            qd,
            qdd,
            u_b,
            k,
        })
    }

    pub(crate) fn kinematics(
        &self,
        theta: f64,
        cam: &BodyState,
        frame: &Frame,
        touch: Touch,
        found: Found,
    ) -> Result<FollowerState, CamError> {
        let Core {
            body_a,
            ea,
            nu,
            jb,
            qd,
            qdd,
            u_b,
            k,
        } = self.core(theta, cam, frame, touch)?;
        let g = &self.geometry;
        let c = ea.p;
        let body_b = g.joint.body(touch.q, qd, qdd);
        let kappa_conv = self.orientation * k.kappa_a;
        let at_breakpoint = self.at_breakpoint(touch.u);
        let jerk = if at_breakpoint || !self.options.jerk {
            None
        } else {
            let dq = self.jet_derivatives(theta, cam, touch)?;
            let (w, al) = (self.cam.speed, self.cam.angular_acceleration);
            Some(w * w * w * dq[2] + 3.0 * w * al * dq[1])
        };
        Ok(FollowerState {
            cam_angle: theta,
            position: touch.q,
            velocity: qd,
            acceleration: qdd,
            jerk,
            contact_world: c,
            contact_cam: body_a.p,
            cam_param: touch.u,
            cam_param_rate: k.param_rate_a,
            follower_param: u_b,
            sliding_rate_cam: k.sliding_rate_a,
            sliding_rate_follower: k.sliding_rate_b,
            normal_acceleration_cam: k.normal_acceleration_a(cam),
            normal_acceleration_follower: k.normal_acceleration_b(&body_b),
            normal: nu,
            sigma: k.sigma,
            follower_motion: jb,
            radius_of_curvature: 1.0 / kappa_conv,
            at_breakpoint,
            found,
        })
    }

    /// True when `u` is within the breakpoint tolerance of a node of the profile.
    fn at_breakpoint(&self, u: f64) -> bool {
        let bp = &self.breakpoints;
        if bp.is_empty() {
            return false;
        }
        let tol = self.options.breakpoint_tolerance * self.period;
        let i = bp.partition_point(|&b| b <= u);
        let below = if i == 0 {
            bp[bp.len() - 1] - self.period
        } else {
            bp[i - 1]
        };
        let above = if i < bp.len() {
            bp[i]
        } else {
            bp[0] + self.period
        };
        u - below < tol || above - u < tol
    }
}

/// The angle from the direction of motion `jb` of the follower's point to the contact normal
/// `nu` oriented towards the follower, rad, counter-clockwise positive.
fn pressure_angle(jb: Vec2, nu: Vec2) -> f64 {
    let npush = if nu.dot(&jb) >= 0.0 { nu } else { -nu };
    cross(jb, npush).atan2(jb.dot(&npush))
}

impl FollowerState {
    /// Pressure angle: from the direction of motion of the follower's point at the contact
    /// ([`FollowerState::follower_motion`]) to the contact normal oriented towards the follower,
    /// rad, counter-clockwise positive.
    pub fn pressure_angle(&self) -> f64 {
        pressure_angle(self.follower_motion, self.normal)
    }
}

/// Most start candidates refined by the global search.
pub const MAX_CANDIDATES: usize = 8;

/// The best few start candidates `(oriented score, u, q)`, best first, kept without allocating.
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
    pub(crate) fn push(&mut self, c: (f64, f64, f64)) {
        if self.len == self.cap {
            if !(c.0 > self.items[self.len - 1].0) {
                return;
            }
            self.len -= 1;
        }
        let mut i = self.len;
        while i > 0 && self.items[i - 1].0 < c.0 {
            self.items[i] = self.items[i - 1];
            i -= 1;
        }
        self.items[i] = c;
        self.len += 1;
    }
    pub(crate) fn is_empty(&self) -> bool {
        self.len == 0
    }
    pub(crate) fn as_slice(&self) -> &[(f64, f64, f64)] {
        &self.items[..self.len]
    }
}

/// The same parameters as [`bracket_samples`], without storing them.
pub(crate) use crate::curve::piece_samples as bracket_params;

/// Parameters for bracketing: `per_piece` per smooth piece, or `per_curve` over the period.
pub(crate) fn bracket_samples(
    breakpoints: &[f64],
    period: f64,
    per_piece: usize,
    per_curve: usize,
) -> Vec<f64> {
    bracket_params(breakpoints, period, per_piece, per_curve).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    fn paper() -> Mechanism {
        crate::reference::paper_mechanism(false)
    }

    #[test]
    fn back_side_stationary_point_is_not_a_first_touch() {
        let m = paper();
        let frame = m.cam.state(0.0).frame();
        // Newton from the far side converges to the leftmost point, a stationary point of x·d
        let back = m.newton(0.0, &frame, 4.5, -2.8).unwrap();
        assert!(back.q < 0.0);
        assert!(!m.is_first_touch(&frame, &back));
        let front = m.newton(0.0, &frame, 0.1, 4.9).unwrap();
        assert!(m.is_first_touch(&frame, &front));
        assert!((front.q - 5.0).abs() < 1e-14);
    }

    #[test]
    fn bracket_samples_cover_each_piece() {
        let s = bracket_samples(&[0.0, 1.0, 3.0], 4.0, 2, 5);
        assert_eq!(s, vec![0.0, 0.5, 1.0, 2.0, 3.0, 3.5]);
        assert_eq!(bracket_samples(&[], 1.0, 2, 4), vec![0.0, 0.25, 0.5, 0.75]);
        assert_eq!(
            bracket_params(&[0.0, 1.0, 3.0], 4.0, 2, 5).collect::<Vec<_>>(),
            s
        );
        assert_eq!(
            bracket_params(&[], 1.0, 2, 4).collect::<Vec<_>>(),
            vec![0.0, 0.25, 0.5, 0.75]
        );
    }
}
