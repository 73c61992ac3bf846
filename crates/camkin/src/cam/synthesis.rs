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

use super::jet::{scale, Jet, Num};
use super::{CamError, Follower, Sense};
use crate::curve::{unit_direction, Curve, Derivs, Domain};
use crate::geometry::{perp, Point2, Rot, Vec2};
use crate::motion::Program;

/// A profile synthesised from a motion program.
#[derive(Debug, Clone)]
pub struct SynthesizedProfile {
    program: Program,
    kind: Kind,
    sigma: f64,
    s0: f64,
}

#[derive(Debug, Clone, Copy)]
enum Kind {
    Flat {
        d: Vec2,
        p: Vec2,
    },
    Knife {
        d: Vec2,
        p: Vec2,
        e: f64,
    },
    Roller {
        d: Vec2,
        p: Vec2,
        e: f64,
        r: f64,
    },
    /// an arm: angle φ = φ0 + ρ s(θ) (φ0 is the profile's `s0`)
    ArmRoller {
        o: Vec2,
        l: f64,
        r: f64,
        rho: f64,
    },
    ArmFlat {
        o: Vec2,
        e: f64,
        rho: f64,
    },
}

/// The profile that drives `follower` with the motion `program` above a base circle of radius
/// `base_radius` (where the program is at 0), for a cam turning in `direction`; the program's
/// rises are lengths for translating followers and radians of arm angle for oscillating ones.
pub fn synthesize(
    program: Program,
    base_radius: f64,
    follower: &Follower,
    direction: Sense,
) -> Result<SynthesizedProfile, CamError> {
    if !(base_radius.is_finite() && base_radius > 0.0) {
        return Err(CamError::Invalid {
            field: "cam.profile.base_radius",
            value: base_radius,
            reason: "must be positive and finite",
        });
    }
    let unit = |d: Vec2| unit_direction("follower.direction", d).map_err(CamError::from);
    let (kind, s0) = match *follower {
        Follower::TranslatingFlat { direction } => {
            let d = unit(direction)?;
            (Kind::Flat { d, p: perp(d) }, base_radius)
        }
        Follower::TranslatingKnife { direction, offset } => {
            let d = unit(direction)?;
            if offset.abs() >= base_radius {
                return Err(CamError::Invalid {
                    field: "follower.offset",
                    value: offset,
                    reason: "must be smaller than the base radius",
                });
            }
            (
                Kind::Knife {
                    d,
                    p: perp(d),
                    e: offset,
                },
                (base_radius * base_radius - offset * offset).sqrt(),
            )
        }
        Follower::TranslatingRoller {
            direction,
            offset,
            roller_radius,
        } => {
            let d = unit(direction)?;
            let prime = base_radius + roller_radius;
            if offset.abs() >= prime {
                return Err(CamError::Invalid {
                    field: "follower.offset",
                    value: offset,
                    reason: "must be smaller than the prime circle's radius",
                });
            }
            (
                Kind::Roller {
                    d,
                    p: perp(d),
                    e: offset,
                    r: roller_radius,
                },
                (prime * prime - offset * offset).sqrt(),
            )
        }
        Follower::OscillatingRoller {
            pivot,
            arm_length,
            roller_radius,
            closing,
            initial_angle,
        } => {
            let o = pivot.coords;
            let prime = base_radius + roller_radius;
            // |O + L u(φ0)| = R_b + r: O·u(φ0) = K
            let k =
                (prime * prime - o.norm_squared() - arm_length * arm_length) / (2.0 * arm_length);
            let phi0 = solve_angle(
                |phi| o.x * phi.cos() + o.y * phi.sin() - k,
                |phi| -o.x * phi.sin() + o.y * phi.cos(),
                initial_angle,
            )
            .ok_or(CamError::Invalid {
                field: "follower.arm_length",
                value: arm_length,
                reason: "the roller cannot rest on the base circle",
            })?;
            (
                Kind::ArmRoller {
                    o,
                    l: arm_length,
                    r: roller_radius,
                    rho: -closing.sign(),
                },
                phi0,
            )
        }
        Follower::OscillatingFlat {
            pivot,
            face_offset,
            closing,
            initial_angle,
        } => {
            let o = pivot.coords;
            // the face at signed distance h0 = −closing·R_b from the axis: e + O·n(φ0) = h0
            let h0 = -closing.sign() * base_radius;
            let phi0 = solve_angle(
                |phi| face_offset - o.x * phi.sin() + o.y * phi.cos() - h0,
                |phi| -o.x * phi.cos() - o.y * phi.sin(),
                initial_angle,
            )
            .ok_or(CamError::Invalid {
                field: "follower.offset",
                value: face_offset,
                reason: "the face cannot rest on the base circle",
            })?;
            (
                Kind::ArmFlat {
                    o,
                    e: face_offset,
                    rho: -closing.sign(),
                },
                phi0,
            )
        }
    };
    Ok(SynthesizedProfile {
        program,
        kind,
        sigma: direction.sign(),
        s0,
    })
}

impl SynthesizedProfile {
    /// The follower's position at cam angle `theta` (rad) and its first two derivatives in θ.
    pub fn follower_motion(&self, theta: f64) -> [f64; 3] {
        let s = self.program.eval(theta);
        let rho = match self.kind {
            Kind::ArmRoller { rho, .. } | Kind::ArmFlat { rho, .. } => rho,
            _ => 1.0,
        };
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

    /// `y, y', y'', y''', y''''` of `A w` given `w⁽ᵏ⁾`, k = 0..4 (world vectors).
    fn rotated_derivs(&self, rot: &Rot, w: &[Vec2; 5]) -> [Vec2; 5] {
        let sg = self.sigma;
        let aw: Vec<Vec2> = w.iter().map(|v| rot.apply(*v)).collect();
        let m = |v: Vec2| -sg * perp(v); // M = −σJ
        let m2 = |v: Vec2| -v;
        let m3 = |v: Vec2| sg * perp(v);
        [
            aw[0],
            m(aw[0]) + aw[1],
            m2(aw[0]) + 2.0 * m(aw[1]) + aw[2],
            m3(aw[0]) + 3.0 * m2(aw[1]) + 3.0 * m(aw[2]) + aw[3],
            aw[0] + 4.0 * m3(aw[1]) + 6.0 * m2(aw[2]) + 4.0 * m(aw[3]) + aw[4],
        ]
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

/// `1/a` of a jet (a₀ ≠ 0).
fn jet_recip(a: Jet) -> Jet {
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
        let rot = Rot::new(-self.sigma * u);
        let sg = self.sigma;
        let w =
            |d: Vec2, p: Vec2, e: f64| [e * p + s[0] * d, s[1] * d, s[2] * d, s[3] * d, s[4] * d];
        match self.kind {
            Kind::Flat { d, p } => {
                let w = [
                    s[0] * d - sg * s[1] * p,
                    s[1] * d - sg * s[2] * p,
                    s[2] * d - sg * s[3] * p,
                    s[3] * d - sg * s[4] * p,
                    Vec2::zeros(), // not needed: y''' uses w up to w'''
                ];
                let y = self.rotated_derivs(&rot, &w);
                Derivs {
                    p: Point2::from(y[0]),
                    d1: y[1],
                    d2: y[2],
                    d3: y[3],
                }
            }
            Kind::Knife { d, p, e } => {
                let y = self.rotated_derivs(&rot, &w(d, p, e));
                Derivs {
                    p: Point2::from(y[0]),
                    d1: y[1],
                    d2: y[2],
                    d3: y[3],
                }
            }
            Kind::Roller { d, p, e, r } => {
                offset_curve(&self.rotated_derivs(&rot, &w(d, p, e)), r, sg)
            }
            Kind::ArmRoller { o, l, r, rho } => {
                // φ = φ0 + ρ s and its derivatives; u(φ) = (cos φ, sin φ), v = k × u
                let f = [
                    self.s0 + rho * (s[0] - self.s0),
                    rho * s[1],
                    rho * s[2],
                    rho * s[3],
                    rho * s[4],
                ];
                let (sn, cs) = f[0].sin_cos();
                let (u, v) = (Vec2::new(cs, sn), Vec2::new(-sn, cs));
                let (f1, f2, f3) = (f[1], f[2], f[3]);
                let w = [
                    o + l * u,
                    l * f1 * v,
                    l * (f2 * v - f1 * f1 * u),
                    l * ((f3 - f1 * f1 * f1) * v - 3.0 * f1 * f2 * u),
                    l * ((f[4] - 6.0 * f1 * f1 * f2) * v
                        + (f1.powi(4) - 4.0 * f1 * f3 - 3.0 * f2 * f2) * u),
                ];
                offset_curve(&self.rotated_derivs(&rot, &w), r, sg)
            }
            Kind::ArmFlat { o, e, rho } => {
                // the face in the cam frame: y·N(α) = h, α = φ − σθ, h = e + O·n(φ); envelope
                // y = h N − (h'/α') T with N = (−sin α, cos α), T = (cos α, sin α)
                let f = [
                    self.s0 + rho * (s[0] - self.s0),
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
                Derivs {
                    p: Point2::from(at(0, 1.0)),
                    d1: at(1, 1.0),
                    d2: at(2, 2.0),
                    d3: at(3, 6.0),
                }
            }
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
    // y = c − r σ perp(t̂), perp(t) = (−t_y, t_x)
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

/// Newton for `f(φ) = 0` from `start`; `None` when it does not converge.
fn solve_angle(f: impl Fn(f64) -> f64, df: impl Fn(f64) -> f64, start: f64) -> Option<f64> {
    let mut phi = start;
    for _ in 0..100 {
        let step = f(phi) / df(phi);
        if !step.is_finite() {
            return None;
        }
        phi -= step.clamp(-0.5, 0.5);
        if step.abs() < 1e-15 {
            return Some(phi);
        }
    }
    (f(phi).abs() < 1e-12).then_some(phi)
}
