//! Early stop at target points: the stop points' distances equal those of the full run (and
//! the known answers), with fewer events.

mod common;

use exact_geodesics::degeneracy::{degenerate_case, DegenerateKind, MeshSize};
use exact_geodesics::mesh::shapes::{self, SplitMix64};
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{
    propagate, FaceId, GeodesicField, PointError, PropagateOptions, Scalar, SurfacePoint, TriMesh,
    VertexId,
};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

fn vertex(v: u32) -> SurfacePoint {
    SurfacePoint::Vertex(VertexId(v))
}

fn run<'m, S: Scalar>(
    mesh: &'m TriMesh,
    source: u32,
    stops: &[SurfacePoint],
) -> GeodesicField<'m, S> {
    let options = PropagateOptions::default().with_stop_points(stops.iter().copied());
    propagate::<S>(mesh, &[vertex(source)], &options).expect("valid source and stop points")
}

/// The stopped run against the full one: the same distance at every stop point (vertices bit
/// for bit, other points to rounding) and at every vertex no farther than the farthest stop
/// point, with fewer wedges propagated.
fn stopped_run_agrees<S: Scalar>(mesh: &TriMesh, source: u32, stops: &[SurfacePoint]) {
    let full = run::<S>(mesh, source, &[]);
    let stopped = run::<S>(mesh, source, stops);
    assert!(stopped.stats().stopped_at_stop_points);
    assert!(!full.stats().stopped_at_stop_points);
    let mut radius = 0.0f64;
    for p in stops {
        let (want, got) = (
            full.distance_at(p).unwrap(),
            stopped.distance_at(p).unwrap(),
        );
        match p {
            SurfacePoint::Vertex(_) => assert_eq!(got.to_bits(), want.to_bits(), "at {p:?}"),
            _ => assert!(
                (got - want).abs() <= 1e-12 * want.max(1.0),
                "at {p:?}: {got} {want}"
            ),
        }
        radius = radius.max(want);
    }
    let mut inside = 0;
    for v in (0..mesh.vertex_count() as u32).map(VertexId) {
        let want = full.vertex_distance(v);
        if want <= radius {
            inside += 1;
            assert_eq!(
                stopped.vertex_distance(v).to_bits(),
                want.to_bits(),
                "at {v:?}"
            );
            assert_eq!(stopped.nearest_source(v), full.nearest_source(v));
        } else {
            assert!(
                stopped.vertex_distance(v) >= want,
                "an upper bound at {v:?}"
            );
        }
    }
    assert!(
        inside < mesh.vertex_count(),
        "the stop points are not the farthest"
    );
    let (events, all) = (
        stopped.stats().wedges_propagated,
        full.stats().wedges_propagated,
    );
    assert!(
        events < all,
        "{events} wedges propagated, {all} in the full run"
    );
}

#[test]
fn grid_stop_vertices_get_their_straight_distances() {
    let mesh = shapes::grid(20, 20, 1.0, 1.0);
    // Column i, row j is vertex 21 j + i; the source is the corner v0.
    let stops = [vertex(21 * 3 + 5), vertex(21 * 7 + 2), vertex(21 * 6 + 6)];
    for backend_run in [stopped_run_agrees::<f64>, stopped_run_agrees::<Adaptive>] {
        backend_run(&mesh, 0, &stops);
    }
    let stopped = run::<f64>(&mesh, 0, &stops);
    for p in &stops {
        let SurfacePoint::Vertex(v) = *p else {
            unreachable!()
        };
        let want = common::planar_straight_distance(&mesh, 0, v.index());
        assert!((stopped.vertex_distance(v) - want).abs() < 1e-12);
    }
}

#[test]
fn icosphere_stop_points_in_faces_and_on_edges_are_final() {
    let mesh = shapes::icosphere(3);
    let mut rng = SplitMix64::new(13);
    let mut stops: Vec<SurfacePoint> = (0..12)
        .map(|_| common::random_face_point(&mesh, &mut rng))
        .collect();
    stops.push(vertex(40));
    let [a, b] = mesh.edges()[7].vertices;
    stops.push(SurfacePoint::on_edge(&mesh, a.0, b.0, 0.3).unwrap());
    // Keep the points near the source, so that stopping early saves something.
    let full = run::<f64>(&mesh, 0, &[]);
    stops.retain(|p| full.distance_at(p).unwrap() < 1.5);
    assert!(stops.len() >= 4, "{stops:?}");
    stopped_run_agrees::<f64>(&mesh, 0, &stops);
    stopped_run_agrees::<Adaptive>(&mesh, 0, &stops);
    for p in &stops {
        stopped_run_agrees::<f64>(&mesh, 0, std::slice::from_ref(p));
    }
}

#[test]
fn exact_stop_at_a_cube_corner_is_certified() {
    let cube = shapes::cube();
    stopped_run_agrees::<Real>(&cube, 0, &[vertex(1)]);
    let stopped = run::<Real>(&cube, 0, &[vertex(1)]);
    assert!(stopped.is_certified());
    let d = stopped.vertex_distance_exact(VertexId(1)).unwrap();
    assert_eq!(d.to_decimal(20).as_deref(), Some("1.0000000000000000000"));
}

#[test]
fn unreachable_stop_point_lets_the_run_finish() {
    // Two disjoint triangles: vertex 4 cannot be reached from vertex 0.
    let mesh = common::two_triangles();
    let full = run::<f64>(&mesh, 0, &[]);
    let stopped = run::<f64>(&mesh, 0, &[vertex(1), vertex(4)]);
    assert!(!stopped.stats().stopped_at_stop_points);
    assert_eq!(stopped.vertex_distances(), full.vertex_distances());
    assert_eq!(stopped.vertex_distance(VertexId(4)), f64::INFINITY);
}

#[test]
fn stop_point_outside_the_mesh_is_an_error() {
    let cube = shapes::cube();
    let options = PropagateOptions::default().with_stop_points([SurfacePoint::Face {
        face: FaceId(99),
        bary: [1.0, 0.0, 0.0],
    }]);
    let result = propagate::<f64>(&cube, &[vertex(0)], &options);
    assert!(matches!(
        result.err(),
        Some(PointError::FaceOutOfRange { face: 99, .. })
    ));
}

/// On degenerate meshes (coincident vertices, zero-area faces, slivers, extreme scales,
/// non-manifold edges, ...): a run stopped at three vertices gives them, and every vertex no
/// farther than the farthest of them, the full run's distances bit for bit.
fn stopped_run_is_a_prefix_on<S: Scalar>(kind: DegenerateKind, seed: u64) -> Result<(), String> {
    let case = degenerate_case(kind, seed, MeshSize::Full);
    let mesh = &case.mesh;
    let n = mesh.vertex_count() as u64;
    let source = case.focus.first().map_or(0, |v| v.0);
    let stops: Vec<SurfacePoint> = [seed, seed / 7, seed / 49]
        .map(|k| vertex((k % n) as u32))
        .to_vec();
    let full = run::<S>(mesh, source, &[]);
    let stopped = run::<S>(mesh, source, &stops);
    let radius = stops
        .iter()
        .map(|p| full.distance_at(p).unwrap())
        .filter(|d| d.is_finite())
        .fold(0.0, f64::max);
    for v in (0..mesh.vertex_count() as u32).map(VertexId) {
        let (want, got) = (full.vertex_distance(v), stopped.vertex_distance(v));
        if (want <= radius || stops.contains(&SurfacePoint::Vertex(v)))
            && got.to_bits() != want.to_bits()
        {
            return Err(format!(
                "{kind:?} seed {seed}: d(v{}) = {got}, full run {want}",
                v.0
            ));
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 300,
        rng_seed: RngSeed::Fixed(13),
        max_shrink_iters: 0,
        ..ProptestConfig::default()
    })]

    #[test]
    fn stopped_runs_are_prefixes_of_full_runs_on_degenerate_meshes((kind, seed) in common::strategies::degenerate_case()) {
        stopped_run_is_a_prefix_on::<f64>(kind, seed).map_err(TestCaseError::fail)?;
        stopped_run_is_a_prefix_on::<Adaptive>(kind, seed).map_err(TestCaseError::fail)?;
    }

    /// [`stopped_path_is_the_full_runs`] on degenerate meshes, to a vertex and to a point in a
    /// face.
    #[test]
    fn paths_to_stop_points_are_the_full_runs_on_degenerate_meshes((kind, seed) in common::strategies::degenerate_case()) {
        let case = degenerate_case(kind, seed, MeshSize::Full);
        let mesh = &case.mesh;
        let source = case.focus.first().map_or(0, |v| v.0);
        let mut rng = SplitMix64::new(seed);
        let targets = [
            vertex((seed % mesh.vertex_count() as u64) as u32),
            common::random_face_point(mesh, &mut rng),
        ];
        for target in &targets {
            stopped_path_is_the_full_runs::<f64>(mesh, source, target, false)
                .map_err(|e| TestCaseError::fail(format!("{kind:?} seed {seed}: {e}")))?;
            stopped_path_is_the_full_runs::<Adaptive>(mesh, source, target, false)
                .map_err(|e| TestCaseError::fail(format!("{kind:?} seed {seed}: {e}")))?;
        }
    }
}

/// The path to a stop point traced on the stopped run against the full run's: every wedge it
/// crosses lies nearer than the target, where the stopped run's wedges are final. The same
/// source and distance (to a vertex bit for bit, elsewhere to rounding: the wedge that gives a
/// point inside a face its distance may be another of equal value), and a path as long as the
/// distance ([`GeodesicField::trace_back`] checks it); where the full run's trace fails
/// (rounding sent it astray), the stopped run's may fail too. `identical`: the two paths also
/// cross the same simplices at the same points, bit for bit (no ties between wedges), and the
/// full run's trace must succeed. Whether the stopped run stopped before its end.
fn stopped_path_is_the_full_runs<S: Scalar>(
    mesh: &TriMesh,
    source: u32,
    target: &SurfacePoint,
    identical: bool,
) -> Result<bool, String> {
    let full = run::<S>(mesh, source, &[]);
    let stopped = run::<S>(mesh, source, std::slice::from_ref(target));
    let early = stopped.stats().stopped_at_stop_points;
    match (full.trace_back(target), stopped.trace_back(target)) {
        (Ok(want), Ok(got)) => {
            let same_distance = match target {
                SurfacePoint::Vertex(_) => want.distance.to_bits() == got.distance.to_bits(),
                _ => (want.distance - got.distance).abs() <= 1e-12 * want.distance.max(1.0),
            };
            let (start, end) = (got.simplices.first(), got.simplices.last());
            let same = same_distance
                && want.source == got.source
                && start == want.simplices.first()
                && end == want.simplices.last()
                && (got.length() - got.distance).abs() <= 1e-9 * got.distance.max(1.0)
                && (!identical || (got.simplices == want.simplices && got.points == want.points));
            match same {
                true => Ok(early),
                false => Err(format!("to {target:?}: {got:?}, full run {want:?}")),
            }
        }
        (Err(e), _) if identical => Err(format!("to {target:?}: the full run's trace: {e}")),
        (Err(_), _) => Ok(early),
        (Ok(want), Err(e)) => Err(format!("to {target:?}: {e}, full run {want:?}")),
    }
}

#[test]
fn paths_to_stop_points_are_the_full_runs() {
    let mut rng = SplitMix64::new(21);
    // Round a sphere, across flat ground and round the corners of a hole (pseudo-sources).
    let meshes = [
        shapes::icosphere(3),
        shapes::uv_sphere(16, 9),
        shapes::grid(12, 9, 3.0, 2.0),
        shapes::random_convex_triangulation(21, 12, 40),
        shapes::square_with_hole(6),
        shapes::l_shape(6),
    ];
    for mesh in &meshes {
        let n = mesh.vertex_count() as u32;
        let mut targets: Vec<SurfacePoint> = (1..n).step_by(7).map(vertex).collect();
        targets.extend((0..8).map(|_| common::random_face_point(mesh, &mut rng)));
        let mut early = 0;
        for target in &targets {
            early +=
                usize::from(stopped_path_is_the_full_runs::<f64>(mesh, 0, target, true).unwrap());
            stopped_path_is_the_full_runs::<Adaptive>(mesh, 0, target, true).unwrap();
        }
        assert!(
            2 * early > targets.len(),
            "{early} of {} runs stopped early",
            targets.len()
        );
    }
    let cube = shapes::cube();
    let early = (1..8)
        .filter(|&v| stopped_path_is_the_full_runs::<Real>(&cube, 0, &vertex(v), true).unwrap())
        .count();
    assert!(early >= 3, "{early} of 7 runs stopped early");
}
