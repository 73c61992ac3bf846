//! What a system file says for dynamics beyond its bodies' masses and its force elements:
//! `[dynamics]` (gravity, a default restitution) and each contact's restitution, face width and
//! materials (its Hertz pressure).

use super::build::{positive, SpecError};
use super::ContactSpec;
use crate::field::{Field, SystemField, SystemKey, SystemTable};

/// `[dynamics]` of a system file.
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct SystemDynamicsSpec {
    /// gravity in the world, m/s² (default none)
    #[cfg_attr(feature = "serde", serde(default))]
    pub gravity: Option<[f64; 2]>,
    /// Newton's coefficient of restitution of every contact without its own, 0 to 1 (default 0)
    #[cfg_attr(feature = "serde", serde(default))]
    pub restitution: Option<f64>,
}

/// A restitution (or any ratio from 0 to 1) as written at `field`.
pub(super) fn unit_interval(field: Field, e: f64) -> Result<f64, SpecError> {
    if (0.0..=1.0).contains(&e) {
        Ok(e)
    } else {
        Err(SpecError::Invalid {
            field,
            value: crate::human::human(e),
            reason: "must be from 0 to 1".into(),
        })
    }
}

/// Contact `i`'s Hertz data: its face width (lengths times `scale`) and its materials' `E*`
/// (steel on steel unless it says), or none without a face width.
pub(super) fn contact_hertz(
    c: &ContactSpec,
    i: usize,
    scale: f64,
) -> Result<Option<crate::dynamics::ContactHertz>, SpecError> {
    let at = |key| {
        Field::System(SystemField {
            table: SystemTable::Contact,
            index: i,
            key,
        })
    };
    match c.face_width {
        Some(w) => {
            let width = scale * positive(at(SystemKey::FaceWidth), w)?;
            let text = c.materials.as_deref().unwrap_or("steel,steel");
            let m: crate::report::Materials =
                text.parse()
                    .map_err(|e: crate::report::MaterialError| SpecError::Invalid {
                        field: at(SystemKey::Materials),
                        value: text.to_string(),
                        reason: e.to_string(),
                    })?;
            Ok(Some(crate::dynamics::ContactHertz {
                width,
                e_star: m.effective_modulus(),
            }))
        }
        None if c.materials.is_some() => Err(SpecError::Rule {
            field: at(SystemKey::Materials),
            reason: "materials need the contact's face_width (its Hertz pressure)".into(),
        }),
        None => Ok(None),
    }
}
