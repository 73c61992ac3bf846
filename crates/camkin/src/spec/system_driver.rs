//! `[[driver]]` of a system file: the coordinate it drives and its law (an angle at a speed
//! in rpm, a position at a speed in the file's length unit a second, each with an acceleration).

use super::build::{coordinate, finite, SpecError};
use super::kinds::DriverCoordinate;
use super::system::DriverSpec;
use super::system_elements::within;
use crate::field::{Field, SystemField, SystemKey as K, SystemTable as T};
use crate::system::{Coordinate, DriverLaw};

/// The field `key` of driver `index`.
fn at(index: usize, key: K) -> Field {
    Field::System(SystemField {
        table: T::Driver,
        index,
        key,
    })
}

/// Driver `i`'s coordinate and law, lengths times `scale`.
pub(super) fn law(
    d: &DriverSpec,
    i: usize,
    scale: f64,
) -> Result<(Coordinate, DriverLaw), SpecError> {
    let start = within(
        at(i, K::Start),
        finite(at(i, K::Start), d.start.unwrap_or(0.0))?,
        0.0,
        1e9,
    )?;
    let acc = within(
        at(i, K::Acceleration),
        finite(at(i, K::Acceleration), d.acceleration.unwrap_or(0.0))?,
        0.0,
        1e15,
    )?;
    let coord = DriverCoordinate::parse(&d.coordinate).ok_or_else(|| SpecError::Unknown {
        field: at(i, K::Coordinate),
        value: d.coordinate.clone(),
        what: "a coordinate",
        known: DriverCoordinate::names(),
    })?;
    let (coordinate, law) = match coord {
        DriverCoordinate::Angle => {
            if d.speed.is_some() {
                return Err(SpecError::Rule {
                    field: at(i, K::Speed),
                    reason: "an angle's driver takes speed_rpm, not speed".into(),
                });
            }
            let rpm = finite(
                at(i, K::SpeedRpm),
                d.speed_rpm.ok_or_else(|| SpecError::Rule {
                    field: at(i, K::Coordinate),
                    reason: "an angle's driver needs speed_rpm".into(),
                })?,
            )?;
            within(at(i, K::SpeedRpm), rpm, 0.0, 1e9)?;
            (
                Coordinate::Angle,
                DriverLaw::Quadratic {
                    start: start.to_radians(),
                    rate: rpm * std::f64::consts::TAU / 60.0,
                    acceleration: acc.to_radians(),
                },
            )
        }
        c @ (DriverCoordinate::X | DriverCoordinate::Y) => {
            if d.speed_rpm.is_some() {
                return Err(SpecError::Rule {
                    field: at(i, K::SpeedRpm),
                    reason: format!("a driver of {c} takes speed (length/s), not speed_rpm"),
                });
            }
            let v = coordinate(at(i, K::Speed), d.speed.unwrap_or(0.0))?;
            within(at(i, K::Speed), v, 0.0, 1e12)?;
            (
                if c == DriverCoordinate::X {
                    Coordinate::X
                } else {
                    Coordinate::Y
                },
                DriverLaw::Quadratic {
                    start: scale * start,
                    rate: scale * v,
                    acceleration: scale * acc,
                },
            )
        }
    };
    Ok((coordinate, law))
}
