//! `camkin deviation`: a profile measured on a coordinate measuring machine against the design —
//! the deviation in radius, and in the follower's lift, velocity and acceleration: the library's
//! [`camkin::report::DeviationReport`], printed and written as `radius.csv` and `motion.csv`.

use crate::args::RevolutionStep;
use crate::mechfile;
use crate::output::{write_atomic, write_cell_table, Cell, TableFormat};
use crate::Failure;
use anyhow::anyhow;
use camkin::human::human;
use camkin::report::{DeviationError, DeviationReport};
use camkin::spec::BuildOptions;
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub struct DeviationArgs {
    /// Measured points: a CSV of x,y in the cam frame (the design file's length unit), any
    /// spacing, in order round the profile or not.
    pub measured: PathBuf,
    /// The design's mechanism file.
    #[arg(long, value_name = "MECH.toml")]
    pub against: PathBuf,
    /// RMS noise of the measurement, in the file's length unit: the smoothing keeps the fewest
    /// harmonics that fit the points within it [default: 1e-4 of the cam's size].
    #[arg(long, value_name = "LENGTH", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub tolerance: Option<f64>,
    /// Cam-angle step of the comparison, degrees.
    #[arg(long, value_name = "DEG", default_value = "1")]
    pub step: RevolutionStep,
    /// Directory for radius.csv and motion.csv.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
    #[command(flatten)]
    pub force: crate::out_dir::ForceArg,
}

fn fail(m: String) -> Failure {
    Failure::Input(anyhow!(m))
}

pub fn run(args: &DeviationArgs) -> Result<(), Failure> {
    let (spec, design) = mechfile::load_with_spec(&args.against).map_err(|e| fail(e.message))?;
    let opts = BuildOptions {
        base_dir: args
            .against
            .parent()
            .unwrap_or(std::path::Path::new("."))
            .to_path_buf(),
        si: false,
        confine: false,
        limits: mechfile::build_limits(),
    };
    let unit = design.length_unit;
    let l = unit.name();
    let mech = &design.mechanism;
    crate::output::note_input(&args.measured);
    let (pts, _) = camkin::curve::read_points_file(&args.measured)
        .map_err(|e| fail(format!("{}: {e}", args.measured.display())))?;
    let step = args.step.deg();
    let m = (360.0 / step).round() as usize;
    // the design and the measured profile swept, about 400 bytes an angle held
    crate::refuse_large(
        &camkin::work::Work::sweep(mech, m, 2).with_bytes(m as f64 * 400.0),
        args.work.large,
        ", or use a coarser --step",
    )?;
    let r = DeviationReport::new(&spec, mech, unit, &opts, &pts, args.tolerance, step).map_err(
        |e| match e {
            DeviationError::Tolerance { .. } => fail(format!("--tolerance: {e}")),
            DeviationError::Fit(f) => {
                let hint = match f {
                    camkin::measured::MeasuredError::NoFit { .. } => {
                        " (raise --tolerance to the measurement's noise)"
                    }
                    _ => "",
                };
                fail(format!("{}: {f}{hint}", args.measured.display()))
            }
            DeviationError::Polar(why) => fail(format!("{}: {why}", args.against.display())),
            DeviationError::Size { .. } => fail(format!("{}: {e}", args.measured.display())),
            e => fail(e.to_string()),
        },
    )?;
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let mut report = format!(
        "measured profile {}: {} points; smoothed by a Fourier series of the radius with {} harmonics (RMS residual {} {l}, tolerance {} {l})\n",
        args.measured.display(),
        r.points,
        r.harmonics,
        human(r.rms_residual),
        human(r.tolerance)
    );
    report += &format!(
        "radius deviation (measured − design): largest {} {l} at {}°, RMS {} {l}\n",
        human(r.radius_largest.0),
        human((r.radius_largest.1 * 10.0).round() / 10.0),
        human(r.radius_rms)
    );
    for mo in &r.motion {
        let (worst, at) = mo.largest;
        report += &format!(
            "{} deviation: largest {} {} at {}° ({} of the design's peak {} {})\n",
            mo.name,
            human(worst),
            mo.symbol,
            human((at * 10.0).round() / 10.0),
            human(if mo.design_peak > 0.0 {
                worst.abs() / mo.design_peak
            } else {
                0.0
            }),
            human(mo.design_peak),
            mo.symbol
        );
    }
    crate::out!("{report}")?;
    if let Some(od) = od {
        let dir = od.path().to_path_buf();
        let num = |v: f64| Cell::Num(Some(v));
        let cols: Vec<String> = vec![
            "polar_angle_deg".into(),
            format!("measured_radius_{l}"),
            format!("design_radius_{l}"),
            format!("deviation_{l}"),
            format!("smoothed_radius_{l}"),
        ];
        let rd = &r.radius;
        let radius_rows = (0..rd.measured.len())
            .map(|k| {
                vec![
                    num(rd.polar_angle_deg[k]),
                    num(rd.measured[k]),
                    num(rd.design[k]),
                    num(rd.deviation[k]),
                    num(rd.smoothed[k]),
                ]
            })
            .collect();
        write_atomic(Some(&dir.join("radius.csv")), |w| {
            write_cell_table(w, TableFormat::Csv, &cols, radius_rows)
        })
        .map_err(Failure::output)?;
        let mut cols: Vec<String> = vec!["angle_deg".into()];
        for mo in &r.motion {
            cols.push(format!("design_{}_{}", mo.name, mo.key));
            cols.push(format!("measured_{}_{}", mo.name, mo.key));
            cols.push(format!("deviation_{}_{}", mo.name, mo.key));
        }
        let motion_rows = (0..r.angle_deg.len())
            .map(|k| {
                let mut row = vec![num(r.angle_deg[k])];
                for mo in &r.motion {
                    row.extend([
                        num(mo.design[k]),
                        num(mo.measured[k]),
                        num(mo.measured[k] - mo.design[k]),
                    ]);
                }
                row
            })
            .collect();
        write_atomic(Some(&dir.join("motion.csv")), |w| {
            write_cell_table(w, TableFormat::Csv, &cols, motion_rows)
        })
        .map_err(Failure::output)?;
        let dir = od.commit().map_err(Failure::output)?;
        crate::say!("camkin: wrote {}", dir.display());
    }
    Ok(())
}
