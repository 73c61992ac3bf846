//! Joints between two bodies (or a body and the ground): their rows of `Φ`, of `Φ_q` and of `γ`
//! (Haug 1989, §3.3; Nikravesh 2018, ch. 4), in the coordinates `q_i = (x_i, y_i, θ_i)`.
//!
//! With `s` a point fixed in a body, `ρ = R(θ) s` its arm in the world and `P = r + ρ`:
//!
//! ```text
//! revolute    P_a − P_b = 0                      γ = ω_a² ρ_a − ω_b² ρ_b
//! prismatic   n·(P_b − P_a) = 0, n = R_a k×d     γ = ω_a² n·h − 2 ω_a (k×n)·ḣ + n·(ω_b² ρ_b − ω_a² ρ_a)
//!             θ_b − θ_a − φ = 0                  γ = 0
//! fixed       the revolute's two rows and the prismatic's angle row
//! ```
//!
//! with `h = P_b − P_a` and `ḣ` its rate. Each `γ` is the part of `Φ̈` free of `q̈`, negated, so
//! that `Φ_q q̈ = γ`; the unit tests check every row against finite differences of `Φ`.

use super::BodyId;
use crate::body::BodyState;
use crate::geometry::{rot90, Point2, Vec2};

/// How two bodies are joined.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum JointKind {
    /// A pin: point `at_a` of body `a` and point `at_b` of body `b` (each in its body's frame)
    /// coincide. Two rows.
    Revolute {
        /// the first body
        a: BodyId,
        /// the pin in `a`'s frame
        at_a: Point2,
        /// the second body
        b: BodyId,
        /// the pin in `b`'s frame
        at_b: Point2,
    },
    /// A slide: point `at_b` of `b` stays on the line through `at_a` along `axis` (both in `a`'s
    /// frame), and `b` keeps its angle to `a` (`θ_b − θ_a = angle`). Two rows.
    Prismatic {
        /// the body carrying the guide
        a: BodyId,
        /// a point of the guide's line, in `a`'s frame
        at_a: Point2,
        /// the guide's direction in `a`'s frame (normalised on use)
        axis: Vec2,
        /// the sliding body
        b: BodyId,
        /// the point of `b` on the line, in `b`'s frame
        at_b: Point2,
        /// `θ_b − θ_a`, rad
        angle: f64,
    },
    /// A weld: `at_a` and `at_b` coincide and `θ_b − θ_a = angle`. Three rows.
    Fixed {
        /// the first body
        a: BodyId,
        /// the weld's point in `a`'s frame
        at_a: Point2,
        /// the second body
        b: BodyId,
        /// the weld's point in `b`'s frame
        at_b: Point2,
        /// `θ_b − θ_a`, rad
        angle: f64,
    },
}

/// A named joint.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// its name, as errors name it
    pub name: String,
    /// what it is
    pub kind: JointKind,
}

/// One row at an instant: `Φ`'s value, its gradient in the two bodies' coordinates, and `γ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RowEval {
    pub(crate) value: f64,
    pub(crate) grads: [(BodyId, [f64; 3]); 2],
    pub(crate) gamma: f64,
}

/// An arm's world vector `ρ = R s`, the point `P = r + ρ`, and the point's velocity.
fn arm(s: &BodyState, at: Point2) -> (Vec2, Point2, Vec2) {
    let rho = s.pose.frame().rotation * at.coords;
    let p = s.pose.origin + rho;
    (rho, p, s.velocity + s.omega * rot90(rho))
}

impl JointKind {
    /// The two bodies it joins.
    pub fn bodies(&self) -> [BodyId; 2] {
        match *self {
            JointKind::Revolute { a, b, .. }
            | JointKind::Prismatic { a, b, .. }
            | JointKind::Fixed { a, b, .. } => [a, b],
        }
    }

    /// Its two points: each body with its point, in that body's frame.
    pub fn points(&self) -> [(BodyId, Point2); 2] {
        match *self {
            JointKind::Revolute { a, at_a, b, at_b }
            | JointKind::Prismatic {
                a, at_a, b, at_b, ..
            }
            | JointKind::Fixed {
                a, at_a, b, at_b, ..
            } => [(a, at_a), (b, at_b)],
        }
    }

    /// How many rows it adds.
    pub fn rows(&self) -> usize {
        match self {
            JointKind::Revolute { .. } | JointKind::Prismatic { .. } => 2,
            JointKind::Fixed { .. } => 3,
        }
    }

    /// What row `k` constrains, for messages.
    pub(crate) fn row_label(&self, k: usize) -> &'static str {
        match (self, k) {
            (JointKind::Prismatic { .. }, 0) => "across the guide",
            (JointKind::Prismatic { .. }, _) => "angle",
            (_, 0) => "x",
            (_, 1) => "y",
            _ => "angle",
        }
    }

    /// Its rows with the bodies in states `a` and `b` (poses and velocities), added to `out`
    /// (a `Vec`, or a fixed buffer of three where a step must not allocate).
    pub(crate) fn eval(&self, a: &BodyState, b: &BodyState, out: &mut impl Extend<RowEval>) {
        let [ia, ib] = self.bodies();
        match *self {
            JointKind::Revolute { at_a, at_b, .. } => pin(ia, a, at_a, ib, b, at_b, out),
            JointKind::Fixed {
                at_a, at_b, angle, ..
            } => {
                pin(ia, a, at_a, ib, b, at_b, out);
                out.extend([same_angle(ia, a, ib, b, angle)]);
            }
            JointKind::Prismatic {
                at_a,
                axis,
                at_b,
                angle,
                ..
            } => {
                let (rho_a, pa, va) = arm(a, at_a);
                let (rho_b, pb, vb) = arm(b, at_b);
                let d = unit(axis);
                let n = a.pose.frame().rotation * rot90(d);
                let h = pb - pa;
                let hd = vb - va;
                let wa = a.omega;
                out.extend([RowEval {
                    value: n.dot(&h),
                    grads: [
                        (ia, [-n.x, -n.y, -n.dot(&rot90(rho_a)) + rot90(n).dot(&h)]),
                        (ib, [n.x, n.y, n.dot(&rot90(rho_b))]),
                    ],
                    gamma: wa * wa * n.dot(&h) - 2.0 * wa * rot90(n).dot(&hd)
                        + n.dot(&(b.omega * b.omega * rho_b - wa * wa * rho_a)),
                }]);
                out.extend([same_angle(ia, a, ib, b, angle)]);
            }
        }
    }
}

/// The two rows of a pin.
fn pin(
    ia: BodyId,
    a: &BodyState,
    at_a: Point2,
    ib: BodyId,
    b: &BodyState,
    at_b: Point2,
    out: &mut impl Extend<RowEval>,
) {
    let (rho_a, pa, _) = arm(a, at_a);
    let (rho_b, pb, _) = arm(b, at_b);
    let (ta, tb) = (rot90(rho_a), rot90(rho_b));
    let g = a.omega * a.omega * rho_a - b.omega * b.omega * rho_b;
    out.extend([
        RowEval {
            value: pa.x - pb.x,
            grads: [(ia, [1.0, 0.0, ta.x]), (ib, [-1.0, 0.0, -tb.x])],
            gamma: g.x,
        },
        RowEval {
            value: pa.y - pb.y,
            grads: [(ia, [0.0, 1.0, ta.y]), (ib, [0.0, -1.0, -tb.y])],
            gamma: g.y,
        },
    ]);
}

/// `θ_b − θ_a − angle = 0`.
fn same_angle(ia: BodyId, a: &BodyState, ib: BodyId, b: &BodyState, angle: f64) -> RowEval {
    RowEval {
        value: b.pose.angle - a.pose.angle - angle,
        grads: [(ia, [0.0, 0.0, -1.0]), (ib, [0.0, 0.0, 1.0])],
        gamma: 0.0,
    }
}

/// `v` made a unit vector by its largest component first (a direction `[1e-300, 0]` is the x
/// axis: its norm's square underflows).
pub(super) fn unit(v: Vec2) -> Vec2 {
    (v / v.x.abs().max(v.y.abs())).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::Pose;

    /// A body moving as `q(t) = q0 + v t + a t²/2`.
    fn body(q0: [f64; 3], v: [f64; 3], acc: [f64; 3], t: f64) -> BodyState {
        let q = |k: usize| q0[k] + v[k] * t + 0.5 * acc[k] * t * t;
        let qd = |k: usize| v[k] + acc[k] * t;
        BodyState {
            pose: Pose::new(Point2::new(q(0), q(1)), q(2)),
            velocity: Vec2::new(qd(0), qd(1)),
            omega: qd(2),
            acceleration: Vec2::new(acc[0], acc[1]),
            alpha: acc[2],
        }
    }

    /// Every row's gradient is the derivative of its value along the motion (`Φ̇ = Φ_q q̇`), and
    /// `Φ_q q̈ − γ` is its second derivative, both by central differences in time, for each
    /// joint kind, with both bodies moving and turning.
    #[test]
    fn rows_match_finite_differences_of_the_constraint() {
        let (ia, ib) = (BodyId(0), BodyId(1));
        let kinds = [
            JointKind::Revolute {
                a: ia,
                at_a: Point2::new(0.7, -0.2),
                b: ib,
                at_b: Point2::new(-0.3, 0.9),
            },
            JointKind::Prismatic {
                a: ia,
                at_a: Point2::new(0.4, 0.1),
                axis: Vec2::new(0.6, 1.3),
                b: ib,
                at_b: Point2::new(-0.5, 0.25),
                angle: 0.3,
            },
            JointKind::Fixed {
                a: ia,
                at_a: Point2::new(1.1, 0.2),
                b: ib,
                at_b: Point2::new(0.1, -0.6),
                angle: -0.8,
            },
        ];
        let (qa, va, aa) = ([0.3, -0.4, 0.7], [1.2, -0.6, 2.1], [-0.9, 1.7, -3.3]);
        let (qb, vb, ab) = ([1.5, 0.8, -0.4], [-0.7, 0.9, -1.4], [2.2, 0.4, 2.6]);
        let rows_at = |k: &JointKind, t: f64| {
            let mut out = Vec::new();
            k.eval(&body(qa, va, aa, t), &body(qb, vb, ab, t), &mut out);
            out
        };
        let dot = |g: [f64; 3], x: [f64; 3]| g[0] * x[0] + g[1] * x[1] + g[2] * x[2];
        for k in &kinds {
            let r0 = rows_at(k, 0.0);
            assert_eq!(r0.len(), k.rows());
            let h = 1e-4;
            let (rp, rm) = (rows_at(k, h), rows_at(k, -h));
            for (i, r) in r0.iter().enumerate() {
                let [(_, ga), (_, gb)] = r.grads;
                let rate = dot(ga, va) + dot(gb, vb);
                let fd1 = (rp[i].value - rm[i].value) / (2.0 * h);
                assert!((rate - fd1).abs() < 1e-7, "{k:?} row {i}: {rate} {fd1}");
                let second = dot(ga, aa) + dot(gb, ab) - r.gamma;
                let fd2 = (rp[i].value - 2.0 * r.value + rm[i].value) / (h * h);
                assert!(
                    (second - fd2).abs() < 1e-5 * second.abs().max(1.0),
                    "{k:?} row {i}: {second} {fd2}"
                );
            }
        }
    }
}
