//! Gear pairs: what a gear engineer reads from the exact contact of two involute gears.
//!
//! A [`GearPair`] is a [`Mechanism`] whose cam is an [`InvoluteGear`] (the **driver**, gear 1)
//! and whose follower is a rotating joint carrying another (the **driven** gear, 2). The
//! mechanism finds the contact and its kinematics as for any cam; the pair reads them as gear
//! quantities ([`MeshState`]) against the line of action of the flanks in contact.
//!
//! ```text
//! centre distance   a = |O₂ − O₁|          operating pressure angle  cos α_w = (r_b1 + r_b2)/a
//! line of action    tangent to both base circles at T₁, T₂, between the centres, length g = a sin α_w
//! ideal driven angle   φ₂ = const − (r_b1/r_b2) ψ₁   (ψ₁: the driver's frame angle; r_b1/r_b2 = z1/z2)
//! transmission error   TE = φ₂ − φ₂,ideal, rad (TE·r_b2 along the line of action, length)
//! contact ratio     ε = (√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − g) / p_b,  p_b = 2π r_b1/z1
//! specific sliding  ζ₁ = (w₁ − w₂)/w₁, ζ₂ = (w₂ − w₁)/w₂  (w_i: the contact point's speed over flank i)
//! ```
//!
//! The ideal angle is that of the same gears with exact involute flanks (the tooth thicknesses,
//! backlash allowances and profile shifts as built, no tip relief), in contact on the flanks the
//! mechanism's contact is on: for unmodified gears TE is zero wherever the contact is on both
//! involutes, and a tip relief shows as the TE it causes. The line of action is the one of the
//! flanks in contact (the driver's flank unwinding with sense `ε = ±1`).

use crate::cam::{FollowerState, Mechanism};
use crate::curve::{Curve, FlankSide, InvoluteGear};
use crate::geometry::{rot90, wrap_angle_near, Point2, Vec2};
use std::f64::consts::TAU;

/// Why a mechanism is not a gear pair.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum GearError {
    /// the cam's profile is not an involute gear
    #[error("the cam's profile is not an involute gear (cam.profile.kind = \"involute-gear\")")]
    DriverNotGear,
    /// the follower is not a rotating joint carrying an involute gear
    #[error("the follower is not a gear: it must be kind = \"rotating\" carrying a profile of kind = \"involute-gear\"")]
    DrivenNotGear,
    /// the base circles overlap: no external line of action
    #[error("the centre distance {} is not more than the sum of the base radii {}: the gears' base circles overlap, they cannot mesh", crate::human::human(*.centre_distance), format!("{:.4}", .base_radii))]
    TooClose {
        /// `a`, length
        centre_distance: f64,
        /// `r_b1 + r_b2`, length
        base_radii: f64,
    },
    /// the centre distance is below the tight-mesh distance: the teeth overlap (interfere)
    #[error("the centre distance {centre_distance} is below the tight-mesh (zero-backlash) distance {tight:.9}: the teeth overlap by {overlap:.3e} along the line of action and cannot turn; move the centres apart to at least {tight:.9}, or thin the teeth (backlash, profile shift)", centre_distance = crate::human::human(*.centre_distance))]
    Interference {
        /// `a`, length
        centre_distance: f64,
        /// the tight-mesh distance, where the teeth touch on both flanks, length
        tight: f64,
        /// how far the teeth overlap along the line of action, length
        overlap: f64,
    },
    /// the centre distance leaves no path of contact on the involutes
    #[error("the centre distance {centre_distance} leaves the teeth no path of contact on their involutes (contact ratio {contact_ratio:.3}): they touch at most tip to tip; a contact ratio of 1 needs a centre distance of at most {}", crate::human::human(*.for_one), centre_distance = crate::human::human(*.centre_distance))]
    NoMesh {
        /// `a`, length
        centre_distance: f64,
        /// the contact ratio there (≤ 0)
        contact_ratio: f64,
        /// the largest centre distance with a contact ratio of 1, length
        for_one: f64,
    },
    /// the base pitches differ: the teeth cannot hand over
    #[error("the gears' base pitches differ ({} and {}, π m cos α): give both the same module and pressure angle", crate::human::human(*.driver), crate::human::human(*.driven))]
    BasePitch {
        /// the driver's base pitch, length
        driver: f64,
        /// the driven gear's, length
        driven: f64,
    },
}

/// Two involute gears in mesh: see the [module docs](self).
#[derive(Debug, Clone)]
pub struct GearPair {
    driver: InvoluteGear,
    driven: InvoluteGear,
    o1: Point2,
    o2: Point2,
    /// the driver's frame angle per unit cam angle, ±1
    cam_sign: f64,
    alpha_w: f64,
}

/// A gear pair's state at one driver angle. Angles in rad, lengths in the mechanism's unit,
/// time in s.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct MeshState {
    /// the driver's (cam) angle `θ`, rad
    pub driver_angle: f64,
    /// the driven gear's angle `φ₂`, rad (counter-clockwise)
    pub driven_angle: f64,
    /// `φ̇₂/ψ̇₁`, signed: `−z1/z2` for ideal gears
    pub speed_ratio: f64,
    /// the driven gear's angular acceleration `φ̈₂`, rad/s²
    pub driven_acceleration: f64,
    /// transmission error `φ₂ − φ₂,ideal`, rad
    pub transmission_error: f64,
    /// the same along the line of action, `r_b2 · TE`, length
    pub transmission_error_length: f64,
    /// `d TE/dt`, rad/s
    pub transmission_error_rate: f64,
    /// `d² TE/dt²`, rad/s²
    pub transmission_error_acceleration: f64,
    /// the driver's tooth in contact, `0..z1` (tooth `k` centred at `2πk/z1` in its frame)
    pub driver_tooth: u32,
    /// the driven gear's tooth in contact, `0..z2`
    pub driven_tooth: u32,
    /// the driver's flank in contact
    pub driver_flank: FlankSide,
    /// whether the contact is on the involute (relieved or not) of both flanks, not on a tip,
    /// root or fillet
    pub on_flanks: bool,
    /// tooth pairs touching at this instant (within the touch tolerance), this one included
    pub pairs_in_contact: u32,
    /// the contact point's position along the line of action from the pitch point, length,
    /// positive towards the driven gear's base circle
    pub line_of_action_position: f64,
    /// its distance from the line of action, length (0 for a contact on both involutes)
    pub line_of_action_offset: f64,
    /// relative velocity of the flanks at the contact, driver's minus driven's, along the
    /// tangent pointing away from the driver's centre, length/s
    pub sliding_velocity: f64,
    /// the driver flank's specific sliding `(w₁ − w₂)/w₁`; `None` where `w₁ = 0`
    pub specific_sliding_driver: Option<f64>,
    /// the driven flank's specific sliding `(w₂ − w₁)/w₂`; `None` where `w₂ = 0`
    pub specific_sliding_driven: Option<f64>,
}

/// The line of action of the flanks unwinding with sense `eps`.
#[derive(Debug, Clone, Copy)]
struct Line {
    /// the base circles' tangent points' polar angles about each centre
    tau1: f64,
    tau2: f64,
    /// from `T₁` towards `T₂`
    e: Vec2,
    /// the unit normal from `O₁` to the line
    n: Vec2,
    t1: Point2,
}

/// The transverse contact ratio of two external gears at centre distance `a`: the path of
/// contact over the base pitch. The textbook formula `(√(r_a1² − r_b1²) + √(r_a2² − r_b2²) −
/// a sin α_w) / p_b`, except where a flank's involute starts above its base circle (its form
/// circle: a gear of few teeth, undercut by the rack that cut it), which shortens the path
/// (refused as in [`GearPair::new`]).
pub fn contact_ratio(
    driver: &InvoluteGear,
    driven: &InvoluteGear,
    centre_distance: f64,
) -> Result<f64, GearError> {
    check(driver, driven, centre_distance)?;
    Ok(path_over_pitch(driver, driven, centre_distance))
}

/// The contact ratio's formula, unchecked (negative when the path of contact is empty).
fn path_over_pitch(driver: &InvoluteGear, driven: &InvoluteGear, centre_distance: f64) -> f64 {
    let [start, end] = path_ends(driver, driven, centre_distance);
    let pb = TAU * driver.base_radius() / f64::from(driver.teeth());
    (end - start) / pb
}

/// The path of contact's ends, roll lengths on the driver from `T₁`: within both flanks'
/// involutes.
fn path_ends(driver: &InvoluteGear, driven: &InvoluteGear, centre_distance: f64) -> [f64; 2] {
    let (rb1, rb2) = (driver.base_radius(), driven.base_radius());
    let g = (centre_distance * centre_distance - (rb1 + rb2).powi(2)).sqrt();
    let roll = |r: f64, rb: f64| (r * r - rb * rb).max(0.0).sqrt();
    let end = roll(driver.tip_radius(), rb1).min(g - roll(driven.form_radius(), rb2));
    let start = (g - roll(driven.tip_radius(), rb2)).max(roll(driver.form_radius(), rb1));
    [start, end]
}

/// The tight-mesh (zero-backlash) centre distance of two external gears with equal base
/// pitches: where the teeth touch on both flanks at once. From the teeth's half angles at the
/// base circle `γ₁, γ₂` ([`InvoluteGear::base_half_angle`], the thickness as built: shifts and
/// backlash allowances included), the operating pressure angle has
/// `inv α_w = (z₁γ₁ + z₂γ₂ − π)/(z₁ + z₂)` and the distance is `(r_b1 + r_b2)/cos α_w` (for
/// standard gears without allowances, `inv α_w = inv α` and the distance is `m(z₁ + z₂)/2`).
/// Closer than it the teeth overlap.
pub fn tight_mesh_distance(driver: &InvoluteGear, driven: &InvoluteGear) -> f64 {
    let (z1, z2) = (f64::from(driver.teeth()), f64::from(driven.teeth()));
    let y = (z1 * driver.base_half_angle() + z2 * driven.base_half_angle() - std::f64::consts::PI)
        / (z1 + z2);
    let base = driver.base_radius() + driven.base_radius();
    if !(y > 0.0) {
        return base;
    }
    // inv α = y by Newton from the series' first term (inv α ≈ α³/3), monotone from above
    let mut alpha = (3.0 * y).cbrt().min(1.5);
    for _ in 0..60 {
        let t = alpha.tan();
        let step = (t - alpha - y) / (t * t);
        alpha -= step;
        if step.abs() <= 1e-15 * alpha {
            break;
        }
    }
    base / alpha.cos()
}

/// The largest centre distance at which the contact ratio is at least `ratio` (between the
/// tight-mesh distance and the tips' reach), or `None` when even the tight mesh falls short.
pub fn distance_for_contact_ratio(
    driver: &InvoluteGear,
    driven: &InvoluteGear,
    ratio: f64,
) -> Option<f64> {
    let lo0 = tight_mesh_distance(driver, driven).max(driver.base_radius() + driven.base_radius());
    let (mut lo, mut hi) = (lo0, driver.tip_radius() + driven.tip_radius());
    if !(path_over_pitch(driver, driven, lo) >= ratio) {
        return None;
    }
    // the path of contact shortens as the centres move apart
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if path_over_pitch(driver, driven, mid) >= ratio {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo <= 1e-13 * hi {
            break;
        }
    }
    Some(lo)
}

fn check(driver: &InvoluteGear, driven: &InvoluteGear, a: f64) -> Result<(), GearError> {
    let (rb1, rb2) = (driver.base_radius(), driven.base_radius());
    if !(a > rb1 + rb2) {
        return Err(GearError::TooClose {
            centre_distance: a,
            base_radii: rb1 + rb2,
        });
    }
    let p1 = TAU * rb1 / f64::from(driver.teeth());
    let p2 = TAU * rb2 / f64::from(driven.teeth());
    if (p1 - p2).abs() > 1e-9 * p1 {
        return Err(GearError::BasePitch {
            driver: p1,
            driven: p2,
        });
    }
    mesh_check(driver, driven, a)
}

/// Refuses a centre distance at which two gears of equal base pitch interfere (closer than the
/// tight mesh, beyond a rounding of 1e-9 of it) or have no path of contact on their involutes.
pub fn mesh_check(driver: &InvoluteGear, driven: &InvoluteGear, a: f64) -> Result<(), GearError> {
    let tight = tight_mesh_distance(driver, driven);
    if a < tight * (1.0 - 1e-9) {
        // the overlap along the line of action: the normal backlash 2(r_b1 + r_b2)(inv α_a −
        // inv α_tight), negative here, with cos α_d = (r_b1 + r_b2)/d
        let base = driver.base_radius() + driven.base_radius();
        let inv = |d: f64| crate::curve::involute_function((base / d).min(1.0).acos());
        return Err(GearError::Interference {
            centre_distance: a,
            tight,
            overlap: 2.0 * base * (inv(tight) - inv(a)).abs(),
        });
    }
    let eps = path_over_pitch(driver, driven, a);
    if !(eps > 0.0) {
        return Err(GearError::NoMesh {
            centre_distance: a,
            contact_ratio: eps,
            for_one: distance_for_contact_ratio(driver, driven, 1.0).unwrap_or(tight),
        });
    }
    Ok(())
}

fn gear_of(c: &dyn Curve) -> Option<&InvoluteGear> {
    c.as_involute_gear()
}

impl GearPair {
    /// The pair of `mech`, refused when the cam or the follower is not an involute gear, the
    /// base circles overlap or the base pitches differ.
    pub fn new(mech: &Mechanism) -> Result<Self, GearError> {
        let driver = gear_of(mech.cam().profile()).ok_or(GearError::DriverNotGear)?;
        let driven = mech
            .follower()
            .carried_profile()
            .and_then(|c| gear_of(c.as_ref()))
            .ok_or(GearError::DrivenNotGear)?;
        let joint = mech.follower_joint();
        if !joint.is_rotating() {
            return Err(GearError::DrivenNotGear);
        }
        let pivot = joint.origin();
        let o1 = mech.cam().pivot();
        let a = (pivot - o1).norm();
        check(driver, driven, a)?;
        Ok(Self {
            driver: driver.clone(),
            driven: driven.clone(),
            o1,
            o2: pivot,
            cam_sign: mech.cam().direction().sign(),
            alpha_w: ((driver.base_radius() + driven.base_radius()) / a).acos(),
        })
    }

    /// The driver (the cam's gear).
    pub fn driver(&self) -> &InvoluteGear {
        &self.driver
    }
    /// The driven gear.
    pub fn driven(&self) -> &InvoluteGear {
        &self.driven
    }
    /// Centre distance `a`, length.
    pub fn centre_distance(&self) -> f64 {
        (self.o2 - self.o1).norm()
    }
    /// Operating pressure angle `α_w`, rad.
    pub fn operating_pressure_angle(&self) -> f64 {
        self.alpha_w
    }
    /// The transverse contact ratio (see [`contact_ratio`]).
    pub fn contact_ratio(&self) -> f64 {
        contact_ratio(&self.driver, &self.driven, self.centre_distance())
            .expect("checked when the pair was built")
    }
    /// The base pitch `p_b = 2π r_b1/z1`, length: how far along the line of action the contact
    /// moves from one tooth pair to the next.
    pub fn base_pitch(&self) -> f64 {
        TAU * self.driver.base_radius() / f64::from(self.driver.teeth())
    }
    /// The path of contact's ends as roll lengths from the driver's base tangent point `T₁`
    /// along the line of action: from where the driven gear's tip (or the driver's form circle)
    /// meets the line to where the driver's tip (or the driven gear's form circle) does.
    pub fn path_of_contact(&self) -> [f64; 2] {
        path_ends(&self.driver, &self.driven, self.centre_distance())
    }

    /// The nominal ratio `r_b1/r_b2 = z1/z2`.
    pub fn ratio(&self) -> f64 {
        self.driver.base_radius() / self.driven.base_radius()
    }

    fn line(&self, eps: f64) -> Line {
        let d = self.o2 - self.o1;
        let lambda = d.y.atan2(d.x);
        let tau1 = lambda + eps * self.alpha_w;
        let n = Vec2::new(tau1.cos(), tau1.sin());
        Line {
            tau1,
            tau2: tau1 + std::f64::consts::PI,
            e: eps * Vec2::new(n.y, -n.x),
            n,
            t1: self.o1 + self.driver.base_radius() * n,
        }
    }

    /// The driven gear's ideal angle (exact involutes) at cam angle `theta` for the driver's
    /// tooth `k1` and the driven tooth `k2` in contact on flanks unwinding with sense `eps`,
    /// brought within half a turn of `near`.
    pub fn ideal_angle(&self, theta: f64, eps: f64, k1: u32, k2: u32, near: f64) -> f64 {
        let l = self.line(eps);
        let (g1, g2) = (&self.driver, &self.driven);
        let (rb1, rb2) = (g1.base_radius(), g2.base_radius());
        let g = self.centre_distance() * self.alpha_w.sin();
        let b1 = self.cam_sign * theta - eps * g1.base_half_angle()
            + TAU * f64::from(k1) / f64::from(g1.teeth());
        let rho1 = rb1 * wrap_angle_near(eps * (l.tau1 - b1), 0.0);
        let b2 = l.tau2 - eps * (g - rho1) / rb2;
        let q = b2 + eps * g2.base_half_angle() - TAU * f64::from(k2) / f64::from(g2.teeth());
        wrap_angle_near(q, near)
    }

    /// The pair's state from the mechanism's state `s` at its cam angle.
    pub fn mesh(&self, mech: &Mechanism, s: &FollowerState) -> MeshState {
        let theta = s.cam_angle;
        let f1 = self.driver.flank_at(s.cam_param);
        let f2 = self.driven.flank_at(s.follower_param);
        let eps = f1.side.unwinding();
        let ideal = self.ideal_angle(theta, eps, f1.tooth, f2.tooth, s.position);
        let te = s.position - ideal;
        let cam = mech.cam().state(theta);
        let ratio = self.ratio();
        let te_rate = s.velocity + ratio * cam.omega;
        let te_accel = s.acceleration + ratio * cam.alpha;
        let l = self.line(eps);
        let c = s.contact_world;
        let pitch = self.o1
            + self.driver.base_radius() / (self.driver.base_radius() + self.driven.base_radius())
                * (self.o2 - self.o1);
        // velocities of the flanks' material points under the contact
        let v1 = cam.omega * rot90(c - self.o1);
        let v2 = s.velocity * rot90(c - self.o2);
        let radial = c - self.o1;
        let nu = *s.normal;
        let t_cam = Vec2::new(nu.y, -nu.x);
        let t_out = if t_cam.dot(&radial) >= 0.0 {
            t_cam
        } else {
            -t_cam
        };
        let vs = (v1 - v2).dot(&t_out);
        let w1 = s.sliding_rate_cam * t_cam.dot(&t_out);
        let w2 = w1 + vs;
        let finite = |x: f64| x.is_finite().then_some(x);
        MeshState {
            driver_angle: theta,
            driven_angle: s.position,
            speed_ratio: s.velocity / cam.omega,
            driven_acceleration: s.acceleration,
            transmission_error: te,
            transmission_error_length: te * self.driven.base_radius(),
            transmission_error_rate: te_rate,
            transmission_error_acceleration: te_accel,
            driver_tooth: f1.tooth,
            driven_tooth: f2.tooth,
            driver_flank: f1.side,
            on_flanks: f1.roll_length.is_some() && f2.roll_length.is_some(),
            pairs_in_contact: 1 + self.other_pairs_touching(mech, s),
            line_of_action_position: (c - pitch).dot(&l.e),
            line_of_action_offset: (c - l.t1).dot(&l.n),
            sliding_velocity: vs,
            specific_sliding_driver: finite(-vs / w1),
            specific_sliding_driven: finite(vs / w2),
        }
    }

    /// The other tooth pairs that touch at the state's position: Newton on each neighbouring
    /// pair's tangency (up to two teeth either way), started where the line of action puts it
    /// (the contact moved by whole base pitches), counted when it converges on both flanks at
    /// the same driven angle (within the touch tolerance along the line of action).
    fn other_pairs_touching(&self, mech: &Mechanism, s: &FollowerState) -> u32 {
        let Some(c) = mech.touch.carried() else {
            return 0;
        };
        let (f1, f2) = (
            self.driver.flank_at(s.cam_param),
            self.driven.flank_at(s.follower_param),
        );
        let (Some(l1), Some(l2)) = (f1.roll_length, f2.roll_length) else {
            return 0;
        };
        let at = &crate::cam::Instant::new(mech.cam(), s.cam_angle);
        let tol = mech.options().touch_tolerance;
        let rb2 = self.driven.base_radius();
        let pb = self.base_pitch();
        let (z1, z2) = (self.driver.teeth(), self.driven.teeth());
        let shift = |k: u32, by: i32, z: u32| {
            (i64::from(k) + i64::from(by)).rem_euclid(i64::from(z)) as u32
        };
        let mut found: Vec<u32> = Vec::new();
        for j in [-2i32, -1, 1, 2] {
            for sense in [-1i32, 1] {
                let k1 = shift(f1.tooth, sense * j, z1);
                let k2 = shift(f2.tooth, -sense * j, z2);
                let jf = f64::from(j);
                let (Some(u), Some(v)) = (
                    self.driver.param_at_roll(k1, f1.side, l1 + jf * pb),
                    self.driven.param_at_roll(k2, f2.side, l2 - jf * pb),
                ) else {
                    continue;
                };
                let Ok(t) = mech.touch.carried_newton(c, at, u, v, s.position) else {
                    continue;
                };
                let (g1, g2) = (self.driver.flank_at(t.u), self.driven.flank_at(t.v));
                if (t.q - s.position).abs() * rb2 <= tol
                    && g1.tooth == k1
                    && g2.tooth == k2
                    && g1.roll_length.is_some()
                    && g2.roll_length.is_some()
                    && !found.contains(&k1)
                {
                    found.push(k1);
                }
            }
        }
        found.len() as u32
    }
}
