//! Distance matrices from source points to target vertices (among selected vertices: the same
//! vertices as both): one propagation per source, stopped as soon as every target is final
//! ([`PropagateOptions::stop_points`](crate::PropagateOptions::stop_points)) or at a maximum
//! distance (radius-limited rows, kept sparse by [`SparseMatrix`]), sources run in parallel.
//!
//! Rows are handed to the caller's sink as they are done, each with its index, so that only
//! the propagations in flight (one per thread) and the rows waiting for the sink are in memory.
//! Row `i` holds the distances from `sources[i]` to every `targets[j]`: the very values a
//! single-source [`propagate`](crate::propagate) from `sources[i]` gives them. One-directional
//! results differ from their transposes in the last bits (the two propagations round
//! differently); [`DenseMatrix::symmetrize_min`] and [`SparseMatrix::symmetrize_min`] make a
//! matrix among selected vertices symmetric.
//!
//! # Example
//! ```
//! use exact_geodesics::matrix::{distance_matrix, DenseMatrix, MatrixOptions};
//! use exact_geodesics::{mesh::shapes, SurfacePoint, VertexId};
//! let cube = shapes::cube();
//! let corners = [VertexId(0), VertexId(1), VertexId(6)];
//! let sources = corners.map(SurfacePoint::Vertex);
//! let mut matrix = DenseMatrix::new(3, 3);
//! distance_matrix::<f64, _>(&cube, &sources, &corners, &MatrixOptions::default(), |row| {
//!     matrix.insert(&row)
//! })?;
//! matrix.symmetrize_min()?;
//! assert!((matrix.get(0, 1) - 1.0).abs() < 1e-12);
//! assert_eq!(matrix.get(0, 1), matrix.get(1, 0));
//! assert!((matrix.get(2, 0) - 5f64.sqrt()).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod collect;
mod run;

pub use collect::{DenseMatrix, SparseMatrix};
pub use run::distance_matrix;

use crate::mmp::{PointError, SurfacePoint};
use crate::VertexId;
use thiserror::Error;

/// Options of a distance matrix.
#[derive(Clone, Debug, Default, PartialEq)]
#[non_exhaustive]
pub struct MatrixOptions {
    /// Distances beyond this are `f64::INFINITY` (radius-limited rows), and each propagation
    /// stops there. `None`: no limit.
    pub max_distance: Option<f64>,
    /// Sources propagated at once, each on its own thread. `None`: one per core.
    pub threads: Option<usize>,
    /// The exact backend's precision cap of every propagation (see
    /// [`PropagateOptions::precision_cap`](crate::PropagateOptions::precision_cap)).
    pub precision_cap: Option<u32>,
}

impl MatrixOptions {
    /// Limits the rows to this distance.
    pub fn with_max_distance(mut self, d: f64) -> Self {
        self.max_distance = Some(d);
        self
    }

    /// Runs this many propagations at once (at least one).
    pub fn with_threads(mut self, threads: usize) -> Self {
        self.threads = Some(threads);
        self
    }

    /// Sets the exact backend's precision cap.
    pub fn with_precision_cap(mut self, bits: u32) -> Self {
        self.precision_cap = Some(bits);
        self
    }
}

/// One row of a distance matrix, as it is handed to the sink.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct MatrixRow {
    /// The row's index: its source is `sources[index]`.
    pub index: usize,
    /// The distance to each target, in their order (`f64::INFINITY` where unreachable or
    /// beyond the maximum distance).
    pub distances: Vec<f64>,
    /// Decisions of the propagation the backend left uncertified (0 for backends that do not
    /// certify).
    pub uncertified: u64,
    /// Wedges the propagation carried across a face (its events).
    pub wedges_propagated: u64,
}

impl MatrixRow {
    /// The finite entries of the row, as `(row, column, distance)`.
    pub fn finite_entries(&self) -> impl Iterator<Item = (u32, u32, f64)> + '_ {
        self.distances
            .iter()
            .enumerate()
            .filter(|(_, d)| d.is_finite())
            .map(|(j, &d)| (self.index as u32, j as u32, d))
    }
}

/// What does not fit the shape of a [`DenseMatrix`].
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum ShapeError {
    /// A row whose index or length does not fit.
    #[error("row {index} of {length} distances does not fit a {rows} by {columns} matrix")]
    Row {
        /// The row's index.
        index: usize,
        /// Its number of distances.
        length: usize,
        /// The matrix's number of rows.
        rows: usize,
        /// The matrix's number of columns.
        columns: usize,
    },
    /// Symmetrization of a matrix that is not square.
    #[error("a {rows} by {columns} matrix is not square")]
    NotSquare {
        /// The matrix's number of rows.
        rows: usize,
        /// The matrix's number of columns.
        columns: usize,
    },
}

/// Why a distance matrix could not be computed.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum MatrixError<E> {
    /// A source is not a point of the mesh.
    #[error("source {index}: {error}")]
    Source {
        /// Its position among the sources.
        index: usize,
        /// What is wrong with it.
        error: PointError,
    },
    /// A target is not a vertex of the mesh.
    #[error("target {index}: {error}")]
    Target {
        /// Its position among the targets.
        index: usize,
        /// What is wrong with it.
        error: PointError,
    },
    /// No source or no target was given.
    #[error("a matrix needs at least one source and one target")]
    Empty,
    /// Zero threads were asked for.
    #[error("the number of threads must be at least 1")]
    NoThreads,
    /// The thread pool could not be started.
    #[error("cannot start the threads: {0}")]
    Threads(String),
    /// The sink refused a row; the remaining propagations were abandoned.
    #[error("{0}")]
    Sink(E),
}

/// What a distance matrix run did, over all its rows.
#[derive(Clone, Debug, Default, PartialEq)]
#[non_exhaustive]
pub struct MatrixSummary {
    /// Rows computed.
    pub rows: usize,
    /// Rows whose propagation left decisions uncertified.
    pub uncertified_rows: usize,
    /// Wedges carried across a face, over all propagations.
    pub wedges_propagated: u64,
}

/// The sources and targets of a matrix, checked against the mesh.
fn validate<E>(
    mesh: &crate::TriMesh,
    sources: &[SurfacePoint],
    targets: &[VertexId],
) -> Result<(), MatrixError<E>> {
    if sources.is_empty() || targets.is_empty() {
        return Err(MatrixError::Empty);
    }
    for (index, source) in sources.iter().enumerate() {
        source
            .validated(mesh)
            .map_err(|error| MatrixError::Source { index, error })?;
    }
    for (index, &v) in targets.iter().enumerate() {
        SurfacePoint::Vertex(v)
            .validated(mesh)
            .map_err(|error| MatrixError::Target { index, error })?;
    }
    Ok(())
}
