//! The distance field of a propagation, owned together with its mesh: the library's
//! `GeodesicField<'m, S>` borrows the mesh, so the Python object holds the mesh (shared with
//! its solver) and the field that borrows it in one self-referential cell.

use crate::input::{self, rows_of_three, value_error};
use exact_geodesics::mesh::EdgeId;
use exact_geodesics::scalar::exact::set_precision_cap;
use exact_geodesics::scalar::{Adaptive, Backend, Real, Scalar};
use exact_geodesics::{
    propagate_shared, GeodesicField as Field, PointError, PropagateOptions, PseudoSource,
    SurfacePoint, TraceError, TriMesh, VertexId, Wedge,
};
use numpy::{PyArray1, PyArray2};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::sync::Arc;

/// A field of any backend.
pub enum AnyField<'m> {
    F64(Field<'m, f64>),
    Adaptive(Field<'m, Adaptive>),
    Exact(Field<'m, Real>),
}

/// Runs `$body` with `$field` bound to the field, whatever its backend.
macro_rules! on_field {
    ($any:expr, $field:ident => $body:expr) => {
        match $any {
            AnyField::F64($field) => $body,
            AnyField::Adaptive($field) => $body,
            AnyField::Exact($field) => $body,
        }
    };
}

impl AnyField<'static> {
    /// Propagates from `sources` with the backend's number type, on the shared mesh.
    pub fn propagate(
        mesh: &Arc<TriMesh>,
        backend: Backend,
        sources: &[SurfacePoint],
        options: &PropagateOptions,
    ) -> Result<Self, PointError> {
        Ok(match backend {
            Backend::F64 => AnyField::F64(propagate_shared(mesh, sources, options)?),
            Backend::Adaptive => AnyField::Adaptive(propagate_shared(mesh, sources, options)?),
            Backend::Exact => AnyField::Exact(propagate_shared(mesh, sources, options)?),
        })
    }
}

/// The geodesic distance field of a set of sources (``GeodesicSolver.propagate``).
///
/// Unreachable points (another component, a vertex no face uses, beyond ``max_distance``) are
/// at distance ``inf``.
#[pyclass(module = "exact_geodesics", frozen)]
pub struct GeodesicField {
    field: AnyField<'static>,
    backend: Backend,
    precision_cap: Option<u32>,
}

impl GeodesicField {
    pub fn new(field: AnyField<'static>, backend: Backend, precision_cap: Option<u32>) -> Self {
        GeodesicField {
            field,
            backend,
            precision_cap,
        }
    }

    fn mesh(&self) -> &TriMesh {
        on_field!(&self.field, f => f.mesh())
    }

    /// The exact backend's field, for `digits` certified digits, at the field's precision cap.
    fn exact_field(&self, digits: u32) -> PyResult<&Field<'static, Real>> {
        let AnyField::Exact(field) = &self.field else {
            return Err(PyValueError::new_err(
                "exact values need a field of the exact backend (backend=\"exact\")",
            ));
        };
        if digits == 0 {
            return Err(PyValueError::new_err("digits must be at least 1"));
        }
        self.query_cap()?;
        Ok(field)
    }

    /// Queries of the exact backend decide signs at the running thread's precision cap: give
    /// this thread the cap the field was propagated with (a Python thread may differ from the
    /// one that propagated).
    fn query_cap(&self) -> PyResult<()> {
        match self.precision_cap {
            Some(bits) => set_precision_cap(bits).map_err(value_error),
            None => Ok(()),
        }
    }
}

#[pymethods]
impl GeodesicField {
    /// The geodesic distance of every vertex to its nearest source (float64, ``inf`` where
    /// unreachable), in the order of the solver's vertices.
    #[getter]
    fn distances<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let distances = on_field!(&self.field, f => f.vertex_distances());
        PyArray1::from_vec(py, distances)
    }

    /// Index (into ``sources``) of the source nearest to every vertex (int64; ``-1`` where
    /// unreachable).
    #[getter]
    fn nearest_source<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<i64>> {
        let nearest = (0..self.mesh().vertex_count())
            .map(|v| {
                let v = VertexId(v as u32);
                on_field!(&self.field, f => f.nearest_source(v)).map_or(-1, |k| i64::from(k.0))
            })
            .collect();
        PyArray1::from_vec(py, nearest)
    }

    /// The sources as the library validated them, each as ``(kind, index, parameters)``.
    #[getter]
    fn sources<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let sources = on_field!(&self.field, f => f.sources());
        let items = sources
            .iter()
            .map(|p| input::simplex(py, p))
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, items)
    }

    /// The backend the field was computed with: ``"f64"``, ``"adaptive"`` or ``"exact"``.
    #[getter]
    fn backend(&self) -> &'static str {
        self.backend.name()
    }

    /// Whether the backend certified every decision of the propagation. Always ``True`` for
    /// ``f64`` and ``adaptive``, which certify nothing and count nothing; for ``exact``,
    /// ``False`` when a decision reached the precision cap unproved (see ``stats()``).
    #[getter]
    fn is_certified(&self) -> bool {
        on_field!(&self.field, f => f.is_certified())
    }

    /// The geodesic distance from the nearest source to any surface point (``inf`` if
    /// unreachable).
    ///
    /// Raises ``ValueError`` if the point is not a point of the mesh.
    fn distance_at(&self, point: &Bound<'_, PyAny>) -> PyResult<f64> {
        let point = input::surface_point(self.mesh(), point)?;
        self.query_cap()?;
        on_field!(&self.field, f => f.distance_at(&point)).map_err(value_error)
    }

    /// The certified decimal digits of the distance of every vertex (``exact`` backend only): a
    /// list of strings of ``digits`` significant digits, each within one unit of its last digit
    /// of the exact distance, ``None`` where unreachable.
    ///
    /// Raises ``ValueError`` for the float backends or ``digits`` = 0, ``RuntimeError`` where
    /// the digits are out of reach (an uncertified decision, or beyond the precision cap).
    #[pyo3(signature = (digits = 20))]
    fn exact_distances(&self, digits: u32) -> PyResult<Vec<Option<String>>> {
        let field = self.exact_field(digits)?;
        (0..self.mesh().vertex_count())
            .map(|v| {
                let v = VertexId(v as u32);
                field
                    .vertex_distance_exact(v)
                    .map(|d| certified_digits(&d, digits, &v.to_string()))
                    .transpose()
            })
            .collect()
    }

    /// The certified decimal digits of the distance at any surface point (``exact`` backend
    /// only), as ``exact_distances`` gives them; ``None`` if unreachable.
    ///
    /// Raises as ``exact_distances``, and ``ValueError`` if the point is not a point of the mesh.
    #[pyo3(signature = (point, digits = 20))]
    fn exact_distance_at(&self, point: &Bound<'_, PyAny>, digits: u32) -> PyResult<Option<String>> {
        let field = self.exact_field(digits)?;
        let point = input::surface_point(self.mesh(), point)?;
        field
            .distance_at_exact(&point)
            .map_err(value_error)?
            .map(|d| certified_digits(&d, digits, "the point"))
            .transpose()
    }

    /// The shortest path from ``target`` back to its nearest source [LZT §2].
    ///
    /// Raises ``ValueError`` for a target that is not a point of the mesh or that no source
    /// reaches, ``RuntimeError`` if rounding sent the walk astray.
    fn path(&self, py: Python<'_>, target: &Bound<'_, PyAny>) -> PyResult<GeodesicPath> {
        let target = input::surface_point(self.mesh(), target)?;
        self.query_cap()?;
        let path = on_field!(&self.field, f => f.trace_back(&target)).map_err(trace_error)?;
        path_to_python(py, &path)
    }

    /// The shortest path from ``target`` with certified digits (``exact`` backend only):
    /// ``(path, distance, offsets)``, where ``distance`` is the target's distance and
    /// ``offsets[i]``, for each of ``path.simplices`` that is a point the walk found inside an
    /// edge, its offset along the edge from the edge's first vertex (``None`` elsewhere), as
    /// strings of ``digits`` certified significant digits.
    ///
    /// Raises as ``path`` and as ``exact_distances``.
    #[pyo3(signature = (target, digits = 20))]
    fn exact_path(
        &self,
        py: Python<'_>,
        target: &Bound<'_, PyAny>,
        digits: u32,
    ) -> PyResult<(GeodesicPath, String, Vec<Option<String>>)> {
        let field = self.exact_field(digits)?;
        let target = input::surface_point(self.mesh(), target)?;
        let exact = field.trace_back_exact(&target).map_err(trace_error)?;
        let offsets = exact
            .offsets
            .iter()
            .map(|x| {
                x.as_ref()
                    .map(|x| certified_digits(x, digits, "an edge crossing"))
                    .transpose()
            })
            .collect::<PyResult<Vec<_>>>()?;
        let distance = certified_digits(&exact.distance, digits, "the target")?;
        Ok((path_to_python(py, &exact.path)?, distance, offsets))
    }

    /// The final wedges on an edge [LZT Definition 1], sorted along it from its first vertex
    /// (``GeodesicSolver.edges[e][0]``), in the model's units, as dicts with ``b0``, ``b1``
    /// (the range), ``d0``, ``d1`` (distances from the pseudo-source to the range's ends),
    /// ``sigma`` (the pseudo-source's geodesic distance), ``tau`` (0 or 1: the side of the
    /// edge, its first or second face), ``source_x``, ``source_y`` (the unfolded
    /// pseudo-source in the edge's frame), ``pseudo_source`` (``("source", k)`` or
    /// ``("vertex", v)``) and ``source`` (the source the wedge leads back to).
    ///
    /// ``edge`` is an edge index or a pair of vertices ``(a, b)``; raises ``ValueError`` for
    /// an edge that does not exist.
    fn wedges<'py>(
        &self,
        py: Python<'py>,
        edge: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyList>> {
        let mesh = self.mesh();
        let edge = edge_id(mesh, edge)?;
        let dicts = on_field!(&self.field, f => f
            .wedges(edge)
            .iter()
            .map(|w| wedge_dict(py, w))
            .collect::<PyResult<Vec<_>>>())?;
        PyList::new(py, dicts)
    }

    /// What happened during the propagation, as a dict: wedges created, propagated and
    /// filtered, pseudo-source emissions, the cases of eq. (2) (Property 1), queue and memory
    /// peaks, seconds, and how the backend settled its decisions (``backend``: for ``exact``,
    /// certified zeros by proof and ``uncertified`` decisions with their places).
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let stats = on_field!(&self.field, f => f.stats());
        let json =
            serde_json::to_string(stats).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        py.import("json")?.call_method1("loads", (json,))
    }

    fn __repr__(&self) -> String {
        let reached = on_field!(&self.field, f => f
            .vertex_distances()
            .iter()
            .filter(|d| d.is_finite())
            .count());
        format!(
            "GeodesicField(backend={:?}, vertices reached: {reached} of {})",
            self.backend.name(),
            self.mesh().vertex_count()
        )
    }
}

/// An edge given as an index or as a pair of vertices.
fn edge_id(mesh: &TriMesh, edge: &Bound<'_, PyAny>) -> PyResult<EdgeId> {
    if let Ok((a, b)) = edge.extract::<(u32, u32)>() {
        let count = mesh.vertex_count();
        if let Some(v) = [a, b].into_iter().find(|&v| v as usize >= count) {
            return Err(value_error(format!(
                "vertex {v} is out of range: the mesh has {count} vertices"
            )));
        }
        return mesh
            .edge_between(VertexId(a), VertexId(b))
            .ok_or_else(|| value_error(format!("vertices {a} and {b} are not joined by an edge")));
    }
    let e: u32 = edge.extract().map_err(|_| {
        value_error("an edge is an edge index or a pair of vertices (a, b)".to_owned())
    })?;
    if e as usize >= mesh.edge_count() {
        return Err(value_error(format!(
            "edge {e} is out of range: the mesh has {} edges",
            mesh.edge_count()
        )));
    }
    Ok(EdgeId(e))
}

fn wedge_dict<'py, S: Scalar>(py: Python<'py>, w: &Wedge<S>) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    dict.set_item("b0", w.b0.to_f64())?;
    dict.set_item("b1", w.b1.to_f64())?;
    dict.set_item("d0", w.d0().to_f64())?;
    dict.set_item("d1", w.d1().to_f64())?;
    dict.set_item("sigma", w.sigma.to_f64())?;
    dict.set_item("tau", w.tau.index())?;
    dict.set_item("source_x", w.source_x.to_f64())?;
    dict.set_item("source_y", w.source_y.to_f64())?;
    match w.pseudo_source {
        PseudoSource::Source(k) => dict.set_item("pseudo_source", ("source", k.0))?,
        PseudoSource::Vertex(v) => dict.set_item("pseudo_source", ("vertex", v.0))?,
    }
    dict.set_item("source", w.source.0)?;
    Ok(dict)
}

/// A shortest path from a target back to its nearest source (``GeodesicField.path``).
#[pyclass(module = "exact_geodesics", frozen, get_all)]
pub struct GeodesicPath {
    /// The path's points in space, from the target to the source: a (k, 3) float64 array.
    points: Py<PyArray2<f64>>,
    /// The same points as ``(kind, index, parameters)``: ``("vertex", v, ())``,
    /// ``("edge", e, (t,))`` (``t`` from ``GeodesicSolver.edges[e][0]``) or
    /// ``("face", f, (u, v, w))``.
    simplices: Py<PyList>,
    /// The geodesic distance of the target, as the field gives it.
    distance: f64,
    /// Index of the source the path ends at.
    source: usize,
    /// The length of the polyline (equal to ``distance`` up to rounding).
    length: f64,
}

#[pymethods]
impl GeodesicPath {
    fn __len__(&self, py: Python<'_>) -> usize {
        self.simplices.bind(py).len()
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "GeodesicPath({} points, distance={}, source={})",
            self.simplices.bind(py).len(),
            self.distance,
            self.source
        )
    }
}

/// `digits` certified decimal digits of `value`, or a `RuntimeError` naming `what`.
fn certified_digits(value: &Real, digits: u32, what: &str) -> PyResult<String> {
    value
        .certified_decimal(digits)
        .map_err(|e| PyRuntimeError::new_err(format!("{what}: {e}")))
}

/// A trace error as Python raises it: `RuntimeError` for a lost walk, `ValueError` otherwise.
fn trace_error(e: TraceError) -> PyErr {
    match e {
        TraceError::Lost { .. } => PyRuntimeError::new_err(e.to_string()),
        e => value_error(e),
    }
}

/// A library path as the Python class.
fn path_to_python(py: Python<'_>, path: &exact_geodesics::GeodesicPath) -> PyResult<GeodesicPath> {
    let simplices = path
        .simplices
        .iter()
        .map(|p| input::simplex(py, p))
        .collect::<PyResult<Vec<_>>>()?;
    Ok(GeodesicPath {
        points: rows_of_three(py, &path.points).unbind(),
        simplices: PyList::new(py, simplices)?.unbind(),
        distance: path.distance,
        source: path.source.index(),
        length: path.length(),
    })
}
