//! The `camkin` command line as a library: the mechanism-file format, the subcommands and their
//! output. `main.rs` only parses the arguments and maps failures to exit codes (0 success,
//! 1 internal failure, 2 bad input, 3 a design check failed).

/// `eprintln!` that cannot panic: a message to stderr, dropped when stderr cannot take it (a
/// closed pipe, `/dev/full`) — the run still ends with its own exit code.
#[macro_export]
macro_rules! say {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($t)*);
    }};
}

/// `print!` that cannot panic: the text to stdout, or a [`Failure::Internal`] saying why it could
/// not be written (a closed pipe ends the run quietly, see `main`).
#[macro_export]
macro_rules! out {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let mut o = std::io::stdout().lock();
        write!(o, $($t)*)
            .and_then(|_| o.flush())
            .map_err(|e| $crate::Failure::Internal(anyhow::Error::new(e).context("writing to standard output")))
    }};
}

pub mod args;
pub mod commands;
pub mod csv_cells;
pub mod draw;
pub mod exit_codes;
pub mod forces_text;
pub mod manufacture;
pub mod mechfile;
pub mod out_dir;
pub mod output;
pub mod studio;
pub mod study;
pub mod sweep;

use camkin::work::Work;

use std::path::PathBuf;

/// A failure and its exit code.
#[derive(Debug)]
pub enum Failure {
    /// bad input: exit code 2
    Input(anyhow::Error),
    /// internal failure: exit code 1
    Internal(anyhow::Error),
    /// the run finished, but a design check failed (`synth`, `forces`): exit code 3
    Check(anyhow::Error),
}

impl Failure {
    /// A failure to write output. The one rule for every command: when the system refused a write
    /// to a path the user gave (no such directory, a file in the way, no permission, disk full),
    /// exit 2 with the path and the reason; any other failure while producing output, exit 1.
    pub fn output(e: anyhow::Error) -> Self {
        if e.chain().any(|c| c.is::<std::io::Error>()) {
            Failure::Input(e)
        } else {
            Failure::Internal(e)
        }
    }
}

/// Loads the mechanism file, or the paper's built-in mechanism when none is given.
/// The one refusal rule ([`camkin::work`]): `work` over the library's limits is refused unless
/// `--large`; the sentence is the library's, `otherwise` says what else to change
/// (`", or use fewer angles"`).
pub fn refuse_large(work: &Work, large: bool, otherwise: &str) -> Result<(), Failure> {
    match work.refusal() {
        Some(r) if !large => Err(Failure::Input(anyhow::anyhow!(
            "{r}; pass --large to run it anyway{otherwise}"
        ))),
        _ => Ok(()),
    }
}

/// Refuses a sweep of `angles` cam angles (`sweeps` of them) over the library's limits (a large
/// non-convex profile searches its samples at every step), unless `--large`.
pub fn check_sweep_time(
    mech: &camkin::cam::Mechanism,
    angles: usize,
    sweeps: usize,
    large: bool,
) -> Result<(), Failure> {
    refuse_large(
        &Work::sweep(mech, angles, sweeps),
        large,
        ", or use fewer angles",
    )
}

/// A mechanism as loaded, with what its file said about it.
#[derive(Debug, Clone)]
pub struct Loaded {
    /// the mechanism, in the file's length unit
    pub mech: camkin::cam::Mechanism,
    /// the file's length unit
    pub unit: camkin::spec::LengthUnit,
    /// the file's name without its folder and extension (`paper` for the built-in cam), for
    /// titles
    pub name: String,
}

impl Loaded {
    /// A cam preset's mechanism as the cam path takes it (`stem` for titles).
    pub fn of(preset: camkin::spec::Preset, stem: String) -> Self {
        Self {
            mech: preset.built.mechanism,
            unit: preset.built.length_unit,
            name: stem,
        }
    }
}

/// Loads the mechanism file, or the paper's built-in mechanism (in cm) when none is given.
pub fn load_mechanism(path: Option<&PathBuf>) -> Result<Loaded, Failure> {
    match path {
        Some(p) => {
            let built = mechfile::load_built(p).map_err(|e| Failure::Input(anyhow::anyhow!(e)))?;
            Ok(Loaded {
                mech: built.mechanism,
                unit: built.length_unit,
                name: p
                    .file_stem()
                    .map_or_else(|| p.display().to_string(), |s| s.to_string_lossy().into()),
            })
        }
        None => {
            crate::say!(
                "camkin: no mechanism file given; using the paper's cam (examples/paper.toml, lengths in cm)"
            );
            Ok(Loaded {
                mech: mechfile::paper(),
                unit: camkin::spec::LengthUnit::Cm,
                name: "paper".into(),
            })
        }
    }
}
