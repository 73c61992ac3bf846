//! The implicit integrator of stiff systems: the L-stable, stiffly accurate SDIRK method of
//! order 4 with an embedded solution of order 3 of Hairer and Wanner (*Solving Ordinary
//! Differential Equations II*, 2nd ed., Springer 1996, §IV.6, Table 6.5; `γ = 1/4`, five
//! stages), for systems whose fastest elements (a damper of 10⁹ N·s/m, a lash adjuster's oil)
//! would hold the explicit pair ([`super::dopri`]) to steps far shorter than the motion needs.
//!
//! Each stage `Zᵢ = y₀ + h Σⱼ<ᵢ aᵢⱼ kⱼ + h γ f(t₀ + cᵢ h, Zᵢ)` is solved by simplified Newton
//! iterations with the matrix `I − h γ J` (`J = ∂f/∂y` by forward differences at a step's start,
//! kept from step to step while the iterations converge fast, made again where they do not or
//! where the caller says the equations changed), and `kᵢ = (Zᵢ − y₀ − h Σⱼ<ᵢ aᵢⱼ kⱼ)/(h γ)`
//! (not `f(Zᵢ)`: Hairer and Wanner's advice for stiff components, §IV.8). The last stage is the
//! solution (stiffly accurate: no amplification of the stiff components, `R(∞) = 0`). The
//! error is the difference from the embedded third-order solution, filtered by
//! `(I − h γ J)⁻¹` as in RADAU5 (so that a stiff component's estimate does not reject every
//! step: Hairer and Wanner §IV.8, (8.19)–(8.20)); the controller is the explicit pair's with the
//! estimate's order 4. Inside a step the solution is the cubic Hermite interpolant of its ends
//! and their derivatives (third order: for events and outputs).
//!
//! The Newton iterations stop when `η ‖Δ‖ ≤ κ` (`η = θ/(1 − θ)` from the contraction `θ` of the
//! last two increments, `κ = 0.03`, norms in units of the tolerance; §IV.8 (8.10)); an
//! iteration that diverges (`θ ≥ 1`) or is still short after ten rejects the step, which is
//! tried again shorter with a new Jacobian.
//!
//! Evaluated and not used: `diffsol` (BDF and ESDIRK for `M y' = f`, its own step loop: no
//! projection onto the constraints after a step, no contact mode switched at an event, heavy
//! linear-algebra back ends for a 2-core build) and `russell_ode` (Radau5 on the system's
//! BLAS/LAPACK). The tableau, its Newton and its control are written out against the reference.

use nalgebra::{DMatrix, DVector};

/// `γ`, the diagonal.
const GAMMA: f64 = 0.25;
/// `cᵢ`.
const C: [f64; 5] = [0.25, 0.75, 11.0 / 20.0, 0.5, 1.0];
/// `aᵢⱼ` below the diagonal.
const A: [[f64; 4]; 5] = [
    [0.0; 4],
    [0.5, 0.0, 0.0, 0.0],
    [17.0 / 50.0, -1.0 / 25.0, 0.0, 0.0],
    [371.0 / 1360.0, -137.0 / 2720.0, 15.0 / 544.0, 0.0],
    [25.0 / 24.0, -49.0 / 48.0, 125.0 / 16.0, -85.0 / 12.0],
];
/// `bⱼ`: the last row of `A` with `γ` (stiffly accurate).
const B: [f64; 5] = [25.0 / 24.0, -49.0 / 48.0, 125.0 / 16.0, -85.0 / 12.0, 0.25];
/// `b̂ⱼ`: the embedded third-order solution's weights.
const B_HAT: [f64; 5] = [59.0 / 48.0, -17.0 / 96.0, 225.0 / 32.0, -85.0 / 12.0, 0.0];
/// Newton's stopping constant `κ`.
const KAPPA: f64 = 0.03;
/// The most Newton iterations a stage takes.
const MAX_NEWTON: usize = 10;
/// A contraction slower than this makes a new Jacobian for the next step.
const SLOW: f64 = 0.3;

/// A step's stages, its end, its Jacobian and its interpolant: buffers reused from step to step.
#[derive(Debug, Clone, Default)]
pub(crate) struct Sdirk {
    /// `f(t₀, y₀)`, given by the caller before a step
    pub(crate) f0: Vec<f64>,
    /// `k₁ … k₅`
    k: [Vec<f64>; 5],
    /// the step's start and end
    pub(crate) y0: Vec<f64>,
    pub(crate) y1: Vec<f64>,
    /// the step's start and length
    pub(crate) t0: f64,
    pub(crate) h: f64,
    /// `∂f/∂y` (the columns of the first `states` components; the rest, the work integrated
    /// beside the motion, do not enter `f`)
    jac: Option<DMatrix<f64>>,
    /// the factor of `I − h γ J` and the `h` it was made with
    lu: Option<(f64, nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>)>,
    /// make the Jacobian again before the next step
    stale: bool,
    /// Jacobians made and steps whose Newton failed, since the start
    pub(crate) jacobians: usize,
    pub(crate) newton_failures: usize,
}

impl Sdirk {
    /// The equations changed (a contact closed or opened, the state jumped): the next step
    /// makes a new Jacobian.
    pub(crate) fn invalidate(&mut self) {
        self.stale = true;
    }

    /// The Jacobian and its factor of `other`, for a step taken again from its start.
    pub(crate) fn share(&mut self, other: &Sdirk) {
        self.jac.clone_from(&other.jac);
        self.lu.clone_from(&other.lu);
        self.stale = false;
    }

    /// A step of `h` from `(t, y0)` with `f(t, y0)` in `self.f0`: the stages by `f(t, y, dy)`,
    /// the end in `self.y1`; the filtered error's maximum norm with the scales
    /// `scale(i, |y0ᵢ|, |y1ᵢ|)` (components with an infinite scale are not measured), or
    /// infinity where Newton did not converge. `states` components have Jacobian columns;
    /// `typical(i)` is component `i`'s size (its difference quotient's step is `1.5e-8` of it
    /// or of `|yᵢ|`).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn attempt<E>(
        &mut self,
        t: f64,
        y0: &[f64],
        h: f64,
        states: usize,
        f: &mut impl FnMut(f64, &[f64], &mut Vec<f64>) -> Result<(), E>,
        scale: impl Fn(usize, f64, f64) -> f64,
        typical: impl Fn(usize) -> f64,
    ) -> Result<f64, E> {
        let n = y0.len();
        self.t0 = t;
        self.h = h;
        self.y0.clear();
        self.y0.extend_from_slice(y0);
        if self.stale || self.jac.as_ref().is_none_or(|j| j.nrows() != n) {
            self.jacobian(t, states, f, &typical)?;
        }
        let hg = h * GAMMA;
        if self.lu.as_ref().is_none_or(|(at, _)| *at != hg) {
            let j = self.jac.as_ref().expect("made above");
            let m = DMatrix::<f64>::identity(n, n) - j * hg;
            self.lu = Some((hg, m.lu()));
        }
        let sc: Vec<f64> = (0..n).map(|i| scale(i, y0[i].abs(), y0[i].abs())).collect();
        let norm = |v: &[f64]| -> f64 {
            v.iter()
                .zip(&sc)
                .filter(|(_, s)| s.is_finite())
                .fold(0.0f64, |m, (x, s)| m.max((x / s).abs()))
        };
        let mut base = vec![0.0; n];
        let mut z = vec![0.0; n];
        let mut fz = Vec::with_capacity(n);
        let mut delta = DVector::<f64>::zeros(n);
        let mut slow = false;
        for s in 0..5 {
            base.copy_from_slice(y0);
            for (j, &a) in A[s].iter().enumerate().take(s) {
                for (b, k) in base.iter_mut().zip(&self.k[j]) {
                    *b += h * a * k;
                }
            }
            // the guess: the last stage's slope
            let guess = if s == 0 { &self.f0 } else { &self.k[s - 1] };
            for i in 0..n {
                z[i] = base[i] + hg * guess[i];
            }
            let mut last: Option<f64> = None;
            let mut converged = false;
            for _ in 0..MAX_NEWTON {
                f(t + C[s] * h, &z, &mut fz)?;
                for i in 0..n {
                    delta[i] = -(z[i] - base[i] - hg * fz[i]);
                }
                let lu = &self.lu.as_ref().expect("made above").1;
                if !lu.solve_mut(&mut delta) {
                    break;
                }
                for i in 0..n {
                    z[i] += delta[i];
                }
                let d = norm(delta.as_slice());
                if !d.is_finite() {
                    break;
                }
                match last {
                    Some(prev) if prev > 0.0 => {
                        let theta = d / prev;
                        if theta >= 1.0 {
                            break;
                        }
                        slow |= theta > SLOW;
                        if theta / (1.0 - theta) * d <= KAPPA {
                            converged = true;
                            break;
                        }
                    }
                    _ => {
                        if d <= 1e-3 * KAPPA {
                            converged = true;
                            break;
                        }
                    }
                }
                last = Some(d);
            }
            if !converged {
                self.newton_failures += 1;
                self.stale = true;
                return Ok(f64::INFINITY);
            }
            let k = &mut self.k[s];
            k.clear();
            k.extend((0..n).map(|i| (z[i] - base[i]) / hg));
        }
        self.stale = slow;
        std::mem::swap(&mut self.y1, &mut z);
        // the error, filtered by (I − h γ J)⁻¹
        for i in 0..n {
            delta[i] = h
                * (0..5)
                    .map(|j| (B[j] - B_HAT[j]) * self.k[j][i])
                    .sum::<f64>();
        }
        let lu = &self.lu.as_ref().expect("made above").1;
        if !lu.solve_mut(&mut delta) {
            return Ok(f64::INFINITY);
        }
        let mut worst: f64 = 0.0;
        for i in 0..n {
            let s = scale(i, y0[i].abs(), self.y1[i].abs());
            if s.is_finite() {
                worst = worst.max((delta[i] / s).abs());
            }
        }
        Ok(worst)
    }

    /// `J = ∂f/∂y` at `(t, y₀)` by forward differences of the first `states` columns.
    fn jacobian<E>(
        &mut self,
        t: f64,
        states: usize,
        f: &mut impl FnMut(f64, &[f64], &mut Vec<f64>) -> Result<(), E>,
        typical: &impl Fn(usize) -> f64,
    ) -> Result<(), E> {
        let n = self.y0.len();
        let mut jac = DMatrix::<f64>::zeros(n, n);
        let mut y = self.y0.clone();
        let mut fy = Vec::with_capacity(n);
        for j in 0..states.min(n) {
            let d = 1.5e-8 * self.y0[j].abs().max(typical(j));
            y[j] = self.y0[j] + d;
            let d = y[j] - self.y0[j];
            f(t, &y, &mut fy)?;
            for i in 0..n {
                jac[(i, j)] = (fy[i] - self.f0[i]) / d;
            }
            y[j] = self.y0[j];
        }
        self.jac = Some(jac);
        self.lu = None;
        self.stale = false;
        self.jacobians += 1;
        Ok(())
    }

    /// The solution at `θ ∈ [0, 1]` of the step just taken: the cubic Hermite interpolant of
    /// `(y₀, f₀)` and `(y₁, k₅)` (`k₅ = f(t₁, y₁)` to Newton's tolerance).
    pub(crate) fn at(&self, theta: f64, out: &mut Vec<f64>) {
        let (t2, t3) = (theta * theta, theta * theta * theta);
        let (h00, h10, h01, h11) = (
            2.0 * t3 - 3.0 * t2 + 1.0,
            t3 - 2.0 * t2 + theta,
            3.0 * t2 - 2.0 * t3,
            t3 - t2,
        );
        let h = self.h;
        out.clear();
        out.extend((0..self.y0.len()).map(|i| {
            h00 * self.y0[i] + h10 * h * self.f0[i] + h01 * self.y1[i] + h11 * h * self.k[4][i]
        }));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tableau's order conditions: `b` to order 4 (eight conditions), `b̂` to order 3 (four),
    /// each row's sum its `c` (with `γ`), and `R(∞) = 0` (`b` is the last row: stiffly
    /// accurate).
    #[test]
    fn the_tableau_is_of_order_four_with_an_embedded_three() {
        let a = |i: usize, j: usize| -> f64 {
            if j < i {
                A[i][j]
            } else if i == j {
                GAMMA
            } else {
                0.0
            }
        };
        for i in 0..5 {
            let row: f64 = (0..5).map(|j| a(i, j)).sum();
            assert!((row - C[i]).abs() < 1e-15, "row {i}: {row} vs c {}", C[i]);
            assert!((a(4, i) - B[i]).abs() < 1e-15, "stiffly accurate");
        }
        let sum = |w: &[f64; 5], g: &dyn Fn(usize) -> f64| (0..5).map(|i| w[i] * g(i)).sum::<f64>();
        let ac = |i: usize| (0..5).map(|j| a(i, j) * C[j]).sum::<f64>();
        let ac2 = |i: usize| (0..5).map(|j| a(i, j) * C[j] * C[j]).sum::<f64>();
        let aac = |i: usize| (0..5).map(|j| a(i, j) * ac(j)).sum::<f64>();
        type Condition<'a> = (&'a str, f64, Box<dyn Fn(usize) -> f64 + 'a>);
        let third: [Condition<'_>; 4] = [
            ("Σb = 1", 1.0, Box::new(|_| 1.0)),
            ("Σbc = 1/2", 0.5, Box::new(|i| C[i])),
            ("Σbc² = 1/3", 1.0 / 3.0, Box::new(|i| C[i] * C[i])),
            ("Σbac = 1/6", 1.0 / 6.0, Box::new(ac)),
        ];
        for (what, want, g) in &third {
            assert!((sum(&B, g) - want).abs() < 1e-14, "b: {what}");
            assert!((sum(&B_HAT, g) - want).abs() < 1e-14, "b̂: {what}");
        }
        let fourth: [Condition<'_>; 4] = [
            ("Σbc³ = 1/4", 0.25, Box::new(|i| C[i].powi(3))),
            ("Σbcac = 1/8", 0.125, Box::new(|i| C[i] * ac(i))),
            ("Σbac² = 1/12", 1.0 / 12.0, Box::new(ac2)),
            ("Σbaac = 1/24", 1.0 / 24.0, Box::new(aac)),
        ];
        for (what, want, g) in &fourth {
            assert!((sum(&B, g) - want).abs() < 1e-14, "b: {what}");
        }
        // the embedded solution is not of fourth order (its difference estimates the error)
        assert!((sum(&B_HAT, &|i| C[i].powi(3)) - 0.25).abs() > 1e-3);
    }

    /// `y'' = −y` as `(y, y')`.
    fn oscillator(_t: f64, y: &[f64], dy: &mut Vec<f64>) -> Result<(), ()> {
        dy.clear();
        dy.extend([y[1], -y[0]]);
        Ok(())
    }

    fn run(
        f: &mut impl FnMut(f64, &[f64], &mut Vec<f64>) -> Result<(), ()>,
        y: &mut Vec<f64>,
        steps: usize,
        h: f64,
    ) -> Sdirk {
        let mut d = Sdirk::default();
        for i in 0..steps {
            let t = i as f64 * h;
            let mut f0 = std::mem::take(&mut d.f0);
            f(t, y, &mut f0).unwrap();
            d.f0 = f0;
            let err = d
                .attempt(t, y, h, y.len(), f, |_, _, _| 1e-12, |_| 1.0)
                .unwrap();
            assert!(err.is_finite(), "Newton converged");
            y.clone_from(&d.y1);
        }
        d
    }

    #[test]
    fn the_method_is_of_fourth_order() {
        let err = |n: usize, h: f64| {
            let mut y = vec![1.0, 0.0];
            run(&mut oscillator, &mut y, n, h);
            let t = n as f64 * h;
            (y[0] - t.cos()).abs().max((y[1] + t.sin()).abs())
        };
        let order = (err(20, 0.1) / err(40, 0.05)).log2();
        assert!((order - 4.0).abs() < 0.15, "order {order}");
    }

    /// Prothero and Robinson's stiff problem `y' = −λ (y − cos t) − sin t`, `λ = 10⁶`, solution
    /// `cos t`: steps of 0.05 (`h λ = 5·10⁴`, where the explicit pair diverges at once) follow it
    /// to 2e-8 (7.8e-9 measured: the stages' order is 1, so a stiff problem's error is not the
    /// method's `h⁴` but stays far below the step's). (The interpolant's end slopes carry the
    /// stiff component's error times `λ`: a run of a stiff system samples at its steps' ends.)
    #[test]
    fn a_stiff_problem_is_followed_at_steps_far_beyond_its_rate() {
        let lambda = 1e6;
        let mut f = |t: f64, y: &[f64], dy: &mut Vec<f64>| -> Result<(), ()> {
            dy.clear();
            dy.push(-lambda * (y[0] - t.cos()) - t.sin());
            Ok(())
        };
        let mut y = vec![1.0];
        let d = run(&mut f, &mut y, 40, 0.05);
        assert!(
            (y[0] - 2f64.cos()).abs() < 2e-8,
            "{} vs {}",
            y[0],
            2f64.cos()
        );
        assert!(d.jacobians >= 1 && d.newton_failures == 0);
    }

    /// The interpolant is exact at both ends and of fourth order inside (a local error `O(h⁴)`).
    #[test]
    fn the_interpolant_is_exact_at_both_ends_and_of_fourth_order() {
        let err = |h: f64| {
            let mut y = vec![1.0, 0.0];
            let d = run(&mut oscillator, &mut y, 1, h);
            let mut out = Vec::new();
            d.at(0.0, &mut out);
            assert_eq!(out, [1.0, 0.0]);
            d.at(1.0, &mut out);
            assert!((out[0] - y[0]).abs() < 1e-15 && (out[1] - y[1]).abs() < 1e-15);
            (1..10)
                .map(|i| {
                    let th = i as f64 / 10.0;
                    d.at(th, &mut out);
                    let t = th * h;
                    (out[0] - t.cos()).abs().max((out[1] + t.sin()).abs())
                })
                .fold(0.0f64, f64::max)
        };
        let order = (err(0.2) / err(0.1)).log2();
        assert!((order - 4.0).abs() < 0.3, "order {order}");
    }

    /// The error estimate of a step is of order four in the step on a smooth problem.
    #[test]
    fn the_error_estimate_is_of_fourth_order_in_the_step() {
        let est = |h: f64| {
            let mut d = Sdirk {
                f0: vec![0.0, -1.0],
                ..Sdirk::default()
            };
            d.attempt(
                0.0,
                &[1.0, 0.0],
                h,
                2,
                &mut oscillator,
                |_, _, _| 1.0,
                |_| 1.0,
            )
            .unwrap()
        };
        let order = (est(0.1) / est(0.05)).log2();
        assert!((order - 4.0).abs() < 0.3, "order {order}");
    }
}
