//! Oscillating flat-faced follower: the face is the line through `O + e (−sin φ, cos φ)` along
//! `(cos φ, sin φ)`, touching the cam on the arm's side of the pivot. Its curve is the line
//! `y = e` of the arm frame, oriented so that the cam lies on its right.

use super::envelope::{jet_recip, Envelope};
use super::rates::{finite, CamPoint, Refusals};
use super::{
    arm_branch, first_touch_root, Arm, FollowerJoint, Kind, Model, Rates, Sense, Synthesis,
};
use crate::body::WorldDerivs;
use crate::cam::pose::Pose;
use crate::cam::CamError;
use crate::curve::{Derivs, Line};
use crate::field::{Field, FollowerField};
use crate::geometry::{rot90, Point2, Rotation, Vec2};
use crate::jet::{scale, Jet, Num, V2};

#[derive(Debug, Clone, Copy)]
pub(crate) struct OscillatingFlat {
    pub(super) cam_pivot: Point2,
    pub(super) arm: Arm,
    pub(super) e: f64,
}

impl OscillatingFlat {
    pub(super) fn model(cam_pivot: Point2, o: Point2, e: f64, closing: Sense, phi0: f64) -> Model {
        Model::OscillatingFlat(Self {
            cam_pivot,
            arm: Arm::new(cam_pivot, o, closing, phi0, 0.0),
            e,
        })
    }
}

impl OscillatingFlat {
    /// The tangency residual with the arm angle given by its sine and cosine `(s, c)`.
    #[inline(always)]
    fn residual_sc<T: Num>(&self, x: V2<T>, x1: V2<T>, (s, c): (T, T)) -> [T; 2] {
        let y = x - V2::c(self.arm.o.coords);
        let n = V2::new(-s, c);
        [y.dot(n) - T::c(self.e), x1.dot(n)]
    }
}

impl Kind for OscillatingFlat {
    fn joint(&self) -> FollowerJoint {
        self.arm.joint()
    }
    fn curve(&self) -> super::FollowerCurve {
        // cw closing: the cam lies on the −n side of the face, the arm on the +n side
        super::FollowerCurve::Line(
            Line::new(Point2::new(0.0, self.e), Vec2::new(-self.arm.closing, 0.0))
                .expect("unit vector"),
        )
    }
    #[inline]
    fn score(&self, x: Point2) -> Option<(f64, f64)> {
        let y = x - self.arm.o;
        let rho = y.norm();
        let psi = y.y.atan2(y.x);
        let e = self.e;
        if rho < e.abs() || rho == 0.0 {
            return None;
        }
        Some(arm_branch(
            psi - (e / rho).asin(),
            self.arm.toward_cam,
            self.arm.phi0,
            self.arm.closing,
        ))
    }
    fn score_interval(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        // φ = ψ − asin(e/ρ): ψ within the disc's polar interval, ρ within ρ(c) ± r and ≥ |e|
        let (psi, dpsi) = super::polar_interval(self.arm.o, c, r);
        let rho = (c - self.arm.o).norm();
        let (lo, hi) = ((rho - r).max(self.e.abs()), rho + r);
        if hi < self.e.abs() {
            return None;
        }
        let a = |x: f64| (self.e / x).clamp(-1.0, 1.0).asin();
        let (a0, a1) = (a(lo), a(hi));
        let (amin, amax) = (a0.min(a1), a0.max(a1));
        Some((
            psi - 0.5 * (amin + amax),
            dpsi + 0.5 * (amax - amin) + super::ROUNDING,
        ))
    }
    fn stationary_tangents(&self, c: Point2, r: f64) -> Option<(f64, f64)> {
        // the face's direction (cos φ, sin φ) at the arm angles that touch the disc, where the
        // face reaches all of it (the score has no edge there)
        if (c - self.arm.o).norm() - r < self.e.abs() {
            return None;
        }
        self.score_interval(c, r)
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
        [[e.d1.dot(&n), -y.dot(&u)], [e.d2.dot(&n), -e.d1.dot(&u)]]
    }
    /// Cramer's rule without the general solve's row scaling: the residual and the Jacobian's
    /// entries scale at most as a length each (not as its square, as a roller's do), so their
    /// products stay within range for every length camkin accepts (1e-100 to 1e100).
    #[inline(always)]
    fn newton_step(&self, e: &WorldDerivs, q: &Pose) -> [f64; 2] {
        let [[a, b], [c, d]] = self.jacobian(e, q);
        let [f, g] = self.residual(e, q);
        let inv_det = 1.0 / (a * d - b * c);
        [(b * g - d * f) * inv_det, (c * f - a * g) * inv_det]
    }
    #[inline]
    fn toward_follower(&self, _c: Point2, q: &Pose) -> Vec2 {
        let (s, co) = (q.sin, q.cos);
        // cw closing (sign −1): the cam is on the −n side, the arm on the +n side
        -self.arm.closing * Vec2::new(-s, co)
    }
    fn concave_limit(&self) -> Option<f64> {
        Some(0.0)
    }
}

impl Rates for OscillatingFlat {
    /// `z·n = e`, `x'·n = 0` with `z = x − O`, `n = (−sin φ, cos φ)`, `t = (cos φ, sin φ)`
    /// (`ṅ = −φ̇ t`): `φ̇ = (ω J y)·n / z·t`; `u̇ = (φ̇ x'·t − ω (J x')·n) / x''·n`; and
    /// `φ̈ = (b·n − 2 φ̇ ẋ·t − φ̇² z·n) / z·t` with `ẋ = ω J y + u̇ x'`. Declined where the
    /// normal passes through the pivot (locked); a cam straight at the contact is conformal
    /// with the face (`x''·n = 0`).
    #[inline(always)]
    fn rates(&self, c: &CamPoint, q: &Pose, refuse: &Refusals) -> Option<[f64; 3]> {
        let (s, co) = (q.sin, q.cos);
        let (t, n) = (Vec2::new(co, s), Vec2::new(-s, co));
        let z = c.x - self.arm.o;
        let zt = z.dot(&t);
        if !(zt * zt > refuse.lock * refuse.lock * z.norm_squared()) {
            return None;
        }
        let v0 = c.material_velocity();
        let qd = v0.dot(&n) / zt;
        let ud = (qd * c.x1.dot(&t) - c.w * rot90(c.x1).dot(&n)) / c.x2.dot(&n);
        let xdot = v0 + ud * c.x1;
        let b = c.acceleration_but_tangential(ud);
        let qdd = (b.dot(&n) - 2.0 * qd * xdot.dot(&t) - qd * qd * z.dot(&n)) / zt;
        finite([qd, qdd, ud])
    }
}

impl Synthesis for OscillatingFlat {
    fn synthesis_start(&self, base_radius: f64) -> Result<f64, CamError> {
        // the pivot from the cam's axis (the profile is in the cam's frame, centred there)
        let o = self.arm.o - self.cam_pivot;
        let face_offset = self.e;
        // the face at signed distance h0 = −closing·R_b from the axis: e + O·n(φ0) = h0,
        // n = (−sin φ, cos φ)
        let h0 = -self.arm.closing * base_radius;
        // the face touches on the arm's side of the pivot: the foot of the perpendicular from
        // the cam's axis, h0·n, lies ahead of the pivot along the arm, (h0 n − O)·u = −O·u > 0
        first_touch_root(
            [o.y, -o.x, h0 - face_offset],
            |phi: f64| o.x * phi.cos() + o.y * phi.sin() < 0.0,
            self.arm.toward_cam,
            self.arm.phi0,
            self.arm.closing,
        )
        .ok_or(CamError::Invalid {
            field: Field::Follower(FollowerField::Offset),
            value: face_offset,
            reason: "the face cannot rest on the base circle",
        })
    }
    fn envelope(&self, s: &[f64; 5], s0: f64, u: f64, sigma: f64, _rot: &Rotation) -> Envelope {
        // the face in the cam frame: y·N(α) = h, α = φ − σθ, h = e + O·n(φ); envelope
        // y = h N − (h'/α') T with N = (−sin α, cos α), T = (cos α, sin α)
        let (o, e, rho, sg) = (
            self.arm.o - self.cam_pivot,
            self.e,
            -self.arm.closing,
            sigma,
        );
        let f = [
            s0 + rho * (s[0] - s0),
            rho * s[1],
            rho * s[2],
            rho * s[3],
            rho * s[4],
        ];
        let phi = Jet([f[0], f[1], f[2] / 2.0, f[3] / 6.0]);
        let phi1 = Jet([f[1], f[2], f[3] / 2.0, f[4] / 6.0]);
        let (sp, cp) = phi.sin_cos();
        let h = Jet::c(e) + scale(sp, -o.x) + scale(cp, o.y);
        let h1 = phi1 * (scale(cp, -o.x) + scale(sp, -o.y));
        let alpha = Jet([f[0] - sg * u, f[1] - sg, f[2] / 2.0, f[3] / 6.0]);
        let alpha1 = Jet([f[1] - sg, f[2], f[3] / 2.0, f[4] / 6.0]);
        let q = h1 * jet_recip(alpha1);
        let (sa, ca) = alpha.sin_cos();
        let yx = -(h * sa) - q * ca;
        let yy = h * ca - q * sa;
        let at = |j: usize, k: f64| Vec2::new(yx.0[j] * k, yy.0[j] * k);
        Envelope::Derivs(Derivs {
            p: Point2::from(at(0, 1.0)),
            d1: at(1, 1.0),
            d2: at(2, 2.0),
            d3: at(3, 6.0),
        })
    }
}
