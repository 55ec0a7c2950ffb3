//! Invariants of geodesic distance, as property tests on random meshes: symmetry, the triangle
//! inequality, bounds by the Euclidean distance and by shortest paths along edges, and traced
//! paths whose length is the distance and whose consecutive points share a face.

mod common;

use exact_geodesics::glam::DVec3;
use exact_geodesics::mesh::shapes::{self, SplitMix64};
use exact_geodesics::{
    propagate, GeodesicField, PropagateOptions, SurfacePoint, TriMesh, VertexId,
};
use proptest::prelude::*;

/// A random bumpy surface: a convex planar triangulation lifted to a height field (open, with a
/// boundary, saddles and convex vertices), or an icosphere with random radii (closed).
fn random_surface(seed: u64, closed: bool) -> TriMesh {
    let mut rng = SplitMix64::new(seed);
    let base = if closed {
        shapes::icosphere(2)
    } else {
        shapes::random_convex_triangulation(seed, 10, 30)
    };
    let waves: Vec<[f64; 4]> = (0..3)
        .map(|_| {
            [
                0.15 * rng.next_f64(),
                1.0 + 4.0 * rng.next_f64(),
                6.3 * rng.next_f64(),
                6.3 * rng.next_f64(),
            ]
        })
        .collect();
    let bump = |p: DVec3| -> f64 {
        waves
            .iter()
            .map(|w| w[0] * (w[1] * p[0] + w[2]).sin() * (w[1] * p[1] + w[3]).cos())
            .sum()
    };
    let positions = base
        .positions()
        .iter()
        .map(|&p| {
            if closed {
                let r = 1.0 + bump(p) + 0.1 * (3.0 * p.z).sin();
                p * r
            } else {
                p.with_z(bump(p))
            }
        })
        .collect();
    TriMesh::new(positions, base.faces().to_vec()).expect("a perturbed valid mesh")
}

fn random_point(mesh: &TriMesh, rng: &mut SplitMix64) -> SurfacePoint {
    if rng.next_f64() < 0.3 {
        return SurfacePoint::Vertex(VertexId(
            (rng.next_u64() % mesh.vertex_count() as u64) as u32,
        ));
    }
    common::random_face_point(mesh, rng)
}

fn field_from(mesh: &TriMesh, p: SurfacePoint) -> GeodesicField<'_, f64> {
    propagate::<f64>(mesh, &[p], &PropagateOptions::default()).expect("valid source")
}

const REL: f64 = 1e-9;

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    #[test]
    fn distance_is_symmetric_metric_above_euclidean(seed in any::<u64>(), closed in any::<bool>()) {
        let mesh = random_surface(seed, closed);
        let mut rng = SplitMix64::new(seed ^ 0x9e37);
        let points: Vec<SurfacePoint> = (0..3).map(|_| random_point(&mesh, &mut rng)).collect();
        let fields: Vec<_> = points.iter().map(|&p| field_from(&mesh, p)).collect();
        let d = |i: usize, j: usize| fields[i].distance_at(&points[j]).expect("valid point");
        for i in 0..3 {
            for j in 0..3 {
                let (dij, dji) = (d(i, j), d(j, i));
                prop_assert!((dij - dji).abs() <= REL * dij.max(1.0), "d({i},{j}) = {dij}, d({j},{i}) = {dji}");
                let straight = points[i].position(&mesh).distance(points[j].position(&mesh));
                prop_assert!(dij >= straight - REL, "d = {dij} < Euclidean {straight}");
            }
        }
        for (a, b, c) in [(0, 1, 2), (1, 2, 0), (2, 0, 1)] {
            prop_assert!(d(a, c) <= d(a, b) + d(b, c) + REL, "triangle inequality {a}-{b}-{c}");
        }
    }

    #[test]
    fn distance_is_at_most_the_edge_graph_distance(seed in any::<u64>(), closed in any::<bool>()) {
        let mesh = random_surface(seed, closed);
        let s = (seed % mesh.vertex_count() as u64) as usize;
        let field = field_from(&mesh, SurfacePoint::Vertex(VertexId(s as u32)));
        let graph = common::edge_graph_dijkstra(&mesh, s);
        for (v, along_edges) in graph.iter().enumerate() {
            let got = field.vertex_distance(VertexId(v as u32));
            prop_assert!(got <= along_edges * (1.0 + REL), "v{v}: {got} > edge graph {along_edges}");
            let straight = mesh.position(VertexId(s as u32)).distance(mesh.position(VertexId(v as u32)));
            prop_assert!(got >= straight - REL);
        }
        prop_assert!(!field.check_coverage().has_overlaps());
    }

    #[test]
    fn traced_paths_have_the_distance_as_length_and_stay_on_faces(seed in any::<u64>(), closed in any::<bool>()) {
        let mesh = random_surface(seed, closed);
        let mut rng = SplitMix64::new(seed ^ 0x51);
        let source = random_point(&mesh, &mut rng);
        let field = field_from(&mesh, source);
        for _ in 0..10 {
            let target = random_point(&mesh, &mut rng);
            let path = field.trace_back(&target).expect("a connected mesh");
            let d = field.distance_at(&target).expect("valid point");
            prop_assert!((path.length() - d).abs() <= REL * d.max(1.0), "length {} vs distance {d}", path.length());
            let canonical = target.validated(&mesh).expect("valid point");
            prop_assert_eq!(path.simplices.first(), Some(&canonical));
            prop_assert_eq!(path.simplices.last(), Some(&field.sources()[0]));
            for pair in path.simplices.windows(2) {
                let (a, b) = (pair[0].faces(&mesh), pair[1].faces(&mesh));
                prop_assert!(a.iter().any(|f| b.contains(f)), "segment {:?} -> {:?} leaves the faces", pair[0], pair[1]);
            }
        }
    }
}
