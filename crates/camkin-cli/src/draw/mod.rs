//! Pictures: line charts (`chart`) and the mechanism drawn to scale (`mechanism`).

/// A scale bar's length for a drawing `span` wide: the largest 1, 2 or 5 times a power of ten
/// within a fifth of it.
pub fn scale_bar(span: f64) -> f64 {
    let t = 0.2 * span;
    let p = 10f64.powf(t.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * p)
        .find(|&b| b <= t)
        .unwrap_or(p)
}

pub mod chart;
pub mod lubrication;
pub mod mechanism;
pub mod svaj;
pub mod system;
