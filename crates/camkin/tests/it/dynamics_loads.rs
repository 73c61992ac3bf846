//! Issue 64, "elements people expect": a force and a torque applied to a body (`[[load]]`),
//! constant or by a table of time, in the world's frame or turning with the body, against
//! closed forms; their work counted with the drivers', so that the energy less the work is
//! constant; bad loads refused at their key. And a point mass (`inertia = 0`).

use camkin::dynamics::SystemSimulation;

/// A system of one body `block` (mass 2 kg, inertia 0.5 kg·m², lengths in m) with `extra`
/// (its joints and loads), no gravity.
fn block(extra: &str) -> camkin::spec::BuiltSystem {
    let text = format!(
        "length_unit = \"m\"\n[dynamics]\n[[body]]\nname = \"block\"\nmass = 2.0\ninertia = 0.5\n{extra}\n"
    );
    crate::common::read_system(&text, "loads.toml", &Default::default()).unwrap()
}

/// The samples of `t` seconds of `built` in 100 steps.
fn run(built: &camkin::spec::BuiltSystem, t: f64) -> Vec<camkin::dynamics::SystemSample> {
    let mut sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
    sim.run(100, t / 100.0, |_| std::ops::ControlFlow::Continue(()))
        .unwrap()
        .samples
}

/// A free block pushed by a constant world force `(3, −4)` N at its centre moves as
/// `x = F t²/(2m)` and does not turn; the force's work `F·x` is counted, so the energy less the
/// work stays 0 (to 1e-9 J). With the force ramped up by `profile = [[0, 0], [1, 1]]` it moves as
/// `F t³/(6 m T)` over the ramp (to 1e-9 m), then at the whole force.
#[test]
fn a_constant_and_a_ramped_world_force_move_a_free_block_by_their_closed_forms() {
    let (m, f) = (2.0, [3.0, -4.0]);
    let built = block("[[load]]\nname = \"push\"\nbody = \"block\"\nforce = [3.0, -4.0]");
    for s in run(&built, 2.0) {
        let t = s.time;
        for (c, fc) in f.iter().enumerate() {
            let x = fc * t * t / (2.0 * m);
            assert!((s.q[c] - x).abs() < 1e-9, "t = {t}: {} against {x}", s.q[c]);
        }
        assert!(s.q[2].abs() < 1e-15);
        assert!(
            (s.energy - s.driver_work).abs() < 1e-9,
            "{} {}",
            s.energy,
            s.driver_work
        );
    }
    let built = block(
        "[[load]]\nname = \"push\"\nbody = \"block\"\nforce = [3.0, -4.0]\nprofile = [[0.0, 0.0], [1.0, 1.0]]",
    );
    for s in run(&built, 2.0) {
        let t = s.time;
        for (c, &fc) in f.iter().enumerate() {
            // over the ramp F t³/(6 m), then the whole force from t = 1 (x(1) = F/6m, v(1) = F/2m)
            let x = if t <= 1.0 {
                fc * t.powi(3) / (6.0 * m)
            } else {
                let u = t - 1.0;
                fc / (6.0 * m) + fc / (2.0 * m) * u + fc * u * u / (2.0 * m)
            };
            assert!((s.q[c] - x).abs() < 1e-9, "t = {t}: {} against {x}", s.q[c]);
        }
    }
}

/// A bar pinned at its end (the pin at the body's origin, its centre 0.5 m along it) pushed at
/// its tip (1 m along it) by a force across it in its own frame, `(0, 6)` N, and by a torque of
/// 1.5 N·m: a constant moment `6·1 + 1.5` about the pin, so `θ = M t²/(2 I_O)` with
/// `I_O = I + m d²` (to 1e-9 rad). Written in the world's frame instead, the force's moment
/// falls as the bar turns (`6 cos θ`): it turns less (checked to be below the body frame's).
#[test]
fn a_force_turning_with_a_pinned_bar_and_a_torque_turn_it_by_the_closed_form() {
    let (m, i, d) = (2.0, 0.5, 0.5);
    let pinned = |frame: &str| {
        block(&format!(
            "centre_of_mass = [{d}, 0.0]\n[[joint]]\nname = \"pin\"\nkind = \"revolute\"\nbodies = [\"ground\", \"block\"]\n[[load]]\nname = \"push\"\nbody = \"block\"\nat = [1.0, 0.0]\nforce = [0.0, 6.0]\nframe = \"{frame}\"\ntorque = 1.5"
        ))
    };
    let moment = 6.0 * 1.0 + 1.5;
    let io = i + m * d * d;
    let turning = run(&pinned("body"), 1.0);
    for s in &turning {
        let t = s.time;
        let theta = moment * t * t / (2.0 * io);
        assert!(
            (s.q[2] - theta).abs() < 1e-9,
            "t = {t}: {} against {theta}",
            s.q[2]
        );
        // to the tolerance's share of its kinetic energy
        let drift = (s.energy - s.driver_work).abs();
        assert!(
            drift < 1e-9 * s.energy.max(1.0),
            "t = {t}: {drift:e} of {} J",
            s.energy
        );
    }
    let fixed = run(&pinned("world"), 1.0);
    let (a, b) = (turning.last().unwrap().q[2], fixed.last().unwrap().q[2]);
    assert!(b < a - 0.01, "world {b}, body {a}");
}

/// Bad loads exit at their key: an unknown frame, the ground, times that do not increase, a
/// force out of range.
#[test]
fn bad_loads_are_refused_at_their_key() {
    let text = |load: &str| {
        format!(
            "length_unit = \"m\"\n[dynamics]\n[[body]]\nname = \"block\"\n[[load]]\nname = \"push\"\n{load}\n"
        )
    };
    for (load, needles) in [
        (
            "body = \"block\"\nframe = \"cam\"",
            &["load[0].frame", "\"cam\"", "world, body"][..],
        ),
        (
            "body = \"ground\"",
            &["load[0].body", "the ground does not move"][..],
        ),
        (
            "body = \"block\"\nprofile = [[0.0, 1.0], [0.0, 2.0]]",
            &["load[0].profile", "must increase"][..],
        ),
        (
            "body = \"block\"\nforce = [1e13, 0.0]",
            &["load[0].force", "1e13"][..],
        ),
    ] {
        let e = crate::common::read_system(&text(load), "l.toml", &Default::default())
            .map(|_| ())
            .unwrap_err()
            .to_string();
        for n in needles {
            assert!(e.contains(n), "{load}: {e}");
        }
    }
}

/// A simple pendulum: a point mass (`inertia = 0`) of 0.3 kg pinned 1 m from its centre,
/// released level under gravity, reaches the bottom after a quarter of its exact period,
/// `K(sin 45°) √(L/g)` (by the arithmetic–geometric mean), to 1e-9 s, at the speed its fall
/// gives it, `√(2 g L (−sin θ))`, to 1e-9 of it: its angle turns the pin's point about its
/// centre without inertia of its own.
#[test]
fn a_point_mass_on_a_pin_swings_as_a_simple_pendulum() {
    let (l, g) = (1.0f64, 9.81f64);
    let text = format!(
        "length_unit = \"m\"\n[dynamics]\ngravity = [0.0, -{g}]\n[[body]]\nname = \"bob\"\nmass = 0.3\ninertia = 0.0\nposition = [{l}, 0.0]\n[[joint]]\nname = \"pin\"\nkind = \"revolute\"\nbodies = [\"ground\", \"bob\"]\nat = [[0.0, 0.0], [-{l}, 0.0]]\n"
    );
    let built = crate::common::read_system(&text, "bob.toml", &Default::default()).unwrap();
    let mut agm = (1.0f64, std::f64::consts::FRAC_PI_4.cos());
    for _ in 0..8 {
        agm = (0.5 * (agm.0 + agm.1), (agm.0 * agm.1).sqrt());
    }
    let quarter = std::f64::consts::FRAC_PI_2 / agm.0 * (l / g).sqrt();
    let mut sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
    let run = sim
        .run(1000, 1e-3, |_| std::ops::ControlFlow::Continue(()))
        .unwrap();
    // the sample nearest the bottom, then one Newton step on the angle (its acceleration is 0
    // there: the step's error is third order)
    let bottom = -std::f64::consts::FRAC_PI_2;
    let s = run
        .samples
        .iter()
        .min_by(|a, b| (a.q[2] - bottom).abs().total_cmp(&(b.q[2] - bottom).abs()))
        .unwrap();
    let t = s.time + (bottom - s.q[2]) / s.qd[2];
    assert!((t - quarter).abs() < 1e-9, "{t} against {quarter}");
    // the speed the fall gives it, `√(2 g L (−sin θ))`: the bob's kinetic energy is all its
    // translation's
    let speed = s.qd[2].abs() * l;
    let exact = (2.0 * g * l * -s.q[2].sin()).sqrt();
    assert!(
        (speed - exact).abs() < 1e-9 * exact,
        "{speed} against {exact}"
    );
    for s in &run.samples {
        assert!(
            (s.energy - run.samples[0].energy).abs() < 1e-9,
            "{}",
            s.energy
        );
    }
}
