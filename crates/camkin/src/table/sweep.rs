//! The analysis table of a list of cam angles, computed chunk by chunk: the warm-started sweeps
//! of [`Mechanism::analyze_all`] (on all cores, the same rows whatever the chunk), contact jumps
//! marked (also across chunk seams) and lift measured from the follower's rest
//! position. Every front end that writes the table (`camkin analyze`, the Python package) runs
//! this one loop, so they give the same numbers to the last bit.

use super::AnalysisRow;
use crate::cam::{contact_jumps_with, CamError, FollowerState, Mechanism, Travel, SWEEP_CHUNK};
use crate::geometry::deg_to_rad;

/// How many jumped rows [`AnalysisSweep::jump_at`] keeps.
pub const JUMPS_KEPT: usize = 50;

/// The rows of the analysis at `angles_deg`, a chunk of at most `chunk` rows (rounded up to a
/// multiple of [`SWEEP_CHUNK`]) per [`Iterator::next`]; memory stays bounded whatever the number
/// of angles.
#[derive(Debug)]
pub struct AnalysisSweep<'a> {
    mech: &'a Mechanism,
    angles: &'a [f64],
    contiguous: bool,
    chunk: usize,
    conjugate: Option<crate::cam::ConjugateSweep<'a>>,
    stretches: Vec<(f64, f64)>,
    travel: Result<Travel, CamError>,
    prev: Option<Result<FollowerState, CamError>>,
    start: usize,
    failed: usize,
    jumps: usize,
    jump_at: Vec<usize>,
}

impl<'a> AnalysisSweep<'a> {
    /// The sweep over `angles_deg` (degrees, in any order). `contiguous` says the angles are a
    /// range in order: then a contact that passed over a stretch the follower cannot follow
    /// between two rows has jumped, and its row says so even when the warm start held.
    pub fn new(mech: &'a Mechanism, angles_deg: &'a [f64], contiguous: bool, chunk: usize) -> Self {
        Self::with_parts(
            mech,
            angles_deg,
            contiguous,
            chunk,
            mech.travel(),
            mech.unfollowable_stretches(),
        )
    }

    /// As [`AnalysisSweep::new`] with the mechanism's travel ([`Mechanism::travel`]) and
    /// unfollowable stretches ([`Mechanism::unfollowable_stretches`]) computed before (they
    /// depend on the mechanism alone, and the travel's search costs about as much as a thousand
    /// warm steps: a front end that sweeps one mechanism many times keeps them).
    pub fn with_parts(
        mech: &'a Mechanism,
        angles_deg: &'a [f64],
        contiguous: bool,
        chunk: usize,
        travel: Result<Travel, CamError>,
        stretches: Vec<(f64, f64)>,
    ) -> Self {
        Self {
            mech,
            angles: angles_deg,
            contiguous,
            // whole chunks of `Mechanism::analyze_all`, so that the rows are the same as its
            chunk: chunk.max(1).next_multiple_of(SWEEP_CHUNK),
            conjugate: mech.conjugate_sweep(),
            stretches,
            travel,
            prev: None,
            start: 0,
            failed: 0,
            jumps: 0,
            jump_at: Vec::new(),
        }
    }

    /// The follower's travel, the origin of the lift column; when it could not be found, why
    /// (the rows then have no lift).
    pub fn travel(&self) -> Result<&Travel, &CamError> {
        self.travel.as_ref()
    }

    /// The profile's stretches the follower cannot follow (parameter intervals), as
    /// [`Mechanism::unfollowable_stretches`].
    pub fn stretches(&self) -> &[(f64, f64)] {
        &self.stretches
    }

    /// Rows so far that could not be computed.
    pub fn failed(&self) -> usize {
        self.failed
    }

    /// Rows so far whose contact jumped.
    pub fn jumps(&self) -> usize {
        self.jumps
    }

    /// Indices of the first [`JUMPS_KEPT`] rows whose contact jumped.
    pub fn jump_at(&self) -> &[usize] {
        &self.jump_at
    }
}

impl Iterator for AnalysisSweep<'_> {
    type Item = Vec<AnalysisRow>;

    fn next(&mut self) -> Option<Vec<AnalysisRow>> {
        if self.start >= self.angles.len() {
            return None;
        }
        let chunk = &self.angles[self.start..(self.start + self.chunk).min(self.angles.len())];
        // the previous chunk's last result leads, so that a jump across the seam is seen
        let mut results: Vec<_> = self.prev.take().into_iter().collect();
        let lead = results.len();
        let thetas: Vec<f64> = chunk.iter().map(|&a| deg_to_rad(a)).collect();
        let before = self
            .start
            .checked_sub(1)
            .map(|k| deg_to_rad(self.angles[k]));
        results.extend(self.mech.analyze_all_after(before, &thetas));
        let jumps = contact_jumps_with(self.mech, &self.stretches, &results, self.contiguous);
        let mut rows = Vec::with_capacity(chunk.len());
        for (k, ((&a, r), &j)) in chunk
            .iter()
            .zip(&results[lead..])
            .zip(&jumps[lead..])
            .enumerate()
        {
            if r.is_err() {
                self.failed += 1;
            }
            if j {
                self.jumps += 1;
                if self.jump_at.len() < JUMPS_KEPT {
                    self.jump_at.push(self.start + k);
                }
            }
            let mut row = AnalysisRow::new(a, r, j);
            if let (Some(c), Ok(s)) = (self.conjugate.as_mut(), r) {
                match c.play(s) {
                    Ok(p) => row.conjugate_play = Some(p),
                    Err(e) => {
                        row.error = Some(format!("the conjugate curve: {e}"));
                        self.failed += 1;
                    }
                }
            }
            rows.push(match &self.travel {
                Ok(t) => row.with_lift(t),
                Err(_) => row,
            });
        }
        self.prev = results.pop();
        self.start += chunk.len();
        Some(rows)
    }
}
