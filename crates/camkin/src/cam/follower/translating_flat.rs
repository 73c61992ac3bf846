//! Translating flat-faced follower: the face is the line `x·d = s` (positions from the cam axis).
//! Its curve is the line through the frame origin along `−rot90(d)` (material on the left: the
//! follower lies on the `+d` side of its face).

use super::envelope::{rotated_derivs, Envelope};
use super::rates::{finite, CamPoint, Refusals};
use super::{FollowerJoint, Kind, Model, Rates, Synthesis};
use crate::body::WorldDerivs;
use crate::cam::pose::Pose;
use crate::cam::CamError;
use crate::curve::Line;
use crate::geometry::{rot90, Point2, Rotation, UnitVec2, Vec2};
use crate::jet::{Num, V2};

#[derive(Debug, Clone, Copy)]
pub(crate) struct TranslatingFlat {
    pub(super) cam_pivot: Point2,
    pub(super) d: Vec2,
    pub(super) p: Vec2,
}

impl TranslatingFlat {
    pub(super) fn model(cam_pivot: Point2, d: UnitVec2) -> Model {
        Model::TranslatingFlat(Self {
            cam_pivot,
            d: d.into_inner(),
            p: rot90(d.into_inner()),
        })
    }
}

impl Kind for TranslatingFlat {
    fn joint(&self) -> FollowerJoint {
        // `d` came in as a `UnitVec2` (`model`)
        FollowerJoint::slide(self.cam_pivot, UnitVec2::new_unchecked(self.d))
    }
    fn curve(&self) -> super::FollowerCurve {
        super::FollowerCurve::Line(Line::new(Point2::origin(), -self.p).expect("unit vector"))
    }
    #[inline]
    fn score(&self, x: Point2) -> Option<(f64, f64)> {
        let q = (x - self.cam_pivot).dot(&self.d);
        Some((q, q))
    }
    fn score_interval(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        Some(super::along_interval(self.cam_pivot, self.d, c, r))
    }
    fn stationary_tangents(&self, _c: Point2, _r: f64) -> Option<(f64, f64)> {
        // the face's direction
        Some((self.p.y.atan2(self.p.x), super::ROUNDING))
    }
    #[inline]
    fn residual_value<T: Num>(&self, x: V2<T>, x1: V2<T>, q: T) -> [T; 2] {
        let y = x - V2::c(self.cam_pivot.coords);
        let d = V2::c(self.d);
        [y.dot(d) - q, x1.dot(d)] // y·d = q, y'·d = 0
    }
    #[inline]
    fn jacobian(&self, e: &WorldDerivs, _q: &Pose) -> [[f64; 2]; 2] {
        [[e.d1.dot(&self.d), -1.0], [e.d2.dot(&self.d), 0.0]]
    }
    /// `J = [[x'·d, −1], [x''·d, 0]]`: `δu = −x'·d / x''·d`, then `δq = (y·d − q) + x'·d δu`.
    #[inline(always)]
    fn newton_step(&self, e: &WorldDerivs, q: &Pose) -> [f64; 2] {
        let d = self.d;
        let x1d = e.d1.dot(&d);
        let du = -x1d / e.d2.dot(&d);
        [du, ((e.p - self.cam_pivot).dot(&d) - q.q) + x1d * du]
    }
    #[inline]
    fn toward_follower(&self, _c: Point2, _q: &Pose) -> Vec2 {
        self.d
    }
    fn concave_limit(&self) -> Option<f64> {
        Some(0.0)
    }
}

impl Rates for TranslatingFlat {
    /// `q = y·d` and `x'·d = 0`: `q̇ = ω (J y)·d`, `u̇ = −ω (J x')·d / x''·d` and
    /// `q̈ = α (J y)·d − ω² y·d + ω u̇ (J x')·d`. A cam straight at the contact (`x''·d = 0`)
    /// is conformal with the face: declined.
    #[inline(always)]
    fn rates(&self, c: &CamPoint, _q: &Pose, _refuse: &Refusals) -> Option<[f64; 3]> {
        let d = self.d;
        let (w, jy, jx1) = (c.w, rot90(c.y).dot(&d), rot90(c.x1).dot(&d));
        let ud = -w * jx1 / c.x2.dot(&d);
        finite([w * jy, c.a * jy - w * w * c.y.dot(&d) + w * ud * jx1, ud])
    }
}

impl Synthesis for TranslatingFlat {
    fn synthesis_start(&self, base_radius: f64) -> Result<f64, CamError> {
        Ok(base_radius)
    }
    fn envelope(&self, s: &[f64; 5], _s0: f64, _u: f64, sigma: f64, rot: &Rotation) -> Envelope {
        // the envelope of the face lines y·A d = s: y = A (s d − σ s' p)
        let (d, p, sg) = (self.d, self.p, sigma);
        let w = [
            s[0] * d - sg * s[1] * p,
            s[1] * d - sg * s[2] * p,
            s[2] * d - sg * s[3] * p,
            s[3] * d - sg * s[4] * p,
            Vec2::zeros(), // not needed: y''' uses w up to w'''
        ];
        let y = rotated_derivs(sigma, rot, &w);
        Envelope::traced(&y)
    }
}
