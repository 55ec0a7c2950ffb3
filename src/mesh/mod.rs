//! Triangle meshes: positions, faces and the edge-face topology the engine walks on.
//!
//! A [`TriMesh`] keeps the input's vertex order (including vertices that no face uses) and face
//! order. It is built by [`TriMesh::new`], which validates at the door: hard errors become a
//! [`MeshError`], usable oddities a [`ValidationReport`].

mod corners;
mod error;
mod handle;
mod ids;
pub mod io;
pub mod shapes;
mod topology;
mod validation;
pub(crate) mod vector;

pub use error::MeshError;
pub use handle::MeshHandle;
pub use ids::{EdgeId, FaceId, Side, SourceId, VertexId};
pub use topology::{Edge, Wing};
pub use validation::{DuplicateFace, NonManifoldEdge, ValidationReport};
pub(crate) use vector::normalizing_power;

use glam::DVec3;

/// A triangle mesh with its edge-face topology.
///
/// Edges are undirected; each has one or two faces, or more where the surface is not a manifold
/// (a "book" of pages along one edge). Corner `i` of a face and corner `i + 1` (mod 3) span the
/// face's edge `i`.
#[derive(Debug, Clone)]
pub struct TriMesh {
    positions: Vec<DVec3>,
    faces: Vec<[u32; 3]>,
    topology: topology::Topology,
    report: ValidationReport,
}

impl TriMesh {
    /// Builds a mesh from positions and triangles (0-based vertex indices).
    ///
    /// Positions are anything that converts into a [`glam::DVec3`], such as `[f64; 3]` or
    /// `DVec3` itself.
    ///
    /// A mesh needs at least one face; vertices that no face uses are kept (and reported in
    /// [`TriMesh::validation`]), and are unreachable from every source.
    ///
    /// Edges shared by more than two faces and faces repeating another's corners are usable
    /// and reported ([`ValidationReport::non_manifold_edges`],
    /// [`ValidationReport::duplicate_faces`]); [`TriMesh::require_manifold`] refuses them.
    ///
    /// # Errors
    /// [`MeshError`] for no faces at all, a NaN or infinite coordinate, an index out of range, or
    /// a face that repeats a vertex.
    ///
    /// # Example
    /// ```
    /// use exact_geodesics::TriMesh;
    /// let mesh = TriMesh::new(
    ///     vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
    ///     vec![[0, 1, 2]],
    /// )?;
    /// assert_eq!(mesh.edge_count(), 3);
    /// # Ok::<(), exact_geodesics::MeshError>(())
    /// ```
    pub fn new<P: Into<DVec3>>(
        positions: Vec<P>,
        mut faces: Vec<[u32; 3]>,
    ) -> Result<TriMesh, MeshError> {
        const MAX: usize = (u32::MAX - 1) as usize;
        let mut positions: Vec<DVec3> = positions.into_iter().map(Into::into).collect();
        for count in [positions.len(), faces.len()] {
            if count > MAX / 3 {
                return Err(MeshError::TooLarge {
                    count,
                    max: MAX / 3,
                });
            }
        }
        if faces.is_empty() {
            return Err(MeshError::NoFaces {
                vertices: positions.len(),
            });
        }
        for (vertex, p) in positions.iter().enumerate() {
            if !p.is_finite() {
                return Err(MeshError::NonFiniteCoordinate {
                    vertex,
                    x: p.x,
                    y: p.y,
                    z: p.z,
                });
            }
        }
        for (face, f) in faces.iter().enumerate() {
            for &index in f {
                if index as usize >= positions.len() {
                    return Err(MeshError::VertexIndexOutOfRange {
                        face,
                        index: u64::from(index),
                        vertex_count: positions.len(),
                    });
                }
            }
            for i in 0..3 {
                if f[i] == f[(i + 1) % 3] {
                    return Err(MeshError::RepeatedVertex { face, vertex: f[i] });
                }
            }
        }
        // Readers grow these as they go: up to twice the room, for the mesh's lifetime.
        positions.shrink_to_fit();
        faces.shrink_to_fit();
        let (topology, report) = topology::Topology::build(&positions, &faces);
        Ok(TriMesh {
            positions,
            faces,
            topology,
            report,
        })
    }

    /// Number of vertices, including those no face uses.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    pub fn face_count(&self) -> usize {
        self.faces.len()
    }

    /// Number of undirected edges.
    pub fn edge_count(&self) -> usize {
        self.topology.edges.len()
    }

    /// All vertex positions, in input order.
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// The position of a vertex.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    #[inline]
    pub fn position(&self, v: VertexId) -> DVec3 {
        self.positions[v.index()]
    }

    /// All faces as corner vertex indices, in input order.
    pub fn faces(&self) -> &[[u32; 3]] {
        &self.faces
    }

    /// The corners of a face.
    ///
    /// # Panics
    /// If `f` is not a face of the mesh.
    #[inline]
    pub fn face(&self, f: FaceId) -> [VertexId; 3] {
        let c = self.faces[f.index()];
        [VertexId(c[0]), VertexId(c[1]), VertexId(c[2])]
    }

    /// The edge with the given id.
    ///
    /// # Panics
    /// If `e` is not an edge of the mesh.
    #[inline]
    pub fn edge(&self, e: EdgeId) -> &Edge {
        &self.topology.edges[e.index()]
    }

    /// All edges.
    pub fn edges(&self) -> &[Edge] {
        &self.topology.edges
    }

    /// Edge `i` of face `f`: the one from corner `i` to corner `i + 1` (mod 3).
    ///
    /// # Panics
    /// If `f` is not a face of the mesh.
    #[inline]
    pub fn face_edges(&self, f: FaceId) -> [EdgeId; 3] {
        self.topology.face_edges[f.index()]
    }

    /// The edge joining two vertices, if there is one.
    ///
    /// # Panics
    /// If `a` or `b` is not a vertex of the mesh.
    pub fn edge_between(&self, a: VertexId, b: VertexId) -> Option<EdgeId> {
        self.topology
            .vertex_edges(a)
            .iter()
            .copied()
            .find(|&e| self.edge(e).other(a) == Some(b))
    }

    /// Faces incident to a vertex.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn vertex_faces(&self, v: VertexId) -> &[FaceId] {
        self.topology.vertex_faces(v)
    }

    /// Edges incident to a vertex.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn vertex_edges(&self, v: VertexId) -> &[EdgeId] {
        self.topology.vertex_edges(v)
    }

    /// Sum of the face angles at a vertex, in radians (0 for a vertex no face uses).
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn angle_sum(&self, v: VertexId) -> f64 {
        self.topology.angle_sum[v.index()]
    }

    /// Whether geodesics may bend at the vertex, so that it must act as a pseudo-source \[MMP87\]:
    /// boundary and bowtie vertices, ends of edges shared by more than two faces, vertices whose angle sum is at least 2 pi (saddles and,
    /// to be safe under rounding, flat ones), and the corners of degenerate faces
    /// ([`ValidationReport::zero_area_faces`]). Over-approximating costs wedges, never
    /// correctness: a path through any vertex is a path on the surface. An interior vertex
    /// that [`is_flat_vertex`](Self::is_flat_vertex) bends no geodesic and is left out: its
    /// wedges would only tie with the wedges passing it, along its shadow lines, and cut them
    /// there (in a flat region, one cut per vertex behind an edge). A flat boundary vertex
    /// stays in: the way along the boundary line runs through it, and the engine sends its
    /// distance on along its edges only.
    ///
    /// Corners of degenerate faces bend because their angle sums mean nothing: a vertex at the
    /// same place as another is, on the surface, the same point, so it must send wedges into
    /// its own faces whenever its twin is reached (or is the source), whatever its angles. The
    /// ends of an edge shorter than `1e-8` of its face's longest edge bend too: the rays through
    /// such an edge make windows narrower than a float backend keeps, and a path through one of
    /// its ends is then the best a float backend can offer (within the edge's length).
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn may_bend_geodesics(&self, v: VertexId) -> bool {
        /// Angle sums this close to 2 pi (relative) count as flat; acos-based sums carry ~1e-15.
        const FLAT_SLACK: f64 = 1e-9;
        let i = v.index();
        self.topology.boundary_vertex[i]
            || self.topology.on_degenerate_face[i]
            || (self.topology.angle_sum[i] >= std::f64::consts::TAU * (1.0 - FLAT_SLACK)
                && !self.topology.flat_vertex[i])
    }

    /// Whether the vertex is exactly flat: a vertex where the surface is a manifold, on no
    /// degenerate face, whose faces lie exactly in one plane and turn the same way in it once
    /// around, on either side of each edge two of them share (none folded onto its
    /// neighbour), or, on the boundary, whose two boundary neighbours lie on one line through it
    /// (an angle of exactly pi): decided exactly on the input coordinates by orient3d and
    /// orient2d. No geodesic bends there: the straight way through it is a straight way in
    /// the plane.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn is_flat_vertex(&self, v: VertexId) -> bool {
        self.topology.flat_vertex[v.index()]
    }

    /// Whether the vertex lies on a straight crease: an interior vertex with two neighbours on
    /// one line through it, the faces on each side of that line exactly in one plane. Its
    /// angle sum is exactly 2 pi, so no geodesic bends there; decided exactly on the input
    /// coordinates by orient3d and orient2d, when asked (only exact runs ask, so loading a
    /// mesh does not pay for it).
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn is_crease_vertex(&self, v: VertexId) -> bool {
        let i = v.index();
        let t = &self.topology;
        let flat_angle =
            (t.angle_sum[i] - std::f64::consts::TAU).abs() < std::f64::consts::FRAC_PI_2;
        if t.boundary_vertex[i] || t.on_degenerate_face[i] || t.flat_vertex[i] || !flat_angle {
            return false;
        }
        let corners: Vec<[u32; 3]> = self
            .vertex_faces(v)
            .iter()
            .map(|&f| self.face(f).map(|c| c.0))
            .collect();
        let scale = t.unit_scale;
        topology::straight_crease(i, &corners, |u| self.positions()[u] * scale)
    }

    /// Whether three vertices lie on one line in space, decided exactly on the input
    /// coordinates.
    ///
    /// # Panics
    /// If one of them is not a vertex of the mesh.
    pub fn are_collinear(&self, vertices: [VertexId; 3]) -> bool {
        let scale = self.topology.unit_scale;
        topology::collinear(vertices.map(|v| self.positions()[v.index()] * scale))
    }

    /// The power of two by which the engine multiplies coordinates so that its arithmetic
    /// stays in range whatever the model's units: 1 unless the largest coordinate magnitude
    /// lies outside `2^-64 ..= 2^64`. Multiplying by it is exact (but for subnormals, which
    /// only a model spanning more than 300 orders of magnitude meets), and every distance the
    /// library reports is in the model's own units.
    pub fn unit_scale(&self) -> f64 {
        self.topology.unit_scale
    }

    /// Whether the vertex lies on the boundary or where the surface is not a manifold: it joins
    /// several fans (a bowtie) or ends an edge shared by more than two faces.
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.topology.boundary_vertex[v.index()]
    }

    /// Whether the vertex is a corner of a degenerate face or an end of an edge shorter than
    /// `1e-8` of its face's longest edge: its angles mean little to a float backend (see
    /// [`TriMesh::may_bend_geodesics`]).
    ///
    /// # Panics
    /// If `v` is not a vertex of the mesh.
    pub fn is_on_degenerate_face(&self, v: VertexId) -> bool {
        self.topology.on_degenerate_face[v.index()]
    }

    /// The face on side `side` of an edge (below [`TriMesh::side_count`]; sides 0 and 1 are
    /// [`Edge::faces`]), with its apex and its two other edges; `None` if that side has no face.
    ///
    /// # Panics
    /// If `e` is not an edge of the mesh.
    #[inline]
    pub fn wing(&self, e: EdgeId, side: Side) -> Option<Wing> {
        self.topology.wing(&self.faces, e, side.index())
    }

    /// The face on side `side` of an edge, if that side has one (the face of [`TriMesh::wing`],
    /// read from the edge's record alone).
    ///
    /// # Panics
    /// If `e` is not an edge of the mesh.
    #[inline]
    pub fn face_on(&self, e: EdgeId, side: Side) -> Option<FaceId> {
        self.topology.face_on(e, side.index())
    }

    /// The number of sides of an edge: 2 (side 1 is empty on the boundary), or one per face on
    /// an edge shared by more than two faces.
    ///
    /// # Panics
    /// If `e` is not an edge of the mesh.
    #[inline]
    pub fn side_count(&self, e: EdgeId) -> usize {
        2 + self.topology.extra_faces(e).len()
    }

    /// The sides of an edge, in order ([`TriMesh::side_count`] of them).
    ///
    /// # Panics
    /// If `e` is not an edge of the mesh.
    #[inline]
    pub fn sides(&self, e: EdgeId) -> impl Iterator<Item = Side> {
        (0..self.side_count(e)).map(Side::from_index)
    }

    /// The faces of an edge, side by side.
    ///
    /// # Panics
    /// If `e` is not an edge of the mesh.
    pub fn edge_faces(&self, e: EdgeId) -> impl Iterator<Item = FaceId> + '_ {
        let extra = self.topology.extra_faces(e).iter().copied();
        self.edge(e).faces().into_iter().flatten().chain(extra)
    }

    /// The side of edge `e` on which face `f` lies, if `f` is one of its faces.
    ///
    /// # Panics
    /// If `e` is not an edge of the mesh.
    #[inline]
    pub fn side_of(&self, e: EdgeId, f: FaceId) -> Option<Side> {
        let index = match self.edge(e).faces().iter().position(|&g| g == Some(f)) {
            Some(side) => Some(side),
            None => self
                .topology
                .extra_faces(e)
                .iter()
                .position(|&g| g == f)
                .map(|i| i + 2),
        };
        index.map(Side::from_index)
    }

    /// Where the data of side `side` of edge `e` lives in an array with one entry per side
    /// of every edge (of length [`TriMesh::side_slot_count`]).
    #[inline]
    pub(crate) fn side_slot(&self, e: EdgeId, side: Side) -> usize {
        self.topology.side_slot(e, side.index())
    }

    /// The number of sides of all edges.
    pub(crate) fn side_slot_count(&self) -> usize {
        self.topology.side_slot_count()
    }

    /// The strict check: refuses a mesh that is not a manifold along its edges, as a caller who
    /// wants no such surface asks.
    ///
    /// # Errors
    /// [`MeshError::NonManifoldEdge`] for the first edge shared by more than two faces,
    /// otherwise [`MeshError::DuplicateFace`] for the first face repeating an earlier one.
    ///
    /// # Example
    /// ```
    /// use exact_geodesics::{MeshError, TriMesh};
    /// // Three pages along the edge (0, 1).
    /// let positions = vec![
    ///     [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0],
    /// ];
    /// let mesh = TriMesh::new(positions, vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]])?;
    /// assert_eq!(mesh.validation().non_manifold_edges.len(), 1);
    /// assert!(matches!(
    ///     mesh.require_manifold(),
    ///     Err(MeshError::NonManifoldEdge { a: 0, b: 1, face_count: 3, .. })
    /// ));
    /// # Ok::<(), MeshError>(())
    /// ```
    pub fn require_manifold(&self) -> Result<(), MeshError> {
        if let Some(n) = self.report.non_manifold_edges.first() {
            let faces: Vec<usize> = self.edge_faces(n.edge).map(FaceId::index).collect();
            return Err(MeshError::NonManifoldEdge {
                a: n.vertices[0].0,
                b: n.vertices[1].0,
                face_count: faces.len(),
                faces: faces.into_iter().take(3).collect(),
            });
        }
        match self.report.duplicate_faces.first() {
            Some(d) => Err(MeshError::DuplicateFace {
                face: d.face.index(),
                copy_of: d.copy_of.index(),
            }),
            None => Ok(()),
        }
    }

    /// Length of every edge, indexed by [`EdgeId`].
    pub fn edge_lengths(&self) -> &[f64] {
        &self.topology.edge_length
    }

    /// Whether a face is degenerate (listed in [`ValidationReport::zero_area_faces`]).
    ///
    /// # Panics
    /// If `f` is not a face of the mesh.
    pub fn is_degenerate_face(&self, f: FaceId) -> bool {
        self.report.zero_area_faces.binary_search(&f).is_ok()
    }

    /// What was unusual but acceptable about the input.
    pub fn validation(&self) -> &ValidationReport {
        &self.report
    }
}
