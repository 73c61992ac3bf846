//! The follower model: what a follower kind *is*, in one place.
//!
//! A follower is a [`FollowerJoint`] (a slide along a direction, or a revolute pair at a pivot) carrying a
//! contact curve in its own frame ([`FollowerCurve`]: a line, a circle or a point). The five named
//! kinds of [`Follower`] are presets of that shape; each is implemented once, in its own file, by
//! the crate-private `Kind` trait: validation of its reach, the first-touch position through one
//! cam point, the tangency residual and its Jacobian that Newton solves, the contact curve, the
//! synthesis envelope (`super::synthesis`) and the joint (which the dynamics builds on).
//! `Follower::model` is the one place that lists the kinds.
//!
//! Adding a kind: a new file implementing `Kind`, a variant in [`Follower`] and in `Model`, and its
//! line in `Follower::model` and in the `dispatch!` macro.
//!
//! Position `q` (see `cam-follower.md`): translating followers measure `s` from the cam's rotation
//! axis along the unit direction `d`; oscillating followers give the absolute arm angle `φ`
//! (rad, counter-clockwise from the world x axis).

pub(crate) mod carried;
mod centre_path;
mod curve;
pub(crate) mod envelope;
mod joint;
mod kind;
mod oscillating_flat;
mod oscillating_knife;
mod oscillating_roller;
pub(crate) mod rates;
mod translating_flat;
mod translating_knife;
mod translating_roller;

pub(crate) use centre_path::{pitch_point, CentrePath};
pub use curve::FollowerCurve;
pub use joint::FollowerJoint;
pub(crate) use kind::{dispatch, Kind, Model, Rates, Synthesis};

use super::pose::Pose;
use super::CamError;
use crate::body::WorldDerivs;
use crate::curve::{Circle, Line, PointCurve};
use crate::field::{Field, FollowerField};
use crate::geometry::Frame;
use crate::geometry::{rot90, wrap_angle_near, Point2, Rotation, UnitVec2, Vec2};
use crate::jet::{Num, V2};
use envelope::Envelope;
use oscillating_flat::OscillatingFlat;
use oscillating_knife::OscillatingKnife;
use oscillating_roller::OscillatingRoller;
use rates::{CamPoint, Refusals};
use translating_flat::TranslatingFlat;
use translating_knife::TranslatingKnife;
use translating_roller::TranslatingRoller;

/// Rotation sense: of the cam's motion, or of the spring that closes an oscillating follower.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Sense {
    /// counter-clockwise
    #[default]
    Ccw,
    /// clockwise
    Cw,
}

impl Sense {
    /// +1 for counter-clockwise, −1 for clockwise.
    pub fn sign(self) -> f64 {
        match self {
            Sense::Ccw => 1.0,
            Sense::Cw => -1.0,
        }
    }
}

/// The curve a general follower carries, in its own frame (compared by identity).
#[derive(Debug, Clone)]
pub struct FollowerProfile(pub std::sync::Arc<dyn crate::curve::Curve>);

impl PartialEq for FollowerProfile {
    fn eq(&self, other: &Self) -> bool {
        std::sync::Arc::ptr_eq(&self.0, &other.0)
    }
}

/// A follower and its geometry. Build a [`crate::cam::Mechanism`] to validate it.
///
/// A follower is a joint carrying a curve: [`Follower::Translating`] and [`Follower::Rotating`]
/// carry any curve; the five named kinds are presets of them with closed forms (a flat face is a
/// line, a roller a circle, a knife a point) — see `general-follower-and-gears.md`.
#[derive(Debug, Clone, PartialEq)]
pub enum Follower {
    /// A slide carrying any curve: the follower frame's origin is at `e·rot90(d) + s·d` from
    /// the cam axis, its x axis along `d`; `profile` is given in that frame.
    Translating {
        /// direction of travel `d`, from the cam towards the follower
        direction: Vec2,
        /// offset `e` of the line of travel, length
        offset: f64,
        /// the curve, with the follower's material on its left
        profile: FollowerProfile,
    },
    /// An arm carrying any curve: the follower frame's origin is the pivot, turned by the arm
    /// angle `φ` (at `φ = 0` aligned with the world); `profile` is given in that frame.
    Rotating {
        /// the pivot `O`, world
        pivot: Point2,
        /// sense in which the load turns the follower onto the cam
        closing: Sense,
        /// the angle at cam angle 0 is reported within ±180° of it (for a gear-like curve, the
        /// angle continued from it by the nominal ratio), rad
        initial_angle: f64,
        /// the curve, with the follower's material on its left
        profile: FollowerProfile,
    },
    /// Translating flat-faced: the face is the line `x·d = s` (positions from the cam axis).
    TranslatingFlat {
        /// direction of travel `d`, from the cam towards the follower (normalised on use)
        direction: Vec2,
    },
    /// Translating roller: centre at `e·rot90(d) + s·d` from the cam axis.
    TranslatingRoller {
        /// direction of travel `d`
        direction: Vec2,
        /// offset `e` of the line of travel, length
        offset: f64,
        /// roller radius, length
        roller_radius: f64,
    },
    /// Translating knife edge: tip at `e·rot90(d) + s·d` from the cam axis.
    TranslatingKnife {
        /// direction of travel `d`
        direction: Vec2,
        /// offset `e` of the line of travel, length
        offset: f64,
    },
    /// Oscillating flat-faced: the face is the line through `O + e (−sin φ, cos φ)` along
    /// `(cos φ, sin φ)`, touching the cam on the arm's side of the pivot.
    OscillatingFlat {
        /// arm pivot `O`, world
        pivot: Point2,
        /// face offset `e` from the pivot, length
        face_offset: f64,
        /// sense in which the spring turns the arm onto the cam
        closing: Sense,
        /// the arm angle is reported within ±180° of it, rad (any value finds the same contact)
        initial_angle: f64,
    },
    /// Oscillating roller: roller centre at `O + L (cos φ, sin φ)`.
    OscillatingRoller {
        /// arm pivot `O`, world
        pivot: Point2,
        /// arm length `L`
        arm_length: f64,
        /// roller radius
        roller_radius: f64,
        /// sense in which the spring turns the arm onto the cam
        closing: Sense,
        /// the arm angle is reported within ±180° of it, rad (any value finds the same contact)
        initial_angle: f64,
    },
}

impl Follower {
    /// The follower model of this kind with the cam axis at `cam_pivot`, validated: directions
    /// non-zero (normalised), lengths finite, radii and arm lengths positive. The one place
    /// that lists the kinds.
    pub(crate) fn model(&self, cam_pivot: Point2) -> Result<Model, CamError> {
        // scaled by its largest component first, so that a direction's length never matters:
        // [1e-300, 0] is the x axis and [1e300, 1e300] the diagonal (no underflow, no overflow)
        let unit = |d: Vec2| {
            let m = d.x.abs().max(d.y.abs());
            if d.x.is_finite() && d.y.is_finite() && m > 0.0 {
                let s = d / m;
                Ok(UnitVec2::new_normalize(s))
            } else {
                Err(CamError::InvalidVector {
                    field: Field::Follower(FollowerField::Direction),
                    x: d.x,
                    y: d.y,
                    reason: "must be a non-zero direction",
                })
            }
        };
        Ok(match self {
            Follower::Translating {
                direction,
                offset,
                profile,
            } => {
                let (d, e) = (
                    unit(*direction)?,
                    finite(Field::Follower(FollowerField::Offset), *offset)?,
                );
                match carried_point(profile)? {
                    Some(tip) => TranslatingKnife::carrying(cam_pivot, d, e, tip),
                    None => carried::CarriedJoint::translating(cam_pivot, d, e),
                }
            }
            Follower::Rotating {
                pivot,
                closing,
                initial_angle,
                profile,
            } => {
                let o = point(Field::Follower(FollowerField::Pivot), *pivot)?;
                let phi0 = arm_angle(Field::Follower(FollowerField::InitialAngle), *initial_angle)?;
                match carried_point(profile)? {
                    Some(tip) => OscillatingKnife::model(cam_pivot, o, tip, *closing, phi0)?,
                    None => carried::CarriedJoint::rotating(cam_pivot, o, *closing, phi0),
                }
            }
            &Follower::TranslatingFlat { direction } => {
                TranslatingFlat::model(cam_pivot, unit(direction)?)
            }
            &Follower::TranslatingRoller {
                direction,
                offset,
                roller_radius,
            } => {
                let d = unit(direction)?;
                TranslatingRoller::model(
                    cam_pivot,
                    d,
                    finite(Field::Follower(FollowerField::Offset), offset)?,
                    positive(Field::Follower(FollowerField::RollerRadius), roller_radius)?,
                )
            }
            &Follower::TranslatingKnife { direction, offset } => {
                let d = unit(direction)?;
                TranslatingKnife::model(
                    cam_pivot,
                    d,
                    finite(Field::Follower(FollowerField::Offset), offset)?,
                )
            }
            &Follower::OscillatingFlat {
                pivot,
                face_offset,
                closing,
                initial_angle,
            } => OscillatingFlat::model(
                cam_pivot,
                point(Field::Follower(FollowerField::Pivot), pivot)?,
                finite(Field::Follower(FollowerField::Offset), face_offset)?,
                closing,
                arm_angle(Field::Follower(FollowerField::InitialAngle), initial_angle)?,
            ),
            &Follower::OscillatingRoller {
                pivot,
                arm_length,
                roller_radius,
                closing,
                initial_angle,
            } => {
                let o = point(Field::Follower(FollowerField::Pivot), pivot)?;
                OscillatingRoller::model(
                    cam_pivot,
                    o,
                    positive(Field::Follower(FollowerField::ArmLength), arm_length)?,
                    positive(Field::Follower(FollowerField::RollerRadius), roller_radius)?,
                    closing,
                    arm_angle(Field::Follower(FollowerField::InitialAngle), initial_angle)?,
                )
            }
        })
    }

    /// The same follower described relative to a cam axis at `cam_pivot`: an arm's pivot moved
    /// by `−cam_pivot` (translating followers are already placed relative to the cam's axis).
    /// [`crate::cam::synthesis::synthesize`] takes its follower this way.
    pub fn relative_to(&self, cam_pivot: Point2) -> Follower {
        let mut f = self.clone();
        match &mut f {
            Follower::OscillatingFlat { pivot, .. }
            | Follower::OscillatingRoller { pivot, .. }
            | Follower::Rotating { pivot, .. } => {
                *pivot -= cam_pivot.coords;
            }
            _ => {}
        }
        f
    }

    /// Human-readable kind, as in mechanism files.
    pub fn kind_name(&self) -> &'static str {
        match self {
            Follower::Translating { .. } => "translating",
            Follower::Rotating { .. } => "rotating",
            Follower::TranslatingFlat { .. } => "translating-flat",
            Follower::TranslatingRoller { .. } => "translating-roller",
            Follower::TranslatingKnife { .. } => "translating-knife",
            Follower::OscillatingFlat { .. } => "oscillating-flat",
            Follower::OscillatingRoller { .. } => "oscillating-roller",
        }
    }

    /// True for oscillating followers (position in rad).
    pub fn is_oscillating(&self) -> bool {
        matches!(
            self,
            Follower::OscillatingFlat { .. }
                | Follower::OscillatingRoller { .. }
                | Follower::Rotating { .. }
        )
    }

    /// The curve a general follower carries (`None` for the five named kinds).
    pub fn carried_profile(&self) -> Option<&std::sync::Arc<dyn crate::curve::Curve>> {
        match self {
            Follower::Translating { profile, .. } | Follower::Rotating { profile, .. } => {
                Some(&profile.0)
            }
            _ => None,
        }
    }
}

/// The point a general follower carries when its curve is a point (a knife edge), checked
/// within [`LENGTH_RANGE`]; `None` for any other curve.
fn carried_point(profile: &FollowerProfile) -> Result<Option<Vec2>, CamError> {
    if !matches!(profile.0.domain(), crate::curve::Domain::Point) {
        return Ok(None);
    }
    let at = point(
        Field::FollowerProfile(crate::field::ProfileField::At),
        profile.0.position(0.0),
    )?;
    Ok(Some(at.coords))
}

use crate::valid::Rule;
pub use crate::valid::LENGTH_RANGE;

/// An offset or coordinate: finite and at most [`LENGTH_RANGE`]'s upper end in magnitude.
fn finite(field: Field, v: f64) -> Result<f64, CamError> {
    Rule::Bounded.check(v).map_err(|reason| CamError::Invalid {
        field,
        value: v,
        reason,
    })
}

/// A length: within [`LENGTH_RANGE`].
fn positive(field: Field, v: f64) -> Result<f64, CamError> {
    Rule::Size.check(v).map_err(|reason| CamError::Invalid {
        field,
        value: v,
        reason,
    })
}

/// An arm's initial angle, rad: within ±10 turns (the arm angle is reported within ±180° of
/// it, so a larger one would cost the reported angle its accuracy).
fn arm_angle(field: Field, v: f64) -> Result<f64, CamError> {
    Rule::ArmAngle.check(v).map_err(|reason| CamError::Invalid {
        field,
        value: v.to_degrees(),
        reason,
    })
}

fn point(field: Field, p: Point2) -> Result<Point2, CamError> {
    // the larger coordinate decides the words (a NaN beside 1e200 is "not finite")
    let worse = if p.x.is_finite() && p.y.is_finite() {
        p.x.abs().max(p.y.abs())
    } else {
        f64::NAN
    };
    Rule::Bounded
        .check(worse)
        .map(|_| p)
        .map_err(|reason| CamError::InvalidVector {
            field,
            x: p.x,
            y: p.y,
            reason,
        })
}

/// `(oriented score, φ)` of an arm angle `phi`: the score on the branch within ±180° of
/// `toward_cam` (the direction from the pivot to the cam's axis, so that the arm angles that
/// touch the cam form one interval, cut where the arm points away from the cam), the angle
/// reported within ±180° of `phi0`.
#[inline]
fn arm_branch(phi: f64, toward_cam: f64, phi0: f64, closing: f64) -> (f64, f64) {
    let on_branch = wrap_angle_near(phi, toward_cam);
    (-closing * on_branch, wrap_angle_near(phi, phi0))
}

/// The arm angle at which an oscillating follower rests on the base circle: of the roots of
/// `a cos φ + b sin φ = c` that `valid` accepts, the one the arm reaches first turning in its
/// closing sense (the larger oriented score on the branch about `toward_cam`), reported within
/// ±180° of `phi0`; `None` when there is none.
fn first_touch_root(
    [a, b, c]: [f64; 3],
    valid: impl Fn(f64) -> bool,
    toward_cam: f64,
    phi0: f64,
    closing: f64,
) -> Option<f64> {
    let r = a.hypot(b);
    let k = c / r;
    if !(r > 0.0 && (-1.0..=1.0).contains(&k)) {
        return None;
    }
    let (alpha, beta) = (b.atan2(a), k.acos());
    let best = [alpha + beta, alpha - beta]
        .into_iter()
        .filter(|&phi| valid(phi))
        .map(|phi| arm_branch(phi, toward_cam, phi0, closing))
        .fold(
            (f64::NEG_INFINITY, f64::NAN),
            |m, x| {
                if x.0 > m.0 {
                    x
                } else {
                    m
                }
            },
        );
    best.1.is_finite().then_some(best.1)
}

/// Relative rounding allowed for in [`Kind::score_interval`].
const ROUNDING: f64 = 1e-12;

/// The interval of the along-travel coordinate `(x − cam axis)·d` over the disc of radius `r` about
/// `c`: `(mid, half width)`.
fn along_interval(cam_pivot: Point2, d: Vec2, c: Point2, r: f64) -> (f64, f64) {
    let y = c - cam_pivot;
    (y.dot(&d), r + ROUNDING * (y.norm() + r))
}

/// The interval of the polar angle about `o` over the disc of radius `r` about `c`: `(mid, half
/// width)` (half a turn when the disc holds `o`).
fn polar_interval(o: Point2, c: Point2, r: f64) -> (f64, f64) {
    let y = c - o;
    let rho = y.norm();
    if rho <= r * (1.0 + ROUNDING) {
        return (0.0, std::f64::consts::PI);
    }
    (y.y.atan2(y.x), (r / rho).asin() + ROUNDING)
}

/// What every oscillating kind keeps of its arm: the pivot, the closing sense (and its sign), the
/// initial angle, and the arm angle at which the first touch's branch is centred.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Arm {
    /// the pivot `O`, world
    pub(crate) o: Point2,
    /// +1 when the load closes the arm counter-clockwise
    pub(crate) closing: f64,
    pub(crate) phi0: f64,
    /// the arm angle that points the follower's reference at the cam's axis: the direction from
    /// the pivot to the cam's axis less the reference's polar angle `lead` in the arm's frame, rad
    pub(crate) toward_cam: f64,
    pub(crate) sense: Sense,
}

impl Arm {
    fn new(cam_pivot: Point2, o: Point2, closing: Sense, phi0: f64, lead: f64) -> Self {
        Self {
            o,
            closing: closing.sign(),
            phi0,
            toward_cam: toward(cam_pivot, o) - lead,
            sense: closing,
        }
    }

    /// The arm's joint.
    fn joint(&self) -> FollowerJoint {
        FollowerJoint::arm(self.o, self.sense, self.phi0, self.toward_cam)
    }
}

/// The direction (rad) from an arm's pivot `o` to the cam's axis.
fn toward(cam_pivot: Point2, o: Point2) -> f64 {
    let d = cam_pivot - o;
    d.y.atan2(d.x)
}

/// A validated follower: its model, with the joint and the curve cached from it.
#[derive(Debug, Clone)]
pub(crate) struct Geometry {
    pub(crate) follower: Follower,
    /// cam axis (world)
    pub(crate) cam_pivot: Point2,
    pub(crate) model: Model,
    pub(crate) joint: FollowerJoint,
    pub(crate) curve: FollowerCurve,
    /// a general follower's curve with its polyline index
    pub(crate) carried: Option<std::sync::Arc<carried::Carried>>,
}

impl Geometry {
    /// `reach`: how far the cam reaches from its axis (bounds the sampled stretch of an
    /// unbounded carried curve).
    pub(crate) fn new(follower: Follower, cam_pivot: Point2, reach: f64) -> Result<Self, CamError> {
        let model = follower.model(cam_pivot)?;
        let joint = model.joint();
        // a carried point is a knife edge: its kind's closed forms, not a carried curve
        let carries = matches!(model, Model::Carried(_));
        let (curve, carried) = match follower.carried_profile().filter(|_| carries) {
            Some(profile) => {
                let far = (joint.origin() - cam_pivot).norm();
                let c = carried::Carried::new(profile.clone(), &joint, 4.0 * (reach + far))?;
                (
                    FollowerCurve::Carried(c.curve.clone()),
                    Some(std::sync::Arc::new(c)),
                )
            }
            None => (model.curve(), None),
        };
        Ok(Self {
            follower,
            cam_pivot,
            model,
            joint,
            curve,
            carried,
        })
    }

    /// Converts a change of `q` into a length, for tolerances.
    pub(crate) fn q_length_scale(&self, size: f64) -> f64 {
        self.joint.q_length_scale(size, self.cam_pivot)
    }

    pub(crate) fn is_knife(&self) -> bool {
        matches!(self.curve, FollowerCurve::Point(_))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The roots of `gap` on `[lo, lo + width]`: its sign changes over `n` equal steps, each
    /// refined by 80 bisections (the first-touch tests' reference, sharing no formula with a kind).
    pub(in crate::cam::follower) fn crossings(
        gap: impl Fn(f64) -> f64,
        lo: f64,
        width: f64,
        n: u32,
    ) -> Vec<f64> {
        let h = width / f64::from(n);
        (0..n)
            .filter_map(|j| {
                let (mut a0, mut a1) = (lo + f64::from(j) * h, lo + f64::from(j + 1) * h);
                if gap(a0).signum() == gap(a1).signum() {
                    return None;
                }
                for _ in 0..80 {
                    let m = 0.5 * (a0 + a1);
                    if gap(m).signum() == gap(a0).signum() {
                        a0 = m;
                    } else {
                        a1 = m;
                    }
                }
                Some(0.5 * (a0 + a1))
            })
            .collect()
    }

    fn direction_of(d: Vec2) -> Result<Vec2, CamError> {
        let m = Follower::TranslatingFlat { direction: d }.model(Point2::origin())?;
        Ok(*m.joint().direction().expect("a translating follower"))
    }

    #[test]
    fn direction_length_does_not_matter() {
        let h = std::f64::consts::FRAC_1_SQRT_2;
        for (d, expect) in [
            (Vec2::new(1e-300, 0.0), Vec2::new(1.0, 0.0)),
            (Vec2::new(5e-324, 0.0), Vec2::new(1.0, 0.0)),
            (Vec2::new(0.0, -1e-310), Vec2::new(0.0, -1.0)),
            (Vec2::new(1e300, 1e300), Vec2::new(h, h)),
            (Vec2::new(-f64::MAX, f64::MAX), Vec2::new(-h, h)),
            (Vec2::new(3.0, 4.0), Vec2::new(0.6, 0.8)),
        ] {
            let got = direction_of(d).expect("a valid direction");
            assert!((got - expect).norm() < 1e-15, "{d:?} gave {got:?}");
        }
        for d in [
            Vec2::zeros(),
            Vec2::new(f64::INFINITY, 0.0),
            Vec2::new(f64::NAN, 1.0),
        ] {
            assert!(
                matches!(direction_of(d), Err(CamError::InvalidVector { .. })),
                "{d:?} accepted"
            );
        }
    }
}
