//! `camkin synth`: the profile of a `kind = "motion"` cam as points, DXF and SVG; the program's
//! SVAJ curves; design checks; the round-trip error of the contact method.

use crate::args::RevolutionStep;
use crate::draw::svaj;
use crate::output::write_atomic;
use crate::{load_mechanism, Failure};
use anyhow::anyhow;
use camkin::table::{Per, Units};
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
}

/// Bytes written per profile point, about (CSV, DXF, SVG and the four SVAJ SVGs; measured:
/// 5.9 MB for 36 000 points).
const BYTES_PER_POINT: f64 = 165.0;

fn svg_profile(pts: &[(f64, f64)]) -> String {
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in pts {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    let pad = 0.05 * (x1 - x0).max(y1 - y0);
    let (w, h) = (x1 - x0 + 2.0 * pad, y1 - y0 + 2.0 * pad);
    let k = 600.0 / w.max(h);
    let pts: Vec<String> = pts
        .iter()
        .map(|(x, y)| format!("{:.3},{:.3}", (x - x0 + pad) * k, (y1 + pad - y) * k))
        .collect();
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0}\" height=\"{:.0}\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<polygon points=\"{}\" fill=\"none\" stroke=\"rgb(31,119,180)\" stroke-width=\"2\"/>\n<circle cx=\"{:.3}\" cy=\"{:.3}\" r=\"3\" fill=\"black\"/>\n</svg>\n",
        w * k,
        h * k,
        pts.join(" "),
        (-x0 + pad) * k,
        (y1 + pad) * k
    )
}

pub fn run(args: &SynthArgs) -> Result<(), Failure> {
    let step = args.step.deg();
    if !(args.pressure_limit.is_finite() && args.pressure_limit > 0.0 && args.pressure_limit < 90.0)
    {
        return Err(Failure::Input(anyhow!(
            "--pressure-limit: {} must be in (0, 90) degrees",
            args.pressure_limit
        )));
    }
    let points = (360.0 / step).round();
    let loaded = load_mechanism(Some(&args.mechanism))?;
    let mech = &loaded.mech;
    let u = Units::new(mech, loaded.unit, args.units.angle_unit, args.units.per);
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
    std::fs::create_dir_all(&args.out)
        .map_err(|e| Failure::Input(anyhow!("cannot create {}: {e}", args.out.display())))?;
    let n = (360.0 / step).round() as usize;
    let thetas: Vec<f64> = (0..n).map(|k| (k as f64 * step).to_radians()).collect();
    let pts: Vec<(f64, f64)> = thetas
        .iter()
        .map(|&t| profile.position(t))
        .map(|p| (p.x, p.y))
        .collect();
    let out = |name: &str| args.out.join(name);
    let made = crate::manufacture::write(
        mech,
        loaded.unit,
        &args.out,
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
        Ok(w.write_all(svg_profile(&pts).as_bytes())?)
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
    let mut report = String::new();
    let rt = checks
        .round_trip
        .ok_or_else(|| Failure::Internal(anyhow!("a motion profile without its round trip")))?;
    let rel = if rt.has_peak {
        format!("{:.1e} of the peak", rt.acceleration / rt.scale)
    } else {
        format!(
            "{:.1e} of ω² × the cam's size; the program has no acceleration",
            rt.acceleration / rt.scale
        )
    };
    // the round trip is in time derivatives whatever --per says
    let ut = Units::new(mech, loaded.unit, args.units.angle_unit, Per::S);
    let (su, vu, au) = (
        ut.motion_symbol(0),
        ut.motion_symbol(1),
        ut.motion_symbol(2),
    );
    let cv = |x: f64| u.coord_value(x);
    report += &format!(
        "round trip (contact method against the motion law): |Δs| ≤ {:.2e} {su}, |Δv| ≤ {:.2e} {vu}, |Δa| ≤ {:.2e} {au} ({rel})\n",
        cv(rt.position),
        cv(rt.velocity),
        cv(rt.acceleration)
    );
    if !rt.passed {
        report += "round trip FAILED: the follower does not follow the synthesised profile (see the checks below)\n";
    }
    let h = camkin::human::human;
    let len = loaded.unit.name();
    if let Some((rho, at)) = checks.convex_min {
        report += &format!(
            "smallest convex radius of curvature of the profile: {} {len} at {}°\n",
            h(rho),
            h(at)
        );
    }
    report += &match checks.concave_sharpest {
        Some((rho, at)) => format!(
            "sharpest concave radius of curvature of the profile: {} {len} at {}° (negative: concave)\n",
            h(rho),
            h(at)
        ),
        None => "the profile is convex at every contact\n".to_string(),
    };
    let folded = &checks.undercut_deg;
    let bad_span = |v: &[f64]| {
        if v.is_empty() {
            String::new()
        } else {
            format!(
                " at {} angles, from {}° to {}°",
                v.len(),
                camkin::human::human(v[0]),
                camkin::human::human(v[v.len() - 1])
            )
        }
    };
    let broken = checks.undercut();
    if let (Some(r), Some(pitch_min)) = (checks.roller_radius, checks.pitch_convex_min()) {
        // the pitch curve (the roller centre's path) has radius of curvature ρ + r: where it
        // is convex with a radius below r, the profile folds back (undercut)
        let pitch_concave = checks
            .concave_sharpest
            .and_then(|(c, _)| (c + r < 0.0).then_some(c + r));
        report +=
            &format!(
            "pitch curve (roller centre path): smallest convex radius of curvature {} {len}{}\n",
            if pitch_min.is_finite() { h(pitch_min) } else { "∞".into() },
            pitch_concave.map_or(String::new(), |c| format!(", sharpest concave {} {len}", h(c)))
        );
        report += &if broken {
            format!("undercut: the profile is concave more sharply than the roller (radius {} {len}){}\n", h(r), bad_span(folded))
        } else {
            format!(
                "undercut: none (the roller's radius {} {len} fits everywhere)\n",
                h(r)
            )
        };
    } else if checks.flat_face {
        report += &if broken {
            format!(
                "concave stretches under the flat face: the follower cannot follow the profile{}\n",
                bad_span(folded)
            )
        } else {
            "concave stretches under the flat face: none\n".to_string()
        };
        if let Some((umin, umax)) = checks.face_range {
            report += &format!(
                "face width needed: {} {len} (contact from {} to {} {len} along the face)\n",
                h(umax - umin),
                h(umin),
                h(umax)
            );
        }
    }
    let (pa_peak, over, failed) = (
        checks.pressure_peak,
        &checks.pressure_over_deg,
        checks.failed,
    );
    let peak = format!(
        "peak {}° at {}°",
        h((pa_peak.0 * 100.0).round() / 100.0),
        h((pa_peak.1 * 100.0).round() / 100.0)
    );
    report += &if over.is_empty() {
        format!(
            "pressure angle: {peak}, within ±{}° everywhere\n",
            h(args.pressure_limit)
        )
    } else {
        format!(
            "pressure angle: {peak}, beyond ±{}° at {} angles, from {}° to {}°\n",
            h(args.pressure_limit),
            over.len(),
            h(over[0]),
            h(over[over.len() - 1])
        )
    };
    if let Some(c) = checks.conjugate_play {
        report += &format!(
            "conjugate play: {}\n",
            conjugate_line(&c, mech.follower().is_oscillating(), len)
        );
    }
    if failed > 0 {
        report += &format!("{failed} angles could not be analysed\n");
    }
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
    print!("{report}{}", made.report);
    eprintln!("camkin: wrote {}", args.out.display());
    let failures = checks.failures();
    if failures.is_empty() {
        Ok(())
    } else {
        Err(Failure::Check(anyhow!(
            "design checks failed: {} (the files are written; see {})",
            failures.join(", "),
            out("checks.txt").display()
        )))
    }
}

/// The conjugate check's words (`camkin synth`, the studio): the play's range (an arm's in
/// degrees) and what it means.
pub(crate) fn conjugate_line(c: &camkin::cam::ConjugatePlay, arm: bool, len: &str) -> String {
    let h = camkin::human::human;
    let (k, unit) = if arm {
        (1f64.to_degrees(), "°")
    } else {
        (1.0, len)
    };
    let v = |x: f64| format!("{} {unit}", h(k * x)).replace(" °", "°");
    let at = |x: f64| h((x * 100.0).round() / 100.0);
    let (lo, hi) = (c.min, c.max);
    let range = format!(
        "from {} at {}° to {} at {}°",
        v(lo.0),
        at(lo.1),
        v(hi.0),
        at(hi.1)
    );
    if c.failed > 0 {
        format!("{range}; {} angles could not be computed", c.failed)
    } else if lo.0 < -c.tolerance && hi.0 - lo.0 <= c.tolerance {
        format!("the second curve cuts {} into the cam everywhere", v(-lo.0))
    } else if lo.0 < -c.tolerance {
        format!("{range}: the second curve cuts into the cam")
    } else if hi.0 - lo.0 > c.tolerance {
        format!("{range}: it varies, so the second curve loses touch (the program does not suit the conjugate)")
    } else if hi.0 > c.tolerance {
        format!("a constant clearance of {}", v(hi.0))
    } else {
        format!(
            "none: both curves touch everywhere (|play| ≤ {})",
            v(lo.0.abs().max(hi.0.abs()))
        )
    }
}
