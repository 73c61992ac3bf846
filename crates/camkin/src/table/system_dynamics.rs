//! The tables of a simulated system (`camkin simulate SYSTEM.toml`): one row an output instant
//! — every body's pose, rates and accelerations, every contact's force, gap and whether it is in
//! touch, each lash adjuster's chamber (pressure in bar, height, push), each driver's torque or
//! force (a camshaft's driving torque), the energy and the drivers' work — and one row an event (a contact's lift-off or
//! impact). Lengths in the system's unit, forces in N, energies in N times that unit.

use super::column::Cell;
use super::system::{body_columns, key};
use crate::dynamics::{ContactEvent, EventKind, SystemSample};
use crate::system::System;

/// The columns of a simulated system's samples, lengths in `unit`; each contact with a face
/// width in `hertz` adds its Hertz pressure (`{contact}_hertz_MPa`). A run over the first
/// driver's angle (`angles`) starts with it; a run in time with the time.
pub fn system_sample_columns(
    sys: &System,
    unit: &str,
    hertz: &[Option<crate::dynamics::ContactHertz>],
    angles: bool,
) -> Vec<String> {
    let mut c = Vec::new();
    if angles {
        c.push("driver_angle_deg".to_string());
    }
    c.push("time_s".to_string());
    for b in sys.bodies() {
        c.extend(body_columns(&key(&b.name), unit));
    }
    for (j, k) in sys.contacts().iter().enumerate() {
        let n = key(&k.name);
        c.push(format!("{n}_force_N"));
        c.push(format!("{n}_gap_{unit}"));
        c.push(format!("{n}_in_contact"));
        if hertz.get(j).is_some_and(|h| h.is_some()) {
            c.push(format!("{n}_hertz_MPa"));
        }
    }
    for h in sys.lash_adjusters() {
        let n = key(&h.name);
        c.push(format!("{n}_pressure_bar"));
        c.push(format!("{n}_chamber_{unit}"));
        c.push(format!("{n}_force_N"));
    }
    for d in sys.drivers() {
        let n = key(&d.name);
        c.push(match d.coordinate {
            crate::system::Coordinate::Angle => format!("{n}_torque_N_{unit}"),
            _ => format!("{n}_force_N"),
        });
    }
    c.push(format!("energy_N_{unit}"));
    c.push(format!("driver_work_N_{unit}"));
    for part in crate::dynamics::EnergyBalance::PARTS {
        c.push(format!("{part}_N_{unit}"));
    }
    c
}

/// One sample's row at driver angle `angle_deg` (none in a run in time; under
/// [`system_sample_columns`] with the same `hertz`; a Hertz pressure that is not defined is an
/// empty cell).
pub fn system_sample_cells(
    angle_deg: Option<f64>,
    s: &SystemSample,
    hertz: &[Option<crate::dynamics::ContactHertz>],
) -> Vec<Cell> {
    let mut c: Vec<Cell> = angle_deg.map(|a| Cell::Num(Some(a))).into_iter().collect();
    c.push(Cell::Num(Some(s.time)));
    for i in 0..s.q.len() / 3 {
        let k = 3 * i;
        for v in [
            s.q[k],
            s.q[k + 1],
            s.q[k + 2].to_degrees(),
            s.qd[k],
            s.qd[k + 1],
            s.qd[k + 2].to_degrees(),
            s.qdd[k],
            s.qdd[k + 1],
            s.qdd[k + 2].to_degrees(),
        ] {
            c.push(Cell::Num(Some(v)));
        }
    }
    for k in 0..s.in_contact.len() {
        c.push(Cell::Num(Some(s.contact_forces[k])));
        c.push(Cell::Num(Some(s.gaps[k])));
        c.push(Cell::Flag(Some(s.in_contact[k])));
        if hertz.get(k).is_some_and(|h| h.is_some()) {
            c.push(Cell::Num(s.hertz_pa[k].map(|p| p / 1e6)));
        }
    }
    for h in &s.adjusters {
        c.push(Cell::Num(Some(h.pressure / 1e5)));
        c.push(Cell::Num(Some(h.chamber)));
        c.push(Cell::Num(Some(h.force)));
    }
    for &e in &s.driver_efforts {
        c.push(Cell::Num(Some(e)));
    }
    c.push(Cell::Num(Some(s.energy)));
    c.push(Cell::Num(Some(s.driver_work)));
    for v in s.balance.parts() {
        c.push(Cell::Num(Some(v)));
    }
    c
}

/// The columns of a simulated system's events (the driver's angle where the run is over it:
/// `angles`).
pub fn system_event_columns(unit: &str, angles: bool) -> Vec<String> {
    let mut c = vec!["event".to_string(), "contact".into(), "time_s".into()];
    if angles {
        c.push("driver_angle_deg".into());
    }
    c.push(format!("approach_speed_{unit}_s"));
    c
}

/// One event's row (`angle_deg`: the driver's angle then, none in a run in time).
pub fn system_event_cells(sys: &System, e: &ContactEvent, angle_deg: Option<f64>) -> Vec<Cell> {
    let mut c = vec![
        Cell::Text(Some(
            match e.kind {
                EventKind::LiftOff => "lift-off",
                _ => "impact",
            }
            .into(),
        )),
        Cell::Text(Some(
            sys.contacts()
                .get(e.contact)
                .map_or("?".into(), |c| c.name.clone()),
        )),
        Cell::Num(Some(e.time)),
    ];
    c.extend(angle_deg.map(|a| Cell::Num(Some(a))));
    c.push(Cell::Num(Some(e.approach)));
    c
}

/// The forces of a simulated system's samples (`camkin forces SYSTEM.toml`'s `forces.csv`): of
/// [`system_sample_columns`], the driver's angle, the time, every contact's force and Hertz
/// pressure and every driver's torque; the samples `step_deg` apart from 0 (the decimals of the
/// step, [`super::AngleGrid`]).
pub fn system_force_table(
    sys: &System,
    samples: &[SystemSample],
    unit: &str,
    hertz: &[Option<crate::dynamics::ContactHertz>],
    step_deg: f64,
) -> (Vec<String>, Vec<Vec<Cell>>) {
    let all = system_sample_columns(sys, unit, hertz, true);
    let keep: Vec<usize> = all
        .iter()
        .enumerate()
        .filter(|(k, c)| {
            *k < 2
                || c.ends_with("_force_N")
                || c.ends_with("_hertz_MPa")
                || c.contains("_torque_N_")
        })
        .map(|(k, _)| k)
        .collect();
    let columns = keep.iter().map(|&k| all[k].clone()).collect();
    let grid = super::AngleGrid::new(0.0, step_deg);
    let rows = samples
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let cells = system_sample_cells(Some(grid.at(i)), s, hertz);
            keep.iter().map(|&k| cells[k].clone()).collect()
        })
        .collect();
    (columns, rows)
}

/// The columns of a simulated system's energy balance by element (`energy.csv` of `camkin
/// simulate --out`; see [`crate::dynamics::EnergyBalance`]): the time (and the driver's angle in
/// a run over it), the kinetic energy, each force element's potential (a spring's) and work, in
/// the system's order, gravity's potential and work (where there is gravity), the drivers', the
/// applied loads' and the constraint forces' work, the impacts' and the projections' change of
/// energy, and what the balance leaves unexplained; N·`unit`.
pub fn system_energy_columns(sys: &System, unit: &str, gravity: bool, angles: bool) -> Vec<String> {
    let mut c = Vec::new();
    if angles {
        c.push("driver_angle_deg".to_string());
    }
    c.push("time_s".to_string());
    c.push(format!("kinetic_N_{unit}"));
    for f in sys.forces() {
        let n = key(&f.name);
        if f.kind.stores() {
            c.push(format!("{n}_potential_N_{unit}"));
        }
        c.push(format!("{n}_work_N_{unit}"));
    }
    for h in sys.lash_adjusters() {
        c.push(format!("{}_work_N_{unit}", key(&h.name)));
    }
    if gravity {
        c.push(format!("gravity_potential_N_{unit}"));
        c.push(format!("gravity_work_N_{unit}"));
    }
    for part in [
        "driver_work",
        "load_work",
        "constraint_work",
        "impact_energy",
        "projection_energy",
        "unexplained",
    ] {
        c.push(format!("{part}_N_{unit}"));
    }
    c
}

/// One sample's row under [`system_energy_columns`] (`angle_deg`: the driver's angle, none in a
/// run in time).
pub fn system_energy_cells(angle_deg: Option<f64>, s: &SystemSample, gravity: bool) -> Vec<Cell> {
    let b = &s.balance;
    let mut v: Vec<f64> = angle_deg.into_iter().collect();
    v.push(s.time);
    v.push(b.kinetic);
    for e in &b.elements {
        if e.stores {
            v.push(e.potential);
        }
        v.push(e.work);
    }
    if gravity {
        v.push(b.gravity.potential);
        v.push(b.gravity.work);
    }
    v.extend([
        b.drivers,
        b.applied,
        b.constraints,
        b.impacts,
        b.projections,
        b.residual(),
    ]);
    v.into_iter().map(|x| Cell::Num(Some(x))).collect()
}
