//! Concrete 2D `f64` types: points, vectors, rotations.
//!
//! Points and vectors are distinct types (`Point2 − Point2 = Vec2`, `Point2 + Vec2 = Point2`); they
//! are nalgebra's, so everything nalgebra offers works on them. Conventions: see the
//! [crate docs](crate#sign-conventions).

/// A position in the plane (length units).
pub type Point2 = nalgebra::Point2<f64>;
/// A displacement, velocity, acceleration or direction in the plane.
pub type Vec2 = nalgebra::Vector2<f64>;

/// `k × v`: `v` turned by +90° (counter-clockwise). The left normal of a tangent `t` is `rot90(t)`.
/// (nalgebra's `Vector2::perp` is the scalar cross product, [`cross`] here.)
#[inline]
pub fn rot90(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// The scalar 2D cross product `a × b = a_x b_y − a_y b_x`.
#[inline]
pub fn cross(a: Vec2, b: Vec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// A planar rotation (nalgebra's unit complex number: its cosine and sine, computed once).
pub type Rotation = nalgebra::UnitComplex<f64>;

/// A body frame at one instant: a rotation followed by a translation, `x = p + R r`.
pub type Frame = nalgebra::Isometry2<f64>;

/// A direction or normal that must have unit length.
pub type UnitVec2 = nalgebra::Unit<Vec2>;

/// An angle in degrees as radians, reduced modulo 360° *in degrees first* (exactly: `rem_euclid`
/// of an `f64` by 360 has no rounding error), so that `1e20` and `280` (which `1e20` is, modulo
/// 360) give the same angle. Converting first would multiply the rounding of a huge angle.
pub fn deg_to_rad(deg: f64) -> f64 {
    deg.rem_euclid(360.0).to_radians()
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

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn rotation_round_trips_and_is_ccw() {
        let r = Rotation::new(std::f64::consts::FRAC_PI_2);
        let v = r * Vec2::new(1.0, 0.0);
        assert_relative_eq!(v, Vec2::new(0.0, 1.0), epsilon = 1e-15);
        let w = Vec2::new(0.3, -2.0);
        assert_relative_eq!(r.inverse() * (r * w), w, epsilon = 1e-15);
    }

    #[test]
    fn rot90_is_left_normal_and_cross_is_signed() {
        assert_eq!(rot90(Vec2::new(1.0, 0.0)), Vec2::new(0.0, 1.0));
        assert_eq!(cross(Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0)), 1.0);
        assert_eq!(cross(Vec2::new(0.0, 1.0), Vec2::new(1.0, 0.0)), -1.0);
    }

    #[test]
    fn degrees_are_reduced_before_conversion() {
        // 1e20 = 277 777 777 777 777 777 × 360 + 280 exactly
        assert_eq!(deg_to_rad(1e20), deg_to_rad(280.0));
        assert_eq!(deg_to_rad(-90.0), deg_to_rad(270.0));
        assert_eq!(deg_to_rad(720.5), deg_to_rad(0.5));
    }

    #[test]
    fn wrap_angle_near_lands_in_window() {
        let w = wrap_angle_near(7.0, 0.0);
        assert!(w > -std::f64::consts::PI && w <= std::f64::consts::PI);
        assert_relative_eq!(w, 7.0 - std::f64::consts::TAU, epsilon = 1e-15);
        assert_relative_eq!(wrap_angle_near(-3.0, 3.0), -3.0 + std::f64::consts::TAU);
    }
}
