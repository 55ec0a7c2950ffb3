//! `experiment`: the tables and observations of [LZT §6] over several models, backends and
//! seeded source vertices, written as CSV, JSON and SVG plots into a directory.

mod observation3;
mod plots;

use crate::{load, progress, Backend, PrecisionCap};
use clap::{Args, Subcommand};
use exact_geodesics::experiments::{
    measure_in, normalize_to_unit_cube, random_sources, Measurement, ModelShape, Table1Row,
    Table2Row,
};
use exact_geodesics::scalar::{self, exact};
use exact_geodesics::{TriMesh, VertexId};
use serde::Serialize;
use std::path::{Path, PathBuf};

#[derive(Args)]
pub struct ExperimentArgs {
    #[command(subcommand)]
    table: Table,
}

#[derive(Subcommand)]
enum Table {
    /// Table 1: wedges w(e) per edge (mean, std, max, skewness, share of edges holding half)
    /// and propagation time, per model, backend and source vertex; writes DIR/table1.csv,
    /// DIR/table1.json and the plots of w(e) (Observations 1 and 2).
    Table1(TableArgs),
    /// Table 2: edge lengths l(e) of the model normalized into the unit cube and wedges per
    /// unit length, per model, backend and source vertex; writes DIR/table2.csv and
    /// DIR/table2.json.
    Table2(TableArgs),
    /// Observation 3 by scale (each model scaled uniformly: DIR/observation3_scale.csv) and by
    /// resolution (icospheres, planar grids and refinements of each model, normalized into the
    /// unit cube: DIR/observation3_resolution.csv, the fitted exponents of w/l against l in
    /// DIR/observation3_fit.csv), with DIR/observation3.json and the plots.
    Observation3(observation3::Observation3Args),
}

#[derive(Args)]
struct TableArgs {
    /// Mesh files (OBJ, OFF, PLY) or generated meshes `gen:SHAPE`; each is normalized into the
    /// unit cube first.
    #[arg(required = true)]
    meshes: Vec<String>,
    #[command(flatten)]
    run: RunArgs,
}

/// What every experiment takes besides its models.
#[derive(Args)]
struct RunArgs {
    /// Number types of the engine (repeat the option or give a list: f64,adaptive).
    #[arg(long, value_enum, value_delimiter = ',', default_values_t = [Backend::F64])]
    backend: Vec<Backend>,
    /// Number of seeded random source vertices per model (one row each).
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..))]
    sources: u32,
    /// Seed of the source draw.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    #[command(flatten)]
    cap: PrecisionCap,
    #[command(flatten)]
    read: load::ReadArgs,
    /// Directory to write into (created if missing).
    #[arg(long)]
    out: PathBuf,
}

impl RunArgs {
    /// Sets the precision cap and creates the output directory.
    fn prepare(&self) -> Result<(), String> {
        exact::set_precision_cap(self.cap.precision_cap).map_err(|e| e.to_string())?;
        std::fs::create_dir_all(&self.out).map_err(|e| format!("{}: {e}", self.out.display()))
    }

    /// The backends as the library names them.
    fn backends(&self) -> impl Iterator<Item = scalar::Backend> + '_ {
        self.backend.iter().map(|&b| b.into())
    }

    /// Loads `spec` and normalizes it into the unit cube.
    fn unit_mesh(&self, spec: &str) -> Result<TriMesh, String> {
        let mesh = load::load_mesh(spec, &self.read.options())?;
        normalize_to_unit_cube(&mesh).map_err(|e| format!("{spec}: {e}"))
    }

    /// Measures `mesh` (named `label`) in `backend` from each of the seeded source vertices.
    fn measure_sources(
        &self,
        label: &str,
        mesh: &TriMesh,
        backend: scalar::Backend,
    ) -> Result<Vec<Measurement>, String> {
        random_sources(mesh, self.sources as usize, self.seed)
            .into_iter()
            .map(|source| measure_one(label, mesh, backend, source))
            .collect()
    }
}

/// One propagation with a progress bar headed by the model, backend and source.
fn measure_one(
    label: &str,
    mesh: &TriMesh,
    backend: scalar::Backend,
    source: VertexId,
) -> Result<Measurement, String> {
    let bar = progress::labelled_bar(
        mesh.vertex_count(),
        format!("{label} {} v{}", backend.name(), source.0),
    );
    let measured = measure_in(backend, mesh, source, |p| progress::update(&bar, p))
        .map_err(|e| format!("{label}: {e}"))?;
    bar.finish_and_clear();
    Ok(measured)
}

/// One model measured in one backend from every source.
struct Runs {
    model: String,
    shape: ModelShape,
    backend: scalar::Backend,
    measurements: Vec<Measurement>,
}

pub fn run(args: &ExperimentArgs) -> Result<(), String> {
    match &args.table {
        Table::Table1(t) => {
            let runs = measure_models(t)?;
            let rows: Vec<Table1Row> = rows_of(&runs, Table1Row::new);
            let records = rows.iter().map(Table1Row::csv_record);
            write_table(&t.run.out, "table1", Table1Row::CSV_HEADER, records, &rows)?;
            plots::table1(&t.run.out, &runs)
        }
        Table::Table2(t) => {
            let rows: Vec<Table2Row> = rows_of(&measure_models(t)?, Table2Row::new);
            let records = rows.iter().map(Table2Row::csv_record);
            write_table(&t.run.out, "table2", Table2Row::CSV_HEADER, records, &rows)
        }
        Table::Observation3(o) => observation3::run(o),
    }
}

/// Measures every model in every backend from every source.
fn measure_models(args: &TableArgs) -> Result<Vec<Runs>, String> {
    args.run.prepare()?;
    let mut runs = Vec::new();
    for spec in &args.meshes {
        let unit = args.run.unit_mesh(spec)?;
        let shape = ModelShape::of(&unit);
        for backend in args.run.backends() {
            runs.push(Runs {
                model: spec.clone(),
                shape: shape.clone(),
                backend,
                measurements: args.run.measure_sources(spec, &unit, backend)?,
            });
        }
    }
    Ok(runs)
}

/// One row per model, backend and source.
fn rows_of<R>(
    runs: &[Runs],
    row: impl Fn(&str, scalar::Backend, &ModelShape, &exact_geodesics::experiments::WedgeCounts) -> R,
) -> Vec<R> {
    runs.iter()
        .flat_map(|r| {
            r.measurements
                .iter()
                .map(|m| row(&r.model, r.backend, &r.shape, &m.counts))
        })
        .collect()
}

/// Writes `DIR/NAME.csv` (the header, then the records) and `DIR/NAME.json` (the rows).
fn write_table<R: Serialize>(
    dir: &Path,
    name: &str,
    header: &str,
    records: impl Iterator<Item = String>,
    rows: &R,
) -> Result<(), String> {
    write_csv(&dir.join(format!("{name}.csv")), header, records)?;
    write_json(&dir.join(format!("{name}.json")), rows)
}

fn write_csv(
    path: &Path,
    header: &str,
    records: impl Iterator<Item = String>,
) -> Result<(), String> {
    let mut csv = format!("{header}\n");
    for record in records {
        csv.push_str(&record);
        csv.push('\n');
    }
    write(path, &csv)
}

fn write_json<R: Serialize + ?Sized>(path: &Path, value: &R) -> Result<(), String> {
    let mut json = serde_json::to_string_pretty(value).expect("JSON of plain values");
    json.push('\n');
    write(path, &json)
}

fn write(path: &Path, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}
