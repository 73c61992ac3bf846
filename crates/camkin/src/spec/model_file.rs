//! A mechanism file read once as one model ([`read_model`]): a system file's system, or a
//! cam-follower or gear-pair file's preset, which builds that system on demand. The model picks
//! its solver ([`ModelFile::solver`]): the one-coordinate cam solver answers a preset by its
//! closed forms, the general solver answers a system by Newton on its rows. Front ends ask the
//! model, never the file's text, which solver is theirs.

use super::text::{self, PlacedWarning, TextError};
use super::{BuildOptions, Built, BuiltSystem, LengthUnit, MechanismSpec};
use std::borrow::Cow;

/// A cam-follower or gear-pair file's preset: the spec as read, the mechanism it builds and its
/// warnings placed in the text. The mechanism carries the cam's vocabulary (lift, pressure
/// angle, synthesis, shop output, design checks) and is what the one-coordinate cam solver
/// answers; [`ModelFile::to_system`] is the same mechanism as a system of bodies, joints, a
/// driver and a contact ([`crate::cam::Mechanism::to_system`]).
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
#[derive(Debug, Clone, Copy)]
#[non_exhaustive]
pub enum Solver<'m> {
    /// the one-coordinate cam solver: the follower's closed forms per kind, the fast path (a
    /// cam-follower or gear-pair preset)
    Cam(&'m Preset),
    /// the general solver: Newton on the system's constraint rows, the paper's `γ` for every
    /// contact (a system file)
    General(&'m BuiltSystem),
}

/// A mechanism file read as one model (see the [module docs](self)).
#[derive(Debug, Clone)]
pub struct ModelFile {
    name: String,
    text: String,
    model: Model,
}

#[derive(Debug, Clone)]
enum Model {
    Preset(Box<Preset>),
    System(Box<BuiltSystem>),
}

/// Reads the mechanism file `text` (`name` for messages) as one model: a system file
/// (`[[body]]`, `[[joint]]`, …) builds its system, a cam-follower or gear-pair file its preset;
/// errors are placed at their keys ([`text`]).
///
/// `options.si` builds a preset in metres (the cam solver's dynamics compute in SI); a system is
/// built in its file's unit whatever `si` says, its dynamics scaling by
/// [`crate::dynamics::SystemDynamicsOptions::metres_per_unit`], so one read serves both kinds.
pub fn read_model(text: &str, name: &str, options: &BuildOptions) -> Result<ModelFile, TextError> {
    let kind = text::FileKind::of(text);
    let model = if kind == text::FileKind::System {
        let spec = text::parse_system_toml(text, name)?;
        let options = BuildOptions {
            si: false,
            ..options.clone()
        };
        Model::System(Box::new(text::build_system_placed(
            &spec, text, name, &options,
        )?))
    } else {
        let spec = text::parse_toml_of(text, name, kind)?;
        let (built, warnings) = text::build_placed(&spec, text, name, options)?;
        Model::Preset(Box::new(Preset {
            spec,
            built,
            warnings,
        }))
    };
    Ok(ModelFile {
        name: name.to_string(),
        text: text.to_string(),
        model,
    })
}

impl ModelFile {
    /// The built-in model `preset` (no text: nothing to place its messages in), called `name`.
    pub fn of_preset(preset: Preset, name: &str) -> Self {
        Self {
            name: name.to_string(),
            text: String::new(),
            model: Model::Preset(Box::new(preset)),
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

    /// The preset, taken; `None` for a system file.
    pub fn into_preset(self) -> Option<Preset> {
        match self.model {
            Model::Preset(p) => Some(*p),
            Model::System(_) => None,
        }
    }

    /// The model's length unit.
    pub fn length_unit(&self) -> LengthUnit {
        match &self.model {
            Model::Preset(p) => p.built.length_unit,
            Model::System(s) => s.length_unit,
        }
    }

    /// The model as a system, for the general solver: a system file's own, or a preset's
    /// mechanism as one ([`BuiltSystem::from_mechanism`], swept over its cam angle, the preset's
    /// warnings kept); a preset that cannot be one is an error placed in the text.
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
        match self.to_system()? {
            Cow::Owned(s) => Ok(s),
            Cow::Borrowed(_) => match self.model {
                Model::System(s) => Ok(*s),
                Model::Preset(_) => unreachable!("a preset's system is built, not borrowed"),
            },
        }
    }

    /// Its warnings as people read them: a preset's placed in the text (`name:line:column:
    /// …`), a system's after the file's name.
    pub fn warning_messages(&self) -> Vec<String> {
        match &self.model {
            Model::Preset(p) => p.warnings.iter().map(|w| w.message.clone()).collect(),
            Model::System(s) => s
                .warnings
                .iter()
                .map(|w| format!("{}: {w}", self.name))
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const CAM: &str = include_str!("../../../../examples/paper.toml");
    const SYSTEM: &str = include_str!("../../../../examples/cam-four-bar.toml");

    /// A cam-follower file is answered by the cam solver and a system file by the general one,
    /// whatever else they hold; the cam file as a system is swept over its cam angle, and a
    /// system is built in its file's unit even when a preset would be built in metres.
    #[test]
    fn the_model_picks_its_solver() {
        let options = BuildOptions::default();
        let cam = read_model(CAM, "paper.toml", &options).unwrap();
        assert!(matches!(cam.solver(), Solver::Cam(_)));
        assert!(cam.preset().is_some());
        let as_system = cam.to_system().unwrap();
        assert_eq!(as_system.angle_name(), "cam angle");
        assert_eq!(as_system.length_unit, cam.length_unit());

        let si = BuildOptions {
            si: true,
            ..options.clone()
        };
        let system = read_model(SYSTEM, "cam-four-bar.toml", &si).unwrap();
        let Solver::General(built) = system.solver() else {
            panic!("a system file is answered by the general solver")
        };
        let plain = read_model(SYSTEM, "cam-four-bar.toml", &options).unwrap();
        let Solver::General(plain) = plain.solver() else {
            panic!("a system file is answered by the general solver")
        };
        assert_eq!(
            built.dynamics.metres_per_unit,
            plain.dynamics.metres_per_unit
        );
        assert!(built.dynamics.metres_per_unit < 1.0);
        assert!(system.preset().is_none());
        assert!(matches!(system.to_system(), Ok(Cow::Borrowed(_))));

        let cam_si = read_model(CAM, "paper.toml", &si).unwrap();
        assert!(cam_si.preset().unwrap().built.si);
    }
}
