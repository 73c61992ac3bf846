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
    input_at(field, value, message, None)
}

/// [`input`] placed at 1-based `(line, column)` of a mechanism's text (`.line`, `.column`).
pub fn input_at(
    field: &str,
    value: Option<String>,
    message: String,
    at: Option<(usize, usize)>,
) -> PyErr {
    Python::attach(|py| {
        let field = pyo3::types::PyString::new(py, field).into_any().unbind();
        let value = match value {
            Some(v) => pyo3::types::PyString::new(py, &v).into_any().unbind(),
            None => py.None(),
        };
        let place = |x: Option<usize>| -> Py<PyAny> {
            match x.and_then(|x| x.into_pyobject(py).ok()) {
                Some(x) => x.into_any().unbind(),
                None => py.None(),
            }
        };
        let (line, column) = (place(at.map(|a| a.0)), place(at.map(|a| a.1)));
        raise(py, "InputError", message, vec![field, value, line, column])
    })
}

/// Bad mechanism text (the library's one reader, [`camkin::spec::text`]) as an `InputError`
/// with the field, the value and the place in the text.
pub fn text(e: camkin::spec::text::TextError) -> PyErr {
    use camkin::spec::text::TextProblem;
    if let TextProblem::Spec(s) = &e.problem {
        if let camkin::spec::SpecError::TooMuch { .. } = **s {
            return resource(format!("{}; pass large=True to build it anyway", e.message));
        }
    }
    let (field, value) = match &e.problem {
        TextProblem::Spec(s) => field_value(s),
        TextProblem::Read => ("source".to_string(), Some(e.name.clone())),
        TextProblem::Syntax { value } => (e.path.clone().unwrap_or_default(), value.clone()),
        _ => (e.path.clone().unwrap_or_default(), None),
    };
    input_at(&field, value, e.message, e.at)
}

/// Whether Python has a signal pending (Ctrl-C): its exception (`KeyboardInterrupt`), checked
/// between chunks of work done with the GIL released, so that a long call can be interrupted
/// (called on the thread that called into camkin, Python's main thread when the user's is).
pub fn interrupted() -> PyResult<()> {
    Python::attach(|py| py.check_signals())
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
    if let SpecError::TooMuch { .. } = e {
        return resource(format!("{e}; pass large=True to build it anyway"));
    }
    let (field, value) = field_value(e);
    input(&field, value, e.to_string())
}

/// The field a spec error names (a dotted path) and the value given, as text.
fn field_value(e: &SpecError) -> (String, Option<String>) {
    match e {
        SpecError::Invalid { field, value, .. } | SpecError::Unknown { field, value, .. } => {
            (field.to_string(), Some(value.clone()))
        }
        SpecError::Missing { field, missing, .. } => (format!("{}.{missing}", field.table()), None),
        SpecError::PointsFile { path, .. } => (e.field().to_string(), Some(path.clone())),
        other => (other.field().to_string(), None),
    }
}

/// Whether `x` is a NumPy object (an array or a scalar).
pub fn is_numpy(x: &Bound<'_, PyAny>) -> bool {
    x.get_type()
        .module()
        .map(|m| m.to_string().starts_with("numpy"))
        .unwrap_or(false)
}

/// A NumPy scalar's dtype kind (`"f"`, `"i"`, `"u"`, `"c"`, …), `None` for anything else (an
/// array included).
fn numpy_scalar_kind(x: &Bound<'_, PyAny>) -> PyResult<Option<String>> {
    if !is_numpy(x) || !x.hasattr("dtype")? {
        return Ok(None);
    }
    let scalar = x
        .getattr("ndim")
        .and_then(|n| n.extract::<usize>())
        .unwrap_or(1)
        == 0;
    Ok(if scalar {
        x.getattr("dtype")?.getattr("kind")?.extract().ok()
    } else {
        None
    })
}

/// A real number given as an argument (a Python int or float, or a NumPy integer or floating
/// scalar), for `#[pyo3(from_py_with = …)]`: anything else (text, a complex number, None, a bool)
/// is an `InputError` with the value, whose `.field` the argument's name fills (pyo3 notes
/// "while processing 'NAME'" on the error, which `InputError.add_note` reads).
pub fn real(x: &Bound<'_, PyAny>) -> PyResult<f64> {
    use pyo3::types::{PyBool, PyFloat, PyInt};
    let bad = |what: &str| {
        let shown = x.repr().map_or_else(|_| "?".into(), |r| r.to_string());
        input_at(
            "",
            Some(shown.clone()),
            if what == "None" {
                "must be a real number, not None".to_string()
            } else {
                format!("must be a real number, not {what} ({shown})")
            },
            None,
        )
    };
    if x.is_instance_of::<PyBool>() {
        return Err(bad("a bool"));
    }
    if x.is_instance_of::<PyFloat>() || x.is_instance_of::<PyInt>() {
        return x.extract::<f64>();
    }
    if let Some("f" | "i" | "u") = numpy_scalar_kind(x)?.as_deref() {
        return x.call_method0("item")?.extract::<f64>();
    }
    let name = x
        .get_type()
        .name()
        .map_or_else(|_| "?".into(), |n| n.to_string());
    Err(bad(&match name.as_str() {
        "str" => "text".to_string(),
        "complex" => "a complex number".to_string(),
        "NoneType" => "None".to_string(),
        other => format!("a {other}"),
    }))
}

/// [`real`], or None.
pub fn real_or_none(x: &Bound<'_, PyAny>) -> PyResult<Option<f64>> {
    if x.is_none() {
        Ok(None)
    } else {
        real(x).map(Some)
    }
}

/// Warns with a `camkin.errors.CamkinWarning(message, field, value, line, column)` (Python's
/// `warnings`, pointing at the caller's line): `field` names what it is about as an
/// `InputError` would (`cam.profile.points`, `angles_deg`), `value` the value (text), `at` its
/// 1-based place in a mechanism's text.
pub fn warn(
    py: Python<'_>,
    message: &str,
    field: Option<&str>,
    value: Option<String>,
    at: Option<(usize, usize)>,
) -> PyResult<()> {
    let cls = py.import("camkin.errors")?.getattr("CamkinWarning")?;
    let w = cls.call1((message, field, value, at.map(|a| a.0), at.map(|a| a.1)))?;
    let kwargs = pyo3::types::PyDict::new(py);
    kwargs.set_item("stacklevel", 2)?;
    py.import("warnings")?
        .getattr("warn")?
        .call((w,), Some(&kwargs))?;
    Ok(())
}

/// The field a spec warning is about (a dotted path, as the files write it), when it names one.
pub fn spec_warning_field(w: &camkin::spec::SpecWarning) -> Option<String> {
    match w {
        camkin::spec::SpecWarning::UnevenNodes { field, .. } => Some(field.to_string()),
        camkin::spec::SpecWarning::ConjugateLeftOut => Some("follower.conjugate".into()),
        _ => None,
    }
}

/// A count given as an argument (a Python int or a NumPy integer scalar, not negative), for
/// `#[pyo3(from_py_with = …)]`: anything else (a float, text, None, a bool) is an
/// `InputError` with the value, its `.field` the argument's name (as [`real`]).
pub fn count(x: &Bound<'_, PyAny>) -> PyResult<usize> {
    use pyo3::types::{PyBool, PyInt};
    let shown = x.repr().map_or_else(|_| "?".into(), |r| r.to_string());
    let bad = |why: String| input_at("", Some(shown.clone()), why, None);
    let int = if x.is_instance_of::<PyBool>() {
        None
    } else if x.is_instance_of::<PyInt>() {
        Some(x.clone())
    } else {
        match numpy_scalar_kind(x)?.as_deref() {
            Some("i" | "u") => Some(x.call_method0("item")?),
            _ => None,
        }
    };
    let Some(int) = int else {
        return Err(bad(format!("must be a whole number, not {shown}")));
    };
    int.extract::<usize>()
        .map_err(|_| bad(format!("must be a whole number from 0 up, not {shown}")))
}

/// [`count`], or None.
pub fn count_or_none(x: &Bound<'_, PyAny>) -> PyResult<Option<usize>> {
    if x.is_none() {
        Ok(None)
    } else {
        count(x).map(Some)
    }
}

/// A sequence of real numbers given as an argument (a list, a tuple or a 1-D NumPy array, each
/// item as [`real`] takes it), for `#[pyo3(from_py_with = …)]`; text, a dict or a scalar is an
/// `InputError` naming the value.
pub fn reals(x: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    use pyo3::types::{PyDict, PyString};
    let shown = x.repr().map_or_else(|_| "?".into(), |r| r.to_string());
    if x.is_instance_of::<PyString>() || x.is_instance_of::<PyDict>() {
        return Err(input_at(
            "",
            Some(shown.clone()),
            format!("must be a sequence of real numbers, not {shown}"),
            None,
        ));
    }
    let Ok(items) = x.try_iter() else {
        return Err(input_at(
            "",
            Some(shown.clone()),
            format!("must be a sequence of real numbers, not {shown}"),
            None,
        ));
    };
    let mut out = Vec::new();
    for item in items {
        out.push(real(&item?).map_err(|_| {
            input_at(
                "",
                Some(shown.clone()),
                format!("must be a sequence of real numbers, not {shown}"),
                None,
            )
        })?);
    }
    Ok(out)
}
