//! A simulated system's hydraulic lash adjusters ([`crate::system::LashAdjuster`]): their
//! chambers' pressures are states integrated with the motion (after `(q, q̇)`, before the work),
//! their pushes forces on the bodies, their powers channels of the energy balance (after the
//! force elements' and gravity's).

use super::super::model::body_state;
use super::super::DynamicsError;
use super::{AdjusterSample, SystemSimulation};

impl SystemSimulation<'_> {
    /// How many lash adjusters (pressure states) the system has.
    pub(super) fn adjusters(&self) -> usize {
        self.z.len()
    }

    /// Adds each adjuster's push at the pressures `z` to the generalized forces `f` (at the
    /// frames' coordinates `qf`, `qdf`); each one's power written to `powers`.
    pub(super) fn add_adjuster_forces(
        &self,
        qf: &[f64],
        qdf: &[f64],
        z: &[f64],
        f: &mut [f64],
        powers: &mut [f64],
    ) {
        for ((h, &p), power) in self.sys.lash_adjusters().iter().zip(z).zip(powers) {
            if let Some(line) = h.adjuster.line(|id| body_state(qf, qdf, id.0)) {
                *power = h.adjuster.add_forces(&line, p, f);
            }
        }
    }

    /// Each adjuster's pressure rate at `(q, q̇)` (the centres' coordinates) and pressures `z`,
    /// appended to `dz`; an adjuster whose chamber emptied, or whose pressure fell to absolute
    /// zero, stops the run naming it.
    pub(super) fn adjuster_rates(
        &self,
        t: f64,
        q: &[f64],
        qd: &[f64],
        z: &[f64],
        dz: &mut Vec<f64>,
    ) -> Result<(), DynamicsError> {
        if z.is_empty() {
            return Ok(());
        }
        let (qf, qdf) = self.frames(q, qd);
        for (h, &p) in self.sys.lash_adjusters().iter().zip(z) {
            let a = &h.adjuster;
            let line = a.line(|id| body_state(&qf, &qdf, id.0));
            let rate = line.and_then(|l| a.pressure_rate(l.length, l.rate, p));
            match rate {
                Some(r) => dz.push(r),
                None => {
                    let chamber = line.map_or(f64::NAN, |l| a.chamber_at(l.length));
                    let full = chamber > 1e-3 * a.chamber;
                    return Err(DynamicsError::Adjuster {
                        time: t,
                        adjuster: h.name.clone(),
                        what: if full { "pressure (Pa)" } else { "chamber (L)" },
                        value: if full { p } else { chamber },
                        reason: if full {
                            "fell to absolute zero at this instant: the oil would cavitate, which is not modelled (a stronger check valve, a higher supply or less plunger spring)"
                        } else {
                            "emptied at this instant: the plunger bottomed in its bore (a longer chamber, or less load)"
                        },
                    });
                }
            }
        }
        Ok(())
    }

    /// Each adjuster's chamber now.
    pub(super) fn adjuster_samples(&self) -> Vec<AdjusterSample> {
        self.sys
            .lash_adjusters()
            .iter()
            .zip(&self.z)
            .map(|(h, &p)| {
                let a = &h.adjuster;
                let l = a.line(|id| self.state(id.0)).map_or(f64::NAN, |l| l.length);
                AdjusterSample {
                    pressure: p,
                    chamber: a.chamber_at(l),
                    force: a.force(l, p),
                }
            })
            .collect()
    }
}
