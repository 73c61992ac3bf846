//! A follower position with, for an angle, its sine and cosine: evaluated once by `sin_cos`,
//! then carried along small steps by angle addition (a Newton iteration's, a sweep's), so that
//! a warm step of an oscillating follower, or of the cam's rotation, needs no `sin_cos`. Or
//! the other way round: an arm angle from a direction (a roller's centre about the pivot), by
//! the arctangent of the turn from the last one, needing no `atan2`.

use crate::geometry::Vec2;

/// The largest step (rad) an angle's sine and cosine are carried over by angle addition (the
/// series of [`small_sin_cos`] are exact to rounding up to it: their first omitted terms are
/// below 3e-24), and the most additions before a fresh `sin_cos` (each adds up to an ulp of
/// rounding: the pair stays within 2e-15 of `sin_cos`, measured 1.0e-15).
pub(crate) const CARRY_STEP: f64 = 0.02;
pub(crate) const CARRY_AGE: u32 = 32;

/// `(sin h, cos h)` by their series, exact to rounding for `|h| ≤ CARRY_STEP`: to `h⁹` and
/// `h⁸` (the first omitted terms below 3e-24), to `h⁵` and `h⁴` for `|h| ≤ 1e-3` (below 2e-21),
/// and `h`, `1 − h²/2` for `|h| ≤ 1e-6` (below 2e-19; a Newton step's last correction).
#[inline(always)]
pub(crate) fn small_sin_cos(h: f64) -> (f64, f64) {
    let h2 = h * h;
    if h2 <= 1e-12 {
        return (h, 1.0 - 0.5 * h2);
    }
    if h2 <= 1e-6 {
        return (
            h * (1.0 - h2 / 6.0 * (1.0 - h2 / 20.0)),
            1.0 - h2 / 2.0 * (1.0 - h2 / 12.0),
        );
    }
    let sin = h * (1.0 - h2 / 6.0 * (1.0 - h2 / 20.0 * (1.0 - h2 / 42.0 * (1.0 - h2 / 72.0))));
    let cos = 1.0 - h2 / 2.0 * (1.0 - h2 / 12.0 * (1.0 - h2 / 30.0 * (1.0 - h2 / 56.0)));
    (sin, cos)
}

/// `atan t` by its series, exact to rounding for `|t| ≤ CARRY_STEP`: to `t⁹` (the first
/// omitted term below 2e-20), to `t⁵` for `|t| ≤ 1e-3` (below 2e-22), `t − t³/3` for
/// `|t| ≤ 1e-6` (below 3e-31).
#[inline(always)]
pub(crate) fn small_atan(t: f64) -> f64 {
    let t2 = t * t;
    if t2 <= 1e-12 {
        return t * (1.0 - t2 / 3.0);
    }
    if t2 <= 1e-6 {
        return t * (1.0 - t2 * (1.0 / 3.0 - t2 / 5.0));
    }
    t * (1.0 - t2 * (1.0 / 3.0 - t2 * (1.0 / 5.0 - t2 * (1.0 / 7.0 - t2 / 9.0))))
}

/// A follower's position `q`; for an angle also `sin q` and `cos q` (`NaN` for a length: a
/// kind that read them by mistake would give `NaN`, which every caller refuses).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Pose {
    pub(crate) q: f64,
    pub(crate) sin: f64,
    pub(crate) cos: f64,
    /// angle additions since the last `sin_cos`
    age: u32,
}

impl Pose {
    /// A length (a translating follower's position): no sine or cosine.
    #[inline(always)]
    pub(crate) fn length(q: f64) -> Self {
        Self {
            q,
            sin: f64::NAN,
            cos: f64::NAN,
            age: 0,
        }
    }

    /// An angle, its sine and cosine by `sin_cos`.
    #[inline(always)]
    pub(crate) fn angle(q: f64) -> Self {
        let (sin, cos) = q.sin_cos();
        Self {
            q,
            sin,
            cos,
            age: 0,
        }
    }

    /// The angle `q` from this one: by angle addition when the step is at most
    /// [`CARRY_STEP`] and this one is fewer than [`CARRY_AGE`] additions from a `sin_cos`,
    /// else by `sin_cos`.
    #[inline(always)]
    pub(crate) fn angle_to(self, q: f64) -> Self {
        self.carried_to(q).unwrap_or_else(|| Self::angle(q))
    }

    /// The angle of the direction `v` (not zero), with its sine and cosine from `v` itself:
    /// the angle from this one's by [`small_atan`] of the turn between them when that is at
    /// most [`CARRY_STEP`] and this one is fewer than [`CARRY_AGE`] additions from a fresh
    /// angle, else by `atan2` (within half a turn of this one).
    #[inline(always)]
    pub(crate) fn toward(self, v: Vec2) -> Self {
        let inv = 1.0 / v.norm();
        let (sin, cos) = (v.y * inv, v.x * inv);
        // the turn's cosine and sine
        let (x, y) = (
            self.cos * cos + self.sin * sin,
            self.cos * sin - self.sin * cos,
        );
        if self.age < CARRY_AGE && y.abs() <= CARRY_STEP * x {
            return Self {
                q: self.q + small_atan(y / x),
                sin,
                cos,
                age: self.age + 1,
            };
        }
        let a = v.y.atan2(v.x);
        let turns = ((self.q - a) / std::f64::consts::TAU).round();
        Self {
            q: a + turns * std::f64::consts::TAU,
            sin,
            cos,
            age: 0,
        }
    }

    /// [`Pose::angle_to`] by angle addition only: `None` where it would take a `sin_cos`.
    #[inline(always)]
    pub(crate) fn carried_to(self, q: f64) -> Option<Self> {
        let h = q - self.q;
        if !(h.abs() <= CARRY_STEP && self.age < CARRY_AGE) {
            return None;
        }
        let (s, c) = small_sin_cos(h);
        Some(Self {
            q,
            sin: self.sin * c + self.cos * s,
            cos: self.cos * c - self.sin * s,
            age: self.age + 1,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each of the three series agrees with libm (independent) to an ulp of 1 over its range, at
    /// both ends and between, of both signs: what a carry needs, whose sine and cosine are
    /// combined with a unit vector's (the shortest series' sine is `h` itself, within 2e-19).
    #[test]
    fn small_sin_cos_is_libm_to_an_ulp() {
        let mut worst = 0.0f64;
        for top in [1e-6, 1e-3, CARRY_STEP] {
            for k in 0..=1000 {
                for sign in [1.0, -1.0] {
                    let h = sign * top * f64::from(k) / 1000.0;
                    let (s, c) = small_sin_cos(h);
                    let (se, ce) = h.sin_cos();
                    worst = worst.max((s - se).abs()).max((c - ce).abs());
                }
            }
        }
        // measured 3.5e-18
        assert!(worst <= f64::EPSILON, "{worst:e}");
    }

    /// The series agrees with libm's `atan` (independent) to an ulp of 1 over each tier's range.
    #[test]
    fn small_atan_is_libm_to_an_ulp() {
        let mut worst = 0.0f64;
        for top in [1e-6, 1e-3, CARRY_STEP] {
            for k in 0..=1000 {
                for sign in [1.0, -1.0] {
                    let t = sign * top * f64::from(k) / 1000.0;
                    worst = worst.max((small_atan(t) - t.atan()).abs());
                }
            }
        }
        assert!(worst <= f64::EPSILON, "{worst:e}");
    }

    /// An angle followed from direction to direction stays within 4 ulps of the angle the
    /// directions were made from (independent: libm's `sin_cos` of a known angle) over 20 000
    /// uneven steps of directions of uneven lengths; its sine and cosine are the direction's
    /// own; a turn beyond `CARRY_STEP` or an old angle takes a fresh `atan2`, near the last.
    #[test]
    fn followed_angle_stays_with_the_directions() {
        for start in [0.3, -2.9, 1e3] {
            let mut pose = Pose::angle(start);
            let (mut q, mut worst, mut fresh) = (start, 0.0f64, 0);
            for k in 0..20_000 {
                // turns whose tangent is below CARRY_STEP
                let h = 0.0199 * ((f64::from(k) * 0.618_033_988_7).fract() * 1.2 - 0.2);
                q += h;
                let (s, c) = q.sin_cos();
                let len = 1.0 + 1e3 * (f64::from(k) * 0.3).sin().powi(2);
                pose = pose.toward(Vec2::new(c, s) * len);
                fresh += usize::from(pose.age == 0);
                // in ulps of the angle (which grows to 160 rad)
                worst = worst.max((pose.q - q).abs() / (f64::EPSILON * q.abs().max(1.0)));
                assert!((pose.sin - s).abs() <= 2.0 * f64::EPSILON);
                assert!((pose.cos - c).abs() <= 2.0 * f64::EPSILON);
            }
            // measured 2.9
            assert!(worst <= 4.0, "from {start}: {worst} ulps");
            assert_eq!(fresh, 20_000 / (CARRY_AGE as usize + 1));
        }
        // a long turn: atan2, wrapped near the last angle
        let p = Pose::angle(10.0);
        let far = p.toward(Vec2::new(11.0f64.cos(), 11.0f64.sin()));
        assert!((far.q - 11.0).abs() <= 1e-14 && far.age == 0, "{far:?}");
        let back = p.toward(Vec2::new(9.99f64.cos(), 9.99f64.sin()));
        assert!((back.q - 9.99).abs() <= 1e-14 && back.age == 1, "{back:?}");
    }

    /// An angle carried by angle addition stays within 2e-15 of `sin_cos` (independent: libm)
    /// over 20 000 uneven steps, forwards and back; a step beyond `CARRY_STEP` or an old pair
    /// takes a fresh `sin_cos`, one every `CARRY_AGE + 1` steps.
    #[test]
    fn carried_angle_stays_with_sin_cos() {
        for start in [0.3, -2.9, 1e3] {
            let mut pose = Pose::angle(start);
            let (mut q, mut worst, mut fresh) = (start, 0.0f64, 0);
            for k in 0..20_000 {
                // steps up to 0.02 rad, mostly forwards
                let h = 0.02 * ((f64::from(k) * 0.618_033_988_7).fract() * 1.2 - 0.2);
                q += h;
                pose = pose.carried_to(q).unwrap_or_else(|| {
                    fresh += 1;
                    Pose::angle(q)
                });
                let (s, c) = q.sin_cos();
                worst = worst.max((pose.sin - s).abs()).max((pose.cos - c).abs());
            }
            // measured 1.0e-15
            assert!(worst <= 2e-15, "from {start}: {worst:e}");
            assert_eq!(fresh, 20_000 / (CARRY_AGE as usize + 1));
        }
        let p = Pose::angle(1.0);
        assert!(p.carried_to(1.0 + 1.01 * CARRY_STEP).is_none());
        assert!(p.carried_to(1.0 - 0.99 * CARRY_STEP).is_some());
        assert_eq!(p.angle_to(1.5), Pose::angle(1.5));
        // a length has no sine or cosine to read
        assert!(Pose::length(2.0).sin.is_nan() && Pose::length(2.0).cos.is_nan());
    }
}
