//! Output that is written atomically: to a temporary file beside the target, then renamed, so an
//! interrupted or failed run leaves no partial file and never replaces a good one.

use anyhow::{Context, Result};
use std::io::Write;
use std::path::Path;

/// Writes what `fill` produces to `path` atomically, or to stdout when `path` is `None`.
pub fn write_atomic(
    path: Option<&Path>,
    fill: impl FnOnce(&mut dyn Write) -> Result<()>,
) -> Result<()> {
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
            let tmp = tempfile::NamedTempFile::new_in(dir)
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
