//! The lubrication page: λ (on a log scale, with its regime bands), the film thickness, the
//! entrainment and sliding speeds, and the flash temperature, stacked over one cam-angle axis,
//! each panel's background shaded by the regime at that angle (boundary, mixed, full film).

use super::chart::{register_font, tick, write_png, write_svg, COLORS};
use anyhow::{anyhow, Result};
use camkin::lubrication::{Regime, FULL_FILM_LAMBDA, MIXED_LAMBDA};
use camkin::report::LubricationReport;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// Pixel size of the page.
pub const SIZE: (u32, u32) = (1200, 1400);

/// The regimes' shades (boundary, mixed, full film).
const SHADES: [RGBColor; 3] = [
    RGBColor(250, 215, 215),
    RGBColor(250, 238, 200),
    RGBColor(218, 240, 218),
];

fn shade(r: Regime) -> RGBColor {
    match r {
        Regime::Boundary => SHADES[0],
        Regime::Mixed => SHADES[1],
        _ => SHADES[2],
    }
}

/// Writes `base.svg` and `base.png`.
pub fn save(l: &LubricationReport, base: &Path) -> Result<Vec<PathBuf>> {
    register_font();
    let svg = base.with_extension("svg");
    let png = base.with_extension("png");
    write_svg(&svg, SIZE, |root| draw(root, l))?;
    write_png(&png, SIZE, |root| draw(root, l))?;
    Ok(vec![svg, png])
}

/// A curve: its name, its points (degrees, value), and whether it is dashed.
type Curve = (String, Vec<(f64, f64)>, bool);

/// A panel: its axis label, its curves and whether its axis is logarithmic.
struct Panel {
    label: String,
    curves: Vec<Curve>,
    log: bool,
}

fn draw<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, l: &LubricationReport) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("{e}");
    root.fill(&WHITE).map_err(e)?;
    let root = root.margin(14, 0, 0, 0);
    let title = "lubrication of the cam's contact, shaded by regime: red boundary (λ < 1), amber mixed, green full film (λ ≥ 3)";
    let body = root.titled(title, ("sans-serif", 22)).map_err(e)?;
    let deg: Vec<f64> = l.cam_angles.iter().map(|t| t.to_degrees()).collect();
    let own = |get: &dyn Fn(&camkin::report::LubricationPoint) -> Option<f64>| -> Vec<(f64, f64)> {
        deg.iter()
            .zip(&l.points)
            .map(|(&x, p)| (x, p[0].as_ref().and_then(get).unwrap_or(f64::NAN)))
            .collect()
    };
    let mut panels = vec![
        Panel {
            label: "λ = h_min / σ".into(),
            curves: vec![("λ".into(), own(&|p| p.lambda.filter(|&x| x > 0.0)), false)],
            log: true,
        },
        Panel {
            label: "film thickness (µm)".into(),
            curves: vec![
                (
                    "central".into(),
                    own(&|p| p.film.map(|f| f.central * 1e6)),
                    false,
                ),
                (
                    "minimum".into(),
                    own(&|p| p.film.map(|f| f.minimum * 1e6)),
                    true,
                ),
            ],
            log: false,
        },
        Panel {
            label: "speed at the contact (m/s)".into(),
            curves: vec![
                (
                    "entrainment (u₁ + u₂)/2".into(),
                    own(&|p| Some(p.entrainment)),
                    false,
                ),
                ("sliding u₁ − u₂".into(), own(&|p| Some(p.sliding)), true),
            ],
            log: false,
        },
    ];
    let flash = own(&|p| p.flash_temperature);
    if flash.iter().any(|p| p.1.is_finite()) {
        panels.push(Panel {
            label: "flash temperature, Blok (K)".into(),
            curves: vec![("flash temperature".into(), flash, false)],
            log: false,
        });
    }
    let (x0, x1) = (0.0, 360.0);
    let n = panels.len();
    let areas = body.split_evenly((n, 1));
    for (i, (area, p)) in areas.into_iter().zip(&panels).enumerate() {
        let last = i + 1 == n;
        let ys = p
            .curves
            .iter()
            .flat_map(|c| c.1.iter().map(|q| q.1))
            .filter(|y| y.is_finite() && (!p.log || *y > 0.0));
        let (mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY);
        for y in ys {
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        if !(y0 <= y1) {
            (y0, y1) = if p.log { (0.1, 10.0) } else { (-1.0, 1.0) };
        }
        let mut b = ChartBuilder::on(&area);
        b.margin_left(12)
            .margin_right(24)
            .margin_top(8)
            .margin_bottom(if last { 8 } else { 2 })
            .x_label_area_size(if last { 50 } else { 18 })
            .y_label_area_size(110);
        let x_fmt = |v: &f64| {
            if last {
                tick(*v, x1 - x0)
            } else {
                String::new()
            }
        };
        if p.log {
            // the regime bounds always in view
            let lo = (y0.min(MIXED_LAMBDA) / 2.0).max(1e-6);
            let hi = y1.max(FULL_FILM_LAMBDA) * 2.0;
            let mut ch = b
                .build_cartesian_2d(x0..x1, (lo..hi).log_scale())
                .map_err(e)?;
            shade_regimes(&mut ch, l, &deg, lo, hi).map_err(e)?;
            // the regime bands' bounds
            for bound in [MIXED_LAMBDA, FULL_FILM_LAMBDA] {
                ch.draw_series(DashedLineSeries::new(
                    vec![(x0, bound), (x1, bound)],
                    6,
                    4,
                    BLACK.mix(0.5).stroke_width(1),
                ))
                .map_err(e)?;
            }
            let y_fmt = |v: &f64| tick(*v, *v);
            super::chart::panel_mesh(
                &mut ch,
                &p.label,
                last.then_some("cam angle (°)"),
                &y_fmt,
                &x_fmt,
            )?;
            curves(&mut ch, p, |y| y > 0.0).map_err(e)?;
        } else {
            let pad = 0.12 * (y1 - y0).max(1e-9 * y1.abs().max(1.0));
            let (lo, hi) = (y0 - pad, y1 + pad);
            let span = hi - lo;
            let mut ch = b.build_cartesian_2d(x0..x1, lo..hi).map_err(e)?;
            shade_regimes(&mut ch, l, &deg, lo, hi).map_err(e)?;
            let y_fmt = |v: &f64| tick(*v, span);
            super::chart::panel_mesh(
                &mut ch,
                &p.label,
                last.then_some("cam angle (°)"),
                &y_fmt,
                &x_fmt,
            )?;
            if lo < 0.0 && hi > 0.0 {
                ch.draw_series(std::iter::once(PathElement::new(
                    vec![(x0, 0.0), (x1, 0.0)],
                    BLACK.mix(0.35).stroke_width(1),
                )))
                .map_err(e)?;
            }
            // where the entrainment reverses
            for &t in &l.entrainment_reversals {
                let x = t.to_degrees();
                ch.draw_series(DashedLineSeries::new(
                    vec![(x, lo), (x, hi)],
                    4,
                    4,
                    RGBColor(160, 60, 60).stroke_width(1),
                ))
                .map_err(e)?;
            }
            curves(&mut ch, p, |y| y.is_finite()).map_err(e)?;
        }
    }
    Ok(())
}

/// Each angle's stretch (to the next angle) in its regime's shade, from `lo` to `hi`.
fn shade_regimes<'a, DB: DrawingBackend + 'a, Y: Ranged<ValueType = f64>>(
    ch: &mut ChartContext<'a, DB, Cartesian2d<plotters::coord::types::RangedCoordf64, Y>>,
    l: &LubricationReport,
    deg: &[f64],
    lo: f64,
    hi: f64,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let n = deg.len();
    let step = if n > 0 { 360.0 / n as f64 } else { 360.0 };
    ch.draw_series(deg.iter().zip(&l.points).filter_map(|(&x, p)| {
        let r = p[0].as_ref()?.regime?;
        Some(Rectangle::new(
            [(x - 0.5 * step, lo), (x + 0.5 * step, hi)],
            shade(r).filled(),
        ))
    }))?;
    Ok(())
}

/// The panel's curves, each broken where `keep` refuses a value, with a legend when there are
/// several.
fn curves<'a, DB: DrawingBackend + 'a, Y: Ranged<ValueType = f64>>(
    ch: &mut ChartContext<'a, DB, Cartesian2d<plotters::coord::types::RangedCoordf64, Y>>,
    p: &Panel,
    keep: impl Fn(f64) -> bool,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    for (k, (name, points, dashed)) in p.curves.iter().enumerate() {
        let color = COLORS[k % COLORS.len()];
        let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
        for &(x, y) in points {
            if keep(y) {
                if let Some(r) = runs.last_mut() {
                    r.push((x, y));
                }
            } else if runs.last().is_some_and(|r| !r.is_empty()) {
                runs.push(Vec::new());
            }
        }
        let mut first = true;
        for run in runs.into_iter().filter(|r| r.len() > 1) {
            let style = color.stroke_width(2);
            let legend = move |(x, y): (i32, i32)| {
                PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(2))
            };
            if *dashed {
                let s = ch.draw_series(DashedLineSeries::new(run, 6, 4, style))?;
                if first {
                    s.label(name.clone()).legend(legend);
                }
            } else {
                let s = ch.draw_series(LineSeries::new(run, style))?;
                if first {
                    s.label(name.clone()).legend(legend);
                }
            }
            first = false;
        }
    }
    if p.curves.len() > 1 {
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 15))
            .position(SeriesLabelPosition::UpperRight)
            .draw()?;
    }
    Ok(())
}
