//! `verify`: runs the engine on a benchmark model [LZT §5] and compares the geodesic from p to
//! q with the ground truth.

use crate::{load, with_backend, Backend, Job};
use clap::Args;
use exact_geodesics::benchmark_model::{path_deviation, ModelDescription};
use exact_geodesics::{PropagateOptions, SurfacePoint, VertexId};
use std::path::PathBuf;

#[derive(Args)]
pub struct VerifyArgs {
    /// The scene.json written by benchmark-model; its mesh is read from the same directory.
    scene: PathBuf,
    /// Number type of the engine.
    #[arg(long, value_enum, default_value_t = Backend::F64)]
    backend: Backend,
    /// Largest accepted relative error of d(p, q).
    #[arg(long, default_value_t = 1e-9)]
    distance_tolerance: f64,
    /// Largest accepted distance between the traced path and the ground-truth polyline.
    #[arg(long, default_value_t = 1e-7)]
    path_tolerance: f64,
}

pub fn run(args: &VerifyArgs) -> Result<(), String> {
    let name = args.scene.display();
    let text = std::fs::read_to_string(&args.scene).map_err(|e| format!("{name}: {e}"))?;
    let model: ModelDescription =
        serde_json::from_str(&text).map_err(|e| format!("{name}: {e}"))?;
    let mesh_path = args
        .scene
        .parent()
        .unwrap_or_else(|| std::path::Path::new("."))
        .join(&model.mesh);
    let mesh = load::load_mesh(&mesh_path.to_string_lossy(), &Default::default())?;
    if mesh.vertex_count() != model.vertex_count || mesh.face_count() != model.face_count {
        return Err(format!(
            "{}: {} vertices and {} faces, but {name} describes {} and {}",
            mesh_path.display(),
            mesh.vertex_count(),
            mesh.face_count(),
            model.vertex_count,
            model.face_count
        ));
    }
    let p = SurfacePoint::Vertex(VertexId(model.p_vertex))
        .validated(&mesh)
        .map_err(|e| format!("{name}: p: {e}"))?;
    let q = SurfacePoint::Vertex(VertexId(model.q_vertex))
        .validated(&mesh)
        .map_err(|e| format!("{name}: q: {e}"))?;
    let job = Job {
        mesh,
        sources: vec![p],
        options: PropagateOptions::default(),
        backend: args.backend,
        require_certified: false,
    };
    let (distance, path) = with_backend!(job.backend, S => {
        let field = job.field::<S>()?;
        (field.distance_at(&q).map_err(|e| e.to_string())?, field.trace_back(&q).map_err(|e| e.to_string())?)
    });
    let truth = model.ground_truth.length;
    let relative_error = (distance - truth).abs() / truth;
    let deviation = path_deviation(&path.points, &model.ground_truth.points);
    println!("d(p, q)                 {distance}");
    println!("ground truth            {truth}");
    println!("relative error          {relative_error:e}");
    println!("traced path to truth    {:e}", deviation.traced_to_truth);
    println!("truth to traced path    {:e}", deviation.truth_to_traced);
    println!("largest height on path  {:e}", deviation.max_height);
    if relative_error.is_nan() || relative_error > args.distance_tolerance {
        return Err(format!(
            "relative error of d(p, q) {relative_error:e} exceeds {:e}",
            args.distance_tolerance
        ));
    }
    if deviation.max().is_nan() || deviation.max() > args.path_tolerance {
        return Err(format!(
            "the traced path is {:e} from the ground truth, more than {:e}",
            deviation.max(),
            args.path_tolerance
        ));
    }
    Ok(())
}
