//! Command-line values parsed at the boundary into typed values (`FromStr`, used by clap as value
//! parsers): a bad value is refused by clap with the option's name, the value and the reason,
//! exit code 2, before any work starts.

pub mod forces;

use std::fmt;
use std::str::FromStr;

/// Largest number of angles one run analyses.
pub const MAX_ANGLES: usize = 10_000_000;

/// Why a value was refused (clap prints it after the option and the value).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BadValue(String);

impl fmt::Display for BadValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for BadValue {}

fn bad(msg: impl Into<String>) -> BadValue {
    BadValue(msg.into())
}

/// A finite number (degrees, or whatever the option says).
fn number(what: &str, s: &str) -> Result<f64, BadValue> {
    let t = s.trim();
    let v: f64 = t
        .parse()
        .map_err(|_| bad(format!("{what} {t:?} is not a number")))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(bad(format!("{what} {t:?} must be finite")))
    }
}

/// The value parser of every numeric option (`#[arg(value_parser = real)]`): a finite number,
/// a leading minus taken as a sign (the option's own check says whether a negative value is
/// allowed), a unit typed after the number refused with a message that says so (`12mm`: the
/// unit is the option's, written in its help).
pub fn real(s: &str) -> Result<f64, BadValue> {
    let t = s.trim();
    match t.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(bad(format!("{t:?} must be finite"))),
        Err(_) => {
            // a number followed by letters: a unit typed with it
            let head =
                t.trim_end_matches(|c: char| c.is_alphabetic() || c == '/' || c == '°' || c == ' ');
            if head.len() < t.len() && head.parse::<f64>().is_ok() {
                Err(bad(format!(
                    "{t:?}: write the number alone ({head}); its unit is the option's (see --help)"
                )))
            } else {
                Err(bad(format!("{t:?} is not a number")))
            }
        }
    }
}

/// The override of the work estimate, shared by every command that estimates its work.
#[derive(Debug, Clone, Copy, Default, clap::Args)]
pub struct WorkArgs {
    /// Allow a run estimated at over 30 s or 1 GB (refused otherwise, with the estimate).
    #[arg(long)]
    pub large: bool,
}

/// Where a table goes and in what format (`analyze`, `contacts`, `mesh`).
#[derive(Debug, Clone, clap::Args)]
pub struct TableArgs {
    /// Output format.
    #[arg(long, value_enum, default_value_t = crate::output::TableFormat::Csv)]
    pub format: crate::output::TableFormat,
    /// Output file (written atomically); standard output without it.
    #[arg(short = 'o', long, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
}

impl TableArgs {
    /// Writes the table (`columns`, rows from `next_chunk` a chunk at a time) to `-o FILE`
    /// (atomically) or standard output, in the chosen format. A file that cannot be written is
    /// the user's (exit 2); standard output that cannot be written is not (exit 1).
    pub fn write(
        &self,
        columns: &[String],
        mut next_chunk: impl FnMut() -> Option<Vec<Vec<camkin::table::Cell>>>,
    ) -> Result<(), crate::Failure> {
        self.failure(crate::output::write_atomic(self.output.as_deref(), |w| {
            crate::output::write_cells(w, self.format, columns, &mut next_chunk)
        }))
    }

    /// A write's error as the user's (a file of theirs, exit 2) or not (standard output).
    fn failure(&self, r: anyhow::Result<()>) -> Result<(), crate::Failure> {
        r.map_err(|e| {
            if self.output.is_some() {
                crate::Failure::output(e)
            } else {
                crate::Failure::Internal(e)
            }
        })
    }
}

impl TableArgs {
    /// [`TableArgs::write`] of rows of any type, each made into cells by `cells` where it is
    /// formatted (in parallel for CSV).
    pub fn write_rows<R: Sync>(
        &self,
        columns: &[String],
        mut next_chunk: impl FnMut() -> Option<Vec<R>>,
        cells: impl Fn(&R) -> Vec<camkin::table::Cell> + Sync,
    ) -> Result<(), crate::Failure> {
        self.failure(crate::output::write_atomic(self.output.as_deref(), |w| {
            crate::output::write_rows_as(w, self.format, columns, &mut next_chunk, &cells)
        }))
    }

    /// Refuses, before any work, an output file that is an input of this run (the mechanism
    /// file, one of its points files).
    pub fn check(&self) -> Result<(), crate::Failure> {
        match &self.output {
            Some(p) => crate::output::refuse_input(p, "-o").map_err(crate::Failure::Input),
            None => Ok(()),
        }
    }
}

/// The units of the follower's motion on a page or in a table (`analyze`, `plot`, `synth`).
#[derive(Debug, Clone, Copy, clap::Args)]
pub struct MotionUnitArgs {
    /// Derivatives of the follower's motion per second of time, or per degree of cam angle
    /// (ds/dθ, d²s/dθ², d³s/dθ³, as cam tools print them).
    #[arg(long, value_parser = crate::args::per_parser(), default_value = "s")]
    pub per: camkin::table::Per,
    /// Unit of an oscillating follower's arm angle and its derivatives [default: deg]; refused
    /// for a follower that slides (its coordinate is a length).
    #[arg(long, value_parser = crate::args::angle_unit_parser())]
    pub angle_unit: Option<camkin::table::AngleUnit>,
}

impl MotionUnitArgs {
    /// The arm angle's unit for `mech`: a unit given for a follower that slides is refused,
    /// not ignored.
    pub fn angle_unit_for(
        &self,
        mech: &camkin::cam::Mechanism,
    ) -> Result<camkin::table::AngleUnit, crate::Failure> {
        match self.angle_unit {
            Some(u) if matches!(mech.follower_joint(), camkin::cam::FollowerJoint::Translating { .. }) => {
                Err(crate::Failure::Input(anyhow::anyhow!(
                    "--angle-unit {}: the follower slides (its coordinate is a length, in the file's unit); --angle-unit is an arm's",
                    match u {
                        camkin::table::AngleUnit::Deg => "deg",
                        _ => "rad",
                    }
                )))
            }
            u => Ok(u.unwrap_or_default()),
        }
    }
}

/// The angles a command visits: a list of separate instants or a range that traces the motion
/// (`analyze`, `contacts`, `mesh`).
#[derive(Debug, Clone, clap::Args)]
pub struct AngleArgs {
    /// Angles in degrees, comma-separated (e.g. 0,45,90): the cam's, or a system's or gear
    /// pair's driver's; separate instants, in any order (no contact jump is marked between
    /// them, as it is along a range).
    #[arg(
        long,
        value_name = "A1,A2,...",
        conflicts_with = "angles",
        allow_hyphen_values = true
    )]
    pub at: Option<AngleList>,
    /// Range of angles in degrees: START:STOP:STEP, STOP excluded [default: 0:360:1; mesh: two
    /// mesh cycles, 0:720/z1, 360 steps each: a tooth pair's whole time in mesh and a handover].
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub angles: Option<AngleRange>,
}

impl AngleArgs {
    /// The angles given, or `default`'s when none are.
    pub fn or_else(&self, default: impl FnOnce() -> Vec<f64>) -> Vec<f64> {
        match (&self.at, self.angles) {
            (Some(list), _) => list.0.clone(),
            (None, Some(range)) => range.angles(),
            (None, None) => default(),
        }
    }

    /// The angles given, a revolution in 1° steps by default.
    pub fn or_revolution(&self) -> Vec<f64> {
        self.or_else(|| AngleRange::REVOLUTION.angles())
    }

    /// The angles trace the motion (a range): a contact jump between rows is marked.
    pub fn contiguous(&self) -> bool {
        self.at.is_none()
    }
}

/// Cam angles in degrees, comma-separated: `A1,A2,...`.
#[derive(Debug, Clone, PartialEq)]
pub struct AngleList(pub Vec<f64>);

impl FromStr for AngleList {
    type Err = BadValue;
    fn from_str(s: &str) -> Result<Self, BadValue> {
        let v = s
            .split(',')
            .map(|t| number("angle", t))
            .collect::<Result<Vec<_>, _>>()?;
        if v.len() > MAX_ANGLES {
            return Err(bad(format!("{} angles is more than {MAX_ANGLES}", v.len())));
        }
        Ok(Self(v))
    }
}

/// A range of cam angles in degrees: `START:STOP:STEP`, STOP excluded, at least one angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleRange {
    /// the first angle, degrees
    pub start: f64,
    /// the end, excluded, degrees
    pub stop: f64,
    /// the step, degrees (negative for a decreasing range)
    pub step: f64,
}

impl AngleRange {
    /// One revolution in 1° steps.
    pub const REVOLUTION: Self = Self {
        start: 0.0,
        stop: 360.0,
        step: 1.0,
    };

    /// The angles of the range, degrees.
    pub fn angles(&self) -> Vec<f64> {
        let count = ((self.stop - self.start) / self.step).ceil().max(0.0) as usize;
        let grid = camkin::table::AngleGrid::new(self.start, self.step);
        (0..count)
            .map(|k| grid.at(k))
            .filter(|&a| {
                if self.step > 0.0 {
                    a < self.stop
                } else {
                    a > self.stop
                }
            })
            .collect()
    }
}

impl FromStr for AngleRange {
    type Err = BadValue;
    fn from_str(s: &str) -> Result<Self, BadValue> {
        let parts: Vec<&str> = s.split(':').collect();
        if parts.len() != 3 {
            return Err(bad("not START:STOP:STEP (degrees)"));
        }
        let (start, stop, step) = (
            number("START", parts[0])?,
            number("STOP", parts[1])?,
            number("STEP", parts[2])?,
        );
        if step == 0.0 || (stop - start) * step <= 0.0 {
            return Err(bad(format!(
                "STEP {}° does not lead from START {}° to STOP {}°",
                parts[2].trim(),
                parts[0].trim(),
                parts[1].trim()
            )));
        }
        let count = ((stop - start) / step).ceil();
        if count > MAX_ANGLES as f64 {
            return Err(bad(format!("{count:.3e} angles is more than {MAX_ANGLES}")));
        }
        Ok(Self { start, stop, step })
    }
}

/// An angle step in degrees that divides the revolution: in (0°, 90°], at most 10 000 000 steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RevolutionStep(pub f64);

impl RevolutionStep {
    /// The finest step, degrees: 360° over the most angles.
    pub const MIN_DEG: f64 = 360.0 / MAX_ANGLES as f64;

    /// The step, degrees.
    pub fn deg(self) -> f64 {
        self.0
    }
}

impl FromStr for RevolutionStep {
    type Err = BadValue;
    fn from_str(s: &str) -> Result<Self, BadValue> {
        let step = number("step", s)?;
        // the value as written, not Rust's digits of it (1e300 would print 301 of them)
        let s = s.trim();
        if !(step > 0.0 && step <= 90.0) {
            return Err(bad(format!("{s}° is not in (0°, 90°]")));
        }
        let n = 360.0 / step;
        if n > MAX_ANGLES as f64 {
            return Err(bad(format!(
                "{s}° gives more than {MAX_ANGLES} angles per revolution (the finest step is {}°)",
                RevolutionStep::MIN_DEG
            )));
        }
        if (n - n.round()).abs() > 1e-9 * n {
            return Err(bad(format!("{s}° does not divide 360°")));
        }
        Ok(Self(step))
    }
}

/// Nodal point counts of the interpolation method, comma-separated, each 3 to 1 000 000.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NodeCounts(pub Vec<usize>);

impl FromStr for NodeCounts {
    type Err = BadValue;
    fn from_str(s: &str) -> Result<Self, BadValue> {
        let v = s
            .split(',')
            .map(|t| {
                let t = t.trim();
                t.parse::<usize>()
                    .map_err(|_| bad(format!("{t:?} is not a whole number")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        for &n in &v {
            if !(3..=1_000_000).contains(&n) {
                return Err(bad(format!("{n} is out of range (3 to 1000000)")));
            }
        }
        Ok(Self(v))
    }
}

/// A window of cam angles in degrees: `START:STOP` with START < STOP.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleWindow {
    /// degrees
    pub start: f64,
    /// degrees
    pub stop: f64,
}

impl FromStr for AngleWindow {
    type Err = BadValue;
    fn from_str(s: &str) -> Result<Self, BadValue> {
        let p: Vec<&str> = s.split(':').collect();
        if p.len() != 2 {
            return Err(bad("not START:STOP (degrees)"));
        }
        let (start, stop) = (number("START", p[0])?, number("STOP", p[1])?);
        if start >= stop {
            return Err(bad(format!(
                "START {}° is not below STOP {}°",
                camkin::human::human(start),
                camkin::human::human(stop)
            )));
        }
        Ok(Self { start, stop })
    }
}

/// `--per`: derivatives per second or per degree of cam angle.
pub fn per_parser() -> impl clap::builder::TypedValueParser<Value = camkin::table::Per> {
    use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
    PossibleValuesParser::new([
        PossibleValue::new("s").help("time: velocity in mm/s, acceleration in mm/s², jerk in mm/s³"),
        PossibleValue::new("deg").help("the cam angle in degrees: ds/dθ in mm/deg, d²s/dθ² in mm/deg², d³s/dθ³ in mm/deg³, as cam tools print them"),
    ])
    .try_map(|s| s.parse::<camkin::table::Per>())
}

/// `--angle-unit`: the unit of an oscillating follower's arm angle.
pub fn angle_unit_parser() -> impl clap::builder::TypedValueParser<Value = camkin::table::AngleUnit>
{
    use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
    PossibleValuesParser::new([
        PossibleValue::new("deg").help("degrees"),
        PossibleValue::new("rad").help("radians"),
    ])
    .try_map(|s| s.parse::<camkin::table::AngleUnit>())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angle_ranges_exclude_stop() {
        let r = |s: &str| s.parse::<AngleRange>().map(|r| r.angles());
        assert_eq!(r("0:3:1").unwrap(), vec![0.0, 1.0, 2.0]);
        assert_eq!(r("10:0:-5").unwrap(), vec![10.0, 5.0]);
        assert_eq!(AngleRange::REVOLUTION.angles().len(), 360);
        assert!(r("0:1:0").is_err());
        assert!(r("0:10:-1").is_err());
        assert!(r("0:0:1").is_err(), "an empty range");
        assert!(r("0:1").is_err());
        assert!(r("0:1e12:1e-6").is_err());
        assert!(r("0:inf:1").is_err());
    }

    #[test]
    fn angle_lists_are_finite_numbers() {
        assert_eq!(
            "0, 45,-10".parse::<AngleList>().unwrap().0,
            vec![0.0, 45.0, -10.0]
        );
        for bad in ["a", "1,,2", "nan", "1,inf", ""] {
            assert!(bad.parse::<AngleList>().is_err(), "{bad:?} accepted");
        }
    }

    #[test]
    fn steps_divide_the_revolution() {
        assert_eq!("0.25".parse::<RevolutionStep>().unwrap().deg(), 0.25);
        assert_eq!(real("-10"), Ok(-10.0));
        assert_eq!(real(" 2.5e3 "), Ok(2500.0));
        assert!(real("12mm")
            .unwrap_err()
            .0
            .contains("write the number alone (12)"));
        assert!(real("3000 rpm")
            .unwrap_err()
            .0
            .contains("write the number alone (3000)"));
        assert!(real("inf").unwrap_err().0.contains("finite"));
        assert!(real("mm").unwrap_err().0.contains("is not a number"));
        for bad in ["0", "-1", "7", "91", "1e-6", "nan", "x"] {
            assert!(bad.parse::<RevolutionStep>().is_err(), "{bad:?} accepted");
        }
    }

    #[test]
    fn node_counts_and_windows() {
        assert_eq!(
            "100, 1000".parse::<NodeCounts>().unwrap().0,
            vec![100, 1000]
        );
        for bad in ["2", "1e3", "-5", "10,", "2000000"] {
            assert!(bad.parse::<NodeCounts>().is_err(), "{bad:?} accepted");
        }
        let w: AngleWindow = "5:10".parse().unwrap();
        assert_eq!((w.start, w.stop), (5.0, 10.0));
        for bad in ["10:5", "5:5", "5", "a:b", "1:2:3"] {
            assert!(bad.parse::<AngleWindow>().is_err(), "{bad:?} accepted");
        }
    }
}
