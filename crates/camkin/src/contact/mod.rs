//! Contact between a curve on body A and a curve on body B: pairing points, sliding rates
//! (paper eqs. 3–7, 9), normal accelerations (eqs. 1, 2, 8, 10) and the linear acceleration
//! constraint (eq. 11).
//!
//! Conventions (ccw angles, left normal `ν`, signed curvature `κ`, `σ`, material on the left, the
//! gap's sign): see the [crate docs](crate#sign-conventions). Every vector here is in the **world
//! frame**, and the common normal reported is `ν_A`, A's left normal at its pairing point (`ν_B`
//! with its sign flipped when A is a point).
//!
//! # The method
//!
//! With `c` the contact point, `v_X^P`, `a_X^P` the velocity and acceleration of the material
//! point of body X under `c`, `w = t_A·(v_B^P − v_A^P)` and `D = κ_B − σ κ_A`:
//!
//! ```text
//! ṡ_A = (σ (ω_A − ω_B) + κ_B w) / D                     (eq. 5)
//! ṡ_B = (κ_A w + ω_A − ω_B) / D                         (eq. 6)
//! a_n^A = ν_A·a_A^P + 2 ω_A ṡ_A + κ_A ṡ_A²              (eq. 1)
//! a_n^B = ν_A·a_B^P + σ (2 ω_B ṡ_B + κ_B ṡ_B²)          (eq. 2)
//! a_n^A = a_n^B   ⇔   Φ_q q̈ = γ                        (eq. 11)
//! ```
//!
//! with `q = (p_A, θ_A, p_B, θ_B)`,
//! `Φ_q = [ν_Aᵀ, ν_A·(k × (c − p_A)), −ν_Aᵀ, −ν_A·(k × (c − p_B))]` and
//! `γ = ν_A·(ω_A² (c − p_A) − ω_B² (c − p_B)) − 2 ω_A ṡ_A − κ_A ṡ_A² + σ (2 ω_B ṡ_B + κ_B ṡ_B²)`.
//! `Φ_q` is also the row of the velocity constraint `ν_A·(v_A^P − v_B^P) = 0`. Because the sliding
//! rates depend on velocities only, eq. 11 is linear in the accelerations.
//!
//! A point (knife edge, [`crate::curve::PointCurve`]) is the limit `κ → ∞`: its sliding rate is 0,
//! the other one is `w`, and `κ ṡ² → 0`. `D = 0` is conformal contact (a pin in a hole of its own
//! size, a flat on a flat): the contact point is not determined by the geometry and
//! [`ContactError::Conformal`] is returned rather than a division.

use crate::body::{BodyState, CurveInFrame, WorldDerivs};
use crate::curve::{Curve, Domain};
use crate::geometry::Frame;
use crate::geometry::{cross, rot90, Point2, UnitVec2, Vec2};

mod tree;
pub use tree::CurveIndex;

/// A curve carried by a body at one instant.
#[derive(Debug, Clone, Copy)]
pub struct Surface<'a> {
    /// the curve, in the body frame
    pub curve: &'a dyn Curve,
    /// the body's state
    pub body: &'a BodyState,
    frame: Frame,
}

impl<'a> Surface<'a> {
    /// A curve on a body.
    pub fn new(curve: &'a dyn Curve, body: &'a BodyState) -> Self {
        Self {
            curve,
            body,
            frame: body.frame(),
        }
    }
    fn is_point(&self) -> bool {
        matches!(self.curve.domain(), Domain::Point)
    }
    #[inline]
    fn eval(&self, u: f64) -> WorldDerivs {
        self.frame.curve_at(self.curve, u)
    }
}

/// Tolerances and effort of the pairing-point search. Lengths are in the problem's unit; build
/// them from a length scale of the problem with [`SearchOptions::for_length_scale`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SearchOptions {
    /// Newton stops when the parameter step moves the pairing points less than this (length).
    pub position_tolerance: f64,
    /// `|gap|` at or below this is contact; above it the curves are apart (length).
    pub contact_tolerance: f64,
    /// Samples per smooth piece of a curve for the global bracketing (a spline segment is a
    /// piece; an analytic closed curve is one piece).
    pub samples_per_piece: usize,
    /// Samples for a curve without breakpoints.
    pub samples_per_curve: usize,
    /// Newton iterations before giving up.
    pub max_iterations: u32,
    /// `D` counts as zero (conformal contact) when `|D| ≤ conformal_tolerance (|κ_A| + |κ_B|)`.
    pub conformal_tolerance: f64,
}

/// Relative tolerance on `D = κ_B − σ κ_A` below which contact is conformal.
pub const CONFORMAL_TOLERANCE: f64 = 1e-9;

impl SearchOptions {
    /// Options for a problem whose size is about `length` (e.g. the cam's radius).
    pub fn for_length_scale(length: f64) -> Self {
        Self {
            position_tolerance: 1e-13 * length,
            contact_tolerance: 1e-9 * length,
            samples_per_piece: 16,
            samples_per_curve: 256,
            max_iterations: 50,
            conformal_tolerance: CONFORMAL_TOLERANCE,
        }
    }
}

impl Default for SearchOptions {
    fn default() -> Self {
        Self::for_length_scale(1.0)
    }
}

/// A pair of pairing points: the parameters where `x_A − x_B` is normal to both curves.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Pairing {
    /// parameter on A
    pub u_a: f64,
    /// parameter on B (0 for a point)
    pub u_b: f64,
    /// A's pairing point, world frame
    pub point_a: Point2,
    /// B's pairing point, world frame
    pub point_b: Point2,
    /// the common normal `ν_A` (unit, world frame; see the [module docs](crate::contact))
    pub normal: UnitVec2,
    /// `ν·(x_A − x_B)`, length: > 0 apart, < 0 overlapping, for curves oriented material-on-the-left
    pub gap: f64,
    /// Newton iterations used (0 when the pairing was given, not searched)
    pub iterations: u32,
}

/// Why the contact could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ContactError {
    /// `D = κ_B − σ κ_A = 0`: the contact point is not determined by the geometry.
    #[error("conformal contact at ({x}, {y}): κ_A = {ka}, κ_B = {kb}, σ = {sigma}; the contact point is not determined by the geometry", x = crate::human::human(point.x), y = crate::human::human(point.y), ka = crate::human::human(*kappa_a), kb = crate::human::human(*kappa_b))]
    Conformal {
        /// contact point, world
        point: Point2,
        /// A's curvature
        kappa_a: f64,
        /// B's curvature
        kappa_b: f64,
        /// σ
        sigma: f64,
    },
    /// Newton did not converge.
    #[error("pairing-point search did not converge after {iterations} iterations (u_a = {}, u_b = {}, last step {})", crate::human::human(*.u_a), crate::human::human(*.u_b), crate::human::human(*.last_step))]
    NoConvergence {
        /// iterations done
        iterations: u32,
        /// last parameter on A
        u_a: f64,
        /// last parameter on B
        u_b: f64,
        /// length of the last step, length
        last_step: f64,
    },
    /// Both curves are unbounded, or both are points: no nearest pair to search for.
    #[error("cannot search a nearest pair between {0}")]
    Unsupported(&'static str),
    /// A curve is singular (zero tangent) at its pairing point.
    #[error("curve {which} has a zero-length tangent at u = {u}")]
    Singular {
        /// "A" or "B"
        which: &'static str,
        /// the parameter
        u: f64,
    },
}

/// Evaluates the pairing geometry at given parameters (no search).
pub fn pairing_at(a: &Surface<'_>, b: &Surface<'_>, u_a: f64, u_b: f64) -> Pairing {
    let ea = a.eval(u_a);
    let eb = b.eval(u_b);
    // a unit vector by construction (`Derivs::normal`)
    let normal = UnitVec2::new_unchecked(if a.is_point() {
        -eb.as_derivs().normal()
    } else {
        ea.as_derivs().normal()
    });
    Pairing {
        u_a,
        u_b,
        point_a: ea.p,
        point_b: eb.p,
        normal,
        gap: normal.dot(&(ea.p - eb.p)),
        iterations: 0,
    }
}

/// Newton's method for a pairing from `(u_a, u_b)`: `r_A' × r_B' = 0` (parallel tangents) and
/// `r_A'·(x_A − x_B) = 0`; with a point, `r'·(x_A − x_B) = 0` on the other curve alone.
pub fn refine(
    a: &Surface<'_>,
    b: &Surface<'_>,
    u_a: f64,
    u_b: f64,
    opts: &SearchOptions,
) -> Result<Pairing, ContactError> {
    let (pa, pb) = (a.is_point(), b.is_point());
    if pa && pb {
        return Err(ContactError::Unsupported("two points"));
    }
    let (mut ua, mut ub) = (u_a, u_b);
    let mut last_step = f64::INFINITY;
    for it in 1..=opts.max_iterations {
        let ea = a.eval(ua);
        let eb = b.eval(ub);
        let d = ea.p - eb.p;
        let (dua, dub) = if pb {
            let f = ea.d1.dot(&d);
            let j = ea.d2.dot(&d) + ea.d1.norm_squared();
            (-f / j, 0.0)
        } else if pa {
            let f = eb.d1.dot(&d);
            let j = eb.d2.dot(&d) - eb.d1.norm_squared();
            (0.0, -f / j)
        } else {
            // Tangents parallel and x_A − x_B normal to A. (The symmetric form r_A'·d = r_B'·d = 0
            // has a singular Jacobian at contact, d = 0, and is also solved by crossings; this one's
            // Jacobian determinant there is g_A³ g_B² (κ_A − σ κ_B), zero only for conformal contact.)
            let f1 = cross(ea.d1, eb.d1);
            let f2 = ea.d1.dot(&d);
            let j11 = cross(ea.d2, eb.d1);
            let j12 = cross(ea.d1, eb.d2);
            let j21 = ea.d2.dot(&d) + ea.d1.norm_squared();
            let j22 = -ea.d1.dot(&eb.d1);
            let det = j11 * j22 - j12 * j21;
            ((-f1 * j22 + f2 * j12) / det, (-j11 * f2 + j21 * f1) / det)
        };
        if !(dua.is_finite() && dub.is_finite()) {
            break;
        }
        ua += dua;
        ub += dub;
        last_step = (dua * ea.d1.norm()).abs().max((dub * eb.d1.norm()).abs());
        if last_step <= opts.position_tolerance {
            let mut p = pairing_at(a, b, ua, ub);
            p.iterations = it;
            return Ok(p);
        }
    }
    Err(ContactError::NoConvergence {
        iterations: opts.max_iterations,
        u_a: ua,
        u_b: ub,
        last_step,
    })
}

/// Starting pairs refined by Newton in a global search.
const STARTS: usize = 6;

/// Sample parameters for the global bracketing of one curve; `None` for an unbounded curve.
fn sample_params(c: &dyn Curve, opts: &SearchOptions) -> Option<Vec<f64>> {
    match c.domain() {
        Domain::Point => Some(vec![0.0]),
        Domain::Periodic { period } => {
            let bp = c.breakpoints();
            Some(
                crate::curve::piece_samples(
                    &bp,
                    period,
                    opts.samples_per_piece.max(2),
                    opts.samples_per_curve.max(8),
                )
                .collect(),
            )
        }
        Domain::Interval { min, max } if min.is_finite() && max.is_finite() => {
            let n = opts.samples_per_curve.max(8);
            Some(
                (0..=n)
                    .map(|i| min + (max - min) * i as f64 / n as f64)
                    .collect(),
            )
        }
        Domain::Interval { .. } => None,
    }
}

/// How two curves lie relative to each other: the result of [`find_contact`]. Overlap is a
/// result (the curves are placed so), not a failure of the search.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub enum Proximity {
    /// The curves are apart: the nearest pair, with `gap > contact_tolerance`.
    Apart(Pairing),
    /// The curves touch: `|gap| ≤ contact_tolerance`; the pairing is the contact.
    Touching(Pairing),
    /// The curves overlap: the deepest pair found, with `gap < −contact_tolerance` (the depth is
    /// `−gap`).
    Overlapping(Pairing),
}

impl Proximity {
    /// The pairing: the nearest pair, the contact, or the deepest pair.
    pub fn pairing(&self) -> Pairing {
        match *self {
            Proximity::Apart(p) | Proximity::Touching(p) | Proximity::Overlapping(p) => p,
        }
    }
    /// The signed gap, length: > 0 apart, < 0 overlapping.
    pub fn gap(&self) -> f64 {
        self.pairing().gap
    }
    /// The contact, when the curves touch.
    pub fn contact(&self) -> Option<Pairing> {
        match *self {
            Proximity::Touching(p) => Some(p),
            _ => None,
        }
    }
}

/// Where two curves carried by bodies touch, or how far apart they are, or how deep they overlap:
/// the nearest pair of pairing points, found by global bracketing (sampling every smooth piece of
/// both curves, the best sampled pairs refined by Newton), never a far pair when a nearer one
/// exists.
///
/// The gap's sign needs both curves oriented material-on-the-left (see the
/// [crate docs](crate#sign-conventions)). At most one of the two curves may be unbounded (a line).
/// An error says why the search stopped (two unbounded curves, no pairing point converged).
///
/// ```
/// use camkin::body::{BodyState, Pose};
/// use camkin::contact::{find_contact, Proximity, SearchOptions, Surface};
/// use camkin::curve::Circle;
/// use camkin::Point2;
///
/// // a disc of radius 2 at the origin and one of radius 1 whose centre is 3 away: they touch
/// let (big, small) = (Circle::new(Point2::origin(), 2.0)?, Circle::new(Point2::origin(), 1.0)?);
/// let a = BodyState::at_rest(Pose::new(Point2::origin(), 0.0));
/// let b = BodyState::at_rest(Pose::new(Point2::new(3.0, 0.0), 0.0));
/// let opts = SearchOptions::for_length_scale(2.0);
/// match find_contact(&Surface::new(&big, &a), &Surface::new(&small, &b), &opts)? {
///     Proximity::Touching(p) => assert!((p.point_a.x - 2.0).abs() < 1e-12),
///     other => panic!("expected contact, got {other:?}"),
/// }
/// // moved 0.5 closer they overlap by 0.5: a result, not an error
/// let b = BodyState::at_rest(Pose::new(Point2::new(2.5, 0.0), 0.0));
/// let p = find_contact(&Surface::new(&big, &a), &Surface::new(&small, &b), &opts)?;
/// assert!(matches!(p, Proximity::Overlapping(_)) && (p.gap() + 0.5).abs() < 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn find_contact(
    a: &Surface<'_>,
    b: &Surface<'_>,
    opts: &SearchOptions,
) -> Result<Proximity, ContactError> {
    let ia = CurveIndex::new(a.curve, opts);
    let ib = CurveIndex::new(b.curve, opts);
    find_contact_indexed(a, ia.as_ref(), b, ib.as_ref(), opts)
}

/// [`find_contact`] with the curves' indexes built once ([`CurveIndex::new`] with the same
/// options; `None` for an unbounded curve): the search at many poses of the same curves.
pub fn find_contact_indexed(
    a: &Surface<'_>,
    ia: Option<&CurveIndex>,
    b: &Surface<'_>,
    ib: Option<&CurveIndex>,
    opts: &SearchOptions,
) -> Result<Proximity, ContactError> {
    // an index missing for a bounded curve is built here; one that is not of its curve refused
    let (own_a, own_b);
    let ia = match ia {
        Some(i) => Some(i),
        None => {
            own_a = CurveIndex::new(a.curve, opts);
            own_a.as_ref()
        }
    };
    let ib = match ib {
        Some(i) => Some(i),
        None => {
            own_b = CurveIndex::new(b.curve, opts);
            own_b.as_ref()
        }
    };
    for (i, s) in [(ia, a), (ib, b)] {
        if i.is_some_and(|i| !i.samples(s.curve)) {
            return Err(ContactError::Unsupported(
                "an index built for another curve (build it with CurveIndex::new from this curve)",
            ));
        }
    }
    // Candidate starting pairs: (distance², u_a, u_b).
    let mut starts: Vec<(f64, f64, f64)> = match (ia, ib) {
        (None, None) => return Err(ContactError::Unsupported("two unbounded curves")),
        // each sample of A with its nearest sample of B, the nearest few (a tree of bounding
        // circles prunes the pairs that cannot be among them)
        (Some(ia), Some(ib)) => tree::nearest_pairs(ia, &a.frame, ib, &b.frame, STARTS)
            .into_iter()
            .map(|(d2, i, j)| (d2, ia.param(i), ib.param(j)))
            .collect(),
        (Some(ia), None) => (0..ia.len())
            .map(|i| {
                let ua = ia.param(i);
                let x = a.eval(ua).p;
                let ub = project_onto(b, x, 0.0, opts);
                ((x - b.eval(ub).p).norm_squared(), ua, ub)
            })
            .collect(),
        (None, Some(ib)) => (0..ib.len())
            .map(|j| {
                let ub = ib.param(j);
                let x = b.eval(ub).p;
                let ua = project_onto(a, x, 0.0, opts);
                ((a.eval(ua).p - x).norm_squared(), ua, ub)
            })
            .collect(),
    };
    starts.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut best: Option<Pairing> = None;
    let mut deepest: Option<Pairing> = None;
    let mut last_err = None;
    for &(_, ua, ub) in starts.iter().take(STARTS) {
        match refine(a, b, ua, ub, opts) {
            Ok(p) => {
                if p.gap < -opts.contact_tolerance {
                    // a pair with normals opposed across a space (a gear's flank and the next
                    // tooth's tip) has a negative gap too: only points inside each other's
                    // outline are an overlap
                    if !penetrates(a, ia, b, ib, &p) {
                        continue;
                    }
                    if deepest.is_none_or(|d| p.gap < d.gap) {
                        deepest = Some(p);
                    }
                } else if best.is_none_or(|q| p.gap < q.gap) {
                    best = Some(p);
                }
            }
            Err(e) => last_err = Some(e),
        }
    }
    // A crossing of the two curves shows up as a sampled distance near zero with no tangent pair.
    if let Some(d) = deepest {
        return Ok(Proximity::Overlapping(d));
    }
    match best {
        Some(p) if p.gap <= opts.contact_tolerance => Ok(Proximity::Touching(p)),
        Some(p) => Ok(Proximity::Apart(p)),
        None => Err(last_err.unwrap_or(ContactError::Unsupported("curves with no pairing points"))),
    }
}

/// Whether a pair with a negative gap is a real overlap: each point inside the other curve's
/// outline (for a closed curve, by its sample polygon; an overlap shallower than the polygon's
/// longest side, where the polygon may differ from the curve, is taken as the local geometry
/// says, and an open curve's side is its material side there).
fn penetrates(
    a: &Surface<'_>,
    ia: Option<&CurveIndex>,
    b: &Surface<'_>,
    ib: Option<&CurveIndex>,
    p: &Pairing,
) -> bool {
    let depth = -p.gap;
    let inside = |s: &Surface<'_>, i: Option<&CurveIndex>, x: Point2| {
        let closed = matches!(s.curve.domain(), Domain::Periodic { .. });
        let local = s.frame.inverse_transform_point(&x);
        match i.and_then(|i| i.polygon_contains(closed, local)) {
            Some((inside, longest)) => inside || depth <= longest,
            None => true,
        }
    };
    inside(a, ia, p.point_b) && inside(b, ib, p.point_a)
}

/// The parameter of the foot of the perpendicular from `x` onto the surface's curve (Newton from
/// `u0`; exact in one step for a line).
fn project_onto(s: &Surface<'_>, x: Point2, u0: f64, opts: &SearchOptions) -> f64 {
    let mut u = u0;
    for _ in 0..opts.max_iterations {
        let e = s.eval(u);
        let d = e.p - x;
        let j = e.d2.dot(&d) + e.d1.norm_squared();
        let du = -e.d1.dot(&d) / j;
        if !du.is_finite() {
            break;
        }
        u += du;
        if du.abs() * e.d1.norm() <= opts.position_tolerance {
            break;
        }
    }
    u
}

/// Velocity-level contact kinematics at a pairing (paper eqs. 3–7, 9) and the acceleration
/// constraint row (eq. 11). All quantities are in the world frame.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ContactKinematics {
    /// the contact point `c` (A's pairing point), length
    pub point: Point2,
    /// the common normal `ν_A` (unit)
    pub normal: UnitVec2,
    /// A's unit tangent at `c`
    pub tangent_a: Vec2,
    /// `σ = t_A·t_B = ±1`. When a curve is a point it is −1: with B a point it multiplies zeros;
    /// with A a point the normal is `−ν_B`, so B's terms enter eq. 2 with the sign −1.
    pub sigma: f64,
    /// `κ_A`, 1/length (`+∞` for a point)
    pub kappa_a: f64,
    /// `κ_B`, 1/length (`+∞` for a point)
    pub kappa_b: f64,
    /// metric factor `g_A = |r_A'|`
    pub metric_a: f64,
    /// metric factor `g_B = |r_B'|` (0 for a point)
    pub metric_b: f64,
    /// `w = t_A·(v_B^P − v_A^P)`, length/s
    pub w: f64,
    /// `D = κ_B − σ κ_A`, 1/length (`∞` when a curve is a point)
    pub d: f64,
    /// `ṡ_A`, sliding rate of the contact point along A relative to body A (eq. 5), length/s
    pub sliding_rate_a: f64,
    /// `ṡ_B` (eq. 6), length/s
    pub sliding_rate_b: f64,
    /// `u̇_A = ṡ_A/g_A` (eq. 7), parameter/s
    pub param_rate_a: f64,
    /// `u̇_B = ṡ_B/g_B` (eq. 9), parameter/s (0 for a point)
    pub param_rate_b: f64,
    /// `ν_A·(v_A^P − v_B^P)`, the velocity-constraint residual, length/s (zero in sustained contact)
    pub normal_velocity: f64,
    /// `Φ_q` for `q = (p_A.x, p_A.y, θ_A, p_B.x, p_B.y, θ_B)`
    pub phi_q: [f64; 6],
    /// `γ`, the right-hand side of `Φ_q q̈ = γ`, length/s²
    pub gamma: f64,
    omega_a: f64,
    omega_b: f64,
}

/// The normal acceleration of the contact point as seen from one body (eq. 1 or 2), split in its
/// terms; components along the common normal `ν_A`, length/s².
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct NormalAcceleration {
    /// `ν_A·a_X^P`: the material point of the body under `c`
    pub material: f64,
    /// Coriolis term `2 ω_X ṡ_X` (times σ for B)
    pub coriolis: f64,
    /// relative term `κ_X ṡ_X²` (times σ for B)
    pub relative: f64,
}

impl NormalAcceleration {
    /// The sum of the three terms.
    pub fn total(&self) -> f64 {
        self.material + self.coriolis + self.relative
    }
}

impl ContactKinematics {
    /// Kinematics at `pairing` of the surfaces `a` and `b` (which should be in contact there).
    pub fn new(
        a: &Surface<'_>,
        b: &Surface<'_>,
        pairing: &Pairing,
        conformal_tolerance: f64,
    ) -> Result<Self, ContactError> {
        match (a.is_point(), b.is_point()) {
            (true, true) => Err(ContactError::Unsupported("two points")),
            (true, false) => {
                // Solve with the roles swapped (normal ν_B) and report with normal −ν_B.
                let swapped = Pairing {
                    u_a: pairing.u_b,
                    u_b: pairing.u_a,
                    point_a: pairing.point_b,
                    point_b: pairing.point_a,
                    normal: -pairing.normal,
                    gap: pairing.gap,
                    iterations: pairing.iterations,
                };
                let k = Self::new(b, a, &swapped, conformal_tolerance)?;
                let p = k.phi_q;
                Ok(Self {
                    point: pairing.point_a,
                    normal: -k.normal,
                    tangent_a: -k.tangent_a,
                    sigma: k.sigma,
                    kappa_a: k.kappa_b,
                    kappa_b: k.kappa_a,
                    metric_a: k.metric_b,
                    metric_b: k.metric_a,
                    w: k.w,
                    d: k.d,
                    sliding_rate_a: k.sliding_rate_b,
                    sliding_rate_b: k.sliding_rate_a,
                    param_rate_a: k.param_rate_b,
                    param_rate_b: k.param_rate_a,
                    normal_velocity: k.normal_velocity,
                    // ν_B·(a_B − a_A) = (−ν_B)·(a_A − a_B): the swapped equation is this one,
                    // with the blocks of q exchanged
                    phi_q: [p[3], p[4], p[5], p[0], p[1], p[2]],
                    gamma: k.gamma,
                    omega_a: k.omega_b,
                    omega_b: k.omega_a,
                })
            }
            (false, b_point) => {
                let ea = a.eval(pairing.u_a);
                let eb = b.eval(pairing.u_b);
                Self::from_geometry(
                    a.body,
                    &ea,
                    b.body,
                    &eb,
                    b_point,
                    pairing,
                    conformal_tolerance,
                )
            }
        }
    }

    /// As [`ContactKinematics::new`] from curve points already evaluated in the world frame
    /// (`ea` on A at `pairing.u_a`, `eb` on B at `pairing.u_b`); A must not be a point.
    #[inline(always)]
    pub fn from_geometry(
        body_a: &BodyState,
        ea: &WorldDerivs,
        body_b: &BodyState,
        eb: &WorldDerivs,
        b_point: bool,
        pairing: &Pairing,
        conformal_tolerance: f64,
    ) -> Result<Self, ContactError> {
        let ea = ea.as_derivs();
        let eb = eb.as_derivs();
        let g_a = ea.metric();
        if !(g_a > 0.0) {
            return Err(ContactError::Singular {
                which: "A",
                u: pairing.u_a,
            });
        }
        let g_b = eb.metric();
        if !b_point && !(g_b > 0.0) {
            return Err(ContactError::Singular {
                which: "B",
                u: pairing.u_b,
            });
        }
        let c = pairing.point_a;
        let inv_ga = 1.0 / g_a;
        let t_a = ea.d1 * inv_ga;
        let nu = rot90(t_a);
        let kappa_a = cross(ea.d1, ea.d2) * (inv_ga * inv_ga * inv_ga);
        let (wa, wb) = (body_a.omega, body_b.omega);
        let va = body_a.velocity_at(c);
        let vb = body_b.velocity_at(c);
        let w = t_a.dot(&(vb - va));
        let (sigma, kappa_b, d, sa, sb, ub_dot) = if b_point {
            (-1.0, f64::INFINITY, f64::INFINITY, w, 0.0, 0.0)
        } else {
            let sigma = if t_a.dot(&eb.d1) >= 0.0 { 1.0 } else { -1.0 };
            let kappa_b = cross(eb.d1, eb.d2) / (g_b * g_b * g_b);
            let d = kappa_b - sigma * kappa_a;
            if !(d.abs() > conformal_tolerance * (kappa_a.abs() + kappa_b.abs())) {
                return Err(ContactError::Conformal {
                    point: c,
                    kappa_a,
                    kappa_b,
                    sigma,
                });
            }
            let inv_d = 1.0 / d;
            let sa = (sigma * (wa - wb) + kappa_b * w) * inv_d; // eq. 5
            let sb = (kappa_a * w + wa - wb) * inv_d; // eq. 6
            (sigma, kappa_b, d, sa, sb, sb / g_b)
        };
        let ra = c - body_a.pose.origin;
        let rb = c - body_b.pose.origin;
        let b_terms = if b_point {
            0.0
        } else {
            sigma * (2.0 * wb * sb + kappa_b * sb * sb)
        };
        let gamma =
            nu.dot(&(wa * wa * ra - wb * wb * rb)) - 2.0 * wa * sa - kappa_a * sa * sa + b_terms;
        Ok(Self {
            point: c,
            normal: UnitVec2::new_unchecked(nu),
            tangent_a: t_a,
            sigma,
            kappa_a,
            kappa_b,
            metric_a: g_a,
            metric_b: if b_point { 0.0 } else { g_b },
            w,
            d,
            sliding_rate_a: sa,
            sliding_rate_b: sb,
            param_rate_a: sa * inv_ga,
            param_rate_b: ub_dot,
            normal_velocity: nu.dot(&(va - vb)),
            phi_q: [
                nu.x,
                nu.y,
                nu.dot(&rot90(ra)),
                -nu.x,
                -nu.y,
                -nu.dot(&rot90(rb)),
            ],
            gamma,
            omega_a: wa,
            omega_b: wb,
        })
    }

    /// The normal acceleration of the contact point seen from body A (eq. 1), with A's
    /// accelerations taken from `a`.
    pub fn normal_acceleration_a(&self, a: &BodyState) -> NormalAcceleration {
        let s = self.sliding_rate_a;
        NormalAcceleration {
            material: self.normal.dot(&a.acceleration_at(self.point)),
            coriolis: 2.0 * self.omega_a * s,
            relative: if s == 0.0 { 0.0 } else { self.kappa_a * s * s },
        }
    }

    /// The normal acceleration of the contact point seen from body B (eq. 2).
    pub fn normal_acceleration_b(&self, b: &BodyState) -> NormalAcceleration {
        let s = self.sliding_rate_b;
        NormalAcceleration {
            material: self.normal.dot(&b.acceleration_at(self.point)),
            coriolis: self.sigma * 2.0 * self.omega_b * s,
            relative: if s == 0.0 {
                0.0
            } else {
                self.sigma * self.kappa_b * s * s
            },
        }
    }

    /// `Φ_q q̈ − γ` for the generalized accelerations `q̈ = (p̈_A, ω̇_A, p̈_B, ω̇_B)` taken from
    /// the two body states: zero exactly when eq. 11 holds (`a_n^A − a_n^B`).
    pub fn acceleration_residual(&self, a: &BodyState, b: &BodyState) -> f64 {
        let q = [
            a.acceleration.x,
            a.acceleration.y,
            a.alpha,
            b.acceleration.x,
            b.acceleration.y,
            b.alpha,
        ];
        self.phi_q.iter().zip(q).map(|(p, q)| p * q).sum::<f64>() - self.gamma
    }
}

/// `t_A × t_B` at a pairing: zero when the tangents are parallel (used by tests and callers that
/// check a given pairing).
pub fn tangent_misalignment(a: &Surface<'_>, b: &Surface<'_>, p: &Pairing) -> f64 {
    let ta = a.eval(p.u_a).as_derivs().tangent();
    let tb = b.eval(p.u_b).as_derivs().tangent();
    cross(ta, tb)
}
