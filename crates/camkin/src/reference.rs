//! Reference problems shared by tests, examples and the command line.
//!
//! The paper's example cam (section 3, `cam-follower.md`): a closed cubic spline through nine
//! nodes (cm), turning at 1000 rpm counter-clockwise, with a translating flat-faced follower moving
//! along +x. Reference values (exact, to the digits shown): θ = 0: s = 5 cm,
//! a = −26 961.97 cm/s²; θ = 45°: s = 4.448456 cm, a = −6 291.918 cm/s².

use crate::body::Pose;
use crate::cam::{Cam, Follower, Mechanism, Sense};
use crate::curve::{Circle, ClosedSpline, Ellipse, Line};
use crate::system::{
    Body, BodyId, Contact, Coordinate, Driver, DriverLaw, Joint, JointKind, System,
};
use crate::{Point2, Vec2};
use std::sync::Arc;

/// The paper's nine nodes (cm); `revised` replaces the right-extreme node (5, 0) by (4.2, 0).
pub fn paper_nodes(revised: bool) -> [Point2; 9] {
    let x0 = if revised { 4.2 } else { 5.0 };
    [
        (x0, 0.0),
        (3.4, 2.8),
        (0.6, 3.4),
        (-1.5, 2.6),
        (-2.8, 1.0),
        (-2.8, -1.0),
        (-1.5, -2.6),
        (0.6, -3.4),
        (3.4, -2.8),
    ]
    .map(|(x, y)| Point2::new(x, y))
}

/// The paper's cam profile.
pub fn paper_profile(revised: bool) -> ClosedSpline {
    ClosedSpline::new(&paper_nodes(revised)).expect("the paper's nodes are valid")
}

/// The paper's mechanism: 1000 rpm ccw about the origin, flat-faced follower along +x.
pub fn paper_mechanism(revised: bool) -> Mechanism {
    let cam = Cam::from_rpm(
        Arc::new(paper_profile(revised)),
        Point2::origin(),
        Sense::Ccw,
        1000.0,
    )
    .expect("valid cam");
    Mechanism::new(
        cam,
        Follower::TranslatingFlat {
            direction: Vec2::x(),
        },
    )
    .expect("valid mechanism")
}

/// A body of the valve train (its mass properties are placeholders for the kinematics).
fn valve_body(name: &str, x: f64, y: f64, angle: f64) -> Body {
    Body {
        name: name.into(),
        mass: 1.0,
        inertia: 1.0,
        pose: Pose::new(Point2::new(x, y), angle),
        centre_of_mass: crate::geometry::Point2::origin(),
    }
}

/// A single-valve train (mm, rad/s): a camshaft turning at `w` about the origin (an ellipse
/// 15 × 20 mm, its centre 4 mm below the axis: one lobe, full lift at angle 0) above a roller
/// finger follower pivoting on a lash adjuster's ball at (−35, −30), its 6 mm roller at (35, 0) and
/// its pad (a 15 mm arc centred at (60, 12)) in its own frame, the pad on the flat tip of a valve
/// sliding along x = 25. Returns the system and the ids of the camshaft, the finger and the valve.
pub fn single_valve_train(w: f64) -> (System, [BodyId; 3]) {
    let mut sys = System::new();
    let g = BodyId::GROUND;
    let cam = sys.add_body(valve_body("camshaft", 0.0, 0.0, 0.0));
    // the finger and the valve start a little off their assembled poses
    let finger = sys.add_body(valve_body("finger", -35.0, -30.0, 0.02));
    let valve = sys.add_body(valve_body("valve", 25.0, -32.5, 0.0));
    sys.add_joint(Joint {
        name: "camshaft bearing".into(),
        kind: JointKind::Revolute {
            a: g,
            at_a: Point2::origin(),
            b: cam,
            at_b: Point2::origin(),
        },
    });
    sys.add_joint(Joint {
        name: "lash adjuster".into(),
        kind: JointKind::Revolute {
            a: g,
            at_a: Point2::new(-35.0, -30.0),
            b: finger,
            at_b: Point2::origin(),
        },
    });
    sys.add_joint(Joint {
        name: "valve guide".into(),
        kind: JointKind::Prismatic {
            a: g,
            at_a: Point2::new(25.0, 0.0),
            axis: Vec2::y(),
            b: valve,
            at_b: Point2::origin(),
            angle: 0.0,
        },
    });
    sys.add_driver(Driver {
        name: "crank".into(),
        body: cam,
        coordinate: Coordinate::Angle,
        law: DriverLaw::linear(0.0, w),
    });
    sys.add_contact(Contact {
        name: "cam on roller".into(),
        a: cam,
        curve_a: Arc::new(
            Ellipse::new(Point2::new(0.0, -4.0), 15.0, 20.0, 0.0).expect("a valid ellipse"),
        ),
        b: finger,
        curve_b: Arc::new(Circle::new(Point2::new(35.0, 0.0), 6.0).expect("a valid circle")),
    });
    sys.add_contact(Contact {
        name: "pad on valve".into(),
        a: finger,
        curve_a: Arc::new(Circle::new(Point2::new(60.0, 12.0), 15.0).expect("a valid circle")),
        b: valve,
        // the tip, the valve below it
        curve_b: Arc::new(Line::new(Point2::origin(), Vec2::new(-1.0, 0.0)).expect("a valid line")),
    });
    (sys, [cam, finger, valve])
}
