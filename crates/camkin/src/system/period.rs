//! A system that repeats: where every driver is back where it started after a revolution (a
//! camshaft at a constant speed, a crank), the poses after some whole number of revolutions are
//! the starting ones, each body turned by whole turns. An instant many revolutions away is then
//! the one that many periods nearer the start, its bodies turned by the periods' turns: reached
//! in one revolution's instants rather than through every instant between (a valve train asked
//! at 1e7° was otherwise stepped in instants too far apart for Newton and reported a dead point
//! it does not have).

use super::solve::SystemState;
use super::{Coordinate, DriverLaw, System, SystemError};

/// Most revolutions of the first driver over which a system is checked for repeating.
pub(super) const MAX_REVOLUTIONS: u32 = 8;

/// Instants a revolution is swept in while a system is checked for repeating.
const INSTANTS: u32 = 360;

/// After how long a system repeats, and how far each body turns meanwhile.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Period {
    /// its length, s
    pub time: f64,
    /// each body's turn over a period, rad (a whole number of turns)
    pub turns: Vec<f64>,
}

impl Period {
    /// `state` (an instant within the first periods) moved on by `periods` periods: the same
    /// poses, each body turned by its turns, at the later time.
    pub(super) fn shift(&self, mut state: SystemState, periods: f64) -> SystemState {
        state.time += periods * self.time;
        for (b, turn) in state.bodies.iter_mut().zip(&self.turns) {
            b.pose.angle += periods * turn;
        }
        state
    }
}

impl System {
    /// The time after which every driver is back where it started: a revolution of the first
    /// driver when it turns an angle at a constant speed and every other driver turns at the
    /// same speed or stands still; `None` otherwise (an acceleration, a slide that moves on).
    pub(super) fn driver_period(&self) -> Option<f64> {
        let first = self.drivers().first()?;
        let DriverLaw::Quadratic { rate, .. } = first.law;
        if first.coordinate != Coordinate::Angle || !(rate != 0.0 && rate.is_finite()) {
            return None;
        }
        let repeats = self.drivers().iter().all(|d| {
            let DriverLaw::Quadratic {
                rate: r,
                acceleration,
                ..
            } = d.law;
            acceleration == 0.0
                && match d.coordinate {
                    Coordinate::Angle => r == 0.0 || r.abs() == rate.abs(),
                    _ => r == 0.0,
                }
        });
        repeats.then(|| std::f64::consts::TAU / rate.abs())
    }

    /// Whether the system repeats within [`MAX_REVOLUTIONS`] revolutions of its first driver:
    /// swept revolution by revolution from its start, the first whole number of them after
    /// which every body's position is its starting one (to 1e-9 of the size) and its angle the
    /// starting one plus whole turns (to 1e-9 rad).
    pub(super) fn period(&self) -> Result<Option<Period>, SystemError> {
        let Some(revolution) = self.driver_period() else {
            return Ok(None);
        };
        let size = self.size();
        let mut sweep = self.sweep()?;
        let start = sweep.step(0.0)?;
        for m in 1..=MAX_REVOLUTIONS {
            let mut last = None;
            for k in 1..=INSTANTS {
                let t = revolution * (f64::from(m - 1) + f64::from(k) / f64::from(INSTANTS));
                last = Some(sweep.step(t)?);
            }
            let Some(end) = last else { break };
            let turns: Option<Vec<f64>> = start
                .bodies
                .iter()
                .zip(&end.bodies)
                .map(|(a, b)| {
                    let turned = b.pose.angle - a.pose.angle;
                    let whole = (turned / std::f64::consts::TAU).round() * std::f64::consts::TAU;
                    ((b.pose.origin - a.pose.origin).norm() <= 1e-9 * size
                        && (turned - whole).abs() <= 1e-9)
                        .then_some(whole)
                })
                .collect();
            if let Some(turns) = turns {
                return Ok(Some(Period {
                    time: f64::from(m) * revolution,
                    turns,
                }));
            }
        }
        Ok(None)
    }
}
