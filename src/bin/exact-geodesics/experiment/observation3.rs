//! `experiment observation3`: Observation 3 [LZT §6] tested by scale and by resolution.

use super::{measure_one, plots, write_csv, write_json, RunArgs};
use clap::{Args, ValueEnum};
use exact_geodesics::experiments::{
    fit_resolution, normalize_to_unit_cube, random_sources, scale_factor, scale_uniformly,
    ModelShape, ResolutionFit, ResolutionRow, ScaleRow,
};
use exact_geodesics::mesh::shapes;
use exact_geodesics::TriMesh;
use serde::Serialize;

#[derive(Args)]
pub struct Observation3Args {
    /// Models (files or `gen:SHAPE`), each normalized into the unit cube, then scaled by every
    /// power in --scale-exponents (the scale series) and subdivided --refinements times (a
    /// resolution series of its own).
    #[arg(required = true)]
    meshes: Vec<String>,
    /// Resolution series to run (a list): icospheres, planar grids, refinements of the models.
    #[arg(long, value_enum, value_delimiter = ',', default_values_t = [Series::Icosphere, Series::Grid, Series::Refined])]
    series: Vec<Series>,
    /// Levels of the built-in resolution series: gen:icosphere:K for K = 1..=N and
    /// gen:grid:n,n for n = 4, 8, ..., 2^(N+1).
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(3..=6))]
    levels: u32,
    /// Midpoint subdivisions of each model for its resolution series `refined` (levels 0..=R,
    /// each face split into four per level; the surface stays the same); 0 leaves the models
    /// out of the resolution series.
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u32).range(0..=4))]
    refinements: u32,
    /// Powers of --scale-base by which each model is scaled (a list: -6,0,6).
    #[arg(
        long,
        value_delimiter = ',',
        allow_negative_numbers = true,
        default_values_t = [-12, -9, -6, -3, 0, 3, 6, 9, 12],
        value_parser = clap::value_parser!(i32).range(-1000..=1000)
    )]
    scale_exponents: Vec<i32>,
    /// Base of the scales: 10 (factors rounded to f64, so the scaled model moves by an ulp) or
    /// 2 (exact factors: the same model in every way but its units).
    #[arg(long, value_enum, default_value_t = ScaleBase::Ten)]
    scale_base: ScaleBase,
    #[command(flatten)]
    run: RunArgs,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Series {
    /// gen:icosphere:K, K = 1..=N (a sphere ever finer).
    Icosphere,
    /// gen:grid:n,n, n = 4..=2^(N+1) (the unit square ever finer).
    Grid,
    /// Each model subdivided 0..=R times (the same surface).
    Refined,
}

#[derive(Clone, Copy, ValueEnum)]
enum ScaleBase {
    #[value(name = "2")]
    Two,
    #[value(name = "10")]
    Ten,
}

impl ScaleBase {
    fn value(self) -> u32 {
        match self {
            ScaleBase::Two => 2,
            ScaleBase::Ten => 10,
        }
    }
}

/// Everything observation3 measured, as DIR/observation3.json holds it.
#[derive(Serialize)]
struct Observation3 {
    scale: Vec<ScaleRow>,
    resolution: Vec<ResolutionRow>,
    fits: Vec<ResolutionFit>,
}

pub fn run(args: &Observation3Args) -> Result<(), String> {
    args.run.prepare()?;
    let scale = scale_series(args)?;
    let resolution = resolution_series(args)?;
    let fits = fit_resolution(&resolution);
    let out = &args.run.out;
    write_csv(
        &out.join("observation3_scale.csv"),
        ScaleRow::CSV_HEADER,
        scale.iter().map(ScaleRow::csv_record),
    )?;
    write_csv(
        &out.join("observation3_resolution.csv"),
        ResolutionRow::CSV_HEADER,
        resolution.iter().map(ResolutionRow::csv_record),
    )?;
    write_csv(
        &out.join("observation3_fit.csv"),
        ResolutionFit::CSV_HEADER,
        fits.iter().map(ResolutionFit::csv_record),
    )?;
    plots::scale(&out.join("observation3_scale.svg"), &scale)?;
    plots::resolution(&out.join("observation3_resolution.svg"), &fits)?;
    write_json(
        &out.join("observation3.json"),
        &Observation3 {
            scale,
            resolution,
            fits,
        },
    )
}

/// Every model, normalized, then scaled by each power: one row per model, backend, source and
/// power, each against the unscaled run from the same source in the same backend.
fn scale_series(args: &Observation3Args) -> Result<Vec<ScaleRow>, String> {
    let base = args.scale_base.value();
    let mut rows = Vec::new();
    for spec in &args.meshes {
        let unit = args.run.unit_mesh(spec)?;
        let scaled = args
            .scale_exponents
            .iter()
            .map(|&k| {
                scale_uniformly(&unit, scale_factor(base, k))
                    .map(|mesh| (k, mesh))
                    .map_err(|e| format!("{spec} scaled by {base}^{k}: {e}"))
            })
            .collect::<Result<Vec<(i32, TriMesh)>, String>>()?;
        for backend in args.run.backends() {
            for source in random_sources(&unit, args.run.sources as usize, args.run.seed) {
                let reference = measure_one(spec, &unit, backend, source)?;
                for (k, mesh) in &scaled {
                    let label = format!("{spec} x{base}^{k}");
                    let measured = measure_one(&label, mesh, backend, source)?;
                    rows.push(ScaleRow::new(
                        spec, backend, base, *k, &reference, &measured,
                    ));
                }
            }
        }
    }
    Ok(rows)
}

/// The icosphere and grid series and each model's refinement series, every mesh normalized
/// into the unit cube: one row per mesh, backend and source. A refined model is named
/// `MODEL@R`, R the number of subdivisions.
fn resolution_series(args: &Observation3Args) -> Result<Vec<ResolutionRow>, String> {
    let mut rows = Vec::new();
    let mut measure = |series: &str, model: &str, level: u32, mesh: &TriMesh| {
        let shape = ModelShape::of(mesh);
        for backend in args.run.backends() {
            for m in args.run.measure_sources(model, mesh, backend)? {
                rows.push(ResolutionRow::new(
                    series, model, level, backend, &shape, &m,
                ));
            }
        }
        Ok::<(), String>(())
    };
    for level in 1..=args.levels {
        for (series, name, spec) in [
            (
                Series::Icosphere,
                "icosphere",
                format!("gen:icosphere:{level}"),
            ),
            (
                Series::Grid,
                "grid",
                format!("gen:grid:{n},{n}", n = 2u32 << level),
            ),
        ] {
            if args.series.contains(&series) {
                measure(name, &spec, level, &args.run.unit_mesh(&spec)?)?;
            }
        }
    }
    if args.series.contains(&Series::Refined) && args.refinements > 0 {
        for spec in &args.meshes {
            let series = format!("refined:{spec}");
            let mut mesh = crate::load::load_mesh(spec, &args.run.read.options())?;
            for level in 0..=args.refinements {
                if level > 0 {
                    mesh = shapes::subdivide(&mesh);
                }
                let unit = normalize_to_unit_cube(&mesh).map_err(|e| format!("{spec}: {e}"))?;
                measure(&series, &format!("{spec}@{level}"), level, &unit)?;
            }
        }
    }
    Ok(rows)
}
