//! Mechanism files (TOML) for the command and the studio: the library's one reader
//! ([`camkin::spec::text`]: bounded read, TOML to spec, errors and warnings placed at their
//! keys' lines and columns), with the command's own wording of a missing `[dynamics]` and its
//! warnings printed on stderr.

use camkin::cam::Mechanism;
use camkin::dynamics::FollowerDynamics;
use camkin::spec::text;
use camkin::spec::{BuildOptions, Built, MechanismSpec};
use std::path::Path;

pub use camkin_studio::mechtext::{
    build_placed, line_column, paper, parse_spec, FromText, InputError, Warning, MAX_FILE_BYTES,
    MAX_POINTS, PAPER_TOML,
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
    let built = build_spec(
        &spec,
        &text,
        &name,
        path.parent().unwrap_or(Path::new(".")),
        false,
    )?;
    Ok((spec, built))
}

/// Reads a mechanism file for a simulation (see [`parse_dynamics`]).
pub fn load_dynamics(
    path: &Path,
) -> Result<(Mechanism, FollowerDynamics, camkin::spec::LengthUnit), InputError> {
    load_forces(path).map(|(m, p, u, _)| (m, p, u))
}

/// A mechanism file built in SI units (lengths in metres), `[dynamics]` or not, with its length
/// unit and its `[lubrication]`.
pub fn load_si(path: &Path) -> Result<Built, InputError> {
    let (name, text) = read_text(path)?;
    build(&text, &name, path.parent().unwrap_or(Path::new(".")), true)
}

/// [`load_dynamics`] and the file's `[lubrication]`, when it has one.
pub fn load_forces(
    path: &Path,
) -> Result<
    (
        Mechanism,
        FollowerDynamics,
        camkin::spec::LengthUnit,
        Option<camkin::spec::BuiltLubrication>,
    ),
    InputError,
> {
    let (name, text) = read_text(path)?;
    let b = build(&text, &name, path.parent().unwrap_or(Path::new(".")), true)?;
    let unit = b.length_unit;
    Ok((b.mechanism, b.dynamics.ok_or_else(|| InputError::new(format!("{name}: this command needs a [dynamics] section (mass or inertia; spring_stiffness and spring_preload, default 0, damping, restitution, gravity optional)")))?, unit, b.lubrication))
}

/// Parses and builds a mechanism from the text of a mechanism file called `name` (for messages);
/// `base` resolves a relative points-file path.
pub fn parse(text: &str, name: &str, base: &Path) -> Result<Mechanism, InputError> {
    build(text, name, base, false).map(|b| b.mechanism)
}

/// Parses a mechanism file for a dynamic simulation: the geometry converted to metres with the
/// file's `length_unit`, and the `[dynamics]` section (required).
pub fn parse_dynamics(
    text: &str,
    name: &str,
    base: &Path,
) -> Result<(Mechanism, FollowerDynamics), InputError> {
    let b = build(text, name, base, true)?;
    Ok((b.mechanism, b.dynamics.ok_or_else(|| InputError::new(format!("{name}: a simulation needs a [dynamics] section (mass or inertia; spring_stiffness and spring_preload, default 0, damping, restitution, gravity optional)")))?))
}

fn build(text: &str, name: &str, base: &Path, si: bool) -> Result<Built, InputError> {
    let spec = parse_spec(text, name)?;
    build_spec(&spec, text, name, base, si)
}

/// Builds a parsed spec, placing errors in `text`; warnings are printed.
fn build_spec(
    spec: &MechanismSpec,
    text: &str,
    name: &str,
    base: &Path,
    si: bool,
) -> Result<Built, InputError> {
    let options = BuildOptions {
        base_dir: base.to_path_buf(),
        si,
        confine: false,
        limits: build_limits(),
    };
    // its points files are inputs of the run too: no output may replace them
    for f in spec.files() {
        crate::output::note_input(&base.join(f));
    }
    let (built, warnings) = build_placed(spec, text, name, &options).map_err(|mut e| {
        if e.too_much {
            e.message.push_str("; pass --large to build it anyway");
        }
        e
    })?;
    for w in warnings {
        crate::say!("camkin: warning: {}", w.message);
    }
    Ok(built)
}

/// The system in `text` (read from `path`, `name` for messages), built; errors at their keys.
/// A cam-follower or gear-pair file is its mechanism as a system.
pub fn load_system(
    path: &Path,
    name: &str,
    text: &str,
) -> Result<camkin::spec::BuiltSystem, crate::Failure> {
    let options = camkin::spec::BuildOptions {
        base_dir: path.parent().unwrap_or(Path::new(".")).to_path_buf(),
        si: false,
        confine: false,
        limits: build_limits(),
    };
    let built = camkin::spec::text::read_system(text, name, &options)
        .map_err(|e| crate::Failure::Input(anyhow::anyhow!(e.message)))?;
    for w in &built.warnings {
        crate::say!("camkin: warning: {name}: {w}");
    }
    Ok(built)
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
