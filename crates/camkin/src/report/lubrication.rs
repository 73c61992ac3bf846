//! Lubrication of a cam mechanism's contacts over a revolution: the entrainment and sliding
//! speeds (and the exact angles where the entrainment changes sign), the EHL film, λ and its
//! regime, the friction coefficient, Blok's flash temperature and the friction power, from the
//! force report's states (the formulas are [`crate::lubrication`]'s).

use super::{Extreme, ForceField, ReportError};
use crate::dynamics::{ForceState, Forces};
use crate::lubrication::{
    blok_flash_temperature, composite_roughness, film_thickness, plausible_friction,
    reduced_radius, regime, roughness_from_um, Film, FilmFormula, Friction, LineContact, Lubricant,
    Regime, SurfaceProperties, FRICTION_RULE, PRESSURE_VISCOSITY_RANGE, VISCOSITY_RANGE,
};
use crate::table::Cell;
use std::f64::consts::TAU;

/// What a lubrication report needs beyond the forces: the oil, the film formula, the two
/// surfaces (the cam's, the follower's) and the friction model.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LubricationRequest {
    /// the lubricant at the inlet temperature
    pub lubricant: Lubricant,
    /// the film formula
    pub formula: FilmFormula,
    /// the cam's surface, the follower's
    pub surfaces: [SurfaceProperties; 2],
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
        if !(l.viscosity >= VISCOSITY_RANGE.0 && l.viscosity <= VISCOSITY_RANGE.1) {
            return bad(
                ForceField::Viscosity,
                l.viscosity,
                "Pa·s",
                "is not a plausible viscosity: from 1e-4 to 100 Pa·s (an engine oil's is about 0.01 hot: a value in mPa·s or cP is a thousand times too large)",
            );
        }
        if !(l.pressure_viscosity >= PRESSURE_VISCOSITY_RANGE.0
            && l.pressure_viscosity <= PRESSURE_VISCOSITY_RANGE.1)
        {
            return bad(
                ForceField::PressureViscosity,
                l.pressure_viscosity,
                "1/Pa",
                "is not a plausible pressure-viscosity coefficient: from 0 to 1e-7 1/Pa (mineral oils 1e-8 to 3e-8: a value in 1/GPa is a thousand million times too large)",
            );
        }
        for s in &self.surfaces {
            if roughness_from_um(s.roughness * 1e6).is_none() {
                return bad(
                    ForceField::Roughness,
                    s.roughness,
                    "m",
                    "is not a plausible roughness: Rq from above 0 to 1e-4 m (a ground surface's is 0.1 to 0.5 µm; λ divides by it)",
                );
            }
            if let Some(t) = s.thermal {
                for v in [t.conductivity, t.density, t.specific_heat] {
                    if !(v.is_finite() && v > 0.0) {
                        return bad(
                            ForceField::Thermal,
                            v,
                            "(SI)",
                            "must be positive (conductivity W/(m·K), density kg/m³, specific heat J/(kg·K))",
                        );
                    }
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
            if !plausible_friction(mu) {
                return bad(ForceField::Friction, mu, "", FRICTION_RULE);
            }
        }
        Ok(())
    }
}

/// One contact at one cam angle.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
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
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct LubricationReport {
    /// what was asked
    pub request: LubricationRequest,
    /// the face width, m
    pub face_width: f64,
    /// the effective modulus `E'` (`2/E' = Σ (1 − ν²)/E`), Pa
    pub effective_modulus: f64,
    /// the composite roughness `√(Rq₁² + Rq₂²)`, m
    pub composite_roughness: f64,
    /// the cam angles of the rows, rad
    pub cam_angles: Vec<f64>,
    /// per angle of the force report, the follower's own contact and a form-closed follower's
    /// second (`None` where that curve carries no force)
    pub points: Vec<[Option<LubricationPoint>; 2]>,
    /// the follower is form-closed: the table has the second contact's columns
    pub closed: bool,
    /// the cam angles (rad, ascending) where the own contact's entrainment changes sign, each
    /// located by bisection on the exact state to 1e-12 rad (to the bracket reached, should the
    /// state fail to be found inside one sample step)
    pub entrainment_reversals: Vec<f64>,
    /// the smallest λ and where (over the own contact's loaded angles)
    pub min_lambda: Option<Extreme>,
    /// the largest flash temperature and where, K
    pub max_flash_temperature: Option<Extreme>,
    /// the thinnest minimum film and where, m
    pub thinnest_film: Option<Extreme>,
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

/// One line contact's lubrication: `force` N on `face_width` m, the curves' radii (m, convex
/// positive; the second `None`: no line contact), the surfaces' speeds past the contact `u`
/// (m/s, along one tangent), `sigma` the composite roughness (m), `beta` the two surfaces'
/// thermal coefficients (Blok's), `e_prime` Pa.
#[allow(clippy::too_many_arguments)]
pub(crate) fn line_point(
    request: &LubricationRequest,
    sigma: f64,
    beta: Option<[f64; 2]>,
    face_width: f64,
    e_prime: f64,
    force: f64,
    radii: (f64, Option<f64>),
    u: [f64; 2],
) -> LubricationPoint {
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
        flash_temperature: beta
            .filter(|_| force > 0.0)
            .and_then(|beta| blok_flash_temperature(&contact, mu, beta)),
        friction_power: mu * force.max(0.0) * contact.sliding().abs(),
    }
}

/// The two surfaces' thermal coefficients (Blok's), where both have thermal constants.
pub(crate) fn thermal_coefficients(request: &LubricationRequest) -> Option<[f64; 2]> {
    match request.surfaces.map(|s| s.thermal) {
        [Some(a), Some(b)] => Some([a.coefficient(), b.coefficient()]),
        _ => None,
    }
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
        let beta = thermal_coefficients(request);
        let point = |force: f64, radii: (f64, Option<f64>), u: [f64; 2]| {
            line_point(request, sigma, beta, face_width, e_prime, force, radii, u)
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
                // one warm sweep through the bisection (each point within a sample of the last)
                let mut sweep = forces.sweep();
                while hi - lo > REVERSAL_TOLERANCE {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    // where the exact state cannot be had, the bracket so far
                    let Ok(s) = sweep.step(mid) else { break };
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
        let thinnest_film = extreme(&|p| p.film.map(|f| f.minimum), -1.0);
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
        let closed = states.iter().any(|s| s.second.is_some());
        Self {
            request: *request,
            face_width,
            effective_modulus: e_prime,
            composite_roughness: sigma,
            cam_angles: thetas.to_vec(),
            points,
            closed,
            entrainment_reversals: reversals,
            min_lambda,
            max_flash_temperature,
            thinnest_film,
            mean_friction_power,
            friction_energy_per_revolution: mean_friction_power * TAU / speed,
            mean_friction_torque: mean_friction_power / speed,
            regime_shares: counts.map(|c| c as f64 / loaded),
        }
    }
}

impl LubricationReport {
    /// The per-angle table (`lubrication.csv`): each column's name with its unit and its cell,
    /// written once; a form-closed follower's second contact in `second_…` columns. A contact
    /// that carries no force has empty cells.
    pub fn table(&self) -> (Vec<String>, Vec<Vec<Cell>>) {
        let per_contact = point_columns();
        let sides = if self.closed { 2 } else { 1 };
        let mut columns = vec!["angle_deg".to_string()];
        for side in 0..sides {
            let prefix = if side == 0 { "" } else { "second_" };
            columns.extend(per_contact.iter().map(|c| format!("{prefix}{}", c.0)));
        }
        let empty = |c: &Cell| match c {
            Cell::Text(_) => Cell::Text(None),
            _ => Cell::Num(None),
        };
        // the angle column as the grid's decimals (7.5, not 7.499999999999999)
        let grid = crate::table::AngleGrid::new(0.0, 360.0 / self.cam_angles.len().max(1) as f64);
        let rows = self
            .cam_angles
            .iter()
            .zip(&self.points)
            .enumerate()
            .map(|(k, (_, p))| {
                let mut row = vec![Cell::Num(Some(grid.at(k)))];
                for point in &p[..sides] {
                    for (_, get) in &per_contact {
                        row.push(match point {
                            Some(q) => get(q),
                            // the cell's kind from a contact that exists, emptied
                            None => empty(&get(&LubricationPoint::EMPTY)),
                        });
                    }
                }
                row
            })
            .collect();
        (columns, rows)
    }
}

/// A column's empty cell, of the kind its cells are (a text column's is text).
pub(crate) fn empty_cell(get: fn(&LubricationPoint) -> Cell) -> Cell {
    match get(&LubricationPoint::EMPTY) {
        Cell::Text(_) => Cell::Text(None),
        _ => Cell::Num(None),
    }
}

/// A per-point column's getter.
pub(crate) type PointColumn = (&'static str, fn(&LubricationPoint) -> Cell);

/// The per-contact columns of a lubrication table (names with their units), written once.
pub(crate) fn point_columns() -> [PointColumn; 12] {
    [
        ("entrainment_m_s", |p| Cell::Num(Some(p.entrainment))),
        ("sliding_m_s", |p| Cell::Num(Some(p.sliding))),
        ("slide_to_roll", |p| Cell::Num(p.slide_to_roll)),
        ("load_N_per_m", |p| Cell::Num(Some(p.load_per_width))),
        ("reduced_radius_m", |p| Cell::Num(p.reduced_radius)),
        ("film_central_um", |p| {
            Cell::Num(p.film.map(|f| f.central * 1e6))
        }),
        ("film_minimum_um", |p| {
            Cell::Num(p.film.map(|f| f.minimum * 1e6))
        }),
        ("lambda", |p| Cell::Num(p.lambda)),
        ("regime", |p| {
            Cell::Text(p.regime.map(|r| r.name().to_string()))
        }),
        ("friction_coefficient", |p| {
            Cell::Num(Some(p.friction_coefficient))
        }),
        ("flash_temperature_K", |p| Cell::Num(p.flash_temperature)),
        ("friction_power_W", |p| Cell::Num(Some(p.friction_power))),
    ]
}

impl LubricationPoint {
    /// A point with every value absent, for the kinds of a table's empty cells.
    const EMPTY: Self = Self {
        entrainment: 0.0,
        sliding: 0.0,
        slide_to_roll: None,
        reduced_radius: None,
        load_per_width: 0.0,
        film: None,
        lambda: None,
        regime: None,
        friction_coefficient: 0.0,
        flash_temperature: None,
        friction_power: 0.0,
    };
}
