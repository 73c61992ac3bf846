//! The forces of a simulated system over its run, for people (`camkin forces SYSTEM.toml`): each
//! contact's largest and smallest compressive force and its largest Hertz pressure, each
//! driver's effort (a camshaft's torque: largest, smallest, mean and RMS), and each impact.

use crate::dynamics::{EventKind, SystemRun};
use crate::system::{Coordinate, System};

/// A value and the driver angle where it is.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct AtAngle {
    /// the value
    pub value: f64,
    /// the first driver's angle from the start, degrees
    pub angle_deg: f64,
}

/// One contact's forces over the run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ContactForces {
    /// its name
    pub name: String,
    /// the largest compressive force, N
    pub max_n: AtAngle,
    /// the smallest force while in touch, N (none: never in touch at a sample)
    pub min_closed_n: Option<AtAngle>,
    /// whether it is in touch at every sample
    pub always_closed: bool,
    /// the largest Hertz pressure, MPa (none without a width, or never closed)
    pub max_hertz_mpa: Option<AtAngle>,
}

/// One driver's effort over the run: a turning driver's torque (N·m, counter-clockwise
/// positive), a sliding one's force (N).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DriverEffort {
    /// its name
    pub name: String,
    /// "N·m" or "N"
    pub unit: &'static str,
    /// the largest
    pub max: AtAngle,
    /// the smallest
    pub min: AtAngle,
    /// the mean over the samples (the run's output steps are even); 0 where it is within the
    /// sum's rounding (`n ε` times the mean magnitude: a driven cam's torque over a revolution,
    /// zero in a conservative train, summed to 4e-17 N·m)
    pub mean: f64,
    /// the root mean square
    pub rms: f64,
}

/// An impact of the run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Impact {
    /// the contact's name
    pub contact: String,
    /// the first driver's angle from the start, degrees
    pub angle_deg: f64,
    /// the approach speed along the normal, m/s
    pub approach_m_s: f64,
}

/// A simulated system's forces (see the module docs).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SystemForces {
    /// each contact's, in the system's order
    pub contacts: Vec<ContactForces>,
    /// each driver's
    pub drivers: Vec<DriverEffort>,
    /// every impact, in order
    pub impacts: Vec<Impact>,
}

impl SystemForces {
    /// The forces of `run` of `sys` (lengths in `metres_per_unit` m); `angle_deg(t)` is the first
    /// driver's angle at time `t`.
    pub fn new(
        sys: &System,
        run: &SystemRun,
        metres_per_unit: f64,
        angle_deg: impl Fn(f64) -> f64,
    ) -> Self {
        let samples = &run.samples;
        let at = |value: f64, k: usize| AtAngle {
            value,
            angle_deg: angle_deg(samples[k].time),
        };
        let largest = |f: &dyn Fn(usize) -> Option<f64>| -> Option<AtAngle> {
            (0..samples.len())
                .filter_map(|k| f(k).map(|v| (v, k)))
                .fold(None, |best: Option<(f64, usize)>, (v, k)| match best {
                    Some((b, _)) if b >= v => best,
                    _ => Some((v, k)),
                })
                .map(|(v, k)| at(v, k))
        };
        let contacts = sys
            .contacts()
            .iter()
            .enumerate()
            .map(|(c, contact)| {
                let closed = |k: usize| samples[k].in_contact[c];
                ContactForces {
                    name: contact.name.clone(),
                    max_n: largest(&|k| Some(samples[k].contact_forces[c])).unwrap_or(AtAngle {
                        value: 0.0,
                        angle_deg: 0.0,
                    }),
                    min_closed_n: largest(&|k| closed(k).then(|| -samples[k].contact_forces[c]))
                        .map(|a| AtAngle {
                            value: -a.value,
                            ..a
                        }),
                    always_closed: (0..samples.len()).all(closed),
                    max_hertz_mpa: largest(&|k| samples[k].hertz_pa[c].map(|p| p * 1e-6))
                        .filter(|a| a.value > 0.0),
                }
            })
            .collect();
        let drivers = sys
            .drivers()
            .iter()
            .enumerate()
            .map(|(d, driver)| {
                // N·L to N·m for a torque
                let (scale, unit) = match driver.coordinate {
                    Coordinate::Angle => (metres_per_unit, "N·m"),
                    _ => (1.0, "N"),
                };
                let e = |k: usize| samples[k].driver_efforts.get(d).map(|v| v * scale);
                let n = samples.len().max(1) as f64;
                let values: Vec<f64> = (0..samples.len()).filter_map(e).collect();
                DriverEffort {
                    name: driver.name.clone(),
                    unit,
                    max: largest(&e).unwrap_or(AtAngle {
                        value: 0.0,
                        angle_deg: 0.0,
                    }),
                    min: largest(&|k| e(k).map(|v| -v))
                        .map(|a| AtAngle {
                            value: -a.value,
                            ..a
                        })
                        .unwrap_or(AtAngle {
                            value: 0.0,
                            angle_deg: 0.0,
                        }),
                    mean: mean_of(&values),
                    rms: (values.iter().map(|v| v * v).sum::<f64>() / n).sqrt(),
                }
            })
            .collect();
        let impacts = run
            .events
            .iter()
            .filter(|e| e.kind == EventKind::Impact)
            .map(|e| Impact {
                contact: sys
                    .contacts()
                    .get(e.contact)
                    .map_or_else(String::new, |c| c.name.clone()),
                angle_deg: angle_deg(e.time),
                approach_m_s: e.approach * metres_per_unit,
            })
            .collect();
        Self {
            contacts,
            drivers,
            impacts,
        }
    }
}

/// A check of a system's forces that failed (`camkin forces SYSTEM.toml --margin`,
/// `--allowable`; Python's `System.forces(margin=…, allowable_mpa=…)`).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub enum SystemForceFailure {
    /// a contact closed all the revolution whose force falls under the margin, N
    Margin {
        /// the contact
        contact: String,
        /// its smallest force and where
        force: AtAngle,
        /// the margin
        margin: f64,
    },
    /// a contact whose Hertz pressure rises over the allowable, MPa
    Allowable {
        /// the contact
        contact: String,
        /// its largest pressure and where
        pressure: AtAngle,
        /// the allowable
        allowable: f64,
    },
    /// a contact closed all the revolution at the sweep's slowest speed opens below the target
    /// speed (the no-follow speed, [`crate::dynamics::no_follow_speed`])
    NoFollow {
        /// the contact
        contact: String,
        /// where it opens, degrees of the first driver
        angle_deg: f64,
        /// the speed at which it opens, rpm
        speed_rpm: f64,
        /// the target, rpm
        target_rpm: f64,
        /// the sweep's slowest speed, rpm
        from_rpm: f64,
    },
}

impl SystemForceFailure {
    /// The failure of a speed sweep that found `nf` below its target.
    pub fn no_follow(
        sys: &System,
        nf: &crate::dynamics::NoFollow,
        sweep: &crate::dynamics::SpeedSweep,
    ) -> Self {
        Self::NoFollow {
            contact: sys
                .contacts()
                .get(nf.contact)
                .map_or_else(|| "?".into(), |c| c.name.clone()),
            angle_deg: nf.angle_deg,
            speed_rpm: nf.speed_rpm,
            target_rpm: sweep.to_rpm,
            from_rpm: sweep.from_rpm,
        }
    }
}

impl SystemForces {
    /// The checks that fail: every contact closed all the revolution keeps `margin` N, and
    /// (given) every contact's Hertz pressure stays under `allowable_mpa`.
    pub fn failures(&self, margin: f64, allowable_mpa: Option<f64>) -> Vec<SystemForceFailure> {
        let mut out = Vec::new();
        for c in &self.contacts {
            if let (Some(m), true) = (&c.min_closed_n, c.always_closed) {
                if m.value < margin {
                    out.push(SystemForceFailure::Margin {
                        contact: c.name.clone(),
                        force: *m,
                        margin,
                    });
                }
            }
            if let (Some(p), Some(limit)) = (&c.max_hertz_mpa, allowable_mpa) {
                if p.value > limit {
                    out.push(SystemForceFailure::Allowable {
                        contact: c.name.clone(),
                        pressure: *p,
                        allowable: limit,
                    });
                }
            }
        }
        out
    }
}

/// The mean of `values`, 0 where it is within the rounding of their sum (at most `n ε` times
/// their mean magnitude: Higham, *Accuracy and Stability of Numerical Algorithms*, §4.2).
fn mean_of(values: &[f64]) -> f64 {
    let n = values.len().max(1) as f64;
    let mean = values.iter().sum::<f64>() / n;
    let magnitude = values.iter().map(|v| v.abs()).sum::<f64>() / n;
    if mean.abs() <= n * f64::EPSILON * magnitude {
        0.0
    } else {
        mean
    }
}

#[cfg(test)]
mod tests {
    use super::mean_of;

    /// A torque over a revolution whose true mean is zero (a sine sampled over whole periods)
    /// gives 0, not its sum's rounding; a true mean a millionth of the amplitude is kept.
    #[test]
    fn a_mean_within_its_sums_rounding_is_zero() {
        let n = 1440;
        let sine: Vec<f64> = (0..n)
            .map(|k| 3.519 * (std::f64::consts::TAU * k as f64 / n as f64).sin())
            .collect();
        assert_eq!(mean_of(&sine), 0.0);
        let offset: Vec<f64> = sine.iter().map(|v| v + 3.519e-6).collect();
        assert!((mean_of(&offset) - 3.519e-6).abs() < 1e-12);
        assert_eq!(mean_of(&[]), 0.0);
    }
}
