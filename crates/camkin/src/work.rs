//! Work estimates, and the one rule that refuses up front what would take minutes or gigabytes.
//!
//! Every entry point — each command, each Python call, each studio request — estimates its work
//! as a [`Work`] before it starts and asks [`Work::refusal`]. A refusal's sentence is the
//! library's (`"720000 cam angles on this profile would take about 1440 s (why)"`); each front end
//! adds only how to run it anyway in its own words (`--large`, `large=True`) or, where there is
//! no such override (a studio request), its own limit ([`Work::refusal_within`]).

use crate::cam::Mechanism;
use crate::human::human;
use std::fmt;

/// Above this many seconds work is refused without the front end's override.
pub const SECONDS_LIMIT: f64 = 30.0;

/// Above this many bytes (memory held, or files written) work is refused without the override.
pub const BYTES_LIMIT: f64 = 1e9;

/// The most work an entry point does without being asked to: the library's
/// ([`SECONDS_LIMIT`], [`BYTES_LIMIT`]) by default, a server's per-request limits, or
/// [`Limits::NONE`] when the user asked for large work (`--large`, `large=True`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// seconds of wall time on one core
    pub seconds: f64,
    /// bytes of memory held or files written
    pub bytes: f64,
}

impl Limits {
    /// No limit: the user asked for the work however large.
    pub const NONE: Limits = Limits {
        seconds: f64::INFINITY,
        bytes: f64::INFINITY,
    };
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            seconds: SECONDS_LIMIT,
            bytes: BYTES_LIMIT,
        }
    }
}

/// An estimate of the work an entry point is about to do.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Work {
    /// what is counted, as a person reads it (`720 cam angles on this profile`)
    pub what: String,
    /// wall time on one core, s
    pub seconds: f64,
    /// memory held or bytes written, whichever is larger
    pub bytes: f64,
    /// why it costs that much, where that is worth saying (`it is not convex, so …`)
    pub why: Option<String>,
}

impl Work {
    /// `what`, estimated at `seconds`, holding no memory worth counting.
    pub fn new(what: impl Into<String>, seconds: f64) -> Self {
        Self {
            what: what.into(),
            seconds,
            bytes: 0.0,
            why: None,
        }
    }

    /// With `bytes` of memory held or files written.
    pub fn with_bytes(mut self, bytes: f64) -> Self {
        self.bytes = bytes;
        self
    }

    /// With the reason for its cost.
    pub fn because(mut self, why: impl Into<String>) -> Self {
        self.why = Some(why.into());
        self
    }

    /// Both pieces of work, one after the other (the first one's words).
    pub fn and(mut self, other: &Work) -> Self {
        self.seconds += other.seconds;
        self.bytes = self.bytes.max(other.bytes);
        if self.why.is_none() {
            self.why.clone_from(&other.why);
        }
        self
    }

    /// `sweeps` warm-started sweeps of `angles` cam angles of `mech`
    /// ([`Mechanism::sweep_seconds_estimate`]), each with the follower's travel that its lift
    /// is measured from ([`Mechanism::travel_seconds_estimate`]), with the reason when each
    /// angle also searches.
    pub fn sweep(mech: &Mechanism, angles: usize, sweeps: usize) -> Self {
        let n = angles * sweeps;
        // a warm step's cost once (a carried curve's is timed), for the angles and for the
        // travel's 720 alike
        let step = mech.step_seconds_estimate(angles);
        let work = Self::new(
            format!(
                "{n} cam angle{} on this profile, with the follower's travel,",
                if n == 1 { "" } else { "s" }
            ),
            (angles as f64 * step + mech.travel_seconds_with(step)) * sweeps as f64,
        );
        match mech.search_cost_reason() {
            Some(why) => work.because(why),
            None => work,
        }
    }

    /// `instants` instants of a system swept warm ([`crate::system::System::sweep`]): each
    /// [`System::instant_seconds`](crate::system::System::instant_seconds), with
    /// [`System::held_bytes`](crate::system::System::held_bytes) held, and its table's
    /// numbers, 24 bytes each written or held (twelve a body's: coordinates, rates,
    /// accelerations and jerk; thirteen a contact's).
    pub fn system(sys: &crate::system::System, instants: usize) -> Self {
        let cells = 2 + 12 * sys.bodies().len() + 13 * sys.contacts().len();
        Self::new(
            format!(
                "{instants} instant{} of this system",
                if instants == 1 { "" } else { "s" }
            ),
            instants as f64 * sys.instant_seconds(),
        )
        .with_bytes(instants as f64 * cells as f64 * 24.0 + sys.held_bytes())
    }

    /// `steps` simulated steps of a system ([`crate::dynamics::SystemSimulation`]) and
    /// `samples` samples made: a step seven evaluations of the equations of motion and a
    /// projection, about 1.5e-5 s a body; a sample a projection and an evaluation, about 5e-6 s
    /// a body (the valve train measured: 1.1e-5 s and 5e-6 s a body); and `outputs` rows held,
    /// of 24-byte numbers (nine a body, three a contact, one a driver).
    pub fn system_simulation(
        sys: &crate::system::System,
        steps: f64,
        samples: f64,
        outputs: usize,
    ) -> Self {
        let n = sys.bodies().len().max(1) as f64;
        let cells = 4 + 9 * sys.bodies().len() + 3 * sys.contacts().len() + sys.drivers().len();
        Self::new(
            format!(
                "{} simulated steps of this system and {} samples",
                crate::human::human(steps.ceil()),
                crate::human::human(samples.ceil())
            ),
            (steps * 1.5e-5 + samples * 5e-6) * n,
        )
        .with_bytes(outputs as f64 * cells as f64 * 24.0)
    }

    /// Every contact at `angles` cam angles of `mech`
    /// ([`Mechanism::contacts_seconds_estimate`]: a sweep and one more search per angle).
    pub fn contacts(mech: &Mechanism, angles: usize) -> Self {
        Self::new(
            format!("{angles} cam angles, every contact searched,"),
            mech.contacts_seconds_estimate(angles),
        )
    }

    /// The refusal of this work under the library's limits ([`SECONDS_LIMIT`], [`BYTES_LIMIT`]),
    /// `None` within them.
    pub fn refusal(&self) -> Option<Refusal> {
        self.refusal_within(SECONDS_LIMIT, BYTES_LIMIT)
    }

    /// The refusal under `limits`, `None` within them.
    pub fn refusal_under(&self, limits: &Limits) -> Option<Refusal> {
        self.refusal_within(limits.seconds, limits.bytes)
    }

    /// The refusal under other limits (a server's per-request time).
    pub fn refusal_within(&self, seconds: f64, bytes: f64) -> Option<Refusal> {
        // NaN (an estimate of nonsense) is refused too
        (!(self.seconds <= seconds && self.bytes <= bytes)).then(|| Refusal(self.clone()))
    }
}

/// Work refused before it started; its `Display` is the sentence every front end begins with.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct Refusal(pub Work);

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let w = &self.0;
        write!(
            f,
            "{} would take about {} s",
            w.what,
            human(w.seconds.ceil())
        )?;
        // memory below a megabyte is not worth a word
        if w.bytes >= 1e6 {
            write!(f, " and {}", bytes(w.bytes))?;
        }
        if let Some(why) = &w.why {
            write!(f, " ({why})")?;
        }
        Ok(())
    }
}

/// A byte count as a person reads it: `2.4 GB`, `310 MB`, `12 kB`.
pub fn bytes(b: f64) -> String {
    let (v, unit) = if b >= 1e9 {
        (b / 1e9, "GB")
    } else if b >= 1e6 {
        (b / 1e6, "MB")
    } else if b >= 1e3 {
        (b / 1e3, "kB")
    } else {
        (b, "B")
    };
    format!("{} {unit}", human((v * 10.0).ceil() / 10.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_over_either_limit_and_nonsense() {
        let w = Work::new("10 cam angles", 1.0);
        assert!(w.refusal().is_none());
        assert!(Work::new("x", 31.0).refusal().is_some());
        assert!(Work::new("x", 1.0).with_bytes(1.1e9).refusal().is_some());
        assert!(Work::new("x", 1.0).with_bytes(0.9e9).refusal().is_none());
        assert!(Work::new("x", f64::NAN).refusal().is_some());
        assert!(w.refusal_within(0.5, 1e9).is_some());
    }

    /// A system's sweep is estimated by its instants: a revolution in quarter degrees is work
    /// for a moment, a million instants are refused with the count.
    #[test]
    fn a_systems_sweep_is_estimated_by_its_instants() {
        let (sys, _) = crate::reference::single_valve_train(300.0);
        assert!(Work::system(&sys, 1440).refusal().is_none());
        let r = Work::system(&sys, 1_000_000).refusal().unwrap().to_string();
        assert!(
            r.starts_with("1000000 instants of this system would take about"),
            "{r}"
        );
    }

    /// A system of `n` driven wheels: its dense Jacobian is `3n × 3n`, its factorisation's
    /// work `(3n)³`: 1 000 wheels' one instant is allowed (measured 0.82 s, 300 MB), 3 000
    /// wheels' is refused for its memory (81e6 numbers a matrix: measured 2.5 GB), and a
    /// revolution in degrees of 1 000 for its time.
    #[test]
    fn a_systems_size_is_in_its_estimate() {
        use crate::system::{
            Body, BodyId, Coordinate, Driver, DriverLaw, Joint, JointKind, System,
        };
        let wheels = |n: usize| {
            let mut sys = System::new();
            for i in 0..n {
                let p = crate::Point2::new(i as f64, 0.0);
                let b = sys.add_body(Body {
                    name: format!("w{i}"),
                    mass: 1.0,
                    inertia: 1.0,
                    pose: crate::body::Pose::new(p, 0.0),
                    centre_of_mass: crate::Point2::origin(),
                });
                sys.add_joint(Joint {
                    name: format!("p{i}"),
                    kind: JointKind::Revolute {
                        a: BodyId::GROUND,
                        at_a: p,
                        b,
                        at_b: crate::Point2::origin(),
                    },
                });
                sys.add_driver(Driver {
                    name: format!("d{i}"),
                    body: b,
                    coordinate: Coordinate::Angle,
                    law: DriverLaw::linear(0.0, 1.0),
                });
            }
            sys
        };
        let thousand = wheels(1000);
        assert!(Work::system(&thousand, 1).refusal().is_none());
        let r = Work::system(&thousand, 361).refusal().unwrap().to_string();
        assert!(
            r.starts_with("361 instants of this system would take about"),
            "{r}"
        );
        let r = Work::system(&wheels(3000), 1)
            .refusal()
            .unwrap()
            .to_string();
        assert!(r.contains(" GB"), "{r}");
    }

    #[test]
    fn the_sentence_names_what_time_memory_and_why() {
        let r = Work::new("720000 cam angles on this profile", 1439.2)
            .with_bytes(2.41e9)
            .because("it is not convex")
            .refusal()
            .unwrap();
        assert_eq!(
            r.to_string(),
            "720000 cam angles on this profile would take about 1440 s and 2.5 GB (it is not convex)"
        );
        assert_eq!(bytes(310e6), "310 MB");
        assert_eq!(bytes(999.0), "999 B");
    }
}
