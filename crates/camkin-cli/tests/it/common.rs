//! Helpers shared by the scenario modules: the `camkin` binary run as a child process, its output
//! checked (a small stand-in for assert_cmd and predicates, whose regex engines doubled the cold
//! build of these tests).

use std::ffi::OsStr;
use std::path::PathBuf;
use std::process::{Command, Output};

/// The `camkin` binary of this build, ready for arguments.
pub fn camkin() -> Cmd {
    Cmd(Command::new(env!("CARGO_BIN_EXE_camkin")))
}

/// The repository's `examples/` folder.
pub fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// A command to run.
#[derive(Debug)]
pub struct Cmd(Command);

impl Cmd {
    pub fn arg(&mut self, a: impl AsRef<OsStr>) -> &mut Self {
        self.0.arg(a);
        self
    }
    pub fn args<I, S>(&mut self, a: I) -> &mut Self
    where
        I: IntoIterator<Item = S>,
        S: AsRef<OsStr>,
    {
        self.0.args(a);
        self
    }
    /// Sends standard output to `file` instead of capturing it.
    pub fn stdout_to(&mut self, file: std::fs::File) -> &mut Self {
        self.0.stdout(file);
        self
    }
    /// Runs the command to its end, stdin closed.
    pub fn assert(&mut self) -> Assert {
        let out = self
            .0
            .stdin(std::process::Stdio::null())
            .output()
            .expect("camkin runs");
        Assert(out)
    }
}

/// A finished run, checked by chained assertions that print its output when they fail.
#[derive(Debug)]
pub struct Assert(Output);

impl Assert {
    fn fail(&self, what: &str) -> ! {
        panic!(
            "{what}\nexit: {:?}\n--- stdout\n{}\n--- stderr\n{}",
            self.0.status.code(),
            String::from_utf8_lossy(&self.0.stdout),
            String::from_utf8_lossy(&self.0.stderr)
        )
    }
    pub fn success(self) -> Self {
        if !self.0.status.success() {
            self.fail("expected success");
        }
        self
    }
    pub fn code(self, code: i32) -> Self {
        if self.0.status.code() != Some(code) {
            self.fail(&format!("expected exit code {code}"));
        }
        self
    }
    pub fn stdout(self, p: impl predicate::Check) -> Self {
        if !p.check(&String::from_utf8_lossy(&self.0.stdout)) {
            self.fail(&format!("stdout: expected {}", p.describe()));
        }
        self
    }
    pub fn stderr(self, p: impl predicate::Check) -> Self {
        if !p.check(&String::from_utf8_lossy(&self.0.stderr)) {
            self.fail(&format!("stderr: expected {}", p.describe()));
        }
        self
    }
    pub fn get_output(&self) -> &Output {
        &self.0
    }
}

/// Checks on a run's text output.
pub mod predicate {
    /// A check on text.
    pub trait Check {
        fn check(&self, s: &str) -> bool;
        fn describe(&self) -> String;
    }

    /// Equal to the text.
    impl Check for &str {
        fn check(&self, s: &str) -> bool {
            s == *self
        }
        fn describe(&self) -> String {
            format!("exactly {self:?}")
        }
    }

    /// Containing a text.
    #[derive(Debug)]
    pub struct Contains(String);

    impl Contains {
        /// The opposite check.
        pub fn not(self) -> Not<Self> {
            Not(self)
        }
    }

    impl Check for Contains {
        fn check(&self, s: &str) -> bool {
            s.contains(&self.0)
        }
        fn describe(&self) -> String {
            format!("to contain {:?}", self.0)
        }
    }

    /// Not passing a check.
    #[derive(Debug)]
    pub struct Not<C>(C);

    impl<C: Check> Check for Not<C> {
        fn check(&self, s: &str) -> bool {
            !self.0.check(s)
        }
        fn describe(&self) -> String {
            format!("not {}", self.0.describe())
        }
    }

    pub mod str {
        /// Containing `needle`.
        pub fn contains(needle: impl Into<String>) -> super::Contains {
            super::Contains(needle.into())
        }
    }
}
