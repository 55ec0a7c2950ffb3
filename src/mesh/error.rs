//! Errors raised when a mesh is built from vertices and faces.

use thiserror::Error;

/// Why a set of vertices and faces is not a mesh the engine can run on.
///
/// Face and vertex numbers are 0-based, in input order. Readers in [`crate::mesh::io`] wrap these
/// with the file name and line.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum MeshError {
    /// A coordinate is NaN or infinite.
    #[error("vertex {vertex} has a non-finite coordinate ({x}, {y}, {z})")]
    NonFiniteCoordinate {
        /// The offending vertex.
        vertex: usize,
        /// Its x coordinate.
        x: f64,
        /// Its y coordinate.
        y: f64,
        /// Its z coordinate.
        z: f64,
    },
    /// A face refers to a vertex that does not exist.
    #[error("face {face} refers to vertex {index}, but the mesh has {vertex_count} vertices")]
    VertexIndexOutOfRange {
        /// The offending face.
        face: usize,
        /// The index it uses.
        index: u64,
        /// How many vertices there are.
        vertex_count: usize,
    },
    /// A face uses the same vertex twice.
    #[error("face {face} repeats vertex {vertex}")]
    RepeatedVertex {
        /// The offending face.
        face: usize,
        /// The repeated vertex.
        vertex: u32,
    },
    /// An edge is shared by more than two faces (refused by [`TriMesh::require_manifold`](super::TriMesh::require_manifold) only).
    #[error("edge ({a}, {b}) is shared by {face_count} faces (first three: {faces:?}); the surface is not a manifold there")]
    NonManifoldEdge {
        /// One end of the edge.
        a: u32,
        /// The other end.
        b: u32,
        /// How many faces share it.
        face_count: usize,
        /// The first faces found on it.
        faces: Vec<usize>,
    },
    /// A face repeats the corners of an earlier one (refused by
    /// [`TriMesh::require_manifold`](super::TriMesh::require_manifold) only).
    #[error(
        "face {face} has the same corners as face {copy_of}; the surface is not a manifold there"
    )]
    DuplicateFace {
        /// The later face.
        face: usize,
        /// The earlier face with the same corners.
        copy_of: usize,
    },
    /// There are no faces: no surface to measure distances on. An empty file, a point cloud, or
    /// faces under a name the reader does not know (a PLY element `faces` rather than `face`)
    /// all end here rather than in a result where every point is unreachable.
    #[error("the mesh has no faces ({vertices} vertices, 0 triangles): there is no surface to measure distances on")]
    NoFaces {
        /// How many vertices there are.
        vertices: usize,
    },
    /// Too many vertices or faces for 32-bit indices.
    #[error("the mesh has {count} elements; at most {max} are supported")]
    TooLarge {
        /// The element count.
        count: usize,
        /// The largest supported count.
        max: usize,
    },
}
