//! Elastic materials for the Hertz contact stress: named presets and `E=<Pa>:nu=<ratio>`, each
//! checked for plausibility (a modulus typed in GPa where Pa is asked for is refused, not taken
//! as a thousand-millionth of steel).

use crate::human::human;
use std::fmt;
use std::str::FromStr;

/// A material's elastic constants.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Material {
    /// its name (a preset's, or `E = … GPa, ν = …`)
    pub name: String,
    /// Young's modulus, Pa
    pub e: f64,
    /// Poisson's ratio
    pub nu: f64,
    /// thermal conductivity, density and specific heat, for the flash temperature (`None`: not
    /// given)
    pub thermal: Option<crate::lubrication::Thermal>,
}

/// Named materials: nominal handbook values, E in GPa and ν (ASM Handbook vol. 1 and 2; the
/// steels' 200–210 GPa, ductile and grey cast iron 169 and 100 GPa, bronze 110 GPa).
pub const PRESETS: [(&str, f64, f64); 8] = [
    ("steel", 206.0, 0.30),
    ("aisi-52100", 210.0, 0.30),
    ("aisi-4140", 205.0, 0.29),
    ("aisi-1045", 206.0, 0.29),
    ("stainless-440c", 200.0, 0.28),
    ("ductile-iron", 169.0, 0.28),
    ("cast-iron", 100.0, 0.26),
    ("bronze", 110.0, 0.34),
];

/// The presets' thermal constants at room temperature, in [`PRESETS`]' order: conductivity
/// W/(m·K), density kg/m³, specific heat J/(kg·K) (nominal handbook values, ASM Handbook vol. 1
/// and 2: plain carbon steel 50, 7850, 470; AISI 52100 46.6, 7810, 475; AISI 4140 42.6, 7850,
/// 473; AISI 1045 49.8, 7870, 486; 440C 24.2, 7800, 460; ductile iron 36, 7100, 506; grey iron
/// 46, 7200, 490; phosphor bronze 69.6, 8860, 380).
pub const THERMAL_PRESETS: [(f64, f64, f64); 8] = [
    (50.0, 7850.0, 470.0),
    (46.6, 7810.0, 475.0),
    (42.6, 7850.0, 473.0),
    (49.8, 7870.0, 486.0),
    (24.2, 7800.0, 460.0),
    (36.0, 7100.0, 506.0),
    (46.0, 7200.0, 490.0),
    (69.6, 8860.0, 380.0),
];

/// The range of Young's modulus taken as plausible for a cam, follower or gear, Pa: from
/// engineering plastics (about 1 GPa; 0.5 GPa allowed) to tungsten carbide (about 700 GPa;
/// 1200 GPa allowed, diamond's).
pub const MODULUS_RANGE_PA: (f64, f64) = (0.5e9, 1.2e12);

/// The range of Poisson's ratio taken as plausible: `[0, 0.5)` (metals 0.26–0.35, plastics up to
/// 0.45; 0.5 is incompressible, where `1 − ν²` no longer describes a solid that takes a load).
pub const POISSON_RANGE: (f64, f64) = (0.0, 0.5);

/// What is wrong with a material as written.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MaterialError {
    /// Neither a preset nor `E=…:nu=…`.
    #[error(
        "{text:?} is not a material: a preset ({}) or E=<Pa>:nu=<ratio>, e.g. E=210e9:nu=0.3",
        preset_names()
    )]
    Unknown {
        /// the text as written
        text: String,
    },
    /// A key other than `E` and `nu`.
    #[error("{text:?}: unknown key {key:?}: a material is E=<Pa>:nu=<ratio> (Young's modulus and Poisson's ratio), with k=<W/(m·K)>:rho=<kg/m³>:c=<J/(kg·K)> for the flash temperature, e.g. E=210e9:nu=0.3:k=50:rho=7850:c=470")]
    UnknownKey {
        /// the text as written
        text: String,
        /// the key
        key: String,
    },
    /// `E` or `nu` is missing, repeated or not a number.
    #[error("{text:?}: {key} {problem}: a material is E=<Pa>:nu=<ratio>, e.g. E=210e9:nu=0.3")]
    BadValue {
        /// the text as written
        text: String,
        /// `E` or `nu`
        key: &'static str,
        /// what is wrong
        problem: &'static str,
    },
    /// `E` outside [`MODULUS_RANGE_PA`].
    #[error("{text:?}: E = {value} Pa is not a plausible Young's modulus (from {} to {} GPa){hint}", human(MODULUS_RANGE_PA.0 / 1e9), human(MODULUS_RANGE_PA.1 / 1e9))]
    ImplausibleModulus {
        /// the text as written
        text: String,
        /// E as written
        value: String,
        /// a hint on the unit
        hint: &'static str,
    },
    /// `nu` outside [`POISSON_RANGE`].
    #[error("{text:?}: nu = {value} is not a plausible Poisson's ratio (from 0 to below 0.5; metals 0.26 to 0.35)")]
    ImplausiblePoisson {
        /// the text as written
        text: String,
        /// ν as written
        value: String,
    },
}

fn preset_names() -> String {
    PRESETS.map(|p| p.0).join(", ")
}

impl FromStr for Material {
    type Err = MaterialError;
    fn from_str(s: &str) -> Result<Self, MaterialError> {
        let t = s.trim();
        if let Some(i) = PRESETS.iter().position(|p| p.0 == t) {
            let ((n, e, nu), (k, rho, c)) = (PRESETS[i], THERMAL_PRESETS[i]);
            return Ok(Self {
                name: n.into(),
                e: e * 1e9,
                nu,
                thermal: Some(crate::lubrication::Thermal {
                    conductivity: k,
                    density: rho,
                    specific_heat: c,
                }),
            });
        }
        if !t.contains('=') {
            return Err(MaterialError::Unknown { text: t.into() });
        }
        let text = || t.to_string();
        let mut e: Option<(f64, &str)> = None;
        let mut nu: Option<(f64, &str)> = None;
        let mut cond: Option<(f64, &str)> = None;
        let mut rho: Option<(f64, &str)> = None;
        let mut c: Option<(f64, &str)> = None;
        for part in t.split(':') {
            let Some((k, v)) = part.split_once('=') else {
                return Err(MaterialError::Unknown { text: text() });
            };
            let (key, slot): (&'static str, &mut Option<(f64, &str)>) = match k.trim() {
                "E" => ("E", &mut e),
                "nu" => ("nu", &mut nu),
                "k" => ("k", &mut cond),
                "rho" => ("rho", &mut rho),
                "c" => ("c", &mut c),
                other => {
                    return Err(MaterialError::UnknownKey {
                        text: text(),
                        key: other.into(),
                    })
                }
            };
            if slot.is_some() {
                return Err(MaterialError::BadValue {
                    text: text(),
                    key,
                    problem: "is given twice",
                });
            }
            let v = v.trim();
            let x = v.parse::<f64>().map_err(|_| MaterialError::BadValue {
                text: text(),
                key,
                problem: "is not a number",
            })?;
            *slot = Some((x, v));
        }
        let missing = |key| MaterialError::BadValue {
            text: text(),
            key,
            problem: "is missing",
        };
        let (e, e_text) = e.ok_or_else(|| missing("E"))?;
        let (nu, nu_text) = nu.ok_or_else(|| missing("nu"))?;
        if !(e >= MODULUS_RANGE_PA.0 && e <= MODULUS_RANGE_PA.1) {
            let hint = if e > 0.0 && e * 1e9 >= MODULUS_RANGE_PA.0 && e * 1e9 <= MODULUS_RANGE_PA.1
            {
                ": E is in Pa; did you mean GPa? write E=210e9 for 210 GPa"
            } else {
                ""
            };
            return Err(MaterialError::ImplausibleModulus {
                text: text(),
                value: e_text.into(),
                hint,
            });
        }
        if !(nu >= POISSON_RANGE.0 && nu < POISSON_RANGE.1) {
            return Err(MaterialError::ImplausiblePoisson {
                text: text(),
                value: nu_text.into(),
            });
        }
        // the thermal constants: all three or none, each positive
        let thermal = match (cond, rho, c) {
            (None, None, None) => None,
            (Some(k), Some(rho), Some(c)) => {
                for (key, (v, v_text)) in [("k", k), ("rho", rho), ("c", c)] {
                    if !(v.is_finite() && v > 0.0) {
                        return Err(MaterialError::BadValue {
                            text: text(),
                            key,
                            problem: if v_text.is_empty() {
                                "is missing"
                            } else {
                                "must be a positive number"
                            },
                        });
                    }
                }
                Some(crate::lubrication::Thermal {
                    conductivity: k.0,
                    density: rho.0,
                    specific_heat: c.0,
                })
            }
            (k, rho, _) => {
                return Err(MaterialError::BadValue {
                    text: text(),
                    key: if k.is_none() {
                        "k"
                    } else if rho.is_none() {
                        "rho"
                    } else {
                        "c"
                    },
                    problem: "is missing (the thermal constants k, rho and c are given together)",
                })
            }
        };
        Ok(Self {
            name: format!("E = {} GPa, ν = {nu}", human(e / 1e9)),
            e,
            nu,
            thermal,
        })
    }
}

impl fmt::Display for Material {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name)
    }
}

/// The cam's and the follower's materials, written `CAM,FOLLOWER`.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Materials {
    /// the cam's (the driving gear's)
    pub cam: Material,
    /// the follower's (the driven gear's)
    pub follower: Material,
}

impl Default for Materials {
    /// Steel on steel.
    fn default() -> Self {
        let steel = || Material::from_str("steel").expect("a preset");
        Self {
            cam: steel(),
            follower: steel(),
        }
    }
}

impl Materials {
    /// `E*` of the pair: `1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂`, Pa.
    pub fn effective_modulus(&self) -> f64 {
        crate::dynamics::effective_modulus(
            self.cam.e,
            self.cam.nu,
            self.follower.e,
            self.follower.nu,
        )
    }
}

impl FromStr for Materials {
    type Err = MaterialError;
    fn from_str(s: &str) -> Result<Self, MaterialError> {
        let (a, b) = s.split_once(',').ok_or_else(|| MaterialError::Unknown {
            text: format!("{s} (CAM,FOLLOWER is needed, e.g. steel,steel)"),
        })?;
        Ok(Self {
            cam: a.parse()?,
            follower: b.parse()?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_in_pascal() {
        let m: Material = "steel".parse().unwrap();
        assert_eq!(m.e, 206e9);
        assert_eq!(m.nu, 0.3);
        let m: Material = "E=210e9:nu=0.3".parse().unwrap();
        assert_eq!((m.e, m.nu), (210e9, 0.3));
        assert_eq!(m.name, "E = 210 GPa, ν = 0.3");
        // steel on steel: E* = E / (2 (1 − ν²)) = 206 / 1.82 GPa
        let both = Materials::default();
        assert!((both.effective_modulus() - 206e9 / 1.82).abs() < 1e-3);
    }

    #[test]
    fn implausible_and_unknown_input_is_refused_naming_it() {
        for (text, needle) in [
            ("E=210:nu=0.3", "did you mean GPa"),
            ("E=210e9:nu=-1", "nu = -1"),
            ("E=210e9:nu=0.5", "nu = 0.5"),
            ("E=5e-324:nu=0.3", "E = 5e-324 Pa"),
            ("E=inf:nu=0.3", "E = inf Pa"),
            ("E=NaN:nu=0.3", "E = NaN Pa"),
            ("E=210e9:nu=0.3:rho=7800", "k is missing"),
            ("E=210e9:nu=0.3:k=50:rho=7800", "c is missing"),
            (
                "E=210e9:nu=0.3:k=-50:rho=7800:c=470",
                "k must be a positive number",
            ),
            ("E=210e9:nu=0.3:T=300", "unknown key \"T\""),
            ("E=210e9", "nu is missing"),
            ("E=210e9:E=200e9:nu=0.3", "E is given twice"),
            ("E=2l0e9:nu=0.3", "E is not a number"),
            ("unobtainium", "is not a material"),
        ] {
            let e = text.parse::<Material>().unwrap_err().to_string();
            assert!(e.contains(needle), "{text}: {e}");
            assert!(e.contains(text), "{text}: the message names the text: {e}");
        }
        assert!("steel".parse::<Materials>().is_err());
        assert!("steel,bronze".parse::<Materials>().is_ok());
    }
}
