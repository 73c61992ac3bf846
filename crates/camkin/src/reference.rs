//! Reference problems shared by tests, examples and the command line.
//!
//! The paper's example cam (section 3, `cam-follower.md`): a closed cubic spline through nine
//! nodes (cm), turning at 1000 rpm counter-clockwise, with a translating flat-faced follower moving
//! along +x. Reference values (exact, to the digits shown): θ = 0: s = 5 cm,
//! a = −26 961.97 cm/s²; θ = 45°: s = 4.448456 cm, a = −6 291.918 cm/s².

use crate::cam::{Cam, Follower, Mechanism, Sense};
use crate::curve::ClosedSpline;
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
