//! Where output goes, and the one exit-code rule for output that cannot be written: a path the
//! user gave that the system refuses is exit 2 in every command (with the path and the reason);
//! standard output that cannot be written is exit 1.
#![allow(clippy::unwrap_used)]
use crate::common::predicate;
use crate::common::*;

/// A directory path under a regular file: no command can create or write it.
fn blocked(dir: &std::path::Path) -> std::path::PathBuf {
    let file = dir.join("a-file");
    std::fs::write(&file, "not a directory").unwrap();
    file.join("out")
}

#[test]
fn an_output_path_that_cannot_be_written_is_exit_2_in_every_command() {
    let dir = tempfile::tempdir().unwrap();
    let bad = blocked(dir.path());
    let ex = examples();
    // each run's arguments, split at spaces; {ex}/ is the examples' folder, {bad} the path
    let runs = [
        "analyze --at 0 -o {bad}/x.csv",
        "plot --at 0 --step 5 --frames 4 --out {bad}",
        "synth {ex}/motion-roller.toml --step 5 --out {bad}",
        "simulate {ex}/paper-dynamics.toml --step 5 --out {bad}",
        "compare {ex}/paper.toml --nodes 10 --step 5 --out {bad}",
        "paper --nodes 10 --step 5 --out {bad}",
        "mesh --at 0 -o {bad}/x.csv",
        "contacts {ex}/gear-pair-20-42.toml --at 0 -o {bad}/x.csv",
    ];
    for run in runs {
        let args: Vec<String> = run
            .split(' ')
            .map(|a| {
                a.replace("{ex}", &ex.display().to_string())
                    .replace("{bad}", &bad.display().to_string())
            })
            .collect();
        camkin()
            .args(&args)
            .refused("a-file")
            .stderr(predicate::str::contains("panicked").not());
    }
    // a directory where the file should go
    run!("analyze", "--at", "0", "-o", dir.path()).refused("cannot write");
}

#[test]
fn standard_output_that_cannot_be_written_is_exit_1() {
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full");
    let Ok(full) = full else {
        eprintln!("no /dev/full on this system: skipped");
        return;
    };
    run!("analyze", "--at", "0,1,2")
        .stdout_to(full)
        .assert()
        .code(1)
        .stderr(predicate::str::contains("internal error"));
}

/// Issue 12, class 5: a reader that goes away (`camkin analyze | head -1`) ends the command
/// quietly with exit 0: no panic, no "internal error".
#[test]
fn a_closed_pipe_ends_quietly() {
    use std::io::{BufRead, BufReader};
    use std::process::{Command, Stdio};
    for args in [
        vec!["analyze", "--angles", "0:360:0.005"],
        vec!["bench", "--repeats", "1"],
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_camkin"))
            .args(&args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut out = BufReader::new(child.stdout.take().unwrap());
        let mut first = String::new();
        out.read_line(&mut first).unwrap();
        drop(out);
        let res = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&res.stderr);
        assert_eq!(res.status.code(), Some(0), "{args:?}: {err}");
        assert!(
            !err.contains("panicked") && !err.contains("internal error"),
            "{args:?}: {err}"
        );
    }
}

/// Issue 12, class 5: a run terminated (SIGTERM, as Ctrl-C's SIGINT) while writing removes its
/// temporary file, leaves no output file and exits 130.
#[cfg(unix)]
#[test]
fn a_terminated_run_leaves_no_temporary_file() {
    use std::process::{Command, Stdio};
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.csv");
    let mut child = Command::new(env!("CARGO_BIN_EXE_camkin"))
        .args(["analyze", "--angles", "0:360:0.0002", "-o"])
        .arg(&out)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let temporary = || {
        std::fs::read_dir(dir.path())
            .unwrap()
            .any(|e| e.unwrap().file_name().to_string_lossy().starts_with(".tmp"))
    };
    // wait (at most 60 s) until the writing has begun
    let start = std::time::Instant::now();
    while !temporary() && start.elapsed().as_secs() < 60 {
        if child.try_wait().unwrap().is_some() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    if child.try_wait().unwrap().is_some() {
        return; // finished before we could interrupt it: nothing to check on this machine
    }
    assert!(temporary(), "the write never began");
    let killed = Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(130));
    assert!(!temporary(), "a temporary file was left behind");
    assert!(!out.exists(), "a partial output file was written");
}
