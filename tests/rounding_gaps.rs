//! Vertices in the gaps that rounding leaves between the cones of two wedges meeting at a range
//! end (`src/mmp/rounded_gap.rs`). On regular solids whose coordinates were rounded to 8
//! decimals (or built in floating point), geodesics graze vertices 1e-8 away, eq. (2) nearly
//! has double roots there, and the rounded backends lost such vertices: from 12 of 1,125
//! sources, some vertex came out 0.3 to 3 % long in `f64` or in the adaptive backend.

mod common;

use exact_geodesics::scalar::{Adaptive, Real, Scalar};
use exact_geodesics::{
    propagate, GeodesicField, GeodesicPath, PropagateOptions, SurfacePoint, TraceError, TriMesh,
    VertexId,
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

/// From every vertex of the three solids, the `f64` and adaptive backends give every vertex
/// the same distance to 1e-12: the two round differently, and lost different vertices.
#[test]
fn rounded_backends_agree_from_every_vertex_of_rounded_solids() {
    for file in SOLIDS {
        let mesh = common::data_mesh(file);
        for source in 0..mesh.vertex_count() as u32 {
            let float = common::distances::<f64>(&mesh, source);
            let adaptive = common::distances::<Adaptive>(&mesh, source);
            for (v, (f, a)) in float.iter().zip(&adaptive).enumerate() {
                assert!(
                    relative(*f, *a) <= 1e-12,
                    "{file} from v{source}: vertex {v} at {f} (f64) and {a} (adaptive)"
                );
            }
        }
    }
}

/// Sources from which a vertex fell in a gap, against the exact backend: both rounded backends
/// give every vertex its exact distance to 1e-12, and the path traced back to the vertex that
/// was lost is as long as its distance (the way through the range's end, then the wedge's).
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
        let check = |name: &str, distances: &[f64], path: Result<GeodesicPath, TraceError>| {
            for (v, d) in distances.iter().enumerate() {
                let truth = exact.vertex_distance(VertexId(v as u32));
                assert!(
                    relative(*d, truth) <= 1e-12,
                    "{file} from v{source}, {name}: vertex {v} at {d}, exact {truth}"
                );
            }
            let path = path.unwrap_or_else(|e| {
                panic!("{file} from v{source}, {name}: no path to v{lost}: {e}")
            });
            assert!(
                path.is_as_long_as_its_distance(1e-12),
                "{file} from v{source}, {name}: path to v{lost} {} long, distance {}",
                path.length(),
                path.distance
            );
        };
        let target = SurfacePoint::Vertex(VertexId(lost));
        let float = field::<f64>(&mesh, source);
        check("f64", &float.vertex_distances(), float.trace_back(&target));
        let adaptive = field::<Adaptive>(&mesh, source);
        check(
            "adaptive",
            &adaptive.vertex_distances(),
            adaptive.trace_back(&target),
        );
    }
}
