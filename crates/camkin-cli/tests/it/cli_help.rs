//! Issue 49: the help, the exit codes and the guide (docs/limits.md) agree. Every subcommand's `--help` ends
//! with the exit codes it can return (the registry `camkin_cli::exit_codes`: 3 only for the
//! commands with design checks), the command's own `--help` names those commands, and the
//! guide's sentence (docs/limits.md) names the same ones; a command that exits 3 does so only if it is listed.

use crate::common::*;
use camkin_cli::exit_codes::{sentence, CHECKS};

fn help(args: &[&str]) -> String {
    let out = camkin().args(args).arg("--help").assert().success();
    String::from_utf8(out.get_output().stdout.clone()).unwrap()
}

/// The subcommands `camkin --help` lists.
fn subcommands() -> Vec<String> {
    let text = help(&[]);
    let list = text
        .split("Commands:")
        .nth(1)
        .and_then(|t| t.split("Options:").next())
        .unwrap();
    list.lines()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|w| *w != "help")
        .map(str::to_string)
        .collect()
}

#[test]
fn every_help_states_its_exit_codes() {
    let top = help(&[]);
    assert!(top.contains(&sentence(None)), "{top}");
    let subs = subcommands();
    assert!(subs.len() >= 14, "{subs:?}");
    for c in &subs {
        let text = help(&[c]);
        let own = sentence(Some(c));
        assert!(text.trim_end().ends_with(&own), "{c}: {text}");
        // the commands with checks, and only they, exit 3
        let checks = CHECKS.iter().any(|k| k.0 == c);
        assert_eq!(own.contains(", 3 "), checks, "{c}");
    }
    for (c, _) in CHECKS {
        assert!(subs.iter().any(|s| s == c), "{c} is not a subcommand");
    }
}

#[test]
fn the_readme_names_the_commands_that_exit_3() {
    let readme = std::fs::read_to_string(examples().join("../docs/limits.md")).unwrap();
    let at = readme
        .find("**3** a design check failed (")
        .expect("the guide's exit codes (docs/limits.md)");
    let list = readme[at..]
        .split('(')
        .nth(1)
        .and_then(|t| t.split(':').next())
        .unwrap();
    let mut named: Vec<String> = list
        .split(',')
        .map(|w| w.trim().trim_matches('`').to_string())
        .collect();
    named.sort();
    let mut want: Vec<String> = CHECKS.iter().map(|c| c.0.to_string()).collect();
    want.sort();
    assert_eq!(named, want);
    assert!(readme.contains("**130** interrupted"));
}

/// A command that exits 3 is one the registry lists: synth's design checks (a motion too fast
/// for its base circle) and profile's tool (larger than the concave radius).
#[test]
fn the_commands_that_exit_3_are_the_listed_ones() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(examples().join("motion-roller.toml"))
        .unwrap()
        .replace("base_radius = 40.0          # mm", "base_radius = 8.0");
    let file = dir.path().join("tight.toml");
    std::fs::write(&file, text).unwrap();
    let code = run!("synth", &file, "--out", dir.path().join("s"))
        .assert()
        .get_output()
        .status
        .code();
    assert_eq!(code, Some(3), "synth on a base circle too small");
    assert!(CHECKS.iter().any(|c| c.0 == "synth"));
}

/// Numeric flags take a leading minus as a sign (the option's own check then speaks), a unit
/// typed with the number is refused with a message that says so, and a flag that does not
/// apply to the mechanism is refused, not ignored.
#[test]
fn flags_say_what_is_wrong_with_them() {
    let paper = examples().join("paper-dynamics.toml");
    for (args, says) in [
        (
            vec!["forces", "--face-width", "12mm"],
            "write the number alone",
        ),
        (vec!["forces", "--target-rpm", "-10"], "--target-rpm"),
        (
            vec!["analyze", "--at", "0", "--angle-unit", "rad"],
            "the follower slides",
        ),
        (
            vec!["plot", "--at", "0", "--angle-unit", "deg"],
            "--angle-unit",
        ),
    ] {
        let out = run!(args[0], &paper).args(&args[1..]).assert().code(2);
        let err = String::from_utf8_lossy(&out.get_output().stderr).to_string();
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!err.contains("unexpected argument"), "{args:?}: {err}");
    }
    // an arm takes either unit
    run!(
        "analyze",
        examples().join("oscillating-roller.toml"),
        "--at",
        "0",
        "--angle-unit",
        "rad"
    )
    .assert()
    .success();
}
