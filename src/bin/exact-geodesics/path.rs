//! `path`: the shortest path from a target back to its nearest source.

use crate::{emit, spec, with_backend, Backend, Common};
use clap::{Args, ValueEnum};
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
    let job = args.common.job()?;
    let target = spec::parse_point(&job.mesh, &args.common.mesh, &args.target)?;
    let path = with_backend!(job.backend, S => job.field::<S>()?.trace_back(&target).map_err(|e| e.to_string())?);
    emit(args.out.as_ref(), &render(&path, args.format))
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

fn render(path: &GeodesicPath, format: PathFormat) -> String {
    let mut out = String::new();
    match format {
        PathFormat::Json => {
            let json = serde_json::json!({
                "distance": path.distance,
                "length": path.length(),
                "source": path.source,
                "points": path.points,
                "simplices": path.simplices.iter().map(simplex).collect::<Vec<_>>(),
            });
            out = serde_json::to_string_pretty(&json).expect("JSON of plain values");
            out.push('\n');
        }
        PathFormat::Csv => {
            out.push_str("index,x,y,z,simplex\n");
            for (i, (p, s)) in path.points.iter().zip(&path.simplices).enumerate() {
                writeln!(out, "{i},{},{},{},{}", p[0], p[1], p[2], simplex(s)).expect("String");
            }
        }
        PathFormat::Obj => {
            writeln!(
                out,
                "# geodesic path, length {}, from target to source {}",
                path.length(),
                path.source
            )
            .expect("String");
            for p in &path.points {
                writeln!(out, "v {} {} {}", p[0], p[1], p[2]).expect("String");
            }
            let ids: Vec<String> = (1..=path.points.len()).map(|i| i.to_string()).collect();
            writeln!(out, "l {}", ids.join(" ")).expect("String");
        }
    }
    out
}
