//! The no-follow (separation) speed of a system driven by an angle: the lowest driver speed at
//! which a contact that stays closed at low speed opens during a revolution — a valve train's
//! finger leaving its cam, or the valve its pad, where their inertia outgrows the spring — found
//! by simulating a revolution at speeds in steps and bisecting the first step where it happens.
//! A contact that opens within [`SpeedSweep::after_impact_deg`] of an impact elsewhere (the
//! finger jolted off its cam as the valve lands on its seat) is the impact's bounce, not a
//! no-follow, and is not counted. Each speed's run starts with
//! [`SpeedSweep::settle_revolutions`] that are not judged, so that the revolutions judged start
//! from the settled periodic state at that speed (a spring's surge started by the start from
//! rest has run its course), not from the file's state. A contact that the starting poses leave apart but the slow
//! revolution closes and keeps closed is assembled in touch at the start of every run
//! ([`super::SystemDynamicsOptions::start_touching`]), so the verdict does not depend on how
//! near the file's poses were.

use super::{DynamicsError, EventKind, SystemDynamicsOptions, SystemSimulation};
use crate::system::{Coordinate, DriverLaw, System};

/// Where a system stops following its driver.
#[derive(Debug, Clone, PartialEq)]
pub struct NoFollow {
    /// the lowest speed at which a contact opens, rpm (within the bisection's tolerance)
    pub speed_rpm: f64,
    /// a speed at which it does not, rpm (the bracket's other end)
    pub following_rpm: f64,
    /// the contact that opens first, in the system's order
    pub contact: usize,
    /// the driver's angle where it opens, degrees
    pub angle_deg: f64,
    /// the simulations run
    pub simulations: usize,
}

/// How a speed sweep runs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedSweep {
    /// the slowest speed, rpm: the contacts closed through its revolution are watched
    pub from_rpm: f64,
    /// the fastest, rpm
    pub to_rpm: f64,
    /// the sweep's step, rpm
    pub step_rpm: f64,
    /// the bisection stops when the bracket is narrower than this, rpm
    pub tolerance_rpm: f64,
    /// the output step of each simulation, degrees of the driver (the time step is this or
    /// shorter, as the stiffest element needs)
    pub step_deg: f64,
    /// revolutions simulated at each speed
    pub revolutions: f64,
    /// a lift-off this many degrees of the driver after an impact is the impact's bounce
    pub after_impact_deg: f64,
    /// revolutions run at each speed before those judged (its start's transient settled): a
    /// watched contact open when the judged revolutions begin opened at that speed
    pub settle_revolutions: f64,
}

impl SpeedSweep {
    /// The sweep that checks a system up to `target_rpm` (`camkin forces SYSTEM.toml
    /// --target-rpm`, Python's `System.forces(target_rpm=…)`): from a quarter of the lower of
    /// the target and the file's speed (`sys`'s first driver's), in eight steps to the target,
    /// then bisected to 1 rpm; one revolution at each speed in `step_deg` output steps.
    pub fn to_target(sys: &System, target_rpm: f64, step_deg: f64) -> Self {
        let rpm = sys.first_driver_rpm();
        let from = 0.25 * target_rpm.min(rpm.abs().max(1.0));
        Self {
            from_rpm: from,
            to_rpm: target_rpm,
            step_rpm: (target_rpm - from) / 8.0,
            tolerance_rpm: 1.0,
            step_deg,
            revolutions: 1.0,
            after_impact_deg: 5.0,
            settle_revolutions: 1.0,
        }
    }

    /// The time steps and samples of the sweep's runs, at most (the slow run twice where it
    /// assembles a contact the file's poses leave apart; each run a revolution at most at the
    /// target's speed) of `sim`'s system ([`super::SystemSimulation::steps_estimate_at`]).
    pub fn work(&self, sim: &super::SystemSimulation<'_>) -> (f64, f64) {
        // the speeds tried, the bisection's to its tolerance, the slow run again
        let runs = ((self.to_rpm - self.from_rpm) / self.step_rpm).ceil()
            + 1.0
            + (self.step_rpm / self.tolerance_rpm).max(1.0).log2().ceil()
            + 1.0;
        let w = self.to_rpm * std::f64::consts::TAU / 60.0;
        let h_target = self.step_deg.to_radians() / w;
        let speed = self.to_rpm / sim.system().first_driver_rpm().abs().max(1e-300);
        let revolutions = self.revolutions + self.settle_revolutions.max(0.0);
        let duration = revolutions * std::f64::consts::TAU / w;
        let samples = (revolutions * 360.0 / self.step_deg).ceil() + 1.0;
        (
            runs * sim.steps_estimate_at(duration, h_target, speed),
            runs * samples,
        )
    }
}

/// A run's first opening of a watched contact (`(contact, angle_deg)` from the start of the
/// revolutions judged), whether each contact was closed when they started and when the run was
/// assembled, and the contacts closed at the end that never opened while judged.
struct Opening {
    first: Option<(usize, f64)>,
    closed_at_start: Vec<bool>,
    assembled: Vec<bool>,
    stayed: Vec<bool>,
}

/// The first contact lift-off of `watched` contacts in `revolutions` of `sys` with its first
/// driver at `rpm` (`first`: `Some((contact, angle_deg))`, or `None` when every one stays
/// closed).
fn first_opening(
    sys: &System,
    opts: &SystemDynamicsOptions,
    sweep: &SpeedSweep,
    rpm: f64,
    watched: Option<&[bool]>,
) -> Result<Opening, DynamicsError> {
    let mut s = sys.clone();
    let Some(d) = sys.drivers().first() else {
        return Err(no_angle_driver());
    };
    let start = match (d.coordinate, d.law) {
        (Coordinate::Angle, DriverLaw::Quadratic { start, .. }) => start,
        _ => return Err(no_angle_driver()),
    };
    let w = rpm * std::f64::consts::TAU / 60.0;
    s.set_driver_law(0, DriverLaw::linear(start, w));
    let mut sim = SystemSimulation::new(&s, opts.clone())?;
    let assembled = sim.sample()?.in_contact;
    let h = sweep.step_deg.to_radians() / w;
    // the revolutions that settle the start's transient, not judged
    let settle = (sweep.settle_revolutions.max(0.0) * 360.0 / sweep.step_deg).round() as usize;
    for _ in 0..settle {
        sim.advance(h)?;
    }
    // the driver's angle the judged revolutions start at, degrees, and its whole turns (the
    // angles reported are the driver's less these)
    let settled = settle as f64 * sweep.step_deg;
    let turns = 360.0 * (settled / 360.0).floor();
    let closed_at_start = if settle == 0 {
        assembled.clone()
    } else {
        sim.sample()?.in_contact
    };
    // a watched contact the settling left open has opened at this speed
    if let Some(k) = watched.and_then(|w| (0..w.len()).find(|&k| w[k] && !closed_at_start[k])) {
        let n = assembled.len();
        return Ok(Opening {
            first: Some((k, settled - turns)),
            closed_at_start,
            assembled,
            stayed: vec![false; n],
        });
    }
    let steps = (sweep.revolutions * 360.0 / sweep.step_deg).round() as usize;
    let mut opened = vec![false; closed_at_start.len()];
    let mut last_impact = f64::NEG_INFINITY;
    for _ in 0..steps {
        for e in sim.advance(h)? {
            let angle = (w * e.time).to_degrees() - turns;
            if e.kind == EventKind::Impact {
                last_impact = angle;
                continue;
            }
            if angle - last_impact <= sweep.after_impact_deg {
                continue;
            }
            if e.kind == EventKind::LiftOff {
                if watched.is_some_and(|w| w[e.contact]) {
                    return Ok(Opening {
                        first: Some((e.contact, angle)),
                        closed_at_start,
                        assembled,
                        stayed: opened,
                    });
                }
                opened[e.contact] = true;
            }
        }
    }
    let closed_at_end = sim.sample()?.in_contact;
    let stayed = closed_at_end
        .iter()
        .zip(&opened)
        .map(|(&c, &o)| c && !o)
        .collect();
    Ok(Opening {
        first: None,
        closed_at_start,
        assembled,
        stayed,
    })
}

fn no_angle_driver() -> DynamicsError {
    DynamicsError::Element {
        element: "the first driver".into(),
        key: "coordinate",
        value: f64::NAN,
        reason: "must turn an angle at a constant speed for a speed sweep",
    }
}

/// The no-follow speed of `sys` (see the module docs): the contacts closed at the start that
/// stay closed through a revolution at `sweep.from_rpm` are watched; the speed rises in steps of
/// `sweep.step_rpm` until one of them opens, and that step is bisected to
/// `sweep.tolerance_rpm`. `None` when none opens up to `sweep.to_rpm`.
pub fn no_follow_speed(
    sys: &System,
    opts: &SystemDynamicsOptions,
    sweep: &SpeedSweep,
) -> Result<Option<NoFollow>, DynamicsError> {
    let check = |key: &'static str, v: f64| {
        if v > 0.0 && v.is_finite() {
            Ok(())
        } else {
            Err(DynamicsError::Element {
                element: "the speed sweep".into(),
                key,
                value: v,
                reason: "must be positive",
            })
        }
    };
    check("from (rpm)", sweep.from_rpm)?;
    check("step (rpm)", sweep.step_rpm)?;
    check("tolerance (rpm)", sweep.tolerance_rpm)?;
    check("output step (deg)", sweep.step_deg)?;
    check("revolutions", sweep.revolutions)?;
    if !(sweep.settle_revolutions >= 0.0 && sweep.settle_revolutions.is_finite()) {
        return Err(DynamicsError::Element {
            element: "the speed sweep".into(),
            key: "settle revolutions",
            value: sweep.settle_revolutions,
            reason: "must be zero or more",
        });
    }
    // the contacts a slow revolution keeps closed are watched; one that starts apart (the
    // file's pose a little off it) and closes for good is assembled in touch at the start of
    // every run, so the verdict does not depend on how near the pose was
    let slow = first_opening(sys, opts, sweep, sweep.from_rpm, None)?;
    let mut simulations = 1;
    let closes = |o: &Opening, k: usize| o.stayed[k] && !o.assembled[k];
    let mut watched = slow.stayed.clone();
    let assembled;
    let opts = if (0..watched.len()).any(|k| closes(&slow, k)) {
        let mut o = opts.clone();
        o.start_touching = (0..watched.len())
            .map(|k| {
                if closes(&slow, k) {
                    Some(true)
                } else {
                    opts.start_touching.get(k).copied().flatten()
                }
            })
            .collect();
        assembled = o;
        let again = first_opening(sys, &assembled, sweep, sweep.from_rpm, None)?;
        simulations += 1;
        watched = (0..watched.len())
            .map(|k| again.stayed[k] && again.closed_at_start[k])
            .collect();
        &assembled
    } else {
        opts
    };
    let mut below = sweep.from_rpm;
    let mut rpm = sweep.from_rpm;
    while rpm < sweep.to_rpm {
        rpm = (rpm + sweep.step_rpm).min(sweep.to_rpm);
        simulations += 1;
        let Some(mut first) = first_opening(sys, opts, sweep, rpm, Some(&watched))?.first else {
            below = rpm;
            continue;
        };
        let mut above = rpm;
        while above - below > sweep.tolerance_rpm {
            let mid = 0.5 * (below + above);
            simulations += 1;
            match first_opening(sys, opts, sweep, mid, Some(&watched))?.first {
                Some(f) => {
                    above = mid;
                    first = f;
                }
                None => below = mid,
            }
        }
        return Ok(Some(NoFollow {
            speed_rpm: above,
            following_rpm: below,
            contact: first.0,
            angle_deg: first.1,
            simulations,
        }));
    }
    Ok(None)
}
