//! A force given by a table of the crank angle — the gas force on a valve — acting along a fixed
//! world direction at a point of a body. The crank angle is the first driver's angle times
//! `crank_per_driver` (2 for a four-stroke camshaft), the table periodic over `period_deg`, and
//! linear between its points.

use super::BodyId;
use crate::geometry::{cross, Point2, Vec2};

/// A force from a table of the crank angle (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct TableForce {
    /// its name
    pub name: String,
    /// the body it pushes
    pub body: BodyId,
    /// where, in the body's frame
    pub at: Point2,
    /// its direction in the world (unit)
    pub direction: Vec2,
    /// `(crank angle in degrees, N)`, the angles increasing within one period
    pub table: Vec<(f64, f64)>,
    /// crank degrees per degree of the first driver
    pub crank_per_driver: f64,
    /// the table's period, crank degrees (720 for a four-stroke engine)
    pub period_deg: f64,
}

impl TableForce {
    /// The force, N, at `driver_deg` degrees of the first driver from its start.
    pub fn force_at(&self, driver_deg: f64) -> f64 {
        let t = &self.table;
        if t.is_empty() {
            return 0.0;
        }
        let x = (driver_deg * self.crank_per_driver).rem_euclid(self.period_deg);
        let i = t.partition_point(|p| p.0 <= x);
        // the neighbours, across the period's seam
        let (a, b) = match i {
            0 => ((t[t.len() - 1].0 - self.period_deg, t[t.len() - 1].1), t[0]),
            i if i == t.len() => (t[i - 1], (t[0].0 + self.period_deg, t[0].1)),
            i => (t[i - 1], t[i]),
        };
        if b.0 == a.0 {
            return a.1;
        }
        a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)
    }

    /// Adds its generalized force at `driver_deg` to `f` (three a body), the body's pose
    /// `(origin, angle)`; returns its power with the body's velocity `(v, ω)`.
    pub(crate) fn add_force(
        &self,
        driver_deg: f64,
        pose: crate::body::Pose,
        velocity: (Vec2, f64),
        f: &mut [f64],
    ) -> f64 {
        let Some(i) = self.body.index() else {
            return 0.0;
        };
        let force = self.direction * self.force_at(driver_deg);
        let arm = pose.to_world(self.at) - pose.origin;
        f[3 * i] += force.x;
        f[3 * i + 1] += force.y;
        f[3 * i + 2] += cross(arm, force);
        force.dot(&(velocity.0 + velocity.1 * crate::geometry::rot90(arm)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Linear between points, periodic across the seam, the crank twice the driver.
    #[test]
    fn a_table_is_read_linearly_and_periodically() {
        let g = TableForce {
            name: "gas".into(),
            body: BodyId(0),
            at: Point2::origin(),
            direction: Vec2::y(),
            table: vec![(0.0, 100.0), (360.0, 300.0), (540.0, 0.0)],
            crank_per_driver: 2.0,
            period_deg: 720.0,
        };
        assert_eq!(g.force_at(0.0), 100.0);
        assert_eq!(g.force_at(90.0), 200.0); // crank 180°
        assert_eq!(g.force_at(225.0), 150.0); // crank 450°
        assert_eq!(g.force_at(315.0), 50.0); // crank 630°: halfway from 0 N at 540° to 100 N at 720°
        assert_eq!(g.force_at(360.0 + 90.0), 200.0); // the next cycle
        assert_eq!(
            g.force_at(-90.0),
            0.0 + (100.0 - 0.0) * (540.0 - 540.0) / 180.0
        ); // crank 540°
    }
}
