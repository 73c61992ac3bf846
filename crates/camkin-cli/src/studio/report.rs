//! The studio's downloads: the analysis table (CSV, as `camkin analyze` writes it) and the
//! report, one self-contained HTML file (the page with its data, style and script inlined; no
//! network, no server) for a design review.

use super::model;
use super::source::Source;
use super::{assets, Limits, StudioError};
use crate::output::{write_cells, TableFormat};
use camkin::spec::Solver;
use camkin::table::{analysis_cells, analysis_columns, AnalysisSweep, AngleUnit, Per, Units};
use serde::Serialize;

/// The node count of the report's interpolation study (the paper's nine-node cam sampled 36
/// times a revolution is its Figure 4 case).
pub const REPORT_COMPARE_NODES: usize = 36;

/// The analysis table at `step_deg` over a revolution: the bytes `camkin analyze FILE --angles
/// 0:360:STEP` writes.
pub fn csv(
    text: &str,
    source: &Source,
    step_deg: f64,
    limits: &Limits,
) -> Result<String, StudioError> {
    let model = super::source::read(text, source, limits)?;
    let parsed = match model.solver() {
        Solver::Cam(preset) => preset,
        Solver::General(built) => {
            let (columns, rows) = super::analysis::system_table(built, step_deg, limits)?;
            let mut rows = Some(rows);
            return csv_text(&columns, || rows.take());
        }
    };
    let mech = &parsed.built.mechanism;
    let angles = super::answer::revolution(step_deg);
    model::check_work(mech, angles.len(), limits)?;
    let units = Units::new(mech, parsed.built.length_unit, AngleUnit::Deg, Per::S);
    let columns = analysis_columns(&units);
    let mut rows = AnalysisSweep::new(mech, &angles, true, angles.len());
    csv_text(&columns, || {
        rows.next()
            .map(|chunk| chunk.iter().map(|r| analysis_cells(r, &units)).collect())
    })
}

/// A table as CSV text, its rows from `chunks` (as the command writes it).
pub fn csv_text(
    columns: &[String],
    chunks: impl FnMut() -> Option<Vec<Vec<camkin::table::Cell>>>,
) -> Result<String, StudioError> {
    let mut out = Vec::new();
    write_cells(&mut out, TableFormat::Csv, columns, chunks).map_err(|e| {
        StudioError::BadRequest {
            message: format!("cannot write the table: {e}"),
        }
    })?;
    String::from_utf8(out).map_err(|e| StudioError::BadRequest {
        message: format!("the table is not text: {e}"),
    })
}

/// What a report holds: the same data the studio shows, and its review header.
#[derive(Debug, Serialize)]
struct ReportData<'a> {
    toml: &'a str,
    result: super::answer::Analysis,
    compare: Option<super::answer::Compare>,
    generated_by: String,
    review: Review,
}

/// The design review's header: when it was made, and the profile's extent for the shop.
#[derive(Debug, Serialize)]
struct Review {
    /// the day it was made, UTC, `YYYY-MM-DD`
    date: String,
    /// the cam profile's smallest and largest radius from the axis, the file's unit (none for a
    /// system)
    radius: Option<[f64; 2]>,
    /// what `camkin profile` would make of it (none for a system)
    shop: Option<Shop>,
}

/// The manufacturing summary of a design review: the library's [`camkin::report::ShopReport`]
/// at 1° (what `camkin profile` writes), in the file's unit.
#[derive(Debug, Serialize)]
struct Shop {
    /// the polar table's smallest and largest radius, or why there is no polar table
    polar_radius: Result<[f64; 2], String>,
    /// the pitch curve's (a roller centre's path) smallest and largest radius
    pitch_radius: Option<[f64; 2]>,
    /// the DXF's arcs, and their largest distance from the exact curves
    dxf_arcs: usize,
    dxf_deviation: f64,
}

fn radius_range(points: &[[f64; 2]]) -> [f64; 2] {
    points.iter().fold([f64::INFINITY, 0.0f64], |[lo, hi], p| {
        let r = p[0].hypot(p[1]);
        [lo.min(r), hi.max(r)]
    })
}

/// The shop summary of the cam `parsed` (none when it cannot be made).
fn shop(parsed: &camkin::spec::Preset) -> Option<Shop> {
    let req = camkin::report::ShopRequest {
        step_deg: 1.0,
        tool_radius: None,
        tolerance: None,
    };
    let r =
        camkin::report::ShopReport::new(&parsed.built.mechanism, parsed.built.length_unit, &req)
            .ok()?;
    Some(Shop {
        polar_radius: r
            .polar
            .as_ref()
            .map(|p| radius_range(&p.points))
            .map_err(|e| e.clone()),
        pitch_radius: r
            .offsets
            .iter()
            .find(|o| o.name == "pitch")
            .map(|o| radius_range(&o.points)),
        dxf_arcs: r.dxf.arcs,
        dxf_deviation: r.dxf.largest_deviation,
    })
}

/// Days since 1970-01-01 as a civil date (the proleptic Gregorian calendar; Howard Hinnant's
/// `civil_from_days`).
fn civil(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (yoe + era * 400 + i64::from(m <= 2), m, d)
}

/// Today, UTC.
fn today() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs() as i64);
    let (y, m, d) = civil(secs.div_euclid(86_400));
    format!("{y:04}-{m:02}-{d:02}")
}

/// JSON that can sit inside a `<script>` element: `</` written `<\/`.
fn script_safe(json: &str) -> String {
    json.replace("</", "<\\/").replace("<!--", "<\\!--")
}

/// The report of the mechanism in `text`: one HTML file, everything inlined.
pub fn html(
    text: &str,
    source: &Source,
    step_deg: f64,
    pressure_limit_deg: f64,
    limits: &Limits,
) -> Result<String, StudioError> {
    let model = super::source::read(text, source, limits)?;
    let result =
        super::analysis::analyze_model(&model, source, step_deg, pressure_limit_deg, limits)?;
    // what only a cam has: the interpolation study (one that cannot be made, an open profile
    // say, leaves the report without it), the radii and the shop summary
    let preset = model.preset();
    let compare = preset
        .and_then(|p| model::compare_preset(p, &[REPORT_COMPARE_NODES], step_deg, limits).ok());
    let radius =
        (!result.system && !result.profile.is_empty()).then(|| radius_range(&result.profile));
    let shop = preset.and_then(shop);
    let data = ReportData {
        toml: text,
        result,
        compare,
        generated_by: format!("camkin {}", env!("CARGO_PKG_VERSION")),
        review: Review {
            date: today(),
            radius,
            shop,
        },
    };
    let json = serde_json::to_string(&data).map_err(|e| StudioError::BadRequest {
        message: format!("cannot write the report's data: {e}"),
    })?;
    Ok(inline(&json))
}

/// The page with `json` as its data and its style and script inlined.
fn inline(json: &str) -> String {
    let page = assets::INDEX_HTML;
    let style = format!("<style>\n{}</style>", assets::STYLE_CSS);
    let script = format!(
        "<script>window.CAMKIN_REPORT = {};</script>\n<script>\n{}</script>",
        script_safe(json),
        assets::STUDIO_JS
    );
    page.replace(r#"<link rel="stylesheet" href="studio.css">"#, &style)
        .replace(r#"<script src="studio.js"></script>"#, &script)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn civil_dates() {
        assert_eq!(civil(0), (1970, 1, 1));
        assert_eq!(civil(11_016), (2000, 2, 29));
        assert_eq!(civil(20_783), (2026, 11, 26));
        assert_eq!(civil(-1), (1969, 12, 31));
    }

    #[test]
    fn the_report_inlines_everything_and_fetches_nothing() {
        let page = inline("{\"x\": \"</script><script>alert(1)</script>\"}");
        assert!(!page.contains("src=\"studio.js\""));
        assert!(!page.contains("href=\"studio.css\""));
        assert!(page.contains("window.CAMKIN_REPORT"));
        // the data cannot close its script element
        assert_eq!(page.matches("</script>").count(), 2, "{page}");
        assert!(!page.contains("http://") && !page.contains("https://"));
    }
}
