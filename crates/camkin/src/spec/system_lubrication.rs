//! `[lubrication]` of a system file and each contact's `roughness_um` and `rolls`: the oil of
//! every contact with a face width (its line contact), for the lubrication of its simulation.
//!
//! ```toml
//! [lubrication]
//! oil = "sae-30@100c"        # a preset, or "eta=<Pa·s>:alpha=<1/Pa>"
//! roughness_um = [0.2, 0.3]  # each contact's curve A and curve B, unless it says (optional)
//! film = "dowson-higginson"  # or "hamrock" (optional)
//! friction = [0.1, 0.03]     # or one coefficient (optional)
//!
//! [[contact]]
//! # … face_width = 12.0, materials = "steel,steel" (the thermal constants) …
//! roughness_um = [0.3, 0.2]  # this contact's (optional)
//! rolls = "b"                # curve B is a roller turning on its pin: it rolls without slip
//! ```

use super::build::SpecError;
use super::{ContactSpec, FrictionSpec};
use crate::field::{Field, SystemField, SystemKey, SystemTable};
use crate::lubrication::SurfaceProperties;
use crate::report::{ContactLubrication, LubricationRequest, Materials};

/// `[lubrication]` of a system file as written.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SystemLubricationSpec {
    /// a preset oil or `eta=<Pa·s>:alpha=<1/Pa>`
    pub oil: String,
    /// every contact's curve A and curve B RMS roughness, µm, unless it gives its own
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "super::pair::option"
    )]
    pub roughness_um: Option<[f64; 2]>,
    /// `"dowson-higginson"` (default) or `"hamrock"`
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub film: Option<String>,
    /// one coefficient, or `[boundary, full_film]` (default `[0.1, 0.03]`)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction: Option<FrictionSpec>,
}

/// Contact `i`'s lubrication under the file's `[lubrication]` (`lengths` metres a length unit):
/// none without the table or without a face width; its keys refused where they cannot apply.
pub(super) fn contact_lubrication(
    table: Option<&SystemLubricationSpec>,
    c: &ContactSpec,
    i: usize,
    metres: f64,
) -> Result<Option<ContactLubrication>, SpecError> {
    let at = |key| {
        Field::System(SystemField {
            table: SystemTable::Contact,
            index: i,
            key,
        })
    };
    let own_key = match (&c.roughness_um, &c.rolls) {
        (Some(_), _) => Some(at(SystemKey::RoughnessUm(0))),
        (None, Some(_)) => Some(at(SystemKey::Rolls)),
        _ => None,
    };
    let Some(table) = table else {
        return match own_key {
            Some(field) => Err(SpecError::Rule {
                field,
                reason: "is for the contact's lubrication: give the file a [lubrication] table (its oil)".into(),
            }),
            None => Ok(None),
        };
    };
    let Some(width) = c.face_width else {
        return match own_key {
            Some(field) => Err(SpecError::Rule {
                field,
                reason: "the lubrication is a line contact's: give the contact its face_width"
                    .into(),
            }),
            None => Ok(None),
        };
    };
    // the oil, the film formula and the friction, checked as a mechanism file's (its keys)
    let lubricant = super::lubrication::lubricant(&table.oil)?;
    let table_rq = table
        .roughness_um
        .map(|r| {
            super::lubrication::roughness(r, |k| {
                Field::Lubrication(crate::field::LubricationField::RoughnessUm(k))
            })
        })
        .transpose()?;
    let formula = super::lubrication::formula(table.film.as_deref())?;
    let friction = super::lubrication::friction(table.friction)?;
    let roughness = match (c.roughness_um, table_rq) {
        (Some(r), _) => super::lubrication::roughness(r, |k| at(SystemKey::RoughnessUm(k)))?,
        (None, Some(rq)) => rq,
        (None, None) => {
            return Err(SpecError::Rule {
                field: at(SystemKey::FaceWidth),
                reason: "its lubrication needs each curve's roughness: give it roughness_um = [A, B] in µm, or [lubrication] one for every contact".into(),
            })
        }
    };
    let rolls = match c.rolls.as_deref() {
        None => None,
        Some(side @ ("a" | "b")) => {
            let (k, curve) = if side == "a" {
                (0, &c.curve_a)
            } else {
                (1, &c.curve_b)
            };
            if curve.kind != super::ProfileKind::Circle.name() {
                return Err(SpecError::Rule {
                    field: at(SystemKey::Rolls),
                    reason: format!(
                        "{side:?}: a roller is a circle; curve_{side} is a {:?}",
                        curve.kind
                    ),
                });
            }
            Some(k)
        }
        Some(other) => {
            return Err(SpecError::Unknown {
                field: at(SystemKey::Rolls),
                value: other.into(),
                what: "a curve of the contact",
                known: "a, b".into(),
            })
        }
    };
    let text = c.materials.as_deref().unwrap_or("steel,steel");
    let m: Materials =
        text.parse()
            .map_err(|e: crate::report::MaterialError| SpecError::Invalid {
                field: at(SystemKey::Materials),
                value: text.to_string(),
                reason: e.to_string(),
            })?;
    let thermal = [m.cam.thermal, m.follower.thermal];
    Ok(Some(ContactLubrication {
        request: LubricationRequest {
            lubricant,
            formula,
            surfaces: [0, 1].map(|k| SurfaceProperties {
                roughness: roughness[k],
                thermal: thermal[k],
            }),
            friction,
        },
        face_width: width * metres,
        effective_modulus: 2.0 * m.effective_modulus(),
        rolls,
    }))
}
