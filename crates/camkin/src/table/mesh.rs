//! The gear-mesh table (`camkin mesh`): one [`MeshRow`] per driver angle, read from a gear pair's
//! [`MeshState`](crate::gears::MeshState), with its columns named and converted by [`Units`].

use super::column::Cell;
use super::column::{fixed, named, names, Col};
use super::units::Units;
use super::FoundBy;
use crate::cam::{CamError, FollowerState, Mechanism};
use crate::curve::FlankSide;
use crate::gears::GearPair;

/// One row of the mesh table: the pair's state at one driver angle. A row that could not be
/// computed has only `angle_deg` and `error`. Angles in rad, lengths in the mechanism's unit,
/// time in seconds (the columns convert: see [`mesh_columns`]).
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct MeshRow {
    /// the driver's angle, degrees, as asked for
    pub angle_deg: f64,
    /// the driven gear's angle, rad (counter-clockwise)
    pub driven_angle: Option<f64>,
    /// `φ̇₂/ψ̇₁` (signed: `−z1/z2` for ideal gears turning in opposite senses)
    pub speed_ratio: Option<f64>,
    /// the driven gear's angular acceleration, rad/s²
    pub driven_acceleration: Option<f64>,
    /// transmission error `φ₂ − φ₂,ideal`, rad
    pub transmission_error: Option<f64>,
    /// the same along the line of action, `r_b2 · TE`, length
    pub transmission_error_length: Option<f64>,
    /// its rate, rad/s
    pub transmission_error_rate: Option<f64>,
    /// its second derivative, rad/s²
    pub transmission_error_acceleration: Option<f64>,
    /// the driver's tooth in contact
    pub driver_tooth: Option<u32>,
    /// the driven gear's tooth in contact
    pub driven_tooth: Option<u32>,
    /// the driver's flank in contact
    pub driver_flank: Option<FlankSide>,
    /// the contact on both involutes (not a tip, root or fillet)
    pub on_flanks: Option<bool>,
    /// tooth pairs touching, this one included
    pub pairs_in_contact: Option<u32>,
    /// the contact along the line of action from the pitch point, length (towards the driven
    /// gear's base circle)
    pub line_of_action: Option<f64>,
    /// its distance from the line of action, length
    pub line_of_action_offset: Option<f64>,
    /// the flanks' sliding velocity, length/s
    pub sliding_velocity: Option<f64>,
    /// the driver flank's specific sliding
    pub specific_sliding_driver: Option<f64>,
    /// the driven flank's specific sliding
    pub specific_sliding_driven: Option<f64>,
    /// how the contact was found (`jump`: another tooth pair took over, or the contact jumped)
    pub found: Option<FoundBy>,
    /// why the row could not be computed
    pub error: Option<String>,
}

impl MeshRow {
    /// The row of one result of `mech` (the mechanism of `pair`); `jump` marks a contact that
    /// jumped since the previous row.
    pub fn new(
        pair: &GearPair,
        mech: &Mechanism,
        angle_deg: f64,
        result: &Result<FollowerState, CamError>,
        jump: bool,
    ) -> Self {
        match result {
            Ok(s) => {
                let g = pair.mesh(mech, s);
                Self {
                    angle_deg,
                    driven_angle: Some(g.driven_angle),
                    speed_ratio: Some(g.speed_ratio),
                    driven_acceleration: Some(g.driven_acceleration),
                    transmission_error: Some(g.transmission_error),
                    transmission_error_length: Some(g.transmission_error_length),
                    transmission_error_rate: Some(g.transmission_error_rate),
                    transmission_error_acceleration: Some(g.transmission_error_acceleration),
                    driver_tooth: Some(g.driver_tooth),
                    driven_tooth: Some(g.driven_tooth),
                    driver_flank: Some(g.driver_flank),
                    on_flanks: Some(g.on_flanks),
                    pairs_in_contact: Some(g.pairs_in_contact),
                    line_of_action: Some(g.line_of_action_position),
                    line_of_action_offset: Some(g.line_of_action_offset),
                    sliding_velocity: Some(g.sliding_velocity),
                    specific_sliding_driver: g.specific_sliding_driver,
                    specific_sliding_driven: g.specific_sliding_driven,
                    found: Some(FoundBy::of(s.found, jump)),
                    error: None,
                }
            }
            Err(e) => Self {
                angle_deg,
                error: Some(e.to_string()),
                ..Self::default()
            },
        }
    }
}

/// µrad per rad.
const MICRO: f64 = 1e6;

/// The column names of the mesh table, each with its unit (transmission error and its rates in
/// The mesh table (`camkin mesh`, `Mechanism.mesh`): each column once.
static MESH: &[Col<MeshRow, ()>] = &[
    fixed!("angle_deg", |r, _| Cell::Num(Some(r.angle_deg))),
    fixed!("driven_angle_deg", |r, _| {
        Cell::Num(r.driven_angle.map(f64::to_degrees))
    }),
    fixed!("speed_ratio", |r, _| Cell::Num(r.speed_ratio)),
    fixed!("driven_acceleration_rad_s2", |r, _| {
        Cell::Num(r.driven_acceleration)
    }),
    fixed!("transmission_error_urad", |r, _| {
        Cell::Num(r.transmission_error.map(|x| x * MICRO))
    }),
    named!(|u| format!("transmission_error_{}", u.len()), |r, _| {
        Cell::Num(r.transmission_error_length)
    }),
    fixed!("transmission_error_rate_urad_s", |r, _| {
        Cell::Num(r.transmission_error_rate.map(|x| x * MICRO))
    }),
    fixed!("transmission_error_acceleration_urad_s2", |r, _| {
        Cell::Num(r.transmission_error_acceleration.map(|x| x * MICRO))
    }),
    fixed!("driver_tooth", |r, _| Cell::Count(r.driver_tooth)),
    fixed!("driven_tooth", |r, _| Cell::Count(r.driven_tooth)),
    fixed!("driver_flank", |r, _| {
        Cell::Text(r.driver_flank.map(|f| {
            match f {
                FlankSide::Clockwise => "cw",
                FlankSide::CounterClockwise => "ccw",
            }
            .to_string()
        }))
    }),
    fixed!("on_flanks", |r, _| Cell::Flag(r.on_flanks)),
    fixed!("pairs_in_contact", |r, _| Cell::Count(r.pairs_in_contact)),
    named!(|u| format!("line_of_action_{}", u.len()), |r, _| {
        Cell::Num(r.line_of_action)
    }),
    named!(|u| format!("line_of_action_offset_{}", u.len()), |r, _| {
        Cell::Num(r.line_of_action_offset)
    }),
    named!(|u| format!("sliding_velocity_{}_s", u.len()), |r, _| {
        Cell::Num(r.sliding_velocity)
    }),
    fixed!("specific_sliding_driver", |r, _| {
        Cell::Num(r.specific_sliding_driver)
    }),
    fixed!("specific_sliding_driven", |r, _| {
        Cell::Num(r.specific_sliding_driven)
    }),
    fixed!("found", |r, _| Cell::Text(
        r.found.map(|f| f.name().to_string())
    )),
    fixed!("error", |r, _| Cell::Text(r.error.clone())),
];

/// The column names of the mesh table, each with its unit.
pub fn mesh_columns(u: &Units) -> Vec<String> {
    names(MESH, u)
}

/// One row's cells, in the order of [`mesh_columns`].
pub fn mesh_cells(r: &MeshRow) -> Vec<Cell> {
    // no mesh column depends on the units for its cell or its presence
    MESH.iter().map(|c| (c.cell)(r, &())).collect()
}
