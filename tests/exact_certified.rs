//! The exact backend certifies every decision on ordinary float meshes (issue 11), and a run
//! that leaves decisions uncertified says so.

mod common;

use common::cli::{fails_with, run, stdout, temp_file};
use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::Real;
use exact_geodesics::{propagate, PropagateOptions, SurfacePoint, TriMesh, VertexId};

/// An icosphere whose vertices are moved radially by up to 2 % (a seeded linear congruential
/// draw): float coordinates with no symmetry and no rational structure, and saddle vertices.
fn jittered_icosphere(level: u32, seed: u64) -> TriMesh {
    let sphere = shapes::icosphere(level);
    let mut state = seed;
    let mut draw = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let positions = sphere
        .positions()
        .iter()
        .map(|p| {
            let factor = 1.0 + 0.04 * (draw() - 0.5);
            p.map(|c| c * factor)
        })
        .collect();
    TriMesh::new(positions, sphere.faces().to_vec()).expect("a jittered sphere is a mesh")
}

#[test]
fn a_jittered_icosphere_is_certified_and_agrees_with_f64() {
    for (level, seed) in [(1, 7), (2, 11)] {
        let mesh = jittered_icosphere(level, seed);
        let source = [SurfacePoint::Vertex(VertexId(0))];
        let options = PropagateOptions::default();
        let exact = propagate::<Real>(&mesh, &source, &options).expect("a vertex source");
        let counts = &exact.stats().backend;
        assert!(
            exact.is_certified() && counts.uncertified == 0,
            "level {level}: {} of {} decisions uncertified: {:?}",
            counts.uncertified,
            counts.decisions,
            counts.uncertified_sites.first()
        );
        assert!(
            counts.zeros_by_structure > 0,
            "the identities are proved by structure"
        );
        let float = propagate::<f64>(&mesh, &source, &options).expect("a vertex source");
        for v in 0..mesh.vertex_count() as u32 {
            let (d, e) = (
                float.vertex_distance(VertexId(v)),
                exact.vertex_distance(VertexId(v)),
            );
            assert!(
                (d - e).abs() <= 1e-12 * e.max(1.0),
                "level {level}, v{v}: f64 {d} against exact {e}"
            );
        }
    }
}

/// Two squares hinged along `x = 1`, the first folded out of its plane by 2^-150 at one corner:
/// deciding which way the fold goes needs more than 128 bits.
const FOLD: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 7.006492321624085e-46\nv 2 0 0\nv 2 1 0\n\
                    f 1 2 4\nf 1 4 3\nf 2 5 6\nf 2 6 4\n";

#[test]
fn uncertified_decisions_are_warned_of_and_refused_on_demand() {
    let file = temp_file("fold.obj", FOLD);
    let path = file.to_str().expect("a UTF-8 path");
    let args = |extra: &[&'static str]| {
        let mut a = vec!["distance", path, "--source", "v:0", "--backend", "exact"];
        a.extend_from_slice(extra);
        a
    };
    let low = run(&args(&["--precision-cap", "128"]));
    let err = String::from_utf8_lossy(&low.stderr);
    assert!(low.status.success(), "a warning, not an error: {err}");
    assert!(
        err.contains("warning:") && err.contains("not certified"),
        "{err}"
    );
    fails_with(
        &args(&["--precision-cap", "128", "--require-certified"]),
        "not certified",
    );
    let full = run(&args(&["--require-certified"]));
    stdout(&full);
    assert!(String::from_utf8_lossy(&full.stderr).is_empty());
}

/// `sqrt 5`, the distance across two faces of the unit cube to the opposite corner, to 60
/// significant digits (correctly rounded by Python's `decimal` at 80 digits).
const ROOT_5: &str = "2.23606797749978969640917366873127623544061835961152572427090";

#[test]
fn distances_print_with_certified_digits() {
    let csv = stdout(&run(&[
        "distance",
        "gen:cube",
        "--source",
        "v:0",
        "--backend",
        "exact",
        "--digits",
        "60",
    ]));
    let row = csv
        .lines()
        .find(|l| l.starts_with("6,"))
        .expect("the opposite corner");
    assert_eq!(row, format!("6,{ROOT_5},0"));
    assert!(csv.contains("\n1,1.00000000000000000000000000000000000000000000000000000000000,0\n"));
    let json = stdout(&run(&[
        "path",
        "gen:cube",
        "--source",
        "v:0",
        "--target",
        "v:6",
        "--backend",
        "exact",
        "--digits",
        "30",
    ]));
    let json: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    assert_eq!(json["distance_digits"], ROOT_5[..31]);
    fails_with(
        &["distance", "gen:cube", "--source", "v:0", "--digits", "5"],
        "--digits needs --backend exact",
    );
}
