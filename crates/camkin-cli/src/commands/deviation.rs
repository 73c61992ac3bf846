//! `camkin deviation`: a profile measured on a coordinate measuring machine against the design —
//! the deviation in radius, and in the follower's lift, velocity and acceleration.
//!
//! The measured points (x, y in the cam frame, the design file's length unit) are smoothed by a
//! least-squares Fourier series of the radius in the polar angle with the fewest harmonics whose
//! RMS residual is within `--tolerance` (the measurement's noise); the smoothed profile (a
//! chord-length spline through 1440 of its points) drives the design's follower.

use crate::args::RevolutionStep;
use crate::manufacture::polar_params;
use crate::mechfile;
use crate::output::{write_atomic, write_cell_table, Cell, TableFormat};
use crate::Failure;
use anyhow::anyhow;
use camkin::cam::Mechanism;
use camkin::human::human;
use camkin::measured::FourierRadius;
use camkin::spec::{BuildOptions, ProfileSpec};
use camkin::table::Units;
use std::f64::consts::TAU;
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
    let size = mech.size();
    let tol = args.tolerance.unwrap_or(1e-4 * size);
    if !(tol.is_finite() && tol > 0.0 && tol < 0.1 * size) {
        return Err(fail(format!(
            "--tolerance: {} {l} must be positive and below 0.1 of the cam's size ({} {l})",
            human(tol),
            human(size)
        )));
    }
    let fit = FourierRadius::fit(&pts, tol).map_err(|e| {
        let hint = match e {
            camkin::measured::MeasuredError::NoFit { .. } => {
                " (raise --tolerance to the measurement's noise)"
            }
            _ => "",
        };
        fail(format!("{}: {e}{hint}", args.measured.display()))
    })?;
    // deviation in radius at the measured points
    let phis: Vec<f64> = pts.iter().map(|p| p.y.atan2(p.x).rem_euclid(TAU)).collect();
    let us = polar_params(mech.cam().profile(), &phis)
        .map_err(|e| fail(format!("{}: {e}", args.against.display())))?;
    let mut radius_rows = Vec::with_capacity(pts.len());
    let (mut dmax, mut dmax_at, mut sq) = (0.0f64, 0.0f64, 0.0f64);
    for ((p, &phi), &u) in pts.iter().zip(&phis).zip(&us) {
        let design_r = mech.cam().profile().position(u).coords.norm();
        let r = p.coords.norm();
        let d = r - design_r;
        sq += d * d;
        if d.abs() > dmax.abs() {
            (dmax, dmax_at) = (d, phi);
        }
        radius_rows.push(vec![
            Cell::Num(Some(phi.to_degrees())),
            Cell::Num(Some(r)),
            Cell::Num(Some(design_r)),
            Cell::Num(Some(d)),
            Cell::Num(Some(fit.radius(phi))),
        ]);
    }
    let rms = (sq / pts.len() as f64).sqrt();
    // the smoothed profile driving the design's follower
    let n = 1440;
    let smooth: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let p = fit.point(TAU * k as f64 / n as f64);
            [p.x, p.y]
        })
        .collect();
    let mut sspec = spec.clone();
    sspec.cam.profile = ProfileSpec {
        kind: "spline".into(),
        points: Some(smooth),
        parameterization: Some(camkin::curve::Parameterization::ChordLength),
        ..ProfileSpec::default()
    };
    let measured = sspec
        .build(&opts)
        .map_err(|e| fail(format!("the smoothed measured profile: {e}")))?
        .mechanism;
    let u = Units::plain(mech, unit);
    let step = args.step.deg();
    let m = (360.0 / step).round() as usize;
    // the design and the measured profile swept, about 400 bytes an angle held
    crate::refuse_large(
        &camkin::work::Work::sweep(mech, m, 2).with_bytes(m as f64 * 400.0),
        args.work.large,
        ", or use a coarser --step",
    )?;
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let grid = camkin::table::AngleGrid::new(0.0, step);
    let thetas: Vec<f64> = (0..m).map(|k| grid.at(k).to_radians()).collect();
    let sweep = |mm: &Mechanism| -> Result<Vec<[f64; 4]>, Failure> {
        let t = mm
            .travel()
            .map_err(|e| fail(format!("the follower's travel: {e}")))?;
        mm.analyze_all(&thetas)
            .into_iter()
            .map(|r| {
                r.map(|s| {
                    let c = u.motion(s.position, s.velocity, s.acceleration, None);
                    [
                        u.coord_value(t.lift(s.position)),
                        c[1].unwrap_or(f64::NAN),
                        c[2].unwrap_or(f64::NAN),
                        c[0].unwrap_or(f64::NAN),
                    ]
                })
                .map_err(|e| fail(format!("analysis: {e}")))
            })
            .collect()
    };
    let d = sweep(mech)?;
    let g = sweep(&measured)?;
    let mut report = format!(
        "measured profile {}: {} points; smoothed by a Fourier series of the radius with {} harmonics (RMS residual {} {l}, tolerance {} {l})\n",
        args.measured.display(),
        pts.len(),
        fit.harmonics(),
        human(fit.rms_residual),
        human(tol)
    );
    report += &format!(
        "radius deviation (measured − design): largest {} {l} at {}°, RMS {} {l}\n",
        human(dmax),
        human((dmax_at.to_degrees() * 10.0).round() / 10.0),
        human(rms)
    );
    let names = ["lift", "velocity", "acceleration"];
    let mut motion_rows: Vec<Vec<Cell>> = Vec::with_capacity(m);
    for k in 0..m {
        let mut row = vec![Cell::Num(Some(thetas[k].to_degrees()))];
        for j in 0..3 {
            row.extend([
                Cell::Num(Some(d[k][j])),
                Cell::Num(Some(g[k][j])),
                Cell::Num(Some(g[k][j] - d[k][j])),
            ]);
        }
        motion_rows.push(row);
    }
    for (j, nm) in names.iter().enumerate() {
        let peak = d.iter().map(|r| r[j].abs()).fold(0.0, f64::max);
        let (mut worst, mut at) = (0.0f64, 0.0);
        for (k, (a, b)) in d.iter().zip(&g).enumerate() {
            if (b[j] - a[j]).abs() > worst.abs() {
                (worst, at) = (b[j] - a[j], thetas[k]);
            }
        }
        report += &format!(
            "{nm} deviation: largest {} {} at {}° ({} of the design's peak {} {})\n",
            human(worst),
            u.motion_symbol(j),
            human((at.to_degrees() * 10.0).round() / 10.0),
            human(if peak > 0.0 { worst.abs() / peak } else { 0.0 }),
            human(peak),
            u.motion_symbol(j)
        );
    }
    crate::out!("{report}")?;
    if let Some(od) = od {
        let dir = od.path().to_path_buf();
        let cols: Vec<String> = vec![
            "polar_angle_deg".into(),
            format!("measured_radius_{l}"),
            format!("design_radius_{l}"),
            format!("deviation_{l}"),
            format!("smoothed_radius_{l}"),
        ];
        write_atomic(Some(&dir.join("radius.csv")), |w| {
            write_cell_table(w, TableFormat::Csv, &cols, radius_rows)
        })
        .map_err(Failure::output)?;
        let mut cols: Vec<String> = vec!["angle_deg".into()];
        for (j, nm) in names.iter().enumerate() {
            let key = u.motion_key(j);
            cols.push(format!("design_{nm}_{key}"));
            cols.push(format!("measured_{nm}_{key}"));
            cols.push(format!("deviation_{nm}_{key}"));
        }
        write_atomic(Some(&dir.join("motion.csv")), |w| {
            write_cell_table(w, TableFormat::Csv, &cols, motion_rows)
        })
        .map_err(Failure::output)?;
        let dir = od.commit().map_err(Failure::output)?;
        crate::say!("camkin: wrote {}", dir.display());
    }
    Ok(())
}
