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

/// The `camkin` binary with these arguments (each anything a command line takes: `&str`,
/// `String`, a path), ready to run: `run!("analyze", &file, "--at", "0").stdout_ok()`.
macro_rules! run {
    ($($a:expr),* $(,)?) => {{
        let mut c = $crate::common::camkin();
        $(c.arg($a);)*
        c
    }};
}
pub(crate) use run;

/// The repository's `examples/` folder.
pub fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// `text` written to a file `name` in a new temporary folder (removed when the folder is dropped:
/// keep it while the file is read).
pub fn written(name: &str, text: impl AsRef<[u8]>) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    (dir, path)
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
    /// Sets an environment variable of the child.
    pub fn env(&mut self, k: impl AsRef<OsStr>, v: impl AsRef<OsStr>) -> &mut Self {
        self.0.env(k, v);
        self
    }
    /// Runs the command in `dir`.
    pub fn current_dir(&mut self, dir: impl AsRef<std::path::Path>) -> &mut Self {
        self.0.current_dir(dir);
        self
    }
    /// Runs the command to its end, stdin closed, and returns its output unchecked.
    pub fn output_of(&mut self) -> Output {
        self.0
            .stdin(std::process::Stdio::null())
            .output()
            .expect("camkin runs")
    }
    /// Sends standard output to `file` instead of capturing it.
    pub fn stdout_to(&mut self, file: std::fs::File) -> &mut Self {
        self.0.stdout(file);
        self
    }
    /// Runs the command to its end, checks that it succeeded, and returns its standard output.
    pub fn stdout_ok(&mut self) -> Vec<u8> {
        self.assert().success().get_output().stdout.clone()
    }
    /// Runs the command to its end and checks that it refused its input (exit code 2) with a
    /// message holding `needle`; the run for more checks.
    pub fn refused(&mut self, needle: impl Into<String>) -> Assert {
        self.assert()
            .code(2)
            .stderr(predicate::str::contains(needle))
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

/// A polyline of an ASCII DXF: its layer, closed flag (group 70, bit 1) and vertices
/// `(x, y, bulge)` (groups 10, 20, 42).
#[derive(Debug, Clone)]
pub struct DxfPolyline {
    pub layer: String,
    pub closed: bool,
    pub vertices: Vec<(f64, f64, f64)>,
}

/// An ASCII DXF read from the format's definition (group code / value line pairs), not with the
/// writer's code: the header variables and the POLYLINE entities.
#[derive(Debug, Clone, Default)]
pub struct Dxf {
    pub header: std::collections::HashMap<String, String>,
    pub polylines: Vec<DxfPolyline>,
}

pub fn read_dxf(text: &str) -> Dxf {
    let lines: Vec<&str> = text.lines().map(str::trim).collect();
    assert!(lines.len() % 2 == 0, "DXF is pairs of lines");
    let pairs: Vec<(i32, &str)> = lines
        .chunks(2)
        .map(|p| (p[0].parse().expect("a group code"), p[1]))
        .collect();
    let mut out = Dxf::default();
    let mut k = 0;
    while k < pairs.len() {
        if pairs[k].0 == 9 {
            // a header variable: its name, then its value's group
            out.header
                .insert(pairs[k].1.to_string(), pairs[k + 1].1.to_string());
        }
        if pairs[k] == (0, "POLYLINE") {
            let mut p = DxfPolyline {
                layer: String::new(),
                closed: false,
                vertices: Vec::new(),
            };
            k += 1;
            while pairs[k].0 != 0 {
                match pairs[k].0 {
                    8 => p.layer = pairs[k].1.to_string(),
                    70 => p.closed = pairs[k].1.parse::<i32>().unwrap() & 1 == 1,
                    _ => {}
                }
                k += 1;
            }
            while pairs[k] == (0, "VERTEX") {
                let (mut x, mut y, mut b) = (None, None, 0.0);
                k += 1;
                while pairs[k].0 != 0 {
                    match pairs[k].0 {
                        10 => x = Some(pairs[k].1.parse::<f64>().unwrap()),
                        20 => y = Some(pairs[k].1.parse::<f64>().unwrap()),
                        42 => b = pairs[k].1.parse::<f64>().unwrap(),
                        _ => {}
                    }
                    k += 1;
                }
                p.vertices.push((x.expect("x"), y.expect("y"), b));
            }
            assert_eq!(pairs[k], (0, "SEQEND"), "a polyline ends with SEQEND");
            out.polylines.push(p);
        }
        k += 1;
    }
    assert_eq!(pairs.last(), Some(&(0, "EOF")));
    out
}

/// Points along a polyline's arcs: from each vertex to the next by its bulge (`tan(θ/4)`, the
/// arc's angle θ counter-clockwise positive), `n` points per arc, from the DXF definition.
pub fn polyline_points(p: &DxfPolyline, n: usize) -> Vec<(f64, f64)> {
    let m = p.vertices.len();
    let mut out = Vec::new();
    for i in 0..m {
        let (x0, y0, b) = p.vertices[i];
        let (x1, y1, _) = p.vertices[(i + 1) % m];
        let theta = 4.0 * b.atan();
        let (cx, cy) = ((x1 - x0), (y1 - y0));
        let c = cx.hypot(cy);
        for j in 0..n {
            let t = j as f64 / n as f64;
            if theta.abs() < 1e-12 {
                out.push((x0 + t * cx, y0 + t * cy));
                continue;
            }
            // the centre lies off the chord's midpoint by (c/2)/tan(θ/2), on the left for θ > 0
            let d = 0.5 * c / (0.5 * theta).tan();
            let (mx, my) = (x0 + 0.5 * cx, y0 + 0.5 * cy);
            let (ox, oy) = (mx - d * cy / c, my + d * cx / c);
            let a0 = (y0 - oy).atan2(x0 - ox);
            let r = (x0 - ox).hypot(y0 - oy);
            let a = a0 + t * theta;
            out.push((ox + r * a.cos(), oy + r * a.sin()));
        }
    }
    out
}

/// A CSV header's column indices by name.
pub fn columns(header: &[String]) -> std::collections::HashMap<&str, usize> {
    header
        .iter()
        .enumerate()
        .map(|(i, h)| (h.as_str(), i))
        .collect()
}

/// A CSV table: its header and its rows as text.
pub fn parse_csv(out: &[u8]) -> (Vec<String>, Vec<Vec<String>>) {
    let text = String::from_utf8(out.to_vec()).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (header, rows)
}
