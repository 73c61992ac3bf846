//! The studio's answers for any file it opens, one path each: a cam-follower or gear-pair
//! mechanism ([`crate::model`]), a system whose every degree of freedom is driven
//! ([`crate::kinematic`]) or one moved by its forces ([`crate::simulated`]).

use super::answer::{Analysis, CellTable};
use super::source::{read, Source};
use super::{Limits, StudioError};
use camkin::spec::{ModelFile, Solver};

/// The analysis of the file `text` at `step_deg` (a mechanism's checks against
/// `pressure_limit_deg`).
pub fn analyze(
    text: &str,
    source: &Source,
    step_deg: f64,
    pressure_limit_deg: f64,
    limits: &Limits,
) -> Result<Analysis, StudioError> {
    let model = read(text, source, limits)?;
    analyze_model(&model, source, step_deg, pressure_limit_deg, limits)
}

/// The analysis of `model` read from `source`, by the solver it picks: a preset's by the cam
/// solver; a system's by the general one, with `[dynamics]` its simulation and the force panel.
pub fn analyze_model(
    model: &ModelFile,
    source: &Source,
    step_deg: f64,
    pressure_limit_deg: f64,
    limits: &Limits,
) -> Result<Analysis, StudioError> {
    match model.solver() {
        Solver::General(built) if built.simulated => {
            super::simulated::analyze(built, &source.name, step_deg, limits)
        }
        Solver::General(built) => super::kinematic::analyze(built, &source.name, step_deg, limits),
        Solver::Cam(preset) => super::model::analyze_mechanism(
            model.text(),
            preset,
            source,
            step_deg,
            pressure_limit_deg,
            limits,
        ),
    }
}

/// A system's table at `step_deg` over a revolution: what `camkin analyze FILE --angles
/// 0:360:STEP` writes (a simulated system's, what `camkin simulate FILE --step STEP` does).
pub fn system_table(
    built: &camkin::spec::BuiltSystem,
    step_deg: f64,
    limits: &Limits,
) -> Result<CellTable, StudioError> {
    if built.simulated {
        super::simulated::table(built, step_deg, limits)
    } else {
        super::kinematic::table(built, step_deg, limits)
    }
}
