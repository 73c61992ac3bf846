//! Helpers shared by the scenario modules.

use assert_cmd::Command;
use std::path::PathBuf;

/// The `camkin` binary of this build.
pub fn camkin() -> Command {
    Command::cargo_bin("camkin").unwrap()
}

/// The repository's `examples/` folder.
pub fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}
