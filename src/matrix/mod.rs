//! Distance matrices among selected vertices: one propagation per source, stopped as soon as
//! every selected vertex is final ([`PropagateOptions::stop_points`]) or at a maximum distance
//! (radius-limited rows, kept sparse by [`SparseMatrix`]), sources run in parallel.
//!
//! Rows are handed to the caller's sink as they are done, each with its index, so that only
//! the propagations in flight (one per thread) and the rows waiting for the sink are in memory.
//! Row `i` holds the distances from `vertices[i]` to every `vertices[j]`: the very values a
//! single-source [`propagate`](crate::propagate) from `vertices[i]` gives them. One-directional
//! results differ from their transposes in the last bits (the two propagations round
//! differently); [`DenseMatrix::symmetrize_min`] and [`SparseMatrix::symmetrize_min`] make them
//! symmetric.
//!
//! # Example
//! ```
//! use exact_geodesics::matrix::{distance_matrix, DenseMatrix, MatrixOptions};
//! use exact_geodesics::{mesh::shapes, VertexId};
//! let cube = shapes::cube();
//! let corners = [VertexId(0), VertexId(1), VertexId(6)];
//! let mut matrix = DenseMatrix::new(corners.len());
//! distance_matrix::<f64, _>(&cube, &corners, &MatrixOptions::default(), |row| {
//!     matrix.insert(&row)
//! })?;
//! matrix.symmetrize_min();
//! assert!((matrix.get(0, 1) - 1.0).abs() < 1e-12);
//! assert_eq!(matrix.get(0, 1), matrix.get(1, 0));
//! assert!((matrix.get(2, 0) - 5f64.sqrt()).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod collect;
mod run;

pub use collect::{DenseMatrix, SparseMatrix};
pub use run::distance_matrix;

use crate::mmp::PointError;
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
    /// The row's index: its source is `vertices[index]`.
    pub index: usize,
    /// The distance to each selected vertex, in their order (`f64::INFINITY` where unreachable
    /// or beyond the maximum distance).
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

/// A row that does not fit a [`DenseMatrix`].
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error("row {index} of {length} distances does not fit a {size} by {size} matrix")]
pub struct RowSizeError {
    /// The row's index.
    pub index: usize,
    /// Its number of distances.
    pub length: usize,
    /// The matrix's number of rows and columns.
    pub size: usize,
}

/// Why a distance matrix could not be computed.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum MatrixError<E> {
    /// A selected vertex is not a vertex of the mesh.
    #[error("selected vertex {index}: {error}")]
    Vertex {
        /// Its position in the selection.
        index: usize,
        /// What is wrong with it.
        error: PointError,
    },
    /// No vertex was selected.
    #[error("no vertex selected")]
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

/// The vertices selected for a matrix, checked against the mesh.
fn validate<E>(mesh: &crate::TriMesh, vertices: &[VertexId]) -> Result<(), MatrixError<E>> {
    if vertices.is_empty() {
        return Err(MatrixError::Empty);
    }
    for (index, &v) in vertices.iter().enumerate() {
        crate::SurfacePoint::Vertex(v)
            .validated(mesh)
            .map_err(|error| MatrixError::Vertex { index, error })?;
    }
    Ok(())
}
