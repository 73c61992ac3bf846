//! `camkin synth`: the profile of a `kind = "motion"` cam as points, DXF and SVG; the program's
//! SVAJ curves; design checks; the round-trip error of the contact method.

use crate::args::RevolutionStep;
use crate::draw::svaj;
use crate::output::write_atomic;
use crate::{load_mechanism, Failure};
use anyhow::anyhow;
use camkin::report::DesignReport;
use camkin::table::Units;
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub struct SynthArgs {
    /// Mechanism file whose profile is `kind = "motion"`.
    pub mechanism: PathBuf,
    /// Directory for the profile (CSV, DXF, SVG), the SVAJ plot and the checks.
    #[arg(long, value_name = "DIR", default_value = "camkin-synth")]
    pub out: PathBuf,
    /// Cam-angle step of the profile points and the checks, degrees.
    #[arg(long, value_name = "DEG", default_value = "0.5")]
    pub step: RevolutionStep,
    /// Largest acceptable pressure angle, degrees.
    #[arg(long, value_name = "DEG", default_value_t = 30.0, value_parser = crate::args::real, allow_negative_numbers = true)]
    pub pressure_limit: f64,
    #[command(flatten)]
    pub units: crate::args::MotionUnitArgs,
    /// Radius of the cutter or grinding wheel whose centre path to write (cutter.csv and a
    /// layer of profile.dxf), in the file's length unit.
    #[arg(long, value_name = "R", value_parser = crate::args::real, allow_negative_numbers = true)]
    pub tool_radius: Option<f64>,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
    #[command(flatten)]
    pub force: crate::out_dir::ForceArg,
}

/// Bytes written per profile point, about (CSV, DXF, SVG and the four SVAJ SVGs; measured:
/// 5.9 MB for 36 000 points).
const BYTES_PER_POINT: f64 = 165.0;

/// The profile drawn to scale: the SVG's user unit is the file's length unit and its size is
/// given in that unit (a metre file in centimetres, 100 to the metre), y up, with the cam's
/// centre marked, the 0° reference line along +x, a scale bar and the unit written.
fn svg_profile(pts: &[(f64, f64)], unit: &str) -> String {
    let (mut x0, mut x1, mut y0, mut y1) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for &(x, y) in pts {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    let size = (x1 - x0).max(y1 - y0);
    let pad = 0.12 * size;
    let (w, h) = (x1 - x0 + 2.0 * pad, y1 - y0 + 2.0 * pad);
    // SVG knows mm, cm and in; a metre is 100 cm
    let (svg_unit, per) = match unit {
        "m" => ("cm", 100.0),
        u @ ("mm" | "cm" | "in") => (u, 1.0),
        _ => ("mm", 1.0),
    };
    let stroke = 0.004 * size;
    // the scale bar: the largest 1, 2 or 5 times a power of ten within a fifth of the drawing
    let bar = crate::draw::scale_bar(size);
    let text = 0.035 * size;
    let pts: Vec<String> = pts.iter().map(|(x, y)| format!("{x:.6},{y:.6}")).collect();
    let (bx, by) = (x0, y0 - 0.6 * pad);
    format!(
        concat!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w_out}{su}\" height=\"{h_out}{su}\" viewBox=\"{vx} {vy} {w} {h}\">\n",
            "<title>cam profile, lengths in {unit} (1 user unit = 1 {unit}), y up</title>\n",
            "<rect x=\"{vx}\" y=\"{vy}\" width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n",
            "<g transform=\"scale(1,-1)\" fill=\"none\" stroke-width=\"{sw}\">\n",
            "<polygon points=\"{pts}\" stroke=\"rgb(31,119,180)\"/>\n",
            "<path d=\"M {cm0} 0 H {cm1} M 0 {cm0} V {cm1}\" stroke=\"black\"/>\n",
            "<path d=\"M 0 0 H {reach}\" stroke=\"gray\" stroke-dasharray=\"{dash} {dash}\"/>\n",
            "<path d=\"M {bx} {by} H {bx2}\" stroke=\"black\" stroke-width=\"{sw2}\"/>\n",
            "</g>\n",
            "<text x=\"{reach}\" y=\"{t0}\" font-size=\"{ts}\" font-family=\"sans-serif\">0°</text>\n",
            "<text x=\"{bx}\" y=\"{tby}\" font-size=\"{ts}\" font-family=\"sans-serif\">{bar} {unit}</text>\n",
            "</svg>\n"
        ),
        w_out = w * per,
        h_out = h * per,
        su = svg_unit,
        vx = x0 - pad,
        vy = -(y1 + pad),
        w = w,
        h = h,
        unit = unit,
        sw = stroke,
        sw2 = 3.0 * stroke,
        pts = pts.join(" "),
        cm0 = -0.05 * size,
        cm1 = 0.05 * size,
        reach = x1 + 0.5 * pad,
        dash = 4.0 * stroke,
        t0 = -0.3 * text,
        ts = text,
        bx = bx,
        by = by,
        bx2 = bx + bar,
        tby = -by - 0.6 * text,
        bar = camkin::human::human(bar),
    )
}

pub fn run(args: &SynthArgs) -> Result<(), Failure> {
    let step = args.step.deg();
    if !(args.pressure_limit.is_finite() && args.pressure_limit > 0.0 && args.pressure_limit < 90.0)
    {
        return Err(Failure::Input(anyhow!(
            "--pressure-limit: {} must be in (0, 90) degrees",
            camkin::human::human(args.pressure_limit)
        )));
    }
    let points = (360.0 / step).round();
    let loaded = load_mechanism(Some(&args.mechanism))?;
    let mech = &loaded.mech;
    let u = Units::new(
        mech,
        loaded.unit,
        args.units.angle_unit_for(mech)?,
        args.units.per,
    );
    // the files written
    crate::refuse_large(
        &camkin::work::Work::sweep(mech, points as usize, 1).with_bytes(points * BYTES_PER_POINT),
        args.work.large,
        ", or use a coarser --step",
    )?;
    let profile = mech.cam().profile();
    let Some(synth) = mech.cam().synthesis() else {
        return Err(Failure::Input(anyhow!(
            "{}: the profile is not kind = \"motion\"; synth needs a motion program",
            args.mechanism.display()
        )));
    };
    let od = crate::out_dir::OutDir::begin(&args.out, args.force.force)?;
    let n = (360.0 / step).round() as usize;
    let grid = camkin::table::AngleGrid::new(0.0, step);
    let thetas: Vec<f64> = (0..n).map(|k| grid.at(k).to_radians()).collect();
    let pts: Vec<(f64, f64)> = thetas
        .iter()
        .map(|&t| profile.position(t))
        .map(|p| (p.x, p.y))
        .collect();
    let out = |name: &str| od.path().join(name);
    let made = crate::manufacture::write(
        mech,
        loaded.unit,
        od.path(),
        &crate::manufacture::Options {
            step_deg: step,
            tool_radius: args.tool_radius,
            tolerance: None,
        },
    )
    .map_err(|e| match e {
        crate::manufacture::Error::Input(e) => Failure::Input(e),
        crate::manufacture::Error::Output(e) => Failure::output(e),
    })?;
    write_atomic(Some(&out("profile.svg")), |w| {
        Ok(w.write_all(svg_profile(&pts, loaded.unit.name()).as_bytes())?)
    })
    .map_err(Failure::output)?;

    // the program's SVAJ page: lift is the program itself (zero on the base circle)
    let (w, al) = (mech.cam().speed(), mech.cam().angular_acceleration());
    let deg: Vec<f64> = thetas.iter().map(|t| t.to_degrees()).collect();
    let prog: Vec<[Option<f64>; 4]> = thetas
        .iter()
        .map(|&t| {
            let p = synth.program_derivatives(t);
            // time derivatives at the cam's speed (and constant angular acceleration)
            u.motion(
                p[0],
                w * p[1],
                w * w * p[2] + al * p[1],
                Some(w * w * w * p[3] + 3.0 * w * al * p[2]),
            )
        })
        .collect();
    let names = ["lift", "velocity", "acceleration", "jerk"];
    let page = svaj::Page {
        title: crate::commands::plot::svaj_title(&loaded, &u)
            .replace(": SVAJ,", ": SVAJ of the motion program,"),
        panels: (0..4)
            .map(|k| svaj::Panel {
                label: format!("{} ({})", names[k], u.motion_symbol(k)),
                unit: u.motion_symbol(k),
                points: deg
                    .iter()
                    .zip(&prog)
                    .map(|(a, p)| (*a, p[k].unwrap_or(f64::NAN)))
                    .collect(),
                resolution: 0.0,
            })
            .collect(),
        marks: synth
            .discontinuities()
            .iter()
            .map(|d| svaj::Mark {
                angle_deg: d.at.to_degrees().rem_euclid(360.0),
                order: d.order,
            })
            .collect(),
        x: svaj::Page::REVOLUTION,
        x_label: "cam angle (°)".into(),
    };
    svaj::save(&page, &out("svaj")).map_err(Failure::output)?;

    // analysis of the synthesised profile: the round trip and the design checks
    let checks = mech.design_checks(&thetas, args.pressure_limit);
    if checks.round_trip.is_none() {
        return Err(Failure::Internal(anyhow!(
            "a motion profile without its round trip"
        )));
    }
    let design = DesignReport::new(checks, loaded.unit.name(), mech.follower().is_oscillating());
    let h = camkin::human::human;
    let mut report = design.text();
    for j in synth.discontinuities() {
        report += &format!(
            "program junction at {}°: {} jumps\n",
            h((j.at.to_degrees() * 1000.0).round() / 1000.0),
            ["position", "velocity", "acceleration", "jerk"][j.order]
        );
    }
    write_atomic(Some(&out("checks.txt")), |w| {
        Ok(w.write_all(format!("{report}{}", made.report).as_bytes())?)
    })
    .map_err(Failure::output)?;
    od.commit().map_err(Failure::output)?;
    crate::out!("{report}{}", made.report)?;
    crate::say!("camkin: wrote {}", args.out.display());
    let failures = design.failures();
    if failures.is_empty() {
        Ok(())
    } else {
        Err(Failure::Check(anyhow!(
            "design checks failed: {} (the files are written; see {})",
            failures.join(", "),
            args.out.join("checks.txt").display()
        )))
    }
}
