//! Issue 64, "a stiffly accurate implicit scheme for stiff systems": the SDIRK integrator
//! (`Scheme::Implicit`, chosen by `Scheme::Auto` where a damper's decay is the fastest rate by
//! far) against the closed form of a block on a slide held by a spring and a damper to the
//! ground, `m ẍ + c ẋ + k x = 0`: `x = A e^{λ₁t} + B e^{λ₂t}` with `λ = (−c ± √(c² − 4mk))/2m`
//! (overdamped) or `x = x₀ e^{−ζωt}(cos ω_d t + ζω/ω_d sin ω_d t)` (underdamped).

use crate::common::*;
use camkin::dynamics::{Scheme, SystemDynamicsOptions, SystemSimulation, Tolerances};
use camkin::system::{Body, BodyId, ForceElement, ForceKind, Joint, JointKind, System};
use camkin::{Point2, Vec2};
use std::ops::ControlFlow;

/// A 1 kg block on a slide along x (metres) at `x0`, a spring `k` and a damper `c` from the
/// ground 1 m behind its rest.
fn block(k: f64, c: f64, x0: f64) -> System {
    let mut sys = System::new();
    let b = sys.add_body(Body {
        name: "block".into(),
        mass: 1.0,
        inertia: 1e-3,
        pose: camkin::body::Pose::new(Point2::new(x0, 0.0), 0.0),
        centre_of_mass: Point2::origin(),
    });
    sys.add_joint(Joint {
        name: "slide".into(),
        kind: JointKind::Prismatic {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            axis: Vec2::x(),
            b,
            at_b: Point2::origin(),
            angle: 0.0,
        },
    });
    let anchor = Point2::new(-1.0, 0.0);
    sys.add_force(ForceElement {
        name: "spring".into(),
        kind: ForceKind::Spring {
            a: BodyId::GROUND,
            at_a: anchor,
            b,
            at_b: Point2::origin(),
            stiffness: k,
            free_length: 1.0,
            preload: 0.0,
        },
    });
    sys.add_force(ForceElement {
        name: "damper".into(),
        kind: ForceKind::Damper {
            a: BodyId::GROUND,
            at_a: anchor,
            b,
            at_b: Point2::origin(),
            damping: c,
        },
    });
    sys
}

/// `x(t)` of `ẍ + c ẋ + k x = 0` (unit mass) from `x0` at rest.
fn exact(k: f64, c: f64, x0: f64, t: f64) -> f64 {
    let disc = c * c - 4.0 * k;
    if disc > 0.0 {
        let r = disc.sqrt();
        let (l1, l2) = (0.5 * (-c + r), 0.5 * (-c - r));
        let (a, b) = (x0 * l2 / (l2 - l1), -x0 * l1 / (l2 - l1));
        a * (l1 * t).exp() + b * (l2 * t).exp()
    } else {
        let w = k.sqrt();
        let z = c / (2.0 * w);
        let wd = w * (1.0 - z * z).sqrt();
        x0 * (-z * w * t).exp() * ((wd * t).cos() + z * w / wd * (wd * t).sin())
    }
}

/// Runs `sys` with `scheme` for `outputs` intervals of `h`: the positions and the steps taken.
fn run(
    sys: &System,
    scheme: Scheme,
    outputs: usize,
    h: f64,
) -> (Vec<(f64, f64)>, (usize, usize), Scheme) {
    let opts = SystemDynamicsOptions {
        tolerances: Tolerances {
            relative: 1e-10,
            absolute: 1e-10,
        },
        scheme,
        ..Default::default()
    };
    let mut sim = SystemSimulation::new(sys, opts).unwrap();
    let used = sim.scheme_in_use();
    let run = sim.run(outputs, h, |_| ControlFlow::Continue(())).unwrap();
    let xs = run.samples.iter().map(|s| (s.time, s.q[0])).collect();
    (xs, sim.steps_taken(), used)
}

/// A spring of 10⁶ N/m and a damper of 10⁶ N·s/m on 1 kg, let go 10 mm from rest: a decay at
/// 10⁶/s (the explicit pair's stable step 3.3 µs: 1.5 million steps in 5 s) and a creep back at
/// 1/s. `Scheme::Auto` takes the implicit method, which follows the closed form to 1e-8 of `x₀`
/// over 5 s in under a thousandth of the explicit pair's steps.
#[test]
fn an_overdamped_stiff_block_creeps_back_by_its_closed_form_in_few_implicit_steps() {
    let (k, c, x0) = (1e6, 1e6, 0.01);
    let sys = block(k, c, x0);
    let (xs, (accepted, rejected), used) = run(&sys, Scheme::Auto, 100, 0.05);
    assert_eq!(used, Scheme::Implicit, "chosen by the rates");
    let mut worst: f64 = 0.0;
    for &(t, x) in &xs {
        let want = exact(k, c, x0, t);
        assert_close(x, want, 1e-8, x0, &format!("t = {t} s"));
        worst = worst.max((x - want).abs() / x0);
    }
    eprintln!("implicit: {accepted} steps ({rejected} rejected), within {worst:.1e} of x₀");
    assert!(accepted + rejected < 1500, "{accepted} + {rejected} steps");
}

/// Where nothing is stiff both integrators follow an underdamped block (ω = 1000/s, ζ = 0.05)
/// to 1e-7 of `x₀` over 20 ms, and `Scheme::Auto` takes the explicit pair.
#[test]
fn both_integrators_follow_an_underdamped_block() {
    let (k, c, x0) = (1e6, 100.0, 0.01);
    let sys = block(k, c, x0);
    for scheme in [Scheme::Auto, Scheme::Explicit, Scheme::Implicit] {
        let (xs, steps, used) = run(&sys, scheme, 200, 1e-4);
        if scheme == Scheme::Auto {
            assert_eq!(used, Scheme::Explicit);
        }
        for &(t, x) in &xs {
            assert_close(
                x,
                exact(k, c, x0, t),
                1e-7,
                x0,
                &format!("{used:?} at t = {t} s"),
            );
        }
        eprintln!("{used:?}: {steps:?} steps");
    }
}
