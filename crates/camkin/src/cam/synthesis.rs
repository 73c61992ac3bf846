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

use super::follower::envelope::{jet_recip, Envelope};
use super::follower::{Kind as _, Model, Synthesis as _};
use super::{CamError, Follower, Sense};
use crate::curve::{Curve, Derivs, Domain};
use crate::field::{Field, ProfileField};
use crate::geometry::{Point2, Rotation, Vec2};
use crate::jet::{scale, Jet};
use crate::motion::Program;

/// A profile synthesised from a motion program.
#[derive(Debug, Clone)]
pub struct SynthesizedProfile {
    program: Program,
    model: Model,
    sigma: f64,
    s0: f64,
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

/// `√a` of a jet (a₀ > 0).
fn jet_sqrt(a: Jet) -> Jet {
    let a = a.0;
    let b0 = a[0].sqrt();
    let b1 = a[1] / (2.0 * b0);
    let b2 = (a[2] - b1 * b1) / (2.0 * b0);
    let b3 = (a[3] - 2.0 * b1 * b2) / (2.0 * b0);
    Jet([b0, b1, b2, b3])
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
