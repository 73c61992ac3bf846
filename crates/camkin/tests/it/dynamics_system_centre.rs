//! Issue 46: bodies whose centre of mass is away from their frame's origin, against closed forms
//! that share no formula with the simulation (which integrates the centres' coordinates and
//! carries the rows and forces over): a compound pendulum released level reaches the bottom at a
//! quarter of its exact period (the arithmetic–geometric mean) and strikes a stop there at
//! `L √(2 m g d / I_O)`, `I_O = I_G + m d²`; a crank with angular acceleration under gravity
//! needs `I_O α + m g d cos θ`; a slide driven along x needs `m ẍ` whatever its centre. Each is
//! run with the body's frame at the pivot, at the centre (the centre at the frame's origin) and
//! anywhere else, turned: the answers are the same.

use camkin::curve::{Line, PointCurve};
use camkin::dynamics::{EventKind, SystemDynamicsOptions, SystemSimulation};
use camkin::geometry::Rotation;
use camkin::system::{
    Body, BodyId, Contact, Coordinate, Driver, DriverLaw, Joint, JointKind, System,
};
use camkin::{Point2, Vec2};
use std::sync::Arc;

const M: f64 = 0.3;
const I_G: f64 = 2e-3;
const D: f64 = 0.1;
const L: f64 = 0.15;
const G: f64 = 9.81;

/// The body's frames tried: `(t, φ)` puts a point `p_N` of the natural frame (pivot at the
/// origin, centre at `(D, 0)`) at `R(φ) p_F + t` of the body's frame `F`.
const FRAMES: [([f64; 2], f64); 3] = [([0.0, 0.0], 0.0), ([D, 0.0], 0.0), ([0.07, -0.03], 0.4)];

/// A natural-frame point in the body's frame `(t, φ)`.
fn in_frame(p: [f64; 2], (t, phi): ([f64; 2], f64)) -> Point2 {
    Point2::from(Rotation::new(-phi) * Vec2::new(p[0] - t[0], p[1] - t[1]))
}

/// A bar pinned to the ground at the world's origin, its natural frame level at the start.
fn bar(sys: &mut System, frame: ([f64; 2], f64)) -> BodyId {
    let (t, phi) = frame;
    let bar = sys.add_body(Body {
        name: "bar".into(),
        mass: M,
        inertia: I_G,
        pose: camkin::body::Pose::new(Point2::new(t[0], t[1]), phi),
        centre_of_mass: in_frame([D, 0.0], frame),
    });
    sys.add_joint(Joint {
        name: "pivot".into(),
        kind: JointKind::Revolute {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            b: bar,
            at_b: in_frame([0.0, 0.0], frame),
        },
    });
    bar
}

/// Arithmetic–geometric mean.
fn agm(mut a: f64, mut b: f64) -> f64 {
    // quadratic convergence: 8 rounds are more than double precision needs
    for _ in 0..8 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    a
}

#[test]
fn a_compound_pendulum_strikes_its_stop_when_and_as_fast_as_the_closed_form_says() {
    let i_o = I_G + M * D * D;
    // released at 90° from the bottom: a quarter period, K(sin 45°) √(I_O / m g d)
    let quarter = std::f64::consts::FRAC_PI_2 / agm(1.0, std::f64::consts::FRAC_PI_4.cos())
        * (i_o / (M * G * D)).sqrt();
    let approach = L * (2.0 * M * G * D / i_o).sqrt();
    for frame in FRAMES {
        let mut sys = System::new();
        let bar = bar(&mut sys, frame);
        // the stop: the ground's line x = 0, material on −x, struck by the bar's point at L
        sys.add_contact(Contact {
            name: "stop".into(),
            a: BodyId::GROUND,
            curve_a: Arc::new(Line::new(Point2::origin(), Vec2::y()).unwrap()),
            b: bar,
            curve_b: Arc::new(PointCurve::new(in_frame([L, 0.0], frame)).unwrap()),
        });
        let opts = SystemDynamicsOptions {
            gravity: Vec2::new(0.0, -G),
            restitution: vec![0.5],
            ..SystemDynamicsOptions::default()
        };
        let mut sim = SystemSimulation::new(&sys, opts).unwrap();
        let e0 = sim.sample().unwrap().energy;
        let mut impact = None;
        let h = 1e-4;
        while impact.is_none() {
            assert!(
                sim.time() < 2.0 * quarter,
                "{frame:?}: no impact by {} s",
                sim.time()
            );
            for ev in sim.advance(h).unwrap() {
                assert_eq!(ev.kind, EventKind::Impact, "{ev:?}");
                impact = Some(ev);
            }
            if impact.is_none() {
                // no damping: the energy stays (RK4 at 0.1 ms)
                let e = sim.sample().unwrap().energy;
                assert!(
                    (e - e0).abs() < 1e-10 * M * G * D,
                    "{frame:?}: {e} J, {e0} J"
                );
            }
        }
        let ev = impact.unwrap();
        assert!(
            (ev.time - quarter).abs() < 1e-9 * quarter,
            "{frame:?}: impact at {} s, closed form {quarter} s",
            ev.time
        );
        assert!(
            (ev.approach - approach).abs() < 1e-9 * approach,
            "{frame:?}: approach {} m/s, closed form {approach} m/s",
            ev.approach
        );
        // the sample, at the step's end just after the impact, gives the frame's pose: the
        // natural frame turned about the pivot, nearly −90°
        let s = sim.sample().unwrap();
        let (t, phi) = frame;
        let w = (2.0 * M * G * D / i_o).sqrt();
        let turned = s.q[2] - phi;
        assert!(
            (turned + std::f64::consts::FRAC_PI_2).abs() < w * h,
            "{frame:?}: {:?}",
            &s.q
        );
        let origin = Rotation::new(turned) * Vec2::new(t[0], t[1]);
        assert!(
            (s.q[0] - origin.x).abs() < 1e-12 && (s.q[1] - origin.y).abs() < 1e-12,
            "{frame:?}: {:?}",
            &s.q
        );
        // the rebound: the bar's rate reversed times the restitution (gravity, with no moment
        // at the bottom, changes it by 1e-7 of itself in what is left of the step)
        assert!(
            (s.qd[2] - 0.5 * w).abs() < 1e-6 * w,
            "{frame:?}: {:?}",
            &s.qd
        );
    }
}

#[test]
fn a_crank_speeding_up_under_gravity_needs_the_parallel_axis_torque() {
    let (w0, alpha) = (20.0, 150.0);
    let i_o = I_G + M * D * D;
    for frame in FRAMES {
        let mut sys = System::new();
        let bar = bar(&mut sys, frame);
        sys.add_driver(Driver {
            name: "motor".into(),
            body: bar,
            coordinate: Coordinate::Angle,
            law: DriverLaw::Quadratic {
                start: frame.1,
                rate: w0,
                acceleration: alpha,
            },
        });
        let opts = SystemDynamicsOptions {
            gravity: Vec2::new(0.0, -G),
            ..SystemDynamicsOptions::default()
        };
        let mut sim = SystemSimulation::new(&sys, opts).unwrap();
        for _ in 0..50 {
            sim.advance(1e-3).unwrap();
            let s = sim.sample().unwrap();
            let theta = s.q[2] - frame.1;
            let torque = i_o * alpha + M * G * D * theta.cos();
            assert!(
                (s.driver_efforts[0] - torque).abs() < 1e-9 * torque.abs().max(i_o * alpha),
                "{frame:?} at {} s: {} N·m, closed form {torque} N·m",
                s.time,
                s.driver_efforts[0]
            );
            // the frame's origin goes round the pivot: |o| = |t|
            let r = (s.q[0].hypot(s.q[1]) - frame.0[0].hypot(frame.0[1])).abs();
            assert!(r < 1e-12, "{frame:?}: {:?}", &s.q);
            // and its acceleration is the circle's: −ω² o + α J o
            let w = w0 + alpha * s.time;
            let (ox, oy) = (s.q[0], s.q[1]);
            let (ax, ay) = (-w * w * ox - alpha * oy, -w * w * oy + alpha * ox);
            assert!(
                (s.qdd[0] - ax).abs() < 1e-9 * w * w && (s.qdd[1] - ay).abs() < 1e-9 * w * w,
                "{frame:?}: {:?} against ({ax}, {ay})",
                &s.qdd
            );
        }
    }
}

#[test]
fn a_slide_driven_along_x_needs_its_mass_times_its_acceleration_wherever_its_centre() {
    let a = 3.0;
    for centre in [[0.0, 0.0], [0.2, -0.1], [-0.05, 0.3]] {
        let mut sys = System::new();
        let slide = sys.add_body(Body {
            name: "slide".into(),
            mass: M,
            inertia: I_G,
            pose: camkin::body::Pose::new(Point2::origin(), 0.0),
            centre_of_mass: Point2::new(centre[0], centre[1]),
        });
        sys.add_joint(Joint {
            name: "guide".into(),
            kind: JointKind::Prismatic {
                a: BodyId::GROUND,
                at_a: Point2::origin(),
                axis: Vec2::x(),
                b: slide,
                at_b: Point2::origin(),
                angle: 0.0,
            },
        });
        sys.add_driver(Driver {
            name: "push".into(),
            body: slide,
            coordinate: Coordinate::X,
            law: DriverLaw::Quadratic {
                start: 0.0,
                rate: 1.0,
                acceleration: a,
            },
        });
        let opts = SystemDynamicsOptions {
            gravity: Vec2::new(0.0, -G),
            ..SystemDynamicsOptions::default()
        };
        let mut sim = SystemSimulation::new(&sys, opts).unwrap();
        for _ in 0..20 {
            sim.advance(1e-3).unwrap();
            let s = sim.sample().unwrap();
            assert!(
                (s.driver_efforts[0] - M * a).abs() < 1e-12,
                "{centre:?}: {} N, m a = {} N",
                s.driver_efforts[0],
                M * a
            );
            let t = s.time;
            assert!((s.q[0] - (t + 0.5 * a * t * t)).abs() < 1e-12, "{:?}", &s.q);
            assert!(s.q[1].abs() < 1e-14 && s.q[2].abs() < 1e-14, "{:?}", &s.q);
        }
    }
}
