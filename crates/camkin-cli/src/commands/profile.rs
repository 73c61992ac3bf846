//! `camkin profile`: manufacturing output from any cam profile — the polar table, the pitch
//! curve, a cutter's centre path with its undercut check, and a DXF of arcs with its units.

use crate::args::RevolutionStep;
use crate::manufacture::{self, Error, Options};
use crate::{load_mechanism, Failure};
use anyhow::anyhow;
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub struct ProfileArgs {
    /// Mechanism file (TOML); without it, the paper's built-in cam.
    pub mechanism: Option<PathBuf>,
    /// Directory for polar.csv, pitch.csv, cutter.csv and profile.dxf.
    #[arg(long, value_name = "DIR", default_value = "camkin-profile")]
    pub out: PathBuf,
    /// Angle step of the polar table, degrees.
    #[arg(long, value_name = "DEG", default_value = "1")]
    pub step: RevolutionStep,
    /// Radius of the cutter or grinding wheel, in the file's length unit: its centre path
    /// (cutter.csv, layer CUTTER of profile.dxf) and where it cannot cut the profile.
    #[arg(long, value_name = "R", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub tool_radius: Option<f64>,
    /// Largest distance of the DXF's arcs from the exact curves, in the file's length unit
    /// [default: 1e-6 of the cam's size].
    #[arg(long, value_name = "LENGTH", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub tolerance: Option<f64>,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
    #[command(flatten)]
    pub force: crate::out_dir::ForceArg,
}

pub fn run(args: &ProfileArgs) -> Result<(), Failure> {
    let loaded = load_mechanism(args.mechanism.as_ref())?;
    // the tool radius and the tolerance are checked by the library's shop report
    // a sweep for the table (and the cutter's path), about 250 bytes of files an angle
    let angles = (360.0 / args.step.deg()).round() as usize;
    crate::refuse_large(
        &camkin::work::Work::sweep(&loaded.mech, angles, 2).with_bytes(angles as f64 * 250.0),
        args.work.large,
        ", or use a coarser --step",
    )?;
    let od = crate::out_dir::OutDir::begin(&args.out, args.force.force)?;
    let made = manufacture::write(
        &loaded.mech,
        loaded.unit,
        od.path(),
        &Options {
            step_deg: args.step.deg(),
            tool_radius: args.tool_radius,
            tolerance: args.tolerance,
        },
    )
    .map_err(|e| match e {
        Error::Input(e) => Failure::Input(e),
        Error::Output(e) => Failure::output(e),
    })?;
    od.commit().map_err(Failure::output)?;
    crate::out!("{}", made.report)?;
    if let Some(chain) = loaded.mech.cam().profile().as_arcs_and_lines() {
        crate::out!("{}", joins(chain, loaded.unit.name()))?;
    }
    crate::say!(
        "camkin: wrote {} files to {}",
        made.files.len(),
        args.out.display()
    );
    if made.tool_undercut {
        return Err(Failure::Check(anyhow!(
            "design check failed: the cutter cannot cut the profile (see above)"
        )));
    }
    Ok(())
}

/// An arcs-and-lines profile's joins: where each is (its point and polar angle), whether the
/// tangent turns there (a corner) and the radius of curvature on either side.
fn joins(chain: &camkin::curve::ArcsAndLines, unit: &str) -> String {
    use camkin::curve::Curve;
    let radius = |r: f64| {
        if r.is_finite() {
            format!("{} {unit}", crate::forces_text::num(r))
        } else {
            "∞ (a line)".to_string()
        }
    };
    let mut out = String::from(
        "joins of the arcs and lines (the radius of curvature jumps there, and so does the follower's acceleration):\n",
    );
    for j in chain.joins() {
        let p = chain.position(j.param);
        out += &format!(
            "  at ({}, {}) {unit}, {}° round the axis: radius {} before, {} after; {}\n",
            crate::forces_text::num(p.x),
            crate::forces_text::num(p.y),
            crate::forces_text::num(p.y.atan2(p.x).to_degrees().rem_euclid(360.0)),
            radius(j.radius[0]),
            radius(j.radius[1]),
            if j.turn.abs() < 1e-9 {
                "tangent".to_string()
            } else {
                format!(
                    "a corner of {}°",
                    crate::forces_text::num(j.turn.to_degrees())
                )
            }
        );
    }
    out
}
