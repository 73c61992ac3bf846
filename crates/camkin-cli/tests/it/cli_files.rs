//! Issue 44: no run loses a file. An output that is an input of the run (the mechanism file, a
//! points file, a measured profile, through a link or not) is refused before any work, for
//! every command that writes; a dangling link is written through, not replaced; a results
//! folder changes as a whole or not at all (someone else's files refused without `--force`,
//! an interrupted run leaves the old folder as it was and no staging folder).

use crate::common::predicate;
use crate::common::*;
use std::path::{Path, PathBuf};

/// A folder holding copies of the examples a command reads.
fn workspace() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for f in [
        "paper.toml",
        "motion-roller.toml",
        "eccentric-flat-dynamics.toml",
        "eccentric-roller.toml",
        "measured-eccentric.csv",
        "gear-pair-20-42.toml",
    ] {
        std::fs::copy(examples().join(f), dir.path().join(f)).unwrap();
    }
    // a mechanism reading a points file
    std::fs::write(
        dir.path().join("p.csv"),
        (0..24)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / 24.0;
                format!("{},{}\n", 3.0 * t.cos() + 0.5, 3.0 * t.sin())
            })
            .collect::<String>(),
    )
    .unwrap();
    std::fs::write(
        dir.path().join("points.toml"),
        "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100.0\n[cam.profile]\nkind = \"points-file\"\npath = \"p.csv\"\n[follower]\nkind = \"translating-flat\"\n",
    )
    .unwrap();
    dir
}

/// Staging folders left in `d`.
fn strays(d: &Path) -> Vec<String> {
    std::fs::read_dir(d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".camkin-"))
        .collect()
}

fn snapshot(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut v: Vec<(PathBuf, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_file())
        .map(|p| (p.clone(), std::fs::read(&p).unwrap()))
        .collect();
    v.sort();
    v
}

/// Every command writing a table or a page, `-o` onto each of its inputs (directly or through a
/// link): exit 2 before any work, every file as it was.
#[test]
fn an_output_onto_an_input_is_refused_for_every_command() {
    let ws = workspace();
    let d = ws.path();
    std::os::unix::fs::symlink(d.join("paper.toml"), d.join("link.csv")).unwrap();
    let before = snapshot(d);
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["analyze", "paper.toml", "-o", "paper.toml"],
            "paper.toml",
        ),
        (vec!["analyze", "paper.toml", "-o", "link.csv"], "link.csv"),
        (vec!["analyze", "points.toml", "-o", "p.csv"], "p.csv"),
        (
            vec!["contacts", "paper.toml", "-o", "paper.toml"],
            "paper.toml",
        ),
        (vec!["contacts", "points.toml", "-o", "./p.csv"], "p.csv"),
        (
            vec!["mesh", "gear-pair-20-42.toml", "-o", "gear-pair-20-42.toml"],
            "gear-pair",
        ),
        (
            vec!["report", "paper.toml", "-o", "paper.toml"],
            "paper.toml",
        ),
        (vec!["report", "points.toml", "-o", "p.csv"], "p.csv"),
    ];
    for (args, named) in cases {
        camkin()
            .current_dir(d)
            .args(&args)
            .refused("an input of this run")
            .stderr(predicate::str::contains(named));
        assert_eq!(snapshot(d), before, "{args:?} changed a file");
    }
}

/// Every command writing a folder, into the folder that holds its input: refused (the swap
/// would remove the input); into a folder with someone else's file: refused naming it, and with
/// `--force` replaced; twice into its own folder: the second run replaces the first whole.
#[test]
fn results_folders_change_whole_and_never_take_an_input_or_a_strangers_file() {
    let ws = workspace();
    let d = ws.path();
    let commands: Vec<Vec<&str>> = vec![
        vec![
            "plot",
            "paper.toml",
            "--step",
            "10",
            "--frames",
            "2",
            "--out",
        ],
        vec!["synth", "motion-roller.toml", "--step", "2", "--out"],
        vec!["profile", "paper.toml", "--step", "2", "--out"],
        vec![
            "simulate",
            "eccentric-flat-dynamics.toml",
            "--revolutions",
            "1",
            "--out",
        ],
        vec![
            "forces",
            "eccentric-flat-dynamics.toml",
            "--step",
            "2",
            "--out",
        ],
        vec![
            "deviation",
            "measured-eccentric.csv",
            "--against",
            "eccentric-roller.toml",
            "--out",
        ],
        vec![
            "compare",
            "paper.toml",
            "--nodes",
            "100",
            "--step",
            "2",
            "--out",
        ],
        vec![
            "mesh",
            "gear-pair-20-42.toml",
            "--angles",
            "0:18:2",
            "-o",
            "/dev/null",
            "--plot",
        ],
    ];
    let before = snapshot(d);
    for (k, c) in commands.iter().enumerate() {
        // the input's own folder
        camkin()
            .current_dir(d)
            .args(c)
            .arg(".")
            .refused("holds an input of this run");
        assert_eq!(snapshot(d), before, "{c:?}");
        // a folder with someone else's file
        let out = d.join(format!("out{k}"));
        std::fs::create_dir(&out).unwrap();
        std::fs::write(out.join("notes.txt"), "mine").unwrap();
        camkin()
            .current_dir(d)
            .args(c)
            .arg(&out)
            .refused("notes.txt")
            .stderr(predicate::str::contains("--force"));
        assert_eq!(
            std::fs::read_to_string(out.join("notes.txt")).unwrap(),
            "mine"
        );
        // --force replaces it whole; its own folder is replaced without it, stale files gone
        let ok = |extra: &[&str]| {
            let o = camkin()
                .current_dir(d)
                .args(c)
                .arg(&out)
                .args(extra)
                .output_of();
            assert!(
                matches!(o.status.code(), Some(0) | Some(3)),
                "{c:?}: {}",
                String::from_utf8_lossy(&o.stderr)
            );
        };
        ok(&["--force"]);
        assert!(!out.join("notes.txt").exists(), "{c:?}");
        assert!(out.join(".camkin-results").exists(), "{c:?}");
        std::fs::write(out.join("stale.csv"), "old").unwrap();
        let listed = std::fs::read_to_string(out.join(".camkin-results")).unwrap();
        std::fs::write(out.join(".camkin-results"), format!("{listed}stale.csv\n")).unwrap();
        ok(&[]);
        assert!(
            !out.join("stale.csv").exists(),
            "{c:?}: a stale result survived"
        );
        // no staging folder left beside it
        assert!(strays(d).is_empty(), "{c:?}: {:?}", strays(d));
    }
}

/// `-o` onto a dangling link writes the file it points to and keeps the link.
#[test]
fn a_dangling_link_is_written_through() {
    let ws = workspace();
    let d = ws.path();
    std::os::unix::fs::symlink("made.csv", d.join("link.csv")).unwrap();
    camkin()
        .current_dir(d)
        .args(["analyze", "paper.toml", "--at", "0", "-o", "link.csv"])
        .assert()
        .success();
    assert!(std::fs::symlink_metadata(d.join("link.csv"))
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(std::fs::read_to_string(d.join("made.csv"))
        .unwrap()
        .starts_with("angle_deg"));
}

/// A run interrupted while it computes (Ctrl-C) leaves its old results folder as it was and no
/// staging folder (a CI run once found one left: the interrupt emptied the folder while the run
/// wrote a frame into it, so removing it failed).
#[test]
fn an_interrupted_run_leaves_the_old_folder() {
    let ws = workspace();
    let d = ws.path();
    let out = d.join("plots");
    camkin()
        .current_dir(d)
        .args([
            "plot",
            "paper.toml",
            "--step",
            "10",
            "--frames",
            "2",
            "--out",
        ])
        .arg(&out)
        .assert()
        .success();
    let before = snapshot(&out);
    // a slow run into the same folder, interrupted while it starts, and while it writes its
    // frames into the staging folder (a folder being filled as it is removed)
    for writing in [false, true] {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_camkin"))
            .current_dir(d)
            .args([
                "plot",
                "paper.toml",
                "--step",
                "0.01",
                "--frames",
                "3600",
                "--large",
                "--out",
            ])
            .arg(&out)
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        if writing {
            // wait until the run has begun writing into its staging folder
            let filled = || {
                strays(d)
                    .iter()
                    .any(|s| std::fs::read_dir(d.join(s)).is_ok_and(|r| r.count() >= 1))
            };
            let start = std::time::Instant::now();
            while !filled() {
                assert!(child.try_wait().unwrap().is_none(), "the run ended first");
                assert!(start.elapsed().as_secs() < 120, "no frames written");
                std::thread::sleep(std::time::Duration::from_millis(2));
            }
        } else {
            std::thread::sleep(std::time::Duration::from_millis(150));
        }
        std::process::Command::new("kill")
            .args(["-INT", &child.id().to_string()])
            .status()
            .unwrap();
        let status = child.wait().unwrap();
        assert!(!status.success(), "writing: {writing}");
        assert_eq!(snapshot(&out), before, "writing: {writing}");
        assert!(strays(d).is_empty(), "writing: {writing}: {:?}", strays(d));
    }
}

/// Issue 44: a run whose stderr cannot be written (`/dev/full`, closed) never panics (exit
/// 101): it ends with the exit code it has with a working stderr; stdout that cannot be written
/// is an output failure (exit 1), a closed pipe on it a quiet end (exit 0).
#[test]
fn an_unwritable_stderr_or_stdout_never_panics() {
    let ws = workspace();
    let d = ws.path();
    let runs: Vec<Vec<&str>> = vec![
        vec!["analyze", "--at", "0"],
        vec!["analyze", "nope.toml"],
        vec!["analyze", "paper.toml", "--at", "0", "--angles", "0:1:1"],
        vec![
            "plot",
            "paper.toml",
            "--step",
            "30",
            "--frames",
            "1",
            "--out",
            "p1",
        ],
        vec!["forces", "eccentric-flat-dynamics.toml", "--step", "5"],
        vec!["mesh", "gear-pair-20-42.toml", "--angles", "0:4:1"],
        vec![
            "synth",
            "motion-roller.toml",
            "--step",
            "5",
            "--out",
            "s1",
            "--force",
        ],
    ];
    let bin = env!("CARGO_BIN_EXE_camkin");
    for r in &runs {
        let code = |redirect: &str| {
            let line = format!("'{bin}' {} {redirect}", r.join(" "));
            std::process::Command::new("sh")
                .current_dir(d)
                .args(["-c", &line])
                .output()
                .unwrap()
                .status
                .code()
        };
        let normal = code(">/dev/null 2>/dev/null");
        assert_ne!(normal, Some(101), "{r:?}");
        for redirect in [">/dev/null 2>/dev/full", ">/dev/null 2>&-"] {
            assert_eq!(code(redirect), normal, "{r:?} with {redirect}");
        }
        // stdout full: a failure to write (1) when there was output, never a panic
        let full = code(">/dev/full 2>/dev/null");
        assert_ne!(full, Some(101), "{r:?}");
        // stdout closed by its reader: a quiet end
        let piped = code("2>/dev/null | head -c 1 >/dev/null; exit ${PIPESTATUS:-0}");
        assert_ne!(piped, Some(101), "{r:?}");
    }
}

/// Issue 63: every file a system file reads is an input of the run too, as a cam file's are: a
/// contact's points file is not replaced by `-o` and its folder is not replaced by `--out`, even
/// with `--force`.
#[test]
fn a_systems_points_files_are_inputs_too() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::create_dir(d.join("pts")).unwrap();
    // the example's disc (radius 20 about (5, 0)) as 36 measured points
    let disc: String = (0..36)
        .map(|k| {
            let t = f64::from(k) * std::f64::consts::TAU / 36.0;
            format!("{},{}\n", 5.0 + 20.0 * t.cos(), 20.0 * t.sin())
        })
        .collect();
    std::fs::write(d.join("pts/disc.csv"), &disc).unwrap();
    let text = std::fs::read_to_string(examples().join("two-followers.toml"))
        .unwrap()
        .replacen(
            "curve_a = { kind = \"circle\", center = [5.0, 0.0], radius = 20.0 }",
            "curve_a = { kind = \"points-file\", path = \"pts/disc.csv\" }",
            1,
        );
    assert!(text.contains("pts/disc.csv"));
    std::fs::write(d.join("system.toml"), text).unwrap();
    // the file is good: what follows is refused for its output alone
    camkin()
        .current_dir(d)
        .args(["contacts", "system.toml", "--at", "0"])
        .stdout_ok();
    for args in [
        vec!["contacts", "system.toml", "--at", "0", "-o", "pts/disc.csv"],
        vec!["analyze", "system.toml", "--at", "0", "-o", "pts/disc.csv"],
        vec![
            "plot",
            "system.toml",
            "--frames",
            "2",
            "--out",
            "pts",
            "--force",
        ],
    ] {
        camkin()
            .current_dir(d)
            .args(&args)
            .refused("input of this run")
            .stderr(predicate::str::contains("pts"));
        let now = std::fs::read_to_string(d.join("pts/disc.csv")).unwrap();
        assert_eq!(now, disc, "{args:?} changed the points file");
    }
}

/// Issue 65: a lift table (`law = "table"`, `file = …`) is an input of the run, in a cam file
/// as in a system file: `-o` onto it and `--out` onto its folder are refused, even with
/// `--force`, and the table is unchanged.
#[test]
fn a_lift_table_is_an_input_too() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::create_dir(d.join("tables")).unwrap();
    let table = std::fs::read_to_string(examples().join("lift-table.csv")).unwrap();
    std::fs::write(d.join("tables/lift.csv"), &table).unwrap();
    let text = std::fs::read_to_string(examples().join("lift-table.toml"))
        .unwrap()
        .replace("file = \"lift-table.csv\"", "file = \"tables/lift.csv\"");
    assert!(text.contains("tables/lift.csv"));
    std::fs::write(d.join("cam.toml"), &text).unwrap();
    camkin()
        .current_dir(d)
        .args(["analyze", "cam.toml", "--at", "0"])
        .stdout_ok();
    for args in [
        vec!["analyze", "cam.toml", "--at", "0", "-o", "tables/lift.csv"],
        vec!["synth", "cam.toml", "--out", "tables", "--force"],
    ] {
        camkin()
            .current_dir(d)
            .args(&args)
            .refused("input of this run")
            .stderr(predicate::str::contains("tables"));
        let now = std::fs::read_to_string(d.join("tables/lift.csv")).unwrap();
        assert_eq!(now, table, "{args:?} changed the lift table");
    }
}
