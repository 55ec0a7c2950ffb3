//! Exactly flat regions (issue 13): one image of the source lights the whole region, so the
//! wedges of an edge stay a few whatever the size of the region, and the distances are the
//! straight-line ones. On a flat grid from a corner, every vertex is visible from the source.

use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{propagate, PropagateOptions, Scalar, SurfacePoint, VertexId};

/// The mean number of wedges per edge of an `n` by `n` unit grid lit from its corner (vertex
/// 0), after checking every vertex's distance against the straight line.
fn wedges_per_edge_on_grid<S: Scalar>(n: usize) -> f64 {
    let mesh = shapes::grid(n, n, 1.0, 1.0);
    let source = [SurfacePoint::Vertex(VertexId(0))];
    let field = propagate::<S>(&mesh, &source, &PropagateOptions::default()).expect("valid");
    for v in 0..mesh.vertex_count() {
        let v = VertexId(v as u32);
        // Vertex j (n + 1) + i lies at (i / n, j / n): its distance from the corner is the
        // straight line, a closed form independent of the program.
        let (i, j) = (v.0 as usize % (n + 1), v.0 as usize / (n + 1));
        let want = (i as f64).hypot(j as f64) / n as f64;
        let got = field.vertex_distance(v);
        assert!(
            (got - want).abs() <= 1e-13 * want.max(1.0),
            "grid {n}: vertex ({i}, {j}) at {got}, the straight line gives {want}"
        );
    }
    let counts = field.wedge_counts();
    counts.iter().sum::<usize>() as f64 / counts.len() as f64
}

/// Bounded by a constant: a vertex behind an edge no longer cuts the wedge of the image that
/// passes it (before issue 13: 3.1, 10.8 and 43.5 on grids of side 12, 60 and 150 in `f64`,
/// 2.7, 9.5 and 34.2 in the adaptive backend, 1.3 and 2.1 on sides 6 and 12 in the exact one;
/// the float backends also missed the straight line by up to 0.9 % on grids of side 40 up). Near the boundary line through the corner, the boundary vertices'
/// own wedges still leave slivers along it (up to 88 on one edge of a 150 by 150 grid in the
/// adaptive backend), hence the mean.
const FEW: f64 = 1.25;

#[test]
fn flat_grid_keeps_few_wedges_per_edge_in_f64() {
    for n in [12, 60, 150] {
        let most = wedges_per_edge_on_grid::<f64>(n);
        assert!(most <= FEW, "grid {n}: {most} wedges per edge");
    }
}

#[test]
fn flat_grid_keeps_few_wedges_per_edge_in_adaptive() {
    for n in [12, 60, 150] {
        let most = wedges_per_edge_on_grid::<Adaptive>(n);
        assert!(most <= FEW, "grid {n}: {most} wedges per edge");
    }
}

#[test]
fn flat_grid_keeps_few_wedges_per_edge_in_exact() {
    for n in [6, 12] {
        let most = wedges_per_edge_on_grid::<Real>(n);
        assert!(most <= FEW, "grid {n}: {most} wedges per edge");
    }
}
