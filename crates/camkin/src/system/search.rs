//! The contacts' global searches: the first instant's pairings, and the check that two curves
//! overlap nowhere but at the pair of points a contact follows (skipped for two convex curves).

use super::newton::{get, states};
use super::solve::SystemSweep;
use super::SystemError;
use crate::contact::{self, Proximity, Surface};

impl SystemSweep<'_> {
    /// Whether any contact's curves overlap at another pair of points at positions `q` (by the
    /// global search over their indexes); each that does takes the deepest such pair.
    pub(super) fn overlaps(
        &self,
        t: f64,
        q: &[f64],
        pairings: &mut [(f64, f64)],
        jumped: &mut [bool],
    ) -> Result<bool, SystemError> {
        // two convex curves touching at a point overlap nowhere else: nothing to check
        if self.convex.iter().all(|&c| c) {
            return Ok(false);
        }
        let st = states(q, None, self.sys.bodies.len());
        let mut moved = false;
        for (k, c) in self.sys.contacts.iter().enumerate() {
            if self.convex[k] {
                continue;
            }
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
    pub(super) fn global_pairings(
        &self,
        t: f64,
        q: &[f64],
    ) -> Result<Vec<(f64, f64)>, SystemError> {
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
