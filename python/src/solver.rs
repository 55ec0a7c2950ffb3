//! The stateful solver: a validated mesh and a backend, from which fields are propagated, one
//! at a time or one per source on every core (the library's distance matrices).

use crate::field::{AnyField, GeodesicField};
use crate::input::{self, rows_of_three, value_error};
use exact_geodesics::matrix::{distance_matrix, MatrixOptions, MatrixRow};
use exact_geodesics::scalar::{Adaptive, Backend, Real, Scalar};
use exact_geodesics::{
    propagate_vertices, PointError, PropagateOptions, SurfacePoint, TriMesh, VertexId,
};
use numpy::ndarray::{Array2, ArrayView1};
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;
use std::convert::Infallible;
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
    /// With ``max_distance``, points farther than it are unreachable (``inf``). With
    /// ``stop_points`` (points as ``sources``), the propagation stops as soon as their
    /// distances are final: theirs, and those of every vertex no farther than the farthest of
    /// them, are the full run's; other vertices hold an upper bound or ``inf``. The GIL is
    /// released while the wedges propagate. Raises ``ValueError`` for no source, a point that
    /// is not on the mesh, or a negative ``max_distance``.
    #[pyo3(signature = (sources, max_distance = None, stop_points = None))]
    fn propagate(
        &self,
        py: Python<'_>,
        sources: &Bound<'_, PyAny>,
        max_distance: Option<f64>,
        stop_points: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<GeodesicField> {
        let sources = input::surface_points(&self.mesh, sources)?;
        let mut options = input::options(max_distance, self.precision_cap)?;
        if let Some(points) = stop_points {
            options.stop_points = input::surface_points(&self.mesh, points)?;
        }
        let (mesh, backend) = (Arc::clone(&self.mesh), self.backend);
        let field = py
            .detach(move || AnyField::propagate(&mesh, backend, &sources, &options))
            .map_err(value_error)?;
        Ok(GeodesicField::new(field, backend, self.precision_cap))
    }

    /// The geodesic distance of every vertex to the nearest of ``sources`` and that source:
    /// ``(distances, nearest_source)``, a float64 array (``inf`` where unreachable) and an int64
    /// array of indices into ``sources`` (``-1`` where unreachable), in the order of the
    /// vertices. What ``propagate(sources, max_distance).distances`` and ``.nearest_source``
    /// give, without the field: the wedges of an edge are given up as soon as no later one can
    /// change a vertex (the memory of a run is that of its front), and the directions of a
    /// single source vertex are split between two threads when ``threads`` (all cores if
    /// ``None``) is two or more (backends ``"f64"`` and ``"adaptive"``; the distances are then
    /// one thread's up to the last bits where geodesics of the two halves tie). The GIL is
    /// released while the wedges propagate. Raises ``ValueError`` as ``propagate`` does, or for
    /// ``threads`` below 1.
    #[pyo3(signature = (sources, max_distance = None, threads = None))]
    fn vertex_distances<'py>(
        &self,
        py: Python<'py>,
        sources: &Bound<'py, PyAny>,
        max_distance: Option<f64>,
        threads: Option<usize>,
    ) -> PyResult<VertexColumns<'py>> {
        let sources = input::surface_points(&self.mesh, sources)?;
        let threads = match threads {
            Some(0) => return Err(value_error("threads must be at least 1")),
            Some(n) => n,
            None => std::thread::available_parallelism().map_or(1, |n| n.get()),
        };
        let options = input::options(max_distance, self.precision_cap)?.with_threads(threads);
        let mesh = &*self.mesh;
        let (distances, nearest) = py
            .detach(|| match self.backend {
                Backend::F64 => vertex_columns::<f64>(mesh, &sources, &options),
                Backend::Adaptive => vertex_columns::<Adaptive>(mesh, &sources, &options),
                Backend::Exact => vertex_columns::<Real>(mesh, &sources, &options),
            })
            .map_err(value_error)?;
        Ok((
            PyArray1::from_vec(py, distances),
            PyArray1::from_vec(py, nearest),
        ))
    }

    /// The distances from each source alone (one propagation per source, stopped once every
    /// target is final) to ``targets``: a float64 array of shape (len(sources), len(targets)),
    /// ``inf`` where unreachable; each row is what ``propagate`` from its source gives.
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
        let targets = self.targets(targets, "targets")?;
        let options = self.matrix_options(max_distance, threads)?;
        let mut matrix = Array2::from_elem((sources.len(), targets.len()), f64::INFINITY);
        if !matrix.is_empty() {
            py.detach(|| {
                self.rows(&sources, &targets, &options, |row| {
                    matrix
                        .row_mut(row.index)
                        .assign(&ArrayView1::from(&row.distances));
                })
            })?;
        }
        Ok(matrix.into_pyarray(py))
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
        let vertices = self.targets(sources, "sources")?;
        let sources: Vec<SurfacePoint> =
            vertices.iter().map(|&v| SurfacePoint::Vertex(v)).collect();
        let everywhere = self.targets(None, "targets")?;
        let options = self.matrix_options(max_distance, threads)?;
        let mut rows: Vec<Vec<(u32, u32, f64)>> = vec![Vec::new(); sources.len()];
        if !sources.is_empty() {
            py.detach(|| {
                self.rows(&sources, &everywhere, &options, |row| {
                    rows[row.index] = row.finite_entries().filter(|e| e.2 != 0.0).collect();
                })
            })?;
        }
        let (mut data, mut row_index, mut column_index) = (Vec::new(), Vec::new(), Vec::new());
        for (i, j, d) in rows.into_iter().flatten() {
            data.push(d);
            row_index.push(i64::from(vertices[i as usize].0));
            column_index.push(i64::from(j));
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

/// Every vertex's distance and the index of its nearest source, as NumPy arrays.
type VertexColumns<'py> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<i64>>);

/// The distance of every vertex from `sources` and the index of its nearest source (`-1`
/// where unreachable), by [`propagate_vertices`].
fn vertex_columns<S: Scalar>(
    mesh: &TriMesh,
    sources: &[SurfacePoint],
    options: &PropagateOptions,
) -> Result<(Vec<f64>, Vec<i64>), PointError> {
    let field = propagate_vertices::<S>(mesh, sources, options)?;
    Ok((0..mesh.vertex_count() as u32)
        .map(VertexId)
        .map(|v| {
            let nearest = field.nearest_source(v).map_or(-1, |k| i64::from(k.0));
            (field.vertex_distance(v), nearest)
        })
        .unzip())
}

impl GeodesicSolver {
    /// Vertex indices of any integer dtype, each a vertex of the mesh; every vertex if `None`.
    fn targets(&self, obj: Option<&Bound<'_, PyAny>>, what: &str) -> PyResult<Vec<VertexId>> {
        let count = self.mesh.vertex_count();
        let Some(obj) = obj else {
            return Ok((0..count as u32).map(VertexId).collect());
        };
        let (indices, _) = input::indices(obj, what)?;
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

    /// The options of a matrix: a valid `max_distance`, at least one thread.
    fn matrix_options(
        &self,
        max_distance: Option<f64>,
        threads: Option<usize>,
    ) -> PyResult<MatrixOptions> {
        let propagation = input::options(max_distance, self.precision_cap)?;
        if threads == Some(0) {
            return Err(value_error("threads must be at least 1"));
        }
        let mut options = MatrixOptions::default();
        options.max_distance = propagation.max_distance;
        options.precision_cap = self.precision_cap;
        options.threads = threads;
        Ok(options)
    }

    /// One propagation per source with the solver's backend, on every thread asked for;
    /// `store` receives each row as it is done.
    fn rows(
        &self,
        sources: &[SurfacePoint],
        targets: &[VertexId],
        options: &MatrixOptions,
        mut store: impl FnMut(MatrixRow),
    ) -> PyResult<()> {
        let sink = |row: MatrixRow| -> Result<(), Infallible> {
            store(row);
            Ok(())
        };
        let mesh = &self.mesh;
        match self.backend {
            Backend::F64 => distance_matrix::<f64, _>(mesh, sources, targets, options, sink),
            Backend::Adaptive => {
                distance_matrix::<Adaptive, _>(mesh, sources, targets, options, sink)
            }
            Backend::Exact => distance_matrix::<Real, _>(mesh, sources, targets, options, sink),
        }
        .map(drop)
        .map_err(value_error)
    }
}
