//! How the one-coordinate model sees a jump of the contact (see the parent module's docs): a
//! first touch that is not the smooth continuation of the last one, and where the two parts'
//! first touches cross.

use super::{Kin, Reduced};

impl Reduced<'_> {
    /// Whether the first touch `k` at `th` is not the smooth continuation of `k0` at `th0`: the
    /// sweep says it jumped, or the change of its slope is not the trapezoidal integral of its
    /// second derivative (exact to `O(Δθ³)` on a smooth first touch, off by the whole kink where
    /// the sweep's Newton slid onto the crossing part unflagged).
    pub(super) fn broke(&self, k0: &Kin, th0: f64, k: &Kin, th: f64) -> bool {
        if k.jumped {
            return true;
        }
        let d = th - th0;
        let change = k.d1 - k0.d1;
        let scale = if self.rotating { 1.0 } else { self.size };
        (change - 0.5 * d * (k0.d2 + k.d2)).abs() > 0.05 * change.abs() + 1e-9 * scale
    }

    /// The cam angle near `th_b` where the first touch `ka` (at `th_a`, followed so far) and
    /// `kb` (at `th_b`, the part that leads there) cross, by Newton on their second-order
    /// expansions; `th_b` where they run parallel (an ideal involute handover: both touch).
    pub(super) fn crossing(ka: &Kin, th_a: f64, kb: &Kin, th_b: f64) -> f64 {
        let at = |k: &Kin, th0: f64, th: f64| {
            let d = th - th0;
            (k.o + d * (k.d1 + 0.5 * d * k.d2), k.d1 + d * k.d2)
        };
        let mut th = th_b;
        for _ in 0..4 {
            let ((oa, sa), (ob, sb)) = (at(ka, th_a, th), at(kb, th_b, th));
            let slope = sb - sa;
            if slope.abs() <= 1e-9 * (sa.abs() + sb.abs()) {
                return th_b;
            }
            th -= (ob - oa) / slope;
        }

        // behind the detection by at most a few samples of the profile; never after it
        if th <= th_b && th_b - th <= 0.05 {
            th
        } else {
            th_b
        }
    }
}
