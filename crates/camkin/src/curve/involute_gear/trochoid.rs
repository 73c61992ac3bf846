//! The root a rack cutter leaves: the envelope of the generating rack's tooth-tip round as the
//! rack rolls on the gear's pitch circle (the trochoid's parallel curve), in closed form.
//!
//! The rack's tooth fills the gear's space. In the frame of the space (its middle on the +x
//! axis, gear centre at the origin), with the rack at rest, its tip line is the root circle's
//! tangent `X = r_f`, its flank on the tooth's side `Y = w − (r − X) tan α` (`w`: half the
//! space on the pitch circle), and the round of radius `ρ` tangent to both has its centre at
//!
//! ```text
//! X_c = r_f + ρ,   Y_c = w − (r − X_c) tan α − ρ / cos α,   d = r − X_c > 0.
//! ```
//!
//! Rolling the gear by `φ` moves the rack by `r φ` along `Y`; seen from the gear the round's centre
//! is `C = R(−φ) (X_c, s)` with `s = Y_c + r φ`, and the envelope touches the round where its
//! normal is square to the centre's velocity `R(−φ) (s, −d)`:
//!
//! ```text
//! E(s) = R(−φ) P(s),   P(s) = (X_c − ρ d / q,  s (1 + ρ / q)),   q = √(s² + d²),   φ = (s − Y_c)/r.
//! ```
//!
//! `s = 0` is the round's lowest point on the root circle (the envelope is tangent to it there);
//! `s = d cot α` is where the round hands over to the straight flank, which generates the
//! involute: there the envelope meets the involute with a common tangent, unless the flank's
//! lowest point `h = r − X_c + ρ sin α` below the pitch line is deeper than `r sin² α` (the
//! interference point): then the rack cuts into the involute (undercut) and the two cross at a
//! corner above the base circle.

use crate::geometry::Vec2;

/// The envelope `E(s)` of one space's rack round, turned into the frame of the tooth after it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Trochoid {
    /// `X_c`, `ρ`, `d`, the pitch radius `r`
    pub(super) xc: f64,
    pub(super) rho: f64,
    pub(super) d: f64,
    pub(super) r: f64,
    /// the frame angle of `E` at `s = 0`: the space's middle `−π/z` plus `Y_c / r`
    pub(super) angle0: f64,
}

impl Trochoid {
    /// The rack round of radius `rho` for a gear of pitch radius `r`, root radius `rf`, pressure
    /// angle `alpha` whose space is `2w` wide on the pitch circle, in the frame of the tooth whose
    /// space's middle is at the angle `space_middle`; with `Y_c`. `None` when the round does not
    /// fit on the rack's tooth tip (`Y_c < 0`, or its centre at or above the pitch line).
    pub(super) fn new(
        r: f64,
        rf: f64,
        alpha: f64,
        w: f64,
        rho: f64,
        space_middle: f64,
    ) -> Option<(Self, f64)> {
        let xc = rf + rho;
        let d = r - xc;
        let yc = w - d * alpha.tan() - rho / alpha.cos();
        (d > 0.0 && yc >= 0.0).then_some((
            Self {
                xc,
                rho,
                d,
                r,
                angle0: space_middle + yc / r,
            },
            yc,
        ))
    }

    /// The largest round the rack's tooth tip holds (`Y_c = 0`: the two rounds meet on the
    /// tooth's centre line), at most `r − r_f` (its centre on the pitch line); negative when the
    /// rack's tooth comes to a point above its tip line.
    pub(super) fn largest(r: f64, rf: f64, alpha: f64, w: f64) -> f64 {
        let (tan, sec) = (alpha.tan(), 1.0 / alpha.cos());
        ((w - (r - rf) * tan) / (sec - tan)).min(r - rf)
    }

    /// `s` where the round hands over to the rack's straight flank, `d cot α`.
    pub(super) fn flank_start(&self, alpha: f64) -> f64 {
        self.d / alpha.tan()
    }

    /// The depth of the rack flank's lowest point below the pitch line, `h`: the rack undercuts
    /// the involute when `h > r sin² α`.
    pub(super) fn flank_depth(&self, alpha: f64) -> f64 {
        self.d + self.rho * alpha.sin()
    }

    /// `E(s)` and its first three derivatives in `s` (tooth frame).
    pub(super) fn eval(&self, s: f64) -> [Vec2; 4] {
        let (rho, d) = (self.rho, self.d);
        let q2 = s * s + d * d;
        let g = 1.0 / q2.sqrt();
        let g3 = g * g * g;
        let g5 = g3 * g * g;
        let g7 = g5 * g * g;
        let (g1, g2, g3d) = (
            -s * g3,
            (2.0 * s * s - d * d) * g5,
            3.0 * s * (3.0 * d * d - 2.0 * s * s) * g7,
        );
        let p0 = Vec2::new(self.xc - rho * d * g, s + rho * s * g);
        let p1 = Vec2::new(-rho * d * g1, 1.0 + rho * (g + s * g1));
        let p2 = Vec2::new(-rho * d * g2, rho * (2.0 * g1 + s * g2));
        let p3 = Vec2::new(-rho * d * g3d, rho * (3.0 * g2 + s * g3d));
        // E = M P with M = R(angle0 − s/r): M' = −k J M, k = 1/r
        let k = 1.0 / self.r;
        let j = |v: Vec2| Vec2::new(-v.y, v.x);
        let e0 = p0;
        let e1 = p1 - k * j(p0);
        let e2 = p2 - 2.0 * k * j(p1) - k * k * p0;
        let e3 = p3 - 3.0 * k * j(p2) - 3.0 * k * k * p1 + k * k * k * j(p0);
        let (sn, cs) = (self.angle0 - s * k).sin_cos();
        let rot = |v: Vec2| Vec2::new(cs * v.x - sn * v.y, sn * v.x + cs * v.y);
        [rot(e0), rot(e1), rot(e2), rot(e3)]
    }
}
