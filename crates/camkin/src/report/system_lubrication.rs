//! The lubrication of a simulated system's contacts (`camkin forces SYSTEM.toml` with
//! `[lubrication]`): at every sample where a contact with a face width is closed, its
//! entrainment and sliding, its EHL film, λ and regime, the friction and Blok's flash
//! temperature (the cam mechanism's formulas, [`super::LubricationReport`]), from the sample's
//! force and its curves' radii and surface speeds ([`crate::dynamics::ContactSurface`]).
//!
//! A circle that is a roller turning freely on its pin (`rolls`) is taken as rolling on the
//! other curve without slip, as a cam mechanism's roller is: its surface moves with the other's.
//! Without it a circle is part of its body and slides. The entrainment's reversals are between
//! samples (its sign changes from one to the next, the angle interpolated linearly): a
//! simulation's state is known at its samples, so they are as fine as its output step.

use super::lubrication::{line_point, thermal_coefficients, LubricationPoint, LubricationRequest};
use super::AtAngle;
use crate::dynamics::SystemRun;
use crate::lubrication::{composite_roughness, Regime};
use crate::system::System;
use crate::table::Cell;

/// What one contact's lubrication needs.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ContactLubrication {
    /// the oil, the film formula, curve A's and curve B's surfaces, the friction model
    pub request: LubricationRequest,
    /// the face width, m
    pub face_width: f64,
    /// `E'` of the two materials (`2 E*`), Pa
    pub effective_modulus: f64,
    /// the curve (0: A, 1: B) that is a roller rolling on the other without slip
    pub rolls: Option<usize>,
}

/// A system's lubrication: each contact's, in the system's order (`None`: not lubricated, a
/// contact without a face width).
#[derive(Debug, Clone, PartialEq)]
pub struct SystemLubricationRequest {
    /// per contact
    pub contacts: Vec<Option<ContactLubrication>>,
}

/// One contact's lubrication over the run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ContactLubricationReport {
    /// the contact's name
    pub name: String,
    /// what was asked
    pub lubrication: ContactLubrication,
    /// the composite roughness, m
    pub composite_roughness: f64,
    /// per sample (`None` where it is open or carries nothing)
    pub points: Vec<Option<LubricationPoint>>,
    /// the driver angles (degrees) where its entrainment changes sign while it is closed,
    /// interpolated between the two moving samples either side (an entrainment within 1e-9 of
    /// its largest has no sign; a stop longer than one sample is a rest, not a reversal)
    pub entrainment_reversals_deg: Vec<f64>,
    /// the smallest λ and where
    pub min_lambda: Option<AtAngle>,
    /// the largest flash temperature, K, and where
    pub max_flash_temperature: Option<AtAngle>,
    /// the thinnest minimum film, m, and where
    pub thinnest_film: Option<AtAngle>,
    /// the friction power's mean over the samples, W
    pub mean_friction_power: f64,
    /// the share of its loaded samples in each regime (boundary, mixed, full film)
    pub regime_shares: [f64; 3],
}

/// A simulated system's lubrication.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SystemLubricationReport {
    /// the first driver's angle of each sample, degrees
    pub angles_deg: Vec<f64>,
    /// each lubricated contact's, in the system's order
    pub contacts: Vec<ContactLubricationReport>,
}

impl SystemLubricationReport {
    /// The lubrication of `run` of `sys` asked for by `req`; `angle_deg(t)` is the first
    /// driver's angle at time `t`.
    pub fn new(
        sys: &System,
        run: &SystemRun,
        req: &SystemLubricationRequest,
        angle_deg: impl Fn(f64) -> f64,
    ) -> Self {
        let samples = &run.samples;
        let angles: Vec<f64> = samples.iter().map(|s| angle_deg(s.time)).collect();
        let contacts = sys
            .contacts()
            .iter()
            .enumerate()
            .filter_map(|(k, c)| req.contacts.get(k).copied().flatten().map(|l| (k, c, l)))
            .map(|(k, c, l)| {
                let sigma = composite_roughness(&l.request.surfaces[0], &l.request.surfaces[1]);
                let beta = thermal_coefficients(&l.request);
                let points: Vec<Option<LubricationPoint>> = samples
                    .iter()
                    .map(|s| {
                        let surface = s.surfaces.get(k).copied().flatten()?;
                        let force = s.contact_forces[k];
                        if !(force > 0.0) {
                            return None;
                        }
                        let u = match l.rolls {
                            Some(0) => [surface.speed[1]; 2],
                            Some(_) => [surface.speed[0]; 2],
                            None => surface.speed,
                        };
                        Some(line_point(
                            &l.request,
                            sigma,
                            beta,
                            l.face_width,
                            l.effective_modulus,
                            force,
                            (surface.radius[0], Some(surface.radius[1])),
                            u,
                        ))
                    })
                    .collect();
                // an entrainment within rounding of zero has no sign: a reversal is a sign
                // change between two moving samples with at most one sample at zero between
                // them (a pass through zero; a longer stop, a valve on its seat, is a rest)
                let floor = 1e-9
                    * points
                        .iter()
                        .flatten()
                        .fold(0.0f64, |m, p| m.max(p.entrainment.abs()));
                let mut reversals = Vec::new();
                let mut last: Option<(usize, f64)> = None;
                for (i, p) in points.iter().enumerate() {
                    let Some(p) = p else {
                        last = None;
                        continue;
                    };
                    let e = p.entrainment;
                    if e.abs() <= floor {
                        continue;
                    }
                    if let Some((j, ej)) = last {
                        if ej * e < 0.0 && i - j <= 2 {
                            let f = ej / (ej - e);
                            reversals.push(angles[j] + f * (angles[i] - angles[j]));
                        }
                    }
                    last = Some((i, e));
                }
                let extreme = |get: &dyn Fn(&LubricationPoint) -> Option<f64>, sign: f64| {
                    points
                        .iter()
                        .zip(&angles)
                        .filter_map(|(p, &a)| p.as_ref().and_then(get).map(|v| (v, a)))
                        .max_by(|x, y| (sign * x.0).total_cmp(&(sign * y.0)))
                        .map(|(value, angle_deg)| AtAngle { value, angle_deg })
                };
                let mut counts = [0usize; 3];
                for r in points.iter().flatten().filter_map(|p| p.regime) {
                    counts[match r {
                        Regime::Boundary => 0,
                        Regime::Mixed => 1,
                        _ => 2,
                    }] += 1;
                }
                let loaded = counts.iter().sum::<usize>().max(1) as f64;
                ContactLubricationReport {
                    name: c.name.clone(),
                    lubrication: l,
                    composite_roughness: sigma,
                    min_lambda: extreme(&|p| p.lambda, -1.0),
                    max_flash_temperature: extreme(&|p| p.flash_temperature, 1.0),
                    thinnest_film: extreme(&|p| p.film.map(|f| f.minimum), -1.0),
                    mean_friction_power: points
                        .iter()
                        .flatten()
                        .map(|p| p.friction_power)
                        .sum::<f64>()
                        / samples.len().max(1) as f64,
                    regime_shares: counts.map(|c| c as f64 / loaded),
                    entrainment_reversals_deg: reversals,
                    points,
                }
            })
            .collect();
        Self {
            angles_deg: angles,
            contacts,
        }
    }

    /// The per-sample table (`lubrication.csv` of a system): one row per sample and lubricated
    /// contact, the driver angle and the contact's name first, then the cam mechanism's
    /// per-contact columns; a contact that is open or carries nothing has empty cells.
    pub fn table(&self) -> (Vec<String>, Vec<Vec<Cell>>) {
        let per = super::lubrication::point_columns();
        let mut names = vec!["driver_angle_deg".to_string(), "contact".to_string()];
        names.extend(per.iter().map(|(n, _)| n.to_string()));
        let mut rows = Vec::new();
        for (i, &a) in self.angles_deg.iter().enumerate() {
            for c in &self.contacts {
                let mut row = vec![Cell::Num(Some(a)), Cell::Text(Some(c.name.clone()))];
                match &c.points[i] {
                    Some(p) => row.extend(per.iter().map(|(_, get)| get(p))),
                    None => row.extend(
                        per.iter()
                            .map(|(_, get)| super::lubrication::empty_cell(*get)),
                    ),
                }
                rows.push(row);
            }
        }
        (names, rows)
    }
}
