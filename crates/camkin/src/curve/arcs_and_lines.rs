//! A closed profile of circular arcs and straight lines, exact (no spline between them):
//! the classic cams of the textbooks — the tangent cam (base circle, straight flanks, nose
//! circle) and the circular-arc cam (base circle, convex circular flanks, nose circle) — and any
//! other chain of arcs and lines, joined tangentially or at corners.
//!
//! The parameter is the arc length from the chain's start, counter-clockwise round the
//! profile (the cam's material on the left), periodic with the perimeter. On an arc of radius
//! `ρ` about `c`, turning with sense `s` (+1 counter-clockwise: convex; −1: concave),
//! `r = c + ρ (cos φ, sin φ)` with `φ = φ₀ + s u/ρ`: `r' = t`, `r'' = (s/ρ) k × t`,
//! `r''' = −t/ρ²`; on a line `r' = t`, `r'' = r''' = 0`. The curvature jumps at the joins
//! ([`Curve::breakpoints`]); the tangent turns at a corner.

use super::{Curve, Derivs, Domain};
use crate::geometry::{Point2, Vec2};
use std::f64::consts::PI;

/// One piece of the chain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Piece {
    /// a straight line from `from` to `to`
    Line {
        /// where it starts
        from: Point2,
        /// where it ends
        to: Point2,
    },
    /// a circular arc about `centre` of `radius`, from the polar angle `start` (rad) turning by
    /// `sweep` (rad; positive counter-clockwise: convex on a counter-clockwise profile)
    Arc {
        /// its centre
        centre: Point2,
        /// its radius
        radius: f64,
        /// the polar angle of its start about the centre, rad
        start: f64,
        /// the signed angle it turns, rad
        sweep: f64,
    },
}

impl Piece {
    /// Its length.
    pub fn length(&self) -> f64 {
        match *self {
            Piece::Line { from, to } => (to - from).norm(),
            Piece::Arc { radius, sweep, .. } => radius * sweep.abs(),
        }
    }

    /// Where it starts and ends.
    pub fn ends(&self) -> (Point2, Point2) {
        match *self {
            Piece::Line { from, to } => (from, to),
            Piece::Arc {
                centre,
                radius,
                start,
                sweep,
            } => {
                let at = |a: f64| centre + radius * Vec2::new(a.cos(), a.sin());
                (at(start), at(start + sweep))
            }
        }
    }

    /// A box holding it, grown by `pad`: (lower left, upper right). An arc's is its circle's.
    fn bounds(&self, pad: f64) -> (Point2, Point2) {
        let (lo, hi) = match *self {
            Piece::Line { from, to } => (
                Point2::new(from.x.min(to.x), from.y.min(to.y)),
                Point2::new(from.x.max(to.x), from.y.max(to.y)),
            ),
            Piece::Arc { centre, radius, .. } => (
                centre - Vec2::new(radius, radius),
                centre + Vec2::new(radius, radius),
            ),
        };
        (lo - Vec2::new(pad, pad), hi + Vec2::new(pad, pad))
    }

    /// Its unit tangent at its start and at its end (the direction of travel).
    pub fn tangents(&self) -> (Vec2, Vec2) {
        match *self {
            Piece::Line { from, to } => {
                let t = (to - from).normalize();
                (t, t)
            }
            Piece::Arc { start, sweep, .. } => {
                let s = sweep.signum();
                let t = |a: f64| s * Vec2::new(-a.sin(), a.cos());
                (t(start), t(start + sweep))
            }
        }
    }

    /// Its signed curvature (1/length; 0 on a line).
    pub fn curvature(&self) -> f64 {
        match *self {
            Piece::Line { .. } => 0.0,
            Piece::Arc { radius, sweep, .. } => sweep.signum() / radius,
        }
    }

    /// The piece at arc length `u` from its start.
    fn eval(&self, u: f64) -> Derivs {
        match *self {
            Piece::Line { from, to } => {
                let t = (to - from) / (to - from).norm();
                Derivs {
                    p: from + u * t,
                    d1: t,
                    d2: Vec2::zeros(),
                    d3: Vec2::zeros(),
                }
            }
            Piece::Arc {
                centre,
                radius,
                start,
                sweep,
            } => {
                let s = sweep.signum();
                let a = start + s * u / radius;
                let (sn, cs) = a.sin_cos();
                let radial = Vec2::new(cs, sn);
                let t = s * Vec2::new(-sn, cs);
                Derivs {
                    p: centre + radius * radial,
                    d1: t,
                    d2: -radial / radius,
                    d3: -t / (radius * radius),
                }
            }
        }
    }
}

/// Why a chain of arcs and lines is not a profile.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ArcsError {
    /// Fewer than two pieces.
    #[error("a closed profile needs at least two pieces, got {count}")]
    TooFew {
        /// the pieces given
        count: usize,
    },
    /// A piece of no length, or not finite.
    #[error("piece {index} has no length or is not finite (length {})", crate::human::human(*.length))]
    Degenerate {
        /// its index
        index: usize,
        /// its length
        length: f64,
    },
    /// A piece does not start where the one before it ends.
    #[error("piece {index} starts {} away from where piece {previous} ends: the pieces do not join (at most {} allowed)", crate::human::human(*.gap), crate::human::human(*.tolerance))]
    Gap {
        /// the piece's index
        index: usize,
        /// the one before it
        previous: usize,
        /// the distance between the ends
        gap: f64,
        /// the largest gap taken as a join (1e-9 of the profile's size)
        tolerance: f64,
    },
    /// Two pieces meet somewhere other than the join they share: the chain crosses itself (a
    /// figure of eight), folds back, or runs over itself.
    #[error("pieces {first} and {second} meet at ({}, {}), not at a join they share: the profile crosses or overlaps itself (a figure of eight, a fold); a cam's outline must be a simple closed curve", crate::human::human(.at.x), crate::human::human(.at.y))]
    Crosses {
        /// the earlier piece's index
        first: usize,
        /// the later piece's index
        second: usize,
        /// a point where they meet
        at: Point2,
    },
    /// A textbook cam's parameters that make no cam.
    #[error("{0}")]
    Preset(String),
}

/// A closed chain of arcs and lines (see the module's docs).
#[derive(Debug, Clone, PartialEq)]
pub struct ArcsAndLines {
    pieces: Vec<Piece>,
    /// the arc length at each piece's start, and the perimeter last
    starts: Vec<f64>,
}

/// A join of two pieces: where it is and what jumps there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Join {
    /// the parameter (arc length) of the join
    pub param: f64,
    /// the index of the piece that starts there
    pub piece: usize,
    /// the angle the tangent turns there, rad (0: a tangent join; a corner otherwise)
    pub turn: f64,
    /// the radius of curvature before and after it (∞ on a line; negative: concave)
    pub radius: [f64; 2],
}

impl ArcsAndLines {
    /// The chain of `pieces`, each starting where the one before it ends (the first where the
    /// last ends), within 1e-9 of the profile's size.
    pub fn new(pieces: Vec<Piece>) -> Result<Self, ArcsError> {
        if pieces.len() < 2 {
            return Err(ArcsError::TooFew {
                count: pieces.len(),
            });
        }
        let mut size = 0.0f64;
        for (index, p) in pieces.iter().enumerate() {
            let length = p.length();
            let (a, b) = p.ends();
            if !(length > 0.0 && length.is_finite() && a.coords.norm().is_finite()) {
                return Err(ArcsError::Degenerate { index, length });
            }
            size = size.max(a.coords.norm()).max(b.coords.norm());
        }
        let tolerance = 1e-9 * size;
        let n = pieces.len();
        for index in 0..n {
            let previous = (index + n - 1) % n;
            let gap = (pieces[index].ends().0 - pieces[previous].ends().1).norm();
            if !(gap <= tolerance) {
                return Err(ArcsError::Gap {
                    index,
                    previous,
                    gap,
                    tolerance,
                });
            }
        }
        Self::simple(&pieces, size)?;
        let mut starts = Vec::with_capacity(n + 1);
        let mut at = 0.0;
        for p in &pieces {
            starts.push(at);
            at += p.length();
        }
        starts.push(at);
        Ok(Self { pieces, starts })
    }

    /// Refuses a chain two of whose pieces meet anywhere but at the join they share (found in
    /// closed form, [`super::piece_crossings`]); neighbours' joins are left out within 1e-6 of
    /// `size` (a tangent join's double root is found only to about `√ε`). Pairs whose boxes do
    /// not overlap are skipped: at the 10 000 pieces a file may have, 5e7 box tests.
    fn simple(pieces: &[Piece], size: f64) -> Result<(), ArcsError> {
        let n = pieces.len();
        let tol = 1e-9 * size;
        let join = 1e-6 * size;
        let boxes: Vec<(Point2, Point2)> = pieces.iter().map(|p| p.bounds(tol)).collect();
        for i in 0..n {
            for j in i + 1..n {
                let (a, b) = (boxes[i], boxes[j]);
                if a.1.x < b.0.x || b.1.x < a.0.x || a.1.y < b.0.y || b.1.y < a.0.y {
                    continue;
                }
                // the joins the two share: i's end (j next), j's end (i first, j last)
                let mut shared: Vec<Point2> = Vec::with_capacity(2);
                if j == i + 1 {
                    shared.push(pieces[i].ends().1);
                }
                if i == 0 && j == n - 1 {
                    shared.push(pieces[0].ends().0);
                }
                let met = super::piece_crossings::meeting_points(&pieces[i], &pieces[j], tol);
                if let Some(&at) = met
                    .iter()
                    .find(|x| shared.iter().all(|s| (*x - s).norm() > join))
                {
                    return Err(ArcsError::Crosses {
                        first: i,
                        second: j,
                        at,
                    });
                }
            }
        }
        Ok(())
    }

    /// The pieces.
    pub fn pieces(&self) -> &[Piece] {
        &self.pieces
    }

    /// The perimeter (the parameter's period).
    pub fn perimeter(&self) -> f64 {
        self.starts[self.pieces.len()]
    }

    /// Every join, with the tangent's turn and the radius of curvature on either side.
    pub fn joins(&self) -> Vec<Join> {
        let n = self.pieces.len();
        (0..n)
            .map(|k| {
                let before = &self.pieces[(k + n - 1) % n];
                let after = &self.pieces[k];
                let (t0, t1) = (before.tangents().1, after.tangents().0);
                let radius = |p: &Piece| {
                    let c = p.curvature();
                    if c == 0.0 {
                        f64::INFINITY
                    } else {
                        1.0 / c
                    }
                };
                Join {
                    param: self.starts[k],
                    piece: k,
                    turn: crate::geometry::cross(t0, t1).atan2(t0.dot(&t1)),
                    radius: [radius(before), radius(after)],
                }
            })
            .collect()
    }

    /// The textbook **tangent cam**: a base circle of radius `base` about the origin, a nose
    /// circle of radius `nose` whose centre is on +x at `lift + base − nose`, and two straight
    /// flanks tangent to both (the lift is the nose's farthest point less the base radius).
    pub fn tangent_cam(base: f64, nose: f64, lift: f64) -> Result<Self, ArcsError> {
        let d = check_preset(base, nose, lift)?;
        // the flanks' normals at ±ψ from +x: cos ψ = (base − nose)/d
        let psi = ((base - nose) / d).acos();
        let c = Point2::new(d, 0.0);
        let polar = |o: Point2, r: f64, a: f64| o + r * Vec2::new(a.cos(), a.sin());
        Self::new(vec![
            // the base circle from the upper flank's foot round the back to the lower one's
            Piece::Arc {
                centre: Point2::origin(),
                radius: base,
                start: psi,
                sweep: 2.0 * (PI - psi),
            },
            Piece::Line {
                from: polar(Point2::origin(), base, -psi),
                to: polar(c, nose, -psi),
            },
            Piece::Arc {
                centre: c,
                radius: nose,
                start: -psi,
                sweep: 2.0 * psi,
            },
            Piece::Line {
                from: polar(c, nose, psi),
                to: polar(Point2::origin(), base, psi),
            },
        ])
    }

    /// The textbook **circular-arc cam**: the tangent cam's base and nose circles joined by
    /// convex circular flanks of radius `flank` tangent to both (each flank's centre on the far
    /// side of the cam's axis, `flank − base` from it and `flank − nose` from the nose's centre).
    pub fn circular_arc_cam(
        base: f64,
        nose: f64,
        lift: f64,
        flank: f64,
    ) -> Result<Self, ArcsError> {
        let d = check_preset(base, nose, lift)?;
        if !(flank.is_finite() && flank > base) {
            return Err(ArcsError::Preset(format!(
                "a circular-arc cam's flank radius ({flank}) must be larger than its base radius ({base})"
            )));
        }
        // the upper flank's centre F = (fx, −fy): |F| = flank − base, |F − C| = flank − nose
        let (a, b) = (flank - base, flank - nose);
        let fx = (a * a - b * b + d * d) / (2.0 * d);
        let fy2 = a * a - fx * fx;
        if !(fy2 > 0.0) {
            return Err(ArcsError::Preset(format!(
                "a flank of radius {flank} cannot touch both the base circle ({base}) and the nose ({nose} at {d}): make it larger"
            )));
        }
        let fy = fy2.sqrt();
        let c = Point2::new(d, 0.0);
        // the tangent points: on the line from F through each circle's centre
        let upper = Point2::new(fx, -fy);
        let lower = Point2::new(fx, fy);
        let angle = |from: Point2, to: Point2| (to - from).y.atan2((to - from).x);
        // base: from the upper flank's foot round the back to the lower flank's
        let base_up = angle(upper, Point2::origin());
        let base_low = angle(lower, Point2::origin());
        let nose_up = angle(upper, c);
        let nose_low = angle(lower, c);
        let ccw = |from: f64, to: f64| (to - from).rem_euclid(2.0 * PI);
        Self::new(vec![
            Piece::Arc {
                centre: Point2::origin(),
                radius: base,
                start: base_up,
                sweep: ccw(base_up, base_low),
            },
            // the lower flank, about the lower flank's centre (above the axis)
            Piece::Arc {
                centre: lower,
                radius: flank,
                start: base_low,
                sweep: ccw(base_low, nose_low),
            },
            Piece::Arc {
                centre: c,
                radius: nose,
                start: nose_low,
                sweep: ccw(nose_low, nose_up),
            },
            Piece::Arc {
                centre: upper,
                radius: flank,
                start: nose_up,
                sweep: ccw(nose_up, base_up),
            },
        ])
    }

    fn piece_at(&self, u: f64) -> (usize, f64) {
        let n = self.pieces.len();
        let per = self.perimeter();
        let u = if (0.0..per).contains(&u) {
            u
        } else {
            u.rem_euclid(per)
        };
        let k = self.starts[..n]
            .partition_point(|&s| s <= u)
            .saturating_sub(1);
        (k, u - self.starts[k])
    }
}

/// A tangent or circular-arc cam's `(base, nose, lift)` checked: the nose centre's distance.
fn check_preset(base: f64, nose: f64, lift: f64) -> Result<f64, ArcsError> {
    let ok = |x: f64| x.is_finite() && x > 0.0;
    if !(ok(base) && ok(nose) && ok(lift)) {
        return Err(ArcsError::Preset(format!(
            "base radius ({base}), nose radius ({nose}) and lift ({lift}) must be positive"
        )));
    }
    if !(nose < base) {
        return Err(ArcsError::Preset(format!(
            "the nose radius ({nose}) must be smaller than the base radius ({base})"
        )));
    }
    // the nose circle's centre, beyond the base circle's edge less the nose
    Ok(lift + base - nose)
}

impl Curve for ArcsAndLines {
    fn as_arcs_and_lines(&self) -> Option<&ArcsAndLines> {
        Some(self)
    }
    fn eval(&self, u: f64) -> Derivs {
        let (k, s) = self.piece_at(u);
        self.pieces[k].eval(s)
    }
    fn domain(&self) -> Domain {
        Domain::Periodic {
            period: self.perimeter(),
        }
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.starts[..self.pieces.len()].to_vec()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::test_support::check_derivatives;

    #[test]
    fn the_tangent_cam_closes_tangentially_with_its_textbook_dimensions() {
        let cam = ArcsAndLines::tangent_cam(20.0, 8.0, 12.0).unwrap();
        // the nose's farthest point is base + lift from the axis
        let far = (0..4000)
            .map(|k| {
                cam.position(cam.perimeter() * f64::from(k) / 4000.0)
                    .coords
                    .norm()
            })
            .fold(0.0f64, f64::max);
        assert!((far - 32.0).abs() < 1e-4, "{far}");
        for j in cam.joins() {
            assert!(j.turn.abs() < 1e-12, "a tangent join: {j:?}");
        }
        // the flanks' radius is infinite, the arcs' their own
        let radii: Vec<[f64; 2]> = cam.joins().iter().map(|j| j.radius).collect();
        assert_eq!(radii[1], [20.0, f64::INFINITY]);
        assert_eq!(radii[2], [f64::INFINITY, 8.0]);
        for k in 0..50 {
            let u = cam.perimeter() * (f64::from(k) + 0.37) / 50.0;
            check_derivatives(&cam, u, 1e-7);
        }
    }

    #[test]
    fn the_circular_arc_cam_closes_tangentially_and_refuses_a_short_flank() {
        let cam = ArcsAndLines::circular_arc_cam(20.0, 8.0, 12.0, 60.0).unwrap();
        for j in cam.joins() {
            assert!(j.turn.abs() < 1e-12, "a tangent join: {j:?}");
            assert!(j.radius[0] > 0.0 && j.radius[1] > 0.0, "convex: {j:?}");
        }
        for k in 0..50 {
            let u = cam.perimeter() * (f64::from(k) + 0.37) / 50.0;
            check_derivatives(&cam, u, 1e-7);
        }
        assert!(ArcsAndLines::circular_arc_cam(20.0, 8.0, 12.0, 15.0).is_err());
        assert!(ArcsAndLines::tangent_cam(8.0, 20.0, 12.0).is_err());
        assert!(ArcsAndLines::tangent_cam(20.0, 8.0, -1.0).is_err());
    }

    /// A bow tie (its diagonals cross at the origin), a line folding back over the one before,
    /// and a circle's two halves sharing a quarter are refused, naming the pieces and a point
    /// where they meet; a tangent cam's and a D's neighbours meeting only at their joins are
    /// not.
    #[test]
    fn a_chain_that_crosses_or_overlaps_itself_is_refused() {
        let l = |a: [f64; 2], b: [f64; 2]| Piece::Line {
            from: Point2::new(a[0], a[1]),
            to: Point2::new(b[0], b[1]),
        };
        let bow = vec![
            l([-1.0, -1.0], [2.0, 2.0]),
            l([2.0, 2.0], [2.0, -2.0]),
            l([2.0, -2.0], [-1.0, 1.0]),
            l([-1.0, 1.0], [-1.0, -1.0]),
        ];
        match ArcsAndLines::new(bow) {
            Err(ArcsError::Crosses { first, second, at }) => {
                assert_eq!((first, second), (0, 2));
                assert!(at.coords.norm() < 1e-12, "{at}");
            }
            other => panic!("{other:?}"),
        }
        // out along x, back past the start, then round to it: the second line runs over the first
        let fold = vec![
            l([0.0, 0.0], [2.0, 0.0]),
            l([2.0, 0.0], [-1.0, 0.0]),
            l([-1.0, 0.0], [0.0, 1.0]),
            l([0.0, 1.0], [0.0, 0.0]),
        ];
        assert!(matches!(
            ArcsAndLines::new(fold),
            Err(ArcsError::Crosses {
                first: 0,
                second: 1,
                ..
            })
        ));
        // a circle's upper half, then on round one and a half turns to its start: over the first
        let arc = |start: f64, sweep: f64| Piece::Arc {
            centre: Point2::origin(),
            radius: 1.0,
            start: start.to_radians(),
            sweep: sweep.to_radians(),
        };
        assert!(matches!(
            ArcsAndLines::new(vec![arc(0.0, 180.0), arc(180.0, 540.0)]),
            Err(ArcsError::Crosses { .. })
        ));
        assert!(ArcsAndLines::tangent_cam(20.0, 7.0, 10.0).is_ok());
        let d = vec![arc(0.0, 180.0), l([-1.0, 0.0], [1.0, 0.0])];
        assert!(ArcsAndLines::new(d).is_ok());
    }

    #[test]
    fn pieces_that_do_not_join_are_refused_and_a_corner_is_reported() {
        let sq = |a: (f64, f64), b: (f64, f64)| Piece::Line {
            from: Point2::new(a.0, a.1),
            to: Point2::new(b.0, b.1),
        };
        // a square: four corners of a quarter turn
        let square = ArcsAndLines::new(vec![
            sq((0.0, 0.0), (1.0, 0.0)),
            sq((1.0, 0.0), (1.0, 1.0)),
            sq((1.0, 1.0), (0.0, 1.0)),
            sq((0.0, 1.0), (0.0, 0.0)),
        ])
        .unwrap();
        for j in square.joins() {
            assert!((j.turn - PI / 2.0).abs() < 1e-15, "{j:?}");
        }
        let open = ArcsAndLines::new(vec![
            sq((0.0, 0.0), (1.0, 0.0)),
            sq((1.0, 0.0), (1.0, 1.0)),
            sq((1.0, 1.001), (0.0, 0.0)),
        ]);
        assert!(
            matches!(
                open,
                Err(ArcsError::Gap {
                    index: 2,
                    previous: 1,
                    ..
                })
            ),
            "{open:?}"
        );
    }
}
