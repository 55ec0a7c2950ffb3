//! Queries at and next to sources inside edges and faces: the source point itself is at
//! distance 0, and a point of a source's edge is reached along the edge, whatever other
//! sources trimmed the source's wedges (found from the Python package's tests).

use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{propagate, EdgeId, FaceId, PropagateOptions, Scalar, SurfacePoint};

fn check<S: Scalar>() {
    let mesh = shapes::icosphere(2);
    let edge = EdgeId(10);
    let on_edge = SurfacePoint::Edge { edge, t: 0.25 };
    let in_face = SurfacePoint::Face {
        face: FaceId(7),
        bary: [0.25, 0.5, 0.25],
    };
    let [a, b] = mesh.edge(edge).vertices.map(|v| mesh.position(v));
    let length = (0..3).map(|i| (b[i] - a[i]).powi(2)).sum::<f64>().sqrt();
    for sources in [
        vec![on_edge],
        vec![on_edge, in_face],
        vec![in_face, on_edge],
    ] {
        let field = propagate::<S>(&mesh, &sources, &PropagateOptions::default()).expect("sources");
        for source in &sources {
            assert_eq!(
                field.distance_at(source),
                Ok(0.0),
                "{source:?} of {sources:?}"
            );
            let path = field.trace_back(source).expect("a path");
            assert_eq!((path.distance, path.length()), (0.0, 0.0));
        }
        // Straight along the edge from the source at t = 0.25.
        let next = SurfacePoint::Edge { edge, t: 0.2501 };
        let d = field.distance_at(&next).expect("a point of the mesh");
        assert!(
            (d - 1e-4 * length).abs() <= 1e-12 * length,
            "{d} of {sources:?}"
        );
    }
}

#[test]
fn sources_inside_edges_and_faces_are_found_in_every_backend() {
    check::<f64>();
    check::<Adaptive>();
    check::<Real>();
}
