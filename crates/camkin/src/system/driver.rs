//! Driven coordinates: a body's angle or position as a function of time, `q_k − f(t) = 0`, with
//! `Φ_t = −ḟ` and `γ = f̈`.

use super::BodyId;

/// Which coordinate of a body a driver sets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Coordinate {
    /// the frame origin's x
    X,
    /// the frame origin's y
    Y,
    /// the angle, rad
    Angle,
}

impl Coordinate {
    /// Its index in a body's `(x, y, θ)`.
    pub(crate) fn index(self) -> usize {
        match self {
            Coordinate::X => 0,
            Coordinate::Y => 1,
            Coordinate::Angle => 2,
        }
    }
}

impl std::fmt::Display for Coordinate {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Coordinate::X => "x",
            Coordinate::Y => "y",
            Coordinate::Angle => "angle",
        })
    }
}

/// How a driven coordinate moves in time.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum DriverLaw {
    /// `f(t) = start + rate t + acceleration t²/2` (a cam at constant speed: `acceleration` 0)
    Quadratic {
        /// `f(0)`
        start: f64,
        /// `ḟ(0)`
        rate: f64,
        /// `f̈`
        acceleration: f64,
    },
}

impl DriverLaw {
    /// A coordinate at constant rate.
    pub fn linear(start: f64, rate: f64) -> Self {
        DriverLaw::Quadratic {
            start,
            rate,
            acceleration: 0.0,
        }
    }

    /// `(f, ḟ, f̈)` at time `t`.
    pub fn at(&self, t: f64) -> [f64; 3] {
        match *self {
            DriverLaw::Quadratic {
                start,
                rate,
                acceleration,
            } => [
                start + rate * t + 0.5 * acceleration * t * t,
                rate + acceleration * t,
                acceleration,
            ],
        }
    }

    /// Its Taylor coefficients at `t`: `f(t + ε) = c₀ + c₁ ε + c₂ ε² + c₃ ε³ + …` (`c₃` is the
    /// third derivative over 6), for the jerk.
    pub fn taylor(&self, t: f64) -> [f64; 4] {
        let [f, fd, fdd] = self.at(t);
        match *self {
            DriverLaw::Quadratic { .. } => [f, fd, 0.5 * fdd, 0.0],
        }
    }
}

/// A named driver: `body`'s `coordinate` follows `law`.
#[derive(Debug, Clone, PartialEq)]
pub struct Driver {
    /// its name
    pub name: String,
    /// the driven body (not the ground)
    pub body: BodyId,
    /// which of its coordinates
    pub coordinate: Coordinate,
    /// how it moves
    pub law: DriverLaw,
}
