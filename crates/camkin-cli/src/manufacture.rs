//! Manufacturing output from any cam profile: the polar table (radius at each angle of the cam
//! frame), the pitch curve (a roller centre's path), a cutter's or grinding wheel's centre path
//! with its undercut check, and a DXF drawing with its units set whose curves are circular arcs
//! (polyline bulges) within a stated tolerance of the exact profile.
//!
//! Offsets: a path at distance `R` outside the profile is `c(u) = p(u) + R n(u)`, `n` the outward
//! unit normal. It folds back (the tool cannot cut, the roller cannot follow) where the profile
//! is concave with a radius of curvature below `R`.

use crate::output::{write_atomic, write_cell_table, Cell, TableFormat};
use anyhow::anyhow;
use camkin::cam::Mechanism;
use camkin::curve::{Curve, Domain};
use camkin::spec::LengthUnit;
use camkin::{Point2, Vec2};
use std::f64::consts::{PI, TAU};
use std::path::{Path, PathBuf};

/// What to write.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// angle step of the polar table, degrees (divides 360)
    pub step_deg: f64,
    /// a cutter's or grinding wheel's radius, file units
    pub tool_radius: Option<f64>,
    /// largest distance of the DXF's arcs from the exact curve, file units (default 1e-6 of the
    /// cam's size)
    pub tolerance: Option<f64>,
}

/// Why nothing (or not everything) was written.
#[derive(Debug)]
pub enum Error {
    /// bad input (exit 2)
    Input(anyhow::Error),
    /// a write failed
    Output(anyhow::Error),
}

/// What was written, and a report for people.
#[derive(Debug, Clone, Default)]
pub struct Made {
    /// the files
    pub files: Vec<PathBuf>,
    /// lines for the report (units included)
    pub report: String,
    /// the tool cannot cut the profile everywhere
    pub tool_undercut: bool,
}

/// Most vertices one DXF curve may have.
const MAX_VERTICES: usize = 2_000_000;

/// The profile's period and the starts of its smooth pieces.
fn pieces(profile: &dyn Curve) -> (f64, Vec<f64>) {
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
                camkin::human::human(at.round())
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

/// The circle through `a`, `m`, `b` as a polyline bulge from `a` to `b` (tan of a quarter of
/// the arc's angle, positive counter-clockwise).
pub fn bulge(a: Point2, m: Point2, b: Point2) -> f64 {
    let (ma, mb) = (a - m, b - m);
    let angle = (ma.x * mb.y - ma.y * mb.x).abs().atan2(ma.dot(&mb)); // ∠AMB
    let chord = b - a;
    let side = chord.x * (m.y - a.y) - chord.y * (m.x - a.x);
    let mag = ((PI - angle) / 2.0).tan();
    if side < 0.0 {
        mag
    } else {
        -mag
    }
}

/// The points of the arc from `a` to `b` with bulge `bulge`, `n` of them (the ends included).
pub fn arc_points(a: Point2, b: Point2, bulge: f64, n: usize) -> Vec<Point2> {
    let theta = 4.0 * bulge.atan();
    if theta.abs() < 1e-12 {
        return (0..n)
            .map(|k| a + (b - a) * (k as f64 / (n - 1) as f64))
            .collect();
    }
    let chord = b - a;
    let c = chord.norm();
    let r = c / (2.0 * (theta / 2.0).sin());
    // the centre: from the chord's midpoint along its left normal (counter-clockwise arc)
    let mid = a + 0.5 * chord;
    let left = Vec2::new(-chord.y, chord.x) / c;
    let h = r * (theta / 2.0).cos();
    let centre = mid + h * left;
    let a0 = (a.y - centre.y).atan2(a.x - centre.x);
    let rr = (a - centre).norm();
    (0..n)
        .map(|k| {
            let t = a0 + theta * k as f64 / (n - 1) as f64;
            centre + rr * Vec2::new(t.cos(), t.sin())
        })
        .collect()
}

/// Distance of `q` from the arc through `a`, `m`, `b` (its circle, or the chord's line when the
/// three are collinear).
fn arc_distance(a: Point2, m: Point2, b: Point2, q: Point2) -> f64 {
    let (bx, by) = (m.x - a.x, m.y - a.y);
    let (cx, cy) = (b.x - a.x, b.y - a.y);
    let d = 2.0 * (bx * cy - by * cx);
    let chord = (b - a).norm().max(f64::MIN_POSITIVE);
    if d.abs() <= 1e-14 * chord * chord {
        let n = Vec2::new(-(b - a).y, (b - a).x) / chord;
        return (q - a).dot(&n).abs();
    }
    let (b2, c2) = (bx * bx + by * by, cx * cx + cy * cy);
    let ux = (cy * b2 - by * c2) / d;
    let uy = (bx * c2 - cx * b2) / d;
    let centre = Point2::new(a.x + ux, a.y + uy);
    ((q - centre).norm() - (a - centre).norm()).abs()
}

/// Arcs through a closed curve `f` on `[0, period)` within `tol`: the vertices' parameters and
/// bulges, and the largest distance found between an arc and the curve.
pub fn fit_arcs(
    f: &dyn Fn(f64) -> Point2,
    period: f64,
    starts: &[f64],
    tol: f64,
) -> Result<(Vec<(Point2, f64)>, f64), String> {
    let mut out: Vec<(Point2, f64)> = Vec::new();
    let mut worst = 0.0f64;
    fn split(
        f: &dyn Fn(f64) -> Point2,
        a: f64,
        b: f64,
        tol: f64,
        depth: usize,
        out: &mut Vec<(Point2, f64)>,
        worst: &mut f64,
    ) -> Result<(), String> {
        let (pa, pm, pb) = (f(a), f(0.5 * (a + b)), f(b));
        let dev = [0.25, 0.75, 0.125, 0.875]
            .iter()
            .map(|t| arc_distance(pa, pm, pb, f(a + t * (b - a))))
            .fold(0.0f64, f64::max);
        if dev <= tol || depth >= 40 {
            *worst = worst.max(dev);
            out.push((pa, bulge(pa, pm, pb)));
            if out.len() > MAX_VERTICES {
                return Err(format!("more than {MAX_VERTICES} arcs"));
            }
            return Ok(());
        }
        let m = 0.5 * (a + b);
        split(f, a, m, tol, depth + 1, out, worst)?;
        split(f, m, b, tol, depth + 1, out, worst)
    }
    for (k, &a) in starts.iter().enumerate() {
        let b = starts.get(k + 1).copied().unwrap_or(period);
        for j in 0..8 {
            let (x, y) = (
                a + (b - a) * j as f64 / 8.0,
                a + (b - a) * (j + 1) as f64 / 8.0,
            );
            split(f, x, y, tol, 0, &mut out, &mut worst)?;
        }
    }
    Ok((out, worst))
}

/// DXF `$INSUNITS` code of a length unit.
pub fn insunits(unit: LengthUnit) -> u8 {
    match unit {
        LengthUnit::In => 1,
        LengthUnit::Mm => 4,
        LengthUnit::Cm => 5,
        _ => 6,
    }
}

/// The layer of the centre mark and the 0° reference line.
pub const CENTRE_LAYER: &str = "CENTRE";

/// A DXF (R12, ASCII) with the drawing units set, its layers declared in a LAYER table (each
/// curve's, and `CENTRE`), one closed polyline of arcs per curve layer, and on `CENTRE` a
/// centre mark at the cam's axis (two lines `mark` long, crossing there) and the 0° reference
/// (a line from the axis along +x, `reach` long: the cam angle's zero, the polar table's first
/// row).
pub fn dxf(
    unit: LengthUnit,
    layers: &[(&str, Vec<(Point2, f64)>)],
    mark: f64,
    reach: f64,
) -> String {
    let metric = u8::from(unit != LengthUnit::In);
    let mut s = format!(
        "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1009\n9\n$INSUNITS\n70\n{}\n9\n$MEASUREMENT\n70\n{metric}\n0\nENDSEC\n",
        insunits(unit)
    );
    // the tables: one line type (continuous) and every layer used, each its own colour
    let names: Vec<&str> = layers
        .iter()
        .map(|(n, _)| *n)
        .chain(std::iter::once(CENTRE_LAYER))
        .collect();
    s.push_str("0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nLTYPE\n70\n1\n0\nLTYPE\n2\nCONTINUOUS\n70\n0\n3\nSolid line\n72\n65\n73\n0\n40\n0.0\n0\nENDTAB\n");
    s.push_str(&format!("0\nTABLE\n2\nLAYER\n70\n{}\n", names.len()));
    for (k, name) in names.iter().enumerate() {
        s.push_str(&format!(
            "0\nLAYER\n2\n{name}\n70\n0\n62\n{}\n6\nCONTINUOUS\n",
            k + 1
        ));
    }
    s.push_str("0\nENDTAB\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n");
    for (layer, verts) in layers {
        s.push_str(&format!(
            "0\nPOLYLINE\n8\n{layer}\n66\n1\n70\n1\n10\n0.0\n20\n0.0\n30\n0.0\n"
        ));
        for (p, b) in verts {
            s.push_str(&format!(
                "0\nVERTEX\n8\n{layer}\n10\n{:?}\n20\n{:?}\n30\n0.0\n42\n{:?}\n",
                p.x, p.y, b
            ));
        }
        s.push_str(&format!("0\nSEQEND\n8\n{layer}\n"));
    }
    let line = |a: (f64, f64), b: (f64, f64)| {
        format!(
            "0\nLINE\n8\n{CENTRE_LAYER}\n10\n{:?}\n20\n{:?}\n30\n0.0\n11\n{:?}\n21\n{:?}\n31\n0.0\n",
            a.0, a.1, b.0, b.1
        )
    };
    let h = 0.5 * mark;
    s.push_str(&line((-h, 0.0), (h, 0.0)));
    s.push_str(&line((0.0, -h), (0.0, h)));
    s.push_str(&line((0.0, 0.0), (reach, 0.0)));
    s.push_str("0\nENDSEC\n0\nEOF\n");
    s
}

/// Writes `polar.csv`, `pitch.csv` (rollers), `cutter.csv` (with a tool radius) and
/// `profile.dxf` into `dir`.
pub fn write(
    mech: &Mechanism,
    unit: LengthUnit,
    dir: &Path,
    opts: &Options,
) -> Result<Made, Error> {
    let l = unit.name();
    let h = camkin::human::human;
    let profile = mech.cam().profile();
    let orient = mech.orientation();
    let size = mech.size();
    if let Some(r) = opts.tool_radius {
        if !(r.is_finite() && r > 0.0 && r < 1e3 * size) {
            return Err(Error::Input(anyhow!(
                "--tool-radius: {} {l} must be positive, finite and below 1000 times the cam's size ({} {l})",
                h(r),
                h(size)
            )));
        }
    }
    let tol = opts.tolerance.unwrap_or(1e-6 * size);
    std::fs::create_dir_all(dir)
        .map_err(|e| Error::Input(anyhow!("cannot create {}: {e}", dir.display())))?;
    let mut made = Made::default();
    let n = (360.0 / opts.step_deg).round() as usize;
    let grid = camkin::table::AngleGrid::new(0.0, opts.step_deg);
    let phis: Vec<f64> = (0..n).map(|k| grid.at(k).to_radians()).collect();
    let out = |e: anyhow::Error| Error::Output(e);
    // the polar table
    match polar_params(profile, &phis) {
        Ok(us) => {
            let p = dir.join("polar.csv");
            let columns: Vec<String> = vec![
                "polar_angle_deg".into(),
                format!("radius_{l}"),
                format!("x_{l}"),
                format!("y_{l}"),
            ];
            let rows = phis
                .iter()
                .zip(&us)
                .map(|(phi, &u)| {
                    let q = profile.position(u);
                    vec![
                        Cell::Num(Some(phi.to_degrees())),
                        Cell::Num(Some(q.coords.norm())),
                        Cell::Num(Some(q.x)),
                        Cell::Num(Some(q.y)),
                    ]
                })
                .collect();
            write_atomic(Some(&p), |w| {
                write_cell_table(w, TableFormat::Csv, &columns, rows)
            })
            .map_err(out)?;
            made.files.push(p);
            // the paths offset from the profile, at the polar table's points
            let mut offsets: Vec<(&str, f64)> = Vec::new();
            if let Some(r) = mech.roller_radius() {
                offsets.push(("pitch", r));
            }
            if let Some(r) = opts.tool_radius {
                offsets.push(("cutter", r));
            }
            for (name, r) in offsets {
                let p = dir.join(format!("{name}.csv"));
                let columns: Vec<String> = vec![
                    "polar_angle_deg".into(),
                    format!("x_{l}"),
                    format!("y_{l}"),
                    format!("profile_x_{l}"),
                    format!("profile_y_{l}"),
                ];
                let rows = phis
                    .iter()
                    .zip(&us)
                    .map(|(phi, &u)| {
                        let q = profile.position(u);
                        let c = offset_point(profile, orient, u, r);
                        [phi.to_degrees(), c.x, c.y, q.x, q.y]
                            .iter()
                            .map(|v| Cell::Num(Some(*v)))
                            .collect()
                    })
                    .collect();
                write_atomic(Some(&p), |w| {
                    write_cell_table(w, TableFormat::Csv, &columns, rows)
                })
                .map_err(out)?;
                made.files.push(p);
            }
        }
        Err(why) => {
            made.report += &format!("polar table: none ({why})\n");
        }
    }
    // where the profile is concave more sharply than the tool: it cannot be cut
    let (period, starts) = pieces(profile);
    if let Some(r) = opts.tool_radius {
        let samples = 64 * starts.len().max(16);
        let mut bad: Vec<f64> = Vec::new();
        let us: Vec<f64> = (0..samples)
            .map(|k| period * k as f64 / samples as f64)
            .collect();
        let concave = |u: f64| Some(convex_radius(profile, orient, u)).filter(|&x| x < 0.0);
        let values: Vec<Option<f64>> = us.iter().map(|&u| concave(u)).collect();
        // the sharpest concave radius where it is, refined between the samples
        let sharpest = camkin::extreme::best_refined(&us, &values, 1.0, Some(period), concave)
            .map_or(f64::NEG_INFINITY, |(_, v)| v);
        for (&u, rho) in us.iter().zip(&values) {
            if let Some(rho) = *rho {
                if rho > -r {
                    let p = profile.position(u);
                    bad.push(p.y.atan2(p.x).to_degrees().rem_euclid(360.0));
                }
            }
        }
        made.report += &if bad.is_empty() {
            format!("cutter (radius {} {l}): cuts the whole profile\n", h(r))
        } else {
            made.tool_undercut = true;
            bad.sort_by(f64::total_cmp);
            format!(
                "cutter (radius {} {l}): UNDERCUT — the profile is concave more sharply than the tool (radius of curvature down to {} {l}) at polar angles from {}° to {}°\n",
                h(r),
                h(sharpest),
                h(bad[0].round()),
                h(bad[bad.len() - 1].round())
            )
        };
    }
    // the DXF: the profile, the pitch curve and the cutter path as arcs
    let mut layers: Vec<(&str, Vec<(Point2, f64)>)> = Vec::new();
    let mut worst = 0.0f64;
    let mut curves: Vec<(&str, f64)> = vec![("PROFILE", 0.0)];
    if let Some(r) = mech.roller_radius() {
        curves.push(("PITCH", r));
    }
    if let Some(r) = opts.tool_radius {
        curves.push(("CUTTER", r));
    }
    for (layer, r) in curves {
        let f = |u: f64| offset_point(profile, orient, u, r);
        let (verts, dev) = fit_arcs(&f, period, &starts, tol)
            .map_err(|e| Error::Input(anyhow!("profile.dxf: {e}")))?;
        worst = worst.max(dev);
        layers.push((layer, verts));
    }
    let arcs: usize = layers.iter().map(|(_, v)| v.len()).sum();
    let p = dir.join("profile.dxf");
    // the centre mark a tenth of the cam's size, the 0° line to just beyond its reach
    let text = dxf(unit, &layers, 0.2 * size, 1.15 * size);
    write_atomic(Some(&p), |w| Ok(w.write_all(text.as_bytes())?)).map_err(out)?;
    made.files.push(p);
    made.report += &format!(
        "profile.dxf: {arcs} arcs on layers {}, the centre mark and the 0° line on {CENTRE_LAYER} (units {l}); largest distance from the exact curves {:.1e} {l}\n",
        layers.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", "),
        worst
    );
    Ok(made)
}
