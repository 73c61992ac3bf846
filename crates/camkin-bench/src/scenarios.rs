//! The operations whose instructions are counted (`scripts/instruction-counts`, the
//! `instruction_counts` example): each is set up first and then repeated inside [`counted_repetitions`], the
//! only function whose instructions callgrind collects (`--toggle-collect=*counted_repetitions*`), so the
//! count divided by the repetitions is the cost of one operation, set-up excluded.

use camkin::body::BodyState;
use camkin::cam::{Cam, Follower, FollowerProfile, Mechanism, Sense};
use camkin::contact::{find_contact_indexed, CurveIndex, SearchOptions, Surface};
use camkin::curve::{ClosedSpline, Curve, InvoluteGear, InvoluteGearSpec};
use camkin::dynamics::{AugmentedLagrangian, FollowerDynamics, Simulation};
use camkin::reference::{paper_mechanism, paper_profile};
use camkin::{Point2, Vec2};
use std::hint::black_box;
use std::sync::Arc;

/// The five named follower kinds placed about the paper's cam (size 5).
pub fn paper_followers() -> Vec<Follower> {
    vec![
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
        Follower::TranslatingRoller {
            direction: Vec2::y(),
            offset: 0.7,
            roller_radius: 1.2,
        },
        Follower::TranslatingKnife {
            direction: Vec2::new(-1.0, 0.2),
            offset: -0.4,
        },
        Follower::OscillatingFlat {
            pivot: Point2::new(-3.0, 7.0),
            face_offset: 0.5,
            closing: Sense::Cw,
            initial_angle: (-30f64).to_radians(),
        },
        Follower::OscillatingRoller {
            pivot: Point2::new(-3.0, 7.0),
            arm_length: 9.0,
            roller_radius: 1.0,
            closing: Sense::Cw,
            initial_angle: (-30f64).to_radians(),
        },
    ]
}

/// The paper's cam at 1000 rpm with follower `f`, without the jerk (what a sweep of position,
/// velocity and acceleration costs).
pub fn paper_with(f: Follower) -> Mechanism {
    let cam = Cam::from_rpm(
        Arc::new(paper_profile(false)),
        Point2::origin(),
        Sense::Ccw,
        1000.0,
    )
    .expect("cam");
    without_jerk(Mechanism::new(cam, f).expect("mechanism"))
}

fn without_jerk(mut m: Mechanism) -> Mechanism {
    let mut o = *m.options();
    o.jerk = false;
    m.set_options(o);
    m
}

/// The follower's properties of the simulated scenarios: a stiff spring, permanent contact.
pub fn paper_dynamics() -> FollowerDynamics {
    FollowerDynamics {
        mass: 0.005,
        inertia: 0.0,
        spring_stiffness: 2.0e4,
        spring_preload: 200.0,
        damping: 5.0,
        restitution: 0.5,
        gravity: Vec2::zeros(),
    }
}

/// The ideal 20/42 involute pair at the standard centre distance (module 2 mm).
pub fn gear_pair() -> Mechanism {
    let (m, alpha) = (2.0, 20f64.to_radians());
    let g1 = InvoluteGear::new(InvoluteGearSpec::new(m, 20, alpha)).expect("gear");
    let g2 = InvoluteGear::new(InvoluteGearSpec::new(m, 42, alpha)).expect("gear");
    let cam = Cam::from_rpm(Arc::new(g1), Point2::origin(), Sense::Ccw, 1000.0).expect("cam");
    let follower = Follower::Rotating {
        pivot: Point2::new(62.0, 0.0),
        closing: Sense::Ccw,
        initial_angle: std::f64::consts::PI + std::f64::consts::PI / 42.0,
        profile: FollowerProfile(Arc::new(g2)),
    };
    without_jerk(Mechanism::new(cam, follower).expect("gear pair"))
}

/// A three-lobed cam of radius 40 (±15 %), concave between the lobes, through `n` nodes.
pub fn lobed(n: usize) -> ClosedSpline {
    let pts: Vec<Point2> = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            let r = 40.0 * (1.0 + 0.15 * (3.0 * t).sin());
            Point2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    ClosedSpline::new(&pts).expect("a star-shaped polygon")
}

/// The follower of each kind placed about the [`lobed`] cam; `None` for an unknown kind.
pub fn lobed_follower(kind: &str) -> Option<Follower> {
    Some(match kind {
        "translating-flat" => Follower::TranslatingFlat {
            direction: Vec2::y(),
        },
        "translating-roller" => Follower::TranslatingRoller {
            direction: Vec2::y(),
            offset: 5.0,
            roller_radius: 8.0,
        },
        "translating-knife" => Follower::TranslatingKnife {
            direction: Vec2::y(),
            offset: 3.0,
        },
        "oscillating-flat" => Follower::OscillatingFlat {
            pivot: Point2::new(-30.0, 80.0),
            face_offset: 5.0,
            closing: Sense::Cw,
            initial_angle: (-20f64).to_radians(),
        },
        "oscillating-roller" => Follower::OscillatingRoller {
            pivot: Point2::new(-60.0, 60.0),
            arm_length: 75.0,
            roller_radius: 8.0,
            closing: Sense::Cw,
            initial_angle: (-20f64).to_radians(),
        },
        _ => return None,
    })
}

/// A wavy closed spline of 1000 nodes: radius `r`, `lobes` waves of relative height `wobble`.
pub fn star(r: f64, wobble: f64, lobes: f64) -> ClosedSpline {
    let pts: Vec<Point2> = (0..1000)
        .map(|i| {
            let t = std::f64::consts::TAU * f64::from(i) / 1000.0;
            let rr = r * (1.0 + wobble * (lobes * t).sin());
            Point2::new(rr * t.cos(), rr * t.sin())
        })
        .collect();
    ClosedSpline::new(&pts).expect("star")
}

/// One counted scenario: its name, what one operation is, and how many are repeated.
#[derive(Debug, Clone)]
pub struct Scenario {
    pub name: String,
    pub operation: &'static str,
    pub reps: usize,
}

/// Every scenario, in the order they are reported.
pub fn all() -> Vec<Scenario> {
    let mut out = Vec::new();
    let mut add = |name: String, operation, reps| {
        out.push(Scenario {
            name,
            operation,
            reps,
        })
    };
    add(
        "spline/eval".into(),
        "a spline evaluation (position and three derivatives)",
        20_000,
    );
    add(
        "spline/position".into(),
        "a spline evaluation (position only)",
        20_000,
    );
    for f in paper_followers() {
        let k = f.kind_name();
        add(
            format!("cold/{k}"),
            "a query at an arbitrary angle (Mechanism::motion)",
            500,
        );
        add(
            format!("warm/{k}"),
            "a step of a 0.05° sweep (Sweep::step_motion)",
            2_000,
        );
    }
    // every profile kind and follower kind of the examples, warm (issue 47: circle and ellipse
    // call sine and cosine every evaluation, a motion law allocated, a carried curve's search
    // is a search)
    for (file, _) in EXAMPLE_MECHANISMS {
        add(
            format!("example-warm/{file}"),
            "a step of a 0.05° sweep of examples/<name>.toml (Sweep::step_motion)",
            if file.starts_with("mushroom") {
                50
            } else {
                2_000
            },
        );
    }
    add(
        "floor/translating-flat".into(),
        "a hand-written warm step of the flat face on the paper's cam (the floor)",
        2_000,
    );
    add(
        "warm-full/translating-flat".into(),
        "a step of a 0.05° sweep, every output but the jerk (Sweep::step)",
        2_000,
    );
    for k in ["translating-flat", "oscillating-roller"] {
        add(
            format!("warm-nonconvex/{k}"),
            "a step of a 0.05° sweep on a non-convex 1000-node cam",
            300,
        );
    }
    add(
        "gear/warm".into(),
        "a step of a 0.05° sweep of the 20/42 involute pair",
        100,
    );
    add(
        "contact/indexed-1000".into(),
        "a global contact search between two 1000-node splines, indexes built",
        50,
    );
    add(
        "system/valve-train-warm".into(),
        "a warm instant of the single-valve train (3 bodies, 2 contacts), 0.25° steps",
        200,
    );
    add(
        "dynamics/step-1deg".into(),
        "a simulated 1° step of the paper's cam (advance and sample)",
        360,
    );
    add(
        "dynamics/valve-train-step".into(),
        "a simulated 0.25° step of examples/valve-train.toml (12 bodies, 12 contacts)",
        100,
    );
    out
}

/// The examples whose warm step the harness counts, by file name: a circle, an ellipse, a motion
/// program, a conjugate yoke, a carried curve (the mushroom), an oscillating knife.
pub const EXAMPLE_MECHANISMS: [(&str, &str); 6] = [
    (
        "eccentric-roller",
        include_str!("../../../examples/eccentric-roller.toml"),
    ),
    (
        "ellipse-knife",
        include_str!("../../../examples/ellipse-knife.toml"),
    ),
    (
        "motion-roller",
        include_str!("../../../examples/motion-roller.toml"),
    ),
    (
        "conjugate-yoke",
        include_str!("../../../examples/conjugate-yoke.toml"),
    ),
    (
        "mushroom-follower",
        include_str!("../../../examples/mushroom-follower.toml"),
    ),
    (
        "oscillating-knife",
        include_str!("../../../examples/oscillating-knife.toml"),
    ),
];

/// An example of [`EXAMPLE_MECHANISMS`], built as the command builds it (without the jerk).
pub fn example_mechanism(file: &str) -> Option<Mechanism> {
    let (_, text) = EXAMPLE_MECHANISMS.iter().find(|(f, _)| *f == file)?;
    let spec = camkin::spec::text::parse_toml(text, file).ok()?;
    let built = spec
        .build(&camkin::spec::BuildOptions::default())
        .expect("the example builds");
    Some(without_jerk(built.mechanism))
}

/// `examples/valve-train.toml`, built as the command builds it.
pub fn valve_train_example() -> camkin::spec::BuiltSystem {
    let text = include_str!("../../../examples/valve-train.toml");
    camkin::spec::read_model(
        text,
        "valve-train.toml",
        &camkin::spec::BuildOptions::default(),
    )
    .and_then(camkin::spec::ModelFile::into_system)
    .expect("the example builds")
}

/// Repeats `f` `reps` times: the only function whose instructions are collected.
#[inline(never)]
pub fn counted_repetitions(reps: usize, mut f: impl FnMut(usize) -> f64) -> f64 {
    let mut acc = 0.0;
    for k in 0..reps {
        acc += f(k);
    }
    black_box(acc)
}

/// The floor of a warm step: a hand-written sweep of the paper's cam (counter-clockwise at `w`
/// rad/s about the origin) under a flat face along x, with nothing general in it. The contact
/// is where the turned tangent is normal to x: `g(u) = (R p'(u))·x = 0`, one Newton step from
/// the previous parameter extrapolated to second order (a start off by O(Δθ³), so one step
/// leaves O(Δθ⁶)), Newton again while the step is not tiny; then `q = (R p)·x`,
/// `q̇ = ω (J R p)·x` and `q̈ = −ω² (R p)·x + ω u̇ (J R p')·x` with `u̇ = −ω (J R p')·x / (R p'')·x`
/// (`J` the quarter turn).
#[derive(Debug, Clone)]
pub struct FloorFlat {
    profile: ClosedSpline,
    w: f64,
    u: f64,
    /// `du/dθ` and `d²u/dθ²` (from the last two rates)
    du: f64,
    d2u: f64,
    theta: f64,
}

impl FloorFlat {
    /// Starts at `theta` from the contact parameter `u` (a global search's).
    pub fn new(w: f64, theta: f64, u: f64) -> Self {
        Self {
            profile: paper_profile(false),
            w,
            u,
            du: 0.0,
            d2u: 0.0,
            theta,
        }
    }

    /// Position, velocity and acceleration at `theta`.
    #[inline]
    pub fn step(&mut self, theta: f64) -> [f64; 3] {
        let (s, c) = theta.sin_cos();
        // x-components of R v and of J R v
        let rx = |v: Vec2| c * v.x - s * v.y;
        let jrx = |v: Vec2| -(s * v.x + c * v.y);
        let h = theta - self.theta;
        let mut u = self.u + h * (self.du + 0.5 * h * self.d2u);
        let mut d = self.profile.eval(u);
        for _ in 0..8 {
            let step = rx(d.d1) / rx(d.d2);
            u -= step;
            d = self.profile.eval(u);
            if step.abs() <= 1e-7 {
                break;
            }
        }
        let w = self.w;
        let rate = -w * jrx(d.d1) / rx(d.d2);
        let du = rate / w;
        self.d2u = if h != 0.0 { (du - self.du) / h } else { 0.0 };
        (self.u, self.du, self.theta) = (u, du, theta);
        let p = d.p.coords;
        [rx(p), w * jrx(p), -w * w * rx(p) + w * rate * jrx(d.d1)]
    }
}

fn motion(r: Result<camkin::cam::Motion, camkin::cam::CamError>) -> f64 {
    r.map_or(f64::NAN, |m| m.position + m.velocity + m.acceleration)
}

/// The angle of step `k` of a 0.05° sweep.
fn step_angle(k: usize) -> f64 {
    (k as f64 * 0.05).to_radians()
}

/// `n` inputs computed before the counted_repetitions loop (so that it counts no `fmod` or `to_radians`),
/// taken in turn by [`counted_repetitions`]'s repetition `k` as `inputs[k % n]` (`n` a power of two).
fn inputs(n: usize, f: impl Fn(usize) -> f64) -> Vec<f64> {
    debug_assert!(n.is_power_of_two());
    (0..n).map(f).collect()
}

/// Sets scenario `name` up and runs [`counted_repetitions`] `reps` times; `None` for an unknown name.
pub fn run(name: &str, reps: usize) -> Option<f64> {
    let (group, kind) = name.split_once('/')?;
    let kind_of = |m: &str| paper_followers().into_iter().find(|f| f.kind_name() == m);
    let warm = |m: &Mechanism, full: bool| {
        let mut s = m.sweep();
        // the sweep starts with a global search: not a step
        let _ = black_box(s.step_motion(0.0));
        let angles: Vec<f64> = (1..=reps).map(step_angle).collect();
        counted_repetitions(reps, |k| {
            let th = angles[k];
            if full {
                s.step(th).map_or(f64::NAN, |s| s.acceleration)
            } else {
                motion(s.step_motion(th))
            }
        })
    };
    Some(match (group, kind) {
        ("spline", "eval") => {
            let s = paper_profile(false);
            let u = inputs(1024, |k| k as f64 * 0.37 % 9.0);
            counted_repetitions(reps, |k| {
                let d = s.eval(black_box(u[k & 1023]));
                d.p.x + d.d1.x + d.d2.x + d.d3.x
            })
        }
        ("spline", "position") => {
            let s = paper_profile(false);
            let u = inputs(1024, |k| k as f64 * 0.37 % 9.0);
            counted_repetitions(reps, |k| s.position(black_box(u[k & 1023])).x)
        }
        ("cold", k) => {
            let m = paper_with(kind_of(k)?);
            let th = inputs(1024, |k| {
                (k as f64 * 137.50776405).rem_euclid(360.0).to_radians()
            });
            counted_repetitions(reps, |k| motion(m.motion(th[k & 1023])))
        }
        ("warm", k) => warm(&paper_with(kind_of(k)?), false),
        ("example-warm", file) => warm(&example_mechanism(file)?, false),
        ("floor", "translating-flat") => {
            let m = paper_with(kind_of("translating-flat")?);
            let first = m.analyze(0.0).ok()?;
            // the floor is only a floor if it computes the same: a revolution against the library
            let mut check = FloorFlat::new(m.cam().speed(), 0.0, first.cam_param);
            for k in 1..=7200 {
                let th = step_angle(k);
                let got = check.step(th);
                let lib = m.motion(th).expect("the paper's cam");
                let want = [lib.position, lib.velocity, lib.acceleration];
                let scale = [
                    m.size(),
                    m.size() * m.cam().speed(),
                    m.size() * m.cam().speed().powi(2),
                ];
                for i in 0..3 {
                    assert!(
                        (got[i] - want[i]).abs() <= 1e-12 * scale[i],
                        "the hand-written flat-face step differs from the library at {th} rad: {got:?} vs {want:?}"
                    );
                }
            }
            let mut f = FloorFlat::new(m.cam().speed(), 0.0, first.cam_param);
            let angles: Vec<f64> = (1..=reps).map(step_angle).collect();
            counted_repetitions(reps, |k| {
                let [q, v, a] = f.step(angles[k]);
                q + v + a
            })
        }
        ("warm-full", k) => warm(&paper_with(kind_of(k)?), true),
        ("warm-nonconvex", k) => {
            let cam = Cam::from_rpm(Arc::new(lobed(1000)), Point2::origin(), Sense::Ccw, 100.0)
                .expect("cam");
            let f = match k {
                "translating-flat" | "oscillating-roller" => lobed_follower(k)?,
                _ => return None,
            };
            warm(
                &without_jerk(Mechanism::new(cam, f).expect("mechanism")),
                false,
            )
        }
        ("gear", "warm") => warm(&gear_pair(), false),
        ("contact", "indexed-1000") => {
            let (s1, s2) = (star(50.0, 0.1, 3.0), star(20.0, 0.15, 2.0));
            let o = SearchOptions::for_length_scale(50.0);
            let (i1, i2) = (CurveIndex::new(&s1, &o), CurveIndex::new(&s2, &o));
            counted_repetitions(reps, |k| {
                let b1 = BodyState::at_rest(camkin::body::Pose::new(Point2::origin(), 0.0));
                let b2 = BodyState::at_rest(camkin::body::Pose::new(
                    Point2::new(78.0, 3.0),
                    0.01 * k as f64,
                ));
                let (t1, t2) = (Surface::new(&s1, &b1), Surface::new(&s2, &b2));
                find_contact_indexed(&t1, i1.as_ref(), &t2, i2.as_ref(), &o)
                    .map_or(f64::NAN, |c| c.pairing().gap)
            })
        }
        ("system", "valve-train-warm") => {
            let w = 3000.0 * std::f64::consts::TAU / 60.0;
            let (sys, [_, _, valve]) = camkin::reference::single_valve_train(w);
            let mut sweep = sys.sweep().expect("system");
            let dt = 0.25f64.to_radians() / w;
            let _ = sweep.step(0.0);
            let i = valve.index().unwrap_or(0);
            counted_repetitions(reps, |k| {
                sweep
                    .step((k + 1) as f64 * dt)
                    .map_or(f64::NAN, |s| s.bodies[i].acceleration.y)
            })
        }
        ("dynamics", "valve-train-step") => {
            let built = valve_train_example();
            let mut sim =
                camkin::dynamics::SystemSimulation::new(&built.system, built.dynamics.clone())
                    .expect("simulation");
            let h = 0.25f64.to_radians() / (3000.0 * std::f64::consts::TAU / 60.0);
            // past the seat's lift-off at 3.6°: the steps counted have no event (a bisection
            // is sixty steps)
            for _ in 0..20 {
                let _ = sim.advance(h);
            }
            counted_repetitions(reps, |_| {
                sim.advance(h).map_or(f64::NAN, |e| e.len() as f64)
            })
        }
        ("dynamics", "step-1deg") => {
            let m = paper_mechanism(false);
            let h = 1f64.to_radians() / m.cam().speed();
            let mut sim = Simulation::new(&m, paper_dynamics(), AugmentedLagrangian::default())
                .expect("simulation");
            counted_repetitions(reps, |_| {
                let e = sim.advance(h).map_or(0, |e| e.len());
                e as f64 + sim.sample().map_or(f64::NAN, |s| s.position)
            })
        }
        _ => return None,
    })
}
