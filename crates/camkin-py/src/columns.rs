//! Tables as columns of NumPy arrays: the library's cells (one definition of the columns and
//! their units, shared with the command) gathered by column.

use crate::errors;
use camkin::table::Cell;
use numpy::{PyArray1, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// One column's values.
#[derive(Debug)]
enum Column {
    /// numbers; absent values are NaN
    Num(Vec<f64>),
    /// flags (0/1 cells); absent values are false
    Flag(Vec<bool>),
    /// text or None, each distinct text kept once (`warm` repeats on every row of a sweep: a
    /// string per row would cost more than the float columns)
    Text(Texts),
}

/// A text column: each row's index into its distinct texts.
#[derive(Debug, Default)]
struct Texts {
    distinct: Vec<Option<String>>,
    index: std::collections::HashMap<Option<String>, u32>,
    rows: Vec<u32>,
}

impl Texts {
    fn with_capacity(n: usize) -> Self {
        Self {
            rows: Vec::with_capacity(n),
            ..Self::default()
        }
    }

    fn push(&mut self, t: Option<String>) {
        let k = match self.index.get(&t) {
            Some(&k) => k,
            None => {
                let k = self.distinct.len() as u32;
                self.distinct.push(t.clone());
                self.index.insert(t, k);
                k
            }
        };
        self.rows.push(k);
    }

    fn first(&self) -> Option<String> {
        self.rows
            .first()
            .and_then(|&k| self.distinct[k as usize].clone())
    }
}

/// A table gathered by column.
#[derive(Debug)]
pub struct Columns {
    names: Vec<String>,
    cols: Vec<Option<Column>>,
    capacity: usize,
}

impl Columns {
    pub fn new(names: Vec<String>, capacity: usize) -> Self {
        let cols = names.iter().map(|_| None).collect();
        Self {
            names,
            cols,
            capacity,
        }
    }

    /// Appends one row (cells in column order).
    pub fn push(&mut self, row: Vec<Cell>) {
        let cap = self.capacity;
        for (slot, cell) in self.cols.iter_mut().zip(row) {
            let col = slot.get_or_insert_with(|| match cell {
                Cell::Num(_) | Cell::Count(_) => Column::Num(Vec::with_capacity(cap)),
                Cell::Int(_) | Cell::Flag(_) => Column::Flag(Vec::with_capacity(cap)),
                Cell::Text(_) => Column::Text(Texts::with_capacity(cap)),
            });
            match (col, cell) {
                (Column::Num(v), Cell::Num(x)) => v.push(x.unwrap_or(f64::NAN)),
                (Column::Num(v), Cell::Count(x)) => v.push(x.map_or(f64::NAN, f64::from)),
                (Column::Flag(v), Cell::Int(x)) => v.push(x.is_some_and(|x| x != 0)),
                (Column::Flag(v), Cell::Flag(x)) => v.push(x.unwrap_or(false)),
                (Column::Text(v), Cell::Text(x)) => v.push(x),
                // a column's cells are of one kind (the library's definition)
                (Column::Num(v), _) => v.push(f64::NAN),
                (Column::Flag(v), _) => v.push(false),
                (Column::Text(v), _) => v.push(None),
            }
        }
    }

    /// The table as a dict: name → 1-D array (float64, bool, or object for text); with
    /// `scalar`, name → the one row's value.
    pub fn into_dict(self, py: Python<'_>, scalar: bool) -> PyResult<Bound<'_, PyDict>> {
        let d = PyDict::new(py);
        let np = py.import("numpy")?;
        for (name, col) in self.names.into_iter().zip(self.cols) {
            let col = col.unwrap_or(Column::Num(Vec::new()));
            if scalar {
                match col {
                    Column::Num(v) => d.set_item(name, v.first().copied().unwrap_or(f64::NAN))?,
                    Column::Flag(v) => d.set_item(name, v.first().copied().unwrap_or(false))?,
                    Column::Text(v) => d.set_item(name, v.first())?,
                }
                continue;
            }
            match col {
                Column::Num(v) => d.set_item(name, PyArray1::from_vec(py, v))?,
                Column::Flag(v) => d.set_item(name, PyArray1::from_vec(py, v))?,
                Column::Text(v) => {
                    let kwargs = PyDict::new(py);
                    kwargs.set_item("dtype", np.getattr("object_")?)?;
                    // one Python string per distinct text
                    let objs: Vec<Py<PyAny>> = v
                        .distinct
                        .iter()
                        .map(|t| match t {
                            None => py.None(),
                            Some(t) => pyo3::types::PyString::new(py, t).into_any().unbind(),
                        })
                        .collect();
                    let list = pyo3::types::PyList::new(
                        py,
                        v.rows.iter().map(|&k| objs[k as usize].clone_ref(py)),
                    )?;
                    d.set_item(name, np.call_method("array", (list,), Some(&kwargs))?)?
                }
            }
        }
        crate::columns::result(d)
    }
}

/// Angles from a number or a 1-D array-like (converted to float64): `(angles, was a number)`.
/// Non-finite angles are refused, naming the index.
pub fn angles_from(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    field: &str,
) -> PyResult<(Vec<f64>, bool)> {
    let np = py.import("numpy")?;
    let not_numbers = |why: String| {
        errors::input(
            field,
            x.repr().ok().map(|r| r.to_string()),
            format!("{field}: not a real number or an array of real numbers ({why})"),
        )
    };
    // the array as given first: only integers and reals are angles (a complex number would
    // lose its imaginary part, a string "45" would be read as a number, a bool as 0 or 1)
    let raw = np
        .call_method1("asarray", (x,))
        .map_err(|e| not_numbers(e.to_string()))?;
    let kind: String = raw.getattr("dtype")?.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "i" | "u" | "f") {
        let what = match kind.as_str() {
            "c" => "complex numbers",
            "U" | "S" => "text",
            "b" => "booleans",
            _ => "values of mixed or other types",
        };
        return Err(not_numbers(format!("{what} given")));
    }
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", np.getattr("float64")?)?;
    let arr = np
        .call_method("asarray", (raw,), Some(&kwargs))
        .map_err(|e| not_numbers(e.to_string()))?;
    let ndim: usize = arr.getattr("ndim")?.extract()?;
    if ndim > 1 {
        let shape: Vec<usize> = arr.getattr("shape")?.extract()?;
        return Err(errors::input(
            field,
            Some(format!("an array of shape {shape:?}")),
            format!("{field}: a number or a 1-D array is needed, not an array of shape {shape:?}"),
        ));
    }
    let flat = np.call_method1("ravel", (arr,))?;
    let flat = np.call_method1("ascontiguousarray", (flat,))?;
    let a = flat.cast_into::<PyArray1<f64>>()?;
    let ro = a.readonly();
    let v: Vec<f64> = ro.as_slice()?.to_vec();
    debug_assert_eq!(v.len(), a.len());
    if let Some((k, x)) = v.iter().enumerate().find(|(_, x)| !x.is_finite()) {
        return Err(errors::input(
            field,
            Some(format!("{x}")),
            format!("{field}[{k}] = {x}: angles must be finite"),
        ));
    }
    Ok((v, ndim == 0))
}

/// A result dict as `camkin.Result` (a dict with `to_pandas()`; nested dicts too).
pub fn result<'py>(d: Bound<'py, PyDict>) -> PyResult<Bound<'py, PyDict>> {
    let py = d.py();
    let r = py
        .import("camkin.results")?
        .getattr("Result")?
        .call1((d,))?;
    Ok(r.cast_into::<PyDict>()?)
}
