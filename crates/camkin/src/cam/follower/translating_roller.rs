//! Translating roller: the roller centre at `e·rot90(d) + s·d` from the cam axis; its curve is the
//! circle of radius `r` about the frame origin.

use super::envelope::{rotated_derivs, translating_path, Envelope};
use super::rates::{finite, roller_denominator, CamPoint, Refusals};
use super::{FollowerJoint, Kind, Model, Rates, Synthesis};
use crate::body::WorldDerivs;
use crate::cam::pose::Pose;
use crate::cam::CamError;
use crate::curve::Circle;
use crate::field::{Field, FollowerField};
use crate::geometry::{rot90, Point2, Rotation, UnitVec2, Vec2};
use crate::human::human;
use crate::jet::{Num, V2};

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
    fn joint(&self) -> FollowerJoint {
        // `d` came in as a `UnitVec2` (`model`)
        FollowerJoint::slide(
            self.cam_pivot + self.e * self.p,
            UnitVec2::new_unchecked(self.d),
        )
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
    /// The roller's boundary passes through `x` at the positions `y·d ± √(r² − l²)` (see
    /// [`Kind::score`]); the first is the larger, where the roller's centre lies beyond `x`
    /// along the travel: `q − y·d ≥ 0`, where the later one has `−√(r² − l²)`. Within half the
    /// slack where the two merge (they are `2√(r² − l²)` apart). No square root.
    #[inline(always)]
    fn is_first_through(&self, x: Point2, q: &Pose, slack: f64) -> bool {
        q.q - (x - self.cam_pivot).dot(&self.d) >= -0.5 * slack
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
                lead: 0.0,
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
    fn jacobian(&self, e: &WorldDerivs, q: &Pose) -> [[f64; 2]; 2] {
        let q = q.q;
        let (d, p) = (self.d, self.p);
        let y = e.p - self.cam_pivot;
        let m = y - (self.e * p + q * d);
        [
            [e.d1.dot(&m), -d.dot(&m)],
            [e.d2.dot(&m) + e.d1.norm_squared(), -e.d1.dot(&d)],
        ]
    }
    #[inline]
    fn toward_follower(&self, c: Point2, q: &Pose) -> Vec2 {
        (self.cam_pivot + self.e * self.p + q.q * self.d) - c
    }
    fn check_reach(&self, size: f64) -> Result<(), CamError> {
        let (e, r) = (self.e, self.r);
        if e.abs() >= size + r {
            return Err(CamError::Unreachable {
                field: Field::Follower(FollowerField::Offset),
                value: e,
                reason: format!(
                    "the roller (radius {}) passes the cam, which reaches {} from its axis",
                    human(r),
                    human(size)
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
}

impl Rates for TranslatingRoller {
    /// `½(|m|² − r²) = 0` and `x'·m = 0` with `m = y − e p − q d` (from the roller's centre):
    /// `q̇ = m·(ω J y) / m·d`; `u̇ (x''·m + |x'|²) = −(ω (J x')·m + x'·ω J y − q̇ x'·d)`; and
    /// `q̈ = (m·b + |ṁ|²) / m·d` with `ṁ = ω J y + u̇ x' − q̇ d`. Declined where the normal is
    /// perpendicular to the travel (locked) or the cam's curvature matches the roller's.
    #[inline(always)]
    fn rates(&self, c: &CamPoint, q: &Pose, refuse: &Refusals) -> Option<[f64; 3]> {
        let q = q.q;
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
}

impl Synthesis for TranslatingRoller {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The cheap first-touch test against the score's (the default of [`Kind::is_first_through`])
    /// at both positions where the roller's boundary passes through a point, found
    /// independently: sign changes of `|x − C(q)|² − r²` along the travel, refined by bisection.
    #[test]
    fn first_through_agrees_with_the_score_at_both_crossings() {
        let (mut checked, mut first) = (0, 0);
        for (dir, e, r) in [
            (Vec2::new(0.0, 1.0), 0.5, 1.0),
            (Vec2::new(0.6, -0.8), -0.2, 0.3),
            (Vec2::new(1.0, 0.0), 0.0, 0.01),
        ] {
            let d = UnitVec2::new_normalize(dir);
            let Model::TranslatingRoller(k) =
                TranslatingRoller::model(Point2::new(1.0, 2.0), d, e, r)
            else {
                unreachable!()
            };
            let slack = 1e-12;
            let centre = |q: f64| k.cam_pivot + e * k.p + q * k.d;
            let gap = |x: Point2, q: f64| (x - centre(q)).norm_squared() - r * r;
            for i in 0..40 {
                // points the roller reaches beside its path
                let (along, side) = (
                    3.0 * (f64::from(i) * 0.37).sin(),
                    0.95 * r * (f64::from(i) * 1.3).cos(),
                );
                let x = k.cam_pivot + (e + side) * k.p + along * k.d;
                for q in
                    super::super::tests::crossings(|q| gap(x, q), along - 2.0 * r, 4.0 * r, 20_000)
                {
                    let by_score =
                        matches!(k.score(x), Some((_, qs)) if (qs - q).abs() <= 1e-9 * r);
                    let cheap = k.is_first_through(x, &k.pose(q), slack);
                    assert_eq!(cheap, by_score, "{dir:?}, e {e}, r {r}: x {x:?} at q {q}");
                    checked += 1;
                    first += usize::from(cheap);
                }
            }
        }
        // two crossings of each of the 120 points, one of them the first
        assert_eq!((checked, first), (240, 120));
    }
}
