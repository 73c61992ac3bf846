//! The pages of a simulated system (`camkin simulate SYSTEM.toml --out DIR`): the moving body
//! that travels farthest (a valve) on an SVAJ-style page — its lift, velocity and acceleration
//! over the driver's angle, the impacts marked — every contact's force, and the deviation of its
//! lift from the same system at a tenth of the speed (nearly quasi-static: a hundredth of the
//! inertia forces).

use crate::draw::chart::{self, Chart, Series};
use crate::draw::svaj;
use camkin::dynamics::SystemSample;
use camkin::spec::BuiltSystem;
use std::path::Path;

/// The body and coordinate (0 x, 1 y) that travels farthest, and the sign that makes its
/// largest excursion from the start positive.
fn farthest(samples: &[SystemSample]) -> Option<(usize, usize, f64)> {
    let first = samples.first()?;
    let mut best: Option<(f64, usize, usize, f64)> = None;
    for k in 0..first.q.len() {
        if k % 3 == 2 {
            continue;
        }
        let (mut lo, mut hi) = (0.0f64, 0.0f64);
        for s in samples {
            let d = s.q[k] - first.q[k];
            lo = lo.min(d);
            hi = hi.max(d);
        }
        let range = hi - lo;
        if best.is_none_or(|b| range > b.0) {
            best = Some((range, k / 3, k % 3, if -lo > hi { -1.0 } else { 1.0 }));
        }
    }
    best.map(|(_, b, c, sign)| (b, c, sign))
}

/// Writes `lift`, `forces` and `deviation` (each `.svg` and `.png`) into `dir`.
pub fn write(
    dir: &Path,
    name: &str,
    built: &BuiltSystem,
    samples: &[SystemSample],
    slow: &[SystemSample],
    step: f64,
    impacts_deg: &[f64],
) -> anyhow::Result<()> {
    let sys = &built.system;
    let u = built.length_unit.name();
    let Some((body, c, sign)) = farthest(samples) else {
        return Ok(());
    };
    let bname = &sys.bodies()[body].name;
    let k = 3 * body + c;
    let axis = ["x", "y"][c];
    let angle = |i: usize| step * i as f64;
    let rpm = sys.first_driver_rpm();
    let h = camkin::human::human;
    let series = |f: &dyn Fn(&SystemSample) -> f64| -> Vec<(f64, f64)> {
        samples
            .iter()
            .enumerate()
            .map(|(i, s)| (angle(i), f(s)))
            .collect()
    };
    let start = samples[0].q[k];
    let panel = |label: String, unit: String, points| svaj::Panel {
        label,
        unit,
        points,
        resolution: 0.0,
    };
    let page = svaj::Page {
        title: format!(
            "{name}: {bname:?} ({axis} from its start, positive out) at {} rpm; marks: impacts",
            h((rpm * 10.0).round() / 10.0)
        ),
        panels: vec![
            panel(
                format!("lift ({u})"),
                u.to_string(),
                series(&|s| sign * (s.q[k] - start)),
            ),
            panel(
                format!("velocity ({u}/s)"),
                format!("{u}/s"),
                series(&|s| sign * s.qd[k]),
            ),
            panel(
                format!("acceleration ({u}/s²)"),
                format!("{u}/s²"),
                series(&|s| sign * s.qdd[k]),
            ),
        ],
        // an impact: the velocity jumps
        marks: impacts_deg
            .iter()
            .map(|&a| svaj::Mark {
                angle_deg: a,
                order: 1,
            })
            .collect(),
        x: svaj::Page::REVOLUTION,
        x_label: "driver angle (°)".into(),
    };
    svaj::save(&page, &dir.join("lift"))?;
    forces_page(dir, name, sys, samples, step)?;
    let slow_start = slow.first().map_or(start, |s| s.q[k]);
    let deviation = Chart {
        title: format!(
            "{name}: {bname:?} lift less its lift at a tenth of the speed (nearly quasi-static)"
        ),
        x_label: "driver angle (°)".into(),
        y_label: format!("dynamic − quasi-static lift ({u})"),
        series: vec![Series::line(
            "dynamic − quasi-static",
            samples
                .iter()
                .zip(slow)
                .enumerate()
                .map(|(i, (s, q))| (angle(i), sign * ((s.q[k] - start) - (q.q[k] - slow_start))))
                .collect(),
        )],
        log_y: false,
        x_range: Some((0.0, 360.0)),
    };
    chart::save(&deviation, &dir.join("deviation"))?;
    Ok(())
}

/// `forces.svg` and `.png`: every contact's compressive force that ever closes, by driver angle.
pub fn forces_page(
    dir: &Path,
    name: &str,
    sys: &camkin::system::System,
    samples: &[SystemSample],
    step: f64,
) -> anyhow::Result<()> {
    let h = camkin::human::human;
    let rpm = sys.first_driver_rpm();
    let series = |f: &dyn Fn(&SystemSample) -> f64| -> Vec<(f64, f64)> {
        samples
            .iter()
            .enumerate()
            .map(|(i, s)| (step * i as f64, f(s)))
            .collect()
    };
    // the contacts that never close (coil clash that does not happen) are left out
    let closed: Vec<usize> = (0..sys.contacts().len())
        .filter(|&j| samples.iter().any(|s| s.contact_forces[j] > 0.0))
        .collect();
    let never = sys.contacts().len() - closed.len();
    let forces = Chart {
        title: format!(
            "{name}: contact forces at {} rpm{}",
            h((rpm * 10.0).round() / 10.0),
            if never > 0 {
                format!(" ({never} never closed: not drawn)")
            } else {
                String::new()
            }
        ),
        x_label: "driver angle (°)".into(),
        y_label: "compressive force (N)".into(),
        series: closed
            .iter()
            .map(|&j| {
                Series::line(
                    sys.contacts()[j].name.clone(),
                    series(&|s| s.contact_forces[j]),
                )
            })
            .collect(),
        log_y: false,
        x_range: Some((0.0, 360.0)),
    };
    chart::save(&forces, &dir.join("forces"))?;
    Ok(())
}

/// `efforts.svg` and `.png`: each driver's effort (a camshaft's torque in N·m), by driver angle.
pub fn efforts_page(
    dir: &Path,
    name: &str,
    sys: &camkin::system::System,
    samples: &[SystemSample],
    step: f64,
    metres_per_unit: f64,
) -> anyhow::Result<()> {
    let h = camkin::human::human;
    let angles = sys
        .drivers()
        .iter()
        .filter(|d| d.coordinate == camkin::system::Coordinate::Angle)
        .count();
    let chart = Chart {
        title: format!(
            "{name}: drivers' efforts at {} rpm",
            h((sys.first_driver_rpm() * 10.0).round() / 10.0)
        ),
        x_label: "driver angle (°)".into(),
        y_label: match (angles, sys.drivers().len() - angles) {
            (_, 0) => "torque (N·m)",
            (0, _) => "force (N)",
            _ => "torque (N·m), force (N)",
        }
        .into(),
        series: sys
            .drivers()
            .iter()
            .enumerate()
            .map(|(d, driver)| {
                let scale = match driver.coordinate {
                    camkin::system::Coordinate::Angle => metres_per_unit,
                    _ => 1.0,
                };
                Series::line(
                    driver.name.clone(),
                    samples
                        .iter()
                        .enumerate()
                        .map(|(i, s)| (step * i as f64, s.driver_efforts[d] * scale))
                        .collect(),
                )
            })
            .collect(),
        log_y: false,
        x_range: Some((0.0, 360.0)),
    };
    chart::save(&chart, &dir.join("efforts"))?;
    Ok(())
}

/// The pages of a run in time (`--duration`, or a file's `[simulation]`): `motion` (the
/// coordinate that travels farthest, by time, the impacts' instants marked in its title),
/// `energy` (kinetic plus potential energy, the work of the drivers and applied forces, and
/// their difference: constant where the run is right), and `forces` (each contact's that ever
/// closes), each `.svg` and `.png`.
pub fn write_timed(
    dir: &Path,
    name: &str,
    built: &BuiltSystem,
    samples: &[SystemSample],
    impacts: usize,
) -> anyhow::Result<()> {
    let sys = &built.system;
    let u = built.length_unit.name();
    let time = |f: &dyn Fn(&SystemSample) -> f64| -> Vec<(f64, f64)> {
        samples.iter().map(|s| (s.time, f(s))).collect()
    };
    if let Some((body, c, _)) = farthest(samples) {
        let k = 3 * body + c;
        let motion = Chart {
            title: format!(
                "{name}: {:?} {} (the coordinate that travels farthest){}",
                sys.bodies()[body].name,
                ["x", "y"][c],
                if impacts > 0 {
                    format!("; {impacts} impacts (events.csv)")
                } else {
                    String::new()
                }
            ),
            x_label: "time (s)".into(),
            y_label: format!("{} ({u})", ["x", "y"][c]),
            series: vec![Series::line("position", time(&|s| s.q[k]))],
            log_y: false,
            x_range: None,
        };
        chart::save(&motion, &dir.join("motion"))?;
    }
    let e0 = samples.first().map_or(0.0, |s| s.energy);
    let mut series = vec![Series::line("energy − start", time(&|s| s.energy - e0))];
    if samples.iter().any(|s| s.driver_work != 0.0) {
        series.push(Series::dashed(
            "work of the drivers and applied forces",
            time(&|s| s.driver_work),
        ));
    }
    if samples.iter().any(|s| s.balance.dampers() != 0.0) {
        series.push(Series::dashed(
            "work of the dampers (dissipated)",
            time(&|s| s.balance.dampers()),
        ));
    }
    if samples.iter().any(|s| s.balance.impacts != 0.0) {
        series.push(Series::dashed(
            "energy changed by impacts",
            time(&|s| s.balance.impacts),
        ));
    }
    let unexplained = samples
        .iter()
        .map(|s| s.balance.residual().abs())
        .fold(0.0, f64::max);
    series.push(Series::line(
        format!(
            "unexplained: energy − start − every work and impact (at most {} N·{u}; 0 where the run is right)",
            camkin::human::human(unexplained)
        ),
        time(&|s| s.balance.residual()),
    ));
    let energy = Chart {
        title: format!(
            "{name}: energy (kinetic + potential) and the work done on it, from the start"
        ),
        x_label: "time (s)".into(),
        y_label: format!("N·{u}"),
        series,
        log_y: false,
        x_range: None,
    };
    chart::save(&energy, &dir.join("energy"))?;
    if !sys.contacts().is_empty() {
        let forces = Chart {
            title: format!("{name}: contact forces"),
            x_label: "time (s)".into(),
            y_label: "compressive force (N)".into(),
            series: (0..sys.contacts().len())
                .filter(|&j| samples.iter().any(|s| s.contact_forces[j] > 0.0))
                .map(|j| {
                    Series::line(
                        sys.contacts()[j].name.clone(),
                        time(&|s| s.contact_forces[j]),
                    )
                })
                .collect(),
            log_y: false,
            x_range: None,
        };
        chart::save(&forces, &dir.join("forces"))?;
    }
    Ok(())
}
