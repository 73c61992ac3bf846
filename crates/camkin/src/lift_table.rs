//! A lift table as a motion law: a cam supplier's or a measurement's lift at equally spaced cam
//! angles, interpolated by a quintic spline — continuous to its fourth derivative (C⁴), so that
//! the acceleration, jerk and snap that a synthesis and a simulation need are those of one smooth
//! curve, not of the data's differences.
//!
//! On each interval `[θᵢ, θᵢ₊₁]` (`t = (θ − θᵢ)/h`) the spline is the quintic Hermite polynomial of
//! the lifts `pᵢ`, slopes `dᵢ` and second derivatives `eᵢ` at its ends:
//!
//! ```text
//! s = pᵢ H₀ + h dᵢ H₁ + h² eᵢ H₂ + h² eᵢ₊₁ H₃ + h dᵢ₊₁ H₄ + pᵢ₊₁ H₅,
//! H₀ = 1 − 10t³ + 15t⁴ − 6t⁵, H₁ = t − 6t³ + 8t⁴ − 3t⁵, H₂ = (t² − 3t³ + 3t⁴ − t⁵)/2,
//! H₃ = (t³ − 2t⁴ + t⁵)/2,    H₄ = −4t³ + 7t⁴ − 3t⁵,    H₅ = 10t³ − 15t⁴ + 6t⁵,
//! ```
//!
//! continuous with its first two derivatives by construction; the third and fourth are made
//! continuous at every inner knot (with `Dᵢ = h dᵢ`, `Eᵢ = h² eᵢ`):
//!
//! ```text
//! −24 Dᵢ₋₁ − 3 Eᵢ₋₁ + 18 Eᵢ + 24 Dᵢ₊₁ − 3 Eᵢ₊₁ = 60 (pᵢ₋₁ − 2 pᵢ + pᵢ₊₁)
//! −168 Dᵢ₋₁ − 24 Eᵢ₋₁ − 384 Dᵢ − 168 Dᵢ₊₁ + 24 Eᵢ₊₁ = 360 (pᵢ₋₁ − pᵢ₊₁)
//! ```
//!
//! — a block-tridiagonal system in `(Dᵢ, Eᵢ)`, solved by block elimination. The spline is then
//! held as its uniform quintic B-spline coefficients (each from its knot's lift and four
//! derivatives), whose pieces are C⁴ at every knot by construction: each piece is evaluated from
//! its nearer end, and a knot's lift and four derivatives are the same arithmetic from either
//! side — to the last bit, where the Hermite pieces' third derivatives stepped there by their
//! system's rounding (1e-8 of a jerk of 400 mm/rad³ at a 1° step). A table of the whole
//! revolution is **periodic** (the knots wrap round: the system is cyclic, solved by eliminating
//! the first knot's two unknowns last); a table **between dwells** is clamped at rest at both
//! ends (`d = e = 0`: it meets a dwell with continuous velocity and acceleration; the jerk may
//! step there, as a 3-4-5 law's does).
//!
//! A table carries the rounding or measurement noise of its lifts, which an interpolant turns
//! into acceleration noise of about `σ K / h²` (`K` the spline's noise gain, computed): the
//! table's [`LiftTable::noise`] estimates `σ` from the lifts' sixth differences (white noise's
//! `Δ⁶` has variance `924 σ²`, a smooth lift's own `h⁶ s⁽⁶⁾` is far below it at a table's step:
//! `σ = √(mean (Δ⁶p)² / 924)`) and states the acceleration noise against the table's peak
//! acceleration.

use std::f64::consts::TAU;

/// What is wrong with a lift table.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum TableError {
    /// Too few lifts for a quintic spline.
    #[error("{count} lifts: a table needs at least {least}")]
    TooFew {
        /// the lifts given
        count: usize,
        /// the least it needs
        least: usize,
    },
    /// A lift is not finite.
    #[error("lift {index} is {value}, not a finite number")]
    NotFinite {
        /// its index
        index: usize,
        /// its value
        value: f64,
    },
    /// The step is not positive and finite.
    #[error("the step {step} rad must be positive and finite")]
    Step {
        /// the step, rad
        step: f64,
    },
}

/// How noisy a table's lifts are, and what that does to its acceleration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableNoise {
    /// the lifts' noise, estimated from their sixth differences (rise units)
    pub sigma: f64,
    /// the acceleration noise the interpolant carries, `σ K / h²` (rise units per rad²)
    pub acceleration: f64,
    /// the table's largest acceleration (rise units per rad²)
    pub peak_acceleration: f64,
}

impl TableNoise {
    /// The acceleration noise as a fraction of the peak acceleration.
    pub fn fraction(&self) -> f64 {
        if self.peak_acceleration > 0.0 {
            self.acceleration / self.peak_acceleration
        } else {
            0.0
        }
    }
}

/// A lift table interpolated by a quintic spline (see the module's docs).
#[derive(Debug, Clone, PartialEq)]
pub struct LiftTable {
    /// the step between lifts, rad
    step: f64,
    /// the lifts as given
    lifts: Vec<f64>,
    /// the whole revolution, its knots wrapping round (else clamped at rest at both ends)
    periodic: bool,
    /// each interval's polynomial in `t` (`c₀ + c₁ t + … + c₅ t⁵`), and about its right end in
    /// `1 − t` (evaluated from the nearer end)
    coeffs: Vec<[[f64; 6]; 2]>,
}

/// The uniform quintic B-spline's basis matrix (times 120): on an interval `t ∈ [0, 1)` with
/// the coefficients `c_{i−2} … c_{i+3}`, the spline is `Σ_k t^k (BASIS[k] · c) / 120`.
const BASIS: [[f64; 6]; 6] = [
    [1.0, 26.0, 66.0, 26.0, 1.0, 0.0],
    [-5.0, -50.0, 0.0, 50.0, 5.0, 0.0],
    [10.0, 20.0, -60.0, 20.0, 10.0, 0.0],
    [-10.0, 20.0, 0.0, -20.0, 10.0, 0.0],
    [5.0, -20.0, 30.0, -20.0, 5.0, 0.0],
    [-1.0, 5.0, -10.0, 10.0, -5.0, 1.0],
];

/// The inverse of the map from the five B-spline coefficients about a knot, `c_{i−2} … c_{i+2}`,
/// to its lift and four t-derivatives (`k! BASIS[k] / 120`, k = 0…4).
fn knot_inverse() -> &'static [[f64; 5]; 5] {
    static M: std::sync::OnceLock<[[f64; 5]; 5]> = std::sync::OnceLock::new();
    M.get_or_init(|| {
        let fact = [1.0, 1.0, 2.0, 6.0, 24.0];
        let a = nalgebra::Matrix5::from_fn(|r, c| fact[r] * BASIS[r][c] / 120.0);
        let inv = a.try_inverse().expect("the knot's map is invertible");
        std::array::from_fn(|r| std::array::from_fn(|c| inv[(r, c)]))
    })
}

/// The three 2×2 blocks of a knot's two continuity rows, on `(D, E)` of the knots before, at
/// and after it.
const BEFORE: [[f64; 2]; 2] = [[-24.0, -3.0], [-168.0, -24.0]];
const AT: [[f64; 2]; 2] = [[0.0, 18.0], [-384.0, 0.0]];
const AFTER: [[f64; 2]; 2] = [[24.0, -3.0], [-168.0, 24.0]];

type M2 = [[f64; 2]; 2];
type V2 = [f64; 2];

fn mul(a: &M2, b: &M2) -> M2 {
    [
        [
            a[0][0] * b[0][0] + a[0][1] * b[1][0],
            a[0][0] * b[0][1] + a[0][1] * b[1][1],
        ],
        [
            a[1][0] * b[0][0] + a[1][1] * b[1][0],
            a[1][0] * b[0][1] + a[1][1] * b[1][1],
        ],
    ]
}

fn mulv(a: &M2, v: &V2) -> V2 {
    [
        a[0][0] * v[0] + a[0][1] * v[1],
        a[1][0] * v[0] + a[1][1] * v[1],
    ]
}

fn sub(a: &M2, b: &M2) -> M2 {
    [
        [a[0][0] - b[0][0], a[0][1] - b[0][1]],
        [a[1][0] - b[1][0], a[1][1] - b[1][1]],
    ]
}

fn inv(a: &M2) -> M2 {
    let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    [
        [a[1][1] / det, -a[0][1] / det],
        [-a[1][0] / det, a[0][0] / det],
    ]
}

/// Solves the block-tridiagonal rows `BEFORE x₋₁ + AT xᵢ + AFTER xᵢ₊₁ = rᵢ` for `i = 0..m`
/// with `x₋₁ = x_m = 0` (each right side a list of `V2`s, several at once: `rhs[c][i]`).
fn block_thomas(rhs: &mut [Vec<V2>]) {
    let m = rhs.first().map_or(0, Vec::len);
    if m == 0 {
        return;
    }
    // forward: Cᵢ' = (AT − BEFORE Cᵢ₋₁')⁻¹ AFTER, rᵢ' = (AT − BEFORE Cᵢ₋₁')⁻¹ (rᵢ − BEFORE rᵢ₋₁')
    let mut c_prime: Vec<M2> = Vec::with_capacity(m);
    let mut pivots: Vec<M2> = Vec::with_capacity(m);
    for i in 0..m {
        let d = if i == 0 {
            AT
        } else {
            sub(&AT, &mul(&BEFORE, &c_prime[i - 1]))
        };
        let di = inv(&d);
        c_prime.push(mul(&di, &AFTER));
        pivots.push(di);
    }
    for r in rhs.iter_mut() {
        for i in 0..m {
            let mut v = r[i];
            if i > 0 {
                let b = mulv(&BEFORE, &r[i - 1]);
                v = [v[0] - b[0], v[1] - b[1]];
            }
            r[i] = mulv(&pivots[i], &v);
        }
        for i in (0..m.saturating_sub(1)).rev() {
            let c = mulv(&c_prime[i], &r[i + 1]);
            r[i] = [r[i][0] - c[0], r[i][1] - c[1]];
        }
    }
}

/// The right side of knot `i`'s rows from the lifts before, at and after it.
fn rhs(before: f64, at: f64, after: f64) -> V2 {
    [60.0 * (before - 2.0 * at + after), 360.0 * (before - after)]
}

/// The rows `BEFORE xᵢ₋₁ + AT xᵢ + AFTER xᵢ₊₁ = rᵢ` with zero beyond both ends.
fn solve_clamped(r: Vec<V2>) -> Vec<V2> {
    let mut cols = vec![r];
    block_thomas(&mut cols);
    cols.pop().unwrap_or_default()
}

/// The rows wrapping round (`x₋₁ = x_{n−1}`, `x_n = x₀`): knots 1…n−1 solved for the right
/// side and for each of knot 0's two unknowns (its coupling moved to the right side), then knot
/// 0's own rows solved for them.
fn solve_periodic(r: Vec<V2>) -> Vec<V2> {
    let n = r.len();
    let m = n - 1;
    // x = y + Z x₀: y for the right side; Z's columns for x₀ = (1, 0) and (0, 1), which enter
    // knot 1's rows through BEFORE and knot n−1's through AFTER
    let mut cols = vec![r[1..].to_vec(), vec![[0.0, 0.0]; m], vec![[0.0, 0.0]; m]];
    for (c, unit) in [(1, [1.0, 0.0]), (2, [0.0, 1.0])] {
        let b = mulv(&BEFORE, &unit);
        let a = mulv(&AFTER, &unit);
        cols[c][0] = [-b[0], -b[1]];
        cols[c][m - 1] = [cols[c][m - 1][0] - a[0], cols[c][m - 1][1] - a[1]];
    }
    block_thomas(&mut cols);
    // knot 0: BEFORE x_{n−1} + AT x₀ + AFTER x₁ = r₀, with x_k = y_k + Z_k x₀
    let z = |k: usize| -> M2 {
        [
            [cols[1][k][0], cols[2][k][0]],
            [cols[1][k][1], cols[2][k][1]],
        ]
    };
    let lhs = {
        let l = mul(&BEFORE, &z(m - 1));
        let r = mul(&AFTER, &z(0));
        [
            [AT[0][0] + l[0][0] + r[0][0], AT[0][1] + l[0][1] + r[0][1]],
            [AT[1][0] + l[1][0] + r[1][0], AT[1][1] + l[1][1] + r[1][1]],
        ]
    };
    let (by, ay) = (mulv(&BEFORE, &cols[0][m - 1]), mulv(&AFTER, &cols[0][0]));
    let x0 = mulv(
        &inv(&lhs),
        &[r[0][0] - by[0] - ay[0], r[0][1] - by[1] - ay[1]],
    );
    let mut out = vec![x0];
    for (k, y) in cols[0].iter().enumerate() {
        let zx = mulv(&z(k), &x0);
        out.push([y[0] + zx[0], y[1] + zx[1]]);
    }
    out
}

impl LiftTable {
    /// The table of `lifts` every `step` rad: `periodic`, the whole revolution (`lifts.len()`
    /// steps make it, the first lift not repeated at its end); else between dwells, from the
    /// first lift to the last at rest at both.
    pub fn new(step: f64, lifts: Vec<f64>, periodic: bool) -> Result<Self, TableError> {
        if !(step.is_finite() && step > 0.0) {
            return Err(TableError::Step { step });
        }
        let least = if periodic { 6 } else { 3 };
        if lifts.len() < least {
            return Err(TableError::TooFew {
                count: lifts.len(),
                least,
            });
        }
        if let Some((index, &value)) = lifts.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(TableError::NotFinite { index, value });
        }
        let de = if periodic {
            Self::periodic_slopes(&lifts)
        } else {
            Self::clamped_slopes(&lifts)
        };
        let n_int = if periodic {
            lifts.len()
        } else {
            lifts.len() - 1
        };
        let p = |i: usize| lifts[i % lifts.len()];
        // the Hermite quintic of interval i in t: its t⁰…t⁵ coefficients
        let hermite = |i: usize| -> [f64; 6] {
            let (p0, p1) = (p(i), p(i + 1));
            let ([d0, e0], [d1, e1]) = (de[i], de[(i + 1) % de.len()]);
            let dp = p1 - p0;
            [
                p0,
                d0,
                0.5 * e0,
                10.0 * dp - 6.0 * d0 - 4.0 * d1 - 1.5 * e0 + 0.5 * e1,
                -15.0 * dp + 8.0 * d0 + 7.0 * d1 + 1.5 * e0 - e1,
                6.0 * dp - 3.0 * d0 - 3.0 * d1 - 0.5 * e0 + 0.5 * e1,
            ]
        };
        // each knot's lift and four t-derivatives (the third and fourth as the intervals on
        // either side give them, averaged), and from them the B-spline coefficients about it
        let knots = if periodic { n_int } else { n_int + 1 };
        let local: Vec<[f64; 5]> = (0..knots)
            .map(|k| {
                let right = (periodic || k < n_int).then(|| hermite(k % n_int));
                let left = (periodic || k > 0).then(|| hermite((k + n_int - 1) % n_int));
                let third_fourth = |c: &[f64; 6], end: bool| -> [f64; 2] {
                    if end {
                        [
                            6.0 * c[3] + 24.0 * c[4] + 60.0 * c[5],
                            24.0 * c[4] + 120.0 * c[5],
                        ]
                    } else {
                        [6.0 * c[3], 24.0 * c[4]]
                    }
                };
                let [f, g] = match (&left, &right) {
                    (Some(l), Some(r)) => {
                        let (a, b) = (third_fourth(l, true), third_fourth(r, false));
                        [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
                    }
                    (Some(l), None) => third_fourth(l, true),
                    (None, Some(r)) => third_fourth(r, false),
                    (None, None) => [0.0, 0.0],
                };
                let [d, e] = de[k % de.len()];
                let taylor = [p(k), d, e, f, g];
                let m = knot_inverse();
                std::array::from_fn(|r| (0..5).map(|c| m[r][c] * taylor[c]).sum())
            })
            .collect();
        // the coefficients c_j, j from −2 (index 0) to knots + 2; a periodic table's wrap
        let coef = |j: isize| -> f64 {
            if periodic {
                let k = j.rem_euclid(knots as isize) as usize;
                local[k][2]
            } else if j < 0 {
                local[0][(j + 2) as usize]
            } else if j >= knots as isize {
                local[knots - 1]
                    .get((j - knots as isize + 3) as usize)
                    .copied()
                    .unwrap_or(0.0)
            } else {
                local[j as usize][2]
            }
        };
        // interval i's expansion about its left end in t: (row k of the basis matrix) · c / 120
        let left_of = |i: usize| -> [f64; 6] {
            let c: [f64; 6] = std::array::from_fn(|k| coef(i as isize - 2 + k as isize));
            std::array::from_fn(|r| {
                let w = &BASIS[r];
                (w[0] * c[0] + w[1] * c[1] + w[2] * c[2] + w[3] * c[3] + w[4] * c[4] + w[5] * c[5])
                    / 120.0
            })
        };
        let coeffs = (0..n_int)
            .map(|i| {
                let (a, next) = (left_of(i), left_of(i + 1));
                // about its right end in 1 − t: the next interval's left-end values (the same
                // arithmetic: a knot's lift and four derivatives are one from either side), its
                // own fifth derivative
                [a, [next[0], -next[1], next[2], -next[3], next[4], -a[5]]]
            })
            .collect();
        Ok(Self {
            step,
            lifts,
            periodic,
            coeffs,
        })
    }

    /// `(D, E)` at every knot of a table between dwells: zero at both ends, the inner knots
    /// solved.
    fn clamped_slopes(p: &[f64]) -> Vec<V2> {
        let n = p.len() - 1;
        let r: Vec<V2> = (1..n).map(|i| rhs(p[i - 1], p[i], p[i + 1])).collect();
        let inner = solve_clamped(r);
        let mut out = vec![[0.0, 0.0]];
        out.extend(inner);
        out.push([0.0, 0.0]);
        out
    }

    /// `(D, E)` at every knot of a periodic table.
    fn periodic_slopes(p: &[f64]) -> Vec<V2> {
        let n = p.len();
        let at = |i: usize| p[i % n];
        let r: Vec<V2> = (0..n)
            .map(|i| rhs(at(i + n - 1), at(i), at(i + 1)))
            .collect();
        solve_periodic(r)
    }

    /// The step between lifts, rad.
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The lifts as given.
    pub fn lifts(&self) -> &[f64] {
        &self.lifts
    }

    /// Whether it is the whole revolution (else between dwells).
    pub fn periodic(&self) -> bool {
        self.periodic
    }

    /// The angle it covers, rad: a revolution, or its last knot's angle.
    pub fn span(&self) -> f64 {
        if self.periodic {
            TAU
        } else {
            self.step * (self.lifts.len() - 1) as f64
        }
    }

    /// Its lift at its start, and at its end (the same for a periodic table).
    pub fn ends(&self) -> (f64, f64) {
        let first = self.lifts[0];
        (
            first,
            if self.periodic {
                first
            } else {
                self.lifts[self.lifts.len() - 1]
            },
        )
    }

    /// `[s, s', s'', s''', s'''']` at `x` rad from its start (a periodic table taken modulo
    /// the revolution, one between dwells held at its ends outside them).
    pub fn eval5(&self, x: f64) -> [f64; 5] {
        let n = self.coeffs.len();
        let (i, t) = if self.periodic {
            let u = (x / self.step).rem_euclid(n as f64);
            let i = (u.floor() as usize).min(n - 1);
            (i, u - i as f64)
        } else {
            let u = (x / self.step).clamp(0.0, n as f64);
            let i = (u.floor() as usize).min(n - 1);
            (i, u - i as f64)
        };
        // from the nearer end: in 1 − t the odd derivatives change sign
        let (c, t, sign) = if t <= 0.5 {
            (&self.coeffs[i][0], t, 1.0)
        } else {
            (&self.coeffs[i][1], 1.0 - t, -1.0)
        };
        let h = self.step;
        let s = c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
        let d1 = c[1] + t * (2.0 * c[2] + t * (3.0 * c[3] + t * (4.0 * c[4] + t * 5.0 * c[5])));
        let d2 = 2.0 * c[2] + t * (6.0 * c[3] + t * (12.0 * c[4] + t * 20.0 * c[5]));
        let d3 = 6.0 * c[3] + t * (24.0 * c[4] + t * 60.0 * c[5]);
        let d4 = 24.0 * c[4] + t * 120.0 * c[5];
        [
            s,
            sign * d1 / h,
            d2 / (h * h),
            sign * d3 / (h * h * h),
            d4 / (h * h * h * h),
        ]
    }

    /// The largest excursion from its first lift (rise units; 0 for a flat table).
    pub fn excursion(&self) -> f64 {
        let first = self.lifts[0];
        self.lifts
            .iter()
            .fold(0.0f64, |m, &p| m.max((p - first).abs()))
    }

    /// Its noise and what the interpolant makes of it (see the module's docs).
    pub fn noise(&self) -> TableNoise {
        let p = &self.lifts;
        let n = p.len();
        let at = |i: isize| -> Option<f64> {
            if self.periodic {
                Some(p[i.rem_euclid(n as isize) as usize])
            } else {
                usize::try_from(i).ok().and_then(|i| p.get(i).copied())
            }
        };
        // sixth differences: white noise's variance times Σc² = 924; a smooth lift's own
        // h⁶ s⁽⁶⁾ far below it at any table's step
        const C6: [f64; 7] = [1.0, -6.0, 15.0, -20.0, 15.0, -6.0, 1.0];
        let d6: Vec<f64> = (0..n as isize)
            .filter_map(|i| {
                let mut sum = 0.0;
                for (k, c) in C6.iter().enumerate() {
                    sum += c * at(i + k as isize - 3)?;
                }
                Some(sum * sum)
            })
            .collect();
        let sigma = if d6.is_empty() {
            0.0
        } else {
            (d6.iter().sum::<f64>() / d6.len() as f64 / 924.0).sqrt()
        };
        let peak_acceleration = (0..self.coeffs.len() * 4)
            .map(|k| self.eval5(0.25 * k as f64 * self.step)[2].abs())
            .fold(0.0, f64::max);
        TableNoise {
            sigma,
            acceleration: sigma * noise_gain() / (self.step * self.step),
            peak_acceleration,
        }
    }
}

/// The periodic quintic spline's noise gain `K`: the RMS second derivative (per unit step²)
/// over its knots of the interpolant of unit white noise, `√Σ wₖ²` with `wₖ` the knots' second
/// derivatives of the interpolant of a unit impulse.
fn noise_gain() -> f64 {
    static K: std::sync::OnceLock<f64> = std::sync::OnceLock::new();
    *K.get_or_init(|| {
        let n = 64;
        let mut impulse = vec![0.0; n];
        impulse[0] = 1.0;
        let t = LiftTable::new(1.0, impulse, true).expect("a valid table");
        (0..n)
            .map(|k| t.eval5(k as f64)[2].powi(2))
            .sum::<f64>()
            .sqrt()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A periodic table of a smooth periodic lift, its derivatives against the closed form; the
    /// error falls as `h⁶` (the quintic spline's order) — halving the step divides it by ~64.
    #[test]
    fn a_periodic_table_converges_to_its_lift_at_sixth_order() {
        let f = |x: f64| {
            let (s1, c1) = x.sin_cos();
            let (s2, c2) = (2.0 * x).sin_cos();
            [
                3.0 * s1 + c2,
                3.0 * c1 - 2.0 * s2,
                -3.0 * s1 - 4.0 * c2,
                -3.0 * c1 + 8.0 * s2,
                3.0 * s1 + 16.0 * c2,
            ]
        };
        let err = |n: usize| {
            let h = TAU / n as f64;
            let t = LiftTable::new(h, (0..n).map(|i| f(i as f64 * h)[0]).collect(), true).unwrap();
            let mut e = [0.0f64; 5];
            for k in 0..997 {
                let x = TAU * k as f64 / 997.0;
                let (got, want) = (t.eval5(x), f(x));
                for d in 0..5 {
                    e[d] = e[d].max((got[d] - want[d]).abs());
                }
            }
            e
        };
        let (a, b) = (err(90), err(180));
        assert!(a[0] < 1e-9 && a[2] < 1e-5, "{a:?}");
        let ratio = a[0] / b[0];
        assert!(ratio > 50.0 && ratio < 80.0, "{a:?} {b:?} {ratio}");
    }

    /// A table between dwells reproduces a quintic that starts and ends at rest with zero
    /// acceleration exactly (to rounding): the clamped spline's space holds it.
    #[test]
    fn a_table_between_dwells_reproduces_a_quintic_at_rest() {
        // y = x³ (10 − 15x + 6x²) has y' = y'' = 0 at both ends: the 3-4-5 law
        let y = |x: f64| {
            let (x2, x3) = (x * x, x * x * x);
            [
                x3 * (10.0 - 15.0 * x + 6.0 * x2),
                x2 * (30.0 - 60.0 * x + 30.0 * x2),
                x * (60.0 - 180.0 * x + 120.0 * x2),
                60.0 - 360.0 * x + 360.0 * x2,
                -360.0 + 720.0 * x,
            ]
        };
        let n = 12;
        let h = 1.0 / n as f64;
        let t = LiftTable::new(h, (0..=n).map(|i| y(i as f64 * h)[0]).collect(), false).unwrap();
        for k in 0..=101 {
            let x = k as f64 / 101.0;
            let (got, want) = (t.eval5(x), y(x));
            for d in 0..5 {
                assert!(
                    (got[d] - want[d]).abs() < 1e-9 * 360.0,
                    "x {x} d {d}: {got:?} {want:?}"
                );
            }
        }
        assert_eq!(t.span(), 1.0);
    }

    /// The spline is C⁴ at every knot: its third and fourth derivatives from both sides agree;
    /// its lifts are the table's.
    #[test]
    fn the_spline_is_c4_and_interpolates() {
        let lifts: Vec<f64> = (0..40)
            .map(|i| ((i * 7919) % 13) as f64 * 0.1 + (i as f64 * 0.3).sin())
            .collect();
        for periodic in [true, false] {
            let t = LiftTable::new(0.05, lifts.clone(), periodic).unwrap();
            for (i, &p) in lifts.iter().enumerate() {
                let x = i as f64 * 0.05;
                assert!((t.eval5(x)[0] - p).abs() < 1e-12, "{periodic} {i}");
            }
            for i in 1..39 {
                let x = i as f64 * 0.05;
                let (l, r) = (t.eval5(x - 1e-9), t.eval5(x + 1e-9));
                for d in 0..5 {
                    let scale = 1.0 / 0.05f64.powi(d as i32);
                    assert!(
                        (l[d] - r[d]).abs() < 1e-6 * scale * 10.0,
                        "{periodic} knot {i} d {d}: {l:?} {r:?}"
                    );
                }
                // at the knot itself, the piece on its left (from its right end) and the one
                // on its right (from its left end) give the same lift and four derivatives to
                // the last bit
                let (left, right) = (&t.coeffs[i - 1][1], &t.coeffs[i][0]);
                for k in 0..5 {
                    let sign = if k % 2 == 1 { -1.0 } else { 1.0 };
                    assert_eq!(sign * left[k], right[k], "{periodic} knot {i} order {k}");
                }
            }
        }
    }

    /// The noise estimate: a smooth lift's table (8 mm, every 0.5°) is estimated noise-free;
    /// rounded to a resolution `q` (uniform rounding noise, `σ = q/√12`, where the lift moves
    /// more than `q` a step) within 10 % of that; with pseudo-random uniform noise of a known
    /// `σ` added, within 10 % of it.
    #[test]
    fn the_noise_of_a_rounded_or_noisy_table_is_estimated() {
        let n = 720;
        let h = TAU / n as f64;
        let smooth: Vec<f64> = (0..n)
            .map(|i| 4.0 - 4.0 * (i as f64 * h).cos() + 0.5 * (2.0 * i as f64 * h).sin())
            .collect();
        let exact = LiftTable::new(h, smooth.clone(), true).unwrap().noise();
        assert!(exact.sigma < 1e-9, "{exact:?}");
        let q = 1e-3;
        let rounded: Vec<f64> = smooth.iter().map(|p| (p / q).round() * q).collect();
        let noisy = LiftTable::new(h, rounded, true).unwrap().noise();
        let want = q / 12f64.sqrt();
        assert!(
            (noisy.sigma / want - 1.0).abs() < 0.1,
            "{noisy:?} vs {want}"
        );
        // a linear congruential generator's uniform numbers in [−1/2, 1/2): σ = a/√12
        let mut state: u64 = 12345;
        let a = 4e-3;
        let random: Vec<f64> = smooth
            .iter()
            .map(|p| {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                p + a * ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5)
            })
            .collect();
        let noisy = LiftTable::new(h, random, true).unwrap().noise();
        let want = a / 12f64.sqrt();
        assert!(
            (noisy.sigma / want - 1.0).abs() < 0.1,
            "{noisy:?} vs {want}"
        );
        assert!(noisy.acceleration > 1e3 * exact.acceleration.max(1e-12));
    }
}
