//! Oscillating knife edge: a point carried by a general rotating follower (an arm). The tip is at
//! `O + L t(φ + β)` with `t(a) = (cos a, sin a)`, where `(L, β)` are the point's polar coordinates
//! in the arm's frame and `φ` the arm angle; its curve is that point in the arm frame.
//!
//! Its tangency conditions are the tip on the cam: `(x − O)·n = 0`, `(x − O)·t = L` with
//! `t = t(φ + β)`, `n = J t` (`J` the quarter turn). Its first touch is the extreme crossing of
//! the tip's circle with the profile in the closing sense, found as for the translating knife
//! (its circle is the path [`super::CentrePath::Circle`] at distance 0).

use super::envelope::{arm_path, rotated_derivs, Envelope};
use super::rates::{finite, CamPoint, Refusals};
use super::{
    arm_branch, first_touch_root, Arm, FollowerJoint, Kind, Model, Rates, Sense, Synthesis,
};
use crate::body::WorldDerivs;
use crate::cam::pose::Pose;
use crate::cam::CamError;
use crate::curve::PointCurve;
use crate::field::{Field, FollowerField, ProfileField};
use crate::geometry::{rot90, Point2, Rotation, Vec2};
use crate::human::human;
use crate::jet::{Num, V2};

#[derive(Debug, Clone, Copy)]
pub(crate) struct OscillatingKnife {
    pub(super) cam_pivot: Point2,
    pub(super) arm: Arm,
    /// the tip in the arm frame, its distance `L` from the pivot and its polar angle `β`
    pub(super) tip: Vec2,
    pub(super) l: f64,
    pub(super) beta: f64,
    /// `(cos β, sin β)`
    pub(super) cb: f64,
    pub(super) sb: f64,
}

impl OscillatingKnife {
    /// An arm about `o` carrying the point `tip` (arm frame); refused when the point is the pivot
    /// (it never moves).
    pub(super) fn model(
        cam_pivot: Point2,
        o: Point2,
        tip: Vec2,
        closing: Sense,
        phi0: f64,
    ) -> Result<Model, CamError> {
        let l = tip.norm();
        if !(l > 0.0 && l.is_finite()) {
            return Err(CamError::InvalidVector {
                field: Field::FollowerProfile(ProfileField::At),
                x: tip.x,
                y: tip.y,
                reason: "a point carried by a rotating follower must be off its pivot (the frame's origin), or it never moves",
            });
        }
        let beta = tip.y.atan2(tip.x);
        Ok(Model::OscillatingKnife(Self {
            cam_pivot,
            arm: Arm::new(cam_pivot, o, closing, phi0, beta),
            tip,
            l,
            beta,
            cb: tip.x / l,
            sb: tip.y / l,
        }))
    }

    /// `t(φ + β)` from the arm angle's sine and cosine `(s, c)`.
    #[inline(always)]
    fn t_of<T: Num>(&self, (s, c): (T, T)) -> V2<T> {
        let (cb, sb) = (T::c(self.cb), T::c(self.sb));
        V2::new(cb * c - sb * s, sb * c + cb * s)
    }

    /// `t(φ + β)` at a pose.
    #[inline(always)]
    fn t(&self, q: &Pose) -> Vec2 {
        let t = self.t_of((q.sin, q.cos));
        Vec2::new(t.x, t.y)
    }

    #[inline(always)]
    fn residual_sc<T: Num>(&self, x: V2<T>, sc: (T, T)) -> [T; 2] {
        let y = x - V2::c(self.arm.o.coords);
        let t = self.t_of(sc);
        let n = V2::new(T::c(0.0) - t.y, t.x);
        [y.dot(n), y.dot(t) - T::c(self.l)]
    }
}

impl Kind for OscillatingKnife {
    fn joint(&self) -> FollowerJoint {
        self.arm.joint()
    }
    fn curve(&self) -> super::FollowerCurve {
        super::FollowerCurve::Point(PointCurve::new(Point2::from(self.tip)).expect("finite"))
    }
    /// The arm angle that puts the tip's ray through `x` (its polar angle about the pivot less
    /// `β`), as the translating knife's score is the along-travel coordinate of any point.
    #[inline]
    fn score(&self, x: Point2) -> Option<(f64, f64)> {
        let y = x - self.arm.o;
        if y == Vec2::zeros() {
            return None;
        }
        Some(arm_branch(
            y.y.atan2(y.x) - self.beta,
            self.arm.toward_cam,
            self.arm.phi0,
            self.arm.closing,
        ))
    }
    fn score_interval(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        let (mid, half) = super::polar_interval(self.arm.o, c, r);
        Some((mid - self.beta, half))
    }
    fn stationary_tangents(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        // the polar angle about the pivot is stationary where the curve runs radially
        let y = c - self.arm.o;
        let rho = y.norm();
        (rho > r * (1.0 + super::ROUNDING))
            .then(|| (y.y.atan2(y.x), (r / rho).asin() + super::ROUNDING))
    }
    const ANGULAR: bool = true;
    #[inline]
    fn residual_value<T: Num>(&self, x: V2<T>, _x1: V2<T>, q: T) -> [T; 2] {
        self.residual_sc(x, q.sin_cos())
    }
    #[inline(always)]
    fn residual(&self, e: &WorldDerivs, q: &Pose) -> [f64; 2] {
        self.residual_sc(V2::c(e.p.coords), (q.sin, q.cos))
    }
    /// `∂/∂u = (x'·n, x'·t)`, `∂/∂φ = (−y·t, y·n)` (`∂t/∂φ = n`, `∂n/∂φ = −t`).
    #[inline]
    fn jacobian(&self, e: &WorldDerivs, q: &Pose) -> [[f64; 2]; 2] {
        let t = self.t(q);
        let n = rot90(t);
        let y = e.p - self.arm.o;
        [[e.d1.dot(&n), -y.dot(&t)], [e.d1.dot(&t), y.dot(&n)]]
    }
    /// The tip comes from behind its motion in the closing sense.
    #[inline]
    fn toward_follower(&self, _c: Point2, q: &Pose) -> Vec2 {
        -self.arm.closing * rot90(self.t(q))
    }
    fn centre_path(&self) -> Option<(super::CentrePath, f64)> {
        Some((
            super::CentrePath::Circle {
                o: self.arm.o,
                l: self.l,
                lead: self.beta,
            },
            0.0,
        ))
    }
    fn check_reach(&self, size: f64) -> Result<(), CamError> {
        let d = (self.arm.o - self.cam_pivot).norm();
        if (d - self.l).abs() >= size {
            return Err(CamError::Unreachable {
                field: Field::FollowerProfile(ProfileField::At),
                value: self.l,
                reason: format!(
                    "the point, {} from the pivot, stays {} from the cam axis; the cam reaches {}",
                    human(self.l),
                    human((d - self.l).abs()),
                    human(size)
                ),
            });
        }
        Ok(())
    }
    fn concave_limit(&self) -> Option<f64> {
        None
    }
}

impl Rates for OscillatingKnife {
    /// The contact point `x` is the tip: `ẋ = ω J y + u̇ x' = L φ̇ n`, so (its part along `t`)
    /// `u̇ = −(ω J y)·t / x'·t` and `φ̇ = ẋ·n / L`; `b + ü x' = L φ̈ n − L φ̇² t`, so
    /// `ü = −(b·t + L φ̇²) / x'·t` and `φ̈ = (b + ü x')·n / L`. Declined where the profile runs
    /// along the tip's circle (`x'·t ≈ 0`: the tip is locked).
    #[inline(always)]
    fn rates(&self, c: &CamPoint, q: &Pose, refuse: &Refusals) -> Option<[f64; 3]> {
        let t = self.t(q);
        let n = rot90(t);
        let x1t = c.x1.dot(&t);
        if !(x1t.abs() > refuse.lock * c.x1.norm()) {
            return None;
        }
        let l = self.l;
        let v0 = c.material_velocity();
        let ud = -v0.dot(&t) / x1t;
        let qd = (v0 + ud * c.x1).dot(&n) / l;
        let b = c.acceleration_but_tangential(ud);
        let udd = -(b.dot(&t) + l * qd * qd) / x1t;
        finite([qd, (b + udd * c.x1).dot(&n) / l, ud])
    }
}

impl Synthesis for OscillatingKnife {
    fn synthesis_start(&self, base_radius: f64) -> Result<f64, CamError> {
        // |O + L t(φ + β)| = R_b (the pivot from the cam's axis): O·t(φ + β) = K, i.e.
        // (O·t(β)) cos φ + (O·n(β)) sin φ = K
        let o = self.arm.o - self.cam_pivot;
        let l = self.l;
        let k = (base_radius * base_radius - o.norm_squared() - l * l) / (2.0 * l);
        let (tb, nb) = (Vec2::new(self.cb, self.sb), Vec2::new(-self.sb, self.cb));
        first_touch_root(
            [o.dot(&tb), o.dot(&nb), k],
            |_| true,
            self.arm.toward_cam,
            self.arm.phi0,
            self.arm.closing,
        )
        .ok_or(CamError::Invalid {
            field: Field::Follower(FollowerField::Pivot),
            value: base_radius,
            reason: "the point cannot rest on the base circle",
        })
    }
    fn envelope(&self, s: &[f64; 5], s0: f64, _u: f64, sigma: f64, rot: &Rotation) -> Envelope {
        // the tip at φ + β, φ = φ0 + ρ s
        let w = arm_path(
            self.arm.o - self.cam_pivot,
            self.l,
            s,
            s0,
            -self.arm.closing,
            self.beta,
        );
        let y = rotated_derivs(sigma, rot, &w);
        Envelope::traced(&y)
    }
}
