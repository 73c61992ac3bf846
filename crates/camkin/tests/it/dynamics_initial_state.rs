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
