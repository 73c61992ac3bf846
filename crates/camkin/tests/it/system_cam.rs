//! Issue 45: the paper's cam and its flat-faced follower assembled as a system — the cam a body
//! on a pin to the ground, driven at 1000 rpm; the follower a body on a slide, carrying its face
//! as a line; one contact between the cam's spline and the line — gives the cam path's answers
//! (`Mechanism`, its own first-touch search and closed-form flat-face kinematics) to 1e-12 of
//! the size in position and of the peaks in velocity and acceleration, over a revolution, and the
//! contact's row and `γ` with them. And the same with an offset roller carried as a circle on an
//! arm pivoted to the ground.

use crate::common::system_body as body;
use camkin::cam::{Cam, Follower, Mechanism, Sense};
use camkin::curve::{Circle, Line};
use camkin::reference::{paper_mechanism, paper_profile};
use camkin::system::{BodyId, Contact, Coordinate, Driver, DriverLaw, Joint, JointKind, System};
use camkin::{Point2, Vec2};
use std::sync::Arc;

/// The cam on a driven pin; returns the system and the cam's id.
fn cam_system(w: f64) -> (System, BodyId) {
    let mut sys = System::new();
    let cam = sys.add_body(body("cam", 0.0, 0.0, 0.0));
    sys.add_joint(Joint {
        name: "camshaft".into(),
        kind: JointKind::Revolute {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            b: cam,
            at_b: Point2::origin(),
        },
    });
    sys.add_driver(Driver {
        name: "drive".into(),
        body: cam,
        coordinate: Coordinate::Angle,
        law: DriverLaw::linear(0.0, w),
    });
    (sys, cam)
}

/// The cam path's answers at `n` angles over a revolution, with the peaks of its velocity and
/// acceleration (the tolerances' scale).
fn cam_path(mech: &Mechanism, n: u32) -> (Vec<(f64, camkin::cam::FollowerState)>, f64, f64) {
    let rows: Vec<_> = (0..n)
        .map(|k| f64::from(k) * std::f64::consts::TAU / f64::from(n))
        .map(|th| (th, mech.analyze(th).unwrap()))
        .collect();
    let peak = |f: fn(&camkin::cam::FollowerState) -> f64| {
        rows.iter().map(|r| f(&r.1).abs()).fold(0.0, f64::max)
    };
    let (v, a) = (peak(|s| s.velocity), peak(|s| s.acceleration));
    (rows, v, a)
}

#[test]
fn the_papers_cam_as_a_system_gives_the_cam_paths_answers() {
    let mech = paper_mechanism(false);
    let w = mech.cam().speed();
    let (mut sys, cam) = cam_system(w);
    let s0 = mech.analyze(0.0).unwrap().position;
    // the follower starts 0.2 away from the cam: the contact closes the gap
    let face = sys.add_body(body("follower", s0 + 0.2, 0.0, 0.0));
    sys.add_joint(Joint {
        name: "guide".into(),
        kind: JointKind::Prismatic {
            a: BodyId::GROUND,
            at_a: Point2::origin(),
            axis: Vec2::x(),
            b: face,
            at_b: Point2::origin(),
            angle: 0.0,
        },
    });
    sys.add_contact(Contact {
        name: "cam on face".into(),
        a: cam,
        curve_a: Arc::new(paper_profile(false)),
        b: face,
        curve_b: Arc::new(Line::new(Point2::origin(), Vec2::new(0.0, -1.0)).unwrap()),
    });
    let size = mech.size();
    let (rows, vpeak, apeak) = cam_path(&mech, 720);
    let mut sweep = sys.sweep().unwrap();
    for (th, m) in &rows {
        let s = sweep.step(th / w).unwrap();
        let f = &s.bodies[face.index().unwrap()];
        let what = format!("at {:.1}°", th.to_degrees());
        assert!(
            (f.pose.origin.x - m.position).abs() <= 1e-12 * size,
            "{what}: {} against {}",
            f.pose.origin.x,
            m.position
        );
        assert!(
            (f.velocity.x - m.velocity).abs() <= 1e-12 * vpeak,
            "{what}: {} against {}",
            f.velocity.x,
            m.velocity
        );
        assert!(
            (f.acceleration.x - m.acceleration).abs() <= 1e-12 * apeak,
            "{what}: {} against {}",
            f.acceleration.x,
            m.acceleration
        );
        // the cam turns as driven; the contact point is the cam path's
        let c = &s.bodies[cam.index().unwrap()];
        assert!((c.pose.angle - th).abs() <= 1e-12 && (c.omega - w).abs() <= 1e-12 * w);
        let k = &s.contacts[0].kinematics;
        assert!((k.point - m.contact_world).norm() <= 1e-9 * size, "{what}");
        assert!(
            (k.sliding_rate_a - m.sliding_rate_cam).abs() <= 1e-9 * vpeak.max(w * size),
            "{what}: sliding rate {} against {}",
            k.sliding_rate_a,
            m.sliding_rate_cam
        );
        assert!(s.contacts[0].pairing.gap.abs() <= 1e-12 * size, "{what}");
    }
}

/// An eccentric disc (radius 2, eccentricity 0.5) driving a roller (radius 0.4) carried as a
/// circle at the end of an arm (length 3, pivoted at (1.5, 2.5)), against the cam path's
/// oscillating roller on the same geometry.
#[test]
fn an_arm_carrying_a_roller_as_a_system_gives_the_cam_paths_answers() {
    let (r, e, rr, len) = (2.0, 0.5, 0.4, 3.0);
    let pivot = Point2::new(1.5, 2.5);
    let disc = || Arc::new(Circle::new(Point2::new(e, 0.0), r).unwrap());
    let mech = Mechanism::new(
        Cam::from_rpm(disc(), Point2::origin(), Sense::Ccw, 600.0).unwrap(),
        Follower::Rotating {
            pivot,
            closing: Sense::Cw,
            initial_angle: -2.0,
            profile: camkin::cam::FollowerProfile(Arc::new(
                Circle::new(Point2::new(len, 0.0), rr).unwrap(),
            )),
        },
    )
    .unwrap();
    let w = mech.cam().speed();
    let (mut sys, cam) = cam_system(w);
    let phi0 = mech.analyze(0.0).unwrap().position;
    let arm = sys.add_body(body("arm", pivot.x, pivot.y, phi0 + 0.03));
    sys.add_joint(Joint {
        name: "pivot".into(),
        kind: JointKind::Revolute {
            a: BodyId::GROUND,
            at_a: pivot,
            b: arm,
            at_b: Point2::origin(),
        },
    });
    sys.add_contact(Contact {
        name: "disc on roller".into(),
        a: cam,
        curve_a: disc(),
        b: arm,
        curve_b: Arc::new(Circle::new(Point2::new(len, 0.0), rr).unwrap()),
    });
    let (rows, vpeak, apeak) = cam_path(&mech, 360);
    let mut sweep = sys.sweep().unwrap();
    for (th, m) in &rows {
        let s = sweep.step(th / w).unwrap();
        let a = &s.bodies[arm.index().unwrap()];
        let what = format!("at {:.0}°", th.to_degrees());
        let turn = std::f64::consts::TAU;
        let angle = a.pose.angle + ((m.position - a.pose.angle) / turn).round() * turn;
        assert!(
            (angle - m.position).abs() <= 1e-12,
            "{what}: {angle} against {}",
            m.position
        );
        assert!((a.omega - m.velocity).abs() <= 1e-11 * vpeak, "{what}");
        assert!(
            (a.acceleration.norm()) <= 1e-9 * apeak * len,
            "{what}: the pivot moves"
        );
        assert!(
            (a.alpha - m.acceleration).abs() <= 1e-11 * apeak,
            "{what}: {} against {}",
            a.alpha,
            m.acceleration
        );
    }
}

/// Two followers on one cam (two contacts on one body): an eccentric disc (radius 2,
/// eccentricity 0.5) under two flat-faced followers sliding along +x and +y. Each face rests on
/// the disc's support function, `s(θ) = r + e cos(θ − β)` with `β` the face's direction, so
/// `ṡ = −e ω sin(θ − β)` and `s̈ = −e ω² cos(θ − β)`: closed forms, to 1e-12.
#[test]
fn one_cam_drives_two_followers() {
    let (r, e) = (2.0, 0.5);
    let w = 600.0 * std::f64::consts::TAU / 60.0;
    let (mut sys, cam) = cam_system(w);
    let disc = || Arc::new(Circle::new(Point2::new(e, 0.0), r).unwrap());
    let mut faces = Vec::new();
    for (name, dir) in [("x face", Vec2::x()), ("y face", Vec2::y())] {
        let start = (r + 0.3) * dir;
        let f = sys.add_body(body(name, start.x, start.y, 0.0));
        sys.add_joint(Joint {
            name: format!("{name} guide"),
            kind: JointKind::Prismatic {
                a: BodyId::GROUND,
                at_a: Point2::origin(),
                axis: dir,
                b: f,
                at_b: Point2::origin(),
                angle: 0.0,
            },
        });
        // the face: a line through the follower's origin, across the direction of travel, the
        // follower beyond it
        sys.add_contact(Contact {
            name: format!("disc on {name}"),
            a: cam,
            curve_a: disc(),
            b: f,
            curve_b: Arc::new(Line::new(Point2::origin(), Vec2::new(dir.y, -dir.x)).unwrap()),
        });
        faces.push((f, dir));
    }
    let mut sweep = sys.sweep().unwrap();
    for k in 0..360 {
        let th = f64::from(k).to_radians();
        let s = sweep.step(th / w).unwrap();
        for &(f, dir) in &faces {
            let beta = dir.y.atan2(dir.x);
            let b = &s.bodies[f.index().unwrap()];
            let q = b.pose.origin.coords.dot(&dir);
            let what = format!("at {k}°, face along {dir:?}");
            assert!(
                (q - (r + e * (th - beta).cos())).abs() <= 1e-12 * r,
                "{what}"
            );
            let v = b.velocity.dot(&dir);
            assert!(
                (v + e * w * (th - beta).sin()).abs() <= 1e-12 * e * w,
                "{what}: {v}"
            );
            let a = b.acceleration.dot(&dir);
            assert!(
                (a + e * w * w * (th - beta).cos()).abs() <= 1e-11 * e * w * w,
                "{what}: {a}"
            );
        }
        assert_eq!(s.contacts.len(), 2);
    }
}
