//! The number of final wedges w(e) on each edge, from one source, as a random variable over the
//! edges of a model [LZT §6, Table 1].

use super::{ExperimentError, Summary};
use crate::mmp::Progress;
use crate::scalar::{Adaptive, Backend, Real};
use crate::{propagate_with_progress, PropagateOptions, Scalar, SurfacePoint, TriMesh, VertexId};
use serde::Serialize;

/// w(e) over every edge of the model, from one source vertex, and the propagation time.
///
/// Every edge counts, as in the paper's per-edge statistics: an edge that holds no final wedge
/// (one no geodesic from the source crosses, e.g. in another component) is a sample `w(e) = 0`;
/// `edges_without_wedges` says how many there are.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WedgeCounts {
    /// The source vertex.
    pub source: VertexId,
    /// w(e) over all edges.
    pub per_edge: Summary,
    /// Sum of w(e): all final wedges.
    pub total: usize,
    /// Edges with w(e) = 0.
    pub edges_without_wedges: usize,
    /// Wall-clock seconds of the propagation (`Stats::propagation_seconds`).
    pub seconds: f64,
}

/// Propagates from `source` in the number type `S` and counts the final wedges on every edge
/// (`GeodesicField::wedge_counts`); `progress` is called as in [`propagate_with_progress`].
///
/// # Errors
/// [`ExperimentError::Source`] if `source` is not a vertex of `mesh`.
///
/// # Example
/// ```
/// use exact_geodesics::{experiments::count_wedges, mesh::shapes, VertexId};
/// let counts = count_wedges::<f64>(&shapes::cube(), VertexId(0), |_| {})?;
/// assert_eq!(counts.per_edge.count, 18);
/// assert_eq!(counts.edges_without_wedges, 0);
/// # Ok::<(), exact_geodesics::experiments::ExperimentError>(())
/// ```
pub fn count_wedges<S: Scalar>(
    mesh: &TriMesh,
    source: VertexId,
    progress: impl FnMut(&Progress),
) -> Result<WedgeCounts, ExperimentError> {
    let field = propagate_with_progress::<S>(
        mesh,
        &[SurfacePoint::Vertex(source)],
        &PropagateOptions::default(),
        progress,
    )?;
    let counts = field.wedge_counts();
    let samples: Vec<f64> = counts.iter().map(|&c| c as f64).collect();
    Ok(WedgeCounts {
        source,
        per_edge: Summary::of(&samples).expect("a TriMesh has at least one face, so edges"),
        total: counts.iter().sum(),
        edges_without_wedges: counts.iter().filter(|&&c| c == 0).count(),
        seconds: field.stats().propagation_seconds,
    })
}

/// [`count_wedges`] in the backend named at run time. The exact backend uses the precision cap
/// set by `scalar::exact::set_precision_cap`.
///
/// # Errors
/// As [`count_wedges`].
///
/// # Example
/// ```
/// use exact_geodesics::{experiments::count_wedges_in, mesh::shapes, scalar::Backend, VertexId};
/// let cube = shapes::cube();
/// let f = count_wedges_in(Backend::F64, &cube, VertexId(0), |_| {})?;
/// let a = count_wedges_in(Backend::Adaptive, &cube, VertexId(0), |_| {})?;
/// assert_eq!(f.total, a.total);
/// # Ok::<(), exact_geodesics::experiments::ExperimentError>(())
/// ```
pub fn count_wedges_in(
    backend: Backend,
    mesh: &TriMesh,
    source: VertexId,
    progress: impl FnMut(&Progress),
) -> Result<WedgeCounts, ExperimentError> {
    match backend {
        Backend::F64 => count_wedges::<f64>(mesh, source, progress),
        Backend::Adaptive => count_wedges::<Adaptive>(mesh, source, progress),
        Backend::Exact => count_wedges::<Real>(mesh, source, progress),
    }
}
