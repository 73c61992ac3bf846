//! A Python dict read as a mechanism's spec: walked into a TOML value tree (which, unlike JSON,
//! holds a NaN or an infinity, so the spec's validation names the field that has one) and
//! deserialised by the library's reader. Only what a mechanism file can hold is taken: dicts
//! with string keys, lists and tuples (a NumPy array through `tolist()`), strings, booleans,
//! integers and real numbers; a key whose value is `None` is left out, as if absent.

use crate::errors;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use toml::Value;

/// How deep a dict may nest (a mechanism's spec nests five levels).
const MAX_DEPTH: usize = 32;

/// `x` as a TOML value; `path` names it in errors (`cam.profile.points[2]`).
pub fn to_value(x: &Bound<'_, PyAny>, path: &str, depth: usize) -> PyResult<Value> {
    let bad = |why: &str| {
        errors::input(
            path,
            x.repr().ok().map(|r| r.to_string()),
            format!("{}: {why}", if path.is_empty() { "the dict" } else { path }),
        )
    };
    if depth > MAX_DEPTH {
        return Err(bad("nested too deeply for a mechanism"));
    }
    if x.is_instance_of::<PyBool>() {
        return Ok(Value::Boolean(x.extract()?));
    }
    if x.is_instance_of::<PyInt>() {
        return match x.extract::<i64>() {
            Ok(i) => Ok(Value::Integer(i)),
            Err(_) => Err(bad("an integer too large for a mechanism")),
        };
    }
    if x.is_instance_of::<PyFloat>() {
        return Ok(Value::Float(x.extract()?));
    }
    if x.is_instance_of::<PyString>() {
        return Ok(Value::String(x.extract()?));
    }
    if let Ok(d) = x.cast::<PyDict>() {
        let mut t = toml::map::Map::new();
        for (k, v) in d.iter() {
            let Ok(key) = k.extract::<String>() else {
                return Err(bad(&format!(
                    "its keys must be strings, not {}",
                    k.repr().map_or_else(|_| "?".into(), |r| r.to_string())
                )));
            };
            if v.is_none() {
                continue;
            }
            let inner = if path.is_empty() {
                key.clone()
            } else {
                format!("{path}.{key}")
            };
            t.insert(key, to_value(&v, &inner, depth + 1)?);
        }
        return Ok(Value::Table(t));
    }
    if x.is_instance_of::<PyList>() || x.is_instance_of::<PyTuple>() {
        let mut a = Vec::new();
        for (i, v) in x.try_iter()?.enumerate() {
            let v = v?;
            let inner = format!("{path}[{i}]");
            if v.is_none() {
                return Err(errors::input(
                    &inner,
                    Some("None".into()),
                    format!("{inner}: None is not a value"),
                ));
            }
            a.push(to_value(&v, &inner, depth + 1)?);
        }
        return Ok(Value::Array(a));
    }
    // NumPy: an array through `tolist()`, a scalar through `item()` (both give Python's own
    // types, which the cases above take or refuse)
    if errors::is_numpy(x) {
        let method = if x.hasattr("ndim")? && x.getattr("ndim")?.extract::<usize>()? > 0 {
            "tolist"
        } else {
            "item"
        };
        let plain = x.call_method0(method)?;
        if !plain.get_type().is(x.get_type()) {
            return to_value(&plain, path, depth + 1);
        }
    }
    Err(bad(&format!(
        "a {} is not a value a mechanism holds (a number, a string, a list or a dict)",
        x.get_type()
            .name()
            .map_or_else(|_| "?".into(), |n| n.to_string())
    )))
}
