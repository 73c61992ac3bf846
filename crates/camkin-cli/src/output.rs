//! Output that is written atomically: to a temporary file beside the target, then renamed, so an
//! interrupted or failed run leaves no partial file and never replaces a good one.

use anyhow::{Context, Result};
use std::io::Write;
use std::path::Path;

/// The temporary files being written now: removed by [`remove_temporaries`] when the process is
/// interrupted (Ctrl-C, SIGTERM), which would otherwise leave them behind.
static TEMPORARIES: std::sync::Mutex<Vec<std::path::PathBuf>> = std::sync::Mutex::new(Vec::new());

/// Removes the temporary files and folders of writes in progress (called from the interrupt
/// handler, while the run goes on writing).
pub fn remove_temporaries() {
    if let Ok(list) = TEMPORARIES.lock() {
        remove_all(&list);
    }
}

/// Removes each file or folder of `list`. A folder is first renamed aside, so that the run, which
/// writes into it by its path, can no longer add to it while it is emptied.
fn remove_all(list: &[std::path::PathBuf]) {
    for p in list {
        match std::fs::symlink_metadata(p) {
            Ok(m) if m.is_dir() => {
                let mut aside = p.clone().into_os_string();
                aside.push(".removing");
                let aside = std::path::PathBuf::from(aside);
                let gone = if std::fs::rename(p, &aside).is_ok() {
                    &aside
                } else {
                    p
                };
                for _ in 0..100 {
                    if std::fs::remove_dir_all(gone).is_ok() || !gone.exists() {
                        break;
                    }
                }
            }
            Ok(_) => {
                let _ = std::fs::remove_file(p);
            }
            Err(_) => {}
        }
    }
}

/// The files this run reads (canonical paths): the mechanism file, its points files, a measured
/// profile. No output may be written over one of them.
static INPUTS: std::sync::Mutex<Vec<std::path::PathBuf>> = std::sync::Mutex::new(Vec::new());

/// Notes `p` as an input of this run (nothing when it cannot be resolved: it was not read).
pub fn note_input(p: &Path) {
    if let (Ok(c), Ok(mut list)) = (std::fs::canonicalize(p), INPUTS.lock()) {
        if !list.contains(&c) {
            list.push(c);
        }
    }
}

/// The inputs noted so far (canonical paths).
pub fn inputs() -> Vec<std::path::PathBuf> {
    INPUTS.lock().map(|l| l.clone()).unwrap_or_default()
}

/// Where writing `p` would put bytes: `p` itself, or the file a symbolic link points to (followed
/// through every link, a dangling one included: its target is created, the link kept).
pub fn write_target(p: &Path) -> std::path::PathBuf {
    let mut cur = p.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&cur) {
            Ok(m) if m.file_type().is_symlink() => match std::fs::read_link(&cur) {
                Ok(t) => {
                    cur = match cur.parent() {
                        Some(d) if t.is_relative() => d.join(t),
                        _ => t,
                    }
                }
                Err(_) => break,
            },
            _ => break,
        }
    }
    cur
}

/// The input of this run that writing `p` would overwrite, if any.
pub fn input_at(p: &Path) -> Option<std::path::PathBuf> {
    let target = write_target(p);
    // an absent file is no input; a present one is compared by its canonical path
    let canon = std::fs::canonicalize(&target).ok()?;
    INPUTS.lock().ok()?.iter().find(|i| **i == canon).cloned()
}

/// Refuses an output path that is an input of this run (checked before the work starts, and
/// again by every write).
pub fn refuse_input(p: &Path, flag: &str) -> Result<()> {
    match input_at(p) {
        Some(i) => Err(anyhow::anyhow!(
            "{flag} {}: that is an input of this run ({}); camkin never writes over its inputs: choose another path",
            p.display(),
            i.display()
        )),
        None => Ok(()),
    }
}

/// Registers a temporary file or folder for the interrupt handler while it exists.
#[derive(Debug)]
pub(crate) struct Registered(std::path::PathBuf);

impl Registered {
    /// Makes a temporary file or folder with `make` and registers it (its path by `path`) while
    /// holding the list, so an interrupt between making and registering cannot leave it behind:
    /// the interrupt handler waits for the list and then sees it.
    pub(crate) fn make<T, E>(
        make: impl FnOnce() -> Result<T, E>,
        path: impl Fn(&T) -> &Path,
    ) -> Result<(T, Self), E> {
        let mut list = TEMPORARIES.lock().unwrap_or_else(|e| e.into_inner());
        let made = make()?;
        let p = path(&made).to_path_buf();
        list.push(p.clone());
        Ok((made, Self(p)))
    }
}

/// Runs `f` (renames that put results in place) with the interrupt handler held off: an interrupt
/// while an old folder is moved aside and the new one moved in waits until both are done, so it
/// never finds the target missing. `f` must not make or drop a [`Registered`].
pub(crate) fn uninterrupted<R>(f: impl FnOnce() -> R) -> R {
    let _list = TEMPORARIES.lock().unwrap_or_else(|e| e.into_inner());
    f()
}

impl Drop for Registered {
    fn drop(&mut self) {
        if let Ok(mut list) = TEMPORARIES.lock() {
            list.retain(|q| q != &self.0);
        }
    }
}

/// Writes what `fill` produces to `path` atomically, or to stdout when `path` is `None`.
///
/// A regular file (or none yet) gets a temporary file beside it, renamed over it at the end, so
/// that a failure leaves the old file intact. A path that is not a regular file (a device such
/// as `/dev/null`, a FIFO) is written through, never renamed over; a symbolic link is followed,
/// so the file it points to is replaced, not the link; a directory is refused.
pub fn write_atomic(
    path: Option<&Path>,
    fill: impl FnOnce(&mut dyn Write) -> Result<()>,
) -> Result<()> {
    let resolved;
    if let Some(p) = path {
        refuse_input(p, "output")?;
    }
    let path = match path {
        Some(p) => match std::fs::metadata(p) {
            Ok(m) if m.is_dir() => {
                return Err(std::io::Error::new(
                    std::io::ErrorKind::IsADirectory,
                    "is a directory",
                ))
                .with_context(|| format!("cannot write {}", p.display()));
            }
            Ok(m) if !m.is_file() => {
                let f = std::fs::OpenOptions::new()
                    .write(true)
                    .open(p)
                    .with_context(|| format!("cannot write {}", p.display()))?;
                let mut w = std::io::BufWriter::new(f);
                fill(&mut w)?;
                w.flush()
                    .with_context(|| format!("writing {}", p.display()))?;
                return Ok(());
            }
            Ok(_) if std::fs::symlink_metadata(p).is_ok_and(|l| l.file_type().is_symlink()) => {
                resolved = std::fs::canonicalize(p)
                    .with_context(|| format!("cannot resolve {}", p.display()))?;
                Some(resolved.as_path())
            }
            // a dangling link: its target is written (created), the link kept
            Err(_) if std::fs::symlink_metadata(p).is_ok_and(|l| l.file_type().is_symlink()) => {
                resolved = write_target(p);
                Some(resolved.as_path())
            }
            _ => Some(p),
        },
        None => None,
    };
    match path {
        None => {
            let stdout = std::io::stdout();
            let mut w = std::io::BufWriter::new(stdout.lock());
            fill(&mut w)?;
            w.flush().context("writing to stdout")?;
            Ok(())
        }
        Some(p) => {
            let dir = match p.parent() {
                Some(d) if !d.as_os_str().is_empty() => d,
                _ => Path::new("."),
            };
            let (tmp, _registered) =
                Registered::make(|| tempfile::NamedTempFile::new_in(dir), |t| t.path())
                    .with_context(|| format!("cannot create a file in {}", dir.display()))?;
            let mut w = std::io::BufWriter::new(tmp);
            fill(&mut w)?;
            let tmp = w
                .into_inner()
                .map_err(|e| e.into_error())
                .with_context(|| format!("writing {}", p.display()))?;
            tmp.as_file().sync_all().ok();
            // a temporary file is private (0600); the result is an ordinary file
            #[cfg(unix)]
            {
                use std::os::unix::fs::PermissionsExt;
                std::fs::set_permissions(tmp.path(), std::fs::Permissions::from_mode(0o644)).ok();
            }
            tmp.persist(p)
                .map_err(|e| e.error)
                .with_context(|| format!("cannot write {}", p.display()))?;
            Ok(())
        }
    }
}

/// How a table is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum TableFormat {
    /// comma-separated values with a header
    Csv,
    /// an array of objects keyed by the CSV column names
    Json,
}

/// Writes rows as CSV (header from the row type's field names; an absent value is an empty
/// cell) or as a JSON array of objects (an absent or non-finite value is `null`). Numbers keep
/// round-trip precision.
pub fn write_table<T: serde::Serialize>(
    w: &mut dyn Write,
    rows: &[T],
    format: TableFormat,
) -> Result<()> {
    match format {
        TableFormat::Csv => {
            let mut c = csv::Writer::from_writer(w);
            for r in rows {
                c.serialize(r)?;
            }
            c.flush()?;
        }
        TableFormat::Json => {
            serde_json::to_writer(&mut *w, rows)?;
            writeln!(w)?;
        }
    }
    Ok(())
}

/// Writes rows chunk by chunk as `next_chunk` produces them (until it returns `None`), in bounded
/// memory; the same bytes as [`write_table`] on all the rows at once.
pub fn write_rows<T: serde::Serialize>(
    w: &mut dyn Write,
    format: TableFormat,
    mut next_chunk: impl FnMut() -> Option<Vec<T>>,
) -> Result<()> {
    match format {
        TableFormat::Csv => {
            let mut c = csv::Writer::from_writer(w);
            while let Some(rows) = next_chunk() {
                for r in &rows {
                    c.serialize(r)?;
                }
            }
            c.flush()?;
        }
        TableFormat::Json => json_array(w, next_chunk, |w, r| serde_json::to_writer(w, r))?,
    }
    Ok(())
}

/// Writes the rows `next_chunk` yields, chunk by chunk, as one JSON array, each row by `row`.
fn json_array<T>(
    w: &mut dyn Write,
    mut next_chunk: impl FnMut() -> Option<Vec<T>>,
    row: impl Fn(&mut dyn Write, &T) -> serde_json::Result<()>,
) -> Result<()> {
    write!(w, "[")?;
    let mut first = true;
    while let Some(rows) = next_chunk() {
        for r in &rows {
            if !first {
                write!(w, ",")?;
            }
            first = false;
            row(&mut *w, r)?;
        }
    }
    writeln!(w, "]")?;
    Ok(())
}

pub use camkin::table::Cell;

/// A row as a JSON object, keys in column order.
#[derive(Debug)]
pub struct Keyed<'a>(pub &'a [String], pub &'a [Cell]);

impl serde::Serialize for Keyed<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in self.0.iter().zip(self.1) {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

/// Writes rows of cells under `columns` chunk by chunk (until `next_chunk` returns `None`): CSV
/// with the header, or a JSON array of objects keyed by the column names. Numbers keep
/// round-trip precision.
pub fn write_cells(
    w: &mut dyn Write,
    format: TableFormat,
    columns: &[String],
    next_chunk: impl FnMut() -> Option<Vec<Vec<Cell>>>,
) -> Result<()> {
    match format {
        // the csv crate's bytes, formatted in parallel pieces (`crate::csv_cells`)
        TableFormat::Csv => crate::csv_cells::write(w, columns, next_chunk)?,
        TableFormat::Json => json_array(w, next_chunk, |w, r| {
            serde_json::to_writer(w, &Keyed(columns, r))
        })?,
    }
    Ok(())
}

/// [`write_cells`] of rows of any type, each made into cells by `cells` where it is written
/// (for CSV in parallel pieces, `crate::csv_cells`): the same bytes.
pub fn write_rows_as<R: Sync>(
    w: &mut dyn Write,
    format: TableFormat,
    columns: &[String],
    next_chunk: impl FnMut() -> Option<Vec<R>>,
    cells: impl Fn(&R) -> Vec<Cell> + Sync,
) -> Result<()> {
    match format {
        TableFormat::Csv => crate::csv_cells::write_with(w, columns, next_chunk, cells)?,
        TableFormat::Json => json_array(w, next_chunk, |w, r| {
            serde_json::to_writer(w, &Keyed(columns, &cells(r)))
        })?,
    }
    Ok(())
}

/// [`write_cells`] of rows all at once.
pub fn write_cell_table(
    w: &mut dyn Write,
    format: TableFormat,
    columns: &[String],
    rows: Vec<Vec<Cell>>,
) -> Result<()> {
    let mut once = Some(rows);
    write_cells(w, format, columns, || once.take())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A folder the run is still writing into is removed all the same (the CI once found one
    /// left: a file written between emptying it and removing it kept it).
    #[test]
    fn a_folder_being_filled_is_removed() {
        for _ in 0..5 {
            let root = tempfile::tempdir().unwrap();
            let dir = root.path().join("staging");
            std::fs::create_dir(&dir).unwrap();
            let d = dir.clone();
            let writer = std::thread::spawn(move || {
                let mut i = 0u64;
                while std::fs::write(d.join(format!("f{i}")), b"frame").is_ok() {
                    i += 1;
                }
            });
            // let it write a while, then remove the folder under it
            while std::fs::read_dir(&dir).unwrap().count() < 200 {
                std::thread::yield_now();
            }
            remove_all(std::slice::from_ref(&dir));
            assert!(!dir.exists());
            writer.join().unwrap();
        }
    }
    use camkin::cam::{CamError, FollowerState};
    use camkin::table::AnalysisRow;

    fn rows() -> Vec<AnalysisRow> {
        let m = crate::mechfile::paper();
        let err: std::result::Result<FollowerState, _> = Err(CamError::OpenProfile);
        vec![
            AnalysisRow::new(0.0, &m.analyze(0.0), false),
            AnalysisRow::new(1.0, &err, false),
        ]
    }

    fn entries(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn a_fill_that_fails_midway_leaves_the_old_file_and_no_temporary_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("out.csv");
        std::fs::write(&p, "old contents\n").unwrap();
        let r = write_atomic(Some(&p), |w| {
            w.write_all(&[b'x'; 100_000])?; // more than the buffer: bytes reach the temporary file
            anyhow::bail!("failed midway")
        });
        assert!(r.is_err());
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "old contents\n");
        assert_eq!(entries(dir.path()), vec!["out.csv".to_string()]);
        // and a fill that succeeds replaces the file whole, leaving nothing else
        write_atomic(Some(&p), |w| Ok(w.write_all(b"new\n")?)).unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "new\n");
        assert_eq!(entries(dir.path()), vec!["out.csv".to_string()]);
    }

    #[test]
    fn a_new_file_that_fails_midway_is_not_created() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("new.csv");
        let r = write_atomic(Some(&p), |w| {
            w.write_all(b"partial")?;
            anyhow::bail!("failed midway")
        });
        assert!(r.is_err());
        assert!(entries(dir.path()).is_empty());
    }

    #[test]
    fn analysis_csv_header_starts_with_the_fixed_columns_and_rows_match_it() {
        let mut out = Vec::new();
        write_table(&mut out, &rows(), TableFormat::Csv).unwrap();
        let text = String::from_utf8(out).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 3);
        assert!(lines[0].starts_with("angle_deg,position,lift,velocity,acceleration,"));
        let n = lines[0].split(',').count();
        assert_eq!(n, 27);
        assert_eq!(lines[1].split(',').count(), n);
        let err: Vec<&str> = lines[2].split(',').collect();
        assert_eq!(err.len(), n);
        assert_eq!(err[0].parse::<f64>().unwrap(), 1.0);
        assert!(err[1..n - 1].iter().all(|c| c.is_empty()), "{}", lines[2]);
        assert!(err[n - 1].contains("closed"));
    }

    #[test]
    fn analysis_json_keys_are_the_csv_columns() {
        let mut out = Vec::new();
        write_table(&mut out, &rows(), TableFormat::Json).unwrap();
        let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
        let mut csv_out = Vec::new();
        write_table(&mut csv_out, &rows(), TableFormat::Csv).unwrap();
        let header = String::from_utf8(csv_out).unwrap();
        let header: Vec<&str> = header.lines().next().unwrap().split(',').collect();
        let keys: Vec<&str> = j[0]
            .as_object()
            .unwrap()
            .keys()
            .map(|k| k.as_str())
            .collect();
        let mut sorted = header.clone();
        sorted.sort_unstable();
        assert_eq!(keys, sorted); // serde_json's map is ordered by key
        assert_eq!(j[1]["angle_deg"], 1.0);
        assert!(j[1]["position"].is_null());
        assert!(j[1]["error"].as_str().unwrap().contains("closed"));
        assert_eq!(j[0]["found"], "global");
    }

    #[cfg(unix)]
    #[test]
    fn a_device_is_written_through_not_replaced() {
        use std::os::unix::fs::FileTypeExt;
        let null = Path::new("/dev/null");
        write_atomic(Some(null), |w| Ok(w.write_all(b"x")?)).unwrap();
        assert!(std::fs::metadata(null)
            .unwrap()
            .file_type()
            .is_char_device());
    }

    #[cfg(unix)]
    #[test]
    fn a_fifo_is_written_through_and_a_link_is_followed() {
        use std::os::unix::fs::FileTypeExt;
        let dir = tempfile::tempdir().unwrap();
        // a FIFO, when the system has mkfifo: read on another thread while we write
        let fifo = dir.path().join("fifo");
        if std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .is_ok_and(|s| s.success())
        {
            let f2 = fifo.clone();
            let reader = std::thread::spawn(move || std::fs::read_to_string(f2).unwrap());
            write_atomic(Some(&fifo), |w| Ok(w.write_all(b"through")?)).unwrap();
            assert_eq!(reader.join().unwrap(), "through");
            assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
        }
        // a symbolic link: the file it points to is replaced, the link stays a link
        let target = dir.path().join("target.csv");
        std::fs::write(&target, "old").unwrap();
        let link = dir.path().join("link.csv");
        std::os::unix::fs::symlink(&target, &link).unwrap();
        write_atomic(Some(&link), |w| Ok(w.write_all(b"new")?)).unwrap();
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "new");
        // a directory is refused, untouched
        let e = write_atomic(Some(dir.path()), |w| Ok(w.write_all(b"x")?)).unwrap_err();
        assert!(format!("{e:#}").contains("directory"), "{e:#}");
    }

    #[test]
    fn rows_written_in_chunks_are_the_rows_written_at_once() {
        for format in [TableFormat::Csv, TableFormat::Json] {
            let all = rows();
            let mut whole = Vec::new();
            write_table(&mut whole, &all, format).unwrap();
            let mut chunks = all.chunks(1).map(|c| c.to_vec());
            let mut streamed = Vec::new();
            write_rows(&mut streamed, format, || chunks.next()).unwrap();
            assert_eq!(
                String::from_utf8(whole).unwrap(),
                String::from_utf8(streamed).unwrap()
            );
        }
    }
}
