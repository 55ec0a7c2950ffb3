//! Two threads for one source vertex (`PropagateOptions::threads`): its directions split into two
//! sectors propagated at once, each engine giving up what the other's paths beat. The distances
//! must be the one-thread run's (up to the last bits, where geodesics from the two sectors tie)
//! and the known answers, round a closed fan of faces and across a boundary vertex's open one;
//! runs that cannot be split (other sources, stop points, the exact backend, a source with no
//! fan of faces, edge lengths spanning more than 2^20) run on one thread.

mod common;

use common::{brute_force_vertex_distances, data_mesh, strategies::degenerate_case};
use exact_geodesics::degeneracy::{degenerate_mesh, relatively_close};
use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{
    propagate_vertices, PropagateOptions, Scalar, SurfacePoint, TriMesh, VertexField, VertexId,
};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

fn run<S: Scalar>(mesh: &TriMesh, source: u32, threads: usize) -> VertexField<'_, S> {
    let options = PropagateOptions::default().with_threads(threads);
    propagate_vertices::<S>(mesh, &[SurfacePoint::Vertex(VertexId(source))], &options)
        .expect("a vertex of the mesh")
}

/// Asserts that two sectors give the one-thread distances and nearest sources, and returns how
/// many engines ran.
fn same_as_one_thread<S: Scalar>(mesh: &TriMesh, source: u32) -> u32 {
    let (one, two) = (run::<S>(mesh, source, 1), run::<S>(mesh, source, 2));
    for v in (0..mesh.vertex_count() as u32).map(VertexId) {
        let (a, b) = (one.vertex_distance(v), two.vertex_distance(v));
        assert!(
            relatively_close(a, b, 1e-12),
            "from v{source}, {v:?}: {a} on one thread, {b} on two"
        );
        assert_eq!(one.nearest_source(v), two.nearest_source(v), "{v:?}");
    }
    assert_eq!(one.stats().sectors, 1);
    two.stats().sectors
}

/// Meshes and the engines a two-thread run from one of their vertices uses: one where the
/// edge lengths span more than 2^20 (`mixed_magnitudes_5.obj` spans 1.0e10).
fn meshes() -> Vec<(&'static str, TriMesh, u32)> {
    vec![
        ("icosphere 3", shapes::icosphere(3), 2),
        ("hull blob 100", data_mesh("hull_blob_100.obj"), 2),
        ("torus", data_mesh("parametric_torus.obj"), 2),
        ("bour surface", data_mesh("bour_surface.obj"), 2),
        ("mixed magnitudes 5", data_mesh("mixed_magnitudes_5.obj"), 1),
        ("delaunay terrain", data_mesh("delaunay_terrain.obj"), 2),
    ]
}

#[test]
fn two_sectors_give_the_one_thread_distances_in_f64_and_adaptive() {
    for (name, mesh, most) in meshes() {
        let mut split = 0;
        let step = (mesh.vertex_count() / 7).max(1);
        for source in (0..mesh.vertex_count() as u32).step_by(step) {
            eprintln!("{name}, v{source}");
            let engines = same_as_one_thread::<f64>(&mesh, source);
            assert!(engines <= most, "{name} v{source}: {engines} engines");
            assert_eq!(same_as_one_thread::<Adaptive>(&mesh, source), engines);
            split += usize::from(engines == 2);
        }
        assert_eq!(split > 0, most == 2, "{name}: {split} sources split");
    }
}

/// Independent answers: the cube's corners (closed forms) and a subdivided icosahedron's
/// vertices by brute-force unfolding.
#[test]
fn two_sectors_give_the_known_answers() {
    let cube = shapes::cube();
    let field = run::<f64>(&cube, 0, 2);
    assert_eq!(field.stats().sectors, 2);
    let brute = brute_force_vertex_distances(&cube, 0, 12);
    let opposite = (0..8)
        .map(|v| field.vertex_distance(VertexId(v)))
        .fold(0.0, f64::max);
    assert!((opposite - 5f64.sqrt()).abs() < 1e-12, "{opposite}");
    for (v, &d) in brute.iter().enumerate() {
        let got = field.vertex_distance(VertexId(v as u32));
        assert!((got - d).abs() < 1e-12, "cube v{v}: {got}, brute force {d}");
    }
    // On a flat grid, from a corner and from a side, distances are straight lines.
    let grid = shapes::grid(12, 9, 1.2, 0.9);
    for source in [0, 6] {
        let field = run::<f64>(&grid, source, 2);
        assert_eq!(field.stats().sectors, 2);
        let p = grid.position(VertexId(source));
        for v in (0..grid.vertex_count() as u32).map(VertexId) {
            let (got, line) = (field.vertex_distance(v), grid.position(v).distance(p));
            assert!(
                (got - line).abs() < 1e-12,
                "grid v{source} to {v:?}: {got}, {line}"
            );
        }
    }
    let sphere = shapes::subdivide(&shapes::icosahedron());
    let brute = brute_force_vertex_distances(&sphere, 3, 10);
    let field = run::<f64>(&sphere, 3, 2);
    assert_eq!(field.stats().sectors, 2);
    for (v, &d) in brute.iter().enumerate() {
        let got = field.vertex_distance(VertexId(v as u32));
        assert!(
            (got - d).abs() < 1e-12,
            "sphere v{v}: {got}, brute force {d}"
        );
    }
}

/// A boundary vertex's directions are split across its open fan of faces: on open meshes,
/// from boundary vertices, two threads give the one-thread distances.
#[test]
fn boundary_sources_split_across_their_open_fans() {
    // `mixed_magnitudes_12.obj`'s edge lengths span more than 2^20: one engine.
    let open = [
        ("flat grid", shapes::grid(9, 7, 1.3, 1.0), 2),
        ("open cylinder", data_mesh("open_cylinder_32_6.obj"), 2),
        ("bour surface", data_mesh("bour_surface.obj"), 2),
        (
            "mixed magnitudes 12",
            data_mesh("mixed_magnitudes_12.obj"),
            1,
        ),
        ("delaunay terrain", data_mesh("delaunay_terrain.obj"), 2),
    ];
    for (name, mesh, engines) in open {
        let boundary: Vec<u32> = (0..mesh.vertex_count() as u32)
            .filter(|&v| mesh.is_boundary_vertex(VertexId(v)))
            .collect();
        assert!(!boundary.is_empty(), "{name}");
        for &source in boundary.iter().step_by((boundary.len() / 6).max(1)) {
            eprintln!("{name}, v{source}");
            assert_eq!(
                same_as_one_thread::<f64>(&mesh, source),
                engines,
                "{name} v{source}"
            );
            assert_eq!(same_as_one_thread::<Adaptive>(&mesh, source), engines);
        }
    }
}

#[test]
fn runs_that_cannot_be_split_run_on_one_thread() {
    let sphere = shapes::icosphere(2);
    let two = PropagateOptions::default().with_threads(2);
    let at = |v| SurfacePoint::Vertex(VertexId(v));
    let engines = |field: VertexField<'_, f64>| field.stats().sectors;
    let run = |sources: &[SurfacePoint], options: &PropagateOptions| {
        engines(propagate_vertices::<f64>(&sphere, sources, options).expect("valid"))
    };
    assert_eq!(run(&[at(0)], &two), 2);
    assert_eq!(run(&[at(0), at(9)], &two), 1);
    assert_eq!(run(&[at(0)], &two.clone().with_stop_points([at(9)])), 1);
    let on_edge = SurfacePoint::Edge {
        edge: exact_geodesics::EdgeId(0),
        t: 0.5,
    };
    assert_eq!(run(&[on_edge], &two), 1);
    // Where two fans of faces meet at a vertex, neither is all its directions.
    let bowtie = shapes::bowtie();
    let field = propagate_vertices::<f64>(&bowtie, &[at(0)], &two).expect("valid");
    assert_eq!(field.stats().sectors, 1);
    // The exact backend proves ties by paths that one run sees whole.
    let exact = propagate_vertices::<Real>(&sphere, &[at(0)], &two).expect("valid");
    assert_eq!(exact.stats().sectors, 1);
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 200,
        // The same cases on every run, so that CI is repeatable (as the corpus suites'): a
        // failure seen once is seen again.
        rng_seed: RngSeed::Fixed(11),
        ..ProptestConfig::default()
    })]

    /// On the degeneracy corpus, two sectors are right wherever one thread is (against the
    /// exact backend), and never wrong where one thread is not.
    #[test]
    fn two_sectors_lose_nothing_on_degenerate_meshes((kind, seed) in degenerate_case(), pick in any::<u32>()) {
        let mesh = degenerate_mesh(kind, seed);
        prop_assume!(mesh.vertex_count() > 0);
        let source = pick % mesh.vertex_count() as u32;
        prop_assume!(!mesh.vertex_faces(VertexId(source)).is_empty());
        let exact = run::<Real>(&mesh, source, 1);
        let one = run::<f64>(&mesh, source, 1);
        let two = run::<f64>(&mesh, source, 2);
        for v in (0..mesh.vertex_count() as u32).map(VertexId) {
            let e = exact.vertex_distance(v);
            if relatively_close(one.vertex_distance(v), e, 1e-9) {
                prop_assert!(
                    relatively_close(two.vertex_distance(v), e, 1e-9),
                    "{kind:?} {seed} from v{source}, {v:?}: exact {e}, one thread {}, two {}",
                    one.vertex_distance(v),
                    two.vertex_distance(v)
                );
            }
        }
    }
}

/// On a mesh whose edge lengths span 1.1e9 (a mixed-magnitude case of the degeneracy corpus),
/// images of the source that wind round the far vertex along edges 3e8 long lose to no vertex
/// path: two sectors made 61,705 wedges of its 12 faces. Such a mesh runs on one thread, with
/// one thread's distances.
#[test]
fn a_mesh_of_edges_spanning_a_billion_runs_on_one_thread() {
    let mesh = data_mesh("sector_winding_12.obj");
    assert!(mesh.validation().edge_length_span > 1e9);
    let two = run::<f64>(&mesh, 5, 2);
    assert_eq!(two.stats().sectors, 1);
    assert!(
        two.stats().wedges_created < 100,
        "{}",
        two.stats().wedges_created
    );
    same_as_one_thread::<f64>(&mesh, 5);
}

/// A maximum distance on two sectors: the vertices within it get the one-thread distances, the
/// others none (`inf`), as on one thread, where each sector's engine stops at that distance.
#[test]
fn two_sectors_stop_at_the_maximum_distance() {
    for (name, mesh, engines) in meshes() {
        let source = SurfacePoint::Vertex(VertexId(0));
        let full = run::<f64>(&mesh, 0, 1);
        let mut distances: Vec<f64> = (0..mesh.vertex_count() as u32)
            .map(|v| full.vertex_distance(VertexId(v)))
            .filter(|d| d.is_finite())
            .collect();
        distances.sort_by(f64::total_cmp);
        // Half-way out, between two vertices' distances, so that no vertex lies at the limit.
        let i = (distances.len() / 2..distances.len() - 1)
            .find(|&i| distances[i] < distances[i + 1])
            .expect("two distances apart");
        let limit = 0.5 * (distances[i] + distances[i + 1]);
        let limited = |threads| {
            let options = PropagateOptions::default()
                .with_threads(threads)
                .with_max_distance(limit);
            propagate_vertices::<f64>(&mesh, &[source], &options).expect("a vertex")
        };
        let (one, two) = (limited(1), limited(2));
        assert_eq!(two.stats().sectors, engines, "{name}");
        for v in (0..mesh.vertex_count() as u32).map(VertexId) {
            let (want, a, b) = (
                full.vertex_distance(v),
                one.vertex_distance(v),
                two.vertex_distance(v),
            );
            if want <= limit {
                assert_eq!(a.to_bits(), want.to_bits(), "{name}, {v:?}");
                assert!(
                    relatively_close(b, want, 1e-12),
                    "{name}, {v:?}: {b} against {want}"
                );
            } else {
                assert!(
                    a.is_infinite() && b.is_infinite(),
                    "{name}, {v:?}: {a} and {b} beyond {limit}"
                );
            }
        }
    }
}
