//! A field that shares its mesh can be stored beside it, cloned, sent to another thread and
//! queried there, with the answers of the borrowed field; the cube's distances are closed forms.

use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::Real;
use exact_geodesics::{
    propagate, propagate_shared, GeodesicField, PropagateOptions, Scalar, SurfacePoint, TriMesh,
    VertexId,
};
use std::sync::Arc;

/// What a user stores: the mesh and a field on it, with no lifetime.
struct Stored<S: Scalar> {
    mesh: Arc<TriMesh>,
    field: GeodesicField<'static, S>,
}

fn corner() -> [SurfacePoint; 1] {
    [SurfacePoint::Vertex(VertexId(0))]
}

fn stored<S: Scalar>() -> Stored<S> {
    let mesh = Arc::new(shapes::cube());
    let field = propagate_shared::<S>(&mesh, &corner(), &PropagateOptions::default())
        .expect("valid source");
    Stored { mesh, field }
}

#[test]
fn a_stored_field_answers_as_the_borrowed_one() {
    let kept = stored::<f64>();
    let borrowed = propagate::<f64>(&kept.mesh, &corner(), &PropagateOptions::default())
        .expect("valid source");
    assert_eq!(kept.field.vertex_distances(), borrowed.vertex_distances());
    // The cube's far corner is sqrt 5 away, over two faces unfolded into a 1 x 2 rectangle.
    let far = kept.field.vertex_distance(VertexId(6));
    assert!((far - 5f64.sqrt()).abs() < 1e-12, "{far}");
    assert!(std::ptr::eq(kept.field.mesh(), &*kept.mesh));
}

#[test]
fn a_clone_goes_to_another_thread_and_traces_there() {
    let kept = stored::<Real>();
    let field = kept.field.clone();
    let length = std::thread::spawn(move || {
        field
            .trace_back(&SurfacePoint::Vertex(VertexId(6)))
            .expect("reached")
            .length()
    })
    .join()
    .expect("no panic");
    assert!((length - 5f64.sqrt()).abs() < 1e-12, "{length}");
    assert_eq!(kept.field.vertex_distance(VertexId(6)), 5f64.sqrt());
}

#[test]
fn a_field_is_shared_only_with_its_own_mesh() {
    let mesh = shapes::cube();
    let field =
        propagate::<f64>(&mesh, &corner(), &PropagateOptions::default()).expect("valid source");
    let copy = Arc::new(shapes::cube());
    assert!(field.clone().into_shared(copy).is_none());
}
