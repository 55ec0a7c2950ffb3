//! Bad input to the library: typed errors, never a panic.

use exact_geodesics::mesh::shapes;
use exact_geodesics::{
    propagate, EdgeId, FaceId, MeshError, PointError, PropagateOptions, SurfacePoint, TriMesh,
    VertexId,
};

fn triangle() -> Vec<[f64; 3]> {
    vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
}

#[test]
fn non_finite_coordinates_are_refused() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let mut p = triangle();
        p[1][2] = bad;
        assert!(matches!(
            TriMesh::new(p, vec![[0, 1, 2]]),
            Err(MeshError::NonFiniteCoordinate { vertex: 1, .. })
        ));
    }
}

#[test]
fn a_mesh_without_faces_is_refused() {
    assert_eq!(
        TriMesh::new(triangle(), Vec::new()).err(),
        Some(MeshError::NoFaces { vertices: 3 })
    );
    assert_eq!(
        TriMesh::new(Vec::<[f64; 3]>::new(), Vec::new()).err(),
        Some(MeshError::NoFaces { vertices: 0 })
    );
}

#[test]
fn out_of_range_and_repeated_indices_are_refused() {
    assert!(matches!(
        TriMesh::new(triangle(), vec![[0, 1, 3]]),
        Err(MeshError::VertexIndexOutOfRange {
            face: 0,
            index: 3,
            ..
        })
    ));
    assert!(matches!(
        TriMesh::new(triangle(), vec![[0, 1, 1]]),
        Err(MeshError::RepeatedVertex { face: 0, vertex: 1 })
    ));
}

#[test]
fn non_manifold_edges_are_refused_only_by_the_strict_check() {
    let mut p = triangle();
    p.extend([[0.0, -1.0, 0.0], [0.0, 0.0, 1.0]]);
    let mesh = TriMesh::new(p, vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]])
        .expect("three faces on 0-1 are usable");
    let err = mesh.require_manifold().expect_err("three faces on 0-1");
    assert!(
        matches!(
            err,
            MeshError::NonManifoldEdge {
                a: 0,
                b: 1,
                face_count: 3,
                ..
            }
        ),
        "{err}"
    );
}

#[test]
fn duplicate_faces_are_refused_only_by_the_strict_check() {
    let mut p = triangle();
    p.push([1.0, 1.0, 0.0]);
    let mesh = TriMesh::new(p, vec![[0, 1, 2], [1, 3, 2], [2, 1, 0]]).expect("a copy is usable");
    assert_eq!(
        mesh.require_manifold(),
        Err(MeshError::DuplicateFace {
            face: 2,
            copy_of: 0
        })
    );
}

#[test]
fn bad_sources_are_typed_errors() {
    let mesh = shapes::cube();
    let options = PropagateOptions::default();
    let cases = [
        (SurfacePoint::Vertex(VertexId(8)), "vertex"),
        (
            SurfacePoint::Edge {
                edge: EdgeId(999),
                t: 0.5,
            },
            "edge",
        ),
        (
            SurfacePoint::Edge {
                edge: EdgeId(0),
                t: f64::NAN,
            },
            "parameter",
        ),
        (
            SurfacePoint::Face {
                face: FaceId(12),
                bary: [1.0, 0.0, 0.0],
            },
            "face",
        ),
        (
            SurfacePoint::Face {
                face: FaceId(0),
                bary: [-0.5, 1.0, 0.5],
            },
            "barycentric",
        ),
        (
            SurfacePoint::Face {
                face: FaceId(0),
                bary: [0.0, 0.0, 0.0],
            },
            "barycentric",
        ),
    ];
    for (source, what) in cases {
        let err = propagate::<f64>(&mesh, &[source], &options).err();
        assert!(err.is_some(), "{what}: {source:?} accepted");
    }
    assert_eq!(
        propagate::<f64>(&mesh, &[], &options).err(),
        Some(PointError::NoSource)
    );
    let field =
        propagate::<f64>(&mesh, &[SurfacePoint::Vertex(VertexId(0))], &options).expect("valid");
    assert!(field
        .distance_at(&SurfacePoint::Vertex(VertexId(100)))
        .is_err());
    assert!(field
        .trace_back(&SurfacePoint::Vertex(VertexId(100)))
        .is_err());
}

#[test]
fn a_negative_or_nan_max_distance_is_an_error_not_no_limit() {
    let mesh = exact_geodesics::mesh::shapes::cube();
    let source = [exact_geodesics::SurfacePoint::Vertex(
        exact_geodesics::VertexId(0),
    )];
    for bad in [-1.0, f64::NAN, f64::NEG_INFINITY] {
        let options = exact_geodesics::PropagateOptions::default().with_max_distance(bad);
        let result = exact_geodesics::propagate::<f64>(&mesh, &source, &options);
        assert!(
            matches!(result, Err(exact_geodesics::PointError::MaxDistance { .. })),
            "max distance {bad}"
        );
    }
    // Zero and infinity are limits: the source alone, and everything.
    for (limit, reached) in [(0.0, 1), (f64::INFINITY, 8)] {
        let options = exact_geodesics::PropagateOptions::default().with_max_distance(limit);
        let field = exact_geodesics::propagate::<f64>(&mesh, &source, &options).expect("valid");
        let finite = field
            .vertex_distances()
            .iter()
            .filter(|d| d.is_finite())
            .count();
        assert_eq!(finite, reached, "max distance {limit}");
    }
}
