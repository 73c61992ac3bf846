//! Angles of an even grid as people wrote them: `start + k·step` computed, not accumulated, and
//! where `start` and `step` are short decimals (`0.1`, `297.5`), the double nearest that decimal
//! (`0.3`, not `0.30000000000000004`). A table's angle column then reads as typed, and the
//! angle analysed is the one the column shows.

/// The most decimal places a grid is snapped at (a step of 1e-9°).
const MAX_DECIMALS: i32 = 9;

/// An even grid of angles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleGrid {
    start: f64,
    step: f64,
    /// `start` and `step` as whole numbers of `1/10^d`, and `10^d`, when both are such decimals
    decimal: Option<(f64, f64, f64)>,
}

impl AngleGrid {
    /// The grid `start + k·step`.
    pub fn new(start: f64, step: f64) -> Self {
        let decimal = (0..=MAX_DECIMALS).find_map(|d| {
            let p = 10f64.powi(d);
            let (a, b) = ((start * p).round(), (step * p).round());
            // a decimal of d places whose nearest double is the value itself (0.1 is 1/10; 360/7
            // is no short decimal): the grid then moves by exactly that decimal
            let whole = |x: f64, n: f64| n.abs() < 1e15 && n / p == x;
            (whole(start, a) && whole(step, b) && b != 0.0).then_some((a, b, p))
        });
        Self {
            start,
            step,
            decimal,
        }
    }

    /// The `k`-th angle: `(a + k b) / 10^d`, one correctly rounded division of whole numbers,
    /// where the grid is decimal; `start + k·step` otherwise.
    pub fn at(&self, k: usize) -> f64 {
        match self.decimal {
            Some((a, b, p)) => {
                let n = a + k as f64 * b;
                if n.abs() < 9e15 {
                    return n / p;
                }
                self.start + k as f64 * self.step
            }
            None => self.start + k as f64 * self.step,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::AngleGrid;

    #[test]
    fn a_decimal_grid_reads_as_typed() {
        let g = AngleGrid::new(0.0, 0.1);
        assert_eq!(g.at(3), 0.3);
        assert_eq!(g.at(7), 0.7);
        assert_eq!(AngleGrid::new(297.0, 0.5).at(1), 297.5);
        assert_eq!(AngleGrid::new(10.0, -0.25).at(3), 9.25);
        // every angle is the double nearest its decimal, through a whole revolution in 0.05°
        let g = AngleGrid::new(0.0, 0.05);
        for k in 0..7200 {
            let typed: f64 = format!("{}.{:02}", k / 20, (k % 20) * 5).parse().unwrap();
            assert_eq!(g.at(k), typed, "{k}");
        }
    }

    #[test]
    fn a_step_that_is_not_a_short_decimal_is_multiplied() {
        let s = 360.0 / 7.0;
        let g = AngleGrid::new(0.0, s);
        for k in 0..7 {
            assert_eq!(g.at(k), k as f64 * s);
        }
    }
}
