//! The mechanism drawn at one cam angle, as shapes in world coordinates: cam profile with its
//! nodes, cam axis, follower, contact point and common normal. Rendered by plotters (static SVG
//! and PNG) and by a small SVG writer (the animation).

use camkin::cam::{FollowerCurve, FollowerState, Mechanism};
use camkin::curve::Domain;
use camkin::geometry::{rot90, Rotation};
use camkin::{Point2, Vec2};
use std::fmt::Write as _;

/// Colours as RGB.
pub type Rgb = (u8, u8, u8);
pub const CAM: Rgb = (31, 119, 180);
pub const FOLLOWER: Rgb = (60, 60, 60);
pub const CONTACT: Rgb = (214, 39, 40);
pub const NORMAL: Rgb = (44, 160, 44);

#[derive(Debug, Clone)]
pub enum Shape {
    Polyline {
        pts: Vec<Point2>,
        color: Rgb,
        width: u32,
        closed: bool,
    },
    Circle {
        c: Point2,
        r: f64,
        color: Rgb,
        width: u32,
    },
    Dot {
        p: Point2,
        color: Rgb,
        px: u32,
    },
}

fn segment(a: Point2, b: Point2, color: Rgb, width: u32) -> Shape {
    Shape::Polyline {
        pts: vec![a, b],
        color,
        width,
        closed: false,
    }
}

/// The shapes of the mechanism at cam angle `theta` (rad), with the analysed state there.
pub fn scene(mech: &Mechanism, theta: f64, state: Option<&FollowerState>) -> Vec<Shape> {
    let cam = mech.cam();
    let profile = cam.profile();
    let body = cam.state(theta);
    let size = mech.size();
    let mut shapes = Vec::new();
    let period = match profile.domain() {
        Domain::Periodic { period } => period,
        _ => 1.0,
    };
    let n = 720;
    let pts: Vec<Point2> = (0..n)
        .map(|k| {
            body.pose
                .to_world(profile.position(period * k as f64 / n as f64))
        })
        .collect();
    shapes.push(Shape::Polyline {
        pts,
        color: CAM,
        width: 2,
        closed: true,
    });
    // a spline's nodes (a gear's or a motion program's piece joints are not drawn: they are not
    // points anyone placed)
    let spline = profile.as_spline().is_some();
    for u in profile.breakpoints().into_iter().filter(|_| spline) {
        shapes.push(Shape::Dot {
            p: body.pose.to_world(profile.position(u)),
            color: CAM,
            px: 4,
        });
    }
    // the cam axis and a mark for the cam frame's x axis
    let axis = cam.pivot();
    shapes.push(Shape::Circle {
        c: axis,
        r: 0.04 * size,
        color: FOLLOWER,
        width: 1,
    });
    shapes.push(segment(
        axis,
        axis + Rotation::new(body.pose.angle) * Vec2::new(0.25 * size, 0.0),
        CAM,
        1,
    ));
    // the sense of rotation: an arc round the axis with its arrowhead, fixed in the world
    let sign = cam.direction().sign();
    let r = 0.15 * size;
    let arc: Vec<Point2> = (0..=24)
        .map(|k| {
            let t = sign * (30f64 + 120.0 * f64::from(k) / 24.0).to_radians();
            axis + r * Vec2::new(t.cos(), t.sin())
        })
        .collect();
    let tip = arc[arc.len() - 1];
    let back = (arc[arc.len() - 3] - tip).normalize() * (0.06 * size);
    for turn in [-0.5f64, 0.5] {
        shapes.push(segment(tip, tip + Rotation::new(turn) * back, CAM, 1));
    }
    shapes.push(Shape::Polyline {
        pts: arc,
        color: CAM,
        width: 1,
        closed: false,
    });
    let Some(s) = state else { return shapes };
    let c = s.contact_world;
    follower_shapes(mech, s.position, c, size, &mut shapes);
    // every contact: the first touch, the next tooth pair, a conjugate's second curve
    let others = mech.contacts_at(s).unwrap_or_default();
    let nl = 0.35 * size;
    let points =
        std::iter::once((c, s.normal)).chain(others.iter().skip(1).map(|k| (k.point, k.normal)));
    for (p, n) in points {
        shapes.push(segment(p - nl * *n, p + nl * *n, NORMAL, 1));
        shapes.push(Shape::Dot {
            p,
            color: CONTACT,
            px: 5,
        });
    }
    shapes
}

/// The follower at position `q` touching at `c`, drawn from its model: the contact curve in its
/// frame (a face, a roller, a knife's tip) and the joint that carries it (a stem along the
/// direction of travel, or an arm from the pivot).
pub fn follower_shapes(mech: &Mechanism, q: f64, c: Point2, size: f64, shapes: &mut Vec<Shape>) {
    let (pose, _) = mech.follower_body(q);
    let rot = Rotation::new(pose.angle);
    let joint = mech.follower_joint();
    // where the joint attaches to the curve, and how far the curve reaches beyond it along `d`
    let (attach, reach) = match mech.follower_curve() {
        FollowerCurve::Line(l) => {
            let a = pose.to_world(l.anchor());
            let t = rot * l.direction();
            let uc = (c - a).dot(&t);
            let (lo, hi) = (uc.min(0.0) - 0.4 * size, uc.max(0.0) + 0.4 * size);
            shapes.push(segment(a + lo * t, a + hi * t, FOLLOWER, 3));
            (a, 0.0)
        }
        FollowerCurve::Circle(k) => {
            let centre = pose.to_world(k.center());
            shapes.push(Shape::Circle {
                c: centre,
                r: k.radius(),
                color: FOLLOWER,
                width: 2,
            });
            (centre, k.radius())
        }
        FollowerCurve::Point(p) => {
            let tip = pose.to_world(p.at());
            let away = match joint.direction() {
                Some(direction) => *direction,
                None => (tip - c).try_normalize(0.0).unwrap_or(Vec2::x()),
            };
            let (w, back) = (0.06 * size, tip + 0.2 * size * away);
            shapes.push(Shape::Polyline {
                pts: vec![tip, back + w * rot90(away), back - w * rot90(away)],
                color: FOLLOWER,
                width: 2,
                closed: true,
            });
            (back, 0.0)
        }
        FollowerCurve::Carried(curve) => {
            let (pts, closed) = curve_points(curve.as_ref(), &pose, c, size);
            shapes.push(Shape::Polyline {
                pts,
                color: FOLLOWER,
                width: 2,
                closed,
            });
            (pose.origin, 0.0)
        }
        _ => (pose.origin, 0.0),
    };
    match joint.direction() {
        Some(direction) => {
            shapes.push(segment(
                attach,
                attach + (reach + 0.8 * size) * *direction,
                FOLLOWER,
                3,
            ));
        }
        None => {
            let pivot = joint.origin();
            shapes.push(segment(pivot, attach, FOLLOWER, 3));
            shapes.push(Shape::Circle {
                c: pivot,
                r: 0.04 * size,
                color: FOLLOWER,
                width: 2,
            });
        }
    }
    if let Some(curve) = mech.conjugate_curve() {
        conjugate_shapes(mech, curve.as_ref(), &pose, attach, size, shapes);
    }
}

/// A curve of the follower at `pose`: a closed one whole, an open one (a line) over a stretch
/// either side of its point nearest `near` (world); the points and whether they close.
fn curve_points(
    curve: &dyn camkin::curve::Curve,
    pose: &camkin::body::Pose,
    near: Point2,
    size: f64,
) -> (Vec<Point2>, bool) {
    use camkin::curve::Domain;
    let (lo, hi, closed) = match curve.domain() {
        Domain::Periodic { period } => (0.0, period, true),
        Domain::Interval { min, max } => {
            let local = pose.to_body(near);
            // the parameter nearest the point, by samples of a generous stretch
            let (a, b) = (min.max(-1e3 * size), max.min(1e3 * size));
            let near = (0..=2000)
                .map(|k| a + (b - a) * f64::from(k) / 2000.0)
                .min_by(|x, y| {
                    let dx = (curve.position(*x) - local).norm();
                    let dy = (curve.position(*y) - local).norm();
                    dx.total_cmp(&dy)
                })
                .unwrap_or(0.0);
            let span = 0.6 * size / curve.eval(near).metric().max(f64::MIN_POSITIVE);
            ((near - span).max(min), (near + span).min(max), false)
        }
        Domain::Point => (0.0, 0.0, false),
    };
    let n = 4000;
    let pts = (0..=n)
        .map(|k| pose.to_world(curve.position(lo + (hi - lo) * f64::from(k) / f64::from(n))))
        .collect();
    (pts, closed)
}

/// A conjugate follower's second curve at `pose` and what ties it to the first, attached at
/// `attach`: for a slide, a yoke beside the cam; for an arm, a second arm from the pivot.
fn conjugate_shapes(
    mech: &Mechanism,
    curve: &dyn camkin::curve::Curve,
    pose: &camkin::body::Pose,
    attach: Point2,
    size: f64,
    shapes: &mut Vec<Shape>,
) {
    let axis = mech.cam().pivot();
    let (pts, closed) = curve_points(curve, pose, axis, size);
    // a closed curve (a roller) is held at its middle, an open one at its point nearest the cam
    let hold = if closed {
        let sum = pts.iter().fold(Vec2::zeros(), |acc, p| acc + p.coords);
        Point2::from(sum / pts.len() as f64)
    } else {
        pts.iter()
            .copied()
            .min_by(|a, b| (a - axis).norm().total_cmp(&(b - axis).norm()))
            .unwrap_or(pose.origin)
    };
    shapes.push(Shape::Polyline {
        pts,
        color: FOLLOWER,
        width: 2,
        closed,
    });
    let joint = mech.follower_joint();
    match joint.direction() {
        Some(direction) => {
            // out to the side, past the cam, and back in
            let side = rot90(*direction);
            let out = (axis - attach).dot(&side) + 1.3 * size;
            shapes.push(Shape::Polyline {
                pts: vec![
                    attach,
                    attach + out * side,
                    hold + ((attach - hold).dot(&side) + out) * side,
                    hold,
                ],
                color: FOLLOWER,
                width: 3,
                closed: false,
            });
        }
        None => shapes.push(segment(joint.origin(), hold, FOLLOWER, 3)),
    }
}

/// Bounding box of shapes: (min, max).
pub fn bounds<'a>(shapes: impl IntoIterator<Item = &'a Shape>) -> (Point2, Point2) {
    let (mut lo, mut hi) = (
        Point2::new(f64::INFINITY, f64::INFINITY),
        Point2::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
    );
    let mut add = |p: Point2, r: f64| {
        lo = Point2::new(lo.x.min(p.x - r), lo.y.min(p.y - r));
        hi = Point2::new(hi.x.max(p.x + r), hi.y.max(p.y + r));
    };
    for s in shapes {
        match s {
            Shape::Polyline { pts, .. } => pts.iter().for_each(|p| add(*p, 0.0)),
            Shape::Circle { c, r, .. } => add(*c, *r),
            Shape::Dot { p, .. } => add(*p, 0.0),
        }
    }
    (lo, hi)
}

/// An animated SVG: one frame per scene, shown in turn over `seconds`, looping.
pub fn animated_svg(
    frames: &[Vec<Shape>],
    titles: &[String],
    (lo, hi): (Point2, Point2),
    seconds: f64,
) -> String {
    let (w, h) = (hi.x - lo.x, hi.y - lo.y);
    let width = 800.0;
    let k = width / w;
    let height = (h * k).ceil();
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{}" viewBox="0 0 {width} {}">"#,
        height + 40.0,
        height + 40.0
    );
    let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let n = frames.len();
    let tx = |p: &Point2| ((p.x - lo.x) * k, 40.0 + (hi.y - p.y) * k);
    let rgb = |c: &Rgb| format!("rgb({},{},{})", c.0, c.1, c.2);
    for (i, (frame, title)) in frames.iter().zip(titles).enumerate() {
        let (a, b) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
        let (values, times) = if n == 1 {
            ("inline".to_string(), "0".to_string())
        } else if i == 0 {
            ("inline;none".to_string(), format!("0;{b}"))
        } else if i + 1 == n {
            ("none;inline".to_string(), format!("0;{a}"))
        } else {
            ("none;inline;none".to_string(), format!("0;{a};{b}"))
        };
        let _ = writeln!(
            s,
            r#"<g display="{}"><animate attributeName="display" values="{values}" keyTimes="{times}" dur="{seconds}s" calcMode="discrete" repeatCount="indefinite"/>"#,
            if i == 0 { "inline" } else { "none" }
        );
        let _ = writeln!(
            s,
            r#"<text x="10" y="26" font-family="DejaVu Sans, sans-serif" font-size="18">{title}</text>"#
        );
        for shape in frame {
            match shape {
                Shape::Polyline {
                    pts,
                    color,
                    width,
                    closed,
                } => {
                    let d: Vec<String> = pts
                        .iter()
                        .map(|p| {
                            let (x, y) = tx(p);
                            format!("{x:.2},{y:.2}")
                        })
                        .collect();
                    let tag = if *closed { "polygon" } else { "polyline" };
                    let _ = writeln!(
                        s,
                        r#"<{tag} points="{}" fill="none" stroke="{}" stroke-width="{width}"/>"#,
                        d.join(" "),
                        rgb(color)
                    );
                }
                Shape::Circle { c, r, color, width } => {
                    let (x, y) = tx(c);
                    let _ = writeln!(
                        s,
                        r#"<circle cx="{x:.2}" cy="{y:.2}" r="{:.2}" fill="none" stroke="{}" stroke-width="{width}"/>"#,
                        r * k,
                        rgb(color)
                    );
                }
                Shape::Dot { p, color, px } => {
                    let (x, y) = tx(p);
                    let _ = writeln!(
                        s,
                        r#"<circle cx="{x:.2}" cy="{y:.2}" r="{px}" fill="{}"/>"#,
                        rgb(color)
                    );
                }
            }
        }
        let _ = writeln!(s, "</g>");
    }
    s.push_str("</svg>\n");
    s
}
