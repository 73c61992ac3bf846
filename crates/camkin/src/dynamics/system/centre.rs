//! Bodies whose centre of mass is away from their frame's origin. The simulation's coordinates
//! are each body's centre of mass and angle, `(x_G, y_G, θ)`, so that `M` stays diagonal (mass,
//! mass, the inertia about the centre); the model's rows, forces and states, written for the
//! frames' origins `o = x_G − R(θ) c`, are carried over here:
//!
//! - a row's gradient `(g_x, g_y, g_θ)` on a body becomes `(g_x, g_y, g_θ + g_x ρ_y − g_y ρ_x)`
//!   with `ρ = R(θ) c` the arm from the origin to the centre in the world, and its `γ` loses
//!   `θ̇² (g_x ρ_x + g_y ρ_y)` (from `ö = ẍ_G − θ̈ Jρ + θ̇² ρ`);
//! - a generalised force `(f_x, f_y, τ_o)` about the origin becomes `(f_x, f_y, τ_o + f_x ρ_y −
//!   f_y ρ_x)`, the moment about the centre (the same map transposed); gravity acts at the
//!   centre and is taken about it as it is.

use super::super::model::{body_state, Load, Row};
use super::super::projection::DenseRows;
use super::SystemSimulation;
use crate::body::BodyState;
use crate::geometry::{Rotation, Vec2};
use std::borrow::Cow;

/// Frame coordinates and rates.
pub(super) type Frames<'q> = (Cow<'q, [f64]>, Cow<'q, [f64]>);

impl SystemSimulation<'_> {
    /// Body `i`'s arm from its frame's origin to its centre of mass, in the world, at `q`.
    fn arm(&self, q: &[f64], i: usize) -> Vec2 {
        let c = self.centres[i];
        if c == Vec2::zeros() {
            return c;
        }
        Rotation::new(q[3 * i + 2]) * c
    }

    /// The frames' coordinates and rates at the centres' `(q, q̇)` (borrowed where every centre
    /// is at its frame's origin).
    pub(super) fn frames<'q>(&self, q: &'q [f64], qd: &'q [f64]) -> Frames<'q> {
        if !self.offset {
            return (Cow::Borrowed(q), Cow::Borrowed(qd));
        }
        let (mut qf, mut qdf) = (q.to_vec(), qd.to_vec());
        for i in 0..self.centres.len() {
            let r = self.arm(q, i);
            let w = qd[3 * i + 2];
            // o = x_G − ρ, ȯ = ẋ_G − θ̇ Jρ
            qf[3 * i] -= r.x;
            qf[3 * i + 1] -= r.y;
            qdf[3 * i] += w * r.y;
            qdf[3 * i + 1] -= w * r.x;
        }
        (Cow::Owned(qf), Cow::Owned(qdf))
    }

    /// The centres' coordinates at the frames' `q` (the rates' map is the same with signs
    /// turned: the state starts at rest, so only positions are needed).
    pub(super) fn centres_at(&self, qf: &mut [f64]) {
        for i in 0..self.centres.len() {
            let r = self.arm(qf, i);
            qf[3 * i] += r.x;
            qf[3 * i + 1] += r.y;
        }
    }

    /// The frames' accelerations from the centres': `ö = ẍ_G − θ̈ Jρ + θ̇² ρ`.
    pub(super) fn frame_accelerations(&self, q: &[f64], qd: &[f64], qdd: &mut [f64]) {
        if !self.offset {
            return;
        }
        for i in 0..self.centres.len() {
            let r = self.arm(q, i);
            let (w, a) = (qd[3 * i + 2], qdd[3 * i + 2]);
            qdd[3 * i] += a * r.y + w * w * r.x;
            qdd[3 * i + 1] += -a * r.x + w * w * r.y;
        }
    }

    /// Body `i`'s frame state (the ground's for [`super::super::GROUND`]) at the centres'
    /// `(q, q̇)`.
    pub(super) fn frame_state(&self, q: &[f64], qd: &[f64], i: usize) -> BodyState {
        let mut s = body_state(q, qd, i);
        if self.offset && i != super::super::GROUND {
            let r = self.arm(q, i);
            let w = qd[3 * i + 2];
            s.pose.origin -= r;
            s.velocity += Vec2::new(w * r.y, -w * r.x);
        }
        s
    }

    /// Every body's arm at `q` (none where every centre is at its frame's origin).
    pub(super) fn arms(&self, q: &[f64]) -> Vec<Vec2> {
        if !self.offset {
            return Vec::new();
        }
        (0..self.centres.len()).map(|i| self.arm(q, i)).collect()
    }

    /// A row of the frames' coordinates made one of the centres' (see the module docs), with
    /// the bodies' `arms` at its `q`.
    pub(super) fn row_about_centres(&self, arms: &[Vec2], qd: &[f64], row: &mut Row) {
        if self.offset {
            row.about_centres(|i| arms[i], qd);
        }
    }

    /// Dense rows of the frames' coordinates made the centres' (their `Φ` and targets are the
    /// same).
    pub(super) fn dense_about_centres(&self, q: &[f64], rows: &mut DenseRows) {
        if !self.offset {
            return;
        }
        let n = q.len();
        let arms = self.arms(q);
        for r in 0..rows.m {
            let jac = &mut rows.jac[r * n..(r + 1) * n];
            for (i, a) in arms.iter().enumerate() {
                jac[3 * i + 2] += jac[3 * i] * a.y - jac[3 * i + 1] * a.x;
            }
        }
    }

    /// Generalised forces about the frames' origins (gravity among them, at the origins) made
    /// the centres' (gravity acts at a centre, with no moment about it).
    pub(super) fn forces_about_centres(&self, q: &[f64], f: &mut [f64]) {
        if !self.offset {
            return;
        }
        let g = self
            .model
            .forces
            .iter()
            .find_map(|e| match e {
                Load::Gravity(g) => Some(*g),
                _ => None,
            })
            .unwrap_or_else(Vec2::zeros);
        for (i, b) in self.model.bodies.iter().enumerate() {
            let a = self.arm(q, i);
            let (fx, fy) = (f[3 * i] - b.mass * g.x, f[3 * i + 1] - b.mass * g.y);
            f[3 * i + 2] += fx * a.y - fy * a.x;
        }
    }
}
