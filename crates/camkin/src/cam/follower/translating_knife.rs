//! Translating knife edge: the tip at `e·rot90(d) + s·d` from the cam axis; its curve is the point
//! at the frame origin. A point carried by a general translating follower is this kind with the
//! point off the frame origin: the tip at `a·d + b·rot90(d)` in the frame, so that the frame's
//! coordinate is `q = s − a` on the line of travel of offset `e + b`.

use super::envelope::{rotated_derivs, translating_path, Envelope};
use super::rates::{finite, CamPoint, Refusals};
use super::{FollowerJoint, Kind, Model, Rates, Synthesis};
use crate::body::WorldDerivs;
use crate::cam::pose::Pose;
use crate::cam::CamError;
use crate::curve::PointCurve;
use crate::field::{Field, FollowerField};
use crate::geometry::{rot90, Point2, Rotation, UnitVec2, Vec2};
use crate::human::human;
use crate::jet::{Num, V2};

#[derive(Debug, Clone, Copy)]
pub(crate) struct TranslatingKnife {
    pub(super) cam_pivot: Point2,
    pub(super) d: Vec2,
    pub(super) p: Vec2,
    /// the frame origin's line of travel's offset
    pub(super) e: f64,
    /// the tip in the (world-aligned) follower frame: `(0, 0)` for the named kind
    pub(super) tip: Vec2,
    /// the tip's line of travel's offset `e + tip·p`, and its lead `a = tip·d` on the frame
    pub(super) tip_e: f64,
    pub(super) tip_a: f64,
}

impl TranslatingKnife {
    pub(super) fn model(cam_pivot: Point2, d: UnitVec2, e: f64) -> Model {
        Self::carrying(cam_pivot, d, e, Vec2::zeros())
    }
    /// A general translating follower carrying a point at `tip` in its frame (given along the
    /// direction of travel: `tip.x` along `d`, `tip.y` along `rot90(d)`).
    pub(super) fn carrying(cam_pivot: Point2, d: UnitVec2, e: f64, tip: Vec2) -> Model {
        let (d, p) = (d.into_inner(), rot90(d.into_inner()));
        let tip = tip.x * d + tip.y * p;
        Model::TranslatingKnife(Self {
            cam_pivot,
            d,
            p,
            e,
            tip,
            tip_e: e + tip.dot(&p),
            tip_a: tip.dot(&d),
        })
    }
}

impl Kind for TranslatingKnife {
    fn joint(&self) -> FollowerJoint {
        // `d` came in as a `UnitVec2` (`model`)
        FollowerJoint::slide(
            self.cam_pivot + self.e * self.p,
            UnitVec2::new_unchecked(self.d),
        )
    }
    fn curve(&self) -> super::FollowerCurve {
        super::FollowerCurve::Point(PointCurve::new(Point2::from(self.tip)).expect("finite"))
    }
    #[inline]
    fn score(&self, x: Point2) -> Option<(f64, f64)> {
        let q = (x - self.cam_pivot).dot(&self.d) - self.tip_a;
        Some((q, q))
    }
    fn score_interval(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        let (mid, half) = super::along_interval(self.cam_pivot, self.d, c, r);
        Some((mid - self.tip_a, half))
    }
    fn stationary_tangents(&self, _c: Point2, _r: f64) -> Option<(f64, f64)> {
        // the face's direction
        Some((self.p.y.atan2(self.p.x), super::ROUNDING))
    }
    #[inline]
    fn residual_value<T: Num>(&self, x: V2<T>, _x1: V2<T>, q: T) -> [T; 2] {
        let y = x - V2::c(self.cam_pivot.coords);
        let (d, p) = (V2::c(self.d), V2::c(self.p));
        // y·p = e + b, y·d = q + a
        [y.dot(p) - T::c(self.tip_e), y.dot(d) - T::c(self.tip_a) - q]
    }
    #[inline]
    fn jacobian(&self, e: &WorldDerivs, _q: &Pose) -> [[f64; 2]; 2] {
        [[e.d1.dot(&self.p), 0.0], [e.d1.dot(&self.d), -1.0]]
    }
    #[inline]
    fn toward_follower(&self, _c: Point2, _q: &Pose) -> Vec2 {
        self.d
    }
    fn centre_path(&self) -> Option<(super::CentrePath, f64)> {
        Some((
            super::CentrePath::Line {
                d: self.d,
                p: self.p,
                e: self.tip_e,
                lead: self.tip_a,
            },
            0.0,
        ))
    }
    fn check_reach(&self, size: f64) -> Result<(), CamError> {
        if self.tip_e.abs() >= size {
            return Err(CamError::Unreachable {
                field: Field::Follower(FollowerField::Offset),
                value: self.e,
                reason: if self.tip == Vec2::zeros() {
                    format!(
                        "the knife edge's line of travel misses the cam, which reaches {} from its axis",
                        human(size)
                    )
                } else {
                    format!(
                        "the point's line of travel, {} from the cam axis, misses the cam, which reaches {}",
                        human(self.tip_e.abs()),
                        human(size)
                    )
                },
            });
        }
        Ok(())
    }
    fn concave_limit(&self) -> Option<f64> {
        None
    }
}

impl Rates for TranslatingKnife {
    /// `y·p = e + b`, `y·d = q + a`: the contact point's velocity `ẏ = ω J y + u̇ x'` is along `d`, so
    /// `u̇ = −ω (J y)·p / x'·p`, `q̇ = ẏ·d`; its acceleration `b + ü x'` too, so
    /// `ü = −b·p / x'·p` and `q̈ = b·d + ü x'·d`. Declined where the profile runs along the
    /// line of travel (`x'·p ≈ 0`: the tip is locked).
    #[inline(always)]
    fn rates(&self, c: &CamPoint, _q: &Pose, refuse: &Refusals) -> Option<[f64; 3]> {
        let (d, p) = (self.d, self.p);
        let x1p = c.x1.dot(&p);
        if !(x1p.abs() > refuse.lock * c.x1.norm()) {
            return None;
        }
        let v0 = c.material_velocity();
        let ud = -v0.dot(&p) / x1p;
        let b = c.acceleration_but_tangential(ud);
        let udd = -b.dot(&p) / x1p;
        finite([(v0 + ud * c.x1).dot(&d), b.dot(&d) + udd * c.x1.dot(&d), ud])
    }
}

impl Synthesis for TranslatingKnife {
    fn synthesis_start(&self, base_radius: f64) -> Result<f64, CamError> {
        let e = self.tip_e;
        if e.abs() >= base_radius {
            return Err(CamError::Invalid {
                field: Field::Follower(FollowerField::Offset),
                value: self.e,
                reason: if self.tip == Vec2::zeros() {
                    "must be smaller than the base radius"
                } else {
                    "with the point's lateral place, must be smaller than the base radius"
                },
            });
        }
        Ok((base_radius * base_radius - e * e).sqrt() - self.tip_a)
    }
    fn envelope(&self, s: &[f64; 5], _s0: f64, _u: f64, sigma: f64, rot: &Rotation) -> Envelope {
        // the tip's path y = A ((e + b) p + (s + a) d)
        let mut s = *s;
        s[0] += self.tip_a;
        let y = rotated_derivs(
            sigma,
            rot,
            &translating_path(self.d, self.p, self.tip_e, &s),
        );
        Envelope::traced(&y)
    }
}
