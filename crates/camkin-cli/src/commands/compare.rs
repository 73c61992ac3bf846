//! `camkin paper` and `camkin compare`: the paper's study, on its cams or on any mechanism.

use crate::args::{AngleWindow, NodeCounts, RevolutionStep};
use crate::draw::chart::{self, Chart, Series};
use crate::output::{write_atomic, write_cell_table, write_table, Cell, TableFormat};
use crate::study::{self, Study};
use crate::{load_mechanism, Failure};
use anyhow::{Context, Result};
use camkin::spec::LengthUnit;
use camkin::table::Units;
use serde_json::{json, Map, Value};
use std::path::{Path, PathBuf};

/// Format of the summary printed on stdout.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// a readable table (markdown)
    Table,
    /// comma-separated values
    Csv,
    /// one JSON object
    Json,
}

#[derive(Debug, clap::Args)]
pub struct PaperArgs {
    /// Directory for the CSV data, plots and summary.
    #[arg(long, value_name = "DIR", default_value = "camkin-paper")]
    pub out: PathBuf,
    /// Grid on which the errors are evaluated, degrees.
    #[arg(long, value_name = "DEG", default_value = "0.05")]
    pub step: RevolutionStep,
    /// Nodal points of the interpolation method, comma-separated.
    #[arg(long, value_name = "N1,N2,...", default_value = "100,1000,10000")]
    pub nodes: NodeCounts,
    /// Format of the summary on stdout.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
    #[command(flatten)]
    pub force: crate::out_dir::ForceArg,
}

#[derive(Debug, clap::Args)]
pub struct CompareArgs {
    /// Mechanism file (TOML).
    pub mechanism: PathBuf,
    /// Nodal points of the interpolation method, comma-separated.
    #[arg(long, value_name = "N1,N2,...", default_value = "100,1000,10000")]
    pub nodes: NodeCounts,
    /// Grid on which the errors are evaluated, degrees.
    #[arg(long, value_name = "DEG", default_value = "0.05")]
    pub step: RevolutionStep,
    /// Directory for CSV data and plots (none are written without it).
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Zoomed error plot over START:STOP degrees (with --out).
    #[arg(long, value_name = "START:STOP")]
    pub zoom: Option<AngleWindow>,
    /// Format of the summary on stdout.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
    #[command(flatten)]
    pub force: crate::out_dir::ForceArg,
}

/// Writes the study's CSV files and plots into `dir`.
fn write_files(
    study: &Study,
    dir: &Path,
    title: &str,
    u: &Units,
    zoom: Option<(f64, f64)>,
) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let mut written = Vec::new();
    let p = dir.join("displacement.csv");
    write_atomic(Some(&p), |w| {
        let columns: Vec<String> = ["position", "velocity", "acceleration", "jerk"]
            .iter()
            .enumerate()
            .map(|(k, n)| format!("{n}_{}", u.motion_key(k)))
            .collect();
        let columns = [vec!["angle_deg".to_string()], columns].concat();
        let rows: Vec<Vec<Cell>> = study
            .grid_deg
            .iter()
            .zip(&study.exact)
            .map(|(&angle_deg, s)| {
                let m = u.motion(s.position, s.velocity, s.acceleration, s.jerk);
                [vec![Cell::Num(Some(angle_deg))], m.map(Cell::Num).to_vec()].concat()
            })
            .collect();
        write_cell_table(w, TableFormat::Csv, &columns, rows)
    })?;
    written.push(p);
    let p = dir.join("acceleration.csv");
    write_atomic(Some(&p), |w| {
        // one column per node count: a record type cannot name them, so the csv crate's records
        let mut c = csv::Writer::from_writer(w);
        let key = u.motion_key(2);
        let mut head = vec!["angle_deg".to_string(), format!("contact_method_{key}")];
        head.extend(
            study
                .runs
                .iter()
                .map(|r| format!("interpolated_{}_{key}", r.nodes)),
        );
        c.write_record(&head)?;
        let acc = |a: f64| u.motion(0.0, 0.0, a, None)[2].unwrap_or(f64::NAN);
        for (k, (a, s)) in study.grid_deg.iter().zip(&study.exact).enumerate() {
            let mut rec = vec![*a, acc(s.acceleration)];
            rec.extend(study.runs.iter().map(|r| acc(r.acceleration[k])));
            c.serialize(&rec)?;
        }
        Ok(c.flush()?)
    })?;
    written.push(p);
    let p = dir.join("relative_error.csv");
    write_atomic(Some(&p), |w| {
        let mut c = csv::Writer::from_writer(w);
        let mut head = vec!["angle_deg".to_string()];
        head.extend(study.runs.iter().map(|r| format!("n_{}", r.nodes)));
        c.write_record(&head)?;
        for (k, a) in study.grid_deg.iter().enumerate() {
            let mut rec = vec![*a];
            rec.extend(study.runs.iter().map(|r| r.rel_error[k]));
            c.serialize(&rec)?;
        }
        Ok(c.flush()?)
    })?;
    written.push(p);

    let xy = |f: &dyn Fn(usize) -> f64| -> Vec<(f64, f64)> {
        study
            .grid_deg
            .iter()
            .enumerate()
            .map(|(k, &a)| (a, f(k)))
            .collect()
    };
    let displacement = Chart {
        title: format!("{title}: follower displacement"),
        x_label: "cam angle (°)".into(),
        y_label: format!("displacement ({})", u.motion_symbol(0)),
        series: vec![Series::line(
            "displacement",
            xy(&|k| u.coord_value(study.exact[k].position)),
        )],
        log_y: false,
        x_range: Some((0.0, 360.0)),
    };
    written.extend(chart::save(&displacement, &dir.join("displacement"))?);
    // the paper compares with 1000 nodal points; otherwise the N closest to it
    if let Some(r) = study.runs.iter().min_by_key(|r| r.nodes.abs_diff(1000)) {
        let acc = Chart {
            title: format!(
                "{title}: acceleration, contact method and interpolation (N = {})",
                r.nodes
            ),
            x_label: "cam angle (°)".into(),
            y_label: format!("acceleration ({})", u.motion_symbol(2)),
            series: vec![
                Series::line(
                    "contact method (exact)",
                    xy(&|k| u.coord_value(study.exact[k].acceleration)),
                ),
                Series::dashed(
                    format!("interpolated, N = {}", r.nodes),
                    xy(&|k| u.coord_value(r.acceleration[k])),
                ),
            ],
            log_y: false,
            x_range: Some((0.0, 360.0)),
        };
        written.extend(chart::save(&acc, &dir.join("acceleration"))?);
    }
    let mut err = Chart {
        title: format!("{title}: relative error of the interpolated acceleration"),
        x_label: "cam angle (°)".into(),
        y_label: "|a_N − a| / max|a|".into(),
        series: study
            .runs
            .iter()
            .map(|r| Series::line(format!("N = {}", r.nodes), xy(&|k| r.rel_error[k])))
            .collect(),
        log_y: true,
        x_range: Some((0.0, 360.0)),
    };
    written.extend(chart::save(&err, &dir.join("relative_error"))?);
    if let Some((a, b)) = zoom {
        err.title = format!("{title}: relative error, {a}°–{b}°");
        err.x_range = Some((a, b));
        written.extend(chart::save(&err, &dir.join("relative_error_zoom"))?);
    }
    Ok(written)
}

fn fmt_time(s: f64) -> String {
    if s < 1e-6 {
        format!("{:.0} ns", s * 1e9)
    } else if s < 1e-3 {
        format!("{:.1} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.2} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

/// The summary as a markdown section.
fn table(study: &Study, title: &str, u: &Units) -> String {
    let acc_unit = u.motion_symbol(2);
    let mut t = format!("## {title}\n\n");
    t += &format!(
        "Contact method: max |a| = {} {acc_unit} over the revolution; {} angles at {}° in {} ({} per angle); one cold query {}.\n\n",
        camkin::human::human(u.coord_value(study.max_abs_acceleration)),
        study.grid_deg.len(),
        study.grid_deg.get(1).copied().unwrap_or(360.0),
        fmt_time(study.contact_total_seconds),
        fmt_time(study.contact_total_seconds / study.grid_deg.len() as f64),
        fmt_time(study.contact_single_seconds),
    );
    let c = &study.check;
    t += &format!(
        "Independent check (support function of the cam, finite differences in θ) at {} angles: position {:.1e} of the cam's size, velocity {:.1e} and acceleration {:.1e} of their peaks{}\n",
        c.angles,
        c.position,
        c.velocity,
        c.acceleration,
        if c.skipped > 0 { format!(" ({} angles next to contact jumps skipped)", c.skipped) } else { String::new() }
    );
    t += "\n| N | max relative error | mean relative error | whole study | one angle | one angle vs contact method |\n|---:|---:|---:|---:|---:|---:|\n";
    for r in &study.runs {
        t += &format!(
            "| {} | {:.3e} | {:.3e} | {} | {} | {:.0}× |\n",
            r.nodes,
            r.max_rel_error,
            r.mean_rel_error,
            fmt_time(r.total_seconds),
            fmt_time(r.single_seconds),
            r.single_seconds / study.contact_single_seconds
        );
    }
    t
}

fn summary_rows(study: &Study, cam: &str) -> Vec<SummaryRow> {
    study
        .runs
        .iter()
        .map(|r| SummaryRow {
            cam: cam.to_string(),
            nodes: r.nodes,
            max_rel_error: r.max_rel_error,
            mean_rel_error: r.mean_rel_error,
            interp_total_s: r.total_seconds,
            interp_single_s: r.single_seconds,
            contact_total_s: study.contact_total_seconds,
            contact_single_s: study.contact_single_seconds,
        })
        .collect()
}

/// One node count of the study (the summary with `--format csv`).
#[derive(Debug, serde::Serialize)]
struct SummaryRow {
    /// the cam (`original`, `revised`, or the file's name)
    cam: String,
    /// nodal points per revolution
    nodes: usize,
    /// largest |a_N − a| / max|a|
    max_rel_error: f64,
    /// its mean over the grid
    mean_rel_error: f64,
    /// the interpolation method: set-up and all evaluations, s
    interp_total_s: f64,
    /// one evaluation, s
    interp_single_s: f64,
    /// the contact method over the grid, s
    contact_total_s: f64,
    /// one evaluation, s
    contact_single_s: f64,
}

/// The summary as JSON: `max_rel_error` and `mean_rel_error` map every N (as a string) to its value.
fn json_summary(study: &Study) -> Value {
    let by_n = |f: &dyn Fn(&study::NodeRun) -> f64| -> Value {
        let mut m = Map::new();
        for r in &study.runs {
            m.insert(r.nodes.to_string(), json!(f(r)));
        }
        Value::Object(m)
    };
    json!({
        "nodes": study.runs.iter().map(|r| r.nodes).collect::<Vec<_>>(),
        "step_deg": study.grid_deg.get(1).copied().unwrap_or(360.0),
        "angles": study.grid_deg.len(),
        "max_abs_acceleration": study.max_abs_acceleration,
        "max_rel_error": by_n(&|r| r.max_rel_error),
        "mean_rel_error": by_n(&|r| r.mean_rel_error),
        "interp_total_seconds": by_n(&|r| r.total_seconds),
        "interp_single_seconds": by_n(&|r| r.single_seconds),
        "contact_total_seconds": study.contact_total_seconds,
        "contact_single_seconds": study.contact_single_seconds,
        "independent_check": check_json(&study.check),
    })
}

pub fn run_paper(args: &PaperArgs) -> Result<(), Failure> {
    let (nodes, step) = (&args.nodes.0, args.step.deg());
    study::check_bounds(nodes, step, 2, true, args.work.large).map_err(Failure::Input)?;
    let od = crate::out_dir::OutDir::begin(&args.out, args.force.force)?;
    let mut md =
        String::from("# The paper's study: contact method against interpolated displacement\n\n");
    let mut csv = Vec::new();
    let mut js = Map::new();
    for (key, revised, title) in [
        ("original", false, "Original cam"),
        ("revised", true, "Revised cam"),
    ] {
        let mech = camkin::reference::paper_mechanism(revised);
        let study = study::run(&mech, nodes, step, title).map_err(Failure::Internal)?;
        let zoom = if revised { Some((5.0, 10.0)) } else { None };
        let u = Units::plain(&mech, LengthUnit::Cm);
        write_files(&study, &od.path().join(key), title, &u, zoom).map_err(Failure::output)?;
        md += &table(&study, title, &u);
        md.push('\n');
        csv.extend(summary_rows(&study, key));
        js.insert(key.to_string(), json_summary(&study));
    }
    write_atomic(Some(&od.path().join("summary.md")), |w| {
        Ok(w.write_all(md.as_bytes())?)
    })
    .map_err(Failure::output)?;
    od.commit().map_err(Failure::output)?;
    print_summary(args.format, &md, &csv, &Value::Object(js))?;
    crate::say!("camkin: wrote {}", args.out.display());
    Ok(())
}

pub fn run_compare(args: &CompareArgs) -> Result<(), Failure> {
    let (nodes, step) = (&args.nodes.0, args.step.deg());
    study::check_bounds(nodes, step, 1, args.out.is_some(), args.work.large)
        .map_err(Failure::Input)?;
    let zoom = args.zoom.map(|w| (w.start, w.stop));
    let loaded = load_mechanism(Some(&args.mechanism))?;
    let mech = loaded.mech;
    let u = Units::plain(&mech, loaded.unit);
    let title = args
        .mechanism
        .file_stem()
        .map(|s| s.to_string_lossy().to_string())
        .unwrap_or_else(|| "mechanism".into());
    // the grid, and every interpolation node twice (built twice, for its timing)
    let grid = (360.0 / step).round() as usize;
    crate::check_sweep_time(
        &mech,
        grid + 2 * nodes.iter().sum::<usize>(),
        1,
        args.work.large,
    )?;
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let study = study::run(&mech, nodes, step, &title).map_err(Failure::Input)?;
    if let Some(od) = &od {
        write_files(&study, od.path(), &title, &u, zoom).map_err(Failure::output)?;
    }
    let md = table(&study, &title, &u);
    let csv = summary_rows(&study, &title);
    let mut js = json_summary(&study);
    if let Value::Object(m) = &mut js {
        m.insert(
            "mechanism".into(),
            json!(args.mechanism.display().to_string()),
        );
    }
    if let Some(od) = od {
        write_atomic(Some(&od.path().join("summary.md")), |w| {
            Ok(w.write_all(md.as_bytes())?)
        })
        .map_err(Failure::output)?;
        od.commit().map_err(Failure::output)?;
    }
    print_summary(args.format, &md, &csv, &js)
}

fn print_summary(format: Format, md: &str, csv: &[SummaryRow], js: &Value) -> Result<(), Failure> {
    write_atomic(None, |w| match format {
        Format::Table => Ok(w.write_all(md.as_bytes())?),
        Format::Csv => write_table(w, csv, TableFormat::Csv),
        Format::Json => Ok(writeln!(w, "{js}")?),
    })
    .map_err(Failure::Internal)
}

/// The independent check as JSON (relative differences; see [`camkin::cam::IndependentCheck`]).
pub fn check_json(c: &camkin::cam::IndependentCheck) -> Value {
    json!({
        "angles": c.angles,
        "skipped": c.skipped,
        "position": c.position,
        "velocity": c.velocity,
        "acceleration": c.acceleration,
    })
}
