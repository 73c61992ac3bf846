//! The flags of `camkin forces` and the requests they make: the materials, oil, roughness,
//! friction and film formula as flags (each read by the library's reader), the command's
//! arguments, and the lubrication request the flags and the file's `[lubrication]` give.

use crate::args::RevolutionStep;
use crate::Failure;
use anyhow::anyhow;
use camkin::lubrication::{
    plausible_friction, roughness_from_um, FilmFormula, Friction, Lubricant, LubricantError,
    SurfaceProperties, FRICTION_RULE, ROUGHNESS_RULE,
};
use camkin::report::{ForceField, LubricationRequest, Materials, ReportError};
use std::path::PathBuf;
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
pub fn flag(field: ForceField) -> &'static str {
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

pub fn input_error(e: ReportError) -> Failure {
    Failure::Input(match e.field() {
        Some(field) => anyhow!("{}: {e}", flag(field)),
        None => anyhow!(e),
    })
}

/// The lubrication the flags and the file's `[lubrication]` ask for, each flag replacing the
/// file's value: `None` without an oil in either; --roughness needed with an oil, and none of
/// --roughness, --film, --friction without one.
pub fn lubrication_request(
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
