//! A closed curve as circular arcs within a tolerance, and a DXF drawing of such curves with its
//! units and layers declared (R12, ASCII): the shop's drawing ([`super::shop`]).

use crate::spec::LengthUnit;
use crate::{Point2, Vec2};
use std::f64::consts::PI;

/// Most vertices one DXF curve may have.
const MAX_VERTICES: usize = 2_000_000;

/// A DXF drawing: its text, and what it holds.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DxfDrawing {
    /// the file's text
    pub text: String,
    /// the layers of its curves (`PROFILE`, `PITCH`, `CUTTER`), each a closed polyline of arcs
    pub layers: Vec<&'static str>,
    /// the arcs in all
    pub arcs: usize,
    /// the largest distance found between an arc and the exact curve, the length unit
    pub largest_deviation: f64,
}

impl DxfDrawing {
    /// The drawing of `layers` (each a curve's vertices and bulges) in `unit`, with the centre
    /// mark `mark` long and the 0° line `reach` long on [`CENTRE_LAYER`].
    pub fn new(
        unit: LengthUnit,
        layers: Vec<(&'static str, Vec<(Point2, f64)>)>,
        mark: f64,
        reach: f64,
        largest_deviation: f64,
    ) -> Self {
        let text = dxf(unit, &layers, mark, reach);
        Self {
            text,
            arcs: layers.iter().map(|(_, v)| v.len()).sum(),
            layers: layers.iter().map(|(n, _)| *n).collect(),
            largest_deviation,
        }
    }
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
