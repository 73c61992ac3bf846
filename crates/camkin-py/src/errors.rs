//! The library's typed errors as the Python exception hierarchy of `camkin.errors`:
//! `InputError` (with `.field` and `.value`), `ContactError`, `ResourceError`, all
//! `CamkinError`s.

use camkin::spec::SpecError;
use pyo3::prelude::*;

/// Raises `camkin.errors.<class>(message, *extra)`.
fn raise(py: Python<'_>, class: &str, message: String, extra: Vec<Py<PyAny>>) -> PyErr {
    let made = (|| -> PyResult<PyErr> {
        let cls = py.import("camkin.errors")?.getattr(class)?;
        let mut args: Vec<Py<PyAny>> = vec![message.clone().into_pyobject(py)?.into_any().unbind()];
        args.extend(extra);
        let tuple = pyo3::types::PyTuple::new(py, args)?;
        Ok(PyErr::from_value(cls.call1(tuple)?))
    })();
    made.unwrap_or_else(|e| e)
}

/// `InputError(message, field, value)`: bad input, naming the field (a dotted path, as in the
/// files: `follower.roller_radius`) and the value given (None when absent).
pub fn input(field: &str, value: Option<String>, message: String) -> PyErr {
    Python::attach(|py| {
        let field = pyo3::types::PyString::new(py, field).into_any().unbind();
        let value = match value {
            Some(v) => pyo3::types::PyString::new(py, &v).into_any().unbind(),
            None => py.None(),
        };
        raise(py, "InputError", message, vec![field, value])
    })
}

/// `ContactError(message)`: the numerics stopped, and why.
pub fn contact(message: String) -> PyErr {
    Python::attach(|py| raise(py, "ContactError", message, vec![]))
}

/// `ResourceError(message)`: work refused up front, with the estimate.
pub fn resource(message: String) -> PyErr {
    Python::attach(|py| raise(py, "ResourceError", message, vec![]))
}

/// Refuses `work` over the library's limits ([`camkin::work`]) unless `large=True`: a
/// `ResourceError` with the library's sentence and what else to change (`", or use fewer
/// angles"`).
pub fn refuse_large(work: &camkin::work::Work, large: bool, otherwise: &str) -> PyResult<()> {
    match work.refusal() {
        Some(r) if !large => Err(resource(format!(
            "{r}; pass large=True to run it anyway{otherwise}"
        ))),
        _ => Ok(()),
    }
}

/// A spec error as an `InputError` on its field.
pub fn spec(e: &SpecError) -> PyErr {
    let (field, value) = match e {
        SpecError::Invalid { field, value, .. } | SpecError::Unknown { field, value, .. } => {
            (field.to_string(), Some(value.clone()))
        }
        SpecError::Missing { field, missing, .. } => (format!("{}.{missing}", field.table()), None),
        SpecError::PointsFile { path, .. } => (e.field().to_string(), Some(path.clone())),
        other => (other.field().to_string(), None),
    };
    input(&field, value, e.to_string())
}
