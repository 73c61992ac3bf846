//! Issue 64, "any initial state": a simulation started with the rates its user gives, made
//! consistent with the constraints by the mass-orthogonal projection, which says how much it
//! changed them.

use camkin::dynamics::{SystemDynamicsOptions, SystemSimulation, Tolerances};
use camkin::system::{Body, BodyId, Joint, JointKind, System};
use camkin::{Point2, Vec2};

/// A free body (no joint) thrown under gravity with its frame's origin 0.1 m from its centre of
/// mass: its centre follows the parabola `x_G = x₀ + v_G t`, `y_G = y₀ + v_Gy t − ½ g t²` and it
/// turns at `ω` (`v_G = v_o + ω J ρ` from the frame's rates asked), so its frame's origin is
/// `x_G − R(ω t) c`; sampled every 10 ms over 1 s, to 1e-12 m (the pair integrates a parabola
/// exactly: the error is rounding's). Nothing constrains it, so nothing is changed.
#[test]
fn a_thrown_body_follows_its_parabola() {
    let g = 9.81;
    let c = Vec2::new(0.1, 0.0);
    let mut sys = System::new();
    sys.add_body(Body {
        name: "stone".into(),
        mass: 0.3,
        inertia: 2e-3,
        pose: camkin::body::Pose::new(Point2::new(1.0, 2.0), 0.0),
        centre_of_mass: Point2::new(c.x, c.y),
    });
    let opts = SystemDynamicsOptions {
        gravity: Vec2::new(0.0, -g),
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let (vo, w) = (Vec2::new(3.0, 4.0), 2.0);
    let change = sim.set_frame_rates(&[vo.x, vo.y, w]).unwrap();
    assert!(change < 1e-15, "{change}");
    // the centre's velocity: v_o + ω J (R(0) c)
    let vg = vo + w * Vec2::new(-c.y, c.x);
    let g0 = Vec2::new(1.0, 2.0) + c;
    let run = sim
        .run(100, 0.01, |_| std::ops::ControlFlow::Continue(()))
        .unwrap();
    let mut worst: f64 = 0.0;
    for s in &run.samples {
        let t = s.time;
        let theta = w * t;
        let centre = g0 + vg * t - Vec2::new(0.0, 0.5 * g * t * t);
        let arm = Vec2::new(
            c.x * theta.cos() - c.y * theta.sin(),
            c.x * theta.sin() + c.y * theta.cos(),
        );
        let origin = centre - arm;
        worst = worst
            .max((s.q[0] - origin.x).abs())
            .max((s.q[1] - origin.y).abs())
            .max((s.q[2] - theta).abs());
    }
    assert!(worst < 1e-12, "off the parabola by {worst:e}");
    assert_eq!(run.samples.len(), 101);
}

/// A bar of length `L` pinned at one end to the ground, asked to start with its centre moving
/// at `(0, 1)` m/s and not turning: the pin allows only a turn `ω` about it, which moves the
/// centre at `ω L/2` across the bar. The mass-orthogonal projection minimises
/// `m (ω L/2 − 1)² + I ω²`: `ω = m (L/2) / (m L²/4 + I)`, the closed form; the change it
/// reports is the largest of the rates' changes. Asked to slide along itself, it stays at rest
/// (the change is the whole speed asked).
#[test]
fn rates_the_joints_forbid_are_projected_to_the_nearest_they_allow_and_the_change_is_said() {
    let (m, i, l) = (2.0, 0.05, 0.6);
    let mut sys = System::new();
    let bar = sys.add_body(Body {
        name: "bar".into(),
        mass: m,
        inertia: i,
        pose: camkin::body::Pose::new(Point2::new(l / 2.0, 0.0), 0.0),
        centre_of_mass: Point2::origin(),
    });
    sys.add_joint(Joint {
        name: "pin".into(),
        kind: JointKind::Revolute {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            b: bar,
            at_b: Point2::new(-l / 2.0, 0.0),
        },
    });
    let opts = SystemDynamicsOptions {
        tolerances: Tolerances::default(),
        ..SystemDynamicsOptions::default()
    };
    let mut sim = SystemSimulation::new(&sys, opts.clone()).unwrap();
    let change = sim.set_frame_rates(&[0.0, 1.0, 0.0]).unwrap();
    let s = sim.sample().unwrap();
    let w = m * (l / 2.0) / (m * l * l / 4.0 + i);
    assert!((s.qd[2] - w).abs() < 1e-12 * w, "{} against {w}", s.qd[2]);
    assert!(s.qd[0].abs() < 1e-12 && (s.qd[1] - w * l / 2.0).abs() < 1e-12);
    // the largest change: the centre's speed across, or the turn's times the system's size
    // (the farthest point it names: the bar's centre and its pin, L/2 from the origin)
    let size = l / 2.0;
    let expected = (1.0 - w * l / 2.0).abs().max(w * size);
    assert!(
        (change - expected).abs() < 1e-12,
        "{change} against {expected}"
    );
    let mut sim = SystemSimulation::new(&sys, opts).unwrap();
    let change = sim.set_frame_rates(&[1.0, 0.0, 0.0]).unwrap();
    let s = sim.sample().unwrap();
    assert!(s.qd.iter().all(|v| v.abs() < 1e-12), "{:?}", s.qd);
    assert!((change - 1.0).abs() < 1e-12, "{change}");
    // three rates a body, finite
    let mut sim = SystemSimulation::new(&sys, SystemDynamicsOptions::default()).unwrap();
    assert!(sim.set_frame_rates(&[1.0, 0.0]).is_err());
    assert!(sim.set_frame_rates(&[f64::NAN, 0.0, 0.0]).is_err());
}

/// A four-bar with no driver (crank 0.2, coupler 0.5, rocker 0.4, ground 0.6 m: a Grashof
/// crank-rocker, so the crank angle `φ` is a coordinate everywhere), its links uniform bars
/// (masses 1, 2, 1.5 kg), released from rest where its file's poses assemble under gravity.
/// Written again in the
/// one coordinate, from closed forms that share nothing with the method: `B` where the circles
/// about `A` and `O₄` cross, the centres at the links' middles, `T = ½ M(φ) φ̇²` with
/// `M = Σ m |dG/dφ|² + I (dθ/dφ)²` and `V = g Σ m y_G`, so `M φ̈ + ½ M′ φ̇² + V′ = 0`
/// (derivatives by eighth-order central differences), integrated by RK4 at 0.1 ms. Over a second
/// the simulated crank angle (default tolerances) matches it to 1e-8 rad at every 10 ms
/// (measured: 5.2e-10).
#[test]
fn a_driverless_four_bar_falls_as_its_one_coordinate_equation() {
    let (a, b, c, d) = (0.2f64, 0.5f64, 0.4f64, 0.6f64);
    let (m2, m3, m4) = (1.0, 2.0, 1.5);
    let (i2, i3, i4) = (m2 * a * a / 12.0, m3 * b * b / 12.0, m4 * c * c / 12.0);
    let g = 9.81;
    let text = format!(
        r#"length_unit = "m"
[dynamics]
gravity = [0.0, -{g}]
[[body]]
name = "crank"
mass = {m2}
inertia = {i2}
centre_of_mass = [{ha}, 0.0]
angle_deg = 60.0
[[body]]
name = "coupler"
mass = {m3}
inertia = {i3}
centre_of_mass = [{hb}, 0.0]
position = [0.1, 0.1732]
angle_deg = 20.0
[[body]]
name = "rocker"
mass = {m4}
inertia = {i4}
centre_of_mass = [{hc}, 0.0]
position = [{d}, 0.0]
angle_deg = 80.0
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
"#,
        ha = a / 2.0,
        hb = b / 2.0,
        hc = c / 2.0,
    );
    let built = crate::common::read_system(&text, "four-bar.toml", &Default::default()).unwrap();
    let mut sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
    let run = sim
        .run(100, 0.01, |_| std::ops::ControlFlow::Continue(()))
        .unwrap();
    // released from rest where the file's poses assemble (the crank near 48°)
    let s0 = &run.samples[0];
    let phi0 = s0.q[2];
    assert!(s0.qd.iter().all(|v| *v == 0.0), "{:?}", s0.qd);
    // the branch of B the assembly took: above or below the line A O4
    let above = {
        let pa = Vec2::new(a * phi0.cos(), a * phi0.sin());
        let rocker = s0.q[8];
        let pb = Vec2::new(d + c * rocker.cos(), c * rocker.sin());
        let (u, v) = (Vec2::new(d, 0.0) - pa, pb - pa);
        u.x * v.y - u.y * v.x > 0.0
    };
    // the positions as functions of φ: the centres (x, y) and the angles of the three links
    let pose = |phi: f64| -> [f64; 9] {
        let pa = Vec2::new(a * phi.cos(), a * phi.sin());
        let o4 = Vec2::new(d, 0.0);
        let e = o4 - pa;
        let l = e.norm();
        // B from A: along A O4 by x, across by ±h
        let x = (b * b - c * c + l * l) / (2.0 * l);
        let h = (b * b - x * x).sqrt();
        let n = Vec2::new(-e.y, e.x) / l;
        let pb = pa + e * (x / l) + n * if above { h } else { -h };
        let (t3, t4) = (
            (pb - pa).y.atan2((pb - pa).x),
            (pb - o4).y.atan2((pb - o4).x),
        );
        let (g2, g3, g4) = (pa / 2.0, (pa + pb) / 2.0, (o4 + pb) / 2.0);
        [g2.x, g2.y, phi, g3.x, g3.y, t3, g4.x, g4.y, t4]
    };
    let masses = [m2, m2, i2, m3, m3, i3, m4, m4, i4];
    let generalised_mass = |phi: f64| -> f64 {
        (0..9)
            .map(|k| {
                let (dk, _) = crate::common::fd8(|p| pose(p)[k], phi, 1e-3);
                masses[k] * dk * dk
            })
            .sum()
    };
    let potential = |phi: f64| -> f64 {
        let p = pose(phi);
        g * (m2 * p[1] + m3 * p[4] + m4 * p[7])
    };
    let accel = |phi: f64, w: f64| -> f64 {
        let m = generalised_mass(phi);
        let (dm, _) = crate::common::fd8(generalised_mass, phi, 1e-3);
        let (dv, _) = crate::common::fd8(potential, phi, 1e-3);
        -(0.5 * dm * w * w + dv) / m
    };
    let (mut phi, mut w, h) = (phi0, 0.0, 1e-4);
    let mut worst: f64 = 0.0;
    for (k, s) in run.samples.iter().enumerate().skip(1) {
        for _ in 0..100 {
            let (k1p, k1w) = (w, accel(phi, w));
            let (k2p, k2w) = (
                w + 0.5 * h * k1w,
                accel(phi + 0.5 * h * k1p, w + 0.5 * h * k1w),
            );
            let (k3p, k3w) = (
                w + 0.5 * h * k2w,
                accel(phi + 0.5 * h * k2p, w + 0.5 * h * k2w),
            );
            let (k4p, k4w) = (w + h * k3w, accel(phi + h * k3p, w + h * k3w));
            phi += h / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
            w += h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
        }
        assert!((s.time - 0.01 * k as f64).abs() < 1e-12);
        worst = worst.max((s.q[2] - phi).abs());
    }
    assert!(
        worst < 1e-8,
        "the crank angle is {worst:e} rad off the one-coordinate equation"
    );
}

/// A disk of radius `r` (mm) resting on a floor (a line on the ground, material below), gravity
/// down, with the starting state of `body` (TOML keys of its `[[body]]`) and of `contact`.
fn disk_on_floor(body: &str, contact: &str) -> camkin::spec::BuiltSystem {
    let text = format!(
        r#"length_unit = "mm"
[dynamics]
gravity = [0.0, -9.81]
[[body]]
name = "disk"
mass = 0.5
inertia = 2.5e-5
{body}
[[contact]]
name = "floor"
bodies = ["ground", "disk"]
curve_a = {{ kind = "line", anchor = [0.0, 0.0], direction = [-1.0, 0.0] }}
curve_b = {{ kind = "circle", center = [0.0, 0.0], radius = 10.0 }}
{contact}
"#
    );
    crate::common::read_system(&text, "disk.toml", &Default::default()).unwrap()
}

/// A disk resting on a floor, thrown straight up at `v` by its file's `velocity`: the contact
/// opens at the start (the rates part it, a lift-off at t = 0, said in the report), the disk
/// rises and falls as `y = r + v t − g t²/2` (to 1e-9 mm every 10 ms), and lands at `2v/g` (the
/// impact's instant to 1e-9 s, its approach speed `v` to 1e-9 of it). Thrown along the floor
/// instead it stays on it and slides (no friction) at its speed: `x = v t`, the contact force
/// its weight.
#[test]
fn a_body_thrown_off_a_surface_it_rests_on_leaves_it_and_one_thrown_along_slides() {
    let (g, r, v) = (9.81e3, 10.0, 500.0); // mm/s², mm, mm/s
    let built = disk_on_floor(&format!("position = [0.0, {r}]\nvelocity = [0.0, {v}]"), "");
    let mut sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
    let report = sim.start_report().clone();
    assert_eq!(report.opened, vec![0], "{report:?}");
    assert_eq!(report.closed, vec![false]);
    assert_eq!(report.rates[0], [0.0, v, 0.0]);
    assert_eq!(report.largest_rate_change(), Some((0, 0.0)));
    let land = 2.0 * v / g;
    let run = sim
        .run(15, 0.01, |_| std::ops::ControlFlow::Continue(()))
        .unwrap();
    let kinds: Vec<_> = run.events.iter().map(|e| (e.kind, e.time)).collect();
    assert_eq!(run.events[0].kind, camkin::dynamics::EventKind::LiftOff);
    assert_eq!(run.events[0].time, 0.0);
    let impact = run
        .events
        .iter()
        .find(|e| e.kind == camkin::dynamics::EventKind::Impact)
        .unwrap_or_else(|| panic!("no impact: {kinds:?}"));
    assert!(
        (impact.time - land).abs() < 1e-9,
        "{} against {land}",
        impact.time
    );
    assert!(
        (impact.approach - v).abs() < 1e-9 * v,
        "{}",
        impact.approach
    );
    for s in run.samples.iter().filter(|s| s.time < land) {
        let t = s.time;
        let y = r + v * t - 0.5 * g * t * t;
        assert!((s.q[1] - y).abs() < 1e-9, "t = {t}: {} against {y}", s.q[1]);
    }
    // no rebound (restitution 0): it rests on the floor after
    let last = run.samples.last().unwrap();
    assert!(
        (last.q[1] - r).abs() < 1e-9 && last.in_contact[0],
        "{last:?}"
    );

    let built = disk_on_floor(&format!("position = [0.0, {r}]\nvelocity = [{v}, 0.0]"), "");
    let mut sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
    assert!(sim.start_report().opened.is_empty());
    let run = sim
        .run(10, 0.01, |_| std::ops::ControlFlow::Continue(()))
        .unwrap();
    assert!(run.events.is_empty(), "{:?}", run.events);
    for s in &run.samples {
        assert!((s.q[0] - v * s.time).abs() < 1e-9 && (s.q[1] - r).abs() < 1e-9);
        assert!(
            (s.contact_forces[0] - 0.5 * 9.81).abs() < 1e-9,
            "{}",
            s.contact_forces[0]
        );
    }
}

/// A disk 0.5 mm above the floor (beyond the 1e-3 of the size within which a contact starts
/// closed): without `starts_closed` it falls and lands after `√(2 d/g)` (to 1e-9 s); with
/// `starts_closed = true` the start assembles it onto the floor, moving it down by 0.5 mm (the
/// report's distance, to 1e-12 mm) and not turning it.
#[test]
fn a_contact_marked_closed_is_assembled_and_the_distance_moved_is_reported() {
    let (g, r, d) = (9.81e3f64, 10.0, 0.5);
    let pose = format!("position = [3.0, {}]", r + d);
    let built = disk_on_floor(&pose, "");
    let mut sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
    assert_eq!(sim.start_report().closed, vec![false]);
    assert!(sim.start_report().moved[0] == 0.0);
    let run = sim
        .run(5, 0.005, |_| std::ops::ControlFlow::Continue(()))
        .unwrap();
    let land = (2.0 * d / g).sqrt();
    let impact = run.events.first().expect("an impact");
    assert_eq!(impact.kind, camkin::dynamics::EventKind::Impact);
    assert!(
        (impact.time - land).abs() < 1e-9,
        "{} against {land}",
        impact.time
    );

    let built = disk_on_floor(&pose, "starts_closed = true");
    let sim = SystemSimulation::new(&built.system, built.dynamics.clone()).unwrap();
    let report = sim.start_report();
    assert_eq!(report.closed, vec![true]);
    assert!((report.moved[0] - d).abs() < 1e-12, "{:?}", report.moved);
    assert!(report.turned[0].abs() < 1e-15);
    let s = sim.sample().unwrap();
    assert!(
        (s.q[0] - 3.0).abs() < 1e-12 && (s.q[1] - r).abs() < 1e-12,
        "{:?}",
        s.q
    );
    let text = report.describe(&built.system, "mm").join("\n");
    assert!(text.contains("\"disk\" moved 0.5 mm"), "{text}");
}

/// The pinned bar of the test above started through the options. Given its centre's upward
/// speed alone (`v_y = 1` m/s), its other rates are free: the start finds them so that the pin
/// holds (`v_x = 0`, `ω = v_y/(L/2)`) and keeps the speed given, changing nothing it was
/// given. Given all three (`(0, 1, 0)`: not turning), they conflict with the pin, and the
/// nearest in the kinetic energy's metric is the closed form `ω = m (L/2) / (m L²/4 + I)`;
/// the report gives both and the largest change.
#[test]
fn the_start_finds_the_rates_not_given_and_reports_a_change_to_those_given() {
    let (m, i, l) = (2.0, 0.05, 0.6);
    let mut sys = System::new();
    let bar = sys.add_body(Body {
        name: "bar".into(),
        mass: m,
        inertia: i,
        pose: camkin::body::Pose::new(Point2::new(l / 2.0, 0.0), 0.0),
        centre_of_mass: Point2::origin(),
    });
    sys.add_joint(Joint {
        name: "pin".into(),
        kind: JointKind::Revolute {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            b: bar,
            at_b: Point2::new(-l / 2.0, 0.0),
        },
    });
    let start = |rates: [Option<f64>; 3]| {
        let opts = SystemDynamicsOptions {
            initial_rates: vec![rates],
            ..SystemDynamicsOptions::default()
        };
        SystemSimulation::new(&sys, opts)
            .unwrap()
            .start_report()
            .clone()
    };
    let report = start([None, Some(1.0), None]);
    let [vx, vy, wz] = report.rates[0];
    assert!(vx.abs() < 1e-15 && (vy - 1.0).abs() < 1e-15, "{report:?}");
    assert!((wz - 1.0 / (l / 2.0)).abs() < 1e-14, "{wz}");
    assert!(report.largest_rate_change().unwrap().1 < 1e-14);
    assert!(report.describe(&sys, "m").is_empty(), "{report:?}");

    let report = start([Some(0.0), Some(1.0), Some(0.0)]);
    let w = m * (l / 2.0) / (m * l * l / 4.0 + i);
    assert_eq!(report.asked_rates, vec![[Some(0.0), Some(1.0), Some(0.0)]]);
    let [vx, vy, wz] = report.rates[0];
    assert!(vx.abs() < 1e-12 && (vy - w * l / 2.0).abs() < 1e-12 && (wz - w).abs() < 1e-12);
    let (body, change) = report.largest_rate_change().unwrap();
    let expected = (1.0 - w * l / 2.0).abs().max(w * report.size);
    assert_eq!(body, 0);
    assert!(
        (change - expected).abs() < 1e-12,
        "{change} against {expected}"
    );
    let text = report.describe(&sys, "m").join("\n");
    assert!(text.contains("not all ones the joints"), "{text}");
}
