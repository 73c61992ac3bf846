//! Issue 64, "energy, momentum and work reports": the balance of a simulated system
//! (`SystemSample::balance`) against closed forms that share no formula with it — a damped
//! oscillator in millimetres (its energy and its damper's dissipation from the solution
//! `x(t)`), a block bouncing with restitution (each impact's loss `(1 − e²) ½ m v²`), a driven
//! crank against a torsion damper and gravity (the driver's work `c ω² t + m g Δy_G`), and a body
//! thrown in the air (its momentum `p₀ + m g t`); the joints' and contacts' forces do no work.

use camkin::dynamics::{SystemDynamicsOptions, SystemSimulation, Tolerances};
use camkin::system::{
    Body, BodyId, Coordinate, Driver, DriverLaw, ForceElement, ForceKind, Joint, JointKind, System,
};
use camkin::{Point2, Vec2};
use std::ops::ControlFlow;

fn tight() -> Tolerances {
    Tolerances {
        relative: 1e-10,
        absolute: 1e-10,
    }
}

/// A 0.5 kg block on a slide along x (lengths in mm), a 2 N/mm spring and a 0.01 N·s/mm damper
/// to the ground, let go 5 mm from its rest at rest: `x(t) = x₀ e^{−ζωt} (cos ω_d t + ζω/ω_d
/// sin ω_d t)`, `v(t) = −(ω²x₀/ω_d) e^{−ζωt} sin ω_d t` (ω = √(k/m) in SI). The balance's
/// kinetic energy is `½ m v²` in N·mm (kg·mm²/s² is 1e-3 N·mm: the unit's size), the spring's
/// potential `½ k x²`, the damper's work the energy lost, `E(t) − E₀`, to 1e-8 of `E₀`; the
/// spring's work is minus its potential's change, the slide does none, and nothing is left
/// unexplained.
#[test]
fn a_damped_oscillators_balance_is_its_closed_form_in_millimetres() {
    let (m, k, c, x0) = (0.5, 2.0, 0.01, 5.0);
    let mut sys = System::new();
    let block = sys.add_body(Body {
        name: "block".into(),
        mass: m,
        inertia: 1e-4,
        pose: camkin::body::Pose::new(Point2::new(x0, 0.0), 0.0),
        centre_of_mass: Point2::origin(),
    });
    sys.add_joint(Joint {
        name: "slide".into(),
        kind: JointKind::Prismatic {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            axis: Vec2::x(),
            b: block,
            at_b: Point2::origin(),
            angle: 0.0,
        },
    });
    let anchor = Point2::new(-40.0, 0.0);
    sys.add_force(ForceElement {
        name: "spring".into(),
        kind: ForceKind::Spring {
            a: BodyId::GROUND,
            at_a: anchor,
            b: block,
            at_b: Point2::origin(),
            stiffness: k,
            free_length: 40.0,
            preload: 0.0,
        },
    });
    sys.add_force(ForceElement {
        name: "damper".into(),
        kind: ForceKind::Damper {
            a: BodyId::GROUND,
            at_a: anchor,
            b: block,
            at_b: Point2::origin(),
            damping: c,
        },
    });
    let opts = SystemDynamicsOptions {
        metres_per_unit: 1e-3,
        tolerances: tight(),
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let run = sim.run(300, 1e-3, |_| ControlFlow::Continue(())).unwrap();
    // SI: k in N/m, c in N·s/m
    let (k_si, c_si) = (k * 1e3, c * 1e3);
    let w = (k_si / m).sqrt();
    let zeta = c_si / (2.0 * (k_si * m).sqrt());
    let wd = w * (1.0 - zeta * zeta).sqrt();
    let e0 = 0.5 * k * x0 * x0; // N·mm
    let mut checked = 0;
    for s in &run.samples {
        let t = s.time;
        let decay = (-zeta * w * t).exp();
        let x = x0 * decay * ((wd * t).cos() + zeta * w / wd * (wd * t).sin());
        let v = -(w * w * x0 / wd) * decay * (wd * t).sin(); // mm/s
        let kinetic = 0.5 * m * v * v * 1e-3; // kg·mm²/s² → N·mm
        let potential = 0.5 * k * x * x;
        let b = &s.balance;
        let close = |a: f64, e: f64, what: &str| {
            assert!(
                (a - e).abs() < 1e-8 * e0,
                "{what} at {t} s: {a} N·mm, closed form {e} N·mm"
            )
        };
        close(b.kinetic, kinetic, "kinetic energy");
        close(b.elements[0].potential, potential, "spring's potential");
        close(
            b.elements[1].work,
            kinetic + potential - e0,
            "damper's work",
        );
        close(b.elements[0].work, -(potential - e0), "spring's work");
        close(b.constraints, 0.0, "slide's work");
        close(b.residual(), 0.0, "residual");
        assert!(b.elements[0].stores && !b.elements[1].stores);
        assert_eq!(b.initial, e0);
        checked += 1;
    }
    assert_eq!(checked, 301);
    // it has lost most of its energy by 0.3 s (e^{−2ζωt} ≈ 0.002)
    let last = &run.samples.last().unwrap().balance;
    assert!(last.dampers() < -0.99 * e0, "{last:?}");
}

/// A 0.2 kg block dropped 50 mm onto a seat with restitution 0.6 (in m): each impact at
/// `v_k = e^k √(2 g h₀)` loses `(1 − e²) ½ m v_k²`, so after four the impacts' sum is their
/// closed form to 1e-9 J, gravity's work is minus its potential's change, and the balance
/// explains the rest to 1e-9 of `m g h₀`; the guide and the seat do no work.
#[test]
fn a_bouncing_blocks_impacts_lose_their_closed_form() {
    let (g, h0, e, m) = (9.81, 0.05, 0.6, 0.2);
    // the block of `dynamics_system`: 0.2 kg on a vertical guide, h₀ above a seat
    let sys = crate::dynamics_system::dropped_block(h0);
    let opts = SystemDynamicsOptions {
        gravity: Vec2::new(0.0, -g),
        restitution: vec![e],
        tolerances: tight(),
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let v1 = (2.0 * g * h0).sqrt();
    // the fourth impact: t₁ + 2 e v₁/g + 2 e² v₁/g + 2 e³ v₁/g
    let t4 = v1 / g + 2.0 * (e + e * e + e * e * e) * v1 / g;
    let run = sim
        .run(((t4 + 0.02) / 1e-3) as usize, 1e-3, |_| {
            ControlFlow::Continue(())
        })
        .unwrap();
    let impacts = run.events.len();
    assert_eq!(impacts, 4, "{:?}", run.events);
    let lost: f64 = (0..4)
        .map(|j| {
            let v = e.powi(j) * v1;
            -(1.0 - e * e) * 0.5 * m * v * v
        })
        .sum();
    let b = &run.samples.last().unwrap().balance;
    let scale = m * g * h0;
    assert!(
        (b.impacts - lost).abs() < 1e-9 * scale,
        "impacts {} J, closed form {lost} J",
        b.impacts
    );
    for s in &run.samples {
        let b = &s.balance;
        // gravity's potential m g y, from m g h₀ at the start
        let potential = m * g * s.q[1];
        assert!(
            (b.gravity.potential - potential).abs() < 1e-12 * scale,
            "{b:?}"
        );
        assert!(
            (b.gravity.work + (potential - scale)).abs() < 1e-9 * scale,
            "{b:?}"
        );
        assert!(b.constraints.abs() < 1e-9 * scale, "{b:?}");
        assert!(b.residual().abs() < 1e-9 * scale, "{b:?}");
    }
}

/// A disc of 2 kg pinned at its frame's origin, its centre of mass 0.1 m off it, driven at
/// 10 rad/s against a torsion damper of 0.3 N·m·s to the ground, under gravity: the damper takes
/// `c ω² t`, and the driver gives that plus the centre's rise against gravity, `m g Δy_G`
/// (`y_G = 0.1 sin ωt`); the kinetic energy stays `½ (I_G + m r²) ω²`, and the pin does no
/// work.
#[test]
fn a_driven_cranks_driver_pays_the_damper_and_gravity() {
    let (m, ig, r, w, c, g) = (2.0, 0.01, 0.1, 10.0, 0.3, 9.81);
    let mut sys = System::new();
    let disc = sys.add_body(Body {
        name: "disc".into(),
        mass: m,
        inertia: ig,
        pose: camkin::body::Pose::new(Point2::origin(), 0.0),
        centre_of_mass: Point2::new(r, 0.0),
    });
    sys.add_joint(Joint {
        name: "pin".into(),
        kind: JointKind::Revolute {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            b: disc,
            at_b: Point2::origin(),
        },
    });
    sys.add_driver(Driver {
        name: "motor".into(),
        body: disc,
        coordinate: Coordinate::Angle,
        law: DriverLaw::linear(0.0, w),
    });
    sys.add_force(ForceElement {
        name: "bearing drag".into(),
        kind: ForceKind::TorsionDamper {
            a: BodyId::GROUND,
            b: disc,
            damping: c,
        },
    });
    let opts = SystemDynamicsOptions {
        gravity: Vec2::new(0.0, -g),
        tolerances: tight(),
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let run = sim.run(200, 5e-3, |_| ControlFlow::Continue(())).unwrap();
    let kinetic = 0.5 * (ig + m * r * r) * w * w;
    let scale = kinetic;
    for s in &run.samples {
        let (t, b) = (s.time, &s.balance);
        let rise = m * g * r * (w * t).sin();
        let close = |a: f64, e: f64, what: &str| {
            assert!(
                (a - e).abs() < 1e-8 * scale,
                "{what} at {t} s: {a} J, closed form {e} J"
            )
        };
        close(b.kinetic, kinetic, "kinetic energy");
        close(b.elements[0].work, -c * w * w * t, "damper's work");
        close(b.drivers, c * w * w * t + rise, "driver's work");
        close(b.gravity.work, -rise, "gravity's work");
        close(b.constraints, 0.0, "pin's work");
        close(b.residual(), 0.0, "residual");
        close(s.driver_work, b.drivers, "driver_work");
    }
}

/// A free body of 0.3 kg thrown at (3, 4) m/s turning at 2 rad/s under gravity: its momentum is
/// `m (v₀ + g t)`, its angular momentum about the origin `m r_G × v_G + I ω` with the centre on
/// its parabola, and its energy constant.
#[test]
fn a_thrown_bodys_momentum_changes_by_its_weights_impulse() {
    let (m, i, g) = (0.3, 2e-3, 9.81);
    let mut sys = System::new();
    sys.add_body(Body {
        name: "stone".into(),
        mass: m,
        inertia: i,
        pose: camkin::body::Pose::new(Point2::new(1.0, 2.0), 0.0),
        centre_of_mass: Point2::origin(),
    });
    let opts = SystemDynamicsOptions {
        gravity: Vec2::new(0.0, -g),
        tolerances: tight(),
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let (v0, w) = (Vec2::new(3.0, 4.0), 2.0);
    sim.set_frame_rates(&[v0.x, v0.y, w]).unwrap();
    let run = sim.run(100, 0.01, |_| ControlFlow::Continue(())).unwrap();
    let e0 = 0.5 * m * v0.norm_squared() + 0.5 * i * w * w + m * g * 2.0;
    for s in &run.samples {
        let (t, b) = (s.time, &s.balance);
        let v = Vec2::new(v0.x, v0.y - g * t);
        let r = Vec2::new(1.0 + v0.x * t, 2.0 + v0.y * t - 0.5 * g * t * t);
        let p = m * v;
        let l = m * (r.x * v.y - r.y * v.x) + i * w;
        assert!(
            (b.momentum[0] - p.x).abs() < 1e-12 && (b.momentum[1] - p.y).abs() < 1e-12,
            "momentum {:?} at {t} s, closed form {p:?}",
            b.momentum
        );
        assert!(
            (b.angular_momentum - l).abs() < 1e-12,
            "angular momentum {} at {t} s, closed form {l}",
            b.angular_momentum
        );
        assert!((b.initial - e0).abs() < 1e-12, "{} {e0}", b.initial);
        assert!((b.total() - e0).abs() < 1e-12 * e0, "{b:?}");
        assert!(b.residual().abs() < 1e-12 * e0, "{b:?}");
    }
}
