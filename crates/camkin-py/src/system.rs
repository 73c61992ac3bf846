//! `camkin.System`: a planar multibody system read from a system file, analysed over its first
//! driver's angle with the command's columns.

use crate::columns::{angles_from, Columns};
use crate::errors;
use crate::mech::TomlSource;
use camkin::spec::text::read_system;
use camkin::spec::{BuildOptions, BuiltSystem};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A planar multibody system: bodies, joints, drivers and contacts, as a system file describes
/// them (``[[body]]``, ``[[joint]]``, ``[[driver]]``, ``[[contact]]``; see the README). Every
/// contact is the paper's exact row. Build one with ``System.from_toml(path_or_text)``.
#[pyclass(frozen, module = "camkin", name = "System")]
#[derive(Debug, Clone)]
pub struct PySystem {
    built: BuiltSystem,
    name: String,
}

#[pymethods]
impl PySystem {
    /// System.from_toml(source, *, large=False) -> System
    ///
    /// A system from a system file (a path, ``str`` or ``os.PathLike``) or its TOML text. A
    /// cam-follower or gear-pair file is its mechanism as a system (bodies ``cam`` and
    /// ``follower``, one contact), analysed at cam angles: ``camkin analyze --system``. Bad
    /// input raises ``camkin.InputError`` naming the element, its key and the value, with the
    /// line and column (``.line``, ``.column``), as the command does.
    #[staticmethod]
    #[pyo3(signature = (source, *, large = false))]
    fn from_toml(py: Python<'_>, source: &Bound<'_, PyAny>, large: bool) -> PyResult<Self> {
        let s = TomlSource::read(py, source, "System.from_toml", "system")?;
        let options = BuildOptions {
            base_dir: s.base,
            si: false,
            confine: false,
            limits: crate::mech::limits(large),
        };
        let built = read_system(&s.text, &s.file, &options).map_err(errors::text)?;
        for w in &built.warnings {
            crate::mech::PyMechanism::warn(py, &format!("{}: {w}", s.file))?;
        }
        Ok(Self {
            built,
            name: s.name,
        })
    }

    /// The bodies' names, in the file's order.
    #[getter]
    fn bodies(&self) -> Vec<String> {
        self.built
            .system
            .bodies()
            .iter()
            .map(|b| b.name.clone())
            .collect()
    }

    /// The contacts' names, in the file's order.
    #[getter]
    fn contacts(&self) -> Vec<String> {
        self.built
            .system
            .contacts()
            .iter()
            .map(|c| c.name.clone())
            .collect()
    }

    /// analyze(angles_deg, *, strict=False, large=False) -> dict
    ///
    /// The system at its first driver's angles (degrees; a number or a 1-D array), swept in
    /// order, each instant warm-started from the last: a dict of NumPy arrays keyed by the
    /// columns of ``camkin analyze SYSTEM.toml`` — each body's ``x``, ``y``, ``angle`` and their
    /// rates and accelerations, each contact's point, gap, sliding rates, ``gamma`` and ``jump``,
    /// and ``error``. An instant that cannot be solved has NaN and its reason in ``error``;
    /// ``strict=True`` raises ``camkin.ContactError`` instead.
    #[pyo3(signature = (angles_deg, *, strict = false, large = false))]
    fn analyze<'py>(
        &self,
        py: Python<'py>,
        angles_deg: &Bound<'py, PyAny>,
        strict: bool,
        large: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (angles, scalar) = angles_from(py, angles_deg, "angles_deg")?;
        let sys = &self.built.system;
        let times = self.built.times(&angles).map_err(|e| match e {
            camkin::spec::SweepError::NeverReached { angle_deg } => errors::input(
                "angles_deg",
                Some(camkin::human::human(angle_deg)),
                e.to_string(),
            ),
            _ => errors::input("driver", None, e.to_string()),
        })?;
        errors::refuse_large(
            &camkin::work::Work::system(sys, angles.len()),
            large,
            ", or use fewer angles",
        )?;
        let (cols, first_error) = py.detach(|| -> PyResult<_> {
            // a system that cannot be analysed at its first instant (a loop that does not
            // close) is bad input, named by its element; the sweep starts there
            let mut instants = sys.instants(&times).map_err(|e| {
                errors::input(
                    "",
                    None,
                    format!(
                        "the system cannot be analysed at its first instant ({}°): {e}",
                        camkin::human::human(angles.first().copied().unwrap_or(0.0))
                    ),
                )
            })?;
            let mut cols = Columns::new(camkin::table::system_columns(&self.built), angles.len());
            let mut first_error = None;
            for (k, (&a, &t)) in angles.iter().zip(&times).enumerate() {
                if k % 4096 == 0 {
                    errors::interrupted()?;
                }
                let Some(s) = instants.next() else { break };
                if let Err(e) = &s {
                    first_error.get_or_insert((a, e.to_string()));
                }
                cols.push(camkin::table::system_cells(sys, a, t, &s));
            }
            Ok((cols, first_error))
        })?;
        if let (true, Some((a, e))) = (strict, &first_error) {
            return Err(errors::contact(format!(
                "at {} {}°: {e}",
                self.built.angle_name(),
                camkin::human::human(*a)
            )));
        }
        cols.into_dict(py, scalar)
    }

    fn __repr__(&self) -> String {
        let s = &self.built.system;
        format!(
            "<camkin.System {:?}: {} bodies, {} joints, {} drivers, {} contacts, lengths in {}>",
            self.name,
            s.bodies().len(),
            s.joints().len(),
            s.drivers().len(),
            s.contacts().len(),
            self.built.length_unit.name()
        )
    }
}
