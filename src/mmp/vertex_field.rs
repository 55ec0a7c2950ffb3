//! The distances of a propagation at the vertices only: continuous Dijkstra [SSK+05 §4] run
//! so that the wedges of an edge are given up once no later wedge can win a point of it
//! ([`WedgeLists::close`](super::wedge_lists::WedgeLists::close)). The vertices' distances
//! are those of a full run, bit for bit; a run then holds the wedges near its front, not the
//! whole subdivision of the edges, which is what a [`GeodesicField`] keeps for queries inside
//! faces and for tracing paths back.

use super::field::GeodesicField;
use super::propagate::{propagate_with_progress, Progress, PropagateOptions};
use super::source::{PointError, SurfacePoint};
use super::stats::Stats;
use crate::mesh::{SourceId, TriMesh, VertexId};
use crate::scalar::Scalar;

/// The geodesic distance of every vertex from the nearest of a set of sources, and which
/// source that is, without the distance field between the vertices.
///
/// # Example
/// ```
/// use exact_geodesics::{mesh::shapes, propagate_vertices, PropagateOptions, SurfacePoint, VertexId};
/// let cube = shapes::cube();
/// let field = propagate_vertices::<f64>(&cube, &[SurfacePoint::Vertex(VertexId(0))], &PropagateOptions::default())?;
/// assert!((field.vertex_distance(VertexId(6)) - 5f64.sqrt()).abs() < 1e-12);
/// # Ok::<(), exact_geodesics::PointError>(())
/// ```
#[derive(Clone, Debug)]
pub struct VertexField<'m, S: Scalar> {
    /// A field whose edges kept only the wedges they held when the run ended: only its
    /// vertex queries are offered.
    field: GeodesicField<'m, S>,
}

impl<'m, S: Scalar> VertexField<'m, S> {
    /// The mesh the distances live on.
    pub fn mesh(&self) -> &TriMesh {
        self.field.mesh()
    }

    /// The sources, validated and in canonical form, in the order given.
    pub fn sources(&self) -> &[SurfacePoint] {
        self.field.sources()
    }

    /// What happened during the propagation.
    pub fn stats(&self) -> &Stats {
        self.field.stats()
    }

    /// Whether the backend certified every decision of the propagation
    /// ([`GeodesicField::is_certified`]).
    pub fn is_certified(&self) -> bool {
        self.field.is_certified()
    }

    /// The geodesic distance of a vertex to its nearest source; `f64::INFINITY` if unreachable.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn vertex_distance(&self, v: VertexId) -> f64 {
        self.field.vertex_distance(v)
    }

    /// The distance of every vertex, in file order (`f64::INFINITY` where unreachable).
    pub fn vertex_distances(&self) -> Vec<f64> {
        self.field.vertex_distances()
    }

    /// A vertex's distance in the backend's own number type; `None` if unreachable.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn vertex_distance_exact(&self, v: VertexId) -> Option<S> {
        self.field.vertex_distance_exact(v)
    }

    /// Index (into [`sources`](Self::sources)) of the source nearest to a vertex.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn nearest_source(&self, v: VertexId) -> Option<SourceId> {
        self.field.nearest_source(v)
    }
}

/// The distances of the vertices from `sources`: [`propagate`](crate::propagate) with the
/// wedges of every edge given up once they are no longer needed, so that a run's memory is
/// that of its front. The distances are those of [`propagate`](crate::propagate), bit for bit.
///
/// # Errors
/// As [`propagate`](crate::propagate).
pub fn propagate_vertices<'m, S: Scalar>(
    mesh: &'m TriMesh,
    sources: &[SurfacePoint],
    options: &PropagateOptions,
) -> Result<VertexField<'m, S>, PointError> {
    propagate_vertices_with_progress(mesh, sources, options, |_| {})
}

/// [`propagate_vertices`], calling `progress` now and then with how far it got.
///
/// # Errors
/// As [`propagate`](crate::propagate).
pub fn propagate_vertices_with_progress<'m, S: Scalar>(
    mesh: &'m TriMesh,
    sources: &[SurfacePoint],
    options: &PropagateOptions,
    progress: impl FnMut(&Progress),
) -> Result<VertexField<'m, S>, PointError> {
    let options = PropagateOptions {
        vertices_only: true,
        ..options.clone()
    };
    let field = propagate_with_progress(mesh, sources, &options, progress)?;
    Ok(VertexField { field })
}

/// The geodesic distance of every vertex, in file order, from the nearest of `sources`
/// (`f64::INFINITY` where unreachable): [`propagate_vertices`] and
/// [`VertexField::vertex_distances`] in one call, for the common case.
///
/// # Errors
/// As [`propagate`](crate::propagate).
///
/// # Example
/// ```
/// use exact_geodesics::{geodesic_distances, mesh::shapes, PropagateOptions, SurfacePoint, VertexId};
/// let d = geodesic_distances::<f64>(&shapes::cube(), &[SurfacePoint::Vertex(VertexId(0))], &PropagateOptions::default())?;
/// assert!((d[6] - 5f64.sqrt()).abs() < 1e-12);
/// # Ok::<(), exact_geodesics::PointError>(())
/// ```
pub fn geodesic_distances<S: Scalar>(
    mesh: &TriMesh,
    sources: &[SurfacePoint],
    options: &PropagateOptions,
) -> Result<Vec<f64>, PointError> {
    Ok(propagate_vertices::<S>(mesh, sources, options)?.vertex_distances())
}
