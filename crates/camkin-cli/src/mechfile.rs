//! Mechanism files (TOML) for the command and the studio: the library's one reader
//! ([`camkin::spec::text`]: bounded read, TOML to spec, errors and warnings placed at their
//! keys' lines and columns), with the command's own wording of a missing `[dynamics]` and its
//! warnings printed on stderr.

use crate::Failure;
use camkin::cam::Mechanism;
use camkin::dynamics::FollowerDynamics;
use camkin::spec::text;
use camkin::spec::{BuildOptions, Built, MechanismSpec, ModelFile};
use std::path::Path;

pub use camkin_studio::mechtext::{
    build_placed, line_column, paper, parse_spec, InputError, MAX_FILE_BYTES, MAX_POINTS,
    PAPER_TOML,
};

/// Whether the user allowed large work (`--large`): set once by the command from its
/// arguments, read when a mechanism is built (a profile whose search index would take over
/// the library's limits is refused without it).
static LARGE: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Allows (or not) building mechanisms over the library's work limits, for this run.
pub fn allow_large(large: bool) {
    LARGE.store(large, std::sync::atomic::Ordering::Relaxed);
}

/// The work limits of building a mechanism in this run.
pub fn build_limits() -> camkin::work::Limits {
    if LARGE.load(std::sync::atomic::Ordering::Relaxed) {
        camkin::work::Limits::NONE
    } else {
        camkin::work::Limits::default()
    }
}

/// Reads a mechanism file's text (at most [`MAX_FILE_BYTES`] counted while reading, a byte-order
/// mark dropped): `(name for messages, text)`.
pub fn read_text(path: &Path) -> Result<(String, String), InputError> {
    let read = text::read_file(path)?;
    crate::output::note_input(path);
    Ok(read)
}

/// Reads and builds a mechanism file; every error is bad input (exit code 2).
pub fn load(path: &Path) -> Result<Mechanism, InputError> {
    let (name, text) = read_text(path)?;
    parse(&text, &name, path.parent().unwrap_or(Path::new(".")))
}

/// Reads and builds a mechanism file in its own length unit, with its unit and warnings.
pub fn load_built(path: &Path) -> Result<Built, InputError> {
    load_with_spec(path).map(|(_, b)| b)
}

/// Reads a mechanism file once: its spec (to build variants of it) and the mechanism it builds.
pub fn load_with_spec(path: &Path) -> Result<(MechanismSpec, Built), InputError> {
    let (name, text) = read_text(path)?;
    let spec = parse_spec(&text, &name)?;
    let built = build_spec(&spec, &text, &name, path.parent().unwrap_or(Path::new(".")))?;
    Ok((spec, built))
}

/// A preset's `[dynamics]` (`name` for the message when it has none).
pub fn dynamics_of(built: &Built, name: &str) -> Result<FollowerDynamics, Failure> {
    built.dynamics.ok_or_else(|| Failure::Input(anyhow::anyhow!("{name}: this command needs a [dynamics] section (mass or inertia; spring_stiffness and spring_preload, default 0, damping, restitution, gravity optional)")))
}

/// Parses and builds a mechanism from the text of a mechanism file called `name` (for messages);
/// `base` resolves a relative points-file path.
pub fn parse(text: &str, name: &str, base: &Path) -> Result<Mechanism, InputError> {
    let spec = parse_spec(text, name)?;
    build_spec(&spec, text, name, base).map(|b| b.mechanism)
}

/// How a file in the folder `base` is built in this run (`si`: in metres).
fn options(base: &Path, si: bool) -> BuildOptions {
    BuildOptions {
        base_dir: base.to_path_buf(),
        si,
        confine: false,
        limits: build_limits(),
    }
}

/// Notes the points files of `spec` (in the folder `base`) as inputs of the run: no output may
/// replace them.
fn note_files(spec: &MechanismSpec, base: &Path) {
    for f in spec.files() {
        crate::output::note_input(&base.join(f));
    }
}

/// `e`, saying how to build what is over the work limits anyway.
fn with_large_hint(mut e: InputError) -> InputError {
    if e.too_much {
        e.message.push_str("; pass --large to build it anyway");
    }
    e
}

/// Builds a parsed spec, placing errors in `text`; warnings are printed.
fn build_spec(
    spec: &MechanismSpec,
    text: &str,
    name: &str,
    base: &Path,
) -> Result<Built, InputError> {
    note_files(spec, base);
    let (built, warnings) =
        build_placed(spec, text, name, &options(base, false)).map_err(with_large_hint)?;
    for w in warnings {
        crate::say!("camkin: warning: {}", w.message);
    }
    Ok(built)
}

/// A mechanism file read once as one model, which picks its solver
/// ([`camkin::spec::ModelFile::solver`]), with its name for titles.
#[derive(Debug, Clone)]
pub struct LoadedModel {
    /// the model
    pub model: ModelFile,
    /// the file's name without its folder and extension (`paper` for the built-in cam)
    pub stem: String,
}

/// What a command answers, as the model's solver picked it.
#[derive(Debug)]
pub enum BySolver {
    /// the one-coordinate cam solver's preset (a cam-follower or gear-pair file)
    Cam {
        /// the preset
        preset: Box<camkin::spec::Preset>,
        /// the file's name, for messages
        name: String,
        /// the file's name without its folder and extension, for titles
        stem: String,
    },
    /// the general solver's system
    General {
        /// the file's name, for messages
        name: String,
        /// the file's name without its folder and extension, for titles
        stem: String,
        /// the system
        built: Box<camkin::spec::BuiltSystem>,
    },
}

impl LoadedModel {
    /// What the command answers: the solver the model picks, or the general one on any model
    /// when `general` (`--system`: a preset's mechanism as a system); its warnings printed.
    pub fn by_solver(self, general: bool) -> Result<BySolver, Failure> {
        let name = self.model.name().to_string();
        let model = if general {
            // --system: the general solver on any model (a cam's preset as a system)
            self.model
        } else {
            match self.model.into_preset() {
                Ok(preset) => {
                    for w in &preset.warnings {
                        crate::say!("camkin: warning: {}", w.message);
                    }
                    return Ok(BySolver::Cam {
                        preset: Box::new(preset),
                        name,
                        stem: self.stem,
                    });
                }
                Err(model) => model,
            }
        };
        let built = model
            .into_system()
            .map_err(|e| Failure::Input(anyhow::anyhow!(e.message)))?;
        for w in &built.warnings {
            crate::say!("camkin: warning: {name}: {w}");
        }
        Ok(BySolver::General {
            name,
            stem: self.stem,
            built: Box::new(built),
        })
    }
}

/// Reads the mechanism file at `path` once as one model (`si`: a preset in metres, see
/// [`camkin::spec::read_model`]), or the paper's built-in cam (in cm) when there is none;
/// nothing is printed yet ([`LoadedModel::by_solver`] prints its warnings).
pub fn load_model(path: Option<&std::path::PathBuf>, si: bool) -> Result<LoadedModel, Failure> {
    let Some(path) = path else {
        crate::say!(
            "camkin: no mechanism file given; using the paper's cam (examples/paper.toml, lengths in cm)"
        );
        let preset = camkin::spec::Preset {
            spec: parse_spec(PAPER_TOML, "paper.toml")
                .map_err(|e| Failure::Input(anyhow::anyhow!(e)))?,
            built: Built {
                mechanism: paper(),
                dynamics: None,
                lubrication: None,
                gear_loads: None,
                length_unit: camkin::spec::LengthUnit::Cm,
                si: false,
                warnings: Vec::new(),
            },
            warnings: Vec::new(),
        };
        return Ok(LoadedModel {
            model: ModelFile::of_preset(preset, "paper"),
            stem: "paper".into(),
        });
    };
    let (name, text) = read_text(path).map_err(|e| Failure::Input(anyhow::anyhow!(e)))?;
    let base = path.parent().unwrap_or(Path::new("."));
    let model = camkin::spec::read_model(&text, &name, &options(base, si))
        .map_err(|e| Failure::Input(anyhow::anyhow!(with_large_hint(e.into()))))?;
    // every file the model reads is an input of the run: no output may replace it
    for f in model.inputs() {
        crate::output::note_input(f);
    }
    Ok(LoadedModel {
        model,
        stem: path.file_stem().map_or_else(
            || path.display().to_string(),
            |s| s.to_string_lossy().into(),
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> String {
        parse(text, "m.toml", Path::new("."))
            .map(|_| ())
            .unwrap_err()
            .message
    }

    #[test]
    fn example_file_is_the_built_in_paper_mechanism() {
        let m = parse(PAPER_TOML, "paper.toml", Path::new(".")).unwrap();
        let (a, b) = (m.analyze(0.7).unwrap(), paper().analyze(0.7).unwrap());
        assert_eq!((a.position, a.acceleration), (b.position, b.acceleration));
    }

    #[test]
    fn errors_name_line_field_and_value() {
        let e = err(&PAPER_TOML.replace("direction = [1.0, 0.0]", "roller_radius = 1.0"));
        assert!(
            e.contains("takes no `roller_radius`") && e.contains("m.toml:"),
            "{e}"
        );
        let e = err(&PAPER_TOML.replace("kind = \"spline\"", "kind = \"blob\""));
        assert!(e.contains("\"blob\"") && e.contains("m.toml:11:8:"), "{e}");
        let e = err(&PAPER_TOML.replace("speed_rpm = 1000.0", "speed_rpm = -5.0"));
        assert!(
            e.contains("cam.speed_rpm = -5") && e.contains("m.toml:6:"),
            "{e}"
        );
        let e = err(&PAPER_TOML.replace("speed_rpm = 1000.0", "speed_rpm = \"fast\""));
        assert!(e.contains("line 6") && e.contains("speed_rpm"), "{e}");
    }
}
