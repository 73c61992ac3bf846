//! The first-touch query engine: everything a first-touch query needs, owned in one place —
//! the profile with its search index (samples and their trees, corners, cusps, summary), the
//! follower's model and joint, and the options with their prepared constants — apart from the
//! mechanism's public face ([`Mechanism`](super::Mechanism): construction and the public
//! queries). The query families live one file each, as parry's do: the named kinds' closed forms
//! and Newton (`search.rs`), the starts (`starts.rs`), a carried curve against a profile
//! (`carried.rs`, `carried_accept.rs`), corners (`corner_touch.rs`), overtaking (`overtake.rs`).

use super::follower::Geometry;
pub(crate) mod carried;
mod carried_accept;
pub(crate) mod corner_touch;
pub(crate) mod overtake;
pub(crate) mod search;
pub(crate) mod starts;

use super::{corners, AnalysisOptions, Cam};
use crate::geometry::Point2;
use std::sync::Arc;

/// The first-touch engine of one cam profile and one follower.
#[derive(Debug, Clone)]
pub(crate) struct FirstTouch {
    /// the cam: its profile (cam frame), axis, sense and speed
    pub(crate) cam: Cam,
    pub(crate) geometry: Geometry,
    pub(crate) options: AnalysisOptions,
    /// what the options give Newton and the first-touch test, prepared once
    pub(crate) prepared: search::Prepared,
    /// the profile's samples and their trees for the first-touch search
    pub(crate) index: Arc<starts::SearchIndex>,
    /// the profile's points at the dense samples (cam frame), for the coverage of a carried curve
    pub(crate) sample_points: Vec<Point2>,
    /// the longest chord between neighbouring `sample_points` (0 without them)
    pub(crate) sample_chord: f64,
    pub(crate) period: f64,
    pub(crate) size: f64,
    pub(crate) orientation: f64,
    pub(crate) convex: bool,
    /// the follower is a roller (translating or oscillating)
    pub(crate) roller: bool,
    /// the mean `|r'|` of the profile: below 1e-6 of it a contact is taken to sit on a cusp
    pub(crate) mean_speed: f64,
    /// the cusps of a folded profile (parameters)
    pub(crate) cusps: Vec<f64>,
    pub(crate) breakpoints: Vec<f64>,
    /// the profile's corners and the samples to measure a depth inside the cam from
    pub(crate) corners: Arc<corners::Corners>,
}

impl FirstTouch {
    /// How much earlier, in units of `q`, the follower touches at `q` than at `other`.
    pub(crate) fn ahead(&self, q: f64, other: f64) -> f64 {
        self.geometry
            .joint
            .difference(self.oriented(q), self.oriented(other))
    }

    /// Replaces the options: the samples, their trees and Newton's constants follow them.
    pub(crate) fn set_options(&mut self, options: AnalysisOptions) {
        let dense = search::bracket_samples(
            &self.breakpoints,
            self.period,
            options.samples_per_piece.max(2),
            options.samples_per_curve.max(8),
        );
        self.sample_points = if self.geometry.carried.is_some() {
            let profile = self.cam.profile.as_ref();
            dense.iter().map(|&u| profile.position(u)).collect()
        } else {
            Vec::new()
        };
        let n = self.sample_points.len();
        self.sample_chord = (0..n)
            .map(|i| (self.sample_points[(i + 1) % n] - self.sample_points[i]).norm())
            .fold(0.0, f64::max);
        let coarse = search::bracket_samples(
            &self.breakpoints,
            self.period,
            options.convex_samples_per_piece.max(2),
            options.convex_samples_per_curve.max(8),
        );
        self.index = Arc::new(starts::SearchIndex {
            dense: starts::Sampled::new(self, dense),
            coarse: starts::Sampled::new(self, coarse),
        });
        self.options = options;
        self.prepared = search::Prepared::new(&options, self.q_scale(), self.period);
    }
}
