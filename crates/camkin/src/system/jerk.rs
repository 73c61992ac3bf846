//! The bodies' jerk at a solved instant: the third time derivatives of their coordinates, by
//! implicit differentiation of the rows in time with Taylor jets (see the crate's `jet` module),
//! exact — no difference in time.
//!
//! The unknowns are the coordinates `q` and every contact's pairing parameters `u_A`, `u_B`
//! (one where a curve is a point); the rows are the joints' and drivers' and, for each contact,
//! the pairing's conditions
//!
//! ```text
//! x_A(u_A) − x_B(u_B) = 0          the pairing points coincide (two rows)
//! x_A'(u_A) × x_B'(u_B) = 0        the tangents are parallel (none where a curve is a point)
//! ```
//!
//! — a formulation of the contact that shares no formula with the paper's `γ`. Writing every
//! unknown as `z(t₀ + ε) = z₀ + z₁ ε + z₂ ε² + z₃ ε³`, `z_k` solves `J z_k = −[F(z₀ … z_{k−1})]_k`
//! with `J = ∂F/∂z`, so `q̇ = q₁`, `q̈ = 2 q₂` (a check of the analysis) and `q⃛ = 6 q₃`. The
//! tangency row would need the curves' fourth derivatives at order 3, but they do not reach `q₃`:
//! with the tangents parallel, a change of that row is met by moving both pairing points along
//! the common tangent with `q` unchanged (the same argument as the cam's, see `jet`). They are
//! taken as zero; only the parameters' third derivatives, not reported, are affected.

use super::lu::Lu;
use super::{BodyId, Coordinate, JointKind, System, SystemError, SystemState};
use crate::curve::{Curve, Derivs, Domain};
use crate::geometry::{rot90, Point2, Vec2};
use crate::jet::{curve_jets, turned, Jet, Num, V2};

/// A body's jerk: the third time derivatives of its coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyJerk {
    /// `d³r/dt³` of the frame's origin, length/s³
    pub linear: Vec2,
    /// `d³θ/dt³`, rad/s³
    pub angular: f64,
}

/// A pairing parameter within this fraction of its curve's period (or span) of a breakpoint is
/// at it: the third derivative jumps there and the jerk is not defined.
const AT_BREAKPOINT: f64 = 1e-9;

/// The smallest pivot of the scaled Jacobian below this times the largest: no jerk (a conformal
/// contact, a dead point).
const SINGULAR: f64 = 1e-10;

/// A contact's curves at its pairing: each curve's derivatives, `None` for a point.
struct Pair {
    a: Option<Derivs>,
    b: Option<Derivs>,
}

/// A body's pose as jets: origin and `(cos, sin)` of its angle.
#[derive(Clone, Copy)]
struct PoseJet {
    origin: V2<Jet>,
    rot: (Jet, Jet),
}

impl PoseJet {
    fn ground() -> Self {
        Self {
            origin: V2::c(Vec2::zeros()),
            rot: (Jet::c(1.0), Jet::c(0.0)),
        }
    }
    /// A body-fixed point in the world.
    fn point(&self, s: Point2) -> V2<Jet> {
        self.origin + turned(self.rot, V2::c(s.coords))
    }
}

impl System {
    /// Every body's jerk at the solved instant `state` (from [`System::analyze`] or a sweep of
    /// this system), in the system's order. Exact: the rows differentiated three times in time
    /// (see the module's docs), with the contacts as their pairing conditions, the curves'
    /// third derivatives at the pairing points. An error where the jerk is not defined: a
    /// contact on a breakpoint of a curve (a spline node, where the third derivative jumps), a
    /// conformal contact or a singular instant (the rows do not determine it).
    pub fn jerk(&self, state: &SystemState) -> Result<Vec<BodyJerk>, SystemError> {
        let t = state.time;
        let nb = self.bodies.len();
        let size = self.size();
        let undefined = |element: &str, reason: &'static str| SystemError::NoJerk {
            time: t,
            element: element.to_string(),
            reason,
        };
        // the contacts' curves at their pairings, and where their parameters sit in z
        let mut pairs = Vec::with_capacity(self.contacts.len());
        let mut params = Vec::new();
        for (c, s) in self.contacts.iter().zip(&state.contacts) {
            let at = |curve: &dyn Curve, u: f64| -> Result<Option<Derivs>, SystemError> {
                if matches!(curve.domain(), Domain::Point) {
                    return Ok(None);
                }
                if at_breakpoint(curve, u) {
                    return Err(undefined(
                        &c.name,
                        "the contact is on a breakpoint of a curve, where its third derivative jumps",
                    ));
                }
                Ok(Some(curve.eval(u)))
            };
            let pair = Pair {
                a: at(c.curve_a.as_ref(), s.pairing.u_a)?,
                b: at(c.curve_b.as_ref(), s.pairing.u_b)?,
            };
            if pair.a.is_none() && pair.b.is_none() {
                return Err(undefined(&c.name, "both of its curves are points"));
            }
            params.extend(pair.a.map(|d| (d, s.pairing.u_a)));
            params.extend(pair.b.map(|d| (d, s.pairing.u_b)));
            pairs.push(pair);
        }
        let n = 3 * nb + params.len();
        // columns scaled to lengths (an angle times the size, a parameter times its metric) and
        // rows to lengths, so that the pivots compare
        let col: Vec<f64> = (0..nb)
            .flat_map(|_| [1.0, 1.0, 1.0 / size])
            .chain(params.iter().map(|(d, _)| 1.0 / d.metric()))
            .collect();
        let row = self.jerk_row_scales(&pairs, size);
        debug_assert_eq!(row.len(), n);
        // z₀ and the first coefficients: q₁ = q̇ (what the analysis found) is not assumed, each
        // order is solved
        let mut z: Vec<Jet> = state
            .bodies
            .iter()
            .flat_map(|b| [b.pose.origin.x, b.pose.origin.y, b.pose.angle])
            .chain(params.iter().map(|&(_, u)| u))
            .map(Jet::c)
            .collect();
        let jac = self.jerk_jacobian(state, &pairs, &row, &col);
        let mut f = Vec::with_capacity(n);
        // the bodies' angles' sines and cosines, once
        let trig: Vec<(f64, f64)> = state
            .bodies
            .iter()
            .map(|b| b.pose.angle.sin_cos())
            .collect();
        let mut lu = Lu::default();
        lu.factor(&jac, n);
        let (lo, hi) = lu.pivots;
        if !(lo > SINGULAR * hi && lo.is_finite()) {
            return Err(undefined(
                "",
                "the rows with the contacts' pairing conditions are singular (a conformal contact, a dead point)",
            ));
        }
        let (mut rhs, mut x) = (vec![0.0; n], Vec::with_capacity(n));
        for k in 1..=3 {
            f.clear();
            self.jerk_rows(&z, &trig, &pairs, t, &mut f);
            for i in 0..n {
                rhs[i] = -f[i].0[k] * row[i];
            }
            lu.solve(&rhs, &mut x);
            for j in 0..n {
                z[j].0[k] = x[j] * col[j];
            }
        }
        Ok((0..nb)
            .map(|i| BodyJerk {
                linear: Vec2::new(6.0 * z[3 * i].0[3], 6.0 * z[3 * i + 1].0[3]),
                angular: 6.0 * z[3 * i + 2].0[3],
            })
            .collect())
    }

    /// `J = ∂F/∂z` at the instant, scaled (`row` and `col`, see [`System::jerk`]): the joints'
    /// gradients as the analysis has them, a driver's unit entry, and each contact's pairing
    /// conditions differentiated by hand — `x_A − x_B` moves with a body's origin, with its
    /// angle by the arm turned a quarter (`k × (x − r)`) and with a parameter by the tangent;
    /// `x_A' × x_B'` with an angle by its tangent turned a quarter and with a parameter by the
    /// second derivative.
    fn jerk_jacobian(
        &self,
        state: &SystemState,
        pairs: &[Pair],
        row: &[f64],
        col: &[f64],
    ) -> Vec<f64> {
        let n = col.len();
        let mut jac = vec![0.0; n * n];
        let body = |id: BodyId| {
            id.index().map_or_else(
                || crate::body::BodyState::at_rest(crate::body::Pose::new(Point2::origin(), 0.0)),
                |i| state.bodies[i],
            )
        };
        let put = |jac: &mut [f64], r: usize, id: BodyId, g: [f64; 3]| {
            if let Some(i) = id.index() {
                for (c, v) in g.into_iter().enumerate() {
                    jac[r * n + 3 * i + c] += v;
                }
            }
        };
        let mut r = 0;
        let mut rows = Vec::new();
        for j in &self.joints {
            let [a, b] = j.kind.bodies();
            rows.clear();
            j.kind.eval(&body(a), &body(b), &mut rows);
            for e in &rows {
                for (id, g) in e.grads {
                    put(&mut jac, r, id, g);
                }
                r += 1;
            }
        }
        for d in &self.drivers {
            let mut g = [0.0; 3];
            g[d.coordinate.index()] = 1.0;
            put(&mut jac, r, d.body, g);
            r += 1;
        }
        // each side's arm to its point, and its tangent and second derivative in the world
        let side = |id: BodyId, curve: &dyn Curve, d: &Option<Derivs>| {
            let s = body(id);
            let rot = s.pose.frame().rotation;
            match d {
                Some(d) => (rot * d.p.coords, Some((rot * d.d1, rot * d.d2))),
                None => (rot * curve.position(0.0).coords, None),
            }
        };
        let mut k = 3 * self.bodies.len();
        let mut params = Vec::new();
        for (c, p) in self.contacts.iter().zip(pairs) {
            let (arm_a, da) = side(c.a, c.curve_a.as_ref(), &p.a);
            let (arm_b, db) = side(c.b, c.curve_b.as_ref(), &p.b);
            let (qa, qb) = (rot90(arm_a), rot90(arm_b));
            put(&mut jac, r, c.a, [1.0, 0.0, qa.x]);
            put(&mut jac, r, c.b, [-1.0, 0.0, -qb.x]);
            put(&mut jac, r + 1, c.a, [0.0, 1.0, qa.y]);
            put(&mut jac, r + 1, c.b, [0.0, -1.0, -qb.y]);
            params.clear();
            if let Some((t, _)) = da {
                params.push((k, t));
                k += 1;
            }
            if let Some((t, _)) = db {
                params.push((k, -t));
                k += 1;
            }
            for &(j, t) in &params {
                jac[r * n + j] = t.x;
                jac[(r + 1) * n + j] = t.y;
            }
            r += 2;
            if let (Some((ta, ta2)), Some((tb, tb2))) = (da, db) {
                let cross = |u: Vec2, v: Vec2| u.x * v.y - u.y * v.x;
                put(&mut jac, r, c.a, [0.0, 0.0, cross(rot90(ta), tb)]);
                put(&mut jac, r, c.b, [0.0, 0.0, cross(ta, rot90(tb))]);
                jac[r * n + k - 2] = cross(ta2, tb);
                jac[r * n + k - 1] = cross(ta, tb2);
                r += 1;
            }
        }
        debug_assert_eq!(r, n);
        for i in 0..n {
            for j in 0..n {
                jac[i * n + j] *= row[i] * col[j];
            }
        }
        jac
    }

    /// Each row's scale to a length: an angle row times the size, a tangency row times the size
    /// over its tangents' lengths.
    fn jerk_row_scales(&self, pairs: &[Pair], size: f64) -> Vec<f64> {
        let mut s = Vec::new();
        for j in &self.joints {
            match j.kind {
                JointKind::Revolute { .. } => s.extend([1.0, 1.0]),
                JointKind::Prismatic { .. } => s.extend([1.0, size]),
                JointKind::Fixed { .. } => s.extend([1.0, 1.0, size]),
            }
        }
        for d in &self.drivers {
            s.push(match d.coordinate {
                Coordinate::Angle => size,
                _ => 1.0,
            });
        }
        for p in pairs {
            s.extend([1.0, 1.0]);
            if let (Some(a), Some(b)) = (&p.a, &p.b) {
                s.push(size / (a.metric() * b.metric()));
            }
        }
        s
    }

    /// The rows at the unknowns `z` (jets in time from the instant `t`; `trig` the sines and
    /// cosines of the bodies' angles there): the joints', the drivers' (their laws' Taylor
    /// coefficients) and each contact's pairing conditions.
    fn jerk_rows(
        &self,
        z: &[Jet],
        trig: &[(f64, f64)],
        pairs: &[Pair],
        t: f64,
        out: &mut Vec<Jet>,
    ) {
        let pose = |id: BodyId| match id.index() {
            Some(i) => {
                let (sin, cos) = z[3 * i + 2].sin_cos_with(trig[i]);
                PoseJet {
                    origin: V2::new(z[3 * i], z[3 * i + 1]),
                    rot: (cos, sin),
                }
            }
            None => PoseJet::ground(),
        };
        let angle = |id: BodyId| id.index().map_or(Jet::c(0.0), |i| z[3 * i + 2]);
        for j in &self.joints {
            match j.kind {
                JointKind::Revolute { a, at_a, b, at_b } => {
                    let d = pose(a).point(at_a) - pose(b).point(at_b);
                    out.extend([d.x, d.y]);
                }
                JointKind::Fixed {
                    a,
                    at_a,
                    b,
                    at_b,
                    angle: phi,
                } => {
                    let d = pose(a).point(at_a) - pose(b).point(at_b);
                    out.extend([d.x, d.y, angle(b) - angle(a) - Jet::c(phi)]);
                }
                JointKind::Prismatic {
                    a,
                    at_a,
                    axis,
                    b,
                    at_b,
                    angle: phi,
                } => {
                    let (pa, pb) = (pose(a), pose(b));
                    let normal = turned(pa.rot, V2::c(rot90(super::joint::unit(axis))));
                    let h = pb.point(at_b) - pa.point(at_a);
                    out.extend([normal.dot(h), angle(b) - angle(a) - Jet::c(phi)]);
                }
            }
        }
        for d in &self.drivers {
            let i = d.body.index().unwrap_or(0);
            out.push(z[3 * i + d.coordinate.index()] - Jet(d.law.taylor(t)));
        }
        let mut k = 3 * self.bodies.len();
        for (c, p) in self.contacts.iter().zip(pairs) {
            // a curve's point and tangent in the world, its parameter z[k] moving
            let mut side = |id: BodyId, curve: &dyn Curve, d: &Option<Derivs>| {
                let body = pose(id);
                match d {
                    Some(d) => {
                        let mut dl = z[k];
                        dl.0[0] = 0.0;
                        k += 1;
                        let (x, x1) = curve_jets(d, dl);
                        (
                            body.origin + turned(body.rot, x),
                            Some(turned(body.rot, x1)),
                        )
                    }
                    None => (body.point(curve.position(0.0)), None),
                }
            };
            let (xa, ta) = side(c.a, c.curve_a.as_ref(), &p.a);
            let (xb, tb) = side(c.b, c.curve_b.as_ref(), &p.b);
            let d = xa - xb;
            out.extend([d.x, d.y]);
            if let (Some(ta), Some(tb)) = (ta, tb) {
                out.push(ta.x * tb.y - ta.y * tb.x);
            }
        }
    }
}

/// Whether `u` is at one of the curve's breakpoints (within [`AT_BREAKPOINT`] of its period or
/// span, across a closed curve's seam too).
fn at_breakpoint(curve: &dyn Curve, u: f64) -> bool {
    let bp = curve.breakpoints();
    if bp.is_empty() {
        return false;
    }
    let (span, period) = match curve.domain() {
        Domain::Periodic { period } => (period, Some(period)),
        Domain::Interval { min, max } if (max - min).is_finite() => (max - min, None),
        _ => (1.0, None),
    };
    let tol = AT_BREAKPOINT * span;
    bp.iter().any(|&b| {
        let d = u - b;
        let d = match period {
            Some(p) => d - p * (d / p).round(),
            None => d,
        };
        d.abs() <= tol
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::Pose;
    use crate::system::{Body, Driver, DriverLaw, Joint};

    /// A crank of length `L` pinned to the ground, its angle driven with an angular
    /// acceleration: its frame's origin moves on `L (cos θ, sin θ)`, whose third derivative is
    /// `L (sin θ θ̇³ − 3 cos θ θ̇ θ̈, −cos θ θ̇³ − 3 sin θ θ̇ θ̈)` by hand; `θ⃛ = 0`.
    #[test]
    fn a_driven_crank_has_its_closed_form_jerk() {
        let l = 0.7;
        let mut sys = System::new();
        let crank = sys.add_body(Body {
            name: "crank".into(),
            mass: 1.0,
            inertia: 1.0,
            pose: Pose::new(Point2::new(l, 0.0), 0.0),
            centre_of_mass: crate::geometry::Point2::origin(),
        });
        sys.add_joint(Joint {
            name: "pin".into(),
            kind: JointKind::Revolute {
                a: BodyId::GROUND,
                at_a: Point2::origin(),
                b: crank,
                at_b: Point2::new(-l, 0.0),
            },
        });
        let (w0, alpha) = (3.0, -5.0);
        sys.add_driver(Driver {
            name: "drive".into(),
            body: crank,
            coordinate: Coordinate::Angle,
            law: DriverLaw::Quadratic {
                start: 0.2,
                rate: w0,
                acceleration: alpha,
            },
        });
        let mut sweep = sys.sweep().unwrap();
        for k in 0..20 {
            let t = 0.05 * f64::from(k);
            let s = sweep.step(t).unwrap();
            let j = sys.jerk(&s).unwrap()[0];
            let (th, w) = (0.2 + w0 * t + 0.5 * alpha * t * t, w0 + alpha * t);
            let (sin, cos) = th.sin_cos();
            let x = l * (sin * w * w * w - 3.0 * cos * w * alpha);
            let y = l * (-cos * w * w * w - 3.0 * sin * w * alpha);
            let scale = l * (w0.abs() + 5.0).powi(3);
            assert!(
                (j.linear.x - x).abs() <= 1e-13 * scale,
                "{t}: {} {x}",
                j.linear.x
            );
            assert!(
                (j.linear.y - y).abs() <= 1e-13 * scale,
                "{t}: {} {y}",
                j.linear.y
            );
            assert!(j.angular.abs() <= 1e-13 * scale, "{t}: {}", j.angular);
        }
    }
}
