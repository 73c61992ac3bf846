//! Issue 64, "energy, momentum and work reports for every simulation": a cam file's follower
//! (`Sample::balance`) in both of its models — the preset system and the one-coordinate model —
//! against closed forms that share no formula with them: an eccentric disc under a damped flat
//! face (the motion `s = R + e cos θ`, its spring's and gravity's potential, the damper's
//! dissipation `c e² ω² (t/2 − sin 2ωt / 4ω)` and the driver's work from them), and plastic
//! impacts of a follower thrown off the paper's cam (each loses `½ m u²` of the approach speed
//! the event reports, the driver's impulse counted as the driver's work); the two models'
//! balances agree term by term.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Mechanism, Sense};
use camkin::dynamics::{
    AugmentedLagrangian, EventKind, FollowerDynamics, Reduced, Sample, Simulation, Tolerances,
};
use camkin::{Point2, Vec2};
use std::f64::consts::TAU;

/// The preset system at tight tolerances, and the one-coordinate model, of `m` with `p`.
fn both(m: &Mechanism, p: FollowerDynamics) -> [Simulation<'_>; 2] {
    let mut a = Simulation::new(m, p, AugmentedLagrangian::default()).unwrap();
    assert!(matches!(a, Simulation::Preset(_)), "the preset system");
    a.set_tolerances(Tolerances {
        relative: 1e-11,
        absolute: 1e-11,
    })
    .unwrap();
    let b = Simulation::Reduced(Reduced::starting_at(m, p, 0.0).unwrap());
    [a, b]
}

/// A disc of radius 40 mm, 5 mm off the cam's axis, at 300 rpm ccw under a flat face on a slide
/// along x (SI): the face stays on the disc, `s = R + e cos θ`.
fn eccentric() -> Mechanism {
    mechanism(
        eccentric_circle(0.04, 0.005),
        Point2::origin(),
        Sense::Ccw,
        300.0,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    )
}

/// The follower's balance on the eccentric disc over a revolution at 1° samples, in both
/// models: a 0.5 kg face, 20 kN/m with 200 N at its lowest position, 20 N·s/m, gravity 9.81 m/s²
/// towards the cam. With `x = s − (R − e)` and `ṡ = −e ω sin θ`:
/// - kinetic `½ m ṡ²`; the spring's potential `½ k x² + F₀ x` and its work minus its change;
/// - gravity's potential `m g s` (the slide's origin is the cam's axis) and its work;
/// - the damper's work `−c e² ω² (t/2 − sin 2ωt / 4ω)`;
/// - the driver's work the change of `T + V` less the damper's: nothing unexplained, the joints
///   and the contact do no work, nothing lost in impacts.
///
/// Each to 1e-8 of the energy's scale `F₀ · 2e`.
#[test]
fn a_damped_face_on_an_eccentric_disc_balances_in_both_models() {
    let m = eccentric();
    let (mass, k, f0, c, g) = (0.5, 2.0e4, 200.0, 20.0, 9.81);
    let (r, e) = (0.04, 0.005);
    let p = FollowerDynamics {
        mass,
        inertia: 0.0,
        spring_stiffness: k,
        spring_preload: f0,
        damping: c,
        restitution: 0.0,
        gravity: Vec2::new(-g, 0.0),
    };
    let w = m.cam().speed();
    let h = 1f64.to_radians() / w;
    let scale = f0 * 2.0 * e;
    let exact = |t: f64| {
        let th = w * t;
        let s = r + e * th.cos();
        let sd = -e * w * th.sin();
        let x = s - (r - e);
        let kinetic = 0.5 * mass * sd * sd;
        let spring = 0.5 * k * x * x + f0 * x;
        let gravity = mass * g * s;
        let damper = -c * e * e * w * w * (0.5 * t - (2.0 * th).sin() / (4.0 * w));
        (kinetic, spring, gravity, damper)
    };
    let (k0, s0, g0, _) = exact(0.0);
    for (model, mut sim) in ["preset", "one-coordinate"].into_iter().zip(both(&m, p)) {
        let mut worst: f64 = 0.0;
        for i in 0..=360 {
            if i > 0 {
                assert!(sim.advance(h).unwrap().is_empty(), "{model}: no lift-off");
            }
            let smp = sim.sample().unwrap();
            let b = &smp.balance;
            let (kin, spring, gravity, damper) = exact(smp.time);
            let driver = kin + spring + gravity - (k0 + s0 + g0) - damper;
            let at = format!("{model}, {i}°");
            assert_eq!(b.elements.len(), 2, "{at}: the spring and the damper");
            for (what, got, want) in [
                ("kinetic", b.kinetic, kin),
                ("spring's potential", b.elements[0].potential, spring),
                ("spring's work", b.elements[0].work, s0 - spring),
                ("gravity's potential", b.gravity.potential, gravity),
                ("gravity's work", b.gravity.work, g0 - gravity),
                ("damper's work", b.elements[1].work, damper),
                ("dampers()", b.dampers(), damper),
                ("driver's work", b.drivers, driver),
                ("sample's driver_work", smp.driver_work, driver),
                ("start", b.initial, k0 + s0 + g0),
                ("joints' and contact's work", b.constraints, 0.0),
                ("impacts", b.impacts, 0.0),
                ("unexplained", b.residual(), 0.0),
            ] {
                assert_close(got, want, 1e-8, scale, &format!("{at}: {what}"));
                worst = worst.max((got - want).abs() / scale);
            }
            assert!(b.elements[0].stores && !b.elements[1].stores);
            // the slide's momentum along x
            assert_close(b.momentum[0], mass * smp.velocity, 1e-9, mass * e * w, &at);
            assert_close(b.momentum[1], 0.0, 1e-9, mass * e * w, &at);
        }
        // a revolution dissipates π c e² ω
        let last = sim.sample().unwrap();
        assert_close(
            last.balance.dampers(),
            -std::f64::consts::PI * c * e * e * w,
            1e-8,
            scale,
            &format!("{model}: a revolution's dissipation"),
        );
        eprintln!("{model}: every term within {worst:.1e} of F₀·2e");
    }
}

/// The paper's cam (read in metres) at 1000 rpm under a flat face on a soft spring, three
/// revolutions: the face is thrown off and lands again and again. With no restitution each landing loses the
/// kinetic energy of its approach, `½ m u²` (`u` the event's approach speed along the face's
/// normal, the slide's direction), and the driver's impulse, which keeps the cam's speed, is
/// the driver's work: the impacts' total is `−½ m Σ u²` in both models to 1e-6, and the balance
/// leaves 1e-8 of the energy's scale unexplained. Both models' balances agree term by term.
#[test]
fn plastic_landings_lose_their_approach_energy_in_both_models() {
    let m = mechanism(
        paper_profile(false),
        Point2::origin(),
        Sense::Ccw,
        1000.0,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    );
    let mass = 0.5;
    let p = FollowerDynamics {
        mass,
        inertia: 0.0,
        spring_stiffness: 500.0,
        spring_preload: 1000.0,
        damping: 5.0,
        restitution: 0.0,
        gravity: Vec2::zeros(),
    };
    let h = 0.25f64.to_radians() / m.cam().speed();
    let mut runs: Vec<(Vec<Sample>, f64, usize)> = Vec::new();
    for (model, mut sim) in ["preset", "one-coordinate"].into_iter().zip(both(&m, p)) {
        let (mut samples, mut lost, mut landings) = (vec![sim.sample().unwrap()], 0.0, 0);
        for _ in 0..3 * 1440 {
            for ev in sim.advance(h).unwrap() {
                if ev.kind == EventKind::Impact {
                    lost -= 0.5 * mass * ev.impact_velocity * ev.impact_velocity;
                    landings += 1;
                }
            }
            samples.push(sim.sample().unwrap());
        }
        let b = &samples.last().unwrap().balance;
        let scale = b.kinetic.abs().max(b.initial.abs()).max(b.drivers.abs());
        eprintln!(
            "{model}: {landings} landings lose {lost:.6e} J; balance {:.6e}, unexplained {:.1e} of {scale:.3e}",
            b.impacts,
            b.residual()
        );
        assert!(landings >= 2, "{model}: {landings} landings");
        assert_close(
            b.impacts,
            lost,
            1e-6,
            lost.abs(),
            &format!("{model}: impacts"),
        );
        for s in &samples {
            assert_close(
                s.balance.residual(),
                0.0,
                1e-8,
                scale,
                &format!("{model}: unexplained"),
            );
            assert!(s.balance.impacts <= 0.0, "{model}: an impact gained energy");
        }
        runs.push((samples, scale, landings));
    }
    let ((a, scale, _), (b, _, _)) = (&runs[0], &runs[1]);
    for (x, y) in a.iter().zip(b) {
        let (p, q) = (&x.balance, &y.balance);
        let at = format!("{:.2}°", x.cam_angle.to_degrees());
        for (what, u, v) in [
            ("kinetic", p.kinetic, q.kinetic),
            ("potential", p.potential(), q.potential()),
            ("dampers", p.dampers(), q.dampers()),
            ("drivers", p.drivers, q.drivers),
            ("impacts", p.impacts, q.impacts),
        ] {
            assert_close(u, v, 1e-6, *scale, &format!("{at}: {what}"));
        }
    }
}

/// An oscillating roller (arm 60 mm, roller 10 mm, pivot 80 mm off the axis) on the eccentric
/// disc, held on by a torsion spring in each closing sense: both models give the same potential
/// (the torsion spring's `½ k x² + F₀ x` from its rest, whatever the closing sense), the
/// angular momentum `I ω` of the arm, and nothing unexplained (1e-8).
#[test]
fn an_arms_balance_agrees_in_both_models_for_both_closing_senses() {
    for closing in [Sense::Ccw, Sense::Cw] {
        let m = mechanism(
            eccentric_circle(0.04, 0.005),
            Point2::origin(),
            Sense::Ccw,
            300.0,
            Follower::OscillatingRoller {
                pivot: Point2::new(0.08, 0.0),
                arm_length: 0.06,
                roller_radius: 0.01,
                closing,
                initial_angle: match closing {
                    Sense::Ccw => TAU / 2.0 - 0.6,
                    Sense::Cw => TAU / 2.0 + 0.6,
                },
            },
        );
        let inertia = 2e-4;
        let p = FollowerDynamics {
            mass: 0.0,
            inertia,
            spring_stiffness: 50.0,
            spring_preload: 5.0,
            damping: 0.01,
            restitution: 0.0,
            gravity: Vec2::zeros(),
        };
        let h = 1f64.to_radians() / m.cam().speed();
        let [mut a, mut b] = both(&m, p);
        let scale = p.spring_preload * 0.2;
        for i in 0..360 {
            assert!(a.advance(h).unwrap().is_empty() && b.advance(h).unwrap().is_empty());
            let (x, y) = (a.sample().unwrap(), b.sample().unwrap());
            let at = format!("closing {closing:?}, {}°", i + 1);
            for (what, u, v) in [
                ("kinetic", x.balance.kinetic, y.balance.kinetic),
                ("potential", x.balance.potential(), y.balance.potential()),
                ("start", x.balance.initial, y.balance.initial),
                ("dampers", x.balance.dampers(), y.balance.dampers()),
                ("drivers", x.balance.drivers, y.balance.drivers),
            ] {
                assert_close(u, v, 1e-8, scale, &format!("{at}: {what}"));
            }
            for (model, s) in [("preset", &x), ("one-coordinate", &y)] {
                assert_close(
                    s.balance.residual(),
                    0.0,
                    1e-8,
                    scale,
                    &format!("{at}: {model}"),
                );
                assert_close(
                    s.balance.angular_momentum,
                    inertia * s.velocity,
                    1e-9,
                    inertia * 10.0,
                    &format!("{at}: {model}'s angular momentum"),
                );
            }
        }
    }
}
