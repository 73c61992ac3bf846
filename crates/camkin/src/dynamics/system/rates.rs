//! How fast a system's force elements make it move: their fastest rate (a bound on the
//! stiffness's and the damping's largest eigenvalues over the masses) and the longest step the
//! integration is stable at, for its work estimate and its scales.

use super::super::model::Load;
use super::SystemSimulation;

/// The fastest rate of a system's elements ([`SystemSimulation::fastest_rate`]).
#[derive(Debug, Clone, Default)]
pub(crate) struct Fastest {
    /// the fastest rate, 1/s
    pub(crate) rate: f64,
    /// the element that sets it, named (`damper "lash"`)
    pub(crate) element: String,
    /// it is a damper's (a decay's, not a vibration's)
    pub(crate) damper: bool,
    /// the fastest vibration's rate (the springs'), 1/s
    pub(crate) vibration: f64,
}

/// An implicit step's cost in explicit steps (five stages of about two Newton iterations, seven
/// evaluations an explicit step).
const IMPLICIT_STEP: f64 = 1.5;
/// The implicit steps a Jacobian serves, about.
const JACOBIAN_REUSE: f64 = 4.0;

impl SystemSimulation<'_> {
    /// The fastest rate of the system's force elements, 1/s, and the element that sets it: a
    /// bound on the largest eigenvalue of `M⁻¹K` (a rate `√λ`) and of `M⁻¹C` (a rate `λ`) by
    /// Gershgorin's theorem on the symmetric `M^{-1/2} K M^{-1/2}`: each body's row sums, for
    /// every spring on it, `k/m_i + k/√(m_i m_j)` (the ground's infinite mass adds nothing),
    /// rotations apart with the inertias. A lone spring to the ground gives `√(k/m)`; a chain
    /// of equal masses and springs `2√(k/m)`, its highest mode's frequency (before, each
    /// spring's own `√(k/m)` let a coil of 64 masses run at a step where that mode grows, and
    /// its masses clashed at 59 m/s). The element named is the largest term of the fastest
    /// body's row.
    pub fn fastest_rate(&self) -> (f64, String) {
        let f = self.fastest.get_or_init(|| self.find_fastest_rate());
        (f.rate, f.element.clone())
    }

    /// [`SystemSimulation::fastest_rate`], found.
    pub(super) fn find_fastest_rate(&self) -> Fastest {
        use crate::system::ForceKind;
        let mass = |id: crate::system::BodyId, angular: bool| {
            id.index().map_or(f64::INFINITY, |i| {
                let b = &self.model.bodies[i];
                if angular {
                    b.inertia
                } else {
                    b.mass
                }
            })
        };
        let n = self.model.bodies.len();
        // per body and per kind (0 translational spring, 1 rotational spring, 2 translational
        // damper, 3 rotational damper): the row sum and its largest term with its element
        let mut rows = vec![[(0.0f64, 0.0f64, usize::MAX); 4]; n];
        for (e, f) in self.sys.forces().iter().enumerate() {
            let [a, b] = f.kind.bodies();
            let (kind, value) = match f.kind {
                ForceKind::Spring { stiffness, .. } => (0, stiffness),
                ForceKind::TorsionSpring { stiffness, .. } => (1, stiffness),
                ForceKind::Damper { damping, .. } => (2, damping),
                ForceKind::TorsionDamper { damping, .. } => (3, damping),
            };
            let angular = kind % 2 == 1;
            for (me, other) in [(a, b), (b, a)] {
                let Some(i) = me.index() else { continue };
                let (mi, mj) = (mass(me, angular), mass(other, angular));
                let term = value * (1.0 / mi + 1.0 / (mi * mj).sqrt());
                let row = &mut rows[i][kind];
                row.0 += term;
                if term > row.1 {
                    row.1 = term;
                    row.2 = e;
                }
            }
        }
        // a lash adjuster's oil is a spring between its bodies: its stiffness `β A / h` as drawn,
        // with the oil's own bulk modulus (air only softens it, less as it is pressed),
        // numbered after the force elements
        let elements = self.sys.forces().len();
        for (k, h) in self.sys.lash_adjusters().iter().enumerate() {
            let a = &h.adjuster;
            let value = a.oil_stiffness();
            for (me, other) in [(a.a, a.b), (a.b, a.a)] {
                let Some(i) = me.index() else { continue };
                let (mi, mj) = (mass(me, false), mass(other, false));
                let term = value * (1.0 / mi + 1.0 / (mi * mj).sqrt());
                let row = &mut rows[i][0];
                row.0 += term;
                if term > row.1 {
                    row.1 = term;
                    row.2 = elements + k;
                }
            }
        }
        let name = |e: usize| match self.sys.forces().get(e) {
            Some(f) => {
                let what = match f.kind {
                    ForceKind::Damper { .. } => "damper",
                    ForceKind::TorsionSpring { .. } => "torsion spring",
                    ForceKind::TorsionDamper { .. } => "torsion damper",
                    ForceKind::Spring { .. } => "spring",
                };
                format!("{what} {:?}", f.name)
            }
            None => format!(
                "lash adjuster {:?}",
                self.sys.lash_adjusters()[e - elements].name
            ),
        };
        let mut fastest = Fastest::default();
        for row in &rows {
            for (kind, &(sum, _, e)) in row.iter().enumerate() {
                let rate = if kind < 2 { sum.sqrt() } else { sum };
                if kind < 2 && e != usize::MAX {
                    fastest.vibration = fastest.vibration.max(rate);
                }
                if rate > fastest.rate && e != usize::MAX {
                    fastest.rate = rate;
                    fastest.element = name(e);
                    fastest.damper = kind >= 2;
                }
            }
        }
        // an open check valve brings the chamber to its supply at `β G / V`: a decay
        for h in self.sys.lash_adjusters() {
            let a = &h.adjuster;
            let rate = a.refill_rate();
            if rate > fastest.rate {
                fastest.rate = rate;
                fastest.element = format!("lash adjuster {:?}'s check valve", h.name);
                fastest.damper = true;
            }
        }
        fastest
    }

    /// The longest step the integration is stable at, s: the Dormand–Prince pair's stability
    /// region reaches 3.3 along the negative real axis (Hairer, Nørsett and Wanner, Solving
    /// ODE I, §IV.2 fig. 2.1 of part II), so 3.3 over the fastest rate; the step the tolerances
    /// choose is no longer than it for long (a longer one's error grows, and it is cut).
    pub fn stable_step(&self) -> f64 {
        let rate = self.fastest.get_or_init(|| self.find_fastest_rate()).rate;
        if rate > 0.0 {
            3.3 / rate
        } else {
            f64::INFINITY
        }
    }

    /// The steps a run of `duration` s with outputs every `h_out` s is expected to take: each
    /// no longer than the run's longest, the step the tolerances allow a smooth motion,
    /// `2 T tol^(1/5)` with `T` the system's time scale (its size over its speed scale, or a
    /// link's swing under gravity) and `tol` the tighter tolerance (the pair's error grows as
    /// `h⁵`; the factor 2 between the double pendulum's 1.1, which set it before, and Andrews'
    /// mechanism's 3: the N-four-bar takes 1.15 times the estimate, the slider-crank 1.14, Andrews' 0.67, a double
    /// pendulum at its factor about 1.8), nor the stiff elements'
    /// `12 h_s tol^(1/5)` (at most `h_s`, [`SystemSimulation::stable_step`]: their vibrations
    /// resolved; measured on the valve train within 3 % with its coils undamped, and at 0.53 of
    /// the estimate with them damped, their high modes no longer ringing).
    pub fn steps_estimate(&self, duration: f64, h_out: f64) -> f64 {
        self.steps_estimate_at(duration, h_out, 1.0)
    }

    /// The system's time scale with its drivers `speed` times as fast, s: its size over its
    /// speed scale, or where gravity moves it the period scale of its shortest link swinging,
    /// `√(l/g)` (`l` the farthest two of a body's joint points apart; links shorter than a
    /// hundredth of the longest left out), whichever is shorter — a chain of forty one-metre
    /// links swings as fast as one link, not as one forty metres long, and a slider-crank as
    /// fast as its crank (with the rod's length its estimate was half the steps it took).
    fn time_scale(&self, speed: f64) -> f64 {
        let whole = self.size / (self.speed_scale * speed);
        let g = self
            .model
            .forces
            .iter()
            .find_map(|f| match f {
                Load::Gravity(g) => Some(g.norm()),
                _ => None,
            })
            .unwrap_or(0.0);
        if !(g > 0.0) {
            return whole;
        }
        // each body's joint points, in its frame; its extent their farthest pair's distance
        let mut points: Vec<Vec<crate::geometry::Point2>> = vec![Vec::new(); self.q.len() / 3];
        for j in self.sys.joints() {
            for (id, at) in j.kind.points() {
                if let Some(i) = id.index() {
                    points[i].push(at);
                }
            }
        }
        let spans: Vec<f64> = points
            .iter()
            .map(|p| {
                p.iter()
                    .flat_map(|x| p.iter().map(move |y| (x - y).norm()))
                    .fold(0.0f64, f64::max)
            })
            .collect();
        let longest = spans.iter().copied().fold(0.0f64, f64::max);
        // the shortest link that is not a sliver (a hundredth of the longest) swings fastest
        let shortest = spans
            .iter()
            .copied()
            .filter(|&l| l >= 0.01 * longest && l > 0.0)
            .fold(f64::INFINITY, f64::min);
        if shortest.is_finite() {
            whole.min((shortest / g).sqrt())
        } else {
            whole
        }
    }

    /// [`SystemSimulation::steps_estimate`] with the drivers `speed` times as fast (a speed
    /// sweep's runs): the time scale and a degree of the driver shorter by that factor, the
    /// stable step the same.
    pub fn steps_estimate_at(&self, duration: f64, h_out: f64, speed: f64) -> f64 {
        let tol = self.opts.tolerances;
        let scale = tol.relative.min(tol.absolute).powf(0.2);
        let smooth = self.smooth_step(speed);
        let longest = h_out.max(self.degree_time() / speed);
        if self.implicit() {
            // the implicit method's steps end at every output and follow the motion; each
            // costs about IMPLICIT_STEP explicit steps and a Jacobian every few
            let h = h_out.min(smooth);
            let per_step = IMPLICIT_STEP + 2.0 * self.q.len() as f64 / 7.0 / JACOBIAN_REUSE;
            return (duration / h).ceil().max(1.0) * per_step;
        }
        let stable = self.stable_step();
        let stiff = stable.min(12.0 * stable * scale);
        let h = longest.min(smooth).min(stiff);
        (duration / h).ceil().max(1.0)
    }

    /// The step the tolerances allow a smooth motion, s: `2 T tol^(1/5)` (see
    /// [`SystemSimulation::steps_estimate`]).
    fn smooth_step(&self, speed: f64) -> f64 {
        let tol = self.opts.tolerances;
        2.0 * self.time_scale(speed) * tol.relative.min(tol.absolute).powf(0.2)
    }

    /// Whether the steps are the implicit method's ([`crate::dynamics::Scheme`]): asked for,
    /// or chosen where the fastest rate is a damper's (a decay, which the implicit method
    /// passes over in steps of the motion's length) and over ten times both the fastest
    /// vibration's and the motion's (one over its time scale).
    pub(crate) fn implicit(&self) -> bool {
        use crate::dynamics::Scheme;
        match self.opts.scheme {
            Scheme::Explicit => false,
            Scheme::Implicit => true,
            _ => *self.auto_implicit.get_or_init(|| {
                let f = self.fastest.get_or_init(|| self.find_fastest_rate());
                f.damper && f.rate > 10.0 * f.vibration.max(1.0 / self.time_scale(1.0))
            }),
        }
    }
}
