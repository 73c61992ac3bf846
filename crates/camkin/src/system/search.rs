//! The contacts' global searches: the first instant's pairings, and the check that two curves
//! overlap nowhere but at the pair of points a contact follows (skipped for two convex curves).

use super::assemble::{get, states};
use super::solve::SystemSweep;
use super::SystemError;
use crate::contact::{self, Proximity, Surface};

/// How a contact's curve bends, from one pass over its samples (16 a piece, at least 256; an
/// open curve 17 over `size` either side): whether it bounds a convex body (a point, a straight
/// line, or a closed curve turning one way only, its corners too), and its smallest radius of
/// curvature (a point's zero; at most `size`).
pub(super) fn bending(curve: &dyn crate::curve::Curve, size: f64) -> (bool, f64) {
    use crate::curve::Domain;
    let kappa = |u: f64| {
        let d = curve.eval(u);
        crate::geometry::cross(d.d1, d.d2) / d.d1.norm().powi(3)
    };
    // (the most negative curvature, the largest magnitude)
    let fold = |ks: &mut dyn Iterator<Item = f64>| {
        ks.fold((f64::INFINITY, 0.0f64), |(lo, big), k| {
            (lo.min(k), big.max(k.abs()))
        })
    };
    let radius = |big: f64| {
        if big > 0.0 {
            (1.0 / big).min(size)
        } else {
            size
        }
    };
    match curve.domain() {
        Domain::Point => (true, 0.0),
        Domain::Interval { min, max } => {
            let (lo, hi) = (min.max(-size), max.min(size));
            let (_, big) = fold(&mut (0..=16).map(|k| kappa(lo + (hi - lo) * f64::from(k) / 16.0)));
            // a line: no curvature anywhere
            (big <= 1e-12 / size, radius(big))
        }
        Domain::Periodic { period } => {
            let bp = curve.breakpoints();
            let (least, big) =
                fold(&mut crate::curve::piece_samples(&bp, period, 16, 256).map(kappa));
            let corners_turn_one_way = bp.iter().all(|&b| {
                let (t0, t1) = (curve.tangent(b.next_down()), curve.tangent(b.next_up()));
                crate::geometry::cross(t0, t1) >= -1e-12
            });
            (least >= -1e-9 / size && corners_turn_one_way, radius(big))
        }
    }
}

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
