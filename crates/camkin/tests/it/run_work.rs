//! Issue 64: a run's estimate is within 2× of its work on every example. The work is counted,
//! not timed: the steps each run takes (accepted and rejected, each the same evaluations)
//! against the steps its estimate assumed; the seconds a step and a sample cost are measured
//! apart (docs/speed.md).

use crate::common::read_system;
use camkin::dynamics::{AugmentedLagrangian, Simulation};
use camkin::spec::BuildOptions;

fn examples() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// Every system example with `[dynamics]` planned over a revolution at 1° outputs (and at
/// 0.25°), or over its `[simulation]` where it has no driver: the steps the engine took against its estimate
/// (`SystemSimulation::steps_estimate`, what `BuiltSystem::run_work` charges).
#[test]
fn every_systems_step_estimate_is_within_twice_its_steps() {
    let mut checked = 0;
    for entry in std::fs::read_dir(examples()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        if !text.contains("[dynamics]") {
            continue;
        }
        let options = BuildOptions {
            base_dir: examples(),
            ..BuildOptions::default()
        };
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let built = read_system(&text, &name, &options).unwrap();
        // (a cam file's [dynamics] is its follower's: the command's `Simulation`, below)
        if !built.simulated {
            continue;
        }
        // a driverless system (a benchmark) over its own `[simulation]`, else a revolution at
        // two output steps
        let plans: Vec<_> = match built.timed_run {
            Some(run) if built.time_of(0.0).is_none() => {
                vec![("its duration", built.plan_timed(run).unwrap())]
            }
            _ => [1.0, 0.25]
                .iter()
                .map(|&step| ("a revolution", built.plan(1.0, step).unwrap()))
                .collect(),
        };
        for (what, (plan, mut sim)) in plans {
            let step = plan.h_out;
            let estimate = sim.steps_estimate(plan.duration(), plan.h_out);
            sim.run(plan.outputs, plan.h_out, |_| {
                std::ops::ControlFlow::Continue(())
            })
            .unwrap();
            let (accepted, rejected) = sim.steps_taken();
            let taken = (accepted + rejected) as f64;
            eprintln!(
                "{name} over {what} at {step} s: {taken} steps, {:.2} of the estimate",
                taken / estimate
            );
            assert!(
                taken <= 2.0 * estimate && estimate <= 2.0 * taken,
                "{name} over {what} at {step} s outputs: {taken} steps taken ({accepted} + {rejected} rejected), {estimate} estimated"
            );
            checked += 1;
        }
    }
    // the valve train, at both output steps, and the N-four-bar
    assert!(checked >= 3, "{checked} runs checked");
}

/// Every cam example with `[dynamics]` run as the command runs it (`Simulation`, the preset
/// system): its steps against `Simulation::steps_per_interval`, what `run_work` charges.
#[test]
fn every_cam_simulations_step_estimate_is_within_twice_its_steps() {
    let mut checked = 0;
    for name in [
        "paper-dynamics.toml",
        "eccentric-flat-dynamics.toml",
        "design-a-cam.toml",
    ] {
        let text = std::fs::read_to_string(examples().join(name)).unwrap();
        // in metres, as the dynamics computes
        let options = BuildOptions {
            base_dir: examples(),
            si: true,
            ..BuildOptions::default()
        };
        let model = camkin::spec::read_model(&text, name, &options).unwrap();
        let built = &model.preset().expect("a cam file").built;
        let params = built.dynamics.expect("[dynamics]");
        let mech = &built.mechanism;
        let mut sim = Simulation::new(mech, params, AugmentedLagrangian::default()).unwrap();
        let h = 1f64.to_radians() / mech.cam().speed();
        let estimate = 360.0 * sim.steps_per_interval(h);
        sim.run(360, h, |_| std::ops::ControlFlow::Continue(()))
            .unwrap();
        let (accepted, rejected) = sim.steps_taken().expect("the preset system");
        let taken = (accepted + rejected) as f64;
        assert!(
            taken <= 2.0 * estimate && estimate <= 2.0 * taken,
            "{name}: {taken} steps taken ({accepted} + {rejected} rejected), {estimate} estimated"
        );
        checked += 1;
    }
    assert_eq!(checked, 3);
}
