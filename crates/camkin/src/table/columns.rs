//! The analysis table's columns with their units (`camkin analyze`, the Python package's
//! `Mechanism.analyze`): [`AnalysisRow`] converted and named by [`Units`].

use super::units::Units;
use super::AnalysisRow;

/// One cell of a table whose column names are only known at run time (they carry units).
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// a number (absent: an empty CSV cell, JSON `null`, NaN in an array)
    Num(Option<f64>),
    /// a small whole number
    Int(Option<u8>),
    /// a count or an index
    Count(Option<u32>),
    /// yes or no (CSV `true`/`false`, JSON a boolean)
    Flag(Option<bool>),
    /// text
    Text(Option<String>),
}

#[cfg(feature = "serde")]
impl serde::Serialize for Cell {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        match self {
            Cell::Num(Some(x)) => s.serialize_f64(*x),
            Cell::Int(Some(x)) => s.serialize_u8(*x),
            Cell::Count(Some(x)) => s.serialize_u32(*x),
            Cell::Flag(Some(x)) => s.serialize_bool(*x),
            Cell::Text(Some(x)) => s.serialize_str(x),
            _ => s.serialize_none(),
        }
    }
}

/// The column names of the analysis table, each with its unit.
pub fn analysis_columns(u: &Units) -> Vec<String> {
    let l = u.len();
    let mut c = vec![
        "angle_deg".to_string(),
        format!("position_{}", u.motion_key(0)),
        format!("lift_{}", u.motion_key(0)),
        format!("velocity_{}", u.motion_key(1)),
        format!("acceleration_{}", u.motion_key(2)),
        format!("jerk_{}", u.motion_key(3)),
    ];
    for name in ["contact_x", "contact_y", "cam_x", "cam_y"] {
        c.push(format!("{name}_{l}"));
    }
    c.push("cam_param".into());
    c.push(format!("sliding_rate_cam_{l}_s"));
    c.push(format!("sliding_rate_follower_{l}_s"));
    for name in [
        "normal_accel_cam",
        "coriolis_cam",
        "relative_cam",
        "normal_accel_follower",
    ] {
        c.push(format!("{name}_{l}_s2"));
    }
    for name in ["normal_x", "normal_y", "sigma", "pressure_angle_deg"] {
        c.push(name.into());
    }
    c.push(format!("radius_of_curvature_{l}"));
    if u.carried {
        c.push("corner".into());
    }
    if u.conjugate {
        c.push(format!("conjugate_play_{}", u.motion_key(0)));
    }
    for name in ["at_node", "found", "error"] {
        c.push(name.into());
    }
    c
}

/// One row's cells, in the order of [`analysis_columns`].
pub fn analysis_cells(r: &AnalysisRow, u: &Units) -> Vec<Cell> {
    let n = Cell::Num;
    let m = match (r.position, r.velocity, r.acceleration) {
        (Some(q), Some(v), Some(a)) => u.motion(q, v, a, r.jerk),
        _ => [None; 4],
    };
    let lift = r.lift.map(|l| u.coord_value(l));
    let mut cells = vec![
        n(Some(r.angle_deg)),
        n(m[0]),
        n(lift),
        n(m[1]),
        n(m[2]),
        n(m[3]),
        n(r.contact_x),
        n(r.contact_y),
        n(r.cam_x),
        n(r.cam_y),
        n(r.cam_param),
        n(r.sliding_rate_cam),
        n(r.sliding_rate_follower),
        n(r.normal_accel_cam),
        n(r.coriolis_cam),
        n(r.relative_cam),
        n(r.normal_accel_follower),
        n(r.normal_x),
        n(r.normal_y),
        n(r.sigma),
        n(r.pressure_angle_deg),
        n(r.radius_of_curvature),
    ];
    if u.carried {
        cells.push(Cell::Text(r.corner.map(str::to_string)));
    }
    if u.conjugate {
        cells.push(n(r.conjugate_play.map(|p| u.coord_value(p))));
    }
    cells.extend([
        Cell::Int(r.at_node),
        Cell::Text(r.found.map(|f| f.name().to_string())),
        Cell::Text(r.error.clone()),
    ]);
    cells
}

/// The column names of a simulation's time series (`camkin simulate`), each with its unit.
pub fn sample_columns(u: &Units) -> Vec<String> {
    let mut c: Vec<String> = vec![
        "time_s".into(),
        "cam_angle_deg".into(),
        format!("position_{}", u.motion_key(0)),
        format!("velocity_{}", u.motion_key(1)),
        format!("acceleration_{}", u.motion_key(2)),
        "contact_force_N".into(),
        "in_contact".into(),
        format!("kinematic_position_{}", u.motion_key(0)),
        format!("kinematic_acceleration_{}", u.motion_key(2)),
    ];
    if u.conjugate {
        c.push("on_conjugate".into());
    }
    c
}

/// Lengths of a simulation (metres) in the mechanism file's unit: the factor.
fn from_metres(u: &Units) -> f64 {
    if u.oscillating {
        1.0
    } else {
        1.0 / u.length.metres()
    }
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
    let mut cells = vec![
        Cell::Num(Some(r.time)),
        Cell::Num(Some(r.cam_angle_deg)),
        Cell::Num(m[0]),
        Cell::Num(m[1]),
        Cell::Num(m[2]),
        Cell::Num(Some(r.contact_force)),
        Cell::Int(Some(r.in_contact)),
        Cell::Num(km[0]),
        Cell::Num(km[2]),
    ];
    if u.conjugate {
        cells.push(Cell::Int(Some(r.on_conjugate)));
    }
    cells
}

/// The column names of a simulation's events.
pub fn event_columns(u: &Units) -> Vec<String> {
    let mut c: Vec<String> = vec![
        "event".into(),
        "time_s".into(),
        "cam_angle_deg".into(),
        format!("impact_velocity_{}_s", u.len()),
    ];
    if u.conjugate {
        c.push("curve".into());
    }
    c
}

/// One event's cells, in the order of [`event_columns`].
pub fn event_cells(e: &super::EventRow, u: &Units) -> Vec<Cell> {
    let mut cells = vec![
        Cell::Text(Some(e.event.to_string())),
        Cell::Num(Some(e.time)),
        Cell::Num(Some(e.cam_angle_deg)),
        Cell::Num(Some(e.impact_velocity / u.length.metres())),
    ];
    if u.conjugate {
        cells.push(Cell::Text(Some(e.curve.to_string())));
    }
    cells
}
