//! The contacts' global searches: the first instant's pairings, and the check that two curves
//! overlap nowhere but at the pair of points a contact follows (skipped for two convex curves).

use super::assemble::{get, states};
use super::solve::SystemSweep;
use super::SystemError;
use crate::contact::{self, Proximity, Surface};

/// Whether `curve` bounds a convex body: a point, a straight line, or a closed curve turning one
/// way only (its curvature, sampled 16 times a piece, nowhere below −1e-9 of 1/`size`).
pub(super) fn is_convex(curve: &dyn crate::curve::Curve, size: f64) -> bool {
    use crate::curve::Domain;
    let bent = |u: f64| {
        let d = curve.eval(u);
        crate::geometry::cross(d.d1, d.d2) / d.d1.norm().powi(3)
    };
    match curve.domain() {
        Domain::Point => true,
        Domain::Interval { min, max } => {
            // a line: no curvature anywhere (sampled over a stretch when unbounded)
            let (lo, hi) = (min.max(-size), max.min(size));
            (0..=16).all(|k| bent(lo + (hi - lo) * f64::from(k) / 16.0).abs() <= 1e-12 / size)
        }
        Domain::Periodic { period } => {
            let bp = curve.breakpoints();
            crate::curve::piece_samples(&bp, period, 16, 256).all(|u| bent(u) >= -1e-9 / size)
                && bp.iter().all(|&b| {
                    // a corner turns the tangent the same way
                    let (t0, t1) = (curve.tangent(b.next_down()), curve.tangent(b.next_up()));
                    crate::geometry::cross(t0, t1) >= -1e-12
                })
        }
    }
}

/// The smallest radius of curvature of `curve` (16 samples a piece; a point's is zero; at most
/// `size`).
pub(super) fn sharpest_radius(curve: &dyn crate::curve::Curve, size: f64) -> f64 {
    use crate::curve::Domain;
    let radius = |u: f64| {
        let d = curve.eval(u);
        d.d1.norm().powi(3) / crate::geometry::cross(d.d1, d.d2).abs()
    };
    match curve.domain() {
        Domain::Point => 0.0,
        Domain::Interval { min, max } => {
            let (lo, hi) = (min.max(-size), max.min(size));
            (0..=16)
                .map(|k| radius(lo + (hi - lo) * f64::from(k) / 16.0))
                .fold(size, f64::min)
        }
        Domain::Periodic { period } => {
            let bp = curve.breakpoints();
            crate::curve::piece_samples(&bp, period, 16, 256)
                .map(radius)
                .fold(size, f64::min)
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
