//! The benchmark model of [LZT §5]: visibility-graph ground truths, the lifted meshes, scene
//! files, and the engine against the ground truth over many seeds and refinement levels.

use exact_geodesics::benchmark_model::{
    path_deviation, shortest_path, BenchmarkError, BenchmarkModel, ModelDescription, ModelOptions,
    Point, Rectangle, Scene,
};
use exact_geodesics::glam::DVec2;
use exact_geodesics::{propagate, PropagateOptions, SurfacePoint, TriMesh, VertexId};
use std::collections::HashMap;

fn scene(obstacles: Vec<Vec<Point>>, p: Point, q: Point) -> Scene {
    Scene {
        rectangle: Rectangle {
            min: [-1.0, -1.0],
            max: [5.0, 5.0],
        },
        obstacles,
        p,
        q,
    }
}

fn square() -> Vec<Point> {
    vec![[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]]
}

fn u_shape() -> Vec<Point> {
    vec![
        [0.0, 0.0],
        [3.0, 0.0],
        [3.0, 3.0],
        [2.0, 3.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 3.0],
        [0.0, 3.0],
    ]
}

fn assert_path(scene: &Scene, length: f64, points: &[Point]) {
    let path = shortest_path(scene).expect("a valid scene");
    assert!(
        (path.length - length).abs() <= 1e-14 * length,
        "length {} instead of {length}",
        path.length
    );
    assert_eq!(path.points, points);
}

#[test]
fn around_one_square_by_the_shorter_side() {
    // Over the top: sqrt(2) + 2 + sqrt(1.25); under it: sqrt(2) + 2 + sqrt(3.25).
    let s = scene(vec![square()], [0.0, 2.0], [4.0, 2.5]);
    let expected = 2f64.sqrt() + 2.0 + 1.25f64.sqrt();
    assert_path(
        &s,
        expected,
        &[[0.0, 2.0], [1.0, 3.0], [3.0, 3.0], [4.0, 2.5]],
    );
}

#[test]
fn clear_sight_grazing_a_corner_or_running_along_an_edge_is_not_blocked() {
    let direct = scene(vec![square()], [0.0, 0.5], [4.0, 0.5]);
    assert_path(&direct, 4.0, &[[0.0, 0.5], [4.0, 0.5]]);
    // Along the square's bottom edge, touching two corners.
    let along = scene(vec![square()], [0.0, 1.0], [4.0, 1.0]);
    assert_eq!(shortest_path(&along).expect("valid").length, 4.0);
    // Through a corner of a triangle that lies on one side of the line.
    let triangle = vec![[2.0, 2.0], [3.0, 3.5], [1.0, 3.5]];
    let grazing = scene(vec![triangle], [0.0, 0.0], [4.0, 4.0]);
    assert_path(&grazing, 32f64.sqrt(), &[[0.0, 0.0], [4.0, 4.0]]);
    // The diagonal of the square goes through its interior.
    let blocked = scene(vec![square()], [0.5, 0.5], [3.5, 3.5]);
    let expected = 2.0 * 6.5f64.sqrt();
    assert!((shortest_path(&blocked).expect("valid").length - expected).abs() < 1e-14);
}

#[test]
fn out_of_a_u_shaped_pocket_around_the_nearer_arm() {
    // From inside the pocket, up past the left arm's inner corner and down its outer side.
    let s = scene(vec![u_shape()], [1.4, 2.0], [1.5, -0.5]);
    let expected = 1.16f64.sqrt() + 1.0 + 3.0 + 2.5f64.sqrt();
    assert_path(
        &s,
        expected,
        &[[1.4, 2.0], [1.0, 3.0], [0.0, 3.0], [0.0, 0.0], [1.5, -0.5]],
    );
    // A clockwise obstacle is the same obstacle.
    let mut clockwise = s.clone();
    clockwise.obstacles[0].reverse();
    assert_eq!(shortest_path(&clockwise), shortest_path(&s));
}

fn check_engine(model: &BenchmarkModel) -> (f64, f64) {
    let field = propagate::<f64>(
        &model.mesh,
        &[SurfacePoint::Vertex(model.p)],
        &PropagateOptions::default(),
    )
    .expect("the engine runs");
    let truth = model.ground_truth.length;
    let error = (field.vertex_distance(model.q) - truth).abs() / truth;
    let path = field
        .trace_back(&SurfacePoint::Vertex(model.q))
        .expect("a path back to p");
    let deviation = path_deviation(&path.points, &model.ground_truth.points);
    (error, deviation.max())
}

#[test]
fn the_engine_finds_the_u_pocket_geodesic_on_the_lifted_mesh() {
    let s = scene(vec![u_shape()], [1.4, 2.0], [1.5, -0.5]);
    for options in [
        ModelOptions::default(),
        ModelOptions {
            min_angle: 28.0,
            max_area: Some(0.01),
            wall_rows: 4,
            ..ModelOptions::default()
        },
    ] {
        let model = BenchmarkModel::build(&s, &options).expect("a valid scene");
        let (error, deviation) = check_engine(&model);
        assert!(
            error <= 1e-9 && deviation <= 1e-7,
            "{error:e} {deviation:e}"
        );
    }
}

/// Three refinement levels: the plain CDT, angle refinement, angle and area refinement with
/// walls in rows.
fn levels() -> [ModelOptions; 3] {
    [
        ModelOptions {
            min_angle: 0.0,
            ..ModelOptions::default()
        },
        ModelOptions {
            min_angle: 25.0,
            wall_rows: 2,
            ..ModelOptions::default()
        },
        ModelOptions {
            min_angle: 28.0,
            max_area: Some(0.01),
            wall_rows: 3,
            ..ModelOptions::default()
        },
    ]
}

#[test]
fn f64_geodesics_match_the_ground_truth_over_seeds_and_refinement_levels() {
    let mut bends = HashMap::new();
    for seed in 0..50 {
        let s = Scene::random(seed, 2 + seed as usize % 11);
        for (level, options) in levels().iter().enumerate() {
            let model = BenchmarkModel::build(&s, options).expect("random scenes are valid");
            let (error, deviation) = check_engine(&model);
            assert!(
                error <= 1e-9,
                "seed {seed} level {level}: relative error {error:e}"
            );
            assert!(
                deviation <= 1e-7,
                "seed {seed} level {level}: path {deviation:e} from the ground truth"
            );
            *bends
                .entry(model.ground_truth.points.len() - 2)
                .or_insert(0) += 1;
        }
    }
    // The seeds exercise paths that bend once and several times, not only straight ones.
    assert!(bends.get(&1).is_some_and(|&n| n > 0), "{bends:?}");
    assert!(bends.keys().any(|&k| k >= 3), "{bends:?}");
}

#[test]
fn random_scenes_are_valid_deterministic_and_mix_convex_and_concave_obstacles() {
    let mut concave = 0;
    let mut convex = 0;
    for seed in 0..30 {
        let s = Scene::random(seed, 1 + seed as usize % 12);
        assert_eq!(s, Scene::random(seed, 1 + seed as usize % 12));
        assert_eq!(s.validate(), Ok(()), "seed {seed}");
        for o in &s.obstacles {
            let n = o.len();
            let turns = (0..n).map(|i| {
                let (a, b, c) = (o[(i + n - 1) % n], o[i], o[(i + 1) % n]);
                (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
            });
            let (left, right) = turns.fold(
                (0, 0),
                |(l, r), t| {
                    if t > 0.0 {
                        (l + 1, r)
                    } else {
                        (l, r + 1)
                    }
                },
            );
            if left == 0 || right == 0 {
                convex += 1;
            } else {
                concave += 1;
            }
        }
    }
    assert!(
        convex > 10 && concave > 20,
        "{convex} convex, {concave} concave"
    );
}

/// Edges with one face, as (smaller, larger) vertex pairs.
fn boundary_edges(mesh: &TriMesh) -> Vec<(u32, u32)> {
    let mut count: HashMap<(u32, u32), usize> = HashMap::new();
    for f in mesh.faces() {
        for i in 0..3 {
            let (a, b) = (f[i], f[(i + 1) % 3]);
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    count
        .into_iter()
        .filter(|&(_, n)| n == 1)
        .map(|(e, _)| e)
        .collect()
}

#[test]
fn lifted_meshes_are_oriented_manifold_disks_with_closed_cylinders() {
    for seed in 0..8 {
        let s = Scene::random(100 + seed, 3 + seed as usize);
        for options in levels() {
            let model = BenchmarkModel::build(&s, &options).expect("valid");
            let mesh = &model.mesh;
            let report = mesh.validation();
            assert!(report.zero_area_faces.is_empty(), "seed {seed}");
            assert!(report.unreferenced_vertices.is_empty(), "seed {seed}");
            assert!(report.non_manifold_vertices.is_empty(), "seed {seed}");
            assert_eq!(report.inconsistently_oriented_edges, 0, "seed {seed}");
            assert_eq!(report.components, 1);
            // The rectangle is the only boundary: every cylinder is closed by its cap and sewn
            // to the floor, and the surface is a disk (Euler characteristic 1).
            let r = &s.rectangle;
            for (a, b) in boundary_edges(mesh) {
                for v in [a, b] {
                    let x = mesh.position(VertexId(v));
                    let on_side = x[0] == r.min[0]
                        || x[0] == r.max[0]
                        || x[1] == r.min[1]
                        || x[1] == r.max[1];
                    assert!(on_side && x[2] == 0.0, "seed {seed}: boundary at {x:?}");
                }
            }
            let euler =
                mesh.vertex_count() as i64 - mesh.edge_count() as i64 + mesh.face_count() as i64;
            assert_eq!(euler, 1, "seed {seed}");
            // Heights are the floor's, the walls' rows and the caps'.
            let rows = options.wall_rows as f64;
            for x in mesh.positions() {
                let row = x.z / model.wall_height * rows;
                assert!((row - row.round()).abs() < 1e-12 && (0.0..=rows).contains(&row.round()));
            }
            for (v, xy) in [(model.p, s.p), (model.q, s.q)] {
                assert_eq!(mesh.position(v), DVec2::from(xy).extend(0.0));
            }
            assert!(model.wall_height >= model.ground_truth.length);
        }
    }
}

#[test]
fn scenes_and_descriptions_round_trip_through_json() {
    let s = Scene::random(5, 6);
    assert_eq!(Scene::from_json(&s.to_json()), Ok(s.clone()));
    let model = BenchmarkModel::build(&s, &ModelOptions::default()).expect("valid");
    let description = model.description("scene.obj", Some(5));
    let text = serde_json::to_string(&description).expect("JSON");
    let back: ModelDescription = serde_json::from_str(&text).expect("its own JSON");
    assert_eq!(back, description);
    assert_eq!(back.p_vertex, model.p.0);
    assert_eq!(back.ground_truth, model.ground_truth);
    // A scene written by hand, in the documented form.
    let hand = r#"{"rectangle": {"min": [-1, -1], "max": [5, 5]},
        "obstacles": [[[1, 1], [3, 1], [3, 3], [1, 3]]], "p": [0, 2], "q": [4, 2.5]}"#;
    let s = Scene::from_json(hand).expect("a scene");
    assert_eq!(s, scene(vec![square()], [0.0, 2.0], [4.0, 2.5]));
}

#[test]
fn bad_scenes_and_options_are_typed_errors() {
    let build = |s: &Scene| build_with(s, &ModelOptions::default());
    let shifted = |dx: f64, dy: f64| square().iter().map(|x| [x[0] + dx, x[1] + dy]).collect();
    let overlap = scene(vec![square(), shifted(1.0, 1.0)], [0.0, 0.0], [4.5, 0.0]);
    let overlap_error = Err(BenchmarkError::ObstaclesOverlap {
        first: 0,
        second: 1,
    });
    assert_eq!(build(&overlap), overlap_error);
    let touching = vec![[3.0, 3.0], [4.0, 3.5], [3.5, 4.0]];
    let corner_touch = scene(vec![square(), touching], [0.0, 0.0], [4.5, 0.0]);
    assert_eq!(corner_touch.validate(), overlap_error);
    let nested = vec![[1.5, 1.5], [2.5, 1.5], [2.0, 2.5]];
    let nested = scene(vec![square(), nested], [0.0, 0.0], [4.5, 0.0]);
    assert_eq!(nested.validate(), overlap_error);

    let p_inside = scene(vec![square()], [2.0, 2.0], [4.0, 4.0]);
    let p_error = Err(BenchmarkError::PointInObstacle {
        point: "p",
        obstacle: 0,
    });
    assert_eq!(build(&p_inside), p_error);
    let q_on_edge = scene(vec![square()], [0.0, 0.0], [3.0, 2.0]);
    assert!(matches!(
        q_on_edge.validate(),
        Err(BenchmarkError::PointInObstacle { point: "q", .. })
    ));

    let bowtie = vec![[1.0, 1.0], [3.0, 3.0], [3.0, 1.0], [1.0, 3.0]];
    assert!(matches!(
        scene(vec![bowtie], [0.0, 0.0], [4.0, 4.0]).validate(),
        Err(BenchmarkError::SelfIntersecting { obstacle: 0, .. })
    ));
    let collinear = vec![[1.0, 1.0], [2.0, 1.0], [3.0, 1.0], [2.0, 3.0]];
    assert_eq!(
        scene(vec![collinear], [0.0, 0.0], [4.0, 4.0]).validate(),
        Err(BenchmarkError::DegenerateCorner {
            obstacle: 0,
            corner: 1
        })
    );
    let outside = shifted(3.5, 0.0);
    assert_eq!(
        scene(vec![outside], [0.0, 0.0], [0.0, 4.0]).validate(),
        Err(BenchmarkError::ObstacleOutsideRectangle { obstacle: 0 })
    );
    assert!(matches!(
        Scene::from_json(r#"{"obstacles": []}"#),
        Err(BenchmarkError::Json(_))
    ));

    let fine = scene(vec![square()], [0.0, 2.0], [4.0, 2.5]);
    let no_rows = ModelOptions {
        wall_rows: 0,
        ..ModelOptions::default()
    };
    assert!(matches!(
        BenchmarkModel::build(&fine, &no_rows),
        Err(BenchmarkError::InvalidOption {
            name: "wall_rows",
            ..
        })
    ));
    let starved = ModelOptions {
        max_area: Some(1e-4),
        max_additional_vertices: 50,
        ..ModelOptions::default()
    };
    assert_eq!(
        build_with(&fine, &starved),
        Err(BenchmarkError::RefinementIncomplete { budget: 50 })
    );
}

fn build_with(s: &Scene, options: &ModelOptions) -> Result<(), BenchmarkError> {
    BenchmarkModel::build(s, options).map(|_| ())
}

/// The ground truth as an exact real: the sum of the exact lengths of its segments.
fn exact_length(path: &[Point]) -> exact_geodesics::scalar::Real {
    use exact_geodesics::scalar::{Field, Real, Ring};
    path.windows(2).fold(Real::from_f64(0.0), |sum, s| {
        let dx = Real::from_f64(s[1][0]) - Real::from_f64(s[0][0]);
        let dy = Real::from_f64(s[1][1]) - Real::from_f64(s[0][1]);
        sum + (dx.clone() * dx + dy.clone() * dy).sqrt()
    })
}

#[test]
fn exact_backend_distance_equals_the_ground_truth_exactly_on_small_scenes() {
    use exact_geodesics::scalar::{exact::Certificate, Real, Sign};
    let mut scenes = vec![
        scene(vec![square()], [0.0, 0.0], [4.0, 3.5]),
        scene(vec![u_shape()], [1.5, 2.0], [4.0, 4.0]),
    ];
    scenes.extend((0..2).map(|seed| Scene::random(seed, 2)));
    for scene in &scenes {
        let model = BenchmarkModel::build(scene, &ModelOptions::default()).expect("a valid scene");
        let field = propagate::<Real>(
            &model.mesh,
            &[SurfacePoint::Vertex(model.p)],
            &PropagateOptions::default(),
        )
        .expect("p is a vertex");
        let engine = field.vertex_distance_exact(model.q).expect("q is reached");
        let truth = exact_length(&model.ground_truth.points);
        let (sign, how) = (engine.clone() - &truth).certified_sign();
        assert!(
            sign == Sign::Zero && matches!(how, Certificate::CertifiedZero(_)),
            "{:?}: {how:?}, engine {engine:?}, ground truth {truth:?}",
            scene.obstacles
        );
    }
}
