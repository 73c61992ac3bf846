//! A system drawn at one instant, as shapes in world coordinates: each contact's two curves on
//! their bodies, the contact point and its common normal, every joint's point, and each body's
//! joint points joined (a link drawn as the bar between its pins).

use super::mechanism::{Rgb, Shape, CONTACT, FOLLOWER, NORMAL};
use camkin::curve::{Curve, Domain};
use camkin::system::{BodyId, JointKind, System, SystemState};
use camkin::{Frame, Point2};

/// A colour for each body, in turn.
const PALETTE: [Rgb; 6] = [
    (31, 119, 180),
    (255, 127, 14),
    (148, 103, 189),
    (140, 86, 75),
    (227, 119, 194),
    (23, 190, 207),
];

fn color(id: BodyId) -> Rgb {
    id.index().map_or(FOLLOWER, |i| PALETTE[i % PALETTE.len()])
}

fn frame(poses: &[camkin::body::Pose], id: BodyId) -> Frame {
    id.index()
        .map_or_else(Frame::identity, |i| poses[i].frame())
}

/// The curve on body `id` in the world: a closed curve whole, an open one over `size` either
/// side of `at` (its pairing parameter), a point as a dot.
fn curve_shape(curve: &dyn Curve, f: &Frame, at: f64, size: f64, color: Rgb) -> Shape {
    match curve.domain() {
        Domain::Periodic { period } => Shape::Polyline {
            pts: (0..720)
                .map(|k| f * curve.position(period * f64::from(k) / 720.0))
                .collect(),
            color,
            width: 2,
            closed: true,
        },
        Domain::Interval { min, max } => {
            // a line's parameter is a length; an open curve's stretch around the contact
            let speed = curve.eval(at).d1.norm().max(1e-300);
            let (lo, hi) = ((at - size / speed).max(min), (at + size / speed).min(max));
            let mut pts: Vec<Point2> = (0..=64)
                .map(|k| f * curve.position(lo + (hi - lo) * f64::from(k) / 64.0))
                .collect();
            // a straight stretch (a line: a face, a seat, a coil's clash plane) is its two
            // ends: the page draws the same, and a simulation's frames are 30 times lighter
            let (a, b) = (pts[0], pts[pts.len() - 1]);
            let chord = b - a;
            let straight = chord.norm() > 0.0
                && pts.iter().all(|p| {
                    (camkin::geometry::cross(chord, p - a) / chord.norm()).abs() <= 1e-9 * size
                });
            if straight {
                pts = vec![a, b];
            }
            Shape::Polyline {
                pts,
                color,
                width: 2,
                closed: false,
            }
        }
        Domain::Point => Shape::Dot {
            p: f * curve.position(0.0),
            color,
            px: 4,
        },
    }
}

/// The shapes of `sys` at the instant `s`; `size` the system's size (for the lengths drawn).
pub fn system_scene(sys: &System, s: &SystemState, size: f64) -> Vec<Shape> {
    let poses: Vec<camkin::body::Pose> = s.bodies.iter().map(|b| b.pose).collect();
    let touches: Vec<Touch> = s
        .contacts
        .iter()
        .map(|k| Touch {
            u_a: k.pairing.u_a,
            u_b: k.pairing.u_b,
            point: k.kinematics.point,
            normal: k.kinematics.normal.into_inner(),
            closed: true,
        })
        .collect();
    scene_at(sys, &poses, &touches, size)
}

/// Where a contact's curves are nearest: their pairing parameters, the contact point and the
/// common normal, and whether they touch (a simulation's contact may be open).
#[derive(Debug, Clone, Copy)]
pub struct Touch {
    /// curve A's parameter
    pub u_a: f64,
    /// curve B's
    pub u_b: f64,
    /// the contact point (A's), world
    pub point: Point2,
    /// the common normal, unit
    pub normal: camkin::Vec2,
    /// in touch: its point and normal are drawn
    pub closed: bool,
}

/// [`system_scene`] from the bodies' poses and each contact's [`Touch`] (a simulation's
/// sample).
pub fn scene_at(
    sys: &System,
    poses: &[camkin::body::Pose],
    touches: &[Touch],
    size: f64,
) -> Vec<Shape> {
    let pairs: Vec<(f64, f64)> = touches.iter().map(|t| (t.u_a, t.u_b)).collect();
    let mut shapes = Vec::new();
    for (c, &(ua, ub)) in sys.contacts().iter().zip(&pairs) {
        for (id, curve, u) in [(c.a, &c.curve_a, ua), (c.b, &c.curve_b, ub)] {
            shapes.push(curve_shape(
                curve.as_ref(),
                &frame(poses, id),
                u,
                0.6 * size,
                color(id),
            ));
        }
    }
    // each body's pins, joined: the bar of a link
    let mut pins: Vec<Vec<Point2>> = vec![Vec::new(); sys.bodies().len()];
    for j in sys.joints() {
        let pin = matches!(j.kind, JointKind::Revolute { .. });
        for (id, at) in j.kind.points() {
            let p = frame(poses, id) * at;
            if let Some(i) = id.index() {
                pins[i].push(p);
            }
            // a pin is a small circle; a slide's guide is drawn below
            if pin {
                shapes.push(Shape::Circle {
                    c: p,
                    r: 0.012 * size,
                    color: FOLLOWER,
                    width: 2,
                });
            }
        }
        if let JointKind::Prismatic { a, at_a, axis, .. } = j.kind {
            // the guide: a line through its point along its axis
            let f = frame(poses, a);
            let d = f.rotation * (axis / axis.norm());
            let p = f * at_a;
            shapes.push(Shape::Polyline {
                pts: vec![p - 0.5 * size * d, p + 0.5 * size * d],
                color: (150, 150, 150),
                width: 1,
                closed: false,
            });
        }
    }
    // a body's contact curves hang on its bar too: a closed curve by its centre (the mean of
    // its samples), an open one by the contact point
    for (c, &(ua, ub)) in sys.contacts().iter().zip(&pairs) {
        for (id, curve, u) in [(c.a, &c.curve_a, ua), (c.b, &c.curve_b, ub)] {
            let Some(i) = id.index() else { continue };
            let f = frame(poses, id);
            let p = match curve.domain() {
                Domain::Periodic { period } => {
                    let n = 64;
                    let sum = (0..n).fold(camkin::Vec2::zeros(), |acc, k| {
                        acc + curve.position(period * f64::from(k) / f64::from(n)).coords
                    });
                    f * Point2::from(sum / f64::from(n))
                }
                _ => f * curve.position(u),
            };
            if !pins[i].iter().any(|q| (q - p).norm() < 1e-9 * size) {
                pins[i].push(p);
            }
        }
    }
    for (i, p) in pins.iter().enumerate() {
        if p.len() >= 2 {
            shapes.push(Shape::Polyline {
                pts: p.clone(),
                color: PALETTE[i % PALETTE.len()],
                width: 4,
                closed: false,
            });
        }
    }
    for t in touches.iter().filter(|t| t.closed) {
        let (c, n) = (t.point, t.normal);
        shapes.push(Shape::Polyline {
            pts: vec![c - 0.08 * size * n, c + 0.08 * size * n],
            color: NORMAL,
            width: 2,
            closed: false,
        });
        shapes.push(Shape::Dot {
            p: c,
            color: CONTACT,
            px: 5,
        });
    }
    shapes
}
