//! The cam studio without its server: the page that shows a mechanism's exact kinematics, its
//! drawing, its design checks, the interpolation study and its forces, and lets the profile be
//! edited; what it shows, computed by the library from a mechanism's text; and its requests
//! answered. Three front ends serve it: `camkin serve` (an HTTP server), `camkin report` (one
//! self-contained HTML file) and the Jupyter widget of the Python package (the kernel answers).
//!
//! - [`model`]: what is shown, computed from a mechanism file's text by the library.
//! - [`api`]: a request's body answered (the same for the server and the widget).
//! - [`scene`]: the mechanism drawn as shapes in its own units.
//! - [`mechtext`]: a mechanism's text read, with its errors placed in it.
//!
//! The page itself (`web/`: HTML, CSS, one script, no dependencies) is embedded.

pub mod analysis;
pub mod answer;
pub mod api;
pub mod kinematic;
pub mod mechtext;
pub mod model;
pub mod page_precision;
pub mod scene;
pub mod simulated;
pub mod source;

use crate::mechtext::InputError;
use serde::{Deserialize, Serialize};

/// The page's HTML, style and script, embedded.
pub mod assets {
    /// the page
    pub const INDEX_HTML: &str = include_str!("../web/index.html");
    /// its style
    pub const STYLE_CSS: &str = include_str!("../web/studio.css");
    /// its script, one for the page: the charts (`web/chart.js`) and the mechanism's drawing
    /// (`web/scene.js`), then the page's state and controls (`web/studio.js`), which uses them
    pub const STUDIO_JS: &str = concat!(
        include_str!("../web/chart.js"),
        include_str!("../web/scene.js"),
        include_str!("../web/studio.js")
    );
}

/// Bounds on the work and the input one request may bring.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// the longest a request's computation may be estimated to take, s
    pub max_seconds: f64,
    /// the largest request body, bytes
    pub max_body_bytes: usize,
    /// the finest cam-angle step, degrees
    pub min_step_deg: f64,
    /// the most interpolation nodes of one study run
    pub max_compare_nodes: usize,
    /// the most node counts in one study
    pub max_compare_runs: usize,
    /// computations run at once (more wait their turn)
    pub workers: usize,
    /// the longest a request waits for its turn before it is refused (503), s
    pub max_wait_seconds: f64,
    /// the longest a client may take to send a request's headers, s (its connection is closed
    /// then: clients that never finish cannot hold the server)
    pub header_seconds: f64,
    /// the most connections open at once (beyond, the oldest one not answering a request is
    /// closed to admit the new one; where every one is answering, the new one is closed)
    pub max_connections: usize,
    /// the most memory one request may be estimated to hold, bytes (a mechanism whose search
    /// indexes would take more is refused before it is built)
    pub max_request_bytes: f64,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            max_seconds: 5.0,
            max_body_bytes: crate::mechtext::MAX_FILE_BYTES as usize,
            min_step_deg: 0.05,
            max_compare_nodes: 100_000,
            max_compare_runs: 4,
            workers: std::thread::available_parallelism().map_or(2, |n| n.get()),
            max_wait_seconds: 30.0,
            header_seconds: 10.0,
            max_connections: 256,
            max_request_bytes: 5e8,
        }
    }
}

/// Why a request was refused; every one is answered as JSON
/// `{"error": {"kind", "message", "line", "column"}}` with a 4xx (or 503) status.
#[derive(Debug, Clone, PartialEq)]
pub enum StudioError {
    /// the mechanism text is invalid (422), with its place when known
    Input {
        /// what is wrong
        message: String,
        /// 1-based line and column
        at: Option<(usize, usize)>,
    },
    /// the request itself is malformed (400)
    BadRequest {
        /// what is wrong
        message: String,
    },
    /// the request asks for more work than one request may take (422)
    TooMuch {
        /// the estimate and the limit
        message: String,
    },
    /// the body is over the size limit (413)
    TooLarge {
        /// the limit
        message: String,
    },
    /// no such route (404)
    NotFound {
        /// the path
        message: String,
    },
    /// the server is busy beyond the wait allowed (503)
    Busy {
        /// how long it waited
        message: String,
    },
}

impl From<InputError> for StudioError {
    fn from(e: InputError) -> Self {
        if e.too_much {
            return StudioError::TooMuch { message: e.message };
        }
        StudioError::Input {
            message: e.message,
            at: e.at,
        }
    }
}

impl StudioError {
    /// The HTTP status.
    pub fn status(&self) -> u16 {
        match self {
            StudioError::Input { .. } | StudioError::TooMuch { .. } => 422,
            StudioError::BadRequest { .. } => 400,
            StudioError::TooLarge { .. } => 413,
            StudioError::NotFound { .. } => 404,
            StudioError::Busy { .. } => 503,
        }
    }

    /// The JSON body.
    pub fn body(&self) -> ErrorBody {
        let (kind, message, at) = match self {
            StudioError::Input { message, at } => ("input", message, *at),
            StudioError::BadRequest { message } => ("bad-request", message, None),
            StudioError::TooMuch { message } => ("too-much-work", message, None),
            StudioError::TooLarge { message } => ("too-large", message, None),
            StudioError::NotFound { message } => ("not-found", message, None),
            StudioError::Busy { message } => ("busy", message, None),
        };
        ErrorBody {
            error: ErrorDetail {
                kind,
                message: message.clone(),
                line: at.map(|a| a.0),
                column: at.map(|a| a.1),
            },
        }
    }
}

/// `{"error": …}`
#[derive(Debug, Serialize)]
pub struct ErrorBody {
    /// the error
    pub error: ErrorDetail,
}

/// An error's kind, message and place.
#[derive(Debug, Serialize)]
pub struct ErrorDetail {
    /// `input`, `bad-request`, `too-much-work`, `too-large`, `not-found`, `busy`
    pub kind: &'static str,
    /// what a person reads
    pub message: String,
    /// 1-based line in the mechanism text
    pub line: Option<usize>,
    /// 1-based column
    pub column: Option<usize>,
}

/// A request for the analysis (`POST /api/analyze`), the table (`/api/csv`) or the report
/// (`/api/report`).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnalyzeRequest {
    /// the mechanism file's text
    pub toml: String,
    /// the cam-angle step, degrees (default 0.5; it divides 360°)
    pub step_deg: Option<f64>,
    /// the pressure-angle limit of the checks, degrees (default 30)
    pub pressure_limit_deg: Option<f64>,
    /// new nodal points of the spline (a drag on the drawing): written into the text first
    pub nodes: Option<Vec<[f64; 2]>>,
}

/// A request for the interpolation study (`POST /api/compare`).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CompareRequest {
    /// the mechanism file's text
    pub toml: String,
    /// the node counts (default 36)
    pub nodes: Option<Vec<usize>>,
    /// the cam-angle step, degrees (default 0.5)
    pub step_deg: Option<f64>,
}

/// The default cam-angle step, degrees.
pub const DEFAULT_STEP_DEG: f64 = 0.5;
/// The default pressure-angle limit, degrees.
pub const DEFAULT_PRESSURE_LIMIT_DEG: f64 = 30.0;

/// The step, checked: it divides the revolution and is no finer than the limit.
pub fn step(step_deg: Option<f64>, limits: &Limits) -> Result<f64, StudioError> {
    let s = step_deg.unwrap_or(DEFAULT_STEP_DEG);
    let bad = |why: String| StudioError::BadRequest {
        message: format!("step_deg = {s}: {why}"),
    };
    if !(s.is_finite() && s >= limits.min_step_deg && s <= 10.0) {
        return Err(bad(format!("must be from {}° to 10°", limits.min_step_deg)));
    }
    let n = 360.0 / s;
    if (n - n.round()).abs() > 1e-9 * n {
        return Err(bad("does not divide 360°".into()));
    }
    Ok(s)
}

/// The pressure-angle limit, checked.
pub fn pressure_limit(limit: Option<f64>) -> Result<f64, StudioError> {
    let l = limit.unwrap_or(DEFAULT_PRESSURE_LIMIT_DEG);
    if l.is_finite() && l > 0.0 && l < 90.0 {
        Ok(l)
    } else {
        Err(StudioError::BadRequest {
            message: format!(
                "pressure_limit_deg = {}: must be in (0°, 90°)",
                camkin::human::human(l)
            ),
        })
    }
}

/// The text with the spline's inline nodes (`cam.profile.points`) replaced by `nodes`, one node
/// per line; the rest of the text (comments, layout) is kept.
pub fn patch_nodes(text: &str, nodes: &[[f64; 2]]) -> Result<String, StudioError> {
    use toml_edit::{Array, DocumentMut, Item, Value};
    let mut doc: DocumentMut = text.parse().map_err(|e: toml_edit::TomlError| {
        let at = e
            .span()
            .map(|s| crate::mechtext::line_column(text, s.start));
        StudioError::Input {
            message: format!("the text is not valid TOML: {}", e.message()),
            at,
        }
    })?;
    if nodes.len() > camkin::curve::MAX_POINTS {
        return Err(StudioError::BadRequest {
            message: format!(
                "nodes: {} points is more than {}",
                nodes.len(),
                camkin::curve::MAX_POINTS
            ),
        });
    }
    if let Some((i, p)) = nodes
        .iter()
        .enumerate()
        .find(|(_, p)| !(p[0].is_finite() && p[1].is_finite()))
    {
        return Err(StudioError::BadRequest {
            message: format!("nodes[{i}] = [{}, {}]: not finite", p[0], p[1]),
        });
    }
    let profile = doc
        .get_mut("cam")
        .and_then(|c| c.get_mut("profile"))
        .and_then(Item::as_table_like_mut);
    let Some(profile) = profile else {
        return Err(StudioError::BadRequest {
            message: "nodes: the text has no [cam.profile] table to put them in".into(),
        });
    };
    let kind = profile.get("kind").and_then(Item::as_str);
    if kind != Some("spline") || profile.get("points").is_none() {
        return Err(StudioError::BadRequest {
            message: "nodes: only a spline profile with inline points (kind = \"spline\", points = [...]) can be edited on the drawing".into(),
        });
    }
    // the file's layout kept: where the points are as many as the nodes, only the numbers that
    // changed are replaced, each in its place (its spacing, its line, its comments stay)
    if let Some(existing) = profile
        .get_mut("points")
        .and_then(Item::as_value_mut)
        .and_then(Value::as_array_mut)
    {
        let pairs = existing.len() == nodes.len()
            && existing
                .iter()
                .all(|v| v.as_array().is_some_and(|a| a.len() == 2));
        if pairs {
            for (i, p) in nodes.iter().enumerate() {
                let Some(pair) = existing.get_mut(i).and_then(Value::as_array_mut) else {
                    continue;
                };
                for (j, &x) in p.iter().enumerate() {
                    let old = pair
                        .get(j)
                        .and_then(|v| v.as_float().or(v.as_integer().map(|n| n as f64)));
                    if old != Some(x) {
                        pair.replace(j, x);
                    }
                }
            }
            return Ok(doc.to_string());
        }
    }
    let mut array = Array::new();
    for p in nodes {
        let mut pair = Array::new();
        pair.push(p[0]);
        pair.push(p[1]);
        let mut v = Value::Array(pair);
        v.decor_mut().set_prefix("\n    ");
        array.push_formatted(v);
    }
    array.set_trailing("\n");
    array.set_trailing_comma(true);
    profile.insert("points", Item::Value(Value::Array(array)));
    Ok(doc.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn patched_nodes_keep_the_rest_of_the_text() {
        let text = crate::mechtext::PAPER_TOML;
        let nodes: Vec<[f64; 2]> = (0..9)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / 9.0;
                [4.0 * t.cos() + 0.5, 3.0 * t.sin()]
            })
            .collect();
        let out = patch_nodes(text, &nodes).unwrap();
        assert!(out.contains("# The paper's cam"), "{out}");
        assert!(out.contains("speed_rpm = 1000.0"));
        let spec = crate::mechtext::parse_spec(&out, "m").unwrap();
        assert_eq!(spec.cam.profile.points.unwrap(), nodes);
    }

    /// Issue 49: a drag keeps the file's layout: a two-line array stays two lines, and only the
    /// moved node's numbers change.
    #[test]
    fn a_drag_changes_only_the_numbers_that_moved() {
        let text = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 1000.0\n[cam.profile]\nkind = \"spline\"\npoints = [[40.0, 0.0], [0.0, 30.0], [-40.0, 0.0],  # the left\n  [0.0, -30.0]]\n[follower]\nkind = \"translating-flat\"\n";
        let nodes = [[40.0, 0.0], [0.0, 31.5], [-40.0, 0.0], [0.0, -30.0]];
        let out = patch_nodes(text, &nodes).unwrap();
        assert_eq!(out, text.replace("[0.0, 30.0]", "[0.0, 31.5]"), "{out}");
        let spec = crate::mechtext::parse_spec(&out, "m").unwrap();
        assert_eq!(spec.cam.profile.points.unwrap(), nodes);
    }

    /// A gear pair's `[gear_loads]` without a face width: the kinematics are shown, and the
    /// loads' reason is a warning, not an error of the whole page.
    #[test]
    fn loads_the_file_cannot_give_leave_the_kinematics_shown() {
        let text = "length_unit = \"mm\"\n[gear_pair]\nteeth = [20, 42]\nmodule = 2.0\nspeed_rpm = 1000.0\n[gear_loads]\ntorque = 5.0\n";
        let source = source::Source {
            name: "g.toml".into(),
            folder: None,
        };
        let a = analysis::analyze(text, &source, 1.0, 30.0, &Limits::default()).unwrap();
        assert!(a.gear_loads.is_none());
        assert!(
            a.warnings.iter().any(|w| w.message.contains("face width")),
            "{:?}",
            a.warnings
        );
        let with = format!("{text}face_width = 20.0\n");
        let a = analysis::analyze(&with, &source, 1.0, 30.0, &Limits::default()).unwrap();
        assert!(a.gear_loads.is_some());
    }

    #[test]
    fn nodes_only_on_inline_splines() {
        let circle = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 1.0\n[cam.profile]\nkind = \"circle\"\nradius = 2.0\n";
        let e = patch_nodes(circle, &[[1.0, 0.0]]).unwrap_err();
        assert_eq!(e.status(), 400);
        let e = patch_nodes("x = [", &[[1.0, 0.0]]).unwrap_err();
        assert!(
            matches!(
                e,
                StudioError::Input {
                    at: Some((1, _)),
                    ..
                }
            ),
            "{e:?}"
        );
        let e = patch_nodes(crate::mechtext::PAPER_TOML, &[[f64::NAN, 0.0]]).unwrap_err();
        assert_eq!(e.status(), 400);
    }

    #[test]
    fn steps_divide_the_revolution_within_limits() {
        let l = Limits::default();
        assert_eq!(step(None, &l).unwrap(), 0.5);
        assert_eq!(step(Some(0.25), &l).unwrap(), 0.25);
        for bad in [0.0, -1.0, 0.01, 7.0, 20.0, f64::NAN] {
            assert!(step(Some(bad), &l).is_err(), "{bad}");
        }
    }
}
