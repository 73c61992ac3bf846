//! Every contact of a cam-follower or a gear pair from Python: `Mechanism.contacts` (the columns
//! of `camkin contacts`) and `Mechanism.mesh` (a gear pair read as gears, `camkin mesh`).

use crate::columns::{angles_from, Columns};
use crate::errors;
use crate::model::{raise_first, PyMechanism};
use camkin::table::Units;
use pyo3::prelude::*;
use pyo3::types::PyDict;

#[pymethods]
impl PyMechanism {
    /// contacts(angles_deg, *, contiguous=None, strict=False, large=False) -> dict
    ///
    /// Every contact between cam and follower at each cam angle (degrees; a number or a 1-D
    /// array): the follower's first touch (``contact`` 0) and each other place its curve touches
    /// the cam at that position (a second tooth pair, a gear's back flank without backlash, a
    /// roller bridging a notch). One row per contact, as a dict of NumPy arrays keyed by the
    /// columns of ``camkin contacts`` (``angle_deg`` repeats for each contact at an angle): the
    /// point, normal, gap, normal velocity, sliding rates, normal accelerations and the
    /// acceleration constraint row ``row_cam·θ̈ + row_follower·q̈ = gamma`` with its
    /// ``residual`` at the follower's motion. An angle that could not be analysed has one row
    /// with NaN and its reason in ``error``; ``strict=True`` raises ``camkin.ContactError``.
    ///
    /// Example::
    ///
    ///     gears = camkin.Mechanism.from_toml("examples/gear-pair-20-42.toml")
    ///     c = gears.contacts([0.0, 4.0, 8.0])       # driver angles, degrees
    ///     c["contact"], c["gamma_mm_s2"]
    #[pyo3(signature = (angles_deg, *, contiguous = None, strict = false, large = false))]
    fn contacts<'py>(
        &self,
        py: Python<'py>,
        angles_deg: &Bound<'py, PyAny>,
        contiguous: Option<bool>,
        strict: bool,
        large: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (angles, _) = angles_from(py, angles_deg, "angles_deg")?;
        self.check_work(angles.len(), large)?;
        errors::refuse_large(
            &camkin::work::Work::contacts(self.mech(), angles.len()),
            large,
            ", or use fewer angles",
        )?;
        let contiguous = contiguous.unwrap_or_else(|| angles.windows(2).all(|w| w[1] > w[0]));
        let mech = self.mech();
        let units = Units::plain(mech, self.built.length_unit);
        let (cols, first_error) = py.detach(|| -> PyResult<_> {
            let mut cols = Columns::new(camkin::table::contact_columns(&units), angles.len());
            let mut first_error = None;
            for (k, (&a, state)) in angles
                .iter()
                .zip(mech.analyze_deg_each(&angles, contiguous))
                .enumerate()
            {
                if k % 4096 == 0 {
                    errors::interrupted()?;
                }
                let found = state.and_then(|s| mech.contacts_at(&s));
                for r in camkin::table::ContactRow::of(a, &found) {
                    if first_error.is_none() {
                        if let Some(e) = &r.error {
                            first_error = Some((a, e.clone()));
                        }
                    }
                    cols.push(camkin::table::contact_cells(&r, &units));
                }
            }
            Ok((cols, first_error))
        })?;
        if strict {
            raise_first(first_error, "cam")?;
        }
        cols.into_dict(py, false)
    }

    /// mesh(angles_deg, *, contiguous=None, strict=False, large=False) -> dict
    ///
    /// A gear pair (the cam's profile and the rotating follower's both ``involute-gear``) read as
    /// gears at each driver angle (degrees; a number or a 1-D array): the columns of ``camkin
    /// mesh`` as NumPy arrays (``driven_angle_deg``, ``speed_ratio``,
    /// ``transmission_error_urad`` and its rates, ``driver_tooth``, ``pairs_in_contact``,
    /// ``line_of_action_mm``, ``sliding_velocity_mm_s``, ``specific_sliding_driver``, …; for a
    /// number, a dict of numbers), ``found`` = ``"jump"`` where another tooth pair takes over.
    /// Not a gear pair: ``camkin.InputError``. A row that could not be computed has NaN and its
    /// reason in ``error``; ``strict=True`` raises ``camkin.ContactError``.
    ///
    /// Example::
    ///
    ///     gears = camkin.Mechanism.from_toml("examples/gear-pair-20-42.toml")
    ///     m = gears.mesh(np.arange(0.0, 18.0, 0.25))  # driver angles, degrees
    ///     m.to_pandas().describe()
    #[pyo3(signature = (angles_deg, *, contiguous = None, strict = false, large = false))]
    fn mesh<'py>(
        &self,
        py: Python<'py>,
        angles_deg: &Bound<'py, PyAny>,
        contiguous: Option<bool>,
        strict: bool,
        large: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let mech = self.mech();
        let pair = camkin::gears::GearPair::new(mech).map_err(|e| {
            use camkin::gears::GearError;
            let field = match e {
                GearError::DriverNotGear => "cam.profile.kind",
                GearError::TooClose { .. }
                | GearError::Interference { .. }
                | GearError::NoMesh { .. } => "follower.pivot",
                GearError::BasePitch { .. } => "follower.profile.module",
                _ => "follower.profile.kind",
            };
            errors::input(field, None, format!("not a gear pair: {e}"))
        })?;
        let (angles, scalar) = angles_from(py, angles_deg, "angles_deg")?;
        self.check_work(angles.len(), large)?;
        let contiguous = contiguous.unwrap_or_else(|| angles.windows(2).all(|w| w[1] > w[0]));
        let units = Units::plain(mech, self.built.length_unit);
        let (cols, first_error) = py.detach(|| {
            let results = mech.analyze_deg_each(&angles, contiguous);
            let jumps = camkin::table::contact_jumps(mech, &results, contiguous);
            let mut cols = Columns::new(camkin::table::mesh_columns(&units), angles.len());
            let mut first_error = None;
            for ((&a, r), &j) in angles.iter().zip(&results).zip(&jumps) {
                let row = camkin::table::MeshRow::new(&pair, mech, a, r, j);
                if first_error.is_none() {
                    if let Some(e) = &row.error {
                        first_error = Some((a, e.clone()));
                    }
                }
                cols.push(camkin::table::mesh_cells(&row));
            }
            (cols, first_error)
        });
        if strict {
            raise_first(first_error, "driver")?;
        }
        cols.into_dict(py, scalar)
    }
}
