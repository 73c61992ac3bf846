//! `camkin forces`: with a `[dynamics]` section, the contact force and the camshaft torque over a
//! revolution under permanent contact, the speed at which the follower leaves the cam, the
//! spring that keeps it on up to a target speed, and the Hertz contact stress; a system file
//! with `[dynamics]` simulated over a revolution of its first driver, each contact's largest and
//! smallest force and Hertz pressure, each driver's effort, each impact
//! (`camkin::report::SystemForces`); a gear pair's loads ([`super::gear_loads`]).

use super::simulate::{bad, plan_err, system_err as dyn_err};
pub use crate::args::forces::ForcesArgs;
use crate::args::forces::{input_error, lubrication_request};
use crate::draw::chart::{self, Chart, Series};
use crate::forces_text::{self, num, LengthUnit};
use crate::mechfile::BySolver;
use crate::output::{write_atomic, write_cell_table, TableFormat};
use crate::Failure;
use anyhow::anyhow;
use camkin::dynamics::SpeedSweep;
use camkin::report::{rpm, ForceReport, ForceRequest, Materials, SystemForceFailure, SystemForces};
use std::path::Path;

pub fn run(args: &ForcesArgs) -> Result<(), Failure> {
    // the model picks its solver: a system file ([[body]], …, [dynamics]) gives its
    // simulation's forces; a cam preset is built in metres
    let model = crate::mechfile::load_model(Some(&args.mechanism), true)?;
    let (preset, name) = match model.by_solver(false)? {
        BySolver::General { name, built, .. } => return run_system(args, &name, &built),
        BySolver::Cam { preset, name, .. } => (preset, name),
    };
    // a gear pair's loads: asked for by a flag, or by the file's [gear_loads]
    if args.torque.is_some() || args.power.is_some() || preset.spec.gear_loads.is_some() {
        return super::gear_loads::run(args, &name, &preset.built);
    }
    let unit = preset.built.length_unit;
    let params = crate::mechfile::dynamics_of(&preset.built, &name)?;
    let file = preset.built.lubrication.clone();
    let mech = preset.built.mechanism;
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
                Series::dashed("margin", vec![(0.0, r.margin), (top, r.margin)]),
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
        let mark = |x: f64, name: String| Series::dashed(name, vec![(x, lo), (x, hi)]);
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
        &Chart::new(title, "cam speed (rpm)", y_label, series),
        &dir.join("force_speed"),
    )?;
    Ok(())
}

/// A system file's forces: its revolution simulated (the time step as the stiffest element
/// needs), its report and the checks `--margin` (every contact closed all the revolution keeps
/// that force), `--allowable` (every contact's Hertz pressure stays under it) and `--target-rpm`
/// (no contact that stays closed at low speed opens up to it: the no-follow speed's sweep).
fn run_system(
    args: &ForcesArgs,
    name: &str,
    built: &camkin::spec::BuiltSystem,
) -> Result<(), Failure> {
    // what a system's file says for each contact
    if let Some(w) = args.face_width {
        return Err(bad(format!(
            "--face-width {}: a system's contacts take their widths in the file ([[contact]] face_width = …)",
            camkin::human::human(w)
        )));
    }
    if args.materials.is_some() {
        return Err(bad(
            "--materials: a system's contacts take their materials in the file ([[contact]] materials = \"A,B\")".into(),
        ));
    }
    for (given, flag) in [
        (args.oil.is_some(), "--oil"),
        (args.roughness.is_some(), "--roughness"),
        (args.film.is_some(), "--film"),
        (args.friction.is_some(), "--friction"),
    ] {
        if given {
            return Err(bad(format!(
                "{flag}: a system's lubrication is in its file: a [lubrication] table (oil, roughness_um, film, friction) and each [[contact]]'s face_width, roughness_um and rolls"
            )));
        }
    }
    if !built.simulated {
        return Err(bad(format!(
            "{name}: a system's forces come from its simulation: give it a [dynamics] table (see docs/systems.md, \"Dynamics of a system\")"
        )));
    }
    // the checks a cam's forces take
    camkin::report::check_limits(args.margin, args.allowable).map_err(input_error)?;
    let sys = &built.system;
    let step = args.step.deg();
    let (plan, mut sim) = built.plan(1.0, step).map_err(|e| plan_err(name, e))?;
    let outputs = plan.outputs;
    let rpm = sys.first_driver_rpm();
    // --target-rpm's sweep: from a quarter of the lower of the two speeds, in eight steps to
    // the target, then bisected to 1 rpm
    let sweep = match args.target_rpm {
        Some(target) if !(target > 0.0 && target.is_finite() && target <= 1e6) => {
            return Err(bad(format!(
                "--target-rpm {}: must be a positive speed, rpm",
                camkin::human::human(target)
            )));
        }
        Some(target) => Some(SpeedSweep::to_target(sys, target, step)),
        None => None,
    };
    // the revolution, and the sweep's runs (each at most a revolution at the target's speed)
    crate::refuse_large(
        &built.run_work(&plan, &sim, false, sweep.as_ref()),
        args.work.large,
        ", or use a coarser --step",
    )?;
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let run = sim
        .run(outputs, plan.h_out, |_| std::ops::ControlFlow::Continue(()))
        .map_err(|e| dyn_err(name, e))?;
    // a run over the driver's angle (`BuiltSystem::plan`) has one at every instant
    let angle_of = |t: f64| plan.angle_of(t).unwrap_or(f64::NAN);
    let u = built.dynamics.metres_per_unit;
    let report = SystemForces::new(sys, &run, u, angle_of);
    let h = camkin::human::human;
    let deg = |a: f64| h((a * 100.0).round() / 100.0);
    let mut text = format!(
        "forces on {name} at {} rpm of {:?}, simulated over a revolution with outputs every {}° (its steps chosen by the integration's tolerances):\n",
        h((rpm * 10.0).round() / 10.0),
        sys.drivers().first().map_or("", |d| d.name.as_str()),
        h(step),
    );
    let force = |x: f64| sig(x, 4);
    let never: Vec<String> = report
        .contacts
        .iter()
        .filter(|c| c.min_closed_n.is_none())
        .map(|c| format!("{:?}", c.name))
        .collect();
    for c in report.contacts.iter().filter(|c| c.min_closed_n.is_some()) {
        text += &format!(
            "contact {:?}: max {} N at {}°",
            c.name,
            force(c.max_n.value),
            deg(c.max_n.angle_deg)
        );
        match (&c.min_closed_n, c.always_closed) {
            (Some(m), true) => {
                text += &format!(
                    ", min {} N at {}° (in touch all the revolution)",
                    force(m.value),
                    deg(m.angle_deg)
                )
            }
            (Some(m), false) => {
                text += &format!(
                    ", min in touch {} N at {}° (opens and closes)",
                    force(m.value),
                    deg(m.angle_deg)
                )
            }
            (None, _) => {}
        }
        if let Some(p) = &c.max_hertz_mpa {
            text += &format!(
                "; Hertz pressure max {} MPa at {}°",
                force(p.value),
                deg(p.angle_deg)
            );
        }
        text += "\n";
    }
    if !never.is_empty() {
        text += &format!("never in touch: {}\n", never.join(", "));
    }
    for d in &report.drivers {
        text += &format!(
            "driver {:?}: max {} {u} at {}°, min {} {u} at {}°, mean {} {u}, RMS {} {u}\n",
            d.name,
            force(d.max.value),
            deg(d.max.angle_deg),
            force(d.min.value),
            deg(d.min.angle_deg),
            force(d.mean),
            force(d.rms),
            u = d.unit,
        );
    }
    for i in &report.impacts {
        text += &format!(
            "impact of {:?} at {}°: {} m/s\n",
            i.contact,
            deg(i.angle_deg),
            sig(i.approach_m_s, 3)
        );
    }
    let lubrication = built
        .lubrication
        .as_ref()
        .map(|req| camkin::report::SystemLubricationReport::new(sys, &run, req, angle_of));
    if let Some(l) = &lubrication {
        text += &lubrication_text(l);
    }
    crate::out!("{text}")?;
    if let Some(od) = od {
        if let Some(l) = &lubrication {
            let (columns, rows) = l.table();
            write_atomic(Some(&od.path().join("lubrication.csv")), |w| {
                write_cell_table(w, TableFormat::Csv, &columns, rows)
            })
            .map_err(Failure::output)?;
        }
        let dir = od.path().to_path_buf();
        let (columns, rows) = camkin::table::system_force_table(
            sys,
            &run.samples,
            built.length_unit.name(),
            &built.dynamics.hertz,
            step,
        );
        write_atomic(Some(&dir.join("forces.csv")), |w| {
            write_cell_table(w, TableFormat::Csv, &columns, rows)
        })
        .map_err(Failure::output)?;
        crate::draw::simulation::forces_page(&dir, name, sys, &run.samples, step)
            .map_err(Failure::output)?;
        crate::draw::simulation::efforts_page(&dir, name, sys, &run.samples, step, u)
            .map_err(Failure::output)?;
        let dir = od.commit().map_err(Failure::output)?;
        crate::say!("camkin: wrote {}", dir.display());
    }
    // the checks
    let mut failures: Vec<String> = report
        .failures(args.margin, args.allowable)
        .into_iter()
        .map(|f| match f {
            SystemForceFailure::Margin {
                contact,
                force: m,
                margin,
            } => format!(
                "contact {contact:?}'s force falls to {} N at {}°, under the margin {} N",
                force(m.value),
                deg(m.angle_deg),
                h(margin)
            ),
            SystemForceFailure::Allowable {
                contact,
                pressure: p,
                allowable,
            } => format!(
                "contact {contact:?}'s Hertz pressure reaches {} MPa at {}°, over the allowable {} MPa",
                force(p.value),
                deg(p.angle_deg),
                h(allowable)
            ),
            other => format!("{other:?}"),
        })
        .collect();
    if let Some(sweep) = sweep {
        let (from, target) = (sweep.from_rpm, sweep.to_rpm);
        let found = camkin::dynamics::no_follow_speed(sys, &built.dynamics, &sweep)
            .map_err(|e| dyn_err(name, e))?;
        match found {
            Some(nf) => failures.push(
                match SystemForceFailure::no_follow(sys, &nf, &sweep) {
                    SystemForceFailure::NoFollow {
                        contact,
                        angle_deg,
                        speed_rpm,
                        target_rpm,
                        from_rpm,
                    } => format!(
                        "contact {contact:?} opens at {}° at {} rpm, below the target {} rpm (the no-follow speed, swept from {} rpm)",
                        deg(angle_deg),
                        h((speed_rpm * 10.0).round() / 10.0),
                        h(target_rpm),
                        h((from_rpm * 10.0).round() / 10.0),
                    ),
                    other => format!("{other:?}"),
                },
            ),
            None => crate::out!(
                "no contact that stays closed at {} rpm opens up to the target {} rpm\n",
                h((from * 10.0).round() / 10.0),
                h(target)
            )?,
        }
    }
    if failures.is_empty() {
        Ok(())
    } else {
        Err(Failure::Check(anyhow!(failures.join("; "))))
    }
}

/// Each lubricated contact's lines: its smallest λ and regime shares, its largest flash
/// temperature, its entrainment's reversals, its friction power.
fn lubrication_text(l: &camkin::report::SystemLubricationReport) -> String {
    let deg = |a: f64| camkin::human::human((a * 100.0).round() / 100.0);
    let mut text = String::new();
    for c in &l.contacts {
        text += &format!("lubrication of {:?}", c.name);
        if c.lubrication.rolls.is_some() {
            text += " (its roller rolls without slip)";
        }
        match &c.min_lambda {
            Some(m) => {
                let [b, mixed, full] = c.regime_shares.map(|x| sig(100.0 * x, 3));
                text += &format!(
                    ": λ min {} at {}° ({}); boundary {b} %, mixed {mixed} %, full film {full} % of its loaded samples",
                    sig(m.value, 3),
                    deg(m.angle_deg),
                    camkin::lubrication::regime(m.value).name()
                );
            }
            None => text += ": it carries no load at any sample with a line contact",
        }
        if let Some(t) = &c.thinnest_film {
            text += &format!(
                "; film min {} µm at {}°",
                sig(t.value * 1e6, 3),
                deg(t.angle_deg)
            );
        }
        if let Some(f) = c.max_flash_temperature.as_ref().filter(|f| f.value > 0.0) {
            text += &format!(
                "; flash temperature max {} K at {}°",
                sig(f.value, 3),
                deg(f.angle_deg)
            );
        }
        if c.max_flash_temperature.is_some_and(|f| f.value == 0.0) {
            text += "; nothing slides: no flash temperature";
        }
        text += &if c.entrainment_reversals_deg.is_empty() {
            "; entrainment never reverses".to_string()
        } else {
            format!(
                "; entrainment reverses near {} (between samples)",
                c.entrainment_reversals_deg
                    .iter()
                    .map(|a| format!("{}°", deg(*a)))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        };
        text += &format!("; friction {} W mean\n", sig(c.mean_friction_power, 3));
    }
    text
}

/// `x` to `n` significant digits, for people.
fn sig(x: f64, n: i32) -> String {
    if x == 0.0 || !x.is_finite() {
        return camkin::human::human(x);
    }
    let scale = 10f64.powi(n - 1 - x.abs().log10().floor() as i32);
    camkin::human::human((x * scale).round() / scale)
}
