//! The page's requests answered, whoever carries them: `camkin serve`'s HTTP server and the
//! Python package's Jupyter widget (whose kernel answers the page's messages) both call these,
//! so the page sees the same answers from either.
//!
//! | request | answer |
//! |---|---|
//! | `analyze` | [`AnalyzeRequest`] → [`AnalyzeAnswer`]: `{toml, result}` ([`Analysis`], at the page's precision); `toml` is the text with dragged nodes written in |
//! | `compare` | [`CompareRequest`] → [`Compare`] (at the page's precision) |
//!
//! A refusal is a [`StudioError`], answered as JSON `{"error": {kind, message, line, column}}`
//! ([`StudioError::body`]) with its status ([`StudioError::status`]).

use crate::answer::{Analysis, Compare};
use crate::model;
use crate::source::Source;
use crate::{
    patch_nodes, pressure_limit, step, AnalyzeRequest, CompareRequest, Limits, StudioError,
};
use serde::Serialize;

/// An analysis answered: the text analysed (with any dragged nodes written in) and what the
/// page shows of it.
#[derive(Debug, Serialize)]
pub struct AnalyzeAnswer {
    /// the mechanism's text analysed
    pub toml: String,
    /// what the page shows
    pub result: Analysis,
}

/// A request's JSON body read as `T`.
pub fn from_json<T: serde::de::DeserializeOwned>(bytes: &[u8]) -> Result<T, StudioError> {
    serde_json::from_slice(bytes).map_err(|e| StudioError::BadRequest {
        message: format!("the request is not the JSON expected: {e}"),
    })
}

fn request_text(req: &AnalyzeRequest) -> Result<String, StudioError> {
    match &req.nodes {
        Some(nodes) => patch_nodes(&req.toml, nodes),
        None => Ok(req.toml.clone()),
    }
}

/// An analysis request's body read and checked before any work: the JSON, the step, the
/// pressure-angle limit and the dragged nodes written into the text. Returns `(text, step,
/// limit)`. Public for the fuzz target of the request parsing.
pub fn check_analysis_request(
    body: &[u8],
    limits: &Limits,
) -> Result<(String, f64, f64), StudioError> {
    let req: AnalyzeRequest = from_json(body)?;
    let step_deg = step(req.step_deg, limits)?;
    let limit = pressure_limit(req.pressure_limit_deg)?;
    Ok((request_text(&req)?, step_deg, limit))
}

/// `analyze` on a checked request ([`check_analysis_request`]).
pub fn analyze_checked(
    toml: String,
    source: &Source,
    step_deg: f64,
    limit: f64,
    limits: &Limits,
) -> Result<AnalyzeAnswer, StudioError> {
    let mut result = crate::analysis::analyze(&toml, source, step_deg, limit, limits)?;
    // the page's precision; downloads are computed apart, at full precision
    crate::page_precision::for_page(&mut result);
    Ok(AnalyzeAnswer { toml, result })
}

/// `analyze`: an [`AnalyzeRequest`]'s body answered.
pub fn analyze(
    body: &[u8],
    source: &Source,
    limits: &Limits,
) -> Result<AnalyzeAnswer, StudioError> {
    let (toml, step_deg, limit) = check_analysis_request(body, limits)?;
    analyze_checked(toml, source, step_deg, limit, limits)
}

/// A [`CompareRequest`]'s body read and checked: the request, its step and its node counts.
pub fn check_compare_request(
    body: &[u8],
    limits: &Limits,
) -> Result<(CompareRequest, f64, Vec<usize>), StudioError> {
    let req: CompareRequest = from_json(body)?;
    let step_deg = step(req.step_deg, limits)?;
    let nodes = req.nodes.clone().unwrap_or_else(|| vec![36]);
    if nodes.is_empty() || nodes.len() > limits.max_compare_runs {
        return Err(StudioError::BadRequest {
            message: format!(
                "nodes: {} node counts; give 1 to {}",
                nodes.len(),
                limits.max_compare_runs
            ),
        });
    }
    if let Some(n) = nodes
        .iter()
        .find(|&&n| !(3..=limits.max_compare_nodes).contains(&n))
    {
        return Err(StudioError::BadRequest {
            message: format!(
                "nodes: {n} is out of range (3 to {})",
                limits.max_compare_nodes
            ),
        });
    }
    Ok((req, step_deg, nodes))
}

/// `compare` on a checked request ([`check_compare_request`]).
pub fn compare_checked(
    req: &CompareRequest,
    step_deg: f64,
    nodes: &[usize],
    source: &Source,
    limits: &Limits,
) -> Result<Compare, StudioError> {
    let mut out = model::compare(&req.toml, source, nodes, step_deg, limits)?;
    crate::page_precision::compare_for_page(&mut out);
    Ok(out)
}

/// `compare`: a [`CompareRequest`]'s body answered.
pub fn compare(body: &[u8], source: &Source, limits: &Limits) -> Result<Compare, StudioError> {
    let (req, step_deg, nodes) = check_compare_request(body, limits)?;
    compare_checked(&req, step_deg, &nodes, source, limits)
}

/// A request named `what` (`"analyze"` or `"compare"`) answered as `(status, JSON text)`: 200
/// and the answer, or the refusal's status and its error body. What the widget's kernel sends
/// the page.
pub fn answer(what: &str, body: &[u8], source: &Source, limits: &Limits) -> (u16, String) {
    let json = |v: Result<String, serde_json::Error>| {
        v.unwrap_or_else(|e| format!("{{\"error\":{{\"kind\":\"internal\",\"message\":\"{e}\"}}}}"))
    };
    let done = match what {
        "analyze" => analyze(body, source, limits).map(|a| json(serde_json::to_string(&a))),
        "compare" => compare(body, source, limits).map(|a| json(serde_json::to_string(&a))),
        other => Err(StudioError::NotFound {
            message: format!("no such request: {other}"),
        }),
    };
    match done {
        Ok(text) => (200, text),
        Err(e) => (e.status(), json(serde_json::to_string(&e.body()))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn analysis(file: &str) -> Analysis {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples")
            .join(file);
        let text = std::fs::read_to_string(&path).unwrap();
        let body = serde_json::json!({ "toml": text, "step_deg": 0.5 }).to_string();
        let source = Source {
            name: file.into(),
            folder: path.parent().map(|p| p.to_path_buf()),
        };
        analyze(body.as_bytes(), &source, &Limits::default())
            .unwrap()
            .result
    }

    fn jumps(a: &Analysis) -> &crate::answer::Check {
        a.checks
            .iter()
            .find(|c| c.kind == camkin::report::Check::Jumps)
            .unwrap()
    }

    /// Issue 49: an ideal gear pair's handovers are not impulses: the check passes, the
    /// acceleration on the page is zero (not its rounding noise), and the interpolation study,
    /// which needs a motion that repeats, is refused with the reason.
    #[test]
    fn an_ideal_gear_pairs_handovers_pass_and_its_zero_acceleration_reads_zero() {
        let a = analysis("gear-pair-20-42.toml");
        let j = jumps(&a);
        assert!(j.ok, "{}", j.message);
        assert!(j.message.contains("handover"), "{}", j.message);
        assert!(!j.angles_deg.is_empty());
        let acc = a.series.iter().find(|s| s.key == "acceleration").unwrap();
        assert!(
            acc.values.iter().flatten().all(|&v| v == 0.0),
            "{:?}",
            &acc.values[..8]
        );
        let jerk = a.series.iter().find(|s| s.key == "jerk").unwrap();
        assert!(jerk.values.iter().flatten().all(|&v| v == 0.0));
        let c = compare(
            serde_json::json!({ "toml": std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/gear-pair-20-42.toml")).unwrap(), "step_deg": 0.5, "nodes": [36] }).to_string().as_bytes(),
            &Source { name: "g".into(), folder: None },
            &Limits::default(),
        )
        .unwrap();
        // its motion does not repeat every revolution: the study is refused, and says why
        assert!(c.runs.is_empty());
        assert!(
            c.refused
                .as_deref()
                .is_some_and(|r| r.contains("does not repeat")),
            "{:?}",
            c.refused
        );
    }

    /// A cam whose contact moves without an impulse keeps its check; a cam's real acceleration is
    /// not rounded away.
    #[test]
    fn a_cams_acceleration_keeps_its_digits() {
        let a = analysis("paper.toml");
        assert!(jumps(&a).ok);
        let acc = a.series.iter().find(|s| s.key == "acceleration").unwrap();
        let top = acc
            .values
            .iter()
            .flatten()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        assert!((top - 26_961.97).abs() < 1.0, "{top}");
    }
}
