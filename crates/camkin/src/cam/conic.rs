//! A circle or an ellipse profile as a sweep evaluates it: `c + R (a cos u, b sin u)` with the
//! parameter's sine and cosine carried from the last evaluation by angle addition
//! ([`super::pose::small_sin_cos`], a fresh `sin_cos` after [`CARRY_AGE`] additions or a step
//! beyond [`CARRY_STEP`]), as the cam's rotation is carried: a warm step's Newton iterations and
//! its final evaluation call no `sin_cos`. The pair stays within 2e-15 of `sin_cos`.

use super::pose::{small_sin_cos, CARRY_AGE, CARRY_STEP};
use crate::curve::{Curve, Derivs, Domain, Ellipse};
use std::sync::atomic::{AtomicU32, AtomicU64, Ordering::Relaxed};

/// A circle (`a = b = R`, no turn) or an ellipse, with the last parameter evaluated and its
/// sine and cosine (atomics only so that it is a `Curve`: one sweep, one thread, uses it).
#[derive(Debug)]
pub(crate) struct CarriedConic {
    /// the curve as an ellipse (a circle's semi-axes are its radius)
    ellipse: Ellipse,
    /// `u`, `sin u`, `cos u` as bits (`u` NaN: none yet)
    last: [AtomicU64; 3],
    age: AtomicU32,
}

impl Clone for CarriedConic {
    fn clone(&self) -> Self {
        Self::new(self.ellipse)
    }
}

impl CarriedConic {
    fn new(ellipse: Ellipse) -> Self {
        Self {
            ellipse,
            last: [
                AtomicU64::new(f64::NAN.to_bits()),
                AtomicU64::new(0),
                AtomicU64::new(0),
            ],
            age: AtomicU32::new(0),
        }
    }

    /// The profile as a carried conic when it is a circle or an ellipse.
    pub(crate) fn of(profile: &dyn Curve) -> Option<Self> {
        if let Some(c) = profile.as_circle() {
            let r = c.radius();
            return Ellipse::new(c.center(), r, r, 0.0).ok().map(Self::new);
        }
        profile.as_ellipse().copied().map(Self::new)
    }

    /// `(sin u, cos u)`, carried from the last evaluation when it is near.
    #[inline(always)]
    fn sin_cos(&self, u: f64) -> (f64, f64) {
        let last = f64::from_bits(self.last[0].load(Relaxed));
        let h = u - last;
        let age = self.age.load(Relaxed);
        let (s, c, age) = if h.abs() <= CARRY_STEP && age < CARRY_AGE {
            let (s0, c0) = (
                f64::from_bits(self.last[1].load(Relaxed)),
                f64::from_bits(self.last[2].load(Relaxed)),
            );
            let (sh, ch) = small_sin_cos(h);
            (s0 * ch + c0 * sh, c0 * ch - s0 * sh, age + 1)
        } else {
            let (s, c) = u.sin_cos();
            (s, c, 0)
        };
        self.last[0].store(u.to_bits(), Relaxed);
        self.last[1].store(s.to_bits(), Relaxed);
        self.last[2].store(c.to_bits(), Relaxed);
        self.age.store(age, Relaxed);
        (s, c)
    }
}

impl Curve for CarriedConic {
    #[inline(always)]
    fn eval(&self, u: f64) -> Derivs {
        let (s, c) = self.sin_cos(u);
        self.ellipse.derivs_at(s, c)
    }
    fn domain(&self) -> Domain {
        Domain::Periodic {
            period: std::f64::consts::TAU,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::Circle;
    use crate::geometry::Point2;

    /// Along a sweep's small steps, Newton's back-and-forth and a jump, the carried evaluation is
    /// the circle's and the ellipse's own (libm's `sin_cos`) to 4e-15 of their size.
    #[test]
    fn carried_evaluations_are_the_curves_own() {
        let circle = Circle::new(Point2::new(0.3, -0.2), 2.5).unwrap();
        let ellipse = Ellipse::new(Point2::new(0.6, -0.3), 4.0, 2.5, 0.4).unwrap();
        for (curve, size) in [(&circle as &dyn Curve, 2.5), (&ellipse as &dyn Curve, 4.0)] {
            let carried = CarriedConic::of(curve).unwrap();
            let mut worst = 0.0f64;
            let mut u = 0.1;
            for k in 0..20_000 {
                // steps of 1e-3 with a Newton-like wobble, and a jump now and then
                u += 1e-3 + 1e-4 * f64::from(k % 7) - if k % 997 == 0 { 2.0 } else { 0.0 };
                let (a, b) = (carried.eval(u), curve.eval(u));
                for (x, y) in [
                    (a.p.coords, b.p.coords),
                    (a.d1, b.d1),
                    (a.d2, b.d2),
                    (a.d3, b.d3),
                ] {
                    worst = worst.max((x - y).norm() / size);
                }
            }
            assert!(worst <= 4e-15, "{worst:e}");
        }
    }
}
