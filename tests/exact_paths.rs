//! Paths with the backend's own numbers: on the unit cube, the shortest path between opposite
//! corners unfolds into the diagonal of a 1 x 2 rectangle, so it crosses the edge between its
//! two faces at the edge's middle, and its length is sqrt 5; the exact backend proves both.

use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::{Real, Ring, Sign};
use exact_geodesics::{propagate, PropagateOptions, Scalar, SurfacePoint, VertexId};

#[test]
fn the_cube_diagonal_crosses_its_edge_at_exactly_one_half() {
    let cube = shapes::cube();
    let field = propagate::<Real>(
        &cube,
        &[SurfacePoint::Vertex(VertexId(0))],
        &PropagateOptions::default(),
    )
    .expect("valid source");
    let exact = field
        .trace_back_exact(&SurfacePoint::Vertex(VertexId(6)))
        .expect("reached");
    assert_eq!(exact.offsets.len(), exact.path.simplices.len());
    let crossings: Vec<&Real> = exact.offsets.iter().flatten().collect();
    assert_eq!(crossings.len(), 1, "{:?}", exact.path.simplices);
    let half = Real::from_f64(0.5);
    assert_eq!((crossings[0].clone() - &half).sign(), Sign::Zero);
    let five = Real::from_f64(5.0);
    assert_eq!(
        (exact.distance.clone() * &exact.distance - &five).sign(),
        Sign::Zero
    );
    assert!(field.is_certified());
    // The f64 path is the same path.
    let plain = field
        .trace_back(&SurfacePoint::Vertex(VertexId(6)))
        .expect("reached");
    assert_eq!(plain, exact.path);
}

#[test]
fn float_backends_give_their_offsets_too() {
    let cube = shapes::cube();
    let field = propagate::<f64>(
        &cube,
        &[SurfacePoint::Vertex(VertexId(0))],
        &PropagateOptions::default(),
    )
    .expect("valid source");
    let exact = field
        .trace_back_exact(&SurfacePoint::Vertex(VertexId(6)))
        .expect("reached");
    let crossings: Vec<f64> = exact.offsets.iter().flatten().copied().collect();
    assert_eq!(crossings.len(), 1);
    assert!((crossings[0] - 0.5).abs() < 1e-15);
    assert!((exact.distance - 5f64.sqrt()).abs() < 1e-15);
}
