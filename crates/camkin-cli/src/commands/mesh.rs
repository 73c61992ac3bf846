//! `camkin mesh`: a gear pair read as gears, at a list or range of driver angles: driven angle,
//! transmission error and its rates, tooth pairs, line of action, sliding; CSV or JSON, and a
//! page of plots over the angles.

use crate::draw::svaj;
use crate::mechfile;
use crate::{load_mechanism, Failure, Loaded};
use anyhow::anyhow;
use camkin::gears::GearPair;
use camkin::human::human;
use camkin::spec::LengthUnit;
use camkin::table::{contact_jumps, mesh_cells, mesh_columns, MeshRow, Units};
use std::path::{Path, PathBuf};

#[derive(Debug, clap::Args)]
pub struct MeshArgs {
    /// Mechanism file (TOML) whose cam and follower profiles are involute gears; without it, the
    /// built-in 20/42 pair (examples/gear-pair-20-42.toml).
    pub mechanism: Option<PathBuf>,
    #[command(flatten)]
    pub sweep: crate::args::AngleArgs,
    #[command(flatten)]
    pub table: crate::args::TableArgs,
    /// Also draw the transmission error, the driven gear's acceleration, the sliding velocity
    /// and both flanks' specific sliding over the angles into DIR/mesh.{svg,png}.
    #[arg(long, value_name = "DIR")]
    pub plot: Option<PathBuf>,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
    #[command(flatten)]
    pub force: crate::out_dir::ForceArg,
}

/// The built-in pair.
pub const GEAR_PAIR_TOML: &str = include_str!("../../../../examples/gear-pair-20-42.toml");

fn load(path: Option<&PathBuf>) -> Result<Loaded, Failure> {
    match path {
        Some(_) => load_mechanism(path),
        None => {
            crate::say!("camkin: no mechanism file given; using the built-in 20/42 gear pair (examples/gear-pair-20-42.toml, lengths in mm)");
            let mech = mechfile::parse(GEAR_PAIR_TOML, "gear-pair-20-42.toml", Path::new("."))
                .map_err(|e| Failure::Internal(anyhow!(e)))?;
            Ok(Loaded {
                mech,
                unit: LengthUnit::Mm,
                name: "gear-pair-20-42".into(),
            })
        }
    }
}

/// A small length for people: µm (or µin) from the mechanism's unit, with the factor.
fn micro_length(unit: LengthUnit) -> (&'static str, f64) {
    match unit {
        LengthUnit::In => ("µin", 1e6),
        u => ("µm", 1e6 * u.metres()),
    }
}

pub fn run(args: &MeshArgs) -> Result<(), Failure> {
    let loaded = load(args.mechanism.as_ref())?;
    args.table.check()?;
    let od = crate::out_dir::OutDir::begin_if(args.plot.as_deref(), args.force.force)?;
    let mech = &loaded.mech;
    let pair = GearPair::new(mech).map_err(|e| {
        Failure::Input(anyhow!(
            "{}: not a gear pair: {e}",
            args.mechanism
                .as_ref()
                .map_or_else(|| "the built-in pair".into(), |p| p.display().to_string())
        ))
    })?;
    let z1 = pair.driver().teeth();
    let angles = args.sweep.or_else(|| {
        let cycle = 360.0 / f64::from(z1);
        (0..720).map(|k| f64::from(k) * cycle / 360.0).collect()
    });
    // the rows are held in memory, about 250 bytes each
    crate::refuse_large(
        &camkin::work::Work::sweep(mech, angles.len(), 1).with_bytes(angles.len() as f64 * 250.0),
        args.work.large,
        ", or use fewer angles",
    )?;
    let contiguous = args.sweep.contiguous();
    let results = mech.analyze_deg_each(&angles, contiguous);
    let jumps = contact_jumps(mech, &results, contiguous);
    let rows: Vec<MeshRow> = angles
        .iter()
        .zip(&results)
        .zip(&jumps)
        .map(|((&a, r), &j)| MeshRow::new(&pair, mech, a, r, j))
        .collect();
    let units = Units::plain(mech, loaded.unit);
    let columns = mesh_columns(&units);
    let mut chunk = Some(rows.clone());
    args.table
        .write_rows(&columns, || chunk.take(), mesh_cells)?;
    summary(&pair, &loaded, &rows);
    if let Some(od) = od {
        let written = plot(&pair, &loaded, &rows, od.path()).map_err(Failure::output)?;
        let shown: Vec<_> = written.iter().map(|p| od.shown(p)).collect();
        od.commit().map_err(Failure::output)?;
        for p in shown {
            crate::say!("camkin: wrote {}", p.display());
        }
    }
    let failed = rows.iter().filter(|r| r.error.is_some()).count();
    if failed > 0 {
        crate::say!(
            "camkin: {failed} of {} angles could not be analysed; see the error column",
            rows.len()
        );
    }
    Ok(())
}

/// The pair and what the rows show, on stderr, rounded for people.
fn summary(pair: &GearPair, loaded: &Loaded, rows: &[MeshRow]) {
    let l = loaded.unit.name();
    let (z1, z2) = (pair.driver().teeth(), pair.driven().teeth());
    crate::say!(
        "camkin: {z1}/{z2} teeth, centre distance {} {l}, operating pressure angle {}°, contact ratio {}, base pitch {} {l}",
        human((pair.centre_distance() * 1e6).round() / 1e6),
        human((pair.operating_pressure_angle().to_degrees() * 1e4).round() / 1e4),
        human((pair.contact_ratio() * 1e4).round() / 1e4),
        human((pair.base_pitch() * 1e4).round() / 1e4),
    );
    let eps = pair.contact_ratio();
    if eps < 1.0 {
        let one = camkin::gears::distance_for_contact_ratio(pair.driver(), pair.driven(), 1.0);
        crate::say!(
            "camkin: warning: contact ratio {} is below 1: between handovers no tooth pair is in contact on the involutes, and the next tooth strikes{}",
            human((eps * 1e4).round() / 1e4),
            one.map_or(String::new(), |d| format!(
                "; a ratio of 1 needs a centre distance of at most {} {l}",
                human((d * 1e6).floor() / 1e6)
            ))
        );
    }
    let (mu, k) = micro_length(loaded.unit);
    let te: Vec<f64> = rows
        .iter()
        .filter_map(|r| r.transmission_error_length)
        .collect();
    if let (Some(lo), Some(hi)) = (
        te.iter().copied().reduce(f64::min),
        te.iter().copied().reduce(f64::max),
    ) {
        let handovers = rows
            .iter()
            .filter(|r| r.found == Some(camkin::table::FoundBy::Jump))
            .count();
        let most = rows.iter().filter_map(|r| r.pairs_in_contact).max();
        crate::say!(
            "camkin: over these angles the transmission error along the line of action is {} to {} {mu} (peak to peak {} {mu}); {handovers} handover{} to another tooth pair (rows marked jump); at most {} tooth pair{} in contact",
            human((lo * k * 1e4).round() / 1e4),
            human((hi * k * 1e4).round() / 1e4),
            human(((hi - lo) * k * 1e4).round() / 1e4),
            if handovers == 1 { "" } else { "s" },
            most.unwrap_or(0),
            if most == Some(1) { "" } else { "s" }
        );
    }
}

/// The mesh page: transmission error, the driven gear's angular acceleration, the sliding
/// velocity and both flanks' specific sliding over the driver angle; handovers marked.
fn plot(
    pair: &GearPair,
    loaded: &Loaded,
    rows: &[MeshRow],
    dir: &Path,
) -> anyhow::Result<Vec<PathBuf>> {
    let l = loaded.unit.name();
    let (mu, k) = micro_length(loaded.unit);
    // a handover: the transmission error has a kink, its rates and the sliding jump
    let handover = |w: &[MeshRow]| {
        w[1].found == Some(camkin::table::FoundBy::Jump)
            || w[0].driver_tooth != w[1].driver_tooth
            || w[0].driven_tooth != w[1].driven_tooth
    };
    // the curve of one quantity; `broken`: a line break at each handover (the quantity jumps)
    let series = |f: &dyn Fn(&MeshRow) -> Option<f64>, broken: bool| -> Vec<(f64, f64)> {
        let mut out = Vec::with_capacity(rows.len() + 8);
        for (k, r) in rows.iter().enumerate() {
            if broken && k > 0 && handover(&rows[k - 1..=k]) {
                out.push((r.angle_deg, f64::NAN));
            }
            out.push((r.angle_deg, f(r).unwrap_or(f64::NAN)));
        }
        out
    };
    let panel = |label: String, unit: &str, points, resolution| svaj::Panel {
        label,
        unit: unit.into(),
        points,
        resolution,
    };
    // an ideal pair's transmission error and acceleration are zero to rounding (1e-12 rad,
    // 1e-15 ω²): drawn as zero, not as noise magnified to fill the panel
    let omega = loaded.mech.cam().speed();
    let size = pair.centre_distance();
    let x0 = rows
        .iter()
        .map(|r| r.angle_deg)
        .fold(f64::INFINITY, f64::min);
    let x1 = rows
        .iter()
        .map(|r| r.angle_deg)
        .fold(f64::NEG_INFINITY, f64::max);
    if !(x0 < x1) {
        return Err(anyhow!("a plot needs at least two different angles"));
    }
    let marks = rows
        .windows(2)
        .filter(|w| handover(w))
        .map(|w| svaj::Mark {
            angle_deg: w[1].angle_deg,
            order: 1,
        })
        .collect();
    let rpm = loaded.mech.cam().speed() * 60.0 / std::f64::consts::TAU;
    let page = svaj::Page {
        title: format!(
            "{}: {}/{} teeth, contact ratio {}, driver at {} rpm; dashed: handover to the next tooth pair",
            loaded.name,
            pair.driver().teeth(),
            pair.driven().teeth(),
            human((pair.contact_ratio() * 1e3).round() / 1e3),
            human((rpm * 1e3).round() / 1e3),
        ),
        panels: vec![
            panel(
                format!("transmission error ({mu})"),
                mu,
                series(&|r| r.transmission_error_length.map(|t| t * k), false),
                1e-10 * size * k,
            ),
            panel(
                "driven acceleration (rad/s²)".into(),
                "rad/s²",
                series(&|r| r.driven_acceleration, true),
                1e-10 * omega * omega,
            ),
            panel(
                format!("sliding velocity ({l}/s)"),
                &format!("{l}/s"),
                series(&|r| r.sliding_velocity, true),
                0.0,
            ),
            panel(
                "specific sliding, driver".into(),
                "",
                series(&|r| r.specific_sliding_driver, true),
                0.0,
            ),
            panel(
                "specific sliding, driven".into(),
                "",
                series(&|r| r.specific_sliding_driven, true),
                0.0,
            ),
        ],
        marks,
        x: (x0, x1),
        x_label: "driver angle (°)".into(),
    };
    svaj::save(&page, &dir.join("mesh"))
}
