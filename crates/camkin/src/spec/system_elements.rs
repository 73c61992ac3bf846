//! A system file's force elements' tables (`[[spring]]`, `[[damper]]`, `[[torsion_spring]]`)
//! and the rules every element of a system file keeps: one name an element, and magnitudes
//! within the range the dynamics is computed in.

use super::build::SpecError;
use super::SystemSpec;
use crate::field::{Field, SystemField, SystemKey, SystemTable};
use std::collections::HashMap;

/// `[[spring]]`: `stiffness` N per length, `free_length` (length), `preload` N at it.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpringSpec {
    /// its name
    pub name: String,
    /// the two bodies its ends are on
    #[serde(deserialize_with = "super::pair::names")]
    pub bodies: [String; 2],
    /// its ends, each in its body's frame
    #[serde(deserialize_with = "super::pair::points")]
    pub at: [[f64; 2]; 2],
    /// N per length unit
    pub stiffness: f64,
    /// length unit
    pub free_length: f64,
    /// N (default 0)
    pub preload: Option<f64>,
}

/// `[[damper]]`: `damping` N·s per length.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DamperSpec {
    /// its name
    pub name: String,
    /// the two bodies its ends are on
    #[serde(deserialize_with = "super::pair::names")]
    pub bodies: [String; 2],
    /// its ends, each in its body's frame
    #[serde(deserialize_with = "super::pair::points")]
    pub at: [[f64; 2]; 2],
    /// N·s per length unit
    pub damping: f64,
}

/// `[[torsion_spring]]`: `stiffness` N·length per rad, `free_angle_deg`, `preload` N·length.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TorsionSpringSpec {
    /// its name
    pub name: String,
    /// the two bodies whose relative angle it resists
    #[serde(deserialize_with = "super::pair::names")]
    pub bodies: [String; 2],
    /// N·length unit per rad
    pub stiffness: f64,
    /// degrees (default 0)
    pub free_angle_deg: Option<f64>,
    /// N·length unit (default 0)
    pub preload: Option<f64>,
}

/// `x` (as written, at `field`) within the range a simulation is computed in: its magnitude
/// from `lo` to `hi`, or zero where `lo` is (the cam follower's dynamics' ranges: wide for any
/// machine, narrow enough that forces, energies and rates stay far from overflow).
pub(super) fn within(field: Field, x: f64, lo: f64, hi: f64) -> Result<f64, SpecError> {
    if x == 0.0 && lo == 0.0 || (lo..=hi).contains(&x.abs()) {
        Ok(x)
    } else {
        Err(SpecError::Invalid {
            field,
            value: crate::human::human(x),
            reason: format!(
                "is outside the range the dynamics is computed in ({}{} to {})",
                if lo == 0.0 { "" } else { "magnitude " },
                crate::human::human(lo),
                crate::human::human(hi)
            ),
        })
    }
}

impl SystemSpec {
    /// Every element's name is its own across the tables (its columns' names in every table:
    /// a body "cam" and a contact "cam" would both write `cam_x_mm`); the ground's and empty
    /// names are the tables' own checks.
    pub(super) fn unique_names(&self) -> Result<(), SpecError> {
        use SystemKey as K;
        use SystemTable as T;
        let at = |table, index, key| Field::System(SystemField { table, index, key });
        let mut seen: HashMap<&str, (T, usize)> = HashMap::new();
        let names = [
            (
                T::Body,
                self.body
                    .iter()
                    .map(|e| e.name.as_str())
                    .collect::<Vec<_>>(),
            ),
            (
                T::Joint,
                self.joint.iter().map(|e| e.name.as_str()).collect(),
            ),
            (
                T::Driver,
                self.driver.iter().map(|e| e.name.as_str()).collect(),
            ),
            (
                T::Contact,
                self.contact.iter().map(|e| e.name.as_str()).collect(),
            ),
            (
                T::Spring,
                self.spring.iter().map(|e| e.name.as_str()).collect(),
            ),
            (
                T::Damper,
                self.damper.iter().map(|e| e.name.as_str()).collect(),
            ),
            (
                T::TorsionSpring,
                self.torsion_spring
                    .iter()
                    .map(|e| e.name.as_str())
                    .collect(),
            ),
            (
                T::CoilSpring,
                self.coil_spring.iter().map(|e| e.name.as_str()).collect(),
            ),
            (
                T::GasForce,
                self.gas_force.iter().map(|e| e.name.as_str()).collect(),
            ),
            (T::Load, self.load.iter().map(|e| e.name.as_str()).collect()),
        ];
        for (t, list) in &names {
            for (i, &name) in list.iter().enumerate() {
                if name.trim().is_empty() || (*t == T::Body && name == "ground") {
                    continue;
                }
                if let Some(&(t0, i0)) = seen.get(name) {
                    return Err(SpecError::Rule {
                    field: at(*t, i, K::Name),
                    reason: format!(
                        "{name:?}: {}[{i0}] has this name already (every element's name is its own: it names its columns in the tables)",
                        t0.name()
                    ),
                });
                }
                seen.insert(name, (*t, i));
            }
        }
        Ok(())
    }
}
