//! The command's exit codes, written once: every `--help` states them from here, and a test
//! holds the guide's sentence (docs/limits.md) to them.

/// Success (`serve`: stopped).
pub const SUCCESS: u8 = 0;
/// An internal failure (a bug, or an output that could not be written).
pub const INTERNAL: u8 = 1;
/// Bad input: a flag, a file or a value; nothing is written.
pub const INPUT: u8 = 2;
/// A design check failed; the run finished and wrote its files.
pub const CHECK: u8 = 3;
/// Interrupted (Ctrl-C, SIGTERM), as shells expect; nothing is left half-written.
pub const INTERRUPTED: u8 = 130;

/// The subcommands that exit [`CHECK`], and what failed when they do.
pub const CHECKS: [(&str, &str); 3] = [
    (
        "synth",
        "a design check failed (pressure angle, radius of curvature, undercut, the round trip)",
    ),
    ("profile", "the tool cannot cut the profile"),
    (
        "forces",
        "a check failed (contact lost below the target speed, the margin or the allowable stress)",
    ),
];

/// The sentence of `command`'s `--help` (`None`: the command as a whole).
pub fn sentence(command: Option<&str>) -> String {
    let first = if command == Some("serve") {
        "0 stopped"
    } else {
        "0 success"
    };
    let check = match command {
        None => Some(format!(
            "3 a design check failed ({})",
            CHECKS.map(|c| c.0).join(", ")
        )),
        Some(c) => CHECKS
            .iter()
            .find(|k| k.0 == c)
            .map(|k| format!("3 {}", k.1)),
    };
    let mut s = format!("Exit codes: {first}, 1 internal failure, 2 bad input");
    if let Some(c) = check {
        s += &format!(", {c}");
    }
    s + ", 130 interrupted."
}

/// `text` (a command's examples and notes) followed by its exit codes.
pub fn help(text: &str, command: &str) -> String {
    format!("{text}\n\n{}", sentence(Some(command)))
}
