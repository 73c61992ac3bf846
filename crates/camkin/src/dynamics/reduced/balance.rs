//! The one-coordinate model's energy balance (see the parent module's docs): the same
//! [`EnergyBalance`] the preset system reports, element for element (the follower's spring,
//! then its damper where it has one), with the same potentials, so that the two models' balances
//! agree where both apply.

use super::Reduced;
use crate::dynamics::{ElementEnergy, EnergyBalance};

impl Reduced<'_> {
    /// The spring's potential at `o`, J: `½ k x² + F₀ x` with `x = o − o_r` (zero at the spring's
    /// rest, where it pushes with its preload `F₀`).
    fn spring_potential(&self, o: f64) -> f64 {
        let x = o - self.o_rest;
        x * (0.5 * self.params.spring_stiffness * x + self.params.spring_preload)
    }

    /// Gravity's potential at `o`, J: `−m g · r` of a slide's frame origin; 0 on an arm, whose
    /// mass is taken at its pivot.
    fn gravity_potential(&self, o: f64) -> f64 {
        if self.rotating {
            return 0.0;
        }
        let r = self.joint.pose(o / self.a).origin;
        -self.params.mass * self.params.gravity.dot(&r.coords)
    }

    /// The follower's kinetic and potential energy at `(o, ȯ)`, J.
    pub(super) fn follower_energy(&self, o: f64, v: f64) -> f64 {
        0.5 * self.m * v * v + self.spring_potential(o) + self.gravity_potential(o)
    }

    /// The damper's loss over `tau` seconds of flight from the current state to the velocity
    /// `v_end`, J: Simpson's rule with the exact state halfway.
    pub(super) fn flight_loss(&self, tau: f64, v_end: f64) -> f64 {
        let c = self.params.damping;
        if c == 0.0 || tau <= 0.0 {
            return 0.0;
        }
        let (_, vm) = self.flight(self.o, self.v, 0.5 * tau);
        c * tau / 6.0 * (self.v * self.v + 4.0 * vm * vm + v_end * v_end)
    }

    /// The energy balance now, J (the follower's: the cam is driven).
    pub fn balance(&self) -> EnergyBalance {
        let (o0, initial) = self.start;
        let (vs, vg) = (
            self.spring_potential(self.o),
            self.gravity_potential(self.o),
        );
        let mut elements = vec![ElementEnergy {
            potential: vs,
            work: self.spring_potential(o0) - vs,
            stores: true,
        }];
        if self.params.damping != 0.0 {
            elements.push(ElementEnergy {
                potential: 0.0,
                work: self.damper_work,
                stores: false,
            });
        }
        let gravity = ElementEnergy {
            potential: vg,
            work: self.gravity_potential(o0) - vg,
            stores: true,
        };
        // a slide's momentum `m v` and its moment `m r × v`; an arm's `I ω` about its pivot
        let body = self.joint.body(self.o / self.a, self.v / self.a, 0.0);
        let (momentum, angular_momentum) = if self.rotating {
            ([0.0; 2], self.m * body.omega)
        } else {
            let p = self.m * body.velocity;
            ([p.x, p.y], body.pose.origin.coords.perp(&p))
        };
        EnergyBalance {
            kinetic: 0.5 * self.m * self.v * self.v,
            elements,
            gravity,
            drivers: self.work,
            applied: 0.0,
            constraints: 0.0,
            impacts: self.impacts,
            projections: 0.0,
            initial,
            momentum,
            angular_momentum,
        }
    }
}
