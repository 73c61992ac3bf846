//! Results as table rows: one type per table, so that every front end (the command's CSV and
//! JSON, the Python package's arrays) reads the same columns from one definition. The field
//! names are the column names; with the `serde` feature the rows derive `Serialize`.
//!
//! Rows keep the library's units: angles in degrees where the column name says `_deg`, lengths in
//! the mechanism's length unit, time in seconds. Numbers are not rounded.

mod column;
mod columns;
mod contacts;
mod grid;
mod lash;
mod mesh;
mod sweep;
mod system;
mod system_dynamics;
mod units;

pub use crate::cam::{contact_jumps, contact_jumps_with};
use crate::cam::{CamError, FollowerState, Found, Mechanism};
use crate::dynamics::{Event, EventKind, Sample};
pub use column::Cell;
pub use columns::{
    analysis_cells, analysis_columns, event_cells, event_columns, sample_cells, sample_columns,
};
pub use contacts::{contact_cells, contact_columns, ContactRow};
pub use grid::AngleGrid;
pub use lash::{lash_cells, lash_columns, LashRow};
pub use mesh::{mesh_cells, mesh_columns, MeshRow};
pub use sweep::{AnalysisSweep, JUMPS_KEPT};
pub use system::{system_cells, system_columns, system_contact_cells, system_contact_columns};
pub use system_dynamics::{
    system_energy_cells, system_energy_columns, system_event_cells, system_event_columns,
    system_force_table, system_sample_cells, system_sample_columns,
};
pub use units::{AngleUnit, Per, Units, UnknownUnit};

/// How a row's contact was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
#[non_exhaustive]
pub enum FoundBy {
    /// a global search (a first angle, or after a failed warm start)
    Global,
    /// Newton's method from the previous row's contact
    Warm,
    /// the contact jumped since the previous row (a global search found a different contact,
    /// or the contact passed over a stretch the follower cannot follow)
    Jump,
}

impl FoundBy {
    /// How a sweep found a row's contact; `jump`: the row's contact jumped since the previous
    /// row, whatever the sweep said.
    pub fn of(found: Found, jump: bool) -> Self {
        match found {
            _ if jump => FoundBy::Jump,
            Found::Global => FoundBy::Global,
            Found::WarmStart => FoundBy::Warm,
            Found::Jump { .. } => FoundBy::Jump,
        }
    }

    /// The name the tables print: `global`, `warm`, `jump`.
    pub fn name(self) -> &'static str {
        match self {
            FoundBy::Global => "global",
            FoundBy::Warm => "warm",
            FoundBy::Jump => "jump",
        }
    }
}

/// One row of the analysis (`camkin analyze`): the follower's motion and the contact at one cam
/// angle. A row that could not be computed has only `angle_deg` and `error`.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct AnalysisRow {
    /// cam angle, degrees, as asked for
    pub angle_deg: f64,
    /// follower position: distance from the cam axis (translating), arm angle in rad (oscillating)
    pub position: Option<f64>,
    /// lift: how far the follower is from its rest position over the revolution, away from the
    /// cam ([`AnalysisRow::with_lift`]; none until then)
    pub lift: Option<f64>,
    /// its time derivative
    pub velocity: Option<f64>,
    /// its second time derivative
    pub acceleration: Option<f64>,
    /// its third time derivative (none at a profile node, where it jumps)
    pub jerk: Option<f64>,
    /// contact point, world frame
    pub contact_x: Option<f64>,
    /// contact point, world frame
    pub contact_y: Option<f64>,
    /// contact point in the cam's frame
    pub cam_x: Option<f64>,
    /// contact point in the cam's frame
    pub cam_y: Option<f64>,
    /// the profile parameter of the contact point
    pub cam_param: Option<f64>,
    /// the sliding rate of the contact point along the cam profile, `ṡ_A` (eq. 3), length/s
    pub sliding_rate_cam: Option<f64>,
    /// along the follower's curve, `ṡ_B` (eq. 4), length/s
    pub sliding_rate_follower: Option<f64>,
    /// the normal acceleration of the contact point seen from the cam (eq. 1), length/s²
    pub normal_accel_cam: Option<f64>,
    /// its Coriolis term, length/s²
    pub coriolis_cam: Option<f64>,
    /// its relative term, length/s²
    pub relative_cam: Option<f64>,
    /// the normal acceleration seen from the follower (eq. 2), length/s²
    pub normal_accel_follower: Option<f64>,
    /// the common normal (the cam profile's left normal), world frame
    pub normal_x: Option<f64>,
    /// the common normal, world frame
    pub normal_y: Option<f64>,
    /// `σ = ±1`: the tangents' relative orientation (eq. 5)
    pub sigma: Option<f64>,
    /// pressure angle, degrees
    pub pressure_angle_deg: Option<f64>,
    /// the cam profile's radius of curvature at the contact, length (∞ on a straight stretch)
    pub radius_of_curvature: Option<f64>,
    /// a conjugate follower's play: how far it can move against its closing sense before its
    /// second curve touches (negative: interference), as `position` ([`Mechanism::conjugate_play`])
    pub conjugate_play: Option<f64>,
    /// which curve has a corner at the contact (`cam`, `follower`; none for a tangency): that
    /// curve is a point there (a carried follower's column)
    pub corner: Option<&'static str>,
    /// 1 when the contact is at a profile node (where the jerk jumps), else 0
    pub at_node: Option<u8>,
    /// how the contact was found
    pub found: Option<FoundBy>,
    /// why the row could not be computed
    pub error: Option<String>,
}

impl AnalysisRow {
    /// The row of one result; `jump` marks a contact that jumped since the previous row.
    pub fn new(angle_deg: f64, result: &Result<FollowerState, CamError>, jump: bool) -> Self {
        match result {
            Ok(s) => Self {
                angle_deg,
                position: Some(s.position),
                lift: None,
                velocity: Some(s.velocity),
                acceleration: Some(s.acceleration),
                jerk: s.jerk,
                contact_x: Some(s.contact_world.x),
                contact_y: Some(s.contact_world.y),
                cam_x: Some(s.contact_cam.x),
                cam_y: Some(s.contact_cam.y),
                cam_param: Some(s.cam_param),
                sliding_rate_cam: Some(s.sliding_rate_cam),
                sliding_rate_follower: Some(s.sliding_rate_follower),
                normal_accel_cam: Some(s.normal_acceleration_cam.total()),
                coriolis_cam: Some(s.normal_acceleration_cam.coriolis),
                relative_cam: Some(s.normal_acceleration_cam.relative),
                normal_accel_follower: Some(s.normal_acceleration_follower.total()),
                normal_x: Some(s.normal.x),
                normal_y: Some(s.normal.y),
                sigma: Some(s.sigma),
                pressure_angle_deg: Some(s.pressure_angle().to_degrees()),
                radius_of_curvature: Some(s.radius_of_curvature),
                conjugate_play: None,
                corner: s.corner.map(crate::cam::Corner::name),
                at_node: Some(u8::from(s.at_breakpoint)),
                found: Some(FoundBy::of(s.found, jump)),
                error: None,
            },
            Err(e) => Self {
                angle_deg,
                error: Some(e.to_string()),
                ..Self::default()
            },
        }
    }
}

impl AnalysisRow {
    /// The row with its lift from the follower's travel ([`Mechanism::travel`]).
    pub fn with_lift(mut self, travel: &crate::cam::Travel) -> Self {
        self.lift = self.position.map(|q| travel.lift(q));
        self
    }
}

/// The analysis rows of a sweep: `angles_deg[k]` gave `results[k]`. `contiguous` says the angles
/// are a range in order (then a contact that passed over a stretch the follower cannot follow
/// between two rows has jumped, and its row says so even when the sweep's warm start held).
pub fn analysis_rows(
    mech: &Mechanism,
    angles_deg: &[f64],
    results: &[Result<FollowerState, CamError>],
    contiguous: bool,
) -> Vec<AnalysisRow> {
    let jumps = contact_jumps(mech, results, contiguous);
    angles_deg
        .iter()
        .zip(results)
        .zip(jumps)
        .map(|((&a, r), j)| AnalysisRow::new(a, r, j))
        .collect()
}

/// One row of a simulation's time series (`camkin simulate`).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SampleRow {
    /// time, s
    pub time: f64,
    /// cam angle, degrees
    pub cam_angle_deg: f64,
    /// follower position (as in [`AnalysisRow::position`])
    pub position: f64,
    /// its time derivative
    pub velocity: f64,
    /// its second time derivative
    pub acceleration: f64,
    /// contact force along the common normal, N, compressive positive; 0 in free flight
    pub contact_force: f64,
    /// 1 while the follower touches the cam, else 0
    pub in_contact: u8,
    /// 1 while the touching curve is the follower's second curve, else 0
    pub on_conjugate: u8,
    /// the position the follower would have in permanent contact (the kinematic motion)
    pub kinematic_position: f64,
    /// the acceleration it would have in permanent contact
    pub kinematic_acceleration: f64,
    /// the torque the cam passes on to the follower, N·m, counter-clockwise positive
    pub driver_torque: f64,
    /// its work since the start, J
    pub driver_work: f64,
    /// the follower's energy balance, J, in the order of
    /// [`crate::dynamics::EnergyBalance::PARTS`]
    pub balance: [f64; 6],
}

impl SampleRow {
    /// The row of a sample, beside the kinematic motion at the same cam angle (`NaN` where it
    /// could not be computed).
    pub fn new(s: &Sample, kinematic: Option<&FollowerState>) -> Self {
        Self {
            time: s.time,
            cam_angle_deg: s.cam_angle.to_degrees(),
            position: s.position,
            velocity: s.velocity,
            acceleration: s.acceleration,
            contact_force: s.contact_force,
            in_contact: u8::from(s.in_contact),
            on_conjugate: u8::from(s.on_conjugate),
            kinematic_position: kinematic.map_or(f64::NAN, |k| k.position),
            kinematic_acceleration: kinematic.map_or(f64::NAN, |k| k.acceleration),
            driver_torque: s.driver_torque,
            driver_work: s.driver_work,
            balance: s.balance.parts(),
        }
    }
}

/// One row of a simulation's events.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct EventRow {
    /// `lift-off`, `impact` or `jump`
    pub event: &'static str,
    /// time, s
    pub time: f64,
    /// cam angle, degrees
    pub cam_angle_deg: f64,
    /// normal approach speed at an impact (0 at a lift-off), m/s
    pub impact_velocity: f64,
    /// the follower's curve: `follower` (its own) or `conjugate` (its second curve)
    pub curve: &'static str,
}

impl From<&Event> for EventRow {
    fn from(e: &Event) -> Self {
        Self {
            event: match e.kind {
                EventKind::LiftOff => "lift-off",
                EventKind::Impact => "impact",
                EventKind::Jump => "jump",
            },
            curve: if e.conjugate { "conjugate" } else { "follower" },
            time: e.time,
            cam_angle_deg: e.cam_angle.to_degrees(),
            impact_velocity: e.impact_velocity,
        }
    }
}
