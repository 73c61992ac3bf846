//! An independent computation of the follower's motion, to check the contact method against.
//!
//! The follower's position is computed as a *support function*: for every cam point `p`, the
//! coordinate at which the follower's boundary passes through `p` entering the follower in its
//! closing sense (a closed form of the joint and its contact curve); the follower's position is
//! the extreme of that over the profile, found by sampling the profile and golden-section
//! search. A knife edge's position is the extreme over the crossings of the profile with the
//! tip's path, found by bisection. No tangency condition, Newton solve, curvature or normal
//! acceleration is involved. The velocity and acceleration are then finite differences in the
//! cam angle (seven points, sixth order centred), on stencils kept within one smooth piece of the profile
//! (a spline's curvature has a corner at its nodes, where differences lose their order).
//!
//! What the check shares with the contact method is only its input: the profile's positions,
//! the joint and contact curve of the follower, and the cam-angle convention. It matches on the
//! joint's kind itself (slide or pivot) rather than call [`FollowerJoint`]'s methods, so that the
//! geometry of the check shares no code with the method it checks.

use super::{CamError, FollowerCurve, FollowerJoint, Mechanism};
use crate::geometry::{Point2, Vec2};
use std::f64::consts::{PI, TAU};

/// The largest step of the finite differences in the cam angle, rad; it is halved
/// `LEVELS − 1` times, to 3.9e-5 rad (rounding grows as 1/h², truncation falls as h⁶ centred,
/// h⁵ shifted). On a sharply curved stretch of a cam the contact point sweeps a tenth of a
/// spline piece a degree; steps of 3.1e-4 rad left a truncation error of 1e-8 there.
const STEP: f64 = 0.005;
const LEVELS: usize = 8;
/// Nodes of a difference stencil.
const NODES: usize = 7;
/// Profile samples per revolution of the parameter for the global maximum (at least 16 per
/// smooth piece).
const SAMPLES: usize = 512;

/// The contact method against the support function over a set of cam angles.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct IndependentCheck {
    /// cam angles compared
    pub angles: usize,
    /// cam angles left out: no seven-point stencil around them stays on one smooth piece of the
    /// profile (the contact jumps there, or the pieces are too short for the step)
    pub skipped: usize,
    /// `max |Δq|`, as a length (an arm angle times the follower's reach from its pivot),
    /// relative to the profile's size; ∞ when the support function found no touch where the
    /// method did
    pub position: f64,
    /// `max |Δq̇| / max |q̇|`
    pub velocity: f64,
    /// `max |Δq̈| / max |q̈|`
    pub acceleration: f64,
}

impl IndependentCheck {
    /// The largest of the three relative differences.
    pub fn worst(&self) -> f64 {
        self.position.max(self.velocity).max(self.acceleration)
    }
}

/// One support-function evaluation: the follower's coordinate and the profile parameter that
/// realises it.
#[derive(Debug, Clone, Copy)]
struct Support {
    q: f64,
    u: f64,
}

/// The body of [`Mechanism::support_position`] (documented there).
pub(crate) fn support_position(mech: &Mechanism, theta: f64) -> Option<(f64, f64)> {
    support(mech, theta).map(|s| (s.q, s.u))
}

/// The body of [`Mechanism::independent_check`] (documented there).
pub(crate) fn independent_check(
    mech: &Mechanism,
    thetas: &[f64],
) -> Result<IndependentCheck, CamError> {
    let (w, al) = (
        mech.touch.cam().speed,
        mech.touch.cam().angular_acceleration,
    );
    let reach = mech.touch.size()
        + match mech.follower_joint() {
            FollowerJoint::Rotating { pivot, .. } => (pivot - mech.touch.cam().pivot).norm(),
            FollowerJoint::Translating { .. } => 0.0,
        };
    let q_length = |dq: f64| match mech.follower_joint() {
        FollowerJoint::Rotating { .. } => dq.abs() * reach,
        FollowerJoint::Translating { .. } => dq.abs(),
    };
    let mut out = IndependentCheck {
        angles: 0,
        skipped: 0,
        position: 0.0,
        velocity: 0.0,
        acceleration: 0.0,
    };
    let (mut dv, mut da, mut vmax, mut amax) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for &theta in thetas {
        let s = mech.analyze(theta)?;
        vmax = vmax.max(s.velocity.abs());
        amax = amax.max(s.acceleration.abs());
        let Some(centre) = support(mech, theta) else {
            out.position = f64::INFINITY;
            continue;
        };
        let dq = match mech.follower_joint() {
            FollowerJoint::Rotating { .. } => wrap_near_zero(s.position - centre.q),
            FollowerJoint::Translating { .. } => s.position - centre.q,
        };
        out.position = out.position.max(q_length(dq) / mech.touch.size());
        let Some((d1, d2)) = differences(mech, theta, centre) else {
            out.skipped += 1;
            continue;
        };
        out.angles += 1;
        dv = dv.max((s.velocity - w * d1).abs());
        da = da.max((s.acceleration - (w * w * d2 + al * d1)).abs());
    }
    out.velocity = if vmax > 0.0 { dv / vmax } else { dv };
    out.acceleration = if amax > 0.0 { da / amax } else { da };
    Ok(out)
}

/// `(dq/dθ, d²q/dθ²)` of the support function at `theta` by seven-point differences at
/// halving steps, each on the stencil nearest to centred whose maxima all lie on
/// the smooth piece of `centre` and move steadily along it: for each derivative, the finer
/// of the two consecutive steps at which it agrees best (truncation falls and rounding grows
/// as the step shrinks, the second derivative's rounding faster); `None` when fewer than two
/// steps have a stencil.
fn differences(mech: &Mechanism, theta: f64, centre: Support) -> Option<(f64, f64)> {
    let half = (NODES / 2) as i32;
    let piece = |u: f64| mech.touch.breakpoints().partition_point(|&b| b <= u);
    let home = piece(centre.u);
    // each derivative with the rounding it carries: the positions' own rounding (a few ulps
    // of the largest) through the stencil's weights
    let estimate = |h: f64| -> Option<([f64; 2], [f64; 2])> {
        let mut cache: Vec<Option<Option<Support>>> = vec![None; (4 * half + 1) as usize];
        for shift in [0, -1, 1, -2, 2, -3, 3] {
            let ks: Vec<i32> = (shift - half..=shift + half).collect();
            let mut nodes = Vec::with_capacity(NODES);
            for &k in &ks {
                let s = if k == 0 {
                    Some(centre)
                } else {
                    *cache[(k + 2 * half) as usize]
                        .get_or_insert_with(|| support(mech, theta + k as f64 * h))
                };
                match s {
                    Some(s) if piece(s.u) == home => nodes.push(s),
                    _ => break,
                }
            }
            if nodes.len() < NODES || !steady(&nodes, mech.touch.period()) {
                continue;
            }
            let x: Vec<f64> = ks.iter().map(|&k| k as f64 * h).collect();
            let w = fornberg(&x, 2);
            let mut q: Vec<f64> = nodes.iter().map(|n| n.q).collect();
            if let FollowerJoint::Rotating { .. } = mech.follower_joint() {
                for v in &mut q {
                    *v = centre.q + wrap_near_zero(*v - centre.q);
                }
            }
            let d = |m: usize| w[m].iter().zip(&q).map(|(a, b)| a * b).sum::<f64>();
            let noise = 4.0 * f64::EPSILON * q.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            let r = |m: usize| noise * w[m].iter().map(|a| a.abs()).sum::<f64>();
            return Some(([d(1), d(2)], [r(1), r(2)]));
        }
        None
    };
    // each derivative at its own step: the finer of the two consecutive steps whose gap, or
    // the finer's rounding if larger, is least (two estimates dominated by rounding can agree
    // by chance; the second derivative's rounding grows faster as h shrinks)
    let mut best: [Option<(f64, f64)>; 2] = [None, None];
    let mut previous = estimate(STEP);
    for l in 1..LEVELS {
        let next = estimate(STEP / f64::from(1u32 << l));
        if let (Some((a, _)), Some((b, rounding))) = (previous, next) {
            for k in 0..2 {
                let error = (a[k] - b[k]).abs().max(rounding[k]);
                if best[k].is_none_or(|(e, _)| error < e) {
                    best[k] = Some((error, b[k]));
                }
            }
        }
        previous = next;
    }
    Some((best[0]?.1, best[1]?.1))
}

/// The support function at `theta`.
fn support(mech: &Mechanism, theta: f64) -> Option<Support> {
    let profile = mech.touch.cam().profile.as_ref();
    let (sn, cs) = (mech.touch.cam().direction.sign() * theta).sin_cos();
    let pivot = mech.touch.cam().pivot;
    let world = |u: f64| {
        let x = profile.position(u);
        pivot + Vec2::new(cs * x.x - sn * x.y, sn * x.x + cs * x.y)
    };
    let joint = mech.follower_joint();
    // a rotating follower: compare angles on the branch centred on the cam's axis, report
    // them within ±180° of the initial angle
    let (branch, report) = match joint {
        FollowerJoint::Rotating {
            pivot: o,
            initial_angle,
            ..
        } => {
            let d = pivot - o;
            (d.y.atan2(d.x), Some(initial_angle))
        }
        FollowerJoint::Translating { .. } => (0.0, None),
    };
    let report = |s: Support| Support {
        q: report.map_or(s.q, |a| a + wrap_near_zero(s.q - a)),
        u: s.u,
    };
    let period = mech.touch.period();
    let grid = sample_grid(mech.touch.breakpoints(), period);
    match mech.follower_curve() {
        curve @ (FollowerCurve::Point(_) | FollowerCurve::Circle(_)) => {
            // the extreme of the crossings of the tip's path with the profile, or of the
            // roller centre's path with the profile's offset by the radius (outward normal
            // −orientation·rot90(r')): a roller's reach beside its path can be far narrower
            // than the sampling
            let (tip, r) = match curve {
                FollowerCurve::Circle(c) => (c.center().coords, c.radius()),
                FollowerCurve::Point(p) => (p.at().coords, 0.0),
                _ => unreachable!("matched above"),
            };
            let shift = -mech.touch.orientation() * r;
            let offset = |u: f64| {
                if r == 0.0 {
                    return world(u);
                }
                let t = profile.eval(u).d1;
                let n = Vec2::new(-t.y, t.x) * (shift / t.norm());
                world(u) + Vec2::new(cs * n.x - sn * n.y, sn * n.x + cs * n.y)
            };
            let path = |u: f64| crossing(&joint, tip, offset(u), branch);
            let mut best: Option<(f64, Support)> = None;
            let mut keep = |u: f64| {
                let q = path(u).1;
                let score = oriented(&joint, q);
                if best.is_none_or(|(s, _)| score > s) {
                    best = Some((
                        score,
                        Support {
                            q,
                            u: u.rem_euclid(period),
                        },
                    ));
                }
            };
            let n = grid.len();
            let at = |i: usize| {
                if i < n {
                    grid[i]
                } else {
                    grid[i - n] + period
                }
            };
            let f: Vec<f64> = (0..=n + 1).map(|i| path(at(i)).0).collect();
            for i in 0..n {
                let (a, b) = (at(i), at(i + 1));
                if f[i] == 0.0 || f[i].signum() != f[i + 1].signum() {
                    keep(bisect(|u| path(u).0, a, b, f[i]));
                } else if f[i + 1].abs() < f[i].abs()
                    && f[i + 1].abs() < f[i + 2].abs()
                    && f[i + 1].signum() == f[i + 2].signum()
                {
                    // |f| has a local minimum at a sample: two crossings may hide around it
                    let sign = f[i + 1].signum();
                    let um = golden_max(
                        &|u| -sign * path(u).0,
                        a,
                        at(i + 2),
                        at(i + 1),
                        -f[i + 1].abs(),
                    );
                    let fm = path(um).0;
                    if fm.signum() != sign {
                        keep(bisect(|u| path(u).0, a, um, f[i]));
                        keep(bisect(|u| path(u).0, um, at(i + 2), fm));
                    }
                }
            }
            best.map(|(_, s)| report(s))
        }
        curve => {
            let f = |u: f64| {
                touch(&joint, &curve, world(u), branch)
                    .map_or(f64::NEG_INFINITY, |q| oriented(&joint, q))
            };
            let values: Vec<f64> = grid.iter().map(|&u| f(u)).collect();
            // every sampled local maximum is refined: near a contact jump two lobes touch
            // almost together and the best sample need not be on the winning one
            let n = grid.len();
            let mut best: Option<(f64, f64)> = None;
            for i in 0..n {
                let (before, after) = (values[(i + n - 1) % n], values[(i + 1) % n]);
                if values[i] == f64::NEG_INFINITY || values[i] < before || values[i] < after {
                    continue;
                }
                let lo = if i == 0 {
                    grid[n - 1] - period
                } else {
                    grid[i - 1]
                };
                let hi = if i + 1 == n {
                    period + grid[0]
                } else {
                    grid[i + 1]
                };
                let u = golden_max(&f, lo, hi, grid[i], values[i]);
                let v = f(u);
                if best.is_none_or(|(b, _)| v > b) {
                    best = Some((v, u));
                }
            }
            let u = best?.1.rem_euclid(period);
            touch(&joint, &curve, world(u), branch).map(|q| report(Support { q, u }))
        }
    }
}

/// The coordinate at which the follower's face (a line, material on its left) passes through the
/// world point `p` entering the follower in its closing sense.
///
/// A rotating follower's angles are taken within ±180° of `branch` (the direction from its
/// pivot to the cam's axis), where the angles that touch the cam form one interval.
fn touch(joint: &FollowerJoint, curve: &FollowerCurve, p: Point2, branch: f64) -> Option<f64> {
    match (*joint, curve) {
        (FollowerJoint::Translating { origin, direction }, FollowerCurve::Line(line)) => {
            // outside distance g(q) = −m·(p − origin − q d − a), m into the material: the
            // follower closes by decreasing q, so g must fall with q: m·d > 0
            let m = left(line.direction());
            let md = m.dot(&direction);
            (md > 0.0).then(|| m.dot(&(p - origin - line.anchor().coords)) / md)
        }
        (FollowerJoint::Rotating { pivot, closing, .. }, curve) => {
            // in polar form about the pivot, the boundary passes through p where
            // cos(ψ − γ − q) = k; it enters the follower (turning in the closing sense κ) at
            // q = ψ − γ − κ acos k
            let y = p - pivot;
            let (rho, psi) = (y.norm(), y.y.atan2(y.x));
            let (gamma, k) = match curve {
                FollowerCurve::Line(line) => {
                    let m = left(line.direction());
                    (m.y.atan2(m.x), m.dot(&line.anchor().coords) / rho)
                }
                _ => return None,
            };
            if rho == 0.0 || !(-1.0..=1.0).contains(&k) {
                return None;
            }
            let q = psi - gamma - closing.sign() * k.acos();
            Some(branch + wrap_near_zero(q - branch))
        }
        _ => None,
    }
}

/// For a knife edge with its tip at `tip` in the follower frame: `(f, q)` where `f` changes sign
/// where the world point `p` crosses the tip's path and `q` is the coordinate putting the tip
/// at `p` there.
fn crossing(joint: &FollowerJoint, tip: Vec2, p: Point2, branch: f64) -> (f64, f64) {
    match *joint {
        FollowerJoint::Translating { origin, direction } => {
            let w = p - origin - tip;
            (w.dot(&left(*direction)), w.dot(&direction))
        }
        FollowerJoint::Rotating { pivot, .. } => {
            let y = p - pivot;
            let q = y.y.atan2(y.x) - tip.y.atan2(tip.x);
            (y.norm() - tip.norm(), branch + wrap_near_zero(q - branch))
        }
    }
}

/// `q` oriented so that larger touches earlier.
fn oriented(joint: &FollowerJoint, q: f64) -> f64 {
    match joint {
        FollowerJoint::Translating { .. } => q,
        FollowerJoint::Rotating { closing, .. } => -closing.sign() * q,
    }
}

fn left(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

fn wrap_near_zero(a: f64) -> f64 {
    let d = a.rem_euclid(TAU);
    if d > PI {
        d - TAU
    } else {
        d
    }
}

/// Parameters at which to sample the profile: every smooth piece evenly, `SAMPLES` in all and
/// at least 16 per piece.
fn sample_grid(breakpoints: &[f64], period: f64) -> Vec<f64> {
    let mut cuts: Vec<f64> = breakpoints.to_vec();
    if cuts.is_empty() {
        cuts.push(0.0);
    }
    let per = (SAMPLES / cuts.len()).max(16);
    let mut grid = Vec::with_capacity(per * cuts.len());
    for (i, &a) in cuts.iter().enumerate() {
        let b = cuts.get(i + 1).copied().unwrap_or(cuts[0] + period);
        grid.extend((0..per).map(|j| a + (b - a) * j as f64 / per as f64));
    }
    grid
}

/// The contact moves steadily along the profile over the stencil: its parameter steps all have
/// one sign and differ by less than a factor 4 (a contact jump makes one step an outlier).
fn steady(nodes: &[Support], period: f64) -> bool {
    let steps: Vec<f64> = nodes
        .windows(2)
        .map(|w| {
            let d = (w[1].u - w[0].u).rem_euclid(period);
            if d > period / 2.0 {
                d - period
            } else {
                d
            }
        })
        .collect();
    let big = steps.iter().fold(0.0f64, |m, d| m.max(d.abs()));
    let small = steps.iter().fold(f64::INFINITY, |m, d| m.min(d.abs()));
    let tiny = 1e-9 * period;
    big <= tiny || (steps.iter().all(|d| d.signum() == steps[0].signum()) && big <= 4.0 * small)
}

/// The maximiser of `f` on `[lo, hi]` by golden-section search, given its best sample.
fn golden_max(f: &impl Fn(f64) -> f64, lo: f64, hi: f64, start: f64, f_start: f64) -> f64 {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut a, mut b) = (lo, hi);
    let (mut best_u, mut best_f) = (start, f_start);
    let mut c = b - g * (b - a);
    let mut d = a + g * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..200 {
        if b - a <= 1e-15 * (a.abs() + b.abs()).max(1.0) {
            break;
        }
        if fc >= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
        for (u, v) in [(c, fc), (d, fd)] {
            if v > best_f {
                best_u = u;
                best_f = v;
            }
        }
    }
    best_u
}

/// A root of `f` in `[a, b]` where it changes sign, by bisection to the last bit.
fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, mut fa: f64) -> f64 {
    if fa == 0.0 {
        return a;
    }
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if fm.signum() == fa.signum() {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// Finite-difference weights (Fornberg 1988): `w[m][j]` is the weight of the value at `x[j]` in
/// the `m`-th derivative at 0, for `m ≤ order`.
fn fornberg(x: &[f64], order: usize) -> Vec<Vec<f64>> {
    let n = x.len();
    let mut c = vec![vec![0.0; n]; order + 1];
    c[0][0] = 1.0;
    let mut c1 = 1.0;
    let mut c4 = x[0];
    for i in 1..n {
        let mn = i.min(order);
        let mut c2 = 1.0;
        let c5 = c4;
        c4 = x[i];
        for j in 0..i {
            let c3 = x[i] - x[j];
            c2 *= c3;
            if j == i - 1 {
                for k in (1..=mn).rev() {
                    c[k][i] = c1 * (k as f64 * c[k - 1][i - 1] - c5 * c[k][i - 1]) / c2;
                }
                c[0][i] = -c1 * c5 * c[0][i - 1] / c2;
            }
            for k in (1..=mn).rev() {
                c[k][j] = (c4 * c[k][j] - k as f64 * c[k - 1][j]) / c3;
            }
            c[0][j] = c4 * c[0][j] / c3;
        }
        c1 = c2;
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn fornberg_weights_are_the_textbook_ones() {
        // centred five points: f'' ≈ (−f₋₂ + 16f₋₁ − 30f₀ + 16f₁ − f₂)/12, f' ≈ (f₋₂ − 8f₋₁ + 8f₁ − f₂)/12
        let w = fornberg(&[-2.0, -1.0, 0.0, 1.0, 2.0], 2);
        let d1 = [1.0 / 12.0, -8.0 / 12.0, 0.0, 8.0 / 12.0, -1.0 / 12.0];
        let d2 = [
            -1.0 / 12.0,
            16.0 / 12.0,
            -30.0 / 12.0,
            16.0 / 12.0,
            -1.0 / 12.0,
        ];
        for j in 0..5 {
            assert_relative_eq!(w[1][j], d1[j], epsilon = 1e-15);
            assert_relative_eq!(w[2][j], d2[j], epsilon = 1e-15);
        }
    }

    #[test]
    fn one_sided_weights_differentiate_a_sextic_exactly() {
        // seven nodes reproduce polynomials to degree 6, wherever the stencil sits
        let x: Vec<f64> = (-1..=5).map(|k| k as f64 * 0.1).collect();
        let w = fornberg(&x, 2);
        let f = |t: f64| 1.0 + 2.0 * t - 3.0 * t * t + 0.5 * t.powi(5) - t.powi(6);
        let d = |m: usize| w[m].iter().zip(&x).map(|(a, &t)| a * f(t)).sum::<f64>();
        assert_relative_eq!(d(1), 2.0, epsilon = 1e-10);
        assert_relative_eq!(d(2), -6.0, epsilon = 1e-8);
    }

    #[test]
    fn golden_section_and_bisection_converge() {
        let u = golden_max(&|u: f64| -(u - 0.3).powi(2), 0.0, 1.0, 0.5, -0.04);
        assert!((u - 0.3).abs() < 1e-7);
        let r = bisect(|u| u * u - 2.0, 1.0, 2.0, -1.0);
        assert_relative_eq!(r, 2f64.sqrt(), epsilon = 4e-16);
    }
}
