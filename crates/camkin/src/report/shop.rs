//! A cam's manufacturing output, computed once for every front end: the polar table (radius at
//! each angle of the cam frame), the pitch curve (a roller centre's path), a cutter's or grinding
//! wheel's centre path with its undercut check, and a DXF drawing whose curves are circular arcs
//! within a stated tolerance of the exact profile ([`super::dxf`]). `camkin profile` writes it as
//! files, Python's `Mechanism.shop()` returns it.
//!
//! Offsets: a path at distance `R` outside the profile is `c(u) = p(u) + R n(u)`, `n` the outward
//! unit normal. It folds back (the tool cannot cut, the roller cannot follow) where the profile
//! is concave with a radius of curvature below `R`.

use crate::cam::Mechanism;
use crate::curve::{Curve, Domain};
use crate::spec::LengthUnit;
use crate::{Point2, Vec2};
use std::f64::consts::TAU;

/// What to make.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShopRequest {
    /// angle step of the polar table, degrees (divides 360)
    pub step_deg: f64,
    /// a cutter's or grinding wheel's radius, the mechanism's length unit
    pub tool_radius: Option<f64>,
    /// largest distance of the DXF's arcs from the exact curve, the mechanism's length unit
    /// (default 1e-6 of the cam's size)
    pub tolerance: Option<f64>,
}

/// The inputs of a shop report, named by enum: each front end words them its own way (the
/// command's `--tool-radius`, Python's `tool_radius`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ShopField {
    /// the polar table's angle step
    Step,
    /// the cutter's radius
    ToolRadius,
    /// the DXF's tolerance
    Tolerance,
}

/// Why a shop report was not made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ShopError {
    /// an input out of its range: the field, its value and the range in words
    #[error("{value} {unit} must be {range}")]
    Invalid {
        /// which input
        field: ShopField,
        /// the value given
        value: String,
        /// the length unit
        unit: &'static str,
        /// the range it must be in, in words with its unit
        range: String,
    },
    /// the DXF's arcs could not be fitted (too many)
    #[error("profile.dxf: {0}")]
    Arcs(String),
}

/// A path at a distance outside the profile, at the polar table's angles.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct OffsetPath {
    /// `"pitch"` (the roller centre's) or `"cutter"` (the tool centre's)
    pub name: &'static str,
    /// its distance from the profile, the length unit
    pub radius: f64,
    /// the path's points, `(x, y)`
    pub points: Vec<[f64; 2]>,
}

/// The cutter's undercut check: where the profile is concave more sharply than the tool.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct CutterCheck {
    /// the tool's radius
    pub radius: f64,
    /// the sharpest concave radius of curvature (negative), or −∞ where the profile is convex
    /// everywhere
    pub sharpest_concave: f64,
    /// the polar angles (degrees, rounded to whole degrees) from and to which the tool cannot
    /// cut, when it cannot somewhere
    pub undercut_deg: Option<(f64, f64)>,
}

/// The polar table: the profile's point at each polar angle of the cam frame.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PolarTable {
    /// polar angles, degrees (the decimals of the step: [`crate::table::AngleGrid`])
    pub angle_deg: Vec<f64>,
    /// the profile's points there, `(x, y)`
    pub points: Vec<[f64; 2]>,
}

/// A cam's manufacturing output.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ShopReport {
    /// the length unit of every length (`"mm"`)
    pub length_unit: &'static str,
    /// the polar table, or why there is none (a profile not star-shaped about the axis)
    pub polar: Result<PolarTable, String>,
    /// the pitch curve (a roller follower) and the cutter's path (a tool radius given)
    pub offsets: Vec<OffsetPath>,
    /// the cutter's check, a tool radius given
    pub cutter: Option<CutterCheck>,
    /// the DXF drawing
    pub dxf: super::dxf::DxfDrawing,
}

impl ShopReport {
    /// The shop output of `mech` (lengths in `unit`, the mechanism's own).
    pub fn new(mech: &Mechanism, unit: LengthUnit, req: &ShopRequest) -> Result<Self, ShopError> {
        let h = crate::human::human;
        let l = unit.name();
        let profile = mech.cam().profile();
        let orient = mech.orientation();
        let size = mech.size();
        if let Some(r) = req.tool_radius {
            if !(r.is_finite() && r > 0.0 && r < 1e3 * size) {
                return Err(ShopError::Invalid {
                    field: ShopField::ToolRadius,
                    value: h(r),
                    unit: l,
                    range: format!(
                        "positive, finite and below 1000 times the cam's size ({} {l})",
                        h(size)
                    ),
                });
            }
        }
        if let Some(t) = req.tolerance {
            if !(t.is_finite() && t >= 1e-12 * size && t <= 0.1 * size) {
                return Err(ShopError::Invalid {
                    field: ShopField::Tolerance,
                    value: h(t),
                    unit: l,
                    range: format!("from 1e-12 to 0.1 of the cam's size ({} {l})", h(size)),
                });
            }
        }
        let n = (360.0 / req.step_deg).round();
        if !(req.step_deg.is_finite() && req.step_deg > 0.0 && n >= 1.0)
            || (n * req.step_deg - 360.0).abs() > 1e-9 * 360.0
        {
            return Err(ShopError::Invalid {
                field: ShopField::Step,
                value: h(req.step_deg),
                unit: "°",
                range: "positive and divide 360°".into(),
            });
        }
        let tol = req.tolerance.unwrap_or(1e-6 * size);
        let n = n as usize;
        let grid = crate::table::AngleGrid::new(0.0, req.step_deg);
        let degs: Vec<f64> = (0..n).map(|k| grid.at(k)).collect();
        let phis: Vec<f64> = degs.iter().map(|d| d.to_radians()).collect();
        let mut offsets = Vec::new();
        let polar = polar_params(profile, &phis).map(|us| {
            let mut radii: Vec<(&'static str, f64)> = Vec::new();
            if let Some(r) = mech.roller_radius() {
                radii.push(("pitch", r));
            }
            if let Some(r) = req.tool_radius {
                radii.push(("cutter", r));
            }
            for (name, r) in radii {
                offsets.push(OffsetPath {
                    name,
                    radius: r,
                    points: us
                        .iter()
                        .map(|&u| {
                            let c = offset_point(profile, orient, u, r);
                            [c.x, c.y]
                        })
                        .collect(),
                });
            }
            PolarTable {
                angle_deg: degs.clone(),
                points: us
                    .iter()
                    .map(|&u| {
                        let q = profile.position(u);
                        [q.x, q.y]
                    })
                    .collect(),
            }
        });
        // where the profile is concave more sharply than the tool: it cannot be cut
        let (period, starts) = pieces(profile);
        let cutter = req.tool_radius.map(|r| {
            let samples = 64 * starts.len().max(16);
            let us: Vec<f64> = (0..samples)
                .map(|k| period * k as f64 / samples as f64)
                .collect();
            let concave = |u: f64| Some(convex_radius(profile, orient, u)).filter(|&x| x < 0.0);
            let values: Vec<Option<f64>> = us.iter().map(|&u| concave(u)).collect();
            // the sharpest concave radius where it is, refined between the samples
            let sharpest = crate::extreme::best_refined(&us, &values, 1.0, Some(period), concave)
                .map_or(f64::NEG_INFINITY, |(_, v)| v);
            let mut bad: Vec<f64> = us
                .iter()
                .zip(&values)
                .filter(|(_, rho)| rho.is_some_and(|rho| rho > -r))
                .map(|(&u, _)| {
                    let p = profile.position(u);
                    p.y.atan2(p.x).to_degrees().rem_euclid(360.0)
                })
                .collect();
            bad.sort_by(f64::total_cmp);
            CutterCheck {
                radius: r,
                sharpest_concave: sharpest,
                undercut_deg: (!bad.is_empty())
                    .then(|| (bad[0].round(), bad[bad.len() - 1].round())),
            }
        });
        // the DXF: the profile, the pitch curve and the cutter path as arcs
        let mut curves: Vec<(&'static str, f64)> = vec![("PROFILE", 0.0)];
        if let Some(r) = mech.roller_radius() {
            curves.push(("PITCH", r));
        }
        if let Some(r) = req.tool_radius {
            curves.push(("CUTTER", r));
        }
        let mut layers = Vec::new();
        let mut worst = 0.0f64;
        for (layer, r) in curves {
            let f = |u: f64| offset_point(profile, orient, u, r);
            let (verts, dev) =
                super::dxf::fit_arcs(&f, period, &starts, tol).map_err(ShopError::Arcs)?;
            worst = worst.max(dev);
            layers.push((layer, verts));
        }
        // the centre mark a tenth of the cam's size, the 0° line to just beyond its reach
        let dxf = super::dxf::DxfDrawing::new(unit, layers, 0.2 * size, 1.15 * size, worst);
        Ok(Self {
            length_unit: unit.name(),
            polar,
            offsets,
            cutter,
            dxf,
        })
    }
}

/// The profile's period and the starts of its smooth pieces (0 first).
pub fn pieces(profile: &dyn Curve) -> (f64, Vec<f64>) {
    let period = match profile.domain() {
        Domain::Periodic { period } => period,
        #[allow(unreachable_patterns)]
        _ => 1.0,
    };
    let mut b = profile.breakpoints();
    if b.is_empty() || b[0] > 0.0 {
        b.insert(0, 0.0);
    }
    (period, b)
}

/// Outward unit normal of the profile at `u` (`orientation` +1 for a counter-clockwise profile).
fn outward(profile: &dyn Curve, orientation: f64, u: f64) -> Vec2 {
    -orientation * profile.normal(u)
}

/// The point at distance `r` outside the profile at `u`.
pub fn offset_point(profile: &dyn Curve, orientation: f64, u: f64, r: f64) -> Point2 {
    profile.position(u) + r * outward(profile, orientation, u)
}

/// Signed radius of curvature, positive where convex.
fn convex_radius(profile: &dyn Curve, orientation: f64, u: f64) -> f64 {
    orientation / profile.curvature(u)
}

/// The parameters of the profile's points at polar angles `phis` (rad, cam frame) about the
/// cam axis (the frame's origin), or why there is no polar table: the profile must be
/// star-shaped about the axis (every ray from it crosses the profile once).
pub fn polar_params(profile: &dyn Curve, phis: &[f64]) -> Result<Vec<f64>, String> {
    let (period, bps) = pieces(profile);
    // dense samples with their unwrapped polar angles
    let mut us = Vec::new();
    for (k, &a) in bps.iter().enumerate() {
        let b = bps.get(k + 1).copied().unwrap_or(period);
        for j in 0..64 {
            us.push(a + (b - a) * j as f64 / 64.0);
        }
    }
    let ang = |u: f64| {
        let p = profile.position(u);
        p.y.atan2(p.x)
    };
    let mut unwrapped = Vec::with_capacity(us.len() + 1);
    let mut prev = ang(us[0]);
    let mut acc = prev;
    for &u in &us {
        let a = ang(u);
        let mut d = a - prev;
        d -= TAU * (d / TAU).round();
        acc += d;
        unwrapped.push(acc);
        prev = a;
    }
    let a0 = unwrapped[0];
    // close the loop
    let mut d = ang(0.0) - prev;
    d -= TAU * (d / TAU).round();
    let total = acc + d - a0;
    let dir = total.signum();
    if (total.abs() - TAU).abs() > 1e-6 {
        return Err("the profile does not go round the cam axis once".into());
    }
    for w in unwrapped.windows(2) {
        if dir * (w[1] - w[0]) <= 0.0 {
            let at = w[0].to_degrees().rem_euclid(360.0);
            return Err(format!(
                "the profile is not star-shaped about the cam axis: near the polar angle {}° a ray from the axis crosses it more than once",
                crate::human::human(at.round())
            ));
        }
    }
    us.push(period);
    unwrapped.push(a0 + total);
    let mut out = Vec::with_capacity(phis.len());
    for &phi in phis {
        // the unwrapped angle in [a0, a0 + 2π) (or down from a0 for a clockwise profile)
        let t = a0 + dir * (dir * (phi - a0)).rem_euclid(TAU);
        let k = unwrapped
            .windows(2)
            .position(|w| dir * (t - w[0]) >= 0.0 && dir * (w[1] - t) >= 0.0)
            .unwrap_or(0);
        let (mut lo, mut hi) = (us[k], us[k + 1]);
        let g = |u: f64| {
            let p = profile.position(u);
            let s = (phi.sin(), phi.cos());
            dir * (p.y * s.1 - p.x * s.0)
        };
        // g < 0 before the ray, > 0 after it
        for _ in 0..200 {
            let m = 0.5 * (lo + hi);
            if m <= lo || m >= hi {
                break;
            }
            if g(m) < 0.0 {
                lo = m;
            } else {
                hi = m;
            }
        }
        out.push((0.5 * (lo + hi)).rem_euclid(period));
    }
    Ok(out)
}
