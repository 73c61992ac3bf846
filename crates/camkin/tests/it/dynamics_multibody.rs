//! The multibody module on its own: closed-form motions under an applied torque and gravity.
#![allow(clippy::unwrap_used)]
use camkin::dynamics::{AugmentedLagrangian, Constraint, ForceElement, RigidBody, System};
use camkin::{Point2, Vec2};

fn system(
    bodies: Vec<RigidBody>,
    constraints: Vec<Constraint>,
    forces: Vec<ForceElement>,
) -> System {
    System {
        bodies,
        constraints,
        forces,
        search: camkin::contact::SearchOptions::default(),
    }
}

#[test]
fn applied_torque_on_a_pinned_disc() {
    // a disc pinned at its centre: θ̈ = τ / I, and the pin carries no force
    let s = system(
        vec![RigidBody {
            mass: 2.0,
            inertia: 0.5,
        }],
        vec![Constraint::Revolute {
            body: 0,
            local: Point2::origin(),
            ground: Point2::new(1.0, 2.0),
        }],
        vec![ForceElement::Torque {
            body: 0,
            torque: 3.0,
        }],
    );
    let e = s
        .evaluate(
            &AugmentedLagrangian::default(),
            0.0,
            &[1.0, 2.0, 0.3],
            &[0.0, 0.0, 4.0],
            &[true],
            &mut [None],
        )
        .unwrap();
    assert!((e.qdd[2] - 6.0).abs() < 1e-12, "{:?}", e.qdd);
    assert!(e.qdd[0].abs() < 1e-12 && e.qdd[1].abs() < 1e-12);
    assert!(e.lambda.iter().all(|l| l.abs() < 1e-9), "{:?}", e.lambda);
}

#[test]
fn pendulum_under_gravity() {
    // a point mass m on a massless arm of length l pinned at the origin, angle θ from +x:
    // θ̈ = −(g/l) cos θ (gravity −y), arm tension from the centripetal balance
    let (m, l, g) = (1.5, 0.8, 9.81);
    let s = system(
        // body frame at the mass: the pin is at (−l, 0) in the body frame when θ_body = θ
        vec![RigidBody {
            mass: m,
            inertia: 1e-12,
        }],
        vec![Constraint::Revolute {
            body: 0,
            local: Point2::new(-l, 0.0),
            ground: Point2::origin(),
        }],
        vec![ForceElement::Gravity(Vec2::new(0.0, -g))],
    );
    for (th, w) in [(0.3f64, 1.0f64), (-1.0, -2.0), (2.0, 0.5)] {
        let q = [l * th.cos(), l * th.sin(), th];
        let qd = [-l * w * th.sin(), l * w * th.cos(), w];
        let e = s
            .evaluate(
                &AugmentedLagrangian::default(),
                0.0,
                &q,
                &qd,
                &[true],
                &mut [None],
            )
            .unwrap();
        let expect = -(g / l) * th.cos();
        assert!(
            (e.qdd[2] - expect).abs() < 1e-6 * expect.abs().max(1.0),
            "θ̈ {} vs {}",
            e.qdd[2],
            expect
        );
    }
}
