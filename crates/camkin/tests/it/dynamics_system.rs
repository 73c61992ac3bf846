//! Issue 46: the dynamics of any system (`camkin::dynamics::SystemSimulation`) against closed
//! forms that share no formula with it: a block dropped onto a seat (free flight, the impact's
//! instant and speed, Newton's restitution, the bounce's height, then resting with the contact
//! force `m g`), a mass on a spring in millimetres (the period `2π √(m/k)` with the unit's size
//! in it), and a pendulum with a spring, undamped, that keeps its energy.

use crate::common::read_system;
use camkin::curve::{Line, PointCurve};
use camkin::dynamics::{
    DynamicsError, EventKind, SystemDynamicsOptions, SystemSimulation, Tolerances,
};
use camkin::system::{Body, BodyId, Contact, ForceElement, ForceKind, Joint, JointKind, System};
use camkin::{Point2, Vec2};
use std::sync::Arc;

/// A block of 0.2 kg on a vertical guide, its lowest point `h0` m above a seat (the ground's
/// line y = 0, material below), under gravity 9.81 m/s² (lengths in m).
pub(crate) fn dropped_block(h0: f64) -> System {
    dropped_block_and_id(h0).0
}

/// [`dropped_block`] and its block's id.
fn dropped_block_and_id(h0: f64) -> (System, BodyId) {
    let mut sys = System::new();
    let block = sys.add_body(Body {
        name: "block".into(),
        mass: 0.2,
        inertia: 1e-4,
        pose: camkin::body::Pose::new(Point2::new(0.0, h0), 0.0),
        centre_of_mass: camkin::geometry::Point2::origin(),
    });
    sys.add_joint(Joint {
        name: "guide".into(),
        kind: JointKind::Prismatic {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            axis: Vec2::y(),
            b: block,
            at_b: Point2::origin(),
            angle: 0.0,
        },
    });
    sys.add_contact(Contact {
        name: "seat".into(),
        a: BodyId::GROUND,
        // material below the line: its left side is −y when it runs along −x
        curve_a: Arc::new(Line::new(Point2::origin(), -Vec2::x()).unwrap()),
        b: block,
        curve_b: Arc::new(PointCurve::new(Point2::origin()).unwrap()),
    });
    (sys, block)
}

#[test]
fn a_dropped_block_flies_lands_and_bounces_as_the_closed_forms_say() {
    let (g, h0, e) = (9.81, 0.05, 0.6);
    let sys = dropped_block(h0);
    let opts = SystemDynamicsOptions {
        gravity: Vec2::new(0.0, -g),
        restitution: vec![e],
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    // it starts apart, at rest
    let s0 = sim.sample().unwrap();
    assert!(
        !s0.in_contact[0] && (s0.gaps[0] - h0).abs() < 1e-15,
        "{s0:?}"
    );
    // impacts at t₁ = √(2h₀/g), then every 2 eᵏ v₁ / g later, each approaching at eᵏ v₁
    let v1 = (2.0 * g * h0).sqrt();
    let t1 = v1 / g;
    let mut expected = vec![(t1, v1)];
    let (mut t, mut v) = (t1, v1);
    for _ in 0..3 {
        t += 2.0 * e * v / g;
        v *= e;
        expected.push((t, v));
    }
    let mut impacts = Vec::new();
    let h = 1e-3;
    let mut peak_after_first: f64 = 0.0;
    while sim.time() < expected[3].0 + 0.5 * h {
        for ev in sim.advance(h).unwrap() {
            assert_eq!(ev.kind, EventKind::Impact, "{ev:?}");
            impacts.push((ev.time, ev.approach));
        }
        let s = sim.sample().unwrap();
        if impacts.len() == 1 {
            peak_after_first = peak_after_first.max(s.q[1]);
        }
        // free flight: the block's acceleration is −g exactly
        if !s.in_contact[0] {
            assert!((s.qdd[1] + g).abs() < 1e-9 * g, "{s:?}");
        }
    }
    assert!(impacts.len() >= 4, "{impacts:?}");
    for ((t, v), (te, ve)) in impacts.iter().zip(&expected) {
        assert!(
            (t - te).abs() < 1e-12,
            "impact at {t} s, closed form {te} s"
        );
        assert!(
            (v - ve).abs() < 1e-9 * v1,
            "approach {v} m/s, closed form {ve} m/s"
        );
    }
    // the first bounce rises to e² h₀ (sampled every millisecond: within the sampling)
    assert!(
        (peak_after_first - e * e * h0).abs() < 0.5 * g * h * h + 1e-9,
        "bounce {peak_after_first} m, closed form {} m",
        e * e * h0
    );
}

#[test]
fn a_block_landing_without_rebound_rests_with_its_weight_on_the_seat() {
    let (g, h0) = (9.81, 0.01);
    let sys = dropped_block(h0);
    let opts = SystemDynamicsOptions {
        gravity: Vec2::new(0.0, -g),
        restitution: vec![0.0],
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let mut events = Vec::new();
    for _ in 0..100 {
        events.extend(sim.advance(1e-3).unwrap());
    }
    assert_eq!(events.len(), 1, "{events:?}");
    let s = sim.sample().unwrap();
    assert!(s.in_contact[0]);
    assert!((s.contact_forces[0] - 0.2 * g).abs() < 1e-9, "{s:?}");
    assert!(s.q[1].abs() < 1e-14 && s.qd[1].abs() < 1e-12, "{s:?}");
}

/// A landing whose rebound is too slow to part the curves re-engages the contact plastically:
/// the block stops dead at the impact. A rider of 10 g on a 100 N/m spring above the block
/// (the valve spring's coils above the valve) then moves the same whatever the output interval
/// (1 ms or 0.25 ms: the steps after the impact differ): a regression (the rebound was left at
/// `−e vₙ` under a closed contact until the next step's projection took it away, so the block
/// jolted the rider for as long as that step lasted: the valve train's coils were 1.7 % off at
/// 1° outputs).
#[test]
fn a_rebound_too_slow_to_part_the_curves_stops_the_block_dead() {
    let (g, h0) = (9.81, 0.05);
    let (mut sys, block) = dropped_block_and_id(h0);
    let rider = sys.add_body(Body {
        name: "rider".into(),
        mass: 0.01,
        inertia: 1e-5,
        pose: camkin::body::Pose::new(Point2::new(0.0, h0 + 0.02), 0.0),
        centre_of_mass: camkin::geometry::Point2::origin(),
    });
    sys.add_joint(Joint {
        name: "rider guide".into(),
        kind: JointKind::Prismatic {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            axis: Vec2::y(),
            b: rider,
            at_b: Point2::origin(),
            angle: 0.0,
        },
    });
    sys.add_force(ForceElement {
        name: "spring".into(),
        kind: ForceKind::Spring {
            a: block,
            at_a: Point2::origin(),
            b: rider,
            at_b: Point2::origin(),
            stiffness: 100.0,
            free_length: 0.02,
            preload: 0.0,
        },
    });
    // the rebound e v₁ = 5e-4 m/s, below 1e-3 of the speed scale √(g size)
    let run = |h: f64| {
        let opts = SystemDynamicsOptions {
            gravity: Vec2::new(0.0, -g),
            restitution: vec![5e-4],
            ..SystemDynamicsOptions::default()
        };
        let mut sim = SystemSimulation::new(&sys, opts).unwrap();
        let r = sim
            .run((0.2 / h).round() as usize, h, |_| {
                std::ops::ControlFlow::Continue(())
            })
            .unwrap();
        assert_eq!(r.events.len(), 1, "{:?}", r.events);
        let last = r.samples.last().unwrap().clone();
        assert!(last.in_contact[0] && last.qd[1].abs() < 1e-12, "{last:?}");
        last
    };
    let (a, b) = (run(1e-3), run(2.5e-4));
    assert!(
        (a.q[4] - b.q[4]).abs() < 1e-10 && (a.qd[4] - b.qd[4]).abs() < 1e-8,
        "the rider at {} m, {} m/s against {} m, {} m/s",
        a.q[4],
        a.qd[4],
        b.q[4],
        b.qd[4]
    );
}

/// A 45 g valve-like mass on a 30 N/mm spring in a guide, lengths in mm, no gravity: released
/// 2 mm from its rest length it oscillates as `x = 2 cos(ω t)`, `ω = √(k/m) = √(30 000/0.045)`
/// rad/s — the unit's size (1e-3 m) is in that number.
#[test]
fn a_mass_on_a_spring_in_millimetres_has_the_closed_form_frequency() {
    let (m, k) = (0.045, 30.0);
    let mut sys = System::new();
    let mass = sys.add_body(Body {
        name: "valve".into(),
        mass: m,
        inertia: 1e-6,
        pose: camkin::body::Pose::new(Point2::new(0.0, 2.0), 0.0),
        centre_of_mass: camkin::geometry::Point2::origin(),
    });
    sys.add_joint(Joint {
        name: "guide".into(),
        kind: JointKind::Prismatic {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            axis: Vec2::y(),
            b: mass,
            at_b: Point2::origin(),
            angle: 0.0,
        },
    });
    // from the ground 40 mm above, free length 40 mm: no force at y = 0
    sys.add_force(ForceElement {
        name: "spring".into(),
        kind: ForceKind::Spring {
            a: BodyId::GROUND,
            at_a: Point2::new(0.0, 40.0),
            b: mass,
            at_b: Point2::origin(),
            stiffness: k,
            free_length: 40.0,
            preload: 0.0,
        },
    });
    let opts = SystemDynamicsOptions {
        metres_per_unit: 1e-3,
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let w = (k * 1e3 / m).sqrt();
    let h = 1e-6;
    let mut worst: f64 = 0.0;
    let e0 = sim.sample().unwrap().energy;
    // half a joule-ish: ½ k x² = ½ 30 N/mm (2 mm)² = 60 N·mm
    assert!((e0 - 60.0).abs() < 1e-12 * 60.0, "{e0}");
    for _ in 0..2000 {
        sim.advance(h).unwrap();
        let s = sim.sample().unwrap();
        worst = worst.max((s.q[1] - 2.0 * (w * s.time).cos()).abs());
    }
    assert!(worst < 1e-9 * 2.0, "off the closed form by {worst} mm");
}

/// A wheel on a pin in a file in mm, its centre of mass 20 mm from the pin, on a torsion spring
/// of 500 N·mm/rad, no gravity: released 0.1 rad from the spring's free angle it swings as
/// `θ = 0.1 cos(ω t)`, `ω = √(k / I_O)`, `I_O = I_G + m d²` in kg·m² (`k` 0.5 N·m/rad, `d` 0.02 m):
/// the inertia's conversion from kg·m² to the file's N·mm·s² and the offset's from mm are in
/// that number (an inertia taken in kg·mm², or a `m d²` in mm², is off by 1e6).
#[test]
fn a_torsion_pendulum_in_millimetres_has_the_closed_form_frequency() {
    let (m, i_g, d, k): (f64, f64, f64, f64) = (0.5, 2e-4, 0.020, 0.5);
    let text = format!(
        r#"length_unit = "mm"
[dynamics]

[[body]]
name = "wheel"
mass = {m}
inertia = {i_g}
centre_of_mass = [{dmm}, 0.0]
angle_deg = {start}

[[joint]]
name = "pin"
kind = "revolute"
bodies = ["ground", "wheel"]

[[torsion_spring]]
name = "spring"
bodies = ["ground", "wheel"]
stiffness = {kmm}
free_angle_deg = 0.0
preload = 0.0
"#,
        dmm = d * 1e3,
        start = 0.1f64.to_degrees(),
        kmm = k * 1e3,
    );
    let built = read_system(&text, "wheel.toml", &Default::default()).unwrap();
    let mut sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
    let w = (k / (i_g + m * d * d)).sqrt();
    // a twentieth of a period in 1000 steps, then to half a period
    let h = std::f64::consts::PI / w / 10_000.0;
    let mut worst: f64 = 0.0;
    for _ in 0..10_000 {
        sim.advance(h).unwrap();
        let s = sim.sample().unwrap();
        worst = worst.max((s.q[2] - 0.1 * (w * s.time).cos()).abs());
    }
    assert!(worst < 1e-9 * 0.1, "off the closed form by {worst} rad");
    // at half a period it is at −0.1 rad
    let s = sim.sample().unwrap();
    assert!((s.q[2] + 0.1).abs() < 1e-9, "{}", s.q[2]);
}

/// A bar pinned to the ground at one end, under gravity, with a spring from its other end to a
/// ground point: no damping, so its energy stays, to the tolerance asked (over 10 s, sampled
/// every millisecond: within 1e-6 of itself at 1e-8, within 1e-8 at 1e-10, and the pin held
/// to 1e-12 at the end).
#[test]
fn an_undamped_pendulum_with_a_spring_keeps_its_energy() {
    let mut sys = System::new();
    let bar = sys.add_body(Body {
        name: "bar".into(),
        mass: 1.5,
        inertia: 0.02,
        pose: camkin::body::Pose::new(Point2::new(0.2, 0.0), 0.0),
        centre_of_mass: camkin::geometry::Point2::origin(),
    });
    sys.add_joint(Joint {
        name: "pin".into(),
        kind: JointKind::Revolute {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            b: bar,
            at_b: Point2::new(-0.2, 0.0),
        },
    });
    sys.add_force(ForceElement {
        name: "spring".into(),
        kind: ForceKind::Spring {
            a: bar,
            at_a: Point2::new(0.2, 0.0),
            b: BodyId::GROUND,
            at_b: Point2::new(0.5, 0.3),
            stiffness: 200.0,
            free_length: 0.2,
            preload: 5.0,
        },
    });
    let drift = |tol: f64| {
        let opts = SystemDynamicsOptions {
            gravity: Vec2::new(0.0, -9.81),
            tolerances: Tolerances {
                relative: tol,
                absolute: tol,
            },
            ..SystemDynamicsOptions::default()
        };
        let (worst, swing, e0) = energy_drift(&sys, opts, 10_000, 1e-3, 2);
        (worst / e0.abs(), swing)
    };
    let (loose, swing) = drift(1e-8);
    let (tight, _) = drift(1e-10);
    assert!(swing > 1.0, "it swings ({swing} rad/s)");
    assert!(
        loose < 1e-6,
        "energy drifted by {loose:e} of itself at 1e-8"
    );
    assert!(
        tight < 1e-8,
        "energy drifted by {tight:e} of itself at 1e-10"
    );
}

/// `outputs` intervals of `h` s of `sys`: the largest change of its energy, the fastest rate of
/// coordinate `rate`, and the energy at the start; the rows held at the end to 1e-12.
fn energy_drift(
    sys: &System,
    opts: SystemDynamicsOptions,
    outputs: usize,
    h: f64,
    rate: usize,
) -> (f64, f64, f64) {
    let mut sim = SystemSimulation::new(sys, opts).unwrap();
    let e0 = sim.sample().unwrap().energy;
    let run = sim
        .run(outputs, h, |_| std::ops::ControlFlow::Continue(()))
        .unwrap();
    let worst = run
        .samples
        .iter()
        .map(|s| (s.energy - e0).abs())
        .fold(0.0, f64::max);
    let fastest = run
        .samples
        .iter()
        .map(|s| s.qd[rate].abs())
        .fold(0.0, f64::max);
    assert!(sim.constraint_residual().unwrap() < 1e-12);
    // the balance explains the energy's change (by nothing: no driver, load, damper or impact)
    // and the joints do no work, to twice the drift's size
    let unexplained = run
        .samples
        .iter()
        .map(|s| s.balance.residual().abs().max(s.balance.constraints.abs()))
        .fold(0.0, f64::max);
    assert!(
        unexplained <= 2.0 * worst.max(1e-12 * e0.abs()),
        "the balance leaves {unexplained:e} unexplained, the energy drifted {worst:e}"
    );
    (worst, fastest, e0)
}

/// The double pendulum: two bars pinned end to end, the first to the ground, released
/// horizontal under gravity (a chaotic motion). Over 100 s at `rtol = atol = 1e-10` its energy
/// stays within 1e-8 of itself (measured from its lowest pose, both bars hanging: 2 m g l), and
/// both pins hold (issue 64; measured 5.6e-9, growing with the tolerance: 1.2e-6 at 1e-8).
#[test]
fn a_double_pendulum_keeps_its_energy_to_the_tolerance_over_100_s() {
    let mut sys = System::new();
    let bar = |sys: &mut System, name: &str, x: f64| {
        sys.add_body(Body {
            name: name.into(),
            mass: 1.0,
            inertia: 1.0 / 12.0,
            pose: camkin::body::Pose::new(Point2::new(x, 0.0), 0.0),
            centre_of_mass: camkin::geometry::Point2::origin(),
        })
    };
    let (a, b) = (bar(&mut sys, "upper", 0.5), bar(&mut sys, "lower", 1.5));
    for (name, ba, at_a, bb) in [
        ("hinge", BodyId::GROUND, Point2::origin(), a),
        ("elbow", a, Point2::new(0.5, 0.0), b),
    ] {
        sys.add_joint(Joint {
            name: name.into(),
            kind: JointKind::Revolute {
                a: ba,
                at_a,
                b: bb,
                at_b: Point2::new(-0.5, 0.0),
            },
        });
    }
    let opts = SystemDynamicsOptions {
        gravity: Vec2::new(0.0, -9.81),
        tolerances: Tolerances {
            relative: 1e-10,
            absolute: 1e-10,
        },
        ..SystemDynamicsOptions::default()
    };
    // its energy above its lowest pose (both bars hanging): m g (0.5 + 1.5) m
    let scale = 1.0 * 9.81 * 2.0;
    let (worst, lower_spin, _) = energy_drift(&sys, opts, 10_000, 1e-2, 5);
    assert!(lower_spin > 5.0, "it tumbles ({lower_spin} rad/s)");
    assert!(
        worst <= 1e-8 * scale,
        "energy drifted by {:e} of itself",
        worst / scale
    );
}

/// A coil spring of `n` masses (`k` N/mm, `m` kg of coils) between two ground points 40 mm
/// apart, its masses moved up by `shape(j)` mm (`j` from 1): the spring, the system and the
/// masses' bodies.
fn coil_in_shape(
    n: usize,
    k: f64,
    m: f64,
    shape: impl Fn(usize) -> f64,
) -> (camkin::system::CoilSpring, System, Vec<BodyId>) {
    damped_coil_in_shape(n, k, m, 0.0, shape)
}

/// [`coil_in_shape`] with its first surge mode's damping ratio `zeta`.
fn damped_coil_in_shape(
    n: usize,
    k: f64,
    m: f64,
    zeta: f64,
    shape: impl Fn(usize) -> f64,
) -> (camkin::system::CoilSpring, System, Vec<BodyId>) {
    let spring = camkin::system::CoilSpring {
        name: "valve spring".into(),
        a: BodyId::GROUND,
        at_a: Point2::new(0.0, 0.0),
        b: BodyId::GROUND,
        at_b: Point2::new(0.0, 40.0),
        stiffness: k,
        free_length: 48.0,
        preload: 0.0,
        mass: m,
        masses: n,
        solid_length: None,
        damping_ratio: zeta,
    };
    let mut chain = System::new();
    let ids = spring.add_to(&mut chain, 1e-3);
    let mut sys = System::new();
    for (i, b) in chain.bodies().iter().enumerate() {
        let mut b = b.clone();
        b.pose.origin.y += shape(i + 1);
        sys.add_body(b);
    }
    for j in chain.joints() {
        sys.add_joint(j.clone());
    }
    for f in chain.forces() {
        sys.add_force(f.clone());
    }
    (spring, sys, ids)
}

/// A coil spring of four lumped masses between two ground points (a valve spring's surge),
/// started in its first mode's shape (`sin(jπ/5)`): every mass moves as `δ_j cos(ω₁ t)` with
/// `ω₁ = 2 √(5k · 4/m) sin(π/10)`, the fixed–fixed chain's closed form, and `surge_frequencies`
/// gives it; the simulation follows it to 1e-6 of the amplitude over three periods.
#[test]
fn a_coil_springs_masses_surge_at_the_chains_closed_form_frequency() {
    let (n, k, m, mm) = (4usize, 30.0, 0.02, 1e-3);
    // the coil with its masses moved into the first mode's shape, 0.5 mm at most
    let shape = |j: usize| 0.5 * (j as f64 * std::f64::consts::PI / (n + 1) as f64).sin();
    let (spring, sys, ids) = coil_in_shape(n, k, m, shape);
    let w1 = 2.0
        * (k * (n + 1) as f64 / mm / (m / n as f64)).sqrt()
        * (std::f64::consts::PI / (2.0 * (n + 1) as f64)).sin();
    let f = spring.surge_frequencies(mm);
    assert!((f[0] * std::f64::consts::TAU - w1).abs() < 1e-9 * w1);
    let opts = SystemDynamicsOptions {
        metres_per_unit: mm,
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let period = std::f64::consts::TAU / w1;
    let h = period / 400.0;
    let mut worst: f64 = 0.0;
    for _ in 0..1200 {
        sim.advance(h).unwrap();
        let s = sim.sample().unwrap();
        for (j, id) in ids.iter().enumerate() {
            let i = id.index().unwrap();
            let rest = 40.0 * (j + 1) as f64 / (n + 1) as f64;
            let exact = shape(j + 1) * (w1 * s.time).cos();
            worst = worst.max((s.q[3 * i + 1] - rest - exact).abs());
        }
    }
    assert!(worst < 1e-6 * 0.5, "off the mode by {worst} mm");
}

/// The same coil with its first surge mode damped at `ζ = 0.05` (stiffness-proportional: the
/// mode keeps its shape), started in that shape at rest: every mass moves as the damped
/// oscillator's free decay, `δ_j e^{−ζω₁t} (cos ω_d t + ζ/√(1−ζ²) sin ω_d t)` with `ω_d = ω₁
/// √(1−ζ²)`, to 1e-6 of the amplitude over three periods, and its kinetic energy is the
/// closed form's to 1e-6 of its peak; the segments' dampers take the energy lost, the balance
/// leaving 1e-8 of the energy unexplained.
#[test]
fn a_damped_coil_springs_surge_decays_at_its_damping_ratio() {
    let (n, k, m, mm, zeta) = (4usize, 30.0, 0.02, 1e-3, 0.05);
    let shape = |j: usize| 0.5 * (j as f64 * std::f64::consts::PI / (n + 1) as f64).sin();
    let (_, sys, ids) = damped_coil_in_shape(n, k, m, zeta, shape);
    assert_eq!(
        sys.forces().len(),
        2 * (n + 1),
        "a damper beside each segment"
    );
    let w1 = 2.0
        * (k * (n + 1) as f64 / mm / (m / n as f64)).sqrt()
        * (std::f64::consts::PI / (2.0 * (n + 1) as f64)).sin();
    let wd = w1 * (1.0 - zeta * zeta).sqrt();
    let opts = SystemDynamicsOptions {
        metres_per_unit: mm,
        tolerances: Tolerances {
            relative: 1e-10,
            absolute: 1e-10,
        },
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let e0 = sim.sample().unwrap().energy;
    let peak_kinetic: f64 = (1..=n)
        .map(|j| 0.5 * (m / n as f64) * (shape(j) * w1).powi(2) * 1e-3)
        .sum();
    let period = std::f64::consts::TAU / w1;
    let run = sim
        .run(
            1200,
            period / 400.0,
            |_| std::ops::ControlFlow::Continue(()),
        )
        .unwrap();
    let mut worst: f64 = 0.0;
    for s in &run.samples {
        let t = s.time;
        let decay = (-zeta * w1 * t).exp()
            * ((wd * t).cos() + zeta / (1.0 - zeta * zeta).sqrt() * (wd * t).sin());
        for (j, id) in ids.iter().enumerate() {
            let i = id.index().unwrap();
            let rest = 40.0 * (j + 1) as f64 / (n + 1) as f64;
            worst = worst.max((s.q[3 * i + 1] - rest - shape(j + 1) * decay).abs());
        }
        let b = &s.balance;
        assert!(b.residual().abs() < 1e-8 * e0, "{b:?}");
        // ½ Σ (m/n) v_j², v_j = −δ_j (ω₁²/ω_d) e^{−ζω₁t} sin ω_d t, in N·mm (kg·mm²/s² is 1e-3)
        let rate = -(w1 * w1 / wd) * (-zeta * w1 * t).exp() * (wd * t).sin();
        let kinetic: f64 = (1..=n)
            .map(|j| 0.5 * (m / n as f64) * (shape(j) * rate).powi(2) * 1e-3)
            .sum();
        assert!(
            (b.kinetic - kinetic).abs() < 1e-6 * peak_kinetic,
            "kinetic {} N·mm at {t} s, closed form {kinetic}",
            b.kinetic
        );
    }
    assert!(worst < 1e-6 * 0.5, "off the decaying mode by {worst} mm");
    assert!(
        run.samples.last().unwrap().balance.dampers() < -0.5 * peak_kinetic,
        "the dampers took the surge's energy"
    );
}

/// A second check of a coil's segments, static where the surge test is dynamic: `n` masses
/// split the spring into `n + 1` segments of `(n + 1) k` each, in series `k`, so at rest at
/// uniform spacing the plate on its free end is pushed by `k (L₀ − L) − F₀` (compressed by
/// `L₀ − L`; the preload `F₀` a tension, as every spring's) whatever `n` is, and accelerates by
/// that over its mass: 1, 4 and 16 masses (in mm: the stiffness in N/mm, the acceleration in
/// mm/s²).
#[test]
fn a_coils_end_force_at_rest_is_its_stiffness_times_its_compression_whatever_its_masses() {
    use camkin::system::CoilSpring;
    let (k, free, length, preload, plate_mass) = (30.0, 48.0, 40.0, 5.0, 0.05);
    for n in [1usize, 4, 16] {
        let mut sys = System::new();
        let plate = sys.add_body(Body {
            name: "plate".into(),
            mass: plate_mass,
            inertia: 1e-6,
            pose: camkin::body::Pose::new(Point2::new(0.0, length), 0.0),
            centre_of_mass: Point2::origin(),
        });
        sys.add_joint(Joint {
            name: "guide".into(),
            kind: JointKind::Prismatic {
                a: BodyId::GROUND,
                at_a: Point2::origin(),
                axis: Vec2::y(),
                b: plate,
                at_b: Point2::origin(),
                angle: 0.0,
            },
        });
        CoilSpring {
            name: "coil".into(),
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            b: plate,
            at_b: Point2::origin(),
            stiffness: k,
            free_length: free,
            preload,
            mass: 0.01,
            masses: n,
            solid_length: None,
            damping_ratio: 0.0,
        }
        .add_to(&mut sys, 1e-3);
        let opts = SystemDynamicsOptions {
            metres_per_unit: 1e-3,
            ..SystemDynamicsOptions::default()
        };
        let sim = SystemSimulation::new(&sys, opts).unwrap();
        let s = sim.sample().unwrap();
        // N over kg is m/s²; the file's unit is mm
        let want = (k * (free - length) - preload) / plate_mass * 1e3;
        let got = s.qdd[1];
        assert!(
            (got - want).abs() < 1e-9 * want,
            "{n} masses: {got} against {want} mm/s²"
        );
        // every inner mass at rest between equal segments feels nothing
        for i in 1..=n {
            assert!(
                s.qdd[3 * i + 1].abs() < 1e-6 * want,
                "{n}: mass {i} {}",
                s.qdd[3 * i + 1]
            );
        }
    }
}

/// The rate bound covers a chain's highest mode: a coil of `n` = 64 masses between two ground
/// points has its fastest mode at `ω_n = 2 √(k_s/m_s) sin(nπ/(2(n + 1)))`, `k_s = (n + 1) k`,
/// `m_s = m/n` (the fixed–fixed chain's closed form), nearly twice each segment's own
/// `√(k_s/m_s)`, the rate the step was once bounded by. The rate is at least `ω_n` and at most
/// `2√(k_s/m_s)`; started in that mode's shape and sampled every stable step at tolerances of
/// 1e-10, the masses keep their amplitude and its energy to 1e-4 (the steps the tolerances
/// choose neither grow the mode nor drain it: with a step bound that missed it, it grew
/// 1e4-fold in 200 steps and the masses clashed).
#[test]
fn a_coils_highest_mode_is_within_the_rate_bound_and_keeps_its_amplitude() {
    let (n, k, m, mm) = (64usize, 30.0, 0.02, 1e-3);
    // the highest mode's shape: sin(j n π/(n + 1)), alternating, 1e-3 mm at most
    let amp = 1e-3;
    let shape =
        |j: usize| amp * (j as f64 * n as f64 * std::f64::consts::PI / (n + 1) as f64).sin();
    let (_, sys, ids) = coil_in_shape(n, k, m, shape);
    let segment = (k * (n + 1) as f64 / mm / (m / n as f64)).sqrt();
    let top = 2.0 * segment * (n as f64 * std::f64::consts::PI / (2.0 * (n + 1) as f64)).sin();
    let opts = SystemDynamicsOptions {
        metres_per_unit: mm,
        tolerances: Tolerances {
            relative: 1e-10,
            absolute: 1e-10,
        },
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let (rate, element) = sim.fastest_rate();
    assert!(
        rate >= top && rate <= 2.0 * segment * (1.0 + 1e-12),
        "{rate} against {top}"
    );
    assert!(element.contains("valve spring"), "{element}");
    let h = sim.stable_step();
    let (mut worst, mut least): (f64, f64) = (0.0, f64::INFINITY);
    for _ in 0..400 {
        sim.advance(h).unwrap();
        let s = sim.sample().unwrap();
        for (j, id) in ids.iter().enumerate() {
            let i = id.index().unwrap();
            let rest = 40.0 * (j + 1) as f64 / (n + 1) as f64;
            worst = worst.max((s.q[3 * i + 1] - rest).abs());
        }
        // the mode's energy: its amplitude whatever its phase
        least = least.min(s.energy);
    }
    let first = sim.sample().unwrap().energy;
    assert!(worst <= amp * (1.0 + 1e-4), "the mode grew to {worst} mm");
    assert!(
        (first - least).abs() <= 1e-4 * first,
        "the mode's energy fell from {first} to {least}"
    );
}

/// A gas force from a table of the crank angle (`TableForce`): a 0.1 kg slide pushed by
/// `F = 2 N` per crank degree, the crank turning twice per turn of the driven camshaft at
/// 600 rpm (7200 crank degrees a second): `F = 14 400 t` N, so `y = 24 000 t³` m exactly (RK4
/// integrates the cubic exactly); the work it does is its kinetic energy.
#[test]
fn a_gas_force_from_a_crank_angle_table_moves_a_mass_as_its_closed_form() {
    use camkin::system::{Coordinate, Driver, DriverLaw, TableForce};
    let mut sys = System::new();
    let cam = sys.add_body(Body {
        name: "camshaft".into(),
        mass: 1.0,
        inertia: 1.0,
        pose: camkin::body::Pose::new(Point2::origin(), 0.0),
        centre_of_mass: camkin::geometry::Point2::origin(),
    });
    sys.add_joint(Joint {
        name: "bearing".into(),
        kind: JointKind::Revolute {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            b: cam,
            at_b: Point2::origin(),
        },
    });
    sys.add_driver(Driver {
        name: "drive".into(),
        body: cam,
        coordinate: Coordinate::Angle,
        law: DriverLaw::linear(0.0, 600.0 * std::f64::consts::TAU / 60.0),
    });
    let slide = sys.add_body(Body {
        name: "slide".into(),
        mass: 0.1,
        inertia: 1e-3,
        pose: camkin::body::Pose::new(Point2::new(1.0, 0.0), 0.0),
        centre_of_mass: camkin::geometry::Point2::origin(),
    });
    sys.add_joint(Joint {
        name: "guide".into(),
        kind: JointKind::Prismatic {
            a: BodyId::GROUND,
            at_a: Point2::new(1.0, 0.0),
            axis: Vec2::y(),
            b: slide,
            at_b: Point2::origin(),
            angle: 0.0,
        },
    });
    sys.add_table_force(TableForce {
        name: "gas".into(),
        body: slide,
        at: Point2::new(0.0, 0.3),
        direction: Vec2::y(),
        table: vec![(0.0, 0.0), (719.0, 1438.0)],
        crank_per_driver: 2.0,
        period_deg: 720.0,
    });
    let mut sim = SystemSimulation::new(&sys, SystemDynamicsOptions::default()).unwrap();
    for _ in 0..90 {
        sim.advance(1e-3).unwrap();
        let s = sim.sample().unwrap();
        let t = s.time;
        let y = 24_000.0 * t * t * t;
        assert!(
            (s.q[4] - y).abs() <= 1e-12 * y.max(1e-3),
            "{t}: {} {y}",
            s.q[4]
        );
        // the drive does no work on the slide: the gas force's work is the slide's kinetic
        // energy (the camshaft's, constant, taken off: to rounding of the whole)
        let ke = 0.5 * 0.1 * s.qd[4] * s.qd[4];
        let cam = 0.5 * s.qd[2] * s.qd[2];
        assert!(
            (s.energy - cam - ke).abs() <= 1e-12 * s.energy,
            "{} {cam} {ke}",
            s.energy
        );
        assert!(
            (s.driver_work - ke).abs() <= 1e-9 * ke.max(1e-9),
            "{} {ke}",
            s.driver_work
        );
    }
}

/// A four-bar driven by its rocker (crank 20, coupler 50, rocker 40, ground 60 mm) simulated
/// into its toggle: the rocker cannot turn past `acos(((b − a)² − d² − c²)/(2dc))` = 153.6°,
/// where crank and coupler fold onto one line. The run stops at that instant (to 1e-6 of it),
/// saying why (a dead point, naming its driver), never a sample past it; before it, every sample
/// is on the loop (a regression: the projection's Newton stopped after eight iterations off the
/// rows without a word, and the run went on to a singular matrix).
#[test]
fn a_four_bar_simulated_into_its_toggle_stops_there_and_says_so() {
    let (a, b, c, d) = (20.0f64, 50.0f64, 40.0f64, 60.0f64);
    let (start_deg, rpm) = (100.0f64, 60.0f64);
    let text = format!(
        r#"length_unit = "mm"
[dynamics]
gravity = [0.0, 0.0]
[[body]]
name = "crank"
mass = 0.1
inertia = 1e-5
angle_deg = 5.0
[[body]]
name = "coupler"
mass = 0.1
inertia = 1e-5
position = [{a}, 0.0]
angle_deg = 50.0
[[body]]
name = "rocker"
mass = 0.1
inertia = 1e-5
position = [{d}, 0.0]
angle_deg = {start_deg}
[[joint]]
name = "O2"
kind = "revolute"
bodies = ["ground", "crank"]
[[joint]]
name = "A"
kind = "revolute"
bodies = ["crank", "coupler"]
at = [[{a}, 0.0], [0.0, 0.0]]
[[joint]]
name = "B"
kind = "revolute"
bodies = ["coupler", "rocker"]
at = [[{b}, 0.0], [{c}, 0.0]]
[[joint]]
name = "O4"
kind = "revolute"
bodies = ["rocker", "ground"]
at = [[0.0, 0.0], [{d}, 0.0]]
[[driver]]
name = "drive rocker"
body = "rocker"
coordinate = "angle"
speed_rpm = {rpm}
start = {start_deg}
"#
    );
    let built = read_system(&text, "toggle.toml", &Default::default()).unwrap();
    let w = rpm / 60.0 * std::f64::consts::TAU;
    let toggle = (((b - a) * (b - a) - d * d - c * c) / (2.0 * d * c)).acos();
    let t_toggle = (toggle - start_deg.to_radians()) / w;
    for h in [1e-3, 2.5e-4] {
        let mut sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
        let e = loop {
            match sim.advance(h) {
                Ok(_) => {
                    let s = sim.sample().unwrap();
                    assert!(
                        s.time <= t_toggle,
                        "a sample at {} s past the toggle",
                        s.time
                    );
                    // B on the rocker and on the coupler: |O₂B| = the loop's
                    let (phi, psi) = (s.q[8], s.q[2]);
                    let bx = d + c * phi.cos() - a * psi.cos();
                    let by = c * phi.sin() - a * psi.sin();
                    assert!(((bx * bx + by * by).sqrt() - b).abs() < 1e-9 * d);
                }
                Err(e) => break e,
            }
            assert!(sim.time() < 2.0 * t_toggle, "ran on past the toggle");
        };
        match &e {
            DynamicsError::DeadPoint { time, drivers } => {
                eprintln!("{h}: {} s before", t_toggle - time);
                assert!(
                    (*time - t_toggle).abs() <= 1e-6 * t_toggle,
                    "{time} against {t_toggle}"
                );
                assert!(drivers.contains("drive rocker"), "{drivers}");
            }
            other => panic!("{other}"),
        }
        assert!(e.to_string().contains("dead point (toggle)"), "{e}");
    }
}

/// The torsion spring's sense as the docs state it: torque `T = k (θ_b − θ_a − free) + P`, `+T`
/// on `a`, `−T` on `b`. A wheel (`b`) pinned to the ground (`a`) with a spring of no stiffness
/// and a preload of 2 N·mm starts turning clockwise at `−P / I`; with a stiffness of 3 N·mm/rad
/// and the wheel 0.5 rad counter-clockwise of the free angle, at `−(3 · 0.5 + P) / I`.
#[test]
fn a_torsion_springs_torque_turns_its_second_body_back() {
    let inertia = 2e-4; // kg·m², its centre on the pin
    for (k, start) in [(0.0, 0.0), (3.0, 0.5f64)] {
        let text = format!(
            r#"length_unit = "mm"
[dynamics]
gravity = [0.0, 0.0]

[[body]]
name = "wheel"
mass = 0.5
inertia = {inertia}
angle_deg = {deg}

[[joint]]
name = "pin"
kind = "revolute"
bodies = ["ground", "wheel"]

[[torsion_spring]]
name = "spring"
bodies = ["ground", "wheel"]
stiffness = {k}
free_angle_deg = 0.0
preload = 2.0
"#,
            deg = start.to_degrees(),
        );
        let built = read_system(&text, "wheel.toml", &Default::default()).unwrap();
        let sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
        let s = sim.sample().unwrap();
        // N·mm over kg·m² is 1e-3 rad/s²
        let want = -(k * start + 2.0) * 1e-3 / inertia;
        assert!(
            (s.qdd[2] - want).abs() < 1e-9 * want.abs(),
            "{} against {want}",
            s.qdd[2]
        );
    }
}
