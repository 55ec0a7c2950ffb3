//! The stateful solver: a validated mesh and a backend, from which fields are propagated, one
//! at a time or one per source on every core.

use crate::field::{AnyField, GeodesicField};
use crate::input::{self, rows_of_three, value_error};
use exact_geodesics::scalar::{Adaptive, Backend, Real, Scalar};
use exact_geodesics::{
    propagate, GeodesicField as Field, PointError, PropagateOptions, SurfacePoint, TriMesh,
    VertexId,
};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

/// Geodesic distances and paths on one triangle mesh, by the MMP algorithm in wedge form
/// [SSK+05, LZT], with the number type of ``backend``:
///
/// - ``"f64"``: hardware floats with one documented tolerance policy (fastest);
/// - ``"adaptive"``: float values, every predicate decided exactly for them;
/// - ``"exact"``: exact reals with certified signs (slow: small meshes).
///
/// ``vertices`` is an (n, 3) array (converted to float64), ``triangles`` an (m, 3) array of
/// vertex indices of any integer dtype (1-based if ``is_one_indexed``). ``precision_cap`` is
/// the exact backend's limit in bits (128 to 2**20). Raises ``ValueError`` with the library's
/// message for a mesh it refuses (non-finite coordinates, indices out of range, a face
/// repeating a vertex, an edge of more than two faces, no faces).
#[pyclass(module = "exact_geodesics", frozen)]
pub struct GeodesicSolver {
    mesh: Arc<TriMesh>,
    backend: Backend,
    precision_cap: Option<u32>,
}

#[pymethods]
impl GeodesicSolver {
    #[new]
    #[pyo3(signature = (vertices, triangles, backend = "f64", precision_cap = None, is_one_indexed = false))]
    fn new(
        vertices: &Bound<'_, PyAny>,
        triangles: &Bound<'_, PyAny>,
        backend: &str,
        precision_cap: Option<u32>,
        is_one_indexed: bool,
    ) -> PyResult<Self> {
        let backend = input::backend(backend)?;
        let precision_cap = input::precision_cap(backend, precision_cap)?;
        let mesh = input::mesh(vertices, triangles, is_one_indexed)?;
        Ok(GeodesicSolver {
            mesh: Arc::new(mesh),
            backend,
            precision_cap,
        })
    }

    /// Propagates from ``sources`` and returns the distance field.
    ///
    /// ``sources`` is one point or a sequence of points (a NumPy array of vertex indices of any
    /// integer dtype, or points as ``v``, ``("edge", a, b, t)``, ``("face", f, (u, v, w))``).
    /// With ``max_distance``, points farther than it are unreachable (``inf``). The GIL is
    /// released while the wedges propagate. Raises ``ValueError`` for no source, a point that
    /// is not on the mesh, or a negative ``max_distance``.
    #[pyo3(signature = (sources, max_distance = None))]
    fn propagate(
        &self,
        py: Python<'_>,
        sources: &Bound<'_, PyAny>,
        max_distance: Option<f64>,
    ) -> PyResult<GeodesicField> {
        let sources = input::surface_points(&self.mesh, sources)?;
        let options = input::options(max_distance, self.precision_cap)?;
        let (mesh, backend) = (Arc::clone(&self.mesh), self.backend);
        let field = py
            .detach(move || AnyField::propagate(&mesh, backend, &sources, &options))
            .map_err(value_error)?;
        Ok(GeodesicField::new(field, backend, self.precision_cap))
    }

    /// The distances from each source alone (one propagation per source) to ``targets``: a
    /// float64 array of shape (len(sources), len(targets)), ``inf`` where unreachable.
    ///
    /// ``targets`` are vertex indices of any integer dtype (all vertices if ``None``).
    /// Propagations run on ``threads`` threads (all cores if ``None``) with the GIL released.
    #[pyo3(signature = (sources, targets = None, max_distance = None, threads = None))]
    fn distance_matrix<'py>(
        &self,
        py: Python<'py>,
        sources: &Bound<'py, PyAny>,
        targets: Option<&Bound<'py, PyAny>>,
        max_distance: Option<f64>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let sources = input::surface_points(&self.mesh, sources)?;
        let targets: Vec<VertexId> = match targets {
            Some(targets) => self.vertex_ids(targets, "targets")?,
            None => (0..self.mesh.vertex_count() as u32).map(VertexId).collect(),
        };
        let options = input::options(max_distance, self.precision_cap)?;
        let threads = thread_count(threads)?;
        let rows = py
            .detach(|| {
                for_each_source(&self.mesh, self.backend, &sources, &options, threads, |f| {
                    targets
                        .iter()
                        .map(|&v| f.vertex_distance(v))
                        .collect::<Vec<f64>>()
                })
            })
            .map_err(value_error)?;
        let flat: Vec<f64> = rows.into_iter().flatten().collect();
        Ok(Array2::from_shape_vec((sources.len(), targets.len()), flat)
            .expect("one row of len(targets) per source")
            .into_pyarray(py))
    }

    /// The distances from every source vertex to every vertex within ``max_distance`` of it,
    /// as the triplet ``(data, rows, columns)`` of a sparse matrix (row: the source, column:
    /// the vertex), leaving out zeros and unreachable vertices: what ``local_gdist_matrix``
    /// builds its CSC matrix from. ``sources`` are vertex indices (all vertices if ``None``).
    #[allow(clippy::type_complexity)]
    #[pyo3(signature = (max_distance, sources = None, threads = None))]
    fn local_distances<'py>(
        &self,
        py: Python<'py>,
        max_distance: Option<f64>,
        sources: Option<&Bound<'py, PyAny>>,
        threads: Option<usize>,
    ) -> PyResult<(
        Bound<'py, PyArray1<f64>>,
        Bound<'py, PyArray1<i64>>,
        Bound<'py, PyArray1<i64>>,
    )> {
        let vertices: Vec<VertexId> = match sources {
            Some(sources) => self.vertex_ids(sources, "sources")?,
            None => (0..self.mesh.vertex_count() as u32).map(VertexId).collect(),
        };
        let sources: Vec<SurfacePoint> =
            vertices.iter().map(|&v| SurfacePoint::Vertex(v)).collect();
        let options = input::options(max_distance, self.precision_cap)?;
        let threads = thread_count(threads)?;
        let rows = py
            .detach(|| {
                for_each_source(&self.mesh, self.backend, &sources, &options, threads, |f| {
                    f.vertex_distances()
                        .into_iter()
                        .enumerate()
                        .filter(|&(_, d)| d.is_finite() && d != 0.0)
                        .collect::<Vec<_>>()
                })
            })
            .map_err(value_error)?;
        let (mut data, mut row_index, mut column_index) = (Vec::new(), Vec::new(), Vec::new());
        for (source, row) in vertices.iter().zip(rows) {
            for (column, d) in row {
                data.push(d);
                row_index.push(i64::from(source.0));
                column_index.push(column as i64);
            }
        }
        Ok((
            PyArray1::from_vec(py, data),
            PyArray1::from_vec(py, row_index),
            PyArray1::from_vec(py, column_index),
        ))
    }

    /// The number type: ``"f64"``, ``"adaptive"`` or ``"exact"``.
    #[getter]
    fn backend(&self) -> &'static str {
        self.backend.name()
    }

    /// Number of vertices (including those no face uses).
    #[getter]
    fn vertex_count(&self) -> usize {
        self.mesh.vertex_count()
    }

    /// Number of triangles.
    #[getter]
    fn face_count(&self) -> usize {
        self.mesh.face_count()
    }

    /// The vertex coordinates, an (n, 3) float64 array.
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        rows_of_three(py, self.mesh.positions())
    }

    /// The triangles, an (m, 3) uint32 array of 0-based vertex indices.
    #[getter]
    fn triangles<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<u32>> {
        rows_of_three(py, self.mesh.faces())
    }

    /// The edges, an (e, 2) uint32 array of vertex pairs: edge ``i`` joins ``edges[i][0]`` to
    /// ``edges[i][1]``, and a point ``("edge", i, (t,))`` lies at fraction ``t`` from the first.
    #[getter]
    fn edges<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<u32>> {
        let flat: Vec<u32> = self
            .mesh
            .edges()
            .iter()
            .flat_map(|e| e.vertices.map(|v| v.0))
            .collect();
        Array2::from_shape_vec((self.mesh.edge_count(), 2), flat)
            .expect("two vertices per edge")
            .into_pyarray(py)
    }

    /// What is unusual but acceptable about the mesh (zero-area faces, vertices no face uses,
    /// several components, ...), one message each; empty for a clean mesh.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.mesh.validation().warnings()
    }

    fn __repr__(&self) -> String {
        format!(
            "GeodesicSolver({} vertices, {} triangles, backend={:?})",
            self.mesh.vertex_count(),
            self.mesh.face_count(),
            self.backend.name()
        )
    }
}

impl GeodesicSolver {
    /// Vertex indices of any integer dtype, each a vertex of the mesh.
    fn vertex_ids(&self, obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<VertexId>> {
        let (indices, _) = input::indices(obj, what)?;
        let count = self.mesh.vertex_count();
        indices
            .into_iter()
            .map(|v| {
                if (v as usize) < count {
                    Ok(VertexId(v))
                } else {
                    Err(value_error(format!(
                        "{what}: vertex {v} is out of range: the mesh has {count} vertices"
                    )))
                }
            })
            .collect()
    }
}

/// The number of threads asked for, or every core.
fn thread_count(threads: Option<usize>) -> PyResult<usize> {
    match threads {
        Some(0) => Err(value_error("threads must be at least 1")),
        Some(n) => Ok(n),
        None => Ok(std::thread::available_parallelism().map_or(1, usize::from)),
    }
}

/// Propagates from each source alone, on up to `threads` threads, and reads each field with
/// `read`; the results are in the order of the sources.
fn for_each_source<T: Send>(
    mesh: &TriMesh,
    backend: Backend,
    sources: &[SurfacePoint],
    options: &PropagateOptions,
    threads: usize,
    read: impl Fn(&dyn Distances) -> T + Sync,
) -> Result<Vec<T>, PointError> {
    // Refuse a bad source before any thread starts.
    for source in sources {
        source.validated(mesh)?;
    }
    match backend {
        Backend::F64 => each_source::<f64, T>(mesh, sources, options, threads, &read),
        Backend::Adaptive => each_source::<Adaptive, T>(mesh, sources, options, threads, &read),
        Backend::Exact => each_source::<Real, T>(mesh, sources, options, threads, &read),
    }
}

/// What `for_each_source` reads of a field, whatever its backend.
trait Distances {
    fn vertex_distance(&self, v: VertexId) -> f64;
    fn vertex_distances(&self) -> Vec<f64>;
}

impl<S: Scalar> Distances for Field<'_, S> {
    fn vertex_distance(&self, v: VertexId) -> f64 {
        Field::vertex_distance(self, v)
    }

    fn vertex_distances(&self) -> Vec<f64> {
        Field::vertex_distances(self)
    }
}

fn each_source<S: Scalar, T: Send>(
    mesh: &TriMesh,
    sources: &[SurfacePoint],
    options: &PropagateOptions,
    threads: usize,
    read: &(impl Fn(&dyn Distances) -> T + Sync),
) -> Result<Vec<T>, PointError> {
    let next = AtomicUsize::new(0);
    let work = || -> Result<Vec<(usize, T)>, PointError> {
        let mut done = Vec::new();
        loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(source) = sources.get(i) else {
                return Ok(done);
            };
            let field = propagate::<S>(mesh, std::slice::from_ref(source), options)?;
            done.push((i, read(&field)));
        }
    };
    let threads = threads.min(sources.len()).max(1);
    let mut results: Vec<Option<T>> = std::iter::repeat_with(|| None)
        .take(sources.len())
        .collect();
    std::thread::scope(|scope| {
        let workers: Vec<_> = (1..threads).map(|_| scope.spawn(work)).collect();
        let mine = work();
        for found in workers
            .into_iter()
            .map(|w| w.join().expect("a propagation does not panic"))
            .chain([mine])
        {
            for (i, value) in found? {
                results[i] = Some(value);
            }
        }
        Ok(results
            .into_iter()
            .map(|r| r.expect("every source was propagated"))
            .collect())
    })
}
