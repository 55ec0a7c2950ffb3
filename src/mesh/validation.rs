//! What is unusual about a mesh that is still usable.
//!
//! Hard errors ([`MeshError`](super::MeshError)) stop a mesh from being built; the conditions
//! here do not, but a researcher wants to know about them because they change what the
//! distances mean (e.g. vertices no face uses are unreachable, with distance +infinity).

use super::{EdgeId, FaceId, VertexId};
use serde::Serialize;

/// An edge that more than two faces share: the surface is not a manifold there. Geodesics
/// reaching it through one face continue into every other, and its ends act as pseudo-sources
/// ([`TriMesh::may_bend_geodesics`](super::TriMesh::may_bend_geodesics)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct NonManifoldEdge {
    /// The edge.
    pub edge: EdgeId,
    /// Its end vertices.
    pub vertices: [VertexId; 2],
    /// How many faces share it (copies of a face not counted).
    pub face_count: usize,
}

/// A face whose three corners are those of an earlier face (in any order): the same triangle
/// twice. The copy is ignored: it shares the earlier face's edges but is none of their faces,
/// and a point named in it is that point of the earlier face.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct DuplicateFace {
    /// The copy, which the engine ignores.
    pub face: FaceId,
    /// The first face with the same corners.
    pub copy_of: FaceId,
}

/// Conditions found while building a [`TriMesh`](super::TriMesh) that leave it usable.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
#[non_exhaustive]
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
    /// Edges shared by more than two faces, in edge order.
    pub non_manifold_edges: Vec<NonManifoldEdge>,
    /// Faces that repeat an earlier face's corners, in face order.
    pub duplicate_faces: Vec<DuplicateFace>,
    /// Edges whose first two faces traverse them in the same direction (inconsistent orientation).
    /// The engine does not need a consistent orientation; writers keep the input order.
    pub inconsistently_oriented_edges: usize,
    /// Number of edges with a single face.
    pub boundary_edges: usize,
    /// Number of connected components of faces (vertices without faces not counted).
    pub components: usize,
}

impl ValidationReport {
    /// Edge length spans beyond this (`2^12`) get a warning: the float backends' distances may
    /// then be off by more than 1e-12 relative (`f64::EPSILON * 2^12` is about 9e-13), and on
    /// spans of 1e9 and more the rounding has lost geodesics outright (the degeneracy corpus's
    /// seed 380: a sliver mesh's vertex 1.8 times its exact distance).
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
                "{} edge(s) shorter than 2^-500 of the model's size, first {}: the f64 and adaptive backends cannot measure them and refuse the mesh (use --backend exact)",
                self.float_unresolved_edges.len(),
                self.float_unresolved_edges[0]
            ));
        }
        if self.edge_length_span > Self::WIDE_SPAN {
            out.push(format!(
                "edge lengths span a factor of {:.1e}: the f64 and adaptive backends round there at about {:.0e} relative and may lose geodesics to it (on such meshes of the degeneracy corpus, distances came out up to 1.8 times too long); use --backend exact",
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
        if !self.non_manifold_edges.is_empty() {
            out.push(format!(
                "{} edge(s) shared by more than two faces{}: geodesics continue into every face of such an edge and may bend at its ends",
                self.non_manifold_edges.len(),
                listed(self.non_manifold_edges.iter().map(|n| {
                    let [a, b] = n.vertices;
                    format!("({}, {}) with {} faces", a.0, b.0, n.face_count)
                }))
            ));
        }
        if !self.duplicate_faces.is_empty() {
            out.push(format!(
                "{} face(s) repeating an earlier face's corners, ignored{}",
                self.duplicate_faces.len(),
                listed(
                    self.duplicate_faces
                        .iter()
                        .map(|d| format!("{} (copy of {})", d.face, d.copy_of))
                )
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

/// `: a, b, c` for the first few items (`, ...` if there are more).
fn listed(items: impl ExactSizeIterator<Item = String>) -> String {
    const SHOWN: usize = 8;
    let more = items.len() > SHOWN;
    let shown: Vec<String> = items.take(SHOWN).collect();
    format!(": {}{}", shown.join(", "), if more { ", ..." } else { "" })
}
