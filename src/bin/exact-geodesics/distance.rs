//! `distance`: the geodesic distance of every vertex.

use crate::{emit, with_backend, Backend, Common};
use clap::{Args, ValueEnum};
use exact_geodesics::{GeodesicField, Scalar, VertexId};
use std::fmt::Write;
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum DistanceFormat {
    Csv,
    Json,
}

#[derive(Args)]
pub struct DistanceArgs {
    #[command(flatten)]
    common: Common,
    /// Output format.
    #[arg(long, value_enum, default_value_t = DistanceFormat::Csv)]
    format: DistanceFormat,
    /// Write to this file instead of stdout.
    #[arg(long)]
    out: Option<PathBuf>,
}

pub fn run(args: &DistanceArgs) -> Result<(), String> {
    let job = args.common.job()?;
    let text = with_backend!(job.backend, S => render(&job.field::<S>()?, args.format));
    emit(args.out.as_ref(), &text)
}

fn render<S: Scalar>(field: &GeodesicField<'_, S>, format: DistanceFormat) -> String {
    let n = field.mesh().vertex_count();
    let rows = (0..n).map(|v| {
        let v = VertexId(v as u32);
        (v.0, field.vertex_distance(v), field.nearest_source(v))
    });
    match format {
        DistanceFormat::Csv => {
            let mut out = String::with_capacity(32 * n);
            out.push_str("vertex,distance,source\n");
            for (v, d, s) in rows {
                let s = s.map(|s| s.to_string()).unwrap_or_default();
                writeln!(out, "{v},{},{s}", Shortest(d)).expect("writing to a String");
            }
            out
        }
        DistanceFormat::Json => {
            let rows: Vec<serde_json::Value> = rows
                .map(|(v, d, s)| {
                    serde_json::json!({"vertex": v, "distance": d.is_finite().then_some(d), "source": s})
                })
                .collect();
            let mut out = serde_json::to_string_pretty(&serde_json::json!({
                "unreachable": "distance null",
                "vertices": rows,
            }))
            .expect("JSON of plain values");
            out.push('\n');
            out
        }
    }
}

/// An `f64` in its shortest round-trip form: plain decimals in everyday magnitudes, exponent
/// notation beyond them (`1e-150`, not 150 zeros).
struct Shortest(f64);

impl std::fmt::Display for Shortest {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        if x == 0.0 || !x.is_finite() || (1e-5..1e16).contains(&x.abs()) {
            write!(f, "{x}")
        } else {
            write!(f, "{x:e}")
        }
    }
}
