//! Units at the boundary: the library computes in the mechanism file's length unit, radians and
//! seconds; every number a front end (the command, the Python package) writes or draws is
//! converted here, once, and every column name, JSON key and axis label says its unit.
//!
//! Column names carry the unit as a suffix (`position_mm`, `velocity_mm_s`, `acceleration_mm_s2`,
//! `velocity_deg_deg` per degree of cam angle); labels use symbols (`mm/s²`).

use crate::cam::Mechanism;
use crate::spec::LengthUnit;

/// The unit of an oscillating follower's arm angle in output.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AngleUnit {
    /// degrees (the default)
    #[default]
    Deg,
    /// radians
    Rad,
}

/// What the follower's derivatives are taken with respect to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Per {
    /// time: velocity in mm/s, acceleration in mm/s², jerk in mm/s³ (the default)
    #[default]
    S,
    /// the cam angle in degrees: ds/dθ in mm/deg, d²s/dθ² in mm/deg², d³s/dθ³ in mm/deg³, as cam
    /// tools print them
    Deg,
}

/// A unit name that is not one of the choices.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{value:?} is not a choice here: {choices}")]
pub struct UnknownUnit {
    /// what was given
    pub value: String,
    /// the choices, comma-separated
    pub choices: &'static str,
}

impl std::str::FromStr for AngleUnit {
    type Err = UnknownUnit;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "deg" => Ok(Self::Deg),
            "rad" => Ok(Self::Rad),
            _ => Err(UnknownUnit {
                value: s.into(),
                choices: "deg, rad",
            }),
        }
    }
}

impl std::str::FromStr for Per {
    type Err = UnknownUnit;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "s" => Ok(Self::S),
            "deg" => Ok(Self::Deg),
            _ => Err(UnknownUnit {
                value: s.into(),
                choices: "s, deg",
            }),
        }
    }
}

/// The units of one run's output.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Units {
    /// the mechanism file's length unit
    pub length: LengthUnit,
    /// the arm angle's unit (oscillating followers)
    pub angle: AngleUnit,
    /// derivatives per second or per degree of cam angle
    pub per: Per,
    /// the follower coordinate is an angle
    pub oscillating: bool,
    /// the follower is conjugate (form-closed): the analysis has a play column
    pub conjugate: bool,
    /// the follower carries a curve of its own: the analysis and contacts have a corner column
    pub carried: bool,
    /// cam speed, rad/s (for derivatives per degree)
    omega: f64,
    /// cam angular acceleration, rad/s²
    alpha: f64,
}

/// Superscripts of the derivative orders, for symbols.
const SUP: [&str; 4] = ["", "", "²", "³"];

impl Units {
    /// The units of a mechanism's output.
    pub fn new(mech: &Mechanism, length: LengthUnit, angle: AngleUnit, per: Per) -> Self {
        Self {
            length,
            angle,
            per,
            oscillating: mech.follower().is_oscillating(),
            conjugate: mech.is_conjugate(),
            carried: mech.carries_curve(),
            omega: mech.cam().speed(),
            alpha: mech.cam().angular_acceleration(),
        }
    }

    /// Time derivatives, arm angles in degrees.
    pub fn plain(mech: &Mechanism, length: LengthUnit) -> Self {
        Self::new(mech, length, AngleUnit::Deg, Per::S)
    }

    /// The length unit's symbol (`mm`).
    pub fn len(&self) -> &'static str {
        self.length.name()
    }

    /// The follower coordinate's unit: the length, or `deg`/`rad` for an arm.
    pub fn coord(&self) -> &'static str {
        if !self.oscillating {
            self.len()
        } else {
            match self.angle {
                AngleUnit::Deg => "deg",
                AngleUnit::Rad => "rad",
            }
        }
    }

    /// Symbol of the coordinate's `order`-th derivative (0 to 3): `mm`, `mm/s`, `mm/s²`, `deg/s³`,
    /// or `mm/deg²` per degree of cam angle. An arm's angle in degrees reads `°` alone.
    pub fn motion_symbol(&self, order: usize) -> String {
        let c = match self.coord() {
            "deg" => "°",
            c => c,
        };
        if order == 0 {
            return c.to_string();
        }
        let per = match self.per {
            Per::S => "s",
            Per::Deg => "°",
        };
        format!("{c}/{per}{}", SUP[order])
    }

    /// Column-name suffix of the coordinate's `order`-th derivative: `mm`, `mm_s`, `mm_s2`,
    /// `deg_deg3`.
    pub fn motion_key(&self, order: usize) -> String {
        let c = self.coord();
        if order == 0 {
            return c.to_string();
        }
        let per = match self.per {
            Per::S => "s",
            Per::Deg => "deg",
        };
        let pow = if order == 1 {
            String::new()
        } else {
            order.to_string()
        };
        format!("{c}_{per}{pow}")
    }

    /// A position or a difference of positions (lift) in output units.
    pub fn coord_value(&self, q: f64) -> f64 {
        if self.oscillating && self.angle == AngleUnit::Deg {
            q.to_degrees()
        } else {
            q
        }
    }

    /// `[position, velocity, acceleration, jerk]` in output units, from the library's values
    /// (the file's length or radians, per second). Per degree of cam angle:
    /// `q' = q̇/ω`, `q'' = (q̈ − q' θ̈)/ω²`, `q''' = (q⃛ − 3 ω θ̈ q'')/ω³` (θ̈ constant), each
    /// then per degree.
    pub fn motion(&self, q: f64, v: f64, a: f64, j: Option<f64>) -> [Option<f64>; 4] {
        let k = self.coord_value(1.0);
        let (v, a, j) = match self.per {
            Per::S => (v, a, j),
            Per::Deg => {
                let (w, al) = (self.omega, self.alpha);
                let d = std::f64::consts::PI / 180.0;
                let q1 = v / w;
                let q2 = (a - q1 * al) / (w * w);
                let q3 = j.map(|j| (j - 3.0 * w * al * q2) / (w * w * w));
                (q1 * d, q2 * d * d, q3.map(|x| x * d * d * d))
            }
        };
        [Some(k * q), Some(k * v), Some(k * a), j.map(|j| k * j)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_and_symbols() {
        let m = crate::reference::paper_mechanism(false);
        let u = Units::new(&m, LengthUnit::Mm, AngleUnit::Deg, Per::S);
        assert_eq!(
            (0..4).map(|k| u.motion_key(k)).collect::<Vec<_>>(),
            ["mm", "mm_s", "mm_s2", "mm_s3"]
        );
        assert_eq!(u.motion_symbol(2), "mm/s²");
        let u = Units::new(&m, LengthUnit::In, AngleUnit::Deg, Per::Deg);
        assert_eq!(u.motion_key(3), "in_deg3");
        assert_eq!(u.motion_symbol(1), "in/°");
    }
}
