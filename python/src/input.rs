//! Python values in, library values out (and back): meshes from NumPy arrays, vertex indices of
//! any integer dtype, surface points as `v`, `("edge", a, b, t)` or `("face", f, (u, v, w))`,
//! and the simplices of a path as `(kind, index, parameters)`.

use exact_geodesics::glam::DVec3;
use exact_geodesics::mesh::{EdgeId, FaceId};
use exact_geodesics::scalar::exact::{MAX_PRECISION_CAP, MIN_PRECISION_CAP};
use exact_geodesics::scalar::Backend;
use exact_geodesics::{PropagateOptions, SurfacePoint, TriMesh, VertexId};
use numpy::ndarray::Array2;
use numpy::{
    IntoPyArray, PyArray2, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyString, PyTuple};

/// The grammar of a point, for error messages.
const POINT_FORMS: &str =
    "a vertex index, (\"edge\", a, b, t), (\"edge\", e, (t,)), (\"face\", f, (u, v, w)) or (\"vertex\", v)";

/// A `ValueError` carrying a message (the Rust error's, where there is one).
pub fn value_error(message: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(message.to_string())
}

/// `obj` as a NumPy array (`numpy.asarray`, no copy when it already is one).
fn as_array<'py>(
    obj: &Bound<'py, PyAny>,
    dtype: Option<&str>,
) -> PyResult<Bound<'py, PyUntypedArray>> {
    let numpy = obj.py().import("numpy")?;
    let array = match dtype {
        Some(dtype) => numpy.call_method1("asarray", (obj, dtype))?,
        None => numpy.call_method1("asarray", (obj,))?,
    };
    Ok(array.cast_into::<PyUntypedArray>()?)
}

/// Integers of any NumPy integer dtype (int8 .. int64, uint8 .. uint64) or a Python sequence of
/// ints, flattened, with the array's shape. Negative values, values beyond `u32` and arrays of
/// other dtypes (floats, booleans) are refused; an empty array of any dtype is empty.
pub fn indices(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<(Vec<u32>, Vec<usize>)> {
    let array = as_array(obj, None)?;
    let shape = array.shape().to_vec();
    if array.len() == 0 {
        return Ok((Vec::new(), shape));
    }
    let dtype = array.dtype();
    let out_of_range = |value: &dyn std::fmt::Display| {
        value_error(format!(
            "{what}: index {value} is out of range (indices are from 0 to {})",
            u32::MAX
        ))
    };
    let values = match dtype.kind() {
        b'i' => {
            let wide = array
                .call_method1("astype", ("int64",))?
                .cast_into::<PyArrayDyn<i64>>()?;
            let wide = wide.readonly();
            wide.as_array()
                .iter()
                .map(|&i| u32::try_from(i).map_err(|_| out_of_range(&i)))
                .collect::<PyResult<Vec<u32>>>()?
        }
        b'u' => {
            let wide = array
                .call_method1("astype", ("uint64",))?
                .cast_into::<PyArrayDyn<u64>>()?;
            let wide = wide.readonly();
            wide.as_array()
                .iter()
                .map(|&i| u32::try_from(i).map_err(|_| out_of_range(&i)))
                .collect::<PyResult<Vec<u32>>>()?
        }
        _ => {
            return Err(value_error(format!(
                "{what} must be integers (any integer dtype), not {}",
                dtype.str()?
            )))
        }
    };
    Ok((values, shape))
}

/// Builds the mesh from an `(n, 3)` array of coordinates (converted to float64) and an `(m, 3)`
/// array of vertex indices (any integer dtype; 1-based if `one_indexed`).
///
/// # Errors
/// `ValueError` for arrays of the wrong shape or dtype, and with the library's message
/// ([`exact_geodesics::MeshError`]) for anything [`TriMesh::new`] refuses.
pub fn mesh(
    vertices: &Bound<'_, PyAny>,
    triangles: &Bound<'_, PyAny>,
    one_indexed: bool,
) -> PyResult<TriMesh> {
    let coordinates = as_array(vertices, Some("float64"))?;
    let shape = coordinates.shape().to_vec();
    if shape.len() != 2 || shape[1] != 3 {
        return Err(value_error(format!(
            "vertices must be an (n, 3) array of coordinates, not of shape {shape:?}"
        )));
    }
    let coordinates = coordinates.cast_into::<PyArray2<f64>>()?;
    let positions = coordinates
        .readonly()
        .as_array()
        .rows()
        .into_iter()
        .map(|row| DVec3::new(row[0], row[1], row[2]))
        .collect();
    let (corners, shape) = indices(triangles, "triangles")?;
    if shape.len() != 2 || shape[1] != 3 {
        return Err(value_error(format!(
            "triangles must be an (m, 3) array of vertex indices, not of shape {shape:?}"
        )));
    }
    let corners = if one_indexed {
        corners
            .into_iter()
            .map(|i| {
                i.checked_sub(1).ok_or_else(|| {
                    value_error("triangles: index 0 in a one-indexed mesh (is_one_indexed=True)")
                })
            })
            .collect::<PyResult<Vec<u32>>>()?
    } else {
        corners
    };
    let faces = corners
        .chunks_exact(3)
        .map(|f| [f[0], f[1], f[2]])
        .collect();
    TriMesh::new(positions, faces).map_err(value_error)
}

/// The backend named `name`.
pub fn backend(name: &str) -> PyResult<Backend> {
    match name {
        "f64" => Ok(Backend::F64),
        "adaptive" => Ok(Backend::Adaptive),
        "exact" => Ok(Backend::Exact),
        _ => Err(value_error(format!(
            "unknown backend {name:?}: expected \"f64\", \"adaptive\" or \"exact\""
        ))),
    }
}

/// Checks a precision cap against the backend and the exact backend's range.
pub fn precision_cap(backend: Backend, bits: Option<u32>) -> PyResult<Option<u32>> {
    match bits {
        Some(_) if backend != Backend::Exact => Err(value_error(format!(
            "precision_cap applies to the exact backend only, not to {:?}",
            backend.name()
        ))),
        Some(bits) if !(MIN_PRECISION_CAP..=MAX_PRECISION_CAP).contains(&bits) => {
            Err(value_error(format!(
                "precision cap {bits} is out of range: it must be from {MIN_PRECISION_CAP} to \
                 {MAX_PRECISION_CAP} bits"
            )))
        }
        bits => Ok(bits),
    }
}

/// The options of a propagation: `max_distance` non-negative (`None` or `inf`: no limit).
pub fn options(
    max_distance: Option<f64>,
    precision_cap: Option<u32>,
) -> PyResult<PropagateOptions> {
    let mut options = PropagateOptions::default();
    options.precision_cap = precision_cap;
    match max_distance {
        Some(d) if d.is_nan() || d < 0.0 => Err(value_error(format!(
            "max_distance must be a non-negative number (inf for no limit), not {d}"
        ))),
        Some(d) if d.is_finite() => {
            options.max_distance = Some(d);
            Ok(options)
        }
        _ => Ok(options),
    }
}

/// A non-negative integer that fits `u32`.
fn index(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<u32> {
    let i: i64 = obj
        .extract()
        .map_err(|_| value_error(format!("{what} must be an integer, not {}", repr(obj))))?;
    u32::try_from(i).map_err(|_| value_error(format!("{what} {i} is out of range")))
}

fn repr(obj: &Bound<'_, PyAny>) -> String {
    obj.repr()
        .map_or_else(|_| "<unprintable>".to_owned(), |r| r.to_string())
}

/// Whether `obj` is one point (an integer, or a tuple naming its kind) rather than a sequence.
fn is_one_point(obj: &Bound<'_, PyAny>) -> bool {
    if let Ok(tuple) = obj.cast::<PyTuple>() {
        return tuple
            .get_item(0)
            .is_ok_and(|kind| kind.is_instance_of::<PyString>());
    }
    obj.extract::<i64>().is_ok()
}

/// One surface point, in any of the forms of [`POINT_FORMS`]; checked against the mesh later,
/// by the library ([`SurfacePoint::validated`]), but for an edge given by its two vertices.
pub fn surface_point(mesh: &TriMesh, obj: &Bound<'_, PyAny>) -> PyResult<SurfacePoint> {
    let Ok(tuple) = obj.cast::<PyTuple>() else {
        return index(obj, "a vertex index")
            .map(|v| SurfacePoint::Vertex(VertexId(v)))
            .map_err(|e| {
                value_error(format!("{e} (a point is {POINT_FORMS}; got {})", repr(obj)))
            });
    };
    let bad = || value_error(format!("a point is {POINT_FORMS}; got {}", repr(obj)));
    let kind: String = tuple.get_item(0)?.extract().map_err(|_| bad())?;
    let item = |i: usize| tuple.get_item(i);
    match (kind.as_str(), tuple.len()) {
        ("vertex", 2) => Ok(SurfacePoint::Vertex(VertexId(index(&item(1)?, "vertex")?))),
        ("vertex", 3) if item(2)?.len()? == 0 => {
            Ok(SurfacePoint::Vertex(VertexId(index(&item(1)?, "vertex")?)))
        }
        ("edge", 4) => {
            let (a, b) = (index(&item(1)?, "vertex")?, index(&item(2)?, "vertex")?);
            let t: f64 = item(3)?.extract().map_err(|_| bad())?;
            SurfacePoint::on_edge(mesh, a, b, t).map_err(value_error)
        }
        ("edge", 3) => {
            let edge = EdgeId(index(&item(1)?, "edge")?);
            let (t,): (f64,) = item(2)?.extract().map_err(|_| bad())?;
            Ok(SurfacePoint::Edge { edge, t })
        }
        ("face", 3) => {
            let face = FaceId(index(&item(1)?, "face")?);
            let (u, v, w): (f64, f64, f64) = item(2)?.extract().map_err(|_| bad())?;
            Ok(SurfacePoint::Face {
                face,
                bary: [u, v, w],
            })
        }
        _ => Err(bad()),
    }
}

/// Points: one point, a NumPy array of vertex indices (any integer dtype), or a sequence of
/// points.
pub fn surface_points(mesh: &TriMesh, obj: &Bound<'_, PyAny>) -> PyResult<Vec<SurfacePoint>> {
    if obj.cast::<PyUntypedArray>().is_ok() {
        let (vertices, _) = indices(obj, "sources")?;
        return Ok(vertices
            .into_iter()
            .map(|v| SurfacePoint::Vertex(VertexId(v)))
            .collect());
    }
    if is_one_point(obj) {
        return Ok(vec![surface_point(mesh, obj)?]);
    }
    obj.try_iter()
        .map_err(|_| value_error(format!("points are {POINT_FORMS}, or a sequence of them")))?
        .map(|item| surface_point(mesh, &item?))
        .collect()
}

/// A point as `(kind, index, parameters)`: `("vertex", v, ())`, `("edge", e, (t,))` with `t`
/// from the edge's first vertex, or `("face", f, (u, v, w))`.
pub fn simplex<'py>(py: Python<'py>, point: &SurfacePoint) -> PyResult<Bound<'py, PyAny>> {
    Ok(match *point {
        SurfacePoint::Vertex(v) => ("vertex", v.0, ()).into_pyobject(py)?.into_any(),
        SurfacePoint::Edge { edge, t } => ("edge", edge.0, (t,)).into_pyobject(py)?.into_any(),
        SurfacePoint::Face { face, bary } => ("face", face.0, (bary[0], bary[1], bary[2]))
            .into_pyobject(py)?
            .into_any(),
    })
}

/// Rows of three (arrays, or vectors such as mesh positions) as an `(n, 3)` NumPy array.
pub fn rows_of_three<'py, T: numpy::Element, R: Copy + Into<[T; 3]>>(
    py: Python<'py>,
    rows: &[R],
) -> Bound<'py, PyArray2<T>> {
    let flat: Vec<T> = rows.iter().flat_map(|&row| row.into()).collect();
    Array2::from_shape_vec((rows.len(), 3), flat)
        .expect("n rows of three make an (n, 3) array")
        .into_pyarray(py)
}
