//! The studio's answers for any file it opens, one path each: a cam-follower or gear-pair
//! mechanism ([`crate::model`]), a system whose every degree of freedom is driven
//! ([`crate::kinematic`]) or one moved by its forces ([`crate::simulated`]).

use super::answer::{Analysis, CellTable};
use super::source::{build_system, is_system, Source};
use super::{Limits, StudioError};

/// The analysis of the file `text` at `step_deg` (a mechanism's checks against
/// `pressure_limit_deg`).
pub fn analyze(
    text: &str,
    source: &Source,
    step_deg: f64,
    pressure_limit_deg: f64,
    limits: &Limits,
) -> Result<Analysis, StudioError> {
    if !is_system(text) {
        return super::model::analyze_mechanism(text, source, step_deg, pressure_limit_deg, limits);
    }
    let built = build_system(text, source, limits)?;
    // with [dynamics]: its simulation, and the force panel
    if built.simulated {
        super::simulated::analyze(&built, &source.name, step_deg, limits)
    } else {
        super::kinematic::analyze(&built, &source.name, step_deg, limits)
    }
}

/// A system file's table at `step_deg` over a revolution: what `camkin analyze FILE --angles
/// 0:360:STEP` writes (a simulated system's, what `camkin simulate FILE --step STEP` does).
pub fn system_table(
    text: &str,
    source: &Source,
    step_deg: f64,
    limits: &Limits,
) -> Result<CellTable, StudioError> {
    let built = build_system(text, source, limits)?;
    if built.simulated {
        super::simulated::table(&built, step_deg, limits)
    } else {
        super::kinematic::table(&built, step_deg, limits)
    }
}
