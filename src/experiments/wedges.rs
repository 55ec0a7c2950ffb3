//! The number of final wedges w(e) on each edge, from one source, as a random variable over the
//! edges of a model [LZT §6, Table 1].

use super::{ExperimentError, Summary};
use crate::mmp::{Eq2Counts, Progress};
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
    /// The smallest fraction of the edges that holds half of all wedges (Observation 1
    /// [LZT §6]: wedges crowd on few edges when this is small); 0 without wedges.
    pub edges_holding_half: f64,
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
    Ok(measure::<S>(mesh, source, progress)?.counts)
}

/// What the experiments read of one propagation from a source vertex: w(e) and its summary,
/// the cases of eq. (2) met [LZT Property 1], and the vertex distances.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Measurement {
    /// w(e) summarized, as Table 1 reports it.
    pub counts: WedgeCounts,
    /// w(e) on every edge, indexed by `EdgeId` (the distribution behind `counts`).
    pub per_edge: Vec<usize>,
    /// How often eq. (2) had zero, one, two or infinitely many solutions.
    pub eq2: Eq2Counts,
    /// The distance of every vertex in the model's units (`f64::INFINITY` where unreachable).
    pub distances: Vec<f64>,
    /// Decisions the exact backend could not certify within its precision cap (always 0 in
    /// the float backends): where this is not 0, the run is not exact.
    pub uncertified: u64,
}

/// Propagates from `source` in the number type `S` and reads the [`Measurement`]; `progress`
/// is called as in [`propagate_with_progress`].
///
/// # Errors
/// [`ExperimentError::Source`] if `source` is not a vertex of `mesh`.
///
/// # Example
/// ```
/// use exact_geodesics::{experiments::measure, mesh::shapes, VertexId};
/// let m = measure::<f64>(&shapes::cube(), VertexId(0), |_| {})?;
/// assert_eq!(m.per_edge.iter().sum::<usize>(), m.counts.total);
/// assert_eq!(m.distances[0], 0.0);
/// # Ok::<(), exact_geodesics::experiments::ExperimentError>(())
/// ```
pub fn measure<S: Scalar>(
    mesh: &TriMesh,
    source: VertexId,
    progress: impl FnMut(&Progress),
) -> Result<Measurement, ExperimentError> {
    let field = propagate_with_progress::<S>(
        mesh,
        &[SurfacePoint::Vertex(source)],
        &PropagateOptions::default(),
        progress,
    )?;
    let per_edge = field.wedge_counts();
    let samples: Vec<f64> = per_edge.iter().map(|&c| c as f64).collect();
    Ok(Measurement {
        counts: WedgeCounts {
            source,
            per_edge: Summary::of(&samples).expect("a TriMesh has at least one face, so edges"),
            total: per_edge.iter().sum(),
            edges_without_wedges: per_edge.iter().filter(|&&c| c == 0).count(),
            edges_holding_half: share_holding_half(&per_edge),
            seconds: field.stats().propagation_seconds,
        },
        eq2: field.stats().eq2.clone(),
        distances: field.vertex_distances(),
        uncertified: field.stats().backend.uncertified,
        per_edge,
    })
}

/// The smallest fraction of `counts` (wedges per edge) whose sum is at least half the total:
/// the fullest edges first. 0 when there is no wedge.
///
/// # Example
/// ```
/// use exact_geodesics::experiments::share_holding_half;
/// // One edge of six holds 5 of the 10 wedges.
/// assert_eq!(share_holding_half(&[1, 5, 1, 1, 1, 1]), 1.0 / 6.0);
/// // Evenly spread: half the edges hold half the wedges.
/// assert_eq!(share_holding_half(&[2, 2, 2, 2]), 0.5);
/// assert_eq!(share_holding_half(&[0, 0]), 0.0);
/// ```
pub fn share_holding_half(counts: &[usize]) -> f64 {
    let total: usize = counts.iter().sum();
    if total == 0 {
        return 0.0;
    }
    let mut fullest = counts.to_vec();
    fullest.sort_unstable_by(|a, b| b.cmp(a));
    let mut held = 0;
    let edges = fullest
        .iter()
        .take_while(|&&c| {
            let before = held;
            held += c;
            2 * before < total
        })
        .count();
    edges as f64 / counts.len() as f64
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
    Ok(measure_in(backend, mesh, source, progress)?.counts)
}

/// [`measure`] in the backend named at run time (the exact backend with the precision cap set
/// by `scalar::exact::set_precision_cap`).
///
/// # Errors
/// As [`measure`].
pub fn measure_in(
    backend: Backend,
    mesh: &TriMesh,
    source: VertexId,
    progress: impl FnMut(&Progress),
) -> Result<Measurement, ExperimentError> {
    match backend {
        Backend::F64 => measure::<f64>(mesh, source, progress),
        Backend::Adaptive => measure::<Adaptive>(mesh, source, progress),
        Backend::Exact => measure::<Real>(mesh, source, progress),
    }
}
