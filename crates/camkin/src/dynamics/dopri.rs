//! The Dormand–Prince 5(4) pair with its step-size control and its dense output: the
//! integrator of every simulated system.
//!
//! One step of `h` from `(t, y)` evaluates seven stages `k₁ … k₇` (the last at the step's end,
//! so that it is the next step's first: "first same as last"), advances by the fifth-order
//! weights (local extrapolation) and estimates the error by the difference from the embedded
//! fourth-order solution, `h Σ eⱼ kⱼ`. The error is measured in the maximum norm
//! `‖e‖ = maxᵢ |eᵢ| / scᵢ` with `scᵢ = atolᵢ + rtol · max(|y₀ᵢ|, |y₁ᵢ|)` (not Hairer's
//! root-mean-square: over the hundreds of coordinates of a valve train it would let one body's
//! error be twenty times the tolerance; measured on a double pendulum, the maximum norm took 17 %
//! more steps and halved the energy's drift); a step is
//! accepted where `‖e‖ ≤ 1`, and the next step is `h · 0.9 ‖e‖^(−0.2 + 0.75 β) ‖e_prev‖^β`
//! (Gustafsson's PI control with `β = 0.04`), from a fifth to ten times the last, never longer
//! after a rejection. The continuous extension of Shampine (1986) gives the solution inside the
//! step to fourth order from the stages already made.
//!
//! References: J. R. Dormand and P. J. Prince, "A family of embedded Runge–Kutta formulae",
//! J. Comp. Appl. Math. 6 (1980) 19–26; E. Hairer, S. P. Nørsett and G. Wanner, *Solving
//! Ordinary Differential Equations I*, 2nd ed., Springer 1993, §II.4 (step control and the
//! starting step), §II.5 (Table 5.2), §II.6 (dense output), and its code DOPRI5.
//!
//! Evaluated and not used: `ode_solvers` (a Dopri5 over nalgebra vectors whose integration loop
//! owns the steps: no projection onto the constraints after each, no mode change at an event),
//! `diffsol` (BDF and SDIRK for `M y' = f` with events, heavy with its linear-algebra back ends
//! for a 2-core build, and its explicit methods later than the version on crates.io we could
//! build), `russell_ode` (Radau5 and DoPri, but built on BLAS/LAPACK from the system). The
//! steps here are the equations of motion's with a projection after each and events that switch
//! contacts; the stepper is the tableau and its control, written out against the references.

/// `cᵢ`: the stages' instants in the step.
const C: [f64; 7] = [0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0];

/// `aᵢⱼ`, row by row (the seventh row is the fifth-order weights `b`).
const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [0.2, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];

/// `eⱼ = bⱼ − b̂ⱼ`: the fifth-order weights less the fourth-order ones.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// Shampine's dense output weights `dⱼ`.
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// The PI controller's `β` (Hairer's DOPRI5).
const BETA: f64 = 0.04;
/// The safety factor on the step the error asks for.
const SAFETY: f64 = 0.9;
/// The most a step shrinks and grows from one to the next.
const SHRINK: f64 = 0.2;
/// (see [`SHRINK`])
const GROW: f64 = 10.0;

/// The tolerances of an integration: each component's error scale `atolᵢ + rtol · |yᵢ|`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    /// relative tolerance `rtol`
    pub relative: f64,
    /// absolute tolerance, as a fraction of each coordinate's scale (see
    /// [`super::SystemSimulation`]: a length's the system's size, an angle's a radian, a rate's
    /// that over the system's time scale)
    pub absolute: f64,
}

impl Default for Tolerances {
    /// `rtol = atol = 1e-10`: every example's outputs right to 1e-6 of their scale (the valve
    /// train's, the hardest, its coils' accelerations: 5.8e-7 against a run at 1e-13; at 1e-8,
    /// 5.9e-5 in half the time).
    fn default() -> Self {
        Self {
            relative: 1e-10,
            absolute: 1e-10,
        }
    }
}

impl Tolerances {
    /// The tightest and loosest tolerance accepted: below 1e-13 the error is rounding's, above
    /// 1e-2 a step's error is no longer small.
    pub const RANGE: (f64, f64) = (1e-13, 1e-2);

    /// `None` where both are within [`Tolerances::RANGE`]; else the one out of it (`"relative"`
    /// or `"absolute"`) and its value.
    pub fn out_of_range(&self) -> Option<(&'static str, f64)> {
        let ok = |x: f64| (Self::RANGE.0..=Self::RANGE.1).contains(&x);
        if !ok(self.relative) {
            Some(("relative", self.relative))
        } else if !ok(self.absolute) {
            Some(("absolute", self.absolute))
        } else {
            None
        }
    }
}

/// A step's stages, its end and its interpolant: buffers reused from step to step.
#[derive(Debug, Clone, Default)]
pub(crate) struct Dopri {
    /// `k₁ … k₇`; `k₁` is given by the caller before a step (the derivative at its start)
    pub(crate) k: [Vec<f64>; 7],
    /// a stage's state
    stage: Vec<f64>,
    /// the step's start and end
    pub(crate) y0: Vec<f64>,
    pub(crate) y1: Vec<f64>,
    /// Shampine's interpolant's five vectors, made by [`Dopri::interpolant`]
    cont: [Vec<f64>; 5],
    /// the step's start and length, for [`Dopri::at`]
    pub(crate) t0: f64,
    pub(crate) h: f64,
}

impl Dopri {
    /// A step of `h` from `(t, y0)` with `k₁ = f(t, y0)` already in `self.k[0]`: the stages by
    /// `f(t, y, dy)`, the end in `self.y1`, `k₇ = f(t + h, y1)` in `self.k[6]`; the error's
    /// maximum norm with the scales `scale(i, |y0ᵢ|, |y1ᵢ|)` (components with an infinite scale
    /// are not measured).
    pub(crate) fn attempt<E>(
        &mut self,
        t: f64,
        y0: &[f64],
        h: f64,
        f: &mut impl FnMut(f64, &[f64], &mut Vec<f64>) -> Result<(), E>,
        scale: impl Fn(usize, f64, f64) -> f64,
    ) -> Result<f64, E> {
        self.t0 = t;
        self.h = h;
        self.y0.clear();
        self.y0.extend_from_slice(y0);
        for s in 1..7 {
            self.stage.clear();
            self.stage.extend_from_slice(y0);
            for (j, &a) in A[s].iter().enumerate().take(s) {
                if a != 0.0 {
                    let ha = h * a;
                    for (y, k) in self.stage.iter_mut().zip(&self.k[j]) {
                        *y += ha * k;
                    }
                }
            }
            if s == 6 {
                // the fifth-order solution: the last stage's state
                std::mem::swap(&mut self.y1, &mut self.stage);
                let mut k = std::mem::take(&mut self.k[6]);
                f(t + h, &self.y1, &mut k)?;
                self.k[6] = k;
            } else {
                let mut k = std::mem::take(&mut self.k[s]);
                f(t + C[s] * h, &self.stage, &mut k)?;
                self.k[s] = k;
            }
        }
        let mut worst: f64 = 0.0;
        for (i, (a, b)) in y0.iter().zip(&self.y1).enumerate() {
            let sc = scale(i, a.abs(), b.abs());
            if !sc.is_finite() {
                continue;
            }
            let e: f64 = h * (0..7).map(|j| E[j] * self.k[j][i]).sum::<f64>();
            worst = worst.max((e / sc).abs());
        }
        Ok(worst)
    }

    /// Shampine's interpolant of the step just accepted, from its stages.
    pub(crate) fn interpolant(&mut self) {
        let h = self.h;
        let [c0, c1, c2, c3, c4] = &mut self.cont;
        c0.clone_from(&self.y0);
        c1.clear();
        c2.clear();
        c3.clear();
        c4.clear();
        for i in 0..self.y0.len() {
            let dy = self.y1[i] - self.y0[i];
            let bspl = h * self.k[0][i] - dy;
            c1.push(dy);
            c2.push(bspl);
            c3.push(dy - h * self.k[6][i] - bspl);
            c4.push(h * (0..7).map(|j| D[j] * self.k[j][i]).sum::<f64>());
        }
    }

    /// The interpolated solution at `θ ∈ [0, 1]` of the step ([`Dopri::interpolant`] made),
    /// written into `out`: `y₀ + θ (c₁ + (1 − θ)(c₂ + θ (c₃ + (1 − θ) c₄)))`.
    pub(crate) fn at(&self, theta: f64, out: &mut Vec<f64>) {
        let s = 1.0 - theta;
        let [c0, c1, c2, c3, c4] = &self.cont;
        out.clear();
        out.extend(
            (0..c0.len())
                .map(|i| c0[i] + theta * (c1[i] + s * (c2[i] + theta * (c3[i] + s * c4[i])))),
        );
    }
}

/// The step-size controller: the next step from the last one's error.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Controller {
    /// the last accepted step's error norm (at least 1e-4)
    previous: Option<f64>,
    /// whether the last attempt was rejected
    rejected: bool,
    /// the error estimate's order in the step (5 for the Dormand–Prince pair's: it is of its
    /// fourth-order solution; 4 for the SDIRK pair's)
    order: f64,
}

impl Default for Controller {
    fn default() -> Self {
        Self::of_order(5.0)
    }
}

impl Controller {
    /// A controller of an error estimate of `order` in the step.
    pub(crate) fn of_order(order: f64) -> Self {
        Self {
            previous: None,
            rejected: false,
            order,
        }
    }

    /// After a step of `h` with error norm `err`: whether it is accepted, and the next step.
    pub(crate) fn judge(&mut self, h: f64, err: f64) -> (bool, f64) {
        let err = if err.is_nan() { f64::INFINITY } else { err };
        let p = 1.0 / self.order;
        if err <= 1.0 {
            let prev = self.previous.unwrap_or(1e-4);
            let fac = SAFETY * err.max(1e-10).powf(-p + 0.75 * BETA) * prev.powf(BETA);
            let mut next = h * fac.clamp(SHRINK, GROW);
            if self.rejected {
                next = next.min(h);
            }
            self.previous = Some(err.max(1e-4));
            self.rejected = false;
            (true, next)
        } else {
            let fac = if err.is_finite() {
                (SAFETY * err.powf(-p)).max(SHRINK)
            } else {
                SHRINK
            };
            self.rejected = true;
            (false, h * fac)
        }
    }
}

/// Hairer's starting step (Solving ODE I, §II.4): from the sizes of `y₀`, `f₀` and of the
/// derivative's change over an Euler step, `h = (0.01 / max(‖f₀‖, ‖f′‖))^(1/5)`, at most 100 times
/// the first guess; `norm` is the error's weighted norm of a vector.
pub(crate) fn starting_step<E>(
    t: f64,
    y0: &[f64],
    f0: &[f64],
    f: &mut impl FnMut(f64, &[f64], &mut Vec<f64>) -> Result<(), E>,
    norm: impl Fn(&[f64]) -> f64,
) -> Result<f64, E> {
    let (d0, d1) = (norm(y0), norm(f0));
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    let y1: Vec<f64> = y0.iter().zip(f0).map(|(y, k)| y + h0 * k).collect();
    let mut f1 = Vec::new();
    f(t + h0, &y1, &mut f1)?;
    let diff: Vec<f64> = f1.iter().zip(f0).map(|(a, b)| a - b).collect();
    let d2 = norm(&diff) / h0;
    let big = d1.max(d2);
    let h1 = if big <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / big).powf(0.2)
    };
    Ok((100.0 * h0).min(h1))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `y'' = −y` as `(y, y')`: the exact solution is `(cos t, −sin t)`.
    fn oscillator(_t: f64, y: &[f64], dy: &mut Vec<f64>) -> Result<(), ()> {
        dy.clear();
        dy.extend([y[1], -y[0]]);
        Ok(())
    }

    /// `n` equal steps of `h` over the oscillator from `(1, 0)`: the error at the end.
    fn fixed_steps(n: usize, h: f64) -> f64 {
        let mut d = Dopri::default();
        let mut y = vec![1.0, 0.0];
        let mut f = oscillator;
        for i in 0..n {
            let t = i as f64 * h;
            let mut k0 = std::mem::take(&mut d.k[0]);
            f(t, &y, &mut k0).unwrap();
            d.k[0] = k0;
            d.attempt(t, &y, h, &mut f, |_, _, _| 1.0).unwrap();
            y.clone_from(&d.y1);
        }
        let t = n as f64 * h;
        (y[0] - t.cos()).abs().max((y[1] + t.sin()).abs())
    }

    #[test]
    fn the_pair_is_of_fifth_order() {
        // halving the step divides the global error by 2⁵ = 32
        let (e1, e2) = (fixed_steps(20, 0.1), fixed_steps(40, 0.05));
        let order = (e1 / e2).log2();
        assert!((order - 5.0).abs() < 0.15, "order {order}: {e1:e} {e2:e}");
    }

    #[test]
    fn the_error_estimate_is_of_fifth_order_in_the_step() {
        // the local estimate of a fourth-order solution: O(h⁵)
        let est = |h: f64| {
            let mut d = Dopri::default();
            d.k[0] = vec![0.0, -1.0];
            d.attempt(0.0, &[1.0, 0.0], h, &mut oscillator, |_, _, _| 1.0)
                .unwrap()
        };
        let order = (est(0.1) / est(0.05)).log2();
        assert!((order - 5.0).abs() < 0.2, "order {order}");
    }

    #[test]
    fn the_interpolant_is_of_fourth_order_and_exact_at_both_ends() {
        let err = |h: f64| {
            let mut d = Dopri::default();
            d.k[0] = vec![0.0, -1.0];
            d.attempt(0.0, &[1.0, 0.0], h, &mut oscillator, |_, _, _| 1.0)
                .unwrap();
            d.interpolant();
            let mut y = Vec::new();
            d.at(0.0, &mut y);
            assert_eq!(y, [1.0, 0.0]);
            d.at(1.0, &mut y);
            assert!((y[0] - d.y1[0]).abs() < 1e-16 && (y[1] - d.y1[1]).abs() < 1e-16);
            // the worst over the step
            (1..10)
                .map(|i| {
                    let th = i as f64 / 10.0;
                    d.at(th, &mut y);
                    let t = th * h;
                    (y[0] - t.cos()).abs().max((y[1] + t.sin()).abs())
                })
                .fold(0.0f64, f64::max)
        };
        // a local error O(h⁵): halving the step divides it by about 32
        let order = (err(0.2) / err(0.1)).log2();
        assert!((order - 5.0).abs() < 0.3, "order {order}");
        assert!(err(0.1) < 1e-7);
    }

    #[test]
    fn a_controlled_run_keeps_the_global_error_near_its_tolerance() {
        // the oscillator over ten periods at rtol = atol = 1e-9
        let tol = 1e-9;
        let mut d = Dopri::default();
        let mut ctl = Controller::default();
        let (mut t, mut y) = (0.0, vec![1.0, 0.0]);
        let mut f = oscillator;
        let scale = |_: usize, a: f64, b: f64| tol + tol * a.max(b);
        let mut k0 = Vec::new();
        f(0.0, &y, &mut k0).unwrap();
        let mut h = starting_step(0.0, &y, &k0, &mut f, |v: &[f64]| {
            (v.iter()
                .map(|x| (x / (tol + tol * 1.0)).powi(2))
                .sum::<f64>()
                / v.len() as f64)
                .sqrt()
        })
        .unwrap();
        let end = 20.0 * std::f64::consts::PI;
        let (mut steps, mut rejected) = (0, 0);
        while t < end {
            h = h.min(end - t);
            d.k[0].clone_from(&k0);
            let err = d.attempt(t, &y, h, &mut f, scale).unwrap();
            let (ok, next) = ctl.judge(h, err);
            if ok {
                t += h;
                y.clone_from(&d.y1);
                k0.clone_from(&d.k[6]);
                steps += 1;
            } else {
                rejected += 1;
            }
            h = next;
        }
        let e = (y[0] - 1.0).abs().max(y[1].abs());
        assert!(e < 100.0 * tol && e > 1e-3 * tol, "error {e:e}");
        assert!(
            rejected <= 3 && steps < 2000,
            "{steps} steps, {rejected} rejected"
        );
    }

    #[test]
    fn a_step_too_long_is_rejected_and_shortened() {
        let mut c = Controller::default();
        let (ok, next) = c.judge(1.0, 32.0);
        assert!(!ok && (SHRINK..1.0).contains(&next));
        // after a rejection the next accepted step does not grow
        let (ok, next) = c.judge(0.5, 1e-6);
        assert!(ok && next <= 0.5);
        // a non-finite error rejects with the largest cut
        let (ok, next) = c.judge(1.0, f64::NAN);
        assert!(!ok && next == SHRINK);
    }

    #[test]
    fn tolerances_out_of_range_are_named() {
        let t = Tolerances {
            relative: 0.0,
            absolute: 1e-8,
        };
        assert_eq!(t.out_of_range(), Some(("relative", 0.0)));
        let t = Tolerances {
            relative: 1e-8,
            absolute: 1.0,
        };
        assert_eq!(t.out_of_range(), Some(("absolute", 1.0)));
        assert_eq!(Tolerances::default().out_of_range(), None);
    }
}
