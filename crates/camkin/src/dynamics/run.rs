//! A simulation run at a fixed output interval: the one loop every front end uses (the
//! command's `simulate`, the Python package's `Mechanism.simulate`), so they agree to the bit.

use super::{DynamicsError, Event, Sample, Simulation};

/// The time series and the events of a run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Run {
    /// the state at time 0 and after every output interval (`outputs + 1` samples)
    pub samples: Vec<Sample>,
    /// lift-offs and impacts, in time order
    pub events: Vec<Event>,
}

impl Simulation<'_> {
    /// Samples the state now and after each of `outputs` intervals of `substeps` steps of `h`
    /// seconds; `progress` is told how many intervals are done, every 1000 of them, and stops
    /// the run ([`DynamicsError::Stopped`]) by breaking (a front end's interrupt).
    pub fn run(
        &mut self,
        outputs: usize,
        substeps: usize,
        h: f64,
        mut progress: impl FnMut(usize) -> std::ops::ControlFlow<()>,
    ) -> Result<Run, DynamicsError> {
        let mut samples = Vec::with_capacity(outputs + 1);
        samples.push(self.sample()?);
        let mut events = Vec::new();
        for k in 0..outputs {
            for _ in 0..substeps {
                events.extend(self.advance(h)?);
            }
            samples.push(self.sample()?);
            if k % 1000 == 0 && progress(k).is_break() {
                return Err(DynamicsError::Stopped { done: k, outputs });
            }
        }
        Ok(Run { samples, events })
    }
}

/// What a run whose time step is too long for the follower's fastest rate needs (see
/// [`Simulation::step_advice`]); each front end words it with its own flags.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum StepAdvice {
    /// this many substeps per output interval (within the allowed most)
    Substeps(usize),
    /// the most substeps and an output interval of at most this many degrees of cam angle
    FinerStep {
        /// degrees
        step_deg: f64,
    },
    /// no allowed interval will do: the cam turns too slowly for outputs by cam angle; a speed
    /// of at least this many rpm would
    FasterCam {
        /// rpm
        rpm: f64,
    },
}

impl Simulation<'_> {
    /// `None` when a run at `step_deg` of cam angle per output with `substeps` steps resolves the
    /// follower's fastest rate at cam speed `omega` (rad/s); else what would: more substeps (at
    /// most `max_substeps`), a finer step (at least `min_step_deg`), or a faster cam.
    pub fn step_advice(
        &self,
        step_deg: f64,
        substeps: usize,
        omega: f64,
        max_substeps: usize,
        min_step_deg: f64,
    ) -> Option<StepAdvice> {
        let max = self.max_step();
        let h = step_deg.to_radians() / omega / substeps as f64;
        if h <= max {
            return None;
        }
        let need = (h / max * substeps as f64).ceil();
        if need <= max_substeps as f64 {
            return Some(StepAdvice::Substeps(need as usize));
        }
        // with the most substeps: the longest output interval that resolves it, rounded down
        // rounded down to 1, 2 or 5 × 10^k degrees, each of which divides the revolution
        let step = (max * omega * max_substeps as f64).to_degrees().min(90.0);
        let decade = 10f64.powf(step.log10().floor());
        let nice = [5.0, 2.0, 1.0]
            .into_iter()
            .map(|m| m * decade)
            .find(|&s| s <= step)
            .unwrap_or(decade);
        if nice >= min_step_deg {
            return Some(StepAdvice::FinerStep { step_deg: nice });
        }
        let omega_needed = min_step_deg.to_radians() / (max * max_substeps as f64);
        Some(StepAdvice::FasterCam {
            rpm: (omega_needed * 60.0 / std::f64::consts::TAU * 1.001).ceil(),
        })
    }
}
