//! How long a step a system's simulation may take: its force elements' fastest rate (a bound on
//! the stiffness's and the damping's largest eigenvalues over the masses) and the step and
//! substeps it allows.

use super::SystemSimulation;

impl SystemSimulation<'_> {
    /// The fastest rate of the system's force elements, 1/s, and the element that sets it: a
    /// bound on the largest eigenvalue of `M⁻¹K` (a rate `√λ`) and of `M⁻¹C` (a rate `λ`) by
    /// Gershgorin's theorem on the symmetric `M^{-1/2} K M^{-1/2}`: each body's row sums, for
    /// every spring on it, `k/m_i + k/√(m_i m_j)` (the ground's infinite mass adds nothing),
    /// rotations apart with the inertias. A lone spring to the ground gives `√(k/m)`; a chain
    /// of equal masses and springs `2√(k/m)`, its highest mode's frequency (before, each
    /// spring's own `√(k/m)` let a coil of 64 masses run at a step where that mode grows, and
    /// its masses clashed at 59 m/s). RK4 is stable for a step up to [`super::super::MAX_RATE_STEP`]
    /// over it. The element named is the largest term of the fastest body's row.
    pub fn fastest_rate(&self) -> (f64, String) {
        self.fastest
            .get_or_init(|| self.find_fastest_rate())
            .clone()
    }

    /// [`SystemSimulation::fastest_rate`], found.
    fn find_fastest_rate(&self) -> (f64, String) {
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
        let mut fastest = (0.0, String::new());
        for row in &rows {
            for (kind, &(sum, _, e)) in row.iter().enumerate() {
                let rate = if kind < 2 { sum.sqrt() } else { sum };
                if rate > fastest.0 && e != usize::MAX {
                    let f = &self.sys.forces()[e];
                    let what = match f.kind {
                        ForceKind::Damper { .. } => "damper",
                        ForceKind::TorsionSpring { .. } => "torsion spring",
                        ForceKind::TorsionDamper { .. } => "torsion damper",
                        ForceKind::Spring { .. } => "spring",
                    };
                    fastest = (rate, format!("{what} {:?}", f.name));
                }
            }
        }
        fastest
    }

    /// The fewest steps that cut an output interval of `h_out` s into steps no longer than
    /// [`SystemSimulation::max_step`] (at least one).
    pub fn substeps(&self, h_out: f64) -> usize {
        (h_out / self.max_step()).ceil().max(1.0) as usize
    }

    /// The longest step [`SystemSimulation::advance`] accepts, s.
    pub fn max_step(&self) -> f64 {
        if let Some(h) = self.step_limit {
            return h;
        }
        let rate = self.fastest.get_or_init(|| self.find_fastest_rate()).0;
        if rate > 0.0 {
            super::super::MAX_RATE_STEP / rate
        } else {
            f64::INFINITY
        }
    }
}
