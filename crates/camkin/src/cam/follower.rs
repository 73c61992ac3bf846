//! The five follower types: geometry in the world frame, the first-touch position of the follower
//! through one cam point, and the tangency residual that Newton solves.
//!
//! Position `q` (see `cam-follower.md`): translating followers measure `s` from the cam's rotation
//! axis along the unit direction `d`; oscillating followers give the absolute arm angle `φ`
//! (rad, counter-clockwise from the world x axis).

use super::jet::{Num, V2};
use crate::body::{BodyState, Frame, Pose, WorldDerivs};
use crate::curve::{Circle, Line, PointCurve};
use crate::geometry::{perp, wrap_angle_near, Point2, Vec2};

/// Rotation sense: of the cam's motion, or of the spring that closes an oscillating follower.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Sense {
    /// counter-clockwise
    #[default]
    Ccw,
    /// clockwise
    Cw,
}

impl Sense {
    /// +1 for counter-clockwise, −1 for clockwise.
    pub fn sign(self) -> f64 {
        match self {
            Sense::Ccw => 1.0,
            Sense::Cw => -1.0,
        }
    }
}

/// A follower and its geometry. Build a [`crate::cam::Mechanism`] to validate it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Follower {
    /// Translating flat-faced: the face is the line `x·d = s` (positions from the cam axis).
    TranslatingFlat {
        /// direction of travel `d`, from the cam towards the follower (normalised on use)
        direction: Vec2,
    },
    /// Translating roller: centre at `e·perp(d) + s·d` from the cam axis.
    TranslatingRoller {
        /// direction of travel `d`
        direction: Vec2,
        /// offset `e` of the line of travel, length
        offset: f64,
        /// roller radius, length
        roller_radius: f64,
    },
    /// Translating knife edge: tip at `e·perp(d) + s·d` from the cam axis.
    TranslatingKnife {
        /// direction of travel `d`
        direction: Vec2,
        /// offset `e` of the line of travel, length
        offset: f64,
    },
    /// Oscillating flat-faced: the face is the line through `O + e (−sin φ, cos φ)` along
    /// `(cos φ, sin φ)`, touching the cam on the arm's side of the pivot.
    OscillatingFlat {
        /// arm pivot `O`, world
        pivot: Point2,
        /// face offset `e` from the pivot, length
        face_offset: f64,
        /// sense in which the spring turns the arm onto the cam
        closing: Sense,
        /// picks the branch: the solution within ±180° of it, rad
        initial_angle: f64,
    },
    /// Oscillating roller: roller centre at `O + L (cos φ, sin φ)`.
    OscillatingRoller {
        /// arm pivot `O`, world
        pivot: Point2,
        /// arm length `L`
        arm_length: f64,
        /// roller radius
        roller_radius: f64,
        /// sense in which the spring turns the arm onto the cam
        closing: Sense,
        /// picks the branch: the solution within ±180° of it, rad
        initial_angle: f64,
    },
}

impl Follower {
    /// Human-readable kind, as in mechanism files.
    pub fn kind_name(&self) -> &'static str {
        match self {
            Follower::TranslatingFlat { .. } => "translating-flat",
            Follower::TranslatingRoller { .. } => "translating-roller",
            Follower::TranslatingKnife { .. } => "translating-knife",
            Follower::OscillatingFlat { .. } => "oscillating-flat",
            Follower::OscillatingRoller { .. } => "oscillating-roller",
        }
    }

    /// True for oscillating followers (position in rad).
    pub fn is_oscillating(&self) -> bool {
        matches!(
            self,
            Follower::OscillatingFlat { .. } | Follower::OscillatingRoller { .. }
        )
    }
}

/// The follower's contact curve in its own body frame.
#[derive(Debug, Clone, Copy)]
pub(crate) enum FollowerCurve {
    Line(Line),
    Circle(Circle),
    Point(PointCurve),
}

impl FollowerCurve {
    /// The curve as a shared trait object (for the dynamics).
    pub(crate) fn to_arc(self) -> std::sync::Arc<dyn crate::curve::Curve> {
        match self {
            FollowerCurve::Line(c) => std::sync::Arc::new(c),
            FollowerCurve::Circle(c) => std::sync::Arc::new(c),
            FollowerCurve::Point(c) => std::sync::Arc::new(c),
        }
    }

    /// The parameter of the world contact point `c` on this curve (the follower frame is
    /// `frame`) and the curve's world derivatives there, without a virtual call; a roller's come
    /// from its radial unit vector.
    #[inline]
    pub(crate) fn world_at(&self, frame: &Frame, c: Point2) -> (f64, WorldDerivs) {
        match self {
            FollowerCurve::Line(l) => {
                let d = frame.rot.apply(l.direction());
                let a = frame.origin + frame.rot.apply(l.anchor().coords);
                let u = (c - a).dot(&d);
                (
                    u,
                    WorldDerivs {
                        p: a + u * d,
                        d1: d,
                        d2: Vec2::zeros(),
                        d3: Vec2::zeros(),
                    },
                )
            }
            FollowerCurve::Circle(k) => {
                let centre = frame.origin + frame.rot.apply(k.center().coords);
                let r = k.radius();
                let m = c - centre;
                let radial = m * (1.0 / m.norm());
                let local = frame.rot.apply_inverse(radial);
                let t = perp(radial);
                (
                    local.y.atan2(local.x),
                    WorldDerivs {
                        p: centre + r * radial,
                        d1: r * t,
                        d2: -r * radial,
                        d3: -r * t,
                    },
                )
            }
            FollowerCurve::Point(q) => (
                0.0,
                WorldDerivs {
                    p: frame.origin + frame.rot.apply(q.at().coords),
                    d1: Vec2::zeros(),
                    d2: Vec2::zeros(),
                    d3: Vec2::zeros(),
                },
            ),
        }
    }
}

/// A validated follower with its derived data (unit vectors, body-frame curve).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Geometry {
    pub(crate) follower: Follower,
    /// cam axis (world)
    pub(crate) cam_pivot: Point2,
    pub(crate) kind: Kind,
    pub(crate) curve: FollowerCurve,
}

#[derive(Debug, Clone, Copy)]
pub(crate) enum Kind {
    /// translating: d, p = perp(d), offset e, roller radius (0 for flat and knife)
    Translating {
        d: Vec2,
        p: Vec2,
        e: f64,
        r: f64,
        flat: bool,
    },
    /// oscillating: pivot, closing sign (+1 ccw), branch centre, and either face offset or arm
    Oscillating {
        o: Point2,
        closing: f64,
        phi0: f64,
        arm: Arm,
    },
}

#[derive(Debug, Clone, Copy)]
pub(crate) enum Arm {
    Flat { e: f64 },
    Roller { l: f64, r: f64 },
}

impl Geometry {
    pub(crate) fn new(follower: Follower, cam_pivot: Point2, d: Option<Vec2>) -> Self {
        let (kind, curve) = match follower {
            Follower::TranslatingFlat { .. } => {
                let d = d.unwrap_or(Vec2::x());
                let p = perp(d);
                (
                    Kind::Translating {
                        d,
                        p,
                        e: 0.0,
                        r: 0.0,
                        flat: true,
                    },
                    // material on the left: the follower lies on the +d side of its face
                    FollowerCurve::Line(Line::new(Point2::origin(), -p).expect("unit vector")),
                )
            }
            Follower::TranslatingRoller {
                offset,
                roller_radius,
                ..
            } => {
                let d = d.unwrap_or(Vec2::x());
                (
                    Kind::Translating {
                        d,
                        p: perp(d),
                        e: offset,
                        r: roller_radius,
                        flat: false,
                    },
                    FollowerCurve::Circle(
                        Circle::new(Point2::origin(), roller_radius).expect("validated radius"),
                    ),
                )
            }
            Follower::TranslatingKnife { offset, .. } => {
                let d = d.unwrap_or(Vec2::x());
                (
                    Kind::Translating {
                        d,
                        p: perp(d),
                        e: offset,
                        r: 0.0,
                        flat: false,
                    },
                    FollowerCurve::Point(PointCurve::new(Point2::origin()).expect("finite")),
                )
            }
            Follower::OscillatingFlat {
                pivot,
                face_offset,
                closing,
                initial_angle,
            } => (
                Kind::Oscillating {
                    o: pivot,
                    closing: closing.sign(),
                    phi0: initial_angle,
                    arm: Arm::Flat { e: face_offset },
                },
                // cw closing: the cam lies on the −n side of the face, the arm on the +n side
                FollowerCurve::Line(
                    Line::new(
                        Point2::new(0.0, face_offset),
                        Vec2::new(-closing.sign(), 0.0),
                    )
                    .expect("unit vector"),
                ),
            ),
            Follower::OscillatingRoller {
                pivot,
                arm_length,
                roller_radius,
                closing,
                initial_angle,
            } => (
                Kind::Oscillating {
                    o: pivot,
                    closing: closing.sign(),
                    phi0: initial_angle,
                    arm: Arm::Roller {
                        l: arm_length,
                        r: roller_radius,
                    },
                },
                FollowerCurve::Circle(
                    Circle::new(Point2::new(arm_length, 0.0), roller_radius)
                        .expect("validated radius"),
                ),
            ),
        };
        Self {
            follower,
            cam_pivot,
            kind,
            curve,
        }
    }

    /// The position at which the follower's boundary first passes through the world cam point
    /// `x`, oriented so that larger is "touches earlier" (the first touch is the maximum), or
    /// `None` when the follower never touches `x`. Returns `(oriented score, q)`.
    #[inline]
    pub(crate) fn score(&self, x: Point2) -> Option<(f64, f64)> {
        match self.kind {
            Kind::Translating { d, p, e, r, .. } => {
                let y = x - self.cam_pivot;
                if r == 0.0 {
                    let q = y.dot(&d);
                    Some((q, q))
                } else {
                    let l = y.dot(&p) - e;
                    let s2 = r * r - l * l;
                    if s2 < 0.0 {
                        None
                    } else {
                        let q = y.dot(&d) + s2.sqrt();
                        Some((q, q))
                    }
                }
            }
            Kind::Oscillating {
                o,
                closing,
                phi0,
                arm,
            } => {
                let y = x - o;
                let rho = y.norm();
                let psi = y.y.atan2(y.x);
                let phi = match arm {
                    Arm::Flat { e } => {
                        if rho < e.abs() || rho == 0.0 {
                            return None;
                        }
                        psi - (e / rho).asin()
                    }
                    Arm::Roller { l, r } => {
                        if rho == 0.0 {
                            return None;
                        }
                        let c = (rho * rho + l * l - r * r) / (2.0 * rho * l);
                        if !(-1.0..=1.0).contains(&c) {
                            return None;
                        }
                        // cw closing (arm comes down): largest φ whose roller holds x
                        psi - closing * c.acos()
                    }
                };
                let phi = wrap_angle_near(phi, phi0);
                Some((-closing * phi, phi))
            }
        }
    }

    /// Residual of the tangency conditions at world cam point `x` (with `x1 = ∂x/∂u`) and
    /// position `q`: two equations, zero at a touch. Generic so that the jerk can be computed by
    /// differentiating it with [`Jet`](super::jet::Jet)s.
    #[inline]
    pub(crate) fn residual_value<T: Num>(&self, x: V2<T>, x1: V2<T>, q: T) -> [T; 2] {
        let half = T::c(0.5);
        match self.kind {
            Kind::Translating {
                d,
                p,
                e: off,
                r,
                flat,
            } => {
                let y = x - V2::c(self.cam_pivot.coords);
                let (d, p) = (V2::c(d), V2::c(p));
                if flat {
                    [y.dot(d) - q, x1.dot(d)] // y·d = q, y'·d = 0
                } else if r == 0.0 {
                    [y.dot(p) - T::c(off), y.dot(d) - q] // knife: y·p = e, y·d = q
                } else {
                    let m = y - (p.scale(T::c(off)) + d.scale(q));
                    [half * (m.dot(m) - T::c(r * r)), x1.dot(m)]
                }
            }
            Kind::Oscillating { o, arm, .. } => {
                let (s, c) = q.sin_cos();
                let y = x - V2::c(o.coords);
                match arm {
                    Arm::Flat { e: off } => {
                        let n = V2::new(-s, c);
                        [y.dot(n) - T::c(off), x1.dot(n)]
                    }
                    Arm::Roller { l, r } => {
                        let m = y - V2::new(c, s).scale(T::c(l));
                        [half * (m.dot(m) - T::c(r * r)), x1.dot(m)]
                    }
                }
            }
        }
    }

    /// The residual at cam point `e` and position `q` with its Jacobian in `(u, q)`.
    #[inline]
    pub(crate) fn residual(&self, e: &WorldDerivs, q: f64) -> ([f64; 2], [[f64; 2]; 2]) {
        let f = self.residual_value(V2::c(e.p.coords), V2::c(e.d1), q);
        (f, self.jacobian(e, q))
    }

    /// `∂(residual)/∂(u, q)`.
    #[inline]
    pub(crate) fn jacobian(&self, e: &WorldDerivs, q: f64) -> [[f64; 2]; 2] {
        match self.kind {
            Kind::Translating {
                d,
                p,
                e: off,
                r,
                flat,
            } => {
                let y = e.p - self.cam_pivot;
                if flat {
                    [[e.d1.dot(&d), -1.0], [e.d2.dot(&d), 0.0]]
                } else if r == 0.0 {
                    [[e.d1.dot(&p), 0.0], [e.d1.dot(&d), -1.0]]
                } else {
                    let m = y - (off * p + q * d);
                    [
                        [e.d1.dot(&m), -d.dot(&m)],
                        [e.d2.dot(&m) + e.d1.norm_squared(), -e.d1.dot(&d)],
                    ]
                }
            }
            Kind::Oscillating { o, arm, .. } => {
                let (s, c) = q.sin_cos();
                let u = Vec2::new(c, s);
                let n = Vec2::new(-s, c);
                let y = e.p - o;
                match arm {
                    Arm::Flat { .. } => [[e.d1.dot(&n), -y.dot(&u)], [e.d2.dot(&n), -e.d1.dot(&u)]],
                    Arm::Roller { l, .. } => {
                        let m = y - l * u;
                        let dm_dq = -l * n;
                        [
                            [e.d1.dot(&m), m.dot(&dm_dq)],
                            [e.d2.dot(&m) + e.d1.norm_squared(), e.d1.dot(&dm_dq)],
                        ]
                    }
                }
            }
        }
    }

    /// A direction from the contact point `c` into the follower at position `q`: along it the
    /// cam's outward normal must point at a genuine touch (the cam's back side, or a roller
    /// touching from inside, fail this).
    pub(crate) fn toward_follower(&self, c: Point2, q: f64) -> Vec2 {
        match self.kind {
            Kind::Translating { d, p, e, r, .. } => {
                if r > 0.0 {
                    (self.cam_pivot + e * p + q * d) - c
                } else {
                    d
                }
            }
            Kind::Oscillating {
                o, closing, arm, ..
            } => {
                let (s, co) = q.sin_cos();
                match arm {
                    // cw closing (sign −1): the cam is on the −n side, the arm on the +n side
                    Arm::Flat { .. } => -closing * Vec2::new(-s, co),
                    Arm::Roller { l, .. } => (o + l * Vec2::new(co, s)) - c,
                }
            }
        }
    }

    /// The follower body's pose at position `q`.
    pub(crate) fn pose(&self, q: f64) -> Pose {
        match self.kind {
            Kind::Translating { d, p, e, .. } => Pose::new(self.cam_pivot + e * p + q * d, 0.0),
            Kind::Oscillating { o, .. } => Pose::new(o, q),
        }
    }

    /// The follower body's state at position `q`, rate `q̇` and acceleration `q̈`.
    pub(crate) fn body(&self, q: f64, qd: f64, qdd: f64) -> BodyState {
        let pose = self.pose(q);
        match self.kind {
            Kind::Translating { d, .. } => BodyState {
                pose,
                velocity: qd * d,
                omega: 0.0,
                acceleration: qdd * d,
                alpha: 0.0,
            },
            Kind::Oscillating { .. } => BodyState {
                pose,
                velocity: Vec2::zeros(),
                omega: qd,
                acceleration: Vec2::zeros(),
                alpha: qdd,
            },
        }
    }

    /// `∂v_B^P/∂q̇` at world point `c`: the velocity of the follower's material point under `c`
    /// per unit rate of the coordinate.
    pub(crate) fn velocity_jacobian(&self, c: Point2) -> Vec2 {
        match self.kind {
            Kind::Translating { d, .. } => d,
            Kind::Oscillating { o, .. } => perp(c - o),
        }
    }

    /// Converts a change of `q` into a length, for tolerances.
    pub(crate) fn q_length_scale(&self, size: f64) -> f64 {
        match self.kind {
            Kind::Translating { .. } => 1.0,
            Kind::Oscillating { o, .. } => size + (o - self.cam_pivot).norm(),
        }
    }

    pub(crate) fn is_knife(&self) -> bool {
        matches!(self.curve, FollowerCurve::Point(_))
    }
}
