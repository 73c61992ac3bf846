//! The studio's downloads: the analysis table (CSV, as `camkin analyze` writes it) and the
//! report, one self-contained HTML file (the page with its data, style and script inlined; no
//! network, no server) for a design review.

use super::model::{self, Source};
use super::{assets, Limits, StudioError};
use crate::output::{write_cells, TableFormat};
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
    if super::system::is_system(text) {
        return super::system::csv(text, source, step_deg, limits);
    }
    let parsed = model::build(text, source, limits)?;
    let mech = &parsed.built.mechanism;
    let angles = model::revolution(step_deg);
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

/// What a report holds: the same data the studio shows.
#[derive(Debug, Serialize)]
struct ReportData<'a> {
    toml: &'a str,
    result: model::Analysis,
    compare: Option<model::Compare>,
    generated_by: String,
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
    let result = model::analyze(text, source, step_deg, pressure_limit_deg, limits)?;
    // a study that cannot be made (an open profile, say) leaves the report without it
    let compare = if super::system::is_system(text) {
        None
    } else {
        model::compare(text, source, &[REPORT_COMPARE_NODES], step_deg, limits).ok()
    };
    let data = ReportData {
        toml: text,
        result,
        compare,
        generated_by: format!("camkin {}", env!("CARGO_PKG_VERSION")),
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
