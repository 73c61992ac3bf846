//! Where two pieces of a chain of arcs and lines meet, in closed form: a line with a line (or
//! the stretch they share when collinear), a line with a circle, a circle with a circle (or the
//! arc they share on one circle). [`super::ArcsAndLines::new`] refuses a chain two of whose
//! pieces meet anywhere but at the join they share: a figure of eight, a fold, an overlap.

use super::arcs_and_lines::Piece;
use crate::{Point2, Vec2};
use std::f64::consts::TAU;

fn cross(a: Vec2, b: Vec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The points where `a` and `b` meet (within `tol`, a length): up to two crossings, or the ends
/// and the middle of a stretch they share.
pub(crate) fn meeting_points(a: &Piece, b: &Piece, tol: f64) -> Vec<Point2> {
    match (*a, *b) {
        (Piece::Line { from: p, to: p1 }, Piece::Line { from: q, to: q1 }) => {
            lines(p, p1, q, q1, tol)
        }
        (Piece::Line { from, to }, arc @ Piece::Arc { .. })
        | (arc @ Piece::Arc { .. }, Piece::Line { from, to }) => line_arc(from, to, &arc, tol),
        (Piece::Arc { .. }, Piece::Arc { .. }) => arcs(a, b, tol),
    }
}

/// Whether `x` lies on the segment `p`–`p1` (within `tol` of its ends along it).
fn on_segment(p: Point2, p1: Point2, x: Point2, tol: f64) -> bool {
    let r = p1 - p;
    let t = (x - p).dot(&r) / r.norm_squared();
    let e = tol / r.norm();
    (-e..=1.0 + e).contains(&t)
}

fn lines(p: Point2, p1: Point2, q: Point2, q1: Point2, tol: f64) -> Vec<Point2> {
    let (r, s) = (p1 - p, q1 - q);
    let denom = cross(r, s);
    if denom.abs() > 1e-12 * r.norm() * s.norm() {
        let t = cross(q - p, s) / denom;
        let x = p + t * r;
        return if on_segment(p, p1, x, tol) && on_segment(q, q1, x, tol) {
            vec![x]
        } else {
            vec![]
        };
    }
    // parallel: apart, or on one line sharing a stretch
    if cross(q - p, r).abs() > tol * r.norm() {
        return vec![];
    }
    let along = |x: Point2| (x - p).dot(&r) / r.norm_squared();
    let (u0, u1) = (along(q), along(q1));
    let lo = u0.min(u1).max(0.0);
    let hi = u0.max(u1).min(1.0);
    if (hi - lo) * r.norm() < -tol {
        return vec![];
    }
    let (lo, hi) = (lo.min(hi), hi.max(lo));
    vec![p + lo * r, p + 0.5 * (lo + hi) * r, p + hi * r]
}

/// An arc's centre, radius, start angle and signed sweep.
fn arc_of(a: &Piece) -> (Point2, f64, f64, f64) {
    match *a {
        Piece::Arc {
            centre,
            radius,
            start,
            sweep,
        } => (centre, radius, start, sweep),
        Piece::Line { .. } => unreachable!("an arc"),
    }
}

/// Whether the point at polar angle `angle` about the arc's centre is on the arc (within `tol`,
/// a length).
fn on_arc(arc: &Piece, x: Point2, tol: f64) -> bool {
    let (c, r, start, sweep) = arc_of(arc);
    if sweep.abs() >= TAU {
        return true;
    }
    let angle = (x.y - c.y).atan2(x.x - c.x);
    let rel = ((angle - start) * sweep.signum()).rem_euclid(TAU);
    let e = tol / r;
    rel <= sweep.abs() + e || rel >= TAU - e
}

fn line_arc(p: Point2, p1: Point2, arc: &Piece, tol: f64) -> Vec<Point2> {
    let (c, rad, _, _) = arc_of(arc);
    let r = p1 - p;
    let d = p - c;
    // |d + t r|² = R²
    let a = r.norm_squared();
    let b = d.dot(&r);
    let cc = d.norm_squared() - rad * rad;
    let disc = b * b - a * cc;
    // a line within `tol` of touching the circle touches it
    if disc < -(2.0 * tol * rad) * a {
        return vec![];
    }
    let root = disc.max(0.0).sqrt();
    [(-b - root) / a, (-b + root) / a]
        .into_iter()
        .map(|t| p + t * r)
        .filter(|&x| on_segment(p, p1, x, tol) && on_arc(arc, x, tol))
        .collect()
}

fn arcs(a: &Piece, b: &Piece, tol: f64) -> Vec<Point2> {
    let (c1, r1, s1, w1) = arc_of(a);
    let (c2, r2, s2, w2) = arc_of(b);
    let dv = c2 - c1;
    let d = dv.norm();
    if d <= tol {
        if (r1 - r2).abs() > tol {
            return vec![];
        }
        // one circle: the ends and middles of each on the other
        let at = |c: Point2, r: f64, ang: f64| c + r * Vec2::new(ang.cos(), ang.sin());
        let mut out: Vec<Point2> = [s2, s2 + 0.5 * w2, s2 + w2]
            .into_iter()
            .map(|ang| at(c2, r2, ang))
            .filter(|&x| on_arc(a, x, tol))
            .collect();
        out.extend(
            [s1, s1 + 0.5 * w1, s1 + w1]
                .into_iter()
                .map(|ang| at(c1, r1, ang))
                .filter(|&x| on_arc(b, x, tol)),
        );
        return out;
    }
    if d > r1 + r2 + tol || d < (r1 - r2).abs() - tol {
        return vec![];
    }
    let e = dv / d;
    let along = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
    let h = (r1 * r1 - along * along).max(0.0).sqrt();
    let n = Vec2::new(-e.y, e.x);
    let base = c1 + along * e;
    [base + h * n, base - h * n]
        .into_iter()
        .filter(|&x| on_arc(a, x, tol) && on_arc(b, x, tol))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(a: [f64; 2], b: [f64; 2]) -> Piece {
        Piece::Line {
            from: Point2::new(a[0], a[1]),
            to: Point2::new(b[0], b[1]),
        }
    }

    fn arc(c: [f64; 2], r: f64, start_deg: f64, sweep_deg: f64) -> Piece {
        Piece::Arc {
            centre: Point2::new(c[0], c[1]),
            radius: r,
            start: start_deg.to_radians(),
            sweep: sweep_deg.to_radians(),
        }
    }

    fn near(points: &[Point2], x: f64, y: f64) -> bool {
        points.iter().any(|p| (p.x - x).hypot(p.y - y) < 1e-12)
    }

    #[test]
    fn crossing_lines_meet_once_and_parallel_ones_only_where_they_overlap() {
        let m = meeting_points(
            &line([-1.0, -1.0], [1.0, 1.0]),
            &line([-1.0, 1.0], [1.0, -1.0]),
            1e-9,
        );
        assert_eq!(m.len(), 1);
        assert!(near(&m, 0.0, 0.0));
        // short of each other
        let m = meeting_points(
            &line([0.0, 0.0], [1.0, 0.0]),
            &line([2.0, 1.0], [2.0, -1.0]),
            1e-9,
        );
        assert!(m.is_empty());
        // parallel apart, collinear apart, collinear sharing [1, 2]
        assert!(meeting_points(
            &line([0.0, 0.0], [2.0, 0.0]),
            &line([0.0, 1.0], [2.0, 1.0]),
            1e-9
        )
        .is_empty());
        assert!(meeting_points(
            &line([0.0, 0.0], [1.0, 0.0]),
            &line([2.0, 0.0], [3.0, 0.0]),
            1e-9
        )
        .is_empty());
        let m = meeting_points(
            &line([0.0, 0.0], [2.0, 0.0]),
            &line([3.0, 0.0], [1.0, 0.0]),
            1e-9,
        );
        assert!(
            near(&m, 1.5, 0.0) && near(&m, 1.0, 0.0) && near(&m, 2.0, 0.0),
            "{m:?}"
        );
    }

    /// A line across a circle meets it at `(±√(R² − y²), y)`, on the arc only where the arc is.
    #[test]
    fn a_line_meets_an_arc_where_the_circle_and_the_arc_say() {
        let y: f64 = 3.0;
        let x = (25.0 - y * y).sqrt();
        let across = line([-10.0, y], [10.0, y]);
        let m = meeting_points(&across, &arc([0.0, 0.0], 5.0, 0.0, 180.0), 1e-9);
        assert!(m.len() == 2 && near(&m, x, y) && near(&m, -x, y), "{m:?}");
        // the right quarter only, clockwise from 90° to 0°
        let m = meeting_points(&arc([0.0, 0.0], 5.0, 90.0, -90.0), &across, 1e-9);
        assert!(m.len() == 1 && near(&m, x, y), "{m:?}");
        // the lower half: none
        assert!(meeting_points(&across, &arc([0.0, 0.0], 5.0, 180.0, 180.0), 1e-9).is_empty());
    }

    /// Two circles of radii 5 and 5 with centres 6 apart meet at `(3, ±4)`.
    #[test]
    fn two_arcs_meet_where_their_circles_do_and_one_circle_where_its_arcs_overlap() {
        let m = meeting_points(
            &arc([0.0, 0.0], 5.0, -90.0, 180.0),
            &arc([6.0, 0.0], 5.0, 90.0, 180.0),
            1e-9,
        );
        assert!(
            m.len() == 2 && near(&m, 3.0, 4.0) && near(&m, 3.0, -4.0),
            "{m:?}"
        );
        let m = meeting_points(
            &arc([0.0, 0.0], 5.0, -90.0, 180.0),
            &arc([6.0, 0.0], 5.0, -90.0, 180.0),
            1e-9,
        );
        assert!(m.is_empty(), "{m:?}");
        // one circle, 0°–90° and 45°–135°: they share 45°–90°
        let m = meeting_points(
            &arc([0.0, 0.0], 5.0, 0.0, 90.0),
            &arc([0.0, 0.0], 5.0, 45.0, 90.0),
            1e-9,
        );
        assert!(near(&m, 0.0, 5.0), "{m:?}");
        let m = meeting_points(
            &arc([0.0, 0.0], 5.0, 0.0, 90.0),
            &arc([0.0, 0.0], 5.0, 180.0, 90.0),
            1e-9,
        );
        assert!(m.is_empty(), "{m:?}");
    }
}
