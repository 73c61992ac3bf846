//! A folder of results that changes as a whole or not at all.
//!
//! A command that writes several files (`plot`, `synth`, `profile`, `simulate --out`, `forces
//! --out`, `deviation --out`, `compare --out`, `mesh --plot`) writes them into a fresh staging
//! folder beside the target, then puts it in the target's place in one rename: an interrupted or
//! failed run leaves the old folder as it was (and removes the staging folder), never a mix of
//! old and new files.
//!
//! The target is checked before any work: it must not hold an input of the run (the swap would
//! remove it), and an existing folder is replaced only when it is empty, or holds only the files
//! a camkin run wrote there (listed in its `.camkin-results` file), or `--force` is given;
//! otherwise the run is refused naming a file that is not camkin's.

use crate::output::Registered;
use anyhow::{anyhow, Context, Result};
use std::path::{Path, PathBuf};

/// The list of the files a camkin run wrote, kept in the folder it wrote.
pub const MANIFEST: &str = ".camkin-results";

/// `--force`: replace a results folder that holds files camkin did not write.
#[derive(Debug, Clone, Copy, Default, clap::Args)]
pub struct ForceArg {
    /// Replace the output folder even when it holds files camkin did not write (they are lost).
    #[arg(long)]
    pub force: bool,
}

/// A results folder being written: see the [module docs](self).
#[derive(Debug)]
pub struct OutDir {
    target: PathBuf,
    staging: Option<tempfile::TempDir>,
    _registered: Registered,
}

impl OutDir {
    /// Checks `target` (refusing it as bad input, before any work) and makes the staging folder
    /// beside it.
    pub fn begin(target: &Path, force: bool) -> Result<Self, crate::Failure> {
        Self::check(target, force).map_err(crate::Failure::Input)?;
        let name = target
            .file_name()
            .map_or_else(|| "results".into(), |n| n.to_string_lossy().into_owned());
        let parent = parent_of(target);
        std::fs::create_dir_all(&parent)
            .with_context(|| format!("cannot create {}", parent.display()))
            .map_err(crate::Failure::Input)?;
        let (staging, registered) = Registered::make(
            || {
                tempfile::Builder::new()
                    .prefix(&format!(".{name}.camkin-"))
                    .tempdir_in(&parent)
            },
            |t| t.path(),
        )
        .with_context(|| format!("cannot create a folder in {}", parent.display()))
        .map_err(crate::Failure::Input)?;
        Ok(Self {
            target: target.to_path_buf(),
            staging: Some(staging),
            _registered: registered,
        })
    }

    /// [`OutDir::begin`] when an optional `--out` (or `--plot`) folder is given.
    pub fn begin_if(target: Option<&Path>, force: bool) -> Result<Option<Self>, crate::Failure> {
        target.map(|t| Self::begin(t, force)).transpose()
    }

    fn check(target: &Path, force: bool) -> Result<()> {
        let meta = std::fs::symlink_metadata(target);
        if let Ok(m) = &meta {
            if m.file_type().is_symlink() {
                return Err(anyhow!(
                    "--out {}: a symbolic link; give the folder itself (the results replace the folder whole)",
                    target.display()
                ));
            }
            if !m.is_dir() {
                return Err(anyhow!("--out {}: a file, not a folder", target.display()));
            }
        }
        // an input inside the target would be replaced with it
        if let Ok(t) = std::fs::canonicalize(target) {
            if let Some(i) = crate::output::inputs()
                .into_iter()
                .find(|i| i.starts_with(&t))
            {
                return Err(anyhow!(
                    "--out {}: the folder holds an input of this run ({}), which replacing it would remove: choose another folder",
                    target.display(),
                    i.display()
                ));
            }
        }
        if meta.is_err() || force {
            return Ok(());
        }
        // no list: no file of camkin's; a list that cannot be read (a folder without read or
        // search permission, a list that is not a file) is said as it is, not taken as none
        let ours: Vec<String> = match std::fs::read_to_string(target.join(MANIFEST)) {
            Ok(t) => t.lines().map(str::to_string).collect(),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Vec::new(),
            Err(e) => {
                return Err(anyhow!(
                    "--out {}: cannot read {MANIFEST}, camkin's list of the files it wrote there ({e}); the results replace the folder whole only when camkin can tell its own files: give a folder you can read and write, or pass --force to replace it (its files are lost)",
                    target.display()
                ))
            }
        };
        let entries = std::fs::read_dir(target)
            .with_context(|| format!("--out {}: cannot read the folder", target.display()))?;
        for e in entries {
            let name = e?.file_name().to_string_lossy().into_owned();
            if name != MANIFEST && !ours.contains(&name) {
                return Err(anyhow!(
                    "--out {}: the folder holds {name}, which camkin did not write there; the results replace the folder whole: choose a new or empty folder, or pass --force to replace it (its files are lost)",
                    target.display()
                ));
            }
        }
        Ok(())
    }

    /// Where to write the results now (the staging folder).
    pub fn path(&self) -> &Path {
        self.staging.as_ref().expect("not yet committed").path()
    }

    /// `p` (a path in the staging folder) as it will be once the results are in place: for
    /// messages.
    pub fn shown(&self, p: &Path) -> PathBuf {
        match p.strip_prefix(self.path()) {
            Ok(rest) => self.target.join(rest),
            Err(_) => p.to_path_buf(),
        }
    }

    /// Puts the results in the target's place: the staging folder renamed over a new or empty
    /// target, or swapped with an old results folder, which is then removed.
    pub fn commit(mut self) -> Result<PathBuf> {
        let staging = self.staging.take().expect("committed once");
        let mut names: Vec<String> = std::fs::read_dir(staging.path())?
            .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
            .filter(|n| n != MANIFEST)
            .collect();
        names.sort();
        let mut list = names.join("\n");
        list.push('\n');
        std::fs::write(staging.path().join(MANIFEST), list)
            .with_context(|| format!("cannot write {}", staging.path().display()))?;
        // a folder made by a temporary-folder helper is private (0700): results are ordinary
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            std::fs::set_permissions(staging.path(), std::fs::Permissions::from_mode(0o755)).ok();
        }
        let t = self.target.clone();
        crate::output::uninterrupted(|| -> Result<()> {
            let staged = staging.keep();
            let t = &t;
            let empty = std::fs::read_dir(t).map(|mut d| d.next().is_none());
            match empty {
                // new, or an empty folder (renamed over)
                Err(_) | Ok(true) => std::fs::rename(&staged, t).with_context(|| {
                    let _ = std::fs::remove_dir_all(&staged);
                    format!("cannot put the results in {}", t.display())
                })?,
                Ok(false) => {
                    let old = tempfile::Builder::new()
                        .prefix(".camkin-old-")
                        .tempdir_in(parent_of(t))?
                        .keep();
                    std::fs::remove_dir(&old)?;
                    std::fs::rename(t, &old).with_context(|| {
                        let _ = std::fs::remove_dir_all(&staged);
                        format!("cannot move the old {} aside", t.display())
                    })?;
                    if let Err(e) = std::fs::rename(&staged, t) {
                        // put the old folder back: nothing changed
                        let _ = std::fs::rename(&old, t);
                        let _ = std::fs::remove_dir_all(&staged);
                        return Err(e)
                            .with_context(|| format!("cannot put the results in {}", t.display()));
                    }
                    let _ = std::fs::remove_dir_all(&old);
                }
            }
            Ok(())
        })?;
        Ok(self.target.clone())
    }
}

fn parent_of(p: &Path) -> PathBuf {
    match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(d: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn results_replace_a_folder_whole_and_a_failed_run_changes_nothing() {
        let root = tempfile::tempdir().unwrap();
        let out = root.path().join("plots");
        // a new folder
        let d = OutDir::begin(&out, false).unwrap();
        std::fs::write(d.path().join("a.csv"), "1").unwrap();
        std::fs::write(d.path().join("b.png"), "2").unwrap();
        assert!(!out.exists(), "nothing in place before the commit");
        assert_eq!(d.shown(&d.path().join("a.csv")), out.join("a.csv"));
        d.commit().unwrap();
        assert_eq!(names(&out), [MANIFEST, "a.csv", "b.png"]);
        // a second run writing fewer files replaces it whole: no stale b.png
        let d = OutDir::begin(&out, false).unwrap();
        std::fs::write(d.path().join("a.csv"), "3").unwrap();
        d.commit().unwrap();
        assert_eq!(names(&out), [MANIFEST, "a.csv"]);
        assert_eq!(std::fs::read_to_string(out.join("a.csv")).unwrap(), "3");
        // a run that fails before its commit leaves the folder as it was, and no staging folder
        {
            let d = OutDir::begin(&out, false).unwrap();
            std::fs::write(d.path().join("a.csv"), "partial").unwrap();
        }
        assert_eq!(std::fs::read_to_string(out.join("a.csv")).unwrap(), "3");
        assert_eq!(names(root.path()), ["plots"]);
    }

    #[test]
    fn a_folder_with_someone_elses_files_is_refused_unless_forced() {
        let root = tempfile::tempdir().unwrap();
        let out = root.path().join("work");
        std::fs::create_dir(&out).unwrap();
        std::fs::write(out.join("notes.txt"), "mine").unwrap();
        let e = format!("{:?}", OutDir::begin(&out, false).unwrap_err());
        assert!(e.contains("notes.txt") && e.contains("--force"), "{e}");
        assert_eq!(names(&out), ["notes.txt"]);
        let d = OutDir::begin(&out, true).unwrap();
        std::fs::write(d.path().join("a.csv"), "1").unwrap();
        d.commit().unwrap();
        assert_eq!(names(&out), [MANIFEST, "a.csv"]);
        // a file is not a folder
        let f = root.path().join("file");
        std::fs::write(&f, "x").unwrap();
        assert!(OutDir::begin(&f, true).is_err());
        // an empty folder is taken
        let empty = root.path().join("empty");
        std::fs::create_dir(&empty).unwrap();
        let d = OutDir::begin(&empty, false).unwrap();
        std::fs::write(d.path().join("x"), "1").unwrap();
        d.commit().unwrap();
        assert_eq!(names(&empty), [MANIFEST, "x"]);
    }

    /// Issue 63: a list of camkin's files that cannot be read (here a folder in its place; a
    /// folder without read permission does the same to anyone but root) is said as it is, not
    /// taken for someone else's files.
    #[test]
    fn a_list_that_cannot_be_read_is_said_as_it_is() {
        let root = tempfile::tempdir().unwrap();
        let out = root.path().join("plots");
        std::fs::create_dir_all(out.join(MANIFEST)).unwrap();
        std::fs::write(out.join("a.csv"), "1").unwrap();
        let e = OutDir::check(&out, false).unwrap_err().to_string();
        assert!(
            e.contains(&format!("cannot read {MANIFEST}")) && !e.contains("did not write"),
            "{e}"
        );
        assert_eq!(std::fs::read_to_string(out.join("a.csv")).unwrap(), "1");
    }
}
