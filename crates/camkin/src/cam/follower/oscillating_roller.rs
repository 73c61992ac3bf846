//! Oscillating roller: the roller centre at `O + L (cos φ, sin φ)`; its curve is the circle of
//! radius `r` about `(L, 0)` in the arm frame.

use super::envelope::{arm_path, rotated_derivs, Envelope};
use super::rates::{finite, roller_denominator, CamPoint, Refusals};
use super::{
    arm_branch, first_touch_root, Arm, FollowerJoint, Kind, Model, Rates, Sense, Synthesis,
};
use crate::body::WorldDerivs;
use crate::cam::pose::Pose;
use crate::cam::CamError;
use crate::curve::Circle;
use crate::field::{Field, FollowerField};
use crate::geometry::{rot90, Point2, Rotation, Vec2};
use crate::human::human;
use crate::jet::{Num, V2};

#[derive(Debug, Clone, Copy)]
pub(crate) struct OscillatingRoller {
    pub(super) cam_pivot: Point2,
    pub(super) arm: Arm,
    pub(super) l: f64,
    pub(super) r: f64,
}

impl OscillatingRoller {
    pub(super) fn model(
        cam_pivot: Point2,
        o: Point2,
        l: f64,
        r: f64,
        closing: Sense,
        phi0: f64,
    ) -> Model {
        Model::OscillatingRoller(Self {
            cam_pivot,
            arm: Arm::new(cam_pivot, o, closing, phi0, 0.0),
            l,
            r,
        })
    }
}

impl OscillatingRoller {
    /// The tangency residual with the arm angle given by its sine and cosine `(s, c)`.
    #[inline(always)]
    fn residual_sc<T: Num>(&self, x: V2<T>, x1: V2<T>, (s, c): (T, T)) -> [T; 2] {
        let y = x - V2::c(self.arm.o.coords);
        let m = y - V2::new(c, s).scale(T::c(self.l));
        [T::c(0.5) * (m.dot(m) - T::c(self.r * self.r)), x1.dot(m)]
    }
}

impl Kind for OscillatingRoller {
    fn joint(&self) -> FollowerJoint {
        self.arm.joint()
    }
    fn curve(&self) -> super::FollowerCurve {
        super::FollowerCurve::Circle(
            Circle::new(Point2::new(self.l, 0.0), self.r).expect("validated radius"),
        )
    }
    #[inline]
    fn score(&self, x: Point2) -> Option<(f64, f64)> {
        let y = x - self.arm.o;
        let rho = y.norm();
        let psi = y.y.atan2(y.x);
        let (l, r) = (self.l, self.r);
        if rho == 0.0 {
            return None;
        }
        // the angle β at the pivot between x and the roller's centre (triangle ρ, L, r) by the
        // half-angle formula, tan²(β/2) = (r − d)(r + d) / ((ρ + L − r)(ρ + L + r)), d = ρ − L:
        // accurate for a small roller, where the law of cosines' acos near 1 loses half the digits
        let d = rho - l;
        let num = (r - d) * (r + d);
        let den = (rho + l - r) * (rho + l + r);
        if !(num >= 0.0 && den > 0.0) {
            return None;
        }
        let beta = 2.0 * (num / den).sqrt().atan();
        // cw closing (arm comes down): largest φ whose roller holds x
        Some(arm_branch(
            psi - self.arm.closing * beta,
            self.arm.toward_cam,
            self.arm.phi0,
            self.arm.closing,
        ))
    }
    /// At a tangency the roller's boundary passes through `x` at the arm angles `ψ ∓ closing·β`
    /// (`ψ` the polar angle of `x` about the pivot, `β ∈ [0, π]` the angle at the pivot between
    /// `x` and the roller's centre: see [`Kind::score`]); the first, `ψ − closing·β`, has `x`
    /// ahead of the arm in the closing sense: `closing·(arm × (x − o)) = ρ sin β ≥ 0`, where
    /// the later one has `−ρ sin β`. Within `slack` where the two merge (`β → 0`), and on the
    /// reported branch (within ±180° of the initial angle). No `atan2` and no wrapping.
    #[inline(always)]
    fn is_first_through(&self, x: Point2, q: &Pose, slack: f64) -> bool {
        let y = x - self.arm.o;
        let (s, c) = (q.sin, q.cos);
        let (ahead, rho) = (self.arm.closing * (c * y.y - s * y.x), y.norm());
        rho > 0.0
            && ahead >= -slack * rho
            && (q.q - self.arm.phi0).abs() <= std::f64::consts::PI + slack
    }
    fn centre_path(&self) -> Option<(super::CentrePath, f64)> {
        Some((
            super::CentrePath::Circle {
                o: self.arm.o,
                l: self.l,
                lead: 0.0,
            },
            self.r,
        ))
    }
    fn score_interval(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        // φ = ψ − closing·β: ψ within the disc's polar interval, β (the angle at the pivot
        // between the point and the roller's centre) over the ρ the roller reaches
        // (|ρ − L| ≤ R) within ρ(c) ± r: β(ρ) rises to its peak at √(L² − R²) and falls, so
        // its least value is at an end and its greatest at the ρ nearest the peak
        let (psi, dpsi) = super::polar_interval(self.arm.o, c, r);
        let (l, rr) = (self.l, self.r);
        let rho = (c - self.arm.o).norm();
        let (lo, hi) = ((rho - r).max(l - rr), (rho + r).min(l + rr));
        if lo > hi {
            return None;
        }
        if l <= rr {
            return Some((psi, std::f64::consts::PI));
        }
        let beta = |x: f64| {
            let d = x - l;
            2.0 * ((rr - d) * (rr + d) / ((x + l - rr) * (x + l + rr)))
                .max(0.0)
                .sqrt()
                .atan()
        };
        let top = beta((l * l - rr * rr).sqrt().clamp(lo, hi));
        let least = beta(lo).min(beta(hi));
        Some((
            psi - self.arm.closing * 0.5 * (top + least),
            dpsi + 0.5 * (top - least) + super::ROUNDING,
        ))
    }
    fn stationary_tangents(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        // the roller's tangent at the point it first touches: normal to x − C, C the roller's
        // centre, found at the disc's centre; over the disc x moves by r and C by L·Δφ
        let rho = (c - self.arm.o).norm();
        if !(rho - r > self.l - self.r && rho + r < self.l + self.r) {
            return None;
        }
        let (_, half) = self.score_interval(c, r)?;
        let (_, phi) = self.score(c)?;
        let centre = self.arm.o + self.l * Vec2::new(phi.cos(), phi.sin());
        let n = c - centre;
        let spread = (r + 2.0 * self.l * half) / self.r;
        (spread < 0.5).then(|| {
            (
                n.y.atan2(n.x) + std::f64::consts::FRAC_PI_2,
                spread.asin() + super::ROUNDING,
            )
        })
    }
    const ANGULAR: bool = true;
    #[inline]
    fn residual_value<T: Num>(&self, x: V2<T>, x1: V2<T>, q: T) -> [T; 2] {
        self.residual_sc(x, x1, q.sin_cos())
    }
    #[inline(always)]
    fn residual(&self, e: &WorldDerivs, q: &Pose) -> [f64; 2] {
        self.residual_sc(V2::c(e.p.coords), V2::c(e.d1), (q.sin, q.cos))
    }
    #[inline]
    fn jacobian(&self, e: &WorldDerivs, q: &Pose) -> [[f64; 2]; 2] {
        let (s, c) = (q.sin, q.cos);
        let u = Vec2::new(c, s);
        let n = Vec2::new(-s, c);
        let y = e.p - self.arm.o;
        let l = self.l;
        let m = y - l * u;
        let dm_dq = -l * n;
        [
            [e.d1.dot(&m), m.dot(&dm_dq)],
            [e.d2.dot(&m) + e.d1.norm_squared(), e.d1.dot(&dm_dq)],
        ]
    }
    #[inline]
    fn toward_follower(&self, c: Point2, q: &Pose) -> Vec2 {
        let (s, co) = (q.sin, q.cos);
        (self.arm.o + self.l * Vec2::new(co, s)) - c
    }
    fn check_reach(&self, size: f64) -> Result<(), CamError> {
        let (l, r) = (self.l, self.r);
        let d = (self.arm.o - self.cam_pivot).norm();
        if (d - l).abs() >= size + r {
            return Err(CamError::Unreachable {
                field: Field::Follower(FollowerField::ArmLength),
                value: l,
                reason: format!(
                    "the roller cannot reach the cam: its centre stays {} from the cam axis, the cam reaches {} and the roller radius is {}",
                    human((d - l).abs()),
                    human(size),
                    human(r)
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

impl Rates for OscillatingRoller {
    /// `½(|m|² − r²) = 0` and `x'·m = 0` with `m = x − O − L t`, `t = (cos φ, sin φ)`, `n = J t`:
    /// `φ̇ = m·(ω J y) / L m·n`; `u̇ (x''·m + |x'|²) = −(ω (J x')·m + x'·ω J y − L φ̇ x'·n)`; and
    /// `φ̈ = (m·b + L φ̇² m·t + |ṁ|²) / L m·n` with `ṁ = ω J y + u̇ x' − L φ̇ n`. Declined where
    /// the normal passes through the pivot (locked) or the cam's curvature matches the roller's.
    #[inline(always)]
    fn rates(&self, c: &CamPoint, q: &Pose, refuse: &Refusals) -> Option<[f64; 3]> {
        let (s, co) = (q.sin, q.cos);
        let (t, n) = (Vec2::new(co, s), Vec2::new(-s, co));
        let l = self.l;
        let m = (c.x - self.arm.o) - l * t;
        // L m·n = m·J(x − O): the paper's lock test, squared
        let lmn = l * m.dot(&n);
        let reach = refuse.lock * self.r;
        if !(lmn * lmn > reach * reach * (c.x - self.arm.o).norm_squared()) {
            return None;
        }
        let den = roller_denominator(c, m, refuse)?;
        let v0 = c.material_velocity();
        let qd = m.dot(&v0) / lmn;
        let ud = -(c.w * rot90(c.x1).dot(&m) + c.x1.dot(&v0) - l * qd * c.x1.dot(&n)) / den;
        let mdot = v0 + ud * c.x1 - (l * qd) * n;
        let b = c.acceleration_but_tangential(ud);
        let qdd = (m.dot(&b) + l * qd * qd * m.dot(&t) + mdot.norm_squared()) / lmn;
        finite([qd, qdd, ud])
    }
}

impl Synthesis for OscillatingRoller {
    fn synthesis_start(&self, base_radius: f64) -> Result<f64, CamError> {
        // the pivot from the cam's axis (the profile is in the cam's frame, centred there)
        let o = self.arm.o - self.cam_pivot;
        let arm_length = self.l;
        let prime = base_radius + self.r;
        // |O + L u(φ0)| = R_b + r: O·u(φ0) = K
        let k = (prime * prime - o.norm_squared() - arm_length * arm_length) / (2.0 * arm_length);
        first_touch_root(
            [o.x, o.y, k],
            |_| true,
            self.arm.toward_cam,
            self.arm.phi0,
            self.arm.closing,
        )
        .ok_or(CamError::Invalid {
            field: Field::Follower(FollowerField::ArmLength),
            value: arm_length,
            reason: "the roller cannot rest on the base circle",
        })
    }
    fn envelope(&self, s: &[f64; 5], s0: f64, _u: f64, sigma: f64, rot: &Rotation) -> Envelope {
        // the roller's centre at φ = φ0 + ρ s
        let w = arm_path(
            self.arm.o - self.cam_pivot,
            self.l,
            s,
            s0,
            -self.arm.closing,
            0.0,
        );
        Envelope::Offset(rotated_derivs(sigma, rot, &w), self.r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cheap first-touch test against the score's (the default of [`Kind::is_first_through`]),
    /// at both arm angles where the roller passes through a point, found independently: sign
    /// changes of `|x − C(φ)|² − r²` over the branch, refined by bisection (no law of cosines).
    #[test]
    fn first_through_agrees_with_the_score_at_both_crossings() {
        let (mut checked, mut first) = (0, 0);
        for (closing, l, r) in [
            (Sense::Ccw, 4.0, 1.0),
            (Sense::Cw, 4.0, 1.0),
            (Sense::Ccw, 3.0, 0.01),
        ] {
            let Model::OscillatingRoller(k) = OscillatingRoller::model(
                Point2::origin(),
                Point2::new(-2.0, 5.0),
                l,
                r,
                closing,
                -1.0,
            ) else {
                unreachable!()
            };
            let slack = 1e-12;
            let gap = |x: Point2, phi: f64| {
                let c = k.arm.o + l * Vec2::new(phi.cos(), phi.sin());
                (x - c).norm_squared() - r * r
            };
            for i in 0..40 {
                // points the roller reaches, around the arm's circle
                let (a, d) = (
                    -1.0 + 0.9 * (f64::from(i) * 0.37).sin(),
                    0.95 * r * (f64::from(i) * 1.3).cos(),
                );
                let x = k.arm.o + (l + d) * Vec2::new(a.cos(), a.sin());
                let lo = k.arm.phi0 - std::f64::consts::PI;
                for phi in
                    super::super::tests::crossings(|p| gap(x, p), lo, std::f64::consts::TAU, 20_000)
                {
                    let by_score = matches!(k.score(x), Some((_, q)) if (q - phi).abs() <= 1e-9);
                    assert_eq!(
                        k.is_first_through(x, &k.pose(phi), slack),
                        by_score,
                        "{closing:?}, L {l}, r {r}: x {x:?} at φ {phi}"
                    );
                    checked += 1;
                    first += usize::from(by_score);
                }
            }
        }
        // two crossings a point: the first accepted, the later refused
        assert_eq!((checked, first), (240, 120));
    }
}
