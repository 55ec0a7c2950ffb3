//! `exact-geodesics`: exact geodesic distances, paths and wedges on triangle meshes.
//!
//! The only part of the crate that prints. Errors go to stderr with exit code 1 (2 for usage).

mod benchmark_model;
mod compare;
mod degeneracy;
mod distance;
mod experiment;
mod load;
mod matrix;
mod matrix_files;
mod path;
mod progress;
mod spec;
mod stats;
mod subdivision;
mod verify;
mod wedges;

use clap::{Args, Parser, Subcommand, ValueEnum};
use exact_geodesics::mmp::Progress;
use exact_geodesics::scalar::exact;
use exact_geodesics::{
    propagate_vertices_with_progress, propagate_with_progress, GeodesicField, PointError,
    PropagateOptions, Scalar, Stats, SurfacePoint, TriMesh, VertexField,
};
use std::io::{BufWriter, Write};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "exact-geodesics",
    version,
    about = "Exact geodesics on triangle meshes (MMP in wedge form)"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Geodesic distance of every vertex to the nearest source (CSV: vertex,distance,source).
    Distance(distance::DistanceArgs),
    /// The shortest path from a target back to its nearest source.
    Path(path::PathArgs),
    /// Geodesic distances among selected vertices (one propagation per source, stopped once
    /// every selected vertex is final, sources in parallel): .npy, .mtx or .csv.
    Matrix(matrix::MatrixArgs),
    /// The final wedges on an edge, on a face's edges, or on every edge, as 7-tuples
    /// (b0, b1, d0, d1, tau, s, sigma) [LZT Example 4].
    Wedges(wedges::WedgesArgs),
    /// Runs f64, adaptive and exact on the same input and reports where they differ: vertex
    /// distances, wedge counts, eq.-(2) cases, and each wedge meeting decided differently.
    Compare(compare::CompareArgs),
    /// Counters and timings of one propagation, as JSON.
    Stats(stats::StatsArgs),
    /// A benchmark model [LZT §5]: obstacles lifted as cylinders over a triangulated rectangle,
    /// with the exact geodesic between p and q from the visibility graph.
    BenchmarkModel(benchmark_model::BenchmarkModelArgs),
    /// Checks the engine on a benchmark model written by benchmark-model.
    Verify(verify::VerifyArgs),
    /// The regions of one face, each closest to one image of a pseudo-source, and their
    /// bisectors [LZT Property 4, Fig. 15]; optionally drawn as SVG.
    Subdivision(subdivision::SubdivisionArgs),
    /// The tables of [LZT §6] (Table 1: wedges per edge; Table 2: edge lengths and wedges per
    /// unit length) over models, backends and seeded sources, as CSV and JSON.
    #[command(subcommand_required = true)]
    Experiment(experiment::ExperimentArgs),
    /// Runs the degenerate-mesh corpus and checks the invariants of every distance (JSON
    /// summary; fails if any is broken).
    Degeneracy(degeneracy::DegeneracyArgs),
}

/// The number type the engine runs on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Backend {
    /// Hardware floating point with the documented tolerance policy.
    F64,
    /// f64 values, every predicate decided exactly for them (Shewchuk's adaptive predicates,
    /// interval filter + exact rationals for eq. (2)).
    Adaptive,
    /// Exact reals (rationals with exact square roots) with certified signs.
    Exact,
}

impl Backend {
    /// The name used on the command line and in reports.
    pub fn name(self) -> &'static str {
        exact_geodesics::scalar::Backend::from(self).name()
    }
}

impl From<Backend> for exact_geodesics::scalar::Backend {
    fn from(backend: Backend) -> Self {
        match backend {
            Backend::F64 => Self::F64,
            Backend::Adaptive => Self::Adaptive,
            Backend::Exact => Self::Exact,
        }
    }
}

/// Arguments every command shares: the mesh, the sources, the backend.
#[derive(Args)]
pub struct Common {
    /// Mesh file (OBJ, OFF, PLY) or a generated mesh `gen:SHAPE` (e.g. gen:icosphere:3).
    pub mesh: String,
    /// A source: v:I (vertex), e:A,B,T (point at T from A to B), f:F,U,V,W (barycentric in face F).
    #[arg(long = "source", required = true)]
    pub sources: Vec<String>,
    /// Number type of the engine.
    #[arg(long, value_enum, default_value_t = Backend::F64)]
    pub backend: Backend,
    #[command(flatten)]
    pub cap: PrecisionCap,
    /// Stop propagating at this distance; farther vertices are reported unreachable (inf).
    /// A non-negative number; `inf` is no limit.
    #[arg(long, allow_hyphen_values = true, value_parser = non_negative_distance)]
    pub max_distance: Option<f64>,
    #[command(flatten)]
    pub read: load::ReadArgs,
    /// Fail (exit 1) when the backend leaves a decision of the propagation uncertified,
    /// instead of warning on stderr.
    #[arg(long)]
    pub require_certified: bool,
}

/// `--precision-cap`: the exact backend's precision cap.
#[derive(Args)]
pub struct PrecisionCap {
    /// Largest precision (bits) the exact backend tries before it records a decision as
    /// uncertified.
    #[arg(
        long,
        default_value_t = exact::DEFAULT_PRECISION_CAP,
        value_parser = clap::value_parser!(u32)
            .range(i64::from(exact::MIN_PRECISION_CAP)..=i64::from(exact::MAX_PRECISION_CAP))
    )]
    pub precision_cap: u32,
}

/// Fails with `message` when the user asked for certified results, else warns with it.
pub fn report_uncertified(message: String, require_certified: bool) -> Result<(), String> {
    if require_certified {
        return Err(message);
    }
    eprintln!("warning: {message}");
    Ok(())
}

/// `--digits N`: significant digits of exact values (the exact backend only).
#[derive(Args)]
pub struct Digits {
    /// Print distances with this many significant digits, each guaranteed: the printed value
    /// differs from the exact distance by less than one unit in its last digit (the exact
    /// backend only; 1 to 100000).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub digits: Option<u32>,
}

impl Digits {
    /// The digits asked for, checked against the backend: only the exact one has exact
    /// values to print.
    pub fn checked(&self, backend: Backend) -> Result<Option<u32>, String> {
        match (self.digits, backend) {
            (Some(_), Backend::F64 | Backend::Adaptive) => Err(format!(
                "--digits needs --backend exact: the {} backend has no exact values to print",
                backend.name()
            )),
            (digits, _) => Ok(digits),
        }
    }
}

/// An exact distance in `digits` significant digits, or an error naming what it is of.
pub fn certified_digits(value: &exact::Real, digits: u32, what: &str) -> Result<String, String> {
    value
        .certified_decimal(digits)
        .map_err(|e| format!("{what}: {e} (see --precision-cap)"))
}

/// Parses `--max-distance`: a number that is not negative (`inf` allowed, NaN not).
fn non_negative_distance(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(d) if d >= 0.0 => Ok(d),
        _ => Err("expected a non-negative number (inf for no limit)".to_owned()),
    }
}

/// A loaded mesh with parsed sources, ready to propagate.
pub struct Job {
    mesh: TriMesh,
    sources: Vec<SurfacePoint>,
    options: PropagateOptions,
    backend: Backend,
    require_certified: bool,
}

impl Common {
    fn job(&self) -> Result<Job, String> {
        let mesh = load::load_mesh(&self.mesh, &self.read.options())?;
        let sources = self
            .sources
            .iter()
            .map(|s| spec::parse_point(&mesh, &self.mesh, s))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Job {
            mesh,
            sources,
            options: {
                let mut options =
                    PropagateOptions::default().with_precision_cap(self.cap.precision_cap);
                options.max_distance = self.max_distance;
                options
            },
            backend: self.backend,
            require_certified: self.require_certified,
        })
    }
}

impl Job {
    /// Propagates with the chosen backend, showing progress on a terminal. A run with
    /// uncertified decisions is an error with `--require-certified`, else a warning.
    fn field<S: Scalar>(&self) -> Result<GeodesicField<'_, S>, String> {
        let field = self.with_progress(|progress| {
            propagate_with_progress(&self.mesh, &self.sources, &self.options, progress)
        })?;
        self.check_certified(field.stats())?;
        Ok(field)
    }

    /// [`Job::field`] for the vertices' distances only, which keeps only the wedges near the
    /// front ([`propagate_vertices_with_progress`]).
    fn vertex_field<S: Scalar>(&self) -> Result<VertexField<'_, S>, String> {
        let field = self.with_progress(|progress| {
            propagate_vertices_with_progress(&self.mesh, &self.sources, &self.options, progress)
        })?;
        self.check_certified(field.stats())?;
        Ok(field)
    }

    /// Runs a propagation with a progress bar on a terminal.
    fn with_progress<T>(
        &self,
        run: impl FnOnce(&mut dyn FnMut(&Progress)) -> Result<T, PointError>,
    ) -> Result<T, String> {
        let bar = progress::bar(self.mesh.vertex_count());
        let result = run(&mut |p| progress::update(&bar, p)).map_err(|e| e.to_string())?;
        bar.finish_and_clear();
        Ok(result)
    }

    /// An error with `--require-certified`, else a warning, if the run left decisions
    /// uncertified.
    fn check_certified(&self, stats: &Stats) -> Result<(), String> {
        let counts = &stats.backend;
        if counts.uncertified == 0 {
            return Ok(());
        }
        let message = format!(
            "{} of {} decisions of the {} backend are not certified: the result may be \
             wrong where they fell (`stats` lists the first of them; a larger \
             --precision-cap may settle them)",
            counts.uncertified,
            counts.decisions,
            self.backend.name()
        );
        report_uncertified(message, self.require_certified)
    }
}

/// Runs `$body` with `$s` bound to the number type of `$backend`.
macro_rules! with_backend {
    ($backend:expr, $s:ident => $body:expr) => {
        match $backend {
            Backend::F64 => {
                type $s = f64;
                $body
            }
            Backend::Adaptive => {
                type $s = exact_geodesics::scalar::Adaptive;
                $body
            }
            Backend::Exact => {
                type $s = exact_geodesics::scalar::Real;
                $body
            }
        }
    };
}
pub(crate) use with_backend;

/// Writes a command's output to `--out` or stdout.
pub fn emit(out: Option<&PathBuf>, text: &str) -> Result<(), String> {
    emit_with(out, |w| w.write_all(text.as_bytes()))
}

/// Writes a command's output to `--out` or stdout as `write` produces it, through a buffer, so
/// that a large output need not be held whole. A closed stdout (`| head`) is not an error.
pub fn emit_with(
    out: Option<&PathBuf>,
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), String> {
    match out {
        Some(path) => std::fs::File::create(path)
            .and_then(|file| {
                let mut file = BufWriter::new(file);
                write(&mut file)?;
                file.flush()
            })
            .map_err(|e| format!("{}: {e}", path.display())),
        None => {
            let mut stdout = BufWriter::new(std::io::stdout().lock());
            match write(&mut stdout).and_then(|()| stdout.flush()) {
                Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(format!("stdout: {e}")),
                _ => Ok(()),
            }
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Distance(args) => distance::run(args),
        Command::Path(args) => path::run(args),
        Command::Matrix(args) => matrix::run(args),
        Command::Wedges(args) => wedges::run(args),
        Command::Stats(args) => stats::run(args),
        Command::Compare(args) => compare::run(args),
        Command::BenchmarkModel(args) => benchmark_model::run(args),
        Command::Verify(args) => verify::run(args),
        Command::Subdivision(args) => subdivision::run(args),
        Command::Degeneracy(args) => degeneracy::run(args),
        Command::Experiment(args) => experiment::run(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}
