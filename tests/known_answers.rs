//! Known answers on closed surfaces: unfoldings of convex polyhedra (checked against a brute-force
//! search over face sequences) and the paper's Example 4.

mod common;

use exact_geodesics::mesh::shapes;
use exact_geodesics::{propagate, PropagateOptions, SurfacePoint, TriMesh, VertexId};

fn all_pairs_match_brute_force(name: &str, mesh: &TriMesh, max_faces: usize) {
    for s in 0..mesh.vertex_count() {
        let field = propagate::<f64>(
            mesh,
            &[SurfacePoint::Vertex(VertexId(s as u32))],
            &PropagateOptions::default(),
        )
        .expect("valid source");
        for t in 0..mesh.vertex_count() {
            let want = common::brute_force_vertex_distance(mesh, s, t, max_faces);
            let got = field.vertex_distance(VertexId(t as u32));
            assert!(
                (got - want).abs() <= 1e-9 * want.max(1.0),
                "{name}: d(v{s}, v{t}) = {got}, brute force {want}"
            );
        }
        let coverage = field.check_coverage();
        assert!(coverage.issues.is_empty(), "{name}: {:?}", coverage.issues);
    }
}

#[test]
fn tetrahedron_matches_unfolding_search() {
    all_pairs_match_brute_force("tetrahedron", &shapes::tetrahedron(), 6);
}

#[test]
fn cube_matches_unfolding_search() {
    let cube = shapes::cube();
    all_pairs_match_brute_force("cube", &cube, 8);
    let field = propagate::<f64>(
        &cube,
        &[SurfacePoint::Vertex(VertexId(0))],
        &PropagateOptions::default(),
    )
    .expect("valid source");
    let far = (0..8)
        .map(|v| field.vertex_distance(VertexId(v)))
        .fold(0.0, f64::max);
    assert!(
        (far - 5f64.sqrt()).abs() < 1e-12,
        "opposite corner of the unit cube"
    );
}

#[test]
fn octahedron_matches_unfolding_search() {
    all_pairs_match_brute_force("octahedron", &shapes::octahedron(), 8);
}

#[test]
fn icosahedron_matches_unfolding_search() {
    all_pairs_match_brute_force("icosahedron", &shapes::icosahedron(), 10);
}

#[test]
fn example4_vertex_distances_match_the_paper() {
    // [LZT Example 4], source v2: the wedge table gives d(v5) = 1.826, d(v4) = 2.778 and
    // d(v13) = 1.0 + 1.934 = 2.934 (through the pseudo-source v6).
    let mesh = shapes::paper_example4();
    let field = propagate::<f64>(
        &mesh,
        &[SurfacePoint::Vertex(VertexId(2))],
        &PropagateOptions::default(),
    )
    .expect("valid source");
    for (v, want) in [(5, 1.826), (4, 2.778), (13, 2.934)] {
        let got = field.vertex_distance(VertexId(v));
        assert!((got - want).abs() < 5e-4, "d(v{v}) = {got}, paper {want}");
    }
    let d13 = field.vertex_distance(VertexId(13));
    let d6 = field.vertex_distance(VertexId(6));
    let edge = ((0.5f64 - 1.0).powi(2) * 2.0 + 1.8f64.powi(2)).sqrt();
    assert!((d6 - 1.0).abs() < 1e-12 && (d13 - (d6 + edge)).abs() < 1e-12);
    for v in 0..14 {
        let want = common::brute_force_vertex_distance(&mesh, 2, v, 9);
        let got = field.vertex_distance(VertexId(v as u32));
        assert!(
            (got - want).abs() < 1e-9,
            "d(v2, v{v}) = {got}, brute force {want}"
        );
    }
}
