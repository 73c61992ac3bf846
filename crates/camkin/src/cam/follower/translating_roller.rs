//! Translating roller: the roller centre at `e·rot90(d) + s·d` from the cam axis; its curve is the
//! circle of radius `r` about the frame origin.

use super::rates::{finite, roller_denominator, CamPoint, Refusals};
use super::{Joint, Kind, Model};
use crate::body::WorldDerivs;
use crate::cam::jet::{Num, V2};
use crate::cam::synthesis::{rotated_derivs, translating_path, Envelope};
use crate::cam::CamError;
use crate::curve::Circle;
use crate::field::{Field, FollowerField};
use crate::geometry::{rot90, Point2, Rotation, UnitVec2, Vec2};

#[derive(Debug, Clone, Copy)]
pub(crate) struct TranslatingRoller {
    pub(super) cam_pivot: Point2,
    pub(super) d: Vec2,
    pub(super) p: Vec2,
    pub(super) e: f64,
    pub(super) r: f64,
}

impl TranslatingRoller {
    pub(super) fn model(cam_pivot: Point2, d: UnitVec2, e: f64, r: f64) -> Model {
        Model::TranslatingRoller(Self {
            cam_pivot,
            d: d.into_inner(),
            p: rot90(d.into_inner()),
            e,
            r,
        })
    }
}

impl Kind for TranslatingRoller {
    fn joint(&self) -> Joint {
        Joint::Translating {
            origin: self.cam_pivot + self.e * self.p,
            // `d` came in as a `UnitVec2` (`model`)
            direction: UnitVec2::new_unchecked(self.d),
        }
    }
    fn curve(&self) -> super::FollowerCurve {
        super::FollowerCurve::Circle(
            Circle::new(Point2::origin(), self.r).expect("validated radius"),
        )
    }
    #[inline]
    fn score(&self, x: Point2) -> Option<(f64, f64)> {
        let y = x - self.cam_pivot;
        let l = y.dot(&self.p) - self.e;
        let s2 = self.r * self.r - l * l;
        if s2 < 0.0 {
            None
        } else {
            let q = y.dot(&self.d) + s2.sqrt();
            Some((q, q))
        }
    }
    fn score_interval(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        // q = along + √(R² − l²) over the disc: along ∈ along(c) ± r, and |l| at least the
        // lateral offset of the disc's nearest point
        let (along, half) = super::along_interval(self.cam_pivot, self.d, c, r);
        let l = (c - self.cam_pivot).dot(&self.p) - self.e;
        let near = (l.abs() - half).max(0.0);
        if near > self.r {
            return None;
        }
        let rise = (self.r - near).sqrt() * (self.r + near).sqrt();
        Some((
            along + 0.5 * rise,
            half + 0.5 * rise + super::ROUNDING * self.r,
        ))
    }
    fn stationary_tangents(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        // the roller's tangent at the point x it first touches: normal to x − C =
        // l p − √(R² − l²) d, at the angle π − asin(l/R) from d, for the lateral offsets l of
        // the disc (all within the roller's reach)
        let l = (c - self.cam_pivot).dot(&self.p) - self.e;
        let (l0, l1) = (l - r, l + r);
        if !(l0 > -self.r && l1 < self.r) {
            return None;
        }
        let (a0, a1) = ((l0 / self.r).asin(), (l1 / self.r).asin());
        Some((
            self.d.y.atan2(self.d.x) + std::f64::consts::FRAC_PI_2 - 0.5 * (a0 + a1),
            0.5 * (a1 - a0) + super::ROUNDING,
        ))
    }
    fn centre_path(&self) -> Option<(super::CentrePath, f64)> {
        Some((
            super::CentrePath::Line {
                d: self.d,
                p: self.p,
                e: self.e,
            },
            self.r,
        ))
    }
    #[inline]
    fn residual_value<T: Num>(&self, x: V2<T>, x1: V2<T>, q: T) -> [T; 2] {
        let y = x - V2::c(self.cam_pivot.coords);
        let (d, p) = (V2::c(self.d), V2::c(self.p));
        let m = y - (p.scale(T::c(self.e)) + d.scale(q));
        [T::c(0.5) * (m.dot(m) - T::c(self.r * self.r)), x1.dot(m)]
    }
    #[inline]
    fn jacobian(&self, e: &WorldDerivs, q: f64) -> [[f64; 2]; 2] {
        let (d, p) = (self.d, self.p);
        let y = e.p - self.cam_pivot;
        let m = y - (self.e * p + q * d);
        [
            [e.d1.dot(&m), -d.dot(&m)],
            [e.d2.dot(&m) + e.d1.norm_squared(), -e.d1.dot(&d)],
        ]
    }
    /// `½(|m|² − r²) = 0` and `x'·m = 0` with `m = y − e p − q d` (from the roller's centre):
    /// `q̇ = m·(ω J y) / m·d`; `u̇ (x''·m + |x'|²) = −(ω (J x')·m + x'·ω J y − q̇ x'·d)`; and
    /// `q̈ = (m·b + |ṁ|²) / m·d` with `ṁ = ω J y + u̇ x' − q̇ d`. Declined where the normal is
    /// perpendicular to the travel (locked) or the cam's curvature matches the roller's.
    #[inline(always)]
    fn rates(&self, c: &CamPoint, q: f64, refuse: &Refusals) -> Option<[f64; 3]> {
        let (d, p) = (self.d, self.p);
        let m = c.y - (self.e * p + q * d);
        let md = m.dot(&d);
        if !(md.abs() > refuse.lock * self.r) {
            return None;
        }
        let den = roller_denominator(c, m, refuse)?;
        let v0 = c.material_velocity();
        let qd = m.dot(&v0) / md;
        let ud = -(c.w * rot90(c.x1).dot(&m) + c.x1.dot(&v0) - qd * c.x1.dot(&d)) / den;
        let mdot = v0 + ud * c.x1 - qd * d;
        let b = c.acceleration_but_tangential(ud);
        finite([qd, (m.dot(&b) + mdot.norm_squared()) / md, ud])
    }
    #[inline]
    fn toward_follower(&self, c: Point2, q: f64) -> Vec2 {
        (self.cam_pivot + self.e * self.p + q * self.d) - c
    }
    fn check_reach(&self, size: f64) -> Result<(), CamError> {
        let (e, r) = (self.e, self.r);
        if e.abs() >= size + r {
            return Err(CamError::Unreachable {
                field: Field::Follower(FollowerField::Offset),
                value: e,
                reason: format!(
                    "the roller (radius {r}) passes the cam, which reaches {size} from its axis"
                ),
            });
        }
        Ok(())
    }
    fn concave_limit(&self) -> Option<f64> {
        Some(-1.0 / self.r)
    }
    fn roller_radius(&self) -> Option<f64> {
        Some(self.r)
    }
    fn synthesis_start(&self, base_radius: f64) -> Result<f64, CamError> {
        let prime = base_radius + self.r;
        if self.e.abs() >= prime {
            return Err(CamError::Invalid {
                field: Field::Follower(FollowerField::Offset),
                value: self.e,
                reason: "must be smaller than the prime circle's radius",
            });
        }
        Ok((prime * prime - self.e * self.e).sqrt())
    }
    fn envelope(&self, s: &[f64; 5], _s0: f64, _u: f64, sigma: f64, rot: &Rotation) -> Envelope {
        // the roller centre's path c = A (e p + s d), offset by the radius towards the cam
        let c = rotated_derivs(sigma, rot, &translating_path(self.d, self.p, self.e, s));
        Envelope::Offset(c, self.r)
    }
}
