//! The mechanism drawn as shapes in its own length unit: a cam-follower's (`mechanism`) and a
//! system's bodies, joints and contacts (`system`), for the studio and the command's pictures.

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

pub mod mechanism;
pub mod system;
