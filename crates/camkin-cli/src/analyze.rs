//! `camkin analyze`: the one-instant analysis at a list or range of cam angles, as CSV.

use crate::output::write_atomic;
use crate::{load_mechanism, Failure};
use anyhow::{anyhow, bail, Result};
use camkin::cam::{CamError, FollowerState, Found, Mechanism};
use std::io::Write;
use std::path::PathBuf;

/// Largest number of angles one run analyses.
pub const MAX_ANGLES: usize = 10_000_000;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Mechanism file (TOML); without it, the paper's built-in cam.
    pub mechanism: Option<PathBuf>,
    /// Cam angles in degrees, comma-separated (e.g. 0,45,90).
    #[arg(
        long,
        value_name = "A1,A2,...",
        conflicts_with = "angles",
        allow_hyphen_values = true
    )]
    pub at: Option<String>,
    /// Range of cam angles in degrees: START:STOP:STEP, STOP excluded [default: 0:360:1].
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub angles: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    pub format: Format,
    /// Output file (written atomically); standard output without it.
    #[arg(short = 'o', long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// The CSV header. The first four columns are fixed by the project's interface.
pub const HEADER: &str = "angle_deg,position,velocity,acceleration,jerk,contact_x,contact_y,cam_x,cam_y,cam_param,\
sliding_rate_cam,sliding_rate_follower,normal_accel_cam,coriolis_cam,relative_cam,normal_accel_follower,\
normal_x,normal_y,sigma,pressure_angle_deg,radius_of_curvature,at_node,found,error";

fn parse_number(field: &str, s: &str) -> Result<f64> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| anyhow!("{field}: {s:?} is not a number"))?;
    if !v.is_finite() {
        bail!("{field}: {s:?} must be finite");
    }
    Ok(v)
}

/// Parses `--at` and `--angles` into a list of angles in degrees.
pub fn angle_list(at: Option<&str>, angles: Option<&str>) -> Result<Vec<f64>> {
    if let Some(at) = at {
        let v = at
            .split(',')
            .map(|s| parse_number("--at", s))
            .collect::<Result<Vec<_>>>()?;
        if v.len() > MAX_ANGLES {
            bail!("--at: {} angles is more than {MAX_ANGLES}", v.len());
        }
        return Ok(v);
    }
    let spec = angles.unwrap_or("0:360:1");
    let parts: Vec<&str> = spec.split(':').collect();
    if parts.len() != 3 {
        bail!("--angles: {spec:?} is not START:STOP:STEP");
    }
    let (start, stop, step) = (
        parse_number("--angles START", parts[0])?,
        parse_number("--angles STOP", parts[1])?,
        parse_number("--angles STEP", parts[2])?,
    );
    if step == 0.0 || (stop - start) * step < 0.0 {
        bail!("--angles: STEP {step} does not lead from START {start} to STOP {stop}");
    }
    let count = ((stop - start) / step).ceil();
    if count > MAX_ANGLES as f64 {
        bail!("--angles: {spec:?} gives {count} angles, more than {MAX_ANGLES}");
    }
    Ok((0..count as usize)
        .map(|k| start + k as f64 * step)
        .filter(|&a| if step > 0.0 { a < stop } else { a > stop })
        .collect())
}

/// One value of a row.
#[derive(Debug, Clone, PartialEq)]
enum Field {
    Num(f64),
    Text(String),
    Empty,
}

/// The values of one row, in the order of [`HEADER`]; `jump` marks a row whose contact jumped
/// since the previous row.
fn fields(
    angle_deg: f64,
    r: &Result<FollowerState, camkin::cam::CamError>,
    jump: bool,
) -> Vec<Field> {
    use Field::{Empty, Num, Text};
    match r {
        Ok(s) => {
            let found = match s.found {
                _ if jump => "jump",
                Found::Global => "global",
                Found::WarmStart => "warm",
                Found::Jump { .. } => "jump",
            };
            vec![
                Num(angle_deg),
                Num(s.position),
                Num(s.velocity),
                Num(s.acceleration),
                s.jerk.map_or(Empty, Num),
                Num(s.contact_world.x),
                Num(s.contact_world.y),
                Num(s.contact_cam.x),
                Num(s.contact_cam.y),
                Num(s.cam_param),
                Num(s.sliding_rate_cam),
                Num(s.sliding_rate_follower),
                Num(s.normal_acceleration_cam.total()),
                Num(s.normal_acceleration_cam.coriolis),
                Num(s.normal_acceleration_cam.relative),
                Num(s.normal_acceleration_follower.total()),
                Num(s.normal.x),
                Num(s.normal.y),
                Num(s.sigma),
                Num(s.pressure_angle().to_degrees()),
                Num(s.radius_of_curvature),
                Num(f64::from(u8::from(s.at_breakpoint))),
                Text(found.into()),
                Empty,
            ]
        }
        Err(e) => {
            let mut v = vec![Num(angle_deg)];
            v.resize(HEADER.split(',').count() - 1, Empty);
            v.push(Text(e.to_string()));
            v
        }
    }
}

fn csv_row(w: &mut dyn Write, f: &[Field]) -> std::io::Result<()> {
    let cells: Vec<String> = f
        .iter()
        .map(|x| match x {
            Field::Num(v) => v.to_string(),
            Field::Empty => String::new(),
            Field::Text(t) if t.contains([',', '"', '\n']) => {
                format!("\"{}\"", t.replace('"', "\"\""))
            }
            Field::Text(t) => t.clone(),
        })
        .collect();
    writeln!(w, "{}", cells.join(","))
}

fn json_row(f: &[Field]) -> serde_json::Value {
    let mut m = serde_json::Map::new();
    for (k, x) in HEADER.split(',').zip(f) {
        let v = match x {
            // non-finite numbers (∞ radius on a straight stretch) become null
            Field::Num(v) => serde_json::Number::from_f64(*v)
                .map_or(serde_json::Value::Null, serde_json::Value::Number),
            Field::Text(t) => serde_json::Value::String(t.clone()),
            Field::Empty => serde_json::Value::Null,
        };
        m.insert(k.to_string(), v);
    }
    serde_json::Value::Object(m)
}

/// Output format of `analyze`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// comma-separated values with a header
    Csv,
    /// an array of objects keyed by the CSV column names
    Json,
}

/// A warm-started sweep, with a progress bar on a terminal when it is long.
fn analyze_with_progress(
    mech: &camkin::cam::Mechanism,
    thetas: &[f64],
) -> Vec<Result<FollowerState, camkin::cam::CamError>> {
    const CHUNK: usize = 10_000;
    if thetas.len() <= 5 * CHUNK {
        return mech.analyze_all(thetas);
    }
    let pb = indicatif::ProgressBar::new(thetas.len() as u64);
    let mut sweep = mech.sweep();
    let mut out = Vec::with_capacity(thetas.len());
    for chunk in thetas.chunks(CHUNK) {
        out.extend(chunk.iter().map(|&t| sweep.step(t)));
        pb.inc(chunk.len() as u64);
    }
    pb.finish_and_clear();
    out
}

/// Rows whose contact jumped since the previous row: flagged by the sweep, or (for a range of
/// angles) the contact parameter passed over a stretch the follower cannot follow, which it can
/// only do by jumping.
fn jump_rows(
    mech: &Mechanism,
    results: &[Result<FollowerState, CamError>],
    stretches: &[(f64, f64)],
    monotone: bool,
) -> Vec<bool> {
    let period = match mech.cam().profile().domain() {
        camkin::curve::Domain::Periodic { period } => period,
        _ => 1.0,
    };
    let mut out = vec![false; results.len()];
    for k in 0..results.len() {
        let Ok(s) = &results[k] else { continue };
        if matches!(s.found, Found::Jump { .. }) {
            out[k] = true;
            continue;
        }
        let Some(Ok(p)) = k.checked_sub(1).map(|i| &results[i]) else {
            continue;
        };
        if !monotone || stretches.is_empty() {
            continue;
        }
        // the arc from the previous contact to this one, in the direction the contact moves
        let dir = if p.cam_param_rate >= 0.0 { 1.0 } else { -1.0 };
        let arc = (dir * (s.cam_param - p.cam_param)).rem_euclid(period);
        let inside = |u: f64| {
            let d = (dir * (u - p.cam_param)).rem_euclid(period);
            d > 0.0 && d < arc
        };
        out[k] = stretches.iter().any(|&(a, b)| inside(a) && inside(b));
    }
    out
}

/// Warnings on stderr: profile stretches the follower cannot follow, and where the contact jumps.
fn report_degenerate(mech: &Mechanism, stretches: &[(f64, f64)], angles: &[f64], jumps: &[bool]) {
    let what = match mech.roller_radius() {
        Some(roller_radius) => format!(
            "concave more sharply than the roller (radius of curvature below {roller_radius})"
        ),
        None => "concave under the flat face".to_string(),
    };
    let p = mech.cam().profile();
    for &(a, b) in stretches {
        let (pa, pb) = (p.position(a), p.position(b));
        eprintln!(
            "camkin: warning: the cam profile from u = {a:.4} ({:.4}, {:.4}) to u = {b:.4} ({:.4}, {:.4}) is {what}: the follower cannot follow it, the contact jumps across and the acceleration is impulsive there",
            pa.x, pa.y, pb.x, pb.y
        );
    }
    let at: Vec<String> = jumps
        .iter()
        .enumerate()
        .filter(|(_, j)| **j)
        .map(|(k, _)| match k {
            0 => format!("{}°", angles[0]),
            _ => format!("{}°–{}°", angles[k - 1], angles[k]),
        })
        .collect();
    if !at.is_empty() {
        eprintln!("camkin: warning: the contact jumps between cam angles {} (rows marked `jump` in the found column)", at.join(", "));
    }
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let mech = load_mechanism(args.mechanism.as_ref())?;
    let angles = angle_list(args.at.as_deref(), args.angles.as_deref()).map_err(Failure::Input)?;
    let thetas: Vec<f64> = angles.iter().map(|a| a.to_radians()).collect();
    let results = analyze_with_progress(&mech, &thetas);
    let failed = results.iter().filter(|r| r.is_err()).count();
    let stretches = mech.unfollowable_stretches();
    let jumps = jump_rows(&mech, &results, &stretches, args.at.is_none());
    report_degenerate(&mech, &stretches, &angles, &jumps);
    write_atomic(args.output.as_deref(), |w| {
        match args.format {
            Format::Csv => {
                writeln!(w, "{HEADER}")?;
                for ((a, r), j) in angles.iter().zip(&results).zip(&jumps) {
                    csv_row(w, &fields(*a, r, *j))?;
                }
            }
            Format::Json => {
                let rows: Vec<serde_json::Value> = angles
                    .iter()
                    .zip(&results)
                    .zip(&jumps)
                    .map(|((a, r), j)| json_row(&fields(*a, r, *j)))
                    .collect();
                serde_json::to_writer(&mut *w, &rows)?;
                writeln!(w)?;
            }
        }
        Ok(())
    })
    .map_err(|e| {
        if args.output.is_some() {
            Failure::Input(e)
        } else {
            Failure::Internal(e)
        }
    })?;
    if failed > 0 {
        eprintln!(
            "camkin: {failed} of {} angles could not be analysed; see the error column",
            angles.len()
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angle_ranges_exclude_stop() {
        assert_eq!(
            angle_list(None, Some("0:3:1")).unwrap(),
            vec![0.0, 1.0, 2.0]
        );
        assert_eq!(angle_list(None, Some("10:0:-5")).unwrap(), vec![10.0, 5.0]);
        assert_eq!(angle_list(None, None).unwrap().len(), 360);
        assert_eq!(
            angle_list(Some("0, 45,-10"), None).unwrap(),
            vec![0.0, 45.0, -10.0]
        );
        assert!(angle_list(None, Some("0:1:0")).is_err());
        assert!(angle_list(None, Some("0:10:-1")).is_err());
        assert!(angle_list(None, Some("0:1")).is_err());
        assert!(angle_list(Some("a"), None).is_err());
        assert!(angle_list(None, Some("0:1e12:1e-6")).is_err());
    }

    #[test]
    fn header_starts_with_the_fixed_columns_and_rows_match_it() {
        assert!(HEADER.starts_with("angle_deg,position,velocity,acceleration,"));
        let m = crate::mechfile::paper();
        let n = HEADER.split(',').count();
        assert_eq!(fields(0.0, &m.analyze(0.0), false).len(), n);
        let err: Result<FollowerState, _> = Err(camkin::cam::CamError::OpenProfile);
        let f = fields(1.0, &err, false);
        assert_eq!(f.len(), n);
        let mut out = Vec::new();
        csv_row(&mut out, &f).unwrap();
        assert_eq!(
            String::from_utf8(out)
                .unwrap()
                .trim_end()
                .split(',')
                .count(),
            n
        );
        let j = json_row(&f);
        assert_eq!(j["angle_deg"], 1.0);
        assert!(j["position"].is_null());
        assert!(j["error"].as_str().unwrap().contains("closed"));
    }
}
