//! Where a studio file's text comes from, and how it is built: a mechanism (a cam-follower or
//! gear-pair file) or a system, its points files confined to the source's folder.

use super::{Limits, StudioError};
use crate::mechtext::{self as mechfile, InputError};
use camkin::spec::text;
use camkin::spec::{BuildOptions, ModelFile, Preset};
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

/// How a file from `source` is built: points files confined to the source's folder; the
/// built-in cam has none, so a file read there that asks for a points file (`cam_file`) is
/// refused.
fn build_options(
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

/// How the spec of the cam `spec` from `source` is built (`si`: in metres, for its dynamics).
pub fn options_for(
    spec: &camkin::spec::MechanismSpec,
    source: &Source,
    si: bool,
    limits: &Limits,
) -> Result<BuildOptions, StudioError> {
    build_options(spec.cam.profile.path.is_some(), source, si, limits)
}

/// Reads `text` once as one model (see [`camkin::spec::read_model`]): its solver is the
/// studio's answer, a preset in its own units; errors and warnings placed in the text.
pub fn read(text: &str, source: &Source, limits: &Limits) -> Result<ModelFile, StudioError> {
    // without a folder no points file may be read: a cam that asks for one is refused first
    let cam_file = source.folder.is_none()
        && !camkin::spec::text::is_system(text)
        && mechfile::parse_spec(text, &source.name)?
            .cam
            .profile
            .path
            .is_some();
    let options = build_options(cam_file, source, false, limits)?;
    Ok(camkin::spec::read_model(text, &source.name, &options).map_err(InputError::from)?)
}

/// Builds the cam-follower or gear-pair file `text` (in its own units) for what only a cam
/// has (the interpolation study, shop output): a system file is refused with the library's
/// message.
pub fn build(text: &str, source: &Source, limits: &Limits) -> Result<Preset, StudioError> {
    let spec = mechfile::parse_spec(text, &source.name)?;
    let options = options_for(&spec, source, false, limits)?;
    let (built, warnings) =
        text::build_placed(&spec, text, &source.name, &options).map_err(InputError::from)?;
    Ok(Preset {
        spec,
        built,
        warnings,
    })
}
