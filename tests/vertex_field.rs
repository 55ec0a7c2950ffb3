//! `propagate_vertices` gives up the wedges of edges the front has passed: its vertex distances
//! and nearest sources are those of `propagate`, bit for bit, in every backend, while the
//! wedges it holds at once are fewer.

mod common;

use common::data_mesh;
use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{
    propagate, propagate_vertices, PropagateOptions, Scalar, SurfacePoint, TriMesh, VertexId,
};

/// Asserts that both runs agree at every vertex, and returns the peak wedge memory of each
/// (full run, vertices only).
fn same_vertices<S: Scalar>(
    mesh: &TriMesh,
    sources: &[u32],
    options: &PropagateOptions,
) -> [usize; 2] {
    let sources: Vec<_> = sources
        .iter()
        .map(|&v| SurfacePoint::Vertex(VertexId(v)))
        .collect();
    let full = propagate::<S>(mesh, &sources, options).expect("valid sources");
    let only = propagate_vertices::<S>(mesh, &sources, options).expect("valid sources");
    for v in (0..mesh.vertex_count() as u32).map(VertexId) {
        let (a, b) = (full.vertex_distance(v), only.vertex_distance(v));
        assert!(
            a.to_bits() == b.to_bits(),
            "{v:?}: {a} in the full run, {b} from vertices only"
        );
        assert_eq!(full.nearest_source(v), only.nearest_source(v), "{v:?}");
    }
    [full.stats().peak_wedge_bytes, only.stats().peak_wedge_bytes]
}

fn meshes() -> Vec<(&'static str, TriMesh)> {
    vec![
        ("icosphere 3", shapes::icosphere(3)),
        ("hull blob 100", data_mesh("hull_blob_100.obj")),
        ("mixed magnitudes 5", data_mesh("mixed_magnitudes_5.obj")),
        ("flat grid", shapes::grid(12, 9, 1.0, 0.7)),
        (
            "convex triangulation",
            shapes::random_convex_triangulation(7, 12, 40),
        ),
    ]
}

#[test]
fn vertex_distances_equal_the_full_run_in_f64_and_adaptive() {
    for (name, mesh) in meshes() {
        for options in [
            PropagateOptions::default(),
            PropagateOptions::default().with_max_distance(0.5),
        ] {
            for sources in [&[0][..], &[0, 5]] {
                eprintln!("{name}, {options:?}, sources {sources:?}");
                same_vertices::<f64>(&mesh, sources, &options);
                same_vertices::<Adaptive>(&mesh, sources, &options);
            }
        }
    }
}

#[test]
fn vertex_distances_equal_the_full_run_in_exact() {
    for mesh in [shapes::icosphere(1), data_mesh("hull_blob_60.obj")] {
        same_vertices::<Real>(&mesh, &[0], &PropagateOptions::default());
    }
}

#[test]
fn edges_behind_the_front_give_up_their_wedges() {
    let [full, only] =
        same_vertices::<f64>(&shapes::icosphere(4), &[0], &PropagateOptions::default());
    assert!(
        only * 2 < full,
        "peak wedge memory {only} from vertices only, {full} in full"
    );
}
