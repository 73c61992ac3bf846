//! A motion program's `law = "table"` segment: a lift table, from a file of `angle_deg, lift`
//! rows (`file = "lift.csv"`) or inline (`step_deg = 1, lift = [0, 0.001, …]`), read into a
//! [`LiftTable`]. Alone in its program it is the whole revolution (periodic: its rows cover 360°,
//! the last at 360° − step, or at 360° repeating the first); with other segments it lies between
//! dwells, from rest to rest, starting where the segment before it ends. Its lifts are in the
//! rise's units (the file's length, or degrees of an oscillating follower's arm), measured from
//! its first lift. A table whose noise puts more than 1 % of its peak acceleration into its
//! acceleration is warned of ([`SpecWarning::NoisyTable`]); nothing is smoothed.

use super::build::{positive, SpecError};
use super::SegmentSpec;
use super::SpecWarning;
use crate::curve::{read_points_file, CurveError};
use crate::field::{Field, SegmentField};
use crate::lift_table::LiftTable;
use crate::motion::{Law, Segment};
use std::path::Path;
use std::sync::Arc;

/// The most rows a table may have (a 0.01° table of a revolution).
const MAX_ROWS: usize = 36_000;

/// A table's acceleration noise, as a fraction of its peak, above which it is warned of.
const NOISE_WARNING: f64 = 0.01;

/// Where a table's rows came from, to place an error at a row.
enum Rows<'a> {
    Inline,
    File { path: &'a str, lines: &'a [usize] },
}

/// Segment `sg`, a `law = "table"` (its keys placed by `seg`): `alone` in its program (the
/// whole revolution), its lifts times `rise_scale`, a file read from `base` (within it when
/// `confine`).
pub(super) fn table_segment(
    sg: &SegmentSpec,
    seg: &dyn Fn(SegmentField) -> Field,
    alone: bool,
    rise_scale: f64,
    base: &Path,
    confine: bool,
    warnings: &mut Vec<SpecWarning>,
) -> Result<Segment, SpecError> {
    let h = crate::human::human;
    for (given, key) in [
        (sg.rise.is_some(), SegmentField::Rise),
        (sg.degrees.is_some(), SegmentField::Degrees),
    ] {
        if given {
            return Err(SpecError::Rule {
                field: seg(key),
                reason: "a table's rise and extent are its lifts': leave them out".into(),
            });
        }
    }
    let (step_deg, lifts, start_deg, file, lines) = match (&sg.file, &sg.lift) {
        (Some(_), Some(_)) | (None, None) => {
            return Err(SpecError::Rule {
                field: seg(SegmentField::Law),
                reason: "a table is a file of `angle_deg, lift` rows (file = \"lift.csv\") or its lifts inline (step_deg = 1, lift = [...]): give one".into(),
            })
        }
        (None, Some(lift)) => {
            let step = positive(
                seg(SegmentField::StepDeg),
                sg.step_deg.ok_or_else(|| SpecError::Rule {
                    field: seg(SegmentField::Lift),
                    reason: "inline lifts need their step: step_deg = …".into(),
                })?,
            )?;
            if let Some((i, v)) = lift.iter().enumerate().find(|(_, v)| !v.is_finite()) {
                return Err(SpecError::Invalid {
                    field: seg(SegmentField::Lift),
                    value: h(*v),
                    reason: format!("lift {i} must be finite"),
                });
            }
            (step, lift.clone(), 0.0, None, Vec::new())
        }
        (Some(path), None) => {
            if sg.step_deg.is_some() {
                return Err(SpecError::Rule {
                    field: seg(SegmentField::StepDeg),
                    reason: "a table file's angles give its step: leave step_deg out".into(),
                });
            }
            if confine {
                super::profile::confined(base, path).map_err(|reason| SpecError::Invalid {
                    field: seg(SegmentField::File),
                    value: format!("{path:?}"),
                    reason,
                })?;
            }
            let full = base.join(path);
            let shown = full.display().to_string();
            let (rows, lines) = read_points_file(&full).map_err(|e| match e {
                CurveError::PointsFileSyntax {
                    line,
                    message,
                    content,
                } => SpecError::PointsFile {
                    path: shown.clone(),
                    line: Some(line),
                    message: format!("{message}: {content:?}"),
                },
                CurveError::PointsFileIo { message, .. } => SpecError::Invalid {
                    field: seg(SegmentField::File),
                    value: format!("{path:?}"),
                    reason: format!("cannot read {shown}: {message}"),
                },
                other => SpecError::Invalid {
                    field: seg(SegmentField::File),
                    value: format!("{path:?}"),
                    reason: other.to_string(),
                },
            })?;
            let at = Rows::File {
                path: &shown,
                lines: &lines,
            };
            if rows.len() < 3 {
                return Err(at.error(
                    seg,
                    rows.len(),
                    format!("{} rows: a table needs at least 3", rows.len()),
                ));
            }
            let step = rows[1].x - rows[0].x;
            for (i, w) in rows.windows(2).enumerate() {
                let d = w[1].x - w[0].x;
                if !(step > 0.0 && (d - step).abs() <= 1e-6 * step) {
                    return Err(at.error(
                        seg,
                        i + 1,
                        format!(
                            "the angles must rise in equal steps (the first is {}°, this one {}°): resample the table",
                            h(step),
                            h(d)
                        ),
                    ));
                }
            }
            let lifts = rows.iter().map(|p| p.y).collect();
            (step, lifts, rows[0].x, Some(shown.clone()), lines)
        }
    };
    let at = match &file {
        Some(path) => Rows::File {
            path,
            lines: &lines,
        },
        None => Rows::Inline,
    };
    if lifts.len() > MAX_ROWS {
        return Err(at.error(
            seg,
            MAX_ROWS,
            format!(
                "{} rows is more than the {MAX_ROWS} a table may have",
                lifts.len()
            ),
        ));
    }
    let mut lifts: Vec<f64> = lifts.into_iter().map(|p| p * rise_scale).collect();
    let excursion = {
        let first = lifts.first().copied().unwrap_or(0.0);
        lifts.iter().fold(0.0f64, |m, &p| m.max((p - first).abs()))
    };
    let periodic = alone;
    if periodic {
        // the whole revolution: n steps of 360°, or n − 1 with the last row repeating the first
        let covered = step_deg * lifts.len() as f64;
        let tol = 1e-6 * step_deg;
        if (covered - 360.0 - step_deg).abs() <= tol {
            let (first, last) = (lifts[0], lifts[lifts.len() - 1]);
            if (last - first).abs() > 1e-9 * excursion.max(f64::MIN_POSITIVE) {
                return Err(at.error(
                    seg,
                    lifts.len() - 1,
                    format!(
                        "the lift at 360° ({}) is not the lift at 0° ({}): a table of the whole revolution closes on itself",
                        h(last / rise_scale),
                        h(first / rise_scale)
                    ),
                ));
            }
            lifts.pop();
        } else if (covered - 360.0).abs() > tol {
            return Err(at.error(
                seg,
                lifts.len() - 1,
                format!(
                    "a table alone in its program is the whole revolution, and its {} rows every {}° cover {}°: give 360° of rows (or add the dwell it lies between)",
                    lifts.len(),
                    h(step_deg),
                    h(step_deg * (lifts.len() - 1) as f64)
                ),
            ));
        }
        // its rows from 0°: a table starting at another multiple of its step is turned round
        let offset = start_deg / step_deg;
        if (offset - offset.round()).abs() > 1e-6 {
            return Err(at.error(
                seg,
                0,
                format!(
                    "a table of the whole revolution starts at a multiple of its step (it starts at {}°, its step is {}°)",
                    h(start_deg),
                    h(step_deg)
                ),
            ));
        }
        let n = lifts.len() as i64;
        let shift = (offset.round() as i64).rem_euclid(n) as usize;
        lifts.rotate_right(shift);
    } else {
        // between dwells: at rest at both ends (the spline is held there), so its first and
        // last steps move little against its fastest
        let fastest = lifts
            .windows(2)
            .fold(0.0f64, |m, w| m.max((w[1] - w[0]).abs()));
        let n = lifts.len();
        for (row, moved) in [
            (0, lifts[1] - lifts[0]),
            (n - 1, lifts[n - 1] - lifts[n - 2]),
        ] {
            if n >= 2 && moved.abs() > 0.1 * fastest {
                return Err(at.error(
                    seg,
                    row,
                    format!(
                        "the table is not at rest at its {} (its step there moves {} of its fastest step's {}): a table between dwells starts and ends at rest (start it on the base circle, or give the whole revolution alone)",
                        if row == 0 { "start" } else { "end" },
                        h(moved.abs() / rise_scale),
                        h(fastest / rise_scale)
                    ),
                ));
            }
        }
    }
    let table =
        LiftTable::new(step_deg.to_radians(), lifts, periodic).map_err(|e| SpecError::Rule {
            field: seg(SegmentField::Law),
            reason: e.to_string(),
        })?;
    let noise = table.noise();
    if noise.fraction() > NOISE_WARNING {
        warnings.push(SpecWarning::NoisyTable {
            field: seg(if file.is_some() {
                SegmentField::File
            } else {
                SegmentField::Lift
            }),
            sigma: noise.sigma / rise_scale,
            fraction: noise.fraction(),
        });
    }
    let (first, last) = table.ends();
    Ok(Segment {
        rise: last - first,
        extent: table.span(),
        law: Law::Table(Arc::new(table)),
    })
}

impl Rows<'_> {
    /// An error at row `row` of the table.
    fn error(&self, seg: &dyn Fn(SegmentField) -> Field, row: usize, message: String) -> SpecError {
        match self {
            Rows::Inline => SpecError::Rule {
                field: seg(SegmentField::Lift),
                reason: format!("row {row}: {message}"),
            },
            Rows::File { path, lines } => SpecError::PointsFile {
                path: path.to_string(),
                line: lines.get(row).copied(),
                message,
            },
        }
    }
}
