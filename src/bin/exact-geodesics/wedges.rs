//! `wedges`: the final wedges as the paper prints them, `(b0, b1, d0, d1, tau, s, sigma)`.

use crate::{emit, spec, with_backend, Backend, Common};
use clap::{Args, ValueEnum};
use exact_geodesics::{
    EdgeId, FaceId, GeodesicField, PseudoSource, Scalar, SurfacePoint, VertexId, Wedge,
};
use serde::Serialize;
use std::fmt::Write;
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

/// One wedge in the paper's 7-tuple form [LZT Example 4].
#[derive(Serialize)]
struct Row {
    b0: f64,
    b1: f64,
    d0: f64,
    d1: f64,
    /// Relative to a face: true if the wedge comes from outside it. Otherwise the face on the
    /// pseudo-source's side.
    tau: String,
    s: String,
    sigma: f64,
}

#[derive(Serialize)]
struct EdgeRows {
    from: u32,
    to: u32,
    wedges: Vec<Row>,
}

pub fn run(args: &WedgesArgs) -> Result<(), String> {
    let job = args.common.job()?;
    let mesh = &job.mesh;
    // Each selected edge: (from, to, id, face that tau is relative to).
    let mut selected: Vec<(VertexId, VertexId, EdgeId, Option<FaceId>)> = Vec::new();
    if let Some(text) = &args.edge {
        let (a, b) = spec::parse_vertex_pair(text)?;
        let (a, b) = (VertexId(a), VertexId(b));
        let e = (a.index() < mesh.vertex_count() && b.index() < mesh.vertex_count())
            .then(|| mesh.edge_between(a, b))
            .flatten()
            .ok_or_else(|| format!("no edge joins vertices {} and {}", a.0, b.0))?;
        selected.push((a, b, e, None));
    } else if let Some(f) = args.face {
        if f as usize >= mesh.face_count() {
            return Err(format!(
                "face {f} is out of range: the mesh has {} faces",
                mesh.face_count()
            ));
        }
        let face = FaceId(f);
        let corners = mesh.face(face);
        for (i, e) in mesh.face_edges(face).into_iter().enumerate() {
            selected.push((corners[i], corners[(i + 1) % 3], e, Some(face)));
        }
    } else {
        for (i, e) in mesh.edges().iter().enumerate() {
            selected.push((e.vertices[0], e.vertices[1], EdgeId(i as u32), None));
        }
    }
    let edges = with_backend!(job.backend, S => {
        let field = job.field::<S>()?;
        selected
            .iter()
            .map(|&(a, b, e, face)| EdgeRows { from: a.0, to: b.0, wedges: rows(&field, a, e, face) })
            .collect::<Vec<_>>()
    });
    let text = match args.format {
        WedgesFormat::Json => {
            let mut s = serde_json::to_string_pretty(&edges).expect("JSON of plain values");
            s.push('\n');
            s
        }
        WedgesFormat::Text => {
            let mut s = String::new();
            for e in &edges {
                writeln!(
                    s,
                    "There are {} wedges at edge (v{}, v{}):",
                    e.wedges.len(),
                    e.from,
                    e.to
                )
                .expect("String");
                for r in &e.wedges {
                    writeln!(
                        s,
                        "({:.3}, {:.3}, {:.3}, {:.3}, {}, {}, {:.3})",
                        r.b0, r.b1, r.d0, r.d1, r.tau, r.s, r.sigma
                    )
                    .expect("String");
                }
            }
            s
        }
    };
    emit(args.out.as_ref(), &text)
}

fn pseudo_source_name<S: Scalar>(field: &GeodesicField<'_, S>, w: &Wedge<S>) -> String {
    match w.pseudo_source {
        PseudoSource::Vertex(v) => format!("v{}", v.0),
        PseudoSource::Source(k) => match field.sources()[k] {
            SurfacePoint::Vertex(v) => format!("v{}", v.0),
            _ => format!("source{k}"),
        },
    }
}

/// The wedges of edge `e` read from vertex `from`, tau relative to `face` when given.
fn rows<S: Scalar>(
    field: &GeodesicField<'_, S>,
    from: VertexId,
    e: EdgeId,
    face: Option<FaceId>,
) -> Vec<Row> {
    let mesh = field.mesh();
    let edge = mesh.edge(e);
    let length = field.edge_length(e).to_f64();
    let reversed = edge.vertices[0] != from;
    let mut out: Vec<Row> = field
        .wedges(e)
        .iter()
        .map(|w| {
            let on_line = w.source_y.to_f64() == 0.0;
            let source_face = edge.faces[w.tau.index()];
            let tau = match face {
                Some(f) => (!on_line && source_face != Some(f)).to_string(),
                None if on_line => "line".to_string(),
                None => source_face.map_or("none".into(), |f| format!("f{}", f.0)),
            };
            let (b0, b1, d0, d1) = (
                w.b0.to_f64(),
                w.b1.to_f64(),
                w.d0().to_f64(),
                w.d1().to_f64(),
            );
            let (b0, b1, d0, d1) = if reversed {
                (length - b1, length - b0, d1, d0)
            } else {
                (b0, b1, d0, d1)
            };
            Row {
                b0,
                b1,
                d0,
                d1,
                tau,
                s: pseudo_source_name(field, w),
                sigma: w.sigma.to_f64(),
            }
        })
        .collect();
    if reversed {
        out.reverse();
    }
    out
}
