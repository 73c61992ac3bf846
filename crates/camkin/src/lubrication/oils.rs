//! Lubricants by name or by their two constants, `eta=<Pa·s>:alpha=<1/Pa>`, checked for
//! plausibility (a viscosity typed in mPa·s, or α in 1/GPa, is refused, not taken).

use super::Lubricant;
use std::str::FromStr;

/// The viscosities taken as plausible, Pa·s: from a light spindle oil hot (about 1 mPa·s; 0.1
/// allowed) to a heavy gear oil cold (about 10 Pa·s; 100 allowed).
pub const VISCOSITY_RANGE: (f64, f64) = (1e-4, 100.0);

/// The pressure–viscosity coefficients taken as plausible, 1/Pa: 0 (a fluid whose viscosity does
/// not grow with pressure: no EHL film enhancement) to 1e-7 (mineral oils 1e-8 to 3e-8,
/// traction fluids up to about 4e-8).
pub const PRESSURE_VISCOSITY_RANGE: (f64, f64) = (0.0, 1e-7);

/// Named oils: `(name, kinematic viscosity in mm²/s at the named temperature, density in kg/m³ at
/// it, the temperature in °C)`. The viscosities are each grade's midpoint: SAE J300's engine oil
/// grades at 100 °C (SAE 20: 6.9 to 9.3 mm²/s, SAE 30: 9.3 to 12.5, SAE 40: 12.5 to 16.3, SAE 50:
/// 16.3 to 21.9) and ISO 3448's industrial grades at 40 °C (ISO VG n: n mm²/s ± 10 %). The
/// densities are a mineral oil's (870 kg/m³ at 15 °C, less 0.64 kg/m³ a kelvin: 854 at 40 °C,
/// 816 at 100 °C), and every preset takes a mineral oil's pressure–viscosity coefficient,
/// 2e-8 1/Pa; give `eta=…:alpha=…` for an oil whose data sheet says otherwise, and at the
/// contact's inlet temperature.
pub const OIL_PRESETS: [(&str, f64, f64, f64); 11] = [
    ("sae-20@100c", 8.1, 816.0, 100.0),
    ("sae-30@100c", 10.9, 816.0, 100.0),
    ("sae-40@100c", 14.4, 816.0, 100.0),
    ("sae-50@100c", 19.1, 816.0, 100.0),
    ("iso-vg-32@40c", 32.0, 854.0, 40.0),
    ("iso-vg-46@40c", 46.0, 854.0, 40.0),
    ("iso-vg-68@40c", 68.0, 854.0, 40.0),
    ("iso-vg-100@40c", 100.0, 854.0, 40.0),
    ("iso-vg-150@40c", 150.0, 854.0, 40.0),
    ("iso-vg-220@40c", 220.0, 854.0, 40.0),
    ("iso-vg-320@40c", 320.0, 854.0, 40.0),
];

/// The pressure–viscosity coefficient every preset takes, 1/Pa.
const PRESET_ALPHA: f64 = 2e-8;

/// What is wrong with a lubricant as written.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LubricantError {
    /// Neither a preset nor `eta=…:alpha=…`.
    #[error("{text:?} is not a lubricant: a preset ({}) or eta=<Pa·s>:alpha=<1/Pa>, e.g. eta=0.009:alpha=2e-8", preset_names())]
    Unknown {
        /// the text as written
        text: String,
    },
    /// A key other than `eta` and `alpha`, a value missing, repeated or not a number.
    #[error(
        "{text:?}: {problem}: a lubricant is eta=<Pa·s>:alpha=<1/Pa>, e.g. eta=0.009:alpha=2e-8"
    )]
    BadValue {
        /// the text as written
        text: String,
        /// what is wrong
        problem: String,
    },
    /// A value outside its plausible range.
    #[error("{text:?}: {key} = {value} {unit} is not plausible (from {lo} to {hi} {unit}){hint}")]
    Implausible {
        /// the text as written
        text: String,
        /// `eta` or `alpha`
        key: &'static str,
        /// the value as written
        value: String,
        /// its unit
        unit: &'static str,
        /// the range's ends
        lo: f64,
        /// the range's ends
        hi: f64,
        /// a hint on the unit
        hint: &'static str,
    },
}

fn preset_names() -> String {
    OIL_PRESETS.map(|p| p.0).join(", ")
}

impl Lubricant {
    /// A named oil of [`OIL_PRESETS`].
    pub fn preset(name: &str) -> Option<Self> {
        OIL_PRESETS
            .iter()
            .find(|p| p.0 == name)
            .map(|&(_, nu, rho, _)| Self {
                viscosity: nu * 1e-6 * rho,
                pressure_viscosity: PRESET_ALPHA,
            })
    }
}

impl FromStr for Lubricant {
    type Err = LubricantError;
    fn from_str(s: &str) -> Result<Self, LubricantError> {
        let t = s.trim();
        if let Some(l) = Self::preset(t) {
            return Ok(l);
        }
        if !t.contains('=') {
            return Err(LubricantError::Unknown { text: t.into() });
        }
        let bad = |problem: String| LubricantError::BadValue {
            text: t.into(),
            problem,
        };
        // each value with its text as written
        let mut eta: Option<(f64, &str)> = None;
        let mut alpha: Option<(f64, &str)> = None;
        for part in t.split(':') {
            let (k, v) = part
                .split_once('=')
                .ok_or_else(|| bad(format!("{part:?} is not key=value")))?;
            let slot = match k.trim() {
                "eta" => &mut eta,
                "alpha" => &mut alpha,
                other => return Err(bad(format!("unknown key {other:?}"))),
            };
            if slot.is_some() {
                return Err(bad(format!("{} is given twice", k.trim())));
            }
            let v = v.trim();
            let x = v
                .parse::<f64>()
                .map_err(|_| bad(format!("{} = {v:?} is not a number", k.trim())))?;
            *slot = Some((x, v));
        }
        let (eta, eta_text) = eta.ok_or_else(|| bad("eta is missing".into()))?;
        let (alpha, alpha_text) = alpha.ok_or_else(|| bad("alpha is missing".into()))?;
        if !(eta >= VISCOSITY_RANGE.0 && eta <= VISCOSITY_RANGE.1) {
            let hint = if eta * 1e-3 >= VISCOSITY_RANGE.0 && eta * 1e-3 <= VISCOSITY_RANGE.1 {
                ": eta is in Pa·s; did you write mPa·s (cP)? 9 mPa·s is eta=0.009"
            } else {
                ""
            };
            return Err(LubricantError::Implausible {
                text: t.into(),
                key: "eta",
                value: eta_text.into(),
                unit: "Pa·s",
                lo: VISCOSITY_RANGE.0,
                hi: VISCOSITY_RANGE.1,
                hint,
            });
        }
        if !(alpha >= PRESSURE_VISCOSITY_RANGE.0 && alpha <= PRESSURE_VISCOSITY_RANGE.1) {
            let hint = if alpha * 1e-9 > 0.0 && alpha * 1e-9 <= PRESSURE_VISCOSITY_RANGE.1 {
                ": alpha is in 1/Pa; did you write 1/GPa? 20 1/GPa is alpha=2e-8"
            } else {
                ""
            };
            return Err(LubricantError::Implausible {
                text: t.into(),
                key: "alpha",
                value: alpha_text.into(),
                unit: "1/Pa",
                lo: PRESSURE_VISCOSITY_RANGE.0,
                hi: PRESSURE_VISCOSITY_RANGE.1,
                hint,
            });
        }
        Ok(Self {
            viscosity: eta,
            pressure_viscosity: alpha,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_dynamic_viscosities_in_pascal_seconds() {
        // SAE 30 at 100 °C: 10.9 mm²/s × 816 kg/m³ = 8.894 mPa·s
        let l: Lubricant = "sae-30@100c".parse().unwrap();
        assert!((l.viscosity - 8.8944e-3).abs() < 1e-9, "{l:?}");
        assert_eq!(l.pressure_viscosity, 2e-8);
        // ISO VG 68 at 40 °C: 68 × 854 = 58.07 mPa·s
        let l: Lubricant = "iso-vg-68@40c".parse().unwrap();
        assert!((l.viscosity - 58.072e-3).abs() < 1e-9);
        let l: Lubricant = "eta=0.009:alpha=2.2e-8".parse().unwrap();
        assert_eq!((l.viscosity, l.pressure_viscosity), (0.009, 2.2e-8));
        for p in OIL_PRESETS {
            let l = Lubricant::preset(p.0).unwrap();
            assert!(l.viscosity >= VISCOSITY_RANGE.0 && l.viscosity <= VISCOSITY_RANGE.1);
        }
    }

    #[test]
    fn implausible_and_unknown_oils_are_refused_naming_the_text() {
        for (text, needle) in [
            ("eta=9000:alpha=2e-8", "did you write mPa·s"),
            ("eta=-0.01:alpha=2e-8", "eta = -0.01"),
            ("eta=0:alpha=2e-8", "eta = 0"),
            ("eta=NaN:alpha=2e-8", "eta = NaN"),
            ("eta=0.01:alpha=20", "did you write 1/GPa"),
            ("eta=0.01:alpha=-1e-8", "alpha = -1e-8"),
            ("eta=0.01", "alpha is missing"),
            ("eta=0.01:eta=0.02:alpha=2e-8", "eta is given twice"),
            ("eta=0.01:alpha=2e-8:rho=850", "unknown key \"rho\""),
            ("eta=0.0l:alpha=2e-8", "is not a number"),
            ("castor", "is not a lubricant"),
        ] {
            let e = text.parse::<Lubricant>().unwrap_err().to_string();
            assert!(e.contains(needle), "{text}: {e}");
            assert!(e.contains(text), "{text}: the message names the text: {e}");
        }
    }
}
