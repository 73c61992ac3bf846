//! `camkin` for Python: a thin layer over the camkin library (no numerics of its own). The
//! extension module is `camkin._camkin`; the package `camkin` (python/camkin) re-exports it with
//! the error classes and the `Contact` result.

mod analyze;
mod columns;
mod contacts;
mod dict;
mod errors;
mod forces;
mod gear_loads;
mod geometry;
mod model;
mod motion;
mod nodes;
mod shop;
mod sim;
mod studio;
mod study;

use pyo3::prelude::*;

/// The camkin extension module.
#[pymodule]
fn _camkin(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<model::PyMechanism>()?;
    m.add_class::<model::PySystem>()?;
    m.add_class::<geometry::PyCurve>()?;
    m.add_class::<geometry::PyBody>()?;
    m.add_function(wrap_pyfunction!(model::paper_cam, m)?)?;
    m.add_function(wrap_pyfunction!(model::_mechanism_from_json, m)?)?;
    m.add_function(wrap_pyfunction!(model::_mechanism_from_text, m)?)?;
    m.add_function(wrap_pyfunction!(geometry::_curve_from_state, m)?)?;
    m.add_function(wrap_pyfunction!(geometry::_contact, m)?)?;
    m.add_function(wrap_pyfunction!(geometry::spline, m)?)?;
    m.add_function(wrap_pyfunction!(geometry::circle, m)?)?;
    m.add_function(wrap_pyfunction!(geometry::ellipse, m)?)?;
    m.add_function(wrap_pyfunction!(geometry::line, m)?)?;
    m.add_function(wrap_pyfunction!(geometry::point, m)?)?;
    m.add_function(wrap_pyfunction!(motion::motion_laws, m)?)?;
    m.add_function(wrap_pyfunction!(motion::motion_law, m)?)?;
    m.add_function(wrap_pyfunction!(study::spline_variants, m)?)?;
    m.add_function(wrap_pyfunction!(study::summarize, m)?)?;
    m.add_function(wrap_pyfunction!(studio::_studio_answer, m)?)?;
    m.add_function(wrap_pyfunction!(studio::_studio_assets, m)?)?;
    m.add("MAX_ANGLES", model::MAX_ANGLES)?;
    m.add("MAX_TEXT_BYTES", camkin::spec::text::MAX_TEXT_BYTES)?;
    Ok(())
}
