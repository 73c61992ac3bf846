//! A hydraulic lash adjuster between two bodies: an oil chamber of bore `d` under a plunger,
//! whose gauge pressure `p` (a state of the simulation) pushes the bodies apart along the line
//! from its point on `a` (the body, the bore) to its point on `b` (the plunger's tip), with a
//! plunger spring:
//!
//! ```text
//! F = p A + k (L − L₀) … (a compression spring: + F₀ − k (L − L₀))      A = π d²/4
//! V = A (h₀ + L − L₀)                                                  the chamber's volume
//! ṗ = β(p) / V · (Q_check − Q_leak − A L̇)
//! Q_leak  = π d c³ (p − p_s) / (12 μ ℓ)                                 the plunger's laminar gap
//! Q_check = G (p_s − Δp_c − p)  where positive, else 0                  the check valve
//! 1/β(p) = (1 − a)/β_oil + a/p_abs,  a = α p_atm/p_abs / ((1 − α) e^{−p/β_oil} + α p_atm/p_abs)
//! ```
//!
//! `L` is the distance between its points (`L₀` as drawn), `h₀` the chamber's height as drawn,
//! `c` the plunger's radial clearance and `ℓ` its length, `μ` the oil's viscosity, `p_s` the
//! supply's gauge pressure (the reservoir the leak returns to and the check valve draws from),
//! `Δp_c` the check valve's opening pressure and `G` its flow per pressure open, `β_oil` the
//! oil's bulk modulus and `α` the free air's volume fraction at atmospheric pressure
//! (compressed isothermally: `p_abs = p + p_atm`). The leak is the laminar flow through a
//! narrow annulus (Hagen–Poiseuille between parallel plates of width `π d`: e.g. Merritt,
//! *Hydraulic Control Systems*, 1967, §3.7). Cavitation is not modelled: a chamber whose
//! absolute pressure falls to zero stops the simulation.

use super::BodyId;
use crate::body::BodyState;
use crate::geometry::{cross, Point2};

/// Atmospheric pressure, Pa.
pub const ATMOSPHERE: f64 = 101_325.0;

/// A hydraulic lash adjuster's data (lengths in the system's unit, pressures in Pa, SI
/// otherwise; see the module's docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LashAdjuster {
    /// the body of its bore
    pub a: BodyId,
    /// its point on `a`
    pub at_a: Point2,
    /// the body its plunger pushes
    pub b: BodyId,
    /// its point on `b`
    pub at_b: Point2,
    /// the bore (the plunger's diameter), L
    pub bore: f64,
    /// the chamber's height at the drawn length, L
    pub chamber: f64,
    /// the drawn length (its points' distance as the file places the bodies), L
    pub drawn_length: f64,
    /// the plunger's radial clearance, L
    pub clearance: f64,
    /// the length of the plunger's sealing gap, L
    pub leak_length: f64,
    /// the oil's dynamic viscosity, Pa·s
    pub viscosity: f64,
    /// the oil's bulk modulus, Pa
    pub bulk_modulus: f64,
    /// free air's volume fraction at atmospheric pressure
    pub air_fraction: f64,
    /// the supply's gauge pressure, Pa
    pub supply: f64,
    /// the check valve's opening pressure, Pa
    pub check_opening: f64,
    /// the check valve's flow per pressure open, L³/(s·Pa)
    pub check_flow: f64,
    /// the plunger spring's stiffness, N/L
    pub spring_stiffness: f64,
    /// its push at the drawn length, N
    pub spring_preload: f64,
    /// the chamber's gauge pressure at the start, Pa
    pub initial_pressure: f64,
    /// the system's length unit in metres (the flows' and volumes' unit)
    pub metres_per_unit: f64,
}

/// A named lash adjuster.
#[derive(Debug, Clone, PartialEq)]
pub struct LashAdjusterElement {
    /// its name
    pub name: String,
    /// its data
    pub adjuster: LashAdjuster,
}

/// Its line at the bodies' states: the ends, the unit vector from `a`'s to `b`'s, the length
/// and its rate.
#[derive(Debug, Clone, Copy)]
pub(crate) struct AdjusterLine {
    pa: Point2,
    pb: Point2,
    sa: BodyState,
    sb: BodyState,
    e: crate::Vec2,
    /// its length, L
    pub(crate) length: f64,
    /// the rate of its length, L/s
    pub(crate) rate: f64,
}

impl LashAdjuster {
    /// The plunger's area, L².
    pub fn area(&self) -> f64 {
        0.25 * std::f64::consts::PI * self.bore * self.bore
    }

    /// Its line at the bodies' states (`state` the state of a body); none where its ends meet.
    pub(crate) fn line(&self, state: impl Fn(BodyId) -> BodyState) -> Option<AdjusterLine> {
        let (sa, sb) = (state(self.a), state(self.b));
        let (pa, pb) = (sa.pose.to_world(self.at_a), sb.pose.to_world(self.at_b));
        let d = pb - pa;
        let length = d.norm();
        (length > 0.0).then(|| {
            let e = d / length;
            AdjusterLine {
                pa,
                pb,
                sa,
                sb,
                e,
                length,
                rate: e.dot(&(sb.velocity_at(pb) - sa.velocity_at(pa))),
            }
        })
    }

    /// The chamber's height at length `l`, L.
    pub fn chamber_at(&self, l: f64) -> f64 {
        self.chamber + l - self.drawn_length
    }

    /// The push apart at length `l` and gauge pressure `p`, N (`A` in m²).
    pub fn force(&self, l: f64, p: f64) -> f64 {
        let u = self.metres_per_unit;
        p * self.area() * u * u + self.spring_preload
            - self.spring_stiffness * (l - self.drawn_length)
    }

    /// The oil's effective bulk modulus at gauge pressure `p`, Pa (`None` at or below
    /// absolute zero): of the mixture whose oil's volume goes as `(1 − α) e^{−p/β}` and whose
    /// air's as `α p_atm / p_abs` (isothermal), `1/β_eff = −dV/(V dp)`.
    pub fn bulk_at(&self, p: f64) -> Option<f64> {
        let abs = p + ATMOSPHERE;
        if !(abs > 0.0) {
            return None;
        }
        let alpha = self.air_fraction;
        if alpha == 0.0 {
            return Some(self.bulk_modulus);
        }
        let oil = (1.0 - alpha) * (-p / self.bulk_modulus).exp();
        let air = alpha * ATMOSPHERE / abs;
        let a = air / (oil + air);
        Some(1.0 / ((1.0 - a) / self.bulk_modulus + a / abs))
    }

    /// The leak's and the check valve's flows at gauge pressure `p`, L³/s (into the chamber
    /// positive: the check's; the leak's out of it).
    pub fn flows(&self, p: f64) -> (f64, f64) {
        let u = self.metres_per_unit;
        // π d c³ / (12 μ ℓ), in m³/(s·Pa), then in L³
        let conductance = std::f64::consts::PI * self.bore * u * (self.clearance * u).powi(3)
            / (12.0 * self.viscosity * self.leak_length * u)
            / (u * u * u);
        let leak = conductance * (p - self.supply);
        let check = self.check_flow * (self.supply - self.check_opening - p).max(0.0);
        (check, leak)
    }

    /// The rate of the chamber's gauge pressure at length `l`, its rate `l_rate` and pressure
    /// `p`, Pa/s; none where the chamber is empty (within a thousandth of its drawn height of
    /// the bottom: its pressure's rate grows without bound there) or its absolute pressure is
    /// not positive.
    pub fn pressure_rate(&self, l: f64, l_rate: f64, p: f64) -> Option<f64> {
        if !(self.chamber_at(l) > 1e-3 * self.chamber) {
            return None;
        }
        let volume = self.area() * self.chamber_at(l);
        let beta = self.bulk_at(p)?;
        let (check, leak) = self.flows(p);
        Some(beta / volume * (check - leak - self.area() * l_rate))
    }

    /// Adds its push, at gauge pressure `p`, to the generalized forces `f` (three a body, the
    /// ground's dropped); its power on the bodies, N·L/s (`F L̇`).
    pub(crate) fn add_forces(&self, line: &AdjusterLine, p: f64, f: &mut [f64]) -> f64 {
        let push = self.force(line.length, p);
        let mut add = |id: BodyId, at: Point2, s: &BodyState, force: crate::Vec2| {
            if let Some(i) = id.index() {
                f[3 * i] += force.x;
                f[3 * i + 1] += force.y;
                f[3 * i + 2] += cross(at - s.pose.origin, force);
            }
        };
        add(self.a, line.pa, &line.sa, -push * line.e);
        add(self.b, line.pb, &line.sb, push * line.e);
        push * line.rate
    }

    /// Its hydraulic stiffness as drawn with the oil's own bulk modulus (air only softens it),
    /// N/L: `β A / h₀` (`A`, `h₀` in metres: `β A² / V`) — a bound for the integration's rates.
    pub fn oil_stiffness(&self) -> f64 {
        let u = self.metres_per_unit;
        self.bulk_modulus * self.area() * u * u / self.chamber
    }

    /// The rate at which the open check valve brings the chamber as drawn to the supply, with
    /// the oil's own bulk modulus, 1/s: `β G / V₀`.
    pub fn refill_rate(&self) -> f64 {
        self.bulk_modulus * self.check_flow / (self.area() * self.chamber)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn adjuster() -> LashAdjuster {
        LashAdjuster {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            b: BodyId::GROUND,
            at_b: Point2::new(0.0, 10.0),
            bore: 12.0,
            chamber: 2.0,
            drawn_length: 10.0,
            clearance: 0.005,
            leak_length: 10.0,
            viscosity: 0.01,
            bulk_modulus: 1.5e9,
            air_fraction: 0.0,
            supply: 3e5,
            check_opening: 1e4,
            check_flow: 10.0,
            spring_stiffness: 0.0,
            spring_preload: 0.0,
            initial_pressure: 3e5,
            metres_per_unit: 1e-3,
        }
    }

    /// The leak in SI against the formula written out in metres: `π d c³ Δp / (12 μ ℓ)` with d
    /// = 12 mm, c = 5 µm, ℓ = 10 mm, μ = 0.01 Pa·s, Δp = 10 MPa; the check valve's flow open
    /// and shut; the force `p A`.
    #[test]
    fn the_flows_and_the_force_are_the_formulas_in_si() {
        let h = adjuster();
        let q_si = std::f64::consts::PI * 0.012 * 0.005e-3f64.powi(3) * 1e7 / (12.0 * 0.01 * 0.01);
        let (check, leak) = h.flows(1e7 + 3e5);
        assert_eq!(check, 0.0);
        assert!((leak * 1e-9 - q_si).abs() < 1e-12 * q_si, "{leak} {q_si}");
        let (check, _) = h.flows(0.0);
        assert!((check - 10.0 * (3e5 - 1e4)).abs() < 1e-6);
        let area_si = std::f64::consts::PI * 0.006 * 0.006;
        assert!((h.force(10.0, 1e6) - 1e6 * area_si).abs() < 1e-9 * 1e6 * area_si);
    }

    /// With air, the mixture's bulk modulus: at atmospheric pressure with 1 % air nearly the
    /// air's (`≈ p_atm / α`); at 100 bar with air compressed a hundred-fold, closer to the oil's.
    #[test]
    fn air_softens_the_oil_most_at_low_pressure() {
        let mut h = adjuster();
        h.air_fraction = 0.01;
        let low = h.bulk_at(0.0).unwrap();
        // at gauge 0 the fraction is α itself
        let want = 1.0 / (0.99 / 1.5e9 + 0.01 / ATMOSPHERE);
        assert!((low - want).abs() < 1e-9 * want);
        let high = h.bulk_at(100e5).unwrap();
        assert!(high > 50.0 * low && high < 1.5e9);
        assert_eq!(h.bulk_at(-2e5), None);
    }
}
