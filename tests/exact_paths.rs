//! Paths with the backend's own numbers: on the unit cube, the shortest path between opposite
//! corners unfolds into the diagonal of a 1 x 2 rectangle, so it crosses the edge between its
//! two faces at the edge's middle, and its length is sqrt 5; the exact backend proves both.

use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::{Real, Ring, Sign};
use exact_geodesics::{
    propagate, ExactPath, GeodesicPath, PropagateOptions, Scalar, SurfacePoint, VertexId,
};

/// The path from the cube's corner 6 back to corner 0, with the backend's numbers and in f64,
/// and whether the propagation was certified.
fn diagonal<S: Scalar>() -> (ExactPath<S>, GeodesicPath, bool) {
    let cube = shapes::cube();
    let field = propagate::<S>(
        &cube,
        &[SurfacePoint::Vertex(VertexId(0))],
        &PropagateOptions::default(),
    )
    .expect("valid source");
    let corner = SurfacePoint::Vertex(VertexId(6));
    let exact = field.trace_back_exact(&corner).expect("reached");
    let plain = field.trace_back(&corner).expect("reached");
    (exact, plain, field.is_certified())
}

#[test]
fn the_cube_diagonal_crosses_its_edge_at_exactly_one_half() {
    let (exact, plain, certified) = diagonal::<Real>();
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
    assert!(certified);
    // The f64 path is the same path.
    assert_eq!(plain, exact.path);
}

#[test]
fn float_backends_give_their_offsets_too() {
    let (exact, plain, _) = diagonal::<f64>();
    assert_eq!(plain, exact.path);
    let crossings: Vec<f64> = exact.offsets.iter().flatten().copied().collect();
    assert_eq!(crossings.len(), 1);
    assert!((crossings[0] - 0.5).abs() < 1e-15);
    assert!((exact.distance - 5f64.sqrt()).abs() < 1e-15);
}
