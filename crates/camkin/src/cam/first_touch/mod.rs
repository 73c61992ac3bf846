//! The first-touch query engine: everything a first-touch query needs, owned in one place —
//! the profile with its search index (samples and their trees, corners, cusps, summary), the
//! follower's model and joint, and the options with their prepared constants — apart from the
//! mechanism's public face ([`Mechanism`](super::Mechanism): construction and the public
//! queries). The query families live one file each, as parry's do: the named kinds' closed forms
//! and Newton (`search.rs`), the starts (`starts.rs`), a carried curve against a profile
//! (`carried.rs`, `carried_accept.rs`), corners (`corner_touch.rs`), overtaking (`overtake.rs`).

use super::follower::{Geometry, Kind as _};
pub(crate) mod carried;
mod carried_accept;
pub(crate) mod corner_touch;
pub(crate) mod overtake;
pub(crate) mod search;
pub(crate) mod starts;

use super::summary::ProfileSummary;
use super::{corners, AnalysisOptions, Cam};
use crate::geometry::Point2;
use std::sync::Arc;

/// The first-touch engine of one cam profile and one follower. Its fields are its own: the
/// mechanism reads them through the accessors below.
#[derive(Debug, Clone)]
pub(crate) struct FirstTouch {
    /// the cam: its profile (cam frame), axis, sense and speed
    cam: Cam,
    geometry: Geometry,
    options: AnalysisOptions,
    /// what the options give Newton and the first-touch test, prepared once
    prepared: search::Prepared,
    /// the profile's samples and their trees for the first-touch search
    index: Arc<starts::SearchIndex>,
    /// the profile's points at the dense samples (cam frame), for the coverage of a carried curve
    sample_points: Vec<Point2>,
    /// the longest chord between neighbouring `sample_points` (0 without them)
    sample_chord: f64,
    period: f64,
    size: f64,
    orientation: f64,
    convex: bool,
    /// the follower is a roller (translating or oscillating)
    roller: bool,
    /// the mean `|r'|` of the profile: below 1e-6 of it a contact is taken to sit on a cusp
    mean_speed: f64,
    /// the cusps of a folded profile (parameters)
    cusps: Vec<f64>,
    breakpoints: Vec<f64>,
    /// the profile's corners and the samples to measure a depth inside the cam from
    corners: Arc<corners::Corners>,
}

impl FirstTouch {
    /// The engine of `cam` and the follower `geometry` on the profile of `summary` (its
    /// `period`, `breakpoints` and `corners`), its samples, trees and Newton's constants
    /// prepared for `options`.
    pub(crate) fn new(
        cam: Cam,
        geometry: Geometry,
        summary: ProfileSummary,
        period: f64,
        breakpoints: Vec<f64>,
        corners: Arc<corners::Corners>,
        options: AnalysisOptions,
    ) -> Self {
        let roller = geometry.model.roller_radius().is_some();
        let ProfileSummary {
            size,
            orientation,
            convex,
            mean_speed,
            cusps,
            ..
        } = summary;
        let mut touch = Self {
            cam,
            geometry,
            options,
            prepared: Default::default(),
            index: Arc::default(),
            sample_points: Vec::new(),
            sample_chord: 0.0,
            period,
            size,
            orientation,
            convex,
            roller,
            mean_speed,
            cusps,
            breakpoints,
            corners,
        };
        touch.set_options(options);
        touch
    }

    /// The cam: its profile (cam frame), axis, sense and speed.
    pub(crate) fn cam(&self) -> &Cam {
        &self.cam
    }

    /// The follower: its model, joint and curve.
    pub(crate) fn geometry(&self) -> &Geometry {
        &self.geometry
    }

    /// The analysis options in force.
    pub(crate) fn options(&self) -> &AnalysisOptions {
        &self.options
    }

    /// What the options give Newton and the first-touch test.
    pub(crate) fn prepared(&self) -> &search::Prepared {
        &self.prepared
    }

    /// The profile's samples and their trees.
    pub(crate) fn index(&self) -> &starts::SearchIndex {
        &self.index
    }

    /// The profile's parameter period.
    pub(crate) fn period(&self) -> f64 {
        self.period
    }

    /// The cam's size, its greatest reach from its axis.
    pub(crate) fn size(&self) -> f64 {
        self.size
    }

    /// `+1` for a counter-clockwise profile, `−1` for a clockwise one.
    pub(crate) fn orientation(&self) -> f64 {
        self.orientation
    }

    /// The profile is convex.
    pub(crate) fn convex(&self) -> bool {
        self.convex
    }

    /// The cusps of a folded profile (parameters).
    pub(crate) fn cusps(&self) -> &[f64] {
        &self.cusps
    }

    /// The profile's breakpoints (parameters).
    pub(crate) fn breakpoints(&self) -> &[f64] {
        &self.breakpoints
    }

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
