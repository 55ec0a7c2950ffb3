//! `wedges`: the final wedges as the paper prints them, `(b0, b1, d0, d1, tau, s, sigma)`.

use crate::{emit, spec, with_backend, Backend, Common};
use clap::{Args, ValueEnum};
use exact_geodesics::paper::table::edge_rows;
use exact_geodesics::{EdgeId, FaceId, VertexId};
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum WedgesFormat {
    Text,
    Json,
}

#[derive(Args)]
pub struct WedgesArgs {
    #[command(flatten)]
    common: Common,
    /// Only the edge joining vertices A and B, parameters measured from A.
    #[arg(long, value_name = "A,B", conflicts_with = "face")]
    edge: Option<String>,
    /// Only the three edges of face F, in the face's vertex order, tau relative to F.
    #[arg(long, value_name = "F")]
    face: Option<u32>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = WedgesFormat::Text)]
    format: WedgesFormat,
    /// Write to this file instead of stdout.
    #[arg(long)]
    out: Option<PathBuf>,
}

pub fn run(args: &WedgesArgs) -> Result<(), String> {
    let job = args.common.job()?;
    let mesh = &job.mesh;
    // Each selected edge: (from, id, face that tau is relative to).
    let mut selected: Vec<(VertexId, EdgeId, Option<FaceId>)> = Vec::new();
    if let Some(text) = &args.edge {
        let (a, b) = spec::parse_vertex_pair(text)?;
        let (a, b) = (VertexId(a), VertexId(b));
        let e = (a.index() < mesh.vertex_count() && b.index() < mesh.vertex_count())
            .then(|| mesh.edge_between(a, b))
            .flatten()
            .ok_or_else(|| {
                format!(
                    "--edge {text}: no edge of {} joins vertices {} and {}",
                    args.common.mesh, a.0, b.0
                )
            })?;
        selected.push((a, e, None));
    } else if let Some(f) = args.face {
        if f as usize >= mesh.face_count() {
            return Err(format!(
                "--face {f}: face {f} is out of range: {} has {} faces",
                args.common.mesh,
                mesh.face_count()
            ));
        }
        let face = FaceId(f);
        let corners = mesh.face(face);
        for (i, e) in mesh.face_edges(face).into_iter().enumerate() {
            selected.push((corners[i], e, Some(face)));
        }
    } else {
        for (i, e) in mesh.edges().iter().enumerate() {
            selected.push((e.vertices[0], EdgeId(i as u32), None));
        }
    }
    let edges = with_backend!(job.backend, S => {
        let field = job.field::<S>()?;
        selected
            .iter()
            .map(|&(a, e, face)| edge_rows(&field, a, e, face))
            .collect::<Vec<_>>()
    });
    let text = match args.format {
        WedgesFormat::Json => {
            let mut s = serde_json::to_string_pretty(&edges).expect("JSON of plain values");
            s.push('\n');
            s
        }
        WedgesFormat::Text => edges.iter().map(ToString::to_string).collect(),
    };
    emit(args.out.as_ref(), &text)
}
