//! The analysis as the page needs it: numbers rounded to what the page can show, so that the
//! answer to a drag is a fraction of its full-precision size and parses in a fraction of the
//! time. Downloads (`/api/csv`, the report) are made apart and keep every digit.
//!
//! - geometry (the drawing's frames, the profile, the follower's curves, the marked stretches):
//!   to a decimal step of at most 1e-6 of the drawing's extent (a thousandth of a pixel on a
//!   1000-pixel canvas);
//! - angles in the frames (rad) to 1e-9, unit normals to 1e-9;
//! - each series to a decimal step of at most 1e-7 of its largest magnitude (the readouts show
//!   four significant digits; smaller values are rounding and read as 0).
//!
//! The spline's nodes, which a drag sends back into the file, and the force coefficients, which
//! the page computes with, are left as they are.

use super::answer::{Analysis, Compare, ShapeOut};

/// `x` to the nearest multiple of `10^-k` (`k` may be negative), written with its shortest
/// decimal: an integer over an exact power of ten is the double nearest that decimal.
fn to_step(x: f64, k: i32) -> f64 {
    // a value too large for the step to matter (its multiples are not exact doubles)
    if !x.is_finite() || (x * 10f64.powi(k)).abs() >= 2f64.powi(52) {
        return x;
    }
    let r = if k >= 0 {
        let p = 10f64.powi(k);
        (x * p).round() / p
    } else {
        let p = 10f64.powi(-k);
        (x / p).round() * p
    };
    // −0 prints as "-0.0"
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

/// The decimal exponent `k` of the largest power-of-ten step `10^-k` not above `fraction` of
/// `scale` (`None` for a zero or non-finite scale: nothing to round against).
fn digits(scale: f64, fraction: f64) -> Option<i32> {
    let s = scale.abs() * fraction;
    (s.is_finite() && s > 0.0).then(|| -(s.log10().floor() as i32))
}

fn point(p: &mut [f64; 2], k: i32) {
    p[0] = to_step(p[0], k);
    p[1] = to_step(p[1], k);
}

/// Rounds the analysis for the page (see the module's docs).
pub fn for_page(a: &mut Analysis) {
    let [x0, y0, x1, y1] = a.extent;
    let size = (x1 - x0).abs().max((y1 - y0).abs());
    if let Some(k) = digits(size, 1e-6) {
        let pose = |p: &mut [f64; 3]| {
            p[0] = to_step(p[0], k);
            p[1] = to_step(p[1], k);
            p[2] = to_step(p[2], 9);
        };
        for f in &mut a.frames {
            pose(&mut f.cam);
            if let Some(c) = &mut f.contact {
                point(c, k);
            }
            if let Some(n) = &mut f.normal {
                point(n, 9);
            }
            for s in &mut f.follower {
                match s {
                    ShapeOut::Line { pts, .. } => pts.iter_mut().for_each(|p| point(p, k)),
                    ShapeOut::Circle { c, r, .. } => {
                        point(c, k);
                        *r = to_step(*r, k);
                    }
                    ShapeOut::Dot { p, .. } => point(p, k),
                    ShapeOut::Curve { pose: p, .. } => pose(p),
                }
            }
        }
        a.profile.iter_mut().for_each(|p| point(p, k));
        for c in &mut a.curves {
            c.iter_mut().for_each(|p| point(p, k));
        }
        for c in &mut a.checks {
            for s in &mut c.stretches {
                s.iter_mut().for_each(|p| point(p, k));
            }
        }
    }
    for s in &mut a.series {
        // rounded against its motion's scale when it has one (its resolution is 1e-9 of it)
        series_scaled(&mut s.values, s.resolution.map_or(0.0, |r| 1e9 * r));
    }
    if let Some(l) = a.dynamics.as_mut().and_then(|d| d.lubrication.as_mut()) {
        series(&mut l.lambda);
        series(&mut l.film_minimum_um);
        series(&mut l.flash_temperature_k);
    }
}

/// The interpolation study for the page: its curves as the analysis' series (the exact one is
/// then the analysis' acceleration, value for value).
pub fn compare_for_page(c: &mut Compare) {
    series_scaled(&mut c.exact, c.scale);
    for r in &mut c.runs {
        series_scaled(&mut r.acceleration, c.scale);
    }
}

/// A series to a decimal step of at most 1e-7 of its largest magnitude.
fn series(values: &mut [Option<f64>]) {
    series_scaled(values, 0.0)
}

/// A series to a decimal step of at most 1e-7 of its largest magnitude, or of `scale` when that
/// magnitude is under 1e-6 of it (a rate that is zero but for rounding: an ideal gear pair's
/// acceleration reads 0, not its noise).
fn series_scaled(values: &mut [Option<f64>], scale: f64) {
    let largest = values
        .iter()
        .flatten()
        .filter(|v| v.is_finite())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let top = if largest < 1e-6 * scale {
        scale
    } else {
        largest
    };
    if let Some(k) = digits(top, 1e-7) {
        for v in values.iter_mut().flatten() {
            *v = to_step(*v, k);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A value rounded to a step is within half the step, prints no longer than the step's
    /// digits, and is the same read back.
    #[test]
    fn rounded_values_are_near_short_and_round_trip() {
        for (i, k) in [(0u32, 6), (1, 3), (2, 0), (3, -2), (4, 12)] {
            for j in 0..2000 {
                let x =
                    (f64::from(j) * 0.618_033_988_749 + f64::from(i)).sin() * 10f64.powi(j % 9 - 3);
                let r = to_step(x, k);
                if (x * 10f64.powi(k)).abs() >= 2f64.powi(52) {
                    assert_eq!(r, x);
                    continue;
                }
                let slack = 0.5 * 10f64.powi(-k) + 4.0 * f64::EPSILON * x.abs();
                assert!((r - x).abs() <= slack, "{x} {k}");
                let text = r.to_string();
                let decimals = text.split('.').nth(1).map_or(0, str::len);
                assert!(decimals as i32 <= k.max(0), "{x} at {k}: {text}");
                assert_eq!(text.parse::<f64>().unwrap(), r);
            }
        }
        assert_eq!(to_step(-1e-20, 6).to_string(), "0");
        assert_eq!(digits(0.0, 1e-6), None);
        assert_eq!(digits(40.0, 1e-6), Some(5));
    }
}
