//! The analysis table's columns with their units (`camkin analyze`, the Python package's
//! `Mechanism.analyze`): [`AnalysisRow`] converted and named by [`Units`].

use super::column::{cells, fixed, named, names, Cell, Col};
use super::units::Units;
use super::AnalysisRow;

/// What an analysis row's cells share: its motion in the table's units.
pub(crate) struct A {
    /// position, velocity, acceleration, jerk converted ([`Units::motion`])
    m: [Option<f64>; 4],
    /// the lift and a conjugate's play in the position's unit
    lift: Option<f64>,
    play: Option<f64>,
}

/// The analysis table (`camkin analyze`, `Mechanism.analyze`): each column once.
static ANALYSIS: &[Col<AnalysisRow, A>] = &[
    fixed!("angle_deg", |r, _| Cell::Num(Some(r.angle_deg))),
    named!(|u| format!("position_{}", u.motion_key(0)), |_, x| {
        Cell::Num(x.m[0])
    }),
    named!(|u| format!("lift_{}", u.motion_key(0)), |_, x| {
        Cell::Num(x.lift)
    }),
    named!(|u| format!("velocity_{}", u.motion_key(1)), |_, x| {
        Cell::Num(x.m[1])
    }),
    named!(|u| format!("acceleration_{}", u.motion_key(2)), |_, x| {
        Cell::Num(x.m[2])
    }),
    named!(|u| format!("jerk_{}", u.motion_key(3)), |_, x| Cell::Num(
        x.m[3]
    )),
    named!(|u| format!("contact_x_{}", u.len()), |r, _| Cell::Num(
        r.contact_x
    )),
    named!(|u| format!("contact_y_{}", u.len()), |r, _| Cell::Num(
        r.contact_y
    )),
    named!(|u| format!("cam_x_{}", u.len()), |r, _| Cell::Num(r.cam_x)),
    named!(|u| format!("cam_y_{}", u.len()), |r, _| Cell::Num(r.cam_y)),
    fixed!("cam_param", |r, _| Cell::Num(r.cam_param)),
    named!(|u| format!("sliding_rate_cam_{}_s", u.len()), |r, _| {
        Cell::Num(r.sliding_rate_cam)
    }),
    named!(
        |u| format!("sliding_rate_follower_{}_s", u.len()),
        |r, _| { Cell::Num(r.sliding_rate_follower) }
    ),
    named!(|u| format!("normal_accel_cam_{}_s2", u.len()), |r, _| {
        Cell::Num(r.normal_accel_cam)
    }),
    named!(
        |u| format!("coriolis_cam_{}_s2", u.len()),
        |r, _| Cell::Num(r.coriolis_cam)
    ),
    named!(
        |u| format!("relative_cam_{}_s2", u.len()),
        |r, _| Cell::Num(r.relative_cam)
    ),
    named!(
        |u| format!("normal_accel_follower_{}_s2", u.len()),
        |r, _| { Cell::Num(r.normal_accel_follower) }
    ),
    fixed!("normal_x", |r, _| Cell::Num(r.normal_x)),
    fixed!("normal_y", |r, _| Cell::Num(r.normal_y)),
    fixed!("sigma", |r, _| Cell::Num(r.sigma)),
    fixed!("pressure_angle_deg", |r, _| Cell::Num(r.pressure_angle_deg)),
    named!(|u| format!("radius_of_curvature_{}", u.len()), |r, _| {
        Cell::Num(r.radius_of_curvature)
    }),
    Col {
        name: |_| "corner".into(),
        when: |u| u.carried,
        cell: |r, _| Cell::Text(r.corner.map(str::to_string)),
    },
    Col {
        name: |u| format!("conjugate_play_{}", u.motion_key(0)),
        when: |u| u.conjugate,
        cell: |_, x| Cell::Num(x.play),
    },
    fixed!("at_node", |r, _| Cell::Int(r.at_node)),
    fixed!("found", |r, _| Cell::Text(
        r.found.map(|f| f.name().to_string())
    )),
    fixed!("error", |r, _| Cell::Text(r.error.clone())),
];

/// The column names of the analysis table, each with its unit.
pub fn analysis_columns(u: &Units) -> Vec<String> {
    names(ANALYSIS, u)
}

/// One row's cells, in the order of [`analysis_columns`].
pub fn analysis_cells(r: &AnalysisRow, u: &Units) -> Vec<Cell> {
    let m = match (r.position, r.velocity, r.acceleration) {
        (Some(q), Some(v), Some(a)) => u.motion(q, v, a, r.jerk),
        _ => [None; 4],
    };
    let (lift, play) = (
        r.lift.map(|l| u.coord_value(l)),
        r.conjugate_play.map(|p| u.coord_value(p)),
    );
    cells(ANALYSIS, u, r, &A { m, lift, play })
}

/// Lengths of a simulation (metres) in the mechanism file's unit: the factor.
fn from_metres(u: &Units) -> f64 {
    if u.oscillating {
        1.0
    } else {
        1.0 / u.length.metres()
    }
}

/// What a simulation sample's cells share: its motion and the kinematic motion in the table's
/// units.
pub(crate) struct S {
    m: [Option<f64>; 4],
    km: [Option<f64>; 4],
    /// N·L per J (energies and torques in the file's length unit)
    energy: f64,
}

/// The energy balance's part `k` ([`crate::dynamics::EnergyBalance::PARTS`]), N·L.
macro_rules! balance {
    ($k:expr) => {
        named!(
            |u| format!(
                "{}_N_{}",
                crate::dynamics::EnergyBalance::PARTS[$k],
                u.len()
            ),
            |r, x| { Cell::Num(Some(r.balance[$k] * x.energy)) }
        )
    };
}

/// A simulation's time series (`camkin simulate`): each column once.
static SAMPLES: &[Col<super::SampleRow, S>] = &[
    fixed!("time_s", |r, _| Cell::Num(Some(r.time))),
    fixed!("cam_angle_deg", |r, _| Cell::Num(Some(r.cam_angle_deg))),
    named!(|u| format!("position_{}", u.motion_key(0)), |_, x| {
        Cell::Num(x.m[0])
    }),
    named!(|u| format!("velocity_{}", u.motion_key(1)), |_, x| {
        Cell::Num(x.m[1])
    }),
    named!(|u| format!("acceleration_{}", u.motion_key(2)), |_, x| {
        Cell::Num(x.m[2])
    }),
    fixed!("contact_force_N", |r, _| Cell::Num(Some(r.contact_force))),
    fixed!("in_contact", |r, _| Cell::Int(Some(r.in_contact))),
    named!(
        |u| format!("kinematic_position_{}", u.motion_key(0)),
        |_, x| { Cell::Num(x.km[0]) }
    ),
    named!(
        |u| format!("kinematic_acceleration_{}", u.motion_key(2)),
        |_, x| { Cell::Num(x.km[2]) }
    ),
    Col {
        name: |_| "on_conjugate".into(),
        when: |u| u.conjugate,
        cell: |r, _| Cell::Int(Some(r.on_conjugate)),
    },
    named!(|u| format!("driver_torque_N_{}", u.len()), |r, x| {
        Cell::Num(Some(r.driver_torque * x.energy))
    }),
    named!(|u| format!("driver_work_N_{}", u.len()), |r, x| {
        Cell::Num(Some(r.driver_work * x.energy))
    }),
    balance!(0),
    balance!(1),
    balance!(2),
    balance!(3),
    balance!(4),
    balance!(5),
];

/// The column names of a simulation's time series (`camkin simulate`), each with its unit.
pub fn sample_columns(u: &Units) -> Vec<String> {
    names(SAMPLES, u)
}

/// One sample's cells, in the order of [`sample_columns`] (the simulation ran in metres; lengths
/// are written back in the file's unit).
pub fn sample_cells(r: &super::SampleRow, u: &Units) -> Vec<Cell> {
    let k = from_metres(u);
    let m = u.motion(k * r.position, k * r.velocity, k * r.acceleration, None);
    let km = u.motion(
        k * r.kinematic_position,
        0.0,
        k * r.kinematic_acceleration,
        None,
    );
    let energy = 1.0 / u.length.metres();
    cells(SAMPLES, u, r, &S { m, km, energy })
}

/// A simulation's events: each column once.
static EVENTS: &[Col<super::EventRow, f64>] = &[
    fixed!("event", |r, _| Cell::Text(Some(r.event.to_string()))),
    fixed!("time_s", |r, _| Cell::Num(Some(r.time))),
    fixed!("cam_angle_deg", |r, _| Cell::Num(Some(r.cam_angle_deg))),
    named!(|u| format!("impact_velocity_{}_s", u.len()), |r, x| {
        Cell::Num(Some(r.impact_velocity / x))
    }),
    Col {
        name: |_| "curve".into(),
        when: |u| u.conjugate,
        cell: |r, _| Cell::Text(Some(r.curve.to_string())),
    },
];

/// The column names of a simulation's events.
pub fn event_columns(u: &Units) -> Vec<String> {
    names(EVENTS, u)
}

/// One event's cells, in the order of [`event_columns`].
pub fn event_cells(e: &super::EventRow, u: &Units) -> Vec<Cell> {
    cells(EVENTS, u, e, &u.length.metres())
}
