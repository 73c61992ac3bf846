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
//!
//! The path's named points (ISO 6336-2, §5.2) are rows of their own, evaluated exactly: `A` its
//! start, `B = E − p_b` the driver's inner point of single-pair contact, `C` the pitch point,
//! `D = A + p_b` its outer point, `E` its end (above a contact ratio of 2, also `E − 2p_b` and
//! `A + 2p_b`, where three pairs start and stop sharing). Where the pairs in contact change the
//! load steps, so such a point has two rows, one of either side. Between the points the pairs are
//! constant, and the extremes are taken over these pieces: Hertz's `p² ∝ 1/ρ₁ + 1/ρ₂` is convex
//! in `x` with its least at `x = g/2`, so its largest is at a piece's end and its smallest there
//! or at `g/2` (closed form); λ and the flash temperature are bracketed on the grid of each piece
//! and refined by golden-section search to 1e-12 of the line of action.

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
    /// the named point this is (`"A"`, `"B"`, `"C"`, `"D"`, `"E"`, `"E-2pb"`, `"A+2pb"`), or
    /// `None` for a point of the grid
    pub name: Option<&'static str>,
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
    /// the points, from the path's start (the driven gear's tip) to its end: the grid and the
    /// named points (two rows where the pairs change, one of either side)
    pub points: Vec<PathPoint>,
    /// the largest Hertz pressure on the path (at a piece's end: see the module docs)
    pub max_hertz: Option<PathPoint>,
    /// the smallest Hertz pressure on the path
    pub min_hertz: Option<PathPoint>,
    /// the smallest λ (with a lubricant)
    pub min_lambda: Option<PathPoint>,
    /// the largest flash temperature (with a lubricant and the thermal constants)
    pub max_flash_temperature: Option<PathPoint>,
}

/// Which side of a roll length the pairs are counted on, where they change there.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Side {
    /// at the point, every pair within a rounding of the path's ends
    At,
    /// just before it (towards `A`)
    Before,
    /// just after it (towards `E`)
    After,
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

    /// A roll length within this of a point counts as at it.
    fn tol(&self) -> f64 {
        1e-9 * self.g
    }

    /// The tooth pairs in contact at roll length `x` on `side` of it: this one and each one a
    /// whole number of base pitches away on the path.
    fn pairs(&self, x: f64, side: Side) -> u32 {
        let [start, end] = self.path;
        let tol = self.tol();
        let on = |y: f64| match side {
            Side::At => y >= start - tol && y <= end + tol,
            Side::Before => y > start + tol && y <= end + tol,
            Side::After => y >= start - tol && y < end - tol,
        };
        // the path is at most a few base pitches long: a contact ratio below 8
        1 + (1..8)
            .flat_map(|k| [-f64::from(k), f64::from(k)])
            .filter(|&k| on(x + k * self.pb))
            .count() as u32
    }

    /// The point at roll length `x` from `T₁`, the pairs counted at it.
    fn at(&self, x: f64) -> PathPoint {
        self.with_pairs(x, self.pairs(x, Side::At), None)
    }

    /// The point at roll length `x` with `pairs` in contact, named `name`.
    fn with_pairs(&self, x: f64, pairs: u32, name: Option<&'static str>) -> PathPoint {
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
            name,
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
        let (tol, pb) = (along.tol(), along.pb);
        let pitch = along.rb[0] * pair.operating_pressure_angle().tan();
        // the points where the pairs change, named, in the path's order
        let mut breaks: Vec<(f64, &'static str)> = vec![(start, "A"), (end, "E")];
        // every whole number of base pitches from either end inside the path, as many as
        // `pairs` counts (a contact ratio below 8)
        for (k, [early, late]) in [
            ["B", "D"],
            ["E-2pb", "A+2pb"],
            ["E-3pb", "A+3pb"],
            ["E-4pb", "A+4pb"],
            ["E-5pb", "A+5pb"],
            ["E-6pb", "A+6pb"],
            ["E-7pb", "A+7pb"],
        ]
        .into_iter()
        .enumerate()
        {
            let k = (k + 1) as f64;
            for (x, name) in [(end - k * pb, early), (start + k * pb, late)] {
                if x > start + tol && x < end - tol {
                    breaks.push((x, name));
                }
            }
        }
        breaks.sort_by(|a, b| a.0.total_cmp(&b.0));
        // the named rows: each side of a break where its pairs differ, and the pitch point
        let mut named = Vec::with_capacity(2 * breaks.len() + 1);
        for (i, &(x, name)) in breaks.iter().enumerate() {
            let before = (i > 0).then(|| along.pairs(x, Side::Before));
            let after = (i + 1 < breaks.len()).then(|| along.pairs(x, Side::After));
            match (before, after) {
                (Some(b), Some(a)) if a != b => {
                    named.push(along.with_pairs(x, b, Some(name)));
                    named.push(along.with_pairs(x, a, Some(name)));
                }
                (Some(n), _) | (None, Some(n)) => named.push(along.with_pairs(x, n, Some(name))),
                (None, None) => {}
            }
        }
        if pitch > start - tol && pitch < end + tol {
            let c = along.with_pairs(pitch, along.pairs(pitch, Side::At), Some("C"));
            let at = named.partition_point(|p| p.roll <= pitch);
            named.insert(at, c);
        }
        // the grid, a point within a rounding of a named one giving way to it
        let n = req.points;
        let mut points: Vec<PathPoint> = Vec::with_capacity(n + named.len());
        let mut named_rows = named.iter().peekable();
        for k in 0..n {
            let x = start + (end - start) * k as f64 / (n - 1) as f64;
            while let Some(p) = named_rows.next_if(|p| p.roll <= x + tol) {
                points.push(*p);
            }
            if !named.iter().any(|p| (p.roll - x).abs() <= tol) {
                points.push(along.at(x));
            }
        }
        points.extend(named_rows.copied());
        // the pieces between the breaks, each with its pairs
        let pieces: Vec<([f64; 2], u32)> = breaks
            .windows(2)
            .map(|w| {
                let (a, b) = (w[0].0, w[1].0);
                ([a, b], along.pairs(0.5 * (a + b), Side::At))
            })
            .collect();
        let best = |candidates: &mut dyn Iterator<Item = PathPoint>,
                    get: &dyn Fn(&PathPoint) -> Option<f64>,
                    sign: f64| {
            candidates
                .filter_map(|p| get(&p).filter(|v| v.is_finite()).map(|v| (p, sign * v)))
                .max_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(p, _)| p)
        };
        let hertz = |p: &PathPoint| Some(p.hertz);
        // Hertz: the largest at a piece's end (the named rows), the smallest there or at g/2
        let max_hertz = best(&mut named.iter().copied(), &hertz, 1.0);
        let half = 0.5 * along.g;
        // (a named row last: it is the one taken where a value ties)
        let min_hertz = best(
            &mut pieces
                .iter()
                .filter(|(r, _)| half > r[0] && half < r[1])
                .map(|&(_, n)| along.with_pairs(half, n, None))
                .chain(named.iter().copied()),
            &hertz,
            -1.0,
        );
        // λ and the flash temperature: bracketed on each piece's grid, refined
        let refined = |get: &dyn Fn(&PathPoint) -> Option<f64>, sign: f64| {
            let per_piece = pieces.iter().filter_map(|&(r, pairs)| {
                extreme_on(&along, r, pairs, n, &|p| get(p).map(|v| sign * v))
            });
            best(
                &mut per_piece.chain(named.iter().copied()),
                &|p| get(p).map(|v| sign * v),
                1.0,
            )
        };
        let min_lambda = refined(&|p| p.lambda, -1.0);
        let max_flash_temperature = refined(&|p| p.flash_temperature, 1.0);
        Ok(Self {
            normal_force: along.force,
            path: along.path,
            pitch_point: pitch,
            base_pitch: along.pb,
            at_pitch: along.at(pitch),
            points,
            max_hertz,
            min_hertz,
            min_lambda,
            max_flash_temperature,
        })
    }

    /// The named points' rows (two where the pairs change there), in the path's order.
    pub fn named(&self) -> impl Iterator<Item = &PathPoint> {
        self.points.iter().filter(|p| p.name.is_some())
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

/// The point of `range` (with `pairs` in contact) where `value` is largest: the best of
/// `grid`-spaced samples over the path, bracketed by its neighbours and refined by
/// golden-section search to 1e-12 of the line of action (a piece too short for a sample inside
/// is searched whole).
fn extreme_on(
    along: &Along<'_>,
    range: [f64; 2],
    pairs: u32,
    grid: usize,
    value: &dyn Fn(&PathPoint) -> Option<f64>,
) -> Option<PathPoint> {
    let [a, b] = range;
    let spacing = (along.path[1] - along.path[0]) / (grid.max(2) - 1) as f64;
    let samples = (((b - a) / spacing).ceil() as usize).clamp(2, 100_000);
    let x = |i: usize| a + (b - a) * i as f64 / samples as f64;
    let v = |x: f64| value(&along.with_pairs(x, pairs, None)).filter(|v| v.is_finite());
    let (i, _) = (0..=samples)
        .filter_map(|i| v(x(i)).map(|y| (i, y)))
        .max_by(|p, q| p.1.total_cmp(&q.1))?;
    let (mut lo, mut hi) = (x(i.saturating_sub(1)), x((i + 1).min(samples)));
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let goal = 1e-12 * along.g;
    let f = |x: f64| v(x).unwrap_or(f64::NEG_INFINITY);
    let (mut c, mut d) = (hi - r * (hi - lo), lo + r * (hi - lo));
    let (mut fc, mut fd) = (f(c), f(d));
    while hi - lo > goal {
        if fc >= fd {
            hi = d;
            (d, fd) = (c, fc);
            c = hi - r * (hi - lo);
            fc = f(c);
        } else {
            lo = c;
            (c, fc) = (d, fd);
            d = lo + r * (hi - lo);
            fd = f(d);
        }
    }
    // the bracket's ends (a piece's end) are candidates too
    let xs = [lo, 0.5 * (lo + hi), hi, x(i)];
    let x = xs
        .into_iter()
        .max_by(|p, q| f(*p).total_cmp(&f(*q)))
        .unwrap_or(x(i));
    Some(along.with_pairs(x, pairs, None))
}

impl GearLoads {
    /// The per-point table (`gear_loads.csv`): each column's name with its unit and its cell,
    /// written once.
    pub fn table(&self) -> (Vec<String>, Vec<Vec<crate::table::Cell>>) {
        use crate::table::Cell;
        type Get = fn(&PathPoint) -> Cell;
        let columns: [(&str, Get); 17] = [
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
            ("point", |p| Cell::Text(p.name.map(str::to_string))),
        ];
        let rows = self
            .points
            .iter()
            .map(|p| columns.iter().map(|c| (c.1)(p)).collect())
            .collect();
        (columns.iter().map(|c| c.0.to_string()).collect(), rows)
    }
}
