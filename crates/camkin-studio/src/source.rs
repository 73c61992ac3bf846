//! Where a studio file's text comes from, and how it is built: a mechanism (a cam-follower or
//! gear-pair file) or a system, its points files confined to the source's folder.

use super::{Limits, StudioError};
use crate::mechtext::{self as mechfile, FromText};
use camkin::spec::{BuildOptions, MechanismSpec};
use std::path::PathBuf;

/// Where a mechanism's text comes from: its name for messages and the folder its points files
/// may be read from (none for the built-in paper cam).
#[derive(Debug, Clone)]
pub struct Source {
    /// the file's name (`paper.toml`)
    pub name: String,
    /// the folder of the file, the only one read from
    pub folder: Option<PathBuf>,
}

/// How a spec from `source` is built: points files confined to the source's folder (the
/// built-in cam has none, so it may read no file at all).
pub fn build_options_for(
    spec: &MechanismSpec,
    source: &Source,
    si: bool,
    limits: &Limits,
) -> Result<BuildOptions, StudioError> {
    build_options(spec.cam.profile.path.is_some(), source, si, limits)
}

/// How a file from `source` that reads a points file for its cam (`cam_file`) is built.
pub fn build_options(
    cam_file: bool,
    source: &Source,
    si: bool,
    limits: &Limits,
) -> Result<BuildOptions, StudioError> {
    let base_dir = match &source.folder {
        Some(f) => f.clone(),
        None if cam_file => {
            return Err(StudioError::Input {
                message: "cam.profile.path: no folder is open, so no points file can be read; start `camkin serve FILE.toml` to read points files beside FILE.toml".into(),
                at: None,
            });
        }
        None => PathBuf::from("."),
    };
    Ok(BuildOptions {
        base_dir,
        si,
        confine: true,
        limits: camkin::work::Limits {
            seconds: limits.max_seconds,
            bytes: limits.max_request_bytes,
        },
    })
}

/// Builds the mechanism in `text` (in its own units), errors and warnings placed in the text.
pub fn build(text: &str, source: &Source, limits: &Limits) -> Result<FromText, StudioError> {
    let spec = mechfile::parse_spec(text, &source.name)?;
    let options = build_options_for(&spec, source, false, limits)?;
    let (built, warnings) = mechfile::build_placed(&spec, text, &source.name, &options)?;
    Ok(FromText {
        spec,
        built,
        warnings,
    })
}

/// Whether `text` is a system file.
pub fn is_system(text: &str) -> bool {
    camkin::spec::text::is_system(text)
}

/// The system in `text`, its points files read only from the source's folder.
pub fn build_system(
    text: &str,
    source: &Source,
    limits: &Limits,
) -> Result<camkin::spec::BuiltSystem, StudioError> {
    let options = build_options(false, source, false, limits)?;
    camkin::spec::text::read_system(text, &source.name, &options).map_err(|e| StudioError::Input {
        message: e.message,
        at: e.at,
    })
}

/// Whether the system in `text` builds (the studio opens a file with an error to be mended).
pub fn check_system(text: &str, source: &Source, limits: &Limits) -> Result<(), StudioError> {
    build_system(text, source, limits).map(|_| ())
}
