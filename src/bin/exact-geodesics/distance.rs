//! `distance`: the geodesic distance of every vertex.

use crate::{certified_digits, emit, with_backend, Backend, Common, Digits};
use clap::{Args, ValueEnum};
use exact_geodesics::scalar::Real;
use exact_geodesics::{Scalar, SourceId, VertexField, VertexId};
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
    #[command(flatten)]
    digits: Digits,
    /// Output format.
    #[arg(long, value_enum, default_value_t = DistanceFormat::Csv)]
    format: DistanceFormat,
    /// Write to this file instead of stdout.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// A vertex's distance as printed: an `f64`, or certified digits of the exact value.
enum Distance {
    Float(f64),
    Digits(String),
}

pub fn run(args: &DistanceArgs) -> Result<(), String> {
    let job = args.common.job()?;
    let rows = match args.digits.checked(job.backend)? {
        Some(digits) => exact_rows(&job.vertex_field::<Real>()?, digits)?,
        None => with_backend!(job.backend, S => float_rows(&job.vertex_field::<S>()?)),
    };
    emit(args.out.as_ref(), &render(rows, args.format))
}

type Row = (u32, Distance, Option<SourceId>);

fn float_rows<S: Scalar>(field: &VertexField<'_, S>) -> Vec<Row> {
    (0..field.mesh().vertex_count() as u32)
        .map(VertexId)
        .map(|v| {
            let d = Distance::Float(field.vertex_distance(v));
            (v.0, d, field.nearest_source(v))
        })
        .collect()
}

fn exact_rows(field: &VertexField<'_, Real>, digits: u32) -> Result<Vec<Row>, String> {
    (0..field.mesh().vertex_count() as u32)
        .map(VertexId)
        .map(|v| {
            let d = match field.vertex_distance_exact(v) {
                Some(d) => Distance::Digits(certified_digits(&d, digits, &format!("v{}", v.0))?),
                None => Distance::Float(f64::INFINITY),
            };
            Ok((v.0, d, field.nearest_source(v)))
        })
        .collect()
}

fn render(rows: Vec<Row>, format: DistanceFormat) -> String {
    match format {
        DistanceFormat::Csv => {
            let mut out = String::with_capacity(32 * rows.len());
            out.push_str("vertex,distance,source\n");
            for (v, d, s) in rows {
                let s = s.map(|s| s.0.to_string()).unwrap_or_default();
                match d {
                    Distance::Float(d) => writeln!(out, "{v},{},{s}", Shortest(d)),
                    Distance::Digits(d) => writeln!(out, "{v},{d},{s}"),
                }
                .expect("writing to a String");
            }
            out
        }
        DistanceFormat::Json => {
            let rows: Vec<serde_json::Value> = rows
                .into_iter()
                .map(|(v, d, s)| {
                    let d = match d {
                        Distance::Float(d) => serde_json::json!(d.is_finite().then_some(d)),
                        Distance::Digits(d) => serde_json::json!(d),
                    };
                    serde_json::json!({"vertex": v, "distance": d, "source": s})
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
pub struct Shortest(pub f64);

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
