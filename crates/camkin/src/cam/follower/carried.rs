//! A follower that carries any curve: a joint (slide or pivot) and a curve in the follower's frame.
//!
//! The five named kinds have closed forms of their first touch; a carried curve does not. Its
//! first touch is found from **coverage**: for every sampled cam point, the follower positions at
//! which that point lies inside the follower's material (from the crossings of a dense polyline
//! of the follower's curve with the line, or circle about the pivot, on which the cam point moves
//! relative to the follower). The follower rests at the end, in its closing sense, of the free
//! gap between covered positions: the gap beyond every covered position for a slide (it comes
//! from `s = +∞`), the gap that holds the arm pointing away from the cam for a pivot, or for a
//! gear-like curve (rotational symmetry `z > 1`) the gap nearest the angle predicted by the
//! nominal ratio. Newton on the exact tangency (`x_A(u) = x_B(v, q)`, tangents parallel) refines
//! it; a contact is accepted when no sampled cam point lies inside the follower there by more than
//! the polyline's chord error (see `crate::cam::carried`).
//!
//! The polyline's frame is the follower frame; a translating follower's curve is given with its
//! x axis along the direction of travel and turned here into the world-aligned follower frame the
//! joint moves.

use super::envelope::Envelope;
use super::{FollowerJoint, Kind, Model, Rates, Sense, Synthesis};
use crate::body::WorldDerivs;
use crate::cam::CamError;
use crate::curve::{Curve, Derivs, Domain};
use crate::field::{Field, FollowerField};
use crate::geometry::{rot90, Point2, Rotation, UnitVec2, Vec2};
use crate::jet::{Num, V2};
use std::sync::Arc;

/// A carried curve's joint: the `Kind` of a follower carrying any curve. Its first touch is not
/// found through `Kind` (see `crate::cam::carried`): only the joint is used from here.
#[derive(Debug, Clone, Copy)]
pub(crate) struct CarriedJoint {
    pub(crate) joint: FollowerJoint,
}

impl Kind for CarriedJoint {
    fn joint(&self) -> FollowerJoint {
        self.joint
    }
    fn curve(&self) -> super::FollowerCurve {
        // never used: `Geometry::new` takes the carried curve itself
        super::FollowerCurve::Point(
            crate::curve::PointCurve::new(Point2::origin()).expect("the origin is finite"),
        )
    }
    fn score(&self, _x: Point2) -> Option<(f64, f64)> {
        None
    }
    fn residual_value<T: Num>(&self, _x: V2<T>, _x1: V2<T>, _q: T) -> [T; 2] {
        [T::c(f64::NAN), T::c(f64::NAN)]
    }
    fn jacobian(&self, _e: &WorldDerivs, _q: &crate::cam::pose::Pose) -> [[f64; 2]; 2] {
        [[f64::NAN; 2]; 2]
    }
    fn toward_follower(&self, _c: Point2, _q: &crate::cam::pose::Pose) -> Vec2 {
        Vec2::zeros()
    }
    fn concave_limit(&self) -> Option<f64> {
        None
    }
}

/// No closed-form rates: the paper's method gives them.
impl Rates for CarriedJoint {}

impl Synthesis for CarriedJoint {
    fn synthesis_start(&self, _base_radius: f64) -> Result<f64, CamError> {
        Err(CamError::Invalid {
            field: Field::Follower(FollowerField::Kind),
            value: f64::NAN,
            reason: "a profile can be synthesised for the five named follower kinds only",
        })
    }
    fn envelope(&self, _s: &[f64; 5], _s0: f64, _u: f64, _sigma: f64, _rot: &Rotation) -> Envelope {
        Envelope::Derivs(Derivs {
            p: Point2::origin(),
            d1: Vec2::zeros(),
            d2: Vec2::zeros(),
            d3: Vec2::zeros(),
        })
    }
}

impl CarriedJoint {
    pub(super) fn translating(cam_pivot: Point2, d: UnitVec2, offset: f64) -> Model {
        Model::Carried(Self {
            joint: FollowerJoint::slide(cam_pivot + offset * rot90(*d), d),
        })
    }
    pub(super) fn rotating(cam_pivot: Point2, o: Point2, closing: Sense, phi0: f64) -> Model {
        Model::Carried(Self {
            joint: FollowerJoint::arm(o, closing, phi0, super::toward(cam_pivot, o)),
        })
    }
}

/// A curve turned by a fixed rotation (a translating follower's curve, given along its
/// direction of travel, in the world-aligned follower frame).
#[derive(Debug)]
pub(crate) struct Turned {
    curve: Arc<dyn Curve>,
    rot: Rotation,
}

impl Curve for Turned {
    fn eval(&self, u: f64) -> Derivs {
        let d = self.curve.eval(u);
        let r = &self.rot;
        Derivs {
            p: Point2::from(r * d.p.coords),
            d1: r * d.d1,
            d2: r * d.d2,
            d3: r * d.d3,
        }
    }
    fn domain(&self) -> Domain {
        self.curve.domain()
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.curve.breakpoints()
    }
    fn symmetry(&self) -> u32 {
        self.curve.symmetry()
    }
}

/// A crossing of the follower's polyline with a level: where along, the curve's parameter there
/// and whether moving in `+along` enters the follower's material.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Crossing {
    pub(crate) along: f64,
    pub(crate) v: f64,
    pub(crate) entering: bool,
}

/// A stretch `[(from, v_from), (to, v_to)]` of `along` inside the follower's material.
pub(crate) type Stretch = ((f64, f64), (f64, f64));

/// The carried curve with its polyline and an index of the polyline's segments by level.
#[derive(Debug)]
pub(crate) struct Carried {
    /// the curve in the follower frame
    pub(crate) curve: Arc<dyn Curve>,
    /// the joint that carries it: a cam point moves along its track ([`FollowerJoint::along`]) at its
    /// level
    pub(crate) joint: FollowerJoint,
    /// the curve's period (closed curves)
    pub(crate) period: Option<f64>,
    /// parameter bounds of an open curve (the sampled stretch of an unbounded one)
    pub(crate) bounds: (f64, f64),
    /// the rotational symmetry `z` (a gear's teeth)
    pub(crate) symmetry: u32,
    /// polyline vertices: point (follower frame), parameter, `(along, level)`
    verts: Vec<(Vec2, f64, (f64, f64))>,
    closed: bool,
    buckets: Vec<Vec<u32>>,
    level_lo: f64,
    bucket_width: f64,
    /// the largest distance between the curve and its polyline (midpoints of the segments)
    pub(crate) chord_error: f64,
    /// the curve's corners and the samples to measure a depth inside the follower from
    pub(crate) corners: crate::cam::corners::Corners,
    /// the parameters where the curve's pieces meet (sorted): its third derivative, and with it
    /// the follower's jerk, jumps there
    pub(crate) breakpoints: Vec<f64>,
    /// the smallest and largest level of the polyline
    pub(crate) level_range: (f64, f64),
    /// for a curve of symmetry `z > 1` on an arm: `(2π/z, period/z)`, the turn and the shift of
    /// the parameter from one tooth to the next. Its crossings are then those of one tooth's
    /// stretch of the polyline (the first `1/z` of its segments) and the stretches inside
    /// are taken round that tooth's turn, not the whole turn: the others are the same turned by
    /// multiples of `2π/z`.
    pub(crate) sector: Option<(f64, f64)>,
    /// a closed curve's bounding circle (follower frame: centre, radius, the chord error
    /// included): its material lies within it
    pub(crate) hull: Option<(Point2, f64)>,
}

/// `(2π/z, period/z)` when the closed polyline `verts` of a curve of symmetry `z > 1` (on an
/// arm) repeats tooth by tooth: as many vertices a tooth, each the one a tooth before turned by
/// `2π/z` (to 1e-9 of the curve's size) with its parameter shifted by `period/z`.
fn tooth_sector(
    verts: &[(Vec2, f64, (f64, f64))],
    symmetry: u32,
    period: Option<f64>,
) -> Option<(f64, f64)> {
    let (z, period) = (symmetry as usize, period?);
    if z < 2 || verts.len() % z != 0 {
        return None;
    }
    let (turn, shift) = (std::f64::consts::TAU / z as f64, period / z as f64);
    let m = verts.len() / z;
    let size = verts.iter().map(|v| v.0.norm()).fold(0.0, f64::max);
    let rot = Rotation::new(turn);
    let repeats = (0..verts.len() - m).all(|i| {
        let (a, b) = (&verts[i], &verts[i + m]);
        (rot * a.0 - b.0).norm() <= 1e-9 * size && (a.1 + shift - b.1).abs() <= 1e-9 * period
    });
    repeats.then_some((turn, shift))
}

/// Polyline vertices per smooth piece, and over a curve without breakpoints.
const PER_PIECE: usize = 48;
const PER_CURVE: usize = 1024;

impl Carried {
    /// Samples `curve` (given in the follower frame of `joint`; a translating follower's is turned
    /// first) and indexes it. `reach` bounds the stretch of an unbounded curve that is sampled.
    pub(crate) fn new(
        curve: Arc<dyn Curve>,
        joint: &FollowerJoint,
        reach: f64,
    ) -> Result<Self, CamError> {
        let joint = *joint;
        // a slide's curve turned into the world-aligned follower frame
        let angle = joint.direction().map_or(0.0, |d| d.y.atan2(d.x));
        let curve: Arc<dyn Curve> = if angle == 0.0 {
            curve
        } else {
            Arc::new(Turned {
                curve,
                rot: Rotation::new(angle),
            })
        };
        let bad = |reason: &'static str| CamError::Invalid {
            field: Field::Follower(FollowerField::Profile),
            value: f64::NAN,
            reason,
        };
        let (period, bounds, params): (Option<f64>, (f64, f64), Vec<f64>) = match curve.domain() {
            Domain::Periodic { period } => {
                let bp = curve.breakpoints();
                (
                    Some(period),
                    (0.0, period),
                    crate::curve::piece_samples(&bp, period, PER_PIECE, PER_CURVE).collect(),
                )
            }
            Domain::Interval { min, max } => {
                // an unbounded curve (a line) is sampled over the stretch that can meet the cam
                let (lo, hi) = (min.max(-reach), max.min(reach));
                if !(lo < hi) {
                    return Err(bad("the follower's curve does not come near the cam"));
                }
                let n = PER_CURVE;
                (
                    None,
                    (lo, hi),
                    (0..=n)
                        .map(|k| lo + (hi - lo) * k as f64 / n as f64)
                        .collect(),
                )
            }
            Domain::Point => return Err(bad(
                "a point carried by a follower is a knife edge: use kind = \"translating-knife\"",
            )),
        };
        let verts: Vec<(Vec2, f64, (f64, f64))> = params
            .iter()
            .map(|&v| {
                let y = curve.position(v).coords;
                (y, v, (joint.along(y), joint.level(y)))
            })
            .collect();
        if verts
            .iter()
            .any(|(y, ..)| !(y.x.is_finite() && y.y.is_finite()))
        {
            return Err(bad("the follower's curve has a point that is not finite"));
        }
        let closed = period.is_some();
        let nseg = if closed { verts.len() } else { verts.len() - 1 };
        let seg = |i: usize| (i, (i + 1) % verts.len());
        let mut chord_error: f64 = 0.0;
        for i in 0..nseg {
            let (a, b) = seg(i);
            let vb = if b == 0 {
                period.unwrap_or(0.0) + verts[0].1
            } else {
                verts[b].1
            };
            let mid = curve.position(0.5 * (verts[a].1 + vb)).coords;
            let (pa, pb) = (verts[a].0, verts[b].0);
            let t = pb - pa;
            let len = t.norm();
            let dist = if len > 0.0 {
                crate::geometry::cross(t, mid - pa).abs() / len
            } else {
                (mid - pa).norm()
            };
            chord_error = chord_error.max(dist);
        }
        let lo = verts.iter().map(|v| v.2 .1).fold(f64::INFINITY, f64::min);
        let hi = verts
            .iter()
            .map(|v| v.2 .1)
            .fold(f64::NEG_INFINITY, f64::max);
        let symmetry = if joint.is_rotating() {
            curve.symmetry().max(1)
        } else {
            1
        };
        let sector = tooth_sector(&verts, symmetry, period);
        // one tooth's segments when the polyline repeats tooth by tooth
        let indexed = match sector {
            Some(_) => nseg / symmetry as usize,
            None => nseg,
        };
        let nb = indexed.clamp(1, 1 << 16);
        let width = ((hi - lo) / nb as f64).max(f64::MIN_POSITIVE);
        let mut buckets = vec![Vec::new(); nb];
        let bucket = |l: f64| (((l - lo) / width) as usize).min(nb - 1);
        for i in 0..indexed {
            let (a, b) = seg(i);
            let (la, lb) = (verts[a].2 .1, verts[b].2 .1);
            for b in &mut buckets[bucket(la.min(lb))..=bucket(la.max(lb))] {
                b.push(i as u32);
            }
        }
        let corners = crate::cam::corners::Corners::of(curve.as_ref(), &params);
        let hull = closed.then(|| {
            let (mut lo, mut hi) = (verts[0].0, verts[0].0);
            for (y, ..) in &verts {
                lo = lo.inf(y);
                hi = hi.sup(y);
            }
            let centre = Point2::from(0.5 * (lo + hi));
            let radius = verts
                .iter()
                .map(|(y, ..)| (Point2::from(*y) - centre).norm())
                .fold(0.0, f64::max);
            (centre, radius + chord_error)
        });
        let mut breakpoints = curve.breakpoints();
        breakpoints.sort_by(f64::total_cmp);
        Ok(Self {
            breakpoints,
            curve,
            joint,
            period,
            bounds,
            symmetry,
            verts,
            closed,
            buckets,
            level_lo: lo,
            bucket_width: width,
            chord_error,
            level_range: (lo, hi),
            corners,
            sector,
            hull,
        })
    }

    /// The parameter of the polyline's vertex within `radius` of `near` (follower frame) whose
    /// chord leaving it points most nearly along `direction` (follower frame): the place on the
    /// curve that can be tangent to a cam whose tangent there is `direction`, the bodies'
    /// material on opposite sides. A start for Newton where the crossing's parameter is far from
    /// the tangency (a curve small beside the cam's samples). `None` when no vertex is near.
    pub(crate) fn facing(&self, direction: Vec2, near: Vec2, radius: f64) -> Option<f64> {
        let n = self.verts.len();
        let segments = if self.closed { n } else { n.saturating_sub(1) };
        (0..segments)
            .filter(|&i| (self.verts[i].0 - near).norm() <= radius)
            .map(|i| {
                let chord = self.verts[(i + 1) % n].0 - self.verts[i].0;
                (chord.dot(&direction) / chord.norm(), self.verts[i].1)
            })
            .filter(|m| m.0.is_finite())
            .max_by(|a, b| a.0.total_cmp(&b.0))
            .map(|m| m.1)
    }

    /// The crossings of the polyline with `level`, appended to `out` (unsorted).
    pub(crate) fn crossings(&self, level: f64, out: &mut Vec<Crossing>) {
        let (lo, hi) = self.level_range;
        if !(level >= lo && level <= hi) {
            return;
        }
        let nb = self.buckets.len();
        let k = (((level - self.level_lo) / self.bucket_width) as usize).min(nb - 1);
        let n = self.verts.len();
        for &i in &self.buckets[k] {
            let i = i as usize;
            let j = (i + 1) % n;
            let (a, b) = (&self.verts[i], &self.verts[j]);
            let (la, lb) = (a.2 .1, b.2 .1);
            if (la < level) == (lb < level) {
                continue;
            }
            let f = (level - la) / (lb - la);
            let y = a.0 + f * (b.0 - a.0);
            let vb = if j == 0 && self.closed {
                b.1 + self.period.unwrap_or(0.0)
            } else {
                b.1
            };
            let rotating = self.joint.is_rotating();
            let entering = if rotating { lb > la } else { lb < la };
            let along = match rotating {
                false => self.joint.along(y),
                // the polar angle interpolated between the vertices' (no atan2 per crossing,
                // which the coverage of a gear makes for every tooth): off the chord's own by
                // the cube of its angular extent, a hundredth of the chord error
                true => {
                    let (pa, pb) = (a.2 .0, b.2 .0);
                    let d = (pb - pa + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
                        - std::f64::consts::PI;
                    let x = pa + f * d;
                    if x > std::f64::consts::PI {
                        x - std::f64::consts::TAU
                    } else if x <= -std::f64::consts::PI {
                        x + std::f64::consts::TAU
                    } else {
                        x
                    }
                }
            };
            out.push(Crossing {
                along,
                v: a.1 + f * (vb - a.1),
                entering,
            });
        }
    }

    /// The stretches `[(from, v_from), (to, v_to)]` of `along` inside the follower's material at
    /// `level` (`±∞` for the open ends of an open curve), from the crossings in `buf`.
    pub(crate) fn inside(&self, level: f64, buf: &mut Vec<Crossing>, out: &mut Vec<Stretch>) {
        buf.clear();
        self.crossings(level, buf);
        if buf.is_empty() {
            return;
        }
        if let Some((turn, shift)) = self.sector {
            // one tooth's crossings, within one tooth's turn from its first vertex (a crossing
            // turned by whole teeth is the next tooth's, its parameter shifted with it)
            let from = self.verts[0].2 .0;
            for c in buf.iter_mut() {
                let teeth = ((c.along - from) / turn).floor();
                c.along -= teeth * turn;
                c.v -= teeth * shift;
            }
        }
        buf.sort_by(|a, b| a.along.total_cmp(&b.along));
        match self.joint.is_rotating() {
            false => {
                let mut open: Option<(f64, f64)> = if buf[0].entering {
                    None
                } else {
                    Some((f64::NEG_INFINITY, f64::NAN))
                };
                for c in buf.iter() {
                    match (open, c.entering) {
                        (None, true) => open = Some((c.along, c.v)),
                        (Some(s), false) => {
                            out.push((s, (c.along, c.v)));
                            open = None;
                        }
                        // two entries in a row (an open curve seen from its end): the later holds
                        (Some(_), true) => open = Some((c.along, c.v)),
                        (None, false) => {}
                    }
                }
                if let Some(s) = open {
                    out.push((s, (f64::INFINITY, f64::NAN)));
                }
            }
            true => {
                // cyclic: start at an entry, pair each with the next exit going round (a whole
                // turn, or one tooth's)
                let Some(first) = buf.iter().position(|c| c.entering) else {
                    return;
                };
                let round = self.sector.map_or(std::f64::consts::TAU, |(turn, _)| turn);
                let n = buf.len();
                let mut open: Option<(f64, f64)> = None;
                for k in 0..n {
                    let c = buf[(first + k) % n];
                    let along = if first + k >= n {
                        c.along + round
                    } else {
                        c.along
                    };
                    match (open, c.entering) {
                        (None, true) | (Some(_), true) => open = Some((along, c.v)),
                        (Some(s), false) => {
                            out.push((s, (along, c.v)));
                            open = None;
                        }
                        (None, false) => {}
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::{Ellipse, InvoluteGear, InvoluteGearSpec};

    fn arm() -> FollowerJoint {
        FollowerJoint::arm(
            Point2::new(62.0, 0.0),
            super::super::Sense::Ccw,
            0.0,
            std::f64::consts::PI,
        )
    }

    /// A gear on an arm is indexed by one tooth; its stretches inside at any level are the
    /// whole turn's (computed from every segment, as a curve without symmetry is) reduced to
    /// one tooth: each whole-turn stretch is a tooth-stretch turned by a whole number of
    /// teeth, with its parameters shifted by as many teeth.
    #[test]
    fn one_tooth_gives_every_tooth_stretch() {
        let z = 42;
        let gear: Arc<dyn Curve> =
            Arc::new(InvoluteGear::new(InvoluteGearSpec::new(2.0, z, 20f64.to_radians())).unwrap());
        let c = Carried::new(gear.clone(), &arm(), 100.0).unwrap();
        let (turn, shift) = c.sector.expect("a gear repeats tooth by tooth");
        assert_eq!(turn, std::f64::consts::TAU / f64::from(z));
        // the same polyline indexed whole (no symmetry)
        let mut whole = Carried::new(gear, &arm(), 100.0).unwrap();
        whole.sector = None;
        let nseg = whole.verts.len();
        let width = whole.bucket_width * whole.buckets.len() as f64 / nseg as f64;
        whole.buckets = vec![Vec::new(); nseg];
        whole.bucket_width = width;
        for i in 0..nseg {
            let (la, lb) = (whole.verts[i].2 .1, whole.verts[(i + 1) % nseg].2 .1);
            let b = |l: f64| (((l - whole.level_lo) / width) as usize).min(nseg - 1);
            for k in b(la.min(lb))..=b(la.max(lb)) {
                whole.buckets[k].push(i as u32);
            }
        }
        let (lo, hi) = c.level_range;
        let (mut buf, mut one, mut all) = (Vec::new(), Vec::new(), Vec::new());
        for k in 1..40 {
            let level = lo + (hi - lo) * f64::from(k) / 40.0;
            one.clear();
            all.clear();
            c.inside(level, &mut buf, &mut one);
            whole.inside(level, &mut buf, &mut all);
            assert_eq!(one.len(), 1, "one stretch a tooth at {level}");
            assert_eq!(all.len(), z as usize, "at {level}");
            let ((a0, v0), (a1, v1)) = one[0];
            for &((b0, w0), (b1, w1)) in &all {
                let teeth = ((b0 - a0) / turn).round();
                assert!((b0 - a0 - teeth * turn).abs() <= 1e-9, "{level}: {b0} {a0}");
                assert!((b1 - a1 - teeth * turn).abs() <= 1e-9);
                let period = shift * f64::from(z);
                let dv = |w: f64, v: f64| (w - v - teeth * shift).rem_euclid(period);
                assert!(dv(w0, v0).min(period - dv(w0, v0)) <= 1e-9 * period);
                assert!(dv(w1, v1).min(period - dv(w1, v1)) <= 1e-9 * period);
            }
        }
        // a curve without symmetry keeps the whole turn
        let e: Arc<dyn Curve> =
            Arc::new(Ellipse::new(Point2::new(3.0, 0.0), 4.0, 2.0, 0.0).unwrap());
        assert!(Carried::new(e, &arm(), 100.0).unwrap().sector.is_none());
    }
}
