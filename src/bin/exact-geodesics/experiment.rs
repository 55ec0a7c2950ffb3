//! `experiment`: the tables of [LZT §6] over several models, backends and seeded source
//! vertices, written as CSV and JSON into a directory.

use crate::{load, progress, Backend};
use clap::{Args, Subcommand};
use exact_geodesics::experiments::{
    count_wedges_in, normalize_to_unit_cube, random_sources, ModelShape, Table1Row, Table2Row,
    WedgeCounts,
};
use exact_geodesics::scalar::{self, exact};
use serde::Serialize;
use std::path::{Path, PathBuf};

#[derive(Args)]
pub struct ExperimentArgs {
    #[command(subcommand)]
    table: Table,
}

#[derive(Subcommand)]
enum Table {
    /// Table 1: wedges w(e) per edge (mean, std, max) and propagation time, per model, backend
    /// and source vertex; writes DIR/table1.csv and DIR/table1.json.
    Table1(TableArgs),
    /// Table 2: edge lengths l(e) of the model normalized into the unit cube and wedges per
    /// unit length, per model, backend and source vertex; writes DIR/table2.csv and
    /// DIR/table2.json.
    Table2(TableArgs),
}

#[derive(Args)]
struct TableArgs {
    /// Mesh files (OBJ, OFF, PLY) or generated meshes `gen:SHAPE`; each is normalized into the
    /// unit cube first.
    #[arg(required = true)]
    meshes: Vec<String>,
    /// Number types of the engine (repeat the option or give a list: f64,adaptive).
    #[arg(long, value_enum, value_delimiter = ',', default_values_t = [Backend::F64])]
    backend: Vec<Backend>,
    /// Number of seeded random source vertices per model (one row each).
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..))]
    sources: u32,
    /// Seed of the source draw.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Largest precision (bits) the exact backend tries before it records a decision as
    /// uncertified.
    #[arg(
        long,
        default_value_t = exact::DEFAULT_PRECISION_CAP,
        value_parser = clap::value_parser!(u32)
            .range(i64::from(exact::MIN_PRECISION_CAP)..=i64::from(exact::MAX_PRECISION_CAP))
    )]
    precision_cap: u32,
    #[command(flatten)]
    read: load::ReadArgs,
    /// Directory to write the table into (created if missing).
    #[arg(long)]
    out: PathBuf,
}

/// One measured (model, backend, source).
struct Measurement<'a> {
    model: &'a str,
    backend: scalar::Backend,
    shape: &'a ModelShape,
    counts: WedgeCounts,
}

pub fn run(args: &ExperimentArgs) -> Result<(), String> {
    match &args.table {
        Table::Table1(t) => write_table(t, "table1", Table1Row::CSV_HEADER, |m| {
            let row = Table1Row::new(m.model, m.backend, m.shape, &m.counts);
            (row.csv_record(), row)
        }),
        Table::Table2(t) => write_table(t, "table2", Table2Row::CSV_HEADER, |m| {
            let row = Table2Row::new(m.model, m.backend, m.shape, &m.counts);
            (row.csv_record(), row)
        }),
    }
}

/// Measures every model, backend and source and writes `DIR/NAME.csv` and `DIR/NAME.json`.
fn write_table<R: Serialize>(
    args: &TableArgs,
    name: &str,
    header: &str,
    row: impl Fn(&Measurement) -> (String, R),
) -> Result<(), String> {
    exact::set_precision_cap(args.precision_cap).map_err(|e| e.to_string())?;
    std::fs::create_dir_all(&args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
    let mut csv = format!("{header}\n");
    let mut rows = Vec::new();
    for spec in &args.meshes {
        let mesh = load::load_mesh(spec, &args.read.options())?;
        let unit = normalize_to_unit_cube(&mesh).map_err(|e| format!("{spec}: {e}"))?;
        let shape = ModelShape::of(&unit);
        for &backend in &args.backend {
            for source in random_sources(&unit, args.sources as usize, args.seed) {
                let label = format!("{spec} {} v{}", backend.name(), source.0);
                let bar = progress::labelled_bar(unit.vertex_count(), label);
                let counts =
                    count_wedges_in(backend.into(), &unit, source, |p| progress::update(&bar, p))
                        .map_err(|e| format!("{spec}: {e}"))?;
                bar.finish_and_clear();
                let (record, value) = row(&Measurement {
                    model: spec,
                    backend: backend.into(),
                    shape: &shape,
                    counts,
                });
                csv.push_str(&record);
                csv.push('\n');
                rows.push(value);
            }
        }
    }
    let mut json = serde_json::to_string_pretty(&rows).expect("JSON of plain values");
    json.push('\n');
    write(&args.out.join(format!("{name}.csv")), &csv)?;
    write(&args.out.join(format!("{name}.json")), &json)
}

fn write(path: &Path, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}
