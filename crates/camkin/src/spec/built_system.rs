//! A system as built from a file (a system file, or a cam-follower or gear-pair file read as
//! one), with what the angles of a sweep over it mean and the instant of each.

use super::{LengthUnit, SpecWarning};
use crate::system::System;

/// A system built from its file, with what else the file said.
#[derive(Debug, Clone)]
pub struct BuiltSystem {
    /// the system, in the file's length unit
    pub system: System,
    /// the file's length unit
    pub length_unit: LengthUnit,
    /// what is valid but probably not meant
    pub warnings: Vec<SpecWarning>,
    /// what the angles of a sweep are: the first driver's, or a cam's
    pub sweep_angle: SweepAngle,
    /// how it is simulated: the unit's size, gravity and each contact's restitution (a
    /// system file's `[dynamics]` and `restitution` keys)
    pub dynamics: crate::dynamics::SystemDynamicsOptions,
    /// its coil springs with mass (their masses, segments and coil-clash contacts are in
    /// `system`), for their surge frequencies
    pub coil_springs: Vec<crate::system::CoilSpring>,
    /// whether its file has `[dynamics]`: forces move its free degrees of freedom (it is
    /// simulated; a kinematic analysis needs every one driven)
    pub simulated: bool,
    /// its `[lubrication]`, each contact's (with a face width), when the file has it
    pub lubrication: Option<crate::report::SystemLubricationRequest>,
    /// its `[simulation]`: a run in time, when the file has it
    pub timed_run: Option<super::TimedRun>,
    /// its contacts with a lash ([`BuiltSystem::with_lash`])
    pub lash: Vec<super::Lashed>,
}

/// What the angles a system is swept over mean, and the instant of each.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum SweepAngle {
    /// the first driver's angle (a system file): see [`System::driver_time`]
    FirstDriver,
    /// a cam-follower or gear-pair file as a system: how far the cam has turned in its own
    /// direction (the cam path's cam angle), `θ = ω t + α t²/2`
    Cam {
        /// rad/s at `t = 0`
        speed: f64,
        /// rad/s², in the cam's direction
        angular_acceleration: f64,
    },
}

impl SweepAngle {
    /// The instant at which `sys` is at the sweep angle `angle` (rad); `None` when it cannot
    /// be swept by an angle (its first driver is not an angle at a constant speed) or never
    /// gets there (a cam slowing down).
    pub fn time(&self, sys: &System, angle: f64) -> Option<f64> {
        match *self {
            SweepAngle::FirstDriver => sys.driver_time(angle),
            SweepAngle::Cam {
                speed,
                angular_acceleration,
            } => {
                // 2θ/(ω + √(ω² + 2αθ)): no cancellation for small α
                let t = 2.0 * angle
                    / (speed + (speed * speed + 2.0 * angular_acceleration * angle).sqrt());
                t.is_finite().then_some(t)
            }
        }
    }
}

/// Why a sweep's angles have no instants.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SweepError {
    /// The system's first driver does not turn at a constant speed.
    #[error("a system is swept over its first driver's angle: [[driver]] number 1 must drive an angle, with a speed_rpm")]
    NotAnAngle,
    /// A cam slowing down never turns so far.
    #[error("the driver, slowing down, never turns {}°", crate::human::human(*.angle_deg))]
    NeverReached {
        /// the angle asked, degrees
        angle_deg: f64,
    },
}

impl BuiltSystem {
    /// A cam-follower or gear-pair mechanism as a system
    /// ([`crate::cam::Mechanism::to_system`]), swept over its cam angle.
    pub fn from_mechanism(
        mechanism: &crate::cam::Mechanism,
        length_unit: LengthUnit,
    ) -> Result<Self, crate::cam::CamError> {
        let preset = mechanism.to_system()?;
        let conjugate = mechanism
            .is_conjugate()
            .then_some(SpecWarning::ConjugateLeftOut);
        Ok(Self {
            sweep_angle: preset.sweep_angle(),
            system: preset.system,
            length_unit,
            // the conjugate curve is no contact of the system
            warnings: conjugate.into_iter().collect(),
            dynamics: crate::dynamics::SystemDynamicsOptions {
                metres_per_unit: length_unit.metres(),
                ..crate::dynamics::SystemDynamicsOptions::default()
            },
            coil_springs: Vec::new(),
            simulated: false,
            lubrication: None,
            timed_run: None,
            lash: Vec::new(),
        })
    }

    /// `e` as people read it, with what to do where a kinematic analysis meets a system its
    /// forces move (a file with `[dynamics]` whose degrees of freedom are not all driven:
    /// `camkin simulate` it).
    pub fn explain(&self, e: &crate::system::SystemError) -> String {
        match e {
            crate::system::SystemError::NotSquare { .. } if self.simulated => format!(
                "{e}; a system moved by its forces ([dynamics]) is simulated: `camkin simulate`, Python's System.simulate"
            ),
            _ => e.to_string(),
        }
    }

    /// A sweep's `e` as people read it: a system with `[dynamics]` and no driver of an angle (a
    /// pendulum, a benchmark released from a state) is simulated in time, not swept.
    pub fn explain_sweep(&self, e: &SweepError) -> String {
        match e {
            SweepError::NotAnAngle if self.simulated => format!(
                "{e}; a system moved by its forces ([dynamics]) is simulated: `camkin simulate` (its [simulation] or --duration), Python's System.simulate"
            ),
            _ => e.to_string(),
        }
    }

    /// The instant at the sweep angle `angle` (rad) (see [`SweepAngle::time`]).
    pub fn time_of(&self, angle: f64) -> Option<f64> {
        self.sweep_angle.time(&self.system, angle)
    }

    /// The instants at the sweep angles `angles_deg` (degrees), or why there are none: what
    /// every front end sweeps a system through.
    pub fn times(&self, angles_deg: &[f64]) -> Result<Vec<f64>, SweepError> {
        angles_deg
            .iter()
            .map(|&a| {
                self.time_of(a.to_radians()).ok_or(match self.sweep_angle {
                    // an angle driver that slows down and never turns so far
                    SweepAngle::FirstDriver if self.time_of(0.0).is_some() => {
                        SweepError::NeverReached { angle_deg: a }
                    }
                    SweepAngle::FirstDriver => SweepError::NotAnAngle,
                    _ => SweepError::NeverReached { angle_deg: a },
                })
            })
            .collect()
    }

    /// What a sweep's angle is, for messages and column headers: `driver angle` or `cam angle`.
    pub fn angle_name(&self) -> &'static str {
        match self.sweep_angle {
            SweepAngle::FirstDriver => "driver angle",
            SweepAngle::Cam { .. } => "cam angle",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cam at 1 rad/s slowing at 1 rad/s² stops after ½ rad: an angle before is reached at
    /// the root of `θ = t − t²/2`, one beyond is refused naming it; a system whose first
    /// driver is not an angle has no sweep angles.
    #[test]
    fn a_sweep_angle_is_an_instant_or_says_why_not() {
        let built = BuiltSystem {
            system: System::new(),
            length_unit: LengthUnit::Mm,
            warnings: Vec::new(),
            sweep_angle: SweepAngle::Cam {
                speed: 1.0,
                angular_acceleration: -1.0,
            },
            dynamics: crate::dynamics::SystemDynamicsOptions::default(),
            coil_springs: Vec::new(),
            simulated: false,
            lubrication: None,
            timed_run: None,
            lash: Vec::new(),
        };
        let t = built.times(&[0.0, 0.4f64.to_degrees()]).unwrap();
        assert_eq!(t[0], 0.0);
        assert!((t[1] - (1.0 - 0.2f64.sqrt())).abs() <= 1e-15, "{}", t[1]);
        assert_eq!(
            built.times(&[0.0, 45.0]),
            Err(SweepError::NeverReached { angle_deg: 45.0 })
        );
        let file = BuiltSystem {
            sweep_angle: SweepAngle::FirstDriver,
            ..built
        };
        assert_eq!(file.times(&[10.0]), Err(SweepError::NotAnAngle));
    }
}
