//! Extremes found where they are, not at the sampling grid: a report scans a quantity at sampled
//! angles (or parameters), then refines the best sample on the exact curve by golden-section
//! search between its neighbours — the way the lift's rest position is found. A quantity that
//! cannot be evaluated at a point (a failed analysis, or outside the class asked for: a
//! concave radius when the smallest convex one is wanted) counts as worse than any value.

/// Golden-section steps: the bracket shrinks by 0.618 each, to 1e-13 of it after 62.
const STEPS: usize = 64;

/// The extreme of `f` near the sample `at = (t, f(t))`, searched on `[a, b]` (`a ≤ t ≤ b`): the
/// largest `sign · f` (`sign` +1 for a maximum, −1 for a minimum), kept only where it improves on
/// the sample. Returns `(t, f(t))`.
pub fn refine(
    f: impl Fn(f64) -> Option<f64>,
    a: f64,
    b: f64,
    at: (f64, f64),
    sign: f64,
) -> (f64, f64) {
    if !(b > a) {
        return at;
    }
    let score = |t: f64| {
        f(t).filter(|v| v.is_finite())
            .map_or(f64::NEG_INFINITY, |v| sign * v)
    };
    let (t, worst) = crate::cam::golden::golden_min(|t| -score(t), a, b, STEPS, |_| false);
    let s = -worst;
    // the search locates an extreme to about 1e-8 of its bracket (the quantity is flat there):
    // a move below 1e-5 of it is the sample itself (the value differs by 1e-10 of the bracket's
    // curvature there)
    if s > sign * at.1 && (t - at.0).abs() > 1e-5 * (b - a) {
        (t, sign * s)
    } else {
        at
    }
}

/// The best of the samples `values` at `ts` (the largest `sign · value`, `None`s skipped),
/// refined by [`refine`] between its neighbours; `period` says the samples cover one period
/// (the first's left neighbour is the last, less the period). `None` without any value.
pub fn best_refined(
    ts: &[f64],
    values: &[Option<f64>],
    sign: f64,
    period: Option<f64>,
    f: impl Fn(f64) -> Option<f64>,
) -> Option<(f64, f64)> {
    // the first of equal samples
    let (k, v) = values
        .iter()
        .enumerate()
        .filter_map(|(k, v)| v.filter(|v| v.is_finite()).map(|v| (k, v)))
        .fold(None, |best: Option<(usize, f64)>, (k, v)| match best {
            Some((_, b)) if sign * v <= sign * b => best,
            _ => Some((k, v)),
        })?;
    let n = ts.len();
    let left = match (k, period) {
        (0, Some(p)) if n > 1 => ts[n - 1] - p,
        (0, _) => ts[0],
        _ => ts[k - 1],
    };
    let right = match (k + 1 == n, period) {
        (true, Some(p)) if n > 1 => ts[0] + p,
        (true, _) => ts[k],
        _ => ts[k + 1],
    };
    Some(refine(f, left, right, (ts[k], v), sign))
}

/// The run of samples around index `k` of a revolution's samples `values` (periodic: the first
/// follows the last) whose values equal `values[k]` within `tol`: `(first, last)` indices
/// (wrapping, `last` may be below `first`), or `None` when the sample is alone at its value. An
/// extreme held over a dwell is named as its stretch, not as one sample of it.
pub fn held_run(values: &[f64], k: usize, tol: f64) -> Option<(usize, usize)> {
    let n = values.len();
    if n < 3 || k >= n {
        return None;
    }
    let same = |i: usize| (values[i % n] - values[k]).abs() <= tol;
    let (mut lo, mut hi) = (0usize, 0usize);
    while lo + 1 < n && same(k + n - lo - 1) {
        lo += 1;
    }
    while hi + 1 < n - lo && same(k + hi + 1) {
        hi += 1;
    }
    (lo + hi > 0).then(|| ((k + n - lo) % n, (k + hi) % n))
}

/// Words for the stretch of cam angles `a` to `b` (degrees) over which a value is held:
/// "from 300° to 360°", "from 350° through 0° to 10°" (`b` below `a`: the run wraps), with
/// `degrees` writing an angle for people.
pub fn stretch_words(a: f64, b: f64, degrees: impl Fn(f64) -> String) -> String {
    if b == 0.0 {
        format!("from {} to 360°", degrees(a))
    } else if b < a {
        format!("from {} through 0° to {}", degrees(a), degrees(b))
    } else {
        format!("from {} to {}", degrees(a), degrees(b))
    }
}

/// Whether the angles `ts` (rad) sample one whole revolution evenly (each step the same, the
/// last one step short of a turn past the first): then the first sample's left neighbour is the
/// last.
pub fn is_revolution(ts: &[f64]) -> bool {
    let n = ts.len();
    if n < 3 {
        return false;
    }
    let step = std::f64::consts::TAU / n as f64;
    ts.windows(2)
        .all(|w| ((w[1] - w[0]) - step).abs() <= 1e-9 * step)
}

#[cfg(test)]
mod tests {

    #[test]
    fn held_runs_wrap_round_the_revolution() {
        let v = [0.0, 0.0, 1.0, 2.0, 2.0, 2.0, 1.0, 0.0];
        assert_eq!(held_run(&v, 4, 1e-12), Some((3, 5)));
        // the run at rest wraps: from index 7 through 0 to 1
        assert_eq!(held_run(&v, 0, 1e-12), Some((7, 1)));
        assert_eq!(held_run(&v, 2, 1e-12), None);
        assert_eq!(
            stretch_words(300.0, 0.0, |d| format!("{d}°")),
            "from 300° to 360°"
        );
        assert_eq!(
            stretch_words(350.0, 10.0, |d| format!("{d}°")),
            "from 350° through 0° to 10°"
        );
    }

    use super::*;

    #[test]
    fn a_minimum_between_samples_is_found_where_it_is() {
        // a minimum at 0.3137, samples every 0.1
        let f = |t: f64| Some(5.0 + (t - 0.3137).powi(2));
        let ts: Vec<f64> = (0..10).map(|k| k as f64 * 0.1).collect();
        let vs: Vec<Option<f64>> = ts.iter().map(|&t| f(t)).collect();
        let (t, v) = best_refined(&ts, &vs, -1.0, None, f).unwrap();
        assert!(
            (t - 0.3137).abs() < 1e-7 && (v - 5.0).abs() < 1e-13,
            "{t} {v}"
        );
        // a maximum across the period's end: samples 0..2π, the peak at −0.02 (= 2π − 0.02)
        let g = |t: f64| Some((t + 0.02).cos());
        let n = 90;
        let ts: Vec<f64> = (0..n)
            .map(|k| k as f64 * std::f64::consts::TAU / n as f64)
            .collect();
        assert!(is_revolution(&ts));
        let vs: Vec<Option<f64>> = ts.iter().map(|&t| g(t)).collect();
        let (t, v) = best_refined(&ts, &vs, 1.0, Some(std::f64::consts::TAU), g).unwrap();
        assert!(
            (t + 0.02).abs() < 1e-7 && (v - 1.0).abs() < 1e-13,
            "{t} {v}"
        );
    }

    #[test]
    fn points_outside_the_class_never_win() {
        // the smallest positive value: negative values are not candidates
        let f = |t: f64| {
            let v = t - 0.25;
            (v > 0.0).then_some(v)
        };
        let (t, v) = refine(f, 0.2, 0.4, (0.3, 0.05), -1.0);
        assert!(v > 0.0 && v < 1e-12 && t > 0.25, "{t} {v}");
        // nothing better: the sample stays
        assert_eq!(refine(|_| None, 0.0, 1.0, (0.5, 3.0), 1.0), (0.5, 3.0));
    }
}
