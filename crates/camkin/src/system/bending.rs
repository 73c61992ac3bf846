//! How a contact's curve bends: whether it bounds a convex body, and its sharpest radius of
//! curvature (for the check that two curves touch nowhere else, and a system's scale).

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
