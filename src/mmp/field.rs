//! The result of a propagation: the final wedges on every edge and the vertex distances.

use super::edge_wedges::EdgeWedges;
use super::front::VertexDistance;
use super::source::SurfacePoint;
use super::stats::Stats;
use super::unfold::Unfolding;
use super::wedge::Wedge;
use crate::mesh::{EdgeId, MeshHandle, SourceId, TriMesh, VertexId};
use crate::scalar::Scalar;
use std::sync::Arc;

/// The geodesic distance field of a set of sources: the 1D subdivision of the edges into final
/// wedges [LZT §2] and everything that can be read from it.
///
/// Unreachable points (another component, a vertex no face uses, or beyond the maximum
/// distance) have distance `f64::INFINITY` and no nearest source.
///
/// # Example
/// Two opposite corners of the unit cube as sources: every other corner is an edge away from
/// one of them, and a point inside a face is answered as a vertex is.
/// ```
/// use exact_geodesics::{mesh::shapes, propagate, FaceId, PropagateOptions, SourceId, SurfacePoint, VertexId};
/// let cube = shapes::cube();
/// let sources = [SurfacePoint::Vertex(VertexId(0)), SurfacePoint::Vertex(VertexId(6))];
/// let field = propagate::<f64>(&cube, &sources, &PropagateOptions::default())?;
/// assert_eq!(field.nearest_source(VertexId(6)), Some(SourceId(1)));
/// for v in [1, 2, 3, 4, 5, 7].map(VertexId) {
///     assert!((field.vertex_distance(v) - 1.0).abs() < 1e-12);
/// }
/// let centre = SurfacePoint::Face { face: FaceId(0), bary: [1.0 / 3.0; 3] };
/// assert!(field.distance_at(&centre)? < 1.0);
/// # Ok::<(), exact_geodesics::PointError>(())
/// ```
///
/// A field borrows its mesh (`'m`) when made by [`propagate`](crate::propagate); one made by
/// [`propagate_shared`](crate::propagate_shared) shares it (`GeodesicField<'static, S>`) and can be
/// stored beside it, cloned and sent to other threads.
#[derive(Clone, Debug)]
pub struct GeodesicField<'m, S: Scalar> {
    mesh: MeshHandle<'m>,
    pub(crate) unfolding: Arc<Unfolding<S>>,
    pub(crate) sources: Vec<SurfacePoint>,
    pub(crate) wedges: EdgeWedges<S>,
    pub(crate) vertices: Vec<Option<VertexDistance<S>>>,
    pub(crate) stats: Stats,
}

impl<'m, S: Scalar> GeodesicField<'m, S> {
    pub(crate) fn new(
        mesh: &'m TriMesh,
        unfolding: Arc<Unfolding<S>>,
        sources: Vec<SurfacePoint>,
        wedges: EdgeWedges<S>,
        vertices: Vec<Option<VertexDistance<S>>>,
        stats: Stats,
    ) -> Self {
        GeodesicField {
            mesh: MeshHandle::Borrowed(mesh),
            unfolding,
            sources,
            wedges,
            vertices,
            stats,
        }
    }

    /// The mesh the field lives on.
    #[inline]
    pub fn mesh(&self) -> &TriMesh {
        &self.mesh
    }

    /// The same field holding `mesh`, shared, instead of its borrow: it then has no lifetime of
    /// its own. `None` if `mesh` is not the mesh the field was propagated on (the same object).
    pub fn into_shared(self, mesh: Arc<TriMesh>) -> Option<GeodesicField<'static, S>> {
        std::ptr::eq(&*self.mesh, &*mesh).then(|| GeodesicField {
            mesh: MeshHandle::Shared(mesh),
            unfolding: self.unfolding,
            sources: self.sources,
            wedges: self.wedges,
            vertices: self.vertices,
            stats: self.stats,
        })
    }

    /// The sources, validated and in canonical form, in the order given.
    pub fn sources(&self) -> &[SurfacePoint] {
        &self.sources
    }

    /// What happened during the propagation.
    pub fn stats(&self) -> &Stats {
        &self.stats
    }

    /// Whether the backend certified every decision of the propagation (always true for
    /// backends that do not certify: they count no decision; see
    /// [`DecisionCounts`](crate::scalar::DecisionCounts)).
    pub fn is_certified(&self) -> bool {
        self.stats.backend.uncertified == 0
    }

    /// The geodesic distance of a vertex to its nearest source; `f64::INFINITY` if unreachable.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn vertex_distance(&self, v: VertexId) -> f64 {
        self.vertices[v.index()]
            .as_ref()
            .map_or(f64::INFINITY, |d| self.model_f64(&d.distance))
    }

    /// The distance of every vertex, in file order (`f64::INFINITY` where unreachable).
    pub fn vertex_distances(&self) -> Vec<f64> {
        (0..self.mesh.vertex_count())
            .map(|v| self.vertex_distance(VertexId(v as u32)))
            .collect()
    }

    /// A vertex's distance in the backend's own number type; `None` if unreachable.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn vertex_distance_exact(&self, v: VertexId) -> Option<S> {
        self.vertices[v.index()]
            .as_ref()
            .map(|d| self.to_model(&d.distance))
    }

    /// Index (into [`sources`](Self::sources)) of the source nearest to a vertex.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn nearest_source(&self, v: VertexId) -> Option<SourceId> {
        self.vertices[v.index()].as_ref().map(|d| d.source)
    }

    /// The final wedges on an edge, sorted along it (from its `vertices[0]`), in the model's
    /// units.
    ///
    /// # Panics
    /// If `e` is not an edge of the mesh.
    pub fn wedges(&self, e: EdgeId) -> Vec<Wedge<S>> {
        let wedges = self.wedges.on(e);
        let mut wedges: Vec<Wedge<S>> = if !self.unfolding.is_reversed(e) {
            wedges.to_vec()
        } else {
            let from_first = |x: &S| self.unfolding.offset_from_first_vertex(e, x);
            wedges
                .iter()
                .rev()
                .map(|w| Wedge {
                    b0: from_first(&w.b1),
                    b1: from_first(&w.b0),
                    source_x: from_first(&w.source_x),
                    ..w.clone()
                })
                .collect()
        };
        if self.mesh.unit_scale() != 1.0 {
            let factor = self.model_factor();
            wedges = wedges.iter().map(|w| w.scaled(&factor)).collect();
        }
        wedges
    }

    /// The number of final wedges on every edge.
    pub fn wedge_counts(&self) -> Vec<usize> {
        self.wedges.per_edge().map(<[Wedge<S>]>::len).collect()
    }

    /// The length of an edge in the backend's number type.
    ///
    /// # Panics
    /// If `e` is not an edge of the mesh.
    pub fn edge_length(&self, e: EdgeId) -> S {
        self.to_model(self.unfolding.length(e))
    }

    /// The factor from the engine's scaled units to the model's (a power of two).
    fn model_factor(&self) -> S {
        S::from_f64(self.mesh.unit_scale().recip())
    }

    /// A length in the engine's scaled units, as the nearest `f64` in the model's units: scaled
    /// back before it is rounded, as a length below `f64`'s range in scaled units (an edge of
    /// 1e-113 in a model of 1e211) may be within it in the model's.
    pub(crate) fn model_f64(&self, x: &S) -> f64 {
        self.to_model(x).to_f64()
    }

    /// A length in the engine's scaled units, in the model's units (exactly).
    pub(crate) fn to_model(&self, x: &S) -> S {
        if self.mesh.unit_scale() == 1.0 {
            return x.clone();
        }
        x.clone() * &self.model_factor()
    }
}
