//! Loads on a gear pair along its whole path of contact: the normal force a torque puts on the
//! flanks, shared between the tooth pairs in contact, the Hertz pressure, the surface speeds and
//! the specific sliding from the driven gear's tip to the driver's tip, and (with a lubricant)
//! the film and the flash temperature there.
//!
//! Along the line of action, a point at roll length `x` from the driver's base tangent point `T₁`
//! is a contact of involutes whose radii of curvature are `ρ₁ = x` and `ρ₂ = g − x` (`g` the line
//! of action's length between `T₁` and `T₂`); the flanks move past it at `w₁ = ω₁ ρ₁` and
//! `w₂ = ω₂ ρ₂` (`ω₂ = ω₁ r_b1/r_b2`). The path of contact runs from `x_A` (the driven gear's tip,
//! or the driver's form circle) to `x_E` (the driver's tip, or the driven gear's form circle);
//! another pair is in contact a base pitch `p_b` before or after, where that is on the path. The
//! torque `T` on the driver puts `F = T/r_b1` along the line of action, shared **equally** between
//! the pairs in contact (rigid teeth; the stated rule of this report, not a mesh-stiffness model).
//! Bending, friction's share of the torque and the tooth's deflection are not in it.

use super::{LubricationRequest, Materials};
use crate::gears::GearPair;
use crate::lubrication::{
    blok_flash_temperature, composite_roughness, film_thickness, reduced_radius, regime,
    LineContact, Regime,
};

/// What a gear load report is asked for (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct GearLoadRequest {
    /// the torque on the driver, N·m (> 0)
    pub torque: f64,
    /// the face width, m
    pub face_width: f64,
    /// the driver's and the driven gear's materials
    pub materials: Materials,
    /// the lubrication, when asked for
    pub lubrication: Option<LubricationRequest>,
    /// points along the path of contact, its ends included (≥ 2)
    pub points: usize,
}

/// One point of the path of contact.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PathPoint {
    /// roll length from the driver's base tangent point `T₁` along the line of action, m
    pub roll: f64,
    /// the contact's radius on the driver and on the driven gear, m
    pub radius: [f64; 2],
    /// the flanks' radii of curvature `ρ₁ = x`, `ρ₂ = g − x`, m
    pub curvature_radius: [f64; 2],
    /// tooth pairs in contact there (1 or 2, or 3 above a contact ratio of 2)
    pub pairs: u32,
    /// the normal load on this pair, N
    pub load: f64,
    /// Hertz's maximum pressure, Pa
    pub hertz: f64,
    /// the flanks' speeds past the contact `w₁`, `w₂`, m/s
    pub surface_speeds: [f64; 2],
    /// the sliding speed `w₁ − w₂`, m/s
    pub sliding: f64,
    /// the specific sliding of the driver `(w₁ − w₂)/w₁` and of the driven gear `(w₂ − w₁)/w₂`
    /// (`None` where that flank's speed is zero: at its base circle)
    pub specific_sliding: [Option<f64>; 2],
    /// the minimum film, m (with a lubricant)
    pub film_minimum: Option<f64>,
    /// λ (with a lubricant)
    pub lambda: Option<f64>,
    /// the regime by λ
    pub regime: Option<Regime>,
    /// Blok's flash temperature, K (with a lubricant and both materials' thermal constants)
    pub flash_temperature: Option<f64>,
}

/// Loads along the whole path of contact.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct GearLoads {
    /// the normal force `T/r_b1`, N
    pub normal_force: f64,
    /// the path of contact's ends, roll lengths from `T₁`, m
    pub path: [f64; 2],
    /// the pitch point's roll length, m
    pub pitch_point: f64,
    /// the base pitch, m
    pub base_pitch: f64,
    /// the pitch point (the pitch circles' contact, where nothing slides)
    pub at_pitch: PathPoint,
    /// the points, from the path's start (the driven gear's tip) to its end
    pub points: Vec<PathPoint>,
    /// the index of the point of the largest Hertz pressure
    pub max_hertz: Option<usize>,
    /// the index of the point of the smallest λ (with a lubricant)
    pub min_lambda: Option<usize>,
    /// the index of the point of the largest flash temperature (with a lubricant)
    pub max_flash_temperature: Option<usize>,
}

/// Why a gear load report could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum GearLoadError {
    /// The torque is not positive and finite.
    #[error("{0} N·m is not a torque the driver can transmit: it must be positive and finite")]
    Torque(f64),
    /// The face width is not positive.
    #[error("{0} m is not a face width: it must be positive")]
    FaceWidth(f64),
    /// Fewer than 2 points, or more than a million.
    #[error("{0} points: from 2 to 1000000 along the path")]
    Points(usize),
}

/// What every point of the path shares: the pair's geometry and speeds, the load, the
/// lubrication's constants.
struct Along<'a> {
    req: &'a GearLoadRequest,
    rb: [f64; 2],
    g: f64,
    path: [f64; 2],
    pb: f64,
    force: f64,
    w: [f64; 2],
    e_star: f64,
    sigma: Option<f64>,
    beta: Option<[f64; 2]>,
}

impl<'a> Along<'a> {
    fn new(pair: &GearPair, omega: f64, req: &'a GearLoadRequest) -> Result<Self, GearLoadError> {
        if !(req.torque.is_finite() && req.torque > 0.0) {
            return Err(GearLoadError::Torque(req.torque));
        }
        if !(req.face_width.is_finite() && req.face_width > 0.0) {
            return Err(GearLoadError::FaceWidth(req.face_width));
        }
        if !(2..=1_000_000).contains(&req.points) {
            return Err(GearLoadError::Points(req.points));
        }
        let rb = [pair.driver().base_radius(), pair.driven().base_radius()];
        let lub = req.lubrication.as_ref();
        Ok(Self {
            req,
            rb,
            g: pair.centre_distance() * pair.operating_pressure_angle().sin(),
            path: pair.path_of_contact(),
            pb: pair.base_pitch(),
            force: req.torque / rb[0],
            w: [omega.abs(), omega.abs() * rb[0] / rb[1]],
            e_star: req.materials.effective_modulus(),
            sigma: lub.map(|l| composite_roughness(&l.surfaces[0], &l.surfaces[1])),
            beta: lub.and_then(|l| match l.surfaces.map(|s| s.thermal) {
                [Some(a), Some(b)] => Some([a.coefficient(), b.coefficient()]),
                _ => None,
            }),
        })
    }

    /// The point at roll length `x` from `T₁`.
    fn at(&self, x: f64) -> PathPoint {
        let [start, end] = self.path;
        let pb = self.pb;
        // a roll length within a rounding of the path's ends counts as on it
        let tol = 1e-9 * self.g;
        let on = |y: f64| y >= start - tol && y <= end + tol;
        let pairs = 1 + [-2.0, -1.0, 1.0, 2.0]
            .iter()
            .filter(|&&k| on(x + k * pb))
            .count() as u32;
        let load = self.force / f64::from(pairs);
        let rho = [x, self.g - x];
        let speeds = [self.w[0] * rho[0], self.w[1] * rho[1]];
        let specific = |a: f64, b: f64| (a != 0.0).then(|| (a - b) / a);
        let rr = reduced_radius(rho[0], rho[1]);
        let width = self.req.face_width;
        let hertz = rr.map_or(f64::NAN, |r| {
            (load * self.e_star / (std::f64::consts::PI * width * r)).sqrt()
        });
        let contact = rr.map(|r| LineContact {
            surface_speeds: speeds,
            reduced_radius: r,
            load_per_width: load / width,
            effective_modulus: 2.0 * self.e_star,
        });
        let lub = self.req.lubrication.as_ref();
        let film = lub
            .zip(contact.as_ref())
            .and_then(|(l, c)| film_thickness(l.formula, &l.lubricant, c));
        let lambda = film.zip(self.sigma).map(|(f, s)| f.minimum / s);
        let flash = lub
            .zip(contact.as_ref())
            .zip(self.beta)
            .and_then(|((l, c), b)| blok_flash_temperature(c, l.friction.coefficient(lambda), b));
        PathPoint {
            roll: x,
            radius: [self.rb[0].hypot(rho[0]), self.rb[1].hypot(rho[1])],
            curvature_radius: rho,
            pairs,
            load,
            hertz,
            surface_speeds: speeds,
            sliding: speeds[0] - speeds[1],
            specific_sliding: [
                specific(speeds[0], speeds[1]),
                specific(speeds[1], speeds[0]),
            ],
            film_minimum: film.map(|f| f.minimum),
            lambda,
            regime: lambda.map(regime),
            flash_temperature: flash,
        }
    }
}

impl GearLoads {
    /// The loads on `pair`, its driver turning at `omega` (rad/s), as `req` asks.
    pub fn new(pair: &GearPair, omega: f64, req: &GearLoadRequest) -> Result<Self, GearLoadError> {
        let along = Along::new(pair, omega, req)?;
        let [start, end] = along.path;
        let n = req.points;
        let points: Vec<PathPoint> = (0..n)
            .map(|k| along.at(start + (end - start) * k as f64 / (n - 1) as f64))
            .collect();
        // the index of the point where `get` is largest times `sign`
        let best = |get: &dyn Fn(&PathPoint) -> Option<f64>, sign: f64| {
            points
                .iter()
                .enumerate()
                .filter_map(|(i, p)| get(p).filter(|v| v.is_finite()).map(|v| (i, sign * v)))
                .max_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(i, _)| i)
        };
        let max_hertz = best(&|p| Some(p.hertz), 1.0);
        let min_lambda = best(&|p| p.lambda, -1.0);
        let max_flash_temperature = best(&|p| p.flash_temperature, 1.0);
        let pitch = along.rb[0] * pair.operating_pressure_angle().tan();
        Ok(Self {
            normal_force: along.force,
            path: along.path,
            pitch_point: pitch,
            base_pitch: along.pb,
            at_pitch: along.at(pitch),
            points,
            max_hertz,
            min_lambda,
            max_flash_temperature,
        })
    }

    /// The point at roll length `x` from `T₁` (on the path or off it), as [`GearLoads::new`]
    /// computes its points.
    pub fn at(
        &self,
        pair: &GearPair,
        omega: f64,
        req: &GearLoadRequest,
        x: f64,
    ) -> Result<PathPoint, GearLoadError> {
        Ok(Along::new(pair, omega, req)?.at(x))
    }
}

impl GearLoads {
    /// The per-point table (`gear_loads.csv`): each column's name with its unit and its cell,
    /// written once.
    pub fn table(&self) -> (Vec<String>, Vec<Vec<crate::table::Cell>>) {
        use crate::table::Cell;
        type Get = fn(&PathPoint) -> Cell;
        let columns: [(&str, Get); 16] = [
            ("roll_length_m", |p| Cell::Num(Some(p.roll))),
            ("driver_radius_m", |p| Cell::Num(Some(p.radius[0]))),
            ("driven_radius_m", |p| Cell::Num(Some(p.radius[1]))),
            ("pairs_in_contact", |p| Cell::Count(Some(p.pairs))),
            ("load_N", |p| Cell::Num(Some(p.load))),
            ("hertz_MPa", |p| {
                Cell::Num(p.hertz.is_finite().then_some(p.hertz / 1e6))
            }),
            ("driver_speed_m_s", |p| Cell::Num(Some(p.surface_speeds[0]))),
            ("driven_speed_m_s", |p| Cell::Num(Some(p.surface_speeds[1]))),
            ("sliding_m_s", |p| Cell::Num(Some(p.sliding))),
            ("specific_sliding_driver", |p| {
                Cell::Num(p.specific_sliding[0])
            }),
            ("specific_sliding_driven", |p| {
                Cell::Num(p.specific_sliding[1])
            }),
            ("film_minimum_um", |p| {
                Cell::Num(p.film_minimum.map(|h| h * 1e6))
            }),
            ("lambda", |p| Cell::Num(p.lambda)),
            ("regime", |p| {
                Cell::Text(p.regime.map(|r| r.name().to_string()))
            }),
            ("flash_temperature_K", |p| Cell::Num(p.flash_temperature)),
            ("curvature_radius_driver_m", |p| {
                Cell::Num(Some(p.curvature_radius[0]))
            }),
        ];
        let rows = self
            .points
            .iter()
            .map(|p| columns.iter().map(|c| (c.1)(p)).collect())
            .collect();
        (columns.iter().map(|c| c.0.to_string()).collect(), rows)
    }
}
