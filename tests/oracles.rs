//! The test oracles themselves are checked against hand-computed answers, so that the engine's
//! tests that rely on them can fail for the right reasons.

mod common;

use exact_geodesics::mesh::shapes;
use exact_geodesics::VertexId;

#[test]
fn brute_force_finds_hand_computed_polyhedron_distances() {
    let cube = shapes::cube();
    assert!((common::brute_force_vertex_distance(&cube, 0, 6, 6) - 5f64.sqrt()).abs() < 1e-12);
    assert!((common::brute_force_vertex_distance(&cube, 0, 2, 6) - 2f64.sqrt()).abs() < 1e-12);
    // Opposite vertices of the octahedron: two equilateral faces of side sqrt(2) unfolded into
    // a rhombus, whose long diagonal is sqrt(6) (shorter than 2 sqrt(2) along two edges).
    let octahedron = shapes::octahedron();
    assert!(
        (common::brute_force_vertex_distance(&octahedron, 0, 1, 6) - 6f64.sqrt()).abs() < 1e-12
    );
    let tetrahedron = shapes::tetrahedron();
    assert!(
        (common::brute_force_vertex_distance(&tetrahedron, 0, 3, 4) - 8f64.sqrt()).abs() < 1e-12
    );
}

#[test]
fn brute_force_is_euclidean_on_a_planar_grid_and_bends_on_an_l_shape() {
    let grid = shapes::grid(3, 2, 3.0, 2.0);
    let far = common::brute_force_vertex_distance(&grid, 0, 11, 12);
    assert!((far - 13f64.sqrt()).abs() < 1e-12, "{far}");
    let l = shapes::l_shape(1);
    let find = |p: [f64; 3]| {
        (0..l.vertex_count())
            .find(|&v| l.position(VertexId(v as u32)) == p)
            .expect("a grid vertex")
    };
    let (a, b) = (find([2.0, 0.0, 0.0]), find([0.0, 2.0, 0.0]));
    let bent = common::brute_force_vertex_distance(&l, a, b, 12);
    assert!((bent - 2.0 * 2f64.sqrt()).abs() < 1e-12, "{bent}");
}

#[test]
fn edge_graph_is_an_upper_bound_of_the_brute_force() {
    let mesh = shapes::icosahedron();
    let graph = common::edge_graph_dijkstra(&mesh, 0);
    for (t, g) in graph.iter().enumerate() {
        let exact = common::brute_force_vertex_distance(&mesh, 0, t, 8);
        assert!(exact <= g + 1e-12);
    }
    // Vertex 3 is antipodal to vertex 0: three edges of length 2 away, and strictly closer
    // across the faces.
    assert!((graph[3] - 6.0).abs() < 1e-12, "{}", graph[3]);
    assert!(common::brute_force_vertex_distance(&mesh, 0, 3, 8) < 6.0 - 0.1);
}
