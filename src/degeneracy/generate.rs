//! Seeded degenerate meshes: the inputs on which a geodesic engine is most tempted to answer
//! wrongly without saying so (coincident vertices, zero-area faces, straight paths through
//! vertices, slivers, exact ties, extreme scales, bowties, non-manifold edges, several
//! components).
//!
//! Every mesh is a deterministic function of its kind and seed (through
//! [`SplitMix64`](crate::mesh::shapes::SplitMix64)) and is accepted by [`TriMesh::new`].
//! Coordinates are dyadic rationals with few bits wherever exactness matters, so that points
//! meant to be collinear, coincident or mirror images are exactly so in `f64`.

use super::{bumpy, figures};
use crate::mesh::shapes::SplitMix64;
use crate::mesh::{TriMesh, VertexId};
use serde::Serialize;

/// The kinds of degeneracy in the corpus.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DegenerateKind {
    /// A bumpy grid in which interior vertices are split in two at the same position, joined
    /// by a zero-length edge and two faces with two coincident corners (or, sometimes, left
    /// apart as a crack).
    CoincidentVertices,
    /// A bumpy grid with T-junctions closed by faces whose three distinct corners are exactly
    /// collinear, inside the mesh and on its boundary.
    ZeroAreaFaces,
    /// An exactly flat grid of random integer size and cell shape, with rising, falling or
    /// mixed diagonals, in a plane with an integer normal: straight paths run exactly through
    /// vertices.
    FlatGrid,
    /// An exactly flat fan (one or two square rings of integer points around a centre): the
    /// straight path between opposite ring vertices runs exactly through the centre.
    FlatFan,
    /// A bumpy grid with slivers: a vertex inserted within `1e-9` of an edge (the face on that
    /// edge has angles below `1e-6` degrees) or a vertex split into two `1e-9` apart (needles).
    Slivers,
    /// A pyramid (open or closed) or bipyramid over a regular polygon exactly symmetric in the
    /// xz-plane, apex on the axis, possibly subdivided: exact ties of two mirror paths.
    Pyramid,
    /// A bumpy grid scaled exactly by `2^k`, `-600 <= k <= 600`.
    Scaled,
    /// A bumpy grid whose x coordinates are multiplied, vertex by vertex, by random powers of
    /// ten from `1e-8` to `1e8`.
    MixedMagnitudes,
    /// Two grids meeting at one corner vertex, or fans around one vertex: a vertex whose faces
    /// form several fans.
    Bowtie,
    /// Several components (grids, bipyramids, single triangles) plus vertices no face uses,
    /// some at the position of a used vertex; vertex numbers shuffled.
    Components,
    /// Edges shared by more than two faces: a book of three to five bumpy pages sharing one
    /// row of edges (the spine), or a bumpy grid with fins standing on some of its edges;
    /// sometimes with a copy of a face.
    NonManifold,
}

impl DegenerateKind {
    /// Every kind, in the order the corpus cycles through them.
    pub const ALL: [DegenerateKind; 11] = [
        DegenerateKind::CoincidentVertices,
        DegenerateKind::ZeroAreaFaces,
        DegenerateKind::FlatGrid,
        DegenerateKind::FlatFan,
        DegenerateKind::Slivers,
        DegenerateKind::Pyramid,
        DegenerateKind::Scaled,
        DegenerateKind::MixedMagnitudes,
        DegenerateKind::Bowtie,
        DegenerateKind::Components,
        DegenerateKind::NonManifold,
    ];

    /// The kind's name in reports (snake case, as serialized).
    pub fn name(self) -> &'static str {
        match self {
            DegenerateKind::CoincidentVertices => "coincident_vertices",
            DegenerateKind::ZeroAreaFaces => "zero_area_faces",
            DegenerateKind::FlatGrid => "flat_grid",
            DegenerateKind::FlatFan => "flat_fan",
            DegenerateKind::Slivers => "slivers",
            DegenerateKind::Pyramid => "pyramid",
            DegenerateKind::Scaled => "scaled",
            DegenerateKind::MixedMagnitudes => "mixed_magnitudes",
            DegenerateKind::Bowtie => "bowtie",
            DegenerateKind::Components => "components",
            DegenerateKind::NonManifold => "non_manifold",
        }
    }
}

/// How large the generated meshes may be.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MeshSize {
    /// At most 150 faces.
    Full,
    /// At most 100 faces, for the exact backend (a fifth of a second per case on average).
    Small,
    /// At most 20 faces: the exact backend's size until it became fast enough for `Small`; the
    /// regressions found then name meshes of this size.
    Tiny,
}

impl MeshSize {
    /// The most faces a mesh of this size has.
    pub fn max_faces(self) -> usize {
        match self {
            MeshSize::Full => 150,
            MeshSize::Small => 100,
            MeshSize::Tiny => 20,
        }
    }
}

/// A generated degenerate mesh and the vertices at its degeneracy.
#[derive(Clone, Debug)]
pub struct DegenerateCase {
    /// What kind of degeneracy the mesh has.
    pub kind: DegenerateKind,
    /// The seed it was generated from.
    pub seed: u64,
    /// The mesh.
    pub mesh: TriMesh,
    /// Vertices at the degeneracy (a split vertex and its copy, the corners of a zero-area
    /// face, a bowtie vertex, an apex, a vertex no face uses, ...): the sources most worth
    /// trying.
    pub focus: Vec<VertexId>,
}

/// The degenerate mesh of `kind` generated from `seed`, with at most `size.max_faces()` faces.
///
/// # Example
/// ```
/// use exact_geodesics::degeneracy::{degenerate_case, DegenerateKind, MeshSize};
/// let case = degenerate_case(DegenerateKind::ZeroAreaFaces, 7, MeshSize::Small);
/// assert!(!case.mesh.validation().zero_area_faces.is_empty());
/// assert!(case.mesh.face_count() <= MeshSize::Small.max_faces());
/// ```
pub fn degenerate_case(kind: DegenerateKind, seed: u64, size: MeshSize) -> DegenerateCase {
    let mut rng = SplitMix64::new(seed ^ (kind as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15));
    let max_faces = size.max_faces();
    let rng = &mut rng;
    let (soup, focus) = match kind {
        DegenerateKind::CoincidentVertices => bumpy::coincident_vertices(rng, max_faces),
        DegenerateKind::ZeroAreaFaces => bumpy::zero_area_faces(rng, max_faces),
        DegenerateKind::FlatGrid => figures::flat_grid(rng, max_faces),
        DegenerateKind::FlatFan => figures::flat_fan(rng, max_faces),
        DegenerateKind::Slivers => bumpy::slivers(rng, max_faces),
        DegenerateKind::Pyramid => figures::pyramid(rng, max_faces),
        DegenerateKind::Scaled => bumpy::scaled(rng, max_faces),
        DegenerateKind::MixedMagnitudes => bumpy::mixed_magnitudes(rng, max_faces),
        DegenerateKind::Bowtie => figures::bowtie(rng, max_faces),
        DegenerateKind::Components => figures::components(rng, max_faces),
        DegenerateKind::NonManifold => figures::non_manifold(rng, max_faces),
    };
    debug_assert!(soup.faces.len() <= max_faces, "{kind:?} seed {seed}");
    let mut focus: Vec<VertexId> = focus.into_iter().map(VertexId).collect();
    focus.sort_unstable();
    focus.dedup();
    DegenerateCase {
        kind,
        seed,
        mesh: soup.into_mesh(),
        focus,
    }
}

/// The degenerate mesh of `kind` generated from `seed`, at most 150 faces
/// ([`MeshSize::Full`]).
///
/// # Example
/// ```
/// use exact_geodesics::degeneracy::{degenerate_mesh, DegenerateKind};
/// let mesh = degenerate_mesh(DegenerateKind::Bowtie, 1);
/// assert!(!mesh.validation().non_manifold_vertices.is_empty());
/// ```
pub fn degenerate_mesh(kind: DegenerateKind, seed: u64) -> TriMesh {
    degenerate_case(kind, seed, MeshSize::Full).mesh
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::FaceId;
    use glam::DVec3;

    const SEEDS: std::ops::Range<u64> = 0..40;

    fn cases(kind: DegenerateKind) -> impl Iterator<Item = DegenerateCase> {
        SEEDS.flat_map(move |seed| {
            [MeshSize::Full, MeshSize::Small].map(|size| degenerate_case(kind, seed, size))
        })
    }

    fn corners(mesh: &TriMesh, f: usize) -> [DVec3; 3] {
        mesh.face(FaceId(f as u32)).map(|v| mesh.position(v))
    }

    /// Whether two distinct vertices used by faces share a position.
    fn has_coincident_used_vertices(mesh: &TriMesh) -> bool {
        let used: Vec<usize> = (0..mesh.vertex_count())
            .filter(|&v| !mesh.vertex_faces(VertexId(v as u32)).is_empty())
            .collect();
        used.iter().enumerate().any(|(i, &u)| {
            used[i + 1..]
                .iter()
                .any(|&w| mesh.positions()[u] == mesh.positions()[w])
        })
    }

    /// The smallest corner angle of any face, in degrees.
    fn smallest_angle_degrees(mesh: &TriMesh) -> f64 {
        (0..mesh.face_count())
            .flat_map(|f| {
                let p = corners(mesh, f);
                (0..3).map(move |i| {
                    let (u, w) = (p[(i + 1) % 3] - p[i], p[(i + 2) % 3] - p[i]);
                    let cross = u.cross(w);
                    cross
                        .x
                        .hypot(cross.y)
                        .hypot(cross.z)
                        .atan2(u.dot(w))
                        .to_degrees()
                })
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// Whether every vertex lies exactly in the plane of the first face.
    fn exactly_flat(mesh: &TriMesh) -> bool {
        let [o, a, b] = corners(mesh, 0);
        let n = (a - o).cross(b - o);
        mesh.positions().iter().all(|&p| n.dot(p - o) == 0.0)
    }

    #[test]
    fn every_kind_is_deterministic_and_within_its_face_budget() {
        for kind in DegenerateKind::ALL {
            for seed in SEEDS {
                for size in [MeshSize::Full, MeshSize::Small, MeshSize::Tiny] {
                    let case = degenerate_case(kind, seed, size);
                    assert!(
                        case.mesh.face_count() <= size.max_faces(),
                        "{kind:?} {seed}"
                    );
                    let again = degenerate_case(kind, seed, size);
                    assert_eq!(again.mesh.positions(), case.mesh.positions());
                    assert_eq!(again.mesh.faces(), case.mesh.faces());
                    assert!(case
                        .focus
                        .iter()
                        .all(|v| v.index() < case.mesh.vertex_count()));
                }
            }
        }
    }

    #[test]
    fn coincident_vertices_share_positions_and_some_faces_two_corners() {
        let mut two_coincident_corners = 0;
        for case in cases(DegenerateKind::CoincidentVertices) {
            assert!(
                has_coincident_used_vertices(&case.mesh),
                "seed {}",
                case.seed
            );
            two_coincident_corners += (0..case.mesh.face_count())
                .filter(|&f| {
                    let p = corners(&case.mesh, f);
                    p[0] == p[1] || p[1] == p[2] || p[2] == p[0]
                })
                .count();
        }
        assert!(two_coincident_corners > 0);
    }

    #[test]
    fn zero_area_faces_have_three_distinct_collinear_corners() {
        let mut on_boundary = 0;
        for case in cases(DegenerateKind::ZeroAreaFaces) {
            let mesh = &case.mesh;
            let flat = &mesh.validation().zero_area_faces;
            // Two insertions at one point from both sides of an edge also make faces with two
            // coincident corners; at least one face has three distinct ones.
            let distinct = flat.iter().any(|&f| {
                let p = corners(mesh, f.index());
                p[0] != p[1] && p[1] != p[2] && p[2] != p[0]
            });
            assert!(distinct, "seed {}", case.seed);
            on_boundary += flat
                .iter()
                .filter(|&&f| {
                    mesh.face_edges(f)
                        .iter()
                        .any(|&e| mesh.edge(e).is_boundary())
                })
                .count();
        }
        assert!(on_boundary > 0);
    }

    #[test]
    fn flat_grids_and_fans_are_exactly_flat_with_integer_coordinates() {
        for kind in [DegenerateKind::FlatGrid, DegenerateKind::FlatFan] {
            for case in cases(kind) {
                assert!(exactly_flat(&case.mesh), "{kind:?} seed {}", case.seed);
                assert!(case.mesh.positions().iter().all(|&p| p.trunc() == p));
            }
        }
    }

    #[test]
    fn flat_fans_have_a_straight_path_through_their_centre() {
        for case in cases(DegenerateKind::FlatFan) {
            let p = case.mesh.positions();
            let centre = p[0];
            let through = p
                .iter()
                .any(|u| p.iter().any(|w| u != w && u + w == 2.0 * centre));
            assert!(through, "seed {}", case.seed);
        }
    }

    #[test]
    fn slivers_have_angles_below_1e_6_degrees() {
        for case in cases(DegenerateKind::Slivers) {
            let angle = smallest_angle_degrees(&case.mesh);
            assert!(angle < 1e-6, "seed {}: {angle}", case.seed);
        }
    }

    #[test]
    fn pyramids_are_exactly_mirror_symmetric() {
        for case in cases(DegenerateKind::Pyramid) {
            let p = case.mesh.positions();
            for q in p {
                assert!(
                    p.contains(&DVec3::new(q.x, -q.y, q.z)),
                    "seed {}: {q:?}",
                    case.seed
                );
            }
        }
    }

    #[test]
    fn scaled_grids_reach_both_ends_of_the_range() {
        let extent = |case: &DegenerateCase| {
            case.mesh
                .positions()
                .iter()
                .fold(0.0, |m: f64, p| m.max(p.abs().max_element()))
        };
        let extents: Vec<f64> = cases(DegenerateKind::Scaled).map(|c| extent(&c)).collect();
        assert!(extents.iter().any(|&e| e > 2f64.powi(500)));
        assert!(extents.iter().any(|&e| e < 2f64.powi(-500)));
        assert!(extents.iter().all(|&e| e > 0.0 && e.is_finite()));
    }

    #[test]
    fn mixed_magnitudes_span_1e_8_to_1e8_in_x() {
        let (mut smallest, mut largest) = (f64::INFINITY, 0.0f64);
        for case in cases(DegenerateKind::MixedMagnitudes) {
            let xs = case.mesh.positions().iter().map(|p| p.x.abs());
            let (lo, hi) = xs.fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            });
            assert!(hi / lo > 1e6, "seed {}: {lo} .. {hi}", case.seed);
            (smallest, largest) = (smallest.min(lo), largest.max(hi));
        }
        // x runs over [1, 10] before its factor, so the factors' ends show as these bounds.
        assert!(smallest < 1e-7 && largest >= 1e8, "{smallest} .. {largest}");
    }

    #[test]
    fn bowties_have_a_non_manifold_vertex() {
        for case in cases(DegenerateKind::Bowtie) {
            let bowties = &case.mesh.validation().non_manifold_vertices;
            assert!(!bowties.is_empty(), "seed {}", case.seed);
            assert!(bowties.iter().all(|v| case.focus.contains(v)));
        }
    }

    #[test]
    fn non_manifold_meshes_have_an_edge_with_more_than_two_faces_at_their_focus() {
        let mut copies = 0;
        for case in cases(DegenerateKind::NonManifold) {
            let report = case.mesh.validation();
            assert!(!report.non_manifold_edges.is_empty(), "seed {}", case.seed);
            assert!(report
                .non_manifold_edges
                .iter()
                .any(|e| e.vertices.iter().any(|v| case.focus.contains(v))));
            copies += report.duplicate_faces.len();
        }
        assert!(copies > 0);
    }

    #[test]
    fn components_come_with_vertices_no_face_uses() {
        for case in cases(DegenerateKind::Components) {
            let report = case.mesh.validation();
            assert!(report.components >= 2, "seed {}", case.seed);
            assert!(
                !report.unreferenced_vertices.is_empty(),
                "seed {}",
                case.seed
            );
        }
    }
}
