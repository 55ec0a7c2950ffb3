//! Vertices in the gaps that rounding leaves between the cones of two wedges meeting at a range
//! end (`src/mmp/rounded_gap.rs`). On regular solids whose coordinates were rounded to 8
//! decimals (or built in floating point), geodesics graze vertices 1e-8 away, eq. (2) nearly
//! has double roots there, and the rounded backends lost such vertices: from 12 of 1,125
//! sources, some vertex came out long (by up to 3.1 %) in `f64` or in the adaptive backend,
//! and the finer the split, the more sources lost one.

mod common;

use exact_geodesics::glam::DVec3;
use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::{Adaptive, Real, Scalar};
use exact_geodesics::{
    propagate, GeodesicField, PropagateOptions, SurfacePoint, TriMesh, VertexId,
};

const SOLIDS: [&str; 3] = [
    "subdivided_tetrahedron_8_decimals.obj",
    "subdivided_octahedron_512.obj",
    "subdivided_icosahedron_8_decimals.obj",
];

fn field<'m, S: Scalar>(mesh: &'m TriMesh, source: u32) -> GeodesicField<'m, S> {
    let source = SurfacePoint::Vertex(VertexId(source));
    propagate::<S>(mesh, &[source], &PropagateOptions::default()).expect("a vertex source")
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1.0)
}

/// A rounded backend's field against the exact one: it reached some vertex through a gap,
/// every vertex distance and the distance of each point agree to 1e-12, and the path traced
/// back from each point is as long as its distance.
fn check_against_exact<S: Scalar>(
    case: &str,
    field: &GeodesicField<S>,
    exact: &GeodesicField<Real>,
    points: &[SurfacePoint],
) {
    assert!(
        field.stats().rounded_gap_offers > 0,
        "{case}: no vertex reached through a gap"
    );
    for (v, d) in field.vertex_distances().iter().enumerate() {
        let truth = exact.vertex_distance(VertexId(v as u32));
        assert!(
            relative(*d, truth) <= 1e-12,
            "{case}: vertex {v} at {d}, exact {truth}"
        );
    }
    for p in points {
        let truth = exact.distance_at(p).expect("a point of the mesh");
        let d = field.distance_at(p).expect("a point of the mesh");
        assert!(
            relative(d, truth) <= 1e-12,
            "{case}: {p:?} at {d}, exact {truth}"
        );
        let path = field
            .trace_back(p)
            .unwrap_or_else(|e| panic!("{case}: no path from {p:?}: {e}"));
        assert!(
            path.is_as_long_as_its_distance(1e-12),
            "{case}: path from {p:?} {} long, distance {}",
            path.length(),
            path.distance
        );
    }
}

/// From each of `sources`, the `f64` and adaptive backends give every vertex the same distance
/// to 1e-12.
fn assert_rounded_backends_agree(mesh: &TriMesh, sources: impl Iterator<Item = u32>, case: &str) {
    for source in sources {
        let float = common::distances::<f64>(mesh, source);
        let adaptive = common::distances::<Adaptive>(mesh, source);
        for (v, (f, a)) in float.iter().zip(&adaptive).enumerate() {
            assert!(
                relative(*f, *a) <= 1e-12,
                "{case} from v{source}: vertex {v} at {f} (f64) and {a} (adaptive)"
            );
        }
    }
}

/// From every vertex of the three solids, the `f64` and adaptive backends give every vertex
/// the same distance to 1e-12: the two round differently, and lost different vertices.
#[test]
fn rounded_backends_agree_from_every_vertex_of_rounded_solids() {
    for file in SOLIDS {
        let mesh = common::data_mesh(file);
        assert_rounded_backends_agree(&mesh, 0..mesh.vertex_count() as u32, file);
    }
}

/// The finer the split, the more sources lose a vertex: an icosahedron split 8 times a side
/// (midpoints, 1,280 faces) and rounded to 8 decimals, from 32 sources spread over its
/// vertices, against the same in the adaptive backend.
#[test]
fn a_finer_rounded_icosahedron_loses_no_vertex() {
    let mut split = shapes::icosahedron();
    for _ in 0..3 {
        split = shapes::subdivide(&split);
    }
    let rounded: Vec<DVec3> = split
        .positions()
        .iter()
        .map(|p| (*p * 1e8).round() / 1e8)
        .collect();
    let mesh = TriMesh::new(rounded, split.faces().to_vec()).expect("a usable mesh");
    let count = mesh.vertex_count() as u32;
    let sources = (0..count).step_by(count as usize / 32);
    assert_rounded_backends_agree(&mesh, sources, "rounded icosahedron");
}

/// Sources from which a vertex fell in a gap, against the exact backend: both rounded backends
/// count vertices lowered through a gap (`Stats::rounded_gap_offers`), exact none; both
/// give every vertex its exact distance to 1e-12, and so points of the geodesic's last segment
/// to the vertex that was lost, and the path traced back to that vertex is as long as its
/// distance (the way through the range's end, then the wedge's).
#[test]
fn vertices_in_rounding_gaps_get_their_geodesic_and_its_path() {
    let cases = [
        ("subdivided_tetrahedron_8_decimals.obj", 129, 62),
        ("subdivided_octahedron_512.obj", 86, 36),
        ("subdivided_octahedron_512.obj", 166, 194),
        ("subdivided_icosahedron_8_decimals.obj", 31, 0),
    ];
    for (file, source, lost) in cases {
        let mesh = common::data_mesh(file);
        let exact = field::<Real>(&mesh, source);
        let target = SurfacePoint::Vertex(VertexId(lost));
        // Points of the exact geodesic's last segment, from the edge it crosses to the vertex
        // (the way that lay in the gap), in the face of both.
        let exact_path = exact.trace_back(&target).expect("an exact path");
        let SurfacePoint::Edge { edge, t } = exact_path.simplices[1] else {
            panic!("{file} from v{source}: the geodesic to v{lost} leaves no edge");
        };
        let [a, b] = mesh.edge(edge).vertices;
        let face = mesh
            .edge_faces(edge)
            .find(|&f| mesh.face(f).contains(&VertexId(lost)))
            .expect("the face of the edge and the vertex");
        let points: Vec<SurfacePoint> = [0.5, 0.8, 0.9, 0.97]
            .iter()
            .map(|&k| {
                let weight = |c: VertexId| match c {
                    c if c == a => (1.0 - k) * (1.0 - t),
                    c if c == b => (1.0 - k) * t,
                    _ => k,
                };
                let bary = mesh.face(face).map(weight);
                SurfacePoint::Face { face, bary }
            })
            .chain([target])
            .collect();
        assert_eq!(
            exact.stats().rounded_gap_offers,
            0,
            "{file} from v{source}: the exact backend leaves no gap"
        );
        let case = format!("{file} from v{source}");
        let float = field::<f64>(&mesh, source);
        check_against_exact(&format!("{case}, f64"), &float, &exact, &points);
        let adaptive = field::<Adaptive>(&mesh, source);
        check_against_exact(&format!("{case}, adaptive"), &adaptive, &exact, &points);
    }
}
