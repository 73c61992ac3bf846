//! The kinematic analysis of a [`System`] at one instant: positions by Newton on `Φ = 0` (each
//! contact's pairing re-solved at every step), then velocities and accelerations by one linear
//! solve each with the same `Φ_q`. A [`SystemSweep`] warm-starts each instant from the last
//! (positions predicted by the last velocities and accelerations, pairings by their rates).

use super::joint::RowEval;
use super::{BodyId, System, SystemError};
use crate::body::{BodyState, Pose};
use crate::contact::{
    self, ContactKinematics, CurveIndex, Pairing, Proximity, SearchOptions, Surface,
};
use crate::geometry::{rot90, Point2, Vec2};
use nalgebra::{DMatrix, DVector};

/// Newton iterations on the positions before giving up.
const MAX_ITERATIONS: u32 = 50;

/// Newton stops when no coordinate moves more than this times the system's size (angles times
/// the size).
const STEP_TOLERANCE: f64 = 1e-13;

/// A converged instant whose rows are still off by more than this times the size did not
/// assemble.
const RESIDUAL_TOLERANCE: f64 = 1e-9;

/// The LU's smallest pivot below this times its largest is a singular matrix (the angle columns
/// scaled by the size, so that every entry is of order one).
const SINGULAR: f64 = 1e-10;

/// One contact at an instant: its pairing points and its kinematics (sliding rates, normal
/// acceleration terms, the row and `γ`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactState {
    /// the pairing (gap 0 at a solved instant)
    pub pairing: Pairing,
    /// the paper's kinematics at it
    pub kinematics: ContactKinematics,
    /// the contact moved to another pair of points since the last instant (the pair it
    /// followed would have let the curves overlap elsewhere: a gear's next tooth, a cam's
    /// concave stretch bridged); the acceleration is impulsive there
    pub jumped: bool,
}

/// Every body's pose, velocity and acceleration and every contact's kinematics at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct SystemState {
    /// the instant, s
    pub time: f64,
    /// the bodies, in the system's order
    pub bodies: Vec<BodyState>,
    /// the contacts, in the system's order
    pub contacts: Vec<ContactState>,
    /// Newton iterations on the positions
    pub iterations: u32,
}

/// What solving the positions keeps for the next instant.
#[derive(Debug, Clone)]
struct Solved {
    time: f64,
    q: DVector<f64>,
    qd: DVector<f64>,
    qdd: DVector<f64>,
    pairings: Vec<(f64, f64)>,
    rates: Vec<(f64, f64)>,
    /// each contact's sliding rates along A and B, length/s
    slides: Vec<(f64, f64)>,
}

/// A contact's gap beyond this times the size, at a Newton step, has the global search check
/// that no nearer pair of points is the contact (a warm-started step predicts gaps far smaller).
const SUSPECT_GAP: f64 = 1e-6;

/// Most times one instant moves its contacts to other pairs of points.
const MAX_JUMPS: usize = 8;

/// Instants of a system in order, each warm-started from the last.
#[derive(Debug)]
pub struct SystemSweep<'a> {
    sys: &'a System,
    opts: SearchOptions,
    size: f64,
    last: Option<Solved>,
    /// each contact's curves' search indexes, for the check that no other pair of points
    /// overlaps
    indexes: Vec<(Option<CurveIndex>, Option<CurveIndex>)>,
    /// the contacts that jumped in any instant solved on the way to the one asked for
    jumps: Vec<bool>,
}

impl System {
    /// The system at time `t` (s), solved from the bodies' starting poses (each contact's
    /// pairing found by a global search first).
    pub fn analyze(&self, t: f64) -> Result<SystemState, SystemError> {
        self.sweep()?.step(t)
    }

    /// A sweep: instants solved in turn, each from the last.
    pub fn sweep(&self) -> Result<SystemSweep<'_>, SystemError> {
        self.check()?;
        let size = self.size();
        let opts = SearchOptions::for_length_scale(size);
        let indexes = self
            .contacts
            .iter()
            .map(|c| {
                (
                    CurveIndex::new(c.curve_a.as_ref(), &opts),
                    CurveIndex::new(c.curve_b.as_ref(), &opts),
                )
            })
            .collect();
        Ok(SystemSweep {
            sys: self,
            opts,
            size,
            last: None,
            indexes,
            jumps: vec![false; self.contacts.len()],
        })
    }
}

/// Body `i`'s state from the coordinate vectors (`qd`, `qdd` optional).
fn state_of(q: &DVector<f64>, qd: Option<&DVector<f64>>, i: usize) -> BodyState {
    let k = 3 * i;
    let mut s = BodyState::at_rest(Pose::new(Point2::new(q[k], q[k + 1]), q[k + 2]));
    if let Some(v) = qd {
        s.velocity = Vec2::new(v[k], v[k + 1]);
        s.omega = v[k + 2];
    }
    s
}

/// The states of every body, and the ground's (at rest at the world's origin).
fn states(q: &DVector<f64>, qd: Option<&DVector<f64>>, n: usize) -> Vec<BodyState> {
    (0..n).map(|i| state_of(q, qd, i)).collect()
}

fn ground() -> BodyState {
    BodyState::at_rest(Pose::new(Point2::origin(), 0.0))
}

fn get(states: &[BodyState], id: BodyId) -> BodyState {
    id.index().map_or_else(ground, |i| states[i])
}

/// The rows of `Φ` at the states, their gradients (columns: `(x, y, size·θ)` of each body) and
/// `γ`; every contact's pairing refined from `pairings` (updated), and its kinematics when the
/// states carry velocities.
struct Assembly {
    phi: DVector<f64>,
    jac: DMatrix<f64>,
    gamma: DVector<f64>,
    rate: DVector<f64>,
    contacts: Vec<(Pairing, Option<ContactKinematics>)>,
}

impl SystemSweep<'_> {
    fn assemble(
        &self,
        t: f64,
        st: &[BodyState],
        pairings: &mut [(f64, f64)],
        jumped: &mut [bool],
        with_kinematics: bool,
    ) -> Result<Assembly, SystemError> {
        let sys = self.sys;
        let n = 3 * sys.bodies.len();
        let m = sys.rows();
        let mut phi = DVector::zeros(m);
        let mut jac = DMatrix::zeros(m, n);
        let mut gamma = DVector::zeros(m);
        let mut rate = DVector::zeros(m);
        let size = self.size;
        let put = |jac: &mut DMatrix<f64>, r: usize, id: BodyId, g: [f64; 3]| {
            if let Some(i) = id.index() {
                jac[(r, 3 * i)] += g[0];
                jac[(r, 3 * i + 1)] += g[1];
                jac[(r, 3 * i + 2)] += g[2] / size;
            }
        };
        let mut r = 0;
        let mut rows: Vec<RowEval> = Vec::with_capacity(3);
        for j in &sys.joints {
            let [a, b] = j.kind.bodies();
            rows.clear();
            j.kind.eval(&get(st, a), &get(st, b), &mut rows);
            for e in &rows {
                phi[r] = e.value;
                gamma[r] = e.gamma;
                for (id, g) in e.grads {
                    put(&mut jac, r, id, g);
                }
                r += 1;
            }
        }
        for d in &sys.drivers {
            let [f, fd, fdd] = d.law.at(t);
            let k = d.coordinate.index();
            let i = d.body.index().unwrap_or(0);
            let s = get(st, d.body);
            let q = [s.pose.origin.x, s.pose.origin.y, s.pose.angle][k];
            phi[r] = q - f;
            let mut g = [0.0; 3];
            g[k] = 1.0;
            put(&mut jac, r, BodyId(i), g);
            rate[r] = fd;
            gamma[r] = fdd;
            r += 1;
        }
        let mut contacts = Vec::with_capacity(sys.contacts.len());
        for (k, (c, pair)) in sys.contacts.iter().zip(pairings.iter_mut()).enumerate() {
            let (sa, sb) = (get(st, c.a), get(st, c.b));
            let (fa, fb) = (
                Surface::new(c.curve_a.as_ref(), &sa),
                Surface::new(c.curve_b.as_ref(), &sb),
            );
            let fail = |reason: String| SystemError::Contact {
                time: t,
                contact: c.name.clone(),
                reason,
            };
            // Newton from the pairing followed, or, where it wanders off (a corner, a pairing
            // far from the new poses), from the nearest or deepest pair the global search finds
            let global = || -> Result<Pairing, SystemError> {
                let (ia, ib) = &self.indexes[k];
                let found =
                    contact::find_contact_indexed(&fa, ia.as_ref(), &fb, ib.as_ref(), &self.opts)
                        .map_err(|e| fail(e.to_string()))?;
                let (Proximity::Apart(g) | Proximity::Touching(g) | Proximity::Overlapping(g)) =
                    found;
                Ok(g)
            };
            let p = match contact::refine(&fa, &fb, pair.0, pair.1, &self.opts) {
                // a pairing that converged far from contact may have left the pair followed for
                // another tangency (past a gear's tip, Newton finds the tip circle against some
                // flank): the contact is the first touch, so a nearer pair found globally wins
                Ok(p) if p.gap.abs() > SUSPECT_GAP * size => {
                    let g = global()?;
                    if g.gap < p.gap - self.opts.contact_tolerance {
                        jumped[k] = true;
                        contact::refine(&fa, &fb, g.u_a, g.u_b, &self.opts).unwrap_or(g)
                    } else {
                        p
                    }
                }
                Ok(p) => p,
                Err(_) => {
                    let g = global()?;
                    jumped[k] = true;
                    contact::refine(&fa, &fb, g.u_a, g.u_b, &self.opts)
                        .map_err(|e| fail(e.to_string()))?
                }
            };
            *pair = (p.u_a, p.u_b);
            let nu = p.normal.into_inner();
            // the gap's gradient: ν on A's point, −ν on B's (the pairing is stationary)
            let ga = [nu.x, nu.y, nu.dot(&rot90(p.point_a - sa.pose.origin))];
            let gb = [-nu.x, -nu.y, -nu.dot(&rot90(p.point_b - sb.pose.origin))];
            phi[r] = p.gap;
            put(&mut jac, r, c.a, ga);
            put(&mut jac, r, c.b, gb);
            let k = if with_kinematics {
                let k = ContactKinematics::new(&fa, &fb, &p, self.opts.conformal_tolerance)
                    .map_err(|e| fail(e.to_string()))?;
                gamma[r] = k.gamma;
                Some(k)
            } else {
                None
            };
            contacts.push((p, k));
            r += 1;
        }
        Ok(Assembly {
            phi,
            jac,
            gamma,
            rate,
            contacts,
        })
    }

    /// The LU of the scaled Jacobian, or the rows it is singular in.
    fn factor(
        &self,
        t: f64,
        jac: &DMatrix<f64>,
    ) -> Result<nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>, SystemError> {
        let lu = jac.clone().lu();
        let u = lu.u();
        let diag = u.diagonal().map(f64::abs);
        let (lo, hi) = (diag.min(), diag.max());
        if diag.is_empty() || (lo > SINGULAR * hi && lo.is_finite()) {
            return Ok(lu);
        }
        // the rows the smallest singular value's left vector weighs: the dependent ones
        let svd = jac.clone().svd(true, false);
        let k = svd.singular_values.imin();
        let names = svd.u.map_or_else(String::new, |u| {
            let col = u.column(k);
            let big = col.amax();
            (0..col.len())
                .filter(|&i| col[i].abs() >= 0.2 * big)
                .map(|i| self.sys.row_name(i))
                .collect::<Vec<_>>()
                .join(", ")
        });
        Err(SystemError::Singular {
            time: t,
            rows: names,
        })
    }

    /// Positions at `t` by Newton from `q`, with the contacts' pairings from `pairings`.
    fn positions(
        &self,
        t: f64,
        mut q: DVector<f64>,
        pairings: &mut [(f64, f64)],
        jumped: &mut [bool],
    ) -> Result<(DVector<f64>, u32), SystemError> {
        let nb = self.sys.bodies.len();
        let size = self.size;
        for it in 1..=MAX_ITERATIONS {
            let st = states(&q, None, nb);
            let a = self.assemble(t, &st, pairings, jumped, false)?;
            let lu = self.factor(t, &a.jac)?;
            let step = lu.solve(&(-&a.phi)).ok_or_else(|| SystemError::Singular {
                time: t,
                rows: String::new(),
            })?;
            // a step longer than a quarter of the size (or a quarter turn) is shortened: far
            // from the solution the linearisation is poor and a full step can jump branches
            let longest = step.amax();
            let step = if longest > 0.25 * size {
                step * (0.25 * size / longest)
            } else {
                step
            };
            // the angle columns were scaled by the size: their unknowns are size·θ
            let mut moved: f64 = 0.0;
            for i in 0..nb {
                q[3 * i] += step[3 * i];
                q[3 * i + 1] += step[3 * i + 1];
                q[3 * i + 2] += step[3 * i + 2] / size;
                moved = moved
                    .max(step[3 * i].abs())
                    .max(step[3 * i + 1].abs())
                    .max(step[3 * i + 2].abs());
            }
            if !moved.is_finite() {
                break;
            }
            if moved <= STEP_TOLERANCE * size {
                return Ok((q, it));
            }
        }
        let st = states(&q, None, nb);
        let a = self.assemble(t, &st, pairings, jumped, false)?;
        let r = a.phi.iamax();
        Err(SystemError::NoAssembly {
            time: t,
            reason: "Newton did not converge",
            residual: a.phi[r].abs(),
            row: self.sys.row_name(r),
        })
    }

    /// The system at time `t`, warm-started from the last instant solved. The first instant is
    /// reached from the bodies' starting poses, which are a guess at `t = 0` (each contact's
    /// pairing found there by a global search). An instant too far from the last for Newton
    /// (the drivers moved a long way) is reached through instants between: the answer is the
    /// assembly continuously connected to the start, on its branch.
    pub fn step(&mut self, t: f64) -> Result<SystemState, SystemError> {
        let first = self.last.is_none();
        if first && t != 0.0 {
            self.step_once(0.0)?;
        }
        self.jumps.iter_mut().for_each(|j| *j = false);
        let mut s = self.step_reached(t)?;
        // a jump in an instant between (the continuation's) is this step's
        for (c, &j) in s.contacts.iter_mut().zip(&self.jumps) {
            c.jumped = j && !first;
        }
        Ok(s)
    }

    /// `t` from the last instant, through instants between where Newton needs them.
    fn step_reached(&mut self, t: f64) -> Result<SystemState, SystemError> {
        match self.step_once(t) {
            Ok(s) => Ok(s),
            Err(e @ (SystemError::NoAssembly { .. } | SystemError::Contact { .. })) => {
                let Some(from) = self.last.as_ref().map(|l| l.time) else {
                    return Err(e);
                };
                self.continue_to(from, t, 0).map_err(|_| e)
            }
            Err(e) => Err(e),
        }
    }

    /// Reaches `t` from the last instant (at `from`) through the midpoint, halving again where
    /// that fails, to a depth of 12 (4096 instants).
    fn continue_to(&mut self, from: f64, t: f64, depth: u32) -> Result<SystemState, SystemError> {
        if depth >= 12 {
            return self.step_once(t);
        }
        let mid = 0.5 * (from + t);
        let saved = self.last.clone();
        let reached = match self.step_once(mid) {
            Ok(_) => Ok(()),
            Err(_) => {
                self.last = saved.clone();
                self.continue_to(from, mid, depth + 1).map(|_| ())
            }
        };
        reached?;
        match self.step_once(t) {
            Ok(s) => Ok(s),
            Err(_) => self.continue_to(mid, t, depth + 1),
        }
    }

    /// One instant from the last, with no continuation.
    fn step_once(&mut self, t: f64) -> Result<SystemState, SystemError> {
        let sys = self.sys;
        let nb = sys.bodies.len();
        let size = self.size;
        let (q0, mut pairings) = match &self.last {
            Some(s) => {
                let dt = t - s.time;
                let q = &s.q + &s.qd * dt + &s.qdd * (0.5 * dt * dt);
                let p = s
                    .pairings
                    .iter()
                    .zip(&s.rates)
                    .map(|(&(ua, ub), &(ra, rb))| (ua + ra * dt, ub + rb * dt))
                    .collect();
                (q, p)
            }
            None => {
                let q = DVector::from_iterator(
                    3 * nb,
                    sys.bodies
                        .iter()
                        .flat_map(|b| [b.pose.origin.x, b.pose.origin.y, b.pose.angle]),
                );
                let p = self.global_pairings(t, &q)?;
                (q, p)
            }
        };
        let mut jumped = vec![false; sys.contacts.len()];
        let (mut q, mut iterations) = self.positions(t, q0, &mut pairings, &mut jumped)?;
        // a contact is unilateral: where the curves overlap at another pair of points, that pair
        // is the contact (the one followed has left), and the instant is solved again with it
        for _ in 0..MAX_JUMPS {
            let moved = self.overlaps(t, &q, &mut pairings, &mut jumped)?;
            if !moved {
                break;
            }
            let (q2, it2) = self.positions(t, q.clone(), &mut pairings, &mut jumped)?;
            q = q2;
            iterations += it2;
        }
        // velocities: Φ_q q̇ = −Φ_t (the drivers' rates)
        // the first instant's pairings are where the search started, not a jump
        if self.last.is_none() {
            jumped.iter_mut().for_each(|j| *j = false);
        }
        let mut still = vec![false; sys.contacts.len()];
        let st = states(&q, None, nb);
        let a = self.assemble(t, &st, &mut pairings, &mut still, false)?;
        let residual = a.phi.amax();
        if residual > RESIDUAL_TOLERANCE * size {
            let r = a.phi.iamax();
            return Err(SystemError::NoAssembly {
                time: t,
                reason: "the rows are not met where Newton stopped",
                residual,
                row: sys.row_name(r),
            });
        }
        let lu = self.factor(t, &a.jac)?;
        let unscale = |mut v: DVector<f64>| {
            for i in 0..nb {
                v[3 * i + 2] /= size;
            }
            v
        };
        let singular = || SystemError::Singular {
            time: t,
            rows: String::new(),
        };
        let qd = unscale(lu.solve(&a.rate).ok_or_else(singular)?);
        // accelerations: Φ_q q̈ = γ, every contact's γ from its exact sliding rates
        let st = states(&q, Some(&qd), nb);
        let b = self.assemble(t, &st, &mut pairings, &mut still, true)?;
        let qdd = unscale(lu.solve(&b.gamma).ok_or_else(singular)?);
        let bodies: Vec<BodyState> = (0..nb)
            .map(|i| {
                let mut s = st[i];
                s.acceleration = Vec2::new(qdd[3 * i], qdd[3 * i + 1]);
                s.alpha = qdd[3 * i + 2];
                s
            })
            .collect();
        // a contact point that moved along its curve much farther than its sliding rates at
        // both ends say (their mean times the step: third-order accurate) went to another pair
        // of points that was touching too (a gear's next tooth pair)
        if let Some(last) = &self.last {
            let dt = t - last.time;
            for (k, c) in sys.contacts.iter().enumerate() {
                let Some(now) = b.contacts[k].1 else { continue };
                let (was, slid) = (last.pairings[k], last.slides[k]);
                let moved = |curve: &dyn crate::curve::Curve, a: f64, b: f64, rates: (f64, f64)| {
                    let chord = (curve.position(b) - curve.position(a)).norm();
                    let expected = (0.5 * (rates.0 + rates.1) * dt).abs();
                    chord > 2.0 * expected + 1e-3 * size
                };
                if moved(
                    c.curve_a.as_ref(),
                    was.0,
                    pairings[k].0,
                    (slid.0, now.sliding_rate_a),
                ) || moved(
                    c.curve_b.as_ref(),
                    was.1,
                    pairings[k].1,
                    (slid.1, now.sliding_rate_b),
                ) {
                    jumped[k] = true;
                }
            }
        }
        for (all, &j) in self.jumps.iter_mut().zip(&jumped) {
            *all |= j;
        }
        let contacts: Vec<ContactState> = b
            .contacts
            .iter()
            .zip(&jumped)
            .filter_map(|((p, k), &jumped)| {
                k.map(|k| ContactState {
                    pairing: *p,
                    kinematics: k,
                    jumped,
                })
            })
            .collect();
        let rates = contacts
            .iter()
            .map(|c| (c.kinematics.param_rate_a, c.kinematics.param_rate_b))
            .collect();
        let slides = contacts
            .iter()
            .map(|c| (c.kinematics.sliding_rate_a, c.kinematics.sliding_rate_b))
            .collect();
        self.last = Some(Solved {
            time: t,
            q,
            qd,
            qdd,
            pairings,
            rates,
            slides,
        });
        Ok(SystemState {
            time: t,
            bodies,
            contacts,
            iterations,
        })
    }

    /// Whether any contact's curves overlap at another pair of points at positions `q` (by the
    /// global search over their indexes); each that does takes the deepest such pair.
    fn overlaps(
        &self,
        t: f64,
        q: &DVector<f64>,
        pairings: &mut [(f64, f64)],
        jumped: &mut [bool],
    ) -> Result<bool, SystemError> {
        let st = states(q, None, self.sys.bodies.len());
        let mut moved = false;
        for (k, c) in self.sys.contacts.iter().enumerate() {
            let (sa, sb) = (get(&st, c.a), get(&st, c.b));
            let fa = Surface::new(c.curve_a.as_ref(), &sa);
            let fb = Surface::new(c.curve_b.as_ref(), &sb);
            let (ia, ib) = &self.indexes[k];
            let found =
                contact::find_contact_indexed(&fa, ia.as_ref(), &fb, ib.as_ref(), &self.opts)
                    .map_err(|e| SystemError::Contact {
                        time: t,
                        contact: c.name.clone(),
                        reason: e.to_string(),
                    })?;
            if let Proximity::Overlapping(p) = found {
                if p.gap < -self.opts.contact_tolerance {
                    pairings[k] = (p.u_a, p.u_b);
                    jumped[k] = true;
                    moved = true;
                }
            }
        }
        Ok(moved)
    }

    /// Each contact's pairing at the starting poses, by a global search: the touching pair, or
    /// the nearest (apart) or deepest (overlapping) one for Newton to close.
    fn global_pairings(&self, t: f64, q: &DVector<f64>) -> Result<Vec<(f64, f64)>, SystemError> {
        let st = states(q, None, self.sys.bodies.len());
        self.sys
            .contacts
            .iter()
            .map(|c| {
                let (sa, sb) = (get(&st, c.a), get(&st, c.b));
                let fa = Surface::new(c.curve_a.as_ref(), &sa);
                let fb = Surface::new(c.curve_b.as_ref(), &sb);
                match contact::find_contact(&fa, &fb, &self.opts) {
                    Ok(
                        Proximity::Apart(p) | Proximity::Touching(p) | Proximity::Overlapping(p),
                    ) => Ok((p.u_a, p.u_b)),
                    Err(e) => Err(SystemError::Contact {
                        time: t,
                        contact: c.name.clone(),
                        reason: e.to_string(),
                    }),
                }
            })
            .collect()
    }
}
