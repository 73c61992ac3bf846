//! A mechanism file read once as one model ([`read_model`]): a system file's system, or a
//! cam-follower or gear-pair file's preset (that system on demand). The model picks its solver
//! ([`ModelFile::solver`]); front ends never ask the file's text.

use super::text::{self, PlacedWarning, TextError};
use super::{BuildOptions, Built, BuiltSystem, MechanismSpec};
use std::borrow::Cow;

/// A cam-follower or gear-pair file's preset: its spec, the mechanism it builds (the cam's
/// vocabulary: lift, pressure angle, synthesis, shop output, checks; what the cam solver answers)
/// and its warnings placed in the text.
#[derive(Debug, Clone)]
pub struct Preset {
    /// the spec as read (to build variants of it)
    pub spec: MechanismSpec,
    /// what it builds
    pub built: Built,
    /// what is valid but probably not meant, placed in the text
    pub warnings: Vec<PlacedWarning>,
}

/// Which solver answers a model, with what it answers.
/// Not `non_exhaustive`: a new solver must be answered by every front end, which the compiler
/// checks.
#[derive(Debug, Clone, Copy)]
pub enum Solver<'m> {
    /// the one-coordinate cam solver (the follower's closed forms per kind) of a preset
    Cam(&'m Preset),
    /// the general solver (Newton on the rows, the paper's `γ` per contact) of a system file
    General(&'m BuiltSystem),
}

/// A mechanism file read as one model ([`read_model`]), which picks its solver.
#[derive(Debug, Clone)]
pub struct ModelFile {
    name: String,
    text: String,
    model: Model,
    /// every file it reads (points files), in the folder it was read from
    inputs: Vec<std::path::PathBuf>,
}

#[derive(Debug, Clone)]
enum Model {
    Preset(Box<Preset>),
    System(Box<BuiltSystem>),
}

/// Reads the file `text` (`name` for messages) as one model, errors placed at their keys.
/// `options.si` builds a preset in metres (the cam solver's dynamics compute in SI); a system is
/// built in its file's unit whatever `si` says, its dynamics scaling by
/// [`crate::dynamics::SystemDynamicsOptions::metres_per_unit`].
pub fn read_model(text: &str, name: &str, options: &BuildOptions) -> Result<ModelFile, TextError> {
    let kind = text::FileKind::of(text);
    let (model, files) = if kind == text::FileKind::System {
        let spec: super::SystemSpec = text::parse_toml_as(text, name)?;
        let mut options = options.clone();
        options.si = false;
        let built = spec.build(&options);
        let files = spec.contact.iter().flat_map(|c| [&c.curve_a, &c.curve_b]);
        let files = files.flat_map(|p| p.files().map(String::from)).collect();
        (
            Model::System(Box::new(built.map_err(|e| text::place(text, name, e))?)),
            files,
        )
    } else {
        let spec = text::parse_toml_of(text, name, kind)?;
        let (built, warnings) = text::build_placed(&spec, text, name, options)?;
        let files: Vec<String> = spec.files().into_iter().map(String::from).collect();
        (
            Model::Preset(Box::new(Preset {
                spec,
                built,
                warnings,
            })),
            files,
        )
    };
    Ok(ModelFile {
        name: name.to_string(),
        text: text.to_string(),
        model,
        inputs: files.iter().map(|f| options.base_dir.join(f)).collect(),
    })
}

impl ModelFile {
    /// The built-in model `preset` (no text), called `name`.
    pub fn of_preset(preset: Preset, name: &str) -> Self {
        Self {
            name: name.to_string(),
            text: String::new(),
            model: Model::Preset(Box::new(preset)),
            inputs: Vec::new(),
        }
    }

    /// The file's name, for messages.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The text it was read from (empty for a built-in model).
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Every file the model reads (its points files): inputs, which no output may replace.
    pub fn inputs(&self) -> &[std::path::PathBuf] {
        &self.inputs
    }

    /// The solver that answers this model, with what it answers.
    pub fn solver(&self) -> Solver<'_> {
        match &self.model {
            Model::Preset(p) => Solver::Cam(p),
            Model::System(s) => Solver::General(s),
        }
    }

    /// The preset, for what needs the cam's vocabulary; `None` for a system file.
    pub fn preset(&self) -> Option<&Preset> {
        match &self.model {
            Model::Preset(p) => Some(p),
            Model::System(_) => None,
        }
    }

    /// The preset, taken; a system file's model is given back.
    pub fn into_preset(self) -> Result<Preset, Self> {
        match self.model {
            Model::Preset(p) => Ok(*p),
            Model::System(_) => Err(self),
        }
    }

    /// The model as a system, for the general solver: a system file's own, or a preset's
    /// mechanism as one ([`BuiltSystem::from_mechanism`]), the preset's warnings kept.
    pub fn to_system(&self) -> Result<Cow<'_, BuiltSystem>, TextError> {
        match &self.model {
            Model::System(s) => Ok(Cow::Borrowed(s)),
            Model::Preset(p) => {
                let mut system =
                    BuiltSystem::from_mechanism(&p.built.mechanism, p.built.length_unit)
                        .map_err(|e| text::place(&self.text, &self.name, e.into()))?;
                system.warnings.extend(p.built.warnings.iter().cloned());
                Ok(Cow::Owned(system))
            }
        }
    }

    /// The model as a system, taken (see [`Self::to_system`]).
    pub fn into_system(self) -> Result<BuiltSystem, TextError> {
        match self.model {
            Model::System(s) => Ok(*s),
            Model::Preset(_) => self.to_system().map(Cow::into_owned),
        }
    }
}
