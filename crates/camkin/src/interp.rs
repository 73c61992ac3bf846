//! The paper's comparison method (section 3): sample the follower's position at `N` equally
//! spaced cam angles over one revolution, interpolate with a periodic cubic spline in `θ`, and
//! differentiate it (`v = θ̇ s'(θ)`, `a = θ̇² s''(θ) + θ̈ s'(θ)`); and the relative error as the
//! paper defines it, `|a_method − a_exact| / max over the cycle of |a_exact|`.

use crate::cam::{CamError, Mechanism};
use crate::periodic::ScalarSpline;
use std::f64::consts::TAU;

/// The follower's motion interpolated from `N` positions per revolution.
#[derive(Debug, Clone)]
pub struct Interpolated {
    spline: ScalarSpline,
    nodes: usize,
    speed: f64,
    angular_acceleration: f64,
}

impl Interpolated {
    /// Samples `mech`'s position at `θ_k = 2πk/N` (each by a global first-touch search) and
    /// interpolates it. `N ≥ 3`.
    pub fn new(mech: &Mechanism, nodes: usize) -> Result<Self, CamError> {
        if nodes < 3 {
            return Err(CamError::TooFewNodes { nodes });
        }
        let positions = (0..nodes)
            .map(|k| mech.position(TAU * k as f64 / nodes as f64))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self::from_positions(
            &positions,
            mech.cam().speed(),
            mech.cam().angular_acceleration(),
        ))
    }

    /// Whether the follower's motion repeats every revolution, as the interpolation of a
    /// revolution's positions by a periodic spline assumes: its net motion over a revolution
    /// (the mean velocity at 64 evenly spaced angles times a revolution's time) must be under
    /// 1 % of its peak velocity times that time. A cam's is zero; a gear pair's driven gear
    /// moves on by its ratio of a turn: [`CamError::MotionDoesNotRepeat`].
    pub fn check_repeats(mech: &Mechanism) -> Result<(), CamError> {
        let n = 64;
        let thetas: Vec<f64> = (0..n).map(|k| TAU * k as f64 / n as f64).collect();
        let v: Vec<f64> = mech
            .analyze_all(&thetas)
            .into_iter()
            .map(|r| r.map(|s| s.velocity))
            .collect::<Result<_, _>>()?;
        let peak = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let mean = v.iter().sum::<f64>() / n as f64;
        let moves_on = if peak > 0.0 { (mean / peak).abs() } else { 0.0 };
        if moves_on > 1e-2 {
            return Err(CamError::MotionDoesNotRepeat { moves_on });
        }
        Ok(())
    }

    /// Interpolates positions given at `θ_k = 2πk/N` (N = `positions.len()` ≥ 3), with cam speed
    /// `speed` (rad/s) and angular acceleration `angular_acceleration` (rad/s²).
    pub fn from_positions(positions: &[f64], speed: f64, angular_acceleration: f64) -> Self {
        Self {
            spline: ScalarSpline::uniform(positions, TAU),
            nodes: positions.len(),
            speed,
            angular_acceleration,
        }
    }

    /// Number of nodal points.
    pub fn nodes(&self) -> usize {
        self.nodes
    }
    /// Interpolated position at cam angle `theta` (rad).
    pub fn position(&self, theta: f64) -> f64 {
        self.spline.eval(theta)[0]
    }
    /// Interpolated velocity `θ̇ s'(θ)`.
    pub fn velocity(&self, theta: f64) -> f64 {
        self.speed * self.spline.eval(theta)[1]
    }
    /// Interpolated acceleration `θ̇² s''(θ) + θ̈ s'(θ)`.
    pub fn acceleration(&self, theta: f64) -> f64 {
        let e = self.spline.eval(theta);
        self.speed * self.speed * e[2] + self.angular_acceleration * e[1]
    }
}

/// The paper's relative error: `|approx_i − exact_i| / max_j |exact_j|`.
pub fn relative_errors(exact: &[f64], approx: &[f64]) -> Vec<f64> {
    let scale = exact.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    exact
        .iter()
        .zip(approx)
        .map(|(e, a)| (a - e).abs() / scale)
        .collect()
}

/// Largest and mean value of a list of errors.
pub fn max_and_mean(errors: &[f64]) -> (f64, f64) {
    let max = errors.iter().fold(0.0f64, |m, &x| m.max(x));
    let mean = errors.iter().sum::<f64>() / errors.len().max(1) as f64;
    (max, mean)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_error_uses_cycle_maximum() {
        let e = relative_errors(&[1.0, -4.0, 2.0], &[1.5, -4.0, 1.0]);
        assert_eq!(e, vec![0.125, 0.0, 0.25]);
        assert_eq!(max_and_mean(&e), (0.25, 0.125));
    }

    #[test]
    fn interpolates_harmonic_motion_with_second_order_acceleration_error() {
        // s = cos θ: s'' = −cos θ; the spline's second derivative converges like h².
        let err = |n: usize| {
            let pos: Vec<f64> = (0..n).map(|k| (TAU * k as f64 / n as f64).cos()).collect();
            let it = Interpolated::from_positions(&pos, 2.0, 0.0);
            (0..5000)
                .map(|k| {
                    let t = TAU * (k as f64 + 0.3) / 5000.0;
                    (it.acceleration(t) + 4.0 * t.cos()).abs()
                })
                .fold(0.0, f64::max)
        };
        let order = (err(200) / err(400)).log2();
        assert!((order - 2.0).abs() < 0.2, "order {order}");
    }
}
