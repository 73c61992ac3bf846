//! `[gear_loads]`: the load a gear pair's file puts on its teeth, and the one rule that merges
//! it with what a front end was given (a flag, a keyword) into the gear load report's inputs.
//!
//! ```toml
//! [gear_loads]
//! torque = 50.0          # N·m on the driver; or power_kw = 5.2 (at the file's speed)
//! face_width = 20.0      # the teeth's face width, in the file's length unit
//! materials = "steel,steel"  # the driver's and the driven gear's (optional)
//! ```
//!
//! `face_width` and `materials` may come from `[lubrication]` instead; given in both, they must
//! agree.

use super::{Built, SpecError};
use crate::field::{Field, GearLoadsField as G};
use crate::report::{plausible_face_width, Materials};

/// `[gear_loads]` as written.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GearLoadsSpec {
    /// the torque on the driver, N·m
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub torque: Option<f64>,
    /// the power the driver transmits, kW (the torque is `P/ω` at the file's speed)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub power_kw: Option<f64>,
    /// the teeth's face width, in the file's length unit
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub face_width: Option<f64>,
    /// `"DRIVER,DRIVEN"` materials (default `[lubrication]`'s, else steel on steel)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub materials: Option<String>,
}

/// `[gear_loads]` checked: the torque (a power turned into one), and what the section gave of
/// the rest.
#[derive(Debug, Clone, PartialEq)]
pub struct BuiltGearLoads {
    /// the torque on the driver, N·m
    pub torque: f64,
    /// the face width, in the file's length unit (`None`: `[lubrication]`'s)
    pub face_width: Option<f64>,
    /// the materials (`None`: `[lubrication]`'s, else steel on steel)
    pub materials: Option<Materials>,
}

/// The power-to-torque rule: `T = P/ω`, ω the driver's speed in rad/s. `None` where the driver
/// stands still.
pub fn torque_from_power(power_w: f64, omega: f64) -> Option<f64> {
    (omega != 0.0).then(|| power_w / omega.abs())
}

fn positive(field: Field, v: f64, unit: &str) -> Result<f64, SpecError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(SpecError::Invalid {
            field,
            value: crate::human::human(v),
            reason: format!("must be positive ({unit})"),
        })
    }
}

impl GearLoadsSpec {
    /// Checks every value, naming its field; `omega` is the driver's speed (rad/s) a power is
    /// turned into a torque at, `lubrication` the file's `[lubrication]` the face width and the
    /// materials must agree with.
    pub fn build(
        &self,
        omega: f64,
        lubrication: Option<&super::BuiltLubrication>,
    ) -> Result<BuiltGearLoads, SpecError> {
        let f = Field::GearLoads;
        let torque = match (self.torque, self.power_kw) {
            (Some(_), Some(_)) => {
                return Err(SpecError::Rule {
                    field: f(G::PowerKw),
                    reason: "give the torque or the power, not both".into(),
                })
            }
            (None, None) => {
                return Err(SpecError::Rule {
                    field: f(G::Table),
                    reason: "needs `torque` (N·m on the driver) or `power_kw`".into(),
                })
            }
            (Some(t), None) => positive(f(G::Torque), t, "N·m on the driver")?,
            (None, Some(p)) => {
                let p = positive(f(G::PowerKw), p, "kW")?;
                torque_from_power(p * 1e3, omega).ok_or_else(|| SpecError::Rule {
                    field: f(G::PowerKw),
                    reason: "a power needs a turning driver (speed_rpm is 0): give the torque"
                        .into(),
                })?
            }
        };
        let face_width = self
            .face_width
            .map(|w| positive(f(G::FaceWidth), w, "the file's length unit"))
            .transpose()?;
        if let (Some(w), Some(l)) = (face_width, lubrication) {
            if w != l.face_width {
                return Err(SpecError::Rule {
                    field: f(G::FaceWidth),
                    reason: format!(
                        "{} differs from lubrication.face_width = {}: the teeth have one width",
                        crate::human::human(w),
                        crate::human::human(l.face_width)
                    ),
                });
            }
        }
        let materials = self
            .materials
            .as_ref()
            .map(|m| {
                m.parse::<Materials>()
                    .map_err(|e: crate::report::MaterialError| SpecError::Rule {
                        field: f(G::Materials),
                        reason: e.to_string(),
                    })
            })
            .transpose()?;
        if let (Some(m), Some(l)) = (&materials, lubrication) {
            if *m != l.materials {
                return Err(SpecError::Rule {
                    field: f(G::Materials),
                    reason: "differs from lubrication.materials: give them once".into(),
                });
            }
        }
        Ok(BuiltGearLoads {
            torque,
            face_width,
            materials,
        })
    }
}

/// What a front end was given for a gear pair's loads, each replacing the file's value: a flag
/// or a keyword.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct GivenLoads {
    /// the torque on the driver, N·m
    pub torque: Option<f64>,
    /// the power, kW
    pub power_kw: Option<f64>,
    /// the face width, in the file's length unit
    pub face_width: Option<f64>,
    /// the materials
    pub materials: Option<Materials>,
}

/// Which input of [`GivenLoads`] (or the file's section) an error is about; front ends name it
/// their way (`--torque`, `torque=`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum LoadInput {
    /// the torque
    Torque,
    /// the power
    Power,
    /// the face width
    FaceWidth,
}

/// A gear load input that cannot be used: which, its value as given, and why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{reason}")]
pub struct LoadInputError {
    /// the input
    pub input: LoadInput,
    /// its value, for people (`None`: it is missing)
    pub value: Option<String>,
    /// what is wrong
    pub reason: String,
}

/// A gear pair's loads' inputs, merged and checked.
#[derive(Debug, Clone, PartialEq)]
pub struct ResolvedLoads {
    /// the torque on the driver, N·m
    pub torque: f64,
    /// the face width, m
    pub face_width: f64,
    /// the materials
    pub materials: Materials,
}

impl Built {
    /// The gear load report's inputs: each of `given` replaces the file's (`[gear_loads]`,
    /// then `[lubrication]` for the face width and the materials). A power is turned into a
    /// torque at the file's speed.
    pub fn gear_loads_inputs(&self, given: &GivenLoads) -> Result<ResolvedLoads, LoadInputError> {
        let file = self.gear_loads.as_ref();
        let lub = self.lubrication.as_ref();
        let human = crate::human::human;
        let err = |input, value: Option<f64>, reason: String| LoadInputError {
            input,
            value: value.map(human),
            reason,
        };
        if let (Some(t), Some(p)) = (given.torque, given.power_kw) {
            return Err(err(
                LoadInput::Power,
                Some(p),
                format!("give the torque ({} N·m) or the power, not both", human(t)),
            ));
        }
        let omega = self.mechanism.cam().speed();
        let torque = match (given.torque, given.power_kw) {
            (Some(t), _) => {
                if !(t.is_finite() && t > 0.0) {
                    return Err(err(
                        LoadInput::Torque,
                        Some(t),
                        "the torque on the driver must be positive (N·m)".into(),
                    ));
                }
                t
            }
            (None, Some(p)) => {
                if !(p.is_finite() && p > 0.0) {
                    return Err(err(
                        LoadInput::Power,
                        Some(p),
                        "the power must be positive (kW)".into(),
                    ));
                }
                torque_from_power(p * 1e3, omega).ok_or_else(|| {
                    err(
                        LoadInput::Power,
                        Some(p),
                        "a power needs a turning driver (the file's speed is 0): give the torque"
                            .into(),
                    )
                })?
            }
            (None, None) => file.map(|f| f.torque).ok_or_else(|| {
                err(
                    LoadInput::Torque,
                    None,
                    "a gear pair's loads need the torque on the driver (N·m) or the power (kW)"
                        .into(),
                )
            })?,
        };
        let unit = self.length_unit;
        let width = given
            .face_width
            .or(file.and_then(|f| f.face_width))
            .or(lub.map(|l| l.face_width))
            .ok_or_else(|| {
                err(
                    LoadInput::FaceWidth,
                    None,
                    format!(
                        "the loads along the path need the teeth's face width ({})",
                        unit.name()
                    ),
                )
            })?;
        // the mechanism's size in metres, whichever unit it was built in
        let size = self.mechanism.size() * if self.si { 1.0 } else { unit.metres() };
        if !(width > 0.0 && plausible_face_width(width * unit.metres(), size)) {
            return Err(err(
                LoadInput::FaceWidth,
                Some(width),
                format!(
                    "{} {} must be positive and from 1e-3 to 1e3 times the gears' size",
                    human(width),
                    unit.name()
                ),
            ));
        }
        let materials = given
            .materials
            .clone()
            .or(file.and_then(|f| f.materials.clone()))
            .or(lub.map(|l| l.materials.clone()))
            .unwrap_or_default();
        Ok(ResolvedLoads {
            torque,
            face_width: width * unit.metres(),
            materials,
        })
    }
}
