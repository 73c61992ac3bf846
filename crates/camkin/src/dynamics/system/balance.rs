//! A simulated system's energy balance: the kinetic energy, each element's potential, and the
//! work every force has done since the start — integrated with the motion as extra components
//! of the state (the powers' quadrature on the steps the motion takes) — so that a run shows it
//! is right: the total `T + V` has changed by the work of the drivers, the applied loads and the
//! dampers, the impacts' losses and the projections' corrections, and by nothing else (the
//! joints' and closed contacts' forces, ideal, do no work).
//!
//! The channels of work integrated beside `(q, q̇)`: the drivers' ([`DRIVERS`]), the applied
//! loads' and the forces from tables of the crank angle ([`APPLIED`]), the joints' and closed
//! contacts' constraint forces ([`CONSTRAINTS`]: `−λᵀ Φ_q q̇` over their rows), then one per
//! force element in the system's order, gravity where there is gravity, and one per lash
//! adjuster.

use super::super::model::{body_state, Load};
use super::SystemSimulation;

/// The channel of the drivers' work.
pub(super) const DRIVERS: usize = 0;
/// The channel of the applied loads' and the forces from tables of the crank angle.
pub(super) const APPLIED: usize = 1;
/// The channel of the joints' and closed contacts' forces.
pub(super) const CONSTRAINTS: usize = 2;
/// The first element's channel.
pub(super) const ELEMENTS: usize = 3;

/// A force element's (or gravity's) share of the balance.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct ElementEnergy {
    /// the energy it stores now (a spring's `½ k x² + P x`, gravity's `−m g · r`; a damper's 0),
    /// N·L
    pub potential: f64,
    /// the work it has done on the bodies since the start, N·L: a spring's is minus its
    /// potential's change (to the integration's tolerance), a damper's negative (dissipated)
    pub work: f64,
    /// whether it stores its work (a spring, gravity) or dissipates it (a damper)
    pub stores: bool,
}

/// The energy and work of a simulated system at one instant (N·L: N·mm in a file in mm), and its
/// momentum.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct EnergyBalance {
    /// `½ Σ (m v_G² + I_G ω²)`, the centres' speeds
    pub kinetic: f64,
    /// each force element's, in the system's order, then each lash adjuster's (its work with
    /// the dampers': its oil leaks and refills, its compression is not counted as stored)
    pub elements: Vec<ElementEnergy>,
    /// gravity's (all zero where there is none)
    pub gravity: ElementEnergy,
    /// the drivers' work since the start (their effort times their coordinate's rate, and
    /// their impulses' in impacts)
    pub drivers: f64,
    /// the applied loads' and the forces from tables of the crank angle (a gas force)
    pub applied: f64,
    /// the joints' and closed contacts' forces: zero for ideal joints and frictionless
    /// contacts, to the tolerance (a check, not a loss)
    pub constraints: f64,
    /// the energy the impacts lost (≤ 0; 0 at a restitution of 1): their change of the kinetic
    /// energy less their driver impulses' work (which [`EnergyBalance::drivers`] counts)
    pub impacts: f64,
    /// the energy the projections onto the rows changed (a step's drift taken away: of the
    /// tolerance)
    pub projections: f64,
    /// `T + V` at the start
    pub initial: f64,
    /// the linear momentum `Σ m v_G`, N·s
    pub momentum: [f64; 2],
    /// the angular momentum about the world's origin, `Σ (m r_G × v_G + I_G ω)`, N·L·s
    pub angular_momentum: f64,
}

impl EnergyBalance {
    /// The potential energy stored: the elements' and gravity's.
    pub fn potential(&self) -> f64 {
        self.elements.iter().map(|e| e.potential).sum::<f64>() + self.gravity.potential
    }

    /// `T + V`.
    pub fn total(&self) -> f64 {
        self.kinetic + self.potential()
    }

    /// The work the dampers have done (≤ 0: the energy they dissipated is its negative).
    pub fn dampers(&self) -> f64 {
        self.elements
            .iter()
            .filter(|e| !e.stores)
            .map(|e| e.work)
            .sum()
    }

    /// What the balance leaves unexplained: the change of `T + V` since the start less the
    /// work of the drivers, applied loads, dampers and constraint forces, the impacts' and the
    /// projections' changes. Zero but for the integration's error.
    pub fn residual(&self) -> f64 {
        self.total()
            - self.initial
            - (self.drivers
                + self.applied
                + self.dampers()
                + self.constraints
                + self.impacts
                + self.projections)
    }
}

impl EnergyBalance {
    /// The balance with every energy times `k` (a change of length unit: J to N·mm is
    /// `k = 1000`); the momentum (N·s) as it is, the angular momentum times `k`.
    pub fn scaled(&self, k: f64) -> Self {
        let e = |x: &ElementEnergy| ElementEnergy {
            potential: k * x.potential,
            work: k * x.work,
            stores: x.stores,
        };
        Self {
            kinetic: k * self.kinetic,
            elements: self.elements.iter().map(e).collect(),
            gravity: e(&self.gravity),
            drivers: k * self.drivers,
            applied: k * self.applied,
            constraints: k * self.constraints,
            impacts: k * self.impacts,
            projections: k * self.projections,
            initial: k * self.initial,
            momentum: self.momentum,
            angular_momentum: k * self.angular_momentum,
        }
    }

    /// The six parts a time series shows, in the order of [`EnergyBalance::PARTS`].
    pub fn parts(&self) -> [f64; 6] {
        [
            self.kinetic,
            self.potential(),
            self.dampers(),
            self.constraints,
            self.impacts,
            self.residual(),
        ]
    }

    /// The names of the columns of [`EnergyBalance::parts`] (without their unit): the kinetic
    /// and potential energy, the dampers' work (≤ 0), the joints' and contacts' work (0 where
    /// the run is right), the impacts' change of energy (≤ 0), and what the balance leaves
    /// unexplained (0 but for the integration's error).
    pub const PARTS: [&'static str; 6] = [
        "kinetic",
        "potential",
        "damper_work",
        "constraint_work",
        "impact_energy",
        "unexplained",
    ];
}

impl EnergyBalance {
    /// The balance for people, one line (energies in N·`unit`, six significant digits): the
    /// energy now and at the start, each work that is not zero, and what is left unexplained
    /// with its size against the largest term.
    pub fn describe(&self, unit: &str) -> String {
        use crate::human::human;
        let mut parts = vec![
            format!("kinetic {}", human(self.kinetic)),
            format!("potential {}", human(self.potential())),
            format!("(start {})", human(self.initial)),
        ];
        for (what, v) in [
            ("drivers' work", self.drivers),
            ("loads' work", self.applied),
            ("dampers' work", self.dampers()),
            ("impacts", self.impacts),
        ] {
            if v != 0.0 {
                parts.push(format!("{what} {}", human(v)));
            }
        }
        parts.push(format!(
            "joints' and contacts' work {}",
            human(self.constraints)
        ));
        let scale = [
            self.kinetic,
            self.potential(),
            self.initial,
            self.drivers,
            self.applied,
            self.dampers(),
            self.impacts,
        ]
        .iter()
        .fold(0.0f64, |m, x| m.max(x.abs()));
        let unexplained = self.residual();
        parts.push(format!(
            "unexplained {}{}",
            human(unexplained),
            if scale > 0.0 {
                format!(" ({} of the largest)", human(unexplained.abs() / scale))
            } else {
                String::new()
            }
        ));
        format!("energy balance (N·{unit}): {}", parts.join(", "))
    }
}

impl SystemSimulation<'_> {
    /// The number of work channels (see the module docs).
    pub(super) fn channels(&self) -> usize {
        ELEMENTS + self.model.forces.len() + self.adjusters()
    }

    /// Each element's power at `(q, q̇)` (the centres' coordinates), from the element channel
    /// on of `powers`.
    pub(super) fn element_powers(&self, q: &[f64], qd: &[f64], powers: &mut [f64]) {
        let (qf, qdf) = self.frames(q, qd);
        for (f, p) in self.model.forces.iter().zip(&mut powers[ELEMENTS..]) {
            *p = match f {
                Load::Element(kind) => kind.power(|id| body_state(&qf, &qdf, id.0)),
                Load::Gravity(g) => self
                    .model
                    .bodies
                    .iter()
                    .enumerate()
                    .map(|(i, b)| b.mass * (g.x * qd[3 * i] + g.y * qd[3 * i + 1]))
                    .sum(),
            };
        }
    }

    /// The kinetic energy at the current state.
    fn kinetic(&self) -> f64 {
        self.model
            .bodies
            .iter()
            .enumerate()
            .map(|(i, b)| {
                let v = &self.qd[3 * i..3 * i + 3];
                0.5 * (b.mass * (v[0] * v[0] + v[1] * v[1]) + b.inertia * v[2] * v[2])
            })
            .sum()
    }

    /// Each element's potential energy at the current state, in the model's order.
    fn potentials(&self) -> impl Iterator<Item = f64> + '_ {
        self.model.forces.iter().map(|f| match f {
            Load::Element(kind) => kind.potential(|id| self.state(id.0)),
            Load::Gravity(g) => self
                .model
                .bodies
                .iter()
                .enumerate()
                .map(|(i, b)| -b.mass * (g.x * self.q[3 * i] + g.y * self.q[3 * i + 1]))
                .sum(),
        })
    }

    /// Kinetic plus potential energy at the current state, N·L.
    pub(super) fn energy(&self) -> f64 {
        self.kinetic() + self.potentials().sum::<f64>()
    }

    /// The energy balance at the current state.
    pub fn balance(&self) -> EnergyBalance {
        let mut elements = Vec::with_capacity(self.sys.forces().len());
        let mut gravity = ElementEnergy::default();
        for ((f, potential), &work) in self
            .model
            .forces
            .iter()
            .zip(self.potentials())
            .zip(&self.work[ELEMENTS..])
        {
            match f {
                Load::Element(kind) => elements.push(ElementEnergy {
                    potential,
                    work,
                    stores: kind.stores(),
                }),
                Load::Gravity(_) => {
                    gravity = ElementEnergy {
                        potential,
                        work,
                        stores: true,
                    }
                }
            }
        }
        // the lash adjusters': their oil's compression not counted as stored (its leak and check
        // valve dissipate): their work is the dampers' kind
        let from = ELEMENTS + self.model.forces.len();
        for &work in &self.work[from..] {
            elements.push(ElementEnergy {
                potential: 0.0,
                work,
                stores: false,
            });
        }
        let (mut momentum, mut angular_momentum) = ([0.0; 2], 0.0);
        for (i, b) in self.model.bodies.iter().enumerate() {
            let (r, v) = (&self.q[3 * i..3 * i + 3], &self.qd[3 * i..3 * i + 3]);
            momentum[0] += b.mass * v[0];
            momentum[1] += b.mass * v[1];
            angular_momentum += b.mass * (r[0] * v[1] - r[1] * v[0]) + b.inertia * v[2];
        }
        EnergyBalance {
            kinetic: self.kinetic(),
            elements,
            gravity,
            drivers: self.work[DRIVERS],
            applied: self.work[APPLIED],
            constraints: self.work[CONSTRAINTS],
            impacts: self.impacts,
            projections: self.projections,
            initial: self.initial_energy,
            momentum,
            angular_momentum,
        }
    }
}
