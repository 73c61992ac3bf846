//! `Mechanism.analyze` and `System.analyze`: the command's `analyze` columns as arrays, at cam
//! angles or at a system's first driver's angles.

use crate::columns::{angles_from, Columns};
use crate::errors;
use crate::model::{raise_first, PyMechanism, PySystem, CHUNK};
use camkin::table::AnalysisSweep;
use pyo3::prelude::*;
use pyo3::types::PyDict;

#[pymethods]
impl PyMechanism {
    /// analyze(angles_deg, *, per="s", angle_unit="deg", contiguous=None, strict=False,
    /// large=False) -> dict
    ///
    /// The follower's motion and the contact at each cam angle (degrees; a number or a 1-D
    /// array), by the exact contact method, warm-started from angle to angle, with the GIL
    /// released. Returns a dict of NumPy arrays keyed by the columns of ``camkin analyze``, each
    /// name carrying its unit (``position_mm``, ``acceleration_mm_s2``, ``pressure_angle_deg``,
    /// …); for a number, a dict of numbers. A row that could not be computed has NaN in every
    /// number column and its reason in ``error`` (``None`` elsewhere); ``strict=True`` raises
    /// ``camkin.ContactError`` instead. ``per="deg"`` gives derivatives per degree of cam angle;
    /// ``angle_unit`` is an arm's. ``contiguous`` (default: the angles increase) says the angles
    /// trace the motion, so that a contact jump between rows is marked ``jump`` in ``found``.
    ///
    /// Example::
    ///
    ///     r = camkin.paper_cam().analyze(np.arange(0.0, 360.0, 0.5))
    ///     r["acceleration_cm_s2"].max()             # cm/s²
    ///     r.to_pandas().head()
    #[pyo3(signature = (angles_deg, *, per = "s", angle_unit = "deg", contiguous = None, strict = false, large = false))]
    #[allow(clippy::too_many_arguments)]
    fn analyze<'py>(
        &self,
        py: Python<'py>,
        angles_deg: &Bound<'py, PyAny>,
        per: &str,
        angle_unit: &str,
        contiguous: Option<bool>,
        strict: bool,
        large: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let units = self.units(per, angle_unit)?;
        let (angles, scalar) = angles_from(py, angles_deg, "angles_deg")?;
        self.check_work(angles.len(), large)?;
        let contiguous = contiguous.unwrap_or_else(|| angles.windows(2).all(|w| w[1] > w[0]));
        let mech = self.mech();
        let parts = &self.parts;
        let (cols, jumps, jump_at, first_error) = py.detach(|| -> PyResult<_> {
            let (travel, stretches) = parts
                .get_or_init(|| (mech.travel(), mech.unfollowable_stretches()))
                .clone();
            let names = camkin::table::analysis_columns(&units);
            let mut cols = Columns::new(names, angles.len());
            let mut rows =
                AnalysisSweep::with_parts(mech, &angles, contiguous, CHUNK, travel, stretches);
            let mut first_error = None;
            for chunk in rows.by_ref() {
                errors::interrupted()?;
                for r in &chunk {
                    if first_error.is_none() {
                        if let Some(e) = &r.error {
                            first_error = Some((r.angle_deg, e.clone()));
                        }
                    }
                    cols.push(camkin::table::analysis_cells(r, &units));
                }
            }
            Ok((cols, rows.jumps(), rows.jump_at().to_vec(), first_error))
        })?;
        if strict {
            raise_first(first_error, "cam")?;
        }
        if jumps > 0 {
            let at: Vec<String> = jump_at
                .iter()
                .take(5)
                .map(|&k| format!("{}°", camkin::human::human(angles[k])))
                .collect();
            Self::warn(
                py,
                &format!(
                    "the contact jumps at {jumps} of the angles (at {}{}; rows marked \"jump\" in found): {}",
                    at.join(", "),
                    if jumps > at.len() { ", …" } else { "" },
                    if camkin::gears::GearPair::new(self.mech()).is_ok() {
                        "the next tooth pair takes over the first contact there (camkin mesh gives the transmission error at the handovers)"
                    } else {
                        "the follower's first touch moves to another part of the profile, and its acceleration is impulsive there"
                    }
                ),
                Some("angles_deg"),
            )?;
        }
        cols.into_dict(py, scalar)
    }
}

#[pymethods]
impl PySystem {
    /// analyze(angles_deg, *, strict=False, large=False) -> dict
    ///
    /// The system at its first driver's angles (degrees; a number or a 1-D array), swept in
    /// order, each instant warm-started from the last: a dict of NumPy arrays keyed by the
    /// columns of ``camkin analyze SYSTEM.toml`` — each body's ``x``, ``y``, ``angle`` and their
    /// rates and accelerations, each contact's point, gap, sliding rates, ``gamma`` and ``jump``,
    /// and ``error``. An instant that cannot be solved has NaN and its reason in ``error``;
    /// ``strict=True`` raises ``camkin.ContactError`` instead.
    ///
    /// Example::
    ///
    ///     s = camkin.System.from_toml("examples/cam-four-bar.toml")
    ///     r = s.analyze(np.arange(0.0, 360.0, 1.0))  # the first driver's angle, degrees
    ///     r.to_pandas().iloc[:, :6]
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
            _ => errors::input("driver", None, self.built.explain_sweep(&e)),
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
                        "the system cannot be analysed at its first instant ({}°): {}",
                        camkin::human::human(angles.first().copied().unwrap_or(0.0)),
                        self.built.explain(&e)
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
}
