//! `stats`: counters and timings of one propagation, as JSON [LZT Tables 1-2].

use crate::{emit, with_backend, Backend, Common};
use clap::Args;
use exact_geodesics::{EdgeId, GeodesicField, Scalar};
use std::path::PathBuf;

#[derive(Args)]
pub struct StatsArgs {
    #[command(flatten)]
    common: Common,
    /// Write to this file instead of stdout.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Mean, standard deviation (population), minimum and maximum.
fn summary(values: impl Iterator<Item = f64> + Clone) -> serde_json::Value {
    let n = values.clone().count().max(1) as f64;
    let mean = values.clone().sum::<f64>() / n;
    let var = values.clone().map(|x| (x - mean) * (x - mean)).sum::<f64>() / n;
    let min = values.clone().fold(f64::INFINITY, f64::min);
    let max = values.fold(f64::NEG_INFINITY, f64::max);
    serde_json::json!({"mean": mean, "std": var.sqrt(), "min": min, "max": max})
}

pub fn run(args: &StatsArgs) -> Result<(), String> {
    let job = args.common.job()?;
    let json =
        with_backend!(job.backend, S => report(&job.field::<S>()?, &args.common.mesh, job.backend));
    let mut text = serde_json::to_string_pretty(&json).expect("JSON of plain values");
    text.push('\n');
    emit(args.out.as_ref(), &text)
}

fn report<S: Scalar>(
    field: &GeodesicField<'_, S>,
    name: &str,
    backend: Backend,
) -> serde_json::Value {
    let mesh = field.mesh();
    let stats = field.stats();
    let counts = field.wedge_counts();
    let lengths = (0..mesh.edge_count()).map(|e| field.edge_length(EdgeId(e as u32)).to_f64());
    let reached = field
        .vertex_distances()
        .iter()
        .filter(|d| d.is_finite())
        .count();
    let coverage = field.check_coverage();
    serde_json::json!({
        "mesh": name,
        "backend": backend.name(),
        "backend_decisions": stats.backend,
        "vertices": mesh.vertex_count(),
        "faces": mesh.face_count(),
        "edges": mesh.edge_count(),
        "sources": field.sources().len(),
        "vertices_reached": reached,
        "wedges": counts.iter().sum::<usize>(),
        "wedges_per_edge": summary(counts.iter().map(|&c| c as f64)),
        "edge_length": summary(lengths),
        "eq2_cases": stats.eq2,
        "wedges_created": stats.wedges_created,
        "wedges_propagated": stats.wedges_propagated,
        "wedges_filtered": stats.wedges_filtered,
        "wedges_joined": stats.wedges_joined,
        "rounded_gap_offers": stats.rounded_gap_offers,
        "tied_wedges_propagated": stats.tied_wedges_propagated,
        "wedges_offered_again": stats.wedges_offered_again,
        "pseudo_source_emissions": stats.pseudo_source_emissions,
        "propagation_seconds": stats.propagation_seconds,
        "peak_queue": stats.peak_queue,
        "wedge_memory_bytes": stats.peak_wedge_bytes,
        "coverage": {
            "edges_reached": coverage.edges_reached,
            "gaps_and_overlaps": coverage.issues.len(),
            "has_overlaps": coverage.has_overlaps(),
            "largest_gap_fraction": coverage.largest_gap_fraction(field),
        },
    })
}
