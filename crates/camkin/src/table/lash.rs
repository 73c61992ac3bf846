//! The table of a lash sweep (`camkin simulate SYSTEM.toml --lash FROM:TO:STEP`): a row per lash
//! and lashed contact, its take-up and the seating that ends its lift, at the first driver's
//! angles, with their approach speeds (lengths in the system's unit).

use super::column::Cell;

/// One lash and lashed contact of a lash sweep
/// ([`crate::spec::BuiltSystem::lash_sweep`]). A take-up or seating the run did not have is
/// empty.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct LashRow {
    /// the lash, the system's length unit
    pub lash: f64,
    /// the lashed contact's name
    pub contact: String,
    /// the first driver's angle at the take-up, degrees
    pub take_up_angle_deg: Option<f64>,
    /// the take-up's approach speed, length unit per s
    pub take_up_speed: Option<f64>,
    /// the contact the valve seats on
    pub seat: Option<String>,
    /// the first driver's angle at the seating, degrees
    pub seating_angle_deg: Option<f64>,
    /// the seating's approach speed, length unit per s
    pub seating_speed: Option<f64>,
}

/// The columns of a lash sweep's rows, lengths in `unit`.
pub fn lash_columns(unit: &str) -> Vec<String> {
    vec![
        format!("lash_{unit}"),
        "contact".into(),
        "take_up_angle_deg".into(),
        format!("take_up_speed_{unit}_s"),
        "seat".into(),
        "seating_angle_deg".into(),
        format!("seating_speed_{unit}_s"),
    ]
}

/// One row's cells, under [`lash_columns`].
pub fn lash_cells(r: &LashRow) -> Vec<Cell> {
    vec![
        Cell::Num(Some(r.lash)),
        Cell::Text(Some(r.contact.clone())),
        Cell::Num(r.take_up_angle_deg),
        Cell::Num(r.take_up_speed),
        Cell::Text(r.seat.clone()),
        Cell::Num(r.seating_angle_deg),
        Cell::Num(r.seating_speed),
    ]
}
