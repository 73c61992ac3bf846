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
//!
//! A form-closed (conjugate) follower has a second curve that touches the cam from the other
//! side ([`Mechanism::with_conjugate`]): where `R = a (M q̈ + c q̇ − G) + F₀ + k ℓ` is negative the
//! follower's own curve would leave the cam and the second curve carries `−R / |J₂|` instead
//! (`J₂` its lever at its own contact), so `F₁ |J₁| − F₂ |J₂| = R`; one curve carries at a time
//! (no preload between the two). The torque sums both contacts. The second curve's contact is
//! taken where it touches at its own first touch: exact for a conjugate without play; with play,
//! the follower's motion is still its own curve's (the dynamics, `camkin simulate`, crosses the
//! play).

use super::{DynamicsError, FollowerDynamics};
use crate::cam::{CamError, FollowerCurve, FollowerState, Mechanism, Sweep, Travel};
use crate::geometry::cross;

/// The forces at one cam angle under permanent contact (SI units).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
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
    /// the follower's curve's radius of curvature at the contact, m (positive: convex; ∞ for a
    /// flat face); `None` where the contact is not a line contact of two smooth surfaces (a knife
    /// edge, or a corner of either curve)
    pub follower_radius: Option<f64>,
    /// the surfaces' speeds relative to the contact point along the cam profile's tangent, m/s:
    /// the cam's, the follower's (see [`surface_speeds`]); their mean is the entrainment speed
    /// of the lubricant, their difference the sliding speed
    pub surface_speeds: [f64; 2],
    /// `q'`, `q''` in the cam angle
    pub dq: [f64; 2],
    /// a form-closed follower's second curve: its contact and the force it carries (`None`
    /// without a second curve)
    pub second: Option<SecondContact>,
}

impl ForceState {
    /// The force a form-closed follower's second curve carries, N (0 without one).
    pub fn second_force(&self) -> f64 {
        self.second.map_or(0.0, |c| c.contact_force)
    }
}

/// The second curve of a form-closed follower at one cam angle ([`ForceState::second`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SecondContact {
    /// the force it carries along its common normal, N, ≥ 0 (zero where the follower's own curve
    /// carries)
    pub contact_force: f64,
    /// its `|J₂|` (as [`ForceState::lever`])
    pub lever: f64,
    /// the cam profile's radius of curvature at its contact, m (positive: convex)
    pub cam_radius: f64,
    /// its pressure angle, rad
    pub pressure_angle: f64,
    /// its radius of curvature at the contact, m (as [`ForceState::follower_radius`])
    pub follower_radius: Option<f64>,
    /// the surfaces' speeds at its contact, m/s (as [`ForceState::surface_speeds`])
    pub surface_speeds: [f64; 2],
}

/// Kinetostatics of a cam mechanism in SI units (lengths in metres).
#[derive(Debug, Clone)]
pub struct Forces<'a> {
    mech: &'a Mechanism,
    /// a form-closed follower's second curve: its own mechanism
    second: Option<&'a Mechanism>,
    params: FollowerDynamics,
    travel: Travel,
    /// mass or inertia
    m: f64,
    /// gravity along the line of travel, N
    g: f64,
}

impl<'a> Forces<'a> {
    /// The kinetostatics of `mech` (lengths in metres) with `params`; for a form-closed
    /// follower, both curves' forces (see the module's notes).
    pub fn new(mech: &'a Mechanism, params: FollowerDynamics) -> Result<Self, DynamicsError> {
        let travel = mech
            .travel()
            .map_err(|source| DynamicsError::Kinematics { source })?;
        let joint = mech.follower_joint();
        let (m, g) = (params.moving_mass(&joint), params.gravity_along(&joint));
        Ok(Self {
            mech,
            second: mech.conjugate_side().map(|(m, _)| m),
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

    /// The follower is form-closed: [`ForceState::second`] is set.
    pub fn is_form_closed(&self) -> bool {
        self.second.is_some()
    }

    /// The forces at cam angle `theta` (rad) at the cam's own speed: a cold search (over many
    /// angles, [`Forces::sweep`] is faster).
    pub fn at(&self, theta: f64) -> Result<ForceState, CamError> {
        let s = self.mech.analyze(theta)?;
        let s2 = self.second.map(|m| m.analyze(theta)).transpose()?;
        Ok(self.of_states(&s, s2.as_ref()))
    }

    /// Warm-started forces from angle to angle ([`ForceSweep::step`]), as [`Mechanism::sweep`].
    pub fn sweep(&self) -> ForceSweep<'_> {
        ForceSweep {
            forces: self,
            first: self.mech.sweep(),
            second: self.second.map(Mechanism::sweep),
        }
    }

    /// The forces from the follower's state `s` and, for a form-closed follower, its second
    /// curve's state `s2` at the same cam angle.
    fn of_states(&self, s: &FollowerState, s2: Option<&FollowerState>) -> ForceState {
        let theta = s.cam_angle;
        let cam = self.mech.cam();
        let (w, al) = (cam.speed(), cam.angular_acceleration());
        let sense = cam.direction().sign();
        let (n, jac) = lever(self.mech, s);
        let a = self.travel.away;
        let lift = self.travel.lift(s.position);
        let p = &self.params;
        let spring = p.spring_preload + p.spring_stiffness * lift;
        // the force if the follower's own curve carried alone: `F |J| = R`
        let f = (self.m * s.acceleration + a * spring + p.damping * s.velocity - self.g) / jac;
        let arm = |s: &FollowerState, n| cross(s.contact_world - cam.pivot(), n);
        let (f1, second, torque2, power2) = match (self.second, s2) {
            (Some(m2), Some(s2)) => {
                // where R < 0 the second curve carries: F₂ |J₂| = −R
                let (n2, jac2) = lever(m2, s2);
                let f2 = if f < 0.0 {
                    -f * jac.abs() / jac2.abs()
                } else {
                    0.0
                };
                let second = SecondContact {
                    contact_force: f2,
                    lever: jac2.abs(),
                    cam_radius: s2.radius_of_curvature,
                    pressure_angle: s2.pressure_angle(),
                    follower_radius: follower_radius(m2, s2),
                    surface_speeds: surface_speeds(m2, s2),
                };
                (
                    f.max(0.0),
                    Some(second),
                    sense * f2 * arm(s2, n2),
                    f2 * jac2 * s2.velocity,
                )
            }
            _ => (f, None, 0.0, 0.0),
        };
        let q1 = s.velocity / w;
        let q2 = (s.acceleration - q1 * al) / (w * w);
        ForceState {
            cam_angle: theta,
            lift,
            contact_force: f1,
            spring_force: spring,
            camshaft_torque: sense * f1 * arm(s, n) + torque2,
            follower_power: f1 * jac * s.velocity + power2,
            lever: jac.abs(),
            cam_radius: s.radius_of_curvature,
            pressure_angle: s.pressure_angle(),
            follower_radius: follower_radius(self.mech, s),
            surface_speeds: surface_speeds(self.mech, s),
            dq: [q1, q2],
            second,
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
    /// with a speed slider evaluates it without asking again). For a form-closed follower this is
    /// `R`: where it is negative the second curve carries `−R / second.lever`.
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
    /// `margin` N (∞ if it never does; 0 if it is below the margin at rest). For a form-closed
    /// follower with `margin` 0: the speed from which its second curve takes the load here.
    pub fn leave_speed(&self, s: &ForceState, margin: f64) -> f64 {
        let (c2, c1, c0) = self.quadratic(s);
        let c0 = c0 - margin * s.lever;
        if c0 < 0.0 {
            return 0.0;
        }
        if c0 == 0.0 {
            // at the margin at rest: below it at once if the force falls with ω, else past the
            // other root `−c1/c2` of `ω (c2 ω + c1)`
            return if c1 < 0.0 || (c1 == 0.0 && c2 < 0.0) {
                0.0
            } else if c2 < 0.0 {
                -c1 / c2
            } else {
                f64::INFINITY
            };
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

/// Warm-started forces over a sequence of cam angles ([`Forces::sweep`]): the follower's (and a
/// second curve's) contact found from the previous angle's, as [`Mechanism::sweep`].
#[derive(Debug, Clone)]
pub struct ForceSweep<'a> {
    forces: &'a Forces<'a>,
    first: Sweep<'a>,
    second: Option<Sweep<'a>>,
}

impl ForceSweep<'_> {
    /// The forces at cam angle `theta` (rad), the next of the sweep.
    pub fn step(&mut self, theta: f64) -> Result<ForceState, CamError> {
        let s = self.first.step(theta)?;
        let s2 = self.second.as_mut().map(|w| w.step(theta)).transpose()?;
        Ok(self.forces.of_states(&s, s2.as_ref()))
    }
}

/// The normal out of the cam onto the follower's curve at the contact of `s` (world) and the
/// lever `J = n·∂v_P/∂q̇` (signed: `a J = |J|`).
fn lever(mech: &Mechanism, s: &FollowerState) -> (crate::Vec2, f64) {
    let n = -mech.orientation() * *s.normal;
    (n, n.dot(&s.follower_motion))
}

/// The two surfaces' speeds relative to the contact point of `s`, along the cam profile's
/// tangent `t` (the normal `ν` turned a right angle clockwise), m/s: the cam's
/// `u₁ = (v₁ − v_P)·t = −ṡ_A` and the follower's `u₂ = (v₂ − v_P)·t`, with `v₁ = ω × (P − C)` and
/// `v₂ = q̇ ∂v_B/∂q̇` the bodies' material velocities at the contact `P` and
/// `v_P = v₁ + ṡ_A t` the contact point's own (the paper's eq. 5). The follower's is `∓ṡ_B`
/// (eq. 6, by the sense of its curve's tangent). Their mean is what draws the lubricant into the
/// contact (the entrainment speed), their difference `(v₁ − v₂)·t` the sliding speed.
///
/// A roller turns on its pin: it is taken as rolling on the cam without slip (the usual
/// assumption of cam design; its surface moves with the cam's, `u₂ = u₁`, and nothing slides).
/// A carried circle is part of its follower's body and slides like any carried curve.
pub fn surface_speeds(mech: &Mechanism, s: &FollowerState) -> [f64; 2] {
    let u_cam = -s.sliding_rate_cam;
    if matches!(mech.follower_curve(), FollowerCurve::Circle(_)) {
        return [u_cam, u_cam];
    }
    let cam = mech.cam();
    let omega = cam.direction().sign() * cam.speed();
    let t = crate::Vec2::new(s.normal.y, -s.normal.x);
    let v_cam = omega * crate::geometry::rot90(s.contact_world - cam.pivot());
    let v_follower = s.velocity * s.follower_motion;
    [u_cam, (v_follower - v_cam).dot(&t) + u_cam]
}

/// The radius of curvature (m, positive: convex) of the follower's curve at the contact of `s`:
/// a roller's radius, a flat face's ∞, a carried curve's at the contact (its material on its
/// left, so convex where it turns counter-clockwise); `None` for a knife edge and where either
/// curve touches with a corner (a point: no line contact).
fn follower_radius(mech: &Mechanism, s: &FollowerState) -> Option<f64> {
    if s.corner.is_some() {
        return None;
    }
    match mech.follower_curve() {
        FollowerCurve::Circle(c) => Some(c.radius()),
        FollowerCurve::Line(_) => Some(f64::INFINITY),
        FollowerCurve::Point(_) => None,
        FollowerCurve::Carried(c) => {
            let d = c.eval(s.follower_param);
            let k = cross(d.d1, d.d2) / d.d1.norm().powi(3);
            Some(if k == 0.0 { f64::INFINITY } else { 1.0 / k })
        }
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
