//! Exact cam profiles synthesised from a motion program, for the five follower types.
//!
//! The profile is an analytic curve in the cam frame parameterised by the cam angle `θ`: the
//! point of the profile that touches the follower at cam angle `θ`. With `A(θ) = R(−σθ)` the
//! rotation from the world into the cam frame (σ = ±1 the cam's direction), `d` the direction of
//! travel, `p = k × d`, `e` the offset and `s(θ)` the follower's position:
//!
//! - knife edge: the tip's path, `y = A (e p + s d)`;
//! - flat face: the envelope of the face lines `y·A d = s`, `y = A (s d − σ s' p)`;
//! - roller: the roller centre's path `c = A (e p + s d)` offset by the roller radius towards the
//!   cam, `y = c − r σ (k × c'/|c'|)`;
//! - oscillating roller: the same offset of the centre's path `c = A (O + L u(φ))`, the arm angle
//!   `φ = φ₀ + ρ s(θ)` (ρ = +1 when the spring closes clockwise: rising turns the arm
//!   counter-clockwise, away from the cam);
//! - oscillating flat face: in the cam frame the face is the line `y·N(α) = h` with
//!   `α = φ − σθ`, `h = e + O·n(φ)`; its envelope is `y = h N − (h'/α') T`.
//!
//! The position `s₀` of the program's zero (translating) or the arm angle `φ₀` puts the follower on
//! the base circle of radius `R_b`: the face at `R_b` from the axis, the knife tip or the roller
//! centre (prime circle `R_b + r`) on the line of travel, the arm's branch nearest its initial
//! angle.
//!
//! Derivatives in `θ` come from the law's: with `A' = −σ J A` (J the rotation by +90°),
//! `y⁽ⁿ⁾ = Σ C(n, k) (−σJ)ⁿ⁻ᵏ A w⁽ᵏ⁾`; the roller's offset is differentiated with truncated Taylor
//! series. The third derivative uses the law's fourth ([`crate::motion::Law::snap`]).

use super::follower::{Kind, Model};
use super::jet::{scale, Jet};
use super::{CamError, Follower, Sense};
use crate::curve::{Curve, Derivs, Domain};
use crate::field::{Field, ProfileField};
use crate::geometry::{rot90, Point2, Rotation, Vec2};
use crate::motion::Program;

/// A profile synthesised from a motion program.
#[derive(Debug, Clone)]
pub struct SynthesizedProfile {
    program: Program,
    model: Model,
    sigma: f64,
    s0: f64,
}

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

/// The profile that drives `follower` with the motion `program` above a base circle of radius
/// `base_radius` (where the program is at 0), for a cam turning in `direction`; the program's
/// rises are lengths for translating followers and radians of arm angle for oscillating ones.
/// The follower's geometry is taken relative to the cam axis.
pub fn synthesize(
    program: Program,
    base_radius: f64,
    follower: &Follower,
    direction: Sense,
) -> Result<SynthesizedProfile, CamError> {
    if !(base_radius.is_finite() && base_radius > 0.0) {
        return Err(CamError::Invalid {
            field: Field::Profile(ProfileField::BaseRadius),
            value: base_radius,
            reason: "must be positive and finite",
        });
    }
    let model = follower.model(Point2::origin())?;
    let s0 = model.synthesis_start(base_radius)?;
    Ok(SynthesizedProfile {
        program,
        model,
        sigma: direction.sign(),
        s0,
    })
}

impl SynthesizedProfile {
    /// The follower's position at cam angle `theta` (rad) and its first two derivatives in θ.
    pub fn follower_motion(&self, theta: f64) -> [f64; 3] {
        let s = self.program.eval(theta);
        let rho = self.model.joint().away();
        [self.s0 + rho * s[0], rho * s[1], rho * s[2]]
    }

    /// The program's `[s, s', s'', s''']` at cam angle `theta` (before the base offset and the
    /// arm's sense).
    pub fn program_derivatives(&self, theta: f64) -> [f64; 4] {
        self.program.eval(theta)
    }

    /// Where the program's segments break continuity (tolerance 1e-9 of each derivative's scale).
    pub fn discontinuities(&self) -> Vec<crate::motion::Discontinuity> {
        self.program.discontinuities(1e-9)
    }
}

/// `y, y', y'', y''', y''''` of `A w` given `w⁽ᵏ⁾`, k = 0..4 (world vectors), with
/// `A = R(−σθ)` (`rot`) and `A' = −σ J A`.
pub(crate) fn rotated_derivs(sigma: f64, rot: &Rotation, w: &[Vec2; 5]) -> [Vec2; 5] {
    let sg = sigma;
    let aw: Vec<Vec2> = w.iter().map(|v| rot * v).collect();
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

/// `√a` of a jet (a₀ > 0).
fn jet_sqrt(a: Jet) -> Jet {
    let a = a.0;
    let b0 = a[0].sqrt();
    let b1 = a[1] / (2.0 * b0);
    let b2 = (a[2] - b1 * b1) / (2.0 * b0);
    let b3 = (a[3] - 2.0 * b1 * b2) / (2.0 * b0);
    Jet([b0, b1, b2, b3])
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

impl Curve for SynthesizedProfile {
    fn eval(&self, u: f64) -> Derivs {
        let s = self.program.eval5(u);
        let s = [self.s0 + s[0], s[1], s[2], s[3], s[4]];
        let rot = Rotation::new(-self.sigma * u);
        match self.model.envelope(&s, self.s0, u, self.sigma, &rot) {
            Envelope::Derivs(d) => d,
            Envelope::Offset(c, r) => offset_curve(&c, r, self.sigma),
        }
    }

    fn domain(&self) -> Domain {
        Domain::Periodic {
            period: std::f64::consts::TAU,
        }
    }

    fn breakpoints(&self) -> Vec<f64> {
        self.program.starts().to_vec()
    }
}

/// A roller's contact curve: the centre's path `c` (with four derivatives) offset by the roller
/// radius `r` towards the cam, `y = c − r σ (k × c'/|c'|)`, differentiated with Taylor series.
fn offset_curve(c: &[Vec2; 5], r: f64, sg: f64) -> Derivs {
    // Taylor series in ε of c(θ + ε) and c'(θ + ε), order 3
    let series = |v0: Vec2, v1: Vec2, v2: Vec2, v3: Vec2, k: usize| -> Jet {
        let comp = |v: Vec2| if k == 0 { v.x } else { v.y };
        Jet([comp(v0), comp(v1), comp(v2) / 2.0, comp(v3) / 6.0])
    };
    let (cx, cy) = (
        series(c[0], c[1], c[2], c[3], 0),
        series(c[0], c[1], c[2], c[3], 1),
    );
    let (tx, ty) = (
        series(c[1], c[2], c[3], c[4], 0),
        series(c[1], c[2], c[3], c[4], 1),
    );
    let inv_g = jet_recip(jet_sqrt(tx * tx + ty * ty));
    let (ux, uy) = (tx * inv_g, ty * inv_g);
    // y = c − r σ rot90(t̂), rot90(t) = (−t_y, t_x)
    let k = -r * sg;
    let yx = cx + scale(-uy, k);
    let yy = cy + scale(ux, k);
    let at = |j: usize, f: f64| Vec2::new(yx.0[j] * f, yy.0[j] * f);
    Derivs {
        p: Point2::from(at(0, 1.0)),
        d1: at(1, 1.0),
        d2: at(2, 2.0),
        d3: at(3, 6.0),
    }
}
