//! `compare`: the same propagation in all three backends, measured against the exact one:
//! distances, wedge counts, eq.-(2) cases and every wedge meeting decided differently.

use crate::{emit, Backend, Common, Job};
use clap::{Args, ValueEnum};
use exact_geodesics::mmp::{Eq2Counts, Eq2Decision};
use exact_geodesics::scalar::{Adaptive, DecisionCounts, Real};
use exact_geodesics::{EdgeId, GeodesicField, PseudoSource, Scalar};
use serde::Serialize;
use std::collections::HashMap;
use std::fmt::Write;
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum CompareFormat {
    Text,
    Json,
}

#[derive(Args)]
pub struct CompareArgs {
    #[command(flatten)]
    common: Common,
    /// Output format.
    #[arg(long, value_enum, default_value_t = CompareFormat::Text)]
    format: CompareFormat,
    /// Most differing decisions listed in text output (JSON lists all).
    #[arg(long, default_value_t = 40)]
    limit: usize,
    /// Write to this file instead of stdout.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// What one backend computed.
struct Run {
    backend: Backend,
    distances: Vec<f64>,
    wedge_counts: Vec<usize>,
    eq2: Eq2Counts,
    counts: DecisionCounts,
    decisions: Vec<Eq2Decision>,
    seconds: f64,
}

fn run_backend<S: Scalar>(job: &Job, backend: Backend) -> Result<Run, String> {
    let field: GeodesicField<'_, S> = job.field()?;
    let stats = field.stats().clone();
    Ok(Run {
        backend,
        distances: field.vertex_distances(),
        wedge_counts: field.wedge_counts(),
        eq2: stats.eq2,
        counts: stats.backend,
        decisions: stats.decisions,
        seconds: stats.propagation_seconds,
    })
}

/// Distances of a backend against exact ones.
#[derive(Serialize)]
struct DistanceDifference {
    backend: &'static str,
    max_absolute: f64,
    mean_absolute: f64,
    max_relative: f64,
    /// Vertices one backend reaches and the other does not.
    reach_differs: usize,
}

fn distance_difference(run: &Run, exact: &Run) -> DistanceDifference {
    let (mut max_abs, mut sum, mut n, mut max_rel, mut reach) = (0f64, 0f64, 0usize, 0f64, 0);
    for (&d, &e) in run.distances.iter().zip(&exact.distances) {
        if d.is_finite() != e.is_finite() {
            reach += 1;
            continue;
        }
        if !e.is_finite() {
            continue;
        }
        let diff = (d - e).abs();
        max_abs = max_abs.max(diff);
        max_rel = max_rel.max(if e > 0.0 { diff / e } else { diff });
        sum += diff;
        n += 1;
    }
    DistanceDifference {
        backend: run.backend.name(),
        max_absolute: max_abs,
        mean_absolute: sum / n.max(1) as f64,
        max_relative: max_rel,
        reach_differs: reach,
    }
}

/// An edge whose final wedge counts differ between backends.
#[derive(Serialize)]
struct WedgeCountDifference {
    edge: u32,
    vertices: [u32; 2],
    f64: usize,
    adaptive: usize,
    exact: usize,
}

/// A meeting of two wedges that f64 or adaptive decided differently from exact. Meetings are
/// matched by edge, the two pseudo-sources, and their order among such meetings.
#[derive(Serialize)]
struct DecisionDifference {
    edge: u32,
    existing: PseudoSource,
    arriving: PseudoSource,
    occurrence: usize,
    exact: Option<Eq2Decision>,
    f64: Option<Eq2Decision>,
    adaptive: Option<Eq2Decision>,
}

type Key = (u32, PseudoSource, PseudoSource, usize);

fn keyed(decisions: &[Eq2Decision]) -> HashMap<Key, &Eq2Decision> {
    let mut seen: HashMap<(u32, PseudoSource, PseudoSource), usize> = HashMap::new();
    decisions
        .iter()
        .map(|d| {
            let n = seen.entry((d.edge, d.existing, d.arriving)).or_default();
            *n += 1;
            ((d.edge, d.existing, d.arriving, *n - 1), d)
        })
        .collect()
}

fn decision_differences(f64_run: &Run, adaptive: &Run, exact: &Run) -> Vec<DecisionDifference> {
    let (f, a, e) = (
        keyed(&f64_run.decisions),
        keyed(&adaptive.decisions),
        keyed(&exact.decisions),
    );
    let mut keys: Vec<Key> = f.keys().chain(a.keys()).chain(e.keys()).copied().collect();
    keys.sort_by_key(|k| (k.0, format!("{:?}{:?}", k.1, k.2), k.3));
    keys.dedup();
    let case = |m: &HashMap<Key, &Eq2Decision>, k: &Key| m.get(k).map(|d| d.case);
    keys.into_iter()
        .filter(|k| case(&f, k) != case(&e, k) || case(&a, k) != case(&e, k))
        .map(|k| DecisionDifference {
            edge: k.0,
            existing: k.1,
            arriving: k.2,
            occurrence: k.3,
            exact: e.get(&k).map(|d| (*d).clone()),
            f64: f.get(&k).map(|d| (*d).clone()),
            adaptive: a.get(&k).map(|d| (*d).clone()),
        })
        .collect()
}

#[derive(Serialize)]
struct BackendSummary {
    backend: &'static str,
    propagation_seconds: f64,
    wedges: usize,
    eq2_cases: Eq2Counts,
    wedge_meetings: usize,
    decisions: DecisionCounts,
}

#[derive(Serialize)]
struct Report {
    mesh: String,
    sources: Vec<String>,
    backends: Vec<BackendSummary>,
    distance_vs_exact: Vec<DistanceDifference>,
    wedge_counts_differ: Vec<WedgeCountDifference>,
    decisions_differ: Vec<DecisionDifference>,
}

pub fn run(args: &CompareArgs) -> Result<(), String> {
    let mut job = args.common.job()?;
    job.options.record_decisions = true;
    let f64_run = run_backend::<f64>(&job, Backend::F64)?;
    let adaptive = run_backend::<Adaptive>(&job, Backend::Adaptive)?;
    let exact = run_backend::<Real>(&job, Backend::Exact)?;
    let mesh = &job.mesh;
    let wedge_counts_differ = (0..mesh.edge_count())
        .filter(|&e| {
            let c = exact.wedge_counts[e];
            f64_run.wedge_counts[e] != c || adaptive.wedge_counts[e] != c
        })
        .map(|e| WedgeCountDifference {
            edge: e as u32,
            vertices: mesh.edge(EdgeId(e as u32)).vertices.map(|v| v.0),
            f64: f64_run.wedge_counts[e],
            adaptive: adaptive.wedge_counts[e],
            exact: exact.wedge_counts[e],
        })
        .collect();
    let report = Report {
        mesh: args.common.mesh.clone(),
        sources: args.common.sources.clone(),
        backends: [&f64_run, &adaptive, &exact]
            .iter()
            .map(|r| BackendSummary {
                backend: r.backend.name(),
                propagation_seconds: r.seconds,
                wedges: r.wedge_counts.iter().sum(),
                eq2_cases: r.eq2.clone(),
                wedge_meetings: r.decisions.len(),
                decisions: r.counts.clone(),
            })
            .collect(),
        distance_vs_exact: vec![
            distance_difference(&f64_run, &exact),
            distance_difference(&adaptive, &exact),
        ],
        wedge_counts_differ,
        decisions_differ: decision_differences(&f64_run, &adaptive, &exact),
    };
    let text = match args.format {
        CompareFormat::Json => {
            let mut s = serde_json::to_string_pretty(&report).expect("JSON of plain values");
            s.push('\n');
            s
        }
        CompareFormat::Text => render_text(&report, args.limit),
    };
    emit(args.out.as_ref(), &text)
}

fn case_of(d: &Option<Eq2Decision>) -> String {
    d.as_ref()
        .map_or("absent".into(), |d| format!("{:?}", d.case).to_lowercase())
}

fn render_text(r: &Report, limit: usize) -> String {
    let mut s = String::new();
    let w = &mut s;
    let _ = writeln!(w, "mesh {}  sources {}", r.mesh, r.sources.join(" "));
    let _ = writeln!(
        w,
        "\n{:<9} {:>10} {:>8} {:>7} {:>7} {:>7} {:>9} {:>9} {:>9} {:>9} {:>9} {:>11}",
        "backend",
        "seconds",
        "wedges",
        "none",
        "one",
        "two",
        "infinite",
        "meetings",
        "filter",
        "exact",
        "zeros",
        "uncertified"
    );
    for b in &r.backends {
        let _ = writeln!(
            w,
            "{:<9} {:>10.4} {:>8} {:>7} {:>7} {:>7} {:>9} {:>9} {:>9} {:>9} {:>9} {:>11}",
            b.backend,
            b.propagation_seconds,
            b.wedges,
            b.eq2_cases.none,
            b.eq2_cases.one,
            b.eq2_cases.two,
            b.eq2_cases.infinite,
            b.wedge_meetings,
            b.decisions.by_filter,
            b.decisions.by_refinement,
            b.decisions.certified_zeros,
            b.decisions.uncertified
        );
    }
    let _ = writeln!(w, "\nvertex distances against exact:");
    for d in &r.distance_vs_exact {
        let _ = writeln!(
            w,
            "  {:<9} max abs {:.3e}  mean abs {:.3e}  max rel {:.3e}  reach differs {}",
            d.backend, d.max_absolute, d.mean_absolute, d.max_relative, d.reach_differs
        );
    }
    let _ = writeln!(
        w,
        "\nedges whose final wedge counts differ: {}",
        r.wedge_counts_differ.len()
    );
    for e in r.wedge_counts_differ.iter().take(limit) {
        let _ = writeln!(
            w,
            "  edge {} (v{}, v{}): f64 {}  adaptive {}  exact {}",
            e.edge, e.vertices[0], e.vertices[1], e.f64, e.adaptive, e.exact
        );
    }
    let _ = writeln!(
        w,
        "\nwedge meetings decided differently from exact: {}",
        r.decisions_differ.len()
    );
    for d in r.decisions_differ.iter().take(limit) {
        let _ = write!(
            w,
            "  edge {} {:?} meets {:?} (#{}): exact {}, f64 {}, adaptive {}",
            d.edge,
            d.existing,
            d.arriving,
            d.occurrence,
            case_of(&d.exact),
            case_of(&d.f64),
            case_of(&d.adaptive)
        );
        if let Some(f) = &d.f64 {
            let _ = write!(
                w,
                "; f64 saw range [{:.6}, {:.6}] A {:.3e} B {:.3e} C {:.3e}",
                f.range[0], f.range[1], f.coefficients[0], f.coefficients[1], f.coefficients[2]
            );
        }
        let _ = writeln!(w);
    }
    s
}
