//! `path`: the shortest path from a target back to its nearest source.

use crate::{certified_digits, emit, spec, with_backend, Backend, Common, Digits};
use clap::{Args, ValueEnum};
use exact_geodesics::scalar::Real;
use exact_geodesics::{GeodesicPath, SurfacePoint};
use std::fmt::Write;
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum PathFormat {
    Json,
    Csv,
    Obj,
}

#[derive(Args)]
pub struct PathArgs {
    #[command(flatten)]
    common: Common,
    /// With --digits, the path's length (the target's geodesic distance) is printed with that
    /// many certified digits too (`distance_digits` in JSON, the OBJ header).
    #[command(flatten)]
    digits: Digits,
    /// The point to trace back from (same forms as --source).
    #[arg(long)]
    target: String,
    /// Output format.
    #[arg(long, value_enum, default_value_t = PathFormat::Json)]
    format: PathFormat,
    /// Write to this file instead of stdout.
    #[arg(long)]
    out: Option<PathBuf>,
}

pub fn run(args: &PathArgs) -> Result<(), String> {
    let mut job = args.common.job()?;
    let target = spec::parse_point(&job.mesh, &args.common.mesh, &args.target)?;
    // The run stops once the target's distance is final: the wedges the path crosses are
    // nearer, and final then too.
    job.options.stop_points = vec![target];
    let (path, digits) = match args.digits.checked(job.backend)? {
        Some(digits) => {
            let field = job.field::<Real>()?;
            let path = field.trace_back(&target).map_err(|e| e.to_string())?;
            let exact = field
                .distance_at_exact(&target)
                .map_err(|e| e.to_string())?;
            let exact = exact.ok_or("the target is unreachable from every source")?;
            let text = certified_digits(&exact, digits, &args.target)?;
            (path, Some(text))
        }
        None => {
            let path = with_backend!(job.backend, S => job.field::<S>()?.trace_back(&target).map_err(|e| e.to_string())?);
            (path, None)
        }
    };
    emit(args.out.as_ref(), &render(&path, digits, args.format))
}

fn simplex(p: &SurfacePoint) -> String {
    match p {
        SurfacePoint::Vertex(v) => format!("v:{}", v.0),
        SurfacePoint::Edge { edge, t } => format!("edge:{},{t}", edge.0),
        SurfacePoint::Face { face, bary } => {
            format!("f:{},{},{},{}", face.0, bary[0], bary[1], bary[2])
        }
    }
}

/// The path in `format`; `digits`: its length in certified digits, if asked for.
fn render(path: &GeodesicPath, digits: Option<String>, format: PathFormat) -> String {
    let mut out = String::new();
    match format {
        PathFormat::Json => {
            let mut json = serde_json::json!({
                "distance": path.distance,
                "length": path.length(),
                "source": path.source,
                "points": path.points,
                "simplices": path.simplices.iter().map(simplex).collect::<Vec<_>>(),
            });
            if let Some(digits) = digits {
                json["distance_digits"] = serde_json::json!(digits);
            }
            out = serde_json::to_string_pretty(&json).expect("JSON of plain values");
            out.push('\n');
        }
        PathFormat::Csv => {
            out.push_str("index,x,y,z,simplex\n");
            for (i, (p, s)) in path.points.iter().zip(&path.simplices).enumerate() {
                writeln!(out, "{i},{},{},{},{}", p.x, p.y, p.z, simplex(s)).expect("String");
            }
        }
        PathFormat::Obj => {
            writeln!(
                out,
                "# geodesic path, length {}, from target to source {}",
                path.length(),
                path.source.0
            )
            .expect("String");
            if let Some(digits) = digits {
                writeln!(out, "# geodesic distance, certified digits: {digits}").expect("String");
            }
            for p in &path.points {
                writeln!(out, "v {} {} {}", p.x, p.y, p.z).expect("String");
            }
            let ids: Vec<String> = (1..=path.points.len()).map(|i| i.to_string()).collect();
            writeln!(out, "l {}", ids.join(" ")).expect("String");
        }
    }
    out
}
