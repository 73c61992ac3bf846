//! A spline profile's nodes replaced (`Mechanism.with_nodes`, `spline_variants`): the spec with
//! its profile's points swapped, refused on a profile that has no nodes.

use crate::errors;
use camkin::spec::MechanismSpec;
use numpy::ndarray::ArrayView2;
use pyo3::prelude::*;

/// Refuses a spec whose profile has no nodes to replace.
pub fn check_spline_kind(spec: &MechanismSpec) -> PyResult<()> {
    let kind = spec.cam.profile.kind.as_str();
    if kind != "spline" && kind != "points-file" {
        return Err(errors::input(
            "cam.profile.kind",
            Some(kind.into()),
            format!("cam.profile.kind = {kind:?}: nodes can only be replaced on a spline profile (\"spline\" or \"points-file\")"),
        ));
    }
    Ok(())
}

/// The spec with its profile's nodes replaced by `points` (a points file becomes inline points).
pub fn with_points(spec: &MechanismSpec, points: Vec<[f64; 2]>) -> MechanismSpec {
    let mut s = spec.clone();
    s.cam.profile.kind = "spline".into();
    s.cam.profile.path = None;
    s.cam.profile.points = Some(points);
    s
}

/// The spec with its spline profile's nodes replaced by an (N, 2) array.
pub fn spec_with_nodes(
    spec: &MechanismSpec,
    points: ArrayView2<'_, f64>,
) -> PyResult<MechanismSpec> {
    check_spline_kind(spec)?;
    if points.ncols() != 2 {
        return Err(errors::input(
            "points",
            Some(format!("an array of shape {:?}", points.shape())),
            format!(
                "points: an (N, 2) array is needed, not one of shape {:?}",
                points.shape()
            ),
        ));
    }
    Ok(with_points(
        spec,
        points.rows().into_iter().map(|r| [r[0], r[1]]).collect(),
    ))
}
