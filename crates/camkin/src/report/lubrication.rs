//! Lubrication of a cam mechanism's contacts over a revolution: the entrainment and sliding
//! speeds (and the exact angles where the entrainment changes sign), the EHL film, λ and its
//! regime, the friction coefficient, Blok's flash temperature and the friction power, from the
//! force report's states (the formulas are [`crate::lubrication`]'s).

use super::{Extreme, ForceField, ReportError};
use crate::dynamics::{ForceState, Forces};
use crate::lubrication::{
    blok_flash_temperature, composite_roughness, film_thickness, reduced_radius, regime, Film,
    FilmFormula, Friction, LineContact, Lubricant, Regime, Surface,
};
use std::f64::consts::TAU;

/// What a lubrication report needs beyond the forces: the oil, the film formula, the two
/// surfaces (the cam's, the follower's) and the friction model.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LubricationRequest {
    /// the lubricant at the inlet temperature
    pub lubricant: Lubricant,
    /// the film formula
    pub formula: FilmFormula,
    /// the cam's surface, the follower's
    pub surfaces: [Surface; 2],
    /// the friction model
    pub friction: Friction,
}

impl LubricationRequest {
    /// Checks each value's range, naming the field (a value in another unit than asked for is
    /// refused as implausible rather than taken).
    pub fn validate(&self) -> Result<(), ReportError> {
        let bad = |field, value, unit, reason| {
            Err(ReportError::Invalid {
                field,
                value,
                unit,
                reason,
            })
        };
        let l = &self.lubricant;
        if !(l.viscosity.is_finite() && l.viscosity > 0.0 && l.viscosity <= 100.0) {
            return bad(
                ForceField::Viscosity,
                l.viscosity,
                "Pa·s",
                "must be in (0, 100] Pa·s (an engine oil's is about 0.01 hot: a value in mPa·s or cP is a thousand times too large)",
            );
        }
        if !(l.pressure_viscosity.is_finite()
            && l.pressure_viscosity >= 0.0
            && l.pressure_viscosity <= 1e-7)
        {
            return bad(
                ForceField::PressureViscosity,
                l.pressure_viscosity,
                "1/Pa",
                "must be in [0, 1e-7] 1/Pa (mineral oils 1e-8 to 3e-8: a value in 1/GPa is a thousand million times too large)",
            );
        }
        for s in &self.surfaces {
            if !(s.roughness.is_finite() && s.roughness > 0.0 && s.roughness <= 1e-4) {
                return bad(
                    ForceField::Roughness,
                    s.roughness,
                    "m",
                    "must be in (0, 1e-4] m (a ground surface's Rq is 0.1 to 0.5 µm; λ divides by it)",
                );
            }
            for v in [s.conductivity, s.density, s.specific_heat] {
                if !(v.is_finite() && v > 0.0) {
                    return bad(
                        ForceField::Thermal,
                        v,
                        "",
                        "must be positive (conductivity W/(m·K), density kg/m³, specific heat J/(kg·K))",
                    );
                }
            }
        }
        let mus = match self.friction {
            Friction::Constant(mu) => [mu, mu],
            Friction::Mixed {
                boundary,
                full_film,
            } => [boundary, full_film],
        };
        for mu in mus {
            if !(mu.is_finite() && (0.0..=1.0).contains(&mu)) {
                return bad(ForceField::Friction, mu, "", "must be in [0, 1]");
            }
        }
        Ok(())
    }
}

/// One contact at one cam angle.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LubricationPoint {
    /// entrainment (mean rolling) speed `(u₁ + u₂)/2`, m/s, signed along the cam's tangent
    pub entrainment: f64,
    /// sliding speed `u₁ − u₂` (cam's minus follower's), m/s
    pub sliding: f64,
    /// slide-to-roll ratio `(u₁ − u₂)/((u₁ + u₂)/2)`; `None` where the entrainment is zero
    pub slide_to_roll: Option<f64>,
    /// the reduced radius, m; `None` where the contact is not a line contact of closing
    /// curvatures (a knife edge, a corner, a concave cam as sharp as its roller)
    pub reduced_radius: Option<f64>,
    /// the contact force per unit face width, N/m (≤ 0: the contact carries nothing)
    pub load_per_width: f64,
    /// the film; `None` where it is not defined (no load, or no line contact)
    pub film: Option<Film>,
    /// `λ = h_min / σ`
    pub lambda: Option<f64>,
    /// the regime by λ
    pub regime: Option<Regime>,
    /// the friction coefficient used
    pub friction_coefficient: f64,
    /// Blok's flash temperature, K above the bulk
    pub flash_temperature: Option<f64>,
    /// the power friction dissipates, `μ F |u₁ − u₂|`, W
    pub friction_power: f64,
}

/// The lubrication over a revolution.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LubricationReport {
    /// what was asked
    pub request: LubricationRequest,
    /// the face width, m
    pub face_width: f64,
    /// the effective modulus `E'` (`2/E' = Σ (1 − ν²)/E`), Pa
    pub effective_modulus: f64,
    /// the composite roughness `√(Rq₁² + Rq₂²)`, m
    pub composite_roughness: f64,
    /// per angle of the force report, the follower's own contact and a form-closed follower's
    /// second (`None` where that curve carries no force)
    pub points: Vec<[Option<LubricationPoint>; 2]>,
    /// the cam angles (rad, ascending) where the own contact's entrainment changes sign, each
    /// located by bisection on the exact state to 1e-12 rad
    pub entrainment_reversals: Vec<f64>,
    /// the smallest λ and where (over the own contact's loaded angles)
    pub min_lambda: Option<Extreme>,
    /// the largest flash temperature and where, K
    pub max_flash_temperature: Option<Extreme>,
    /// the friction power's mean over the revolution, W (both contacts)
    pub mean_friction_power: f64,
    /// the energy friction dissipates in a revolution, J
    pub friction_energy_per_revolution: f64,
    /// the mean friction torque on the camshaft, `P̄/ω`, N·m
    pub mean_friction_torque: f64,
    /// the share of angles in each regime (boundary, mixed, full film) of the own contact's
    /// loaded angles
    pub regime_shares: [f64; 3],
}

/// Angles the entrainment's sign change is located to, rad (1e-12 rad is 6e-11°).
const REVERSAL_TOLERANCE: f64 = 1e-12;

impl LubricationReport {
    /// The lubrication of the states of a force report (`thetas` their angles, a whole
    /// revolution in equal steps) with `face_width` (m) and `e_prime` (Pa, `2 E*`).
    pub(crate) fn new(
        forces: &Forces<'_>,
        states: &[ForceState],
        thetas: &[f64],
        face_width: f64,
        e_prime: f64,
        speed: f64,
        request: &LubricationRequest,
    ) -> Self {
        let sigma = composite_roughness(&request.surfaces[0], &request.surfaces[1]);
        let beta = request.surfaces.map(|s| s.thermal_coefficient());
        let point = |force: f64, radii: (f64, Option<f64>), u: [f64; 2]| -> LubricationPoint {
            let contact = LineContact {
                surface_speeds: u,
                reduced_radius: radii
                    .1
                    .and_then(|r2| reduced_radius(radii.0, r2))
                    .unwrap_or(f64::NAN),
                load_per_width: force / face_width,
                effective_modulus: e_prime,
            };
            let rr = contact.reduced_radius;
            let film = film_thickness(request.formula, &request.lubricant, &contact);
            let lambda = film.map(|f| f.minimum / sigma);
            let mu = request.friction.coefficient(lambda);
            LubricationPoint {
                entrainment: contact.entrainment(),
                sliding: contact.sliding(),
                slide_to_roll: contact.slide_to_roll(),
                reduced_radius: rr.is_finite().then_some(rr),
                load_per_width: contact.load_per_width,
                film,
                lambda,
                regime: lambda.map(regime),
                friction_coefficient: mu,
                flash_temperature: if force > 0.0 {
                    blok_flash_temperature(&contact, mu, beta)
                } else {
                    None
                },
                friction_power: mu * force.max(0.0) * contact.sliding().abs(),
            }
        };
        let of = |s: &ForceState| -> [Option<LubricationPoint>; 2] {
            let own = (s.contact_force > 0.0).then(|| {
                point(
                    s.contact_force,
                    (s.cam_radius, s.follower_radius),
                    s.surface_speeds,
                )
            });
            let second = s.second.filter(|c| c.contact_force > 0.0).map(|c| {
                point(
                    c.contact_force,
                    (c.cam_radius, c.follower_radius),
                    c.surface_speeds,
                )
            });
            [own, second]
        };
        let points: Vec<_> = states.iter().map(of).collect();
        let n = states.len();
        let entrainment = |s: &ForceState| 0.5 * (s.surface_speeds[0] + s.surface_speeds[1]);
        let mut reversals = Vec::new();
        for k in 0..n {
            let (a, b) = (k, (k + 1) % n);
            let (ea, eb) = (entrainment(&states[a]), entrainment(&states[b]));
            if ea == 0.0 {
                reversals.push(thetas[a]);
                continue;
            }
            if ea * eb < 0.0 {
                let (mut lo, mut hi) = (thetas[a], if b == 0 { TAU } else { thetas[b] });
                let mut elo = ea;
                while hi - lo > REVERSAL_TOLERANCE {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    let Ok(s) = forces.at(mid) else { break };
                    let e = entrainment(&s);
                    if e == 0.0 {
                        (lo, hi) = (mid, mid);
                    } else if (e < 0.0) == (elo < 0.0) {
                        (lo, elo) = (mid, e);
                    } else {
                        hi = mid;
                    }
                }
                reversals.push((0.5 * (lo + hi)).rem_euclid(TAU));
            }
        }
        reversals.sort_by(f64::total_cmp);
        let extreme = |get: &dyn Fn(&LubricationPoint) -> Option<f64>, sign: f64| {
            points
                .iter()
                .zip(thetas)
                .filter_map(|(p, &t)| p[0].as_ref().and_then(get).map(|v| (v, t)))
                .max_by(|x, y| (sign * x.0).total_cmp(&(sign * y.0)))
                .map(|(value, cam_angle)| Extreme { value, cam_angle })
        };
        let min_lambda = extreme(&|p| p.lambda, -1.0);
        let max_flash_temperature = extreme(&|p| p.flash_temperature, 1.0);
        let mean_friction_power = points
            .iter()
            .map(|p| p.iter().flatten().map(|q| q.friction_power).sum::<f64>())
            .sum::<f64>()
            / n as f64;
        let mut counts = [0usize; 3];
        for p in points.iter().filter_map(|p| p[0].and_then(|q| q.regime)) {
            counts[match p {
                Regime::Boundary => 0,
                Regime::Mixed => 1,
                _ => 2,
            }] += 1;
        }
        let loaded = counts.iter().sum::<usize>().max(1) as f64;
        Self {
            request: *request,
            face_width,
            effective_modulus: e_prime,
            composite_roughness: sigma,
            points,
            entrainment_reversals: reversals,
            min_lambda,
            max_flash_temperature,
            mean_friction_power,
            friction_energy_per_revolution: mean_friction_power * TAU / speed,
            mean_friction_torque: mean_friction_power / speed,
            regime_shares: counts.map(|c| c as f64 / loaded),
        }
    }
}
