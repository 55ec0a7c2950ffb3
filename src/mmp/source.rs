//! Points on the surface: sources, targets and the points of a traced path.

use crate::mesh::{EdgeId, FaceId, TriMesh, VertexId};
use glam::DVec3;
use serde::Serialize;
use thiserror::Error;

/// A point on the mesh surface, named by the simplex that contains it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum SurfacePoint {
    /// A mesh vertex.
    Vertex(VertexId),
    /// The point at fraction `t` from the edge's `vertices[0]` to its `vertices[1]`.
    Edge {
        /// The edge.
        edge: EdgeId,
        /// Fraction along the edge, in `[0, 1]`.
        t: f64,
    },
    /// A point of a face, by barycentric coordinates of its three corners (in face order).
    ///
    /// The coordinates are homogeneous: any finite, non-negative triple that is not all zero
    /// names the point `bary / (bary[0] + bary[1] + bary[2])`, and [`SurfacePoint::validated`]
    /// divides them by their sum (so `[1, 1, 1]` and `[0.2, 0.2, 0.2]` are both the centroid).
    /// Validated points, and the points the library returns, sum to one up to rounding.
    Face {
        /// The face.
        face: FaceId,
        /// Barycentric coordinates: finite, non-negative, not all zero; homogeneous.
        bary: [f64; 3],
    },
}

/// Why a surface point is not a point of the mesh.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum PointError {
    /// The vertex does not exist.
    #[error("vertex {vertex} is out of range: the mesh has {count} vertices")]
    VertexOutOfRange {
        /// The vertex asked for.
        vertex: u32,
        /// How many vertices the mesh has.
        count: usize,
    },
    /// The face does not exist.
    #[error("face {face} is out of range: the mesh has {count} faces")]
    FaceOutOfRange {
        /// The face asked for.
        face: u32,
        /// How many faces the mesh has.
        count: usize,
    },
    /// The edge does not exist.
    #[error("edge {edge} is out of range: the mesh has {count} edges")]
    EdgeOutOfRange {
        /// The edge asked for.
        edge: u32,
        /// How many edges the mesh has.
        count: usize,
    },
    /// Two vertices are not joined by an edge.
    #[error("vertices {a} and {b} are not joined by an edge")]
    NoSuchEdge {
        /// One vertex.
        a: u32,
        /// The other.
        b: u32,
    },
    /// An edge parameter outside `[0, 1]` or not finite.
    #[error("edge parameter {t} is not in [0, 1]")]
    EdgeParameter {
        /// The parameter given.
        t: f64,
    },
    /// Barycentric coordinates that are negative, not finite, or sum to zero.
    #[error("barycentric coordinates {bary:?} must be finite, non-negative and not all zero")]
    Barycentric {
        /// The coordinates given.
        bary: [f64; 3],
    },
    /// No sources were given.
    #[error("at least one source is needed")]
    NoSource,
    /// A maximum distance that is negative or NaN ([`PropagateOptions::max_distance`]).
    ///
    /// [`PropagateOptions::max_distance`]: crate::PropagateOptions::max_distance
    #[error(
        "the maximum distance {max_distance} must be a non-negative number (inf for no limit)"
    )]
    MaxDistance {
        /// The maximum distance given.
        max_distance: f64,
    },
    /// The mesh has edges shorter than `2^-500` of its size
    /// ([`ValidationReport::float_unresolved_edges`](crate::ValidationReport)), which the
    /// backend cannot measure ([`Scalar::measures_below_float_resolution`](crate::Scalar)):
    /// the `f64` and adaptive backends would put their ends at distance zero from each other.
    /// The exact backend measures them.
    #[error(
        "{count} edge(s) of the mesh, first e{edge}, are shorter than 2^-500 of its largest coordinate: their squared lengths underflow in f64, so the f64 and adaptive backends cannot measure them (use the exact backend)"
    )]
    BeyondFloatRange {
        /// The first such edge.
        edge: u32,
        /// How many there are.
        count: usize,
    },
}

impl SurfacePoint {
    /// The point at fraction `t` from vertex `a` to vertex `b` along their common edge.
    ///
    /// # Errors
    /// [`PointError`] if a vertex is out of range, the vertices share no edge, or `t` is not in
    /// `[0, 1]`.
    pub fn on_edge(mesh: &TriMesh, a: u32, b: u32, t: f64) -> Result<SurfacePoint, PointError> {
        for v in [a, b] {
            if v as usize >= mesh.vertex_count() {
                return Err(PointError::VertexOutOfRange {
                    vertex: v,
                    count: mesh.vertex_count(),
                });
            }
        }
        if !(0.0..=1.0).contains(&t) {
            return Err(PointError::EdgeParameter { t });
        }
        let edge = mesh
            .edge_between(VertexId(a), VertexId(b))
            .ok_or(PointError::NoSuchEdge { a, b })?;
        let t = if mesh.edge(edge).vertices[0] == VertexId(a) {
            t
        } else {
            1.0 - t
        };
        Ok(SurfacePoint::Edge { edge, t })
    }

    /// Checks the point against the mesh and puts it in canonical form: barycentric coordinates
    /// are divided by their sum, and a point on a face's boundary or an edge's end is named by
    /// the smallest simplex containing it (the engine relies on this to emit wedges into every
    /// face around it); a point of a face repeating an earlier face's corners
    /// ([`ValidationReport::duplicate_faces`](crate::mesh::ValidationReport::duplicate_faces))
    /// is named in the earlier face.
    ///
    /// Any finite, non-negative, not-all-zero barycentric triple is accepted, however large or
    /// small: the coordinates are divided by the largest of them before they are summed, so the
    /// sum cannot overflow (`[0, 1e308, 1e308]` is the midpoint of an edge). A coordinate so much
    /// smaller than the largest that their ratio underflows to zero names a point on the face's
    /// boundary.
    ///
    /// # Errors
    /// [`PointError`] for an element out of range or a parameter out of its domain.
    pub fn validated(self, mesh: &TriMesh) -> Result<SurfacePoint, PointError> {
        match self {
            SurfacePoint::Vertex(v) if v.index() >= mesh.vertex_count() => {
                Err(PointError::VertexOutOfRange {
                    vertex: v.0,
                    count: mesh.vertex_count(),
                })
            }
            SurfacePoint::Edge { edge, .. } if edge.index() >= mesh.edge_count() => {
                Err(PointError::EdgeOutOfRange {
                    edge: edge.0,
                    count: mesh.edge_count(),
                })
            }
            SurfacePoint::Edge { t, .. } if !(0.0..=1.0).contains(&t) => {
                Err(PointError::EdgeParameter { t })
            }
            SurfacePoint::Face { face, .. } if face.index() >= mesh.face_count() => {
                Err(PointError::FaceOutOfRange {
                    face: face.0,
                    count: mesh.face_count(),
                })
            }
            SurfacePoint::Face { face, bary } => {
                let largest = bary.iter().copied().fold(0.0, f64::max);
                if bary.iter().any(|b| !b.is_finite() || *b < 0.0) || largest == 0.0 {
                    return Err(PointError::Barycentric { bary });
                }
                // Homogeneous coordinates: scaled into [0, 1] first, the sum lies in [1, 3].
                let scaled = bary.map(|b| b / largest);
                let sum: f64 = scaled.iter().sum();
                let bary = scaled.map(|b| b / sum);
                // A copy of an earlier face is that face.
                let copies = &mesh.validation().duplicate_faces;
                let (face, bary) = match copies.binary_search_by_key(&face, |d| d.face) {
                    Ok(i) => {
                        let (copy, kept) = (mesh.face(face), copies[i].copy_of);
                        let at = |c| copy.iter().position(|&x| x == c).expect("same corners");
                        (kept, mesh.face(kept).map(|c| bary[at(c)]))
                    }
                    Err(_) => (face, bary),
                };
                let corners = mesh.face(face);
                let zeros: Vec<usize> = (0..3).filter(|&i| bary[i] == 0.0).collect();
                Ok(match zeros[..] {
                    [] => SurfacePoint::Face { face, bary },
                    [i] => {
                        let (a, b) = (corners[(i + 1) % 3], corners[(i + 2) % 3]);
                        let edge = mesh.face_edges(face)[(i + 1) % 3];
                        let t = bary[(i + 2) % 3];
                        if mesh.edge(edge).vertices[0] == a {
                            SurfacePoint::Edge { edge, t }
                        } else {
                            debug_assert_eq!(mesh.edge(edge).vertices[0], b);
                            SurfacePoint::Edge { edge, t: 1.0 - t }
                        }
                    }
                    _ => SurfacePoint::Vertex(
                        corners[(0..3)
                            .find(|i| !zeros.contains(i))
                            .expect("one corner is non-zero")],
                    ),
                })
            }
            SurfacePoint::Edge { edge, t } if t == 0.0 || t == 1.0 => Ok(SurfacePoint::Vertex(
                mesh.edge(edge).vertices[usize::from(t == 1.0)],
            )),
            point => Ok(point),
        }
    }

    /// The point's position in space.
    ///
    /// # Panics
    /// If the point names a vertex, edge or face the mesh does not have (see
    /// [`SurfacePoint::validated`]).
    pub fn position(&self, mesh: &TriMesh) -> DVec3 {
        match *self {
            SurfacePoint::Vertex(v) => mesh.position(v),
            SurfacePoint::Edge { edge, t } => {
                let [a, b] = mesh.edge(edge).vertices.map(|v| mesh.position(v));
                a + t * (b - a)
            }
            SurfacePoint::Face { face, bary } => {
                let c = mesh.face(face).map(|v| mesh.position(v));
                bary[0] * c[0] + bary[1] * c[1] + bary[2] * c[2]
            }
        }
    }

    /// The faces that contain the point (one, those of an edge, or a vertex's star).
    ///
    /// # Panics
    /// As [`SurfacePoint::position`].
    pub fn faces(&self, mesh: &TriMesh) -> Vec<FaceId> {
        match *self {
            SurfacePoint::Vertex(v) => mesh.vertex_faces(v).to_vec(),
            SurfacePoint::Edge { edge, .. } => mesh.edge_faces(edge).collect(),
            SurfacePoint::Face { face, .. } => vec![face],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    fn face0(bary: [f64; 3]) -> Result<SurfacePoint, PointError> {
        SurfacePoint::Face {
            face: FaceId(0),
            bary,
        }
        .validated(&shapes::cube())
    }

    #[test]
    fn barycentric_coordinates_near_f64_max_are_normalised_without_overflow() {
        let mesh = shapes::cube();
        let [_, b, c] = mesh.face(FaceId(0));
        let edge = mesh.edge_between(b, c).expect("an edge of face 0");
        // The sum overflowed to infinity, every coordinate became 0 and validation panicked.
        assert_eq!(
            face0([0.0, 1e308, 1e308]),
            Ok(SurfacePoint::Edge { edge, t: 0.5 })
        );
        let centroid = face0([f64::MAX; 3]).expect("a point of face 0");
        assert_eq!(
            centroid,
            SurfacePoint::Face {
                face: FaceId(0),
                bary: [1.0 / 3.0; 3]
            }
        );
    }

    #[test]
    fn barycentric_coordinates_are_homogeneous() {
        let centroid = face0([1.0; 3]);
        assert_eq!(face0([0.2; 3]), centroid);
        assert_eq!(face0([7.0; 3]), centroid);
        // Subnormal coordinates are as good as any others.
        assert_eq!(face0([f64::from_bits(1); 3]), centroid);
        assert_eq!(face0([0.0, 0.0, 3.0]), face0([0.0, 0.0, 1.0]));
    }

    #[test]
    fn barycentric_coordinates_that_name_no_point_are_refused() {
        for bary in [
            [0.0; 3],
            [-1.0, 1.0, 1.0],
            [f64::NAN, 1.0, 1.0],
            [f64::INFINITY, 1.0, 1.0],
        ] {
            assert!(
                matches!(face0(bary), Err(PointError::Barycentric { .. })),
                "{bary:?}"
            );
        }
    }
}
