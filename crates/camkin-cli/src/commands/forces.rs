//! `camkin forces`: with a `[dynamics]` section, the contact force and the camshaft torque over a
//! revolution under permanent contact, the speed at which the follower leaves the cam, the
//! spring that keeps it on up to a target speed, and the Hertz contact stress.

use crate::args::RevolutionStep;
use crate::draw::chart::{self, Chart, Series};
use crate::forces_text::{self, num, LengthUnit};
use crate::mechfile;
use crate::output::{write_atomic, write_cell_table, TableFormat};
use crate::Failure;
use anyhow::anyhow;
use camkin::report::{rpm, ForceField, ForceReport, ForceRequest, Materials, ReportError};
use std::path::{Path, PathBuf};
use std::str::FromStr;

/// The cam's and follower's materials as a flag: `CAM,FOLLOWER` (the library's reader).
#[derive(Debug, Clone, PartialEq)]
pub struct MaterialsArg(pub Materials);

impl FromStr for MaterialsArg {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        s.parse()
            .map(Self)
            .map_err(|e: camkin::report::MaterialError| e.to_string())
    }
}

#[derive(Debug, clap::Args)]
pub struct ForcesArgs {
    /// Mechanism file (TOML) with a `[dynamics]` section, or a system file (`[[body]]`, …) with
    /// one: its simulation's contact forces, Hertz pressures, drivers' torques and impacts over
    /// a revolution of its first driver (see the README's "Dynamics of a system").
    pub mechanism: PathBuf,
    /// Cam-angle step, degrees.
    #[arg(long, value_name = "DEG", default_value = "0.5")]
    pub step: RevolutionStep,
    /// The contact force that must remain, N.
    #[arg(
        long,
        value_name = "N",
        default_value_t = 0.0,
        value_parser = crate::args::real,
        allow_negative_numbers = true
    )]
    pub margin: f64,
    /// The speed up to which the follower must stay on the cam, rpm [default: the file's].
    #[arg(long, value_name = "RPM", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub target_rpm: Option<f64>,
    /// Face width of the contact, in the file's length unit: the Hertz contact stress.
    #[arg(long, value_name = "LENGTH", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub face_width: Option<f64>,
    /// Cam and follower materials for the contact stress: presets (steel, aisi-52100,
    /// aisi-4140, aisi-1045, stainless-440c, ductile-iron, cast-iron, bronze) or `E=<Pa>:nu=<ν>`.
    #[arg(long, value_name = "CAM,FOLLOWER", default_value = "steel,steel")]
    pub materials: MaterialsArg,
    /// Allowable contact stress, MPa: exit 3 when the stress exceeds it.
    #[arg(long, value_name = "MPA", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub allowable: Option<f64>,
    /// Directory for forces.csv, force_speed.csv and their plots.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    #[command(flatten)]
    pub force: crate::out_dir::ForceArg,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
}

/// The flag that sets a field of the request.
fn flag(field: ForceField) -> &'static str {
    match field {
        ForceField::Step => "--step",
        ForceField::Margin => "--margin",
        ForceField::TargetRpm => "--target-rpm",
        ForceField::FaceWidth => "--face-width",
        ForceField::Materials => "--materials",
        ForceField::Allowable => "--allowable",
        _ => "an option",
    }
}

fn input_error(e: ReportError) -> Failure {
    Failure::Input(match e.field() {
        Some(field) => anyhow!("{}: {e}", flag(field)),
        None => anyhow!(e),
    })
}

pub fn run(args: &ForcesArgs) -> Result<(), Failure> {
    // a system file ([[body]], …, [dynamics]): its simulation's forces
    let (name, text) =
        crate::mechfile::read_text(&args.mechanism).map_err(|e| Failure::Input(anyhow!(e)))?;
    if camkin::spec::text::is_system(&text) {
        return super::system_forces::run(args, &name, &text);
    }
    let (mech, params, unit) =
        mechfile::load_dynamics(&args.mechanism).map_err(|e| Failure::Input(anyhow!(e)))?;
    // the folder is checked before any work (a file in its place, an input in it, someone
    // else's files)
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let req = ForceRequest {
        step_deg: args.step.deg(),
        margin: args.margin,
        target_rpm: args.target_rpm,
        face_width: args.face_width,
        materials: args.materials.0.clone(),
        allowable_mpa: args.allowable,
        unit,
        force_speed: true,
        lubrication: None,
    };
    req.validate(&mech).map_err(input_error)?;
    if let Some(refusal) = req.work(&mech).refusal().filter(|_| !args.work.large) {
        return Err(Failure::Input(anyhow!(
            "{refusal}; use a coarser --step, or pass --large to run it anyway"
        )));
    }
    let report = ForceReport::new(&mech, params, &req).map_err(input_error)?;
    let lu = LengthUnit {
        name: unit.name(),
        metres: unit.metres(),
    };
    crate::out!(
        "{}",
        forces_text::summary(&report, &args.mechanism.display().to_string(), lu)
    )?;
    if let Some(od) = od {
        write_files(od.path(), &report).map_err(Failure::output)?;
        let dir = od.commit().map_err(Failure::output)?;
        crate::say!("camkin: wrote {}", dir.display());
    }
    match forces_text::failures(&report) {
        None => Ok(()),
        Some(f) => Err(Failure::Check(anyhow!(f))),
    }
}

fn write_files(dir: &Path, r: &ForceReport) -> anyhow::Result<()> {
    let (columns, rows) = r.table();
    write_atomic(Some(&dir.join("forces.csv")), |w| {
        write_cell_table(w, TableFormat::Csv, &columns, rows)
    })?;
    let (columns, rows) = r.force_speed_table();
    write_atomic(Some(&dir.join("force_speed.csv")), |w| {
        write_cell_table(w, TableFormat::Csv, &columns, rows)
    })?;
    let (_, _, tu) = r.units();
    let series = |name: &str, dashed, y: fn(&camkin::dynamics::ForceState) -> f64| Series {
        name: name.into(),
        points: r
            .states
            .iter()
            .map(|s| (s.cam_angle.to_degrees(), y(s)))
            .collect(),
        dashed,
    };
    let by_angle = |title: &str, y_label: String, series| Chart {
        title: title.into(),
        x_label: "cam angle (°)".into(),
        y_label,
        series,
        log_y: false,
        x_range: Some((0.0, 360.0)),
    };
    chart::save(
        &by_angle(
            "contact force under permanent contact",
            "contact force (N)".into(),
            if r.closed {
                vec![
                    series("follower's own curve", false, |s| s.contact_force),
                    series(
                        "second curve",
                        true,
                        camkin::dynamics::ForceState::second_force,
                    ),
                ]
            } else {
                vec![series("contact force", false, |s| s.contact_force)]
            },
        ),
        &dir.join("contact_force"),
    )?;
    chart::save(
        &by_angle(
            "camshaft torque",
            format!("torque ({tu})"),
            vec![series("camshaft torque", false, |s| s.camshaft_torque)],
        ),
        &dir.join("camshaft_torque"),
    )?;
    let curve = |k: usize, name: &str, dashed| Series {
        name: name.into(),
        points: r.force_speed.iter().map(|(w, f)| (rpm(*w), f[k])).collect(),
        dashed,
    };
    let top = r.force_speed.last().map_or(0.0, |p| rpm(p.0));
    let (title, y_label, series) = if r.closed {
        (
            "largest contact force on each curve over a revolution".to_string(),
            "largest contact force (N)",
            vec![
                curve(0, "largest force on the follower's own curve", false),
                curve(1, "largest force on the second curve", true),
            ],
        )
    } else {
        (
            format!(
                "smallest contact force over a revolution (margin {} N)",
                num(r.margin)
            ),
            "smallest contact force (N)",
            vec![
                curve(0, "smallest contact force", false),
                Series {
                    name: "margin".into(),
                    points: vec![(0.0, r.margin), (top, r.margin)],
                    dashed: true,
                },
            ],
        )
    };
    chart::save(
        &Chart {
            title,
            x_label: "cam speed (rpm)".into(),
            y_label: y_label.into(),
            series,
            log_y: false,
            x_range: None,
        },
        &dir.join("force_speed"),
    )?;
    Ok(())
}
