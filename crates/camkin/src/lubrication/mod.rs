//! Lubrication of a line contact: the elastohydrodynamic (EHL) film, the λ ratio and its
//! regime, Blok's flash temperature and the friction the contact dissipates.
//!
//! Every function here takes one instant of one contact in SI units: the two surfaces' speeds
//! relative to the contact point along the common tangent, the reduced radius of curvature, the
//! load per unit face width and the bodies' elastic and thermal constants. The kinematics that
//! supply them (the paper's sliding rates) and the load (the force report) are computed
//! elsewhere; [`crate::report::LubricationReport`] puts them together over a revolution.
//!
//! Conventions (Hamrock, Schmid and Jacobson, *Fundamentals of Fluid Film Lubrication*, 2nd ed.,
//! 2004, ch. 18 and 21):
//! - the **surface speeds** `u₁`, `u₂` are each body's material velocity relative to the
//!   contact point, along one tangent; the **entrainment** (mean rolling) speed is
//!   `u = (u₁ + u₂)/2`, the **sliding** speed `u₁ − u₂`, and the **slide-to-roll ratio**
//!   `(u₁ − u₂)/u`;
//! - the **reduced radius** `R`: `1/R = 1/r₁ + 1/r₂` (a concave surface's radius negative, a flat
//!   one infinite);
//! - the **effective modulus** `E'`: `2/E' = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂` (twice Johnson's `E*`);
//! - the dimensionless groups `U = η₀ u/(E' R)`, `G = α E'`, `W = w/(E' R)` with `η₀` the
//!   lubricant's viscosity at the inlet (Pa·s), `α` its pressure–viscosity coefficient (1/Pa) and
//!   `w` the load per unit face width (N/m).

mod film;
mod flash;
mod friction;
mod oils;

pub use film::{film_thickness, Film, FilmFormula};
pub use flash::{blok_flash_temperature, hertz_half_width, BLOK_CONSTANT};
pub use friction::{regime, Friction, Regime, FULL_FILM_LAMBDA, MIXED_LAMBDA};
pub use oils::{LubricantError, OIL_PRESETS, PRESSURE_VISCOSITY_RANGE, VISCOSITY_RANGE};

/// A lubricant at the contact's inlet temperature.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Lubricant {
    /// dynamic viscosity at the inlet temperature and atmospheric pressure `η₀`, Pa·s
    pub viscosity: f64,
    /// pressure–viscosity coefficient `α` (Barus: `η = η₀ e^{α p}`), 1/Pa
    pub pressure_viscosity: f64,
}

/// How a body conducts the heat of friction away.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Thermal {
    /// thermal conductivity `k`, W/(m·K)
    pub conductivity: f64,
    /// density `ρ`, kg/m³
    pub density: f64,
    /// specific heat `c`, J/(kg·K)
    pub specific_heat: f64,
}

impl Thermal {
    /// The thermal contact coefficient (thermal effusivity) `β = √(k ρ c)`, W·s^½/(m²·K).
    pub fn coefficient(&self) -> f64 {
        (self.conductivity * self.density * self.specific_heat).sqrt()
    }
}

/// A body's surface at the contact: its roughness and, for the flash temperature, its thermal
/// constants.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SurfaceProperties {
    /// root-mean-square roughness `Rq`, m
    pub roughness: f64,
    /// the thermal constants (`None`: no flash temperature)
    pub thermal: Option<Thermal>,
}

/// Why a roughness given in µm is refused, after the value as written and `µm`: the one rule
/// every front end states.
pub const ROUGHNESS_RULE: &str = "is not a plausible roughness: Rq above 0 and at most 100 µm (a ground surface's is 0.1 to 0.5 µm; λ divides by it)";

/// An RMS roughness given in µm, in metres; `None` unless above 0 and at most 100 µm
/// ([`ROUGHNESS_RULE`]).
pub fn roughness_from_um(um: f64) -> Option<f64> {
    (um > 0.0 && um <= 100.0).then_some(um * 1e-6)
}

/// Why a friction coefficient is refused, after the value as written.
pub const FRICTION_RULE: &str = "is not a friction coefficient: from 0 to 1";

/// A friction coefficient the models take: from 0 to 1 ([`FRICTION_RULE`]).
pub fn plausible_friction(mu: f64) -> bool {
    (0.0..=1.0).contains(&mu)
}

/// The composite roughness of two surfaces, `σ = √(Rq₁² + Rq₂²)`, m: what λ divides the film by.
pub fn composite_roughness(a: &SurfaceProperties, b: &SurfaceProperties) -> f64 {
    a.roughness.hypot(b.roughness)
}

/// One instant of a lubricated line contact (SI units).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LineContact {
    /// surface speeds relative to the contact point along one tangent, m/s: body 1's, body 2's
    pub surface_speeds: [f64; 2],
    /// reduced radius `R` (`1/R = 1/r₁ + 1/r₂`), m; positive where the surfaces close
    pub reduced_radius: f64,
    /// load per unit face width `w`, N/m
    pub load_per_width: f64,
    /// effective modulus `E'` (`2/E' = Σ (1 − ν²)/E`), Pa
    pub effective_modulus: f64,
}

impl LineContact {
    /// The entrainment (mean rolling) speed `(u₁ + u₂)/2`, m/s, signed.
    pub fn entrainment(&self) -> f64 {
        0.5 * (self.surface_speeds[0] + self.surface_speeds[1])
    }

    /// The sliding speed `u₁ − u₂`, m/s, signed.
    pub fn sliding(&self) -> f64 {
        self.surface_speeds[0] - self.surface_speeds[1]
    }

    /// The slide-to-roll ratio `(u₁ − u₂)/((u₁ + u₂)/2)`; `None` where the entrainment is zero.
    pub fn slide_to_roll(&self) -> Option<f64> {
        let u = self.entrainment();
        (u != 0.0).then(|| self.sliding() / u)
    }
}

/// `1/R = 1/r₁ + 1/r₂` (a concave radius negative, a flat one infinite): `None` where the
/// curvatures do not close (`1/R ≤ 0`, conformal or not a line contact).
pub fn reduced_radius(r1: f64, r2: f64) -> Option<f64> {
    let k = 1.0 / r1 + 1.0 / r2;
    (k > 0.0 && k.is_finite()).then(|| 1.0 / k)
}
