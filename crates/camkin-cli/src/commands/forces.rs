//! `camkin forces`: with a `[dynamics]` section, the contact force and the camshaft torque over a
//! revolution under permanent contact, the speed at which the follower leaves the cam, the
//! spring that keeps it on up to a target speed, and the Hertz contact stress.

use crate::args::RevolutionStep;
use crate::draw::chart::{self, Chart, Series};
use crate::mechfile;
use crate::output::{write_atomic, write_cell_table, Cell, TableFormat};
use crate::Failure;
use anyhow::anyhow;
use camkin::cam::FollowerCurve;
use camkin::curve::Domain;
use camkin::dynamics::{effective_modulus, hertz_line_pressure, ForceState, Forces};
use camkin::human::human;
use std::f64::consts::TAU;
use std::path::PathBuf;
use std::str::FromStr;

/// A material's elastic constants.
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    /// its name (a preset's, or `E=…,nu=…`)
    pub name: String,
    /// Young's modulus, Pa
    pub e: f64,
    /// Poisson's ratio
    pub nu: f64,
}

/// Named materials (nominal values of handbooks: E in GPa, ν).
pub const PRESETS: [(&str, f64, f64); 8] = [
    ("steel", 206.0, 0.30),
    ("aisi-52100", 210.0, 0.30),
    ("aisi-4140", 205.0, 0.29),
    ("aisi-1045", 206.0, 0.29),
    ("stainless-440c", 200.0, 0.28),
    ("ductile-iron", 169.0, 0.28),
    ("cast-iron", 100.0, 0.26),
    ("bronze", 110.0, 0.34),
];

impl FromStr for Material {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let t = s.trim();
        if let Some(&(n, e, nu)) = PRESETS.iter().find(|p| p.0 == t) {
            return Ok(Self {
                name: n.into(),
                e: e * 1e9,
                nu,
            });
        }
        // E=210e9:nu=0.3 (Pa)
        let mut e = None;
        let mut nu = None;
        for part in t.split(':') {
            match part.split_once('=') {
                Some(("E", v)) => e = v.trim().parse::<f64>().ok(),
                Some(("nu", v)) => nu = v.trim().parse::<f64>().ok(),
                _ => {}
            }
        }
        match (e, nu) {
            (Some(e), Some(nu)) if e.is_finite() && e > 0.0 && (-1.0..0.5).contains(&nu) => {
                Ok(Self {
                    name: format!("E = {} GPa, ν = {nu}", human(e / 1e9)),
                    e,
                    nu,
                })
            }
            _ => Err(format!(
                "{t:?} is not a material: a preset ({}) or E=<Pa>:nu=<ratio> with E > 0 and −1 ≤ ν < 0.5, e.g. E=210e9:nu=0.3",
                PRESETS.map(|p| p.0).join(", ")
            )),
        }
    }
}

/// The cam's and the follower's materials: `CAM,FOLLOWER`.
#[derive(Debug, Clone, PartialEq)]
pub struct Materials(pub Material, pub Material);

impl FromStr for Materials {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let (a, b) = s
            .split_once(',')
            .ok_or_else(|| format!("{s:?} is not CAM,FOLLOWER (e.g. steel,steel)"))?;
        Ok(Self(a.parse()?, b.parse()?))
    }
}

#[derive(Debug, clap::Args)]
pub struct ForcesArgs {
    /// Mechanism file (TOML) with a `[dynamics]` section.
    pub mechanism: PathBuf,
    /// Cam-angle step, degrees.
    #[arg(long, value_name = "DEG", default_value = "0.5")]
    pub step: RevolutionStep,
    /// The contact force that must remain, N.
    #[arg(long, value_name = "N", default_value_t = 0.0)]
    pub margin: f64,
    /// The speed up to which the follower must stay on the cam, rpm [default: the file's].
    #[arg(long, value_name = "RPM")]
    pub target_rpm: Option<f64>,
    /// Face width of the contact, in the file's length unit: the Hertz contact stress.
    #[arg(long, value_name = "LENGTH")]
    pub face_width: Option<f64>,
    /// Cam and follower materials for the contact stress: presets (steel, aisi-52100,
    /// aisi-4140, aisi-1045, stainless-440c, ductile-iron, cast-iron, bronze) or `E=<Pa>:nu=<ν>`.
    #[arg(long, value_name = "CAM,FOLLOWER", default_value = "steel,steel")]
    pub materials: Materials,
    /// Allowable contact stress, MPa: exit 3 when the stress exceeds it.
    #[arg(long, value_name = "MPA")]
    pub allowable: Option<f64>,
    /// Directory for forces.csv, force_speed.csv and their plots.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

fn angle(t: f64) -> String {
    format!(
        "{}°",
        human((t.to_degrees().rem_euclid(360.0) * 100.0).round() / 100.0)
    )
}

fn num(x: f64) -> String {
    human(if x == 0.0 {
        0.0
    } else {
        let d = 10f64.powi(3 - x.abs().log10().floor() as i32);
        (x * d).round() / d
    })
}

pub fn run(args: &ForcesArgs) -> Result<(), Failure> {
    let bad = |m: String| Failure::Input(anyhow!(m));
    if !(args.margin.is_finite() && args.margin >= 0.0) {
        return Err(bad(format!(
            "--margin: {} N must be finite and ≥ 0",
            args.margin
        )));
    }
    if let Some(r) = args.target_rpm {
        if !(r.is_finite() && r > 0.0 && r <= 1e7) {
            return Err(bad(format!("--target-rpm: {r} must be in (0, 1e7] rpm")));
        }
    }
    if let Some(a) = args.allowable {
        if !(a.is_finite() && a > 0.0) {
            return Err(bad(format!("--allowable: {a} MPa must be positive")));
        }
    }
    let (mech, params, unit) =
        mechfile::load_dynamics(&args.mechanism).map_err(|e| Failure::Input(anyhow!(e)))?;
    let osc = mech.follower().is_oscillating();
    let lu = unit.name();
    let m_per = unit.metres();
    if let Some(wd) = args.face_width {
        if !(wd.is_finite() && wd > 0.0) {
            return Err(bad(format!("--face-width: {wd} {lu} must be positive")));
        }
    }
    // a knife edge (named, or a point carried) touches in a point: no line contact
    let knife = match mech.follower_curve() {
        FollowerCurve::Point(_) => true,
        FollowerCurve::Carried(c) => matches!(c.domain(), Domain::Point),
        _ => false,
    };
    if args.face_width.is_some() && knife {
        return Err(bad(
            "--face-width: a knife-edge follower has no line contact (its edge is a point in the plane): no Hertz stress".into(),
        ));
    }
    let closed = mech.is_conjugate();
    if closed && (args.margin != 0.0 || args.target_rpm.is_some()) {
        return Err(bad(format!(
            "{}: the follower is form-closed (follower.conjugate): its second curve takes the load where its own would lift off, so it has no jump speed and no spring to size",
            if args.margin != 0.0 { "--margin" } else { "--target-rpm" }
        )));
    }
    let n = (360.0 / args.step.deg()).round() as usize;
    crate::check_sweep_time(&mech, n * 2 + 720, if closed { 3 } else { 1 }, false)?;
    let f = Forces::new(&mech, params).map_err(|e| Failure::Input(anyhow!(e)))?;
    let thetas: Vec<f64> = (0..n).map(|k| k as f64 * TAU / n as f64).collect();
    let mut sweep = f.sweep();
    let states: Vec<ForceState> = thetas
        .iter()
        .map(|&t| sweep.step(t))
        .collect::<Result<_, _>>()
        .map_err(|e| Failure::Input(anyhow!("the forces cannot be computed: {e}")))?;
    let w = mech.cam().speed();
    let rpm = w * 60.0 / TAU;
    let target_rpm = args.target_rpm.unwrap_or(rpm);
    let target = target_rpm * TAU / 60.0;
    let (fu, ku, tu) = if osc {
        ("N·m", "N·m/rad", "N·m")
    } else {
        ("N", "N/m", "N·m")
    };
    let mut report = format!(
        "forces on {} at {} rpm, permanent contact, friction neglected{}:\n",
        args.mechanism.display(),
        num(rpm),
        if mech.cam().angular_acceleration() != 0.0 {
            " (with the file's angular acceleration; speeds below assume a constant speed)"
        } else {
            ""
        }
    );
    let extreme = |g: &dyn Fn(&ForceState) -> f64| {
        let mut lo = &states[0];
        let mut hi = &states[0];
        for s in &states {
            if g(s) < g(lo) {
                lo = s;
            }
            if g(s) > g(hi) {
                hi = s;
            }
        }
        (lo, hi)
    };
    let (flo, fhi) = extreme(&|s| s.contact_force);
    if closed {
        report += &form_closed_report(&mech, &states, &thetas, osc, m_per, lu)?;
    } else {
        report += &format!(
            "contact force: max {} N at {}, min {} N at {}\n",
            num(fhi.contact_force),
            angle(fhi.cam_angle),
            num(flo.contact_force),
            angle(flo.cam_angle)
        );
    }
    let (tlo, thi) = extreme(&|s| s.camshaft_torque);
    let rms = (states
        .iter()
        .map(|s| s.camshaft_torque.powi(2))
        .sum::<f64>()
        / n as f64)
        .sqrt();
    report += &format!(
        "camshaft torque: max {} {tu} at {}, min {} {tu} at {}, RMS {} {tu}\n",
        num(thi.camshaft_torque),
        angle(thi.cam_angle),
        num(tlo.camshaft_torque),
        angle(tlo.cam_angle),
        num(rms)
    );
    let pmax = states
        .iter()
        .map(|s| s.follower_power.abs())
        .fold(0.0, f64::max);
    let dmax = states
        .iter()
        .map(|s| (s.camshaft_torque * w - s.follower_power).abs())
        .fold(0.0, f64::max);
    report += &format!(
        "power balance (torque × speed against the power into the follower): largest difference {:.1e} of the peak power {} W\n",
        if pmax > 0.0 { dmax / pmax } else { dmax },
        num(pmax)
    );
    let mut failures: Vec<String> = Vec::new();
    // the speed at which the contact force first reaches the margin (form-closed: from which
    // the second curve takes load)
    let (mut jump, mut jump_at) = (f64::INFINITY, 0.0);
    for s in &states {
        let v = f.leave_speed(s, args.margin);
        if v < jump {
            (jump, jump_at) = (v, s.cam_angle);
        }
    }
    if closed {
        report += &if jump == 0.0 {
            "the second curve takes load at any constant speed (no spring holds the follower's own curve on)\n".to_string()
        } else if jump.is_finite() {
            format!(
                "the second curve takes load from {} rpm (first at {}, at constant speed)\n",
                num(jump * 60.0 / TAU),
                angle(jump_at)
            )
        } else {
            "the second curve takes no load at any constant speed (the spring holds the follower's own curve on)\n".to_string()
        };
    } else {
        if flo.contact_force < args.margin {
            failures.push(format!(
                "the contact force falls to {} N at {} at the file's speed (margin {} N)",
                num(flo.contact_force),
                angle(flo.cam_angle),
                num(args.margin)
            ));
        }
        report += &if jump.is_finite() {
            format!(
                "jump speed: {} rpm (the contact force reaches {} N first at {}, at constant speed)\n",
                num(jump * 60.0 / TAU),
                num(args.margin),
                angle(jump_at)
            )
        } else {
            format!(
                "jump speed: none (the contact force stays above {} N at any constant speed)\n",
                num(args.margin)
            )
        };
        if jump < target {
            failures.push(format!(
                "the follower leaves the cam at {} rpm, below {} rpm",
                num(jump * 60.0 / TAU),
                num(target_rpm)
            ));
        }
        // spring sizing for the target speed
        let preload = states
            .iter()
            .map(|s| f.preload_needed(s, args.margin, target))
            .fold(f64::NEG_INFINITY, f64::max);
        let mut stiffness = f64::NEG_INFINITY;
        let mut stiffness_possible = true;
        for s in &states {
            match f.stiffness_needed(s, args.margin, target) {
                Some(k) => stiffness = stiffness.max(k),
                None => {
                    if f.preload_needed(s, args.margin, target) > params.spring_preload {
                        stiffness_possible = false;
                    }
                }
            }
        }
        report += &format!(
            "spring for {} rpm with a margin of {} N: preload ≥ {} {fu} with the stiffness {} {ku} (file: preload {} {fu}); ",
            num(target_rpm),
            num(args.margin),
            num(preload.max(0.0)),
            num(params.spring_stiffness),
            num(params.spring_preload)
        );
        report += &if stiffness_possible {
            format!(
                "or stiffness ≥ {} {ku} with the preload {} {fu}\n",
                num(stiffness.max(0.0)),
                num(params.spring_preload)
            )
        } else {
            format!(
                "no stiffness will do with the preload {} {fu} (the follower leaves the cam at rest position, where only the preload acts)\n",
                num(params.spring_preload)
            )
        };
    }
    // Hertz contact stress, at each contact
    let mut stress: Vec<[Option<f64>; 2]> = vec![[None; 2]; n];
    if let Some(width) = args.face_width {
        let Materials(a, b) = &args.materials;
        let es = effective_modulus(a.e, a.nu, b.e, b.nu);
        let mut worst_mpa = 0.0f64;
        let sides: &[usize] = if closed { &[0, 1] } else { &[0] };
        for &side in sides {
            let contact = |s: &ForceState| match (side, s.second) {
                (0, _) => Some((s.contact_force, s.cam_radius, s.follower_radius)),
                (_, Some(c)) => Some((c.contact_force, c.cam_radius, c.follower_radius)),
                _ => None,
            };
            let mut worst: Option<(f64, f64, f64)> = None;
            let (mut unclosed, mut cornered) = (0, 0);
            for (k, s) in states.iter().enumerate() {
                let Some((force, rc, rf)) = contact(s) else {
                    continue;
                };
                let Some(rf) = rf else {
                    if force > 0.0 {
                        cornered += 1;
                    }
                    continue;
                };
                match hertz_line_pressure(force.max(0.0), width * m_per, rc, rf, es) {
                    Some(p) => {
                        stress[k][side] = Some(p / 1e6);
                        if worst.is_none_or(|w| p > w.0) {
                            worst = Some((p, s.cam_angle, rc));
                        }
                    }
                    None if force > 0.0 => unclosed += 1,
                    None => {}
                }
            }
            let whose = match (closed, side) {
                (false, _) => "",
                (true, 0) => " on the follower's own curve",
                _ => " on the second curve",
            };
            if let Some((p, t, rho)) = worst {
                worst_mpa = worst_mpa.max(p / 1e6);
                report += &format!(
                    "contact stress{whose} (Hertz line contact, face {} {lu}, {} cam on {} follower, E* = {} GPa): max {} MPa at {} (cam radius of curvature {} {lu})\n",
                    num(width),
                    a.name,
                    b.name,
                    num(es / 1e9),
                    num(p / 1e6),
                    angle(t),
                    if rho.is_finite() { num(rho / m_per) } else { "∞".into() }
                );
            }
            if unclosed > 0 {
                report += &format!("contact stress{whose}: at {unclosed} angles the cam is concave as sharply as the follower's curve: no Hertz solution (conformal contact)\n");
            }
            if cornered > 0 {
                report += &format!("contact stress{whose}: at {cornered} angles the contact rests on a corner of a curve (a point, not a line contact): no Hertz stress there\n");
            }
        }
        match args.allowable {
            Some(al) if worst_mpa > al => {
                report += &format!(
                    "contact stress: max {} MPa, OVER the allowable {} MPa\n",
                    num(worst_mpa),
                    num(al)
                );
                failures.push(format!(
                    "the contact stress {} MPa exceeds the allowable {} MPa",
                    num(worst_mpa),
                    num(al)
                ));
            }
            Some(al) => {
                report += &format!(
                    "contact stress: max {} MPa, within the allowable {} MPa\n",
                    num(worst_mpa),
                    num(al)
                )
            }
            None => {}
        }
    }
    print!("{report}");
    if let Some(dir) = &args.out {
        write_files(dir, &f, &states, &stress, args.margin, target, jump, fu, tu)
            .map_err(Failure::output)?;
        eprintln!("camkin: wrote {}", dir.display());
    }
    if failures.is_empty() {
        Ok(())
    } else {
        Err(Failure::Check(anyhow!(
            "check failed: {}",
            failures.join("; ")
        )))
    }
}

/// The force the second curve of a form-closed follower carries (0 without one).
fn second_force(s: &ForceState) -> f64 {
    s.second.map_or(0.0, |c| c.contact_force)
}

/// A form-closed follower's lines: the largest force on each curve, where the load passes from
/// one curve to the other, and the second curve's play.
fn form_closed_report(
    mech: &camkin::cam::Mechanism,
    states: &[ForceState],
    thetas: &[f64],
    osc: bool,
    m_per: f64,
    lu: &str,
) -> Result<String, Failure> {
    let peak = |g: fn(&ForceState) -> f64| {
        states
            .iter()
            .max_by(|a, b| g(a).total_cmp(&g(b)))
            .expect("a revolution has angles")
    };
    let (p1, p2) = (peak(|s| s.contact_force), peak(second_force));
    let mut r = format!(
        "form-closed: the follower's own curve carries where the load presses it onto the cam, its second curve elsewhere\ncontact force on the follower's own curve: max {} N at {}; on the second curve: max {} N at {}\n",
        num(p1.contact_force),
        angle(p1.cam_angle),
        num(second_force(p2)),
        angle(p2.cam_angle)
    );
    // which curve carries, angle by angle (neither, or a force at rounding level of the peak:
    // the last one's), around the revolution
    let small = 1e-9 * p1.contact_force.max(second_force(p2));
    let side = |s: &ForceState| {
        if s.contact_force > small {
            Some(false)
        } else if second_force(s) > small {
            Some(true)
        } else {
            None
        }
    };
    // `R = F₁ |J₁| − F₂ |J₂|`: where it changes sign, the load passes (linear between samples)
    let net = |s: &ForceState| {
        s.contact_force * s.lever - s.second.map_or(0.0, |c| c.contact_force * c.lever)
    };
    let mut last = states
        .iter()
        .rev()
        .find_map(|s| side(s).map(|d| (d, s.cam_angle - TAU, net(s))));
    let mut reversals = Vec::new();
    for s in states {
        if let Some(now) = side(s) {
            let r = net(s);
            if let Some((_, t0, r0)) = last.filter(|l| l.0 != now) {
                reversals.push(angle(t0 + (s.cam_angle - t0) * r0 / (r0 - r)));
            }
            last = Some((now, s.cam_angle, r));
        }
    }
    r += &if reversals.is_empty() {
        format!(
            "load reversals: none (the {} carries at every angle)\n",
            if last.is_some_and(|l| l.0) {
                "second curve"
            } else {
                "follower's own curve"
            }
        )
    } else {
        let shown = reversals
            .iter()
            .take(6)
            .cloned()
            .collect::<Vec<_>>()
            .join(", ");
        format!(
            "load reversals: {} a revolution, where the load passes to the other curve (at {shown}{}): with play, each is an impact (`camkin simulate`)\n",
            reversals.len(),
            if reversals.len() > 6 { ", …" } else { "" }
        )
    };
    // the second curve's play over the same angles
    let failed = |e: camkin::cam::CamError| {
        Failure::Input(anyhow!("the second curve's play cannot be computed: {e}"))
    };
    let (mut sweep, mut plays) = (mech.sweep(), mech.conjugate_sweep().expect("form-closed"));
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &t in thetas {
        let play = plays
            .play(&sweep.step(t).map_err(failed)?)
            .map_err(failed)?;
        (lo, hi) = (lo.min(play), hi.max(play));
    }
    let show = |x: f64| {
        if osc {
            format!("{}°", num(x.to_degrees()))
        } else {
            format!("{} {lu}", num(x / m_per))
        }
    };
    // as the design check of the play: 1e-6 of the cam's size (of 1 rad for an arm)
    let tol = if osc { 1e-6 } else { 1e-6 * mech.size() };
    r += &if lo.abs().max(hi.abs()) > tol {
        format!(
            "play of the second curve: {} to {} (its force is taken at its own contact, the motion from the follower's own curve: exact without play)\n",
            show(lo),
            show(hi)
        )
    } else {
        format!(
            "play of the second curve: none (within {} at every angle: an exact conjugate)\n",
            show(tol)
        )
    };
    Ok(r)
}

#[allow(clippy::too_many_arguments)]
fn write_files(
    dir: &std::path::Path,
    f: &Forces<'_>,
    states: &[ForceState],
    stress: &[[Option<f64>; 2]],
    margin: f64,
    target: f64,
    jump: f64,
    fu: &str,
    tu: &str,
) -> anyhow::Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| anyhow!("cannot create {}: {e}", dir.display()))?;
    let closed = f.is_form_closed();
    let mut columns: Vec<String> = vec![
        "angle_deg".into(),
        "contact_force_N".into(),
        format!("spring_force_{}", fu.replace('·', "_")),
        format!("camshaft_torque_{}", tu.replace('·', "_")),
        "pressure_angle_deg".into(),
        "contact_stress_MPa".into(),
    ];
    if closed {
        columns.extend([
            "second_contact_force_N".into(),
            "second_pressure_angle_deg".into(),
            "second_contact_stress_MPa".into(),
        ]);
    }
    let rows: Vec<Vec<Cell>> = states
        .iter()
        .zip(stress)
        .map(|(s, p)| {
            let mut row = vec![
                Cell::Num(Some(s.cam_angle.to_degrees())),
                Cell::Num(Some(s.contact_force)),
                Cell::Num(Some(s.spring_force)),
                Cell::Num(Some(s.camshaft_torque)),
                Cell::Num(Some(s.pressure_angle.to_degrees())),
                Cell::Num(p[0]),
            ];
            if let Some(c) = s.second {
                row.extend([
                    Cell::Num(Some(c.contact_force)),
                    Cell::Num(Some(c.pressure_angle.to_degrees())),
                    Cell::Num(p[1]),
                ]);
            }
            row
        })
        .collect();
    write_atomic(Some(&dir.join("forces.csv")), |w| {
        write_cell_table(w, TableFormat::Csv, &columns, rows)
    })?;
    // the smallest contact force over the revolution against a constant speed (form-closed:
    // the largest on each curve)
    let top = 1.5 * target.max(if jump.is_finite() { jump } else { 0.0 });
    let speeds: Vec<f64> = (0..=150).map(|k| top * k as f64 / 150.0).collect();
    let rpm = |w: f64| w * 60.0 / TAU;
    let min_force = |omega: f64| {
        states
            .iter()
            .map(|s| f.force_at_speed(s, omega))
            .fold(f64::INFINITY, f64::min)
    };
    // the first curve's force at ω is `R/|J₁|` where positive; the second's `−R/|J₂|`
    let max_forces = |omega: f64| {
        states.iter().fold((0.0f64, 0.0f64), |(a, b), s| {
            let f1 = f.force_at_speed(s, omega);
            let f2 = s.second.map_or(0.0, |c| -f1 * s.lever / c.lever);
            (a.max(f1), b.max(f2))
        })
    };
    let curves: Vec<Vec<(f64, f64)>> = if closed {
        let m: Vec<(f64, f64)> = speeds.iter().map(|&w| max_forces(w)).collect();
        vec![
            speeds.iter().zip(&m).map(|(&w, x)| (rpm(w), x.0)).collect(),
            speeds.iter().zip(&m).map(|(&w, x)| (rpm(w), x.1)).collect(),
        ]
    } else {
        vec![speeds.iter().map(|&w| (rpm(w), min_force(w))).collect()]
    };
    let names: &[&str] = if closed {
        &["max_contact_force_N", "max_second_contact_force_N"]
    } else {
        &["min_contact_force_N"]
    };
    write_atomic(Some(&dir.join("force_speed.csv")), |w| {
        let mut columns = vec!["speed_rpm".to_string()];
        columns.extend(names.iter().map(|c| c.to_string()));
        write_cell_table(
            w,
            TableFormat::Csv,
            &columns,
            (0..speeds.len())
                .map(|k| {
                    let mut row = vec![Cell::Num(Some(curves[0][k].0))];
                    row.extend(curves.iter().map(|c| Cell::Num(Some(c[k].1))));
                    row
                })
                .collect(),
        )
    })?;
    let deg = |s: &ForceState| s.cam_angle.to_degrees();
    chart::save(
        &Chart {
            title: "contact force under permanent contact".into(),
            x_label: "cam angle (°)".into(),
            y_label: "contact force (N)".into(),
            series: if closed {
                vec![
                    Series {
                        name: "follower's own curve".into(),
                        points: states.iter().map(|s| (deg(s), s.contact_force)).collect(),
                        dashed: false,
                    },
                    Series {
                        name: "second curve".into(),
                        points: states.iter().map(|s| (deg(s), second_force(s))).collect(),
                        dashed: true,
                    },
                ]
            } else {
                vec![Series {
                    name: "contact force".into(),
                    points: states.iter().map(|s| (deg(s), s.contact_force)).collect(),
                    dashed: false,
                }]
            },
            log_y: false,
            x_range: Some((0.0, 360.0)),
        },
        &dir.join("contact_force"),
    )?;
    chart::save(
        &Chart {
            title: "camshaft torque".into(),
            x_label: "cam angle (°)".into(),
            y_label: format!("torque ({tu})"),
            series: vec![Series {
                name: "camshaft torque".into(),
                points: states.iter().map(|s| (deg(s), s.camshaft_torque)).collect(),
                dashed: false,
            }],
            log_y: false,
            x_range: Some((0.0, 360.0)),
        },
        &dir.join("camshaft_torque"),
    )?;
    let mut series: Vec<Series> = if closed {
        vec![
            Series {
                name: "largest force on the follower's own curve".into(),
                points: curves[0].clone(),
                dashed: false,
            },
            Series {
                name: "largest force on the second curve".into(),
                points: curves[1].clone(),
                dashed: true,
            },
        ]
    } else {
        vec![Series {
            name: "smallest contact force".into(),
            points: curves[0].clone(),
            dashed: false,
        }]
    };
    if !closed {
        series.push(Series {
            name: "margin".into(),
            points: vec![(0.0, margin), (rpm(top), margin)],
            dashed: true,
        });
    }
    chart::save(
        &Chart {
            title: if closed {
                "largest contact force on each curve over a revolution".into()
            } else {
                format!(
                    "smallest contact force over a revolution (margin {} N)",
                    num(margin)
                )
            },
            x_label: "cam speed (rpm)".into(),
            y_label: if closed {
                "largest contact force (N)".into()
            } else {
                "smallest contact force (N)".into()
            },
            series,
            log_y: false,
            x_range: None,
        },
        &dir.join("force_speed"),
    )?;
    Ok(())
}
