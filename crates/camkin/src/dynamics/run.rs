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
    /// Samples the state now and after each of `outputs` intervals of `h` seconds (the steps
    /// inside each chosen by the model: [`Simulation::advance`]); `progress` is told how many
    /// intervals are done, every 1000 of them, and stops the run ([`DynamicsError::Stopped`]) by
    /// breaking (a front end's interrupt).
    pub fn run(
        &mut self,
        outputs: usize,
        h: f64,
        mut progress: impl FnMut(usize) -> std::ops::ControlFlow<()>,
    ) -> Result<Run, DynamicsError> {
        let mut samples = Vec::with_capacity(outputs + 1);
        samples.push(self.sample()?);
        let mut events = Vec::new();
        for k in 0..outputs {
            events.extend(self.advance(h)?);
            samples.push(self.sample()?);
            if k % 1000 == 0 && progress(k).is_break() {
                return Err(DynamicsError::Stopped { done: k, outputs });
            }
        }
        Ok(Run { samples, events })
    }
}
