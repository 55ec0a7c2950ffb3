//! Degenerate meshes made outside the project's own generator (an independent corpus of
//! welded and unwelded coincident vertices, zero-area faces, inconsistent orientations,
//! rotations and scalings) on which a backend once broke an invariant of issue 10. Expected
//! values come from the coordinates (closed forms of the unfolded surface), never from the
//! engine.

use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{propagate, PropagateOptions, Scalar, SurfacePoint, TriMesh, VertexId};

fn distances<S: Scalar>(mesh: &TriMesh, source: u32) -> Vec<f64> {
    propagate::<S>(
        mesh,
        &[SurfacePoint::Vertex(VertexId(source))],
        &PropagateOptions::default(),
    )
    .expect("valid source")
    .vertex_distances()
}

/// The distances from `source` in all three backends, labelled.
fn every_backend(mesh: &TriMesh, source: u32) -> [(&'static str, Vec<f64>); 3] {
    [
        ("f64", distances::<f64>(mesh, source)),
        ("adaptive", distances::<Adaptive>(mesh, source)),
        ("exact", distances::<Real>(mesh, source)),
    ]
}

/// A sliver folded back onto its flat neighbour. Apex `v0` at height 1 over the line through
/// `v4`, `v5` (the origin) and `v1`, along `(0.8, -0.6)` rotated in floats (so the sliver
/// `(v4, v1, v5)` has an area of a few ulps); the face `(v5, v4, v3)` lies in the same plane,
/// and its edge with the sliver is traversed the same way by both (inconsistent orientation),
/// so their normals agree although they lie on the same side of that edge. Unfolded, the apex
/// lands at `(0.6, 0.8)`, opposite `v3 = (-0.6, -0.8)`, and the geodesic runs straight through
/// `v5`: d(v3) = 1 + 1 = 2. The exact backend joined the two faces into one flat region and
/// carried the apex's image unreflected onto `v3` itself: d(v3) = 1.1e-16.
#[test]
fn a_sliver_folded_onto_a_coplanar_face_is_unfolded_not_joined_to_it() {
    let mesh = TriMesh::new(
        vec![
            [0.0, 0.0, 1.0],
            [-0.8, 0.6, 0.0],
            [-0.8, 0.6, 0.0],
            [-0.6000000000000001, -0.7999999999999999, 0.0],
            [0.7999999999999999, -0.6000000000000001, 0.0],
            [0.0, 0.0, 0.0],
        ],
        vec![[0, 4, 1], [5, 4, 3], [4, 1, 5]],
    )
    .expect("usable mesh");
    for (backend, d) in every_backend(&mesh, 0) {
        assert!(
            (d[3] - 2.0).abs() <= 1e-12,
            "{backend}: d(v3) = {}, want 2",
            d[3]
        );
        assert_eq!(d[2], f64::INFINITY, "{backend}: v2 is used by no face");
    }
}
