//! Issue 45: system files. The valve train written as a file builds the system the library's
//! reference builds, and gives its answers to the bit; bad files are refused naming the element
//! by its table, index and name, at its key's line and column.

use camkin::spec::text::{is_system, TextError};
use camkin::spec::{read_model, BuildOptions, Solver};
use std::borrow::Cow;
use std::f64::consts::TAU;

const VALVE_TRAIN: &str = include_str!("../../../../examples/valve-train-kinematics.toml");

fn build(text: &str) -> Result<camkin::spec::BuiltSystem, TextError> {
    read_model(text, "s.toml", &BuildOptions::default())
        .and_then(camkin::spec::ModelFile::into_system)
}

#[test]
fn the_valve_train_file_is_the_reference_valve_train() {
    assert!(is_system(VALVE_TRAIN));
    assert!(!is_system(include_str!("../../../../examples/paper.toml")));
    let built = build(VALVE_TRAIN).unwrap();
    let w = 3000.0 * TAU / 60.0;
    let (reference, _) = camkin::reference::single_valve_train(w);
    let (mut a, mut b) = (built.system.sweep().unwrap(), reference.sweep().unwrap());
    for k in 0..90 {
        let t = f64::from(k) * 4f64.to_radians() / w;
        let (sa, sb) = (a.step(t).unwrap(), b.step(t).unwrap());
        for (x, y) in sa.bodies.iter().zip(&sb.bodies) {
            // the starting guesses differ (the file's finger starts at 1°, the reference's at
            // 0.02 rad): the same assembly, to the last bits
            assert!(
                (x.pose.origin - y.pose.origin).norm() <= 1e-12 * 100.0,
                "{k}"
            );
            assert!((x.pose.angle - y.pose.angle).abs() <= 1e-12, "{k}");
            assert!(
                (x.acceleration - y.acceleration).norm() <= 1e-9 * (1.0 + y.acceleration.norm()),
                "{k}"
            );
        }
    }
}

/// A bad file: what it is, its text, what its message must hold, and the `k`-th line holding a
/// text, where the error must be placed.
type Case<'a> = (&'a str, String, &'a [&'a str], (&'a str, usize));

/// Each bad file: its error message holds every needle, and the place is the line given.
#[test]
fn bad_system_files_name_the_element_and_its_line() {
    // the line of the `k`-th (from 1) line of `text` that holds `needle`
    let line = |text: &str, needle: &str, k: usize| {
        text.lines()
            .enumerate()
            .filter(|(_, l)| l.contains(needle))
            .nth(k - 1)
            .map_or(0, |(i, _)| i + 1)
    };
    let cases: [Case<'_>; 9] = [
        (
            "a joint naming a missing body",
            VALVE_TRAIN.replace(
                "bodies = [\"ground\", \"finger\"]",
                "bodies = [\"ground\", \"fingr\"]",
            ),
            &["joint[1].bodies", "\"fingr\"", "a body of this file", "finger"],
            ("\"fingr\"", 1),
        ),
        (
            "two drivers on one coordinate",
            VALVE_TRAIN.replace(
                "speed_rpm = 3000.0\n",
                "speed_rpm = 3000.0\n\n[[driver]]\nname = \"again\"\nbody = \"camshaft\"\ncoordinate = \"angle\"\nspeed_rpm = 10.0\n",
            ),
            &["driver[1].coordinate", "driven already", "\"crankshaft\""],
            ("coordinate = \"angle\"", 2),
        ),
        (
            "an unknown joint kind",
            VALVE_TRAIN.replace("kind = \"prismatic\"", "kind = \"slider\""),
            &["joint[2].kind", "\"slider\"", "revolute, prismatic, fixed"],
            ("\"slider\"", 1),
        ),
        (
            "a key the joint's kind does not take (each kind's keys: spec::JointKindName)",
            VALVE_TRAIN.replacen("kind = \"revolute\"\n", "kind = \"revolute\"\naxis = [1.0, 0.0]\n", 1),
            &["joint[0].axis", "a revolute joint takes no"],
            ("axis = [1.0, 0.0]", 1),
        ),
        (
            "an unknown coordinate",
            VALVE_TRAIN.replace("coordinate = \"angle\"", "coordinate = \"z\""),
            &["driver[0].coordinate", "\"z\"", "angle, x, y"],
            ("coordinate = \"z\"", 1),
        ),
        (
            "an angle driven at a length's speed",
            VALVE_TRAIN.replace("speed_rpm = 3000.0\n", "speed_rpm = 3000.0\nspeed = 1.0\n"),
            &["driver[0].speed", "takes speed_rpm, not speed"],
            ("speed = 1.0", 1),
        ),
        (
            "a contact's curve with a bad radius",
            VALVE_TRAIN.replace("radius = 6.0", "radius = -6.0"),
            &["contact[0].curve_b.radius", "-6"],
            ("radius = -6.0", 1),
        ),
        (
            "a body named twice",
            VALVE_TRAIN.replace("name = \"valve\"\n", "name = \"finger\"\n"),
            &["body[2].name", "body[1] has this name already"],
            ("name = \"finger\"", 2),
        ),
        (
            "no driver: a degree of freedom left free",
            VALVE_TRAIN.replace("[[driver]]", "[[drive]]"),
            &["unknown field `drive`"],
            ("[[drive]]", 1),
        ),
    ];
    for (what, text, needles, (at, nth)) in cases {
        let e = build(&text).map(|_| ()).unwrap_err();
        for n in needles {
            assert!(e.message.contains(n), "{what}: {}", e.message);
        }
        assert_eq!(
            e.at.map(|a| a.0),
            Some(line(&text, at, nth)),
            "{what}: {}",
            e.message
        );
    }
    // no driver at all: 9 coordinates, 8 rows
    let text = VALVE_TRAIN.replace(
        "[[driver]]\nname = \"crankshaft\"\nbody = \"camshaft\"\ncoordinate = \"angle\"\nspeed_rpm = 3000.0\n",
        "",
    );
    let e = build(&text).map(|_| ()).unwrap_err();
    assert!(
        e.message.contains("9 coordinates") && e.message.contains("8 constraint rows"),
        "{}",
        e.message
    );
    // a driver on a coordinate a joint already fixes (the camshaft's x): as many rows as
    // coordinates, but they do not determine the motion; refused when analysed, naming the rows
    let text = VALVE_TRAIN.replace(
        "coordinate = \"angle\"\nspeed_rpm = 3000.0\n",
        "coordinate = \"x\"\n",
    );
    let b = build(&text).unwrap();
    let e = b.system.analyze(0.0).unwrap_err().to_string();
    for n in [
        "singular",
        "driver \"crankshaft\"",
        "joint \"camshaft bearing\" (x)",
    ] {
        assert!(e.contains(n), "{e}");
    }
}

const CAM_ROCKER_SLIDER: &str = include_str!("../../../../examples/cam-rocker-slider.toml");

/// A `kind = "motion"` curve on a body is a cam synthesised for the follower the contact
/// names (`motion_follower`): without one, with one and no program, or with a key the
/// follower's rules refuse (checked by the program's synthesis too), the file is refused at the
/// key written.
#[test]
fn a_motion_program_on_a_body_names_its_follower() {
    let line = |text: &str, needle: &str| {
        text.lines()
            .position(|l| l.contains(needle))
            .map_or(0, |i| i + 1)
    };
    let no_follower: String = CAM_ROCKER_SLIDER
        .lines()
        .filter(|l| !l.starts_with("motion_follower"))
        .collect::<Vec<_>>()
        .join("\n");
    let cases: [(&str, String, &[&str], &str); 4] = [
        (
            "a program with no follower",
            no_follower.clone(),
            &["contact[0]", "motion_follower = {"],
            "[[contact]]",
        ),
        (
            "a follower's negative arm",
            CAM_ROCKER_SLIDER.replace("arm_length = 60.0", "arm_length = -60.0"),
            &["contact[0].motion_follower.arm_length", "-60"],
            "arm_length = -60.0",
        ),
        (
            "a roller that cannot rest on the base circle (found by the synthesis)",
            CAM_ROCKER_SLIDER.replace("pivot = [-60.0, 40.0], arm", "pivot = [-60.0, 140.0], arm"),
            &["contact[0].motion_follower.arm_length", "base circle"],
            "pivot = [-60.0, 140.0], arm",
        ),
        (
            "a program's bad segment",
            CAM_ROCKER_SLIDER.replace("law = \"cycloidal\"", "law = \"cycloid\""),
            &["contact[0].curve_a.segments[0].law", "\"cycloid\""],
            "law = \"cycloid\"",
        ),
    ];
    for (what, text, needles, at) in cases {
        let e = build(&text).map(|_| ()).unwrap_err();
        for n in needles {
            assert!(e.message.contains(n), "{what}: {}", e.message);
        }
        assert_eq!(
            e.at.map(|a| a.0),
            Some(line(&text, at)),
            "{what}: {}",
            e.message
        );
    }
    // a follower beside a contact of two circles: no program to write it for
    let text = format!(
        "{}\nmotion_follower = {{ kind = \"translating-roller\", roller_radius = 8.0 }}\n",
        no_follower.replace(
            "kind = \"motion\", base_radius = 30.0, segments = [\n    { law = \"cycloidal\", rise = 15.0, degrees = 120 },\n    { law = \"dwell\", degrees = 60 },\n    { law = \"3-4-5\", rise = -15.0, degrees = 120 },\n    { law = \"dwell\", degrees = 60 },\n] }",
            "kind = \"circle\", center = [0.0, 0.0], radius = 30.0 }"
        )
    );
    let e = build(&text).map(|_| ()).unwrap_err();
    assert!(
        e.message.contains("contact[0].motion_follower") && e.message.contains("neither curve"),
        "{}",
        e.message
    );
    assert_eq!(e.at.map(|a| a.0), Some(line(&text, "motion_follower = {")));
}

/// Instants asked far apart and out of order give the assembly a fine sweep reaches (the one
/// continuously connected to the start): every system example at driver angles 0, 90, 200, 45,
/// 330 and 10°, against a sweep in 0.5° steps to each. Regression: the valve train asked at 0
/// and 90° converged on another assembly (the finger 68° up, where it is 15.6°), with only
/// the contact's jump flag to say so.
#[test]
fn instants_far_apart_are_the_assembly_a_fine_sweep_reaches() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut checked = 0;
    for e in std::fs::read_dir(&dir).unwrap() {
        let path = e.unwrap().path();
        if path.extension().and_then(|x| x.to_str()) != Some("toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        // the kinematic examples (a file with [dynamics] is simulated: its forces move its free
        // degrees of freedom)
        if !is_system(&text) || text.contains("[dynamics]") {
            continue;
        }
        let built = build(&text).unwrap();
        let sys = &built.system;
        let size = sys.size();
        let mut sparse = sys.sweep().unwrap();
        for deg in [0.0, 90.0, 200.0, 45.0, 330.0, 10.0] {
            let t = built.time_of(f64::to_radians(deg)).unwrap();
            let s = sparse.step(t).unwrap();
            let mut fine = sys.sweep().unwrap();
            let steps = (deg / 0.5) as usize;
            let mut r = fine.step(0.0).unwrap();
            for k in 1..=steps {
                let a = deg * k as f64 / steps as f64;
                r = fine.step(built.time_of(a.to_radians()).unwrap()).unwrap();
            }
            for (x, y) in s.bodies.iter().zip(&r.bodies) {
                let d = (x.pose.origin - y.pose.origin).norm()
                    + size * (x.pose.angle - y.pose.angle).abs();
                assert!(
                    d <= 1e-10 * size,
                    "{}: at {deg}°: {d:e}: {:?} {:?}",
                    path.display(),
                    x.pose,
                    y.pose
                );
            }
            checked += 1;
        }
    }
    assert!(checked >= 30, "{checked}");
}

/// Issue 63: an instant many revolutions away (the valve train's kinematics at 1e7° of its
/// cam) is the instant a whole number of periods nearer the start, each body turned by whole
/// turns: the same poses, rates and accelerations as a half-degree sweep from the start to the
/// angle within the revolution (it was reported as a dead point it does not have, or ran for
/// minutes); a system that does not repeat within 8 revolutions (a gear train of 20, 31 and 42
/// teeth) is refused that far away, saying why, in about a second.
#[test]
fn an_instant_many_revolutions_away_is_the_one_its_period_nearer() {
    let built = build(include_str!(
        "../../../../examples/valve-train-kinematics.toml"
    ))
    .unwrap();
    let sys = &built.system;
    let size = sys.size();
    for deg in [1e7, -1e7, 1e8 + 12.5] {
        let far = sys
            .analyze(built.time_of(f64::to_radians(deg)).unwrap())
            .unwrap();
        let within = deg.rem_euclid(360.0);
        let mut fine = sys.sweep().unwrap();
        let steps = (within / 0.5).ceil() as usize;
        let mut near = fine.step(0.0).unwrap();
        for k in 1..=steps {
            let a = within * k as f64 / steps as f64;
            near = fine.step(built.time_of(a.to_radians()).unwrap()).unwrap();
        }
        for (x, y) in far.bodies.iter().zip(&near.bodies) {
            assert!(
                (x.pose.origin - y.pose.origin).norm() <= 1e-9 * size,
                "{deg}°"
            );
            let turned = x.pose.angle - y.pose.angle;
            let whole = (turned / TAU).round() * TAU;
            assert!((turned - whole).abs() <= 1e-9, "{deg}°: {turned}");
            let w = y.omega.abs().max(1.0);
            assert!((x.omega - y.omega).abs() <= 1e-9 * w, "{deg}°");
            let a = y.alpha.abs().max(1.0);
            assert!(
                (x.alpha - y.alpha).abs() <= 1e-7 * a,
                "{deg}°: {} {}",
                x.alpha,
                y.alpha
            );
        }
    }
    let gears = build(include_str!("../../../../examples/gear-train.toml")).unwrap();
    let t0 = std::time::Instant::now();
    let e = gears
        .system
        .analyze(gears.time_of(f64::to_radians(1e6)).unwrap())
        .unwrap_err();
    assert!(
        matches!(e, camkin::system::SystemError::TooFar { .. }),
        "{e}"
    );
    assert!(
        e.to_string()
            .contains("does not repeat within 8 revolutions"),
        "{e}"
    );
    eprintln!("refused in {:?}", t0.elapsed());
}

/// Issue 63: a first driver with the documented `acceleration` is swept over its angle (it was
/// refused): at each angle θ the instant is the first root of `θ = ω t + α t²/2`, and the driven
/// body's angle, rate and acceleration are θ, `ω + α t` and α there.
#[test]
fn an_accelerating_first_driver_is_swept_over_its_angle() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/valve-train-kinematics.toml"),
    )
    .unwrap();
    let text = text.replace(
        "speed_rpm = 3000.0\n",
        "speed_rpm = 3000.0\nacceleration = 36000.0\n",
    );
    assert!(text.contains("acceleration = 36000.0"));
    let built = build(&text).unwrap();
    let cam = built
        .system
        .bodies()
        .iter()
        .position(|b| b.name == "camshaft")
        .unwrap();
    let (w, a) = (3000.0 * TAU / 60.0, 36000f64.to_radians());
    let times = built.times(&[0.0, 90.0, 400.0, 7200.0]).unwrap();
    let mut sweep = built.system.sweep().unwrap();
    for (deg, t) in [0.0, 90.0, 400.0, 7200.0].into_iter().zip(times) {
        let th = f64::to_radians(deg);
        let closed = (-w + (w * w + 2.0 * a * th).sqrt()) / a;
        assert!(
            (t - closed).abs() <= 1e-12 * closed.max(1e-3),
            "{deg}°: {t} vs {closed}"
        );
        let s = sweep.step(t).unwrap();
        let b = &s.bodies[cam];
        assert!((b.pose.angle - th).abs() <= 1e-9 * th.max(1.0), "{deg}°");
        assert!((b.omega - (w + a * t)).abs() <= 1e-9 * w, "{deg}°");
        assert!((b.alpha - a).abs() <= 1e-9 * a, "{deg}°");
    }
}

/// Issue 63: a prismatic joint's axis is a direction of any length — `[0, 1e-300]` is the y axis
/// (its norm's square underflows; it hung) — and the valve train's kinematics with it are the
/// example's to 1e-12 of the size.
#[test]
fn a_tiny_prismatic_axis_is_its_direction() {
    let text = include_str!("../../../../examples/valve-train-kinematics.toml");
    let tiny = text.replace("axis = [0.0, 1.0]", "axis = [0.0, 1e-300]");
    assert_ne!(tiny, text);
    let (a, b) = (build(text).unwrap(), build(&tiny).unwrap());
    let size = a.system.size();
    for deg in [0.0, 30.0, 100.0] {
        let t = a.time_of(f64::to_radians(deg)).unwrap();
        let (x, y) = (a.system.analyze(t).unwrap(), b.system.analyze(t).unwrap());
        for (p, q) in x.bodies.iter().zip(&y.bodies) {
            assert!(
                (p.pose.origin - q.pose.origin).norm() <= 1e-12 * size,
                "{deg}°"
            );
            assert!((p.pose.angle - q.pose.angle).abs() <= 1e-12, "{deg}°");
        }
    }
}

const CAM_FILE: &str = include_str!("../../../../examples/paper.toml");
const SYSTEM_FILE: &str = include_str!("../../../../examples/cam-four-bar.toml");

/// A cam-follower file is answered by the cam solver and a system file by the general one,
/// whatever else they hold; the cam file as a system is swept over its cam angle, and a
/// system is built in its file's unit even when a preset would be built in metres.
#[test]
fn the_model_picks_its_solver() {
    let options = BuildOptions::default();
    let cam = read_model(CAM_FILE, "paper.toml", &options).unwrap();
    assert!(matches!(cam.solver(), Solver::Cam(_)));
    assert!(cam.preset().is_some());
    let as_system = cam.to_system().unwrap();
    assert_eq!(as_system.angle_name(), "cam angle");
    assert_eq!(as_system.length_unit, camkin::spec::LengthUnit::Cm);

    let si = BuildOptions {
        si: true,
        ..options.clone()
    };
    let system = read_model(SYSTEM_FILE, "cam-four-bar.toml", &si).unwrap();
    let Solver::General(built) = system.solver() else {
        panic!("a system file is answered by the general solver")
    };
    let plain = read_model(SYSTEM_FILE, "cam-four-bar.toml", &options).unwrap();
    let Solver::General(plain) = plain.solver() else {
        panic!("a system file is answered by the general solver")
    };
    assert_eq!(
        built.dynamics.metres_per_unit,
        plain.dynamics.metres_per_unit
    );
    assert!(built.dynamics.metres_per_unit < 1.0);
    assert!(system.preset().is_none());
    assert!(matches!(system.to_system(), Ok(Cow::Borrowed(_))));

    let cam_si = read_model(CAM_FILE, "paper.toml", &si).unwrap();
    assert!(cam_si.preset().unwrap().built.si);
}

/// A system file's starting state and run in time (issue 64): `[simulation]`'s settings,
/// a body's `velocity` and `angular_velocity`, and `[simulation]` without `[dynamics]` are refused
/// at the key written, naming it and the value; good ones reach the options (the velocity in
/// the file's unit, the angular velocity in rad/s) and the run.
#[test]
fn a_starting_state_and_a_run_in_time_are_read_and_refused_by_key() {
    let pendulum = |extra: &str, body: &str| {
        format!(
            "length_unit = \"mm\"\n[dynamics]\ngravity = [0.0, -9.81]\n{extra}\n[[body]]\nname = \"bob\"\nposition = [100.0, 0.0]\n{body}\n[[joint]]\nname = \"pivot\"\nkind = \"revolute\"\nbodies = [\"ground\", \"bob\"]\nat = [[0.0, 0.0], [-100.0, 0.0]]\n"
        )
    };
    let cases = [
        (
            pendulum("[simulation]\nduration = -1.0", ""),
            &["simulation.duration", "-1", "in (0, 1000000] s"][..],
            "duration = -1.0",
        ),
        (
            pendulum("[simulation]\nduration = 1.0\ninterval = 2.0", ""),
            &["simulation.interval", "2", "(0, duration]"][..],
            "interval = 2.0",
        ),
        (
            pendulum("[simulation]\ninterval = 2.0", ""),
            &["duration"][..],
            "[simulation]",
        ),
        (
            pendulum("", "velocity = [1e300, 0.0]"),
            &["body[0].velocity", "1e300"][..],
            "velocity = [1e300, 0.0]",
        ),
        (
            pendulum("", "angular_velocity = nan"),
            &["body[0].angular_velocity", "NaN"][..],
            "angular_velocity = nan",
        ),
        (
            pendulum("", "angular_velocity = 1.0").replace(
                "[dynamics]\ngravity = [0.0, -9.81]\n",
                "[simulation]\nduration = 1.0\n",
            ),
            &["simulation", "[dynamics]"][..],
            "[simulation]",
        ),
    ];
    for (text, needles, at) in cases {
        let e = build(&text).map(|_| ()).unwrap_err();
        for n in needles {
            assert!(e.message.contains(n), "{text}\n{}", e.message);
        }
        let line = text.lines().position(|l| l.contains(at)).map(|i| i + 1);
        assert_eq!(e.at.map(|a| a.0), line, "{}", e.message);
    }
    let built = build(&pendulum(
        "[simulation]\nduration = 0.5\ninterval = 0.01",
        "velocity = [0.0, 250.0]\nangular_velocity = 2.5",
    ))
    .unwrap();
    assert_eq!(
        built.dynamics.initial_rates,
        vec![[Some(0.0), Some(250.0), Some(2.5)]]
    );
    let run = built.timed_run.unwrap();
    assert_eq!((run.duration, run.interval), (0.5, 0.01));
    // the bob at 100 mm asked to move at 250 mm/s across the bar, turning at 2.5 rad/s: the pin
    // at 100 mm behind its frame's origin moves at ω·100 = 250 mm/s with the origin's 250 mm/s
    // less ω·100: consistent, unchanged
    let sim =
        camkin::dynamics::SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
    let r = sim.start_report();
    let [vx, vy, w] = r.rates[0];
    assert!(
        vx.abs() < 1e-9 && (vy - 250.0).abs() < 1e-9 && (w - 2.5).abs() < 1e-12,
        "{r:?}"
    );
}

/// A coil spring's `damping_ratio` is read from 0 to 1 (a damper beside each segment), refused
/// outside it and on a massless spring (which has no surge mode to damp), each refusal naming
/// the key and its line.
#[test]
fn a_coil_springs_damping_ratio_is_read_and_refused_by_key() {
    let coil = |masses: usize, extra: &str| {
        format!(
            "length_unit = \"mm\"\n[dynamics]\n[[body]]\nname = \"valve\"\nmass = 0.05\ninertia = 1e-6\nposition = [0.0, 40.0]\n[[joint]]\nname = \"guide\"\nkind = \"prismatic\"\nbodies = [\"ground\", \"valve\"]\nat = [[0.0, 0.0], [0.0, 0.0]]\naxis = [0.0, 1.0]\n[[coil_spring]]\nname = \"spring\"\nbodies = [\"ground\", \"valve\"]\nat = [[0.0, 0.0], [0.0, 0.0]]\nstiffness = 30.0\nfree_length = 48.0\nmass = 0.02\nmasses = {masses}\n{extra}\n"
        )
    };
    let built = build(&coil(4, "damping_ratio = 0.05")).unwrap();
    let dampers = built
        .system
        .forces()
        .iter()
        .filter(|f| matches!(f.kind, camkin::system::ForceKind::Damper { .. }))
        .count();
    assert_eq!(dampers, 5, "one beside each of the 5 segments");
    assert_eq!(built.coil_springs[0].damping_ratio, 0.05);
    let undamped = build(&coil(4, "")).unwrap();
    assert_eq!(undamped.system.forces().len(), 5, "segments only");
    for (text, needles) in [
        (
            coil(4, "damping_ratio = 1.5"),
            &["coil_spring[0].damping_ratio", "1.5"][..],
        ),
        (
            coil(4, "damping_ratio = -0.1"),
            &["coil_spring[0].damping_ratio", "-0.1"][..],
        ),
        (
            coil(0, "damping_ratio = 0.05"),
            &["coil_spring[0].damping_ratio", "lumped masses"][..],
        ),
    ] {
        let e = build(&text).map(|_| ()).unwrap_err();
        for n in needles {
            assert!(e.message.contains(n), "{text}\n{}", e.message);
        }
        let line = text
            .lines()
            .position(|l| l.starts_with("damping_ratio"))
            .map(|i| i + 1);
        assert_eq!(e.at.map(|a| a.0), line, "{}", e.message);
    }
}
