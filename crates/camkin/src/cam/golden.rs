//! Golden-section search, the one the method's searches share (the independent check in
//! `support` keeps its own, so that it shares no code with the method).

/// The minimum of `f` on `[a, b]` by at most `iterations` golden-section steps, `(u, f(u))`;
/// stops early once `stop` holds for a value evaluated.
pub(crate) fn golden_min(
    f: impl Fn(f64) -> f64,
    mut a: f64,
    mut b: f64,
    iterations: usize,
    stop: impl Fn(f64) -> bool,
) -> (f64, f64) {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - g * (b - a);
    let mut d = a + g * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..iterations {
        if stop(fc) || stop(fd) {
            break;
        }
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    if fc <= fd {
        (c, fc)
    } else {
        (d, fd)
    }
}

#[cfg(test)]
mod tests {
    use super::golden_min;

    #[test]
    fn finds_the_minimum_and_stops_when_asked() {
        let (u, v) = golden_min(|u| (u - 0.3).powi(2), 0.0, 1.0, 80, |_| false);
        assert!((u - 0.3).abs() < 1e-7 && v < 1e-14);
        // stops at the first negative value
        let (_, v) = golden_min(|u| (u - 0.5).powi(2) - 1e-4, 0.0, 1.0, 80, |v| v < 0.0);
        assert!(v < 0.0 && v > -1e-4);
    }
}
