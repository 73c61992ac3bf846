//! Forces under permanent contact (kinetostatics): the contact force, the camshaft torque, the
//! speed at which the follower would leave the cam, and the spring that keeps it on.
//!
//! With the follower in contact, its coordinate `q` follows the kinematic motion. Along `q` the
//! follower's equation of motion is
//!
//! ```text
//! M q̈ = F J − a (F₀ + k ℓ) − c q̇ + G
//! ```
//!
//! with `M` the mass (inertia), `F` the contact force along the common normal (compressive
//! positive, friction neglected), `J = n·∂v_P/∂q̇` the rate at which the follower's contact point
//! moves along the normal `n` out of the cam, `a = ±1` the sense of `q` away from the cam, `ℓ`
//! the lift, `F₀ + k ℓ` the spring (preload at rest), `c` the damping and `G = m g·d` gravity
//! along the line of travel (no gravity torque on an arm: its mass is taken at the pivot). Since
//! `a J = |J|`, `F |J| = a (M q̈ + c q̇ − G) + F₀ + k ℓ`.
//!
//! The torque that drives the cam is `T = σ F ((P − C) × n)` (σ = ±1 the cam's sense, `P` the
//! contact, `C` the cam axis); frictionless, the power `T ω` equals `F J q̇`, the power the
//! follower receives.
//!
//! At a constant cam speed ω, `q̇ = ω q'`, `q̈ = ω² q''` with `q', q''` derivatives in the cam angle,
//! so `F |J|` is a quadratic in ω at every cam angle: the follower leaves the cam first at the
//! smallest ω where it reaches the margin anywhere, and the preload (or stiffness) that keeps it
//! on up to a target speed is a maximum over the revolution of a linear bound.

use super::{DynamicsError, FollowerDynamics};
use crate::cam::{CamError, FollowerState, Mechanism, Travel};
use crate::geometry::cross;

/// The forces at one cam angle under permanent contact (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ForceState {
    /// cam angle, rad
    pub cam_angle: f64,
    /// the follower's lift, m (rad)
    pub lift: f64,
    /// contact force along the common normal, N, compressive positive (negative: the follower
    /// would leave the cam)
    pub contact_force: f64,
    /// spring force (torque) on the follower towards the cam, N (N·m)
    pub spring_force: f64,
    /// the torque driving the cam, in its sense of rotation, N·m
    pub camshaft_torque: f64,
    /// power into the follower `F J q̇`, W (equals `T ω` without friction)
    pub follower_power: f64,
    /// `|J|`: how fast the contact point moves along the normal per unit rate of `q` (m per m,
    /// the pressure angle's cosine for a translating follower; m per rad for an arm)
    pub lever: f64,
    /// the cam profile's radius of curvature at the contact, m (positive: convex)
    pub cam_radius: f64,
    /// pressure angle, rad
    pub pressure_angle: f64,
    /// `q'`, `q''` in the cam angle
    pub dq: [f64; 2],
}

/// Kinetostatics of a cam mechanism in SI units (lengths in metres).
#[derive(Debug, Clone)]
pub struct Forces<'a> {
    mech: &'a Mechanism,
    params: FollowerDynamics,
    travel: Travel,
    /// mass or inertia
    m: f64,
    /// gravity along the line of travel, N
    g: f64,
}

impl<'a> Forces<'a> {
    /// The kinetostatics of `mech` (lengths in metres) with `params`.
    pub fn new(mech: &'a Mechanism, params: FollowerDynamics) -> Result<Self, DynamicsError> {
        if mech.is_conjugate() {
            return Err(DynamicsError::FormClosed);
        }
        let travel = mech
            .travel()
            .map_err(|source| DynamicsError::Kinematics { source })?;
        let oscillating = mech.follower().is_oscillating();
        let m = if oscillating {
            params.inertia
        } else {
            params.mass
        };
        let g = match mech.follower_joint() {
            crate::cam::Joint::Translating { direction, .. } => {
                params.mass * params.gravity.dot(&direction)
            }
            _ => 0.0,
        };
        Ok(Self {
            mech,
            params,
            travel,
            m,
            g,
        })
    }

    /// The follower's travel (rest position, stroke).
    pub fn travel(&self) -> &Travel {
        &self.travel
    }

    /// The forces at cam angle `theta` (rad) at the cam's own speed.
    pub fn at(&self, theta: f64) -> Result<ForceState, CamError> {
        Ok(self.from_state(&self.mech.analyze(theta)?))
    }

    /// The forces at the cam's own speed from the follower's state `s` (of this mechanism, at
    /// its cam angle): a sweep's states ([`Mechanism::sweep`]) give the forces over a revolution
    /// without a cold search at every angle.
    pub fn from_state(&self, s: &FollowerState) -> ForceState {
        let theta = s.cam_angle;
        let cam = self.mech.cam();
        let (w, al) = (cam.speed(), cam.angular_acceleration());
        let orient = self.mech.orientation();
        // the normal out of the cam, onto the follower
        let n = -orient * *s.normal;
        let jac = n.dot(&s.follower_motion);
        let a = self.travel.away;
        let lift = self.travel.lift(s.position);
        let p = &self.params;
        let spring = p.spring_preload + p.spring_stiffness * lift;
        let f = (self.m * s.acceleration + a * spring + p.damping * s.velocity - self.g) / jac;
        let r = s.contact_world - cam.pivot();
        let torque = cam.direction().sign() * f * cross(r, n);
        let q1 = s.velocity / w;
        let q2 = (s.acceleration - q1 * al) / (w * w);
        ForceState {
            cam_angle: theta,
            lift,
            contact_force: f,
            spring_force: spring,
            camshaft_torque: torque,
            follower_power: f * jac * s.velocity,
            lever: jac.abs(),
            cam_radius: s.radius_of_curvature,
            pressure_angle: s.pressure_angle(),
            dq: [q1, q2],
        }
    }

    /// `F |J|` at cam speed ω (rad/s, constant) from a state's geometry: `(c2, c1, c0)` of
    /// `c2 ω² + c1 ω + c0`.
    fn quadratic(&self, s: &ForceState) -> (f64, f64, f64) {
        let [c2, c1, c0] = self.force_coefficients(s);
        (c2, c1, c0)
    }

    /// `[c2, c1, c0]` with `F |J| = c2 ω² + c1 ω + c0` at this angle, at any constant cam speed
    /// ω (rad/s): the contact force at any speed is `(c2 ω² + c1 ω + c0) / lever` (a front end
    /// with a speed slider evaluates it without asking again).
    pub fn force_coefficients(&self, s: &ForceState) -> [f64; 3] {
        let a = self.travel.away;
        [
            a * self.m * s.dq[1],
            a * self.params.damping * s.dq[0],
            s.spring_force - a * self.g,
        ]
    }

    /// The contact force (N) at this angle at the constant cam speed `omega` (rad/s).
    pub fn force_at_speed(&self, s: &ForceState, omega: f64) -> f64 {
        let (c2, c1, c0) = self.quadratic(s);
        (c2 * omega * omega + c1 * omega + c0) / s.lever
    }

    /// The smallest constant cam speed (rad/s) at which the contact force at this angle falls to
    /// `margin` N (∞ if it never does; 0 if it is below the margin at rest).
    pub fn leave_speed(&self, s: &ForceState, margin: f64) -> f64 {
        let (c2, c1, c0) = self.quadratic(s);
        let c0 = c0 - margin * s.lever;
        if c0 < 0.0 {
            return 0.0;
        }
        // smallest positive root of c2 ω² + c1 ω + c0 = 0 where the quadratic turns negative
        if c2 == 0.0 {
            return if c1 < 0.0 { -c0 / c1 } else { f64::INFINITY };
        }
        let disc = c1 * c1 - 4.0 * c2 * c0;
        if disc < 0.0 {
            return f64::INFINITY;
        }
        let sq = disc.sqrt();
        // numerically stable roots
        let qq = -0.5 * (c1 + c1.signum() * sq);
        let mut roots = [qq / c2, if qq != 0.0 { c0 / qq } else { f64::NAN }];
        roots.sort_by(f64::total_cmp);
        roots
            .into_iter()
            .find(|&r| r > 0.0 && r.is_finite())
            .unwrap_or(f64::INFINITY)
    }

    /// The smallest preload (N or N·m) that keeps the contact force at this angle at least
    /// `margin` at every constant speed up to `omega` (rad/s), with the stiffness as given.
    pub fn preload_needed(&self, s: &ForceState, margin: f64, omega: f64) -> f64 {
        let (c2, c1, _) = self.quadratic(s);
        let worst = self.worst_dynamic(c2, c1, omega);
        margin * s.lever - worst - self.params.spring_stiffness * s.lift + self.travel.away * self.g
    }

    /// The smallest stiffness that keeps the contact force at this angle at least `margin` up to
    /// `omega` with the preload as given: `None` where the lift is zero (only the preload acts);
    /// negative or zero where any stiffness does.
    pub fn stiffness_needed(&self, s: &ForceState, margin: f64, omega: f64) -> Option<f64> {
        let (c2, c1, _) = self.quadratic(s);
        let worst = self.worst_dynamic(c2, c1, omega);
        let need =
            margin * s.lever - worst - self.params.spring_preload + self.travel.away * self.g;
        if s.lift > 0.0 {
            Some(need / s.lift)
        } else {
            None
        }
    }

    /// The smallest value of `c2 ω² + c1 ω` over `[0, omega]`.
    fn worst_dynamic(&self, c2: f64, c1: f64, omega: f64) -> f64 {
        let f = |w: f64| c2 * w * w + c1 * w;
        let mut m = f(0.0).min(f(omega));
        if c2 > 0.0 {
            let v = -c1 / (2.0 * c2);
            if v > 0.0 && v < omega {
                m = m.min(f(v));
            }
        }
        m
    }
}

/// Hertz's maximum pressure of a line contact, Pa: two cylinders of radii `r1`, `r2` (m; a
/// concave one negative, a flat `f64::INFINITY`) pressed by `force` N over the length `width` m,
/// with the effective modulus `e_star` (Pa, [`effective_modulus`]):
/// `p = √(F E* / (π L R))`, `1/R = 1/r1 + 1/r2` (Johnson, Contact Mechanics, 1985, §4.2). `None`
/// where the curvatures do not close (`1/R ≤ 0`: a concave cam as sharp as or sharper than the
/// roller) or the force is not compressive.
pub fn hertz_line_pressure(force: f64, width: f64, r1: f64, r2: f64, e_star: f64) -> Option<f64> {
    let k = 1.0 / r1 + 1.0 / r2;
    if !(k > 0.0) || !(force >= 0.0) {
        return None;
    }
    Some((force * e_star * k / (std::f64::consts::PI * width)).sqrt())
}

/// `E*` of two elastic bodies: `1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂`.
pub fn effective_modulus(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cam::{Cam, Follower, Sense};
    use crate::curve::Circle;
    use crate::{Point2, Vec2};
    use std::sync::Arc;

    /// An eccentric disc (R = 40 mm, e = 5 mm) under a flat face: `s = R + e cos θ`, so at any
    /// constant speed ω the contact force is `−m e ω² cos θ − c e ω sin θ + F₀ + k e (1 + cos θ)`
    /// (the lever is 1: the pressure angle is 0).
    #[test]
    fn force_coefficients_give_the_closed_form_force_at_any_speed() {
        let (r, e) = (0.04, 0.005);
        let disc = Arc::new(Circle::new(Point2::new(e, 0.0), r).unwrap());
        let cam = Cam::from_rpm(disc, Point2::origin(), Sense::Ccw, 300.0).unwrap();
        let m = Mechanism::new(
            cam,
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
        )
        .unwrap();
        let p = FollowerDynamics {
            mass: 0.5,
            inertia: 0.0,
            spring_stiffness: 2.0e4,
            spring_preload: 200.0,
            damping: 3.0,
            restitution: 0.0,
            gravity: Vec2::zeros(),
        };
        let f = Forces::new(&m, p).unwrap();
        let w0 = m.cam().speed();
        for k in 0..24 {
            let th = k as f64 * 0.27;
            let s = f.at(th).unwrap();
            let [c2, c1, c0] = f.force_coefficients(&s);
            for w in [0.0, w0, 3.0 * w0] {
                let exact = -p.mass * e * w * w * th.cos() - p.damping * e * w * th.sin()
                    + p.spring_preload
                    + p.spring_stiffness * e * (1.0 + th.cos());
                let got = (c2 * w * w + c1 * w + c0) / s.lever;
                assert!(
                    (got - exact).abs() < 1e-9 * exact.abs().max(1.0),
                    "θ = {th}, ω = {w}: {got} vs {exact}"
                );
            }
        }
    }
}
