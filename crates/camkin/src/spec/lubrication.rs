//! `[lubrication]`: what the force report's lubrication needs, in the mechanism file.
//!
//! ```toml
//! [lubrication]
//! oil = "sae-30@100c"        # a preset, or "eta=<Pa·s>:alpha=<1/Pa>"
//! roughness_um = [0.2, 0.3]  # RMS roughness Rq of the cam and the follower, µm
//! face_width = 10.0          # the contact's width, in the file's length unit
//! film = "dowson-higginson"  # or "hamrock" (optional)
//! friction = [0.1, 0.03]     # boundary and full-film coefficients, or one coefficient (optional)
//! materials = "steel,steel"  # the cam's and the follower's (optional)
//! ```

use super::SpecError;
use crate::field::{Field, LubricationField as L};
use crate::lubrication::{
    plausible_friction, roughness_from_um, FilmFormula, Friction, Lubricant, SurfaceProperties,
    FRICTION_RULE, ROUGHNESS_RULE,
};
use crate::report::{LubricationRequest, Materials};

/// `[lubrication]` as written.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LubricationSpec {
    /// a preset oil or `eta=<Pa·s>:alpha=<1/Pa>`
    pub oil: String,
    /// the cam's and the follower's RMS roughness, µm
    #[serde(deserialize_with = "super::pair::exact")]
    pub roughness_um: [f64; 2],
    /// the contact's face width, in the file's length unit
    pub face_width: f64,
    /// `"dowson-higginson"` (default) or `"hamrock"`
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub film: Option<String>,
    /// one coefficient, or `[boundary, full_film]` (default `[0.1, 0.03]`)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction: Option<FrictionSpec>,
    /// `"CAM,FOLLOWER"` materials (default steel on steel)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub materials: Option<String>,
}

/// `friction`: one coefficient, or the mixed model's two.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(untagged)]
pub enum FrictionSpec {
    /// one coefficient throughout
    Constant(f64),
    /// `[boundary, full_film]`
    Mixed([f64; 2]),
}

/// `[lubrication]` checked and built.
#[derive(Debug, Clone, PartialEq)]
pub struct BuiltLubrication {
    /// the request of the force report
    pub request: LubricationRequest,
    /// the face width, in the file's length unit
    pub face_width: f64,
    /// the materials
    pub materials: Materials,
}

/// The friction model when none is given: boundary 0.1, full film 0.03.
pub const DEFAULT_FRICTION: Friction = Friction::Mixed {
    boundary: 0.1,
    full_film: 0.03,
};

/// `oil` checked at `[lubrication] oil`.
pub(super) fn lubricant(oil: &str) -> Result<Lubricant, SpecError> {
    oil.parse()
        .map_err(|e: crate::lubrication::LubricantError| SpecError::Rule {
            field: Field::Lubrication(L::Oil),
            reason: e.to_string(),
        })
}

/// A pair of RMS roughnesses in µm, each checked at `field(i)`, in metres.
pub(super) fn roughness(
    um: [f64; 2],
    field: impl Fn(usize) -> Field,
) -> Result<[f64; 2], SpecError> {
    let mut rq = [0.0; 2];
    for (i, (slot, &v)) in rq.iter_mut().zip(&um).enumerate() {
        *slot = roughness_from_um(v).ok_or_else(|| SpecError::Invalid {
            field: field(i),
            value: crate::human::human(v),
            reason: format!("µm {ROUGHNESS_RULE}"),
        })?;
    }
    Ok(rq)
}

/// `film` checked at `[lubrication] film` (default Dowson–Higginson).
pub(super) fn formula(film: Option<&str>) -> Result<FilmFormula, SpecError> {
    match film {
        None => Ok(FilmFormula::default()),
        Some(name) => FilmFormula::ALL
            .into_iter()
            .find(|x| x.name() == name)
            .ok_or_else(|| SpecError::Unknown {
                field: Field::Lubrication(L::Film),
                value: name.into(),
                what: "a film formula",
                known: FilmFormula::ALL.map(FilmFormula::name).join(", "),
            }),
    }
}

/// `friction` checked at `[lubrication] friction` (default [`DEFAULT_FRICTION`]).
pub(super) fn friction(spec: Option<FrictionSpec>) -> Result<Friction, SpecError> {
    let friction = match spec {
        None => DEFAULT_FRICTION,
        Some(FrictionSpec::Constant(mu)) => Friction::Constant(mu),
        Some(FrictionSpec::Mixed([b, full])) => Friction::Mixed {
            boundary: b,
            full_film: full,
        },
    };
    let mus = match friction {
        Friction::Mixed {
            boundary,
            full_film,
        } => [boundary, full_film],
        Friction::Constant(mu) => [mu, mu],
    };
    if let Some(&bad) = mus.iter().find(|mu| !plausible_friction(**mu)) {
        return Err(SpecError::Invalid {
            field: Field::Lubrication(L::Friction),
            value: crate::human::human(bad),
            reason: FRICTION_RULE.into(),
        });
    }
    Ok(friction)
}

impl LubricationSpec {
    /// Checks every value, naming its field, and builds the request.
    pub fn build(&self) -> Result<BuiltLubrication, SpecError> {
        let f = Field::Lubrication;
        let lubricant = lubricant(&self.oil)?;
        let rq = roughness(self.roughness_um, |i| f(L::RoughnessUm(i)))?;
        if !(self.face_width.is_finite() && self.face_width > 0.0) {
            return Err(SpecError::Invalid {
                field: f(L::FaceWidth),
                value: crate::human::human(self.face_width),
                reason: "must be positive (the file's length unit)".into(),
            });
        }
        let formula = formula(self.film.as_deref())?;
        let friction = friction(self.friction)?;
        let materials: Materials = match &self.materials {
            None => Materials::default(),
            Some(m) => m
                .parse()
                .map_err(|e: crate::report::MaterialError| SpecError::Rule {
                    field: f(L::Materials),
                    reason: e.to_string(),
                })?,
        };
        let thermal = [materials.cam.thermal, materials.follower.thermal];
        Ok(BuiltLubrication {
            request: LubricationRequest {
                lubricant,
                formula,
                surfaces: [0, 1].map(|i| SurfaceProperties {
                    roughness: rq[i],
                    thermal: thermal[i],
                }),
                friction,
            },
            face_width: self.face_width,
            materials,
        })
    }
}
