//! `benchmark-model`: the benchmark model of [LZT §5], written as a mesh and a JSON description
//! holding p, q and the ground-truth geodesic.

use clap::Args;
use exact_geodesics::benchmark_model::{BenchmarkModel, ModelOptions, Scene};
use exact_geodesics::mesh::io::write_path;
use std::path::PathBuf;
use std::time::Instant;

/// The mesh file's name inside `--out`.
const MESH_FILE: &str = "scene.obj";

#[derive(Args)]
pub struct BenchmarkModelArgs {
    /// Seed of the random scene.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Number of obstacles in the random scene, at most 10000 (the visibility graph grows with
    /// the square of their corners: 10000 take about 15 s).
    #[arg(long, default_value_t = 8, value_parser = clap::value_parser!(u64).range(0..=10_000))]
    obstacles: u64,
    /// A scene written as JSON instead of a random one:
    /// {"rectangle": {"min": [x, y], "max": [x, y]}, "obstacles": [[[x, y], ...], ...], "p": [x, y], "q": [x, y]}.
    #[arg(long, conflicts_with_all = ["seed", "obstacles"])]
    scene: Option<PathBuf>,
    /// Smallest angle of the refined floor triangles, in degrees (0: no angle refinement).
    #[arg(long, default_value_t = ModelOptions::default().min_angle)]
    min_angle: f64,
    /// Largest area of a floor triangle.
    #[arg(long)]
    max_area: Option<f64>,
    /// Rows of quads in each cylinder wall.
    #[arg(long, default_value_t = ModelOptions::default().wall_rows)]
    wall_rows: usize,
    /// Most vertices refinement may add before giving up.
    #[arg(long, default_value_t = ModelOptions::default().max_additional_vertices)]
    max_additional_vertices: usize,
    /// Directory for scene.obj and scene.json, created if missing.
    #[arg(long)]
    out: PathBuf,
}

pub fn run(args: &BenchmarkModelArgs) -> Result<(), String> {
    let start = Instant::now();
    let (scene, seed) = match &args.scene {
        Some(path) => {
            let text =
                std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
            let scene = Scene::from_json(&text).map_err(|e| format!("{}: {e}", path.display()))?;
            (scene, None)
        }
        None => (
            Scene::random(args.seed, args.obstacles as usize),
            Some(args.seed),
        ),
    };
    let options = ModelOptions {
        min_angle: args.min_angle,
        max_area: args.max_area,
        wall_rows: args.wall_rows,
        max_additional_vertices: args.max_additional_vertices,
    };
    let model = BenchmarkModel::build(&scene, &options).map_err(|e| e.to_string())?;
    let built = start.elapsed();
    std::fs::create_dir_all(&args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
    write_path(&model.mesh, &args.out.join(MESH_FILE)).map_err(|e| e.to_string())?;
    let json_path = args.out.join("scene.json");
    let mut json = serde_json::to_string_pretty(&model.description(MESH_FILE, seed))
        .expect("JSON of plain values");
    json.push('\n');
    std::fs::write(&json_path, json).map_err(|e| format!("{}: {e}", json_path.display()))?;
    println!(
        "{}: {} vertices, {} faces, built in {:.3} s",
        args.out.join(MESH_FILE).display(),
        model.mesh.vertex_count(),
        model.mesh.face_count(),
        built.as_secs_f64()
    );
    println!(
        "{}: p = v:{}, q = v:{}, ground-truth length {} through {} corners",
        json_path.display(),
        model.p.0,
        model.q.0,
        model.ground_truth.length,
        model.ground_truth.points.len()
    );
    Ok(())
}
