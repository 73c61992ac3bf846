//! Involute spur gear: the closed outline of an external gear, exact in closed form.
//!
//! Symbols (`general-follower-and-gears.md`): module `m`, teeth `z`, pressure angle `α`, addendum
//! and dedendum factors `h_a`, `h_f`, profile shift coefficient `x`.
//!
//! ```text
//! pitch radius  r   = m z / 2           base radius r_b = r cos α
//! tip radius    r_a = r + m (h_a + x)   root radius r_f = r − m (h_f − x)
//! tooth thickness on the pitch circle   s = m (π/2 + 2 x tan α) − j     (j: backlash allowance)
//! involute      p(t) = r_b (cos t + t sin t, sin t − t cos t),  inv(α) = tan α − α
//! ```
//!
//! Each tooth is symmetric about its centre line; tooth `k` is centred at the frame angle
//! `2πk/z` (tooth 0 on the +x axis); the gear centre is the frame origin. Going counter-clockwise
//! (material on the left), one tooth is: the root circle from the middle of the space before it,
//! the root fillet, the involute flank, the tip relief, the tip circle, then the same mirrored. The
//! parameter `u` is the arc length along each piece (of the unrelieved involute on a relieved
//! stretch), so `|r'| = 1` except on the relief where it differs from 1 by about the relief's
//! slope; `u = 0` is the middle of the space before tooth 0, at the angle `−π/z`; the period is
//! `z` times one tooth's length.
//!
//! - **Root fillet**: what a rack cutter leaves: the envelope of the generating rack's tooth-tip
//!   round (radius: the fillet radius, by default `0.38 m` or the largest the rack's tip holds) as
//!   the rack rolls on the pitch circle, in closed form (`trochoid.rs`). It is tangent to the root
//!   circle and meets the involute with a common tangent, or, when the rack's flank reaches below
//!   the interference point (`h > r sin² α`: few teeth, the textbook's undercut), crosses it at a
//!   corner above the base circle, the involute below cut away.
//! - **Tip relief**: material removed along the flank's normal near the tip, `C_a` at the tip,
//!   growing from zero over a roll length `ℓ` (the length along the line of action) linearly or as
//!   a parabola. On an involute a normal offset `δ` is a rotation by `δ/r_b` about the gear
//!   centre, so the relieved flank is the involute turned by `δ(L)/r_b`, `L = r_b t`, in closed form.
//! - **Backlash** is an allowance `j` (length on the pitch circle) by which this gear's teeth are
//!   thinned; a pair's circumferential backlash is the sum of the two gears' allowances.
//!
//! Pieces meet with a continuous position (C⁰); the tangent turns at the corners (tip, an
//! undercut flank's foot, the root when the rack's tip is sharp) and the curvature jumps at every joint: all joints are
//! [`Curve::breakpoints`]. The involute's curvature is infinite at the base circle (`1/(r_b t)`).

use super::{check_positive, Curve, CurveError, CurveField, Derivs, Domain};
use crate::geometry::{Point2, Vec2};
use std::f64::consts::{FRAC_PI_2, PI, TAU};
use trochoid::Trochoid;

mod joints;
mod trochoid;

/// How tip relief grows from its start to the tip.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ReliefShape {
    /// `δ = C_a (L − L_s)/ℓ`
    Linear,
    /// `δ = C_a ((L − L_s)/ℓ)²` (tangent to the involute where it starts)
    Parabolic,
}

/// Tip relief: `amount` removed at the tip along the flank's normal, growing over the roll
/// `length` (along the line of action) below the tip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TipRelief {
    /// `C_a`, length
    pub amount: f64,
    /// `ℓ`, length along the line of action
    pub length: f64,
    /// linear or parabolic
    pub shape: ReliefShape,
}

/// Which way a tooth's flank faces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum FlankSide {
    /// facing clockwise (tooth 0's flank below the x axis): its involute unwinds
    /// counter-clockwise from the base circle
    Clockwise,
    /// facing counter-clockwise: its involute unwinds clockwise
    CounterClockwise,
}

impl FlankSide {
    /// `+1` for a flank whose involute unwinds counter-clockwise (facing clockwise), else `−1`.
    pub fn unwinding(self) -> f64 {
        match self {
            FlankSide::Clockwise => 1.0,
            FlankSide::CounterClockwise => -1.0,
        }
    }
}

/// Where a parameter lies on a gear: see [`InvoluteGear::flank_at`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlankPoint {
    /// the tooth, `0..z`
    pub tooth: u32,
    /// the side of the tooth
    pub side: FlankSide,
    /// the roll length when on the involute (relieved or not), else `None` (root, fillet, tip)
    pub roll_length: Option<f64>,
}

/// What an involute gear is made from. Build with [`InvoluteGearSpec::new`] and change the
/// defaults by the fields.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InvoluteGearSpec {
    /// module `m`, length
    pub module: f64,
    /// number of teeth `z`
    pub teeth: u32,
    /// pressure angle `α`, rad
    pub pressure_angle: f64,
    /// addendum factor `h_a` (default 1)
    pub addendum: f64,
    /// dedendum factor `h_f` (default 1.25)
    pub dedendum: f64,
    /// profile shift coefficient `x` (default 0)
    pub profile_shift: f64,
    /// backlash allowance `j`: the tooth thinned by this length on the pitch circle (default 0)
    pub backlash: f64,
    /// the generating rack's tooth-tip radius, which leaves the root fillet, length; `None`:
    /// `0.38 m` (the usual), or the largest the rack's tip holds when less
    pub fillet_radius: Option<f64>,
    /// tip relief (default none)
    pub tip_relief: Option<TipRelief>,
}

impl InvoluteGearSpec {
    /// A standard gear: `h_a = 1`, `h_f = 1.25`, no shift, no backlash, no relief.
    pub fn new(module: f64, teeth: u32, pressure_angle: f64) -> Self {
        Self {
            module,
            teeth,
            pressure_angle,
            addendum: 1.0,
            dedendum: 1.25,
            profile_shift: 0.0,
            backlash: 0.0,
            fillet_radius: None,
            tip_relief: None,
        }
    }
}

/// `inv(α) = tan α − α`.
pub fn involute_function(alpha: f64) -> f64 {
    alpha.tan() - alpha
}

/// One smooth piece of a half tooth, in the frame of tooth 0.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Shape {
    /// circle about `centre`, radius `radius`, from angle `a0`, `sense` ±1
    Arc {
        centre: Vec2,
        radius: f64,
        a0: f64,
        sense: f64,
    },
    /// the root fillet the generating rack leaves, in its parameter `s`
    Fillet(Trochoid),
    /// the involute turned by `base` (its start on the base circle), from arc length `s0`;
    /// relieved when `relief` is set
    Involute {
        base: f64,
        s0: f64,
        relief: Option<Relief>,
    },
}

/// Tip relief in terms of the roll length `L`: `δ = amount ((L − start)/length)^power`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Relief {
    amount: f64,
    start: f64,
    length: f64,
    power: i32,
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct Piece {
    /// where the piece starts in the half tooth's parameter
    start: f64,
    shape: Shape,
}

/// An external involute spur gear's outline.
//////
/// Symbols (`general-follower-and-gears.md`): module `m`, teeth `z`, pressure angle `α`, addendum
/// and dedendum factors `h_a`, `h_f`, profile shift coefficient `x`.
///
/// ```text
/// pitch radius  r   = m z / 2           base radius r_b = r cos α
/// tip radius    r_a = r + m (h_a + x)   root radius r_f = r − m (h_f − x)
/// tooth thickness on the pitch circle   s = m (π/2 + 2 x tan α) − j     (j: backlash allowance)
/// involute      p(t) = r_b (cos t + t sin t, sin t − t cos t),  inv(α) = tan α − α
/// ```
///
/// Each tooth is symmetric about its centre line; tooth `k` is centred at the frame angle
/// `2πk/z` (tooth 0 on the +x axis); the gear centre is the frame origin. Going counter-clockwise
/// (material on the left), one tooth is: the root circle from the middle of the space before it,
/// the root fillet, the involute flank, the tip relief, the tip circle, then the same mirrored. The
/// parameter `u` is the arc length along each piece (of the unrelieved involute on a relieved
/// stretch), so `|r'| = 1` except on the relief where it differs from 1 by about the relief's
/// slope; `u = 0` is the middle of the space before tooth 0, at the angle `−π/z`; the period is
/// `z` times one tooth's length.
///
/// - **Root fillet**: what a rack cutter leaves: the envelope of the generating rack's tooth-tip
///   round (radius: the fillet radius, by default `0.38 m` or the largest the rack's tip holds) as
///   the rack rolls on the pitch circle, in closed form (`trochoid.rs`). It is tangent to the root
///   circle and meets the involute with a common tangent, or, when the rack's flank reaches below
///   the interference point (`h > r sin² α`: few teeth, the textbook's undercut), crosses it at a
///   corner above the base circle, the involute below cut away.
/// - **Tip relief**: material removed along the flank's normal near the tip, `C_a` at the tip,
///   growing from zero over a roll length `ℓ` (the length along the line of action) linearly or as
///   a parabola. On an involute a normal offset `δ` is a rotation by `δ/r_b` about the gear
///   centre, so the relieved flank is the involute turned by `δ(L)/r_b`, `L = r_b t`, in closed form.
/// - **Backlash** is an allowance `j` (length on the pitch circle) by which this gear's teeth are
///   thinned; a pair's circumferential backlash is the sum of the two gears' allowances.
///
/// Pieces meet with a continuous position (C⁰); the tangent turns at the corners (tip, an
/// undercut flank's foot, the root when the rack's tip is sharp) and the curvature jumps at every joint: all joints are
/// [`Curve::breakpoints`](crate::curve::Curve::breakpoints). The involute's curvature is infinite at the base circle (`1/(r_b t)`).
#[derive(Debug, Clone, PartialEq)]
pub struct InvoluteGear {
    spec: InvoluteGearSpec,
    rb: f64,
    ra: f64,
    rf: f64,
    fillet: f64,
    /// the form radius: where the involute starts (above the base circle, where the fillet
    /// meets it)
    form: f64,
    /// half the tooth's angle at the base circle: tooth 0's flanks start at `∓γ`
    gamma: f64,
    relief: Option<Relief>,
    half: Vec<Piece>,
    /// length of a half tooth
    half_len: f64,
    /// the angle of tooth `k`'s frame and its rotation, `k = 0..z`
    turns: Vec<(f64, f64)>,
    breakpoints: Vec<f64>,
}

fn bad(field: CurveField, value: f64, reason: String) -> CurveError {
    CurveError::Gear {
        field,
        value,
        reason,
    }
}

impl InvoluteGear {
    /// Builds the outline, refusing a gear that cannot be made: teeth fewer than 3 or more than
    /// 10 000, a pressure angle outside 5°–45°, a tooth that comes to a point below its tip
    /// circle, teeth that overlap at the root, a fillet or a relief that does not fit.
    pub fn new(spec: InvoluteGearSpec) -> Result<Self, CurveError> {
        let m = check_positive(CurveField::Module, spec.module)?;
        let z = spec.teeth;
        if !(3..=10_000).contains(&z) {
            return Err(bad(
                CurveField::Teeth,
                f64::from(z),
                "must be from 3 to 10000".into(),
            ));
        }
        let alpha = spec.pressure_angle;
        if !(alpha.is_finite() && (5f64.to_radians()..=45f64.to_radians()).contains(&alpha)) {
            return Err(bad(
                CurveField::PressureAngle,
                alpha.to_degrees(),
                "must be from 5° to 45°".into(),
            ));
        }
        for (field, v) in [
            (CurveField::Addendum, spec.addendum),
            (CurveField::Dedendum, spec.dedendum),
        ] {
            if !(v.is_finite() && v > 0.0 && v <= 3.0) {
                return Err(bad(field, v, "must be above 0 and at most 3".into()));
            }
        }
        if !(spec.profile_shift.is_finite() && spec.profile_shift.abs() <= 2.0) {
            return Err(bad(
                CurveField::ProfileShift,
                spec.profile_shift,
                "must be from −2 to 2".into(),
            ));
        }
        let (zf, x) = (f64::from(z), spec.profile_shift);
        let r = m * zf / 2.0;
        let rb = r * alpha.cos();
        let ra = r + m * (spec.addendum + x);
        let rf = r - m * (spec.dedendum - x);
        if !(rf > 0.0) {
            return Err(bad(
                CurveField::Dedendum,
                spec.dedendum,
                format!("puts the root circle at radius {rf:.4}: it must be above the centre"),
            ));
        }
        if !(ra > rb && ra > rf) {
            return Err(bad(CurveField::Addendum,
                spec.addendum,
                format!("puts the tip circle (radius {ra:.4}) inside the base circle (radius {rb:.4}): there is no involute"),
            ));
        }
        let j = spec.backlash;
        if !(j.is_finite() && j >= 0.0) {
            return Err(bad(
                CurveField::Backlash,
                j,
                "must be zero or positive".into(),
            ));
        }
        let thickness = m * (FRAC_PI_2 + 2.0 * x * alpha.tan()) - j;
        // the involute's start on the base circle, at −γ for the lower flank of tooth 0
        let gamma = thickness / (2.0 * r) + involute_function(alpha);
        let roll = |radius: f64| (radius * radius - rb * rb).max(0.0).sqrt();
        let arc_at = |radius: f64| {
            let l = roll(radius);
            l * l / (2.0 * rb)
        };
        let half_angle = |radius: f64| gamma - involute_function((rb / radius).min(1.0).acos());
        let space = PI / zf;
        // the generating rack: its tooth fills the space, `2w` wide on the pitch circle; its tip
        // round (the fillet radius) leaves the root fillet, the trochoid's envelope
        let w = space * r - thickness / 2.0;
        let fillet_max = Trochoid::largest(r, rf, alpha, w);
        if !(fillet_max >= 0.0) {
            return Err(bad(
                CurveField::ProfileShift,
                x,
                "leaves no space between the teeth at the root: the teeth overlap".into(),
            ));
        }
        let fillet = match spec.fillet_radius {
            None => (0.38 * m).min(fillet_max * (1.0 - 1e-9)),
            Some(rho) => {
                if !(rho.is_finite() && rho >= 0.0 && rho < fillet_max) {
                    return Err(bad(CurveField::FilletRadius,
                        rho,
                        format!("must be from 0 to below {fillet_max:.4}: the largest round the generating rack's tooth tip holds"),
                    ));
                }
                rho
            }
        };
        let (trochoid, yc) = Trochoid::new(r, rf, alpha, w, fillet, -space).ok_or_else(|| {
            bad(
                CurveField::FilletRadius,
                fillet,
                format!(
                    "does not fit on the generating rack's tooth tip (at most {fillet_max:.4})"
                ),
            )
        })?;
        // where the fillet meets the involute: with a common tangent where the rack's flank
        // takes over, or, undercut, where the two cross above the base circle (a corner)
        let flank_angle = |e: Vec2| e.y.atan2(e.x) + half_angle(e.norm());
        let s_flank = trochoid.flank_start(alpha);
        let s_end = if trochoid.flank_depth(alpha) <= r * alpha.sin().powi(2) {
            s_flank
        } else {
            // the involute is the outline where the envelope is outside it (on the space's
            // side); below, the envelope has cut into the tooth: their last crossing, found by
            // samples from the flank's start down, then bisection
            let side = |s: f64| {
                let e = trochoid.eval(s)[0];
                (e.norm() >= rb).then(|| flank_angle(e))
            };
            let n = 512;
            let at = |k: u32| s_flank * f64::from(k) / f64::from(n);
            let k = (0..n)
                .rev()
                .find(|&k| side(at(k)).is_none_or(|f| f >= 0.0))
                .unwrap_or(0);
            if side(at(k + 1)).is_none() {
                return Err(bad(CurveField::Teeth,
                    zf,
                    "are so few that the rack cuts the involute away down to the base circle (undercut): add profile shift".into(),
                ));
            }
            let (mut inside, mut outside) = (at(k), at(k + 1));
            for _ in 0..200 {
                let mid = 0.5 * (inside + outside);
                if mid <= inside.min(outside) || mid >= inside.max(outside) {
                    break;
                }
                match side(mid) {
                    Some(f) if f < 0.0 => outside = mid,
                    _ => inside = mid,
                }
            }
            inside
        };
        let flank_from = trochoid.eval(s_end)[0].norm().max(rb);
        if half_angle(flank_from) >= space {
            return Err(bad(
                CurveField::ProfileShift,
                x,
                "leaves no space between the teeth at the root: the teeth overlap".into(),
            ));
        }
        let (la, lf) = (roll(ra), roll(flank_from));
        let relief = match spec.tip_relief {
            None => None,
            Some(t) => {
                let amount = check_positive(CurveField::TipReliefAmount, t.amount)?;
                let length = check_positive(CurveField::TipReliefLength, t.length)?;
                if la - length < lf {
                    return Err(bad(CurveField::TipReliefLength,
                        length,
                        format!(
                            "is longer than the flank's roll length {:.4} (along the line of action)",
                            la - lf
                        ),
                    ));
                }
                Some(Relief {
                    amount,
                    start: la - length,
                    length,
                    power: match t.shape {
                        ReliefShape::Linear => 1,
                        ReliefShape::Parabolic => 2,
                    },
                })
            }
        };
        let tip_angle = -half_angle(ra) + relief.map_or(0.0, |r| r.amount / rb);
        if tip_angle >= 0.0 {
            // named after what made it pointed: the thinning, the relief, or the tooth's height
            let plain = -half_angle(ra) - j / (2.0 * r);
            let (field, value) = if plain >= 0.0 {
                (CurveField::Addendum, spec.addendum)
            } else if -half_angle(ra) >= 0.0 {
                (CurveField::Backlash, j)
            } else {
                (
                    CurveField::TipReliefAmount,
                    relief.map_or(0.0, |r| r.amount),
                )
            };
            return Err(bad(
                field,
                value,
                format!("makes the tooth come to a point below its tip circle (radius {ra:.4})"),
            ));
        }
        // the half tooth from the middle of the space (−π/z) to the tooth's centre line: the
        // root circle, the fillet, the involute
        let mut half = Vec::new();
        let mut at = 0.0;
        let mut push = |len: f64, shape: Shape, half: &mut Vec<Piece>| {
            half.push(Piece { start: at, shape });
            at += len;
        };
        if yc > 0.0 {
            push(
                rf * yc / r,
                Shape::Arc {
                    centre: Vec2::zeros(),
                    radius: rf,
                    a0: -space,
                    sense: 1.0,
                },
                &mut half,
            );
        }
        push(s_end, Shape::Fillet(trochoid), &mut half);
        let s_from = arc_at(flank_from);
        let s_tip = arc_at(ra);
        match relief {
            None => push(
                s_tip - s_from,
                Shape::Involute {
                    base: -gamma,
                    s0: s_from,
                    relief: None,
                },
                &mut half,
            ),
            Some(rel) => {
                let s_rel = rel.start * rel.start / (2.0 * rb);
                push(
                    s_rel - s_from,
                    Shape::Involute {
                        base: -gamma,
                        s0: s_from,
                        relief: None,
                    },
                    &mut half,
                );
                push(
                    s_tip - s_rel,
                    Shape::Involute {
                        base: -gamma,
                        s0: s_rel,
                        relief: Some(rel),
                    },
                    &mut half,
                );
            }
        }
        push(
            -ra * tip_angle,
            Shape::Arc {
                centre: Vec2::zeros(),
                radius: ra,
                a0: tip_angle,
                sense: 1.0,
            },
            &mut half,
        );
        let half_len = at;
        let turns = (0..z)
            .map(|k| {
                let a = TAU * f64::from(k) / zf;
                (a.cos(), a.sin())
            })
            .collect();
        let mut gear = Self {
            spec,
            rb,
            ra,
            rf,
            fillet,
            form: flank_from,
            gamma,
            relief,
            half,
            half_len,
            turns,
            breakpoints: Vec::new(),
        };
        gear.breakpoints = gear.joints();
        Ok(gear)
    }

    /// The data the gear was built from.
    pub fn spec(&self) -> &InvoluteGearSpec {
        &self.spec
    }
    /// Pitch radius `m z / 2`.
    pub fn pitch_radius(&self) -> f64 {
        self.spec.module * f64::from(self.spec.teeth) / 2.0
    }
    /// Base radius `r cos α`.
    pub fn base_radius(&self) -> f64 {
        self.rb
    }
    /// Tip radius `r + m (h_a + x)`.
    pub fn tip_radius(&self) -> f64 {
        self.ra
    }
    /// Root radius `r − m (h_f − x)`.
    pub fn root_radius(&self) -> f64 {
        self.rf
    }
    /// The generating rack's tooth-tip radius used (0: a sharp tip, whose trochoid is the fillet).
    pub fn fillet_radius(&self) -> f64 {
        self.fillet
    }
    /// The form radius: where the involute flank starts, at or above the base circle (the
    /// fillet below it; an undercut flank's foot).
    pub fn form_radius(&self) -> f64 {
        self.form
    }
    /// Number of teeth.
    pub fn teeth(&self) -> u32 {
        self.spec.teeth
    }
    /// The parameter length of one tooth.
    pub fn tooth_length(&self) -> f64 {
        2.0 * self.half_len
    }
    /// Which tooth the parameter `u` lies on (`0..z`), as counted from the space before tooth 0.
    pub fn tooth_of(&self, u: f64) -> u32 {
        let period = self.tooth_length() * f64::from(self.spec.teeth);
        let k = (u.rem_euclid(period) / self.tooth_length()).floor();
        (k as u32).min(self.spec.teeth - 1)
    }
    /// The roll length `L = √(R² − r_b²)` (the distance along the line of action from the base
    /// circle's tangent point) of the flank point at parameter `u`, when `u` is on a flank's
    /// involute; `None` elsewhere.
    pub fn roll_length(&self, u: f64) -> Option<f64> {
        let (_, w, _) = self.locate(u);
        let (piece, local) = self.piece(w);
        match piece.shape {
            Shape::Involute { s0, .. } => Some((2.0 * self.rb * (s0 + local)).sqrt()),
            _ => None,
        }
    }

    /// Half the tooth's angle at the base circle, `γ = s/(2r) + inv α` (`s`: the tooth thickness
    /// on the pitch circle): tooth `k`'s flank facing clockwise starts on the base circle at the
    /// frame angle `2πk/z − γ` and unwinds counter-clockwise, the other starts at `2πk/z + γ`
    /// and unwinds clockwise.
    pub fn base_half_angle(&self) -> f64 {
        self.gamma
    }

    /// The tip relief `δ` (length, along the flank's normal) at roll length `roll` (0 below the
    /// relief's start or without relief).
    pub fn relief_at(&self, roll: f64) -> f64 {
        match self.relief {
            Some(r) if roll > r.start => r.amount * ((roll - r.start) / r.length).powi(r.power),
            _ => 0.0,
        }
    }

    /// Where the parameter `u` lies: its tooth, the side of the tooth (the flank facing clockwise
    /// is the first half of the tooth's parameter), and its roll length when on a flank.
    pub fn flank_at(&self, u: f64) -> FlankPoint {
        let (tooth, _, mirrored) = self.locate(u);
        FlankPoint {
            tooth: tooth as u32,
            side: if mirrored {
                FlankSide::CounterClockwise
            } else {
                FlankSide::Clockwise
            },
            roll_length: self.roll_length(u),
        }
    }

    /// The parameter of tooth `tooth`'s flank on `side` at roll length `roll` (the inverse of
    /// [`InvoluteGear::roll_length`]); `None` when the flank does not reach that roll length.
    pub fn param_at_roll(&self, tooth: u32, side: FlankSide, roll: f64) -> Option<f64> {
        let s = roll * roll / (2.0 * self.rb);
        let w = self.half.iter().enumerate().find_map(|(i, p)| {
            let Shape::Involute { s0, .. } = p.shape else {
                return None;
            };
            let end = self.half.get(i + 1).map_or(self.half_len, |n| n.start);
            let w = p.start + (s - s0);
            (roll >= 0.0 && w >= p.start && w <= end).then_some(w)
        })?;
        let base = f64::from(tooth % self.spec.teeth) * self.tooth_length();
        Some(match side {
            FlankSide::Clockwise => base + w,
            FlankSide::CounterClockwise => base + self.tooth_length() - w,
        })
    }

    /// `(tooth, w, mirrored)`: the tooth and the parameter within its half tooth.
    #[inline]
    fn locate(&self, u: f64) -> (usize, f64, bool) {
        let tooth = self.tooth_length();
        let z = self.spec.teeth as usize;
        let period = tooth * z as f64;
        let u = if (0.0..period).contains(&u) {
            u
        } else {
            u.rem_euclid(period)
        };
        let k = ((u / tooth) as usize).min(z - 1);
        let w = u - k as f64 * tooth;
        if w <= self.half_len {
            (k, w, false)
        } else {
            (k, tooth - w, true)
        }
    }

    /// The piece holding `w` and the parameter within it: a joint belongs to the piece it ends,
    /// so the involute is never evaluated at its start on the base circle (mirrored or not).
    #[inline]
    fn piece(&self, w: f64) -> (&Piece, f64) {
        let i = self.half.partition_point(|p| p.start < w).max(1) - 1;
        let p = &self.half[i];
        (p, w - p.start)
    }

    fn half_eval(&self, w: f64) -> [Vec2; 4] {
        let (piece, l) = self.piece(w);
        match piece.shape {
            Shape::Arc {
                centre,
                radius,
                a0,
                sense,
            } => {
                let a = a0 + sense * l / radius;
                let (s, c) = a.sin_cos();
                let (er, et) = (Vec2::new(c, s), Vec2::new(-s, c));
                [
                    centre + radius * er,
                    sense * et,
                    -er / radius,
                    -sense * et / (radius * radius),
                ]
            }
            Shape::Fillet(t) => t.eval(l),
            Shape::Involute { base, s0, relief } => {
                involute(self.rb, base, s0 + l, relief.as_ref())
            }
        }
    }
}

/// The involute of the base circle `r_b` turned by `base` (plus the relief's turn), at arc length
/// `s` from the base circle, with its first three derivatives in `s`.
#[inline]
fn involute(rb: f64, base: f64, s: f64, relief: Option<&Relief>) -> [Vec2; 4] {
    let t = (2.0 * s / rb).sqrt();
    let (sn, cs) = t.sin_cos();
    let p = rb * Vec2::new(cs + t * sn, sn - t * cs);
    let e = Vec2::new(cs, sn);
    let n = Vec2::new(-sn, cs);
    // dt/ds = 1/(r_b t), d²t/ds² = −1/(r_b² t³)
    let tp = 1.0 / (rb * t);
    let p1 = e;
    let p2 = tp * n;
    let p3 = -tp * tp * e - rb * tp * tp * tp * n;
    // the relief's turn ε(s) = δ(L(s))/r_b (towards the tooth's centre) and its derivatives
    let [e0, e1, e2, e3] = match relief {
        Some(r) => {
            let l = rb * t;
            // L' = r_b/L, L'' = −r_b²/L³, L''' = 3 r_b³/L⁵
            let (l1, l2, l3) = (rb / l, -rb * rb / (l * l * l), 3.0 * rb.powi(3) / l.powi(5));
            let x = ((l - r.start) / r.length).max(0.0);
            let k = r.amount / r.length;
            let (f0, f1, f2) = if r.power == 1 {
                (r.amount * x, k, 0.0)
            } else {
                (r.amount * x * x, 2.0 * k * x, 2.0 * k / r.length)
            };
            [
                f0,
                f1 * l1,
                f2 * l1 * l1 + f1 * l2,
                3.0 * f2 * l1 * l2 + f1 * l3,
            ]
            .map(|v| v / rb)
        }
        None => [0.0; 4],
    };
    // q = R(base + ε) p and its derivatives (J = rot90)
    let j = |v: Vec2| Vec2::new(-v.y, v.x);
    let q0 = p;
    let q1 = p1 + e1 * j(p);
    let q2 = p2 + 2.0 * e1 * j(p1) + e2 * j(p) - e1 * e1 * p;
    let q3 = p3 + 3.0 * e1 * j(p2) + 3.0 * e2 * j(p1) - 3.0 * e1 * e1 * p1 + e3 * j(p)
        - 3.0 * e1 * e2 * p
        - e1 * e1 * e1 * j(p);
    let (sb, cb) = (base + e0).sin_cos();
    let rot = |v: Vec2| Vec2::new(cb * v.x - sb * v.y, sb * v.x + cb * v.y);
    [rot(q0), rot(q1), rot(q2), rot(q3)]
}

impl Curve for InvoluteGear {
    fn as_involute_gear(&self) -> Option<&InvoluteGear> {
        Some(self)
    }

    fn eval(&self, u: f64) -> Derivs {
        let (k, w, mirrored) = self.locate(u);
        let [p, d1, d2, d3] = self.half_eval(w);
        // the mirror image (x, −y) traversed backwards: odd derivatives change sign twice over
        let [p, d1, d2, d3] = if mirrored {
            let m = |v: Vec2| Vec2::new(v.x, -v.y);
            [m(p), -m(d1), m(d2), -m(d3)]
        } else {
            [p, d1, d2, d3]
        };
        let (c, s) = self.turns[k];
        let rot = |v: Vec2| Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y);
        Derivs {
            p: Point2::from(rot(p)),
            d1: rot(d1),
            d2: rot(d2),
            d3: rot(d3),
        }
    }
    fn domain(&self) -> Domain {
        Domain::Periodic {
            period: self.tooth_length() * f64::from(self.spec.teeth),
        }
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.breakpoints.clone()
    }
    fn symmetry(&self) -> u32 {
        self.spec.teeth
    }
}

#[cfg(test)]
mod tests;
