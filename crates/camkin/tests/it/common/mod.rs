//! Shared helpers for the scenario tests: the finite-difference helper and the catalogue of
//! reference problems with exact answers.
#![allow(dead_code)]

use camkin::cam::{Cam, Follower, FollowerCurve, FollowerProfile, Mechanism, Sense};
use camkin::curve::{Circle, Curve, Ellipse, Line};
use camkin::{Point2, Vec2};
use std::sync::Arc;

/// The system a file describes (a cam-follower file's mechanism as one), as the front ends read
/// it.
pub fn read_system(
    text: &str,
    name: &str,
    options: &camkin::spec::BuildOptions,
) -> Result<camkin::spec::BuiltSystem, camkin::spec::text::TextError> {
    camkin::spec::read_model(text, name, options).and_then(camkin::spec::ModelFile::into_system)
}

/// A system file's run over its `[simulation]`, as the command runs it: the built system and
/// its samples and events.
pub fn run_timed(
    text: &str,
    name: &str,
) -> (camkin::spec::BuiltSystem, camkin::dynamics::SystemRun) {
    let built = read_system(text, name, &camkin::spec::BuildOptions::default()).unwrap();
    let run = built.timed_run.expect("its [simulation]");
    let (plan, mut sim) = built.plan_timed(run).unwrap();
    let out = sim
        .run(plan.outputs, plan.h_out, |_| {
            std::ops::ControlFlow::Continue(())
        })
        .unwrap();
    (built, out)
}

/// The index of the body `name` of `built`.
pub fn body_index(built: &camkin::spec::BuiltSystem, name: &str) -> usize {
    built
        .system
        .bodies()
        .iter()
        .position(|b| b.name == name)
        .unwrap_or_else(|| panic!("no body {name:?}"))
}

/// Central finite-difference derivatives of `f` at `x` with step `h`, of 8th order for the first
/// and second derivative (error O(h⁸)). Returns `(f', f'')`.
pub fn fd8(f: impl Fn(f64) -> f64, x: f64, h: f64) -> (f64, f64) {
    let c1 = [4.0 / 5.0, -1.0 / 5.0, 4.0 / 105.0, -1.0 / 280.0];
    let c2 = [8.0 / 5.0, -1.0 / 5.0, 8.0 / 315.0, -1.0 / 560.0];
    let f0 = f(x);
    let (mut d1, mut d2) = (0.0, -205.0 / 72.0 * f0);
    for k in 1..=4 {
        let (fp, fm) = (f(x + k as f64 * h), f(x - k as f64 * h));
        d1 += c1[k - 1] * (fp - fm);
        d2 += c2[k - 1] * (fp + fm);
    }
    (d1 / h, d2 / (h * h))
}

/// `|a − b| ≤ tol · scale`, with a message.
#[track_caller]
pub fn assert_close(a: f64, b: f64, tol: f64, scale: f64, what: &str) {
    assert!(
        (a - b).abs() <= tol * scale,
        "{what}: {a} vs {b} (|diff| = {:e}, allowed {:e})",
        (a - b).abs(),
        tol * scale
    );
}

#[allow(unused_imports)]
pub use camkin::reference::{paper_mechanism, paper_nodes};

pub fn paper_profile(revised: bool) -> Arc<dyn Curve> {
    Arc::new(camkin::reference::paper_profile(revised))
}

/// Eccentric circular cam: radius `r`, centre at `(e, 0)` in the cam frame.
pub fn eccentric_circle(r: f64, e: f64) -> Arc<dyn Curve> {
    Arc::new(Circle::new(Point2::new(e, 0.0), r).unwrap())
}

/// Eccentric circular cam: radius `r`, centre at distance `e` in direction `beta` (rad).
#[allow(dead_code)]
pub fn eccentric_circle_at(r: f64, e: f64, beta: f64) -> Arc<dyn Curve> {
    Arc::new(Circle::new(Point2::new(e * beta.cos(), e * beta.sin()), r).unwrap())
}

pub fn ellipse(a: f64, b: f64, center: Point2, rot: f64) -> Arc<dyn Curve> {
    Arc::new(Ellipse::new(center, a, b, rot).unwrap())
}

pub fn mechanism(
    profile: Arc<dyn Curve>,
    pivot: Point2,
    dir: Sense,
    rpm: f64,
    f: Follower,
) -> Mechanism {
    Mechanism::new(Cam::from_rpm(profile, pivot, dir, rpm).unwrap(), f).unwrap()
}

/// A flat face on a slide along +x (the face the line x = 0 of its frame, its material beyond
/// it) on `gear`, the cam, turning counter-clockwise at 1000 rpm about the origin.
pub fn flat_face_on(gear: camkin::curve::InvoluteGear) -> Mechanism {
    let face = Follower::Translating {
        direction: Vec2::x(),
        offset: 0.0,
        profile: FollowerProfile(Arc::new(
            Line::new(Point2::origin(), Vec2::new(0.0, -1.0)).unwrap(),
        )),
    };
    mechanism(Arc::new(gear), Point2::origin(), Sense::Ccw, 1000.0, face)
}

/// Every follower type, placed sensibly around a cam of size about 5 whose axis is `pivot`.
pub fn all_followers(pivot: Point2) -> Vec<Follower> {
    use camkin::Vec2;
    vec![
        Follower::TranslatingFlat {
            direction: Vec2::new(1.0, 0.3),
        },
        Follower::TranslatingRoller {
            direction: Vec2::new(0.0, 1.0),
            offset: 0.7,
            roller_radius: 1.2,
        },
        Follower::TranslatingKnife {
            direction: Vec2::new(-1.0, 0.2),
            offset: -0.4,
        },
        Follower::OscillatingFlat {
            pivot: pivot + Vec2::new(-3.0, 7.0),
            face_offset: 0.5,
            closing: Sense::Cw,
            initial_angle: (-30f64).to_radians(),
        },
        Follower::OscillatingRoller {
            pivot: pivot + Vec2::new(-3.0, 7.0),
            arm_length: 9.0,
            roller_radius: 1.0,
            closing: Sense::Cw,
            initial_angle: (-30f64).to_radians(),
        },
    ]
}

/// Hyper-dual number `a + b ε₁ + c ε₂ + d ε₁ε₂` (ε₁² = ε₂² = 0): evaluating a closed form on
/// `HD::var(x)` gives its value, first and second derivative exactly (to rounding), independently
/// of the code under test.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HD {
    pub v: f64,
    pub d1: f64,
    pub d2: f64, // the ε₁ε₂ part: the second derivative
}

impl HD {
    pub fn var(x: f64) -> Self {
        Self {
            v: x,
            d1: 1.0,
            d2: 0.0,
        }
    }
    pub fn c(x: f64) -> Self {
        Self {
            v: x,
            d1: 0.0,
            d2: 0.0,
        }
    }
    /// Applies a scalar function with derivatives f, f', f'' (chain rule to second order).
    fn chain(self, f: f64, fp: f64, fpp: f64) -> Self {
        Self {
            v: f,
            d1: fp * self.d1,
            d2: fp * self.d2 + fpp * self.d1 * self.d1,
        }
    }
    pub fn sin(self) -> Self {
        self.chain(self.v.sin(), self.v.cos(), -self.v.sin())
    }
    pub fn cos(self) -> Self {
        self.chain(self.v.cos(), -self.v.sin(), -self.v.cos())
    }
    pub fn sqrt(self) -> Self {
        let s = self.v.sqrt();
        self.chain(s, 0.5 / s, -0.25 / (s * s * s))
    }
    pub fn asin(self) -> Self {
        let q = 1.0 - self.v * self.v;
        self.chain(self.v.asin(), 1.0 / q.sqrt(), self.v / (q * q.sqrt()))
    }
    pub fn acos(self) -> Self {
        let q = 1.0 - self.v * self.v;
        self.chain(self.v.acos(), -1.0 / q.sqrt(), -self.v / (q * q.sqrt()))
    }
    pub fn atan2(y: Self, x: Self) -> Self {
        // d atan2 = (x dy − y dx)/(x² + y²)
        let r2 = x * x + y * y;
        let num = x * y.dd() - y * x.dd();
        let d1 = num.v / r2.v;
        // derivative of num/r2
        let q = num / r2;
        Self {
            v: y.v.atan2(x.v),
            d1,
            d2: q.d1,
        }
    }
    /// The derivative as a hyper-dual (value d1, derivative d2).
    fn dd(self) -> Self {
        Self {
            v: self.d1,
            d1: self.d2,
            d2: 0.0,
        }
    }
}

impl std::ops::Add for HD {
    type Output = HD;
    fn add(self, o: HD) -> HD {
        HD {
            v: self.v + o.v,
            d1: self.d1 + o.d1,
            d2: self.d2 + o.d2,
        }
    }
}
impl std::ops::Sub for HD {
    type Output = HD;
    fn sub(self, o: HD) -> HD {
        HD {
            v: self.v - o.v,
            d1: self.d1 - o.d1,
            d2: self.d2 - o.d2,
        }
    }
}
impl std::ops::Mul for HD {
    type Output = HD;
    fn mul(self, o: HD) -> HD {
        HD {
            v: self.v * o.v,
            d1: self.d1 * o.v + self.v * o.d1,
            d2: self.d2 * o.v + 2.0 * self.d1 * o.d1 + self.v * o.d2,
        }
    }
}
impl std::ops::Div for HD {
    type Output = HD;
    fn div(self, o: HD) -> HD {
        let inv = o.chain(1.0 / o.v, -1.0 / (o.v * o.v), 2.0 / (o.v * o.v * o.v));
        self * inv
    }
}
impl std::ops::Neg for HD {
    type Output = HD;
    fn neg(self) -> HD {
        HD {
            v: -self.v,
            d1: -self.d1,
            d2: -self.d2,
        }
    }
}
impl std::ops::Mul<HD> for f64 {
    type Output = HD;
    fn mul(self, o: HD) -> HD {
        HD {
            v: self * o.v,
            d1: self * o.d1,
            d2: self * o.d2,
        }
    }
}
impl std::ops::Add<f64> for HD {
    type Output = HD;
    fn add(self, o: f64) -> HD {
        HD {
            v: self.v + o,
            ..self
        }
    }
}

/// The general follower equivalent to a named one: the named kind's contact curve on the same
/// joint (a translating follower's curve turned into the frame along its direction).
pub fn general_of(m: &Mechanism) -> Follower {
    let arc = |c: FollowerCurve| -> Arc<dyn Curve> { c.to_arc() };
    match m.follower().clone() {
        // the face x·d = s: the line through the origin along −y of the frame along d
        Follower::TranslatingFlat { direction } => Follower::Translating {
            direction,
            offset: 0.0,
            profile: FollowerProfile(Arc::new(
                Line::new(Point2::origin(), Vec2::new(0.0, -1.0)).unwrap(),
            )),
        },
        Follower::TranslatingRoller {
            direction,
            offset,
            roller_radius,
        } => Follower::Translating {
            direction,
            offset,
            profile: FollowerProfile(Arc::new(
                camkin::curve::Circle::new(Point2::origin(), roller_radius).unwrap(),
            )),
        },
        // the tip: the point at the frame's origin
        Follower::TranslatingKnife { direction, offset } => Follower::Translating {
            direction,
            offset,
            profile: FollowerProfile(Arc::new(
                camkin::curve::PointCurve::new(Point2::origin()).unwrap(),
            )),
        },
        Follower::OscillatingFlat {
            pivot,
            closing,
            initial_angle,
            ..
        }
        | Follower::OscillatingRoller {
            pivot,
            closing,
            initial_angle,
            ..
        } => Follower::Rotating {
            pivot,
            closing,
            initial_angle,
            profile: FollowerProfile(arc(m.follower_curve())),
        },
        other => panic!("no general equivalent written for {other:?}"),
    }
}

/// The constant-diameter cam of `examples/conjugate-yoke.toml` as its file's fields (mm): a
/// cycloidal rise of 20 over 180° and the same return, base radius 40, 600 rpm, rollers of 10
/// whose centres are `2 (40 + 10) + 20 = 120` apart, plus `extra` mm; the cam speeding up at
/// `alpha` °/s².
pub fn yoke_spec(extra: f64, alpha: Option<f64>) -> camkin::spec::MechanismSpec {
    use camkin::spec::{CamSpec, FollowerSpec, MechanismSpec, ProfileSpec, SegmentSpec};
    let cycloidal = |rise: f64| SegmentSpec {
        law: "cycloidal".into(),
        rise: Some(rise),
        degrees: Some(180.0),
        ..Default::default()
    };
    MechanismSpec {
        length_unit: Some("mm".into()),
        cam: CamSpec {
            speed_rpm: 600.0,
            angular_acceleration_deg_s2: alpha,
            profile: ProfileSpec {
                kind: "motion".into(),
                base_radius: Some(40.0),
                segments: Some(vec![cycloidal(20.0), cycloidal(-20.0)]),
                ..Default::default()
            },
            ..Default::default()
        },
        follower: FollowerSpec {
            kind: "translating-roller".into(),
            direction: Some([0.0, 1.0]),
            roller_radius: Some(10.0),
            conjugate: Some(Box::new(ProfileSpec {
                kind: "circle".into(),
                center: Some([-(120.0 + extra), 0.0]),
                radius: Some(10.0),
                ..Default::default()
            })),
            ..Default::default()
        },
        ..Default::default()
    }
}

/// The places on the line of action `[start, end]` a contact at `x` repeats at whole base
/// pitches `pb` (within 1e-7 of the ends), and whether one lies within 1e-7 of an end (there
/// the count of pairs touching is not judged).
pub fn base_pitches_inside(x: f64, pb: f64, start: f64, end: f64) -> (Vec<f64>, bool) {
    let inside: Vec<f64> = (-2..=2)
        .map(|j| x + f64::from(j) * pb)
        .filter(|y| *y >= start - 1e-7 && *y <= end + 1e-7)
        .collect();
    let near_end = inside
        .iter()
        .any(|y| (y - start).abs() < 1e-7 || (y - end).abs() < 1e-7);
    (inside, near_end)
}

/// A body of a test system starting at `(x, y)` and `angle` (rad), unit mass properties.
pub fn system_body(name: &str, x: f64, y: f64, angle: f64) -> camkin::system::Body {
    camkin::system::Body {
        name: name.into(),
        mass: 1.0,
        inertia: 1.0,
        pose: camkin::body::Pose::new(Point2::new(x, y), angle),
        centre_of_mass: camkin::geometry::Point2::origin(),
    }
}
