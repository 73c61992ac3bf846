//! The cam studio served: a local web page (`camkin serve`, [`server`]) and a self-contained
//! report (`camkin report`, [`report`]). What the page shows and how its requests are answered is
//! [`camkin_studio`]'s, shared with the Python package's Jupyter widget.

pub use camkin_studio::{
    analysis, answer, api, assets, model, page_precision, patch_nodes, pressure_limit, source,
    step, AnalyzeRequest, CompareRequest, ErrorBody, ErrorDetail, Limits, StudioError,
};

pub mod report;
pub mod server;
