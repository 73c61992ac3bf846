//! Concrete 2D `f64` types: points, vectors, rotations.
//!
//! Points and vectors are distinct types (`Point2 − Point2 = Vec2`, `Point2 + Vec2 = Point2`); they
//! are nalgebra's, so everything nalgebra offers works on them. Conventions: see the
//! [crate docs](crate#sign-conventions).

/// A position in the plane (length units).
pub type Point2 = nalgebra::Point2<f64>;
/// A displacement, velocity, acceleration or direction in the plane.
pub type Vec2 = nalgebra::Vector2<f64>;

/// `k × v`: `v` turned by +90° (counter-clockwise). The left normal of a tangent `t` is `perp(t)`.
#[inline]
pub fn perp(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// The scalar 2D cross product `a × b = a_x b_y − a_y b_x`.
#[inline]
pub fn cross(a: Vec2, b: Vec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// A rotation by `angle` radians (counter-clockwise positive), stored as its cosine and sine.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rot {
    /// cos of the angle
    pub cos: f64,
    /// sin of the angle
    pub sin: f64,
}

impl Rot {
    /// The rotation by `angle` radians.
    #[inline]
    pub fn new(angle: f64) -> Self {
        if angle == 0.0 {
            return Self { cos: 1.0, sin: 0.0 };
        }
        let (sin, cos) = angle.sin_cos();
        Self { cos, sin }
    }

    /// `R v`.
    #[inline]
    pub fn apply(&self, v: Vec2) -> Vec2 {
        Vec2::new(
            self.cos * v.x - self.sin * v.y,
            self.sin * v.x + self.cos * v.y,
        )
    }

    /// `Rᵀ v` (the inverse rotation).
    #[inline]
    pub fn apply_inverse(&self, v: Vec2) -> Vec2 {
        Vec2::new(
            self.cos * v.x + self.sin * v.y,
            -self.sin * v.x + self.cos * v.y,
        )
    }
}

/// The angle `a` shifted by a multiple of 2π into `(centre − π, centre + π]`.
pub fn wrap_angle_near(a: f64, centre: f64) -> f64 {
    let two_pi = std::f64::consts::TAU;
    let mut d = (a - centre) % two_pi;
    if d <= -std::f64::consts::PI {
        d += two_pi;
    } else if d > std::f64::consts::PI {
        d -= two_pi;
    }
    centre + d
}

/// True when every coordinate is finite.
pub fn is_finite_point(p: &Point2) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn rotation_round_trips_and_is_ccw() {
        let r = Rot::new(std::f64::consts::FRAC_PI_2);
        let v = r.apply(Vec2::new(1.0, 0.0));
        assert_relative_eq!(v, Vec2::new(0.0, 1.0), epsilon = 1e-15);
        let w = Vec2::new(0.3, -2.0);
        assert_relative_eq!(r.apply_inverse(r.apply(w)), w, epsilon = 1e-15);
    }

    #[test]
    fn perp_is_left_normal_and_cross_is_signed() {
        assert_eq!(perp(Vec2::new(1.0, 0.0)), Vec2::new(0.0, 1.0));
        assert_eq!(cross(Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0)), 1.0);
        assert_eq!(cross(Vec2::new(0.0, 1.0), Vec2::new(1.0, 0.0)), -1.0);
    }

    #[test]
    fn wrap_angle_near_lands_in_window() {
        let w = wrap_angle_near(7.0, 0.0);
        assert!(w > -std::f64::consts::PI && w <= std::f64::consts::PI);
        assert_relative_eq!(w, 7.0 - std::f64::consts::TAU, epsilon = 1e-15);
        assert_relative_eq!(wrap_angle_near(-3.0, 3.0), -3.0 + std::f64::consts::TAU);
    }
}
