//! Known answers on planar meshes: the geodesic is the straight segment on convex domains, and
//! bends at reflex corners on non-convex ones (ground truth by a visibility graph).

mod common;

use common::random_face_point;
use exact_geodesics::glam::DVec3;
use exact_geodesics::mesh::shapes::{self, SplitMix64};
use exact_geodesics::{propagate, PropagateOptions, SourceId, SurfacePoint, VertexId};

fn assert_close(got: f64, want: f64, what: &str) {
    assert!(
        (got - want).abs() <= 1e-9 * want.max(1.0),
        "{what}: got {got}, want {want}"
    );
}

#[test]
fn convex_planar_triangulations_give_straight_line_distances() {
    for seed in 0..20u64 {
        let mesh = shapes::random_convex_triangulation(seed, 12, 40);
        let mut rng = SplitMix64::new(seed + 1000);
        let source = if seed % 2 == 0 {
            SurfacePoint::Vertex(VertexId(
                (rng.next_u64() % mesh.vertex_count() as u64) as u32,
            ))
        } else {
            random_face_point(&mesh, &mut rng)
        };
        let field =
            propagate::<f64>(&mesh, &[source], &PropagateOptions::default()).expect("valid");
        let s = source.position(&mesh);
        for v in 0..mesh.vertex_count() {
            let v = VertexId(v as u32);
            let what = format!("seed {seed}, vertex {v}");
            assert_close(
                field.vertex_distance(v),
                s.distance(mesh.position(v)),
                &what,
            );
        }
        for _ in 0..20 {
            let q = random_face_point(&mesh, &mut rng);
            let d = field.distance_at(&q).expect("valid point");
            assert_close(
                d,
                s.distance(q.position(&mesh)),
                &format!("seed {seed}, {q:?}"),
            );
            let path = field.trace_back(&q).expect("reachable");
            assert_close(path.length(), d, &format!("path length, seed {seed}"));
        }
        assert!(!field.check_coverage().has_overlaps());
    }
}

#[test]
fn several_sources_split_the_plane_by_their_bisector() {
    let mesh = shapes::grid(10, 10, 1.0, 1.0);
    let sources = [
        SurfacePoint::Vertex(VertexId(0)),
        SurfacePoint::Vertex(VertexId(120)),
    ];
    let field = propagate::<f64>(&mesh, &sources, &PropagateOptions::default()).expect("valid");
    let mut rng = SplitMix64::new(5);
    for _ in 0..50 {
        let q = random_face_point(&mesh, &mut rng);
        let p = q.position(&mesh);
        let (d0, d1) = (p.length(), p.distance(DVec3::new(1.0, 1.0, 0.0)));
        assert_close(
            field.distance_at(&q).expect("valid"),
            d0.min(d1),
            "two sources",
        );
        if (d0 - d1).abs() > 1e-9 {
            let nearest = field.nearest_source_at(&q).expect("valid");
            assert_eq!(nearest, Some(SourceId(u32::from(d1 < d0))), "{q:?}");
        }
    }
}

#[test]
fn regular_grid_from_an_edge_point_gives_straight_line_distances() {
    let mesh = shapes::grid(8, 5, 2.0, 1.25);
    let source = SurfacePoint::on_edge(&mesh, 10, 11, 0.3).expect("an edge of the grid");
    let field = propagate::<f64>(&mesh, &[source], &PropagateOptions::default()).expect("valid");
    let s = source.position(&mesh);
    for v in 0..mesh.vertex_count() {
        let v = VertexId(v as u32);
        assert_close(
            field.vertex_distance(v),
            s.distance(mesh.position(v)),
            &format!("{v}"),
        );
    }
}

/// Whether the segment from `a` to `b` (in the plane z = 0) meets the open box `(lo, hi)^2`.
fn crosses_open_box(a: DVec3, b: DVec3, lo: f64, hi: f64) -> bool {
    // Liang-Barsky clipping against the box shrunk by a hair, so that segments running along
    // its sides or through its corners count as outside.
    let (lo, hi) = (lo + 1e-12, hi - 1e-12);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for axis in 0..2 {
        let d = b[axis] - a[axis];
        for (p, q) in [(-d, a[axis] - lo), (d, hi - a[axis])] {
            if p == 0.0 {
                if q < 0.0 {
                    return false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
    }
    t0 < t1
}

/// Shortest path among the corners of one square obstacle: Dijkstra over the visibility graph of
/// the source, the target and the obstacle's corners.
fn visibility_distance(s: DVec3, t: DVec3, corners: &[DVec3], lo: f64, hi: f64) -> f64 {
    let mut nodes = vec![s];
    nodes.extend_from_slice(corners);
    nodes.push(t);
    let n = nodes.len();
    let mut best = vec![f64::INFINITY; n];
    let mut done = vec![false; n];
    best[0] = 0.0;
    for _ in 0..n {
        let u = (0..n)
            .filter(|&i| !done[i])
            .min_by(|&i, &j| best[i].total_cmp(&best[j]))
            .expect("a node left");
        done[u] = true;
        for v in 0..n {
            if !done[v] && !crosses_open_box(nodes[u], nodes[v], lo, hi) {
                best[v] = best[v].min(best[u] + nodes[u].distance(nodes[v]));
            }
        }
    }
    best[n - 1]
}

#[test]
fn l_shape_paths_bend_at_the_reflex_corner() {
    let mesh = shapes::l_shape(4);
    let source = (0..mesh.vertex_count() as u32)
        .map(VertexId)
        .find(|&v| mesh.position(v) == DVec3::new(2.0, 0.5, 0.0))
        .expect("a vertex at (2, 0.5)");
    let field = propagate::<f64>(
        &mesh,
        &[SurfacePoint::Vertex(source)],
        &PropagateOptions::default(),
    )
    .expect("valid");
    let s = mesh.position(source);
    let mut bent = 0;
    for v in 0..mesh.vertex_count() {
        let v = VertexId(v as u32);
        let p = mesh.position(v);
        // The L-shape is the square [0, 2]^2 without the open square (1, 2)^2.
        let want = visibility_distance(s, p, &[DVec3::new(1.0, 1.0, 0.0)], 1.0, 3.0);
        if want > s.distance(p) + 1e-9 {
            bent += 1;
        }
        assert_close(field.vertex_distance(v), want, &format!("{v} at {p:?}"));
    }
    assert!(bent > 5, "the test must include paths around the corner");
    let far = (0..mesh.vertex_count() as u32)
        .map(VertexId)
        .find(|&v| mesh.position(v) == DVec3::new(0.5, 2.0, 0.0))
        .expect("a vertex at (0.5, 2)");
    let path = field
        .trace_back(&SurfacePoint::Vertex(far))
        .expect("reachable");
    assert_close(path.length(), 2.0 * 1.25f64.sqrt(), "bent path");
    assert!(
        path.points
            .iter()
            .any(|p| p.distance(DVec3::new(1.0, 1.0, 0.0)) < 1e-9),
        "{path:?}"
    );
}

#[test]
fn square_with_hole_matches_the_visibility_graph() {
    let mesh = shapes::square_with_hole(3);
    let corners = [
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(2.0, 1.0, 0.0),
        DVec3::new(2.0, 2.0, 0.0),
        DVec3::new(1.0, 2.0, 0.0),
    ];
    for source in [0u32, 5, 17] {
        let field = propagate::<f64>(
            &mesh,
            &[SurfacePoint::Vertex(VertexId(source))],
            &PropagateOptions::default(),
        )
        .expect("valid");
        let s = mesh.position(VertexId(source));
        for v in 0..mesh.vertex_count() {
            let v = VertexId(v as u32);
            let want = visibility_distance(s, mesh.position(v), &corners, 1.0, 2.0);
            assert_close(
                field.vertex_distance(v),
                want,
                &format!("source {source}, {v}"),
            );
            let path = field
                .trace_back(&SurfacePoint::Vertex(v))
                .expect("reachable");
            assert_close(path.length(), want, &format!("path from {v}"));
        }
    }
}
