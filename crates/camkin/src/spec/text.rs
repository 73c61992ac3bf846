//! The one reader of mechanism text (feature `text`): a file read with a bound on the bytes
//! actually read, TOML or JSON parsed into a [`MechanismSpec`], and every error and warning
//! placed at its key's line and column. The command, the studio's server and the Python package
//! all read mechanisms through here; each maps [`TextError`] to its own form (a message on
//! stderr, a JSON answer, a Python exception with `.line` and `.column`).

use super::{BuildOptions, Built, Field, Key, MechanismSpec, SpecError, SpecWarning};
use std::ops::Range;
use std::path::Path;

/// The largest mechanism text read, bytes (8 MiB).
pub const MAX_TEXT_BYTES: u64 = 8 << 20;

/// What went wrong reading mechanism text.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum TextProblem {
    /// the file could not be read, is too large or is not UTF-8 text
    Read,
    /// the text is not TOML (JSON), or a value has the wrong type: `value` is that value as the
    /// user wrote it (`fast` where a number belongs), when known
    Syntax {
        /// the value at fault, a string without its quotes
        value: Option<String>,
    },
    /// the spec is not valid ([`SpecError`])
    Spec(Box<SpecError>),
}

/// Bad mechanism text, with where it is.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct TextError {
    /// the message, starting with `name:line:column:` when the place is known
    pub message: String,
    /// 1-based `(line, column)` of the place in the text (column in characters), when known
    pub at: Option<(usize, usize)>,
    /// the key path of the value at fault (`follower.direction`), when known
    pub path: Option<String>,
    /// what kind of problem
    pub problem: TextProblem,
    /// the name of the text: the file's path as given, or the caller's name for it
    pub name: String,
}

impl TextError {
    fn read(source: &str, message: String) -> Self {
        Self {
            message,
            at: None,
            path: None,
            problem: TextProblem::Read,
            name: source.to_string(),
        }
    }
}

/// A warning about a valid mechanism (uneven nodes, say), placed in the text where it can be.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedWarning {
    /// `name:line:column: message` (or `name: message`)
    pub message: String,
    /// 1-based `(line, column)`, when known
    pub at: Option<(usize, usize)>,
    /// the warning itself
    pub warning: SpecWarning,
}

/// Reads a mechanism file's text: at most [`MAX_TEXT_BYTES`] counted while reading (a device or
/// a pipe reports no length, a growing file a wrong one), UTF-8, a byte-order mark dropped.
/// Returns `(name for messages, text)`.
pub fn read_file(path: &Path) -> Result<(String, String), TextError> {
    use std::io::Read;
    let name = path.display().to_string();
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_TEXT_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| TextError::read(&name, format!("cannot read mechanism file {name}: {e}")))?;
    if bytes.len() as u64 > MAX_TEXT_BYTES {
        return Err(TextError::read(
            &name,
            format!(
            "{name}: more than {MAX_TEXT_BYTES} bytes ({} MiB), the most a mechanism file may have",
            MAX_TEXT_BYTES >> 20
        ),
        ));
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        TextError::read(
            &name,
            format!(
                "{name}: not UTF-8 text (invalid byte at offset {})",
                e.utf8_error().valid_up_to()
            ),
        )
    })?;
    let text = match text.strip_prefix('\u{feff}') {
        Some(t) => t.to_string(),
        None => text,
    };
    Ok((name, text))
}

/// Refuses text over [`MAX_TEXT_BYTES`] given directly (not read from a file).
fn bounded<'t>(text: &'t str, name: &str) -> Result<&'t str, TextError> {
    if text.len() as u64 > MAX_TEXT_BYTES {
        return Err(TextError::read(
            name,
            format!(
                "{name}: more than {MAX_TEXT_BYTES} bytes ({} MiB), the most a mechanism may have",
                MAX_TEXT_BYTES >> 20
            ),
        ));
    }
    Ok(text.strip_prefix('\u{feff}').unwrap_or(text))
}

/// The spec in a mechanism file's TOML `text` (`name` for messages): a syntax or type error is
/// placed at toml's line and column, with the key path of the value that failed.
pub fn parse_toml(text: &str, name: &str) -> Result<MechanismSpec, TextError> {
    parse_toml_of(text, name, FileKind::of(text))
}

/// [`parse_toml`] of text whose kind is known.
pub(crate) fn parse_toml_of(
    text: &str,
    name: &str,
    kind: FileKind,
) -> Result<MechanismSpec, TextError> {
    match kind {
        FileKind::System => Err(TextError {
            message: format!(
                "{name}: a system file ([[body]], [[joint]], [[driver]], [[contact]]), not a mechanism file ([cam], [follower]): `camkin analyze`, `contacts`, `plot`, `serve`, `simulate` and `forces` (with [dynamics]) and Python's camkin.System read systems"
            ),
            at: None,
            path: None,
            problem: TextProblem::Syntax { value: None },
            name: name.to_string(),
        }),
        FileKind::GearPair => {
            let file: super::GearPairFile = parse_toml_as(text, name)?;
            file.to_mechanism().map_err(|e| place(text, name, e))
        }
        FileKind::Mechanism => parse_toml_as(text, name),
    }
}

/// What a TOML file describes, by its top-level tables in one parse: `[[body]]`, `[[joint]]`,
/// `[[driver]]` or `[[contact]]` without `[cam]`; `[gear_pair]`; or else (text that is not TOML
/// too, whose parse says where it fails) `[cam]` and `[follower]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum FileKind {
    System,
    GearPair,
    Mechanism,
}

impl FileKind {
    pub(crate) fn of(text: &str) -> Self {
        let Ok(doc) = toml_edit::ImDocument::parse(text) else {
            return FileKind::Mechanism;
        };
        let t = doc.as_table();
        if ["body", "joint", "driver", "contact"]
            .iter()
            .any(|k| t.contains_key(k))
            && !t.contains_key("cam")
        {
            FileKind::System
        } else if t.contains_key("gear_pair") {
            FileKind::GearPair
        } else {
            FileKind::Mechanism
        }
    }
}

/// Whether TOML `text` is a system file (`[[body]]`, …), not a mechanism file (`[cam]`, …).
pub fn is_system(text: &str) -> bool {
    FileKind::of(text) == FileKind::System
}

pub(crate) fn parse_toml_as<T: serde::de::DeserializeOwned>(
    text: &str,
    name: &str,
) -> Result<T, TextError> {
    let text = bounded(text, name)?;
    // the path of the value that failed (`follower.direction`), which the TOML error's own
    // message does not name for a value of the wrong shape
    serde_path_to_error::deserialize(toml::Deserializer::new(text)).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        let path = (!path.is_empty() && path != ".").then_some(path);
        let at = inner.span().map(|s| line_column(text, s.start));
        // the value's own text, for a value of the wrong type (not a whole table)
        let value = inner
            .span()
            .and_then(|s| text.get(s))
            .filter(|v| !v.contains('\n') && path.is_some())
            .map(|v| v.trim().trim_matches('"').to_string());
        TextError {
            message: match &path {
                Some(p) => format!("{name}: {p}: {inner}"),
                None => format!("{name}: {inner}"),
            },
            at,
            path,
            problem: TextProblem::Syntax { value },
            name: name.to_string(),
        }
    })
}

/// The spec in JSON `text` (a dict written by Python's `json`, a studio request): a type error
/// names the key path and JSON's line and column.
pub fn parse_json(text: &str, name: &str) -> Result<MechanismSpec, TextError> {
    let text = bounded(text, name)?;
    let mut de = serde_json::Deserializer::from_str(text);
    serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        let at = (inner.line() > 0).then(|| (inner.line(), inner.column()));
        syntax(name, path, &inner, at, |_| None)
    })
}

/// A value of the wrong type or shape at key path `path` (`.` or empty: the whole text), with
/// where it is and, when `value` finds it, the value as written.
fn syntax(
    name: &str,
    path: String,
    inner: &dyn std::fmt::Display,
    at: Option<(usize, usize)>,
    value: impl FnOnce(&str) -> Option<String>,
) -> TextError {
    let path = (!path.is_empty() && path != ".").then_some(path);
    TextError {
        message: match &path {
            Some(p) => format!("{name}: {p}: {inner}"),
            None => format!("{name}: {inner}"),
        },
        at,
        problem: TextProblem::Syntax {
            value: path.as_deref().and_then(value),
        },
        path,
        name: name.to_string(),
    }
}

/// The spec in a TOML value tree (`name` for messages): what a Python dict becomes, its floats
/// kept as they are (a NaN reaches the spec's validation, which names its field, instead of
/// failing JSON's syntax); a type error names the key path.
pub fn from_value(value: toml::Value, name: &str) -> Result<MechanismSpec, TextError> {
    serde_path_to_error::deserialize(value.clone()).map_err(|e| {
        let path = e.path().to_string();
        syntax(name, path, &e.into_inner(), None, |p| value_at(&value, p))
    })
}

/// The value at `path` (`cam.profile.points[1]`) in `v`, written as in a file (a string
/// without its quotes).
fn value_at(v: &toml::Value, path: &str) -> Option<String> {
    let mut cur = v;
    for part in path.split('.') {
        let (name, rest) = part.split_once('[').unwrap_or((part, ""));
        if !name.is_empty() {
            cur = cur.get(name)?;
        }
        for idx in rest.split('[').filter(|s| !s.is_empty()) {
            cur = cur.get(idx.trim_end_matches(']').parse::<usize>().ok()?)?;
        }
    }
    Some(match cur {
        toml::Value::String(s) => s.clone(),
        other => other.to_string(),
    })
}

/// Builds a spec parsed from `text` (`name` for messages) with `options`, placing the error, or
/// each warning, at the key of the field it names in the text.
pub fn build_placed(
    spec: &MechanismSpec,
    text: &str,
    name: &str,
    options: &BuildOptions,
) -> Result<(Built, Vec<PlacedWarning>), TextError> {
    let built = spec.build(options).map_err(|e| place(text, name, e))?;
    let warnings = built
        .warnings
        .iter()
        .map(|w| {
            #[allow(unreachable_patterns)] // SpecWarning is non_exhaustive: more may come
            let field = match w {
                SpecWarning::UnevenNodes { field, .. } => Some(*field),
                SpecWarning::NoisyTable { field, .. } => Some(*field),
                _ => None,
            };
            let (prefix, at) = located(text, name, field);
            PlacedWarning {
                message: format!("{prefix}: {w}"),
                at,
                warning: w.clone(),
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

/// `name:line:column` of `field`'s key (or `name` alone), and the line and column.
fn located(text: &str, name: &str, field: Option<Field>) -> (String, Option<(usize, usize)>) {
    match field.and_then(|f| span_of(text, f)) {
        Some(span) => {
            let (line, col) = line_column(text, span.start);
            (format!("{name}:{line}:{col}"), Some((line, col)))
        }
        None => (name.to_string(), None),
    }
}

/// The error as `name:line:column: message`, at the key of the field it names (the nearest
/// enclosing key when that one is absent: the kind's, for a field the kind needs).
pub(crate) fn place(text: &str, name: &str, e: SpecError) -> TextError {
    let path = Some(e.field().to_string());
    if let SpecError::PointsFile { .. } = e {
        return TextError {
            message: e.to_string(),
            at: None,
            path,
            problem: TextProblem::Spec(Box::new(e)),
            name: name.to_string(),
        };
    }
    let (prefix, at) = located(text, name, Some(e.field()));
    TextError {
        message: format!("{prefix}: {e}"),
        at,
        path,
        problem: TextProblem::Spec(Box::new(e)),
        name: name.to_string(),
    }
}

/// The span of the value at `field`'s key path in TOML `text`, or of the deepest part of the
/// path present; `None` for text that is not TOML (JSON places its own errors).
pub fn span_of(text: &str, field: Field) -> Option<Range<usize>> {
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

#[cfg(test)]
mod tests {
    use super::*;

    const PAPER: &str = include_str!("../../../../examples/paper.toml");

    fn err(text: &str) -> TextError {
        let spec = match parse_toml(text, "m.toml") {
            Ok(s) => s,
            Err(e) => return e,
        };
        build_placed(&spec, text, "m.toml", &BuildOptions::default()).unwrap_err()
    }

    #[test]
    fn errors_name_line_column_field_and_value() {
        let e = err(&PAPER.replace("kind = \"spline\"", "kind = \"blob\""));
        assert!(
            e.message.contains("\"blob\"") && e.message.starts_with("m.toml:11:8:"),
            "{e}"
        );
        assert_eq!(e.at, Some((11, 8)));
        let e = err(&PAPER.replace("speed_rpm = 1000.0", "speed_rpm = -5.0"));
        assert!(e.message.contains("cam.speed_rpm = -5"), "{e}");
        assert_eq!(e.at.map(|a| a.0), Some(6));
        assert!(matches!(e.problem, TextProblem::Spec(_)));
        let e = err(&PAPER.replace("speed_rpm = 1000.0", "speed_rpm = \"fast\""));
        assert_eq!(e.path.as_deref(), Some("cam.speed_rpm"), "{e}");
        assert_eq!(e.at.map(|a| a.0), Some(6), "{e}");
        // the value as written, for a value of the wrong type
        assert_eq!(
            e.problem,
            TextProblem::Syntax {
                value: Some("fast".into())
            }
        );
        let e = err(&PAPER.replace("speed_rpm = 1000.0", "speed_rpm = [1, 2]"));
        assert_eq!(
            e.problem,
            TextProblem::Syntax {
                value: Some("[1, 2]".into())
            },
            "{e}"
        );
    }

    #[test]
    fn json_errors_name_the_key_path() {
        let e = parse_json(
            "{\"length_unit\": \"mm\", \"cam\": {\"speed_rpm\": \"x\"}}",
            "dict",
        )
        .unwrap_err();
        assert_eq!(e.path.as_deref(), Some("cam.speed_rpm"), "{e}");
        assert!(e.at.is_some());
    }

    #[test]
    fn files_are_read_with_a_bound_on_the_bytes_read() {
        let dir = std::env::temp_dir().join(format!("camkin-text-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let big = dir.join("big.toml");
        std::fs::write(&big, vec![b'#'; MAX_TEXT_BYTES as usize + 1]).unwrap();
        let e = read_file(&big).unwrap_err();
        assert!(e.message.contains("more than"), "{e}");
        let bom = dir.join("bom.toml");
        std::fs::write(&bom, format!("\u{feff}{PAPER}")).unwrap();
        assert_eq!(read_file(&bom).unwrap().1, PAPER);
        std::fs::write(&bom, [0xff, 0xfe, 0x00]).unwrap();
        assert!(read_file(&bom).unwrap_err().message.contains("not UTF-8"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
