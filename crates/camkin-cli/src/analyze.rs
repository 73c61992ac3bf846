//! `camkin analyze`: the one-instant analysis at a list or range of cam angles, as CSV.

use crate::output::write_atomic;
use crate::{load_mechanism, Failure};
use anyhow::{anyhow, bail, Result};
use camkin::cam::{FollowerState, Found};
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

fn row(
    w: &mut dyn Write,
    angle_deg: f64,
    r: &Result<FollowerState, camkin::cam::CamError>,
) -> std::io::Result<()> {
    match r {
        Ok(s) => {
            let found = match s.found {
                Found::Global => "global",
                Found::WarmStart => "warm",
                Found::Jump { .. } => "jump",
            };
            writeln!(
                w,
                "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},",
                angle_deg,
                s.position,
                s.velocity,
                s.acceleration,
                s.jerk.map(|j| j.to_string()).unwrap_or_default(),
                s.contact_world.x,
                s.contact_world.y,
                s.contact_cam.x,
                s.contact_cam.y,
                s.cam_param,
                s.sliding_rate_cam,
                s.sliding_rate_follower,
                s.normal_acceleration_cam.total(),
                s.normal_acceleration_cam.coriolis,
                s.normal_acceleration_cam.relative,
                s.normal_acceleration_follower.total(),
                s.normal.x,
                s.normal.y,
                s.sigma,
                s.pressure_angle.to_degrees(),
                s.radius_of_curvature,
                u8::from(s.at_breakpoint),
                found
            )
        }
        Err(e) => {
            let msg = e.to_string().replace('"', "'");
            writeln!(
                w,
                "{angle_deg}{}\"{msg}\"",
                ",".repeat(HEADER.split(',').count() - 1)
            )
        }
    }
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let mech = load_mechanism(args.mechanism.as_ref())?;
    let angles = angle_list(args.at.as_deref(), args.angles.as_deref()).map_err(Failure::Input)?;
    let thetas: Vec<f64> = angles.iter().map(|a| a.to_radians()).collect();
    let results = mech.analyze_all(&thetas);
    let failed = results.iter().filter(|r| r.is_err()).count();
    write_atomic(args.output.as_deref(), |w| {
        writeln!(w, "{HEADER}")?;
        for (a, r) in angles.iter().zip(&results) {
            row(w, *a, r)?;
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
        let mut out = Vec::new();
        let r = m.analyze(0.0);
        row(&mut out, 0.0, &r).unwrap();
        let line = String::from_utf8(out).unwrap();
        assert_eq!(
            line.trim_end().split(',').count(),
            HEADER.split(',').count()
        );
        let r: Result<FollowerState, _> = Err(camkin::cam::CamError::OpenProfile);
        let mut out = Vec::new();
        row(&mut out, 1.0, &r).unwrap();
        assert_eq!(
            String::from_utf8(out)
                .unwrap()
                .trim_end()
                .split(',')
                .count(),
            HEADER.split(',').count()
        );
    }
}
