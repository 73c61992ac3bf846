//! The path of a follower's reference point (a knife's tip, a roller's centre): where the
//! first-touch search looks for it, and the roller's warm Newton, which solves for the cam
//! parameter alone where the profile's pitch curve (its outward offset by the roller's radius)
//! crosses that path.

use super::{along_interval, polar_interval, ROUNDING};
use crate::cam::pose::Pose;
use crate::geometry::{rot90, Frame, Point2, Rotation, Vec2};

/// The path of a follower's reference point (knife tip, roller centre). Its coordinate (the
/// length along the line from the cam's axis, or the polar angle about the pivot) is the
/// follower's position `q` plus `lead`: 0 for the named kinds, whose reference point is on the
/// frame's axis; a carried point's place ahead of its frame's origin on a slide, or its polar
/// angle in the arm's frame.
#[derive(Debug, Clone, Copy)]
pub(crate) enum CentrePath {
    /// the line `cam axis + e·p + (q + lead)·d` of a translating follower (`p = rot90(d)`)
    Line { d: Vec2, p: Vec2, e: f64, lead: f64 },
    /// the circle of radius `l` about an arm's pivot `o` (world), at polar angle `q + lead`
    Circle { o: Point2, l: f64, lead: f64 },
}

impl CentrePath {
    /// The interval `(mid, half width)` of the path coordinate (a length along the line, or the
    /// arm angle) of every point within `r` of `c` that lies on the path; `None` when none does.
    pub(crate) fn interval(&self, cam_pivot: Point2, c: Point2, r: f64) -> Option<(f64, f64)> {
        match *self {
            CentrePath::Line { d, p, e, .. } => {
                let (along, half) = along_interval(cam_pivot, d, c, r);
                let lateral = (c - cam_pivot).dot(&p) - e;
                (lateral.abs() <= half).then_some((along, half))
            }
            CentrePath::Circle { o, l, .. } => {
                let rho = (c - o).norm();
                ((rho - l).abs() <= r + ROUNDING * (rho + r)).then(|| polar_interval(o, c, r))
            }
        }
    }
}

impl CentrePath {
    /// The tangent directions `(mid, half width)`, rad, modulo a half turn, of the path near the
    /// points within `r` of `c`: a piece of curve whose tangent avoids them crosses the path at
    /// most once.
    pub(crate) fn tangents(&self, c: Point2, r: f64) -> (f64, f64) {
        match *self {
            CentrePath::Line { d, .. } => (d.y.atan2(d.x), ROUNDING),
            CentrePath::Circle { o, .. } => {
                let (psi, half) = polar_interval(o, c, r);
                (psi + std::f64::consts::FRAC_PI_2, half)
            }
        }
    }
}

/// A point of a profile's pitch curve, the outward offset `c = x + r n` of its point `x` by
/// a roller's radius `r` (`n` the outward unit normal, `−orientation · J x'/|x'|`), and the
/// ratio `1 + r κ` of `c' = (1 + r κ) x'`, where `κ = orientation · (x' × x'')/|x'|³` is the
/// profile's curvature (positive where convex): the offset's tangent is the profile's. The
/// point and its derivatives `(x, x', x'')` in any one frame (the world's, or the cam's own).
#[inline(always)]
pub(crate) fn pitch_point(
    (x, d1, d2): (Point2, Vec2, Vec2),
    r: f64,
    orientation: f64,
) -> (Point2, f64) {
    let s2 = d1.norm_squared();
    let inv = 1.0 / s2.sqrt();
    let ro = r * orientation;
    let c = x - (ro * inv) * rot90(d1);
    let cross = d1.x * d2.y - d1.y * d2.x;
    (c, 1.0 + ro * cross * inv / s2)
}

impl CentrePath {
    /// How far the point `c` is off the path, and the gradient of that in `c`: the lateral
    /// offset `(c − cam axis)·p − e` from the line and `p`; `½(|c − o|² − l²)` for the circle
    /// and `c − o`.
    #[inline(always)]
    pub(crate) fn residual(&self, cam_pivot: Point2, c: Point2) -> (f64, Vec2) {
        match *self {
            CentrePath::Line { p, e, .. } => ((c - cam_pivot).dot(&p) - e, p),
            CentrePath::Circle { o, l, .. } => {
                let y = c - o;
                (0.5 * (y.norm_squared() - l * l), y)
            }
        }
    }

    /// How far the path coordinate moves per unit length the point moves along the path: 1
    /// along the line, `1/l` (rad) about the circle.
    /// The same path seen from a body `frame` (world `= frame · body`), for body-frame points
    /// measured from the frame's origin: [`CentrePath::residual`] of the result at a body point
    /// with `cam_pivot` at the origin equals this path's at the point's world image (the
    /// residual is a distance or a squared distance, unchanged by the frame's rotation). A
    /// Newton iteration on a cam's curve can then skip rotating the curve's derivatives.
    #[inline(always)]
    pub(crate) fn in_body(&self, cam_pivot: Point2, frame: &Frame) -> Self {
        let r = &frame.rotation;
        match *self {
            CentrePath::Line { d, p, e, lead } => CentrePath::Line {
                d: r.inverse_transform_vector(&d),
                p: r.inverse_transform_vector(&p),
                e: e - (Point2::from(frame.translation.vector) - cam_pivot).dot(&p),
                lead,
            },
            CentrePath::Circle { o, l, lead } => CentrePath::Circle {
                o: frame.inverse_transform_point(&o),
                l,
                lead,
            },
        }
    }

    #[inline(always)]
    pub(crate) fn per_length(&self) -> f64 {
        match *self {
            CentrePath::Line { .. } => 1.0,
            CentrePath::Circle { l, .. } => 1.0 / l,
        }
    }

    /// The path coordinate less its lead at the point `c` on the path: the follower's position
    /// (a length along the line from the cam's axis; an arm angle with its sine and cosine,
    /// followed from `near`: see [`Pose::toward`]).
    #[inline(always)]
    pub(crate) fn pose(&self, cam_pivot: Point2, c: Point2, near: Pose) -> Pose {
        match *self {
            CentrePath::Line { d, lead, .. } => Pose::length((c - cam_pivot).dot(&d) - lead),
            CentrePath::Circle { o, lead, .. } => {
                let y = c - o;
                if lead == 0.0 {
                    near.toward(y)
                } else {
                    near.toward(Rotation::new(-lead) * y)
                }
            }
        }
    }

    /// The path coordinate less its lead (see [`CentrePath::pose`]): a length, or an angle
    /// anywhere.
    #[inline]
    pub(crate) fn coordinate(&self, cam_pivot: Point2, c: Point2) -> f64 {
        match *self {
            CentrePath::Line { d, lead, .. } => (c - cam_pivot).dot(&d) - lead,
            CentrePath::Circle { o, lead, .. } => {
                let y = c - o;
                y.y.atan2(y.x) - lead
            }
        }
    }

    /// The path's lead: its coordinate less the follower's position.
    #[inline]
    pub(crate) fn lead(&self) -> f64 {
        match *self {
            CentrePath::Line { lead, .. } | CentrePath::Circle { lead, .. } => lead,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::WorldDerivs;

    /// A path seen from a turned and moved body frame: its residual at a body point is the
    /// world path's at the point's world image, the world image built by hand (cosine and sine
    /// of the frame's angle, not the frame's own transform), for both kinds of path.
    #[test]
    fn path_in_a_body_frame_keeps_the_residual() {
        let pivot = Point2::new(1.5, -0.5);
        let paths = [
            CentrePath::Line {
                d: Vec2::new(0.6, 0.8),
                p: Vec2::new(-0.8, 0.6),
                e: 2.5,
                lead: 0.3,
            },
            CentrePath::Circle {
                o: Point2::new(-3.0, 4.0),
                l: 2.0,
                lead: 0.0,
            },
        ];
        for path in paths {
            for (angle, origin) in [(0.0, pivot), (2.1, pivot), (-0.7, Point2::new(0.4, 2.0))] {
                let frame = Frame::new(origin.coords, angle);
                let body = path.in_body(pivot, &frame);
                let (s, c) = f64::sin_cos(angle);
                for b in [Point2::new(0.3, -1.2), Point2::new(-4.0, 2.5)] {
                    let w = Point2::new(origin.x + c * b.x - s * b.y, origin.y + s * b.x + c * b.y);
                    let (fw, _) = path.residual(pivot, w);
                    let (fb, _) = body.residual(Point2::origin(), b);
                    assert!(
                        (fw - fb).abs() <= 1e-14 * (1.0 + fw.abs()),
                        "{path:?} {angle}: {fw} {fb}"
                    );
                }
            }
        }
    }

    /// On an ellipse (counter-clockwise: orientation 1; clockwise: −1), the pitch point is the
    /// point pushed out along the tangent turned a quarter clockwise (anticlockwise), and its
    /// derivative, by central differences of the pitch points (independent of the curvature
    /// formula), is the stretch times `x'`; on a circle of radius `R` the stretch is `1 + r/R`.
    #[test]
    fn pitch_point_is_the_offset_and_its_derivative_the_stretched_tangent() {
        let (a, b, r) = (5.0, 3.0, 0.7);
        for orientation in [1.0, -1.0] {
            let at = |u: f64| {
                let (s, c) = (orientation * u).sin_cos();
                WorldDerivs {
                    p: Point2::new(a * c, b * s),
                    d1: orientation * Vec2::new(-a * s, b * c),
                    d2: Vec2::new(-a * c, -b * s),
                    d3: orientation * Vec2::new(a * s, -b * c),
                }
            };
            let jet = |u: f64| {
                let e = at(u);
                (e.p, e.d1, e.d2)
            };
            for k in 0..12 {
                let u = 0.1 + 0.5 * f64::from(k);
                let e = at(u);
                let (c, stretch) = pitch_point((e.p, e.d1, e.d2), r, orientation);
                let t = e.d1 / e.d1.norm();
                let out = orientation * Vec2::new(t.y, -t.x);
                assert!((c - (e.p + r * out)).norm() <= 1e-15 * 5.0, "{u}");
                // outward: away from the ellipse's centre
                assert!(out.dot(&e.p.coords) > 0.0);
                let h = 1e-5;
                let fd = (pitch_point(jet(u + h), r, orientation).0
                    - pitch_point(jet(u - h), r, orientation).0)
                    / (2.0 * h);
                assert!(
                    (fd - stretch * e.d1).norm() <= 1e-9 * e.d1.norm(),
                    "{u}: {fd:?}"
                );
            }
        }
        let circle = WorldDerivs {
            p: Point2::new(0.0, 2.0),
            d1: Vec2::new(-2.0, 0.0),
            d2: Vec2::new(0.0, -2.0),
            d3: Vec2::new(2.0, 0.0),
        };
        let (c, stretch) = pitch_point((circle.p, circle.d1, circle.d2), 0.5, 1.0);
        assert!((c - Point2::new(0.0, 2.5)).norm() <= 1e-15);
        assert!((stretch - 1.25).abs() <= 1e-15);
    }

    /// The residuals vanish on the path and grow with the distance from it, with the stated
    /// gradients (by central differences); the position read back is the point's coordinate.
    #[test]
    fn residual_and_pose_on_both_paths() {
        let pivot = Point2::new(1.0, -2.0);
        let d = Vec2::new(0.6, 0.8);
        let line = CentrePath::Line {
            d,
            p: rot90(d),
            e: 0.3,
            lead: 0.0,
        };
        let circle = CentrePath::Circle {
            o: Point2::new(-3.0, 4.0),
            l: 6.0,
            lead: 0.0,
        };
        let on_line = pivot + 0.3 * rot90(d) + 2.5 * d;
        let on_circle = Point2::new(-3.0, 4.0) + 6.0 * Vec2::new(0.4f64.cos(), 0.4f64.sin());
        for (path, on) in [(line, on_line), (circle, on_circle)] {
            assert!(path.residual(pivot, on).0.abs() <= 1e-14);
            for probe in [Point2::new(0.5, 0.2), Point2::new(-2.0, 7.0)] {
                let (_, g) = path.residual(pivot, probe);
                let h = 1e-6;
                let fd = |v: Vec2| {
                    (path.residual(pivot, probe + h * v).0 - path.residual(pivot, probe - h * v).0)
                        / (2.0 * h)
                };
                assert!((fd(Vec2::x()) - g.x).abs() <= 1e-8 * (1.0 + g.norm()));
                assert!((fd(Vec2::y()) - g.y).abs() <= 1e-8 * (1.0 + g.norm()));
            }
        }
        assert!((line.pose(pivot, on_line, Pose::length(0.0)).q - 2.5).abs() <= 1e-15);
        let q = circle.pose(pivot, on_circle, Pose::angle(0.39)).q;
        assert!((q - 0.4).abs() <= 1e-15, "{q}");
        assert_eq!(circle.per_length(), 1.0 / 6.0);
    }
}
