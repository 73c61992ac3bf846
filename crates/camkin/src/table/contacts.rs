//! The contacts table (`camkin contacts`, the Python package's `Mechanism.contacts`): one
//! [`ContactRow`] per contact per cam angle, from [`Mechanism::contacts_at`](crate::cam::Mechanism::contacts_at),
//! with its columns named and converted by [`Units`].

use super::column::Cell;
use super::column::{cells, fixed, named, names, Col};
use super::units::Units;
use crate::cam::{CamContact, CamError};

/// One contact at one cam angle. A row for an angle that could not be analysed has only
/// `angle_deg` and `error`. Lengths in the mechanism's unit, time in s; the constraint row is
/// in rad for angles (the cam's and an arm's).
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct ContactRow {
    /// the cam angle, degrees, as asked for
    pub angle_deg: f64,
    /// the contact's number at this angle: 0 for the follower's first touch
    pub contact: Option<u32>,
    /// which curve of the follower touches: `follower` (its own), `conjugate` (a form-closed
    /// follower's second curve)
    pub curve: Option<&'static str>,
    /// which curve has a corner at the contact (`cam`, `follower`; none for a tangency)
    pub corner: Option<&'static str>,
    /// the cam-profile parameter at the contact
    pub cam_param: Option<f64>,
    /// the follower curve's parameter at the contact
    pub follower_param: Option<f64>,
    /// the contact point, world frame, length
    pub x: Option<f64>,
    /// the contact point, world frame, length
    pub y: Option<f64>,
    /// the common normal (the cam profile's left normal), world frame
    pub normal_x: Option<f64>,
    /// the common normal's y component
    pub normal_y: Option<f64>,
    /// how far the follower would move in its closing sense before this contact alone
    /// touches, length (zero within the touch tolerance); a conjugate curve's play (negative:
    /// interference)
    pub gap: Option<f64>,
    /// `ν·(v_A − v_B)` at the follower's motion, length/s (zero where the motion keeps the
    /// contact closed)
    pub normal_velocity: Option<f64>,
    /// sliding rate along the cam profile, length/s
    pub sliding_rate_cam: Option<f64>,
    /// sliding rate along the follower's curve, length/s
    pub sliding_rate_follower: Option<f64>,
    /// normal acceleration of the contact point seen from the cam (eq. 1), length/s²
    pub normal_acceleration_cam: Option<f64>,
    /// seen from the follower (eq. 2), length/s²
    pub normal_acceleration_follower: Option<f64>,
    /// `Φ_θ`, length/rad
    pub row_cam: Option<f64>,
    /// `Φ_q`, length per unit of the follower's coordinate (length or rad)
    pub row_follower: Option<f64>,
    /// `γ`, length/s²
    pub gamma: Option<f64>,
    /// `Φ_θ θ̈ + Φ_q q̈ − γ` at the state's motion, length/s²
    pub residual: Option<f64>,
    /// why the angle could not be analysed
    pub error: Option<String>,
}

impl ContactRow {
    /// The rows of one angle's contacts (one row with the error when there are none).
    pub fn of(angle_deg: f64, result: &Result<Vec<CamContact>, CamError>) -> Vec<Self> {
        match result {
            Ok(cs) => cs
                .iter()
                .enumerate()
                .map(|(i, c)| Self {
                    angle_deg,
                    contact: u32::try_from(i).ok(),
                    curve: Some(if c.conjugate { "conjugate" } else { "follower" }),
                    corner: c.corner.map(crate::cam::Corner::name),
                    cam_param: Some(c.cam_param),
                    follower_param: Some(c.follower_param),
                    x: Some(c.point.x),
                    y: Some(c.point.y),
                    normal_x: Some(c.normal.x),
                    normal_y: Some(c.normal.y),
                    gap: Some(c.gap),
                    normal_velocity: Some(c.normal_velocity),
                    sliding_rate_cam: Some(c.sliding_rate_cam),
                    sliding_rate_follower: Some(c.sliding_rate_follower),
                    normal_acceleration_cam: Some(c.normal_acceleration_cam.total()),
                    normal_acceleration_follower: Some(c.normal_acceleration_follower.total()),
                    row_cam: Some(c.row_cam),
                    row_follower: Some(c.row_follower),
                    gamma: Some(c.gamma),
                    residual: Some(c.residual),
                    error: None,
                })
                .collect(),
            Err(e) => vec![Self {
                angle_deg,
                error: Some(e.to_string()),
                ..Self::default()
            }],
        }
    }
}

/// The contact table (`camkin contacts`, `Mechanism.contacts`): each column once.
static CONTACTS: &[Col<ContactRow, ()>] = &[
    fixed!("angle_deg", |r, _| Cell::Num(Some(r.angle_deg))),
    fixed!("contact", |r, _| Cell::Count(r.contact)),
    fixed!("curve", |r, _| Cell::Text(r.curve.map(str::to_string))),
    fixed!("cam_param", |r, _| Cell::Num(r.cam_param)),
    fixed!("follower_param", |r, _| Cell::Num(r.follower_param)),
    named!(|u| format!("x_{}", u.len()), |r, _| Cell::Num(r.x)),
    named!(|u| format!("y_{}", u.len()), |r, _| Cell::Num(r.y)),
    fixed!("normal_x", |r, _| Cell::Num(r.normal_x)),
    fixed!("normal_y", |r, _| Cell::Num(r.normal_y)),
    named!(|u| format!("gap_{}", u.len()), |r, _| Cell::Num(r.gap)),
    named!(|u| format!("normal_velocity_{}_s", u.len()), |r, _| {
        Cell::Num(r.normal_velocity)
    }),
    named!(|u| format!("sliding_rate_cam_{}_s", u.len()), |r, _| {
        Cell::Num(r.sliding_rate_cam)
    }),
    named!(
        |u| format!("sliding_rate_follower_{}_s", u.len()),
        |r, _| { Cell::Num(r.sliding_rate_follower) }
    ),
    named!(
        |u| format!("normal_acceleration_cam_{}_s2", u.len()),
        |r, _| { Cell::Num(r.normal_acceleration_cam) }
    ),
    named!(
        |u| format!("normal_acceleration_follower_{}_s2", u.len()),
        |r, _| { Cell::Num(r.normal_acceleration_follower) }
    ),
    named!(
        |u| format!("row_cam_{}_per_rad", u.len()),
        |r, _| Cell::Num(r.row_cam)
    ),
    named!(
        |u| format!(
            "row_follower_{}_per_{}",
            u.len(),
            if u.oscillating { "rad" } else { u.len() }
        ),
        |r, _| Cell::Num(r.row_follower)
    ),
    named!(|u| format!("gamma_{}_s2", u.len()), |r, _| Cell::Num(
        r.gamma
    )),
    named!(|u| format!("residual_{}_s2", u.len()), |r, _| Cell::Num(
        r.residual
    )),
    Col {
        name: |_| "corner".into(),
        when: |u| u.carried,
        cell: |r, _| Cell::Text(r.corner.map(str::to_string)),
    },
    fixed!("error", |r, _| Cell::Text(r.error.clone())),
];

/// The column names of the contact table, each with its unit.
pub fn contact_columns(u: &Units) -> Vec<String> {
    names(CONTACTS, u)
}

/// One row's cells, in the order of [`contact_columns`].
pub fn contact_cells(r: &ContactRow, u: &Units) -> Vec<Cell> {
    cells(CONTACTS, u, r, &())
}
