//! The SVAJ page cam engineers read: displacement, velocity, acceleration and jerk stacked on one
//! page over one shared cam-angle axis, units on every axis, each panel's peaks annotated with
//! their angles, discontinuities of the motion marked, a title with the mechanism and its speed.

use super::chart::{register_font, tick, write_png, write_svg, COLORS};
use anyhow::{anyhow, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// One panel: a quantity over the page's angle axis.
#[derive(Debug, Clone)]
pub struct Panel {
    /// the axis label with its unit, `acceleration (mm/s²)`
    pub label: String,
    /// the unit's symbol, for the peak annotations
    pub unit: String,
    /// `(angle in degrees, value)`; a NaN breaks the line
    pub points: Vec<(f64, f64)>,
    /// values within this of zero are drawn as zero: the computation's rounding, not a signal
    /// (0: every value as it is)
    pub resolution: f64,
}

/// Where the motion is discontinuous: a vertical mark on the panel of the quantity that jumps
/// (`order` 0 to 3) and those below it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mark {
    /// cam angle, degrees
    pub angle_deg: f64,
    /// the lowest derivative that jumps (0 position … 3 jerk)
    pub order: usize,
}

/// The page.
#[derive(Debug, Clone)]
pub struct Page {
    /// title line (the mechanism and its speed)
    pub title: String,
    /// displacement (lift), velocity, acceleration, jerk
    pub panels: Vec<Panel>,
    /// discontinuities
    pub marks: Vec<Mark>,
    /// the angle axis: its range, degrees, and its label with the unit
    pub x: (f64, f64),
    pub x_label: String,
}

impl Page {
    /// The axis of a revolution of the cam.
    pub const REVOLUTION: (f64, f64) = (0.0, 360.0);
}

/// Pixel size of the page.
pub const SIZE: (u32, u32) = (1200, 1500);

/// Writes `base.svg` and `base.png`.
pub fn save(page: &Page, base: &Path) -> Result<Vec<PathBuf>> {
    register_font();
    let svg = base.with_extension("svg");
    let png = base.with_extension("png");
    write_svg(&svg, SIZE, |root| draw(root, page))?;
    write_png(&png, SIZE, |root| draw(root, page))?;
    Ok(vec![svg, png])
}

/// The largest and smallest finite values with their angles.
pub fn peaks(points: &[(f64, f64)]) -> Option<((f64, f64), (f64, f64))> {
    let mut it = points.iter().filter(|p| p.1.is_finite());
    let first = *it.next()?;
    let (mut lo, mut hi) = (first, first);
    for &p in it {
        if p.1 < lo.1 {
            lo = p;
        }
        if p.1 > hi.1 {
            hi = p;
        }
    }
    Some((lo, hi))
}

fn draw<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, page: &Page) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("{e}");
    root.fill(&WHITE).map_err(e)?;
    let root = root.margin(14, 0, 0, 0);
    let body = root.titled(&page.title, ("sans-serif", 24)).map_err(e)?;
    let n = page.panels.len();
    let (x0, x1) = page.x;
    let areas = body.split_evenly((n, 1));
    for (i, (area, p)) in areas.into_iter().zip(&page.panels).enumerate() {
        let last = i + 1 == n;
        let cleaned;
        let p = if p.resolution > 0.0 {
            let mut q = p.clone();
            for pt in &mut q.points {
                if pt.1.abs() <= p.resolution {
                    pt.1 = 0.0;
                }
            }
            cleaned = q;
            &cleaned
        } else {
            p
        };
        let finite = p.points.iter().filter(|q| q.1.is_finite());
        let (mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY);
        for &(_, y) in finite {
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        if !(y0 <= y1) {
            (y0, y1) = (-1.0, 1.0);
        }
        // a constant (or rounding-noise) quantity gets a span, not a zoom into its noise
        let scale = y0.abs().max(y1.abs());
        if y1 - y0 <= 1e-9 * scale.max(f64::MIN_POSITIVE) || scale == 0.0 {
            let m = if scale < 1e-12 { 0.0 } else { 0.5 * (y0 + y1) };
            let h = (0.1 * m.abs()).max(if scale > 0.0 { scale } else { 1.0 });
            (y0, y1) = (m - h, m + h);
        }
        let pad = 0.12 * (y1 - y0);
        let (lo, hi) = (y0 - pad, y1 + pad);
        let span = hi - lo;
        let mut ch = ChartBuilder::on(&area)
            .margin_left(12)
            .margin_right(24)
            .margin_top(8)
            .margin_bottom(if last { 8 } else { 2 })
            .x_label_area_size(if last { 50 } else { 18 })
            .y_label_area_size(110)
            .build_cartesian_2d(x0..x1, lo..hi)
            .map_err(e)?;
        let x_fmt = |v: &f64| {
            if last {
                tick(*v, x1 - x0)
            } else {
                String::new()
            }
        };
        let y_fmt = |v: &f64| tick(*v, span);
        super::chart::panel_mesh(
            &mut ch,
            &p.label,
            last.then_some(&page.x_label),
            &y_fmt,
            &x_fmt,
        )?;
        // the zero line
        if lo < 0.0 && hi > 0.0 {
            ch.draw_series(std::iter::once(PathElement::new(
                vec![(x0, 0.0), (x1, 0.0)],
                BLACK.mix(0.35).stroke_width(1),
            )))
            .map_err(e)?;
        }
        // discontinuities of this quantity (a jump of a lower derivative is one of it too)
        let grey = RGBColor(160, 60, 60);
        for m in page.marks.iter().filter(|m| m.order <= i) {
            ch.draw_series(DashedLineSeries::new(
                vec![(m.angle_deg, lo), (m.angle_deg, hi)],
                4,
                4,
                grey.stroke_width(1),
            ))
            .map_err(e)?;
        }
        // the curve, broken at NaN
        let color = COLORS[i % COLORS.len()];
        let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
        for &(x, y) in &p.points {
            if y.is_finite() && (x0..=x1).contains(&x) {
                if let Some(r) = runs.last_mut() {
                    r.push((x, y));
                }
            } else if runs.last().is_some_and(|r| !r.is_empty()) {
                runs.push(Vec::new());
            }
        }
        for run in runs.into_iter().filter(|r| r.len() > 1) {
            ch.draw_series(LineSeries::new(run, color.stroke_width(2)))
                .map_err(e)?;
        }
        // the peaks, annotated with value, unit and angle
        if let Some((min, max)) = peaks(&p.points) {
            let vspan = (max.1 - min.1).abs().max(max.1.abs().max(min.1.abs()));
            let mut notes = vec![("max", max, -22)];
            if (max.1 - min.1).abs() > 1e-9 * vspan {
                notes.push(("min", min, 8));
            }
            let ys: Vec<f64> = p.points.iter().map(|q| q.1).collect();
            let deg = |d: f64| format!("{}°", camkin::human::human((d * 100.0).round() / 100.0));
            for (what, (x, y), dy) in notes {
                // an extreme held over a dwell is named as its stretch (a revolution's samples)
                let k = p.points.iter().position(|q| q.0 == x && q.1 == y);
                let revolution = p.points.len() > 2
                    && (p.points[p.points.len() - 1].0 - p.points[0].0
                        + (p.points[1].0 - p.points[0].0)
                        - 360.0)
                        .abs()
                        < 1e-6;
                let place = match k
                    .filter(|_| revolution)
                    .and_then(|k| camkin::extreme::held_run(&ys, k, 1e-9 * vspan))
                {
                    Some((a, b)) => {
                        camkin::extreme::stretch_words(p.points[a].0, p.points[b].0, deg)
                    }
                    None => format!("at {}", deg(x)),
                };
                let text = format!("{what} {} {} {place}", tick(y, vspan), p.unit);
                // keep the label inside the panel: to the left of points near the right edge
                let dx = if x > x0 + 0.7 * (x1 - x0) {
                    -(8 * text.chars().count() as i32) - 6
                } else {
                    8
                };
                let style = ("sans-serif", 15).into_font().color(&BLACK);
                ch.draw_series(std::iter::once(
                    EmptyElement::at((x, y))
                        + Circle::new((0, 0), 4, color.filled())
                        + Text::new(text, (dx, dy), style),
                ))
                .map_err(e)?;
            }
        }
    }
    Ok(())
}
