//! `matrix`: geodesic distances among selected vertices, one propagation per source on every
//! core, rows written as they come (`.npy` dense, `.mtx` sparse) or whole (`.csv`).

use crate::matrix_files::{write_csv, Format, MtxFile, NpyFile};
use crate::{
    load, non_negative_distance, progress, report_uncertified, with_backend, Backend, PrecisionCap,
};
use clap::{ArgGroup, Args, ValueEnum};
use exact_geodesics::experiments::random_sources;
use exact_geodesics::matrix::{
    distance_matrix, DenseMatrix, MatrixOptions, MatrixRow, MatrixSummary, SparseMatrix,
};
use exact_geodesics::{Scalar, SurfacePoint, TriMesh, VertexId};
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Symmetrize {
    /// d(i, j) = d(j, i) = the smaller of the two.
    Min,
}

#[derive(Args)]
#[command(group(ArgGroup::new("selection").required(true).args(["sources", "sources_file", "all", "random"])))]
pub struct MatrixArgs {
    /// Mesh file (OBJ, OFF, PLY) or a generated mesh `gen:SHAPE`.
    mesh: String,
    /// The selected vertices, comma-separated: v:1,v:7,... (or 1,7,...).
    #[arg(long)]
    sources: Option<String>,
    /// A file of selected vertices, v:I or I, separated by commas, spaces or lines (# starts a
    /// comment).
    #[arg(long)]
    sources_file: Option<PathBuf>,
    /// Every vertex.
    #[arg(long)]
    all: bool,
    /// K distinct vertices used by faces, drawn with --seed.
    #[arg(long, value_name = "K", value_parser = clap::value_parser!(u32).range(1..))]
    random: Option<u32>,
    /// Seed of --random.
    #[arg(long, default_value_t = 1, requires = "random")]
    seed: u64,
    /// Radius-limited rows: distances beyond this are left out (.mtx) or inf (.npy, .csv), and
    /// each propagation stops there.
    #[arg(long, allow_hyphen_values = true, value_parser = non_negative_distance)]
    max_distance: Option<f64>,
    /// Propagations at once, each on its own thread (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// Number type of the engine.
    #[arg(long, value_enum, default_value_t = Backend::F64)]
    backend: Backend,
    #[command(flatten)]
    cap: PrecisionCap,
    /// Make the matrix exactly symmetric (the rows are then gathered in memory first).
    #[arg(long, value_enum)]
    symmetrize: Option<Symmetrize>,
    /// Fail (exit 1) when a propagation leaves a decision uncertified, instead of warning.
    #[arg(long)]
    require_certified: bool,
    #[command(flatten)]
    read: load::ReadArgs,
    /// Also write the selected vertices, in the matrix's order, one v:I a line (what
    /// --sources-file reads).
    #[arg(long, value_name = "FILE")]
    save_selection: Option<PathBuf>,
    /// Output file: .npy (dense, float64, rows in selection order), .mtx (Matrix Market,
    /// 1-based, the finite entries) or .csv (dense, with vertex names; for small selections).
    #[arg(long)]
    out: PathBuf,
}

pub fn run(args: &MatrixArgs) -> Result<(), String> {
    let format = Format::of(&args.out)?;
    let mesh = load::load_mesh(&args.mesh, &args.read.options())?;
    let vertices = selection(args, &mesh)?;
    if let Some(path) = &args.save_selection {
        let lines: String = vertices.iter().map(|v| format!("v:{}\n", v.0)).collect();
        std::fs::write(path, lines).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    let mut options = MatrixOptions::default().with_precision_cap(args.cap.precision_cap);
    options.max_distance = args.max_distance;
    options.threads = args.threads.map(|n| n as usize);
    let summary =
        with_backend!(args.backend, S => write::<S>(args, format, &mesh, &vertices, &options)?);
    if summary.uncertified_rows > 0 {
        let message = format!(
            "{} of {} rows have decisions of the {} backend that are not certified (a larger \
             --precision-cap may settle them)",
            summary.uncertified_rows,
            summary.rows,
            args.backend.name()
        );
        report_uncertified(message, args.require_certified)?;
    }
    Ok(())
}

/// Where the rows go: straight into a file, or gathered first (symmetrization, CSV).
enum Sink {
    Npy(NpyFile),
    Mtx(MtxFile),
    Dense(DenseMatrix),
    Sparse(SparseMatrix),
}

fn write<S: Scalar>(
    args: &MatrixArgs,
    format: Format,
    mesh: &TriMesh,
    vertices: &[VertexId],
    options: &MatrixOptions,
) -> Result<MatrixSummary, String> {
    let n = vertices.len();
    let gather = args.symmetrize.is_some() || format == Format::Csv;
    let comment = format!(
        "exact-geodesics matrix {}: {n} vertices, backend {}",
        args.mesh,
        args.backend.name()
    );
    let mut sink = match (format, gather) {
        (Format::Mtx, true) => Sink::Sparse(SparseMatrix::new()),
        (_, true) => Sink::Dense(DenseMatrix::new(n, n)),
        (Format::Npy, false) => Sink::Npy(NpyFile::create(&args.out, n)?),
        (_, false) => Sink::Mtx(MtxFile::create(&args.out, n, &comment)?),
    };
    let bar = progress::row_bar(n);
    let sources: Vec<SurfacePoint> = vertices.iter().map(|&v| SurfacePoint::Vertex(v)).collect();
    let summary =
        distance_matrix::<S, String>(mesh, &sources, vertices, options, |row: MatrixRow| {
            bar.inc(1);
            match &mut sink {
                Sink::Npy(file) => file.row(row.index, &row.distances),
                Sink::Mtx(file) => file.entries(row.finite_entries()),
                Sink::Dense(matrix) => matrix.insert(&row).map_err(|e| e.to_string()),
                Sink::Sparse(matrix) => {
                    matrix.insert(&row);
                    Ok(())
                }
            }
        })
        .map_err(|e| e.to_string())?;
    bar.finish_and_clear();
    match sink {
        Sink::Npy(file) => file.finish()?,
        Sink::Mtx(file) => file.finish()?,
        Sink::Dense(mut matrix) => {
            if args.symmetrize.is_some() {
                matrix.symmetrize_min().map_err(|e| e.to_string())?;
            }
            if format == Format::Csv {
                let names: Vec<u32> = vertices.iter().map(|v| v.0).collect();
                write_csv(&args.out, &names, &matrix)?;
            } else {
                let mut file = NpyFile::create(&args.out, n)?;
                for (i, row) in matrix.values().chunks(n).enumerate() {
                    file.row(i, row)?;
                }
                file.finish()?;
            }
        }
        Sink::Sparse(mut matrix) => {
            matrix.symmetrize_min();
            let mut file = MtxFile::create(&args.out, n, &comment)?;
            file.entries(matrix.entries().iter().copied())?;
            file.finish()?;
        }
    }
    Ok(summary)
}

/// The selected vertices, in the order given; errors name the argument or the file.
fn selection(args: &MatrixArgs, mesh: &TriMesh) -> Result<Vec<VertexId>, String> {
    let count = mesh.vertex_count();
    if args.all {
        return Ok((0..count as u32).map(VertexId).collect());
    }
    if let Some(k) = args.random {
        return Ok(random_sources(mesh, k as usize, args.seed));
    }
    let (text, origin) = match (&args.sources, &args.sources_file) {
        (Some(list), _) => (list.clone(), "--sources".to_owned()),
        (None, Some(path)) => (
            std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?,
            path.display().to_string(),
        ),
        (None, None) => return Err("no vertex selected".to_owned()),
    };
    let mut vertices = Vec::new();
    for (line_number, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or_default();
        for item in line.split([',', ' ', '\t']).filter(|s| !s.is_empty()) {
            let at = || match args.sources_file {
                Some(_) => format!("{origin}:{}", line_number + 1),
                None => origin.clone(),
            };
            let index = item
                .strip_prefix("v:")
                .unwrap_or(item)
                .parse::<u32>()
                .map_err(|_| format!("{}: '{item}' is not a vertex (v:I or I)", at()))?;
            if index as usize >= count {
                return Err(format!(
                    "{}: vertex {index} is out of range: {} has {count} vertices",
                    at(),
                    args.mesh
                ));
            }
            vertices.push(VertexId(index));
        }
    }
    if vertices.is_empty() {
        return Err(format!("{origin}: no vertex selected"));
    }
    Ok(vertices)
}
