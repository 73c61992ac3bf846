//! A mechanism's text read by the library's one reader ([`camkin::spec::text`]: TOML to spec,
//! errors and warnings placed at their keys' lines and columns), nothing printed: what the studio
//! and the command share. The command's file reading is its own (`camkin_cli::mechfile`).

use camkin::cam::Mechanism;
use camkin::spec::text::{self, PlacedWarning, TextError};
use camkin::spec::{BuildOptions, Built, MechanismSpec};

/// Largest mechanism file read, bytes (the library's bound).
pub const MAX_FILE_BYTES: u64 = text::MAX_TEXT_BYTES;
/// Most nodal points of a spline profile (inline or from a points file).
pub const MAX_POINTS: usize = camkin::curve::MAX_POINTS;

/// Bad input, with where it is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InputError {
    /// the message, starting with `file:line:column:` when the place is known
    pub message: String,
    /// the place in the text, 1-based `(line, column)` (column in characters), when known
    pub at: Option<(usize, usize)>,
    /// the mechanism is valid but building it would take over the work limits (each front end
    /// says how to run it anyway)
    pub too_much: bool,
}

impl InputError {
    /// Bad input saying `message`, placed nowhere.
    pub fn new(message: String) -> Self {
        Self {
            message,
            at: None,
            too_much: false,
        }
    }
}

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for InputError {}

impl From<TextError> for InputError {
    fn from(e: TextError) -> Self {
        let too_much = matches!(
            &e.problem,
            text::TextProblem::Spec(s) if matches!(**s, camkin::spec::SpecError::TooMuch { .. })
        );
        Self {
            message: e.message,
            at: e.at,
            too_much,
        }
    }
}

/// The spec in a mechanism file's text.
pub fn parse_spec(text: &str, name: &str) -> Result<MechanismSpec, InputError> {
    Ok(text::parse_toml(text, name)?)
}

/// Builds a spec parsed from `text` with `options` (a server's confined folder, SI units),
/// placing errors and warnings in the text (nothing is printed).
pub fn build_placed(
    spec: &MechanismSpec,
    text: &str,
    name: &str,
    options: &BuildOptions,
) -> Result<(Built, Vec<PlacedWarning>), InputError> {
    Ok(text::build_placed(spec, text, name, options)?)
}

/// 1-based `(line, column)` of byte offset `at` in `text` (column in characters).
pub fn line_column(text: &str, at: usize) -> (usize, usize) {
    text::line_column(text, at)
}

/// The paper's mechanism (section 3), the file `examples/paper.toml`.
pub const PAPER_TOML: &str = include_str!("../../../examples/paper.toml");

/// The built-in paper mechanism.
pub fn paper() -> Mechanism {
    camkin::reference::paper_mechanism(false)
}
