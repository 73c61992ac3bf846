//! Mechanism files (TOML): the library's [`MechanismSpec`] read from TOML, with every error
//! placed in the file.
//!
//! The schema and all of its validation live in the library ([`camkin::spec`]); this module only
//! parses TOML (syntax and type errors come with toml's line and column), builds the spec, and
//! maps the field named by a library error to its key's line and column in the text.

use camkin::cam::Mechanism;
use camkin::dynamics::FollowerDynamics;
use camkin::spec::{BuildOptions, Built, Field, Key, MechanismSpec, SpecError, SpecWarning};
use std::ops::Range;
use std::path::Path;

/// Largest mechanism file read, bytes.
pub const MAX_FILE_BYTES: u64 = 8 << 20;
/// Most nodal points of a spline profile (inline or from a points file).
pub const MAX_POINTS: usize = camkin::curve::MAX_POINTS;

/// Bad input, with where it is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InputError {
    /// the message, starting with `file:line:column:` when the place is known
    pub message: String,
    /// the place in the text, 1-based `(line, column)` (column in characters), when known
    pub at: Option<(usize, usize)>,
}

impl InputError {
    fn new(message: String) -> Self {
        Self { message, at: None }
    }
}

/// A warning about a valid mechanism (uneven nodes, say), placed in the text where it can be.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Warning {
    /// `file:line:column: message`
    pub message: String,
    /// 1-based `(line, column)`, when known
    pub at: Option<(usize, usize)>,
}

/// A mechanism built from a file's text, with its spec and placed warnings.
#[derive(Debug, Clone)]
pub struct FromText {
    /// the spec as read
    pub spec: MechanismSpec,
    /// what it builds
    pub built: Built,
    /// warnings, placed
    pub warnings: Vec<Warning>,
}

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for InputError {}

/// Reads a mechanism file's text (at most [`MAX_FILE_BYTES`], a byte-order mark dropped):
/// `(name for messages, text)`.
pub fn read_text(path: &Path) -> Result<(String, String), InputError> {
    let name = path.display().to_string();
    let cannot =
        |e: std::io::Error| InputError::new(format!("cannot read mechanism file {name}: {e}"));
    // counted while reading: a device or a pipe has no length in its metadata
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| {
            use std::io::Read;
            f.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes)
        })
        .map_err(cannot)?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(InputError::new(format!(
            "{name}: more than {MAX_FILE_BYTES} bytes ({} MiB), the most a mechanism file may have",
            MAX_FILE_BYTES >> 20
        )));
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        InputError::new(format!(
            "{name}: not UTF-8 text (invalid byte at offset {})",
            e.utf8_error().valid_up_to()
        ))
    })?;
    let text = text
        .strip_prefix('\u{feff}')
        .map(str::to_string)
        .unwrap_or(text);
    Ok((name, text))
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
    let (name, text) = read_text(path)?;
    let b = build(&text, &name, path.parent().unwrap_or(Path::new(".")), true)?;
    let unit = b.length_unit;
    Ok((b.mechanism, b.dynamics.ok_or_else(|| InputError::new(format!("{name}: this command needs a [dynamics] section (mass or inertia, spring_stiffness, spring_preload; damping, restitution, gravity optional)")))?, unit))
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
    Ok((b.mechanism, b.dynamics.ok_or_else(|| InputError::new(format!("{name}: a simulation needs a [dynamics] section (mass or inertia, spring_stiffness, spring_preload; damping, restitution, gravity optional)")))?))
}

/// The spec in a mechanism file's text.
pub fn parse_spec(text: &str, name: &str) -> Result<MechanismSpec, InputError> {
    // the path of the value that failed (`follower.direction`), which the TOML error's own
    // message does not name for a value of the wrong shape
    serde_path_to_error::deserialize(toml::Deserializer::new(text)).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        InputError {
            message: if path.is_empty() || path == "." {
                format!("{name}: {inner}")
            } else {
                format!("{name}: {path}: {inner}")
            },
            at: inner.span().map(|s| line_column(text, s.start)),
        }
    })
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
    };
    let (built, warnings) = build_placed(spec, text, name, &options)?;
    for w in warnings {
        eprintln!("camkin: warning: {}", w.message);
    }
    Ok(built)
}

/// Builds a spec parsed from `text` with `options` (a server's confined folder, SI units),
/// placing errors and warnings in the text (nothing is printed).
pub fn build_placed(
    spec: &MechanismSpec,
    text: &str,
    name: &str,
    options: &BuildOptions,
) -> Result<(Built, Vec<Warning>), InputError> {
    let built = spec.build(options).map_err(|e| place(text, name, &e))?;
    let warnings = built
        .warnings
        .iter()
        .map(|w| {
            let field = match w {
                SpecWarning::UnevenNodes { field, .. } => Some(*field),
                _ => None,
            };
            let (prefix, at) = located(text, name, field);
            Warning {
                message: format!("{prefix}: {w}"),
                at,
            }
        })
        .collect();
    Ok((built, warnings))
}

/// 1-based `(line, column)` of byte offset `at` in `text` (column in characters).
pub fn line_column(text: &str, at: usize) -> (usize, usize) {
    let mut at = at.min(text.len());
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    let before = &text[..at];
    let line = before.matches('\n').count() + 1;
    let col = before[before.rfind('\n').map_or(0, |i| i + 1)..]
        .chars()
        .count()
        + 1;
    (line, col)
}

/// `file:line:column` of `field`'s key (or `file` alone), and the line and column.
fn located(text: &str, name: &str, field: Option<Field>) -> (String, Option<(usize, usize)>) {
    match field.and_then(|f| span_of(text, f)) {
        Some(span) => {
            let (line, col) = line_column(text, span.start);
            (format!("{name}:{line}:{col}"), Some((line, col)))
        }
        None => (name.to_string(), None),
    }
}

/// The error as `file:line:column: message`, at the key of the field it names (the nearest
/// enclosing key when that one is absent: the kind's, for a field the kind needs).
fn place(text: &str, name: &str, e: &SpecError) -> InputError {
    if let SpecError::PointsFile { .. } = e {
        return InputError::new(e.to_string());
    }
    let (prefix, at) = located(text, name, Some(e.field()));
    InputError {
        message: format!("{prefix}: {e}"),
        at,
    }
}

/// The span of the value at `field`'s key path, or of the deepest part of the path present.
fn span_of(text: &str, field: Field) -> Option<Range<usize>> {
    let doc = toml_edit::ImDocument::parse(text).ok()?;
    let mut item = doc.as_item();
    let mut span = None;
    for key in field.path() {
        let next = match key {
            Key::Name(n) => item.get(n),
            Key::Index(i) => item.get(i),
        };
        match next {
            Some(it) => {
                item = it;
                span = it.span().or(span);
            }
            None => break,
        }
    }
    span
}

/// The paper's mechanism (section 3), the file `examples/paper.toml`.
pub const PAPER_TOML: &str = include_str!("../../../examples/paper.toml");

/// The built-in paper mechanism.
pub fn paper() -> Mechanism {
    camkin::reference::paper_mechanism(false)
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
