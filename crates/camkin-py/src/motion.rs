//! Motion laws in normalised form, as the mechanism files name them.

use crate::columns::angles_from;
use crate::errors;
use camkin::motion::Law;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// motion_laws() -> list of str: the laws a motion program's segments may name.
///
/// Example::
///
///     camkin.motion_laws()
#[pyfunction]
pub fn motion_laws() -> Vec<&'static str> {
    Law::ALL.iter().map(|l| l.name()).collect()
}

/// motion_law(name, x) -> dict: the normalised law ``y(x)`` on ``x ∈ [0, 1]`` (rising from 0 to 1;
/// the end values outside) and its derivatives: keys ``y``, ``dy``, ``d2y``, ``d3y`` (arrays, or
/// numbers for a number ``x``). A segment of rise h over β rad of cam angle moves the follower by
/// ``h y((θ − θ₀)/β)``, with velocity ``h y'/β · ω`` and acceleration ``h y''/β² · ω²``.
///
/// Example::
///
///     x = np.linspace(0.0, 1.0, 5)               # fraction of the segment
///     camkin.motion_law("cycloidal", x)["y"]     # fraction of the rise
#[pyfunction]
pub fn motion_law<'py>(
    py: Python<'py>,
    name: &str,
    x: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let law = Law::ALL.iter().find(|l| l.name() == name).ok_or_else(|| {
        errors::input(
            "law",
            Some(name.into()),
            format!(
                "law = {name:?} is not a motion law ({})",
                motion_laws().join(", ")
            ),
        )
    })?;
    let (xs, scalar) = angles_from(py, x, "x")?;
    let vals: Vec<[f64; 4]> = xs.iter().map(|&x| law.normalized(x)).collect();
    let d = PyDict::new(py);
    for (k, key) in ["y", "dy", "d2y", "d3y"].iter().enumerate() {
        let col: Vec<f64> = vals.iter().map(|v| v[k]).collect();
        if scalar {
            d.set_item(*key, col[0])?;
        } else {
            d.set_item(*key, PyArray1::from_vec(py, col))?;
        }
    }
    crate::columns::result(d)
}
