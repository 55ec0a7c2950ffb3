//! Python bindings of `exact-geodesics`: the extension module `exact_geodesics._native`, which
//! the Python package `exact_geodesics` (in `python/exact_geodesics/`) re-exports beside its
//! gdist-compatible functions.
//!
//! Errors reach Python as `ValueError` (bad input, with the library's message) or
//! `RuntimeError` (the library could not finish); nothing is printed. Propagations release the
//! GIL.

mod field;
mod input;
mod solver;

use exact_geodesics::mesh::io::{read_path, ReadOptions};
use exact_geodesics::mesh::shapes::parse_shape;
use exact_geodesics::TriMesh;
use input::{rows_of_three, value_error};
use numpy::PyArray2;
use pyo3::prelude::*;

/// A mesh's vertices (float64, (n, 3)) and triangles (int64, (m, 3)).
type MeshArrays<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<i64>>);

fn arrays<'py>(py: Python<'py>, mesh: &TriMesh) -> PyResult<MeshArrays<'py>> {
    let triangles = rows_of_three(py, mesh.faces()).call_method1("astype", ("int64",))?;
    Ok((
        rows_of_three(py, mesh.positions()),
        triangles.cast_into::<PyArray2<i64>>()?,
    ))
}

/// Reads an OBJ, OFF or PLY file (by its extension) as ``(vertices, triangles)``, keeping the
/// file's vertex order. Polygons are refused unless ``triangulate``. Raises ``ValueError``
/// naming the file (and line) for a file that is not a valid mesh.
#[pyfunction]
#[pyo3(signature = (path, triangulate = false))]
fn read_mesh(
    py: Python<'_>,
    path: std::path::PathBuf,
    triangulate: bool,
) -> PyResult<MeshArrays<'_>> {
    let mesh = read_path(
        &path,
        &ReadOptions {
            triangulate,
            ..ReadOptions::default()
        },
    )
    .map_err(value_error)?;
    arrays(py, &mesh)
}

/// A generated mesh as ``(vertices, triangles)``: ``"icosphere:3"``, ``"grid:20,20"``,
/// ``"cube"``, ``"l-shape:8"``, ... (the command line's ``gen:SHAPE`` without ``gen:``).
/// Raises ``ValueError`` for an unknown shape or a size out of its range.
#[pyfunction]
fn generate_mesh<'py>(py: Python<'py>, shape: &str) -> PyResult<MeshArrays<'py>> {
    let mesh = parse_shape(shape).map_err(value_error)?;
    arrays(py, &mesh)
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<solver::GeodesicSolver>()?;
    m.add_class::<field::GeodesicField>()?;
    m.add_class::<field::GeodesicPath>()?;
    m.add_function(wrap_pyfunction!(read_mesh, m)?)?;
    m.add_function(wrap_pyfunction!(generate_mesh, m)?)?;
    Ok(())
}
