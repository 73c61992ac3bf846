//! Line charts as SVG and PNG with an embedded font (DejaVu Sans, Bitstream Vera licence; see
//! `assets/DejaVuSans-LICENSE.txt`), so no system fonts or libraries are needed.

use anyhow::{anyhow, Context, Result};
use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::Once;

static FONT: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

/// Registers the embedded font as "sans-serif" (once per process).
pub fn register_font() {
    REGISTER.call_once(|| {
        // the font is compiled in and known to parse; a failure would only lose text
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, FONT);
    });
}

/// Palette for the series of one chart.
pub const COLORS: [RGBColor; 5] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
];

/// One line of a chart.
#[derive(Debug, Clone)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    /// dashed lines are drawn thinner, on top
    pub dashed: bool,
}

/// A line chart.
#[derive(Debug, Clone)]
pub struct Chart {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
    pub log_y: bool,
    /// the x range shown (all points when `None`)
    pub x_range: Option<(f64, f64)>,
}

impl Series {
    /// A solid line.
    pub fn line(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self {
            name: name.into(),
            points,
            dashed: false,
        }
    }

    /// A dashed line (a reference, drawn thinner on top).
    pub fn dashed(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self {
            name: name.into(),
            points,
            dashed: true,
        }
    }
}

impl Chart {
    /// A chart of `series` on linear axes showing all their points.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
        series: Vec<Series>,
    ) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series,
            log_y: false,
            x_range: None,
        }
    }
}

/// Pixel size of the figures.
pub const SIZE: (u32, u32) = (1000, 600);

/// Writes `base.svg` and `base.png`, each atomically.
pub fn save(chart: &Chart, base: &Path) -> Result<Vec<PathBuf>> {
    register_font();
    let svg = base.with_extension("svg");
    let png = base.with_extension("png");
    write_svg(&svg, SIZE, |root| draw(root, chart))?;
    write_png(&png, SIZE, |root| draw(root, chart))?;
    Ok(vec![svg, png])
}

/// Renders with `f` into an SVG string, then writes it atomically.
pub fn write_svg(
    path: &Path,
    size: (u32, u32),
    f: impl FnOnce(DrawingArea<SVGBackend<'_>, Shift>) -> Result<()>,
) -> Result<()> {
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, size).into_drawing_area();
        f(root)?;
    }
    crate::output::write_atomic(Some(path), |w| Ok(w.write_all(text.as_bytes())?))
}

/// Renders with `f` into a PNG beside `path` under a temporary name, then renames it.
pub fn write_png(
    path: &Path,
    size: (u32, u32),
    f: impl FnOnce(DrawingArea<BitMapBackend<'_>, Shift>) -> Result<()>,
) -> Result<()> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().to_string())
        .unwrap_or_default();
    let tmp = dir.join(format!(".{stem}.{}.tmp.png", std::process::id()));
    let result = (|| {
        let root = BitMapBackend::new(&tmp, size).into_drawing_area();
        f(root.clone())?;
        // the backend's error is the file system's: keep it an I/O error (exit 2 for a bad path)
        root.present()
            .map_err(|e| std::io::Error::other(e.to_string()))
            .with_context(|| format!("cannot write {}", path.display()))?;
        drop(root);
        std::fs::rename(&tmp, path).with_context(|| format!("cannot write {}", path.display()))
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// A tick or value label on an axis spanning `span`: enough digits to tell ticks apart, no
/// rounding noise (a value within 1e-9 of the span from zero is `0`, never `-1.39e-17`), and
/// scientific notation only for magnitudes from 10⁶ or below 10⁻³.
pub fn tick(v: f64, span: f64) -> String {
    let span = if span.is_finite() && span > 0.0 {
        span
    } else {
        v.abs().max(f64::MIN_POSITIVE)
    };
    if v == 0.0 || v.abs() <= 1e-9 * span || !v.is_finite() {
        return if v.is_finite() {
            "0".into()
        } else {
            v.to_string()
        };
    }
    let a = v.abs().max(span);
    if !(1e-3..1e6).contains(&a) {
        let digits = ((v.abs() / span).log10().ceil().max(0.0) as usize + 2).min(8);
        let t = format!("{v:.digits$e}");
        let (m, e) = t.split_once('e').unwrap_or((&t, "0"));
        let m = if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.')
        } else {
            m
        };
        return format!("{m}e{e}");
    }
    let decimals = (3 - span.log10().floor() as i32).clamp(0, 12) as usize;
    let t = format!("{v:.decimals$}");
    let t = if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.')
    } else {
        &t
    };
    if t == "-0" {
        "0".into()
    } else {
        t.to_string()
    }
}

fn bounds(chart: &Chart) -> ((f64, f64), (f64, f64)) {
    let all = chart.series.iter().flat_map(|s| s.points.iter());
    let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
    for &(x, _) in all.clone() {
        x0 = x0.min(x);
        x1 = x1.max(x);
    }
    let (x0, x1) = chart.x_range.unwrap_or((x0, x1));
    let (mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY);
    for &(x, y) in all {
        if x >= x0 && x <= x1 && y.is_finite() && (!chart.log_y || y > 0.0) {
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
    }
    if !(y0 <= y1) {
        (y0, y1) = (0.0, 1.0);
    }
    // a constant (or rounding-noise) series gets a span, not a zoom into its noise
    if !chart.log_y && y1 - y0 <= 1e-9 * (1.0 + y0.abs().max(y1.abs())) {
        let m = 0.5 * (y0 + y1);
        let m = if m.abs() < 1e-9 { 0.0 } else { m };
        let h = (0.1 * m.abs()).max(1.0);
        (y0, y1) = (m - h, m + h);
    }
    ((x0, x1), (y0, y1))
}

/// The grid, ticks and axis names of one panel of a stacked page: the y axis named `y_desc`, the
/// x axis named `x_desc` (only under the last panel), 19 x labels.
pub fn panel_mesh<DB, Y>(
    ch: &mut ChartContext<'_, DB, Cartesian2d<RangedCoordf64, Y>>,
    y_desc: &str,
    x_desc: Option<&str>,
    y_fmt: &dyn Fn(&f64) -> String,
    x_fmt: &dyn Fn(&f64) -> String,
) -> Result<()>
where
    DB: DrawingBackend,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
    DB::ErrorType: 'static,
{
    let mut mesh = ch.configure_mesh();
    mesh.y_desc(y_desc)
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 17))
        .y_label_formatter(y_fmt)
        .x_label_formatter(x_fmt)
        .x_labels(19)
        .light_line_style(RGBColor(235, 235, 235));
    if let Some(x) = x_desc {
        mesh.x_desc(x);
    }
    mesh.draw().map_err(|e| anyhow!("{e}"))
}

/// Draws the chart on any backend.
pub fn draw<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, chart: &Chart) -> Result<()>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(|e| anyhow!("{e}"))?;
    let ((x0, x1), (y0, y1)) = bounds(chart);
    let mut b = ChartBuilder::on(&root);
    b.caption(&chart.title, ("sans-serif", 24))
        .margin(18)
        .x_label_area_size(50)
        .y_label_area_size(95);
    if chart.log_y {
        let lo = y0.max(y1 * 1e-16);
        let (lo, hi) = (lo / 2.0, y1 * 2.0);
        let ch = b
            .build_cartesian_2d(x0..x1, (lo..hi).log_scale())
            .map_err(|e| anyhow!("{e}"))?;
        finish(
            ch,
            chart,
            |y| if y > 0.0 { Some(y.max(lo)) } else { None },
            |v| format!("{v:.0e}"),
        )
    } else {
        let pad = 0.05 * (y1 - y0).max(1e-300);
        let ch = b
            .build_cartesian_2d(x0..x1, (y0 - pad)..(y1 + pad))
            .map_err(|e| anyhow!("{e}"))?;
        finish(
            ch,
            chart,
            |y| if y.is_finite() { Some(y) } else { None },
            move |v| tick(*v, y1 - y0 + 2.0 * pad),
        )
    }
}

fn finish<'a, DB: DrawingBackend + 'a, Y>(
    mut ch: ChartContext<'a, DB, Cartesian2d<RangedCoordf64, Y>>,
    chart: &Chart,
    keep: impl Fn(f64) -> Option<f64>,
    y_fmt: impl Fn(&f64) -> String,
) -> Result<()>
where
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
    DB::ErrorType: 'static,
{
    let xr = ch.x_range();
    let (x0, x1) = (xr.start, xr.end);
    ch.configure_mesh()
        .x_desc(&chart.x_label)
        .y_desc(&chart.y_label)
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 17))
        .y_label_formatter(&y_fmt)
        .x_label_formatter(&|v| tick(*v, x1 - x0))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(|e| anyhow!("{e}"))?;
    for (i, s) in chart.series.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let width = if s.dashed { 1 } else { 2 };
        // split the line where a point is dropped (a zero on a log scale)
        let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
        for &(x, y) in &s.points {
            match keep(y) {
                Some(y) if x >= x0 && x <= x1 => {
                    runs.last_mut().map(|r| r.push((x, y))).unwrap_or(())
                }
                _ => {
                    if runs.last().is_some_and(|r| !r.is_empty()) {
                        runs.push(Vec::new());
                    }
                }
            }
        }
        let style = color.stroke_width(width);
        let mut first = true;
        for run in runs.into_iter().filter(|r| !r.is_empty()) {
            if s.dashed {
                let series = ch
                    .draw_series(DashedLineSeries::new(run, 6, 4, style))
                    .map_err(|e| anyhow!("{e}"))?;
                if first {
                    // the legend's sample dashed as the line is
                    series.label(s.name.clone()).legend(move |(x, y)| {
                        plotters::element::DashedPathElement::new(
                            vec![(x, y), (x + 24, y)],
                            6,
                            4,
                            color.stroke_width(2),
                        )
                    });
                }
            } else {
                let series = ch
                    .draw_series(LineSeries::new(run, style))
                    .map_err(|e| anyhow!("{e}"))?;
                if first {
                    series.label(s.name.clone()).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(2))
                    });
                }
            }
            first = false;
        }
    }
    if chart.series.len() > 1 {
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 15))
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(|e| anyhow!("{e}"))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::tick;

    #[test]
    fn ticks_have_no_rounding_noise() {
        assert_eq!(tick(4.2000000000001, 10.0), "4.2");
        assert_eq!(tick(-25000.0, 1e5), "-25000");
        assert_eq!(tick(0.0, 1.0), "0");
        assert_eq!(tick(1e7, 2e7), "1e7");
        assert_eq!(tick(1.5e7, 2e7), "1.5e7");
        assert_eq!(tick(0.5, 2.0), "0.5");
        // an axis crossing zero by accumulated steps
        assert_eq!(tick(-1.3877787807814457e-17, 2.0), "0");
        assert_eq!(tick(-1.3877787807814457e-17, 1e-12), "-1.39e-17");
        assert_eq!(tick(0.0025, 0.01), "0.0025");
        assert_eq!(tick(339.99999999999994, 360.0), "340");
    }
}
