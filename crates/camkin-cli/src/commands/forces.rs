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
use camkin::lubrication::{
    plausible_friction, roughness_from_um, FilmFormula, Friction, Lubricant, LubricantError,
    SurfaceProperties, FRICTION_RULE, ROUGHNESS_RULE,
};
use camkin::report::{
    rpm, ForceField, ForceReport, ForceRequest, LubricationRequest, Materials, ReportError,
};
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

/// A lubricant as a flag: a preset or `eta=<Pa·s>:alpha=<1/Pa>` (the library's reader).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OilArg(pub Lubricant);

impl FromStr for OilArg {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        s.parse()
            .map(Self)
            .map_err(|e: LubricantError| e.to_string())
    }
}

/// The two surfaces' RMS roughness, `CAM,FOLLOWER` in µm, each above 0 and at most 100 µm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoughnessArg(pub [f64; 2]);

impl FromStr for RoughnessArg {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let (a, b) = s
            .split_once(',')
            .ok_or_else(|| format!("{s:?}: CAM,FOLLOWER in µm is needed, e.g. 0.2,0.3"))?;
        let one = |t: &str| -> Result<f64, String> {
            let t = t.trim();
            let v: f64 = t
                .parse()
                .map_err(|_| format!("{t:?} is not a number (µm)"))?;
            roughness_from_um(v).ok_or_else(|| format!("{t} µm {ROUGHNESS_RULE}"))
        };
        Ok(Self([one(a)?, one(b)?]))
    }
}

/// The friction model as a flag: `MU` throughout, or `BOUNDARY:FULL` (boundary at λ ≤ 1, full
/// film at λ ≥ 3, linear between), each from 0 to 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionArg(pub Friction);

impl FromStr for FrictionArg {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let one = |t: &str| -> Result<f64, String> {
            let t = t.trim();
            match t.parse::<f64>() {
                Ok(v) if plausible_friction(v) => Ok(v),
                Ok(_) => Err(format!("{t} {FRICTION_RULE}")),
                Err(_) => Err(format!("{t:?} is not a number")),
            }
        };
        Ok(Self(match s.split_once(':') {
            None => Friction::Constant(one(s)?),
            Some((b, f)) => Friction::Mixed {
                boundary: one(b)?,
                full_film: one(f)?,
            },
        }))
    }
}

/// The film formula as a flag.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmArg(pub FilmFormula);

impl FromStr for FilmArg {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        FilmFormula::ALL
            .into_iter()
            .find(|f| f.name() == s.trim())
            .map(Self)
            .ok_or_else(|| {
                format!(
                    "{s:?} is not a film formula: {}",
                    FilmFormula::ALL.map(FilmFormula::name).join(" or ")
                )
            })
    }
}

#[derive(Debug, clap::Args)]
pub struct ForcesArgs {
    /// Mechanism file (TOML) with a `[dynamics]` section, or a system file (`[[body]]`, …) with
    /// one: its simulation's contact forces, Hertz pressures, drivers' torques and impacts over
    /// a revolution of its first driver (see docs/systems.md, "Dynamics of a system").
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
    /// aisi-4140, aisi-1045, stainless-440c, ductile-iron, cast-iron, bronze) or `E=<Pa>:nu=<ν>`
    /// (with `:k=<W/(m·K)>:rho=<kg/m³>:c=<J/(kg·K)>` for the flash temperature) [default: the
    /// file's `[lubrication]` materials, or steel,steel].
    #[arg(long, value_name = "CAM,FOLLOWER")]
    pub materials: Option<MaterialsArg>,
    /// Allowable contact stress, MPa: exit 3 when the stress exceeds it.
    #[arg(long, value_name = "MPA", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub allowable: Option<f64>,
    /// Lubricant at the contact's inlet temperature, for the film thickness, λ, the flash
    /// temperature and the friction (with --face-width and --roughness): a preset (sae-20@100c …
    /// sae-50@100c, iso-vg-32@40c … iso-vg-320@40c) or `eta=<Pa·s>:alpha=<1/Pa>` [default: the
    /// file's `[lubrication]`, whose values each of these flags replaces].
    #[arg(long, value_name = "OIL")]
    pub oil: Option<OilArg>,
    /// RMS roughness Rq of the cam's and the follower's surfaces, µm (with --oil).
    #[arg(long, value_name = "CAM,FOLLOWER")]
    pub roughness: Option<RoughnessArg>,
    /// EHL film formula of a line contact: dowson-higginson or hamrock (Pan and Hamrock's)
    /// [default: the file's, or dowson-higginson].
    #[arg(long, value_name = "FORMULA")]
    pub film: Option<FilmArg>,
    /// Friction coefficient: `MU` throughout, or `BOUNDARY:FULL` (boundary lubrication at
    /// λ ≤ 1, a full film at λ ≥ 3, linear in λ between) [default: the file's, or 0.1:0.03].
    #[arg(long, value_name = "MU")]
    pub friction: Option<FrictionArg>,
    /// Torque on a gear pair's driver, N·m: the loads along the whole path of contact (the
    /// normal force shared between the pairs in contact, Hertz with --face-width, the specific
    /// sliding, and with --oil the film and flash temperature); no `[dynamics]` needed.
    #[arg(long, value_name = "N_M", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub torque: Option<f64>,
    /// Power a gear pair's driver transmits, kW (instead of --torque: the torque is P/ω at the
    /// file's speed).
    #[arg(long, value_name = "KW", value_parser = crate::args::real, allow_negative_numbers = true, conflicts_with = "torque")]
    pub power: Option<f64>,
    /// Directory for forces.csv, force_speed.csv and their plots (and lubrication.csv and its
    /// page with --oil; gear_loads.csv with --torque).
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
        ForceField::Viscosity | ForceField::PressureViscosity => "--oil",
        ForceField::Roughness => "--roughness",
        ForceField::Thermal => "--materials",
        ForceField::Friction => "--friction",
        _ => "an option",
    }
}

fn input_error(e: ReportError) -> Failure {
    Failure::Input(match e.field() {
        Some(field) => anyhow!("{}: {e}", flag(field)),
        None => anyhow!(e),
    })
}

/// The lubrication the flags and the file's `[lubrication]` ask for, each flag replacing the
/// file's value: `None` without an oil in either; --roughness needed with an oil, and none of
/// --roughness, --film, --friction without one.
pub(super) fn lubrication_request(
    args: &ForcesArgs,
    file: Option<&camkin::spec::BuiltLubrication>,
    materials: &Materials,
) -> Result<Option<LubricationRequest>, Failure> {
    let from_file = file.map(|f| f.request);
    let Some(lubricant) = args.oil.map(|o| o.0).or(from_file.map(|f| f.lubricant)) else {
        let stray = [
            (args.roughness.is_some(), "--roughness"),
            (args.film.is_some(), "--film"),
            (args.friction.is_some(), "--friction"),
        ];
        if let Some((_, flag)) = stray.iter().find(|s| s.0) {
            return Err(Failure::Input(anyhow!(
                "{flag}: this is for the lubrication; give the lubricant with --oil (e.g. --oil sae-30@100c) or a [lubrication] section"
            )));
        }
        return Ok(None);
    };
    let rq = match (args.roughness, from_file) {
        (Some(RoughnessArg(rq)), _) => rq,
        (None, Some(f)) => f.surfaces.map(|s| s.roughness),
        (None, None) => {
            return Err(Failure::Input(anyhow!(
                "--oil: λ needs each surface's RMS roughness: give --roughness CAM,FOLLOWER in µm (e.g. --roughness 0.2,0.3)"
            )))
        }
    };
    let thermal = [materials.cam.thermal, materials.follower.thermal];
    Ok(Some(LubricationRequest {
        lubricant,
        formula: args
            .film
            .map(|f| f.0)
            .or(from_file.map(|f| f.formula))
            .unwrap_or_default(),
        surfaces: [0, 1].map(|i| SurfaceProperties {
            roughness: rq[i],
            thermal: thermal[i],
        }),
        friction: args
            .friction
            .map(|f| f.0)
            .or(from_file.map(|f| f.friction))
            .unwrap_or(camkin::spec::DEFAULT_FRICTION),
    }))
}

pub fn run(args: &ForcesArgs) -> Result<(), Failure> {
    // a system file ([[body]], …, [dynamics]): its simulation's forces
    let (name, text) =
        crate::mechfile::read_text(&args.mechanism).map_err(|e| Failure::Input(anyhow!(e)))?;
    if camkin::spec::text::is_system(&text) {
        return super::system_forces::run(args, &name, &text);
    }
    // a gear pair's loads: asked for by a flag, or by the file's [gear_loads]
    let file_loads =
        crate::mechfile::parse_spec(&text, &name).is_ok_and(|s| s.gear_loads.is_some());
    if args.torque.is_some() || args.power.is_some() || file_loads {
        return super::gear_loads::run(args, &name);
    }
    let (mech, params, unit, file) =
        mechfile::load_forces(&args.mechanism).map_err(|e| Failure::Input(anyhow!(e)))?;
    // the folder is checked before any work (a file in its place, an input in it, someone
    // else's files)
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    // the file's [lubrication] gives what the flags leave out
    let materials = match (&args.materials, &file) {
        (Some(m), _) => m.0.clone(),
        (None, Some(f)) => f.materials.clone(),
        (None, None) => Materials::default(),
    };
    let lubrication = lubrication_request(args, file.as_ref(), &materials)?;
    let face_width = args
        .face_width
        .or_else(|| file.as_ref().map(|f| f.face_width));
    let req = ForceRequest {
        step_deg: args.step.deg(),
        margin: args.margin,
        target_rpm: args.target_rpm,
        face_width,
        materials,
        allowable_mpa: args.allowable,
        unit,
        force_speed: true,
        lubrication,
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
    if let Some(l) = &r.lubrication {
        let (columns, rows) = l.table();
        write_atomic(Some(&dir.join("lubrication.csv")), |w| {
            write_cell_table(w, TableFormat::Csv, &columns, rows)
        })?;
        crate::draw::lubrication::save(l, &dir.join("lubrication"))?;
    }
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
    // the contact stress over the angle (with a face width)
    if r.hertz.is_some() {
        let stress = |k: usize, name: &str, dashed| Series {
            name: name.into(),
            points: r
                .states
                .iter()
                .zip(&r.stress_mpa)
                .map(|(s, p)| (s.cam_angle.to_degrees(), p[k].unwrap_or(f64::NAN)))
                .collect(),
            dashed,
        };
        chart::save(
            &by_angle(
                "Hertz contact stress under permanent contact",
                "contact stress (MPa)".into(),
                if r.closed {
                    vec![
                        stress(0, "follower's own curve", false),
                        stress(1, "second curve", true),
                    ]
                } else {
                    vec![stress(0, "contact stress", false)]
                },
            ),
            &dir.join("contact_stress"),
        )?;
    }
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
    // the operating speed and the jump speed, marked
    let mut series = series;
    let (lo, hi) = series
        .iter()
        .flat_map(|c| c.points.iter().map(|p| p.1))
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if lo.is_finite() {
        let mark = |x: f64, name: String| Series {
            name,
            points: vec![(x, lo), (x, hi)],
            dashed: true,
        };
        series.push(mark(
            rpm(r.speed),
            format!("operating speed {} rpm", num(rpm(r.speed))),
        ));
        if r.jump.speed.is_finite() && r.jump.speed > 0.0 && rpm(r.jump.speed) <= top {
            let what = if r.closed {
                "second curve loaded from"
            } else {
                "jump speed"
            };
            series.push(mark(
                rpm(r.jump.speed),
                format!("{what} {} rpm", num(rpm(r.jump.speed))),
            ));
        }
    }
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
