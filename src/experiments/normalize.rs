//! Models normalized into the unit cube, as [LZT §6] does before Tables 1-2: "all the models
//! ... are normalized in a 1.0 x 1.0 x 1.0 cube", so that edge lengths compare across models;
//! and models scaled uniformly, to test whether anything depends on the scale (Observation 3).

use super::ExperimentError;
use crate::TriMesh;

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
/// let mesh = TriMesh::new(
///     vec![[1.0, 1.0, 1.0], [5.0, 1.0, 1.0], [1.0, 3.0, 1.0]],
///     vec![[0, 1, 2]],
/// )?;
/// let unit = normalize_to_unit_cube(&mesh)?;
/// assert_eq!(unit.positions(), &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.5, 0.0]]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn normalize_to_unit_cube(mesh: &TriMesh) -> Result<TriMesh, ExperimentError> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for &v in mesh.faces().iter().flatten() {
        let p = mesh.positions()[v as usize];
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let side = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
    if side == 0.0 {
        return Err(ExperimentError::NoExtent { point: lo });
    }
    let positions = mesh
        .positions()
        .iter()
        .map(|p| std::array::from_fn(|k| (p[k] - lo[k]) / side))
        .collect();
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
/// assert_eq!(big.positions()[6], [1e6, 1e6, 1e6]);
/// # Ok::<(), exact_geodesics::experiments::ExperimentError>(())
/// ```
pub fn scale_uniformly(mesh: &TriMesh, factor: f64) -> Result<TriMesh, ExperimentError> {
    if !(factor.is_finite() && factor > 0.0) {
        return Err(ExperimentError::Scale { factor });
    }
    let positions = mesh
        .positions()
        .iter()
        .map(|p| p.map(|c| c * factor))
        .collect();
    Ok(TriMesh::new(positions, mesh.faces().to_vec())?)
}
