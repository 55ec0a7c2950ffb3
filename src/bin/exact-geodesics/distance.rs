//! `distance`: the geodesic distance of every vertex.

use crate::{certified_digits, emit_with, with_backend, Backend, Common, Digits};
use clap::{Args, ValueEnum};
use exact_geodesics::scalar::Real;
use exact_geodesics::{Scalar, SourceId, VertexField, VertexId};
use std::io::Write;
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
    /// Threads (default: every core on meshes of 15,000 faces or more, else 1): two propagate
    /// two sectors of a single source vertex's directions at once (f64 and adaptive; one
    /// thread where edge lengths span more than 2^20); the distances are those of one thread
    /// up to the last bits where geodesics from the two sectors tie.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
}

/// Faces from which `distance` uses every core by default: a second engine adds 0.6-1.9 MiB
/// (its tables, its thread, the wedges it spills into the other sector), which below this
/// outweighs its help. On fandisk (13k faces; v0, v100, v2000, v4000, v6000, medians of 5)
/// two threads take 0.07-0.09 s against 0.08-0.11 s, but peak at 11.1-11.6 MiB against
/// 9.9-10.3 MiB: 0.48-0.54 of Kirsanov's MMP (21.2-23.8 MiB), half or more from three of the
/// five sources, where issue 13 allows at most half; rocker_arm (20k faces) 14.0 against
/// 12.1 MiB, 0.44 of Kirsanov's, and 0.11 against 0.16 s.
const THREADED_FACES: usize = 15_000;

/// A vertex's distance as printed: an `f64`, or certified digits of the exact value.
enum Distance {
    Float(f64),
    Digits(String),
}

pub fn run(args: &DistanceArgs) -> Result<(), String> {
    let mut job = args.common.job()?;
    job.options.threads = match args.threads {
        Some(n) => n as usize,
        None if job.mesh.face_count() >= THREADED_FACES => {
            std::thread::available_parallelism().map_or(1, |n| n.get())
        }
        None => 1,
    };
    let write = |rows: &mut dyn Iterator<Item = Row>| {
        emit_with(args.out.as_ref(), |out| write_rows(rows, args.format, out))
    };
    match args.digits.checked(job.backend)? {
        // Collected first: a value that cannot be certified fails the command before any output.
        Some(digits) => write(&mut exact_rows(&job.vertex_field::<Real>()?, digits)?.into_iter()),
        // Streamed from the field: the rows of a large mesh are never held whole.
        None => with_backend!(job.backend, S => write(&mut float_rows(&job.vertex_field::<S>()?))),
    }
}

type Row = (u32, Distance, Option<SourceId>);

fn float_rows<'a, S: Scalar>(field: &'a VertexField<'_, S>) -> impl Iterator<Item = Row> + 'a {
    (0..field.mesh().vertex_count() as u32)
        .map(VertexId)
        .map(|v| {
            let d = Distance::Float(field.vertex_distance(v));
            (v.0, d, field.nearest_source(v))
        })
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

fn write_rows(
    rows: &mut dyn Iterator<Item = Row>,
    format: DistanceFormat,
    out: &mut dyn Write,
) -> std::io::Result<()> {
    match format {
        DistanceFormat::Csv => {
            writeln!(out, "vertex,distance,source")?;
            for (v, d, s) in rows {
                let s = s.map(|s| s.0.to_string()).unwrap_or_default();
                match d {
                    Distance::Float(d) => writeln!(out, "{v},{},{s}", Shortest(d))?,
                    Distance::Digits(d) => writeln!(out, "{v},{d},{s}")?,
                }
            }
            Ok(())
        }
        DistanceFormat::Json => {
            let rows: Vec<serde_json::Value> = rows
                .map(|(v, d, s)| {
                    let d = match d {
                        Distance::Float(d) => serde_json::json!(d.is_finite().then_some(d)),
                        Distance::Digits(d) => serde_json::json!(d),
                    };
                    serde_json::json!({"vertex": v, "distance": d, "source": s})
                })
                .collect();
            let json = serde_json::to_string_pretty(&serde_json::json!({
                "unreachable": "distance null",
                "vertices": rows,
            }))
            .expect("JSON of plain values");
            writeln!(out, "{json}")
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
