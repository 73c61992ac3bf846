//! The studio's page in a notebook: its requests (`analyze`, `compare`) answered by the same
//! code as `camkin serve`'s ([`camkin_studio::api`]), for the Jupyter widget
//! (`camkin.widget.Studio`), which carries them between the page and the kernel.

use camkin_studio::source::Source;
use camkin_studio::{assets, Limits};
use pyo3::prelude::*;
use std::path::PathBuf;

/// _studio_answer(what, body, name, folder=None) -> (status, answer, toml)
///
/// The page's request ``what`` (``"analyze"`` or ``"compare"``) with its JSON ``body``
/// answered: the HTTP-like status (200, or a refusal's 4xx), the answer's JSON text, and for an
/// analysis the mechanism text analysed (dragged nodes written in; None otherwise). ``name``
/// names the mechanism in messages; ``folder`` is the only folder its points files are read
/// from (None: none read).
#[pyfunction]
#[pyo3(signature = (what, body, name, folder = None))]
pub fn _studio_answer(
    py: Python<'_>,
    what: &str,
    body: &str,
    name: String,
    folder: Option<PathBuf>,
) -> (u16, String, Option<String>) {
    let source = Source { name, folder };
    py.detach(|| {
        let limits = Limits::default();
        let toml = if what == "analyze" {
            camkin_studio::api::check_analysis_request(body.as_bytes(), &limits)
                .ok()
                .map(|(t, _, _)| t)
        } else {
            None
        };
        let (status, text) = camkin_studio::api::answer(what, body.as_bytes(), &source, &limits);
        (status, text, if status == 200 { toml } else { None })
    })
}

/// _studio_assets() -> (html, css, js): the studio's page, style and script, as `camkin serve`
/// sends them.
#[pyfunction]
pub fn _studio_assets() -> (&'static str, &'static str, &'static str) {
    (assets::INDEX_HTML, assets::STYLE_CSS, assets::STUDIO_JS)
}
