//! A force element's generalized forces and potential energy at the bodies' states: what the
//! dynamics of a system applies (the kinematic analysis does not need them).
//!
//! A spring or damper between points `P_a` (on `a`) and `P_b` (on `b`) pulls them together with
//! its tension `T` along `e = (P_b − P_a)/L`: `+T e` at `P_a`, `−T e` at `P_b`, each with its
//! moment `(P − r) × F` about its body's origin (the generalized force on `(x, y, θ)`). A torsion
//! spring's (or torsion damper's) torque `τ` acts `+τ` on `a` and `−τ` on `b`.

use super::{BodyId, ForceKind};
use crate::body::BodyState;
use crate::geometry::{cross, Point2, Vec2};

/// A spring's or damper's line between its ends at the bodies' states: each end's state and
/// world point, the unit vector from `a`'s end to `b`'s, and the length.
#[derive(Clone, Copy)]
struct Line {
    sa: BodyState,
    sb: BodyState,
    pa: Point2,
    pb: Point2,
    e: Vec2,
    l: f64,
}

impl Line {
    /// The line from `at_a` on `a` to `at_b` on `b`; none where the ends meet (no direction).
    fn new(
        state: &impl Fn(BodyId) -> BodyState,
        (a, at_a): (BodyId, Point2),
        (b, at_b): (BodyId, Point2),
    ) -> Option<Self> {
        let (sa, sb) = (state(a), state(b));
        let (pa, pb) = (sa.pose.to_world(at_a), sb.pose.to_world(at_b));
        let d = pb - pa;
        let l = d.norm();
        (l > 0.0).then(|| Self {
            sa,
            sb,
            pa,
            pb,
            e: d / l,
            l,
        })
    }

    /// The rate of its length, `L̇ = e · (v_b − v_a)` at the ends.
    fn rate(&self) -> f64 {
        self.e
            .dot(&(self.sb.velocity_at(self.pb) - self.sa.velocity_at(self.pa)))
    }
}

/// Where a force element acts: each end's body and world point, the tension (or torque) and the
/// potential energy stored.
impl ForceKind {
    /// Adds the element's generalized forces to `f` (three a body, in the system's order; the
    /// ground's are dropped), with `state` the state of a body (the ground's at rest).
    pub(crate) fn add_forces(&self, state: impl Fn(BodyId) -> BodyState, f: &mut [f64]) {
        let mut add = |id: BodyId, at: Point2, s: &BodyState, force: Vec2| {
            if let Some(i) = id.index() {
                f[3 * i] += force.x;
                f[3 * i + 1] += force.y;
                f[3 * i + 2] += cross(at - s.pose.origin, force);
            }
        };
        match *self {
            ForceKind::Spring {
                a, at_a, b, at_b, ..
            }
            | ForceKind::Damper {
                a, at_a, b, at_b, ..
            } => {
                let Some(line) = Line::new(&state, (a, at_a), (b, at_b)) else {
                    return;
                };
                let push = self.tension(&line) * line.e;
                add(a, line.pa, &line.sa, push);
                add(b, line.pb, &line.sb, -push);
            }
            ForceKind::TorsionSpring {
                a,
                b,
                stiffness,
                free_angle,
                preload,
            } => {
                let (ta, tb) = (state(a).pose.angle, state(b).pose.angle);
                let torque = stiffness * (tb - ta - free_angle) + preload;
                if let Some(i) = a.index() {
                    f[3 * i + 2] += torque;
                }
                if let Some(i) = b.index() {
                    f[3 * i + 2] -= torque;
                }
            }
            ForceKind::TorsionDamper { a, b, damping } => {
                let torque = damping * (state(b).omega - state(a).omega);
                if let Some(i) = a.index() {
                    f[3 * i + 2] += torque;
                }
                if let Some(i) = b.index() {
                    f[3 * i + 2] -= torque;
                }
            }
        }
    }

    /// The power the element delivers to the bodies (N·length/s): `−T L̇` for a spring or
    /// damper of tension `T` whose length changes at `L̇` (a damper's `−c L̇² ≤ 0`), `−τ (ω_b −
    /// ω_a)` for a torsion spring or damper — the rate of work of the forces
    /// [`ForceKind::add_forces`] applies, so that a spring's is minus its potential's rate.
    pub(crate) fn power(&self, state: impl Fn(BodyId) -> BodyState) -> f64 {
        match *self {
            ForceKind::Spring {
                a, at_a, b, at_b, ..
            }
            | ForceKind::Damper {
                a, at_a, b, at_b, ..
            } => {
                let Some(line) = Line::new(&state, (a, at_a), (b, at_b)) else {
                    return 0.0;
                };
                let (tension, rate) = (self.tension(&line), line.rate());
                -tension * rate
            }
            ForceKind::TorsionSpring {
                a,
                b,
                stiffness,
                free_angle,
                preload,
            } => {
                let (sa, sb) = (state(a), state(b));
                let torque = stiffness * (sb.pose.angle - sa.pose.angle - free_angle) + preload;
                -torque * (sb.omega - sa.omega)
            }
            ForceKind::TorsionDamper { a, b, damping } => {
                let rate = state(b).omega - state(a).omega;
                -damping * rate * rate
            }
        }
    }

    /// A spring's or damper's tension along its line: `k (L − L₀) + P`, or `c L̇` (0 for a
    /// torsion element).
    fn tension(&self, line: &Line) -> f64 {
        match *self {
            ForceKind::Spring {
                stiffness,
                free_length,
                preload,
                ..
            } => stiffness * (line.l - free_length) + preload,
            ForceKind::Damper { damping, .. } => damping * line.rate(),
            ForceKind::TorsionSpring { .. } | ForceKind::TorsionDamper { .. } => 0.0,
        }
    }

    /// Whether the element stores its work as a potential (a spring), or dissipates it (a
    /// damper).
    pub(crate) fn stores(&self) -> bool {
        matches!(
            self,
            ForceKind::Spring { .. } | ForceKind::TorsionSpring { .. }
        )
    }

    /// The potential energy stored (N·length): `½ k (L − L₀)² + P (L − L₀)` for a spring (its
    /// tension's integral from the free length), the same in the angle for a torsion spring;
    /// zero for a damper.
    pub(crate) fn potential(&self, state: impl Fn(BodyId) -> BodyState) -> f64 {
        match *self {
            ForceKind::Spring {
                a,
                at_a,
                b,
                at_b,
                stiffness,
                free_length,
                preload,
            } => {
                let (pa, pb) = (state(a).pose.to_world(at_a), state(b).pose.to_world(at_b));
                let x = (pb - pa).norm() - free_length;
                0.5 * stiffness * x * x + preload * x
            }
            ForceKind::TorsionSpring {
                a,
                b,
                stiffness,
                free_angle,
                preload,
            } => {
                let x = state(b).pose.angle - state(a).pose.angle - free_angle;
                0.5 * stiffness * x * x + preload * x
            }
            ForceKind::Damper { .. } | ForceKind::TorsionDamper { .. } => 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::Pose;

    /// Each element's generalized forces are minus the gradient of its potential (central
    /// differences in every coordinate of both bodies), and a damper's force opposes the rate of
    /// its length.
    #[test]
    fn forces_are_the_potentials_gradients() {
        let (ia, ib) = (BodyId(0), BodyId(1));
        let kinds = [
            ForceKind::Spring {
                a: ia,
                at_a: Point2::new(0.3, -0.2),
                b: ib,
                at_b: Point2::new(-0.4, 0.5),
                stiffness: 7.0,
                free_length: 1.1,
                preload: -3.0,
            },
            ForceKind::TorsionSpring {
                a: ia,
                b: ib,
                stiffness: 5.0,
                free_angle: 0.2,
                preload: 1.5,
            },
        ];
        let q0 = [0.1, 0.2, 0.3, 1.6, 0.9, -0.7];
        let st = |q: &[f64; 6]| {
            let q = *q;
            move |id: BodyId| {
                let i = id.index().unwrap();
                BodyState::at_rest(Pose::new(Point2::new(q[3 * i], q[3 * i + 1]), q[3 * i + 2]))
            }
        };
        for k in &kinds {
            let mut f = [0.0; 6];
            k.add_forces(st(&q0), &mut f);
            for c in 0..6 {
                let h = 1e-6;
                let (mut qp, mut qm) = (q0, q0);
                qp[c] += h;
                qm[c] -= h;
                let grad = (k.potential(st(&qp)) - k.potential(st(&qm))) / (2.0 * h);
                assert!(
                    (f[c] + grad).abs() < 1e-7,
                    "{k:?} coordinate {c}: {} {grad}",
                    f[c]
                );
            }
        }
        // a damper between two points moving apart pulls them together
        let damper = ForceKind::Damper {
            a: ia,
            at_a: Point2::origin(),
            b: ib,
            at_b: Point2::origin(),
            damping: 2.0,
        };
        let moving = |id: BodyId| {
            let mut s = BodyState::at_rest(Pose::new(
                Point2::new(if id == ia { 0.0 } else { 3.0 }, 0.0),
                0.0,
            ));
            if id == ib {
                s.velocity = Vec2::new(0.5, 0.0);
            }
            s
        };
        let mut f = [0.0; 6];
        damper.add_forces(moving, &mut f);
        assert!(
            (f[0] - 1.0).abs() < 1e-15 && (f[3] + 1.0).abs() < 1e-15,
            "{f:?}"
        );
        // a torsion damper between bodies turning apart (b at 0.5 rad/s, a at −0.25) slows
        // both: −c Δω on b, +c Δω on a
        let torsion = ForceKind::TorsionDamper {
            a: ia,
            b: ib,
            damping: 4.0,
        };
        let turning = |id: BodyId| {
            let mut s = BodyState::at_rest(Pose::new(Point2::origin(), 0.0));
            s.omega = if id == ib { 0.5 } else { -0.25 };
            s
        };
        let mut f = [0.0; 6];
        torsion.add_forces(turning, &mut f);
        assert_eq!(f, [0.0, 0.0, 3.0, 0.0, 0.0, -3.0]);
        assert_eq!(torsion.potential(turning), 0.0);
    }

    /// Each element's power is the work rate of its generalized forces, `Q · q̇` (the forces at
    /// the bodies' origins against their rates), for bodies moving and turning; a spring's is
    /// minus its potential's rate (central differences along the motion), a damper's ≤ 0.
    #[test]
    fn power_is_the_forces_rate_of_work() {
        let (ia, ib) = (BodyId(0), BodyId(1));
        let (pa, pb) = (Point2::new(0.3, -0.2), Point2::new(-0.4, 0.5));
        let kinds = [
            ForceKind::Spring {
                a: ia,
                at_a: pa,
                b: ib,
                at_b: pb,
                stiffness: 7.0,
                free_length: 1.1,
                preload: -3.0,
            },
            ForceKind::Damper {
                a: ia,
                at_a: pa,
                b: ib,
                at_b: pb,
                damping: 2.5,
            },
            ForceKind::TorsionSpring {
                a: ia,
                b: ib,
                stiffness: 5.0,
                free_angle: 0.2,
                preload: 1.5,
            },
            ForceKind::TorsionDamper {
                a: ia,
                b: ib,
                damping: 4.0,
            },
        ];
        let q0 = [0.1, 0.2, 0.3, 1.6, 0.9, -0.7];
        let v = [0.7, -1.3, 2.1, -0.4, 0.9, -1.7];
        let st = |t: f64| {
            move |id: BodyId| {
                let i = id.index().unwrap();
                let q = |c: usize| q0[3 * i + c] + t * v[3 * i + c];
                let mut s = BodyState::at_rest(Pose::new(Point2::new(q(0), q(1)), q(2)));
                s.velocity = Vec2::new(v[3 * i], v[3 * i + 1]);
                s.omega = v[3 * i + 2];
                s
            }
        };
        for k in &kinds {
            let mut f = [0.0; 6];
            k.add_forces(st(0.0), &mut f);
            let work_rate: f64 = f.iter().zip(&v).map(|(a, b)| a * b).sum();
            let p = k.power(st(0.0));
            assert!((p - work_rate).abs() < 1e-12, "{k:?}: {p} {work_rate}");
            if k.stores() {
                let h = 1e-6;
                let rate = (k.potential(st(h)) - k.potential(st(-h))) / (2.0 * h);
                assert!((p + rate).abs() < 1e-7, "{k:?}: {p} {rate}");
            } else {
                assert!(p < 0.0, "{k:?}: {p}");
            }
        }
    }
}
