//! An applied load: a force at a point of a body and a torque on it, constant or scaled by a
//! table of time, its force fixed in the world (gravity-like: a weight, a pull) or turning with
//! the body (a thrust). What a simulation applies; its work is the power `F·v_P + τ ω`
//! integrated (the column `driver_work` of a simulation counts it with the drivers'), so that
//! the energy less that work stays constant where the run is right.
//!
//! Sense: the force is `(F_x, F_y)` in the world (or in the body's frame, turning with it) and
//! acts at the point `at` of the body's frame; the torque is counter-clockwise positive.

use super::BodyId;
use crate::body::Pose;
use crate::geometry::{cross, rot90, Point2, Vec2};

/// The frame an applied force is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum LoadFrame {
    /// fixed in the world: its direction does not turn with the body
    World,
    /// fixed in the body: it turns with it
    Body,
}

/// A force and a torque applied to a body (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct AppliedLoad {
    /// its name
    pub name: String,
    /// the body it acts on
    pub body: BodyId,
    /// where the force acts, in the body's frame
    pub at: Point2,
    /// the force, N, in `frame`
    pub force: Vec2,
    /// the torque, N·L counter-clockwise
    pub torque: f64,
    /// the frame the force is written in
    pub frame: LoadFrame,
    /// `(t in s, factor)`, increasing in time: the force and torque scaled by the factor,
    /// linear between points and held at the ends; empty: constant
    pub profile: Vec<(f64, f64)>,
}

impl AppliedLoad {
    /// The profile's factor at `t`, s (1 without a profile).
    pub fn factor(&self, t: f64) -> f64 {
        let p = &self.profile;
        let (Some(first), Some(last)) = (p.first(), p.last()) else {
            return 1.0;
        };
        if t <= first.0 {
            return first.1;
        }
        if t >= last.0 {
            return last.1;
        }
        let i = p.partition_point(|q| q.0 <= t);
        let (a, b) = (p[i - 1], p[i]);
        a.1 + (b.1 - a.1) * (t - a.0) / (b.0 - a.0)
    }

    /// Adds its generalized force at `t` to `f` (three a body: the force, and its moment about
    /// the frame's origin with the torque), the body at `pose`; returns its power with the
    /// body's velocity `(v, ω)` (of the frame's origin).
    pub(crate) fn add_force(
        &self,
        t: f64,
        pose: Pose,
        velocity: (Vec2, f64),
        f: &mut [f64],
    ) -> f64 {
        let Some(i) = self.body.index() else {
            return 0.0;
        };
        let k = self.factor(t);
        let force = k * match self.frame {
            LoadFrame::World => self.force,
            LoadFrame::Body => pose.frame().rotation * self.force,
        };
        let torque = k * self.torque;
        let arm = pose.to_world(self.at) - pose.origin;
        f[3 * i] += force.x;
        f[3 * i + 1] += force.y;
        f[3 * i + 2] += cross(arm, force) + torque;
        force.dot(&(velocity.0 + velocity.1 * rot90(arm))) + torque * velocity.1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The profile is linear between points and held at its ends; a body-frame force turns with
    /// the body, its moment about the origin `arm × F`; the power `F·v_P + τ ω`.
    #[test]
    fn a_load_scales_turns_and_says_its_power() {
        let mut load = AppliedLoad {
            name: "push".into(),
            body: BodyId(0),
            at: Point2::new(2.0, 0.0),
            force: Vec2::new(0.0, 10.0),
            torque: 3.0,
            frame: LoadFrame::Body,
            profile: vec![(1.0, 0.0), (3.0, 2.0)],
        };
        assert_eq!(load.factor(0.0), 0.0);
        assert_eq!(load.factor(2.0), 1.0);
        assert_eq!(load.factor(9.0), 2.0);
        // the body turned a quarter: the force (0, 10) in its frame is (−10, 0) in the world,
        // at the point (0, 2) from the origin; ω = 0.5, v = (1, 0)
        let pose = Pose::new(Point2::new(5.0, 5.0), std::f64::consts::FRAC_PI_2);
        let mut f = [0.0; 3];
        let power = load.add_force(2.0, pose, (Vec2::new(1.0, 0.0), 0.5), &mut f);
        assert!((f[0] + 10.0).abs() < 1e-12 && f[1].abs() < 1e-12, "{f:?}");
        // arm (0, 2) × (−10, 0) = 0·0 − 2·(−10) = 20, and the torque 3
        assert!((f[2] - 23.0).abs() < 1e-12, "{f:?}");
        // v_P = v + ω J arm = (1, 0) + 0.5 (−2, 0) = (0, 0): the force does no work; τ ω = 1.5
        assert!((power - 1.5).abs() < 1e-12, "{power}");
        load.frame = LoadFrame::World;
        let mut f = [0.0; 3];
        load.add_force(2.0, pose, (Vec2::zeros(), 0.0), &mut f);
        assert!(f[0].abs() < 1e-12 && (f[1] - 10.0).abs() < 1e-12 && (f[2] - 3.0).abs() < 1e-12);
    }
}
