//! Truncated Taylor series ("jets"): third derivatives by implicit differentiation of conditions
//! that hold along a motion — a cam's first-touch tangency in the cam angle, a system's rows in
//! time (the jerk of its bodies).
//!
//! For the cam, with `z = (u, q)` the tangency residual `F(z, θ) = 0` holds at every cam angle. Writing
//! `z(θ₀ + ε) = z₀ + z₁ ε + z₂ ε² + z₃ ε³`, the coefficient `z_k` solves `J z_k = −[F(z₀ … z_{k−1})]_k`,
//! where `J = ∂F/∂z` is the Jacobian of the Newton iteration and `[·]_k` the ε^k coefficient with
//! `z_k = 0`. So `q' = q₁`, `q'' = 2 q₂`, `q''' = 6 q₃`: the jerk. This is independent of the
//! paper's method and serves as a cross-check of its velocity and acceleration.
//!
//! The tangency row of `F` would need the profile's fourth derivative at order 3, but the
//! `q`-row of `J⁻¹` has a zero in that column (`∂F₁/∂u = 0` at a tangency), so `q₃` does not
//! depend on it: it is taken as zero and only `u₃` (not reported) is affected.

use std::ops::{Add, Mul, Neg, Sub};

/// The arithmetic the residual is written in: `f64` or [`Jet`].
pub(crate) trait Num:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
    fn c(x: f64) -> Self;
    fn sin_cos(self) -> (Self, Self);
}

impl Num for f64 {
    #[inline]
    fn c(x: f64) -> Self {
        x
    }
    #[inline]
    fn sin_cos(self) -> (Self, Self) {
        f64::sin_cos(self)
    }
}

/// `c0 + c1 ε + c2 ε² + c3 ε³`, products truncated after ε³.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Jet(pub(crate) [f64; 4]);

impl Add for Jet {
    type Output = Jet;
    fn add(self, o: Jet) -> Jet {
        let (a, b) = (self.0, o.0);
        Jet([a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]])
    }
}
impl Sub for Jet {
    type Output = Jet;
    fn sub(self, o: Jet) -> Jet {
        self + (-o)
    }
}
impl Neg for Jet {
    type Output = Jet;
    fn neg(self) -> Jet {
        let a = self.0;
        Jet([-a[0], -a[1], -a[2], -a[3]])
    }
}
impl Mul for Jet {
    type Output = Jet;
    fn mul(self, o: Jet) -> Jet {
        let (a, b) = (self.0, o.0);
        Jet([
            a[0] * b[0],
            a[0] * b[1] + a[1] * b[0],
            a[0] * b[2] + a[1] * b[1] + a[2] * b[0],
            a[0] * b[3] + a[1] * b[2] + a[2] * b[1] + a[3] * b[0],
        ])
    }
}

impl Num for Jet {
    fn c(x: f64) -> Self {
        Jet([x, 0.0, 0.0, 0.0])
    }
    fn sin_cos(self) -> (Self, Self) {
        self.sin_cos_with(self.0[0].sin_cos())
    }
}

impl Jet {
    /// [`Num::sin_cos`] with the sine and cosine of the constant term given.
    pub(crate) fn sin_cos_with(self, (s, c): (f64, f64)) -> (Self, Self) {
        // sin(a + δ) = sin a cos δ + cos a sin δ, δ without constant term
        let d = Jet([0.0, self.0[1], self.0[2], self.0[3]]);
        let d2 = d * d;
        let d3 = d2 * d;
        let cos_d = Jet::c(1.0) - scale(d2, 0.5);
        let sin_d = d - scale(d3, 1.0 / 6.0);
        (
            scale(cos_d, s) + scale(sin_d, c),
            scale(cos_d, c) - scale(sin_d, s),
        )
    }
}

/// `k · j`.
pub(crate) fn scale(j: Jet, k: f64) -> Jet {
    Jet([j.0[0] * k, j.0[1] * k, j.0[2] * k, j.0[3] * k])
}

/// A plane vector over `f64` or [`Jet`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct V2<T> {
    pub(crate) x: T,
    pub(crate) y: T,
}

impl<T: Num> V2<T> {
    #[inline]
    pub(crate) fn new(x: T, y: T) -> Self {
        Self { x, y }
    }
    /// A constant vector.
    #[inline]
    pub(crate) fn c(v: crate::Vec2) -> Self {
        Self {
            x: T::c(v.x),
            y: T::c(v.y),
        }
    }
    #[inline]
    pub(crate) fn dot(self, o: Self) -> T {
        self.x * o.x + self.y * o.y
    }
    #[inline]
    pub(crate) fn scale(self, k: T) -> Self {
        Self {
            x: self.x * k,
            y: self.y * k,
        }
    }
}

impl<T: Num> Add for V2<T> {
    type Output = V2<T>;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self {
            x: self.x + o.x,
            y: self.y + o.y,
        }
    }
}
impl<T: Num> Sub for V2<T> {
    type Output = V2<T>;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self {
            x: self.x - o.x,
            y: self.y - o.y,
        }
    }
}

/// `c0 + c1 δ + c2 δ²/2 + c3 δ³/6` for a jet `δ` without constant term: a curve's coordinate
/// (or its derivative's) along a parameter that moves by `δ`.
pub(crate) fn taylor(dl: Jet, [c0, c1, c2, c3]: [f64; 4]) -> Jet {
    let (d2, d3) = (dl * dl, dl * dl * dl);
    Jet::c(c0) + scale(dl, c1) + scale(d2, c2 / 2.0) + scale(d3, c3 / 6.0)
}

/// A curve's point and tangent `(x, x')` (its own frame) as jets in a parameter moving by `dl`;
/// the tangent without the fourth derivative (it does not reach `q`: see the `jet` module).
pub(crate) fn curve_jets(r: &crate::curve::Derivs, dl: Jet) -> (V2<Jet>, V2<Jet>) {
    (
        V2::new(
            taylor(dl, [r.p.x, r.d1.x, r.d2.x, r.d3.x]),
            taylor(dl, [r.p.y, r.d1.y, r.d2.y, r.d3.y]),
        ),
        V2::new(
            taylor(dl, [r.d1.x, r.d2.x, r.d3.x, 0.0]),
            taylor(dl, [r.d1.y, r.d2.y, r.d3.y, 0.0]),
        ),
    )
}

/// `(cos, sin)` turning `v` (jets) by an angle given by its cosine and sine (jets).
pub(crate) fn turned((c, s): (Jet, Jet), v: V2<Jet>) -> V2<Jet> {
    V2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jet_sin_cos_match_taylor_series() {
        // sin(0.3 + ε + 0.5 ε²): derivatives by hand
        let a = Jet([0.3, 1.0, 0.5, 0.0]);
        let (s, c) = a.sin_cos();
        // d/dε sin(g) = cos g g', g' = 1 + ε; second: −sin g g'² + cos g g''; third: −cos g g'³ − 3 sin g g' g'' + cos g g'''
        let (s0, c0) = 0.3f64.sin_cos();
        let expect_s = [s0, c0, (-s0 + c0) / 2.0, (-c0 - 3.0 * s0) / 6.0];
        let expect_c = [c0, -s0, (-c0 - s0) / 2.0, (s0 - 3.0 * c0) / 6.0];
        for k in 0..4 {
            assert!((s.0[k] - expect_s[k]).abs() < 1e-15, "sin {k}");
            assert!((c.0[k] - expect_c[k]).abs() < 1e-15, "cos {k}");
        }
    }
}
