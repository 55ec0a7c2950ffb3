//! Why an experiment of [LZT §6] cannot run on a model.

use crate::mesh::MeshError;
use crate::mmp::PointError;
use thiserror::Error;

/// Why a model cannot be normalized or measured.
#[derive(Debug, Error)]
pub enum ExperimentError {
    /// Every vertex that a face uses is at the same point: there is no cube to scale into.
    #[error("the mesh has no extent: every vertex of a face is at {point:?}")]
    NoExtent {
        /// The one point.
        point: [f64; 3],
    },
    /// The normalized coordinates do not make a valid mesh (an extent so small that scaling
    /// overflows).
    #[error("the normalized mesh is invalid: {0}")]
    Mesh(#[from] MeshError),
    /// The source is not a vertex of the mesh.
    #[error("bad source: {0}")]
    Source(#[from] PointError),
}
