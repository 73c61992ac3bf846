//! Small dense linear solves of Newton's steps: 2×2 with rows balanced (no pivoting needed for
//! the tangency systems) and 3×3 by nalgebra's LU, each equation scaled first (they mix lengths
//! and lengths squared). Nothing here knows about cams.

/// `J⁻¹ (−f)` for a 2×2 `J`, each equation first scaled by the sum of its coefficients'
/// magnitudes: the
/// coefficients mix units (a cam parameter and a length: a roller's are lengths squared and
/// lengths), so at extreme sizes the unscaled products underflow or overflow even where the
/// determinant does not (a cam 1e-80 in size lost the position's step entirely). Non-finite
/// when `J` is singular.
#[inline(always)]
pub(crate) fn solve2(j: &[[f64; 2]; 2], f: [f64; 2]) -> [f64; 2] {
    // each row times 1 / (sum of its coefficients' magnitudes), without a branch: a zero row
    // gives infinities, a singular `J` a zero or non-finite determinant, and either way a
    // non-finite solution
    let row = |r: [f64; 2], b: f64| {
        let inv = 1.0 / (r[0].abs() + r[1].abs());
        [r[0] * inv, r[1] * inv, b * inv]
    };
    let [a00, a01, b0] = row(j[0], f[0]);
    let [a10, a11, b1] = row(j[1], f[1]);
    let inv_det = 1.0 / (a00 * a11 - a01 * a10);
    [
        (-b0 * a11 + b1 * a01) * inv_det,
        (-a00 * b1 + a10 * b0) * inv_det,
    ]
}

/// `J⁻¹ (−f)` for a 3×3 `J` (nalgebra's LU with partial pivoting), each equation first scaled by
/// its largest coefficient (they mix lengths and lengths squared); `None` when singular.
pub(crate) fn solve3(a: [[f64; 3]; 3], f: [f64; 3]) -> Option<[f64; 3]> {
    let mut m = nalgebra::Matrix3::from_fn(|r, c| a[r][c]);
    let mut b = nalgebra::Vector3::new(-f[0], -f[1], -f[2]);
    for k in 0..3 {
        let s = m.row(k).amax();
        if !(s > 0.0 && s.is_finite()) {
            return None;
        }
        m.row_mut(k).scale_mut(1.0 / s);
        b[k] /= s;
    }
    let x = m.lu().solve(&b)?;
    x.iter().all(|v| v.is_finite()).then(|| [x[0], x[1], x[2]])
}
