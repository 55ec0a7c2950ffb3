//! Models normalized into the unit cube, as [LZT §6] does before Tables 1-2: "all the models
//! ... are normalized in a 1.0 x 1.0 x 1.0 cube", so that edge lengths compare across models;
//! and models scaled uniformly, to test whether anything depends on the scale (Observation 3).

use super::ExperimentError;
use crate::TriMesh;
use glam::DVec3;

/// The mesh moved and scaled uniformly into `[0, 1]^3`: the minimum corner of the bounding box of
/// the vertices that faces use goes to the origin, and every coordinate is divided by the
/// largest side of that box, which becomes exactly 1. Faces, vertex order and vertices that no
/// face uses are kept (the latter are mapped by the same transformation).
///
/// # Errors
/// [`ExperimentError::NoExtent`] if all those vertices coincide; [`ExperimentError::Mesh`] if
/// the scaled coordinates overflow.
///
/// # Example
/// ```
/// use exact_geodesics::{experiments::normalize_to_unit_cube, TriMesh};
/// use glam::DVec3;
/// let mesh = TriMesh::new(
///     vec![[1.0, 1.0, 1.0], [5.0, 1.0, 1.0], [1.0, 3.0, 1.0]],
///     vec![[0, 1, 2]],
/// )?;
/// let unit = normalize_to_unit_cube(&mesh)?;
/// assert_eq!(unit.positions(), &[DVec3::ZERO, DVec3::X, DVec3::new(0.0, 0.5, 0.0)]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn normalize_to_unit_cube(mesh: &TriMesh) -> Result<TriMesh, ExperimentError> {
    let (lo, hi) = mesh.faces().iter().flatten().fold(
        (DVec3::INFINITY, DVec3::NEG_INFINITY),
        |(lo, hi), &v| {
            let p = mesh.positions()[v as usize];
            (lo.min(p), hi.max(p))
        },
    );
    let side = (hi - lo).max_element();
    if side == 0.0 {
        return Err(ExperimentError::NoExtent {
            point: lo.to_array(),
        });
    }
    let positions = mesh.positions().iter().map(|&p| (p - lo) / side).collect();
    Ok(TriMesh::new(positions, mesh.faces().to_vec())?)
}

/// The mesh with every coordinate multiplied by `factor` (rounded to the nearest `f64`, so the
/// scaled mesh is exact when `factor` is a power of two): the same surface in other units.
/// Faces and vertex order are kept.
///
/// # Errors
/// [`ExperimentError::Scale`] unless `factor` is finite and positive;
/// [`ExperimentError::Mesh`] if the scaled coordinates overflow.
///
/// # Example
/// ```
/// use exact_geodesics::{experiments::scale_uniformly, mesh::shapes};
/// let big = scale_uniformly(&shapes::cube(), 1e6)?;
/// assert_eq!(big.positions()[6], glam::DVec3::splat(1e6));
/// # Ok::<(), exact_geodesics::experiments::ExperimentError>(())
/// ```
pub fn scale_uniformly(mesh: &TriMesh, factor: f64) -> Result<TriMesh, ExperimentError> {
    if !(factor.is_finite() && factor > 0.0) {
        return Err(ExperimentError::Scale { factor });
    }
    let positions = mesh.positions().iter().map(|&p| p * factor).collect();
    Ok(TriMesh::new(positions, mesh.faces().to_vec())?)
}
