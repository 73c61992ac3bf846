//! Manufacturing output written: the library's [`camkin::report::ShopReport`] (polar table,
//! pitch and cutter paths, the cutter's check, the DXF of arcs) as `polar.csv`, `pitch.csv`,
//! `cutter.csv` and `profile.dxf`, with a report for people.

use crate::output::{write_atomic, write_cell_table, Cell, TableFormat};
use anyhow::anyhow;
use camkin::cam::Mechanism;
use camkin::report::dxf::CENTRE_LAYER;
use camkin::report::{ShopError, ShopField, ShopReport, ShopRequest};
use camkin::spec::LengthUnit;
use std::path::{Path, PathBuf};

pub use camkin::report::shop::{offset_point, polar_params};

/// What to write.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// angle step of the polar table, degrees (divides 360)
    pub step_deg: f64,
    /// a cutter's or grinding wheel's radius, file units
    pub tool_radius: Option<f64>,
    /// largest distance of the DXF's arcs from the exact curve, file units (default 1e-6 of the
    /// cam's size)
    pub tolerance: Option<f64>,
}

/// Why nothing (or not everything) was written.
#[derive(Debug)]
pub enum Error {
    /// bad input (exit 2)
    Input(anyhow::Error),
    /// a write failed
    Output(anyhow::Error),
}

/// What was written, and a report for people.
#[derive(Debug, Clone, Default)]
pub struct Made {
    /// the files
    pub files: Vec<PathBuf>,
    /// lines for the report (units included)
    pub report: String,
    /// the tool cannot cut the profile everywhere
    pub tool_undercut: bool,
}

/// Writes `polar.csv`, `pitch.csv` (rollers), `cutter.csv` (with a tool radius) and
/// `profile.dxf` into `dir`.
pub fn write(
    mech: &Mechanism,
    unit: LengthUnit,
    dir: &Path,
    opts: &Options,
) -> Result<Made, Error> {
    let l = unit.name();
    let h = camkin::human::human;
    let shop = ShopReport::new(
        mech,
        unit,
        &ShopRequest {
            step_deg: opts.step_deg,
            tool_radius: opts.tool_radius,
            tolerance: opts.tolerance,
        },
    )
    .map_err(|e| match e {
        ShopError::Invalid { field, .. } => {
            let flag = match field {
                ShopField::ToolRadius => "--tool-radius",
                ShopField::Tolerance => "--tolerance",
                _ => "--step",
            };
            Error::Input(anyhow!("{flag}: {e}"))
        }
        e => Error::Input(anyhow!("{e}")),
    })?;
    std::fs::create_dir_all(dir)
        .map_err(|e| Error::Input(anyhow!("cannot create {}: {e}", dir.display())))?;
    let mut made = Made::default();
    let out = |e: anyhow::Error| Error::Output(e);
    let num = |v: f64| Cell::Num(Some(v));
    match &shop.polar {
        Ok(polar) => {
            let p = dir.join("polar.csv");
            let columns: Vec<String> = vec![
                "polar_angle_deg".into(),
                format!("radius_{l}"),
                format!("x_{l}"),
                format!("y_{l}"),
            ];
            let rows = polar
                .angle_deg
                .iter()
                .zip(&polar.points)
                .map(|(a, q)| vec![num(*a), num(q[0].hypot(q[1])), num(q[0]), num(q[1])])
                .collect();
            write_atomic(Some(&p), |w| {
                write_cell_table(w, TableFormat::Csv, &columns, rows)
            })
            .map_err(out)?;
            made.files.push(p);
            // the paths offset from the profile, at the polar table's points
            for path in &shop.offsets {
                let p = dir.join(format!("{}.csv", path.name));
                let columns: Vec<String> = vec![
                    "polar_angle_deg".into(),
                    format!("x_{l}"),
                    format!("y_{l}"),
                    format!("profile_x_{l}"),
                    format!("profile_y_{l}"),
                ];
                let rows = polar
                    .angle_deg
                    .iter()
                    .zip(&path.points)
                    .zip(&polar.points)
                    .map(|((a, c), q)| vec![num(*a), num(c[0]), num(c[1]), num(q[0]), num(q[1])])
                    .collect();
                write_atomic(Some(&p), |w| {
                    write_cell_table(w, TableFormat::Csv, &columns, rows)
                })
                .map_err(out)?;
                made.files.push(p);
            }
        }
        Err(why) => {
            made.report += &format!("polar table: none ({why})\n");
        }
    }
    if let Some(c) = &shop.cutter {
        made.report += &match c.undercut_deg {
            None => format!(
                "cutter (radius {} {l}): cuts the whole profile\n",
                h(c.radius)
            ),
            Some((from, to)) => {
                made.tool_undercut = true;
                format!(
                    "cutter (radius {} {l}): UNDERCUT — the profile is concave more sharply than the tool (radius of curvature down to {} {l}) at polar angles from {}° to {}°\n",
                    h(c.radius),
                    h(c.sharpest_concave),
                    h(from),
                    h(to)
                )
            }
        };
    }
    let p = dir.join("profile.dxf");
    let text = &shop.dxf.text;
    write_atomic(Some(&p), |w| Ok(w.write_all(text.as_bytes())?)).map_err(out)?;
    made.files.push(p);
    made.report += &format!(
        "profile.dxf: {} arcs on layers {}, the centre mark and the 0° line on {CENTRE_LAYER} (units {l}); largest distance from the exact curves {:.1e} {l}\n",
        shop.dxf.arcs,
        shop.dxf.layers.join(", "),
        shop.dxf.largest_deviation
    );
    Ok(made)
}
