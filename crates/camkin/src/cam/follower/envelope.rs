//! What each follower kind gives the synthesis of a profile from a motion program: its envelope
//! (the profile's derivatives, or a roller centre's path to offset), and the paths of the points
//! of a slide or an arm with their derivatives in the cam angle (see `cam::synthesis`).

use crate::curve::Derivs;
use crate::geometry::{rot90, Point2, Rotation, Vec2};
use crate::jet::Jet;

/// What a follower kind's envelope gives: the profile's derivatives, or a path to offset by a
/// roller's radius.
pub(crate) enum Envelope {
    /// the profile point and its derivatives
    Derivs(Derivs),
    /// a roller centre's path (value and four derivatives) and the roller radius
    Offset([Vec2; 5], f64),
}

impl Envelope {
    /// The profile traced by a point (a knife's tip, a flat face's touching point): its position
    /// and first three derivatives in θ from `y` (value and four derivatives).
    pub(crate) fn traced(y: &[Vec2; 5]) -> Self {
        Envelope::Derivs(Derivs {
            p: Point2::from(y[0]),
            d1: y[1],
            d2: y[2],
            d3: y[3],
        })
    }
}

/// `y, y', y'', y''', y''''` of `A w` given `w⁽ᵏ⁾`, k = 0..4 (world vectors), with
/// `A = R(−σθ)` (`rot`) and `A' = −σ J A`.
pub(crate) fn rotated_derivs(sigma: f64, rot: &Rotation, w: &[Vec2; 5]) -> [Vec2; 5] {
    let sg = sigma;
    let aw: [Vec2; 5] = std::array::from_fn(|k| rot * w[k]);
    let m = |v: Vec2| -sg * rot90(v); // M = −σJ
    let m2 = |v: Vec2| -v;
    let m3 = |v: Vec2| sg * rot90(v);
    [
        aw[0],
        m(aw[0]) + aw[1],
        m2(aw[0]) + 2.0 * m(aw[1]) + aw[2],
        m3(aw[0]) + 3.0 * m2(aw[1]) + 3.0 * m(aw[2]) + aw[3],
        aw[0] + 4.0 * m3(aw[1]) + 6.0 * m2(aw[2]) + 4.0 * m(aw[3]) + aw[4],
    ]
}

/// A translating follower's reference point `e p + s d` and its derivatives in θ.
pub(crate) fn translating_path(d: Vec2, p: Vec2, e: f64, s: &[f64; 5]) -> [Vec2; 5] {
    [e * p + s[0] * d, s[1] * d, s[2] * d, s[3] * d, s[4] * d]
}

/// A point of an arm at distance `l` from the pivot `o` (from the cam's axis), at the angle
/// `φ₀ + ρ (s − φ₀) + β` (`s[0]` the program's value with `φ₀` added, `ρ` the sign of the
/// program's lift, `β` the point's polar angle in the arm's frame), and its derivatives in θ.
pub(crate) fn arm_path(o: Vec2, l: f64, s: &[f64; 5], phi0: f64, rho: f64, beta: f64) -> [Vec2; 5] {
    let f = [
        phi0 + rho * (s[0] - phi0) + beta,
        rho * s[1],
        rho * s[2],
        rho * s[3],
        rho * s[4],
    ];
    // u = (cos f, sin f), v = J u
    let (sn, cs) = f[0].sin_cos();
    let (u, v) = (Vec2::new(cs, sn), Vec2::new(-sn, cs));
    let (f1, f2, f3) = (f[1], f[2], f[3]);
    [
        o + l * u,
        l * f1 * v,
        l * (f2 * v - f1 * f1 * u),
        l * ((f3 - f1 * f1 * f1) * v - 3.0 * f1 * f2 * u),
        l * ((f[4] - 6.0 * f1 * f1 * f2) * v + (f1.powi(4) - 4.0 * f1 * f3 - 3.0 * f2 * f2) * u),
    ]
}

/// `1/a` of a jet (a₀ ≠ 0).
pub(crate) fn jet_recip(a: Jet) -> Jet {
    let a = a.0;
    let r0 = 1.0 / a[0];
    let r1 = -r0 * (a[1] * r0);
    let r2 = -r0 * (a[1] * r1 + a[2] * r0);
    let r3 = -r0 * (a[1] * r2 + a[2] * r1 + a[3] * r0);
    Jet([r0, r1, r2, r3])
}
