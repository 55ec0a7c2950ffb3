//! What is unusual about a mesh that is still usable.
//!
//! Hard errors ([`MeshError`](super::MeshError)) stop a mesh from being built; the conditions
//! here do not, but a researcher wants to know about them because they change what the
//! distances mean (e.g. vertices no face uses are unreachable, with distance +infinity).

use super::{EdgeId, FaceId, VertexId};
use serde::Serialize;

/// Conditions found while building a [`TriMesh`](super::TriMesh) that leave it usable.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct ValidationReport {
    /// Faces whose three corners are collinear or coincident (to within a few ulps in f64):
    /// their corners act as pseudo-sources ([`TriMesh::may_bend_geodesics`](super::TriMesh::may_bend_geodesics)).
    pub zero_area_faces: Vec<FaceId>,
    /// Edges of non-zero length shorter than `2^-500` times the model's largest coordinate:
    /// their squared lengths underflow in `f64`, so the `f64` and adaptive backends treat them
    /// as if their ends coincided. The exact backend measures them exactly.
    pub float_unresolved_edges: Vec<EdgeId>,
    /// The longest edge's length over the shortest (edges of length zero left out; 1 without
    /// edges). Unfolded positions on an edge carry errors of about `f64::EPSILON` times its
    /// length, so the `f64` and adaptive backends' distances are good to about
    /// `f64::EPSILON * edge_length_span` relative where short distances cross long edges.
    pub edge_length_span: f64,
    /// Vertices that no face uses; they are unreachable from any source on a face.
    pub unreferenced_vertices: Vec<VertexId>,
    /// Vertices whose incident faces form more than one fan (a "bowtie"). Geodesics may pass
    /// through such a vertex from one fan to another; it is treated as a pseudo-source.
    pub non_manifold_vertices: Vec<VertexId>,
    /// Edges whose two faces traverse them in the same direction (inconsistent orientation).
    /// The engine does not need a consistent orientation; writers keep the input order.
    pub inconsistently_oriented_edges: usize,
    /// Number of edges with a single face.
    pub boundary_edges: usize,
    /// Number of connected components of faces (vertices without faces not counted).
    pub components: usize,
}

impl ValidationReport {
    /// Edge length spans beyond this (`2^12`) get a warning: the float backends' distances may
    /// then be off by more than 1e-12 relative (`f64::EPSILON * 2^12` is about 9e-13).
    pub const WIDE_SPAN: f64 = 4096.0;

    /// Human-readable warnings, one per kind of condition, empty for a clean closed mesh.
    pub fn warnings(&self) -> Vec<String> {
        let mut out = Vec::new();
        if !self.zero_area_faces.is_empty() {
            out.push(format!(
                "{} zero-area face(s), first {}",
                self.zero_area_faces.len(),
                self.zero_area_faces[0]
            ));
        }
        if !self.float_unresolved_edges.is_empty() {
            out.push(format!(
                "{} edge(s) shorter than 2^-500 of the model's size, first {}: the f64 and adaptive backends cannot resolve them (use --backend exact)",
                self.float_unresolved_edges.len(),
                self.float_unresolved_edges[0]
            ));
        }
        if self.edge_length_span > Self::WIDE_SPAN {
            out.push(format!(
                "edge lengths span a factor of {:.1e}: f64 and adaptive distances may be off by up to about {:.0e} relative (use --backend exact)",
                self.edge_length_span,
                f64::EPSILON * self.edge_length_span
            ));
        }
        if !self.unreferenced_vertices.is_empty() {
            out.push(format!(
                "{} vertex(es) used by no face (unreachable, distance inf), first {}",
                self.unreferenced_vertices.len(),
                self.unreferenced_vertices[0]
            ));
        }
        if !self.non_manifold_vertices.is_empty() {
            out.push(format!(
                "{} non-manifold (bowtie) vertex(es), first {}",
                self.non_manifold_vertices.len(),
                self.non_manifold_vertices[0]
            ));
        }
        if self.inconsistently_oriented_edges > 0 {
            out.push(format!(
                "{} edge(s) with inconsistently oriented faces",
                self.inconsistently_oriented_edges
            ));
        }
        if self.components > 1 {
            out.push(format!(
                "{} connected components: points in other components than the sources are unreachable",
                self.components
            ));
        }
        out
    }
}
