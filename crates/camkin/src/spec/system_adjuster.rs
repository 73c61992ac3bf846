//! `[[lash_adjuster]]` of a system file: a hydraulic lash adjuster between two bodies
//! ([`crate::system::LashAdjuster`]): its bore, chamber and plunger gap in the file's length
//! unit (the clearance in µm), the oil's viscosity (mPa·s), bulk modulus (MPa) and air, its
//! supply and check valve in bar, its plunger spring.

use super::build::SpecError;
use crate::field::{Field, SystemField, SystemKey as K, SystemTable};
use crate::geometry::Point2;
use crate::system::{BodyId, LashAdjuster};

/// `[[lash_adjuster]]` (see the module's docs; docs/valve-train.md#hydraulic-lash-adjusters).
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LashAdjusterSpec {
    /// its name
    pub name: String,
    /// the body of its bore, and the body its plunger pushes
    #[serde(deserialize_with = "super::pair::names")]
    pub bodies: [String; 2],
    /// its two ends, each in its body's frame: it pushes them apart along the line between
    #[serde(deserialize_with = "super::pair::points")]
    pub at: [[f64; 2]; 2],
    /// the plunger's diameter, length unit
    pub bore: f64,
    /// the chamber's height under the plunger as the file draws the bodies, length unit
    pub chamber_length: f64,
    /// the plunger's radial clearance in its bore, µm (0: no leak)
    pub clearance_um: f64,
    /// the length of the plunger's sealing gap, length unit
    pub leak_length: f64,
    /// the oil's dynamic viscosity, mPa·s (10 for a hot engine oil)
    pub viscosity_mpa_s: f64,
    /// the oil's bulk modulus, MPa (default 1500)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bulk_modulus_mpa: Option<f64>,
    /// free air's volume fraction at atmospheric pressure, 0 to 0.5 (default 0)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub air_fraction: Option<f64>,
    /// the oil supply's gauge pressure, bar
    pub supply_bar: f64,
    /// the check valve's opening pressure, bar (default 0)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub check_opening_bar: Option<f64>,
    /// the check valve's flow open, length unit³ per s per bar of pressure across it
    pub check_flow: f64,
    /// the plunger spring's stiffness, N per length unit (default 0)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<f64>,
    /// the plunger spring's push at the drawn length, N (default 0)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preload: Option<f64>,
    /// the chamber's gauge pressure at the start, bar (default the supply's)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub initial_pressure_bar: Option<f64>,
}

const BAR: f64 = 1e5;

/// Lash adjuster `i` between `(a, at_a)` and `(b, at_b)` (in the system's unit; `drawn` its
/// length as the file places the bodies), lengths in the file times `scale`.
#[allow(clippy::too_many_arguments)]
pub(super) fn lash_adjuster(
    s: &LashAdjusterSpec,
    i: usize,
    (a, at_a): (BodyId, Point2),
    (b, at_b): (BodyId, Point2),
    drawn: f64,
    scale: f64,
    metres_per_unit: f64,
) -> Result<LashAdjuster, SpecError> {
    let f = |key| {
        Field::System(SystemField {
            table: SystemTable::LashAdjuster,
            index: i,
            key,
        })
    };
    let h = crate::human::human;
    let check = |key: K, x: f64, ok: bool, what: &str| -> Result<f64, SpecError> {
        if ok && x.is_finite() {
            Ok(x)
        } else {
            Err(SpecError::Invalid {
                field: f(key),
                value: h(x),
                reason: format!("must be {what}"),
            })
        }
    };
    let positive = |key: K, x: f64| check(key, x, x > 0.0 && x < 1e12, "positive");
    let non_negative = |key: K, x: f64| check(key, x, (0.0..1e12).contains(&x), "zero or more");
    let supply = non_negative(K::SupplyBar, s.supply_bar)? * BAR;
    let initial = match s.initial_pressure_bar {
        Some(p) => {
            check(
                K::InitialPressureBar,
                p,
                p * BAR > -crate::system::ATMOSPHERE && p < 1e7,
                "above −1.01325 bar (absolute zero)",
            )? * BAR
        }
        None => supply,
    };
    let adjuster = LashAdjuster {
        a,
        at_a,
        b,
        at_b,
        bore: scale * positive(K::Bore, s.bore)?,
        chamber: scale * positive(K::ChamberLength, s.chamber_length)?,
        drawn_length: drawn,
        // µm, whatever the file's unit
        clearance: 1e-6 / metres_per_unit * non_negative(K::ClearanceUm, s.clearance_um)?,
        leak_length: scale * positive(K::LeakLength, s.leak_length)?,
        viscosity: 1e-3 * positive(K::ViscosityMpaS, s.viscosity_mpa_s)?,
        bulk_modulus: 1e6 * positive(K::BulkModulusMpa, s.bulk_modulus_mpa.unwrap_or(1500.0))?,
        air_fraction: check(
            K::AirFraction,
            s.air_fraction.unwrap_or(0.0),
            (0.0..=0.5).contains(&s.air_fraction.unwrap_or(0.0)),
            "from 0 to 0.5",
        )?,
        supply,
        check_opening: non_negative(K::CheckOpeningBar, s.check_opening_bar.unwrap_or(0.0))? * BAR,
        check_flow: scale * scale * scale * non_negative(K::CheckFlow, s.check_flow)? / BAR,
        spring_stiffness: non_negative(K::Stiffness, s.stiffness.unwrap_or(0.0))? / scale,
        spring_preload: check(
            K::Preload,
            s.preload.unwrap_or(0.0),
            s.preload.unwrap_or(0.0).abs() < 1e12,
            "finite",
        )?,
        initial_pressure: initial,
        metres_per_unit,
    };
    Ok(adjuster)
}
