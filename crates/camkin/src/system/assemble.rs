//! Assembling a system's rows at an instant — `Φ`, `Φ_q` (angle columns scaled by the size, so
//! that every entry is of order one), `γ` and the drivers' rates — and Newton on the positions.

use super::lu::Lu;
use super::newton::{
    fill_states, get, iamax, states, Assembly, Scratch, MAX_ITERATIONS, SINGULAR, STEP_TOLERANCE,
    SUSPECT_GAP,
};
use super::solve::SystemSweep;
use super::{BodyId, SystemError};
use crate::body::BodyState;
use crate::contact::{self, ContactKinematics, Pairing, Proximity, Surface};
use crate::geometry::rot90;

impl SystemSweep<'_> {
    /// Assembles the rows at the states `st` into `out`. `with_kinematics`: the states carry
    /// velocities, the contacts' kinematics and `γ` are computed, and the positions are those the
    /// last assembly refined the pairings at (taken as they are).
    pub(super) fn assemble(
        &self,
        t: f64,
        st: &[BodyState],
        pairings: &mut [(f64, f64)],
        jumped: &mut [bool],
        with_kinematics: bool,
        out: &mut Assembly,
    ) -> Result<(), SystemError> {
        let sys = self.sys;
        let n = 3 * sys.bodies.len();
        let m = sys.rows();
        let Assembly {
            phi,
            jac,
            gamma,
            rate,
            contacts,
            rows,
        } = out;
        for v in [&mut *phi, &mut *gamma, &mut *rate] {
            v.clear();
            v.resize(m, 0.0);
        }
        jac.clear();
        jac.resize(m * n, 0.0);
        contacts.clear();
        let size = self.size;
        let put = |jac: &mut [f64], r: usize, id: BodyId, g: [f64; 3]| {
            if let Some(i) = id.index() {
                jac[r * n + 3 * i] += g[0];
                jac[r * n + 3 * i + 1] += g[1];
                jac[r * n + 3 * i + 2] += g[2] / size;
            }
        };
        let mut r = 0;
        for j in &sys.joints {
            let [a, b] = j.kind.bodies();
            rows.clear();
            j.kind.eval(&get(st, a), &get(st, b), rows);
            for e in rows.iter() {
                phi[r] = e.value;
                gamma[r] = e.gamma;
                for (id, g) in e.grads {
                    put(jac, r, id, g);
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
            put(jac, r, BodyId(i), g);
            rate[r] = fd;
            gamma[r] = fdd;
            r += 1;
        }
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
            // at the positions the last assembly refined the pairings for (the kinematics'
            // assembly), the pairing is taken as it is: a Newton step would not move it
            let followed = if with_kinematics {
                Ok(contact::pairing_at(&fa, &fb, pair.0, pair.1))
            } else {
                contact::refine(&fa, &fb, pair.0, pair.1, &self.opts)
            };
            let p = match followed {
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
            put(jac, r, c.a, ga);
            put(jac, r, c.b, gb);
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
        Ok(())
    }

    /// Factors the scaled Jacobian into `lu`, or names the rows it is singular in.
    pub(super) fn factor(&self, t: f64, jac: &[f64], lu: &mut Lu) -> Result<(), SystemError> {
        let n = 3 * self.sys.bodies.len();
        lu.factor(jac, n);
        let (lo, hi) = lu.pivots;
        if n == 0 || (lo > SINGULAR * hi && lo.is_finite()) {
            return Ok(());
        }
        Err(SystemError::Singular {
            time: t,
            rows: self.dependent_rows(jac),
        })
    }

    /// The rows the smallest singular value's left vector weighs: the dependent ones, named.
    pub(super) fn dependent_rows(&self, jac: &[f64]) -> String {
        self.dependent(jac)
            .into_iter()
            .map(|i| self.sys.row_name(i))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The indices of the rows [`Self::dependent_rows`] names.
    fn dependent(&self, jac: &[f64]) -> Vec<usize> {
        let n = 3 * self.sys.bodies.len();
        let svd = nalgebra::DMatrix::from_row_slice(n, n, jac).svd(true, false);
        let k = svd.singular_values.imin();
        svd.u.map_or_else(Vec::new, |u| {
            let col = u.column(k);
            let big = col.amax();
            (0..col.len())
                .filter(|&i| col[i].abs() >= 0.2 * big)
                .collect()
        })
    }

    /// Where the rows are singular while a contact among the dependent ones is apart (its gap
    /// over 1e-3 of the size): the joints and drivers hold its curves apart and no motion they
    /// allow closes it, which is what to say rather than "singular".
    fn held_apart(&self, t: f64, phi: &[f64], jac: &[f64]) -> Option<SystemError> {
        let first = self.sys.rows() - self.sys.contacts.len();
        let dependent = self.dependent(jac);
        let (&r, gap) = dependent
            .iter()
            .filter(|&&r| r >= first)
            .map(|r| (r, phi[*r].abs()))
            .max_by(|a, b| a.1.total_cmp(&b.1))?;
        (gap > 1e-3 * self.size).then(|| SystemError::HeldApart {
            time: t,
            contact: self.sys.contacts[r - first].name.clone(),
            gap,
            rows: dependent
                .iter()
                .filter(|&&i| i != r)
                .map(|&i| self.sys.row_name(i))
                .collect::<Vec<_>>()
                .join(", "),
        })
    }

    /// Positions at `t` by Newton from `q`, with the contacts' pairings from `pairings`.
    pub(super) fn positions(
        &self,
        t: f64,
        q: &mut [f64],
        pairings: &mut [(f64, f64)],
        jumped: &mut [bool],
        w: &mut Scratch,
    ) -> Result<u32, SystemError> {
        let nb = self.sys.bodies.len();
        let size = self.size;
        let mut previous = f64::INFINITY;
        for it in 1..=MAX_ITERATIONS {
            fill_states(q, None, nb, &mut w.st);
            self.assemble(t, &w.st, pairings, jumped, false, &mut w.asm)?;
            if let Err(e) = self.factor(t, &w.asm.jac, &mut w.lu) {
                return Err(self.held_apart(t, &w.asm.phi, &w.asm.jac).unwrap_or(e));
            }
            w.neg.clear();
            w.neg.extend(w.asm.phi.iter().map(|v| -v));
            w.lu.solve(&w.neg, &mut w.x);
            // a step longer than a quarter of the size (or a quarter turn) is shortened: far
            // from the solution the linearisation is poor and a full step can jump branches
            let longest = w.x.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            if longest > 0.25 * size {
                let k = 0.25 * size / longest;
                w.x.iter_mut().for_each(|v| *v *= k);
            }
            let step = &w.x;
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
                return Ok(it);
            }
            // a first step δ leaves an error of about δ²/ρ, ρ the sharpest radius of curvature
            // of the contacts' curves: below the tolerance, one iteration is enough (a warm
            // instant, predicted to fourth order, starts there)
            if it == 1 && moved * moved <= 0.1 * STEP_TOLERANCE * size * self.sharpest {
                return Ok(it);
            }
            // Newton converges quadratically: after steps `s₁` then `s₂` the error left is about
            // `s₂³ / s₁²`; below the tolerance, a further iteration would not move anything
            if previous.is_finite()
                && moved * moved * moved <= STEP_TOLERANCE * size * previous * previous
                && moved < 1e-3 * previous
            {
                return Ok(it);
            }
            previous = moved;
        }
        let st = states(q, None, nb);
        self.assemble(t, &st, pairings, jumped, false, &mut w.asm)?;
        let r = iamax(&w.asm.phi);
        Err(SystemError::NoAssembly {
            time: t,
            reason: "Newton did not converge",
            residual: w.asm.phi[r].abs(),
            row: self.sys.row_name(r),
        })
    }
}
