//! Bodies, constraints and forces of a planar multibody system.

use crate::body::{BodyState, Pose};
use crate::contact::{refine, ContactKinematics, Pairing, SearchOptions, Surface};
use crate::curve::Curve;
use crate::geometry::{Point2, Vec2};
use std::sync::Arc;

/// Mass properties of a rigid body (its frame's origin is where `q` puts it; the inertia is
/// about that origin).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBody {
    /// mass, kg
    pub mass: f64,
    /// moment of inertia about the body frame's origin, kg·m²
    pub inertia: f64,
}

/// A constraint between a body and the ground, a driver, or a contact between two bodies.
#[derive(Debug, Clone)]
pub enum Constraint {
    /// Curve `curve_a` on body `a` touching `curve_b` on body `b` (either may be [`GROUND`]):
    /// one row (eq. 11).
    Contact {
        /// body carrying curve A
        a: usize,
        /// curve A in its body frame
        curve_a: Arc<dyn Curve>,
        /// body carrying curve B
        b: usize,
        /// curve B in its body frame
        curve_b: Arc<dyn Curve>,
    },
    /// A joint of a [`crate::system::System`] between two bodies or a body and the ground (its
    /// bodies' ids are their indexes here): the kinematic analysis's rows.
    Joint(crate::system::JointKind),
    /// `body`'s `coordinate` follows `law` in time: one row, `Φ_t = −ḟ`, `γ = f̈`.
    Driver {
        /// the body
        body: usize,
        /// which coordinate
        coordinate: crate::system::Coordinate,
        /// how it moves
        law: crate::system::DriverLaw,
    },
}

/// The ground as a body index of a [`Constraint::Contact`]: fixed, no coordinates.
pub const GROUND: usize = usize::MAX;

impl Constraint {
    /// Number of rows.
    pub fn rows(&self) -> usize {
        match self {
            Constraint::Contact { .. } => 1,
            Constraint::Joint(kind) => kind.rows(),
            Constraint::Driver { .. } => 1,
        }
    }

    /// The rate `Φ_q q̇` must have (`−Φ_t`): a driver's speed at `t`, else 0.
    pub(crate) fn target_rate(&self, t: f64) -> f64 {
        match self {
            Constraint::Driver { law, .. } => law.at(t)[1],
            _ => 0.0,
        }
    }
}

/// An applied force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Load {
    /// Gravity on every body, m/s².
    Gravity(Vec2),
    /// A spring, damper or torsion spring of a [`crate::system::System`] between two bodies or a
    /// body and the ground (its bodies' ids are their indexes here).
    Element(crate::system::ForceKind),
}

/// The engine's model of a [`crate::system::System`]: its bodies in absolute coordinates, every
/// joint, driver and contact as a [`Constraint`], and the applied [`Load`]s.
#[derive(Debug, Clone)]
pub struct Model {
    /// the bodies; body `i` owns coordinates `3i .. 3i + 3`
    pub bodies: Vec<RigidBody>,
    /// the constraints
    pub constraints: Vec<Constraint>,
    /// the applied forces
    pub forces: Vec<Load>,
    /// tolerances of the contact pairing search
    pub search: SearchOptions,
}

/// The state of body `i` as a [`BodyState`] (accelerations zero); the ground's ([`GROUND`]) at
/// rest at the world's origin.
pub(crate) fn body_state(q: &[f64], qd: &[f64], i: usize) -> BodyState {
    if i == GROUND {
        return BodyState::at_rest(Pose::new(Point2::origin(), 0.0));
    }
    BodyState {
        pose: Pose::new(Point2::new(q[3 * i], q[3 * i + 1]), q[3 * i + 2]),
        velocity: Vec2::new(qd[3 * i], qd[3 * i + 1]),
        omega: qd[3 * i + 2],
        acceleration: Vec2::zeros(),
        alpha: 0.0,
    }
}

/// One constraint row: `Φ`, `Φ_q` (sparse, as (column, value) pairs, at most six), `γ`.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Row {
    pub(crate) phi: f64,
    jac: [(usize, f64); 6],
    len: usize,
    pub(crate) gamma: f64,
}

impl Row {
    fn new(phi: f64, jac: &[(usize, f64)], gamma: f64) -> Self {
        let mut r = Self {
            phi,
            jac: [(0, 0.0); 6],
            len: jac.len(),
            gamma,
        };
        r.jac[..jac.len()].copy_from_slice(jac);
        r
    }

    /// The row's nonzero entries of `Φ_q`: (column, value).
    pub(crate) fn jac(&self) -> &[(usize, f64)] {
        &self.jac[..self.len]
    }
}

/// The rows of one constraint (one to three).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Rows {
    rows: [Row; 3],
    len: usize,
}

impl Extend<Row> for Rows {
    fn extend<I: IntoIterator<Item = Row>>(&mut self, rows: I) {
        for r in rows {
            self.rows[self.len] = r;
            self.len += 1;
        }
    }
}

impl std::ops::Deref for Rows {
    type Target = [Row];
    fn deref(&self) -> &[Row] {
        &self.rows[..self.len]
    }
}

impl Model {
    /// Number of coordinates.
    pub fn dofs(&self) -> usize {
        3 * self.bodies.len()
    }

    /// Generalized applied forces `Q` at `(q, q̇)`, written to `f` (`dofs()` long).
    pub(crate) fn forces(&self, q: &[f64], qd: &[f64], f: &mut [f64]) {
        f.fill(0.0);
        for e in &self.forces {
            match *e {
                Load::Gravity(g) => {
                    for (i, b) in self.bodies.iter().enumerate() {
                        f[3 * i] += b.mass * g.x;
                        f[3 * i + 1] += b.mass * g.y;
                    }
                }
                Load::Element(kind) => {
                    let state = |id: crate::system::BodyId| body_state(q, qd, id.0);
                    kind.add_forces(state, f);
                }
            }
        }
    }

    /// The rows of constraint `c` at `(t, q, q̇)`; a contact updates its pairing in place
    /// (Newton from the previous one).
    #[inline(always)]
    pub(crate) fn rows(
        &self,
        c: &Constraint,
        t: f64,
        q: &[f64],
        qd: &[f64],
        pairing: &mut Option<Pairing>,
    ) -> Result<Rows, crate::contact::ContactError> {
        let mut rows = Rows::default();
        self.push_rows(c, t, q, qd, pairing, &mut rows)?;
        Ok(rows)
    }

    /// [`System::rows`] added to `out` (a simulation's step writes them straight into its
    /// buffer).
    pub(crate) fn push_rows(
        &self,
        c: &Constraint,
        t: f64,
        q: &[f64],
        qd: &[f64],
        pairing: &mut Option<Pairing>,
        out: &mut impl Extend<Row>,
    ) -> Result<(), crate::contact::ContactError> {
        match c {
            Constraint::Contact {
                a,
                curve_a,
                b,
                curve_b,
            } => {
                let (sa, sb) = (body_state(q, qd, *a), body_state(q, qd, *b));
                let (surf_a, surf_b) = (
                    Surface::new(curve_a.as_ref(), &sa),
                    Surface::new(curve_b.as_ref(), &sb),
                );
                let start = pairing.ok_or(crate::contact::ContactError::Unsupported(
                    "a contact without a starting pairing",
                ))?;
                let p = refine(&surf_a, &surf_b, start.u_a, start.u_b, &self.search)?;
                *pairing = Some(p);
                let k = ContactKinematics::new(
                    &surf_a,
                    &surf_b,
                    &p,
                    crate::contact::CONFORMAL_TOLERANCE,
                )?;
                let row = if *a != GROUND && *b != GROUND {
                    let cols = [3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2];
                    let mut jac = [(0, 0.0); 6];
                    for (e, (&c, v)) in jac.iter_mut().zip(cols.iter().zip(k.phi_q)) {
                        *e = (c, v);
                    }
                    Row::new(p.gap, &jac, k.gamma)
                } else {
                    // one side on the ground: its three entries only
                    let (body, side) = if *a == GROUND { (*b, 3) } else { (*a, 0) };
                    let jac: [(usize, f64); 3] =
                        std::array::from_fn(|c| (3 * body + c, k.phi_q[side + c]));
                    Row::new(p.gap, &jac, k.gamma)
                };
                out.extend(Some(row));
            }
            Constraint::Joint(kind) => joint_rows(kind, q, qd, out),
            Constraint::Driver {
                body,
                coordinate,
                law,
            } => {
                let i = 3 * body + coordinate.index();
                let [f, _, fdd] = law.at(t);
                out.extend(Some(Row::new(q[i] - f, &[(i, 1.0)], fdd)));
            }
        }
        Ok(())
    }
}

/// A system joint's rows (out of line: the cam model's loop stays as small as it was).
#[inline(never)]
fn joint_rows(kind: &crate::system::JointKind, q: &[f64], qd: &[f64], out: &mut impl Extend<Row>) {
    let [a, b] = kind.bodies();
    kind.eval(
        &body_state(q, qd, a.0),
        &body_state(q, qd, b.0),
        &mut JointToRows(out),
    );
}

/// A joint's rows written as [`Row`]s as it gives them: the ground's gradients dropped.
struct JointToRows<'a, E>(&'a mut E);

impl<E: Extend<Row>> Extend<crate::system::RowEval> for JointToRows<'_, E> {
    fn extend<I: IntoIterator<Item = crate::system::RowEval>>(&mut self, rows: I) {
        self.0.extend(rows.into_iter().map(|e| {
            let mut row = Row {
                phi: e.value,
                jac: [(0, 0.0); 6],
                len: 0,
                gamma: e.gamma,
            };
            for (id, g) in e.grads {
                if let Some(i) = id.index() {
                    for (c, v) in g.into_iter().enumerate() {
                        row.jac[row.len] = (3 * i + c, v);
                        row.len += 1;
                    }
                }
            }
            row
        }));
    }
}

impl Row {
    /// The row carried from the frames' coordinates to the centres of mass' (see
    /// `dynamics::system::centre`): `arm(i)` is body `i`'s arm from its frame's origin to its
    /// centre in the world, `qd` the rates (the angles' are the same in both).
    pub(crate) fn about_centres(&mut self, arm: impl Fn(usize) -> Vec2, qd: &[f64]) {
        let mut seen = [usize::MAX; 2];
        for e in 0..self.len {
            let body = self.jac[e].0 / 3;
            if seen.contains(&body) {
                continue;
            }
            let slot = if seen[0] == usize::MAX { 0 } else { 1 };
            seen[slot] = body;
            let a = arm(body);
            if a == Vec2::zeros() {
                continue;
            }
            let mut g = [0.0; 3];
            let mut theta = None;
            for (k, &(c, v)) in self.jac[..self.len].iter().enumerate() {
                if c / 3 == body {
                    g[c % 3] = v;
                    if c % 3 == 2 {
                        theta = Some(k);
                    }
                }
            }
            let shifted = g[2] + g[0] * a.y - g[1] * a.x;
            let w = qd[3 * body + 2];
            self.gamma -= w * w * (g[0] * a.x + g[1] * a.y);
            match theta {
                Some(k) => self.jac[k].1 = shifted,
                None => {
                    // a row on a body's x or y alone (a driver): its angle enters now
                    debug_assert!(self.len < 6);
                    self.jac[self.len] = (3 * body + 2, shifted);
                    self.len += 1;
                }
            }
        }
    }
}
