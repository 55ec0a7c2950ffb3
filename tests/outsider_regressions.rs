//! Degenerate meshes made outside the project's own generator (an independent corpus of
//! welded and unwelded coincident vertices, zero-area faces, inconsistent orientations,
//! rotations and scalings) on which a backend once broke an invariant of issue 10. Expected
//! values come from the coordinates (closed forms of the unfolded surface), never from the
//! engine.

mod common;

use common::{distances, every_backend, straight};
use exact_geodesics::glam::DVec3;
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{
    propagate, PropagateOptions, Scalar, SurfacePoint, TraceError, TriMesh, VertexId,
};

/// A sliver folded back onto its flat neighbour. Apex `v0` at height 1 over the line through
/// `v4`, `v5` (the origin) and `v1`, along `(0.8, -0.6)` rotated in floats (so the sliver
/// `(v4, v1, v5)` has an area of a few ulps); the face `(v5, v4, v3)` lies in the same plane,
/// and its edge with the sliver is traversed the same way by both (inconsistent orientation),
/// so their normals agree although they lie on the same side of that edge. Unfolded, the apex
/// lands at `(0.6, 0.8)`, opposite `v3 = (-0.6, -0.8)`, and the geodesic runs straight through
/// `v5`: d(v3) = 1 + 1 = 2. The exact backend joined the two faces into one flat region and
/// carried the apex's image unreflected onto `v3` itself: d(v3) = 1.1e-16.
#[test]
fn a_sliver_folded_onto_a_coplanar_face_is_unfolded_not_joined_to_it() {
    let mesh = TriMesh::new(
        vec![
            [0.0, 0.0, 1.0],
            [-0.8, 0.6, 0.0],
            [-0.8, 0.6, 0.0],
            [-0.6000000000000001, -0.7999999999999999, 0.0],
            [0.7999999999999999, -0.6000000000000001, 0.0],
            [0.0, 0.0, 0.0],
        ],
        vec![[0, 4, 1], [5, 4, 3], [4, 1, 5]],
    )
    .expect("usable mesh");
    for (backend, d) in every_backend(&mesh, 0) {
        assert!(
            (d[3] - 2.0).abs() <= 1e-12,
            "{backend}: d(v3) = {}, want 2",
            d[3]
        );
        assert_eq!(d[2], f64::INFINITY, "{backend}: v2 is used by no face");
    }
}

/// A bumpy grid (units of 1e20) in which `v5` was moved onto the edge `(v6, v9)`, at a quarter
/// of it: the face `(v5, v6, v9)` is degenerate, and the geodesics to `v10` run through `v5`
/// into the face `(v6, v10, v9)` beyond that edge. Rounded at this scale, `v5`'s height over
/// the edge was a few ulps rather than zero, so the float backends never counted `v5` as a
/// point of the edge, dropped its window there (as narrow as that height), and reached `v10`
/// only around `v6`: 4.794e20 against 4.718e20 (1.6 % long). Checked against the straight
/// segment from `v5` to `v10` (which lies in the face beyond) and against the exact backend.
#[test]
fn a_vertex_moved_onto_an_edge_lights_the_face_beyond_it_in_every_backend() {
    let mesh = TriMesh::new(
        vec![
            [0.0, 0.0, -8.400000000000001e+18],
            [1e+20, 0.0, -2.9e+18],
            [2e+20, 0.0, 1.55e+19],
            [0.0, 1e+20, 2.2199999999999996e+19],
            [1e+20, 1e+20, 1.87e+19],
            [3.0000000000000007e+20, 1.25e+20, 2.8250000000000004e+19],
            [3.0000000000000007e+20, 1e+20, 3.13e+19],
            [1e+20, 2e+20, 4.3e+19],
            [2e+20, 2e+20, -2.34e+19],
            [3.0000000000000007e+20, 2e+20, 1.9100000000000004e+19],
            [4e+20, 2e+20, -4.43e+19],
        ],
        vec![
            [0, 1, 3],
            [1, 4, 3],
            [1, 2, 5],
            [1, 5, 4],
            [2, 6, 5],
            [4, 5, 7],
            [5, 8, 7],
            [5, 6, 9],
            [5, 9, 8],
            [6, 10, 9],
        ],
    )
    .expect("usable mesh");
    let through_v5 = straight(&mesh, 5, 10);
    let exact = distances::<Real>(&mesh, 0)[10];
    for (backend, d) in every_backend(&mesh, 0) {
        assert!(
            d[10] <= (d[5] + through_v5) * (1.0 + 1e-12),
            "{backend}: d(v10) = {} beyond d(v5) + |v5 v10| = {}",
            d[10],
            d[5] + through_v5
        );
        assert!(
            (d[10] - exact).abs() <= 1e-12 * exact,
            "{backend}: d(v10) = {}, exact {exact}",
            d[10]
        );
    }
}

/// The traced path from `target` back to `source` in backend `S`: its length and distance.
fn traced<S: Scalar>(mesh: &TriMesh, source: u32, target: u32) -> (f64, f64) {
    let field = propagate::<S>(
        mesh,
        &[SurfacePoint::Vertex(VertexId(source))],
        &PropagateOptions::default(),
    )
    .expect("valid source");
    let path = field
        .trace_back(&SurfacePoint::Vertex(VertexId(target)))
        .expect("the target is reached, so a path leads back");
    (path.length(), path.distance)
}

/// Asserts that every backend gives `d(a, b)` and `d(b, a)` as `want`, within 1e-12 relative.
fn assert_both_ways_in_every_backend(mesh: &TriMesh, (a, b): (u32, u32), want: f64) {
    for (from, to) in [(a, b), (b, a)] {
        for (backend, d) in every_backend(mesh, from) {
            assert!(
                (d[to as usize] - want).abs() <= 1e-12 * want,
                "{backend}: d(v{from}, v{to}) = {:e}, want {want:e}",
                d[to as usize]
            );
        }
    }
}

fn every_backend_traced(
    mesh: &TriMesh,
    source: u32,
    target: u32,
) -> [(&'static str, (f64, f64)); 3] {
    [
        ("f64", traced::<f64>(mesh, source, target)),
        ("adaptive", traced::<Adaptive>(mesh, source, target)),
        ("exact", traced::<Real>(mesh, source, target)),
    ]
}

/// A flat strip (a grid rotated by (0.6, 0.8) in floats) whose source `v0` was moved onto
/// the edge `(v1, v3)` at a quarter of it: the face `(v0, v1, v3)` is degenerate, and `v0`
/// lights the face beyond that edge as a point of it. The back-trace from `v5` walked into
/// that face and, finding the source neither a corner nor (at its height of a few ulps) a
/// point of the edge, lost its way in the exact backend. The path bends at the boundary
/// corner `v3`: 0.75 + 1 = 1.75.
#[test]
fn a_source_in_the_middle_of_a_degenerate_face_is_traced_to_in_every_backend() {
    let mesh = TriMesh::new(
        vec![
            [0.39999999999999997, 0.9500000000000001, 0.0],
            [0.6, 0.8, 0.0],
            [1.2, 1.6, 0.0],
            [-0.20000000000000007, 1.4, 0.0],
            [0.3999999999999999, 2.2, 0.0],
            [-1.0, 2.0, 0.0],
            [-0.40000000000000013, 2.8, 0.0],
        ],
        vec![[0, 1, 3], [1, 2, 3], [2, 4, 3], [3, 4, 6], [3, 6, 5]],
    )
    .expect("usable mesh");
    let want = straight(&mesh, 0, 3) + straight(&mesh, 3, 5);
    assert_traced_straight(&mesh, 0, 5, want);
}

/// A pyramid (rotated) with its apex `v0` moved to the middle of the base edge `(v2, v3)`, a
/// duplicated face and one corner unwelded. The geodesic to `v3` runs along the edge
/// `(v0, v3)`; the adaptive back-trace arrived at `v3` by the wedge that `v0` sends beyond
/// `(v2, v3)` as a point of it, did not find `v0` on that edge (a height of a few ulps), and
/// went on to the far end `v2` and back: a path of 1.30 for a distance of 0.434.
#[test]
fn a_path_to_the_middle_corner_of_a_degenerate_face_has_the_distance_s_length() {
    let mesh = TriMesh::new(
        vec![
            [
                -0.5195620680722947,
                -0.21926836748828082,
                -0.7026532155827874,
            ],
            [0.47069323441506106, 0.4332837873751152, -0.7685785832780954],
            [
                -0.2529755502849691,
                -0.0023377816125949025,
                -0.967469847455283,
            ],
            [-0.78614858585962, -0.43619895336396675, -0.4378365837102918],
            [
                -0.7273357017733071,
                -0.5415934163951783,
                0.42149655780721373,
            ],
            [
                -0.12082419930722416,
                -0.2391569903884818,
                0.9634341943330076,
            ],
            [0.5766703896017044, 0.24336952729428715, 0.7798862320500174],
            [0.8399204132083549, 0.5426338270908193, 0.009068030253431614],
            [0.0, 0.0, 0.0],
            [
                -0.7273357017733071,
                -0.5415934163951783,
                0.42149655780721373,
            ],
        ],
        vec![
            [0, 1, 2],
            [0, 2, 3],
            [0, 3, 4],
            [0, 9, 5],
            [0, 5, 6],
            [0, 6, 7],
            [0, 7, 1],
            [8, 2, 1],
            [8, 3, 2],
            [8, 4, 3],
            [8, 3, 2],
            [8, 5, 4],
            [8, 6, 5],
            [8, 7, 6],
            [8, 1, 7],
        ],
    )
    .expect("usable mesh");
    let want = straight(&mesh, 0, 3);
    for (backend, (length, distance)) in every_backend_traced(&mesh, 0, 3) {
        assert!(
            (distance - want).abs() <= 1e-12 * want,
            "{backend}: distance {distance}, want {want}"
        );
        assert!(
            (length - want).abs() <= 1e-9 * want,
            "{backend}: length {length}, want {want}"
        );
    }
}

/// A needle face `(v7, v4, v3)`: `v4` lies 1.4e-7 from `v7` (an octahedron's bottom corner,
/// moved). From `v0` the distance of `v7` is right in f64 (20.00000004: down through `v4`, the
/// needle's short edge), but rounding sent the back-trace from `v7` by the wrong face, to the
/// edge `(v2, v3)` near `v3` and on to `v0`: a path 28.28 long, given as the shortest. A
/// path whose length is not the distance is refused ([`TraceError::NotShortest`]), never
/// returned.
#[test]
fn a_traced_path_is_as_long_as_its_distance_or_refused() {
    let positions = [
        [0.0, 0.0, 10.0],
        [10.0, 0.0, 0.0],
        [5.000000000000002, 8.660254037844386, 0.0],
        [-9.999999999995, 8.661478684643534e-12, 0.0],
        [-1e-07, 1.2246467991473531e-23, -9.9999999],
        [-5.000000000000004, -8.660254037844384, 0.0],
        [5.000000000000002, -8.660254037844386, 0.0],
        [0.0, 0.0, -10.0],
    ];
    let faces = vec![[0, 2, 3], [0, 3, 4], [7, 2, 1], [7, 3, 2], [7, 4, 3]];
    let mesh = TriMesh::new(positions.map(DVec3::from_array).to_vec(), faces)
        .expect("a fan with a needle");
    let source = [SurfacePoint::Vertex(VertexId(0))];
    let field = propagate::<f64>(&mesh, &source, &PropagateOptions::default()).expect("a source");
    // Down the face (v0, v3, v4) to v4, then the needle's short edge: the surface's shortest way.
    let p = |v: usize| DVec3::from_array(positions[v]);
    let straight = p(0).distance(p(4)) + p(4).distance(p(7));
    let distance = field.vertex_distance(VertexId(7));
    assert!(
        (distance - straight).abs() <= 1e-12 * straight,
        "{distance} against {straight}"
    );
    match field.trace_back(&SurfacePoint::Vertex(VertexId(7))) {
        Ok(path) => assert!(
            (path.length() - distance).abs() <= 1e-9 * distance,
            "a path {} long for a distance of {distance}",
            path.length()
        ),
        Err(e) => assert!(matches!(e, TraceError::NotShortest { .. }), "{e}"),
    }
}

/// Every backend traces `target` back to `source` with the length and distance `want`.
fn assert_traced_straight(mesh: &TriMesh, source: u32, target: u32, want: f64) {
    for (backend, (length, distance)) in every_backend_traced(mesh, source, target) {
        assert!(
            (distance - want).abs() <= 1e-12 * want,
            "{backend}: v{source} -> v{target}: distance {distance}, want {want}"
        );
        assert!(
            (length - want).abs() <= 1e-12 * want,
            "{backend}: v{source} -> v{target}: length {length}, want {want}"
        );
    }
}

/// A cube of side 2 whose corner `v6` sits one ulp (4.4e-16) beyond `v2` along the edge from
/// `v0`: the slivers `(v2, v6, v7)` and `(v4, v6, v2)` join them. From `v0` the geodesics to
/// both run straight along that edge (`v2` lies on the segment from `v0` to `v6`). In the
/// float backends the back-trace from `v6` walked to `v2` (on its way, rightly) and from `v2`
/// by the sliver `(v2, v6, v7)`, tied at that resolution with the edge to `v0`, back to `v6`,
/// round and round until it gave up ("lost its way"); a shortest path passes a point once.
#[test]
fn vertices_an_ulp_apart_are_traced_through_not_round_in_every_backend() {
    let mesh = TriMesh::new(
        vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [0.0, 2.0, 0.0],
            [2.0, 2.0, 0.0],
            [0.0, 0.0, 2.0],
            [2.0, 0.0, 2.0],
            [0.0, 2.0000000000000004, 0.0],
            [2.0, 2.0, 2.0],
        ],
        vec![
            [0, 2, 1],
            [2, 3, 1],
            [4, 5, 6],
            [5, 7, 6],
            [0, 1, 4],
            [1, 5, 4],
            [2, 6, 7],
            [2, 7, 3],
            [0, 4, 2],
            [4, 6, 2],
            [1, 3, 7],
            [1, 7, 5],
        ],
    )
    .expect("usable mesh");
    assert_traced_straight(&mesh, 0, 6, straight(&mesh, 0, 6));
    assert_traced_straight(&mesh, 0, 2, straight(&mesh, 0, 2));
}

/// An octahedron (rotated) with `v5` one ulp from `v2` in each coordinate, the corner `v3`
/// moved onto the edge `(v5, v0)` (the face `(v5, v0, v3)` has zero area) and a face repeated
/// reversed. The geodesic from `v0` to `v5` is that edge; the float backends' walk from `v5`
/// was sent to `v2` and from `v2` back to `v5`, until it gave up.
#[test]
fn an_octahedron_corner_an_ulp_from_another_is_traced_to_in_every_backend() {
    let mesh = TriMesh::new(
        vec![
            [0.7592294993296627, -0.09255840195443324, 0.6442076602891891],
            [
                -0.7592294993296627,
                0.09255840195443324,
                -0.6442076602891891,
            ],
            [1.1161937051204205, 1.203610787224653, -1.1425553314942765],
            [0.8484705507773522, 0.2314838953403384, 0.19751691234332264],
            [-1.1161937051204207, -1.2036107872246533, 1.1425553314942767],
            [1.1161937051204207, 1.2036107872246533, -1.1425553314942767],
        ],
        vec![
            [2, 0, 4],
            [2, 1, 5],
            [4, 2, 1],
            [4, 1, 3],
            [4, 3, 0],
            [5, 2, 0],
            [5, 1, 2],
            [5, 3, 1],
            [5, 0, 3],
        ],
    )
    .expect("usable mesh");
    assert_traced_straight(&mesh, 0, 5, straight(&mesh, 0, 5));
}

/// A grid of unit steps along `(0.6, 0.8)` (rotated in floats) with heights in {-1, 0, 1},
/// where `v12` was moved onto the edge `(v9, v10)` at 1e-7 of it: `v8`, `v9`, `v12` and `v10`
/// lie on one line, and the sliver `(v8, v9, v12)` leaves `v9` 3e-16 off its opposite edge
/// `(v8, v12)` (of length 1.41), too little for the mesh to call the face degenerate (a
/// side of 1.4e-7 rounded at coordinates of 2 has its direction only to 1e-9). `v11` lies in
/// the one face `(v8, v12, v11)` beyond that edge, and the geodesic to it runs through the
/// saddle `v9` and across the sliver: its length is at most `d(v9) + |v9 v11|` plus twice the
/// height. The float backends kept no window as narrow as that height on the edge and
/// reached `v11` around `v12`, 1.7e-7 long. Checked against that path and the exact backend
/// (an exhaustive unfolding in f64 loses the same window).
#[test]
fn a_saddle_on_its_opposite_edge_at_float_resolution_lights_the_face_beyond_it_in_every_backend() {
    let mesh = TriMesh::new(
        vec![
            [0.0, 0.0, 1.0],
            [0.6, 0.8, -1.0],
            [1.2, 1.6, 1.0],
            [1.7999999999999998, 2.4000000000000004, 1.0],
            [-0.20000000000000007, 1.4, 0.0],
            [0.3999999999999999, 2.2, -1.0],
            [-1.0, 2.0, -1.0],
            [-0.7500000000000004, 4.0, 0.5],
            [-2.4000000000000004, 1.7999999999999998, 1.0],
            [-1.8000000000000003, 2.5999999999999996, 0.0],
            [-1.2000000000000004, 3.4, -1.0],
            [-3.2, 2.4, 0.0],
            [-1.7999999400000002, 2.60000008, -1e-07],
        ],
        vec![
            [0, 1, 4],
            [1, 2, 5],
            [2, 3, 5],
            [4, 7, 6],
            [6, 9, 8],
            [6, 7, 9],
            [7, 10, 9],
            [8, 9, 12],
            [8, 12, 11],
            [9, 10, 12],
        ],
    )
    .expect("usable mesh");
    let exact = distances::<Real>(&mesh, 3)[11];
    for (backend, d) in every_backend(&mesh, 3) {
        let through_v9 = d[9] + straight(&mesh, 9, 11) + 1e-15;
        assert!(
            d[11] <= through_v9 * (1.0 + 1e-12),
            "{backend}: d(v11) = {} beyond d(v9) + |v9 v11| = {through_v9}",
            d[11]
        );
        assert!(
            (d[11] - exact).abs() <= 1e-12 * exact,
            "{backend}: d(v11) = {}, exact {exact}",
            d[11]
        );
    }
}

/// A fan of four faces round `v3` (angles summing to 3.1535, above pi) between `v0` and the
/// unwelded copy `v6` of it; `v3` lies one ulp from `v0` (coordinates of about 0.7), and `v4`
/// 1e-12 away. The geodesic from `v0` to `v6` crosses the fan, so it runs through `v3`:
/// `d = |v0 v3| + |v3 v6| = 3.3e-16`, both ways. The float backends' tolerances, as fractions
/// of the unit edges, exceeded the whole configuration: from `v0` a wedge claimed `v6` 1e-20
/// beyond its range by a straight line (1.8e-5 short); from `v6` (once taken onto the edge
/// `(v3, v5)`, 1.2e-16 from it) 30 % short.
#[test]
fn vertices_an_ulp_from_a_unit_edge_s_end_keep_their_distances_in_every_backend() {
    let mesh = TriMesh::new(
        vec![
            [0.7443580490747195, 0.5982135835632504, -0.2967686021433053],
            [
                -0.7443580482391918,
                -0.5982135716232996,
                0.29676859461074495,
            ],
            [
                -0.7443580490747196,
                -0.5982135835632505,
                0.29676860214330536,
            ],
            [0.7443580490747196, 0.5982135835632505, -0.29676860214330536],
            [0.7443580490740715, 0.5982135835621164, -0.29676860214384737],
            [-0.09626774182948816, 0.5358963579278502, 0.8387774528697804],
            [0.7443580490747195, 0.5982135835632504, -0.2967686021433053],
        ],
        vec![[4, 1, 3], [4, 3, 0], [5, 3, 1], [5, 6, 3]],
    )
    .expect("usable mesh");
    let want = straight(&mesh, 0, 3) + straight(&mesh, 3, 6);
    assert_both_ways_in_every_backend(&mesh, (0, 6), want);
}

/// A square pyramid of height 1 (rotated about its axis in floats) whose apex `v0` has a copy
/// `v1` one ulp above it, and whose corner `v5` was moved to 1e-9 of the apex (a needle),
/// with an unwelded copy `v8`. From `v5`, `v1` is reached by the edge `(v5, v0)` and the
/// ulp-long edge `(v0, v1)`: `d = |v5 v0| + |v0 v1|` both ways, in every backend. From `v5`
/// the float backends gave `v1` 6.5e-17 less (4.6e-8 relative, the straight line in space):
/// the wedge of `v5` on the unit edge `(v1, v2)` claimed its end `v1` 2.6e-16 beyond its range,
/// within a slack of ulps of the edge's length.
#[test]
fn a_vertex_an_ulp_above_a_needle_s_apex_is_reached_round_the_apex_in_every_backend() {
    let mesh = TriMesh::new(
        vec![
            [0.0, 0.0, 1.0],
            [0.0, 0.0, 1.0000000000000002],
            [-0.3928203230275509, 0.9196152422706633, 0.0],
            [-0.992820323027551, 0.11961524227066339, 0.0],
            [-0.6000000000000001, -0.7999999999999999, 0.0],
            [3.9282032302755055e-10, -9.196152422706634e-10, 0.999999999],
            [0.992820323027551, -0.119615242270663, 0.0],
            [0.0, 0.0, 0.0],
            [3.9282032302755055e-10, -9.196152422706634e-10, 0.999999999],
        ],
        vec![
            [0, 1, 2],
            [0, 2, 3],
            [0, 3, 4],
            [0, 4, 5],
            [0, 8, 6],
            [0, 6, 1],
            [7, 2, 1],
            [7, 3, 2],
            [7, 4, 3],
            [7, 5, 4],
            [7, 6, 5],
            [7, 1, 6],
        ],
    )
    .expect("usable mesh");
    let want = straight(&mesh, 5, 0) + straight(&mesh, 0, 1);
    assert_both_ways_in_every_backend(&mesh, (5, 1), want);
}

/// A boundary vertex `v4` (the origin) whose faces fold onto one another: `(v4, v6, v1)`, a
/// needle `(v4, v1, v3)` and `(v2, v3, v4)`, flipped against the needle and folded back over
/// the first, all in the plane z = 0, with the boundary neighbours `v6` and `v2` unwelded
/// copies of one point (the outsider's combo 1196 of seed 3, with a fin on the edge
/// `(v0, v2)`). Its faces turn the same way in their own orders and its boundary neighbours lie
/// on a line through it, so it was taken for an exactly flat vertex and sent no wedge into its
/// faces: from `v6`, whose only face is `(v4, v6, v1)`, `v0` was reached through `v1` at
/// sqrt 3 + sqrt 2 = 3.146 in every backend, against 2.618 from `v0`. The geodesic runs along
/// the edge `(v6, v4)` and from `v4` across the edge `(v2, v3)` to the apex `v0`.
#[test]
fn a_boundary_vertex_whose_faces_fold_onto_each_other_sends_wedges_into_them_in_every_backend() {
    let mesh = TriMesh::new(
        vec![
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 0.0],
            [-0.4999999999999998, 0.8660254037844387, 0.0],
            [0.999999999985, -8.660254037844382e-12, 0.0],
            [0.0, 0.0, 0.0],
            [-0.44179674710093464, -0.4667574167293927, 1.247331232634264],
            [-0.4999999999999998, 0.8660254037844387, 0.0],
        ],
        vec![
            [0, 1, 2],
            [0, 2, 3],
            [0, 3, 1],
            [4, 6, 1],
            [2, 3, 4],
            [4, 1, 3],
            [0, 2, 5],
        ],
    )
    .expect("usable mesh");
    assert!(!mesh.is_flat_vertex(VertexId(4)));
    // v4 and v0 unfolded on either side of the edge (v2, v3).
    let p = |v: u32| mesh.position(VertexId(v));
    let edge = p(3) - p(2);
    let frame = |q: DVec3| {
        let to = q - p(2);
        [to.dot(edge), to.cross(edge).length()].map(|x| x / edge.length())
    };
    let ([x0, h0], [x4, h4]) = (frame(p(0)), frame(p(4)));
    let want = straight(&mesh, 6, 4) + (x0 - x4).hypot(h0 + h4);
    assert_both_ways_in_every_backend(&mesh, (6, 0), want);
}
