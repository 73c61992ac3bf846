//! A coil spring with mass (a valve spring): `masses` lumped masses in a chain between its two
//! ends, each on a slide along the spring's axis, joined by `masses + 1` equal segment springs —
//! the model that shows spring surge — with coil clash as unilateral contacts between neighbours
//! when a segment closes to its share of the solid length.
//!
//! With `N` masses of `m/N` and `N + 1` segments of `(N + 1) k` (the whole spring `k`, `m`), the
//! chain with its ends held vibrates at the fixed–fixed chain's frequencies
//! `ω_j = 2 √((N + 1) k N / m) sin(j π / (2 (N + 1)))`, `j = 1 … N`, whose lowest tends to the
//! continuous spring's `π √(k/m)` as `N` grows.
//!
//! Its internal damping (the wire's hysteresis and the coils' friction) is stiffness-
//! proportional: a damper `β k_s` beside each segment spring `k_s`, so that the chain's damping
//! matrix is `β K` and each surge mode decays on its own with the ratio `ζ_j = β ω_j / 2`;
//! `β = 2 ζ / ω₁` gives the first mode the ratio asked (a valve spring: a few per cent of
//! critical), the higher modes more.

use super::{Body, BodyId, Contact, ForceElement, ForceKind, Joint, JointKind, System};
use crate::body::Pose;
use crate::curve::{Line, PointCurve};
use crate::geometry::{rot90, Point2, Vec2};
use std::sync::Arc;

/// A coil spring with mass between two bodies (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct CoilSpring {
    /// its name: its masses are `"<name> mass 1"` …, its segments `"<name> segment 1"` …
    pub name: String,
    /// the body its first end sits on (a valve spring: the ground, the head's seat)
    pub a: BodyId,
    /// that end, in `a`'s frame
    pub at_a: Point2,
    /// the body its other end pushes (the valve's retainer)
    pub b: BodyId,
    /// that end, in `b`'s frame
    pub at_b: Point2,
    /// the whole spring's stiffness, N per length
    pub stiffness: f64,
    /// its free length
    pub free_length: f64,
    /// its tension at the free length, N (as a [`ForceKind::Spring`]'s)
    pub preload: f64,
    /// the active coils' mass, kg
    pub mass: f64,
    /// lumped masses in the chain (0: a massless spring, one segment)
    pub masses: usize,
    /// the length at which its coils touch (coil clash), or none
    pub solid_length: Option<f64>,
    /// the first surge mode's damping ratio (0: undamped; see the module docs)
    pub damping_ratio: f64,
}

impl CoilSpring {
    /// Adds it to `sys` with both bodies at their starting poses: its masses, evenly along the
    /// line between its ends, each on a slide along that line (in `a`'s frame), the segment
    /// springs, and (with a solid length) a contact between each pair of neighbours that closes
    /// when their segment is its share of the solid length, and with a damping ratio a damper
    /// beside each segment (`metres_per_unit`: the length unit of its stiffness, for its surge
    /// frequency). Returns the masses' ids.
    pub fn add_to(&self, sys: &mut System, metres_per_unit: f64) -> Vec<BodyId> {
        // β = 2ζ/ω₁: each segment's damper β times its stiffness
        let beta = match self.surge_frequencies(metres_per_unit).first() {
            Some(f) if self.damping_ratio > 0.0 => {
                2.0 * self.damping_ratio / (std::f64::consts::TAU * f)
            }
            _ => 0.0,
        };
        let pose = |id: BodyId| {
            id.index()
                .map_or(Pose::new(Point2::origin(), 0.0), |i| sys.bodies()[i].pose)
        };
        let (pa, pb) = (pose(self.a), pose(self.b));
        let (wa, wb) = (pa.to_world(self.at_a), pb.to_world(self.at_b));
        let span = wb - wa;
        let length = span.norm();
        let axis = if length > 0.0 {
            span / length
        } else {
            Vec2::y()
        };
        let n = self.masses;
        let segments = (n + 1) as f64;
        let each = self.mass / n.max(1) as f64;
        // a segment's share of the solid length, and its contacts' curves: a plate facing the
        // next node (material behind it), a point on the next node
        let solid = self.solid_length.map(|s| s / segments);
        let mut ids = Vec::with_capacity(n);
        // the nodes: the end on a, the masses, the end on b, each a body and a point in it
        let mut nodes: Vec<(BodyId, Point2, Pose)> = vec![(self.a, self.at_a, pa)];
        for j in 1..=n {
            let at = wa + span * (j as f64 / segments);
            let start = Pose::new(at, pa.angle);
            let id = sys.add_body(Body {
                name: format!("{} mass {j}", self.name),
                mass: each,
                // its angle is held by its slide: any positive inertia (kg·m², a millimetre's arm)
                inertia: each * 1e-6,
                pose: start,
                centre_of_mass: crate::geometry::Point2::origin(),
            });
            // the slide, in a's frame
            let frame = pa.frame();
            sys.add_joint(Joint {
                name: format!("{} guide {j}", self.name),
                kind: JointKind::Prismatic {
                    a: self.a,
                    at_a: frame.inverse_transform_point(&at),
                    axis: frame.rotation.inverse() * axis,
                    b: id,
                    at_b: Point2::origin(),
                    angle: 0.0,
                },
            });
            ids.push(id);
            nodes.push((id, Point2::origin(), start));
        }
        nodes.push((self.b, self.at_b, pb));
        for (j, w) in nodes.windows(2).enumerate() {
            let ((lo, at_lo, pose_lo), (hi, at_hi, pose_hi)) = (w[0], w[1]);
            sys.add_force(ForceElement {
                name: format!("{} segment {}", self.name, j + 1),
                kind: ForceKind::Spring {
                    a: lo,
                    at_a: at_lo,
                    b: hi,
                    at_b: at_hi,
                    stiffness: self.stiffness * segments,
                    free_length: self.free_length / segments,
                    preload: self.preload,
                },
            });
            if beta > 0.0 {
                sys.add_force(ForceElement {
                    name: format!("{} segment {} damping", self.name, j + 1),
                    kind: ForceKind::Damper {
                        a: lo,
                        at_a: at_lo,
                        b: hi,
                        at_b: at_hi,
                        damping: beta * self.stiffness * segments,
                    },
                });
            }
            if let Some(s) = solid {
                // in each node's frame: half the solid segment from its point along the axis
                let local = |p: Pose, v: Vec2| p.frame().rotation.inverse() * v;
                let plate = at_lo + local(pose_lo, axis * (0.5 * s));
                let tip = at_hi - local(pose_hi, axis * (0.5 * s));
                let (Ok(line), Ok(point)) = (
                    Line::new(plate, local(pose_lo, rot90(axis))),
                    PointCurve::new(tip),
                ) else {
                    continue;
                };
                sys.add_contact(Contact {
                    name: format!("{} coil clash {}", self.name, j + 1),
                    a: lo,
                    curve_a: Arc::new(line),
                    b: hi,
                    curve_b: Arc::new(point),
                });
            }
        }
        ids
    }

    /// Its surge frequencies, Hz, lowest first: the chain's natural frequencies with both ends
    /// held, from the eigenvalues of its stiffness and mass matrices (`metres_per_unit`: the
    /// length unit of its stiffness). None for a massless spring.
    pub fn surge_frequencies(&self, metres_per_unit: f64) -> Vec<f64> {
        let n = self.masses;
        if n == 0 || !(self.mass > 0.0) {
            return Vec::new();
        }
        let k = self.stiffness * (n + 1) as f64 / metres_per_unit;
        let m = self.mass / n as f64;
        // M^{-1/2} K M^{-1/2}: tridiagonal (2, −1) k/m
        let mut a = nalgebra::DMatrix::<f64>::zeros(n, n);
        for i in 0..n {
            a[(i, i)] = 2.0 * k / m;
            if i + 1 < n {
                a[(i, i + 1)] = -k / m;
                a[(i + 1, i)] = -k / m;
            }
        }
        let mut f: Vec<f64> = a
            .symmetric_eigenvalues()
            .iter()
            .map(|l| l.max(0.0).sqrt() / std::f64::consts::TAU)
            .collect();
        f.sort_by(|x, y| x.total_cmp(y));
        f
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The chain's frequencies are the closed form `2 √(k'/m') sin(jπ/(2(N+1)))` to 1e-9, for
    /// 1 to 16 masses and 400; with 400 the lowest is the continuous spring's `½ √(k/m)` Hz to
    /// 0.2 % (the chain's `√(N/(N+1))`).
    #[test]
    fn surge_frequencies_are_the_fixed_fixed_chains() {
        for n in (1..=16).chain([400]) {
            let s = CoilSpring {
                name: "s".into(),
                a: BodyId::GROUND,
                at_a: Point2::origin(),
                b: BodyId::GROUND,
                at_b: Point2::new(0.0, 40.0),
                stiffness: 30.0,
                free_length: 48.0,
                preload: 0.0,
                mass: 0.02,
                masses: n,
                solid_length: None,
                damping_ratio: 0.0,
            };
            let f = s.surge_frequencies(1e-3);
            assert_eq!(f.len(), n);
            let (kk, mm) = (30e3 * (n + 1) as f64, 0.02 / n as f64);
            for (j, fj) in f.iter().enumerate() {
                let closed = 2.0
                    * (kk / mm).sqrt()
                    * ((j + 1) as f64 * std::f64::consts::PI / (2.0 * (n + 1) as f64)).sin()
                    / std::f64::consts::TAU;
                assert!(
                    (fj - closed).abs() <= 1e-9 * closed,
                    "{n} masses, mode {j}: {fj} {closed}"
                );
            }
            if n == 400 {
                let continuous = 0.5 * (30e3f64 / 0.02).sqrt();
                assert!(
                    (f[0] - continuous).abs() < 2e-3 * continuous,
                    "{} {continuous}",
                    f[0]
                );
            }
        }
    }

    /// Added to a system: its masses evenly along the line, one slide each, its segments, and a
    /// coil-clash contact per segment whose curves sit half the solid segment from each node.
    #[test]
    fn added_to_a_system_it_is_a_chain() {
        let mut sys = System::new();
        let s = CoilSpring {
            name: "valve spring".into(),
            a: BodyId::GROUND,
            at_a: Point2::new(25.0, -70.0),
            b: BodyId::GROUND,
            at_b: Point2::new(25.0, -33.0),
            stiffness: 30.0,
            free_length: 45.0,
            preload: 0.0,
            mass: 0.02,
            masses: 3,
            solid_length: Some(24.0),
            damping_ratio: 0.0,
        };
        let ids = s.add_to(&mut sys, 1e-3);
        assert_eq!(ids.len(), 3);
        assert_eq!(sys.joints().len(), 3);
        assert_eq!(sys.forces().len(), 4);
        assert_eq!(sys.contacts().len(), 4);
        for (j, id) in ids.iter().enumerate() {
            let y = sys.bodies()[id.index().unwrap()].pose.origin.y;
            assert!(
                (y - (-70.0 + 37.0 * (j + 1) as f64 / 4.0)).abs() < 1e-12,
                "{y}"
            );
        }
        assert!(matches!(
            sys.forces()[0].kind,
            ForceKind::Spring { stiffness, free_length, .. } if stiffness == 120.0 && free_length == 11.25
        ));
    }
}
