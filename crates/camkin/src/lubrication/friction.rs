//! The lubrication regime from λ and the friction coefficient by a stated model.

/// λ below which the contact runs in boundary lubrication (asperities carry the load).
pub const MIXED_LAMBDA: f64 = 1.0;
/// λ from which the film separates the surfaces fully (Hamrock, Schmid and Jacobson 2004,
/// §1.4 and Fig. 1.6: boundary below 1, mixed from 1 to 3, elastohydrodynamic above 3; Tallian's
/// λ ratio).
pub const FULL_FILM_LAMBDA: f64 = 3.0;

/// The lubrication regime of a contact by its λ ratio (`h_min / σ`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum Regime {
    /// λ < 1: the asperities carry the load
    Boundary,
    /// 1 ≤ λ < 3: film and asperities share it
    Mixed,
    /// λ ≥ 3: the film separates the surfaces
    FullFilm,
}

impl Regime {
    /// The name in tables.
    pub fn name(self) -> &'static str {
        match self {
            Self::Boundary => "boundary",
            Self::Mixed => "mixed",
            Self::FullFilm => "full-film",
        }
    }
}

/// The regime at λ ([`MIXED_LAMBDA`], [`FULL_FILM_LAMBDA`]).
pub fn regime(lambda: f64) -> Regime {
    if lambda < MIXED_LAMBDA {
        Regime::Boundary
    } else if lambda < FULL_FILM_LAMBDA {
        Regime::Mixed
    } else {
        Regime::FullFilm
    }
}

/// How the friction coefficient is found.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub enum Friction {
    /// one coefficient throughout
    Constant(f64),
    /// `boundary` at λ ≤ 1, `full_film` at λ ≥ 3, linear in λ between: the mixed regime's
    /// share of the load passing from the asperities to the film as λ grows (a stated
    /// interpolation, not a traction model: full-film traction depends on the oil's rheology)
    Mixed {
        /// the coefficient of boundary lubrication (about 0.1 for steel on steel in oil)
        boundary: f64,
        /// the coefficient of a full film (a few hundredths)
        full_film: f64,
    },
}

impl Friction {
    /// The coefficient at λ (`None`: no film computed, where [`Friction::Mixed`] takes the
    /// boundary value).
    pub fn coefficient(&self, lambda: Option<f64>) -> f64 {
        match *self {
            Self::Constant(mu) => mu,
            Self::Mixed {
                boundary,
                full_film,
            } => {
                let l = lambda.unwrap_or(0.0);
                if l <= MIXED_LAMBDA {
                    boundary
                } else if l >= FULL_FILM_LAMBDA {
                    full_film
                } else {
                    let t = (l - MIXED_LAMBDA) / (FULL_FILM_LAMBDA - MIXED_LAMBDA);
                    boundary + t * (full_film - boundary)
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regimes_and_the_mixed_model_meet_at_their_bounds() {
        assert_eq!(regime(0.99), Regime::Boundary);
        assert_eq!(regime(1.0), Regime::Mixed);
        assert_eq!(regime(2.99), Regime::Mixed);
        assert_eq!(regime(3.0), Regime::FullFilm);
        let m = Friction::Mixed {
            boundary: 0.12,
            full_film: 0.04,
        };
        assert_eq!(m.coefficient(Some(0.5)), 0.12);
        assert_eq!(m.coefficient(None), 0.12);
        assert_eq!(m.coefficient(Some(1.0)), 0.12);
        assert!((m.coefficient(Some(2.0)) - 0.08).abs() < 1e-15);
        assert_eq!(m.coefficient(Some(3.0)), 0.04);
        assert_eq!(m.coefficient(Some(30.0)), 0.04);
        assert_eq!(Friction::Constant(0.07).coefficient(Some(5.0)), 0.07);
    }
}
