//! Why an experiment of [LZT §6] cannot run on a model.

use crate::mesh::MeshError;
use crate::mmp::PointError;
use thiserror::Error;

/// Why a model cannot be normalized or measured.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum ExperimentError {
    /// Every vertex that a face uses is at the same point: there is no cube to scale into.
    #[error("the mesh has no extent: every vertex of a face is at {point:?}")]
    NoExtent {
        /// The one point.
        point: [f64; 3],
    },
    /// A scale factor that is not a finite positive number.
    #[error("the scale factor {factor} is not finite and positive")]
    Scale {
        /// The factor given.
        factor: f64,
    },
    /// The normalized or scaled coordinates do not make a valid mesh (they overflow).
    #[error("the normalized or scaled mesh is invalid: {0}")]
    Mesh(#[from] MeshError),
    /// The source is not a vertex of the mesh.
    #[error("bad source: {0}")]
    Source(#[from] PointError),
}
