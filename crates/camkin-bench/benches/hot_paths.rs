//! Criterion benchmarks of the hot paths: `cargo bench -p camkin`.
//!
//! - `spline/eval`: one evaluation of the paper's cam profile (position and three derivatives);
//! - `contact/find_contact`: the general pairing-point search between a spline and an ellipse;
//! - `contact/find_contact_1000`, `contact/find_contact_indexed_1000`: the same between two closed
//!   splines of 1000 nodes each (16 000 samples each), the indexes built at each query or once;
//! - `contact/kinematics`: sliding rates, constraint row and right-hand side at a given pairing;
//! - `cold/<follower>`: one query at an arbitrary cam angle (global search, velocity,
//!   acceleration: `Mechanism::motion`) for each follower type on the paper's cam;
//! - `sweep/<follower>`: one warm-started step of a 0.05° sweep (`Sweep::step_motion`);
//! - `sweep_full_state/translating-flat`: the same with every output (`Sweep::step`, no jerk);
//! - `dynamics/revolution_1deg`: one simulated revolution of the paper's cam, 1° steps.
use camkin::body::{BodyState, Pose};
use camkin::contact::{
    find_contact, find_contact_indexed, ContactKinematics, CurveIndex, SearchOptions, Surface,
};
use camkin::curve::{Curve, Ellipse};
use camkin::reference::{paper_mechanism, paper_profile};
use camkin::{Point2, Vec2};
use criterion::{black_box, criterion_group, criterion_main, Criterion};

use camkin_bench::scenarios::{
    paper_dynamics, paper_followers as followers, paper_with as mechanism, star,
};

fn spline(c: &mut Criterion) {
    let s = paper_profile(false);
    let mut u = 0.0;
    c.bench_function("spline/eval", |b| {
        b.iter(|| {
            u = (u + 0.37) % 9.0;
            black_box(s.eval(black_box(u)))
        })
    });
}

fn contact(c: &mut Criterion) {
    let sp = paper_profile(false);
    let el = Ellipse::new(Point2::origin(), 1.5, 1.0, 0.3).expect("ellipse");
    let a = BodyState {
        pose: Pose::new(Point2::origin(), 0.4),
        velocity: Vec2::new(0.1, 0.0),
        omega: 3.0,
        acceleration: Vec2::zeros(),
        alpha: 0.0,
    };
    let b = BodyState {
        pose: Pose::new(Point2::new(7.0, 1.0), -0.2),
        velocity: Vec2::new(0.0, -1.0),
        omega: -2.0,
        acceleration: Vec2::zeros(),
        alpha: 0.0,
    };
    let opts = SearchOptions::for_length_scale(5.0);
    let (sa, sb) = (Surface::new(&sp, &a), Surface::new(&el, &b));
    c.bench_function("contact/find_contact", |bch| {
        bch.iter(|| black_box(find_contact(&sa, &sb, &opts)))
    });
    let p = find_contact(&sa, &sb, &opts).expect("pair").pairing();
    // two wavy closed splines of 1000 nodes, 8 mm apart
    let (s1, s2) = (star(50.0, 0.1, 3.0), star(20.0, 0.15, 2.0));
    let b1 = BodyState::at_rest(Pose::new(Point2::origin(), 0.0));
    let b2 = BodyState::at_rest(Pose::new(Point2::new(78.0, 3.0), 0.0));
    let (t1, t2) = (Surface::new(&s1, &b1), Surface::new(&s2, &b2));
    let o50 = SearchOptions::for_length_scale(50.0);
    c.bench_function("contact/find_contact_1000", |bch| {
        bch.iter(|| black_box(find_contact(&t1, &t2, &o50)))
    });
    let (i1, i2) = (CurveIndex::new(&s1, &o50), CurveIndex::new(&s2, &o50));
    c.bench_function("contact/find_contact_indexed_1000", |bch| {
        bch.iter(|| {
            black_box(find_contact_indexed(
                &t1,
                i1.as_ref(),
                &t2,
                i2.as_ref(),
                &o50,
            ))
        })
    });
    c.bench_function("contact/kinematics", |bch| {
        bch.iter(|| black_box(ContactKinematics::new(&sa, &sb, black_box(&p), 1e-9)))
    });
}

fn followers_bench(c: &mut Criterion) {
    let _ = paper_mechanism(false);
    for f in followers() {
        let name = f.kind_name();
        let m = mechanism(f);
        let mut k = 0u64;
        c.bench_function(&format!("cold/{name}"), |b| {
            b.iter(|| {
                k = k.wrapping_add(1);
                let th = (k as f64 * 137.50776405).rem_euclid(360.0).to_radians();
                black_box(m.motion(th))
            })
        });
        let mut sweep = m.sweep();
        let mut th = 0.0f64;
        c.bench_function(&format!("sweep/{name}"), |b| {
            b.iter(|| {
                th += 0.05f64.to_radians();
                black_box(sweep.step_motion(th))
            })
        });
    }
    // the full analysis (every output but the jerk), flat face
    let m = mechanism(followers()[0].clone());
    let mut sweep = m.sweep();
    let mut th = 0.0f64;
    c.bench_function("sweep_full_state/translating-flat", |b| {
        b.iter(|| {
            th += 0.05f64.to_radians();
            black_box(sweep.step(th))
        })
    });
}

/// One revolution of the paper's cam (stiff spring, permanent contact) at 1000 rpm with a step
/// of 1°: the target is 100 revolutions in under a second.
fn dynamics(c: &mut Criterion) {
    use camkin::dynamics::{AugmentedLagrangian, Simulation};
    let m = paper_mechanism(false);
    let p = paper_dynamics();
    let h = 1f64.to_radians() / m.cam().speed();
    let mut g = c.benchmark_group("dynamics");
    g.sample_size(10);
    g.bench_function("revolution_1deg", |b| {
        b.iter(|| {
            let mut sim =
                Simulation::new(&m, p, AugmentedLagrangian::default()).expect("simulation");
            for _ in 0..360 {
                black_box(sim.advance(h).expect("step"));
                black_box(sim.sample().expect("sample"));
            }
        })
    });
    g.finish();
}

/// A revolution of the single-valve train at 0.25° (1440 warm instants, three bodies, two
/// contacts): issue 45's target is under 10 ms.
fn systems(c: &mut Criterion) {
    let w = 3000.0 * std::f64::consts::TAU / 60.0;
    let (sys, _) = camkin::reference::single_valve_train(w);
    let dt = 0.25f64.to_radians() / w;
    let mut g = c.benchmark_group("system");
    g.sample_size(10);
    g.bench_function("valve_train_revolution_0.25deg", |b| {
        b.iter(|| {
            let mut sweep = sys.sweep().expect("system");
            for k in 0..1440 {
                black_box(sweep.step(f64::from(k) * dt).expect("instant"));
            }
        })
    });
    // issue 46: a simulated revolution of examples/valve-train.toml at 0.25° (target 10 ms)
    let built = camkin_bench::scenarios::valve_train_example();
    let h = 0.25f64.to_radians() / w;
    g.bench_function("valve_train_simulated_revolution_0.25deg", |b| {
        b.iter(|| {
            let mut sim =
                camkin::dynamics::SystemSimulation::new(&built.system, built.dynamics.clone())
                    .expect("simulation");
            for _ in 0..1440 {
                black_box(sim.advance(h).expect("step"));
            }
        })
    });
    g.finish();
}

criterion_group!(benches, spline, contact, followers_bench, dynamics, systems);
criterion_main!(benches);
