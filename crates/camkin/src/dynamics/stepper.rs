//! A simulated system's integrator: the explicit Dormand–Prince pair ([`super::dopri`]) or the
//! implicit SDIRK method for stiff systems ([`super::sdirk`]), chosen by the [`Scheme`] asked
//! for; the steps' control, projection and events are the same for both
//! ([`super::system::SystemSimulation`]).

use super::dopri::Dopri;
use super::sdirk::Sdirk;

/// Which integrator a simulation's steps take.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Scheme {
    /// The implicit method where the system's fastest rate is a damper's decay, over ten times
    /// its fastest vibration's and its motion's (a damper of 10⁶ N·s/m on a kilogram held by a
    /// spring of 10⁶ N/m: a decay at 10⁶/s, a vibration at 10³/s); the explicit pair otherwise
    /// (a spring's vibrations are resolved either way).
    #[default]
    Auto,
    /// The Dormand–Prince 5(4) pair: seven evaluations a step, stable to 3.3 over the fastest
    /// rate.
    Explicit,
    /// The L-stable, stiffly accurate SDIRK method of order 4(3) (Hairer and Wanner): five
    /// implicit stages by Newton with a difference-quotient Jacobian; its steps follow the
    /// motion whatever the stiffness, and each costs more.
    Implicit,
}

impl Scheme {
    /// The names the command line and the files use: `auto`, `explicit`, `implicit`.
    pub const NAMES: [&'static str; 3] = ["auto", "explicit", "implicit"];

    /// The scheme of a name of [`Scheme::NAMES`].
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "auto" => Some(Self::Auto),
            "explicit" => Some(Self::Explicit),
            "implicit" => Some(Self::Implicit),
            _ => None,
        }
    }
}

/// A step's integrator with its stages, end and interpolant.
#[derive(Debug, Clone)]
pub(crate) enum Stepper {
    Explicit(Box<Dopri>),
    Implicit(Box<Sdirk>),
}

impl Default for Stepper {
    fn default() -> Self {
        Self::Explicit(Box::default())
    }
}

impl Stepper {
    /// A stepper of the implicit method (`implicit`) or the explicit pair.
    pub(crate) fn new(implicit: bool) -> Self {
        if implicit {
            Self::Implicit(Box::default())
        } else {
            Self::default()
        }
    }

    /// Whether it is the implicit method.
    pub(crate) fn is_implicit(&self) -> bool {
        matches!(self, Self::Implicit(_))
    }

    /// The order of its error estimate in the step, for the controller.
    pub(crate) fn error_order(&self) -> f64 {
        if self.is_implicit() {
            4.0
        } else {
            5.0
        }
    }

    /// The derivative at the step's start, set by the caller before a step.
    pub(crate) fn first(&mut self) -> &mut Vec<f64> {
        match self {
            Self::Explicit(d) => &mut d.k[0],
            Self::Implicit(s) => &mut s.f0,
        }
    }

    /// (see [`Stepper::first`])
    pub(crate) fn first_ref(&self) -> &[f64] {
        match self {
            Self::Explicit(d) => &d.k[0],
            Self::Implicit(s) => &s.f0,
        }
    }

    /// The last step's start.
    pub(crate) fn t0(&self) -> f64 {
        match self {
            Self::Explicit(d) => d.t0,
            Self::Implicit(s) => s.t0,
        }
    }

    /// The last step's length.
    pub(crate) fn h(&self) -> f64 {
        match self {
            Self::Explicit(d) => d.h,
            Self::Implicit(s) => s.h,
        }
    }

    /// The last step's start state.
    pub(crate) fn y0(&self) -> &[f64] {
        match self {
            Self::Explicit(d) => &d.y0,
            Self::Implicit(s) => &s.y0,
        }
    }

    /// The last step's end state.
    pub(crate) fn y1(&self) -> &[f64] {
        match self {
            Self::Explicit(d) => &d.y1,
            Self::Implicit(s) => &s.y1,
        }
    }

    /// A step of `h` from `(t, y0)` (see [`Dopri::attempt`] and [`Sdirk::attempt`]): the
    /// error's norm. `states` components have Jacobian columns, each of size `typical(i)`.
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
        match self {
            Self::Explicit(d) => d.attempt(t, y0, h, f, scale),
            Self::Implicit(s) => s.attempt(t, y0, h, states, f, scale, typical),
        }
    }

    /// The interpolant of the step just accepted (the explicit pair's from its stages; the
    /// implicit method's needs nothing more).
    pub(crate) fn interpolant(&mut self) {
        if let Self::Explicit(d) = self {
            d.interpolant();
        }
    }

    /// The solution at `θ ∈ [0, 1]` of the last step.
    pub(crate) fn at(&self, theta: f64, out: &mut Vec<f64>) {
        match self {
            Self::Explicit(d) => d.at(theta, out),
            Self::Implicit(s) => s.at(theta, out),
        }
    }

    /// The equations changed (a contact closed or opened): the implicit method makes a new
    /// Jacobian.
    pub(crate) fn invalidate(&mut self) {
        if let Self::Implicit(s) = self {
            s.invalidate();
        }
    }

    /// `redo` made ready to take the last step again from its start: of the same kind, with
    /// its first derivative (and its Jacobian).
    pub(crate) fn prepare_redo(&self, redo: &mut Stepper) {
        if redo.is_implicit() != self.is_implicit() {
            *redo = Stepper::new(self.is_implicit());
        }
        redo.first().clear();
        redo.first().extend_from_slice(self.first_ref());
        if let (Self::Implicit(a), Self::Implicit(b)) = (self, redo) {
            b.share(a);
        }
    }
}
