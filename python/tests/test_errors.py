"""Every bad input raises ValueError with the library's message: never a print, never None."""

from __future__ import annotations

import numpy as np
import pytest

import exact_geodesics as eg

SQUARE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64)
TWO = np.array([[0, 1, 2], [0, 2, 3]])


@pytest.mark.parametrize(
    "vertices, triangles, message",
    [
        (SQUARE[:, :2], TWO, r"vertices must be an \(n, 3\) array"),
        (SQUARE, TWO[:, :2], r"triangles must be an \(m, 3\) array"),
        (SQUARE, TWO.astype(float), "triangles must be integers"),
        (SQUARE, TWO.astype(bool), "triangles must be integers"),
        (SQUARE, -TWO, "index -1 is out of range"),
        (SQUARE, TWO + 2**33, "out of range"),
        (np.where(SQUARE == 1, np.nan, SQUARE), TWO, "non-finite coordinate"),
        (SQUARE, TWO + 2, "refers to vertex 4, but the mesh has 4 vertices"),
        (SQUARE, np.array([[0, 1, 1]]), "repeats vertex 1"),
        (SQUARE, np.zeros((0, 3), dtype=np.int32), "no faces"),
        ([["x", "y", "z"]], TWO, "could not convert"),
    ],
    ids=[
        "vertices-shape", "triangles-shape", "float-triangles", "bool-triangles", "negative",
        "beyond-u32", "nan", "index-out-of-range", "repeated-vertex",
        "no-faces", "not-numbers",
    ],
)
def test_bad_meshes_are_refused(vertices, triangles, message):
    with pytest.raises(ValueError, match=message):
        eg.GeodesicSolver(vertices, triangles)
    with pytest.raises(ValueError, match=message):
        eg.compute_gdist(vertices, triangles)


def test_bad_solver_options_are_refused():
    with pytest.raises(ValueError, match="unknown backend"):
        eg.GeodesicSolver(SQUARE, TWO, backend="float")
    with pytest.raises(ValueError, match="exact backend only"):
        eg.GeodesicSolver(SQUARE, TWO, precision_cap=512)
    with pytest.raises(ValueError, match="precision cap 64 is out of range"):
        eg.GeodesicSolver(SQUARE, TWO, backend="exact", precision_cap=64)
    with pytest.raises(ValueError, match="index 0 in a one-indexed mesh"):
        eg.GeodesicSolver(SQUARE, TWO, is_one_indexed=True)


@pytest.mark.parametrize(
    "sources, message",
    [
        ([], "at least one source"),
        (4, "vertex 4 is out of range: the mesh has 4 vertices"),
        (-1, "out of range"),
        ([0, 1.5], "a vertex index must be an integer"),
        (np.array([0.0]), "sources must be integers"),
        (("edge", 0, 1, 1.5), r"edge parameter 1.5 is not in \[0, 1\]"),
        (("edge", 1, 3, 0.5), "vertices 1 and 3 are not joined by an edge"),
        (("edge", 9, (0.5,)), "edge 9 is out of range"),
        (("face", 2, (1, 1, 1)), "face 2 is out of range"),
        (("face", 0, (1, -1, 1)), "must be finite, non-negative and not all zero"),
        (("face", 0, (0, 0, 0)), "must be finite, non-negative and not all zero"),
        (("face", 0, (1, 1)), "a point is"),
        (("banana", 0), "a point is"),
        ("0", "a vertex index"),
    ],
    ids=str,
)
def test_bad_sources_are_refused(sources, message):
    solver = eg.GeodesicSolver(SQUARE, TWO)
    with pytest.raises(ValueError, match=message):
        solver.propagate(sources)
    if not (isinstance(sources, list) and not sources):  # no sources: an empty matrix
        with pytest.raises(ValueError, match=message):
            solver.distance_matrix(sources, threads=1)


@pytest.mark.parametrize("max_distance", [-1.0, float("nan")])
def test_bad_max_distance_is_refused(max_distance):
    solver = eg.GeodesicSolver(SQUARE, TWO)
    with pytest.raises(ValueError, match="max_distance must be a non-negative number"):
        solver.propagate(0, max_distance=max_distance)
    with pytest.raises(ValueError, match="max_distance must be a non-negative number"):
        eg.compute_gdist(SQUARE, TWO, max_distance=max_distance)


def test_bad_queries_are_refused(two_components):
    vertices, triangles = two_components
    field = eg.GeodesicSolver(vertices, triangles).propagate(0)
    with pytest.raises(ValueError, match="vertex 7 is out of range"):
        field.distance_at(7)
    with pytest.raises(ValueError, match="face 5 is out of range"):
        field.path(("face", 5, (1, 1, 1)))
    with pytest.raises(ValueError, match="unreachable from every source"):
        field.path(4)
    with pytest.raises(ValueError, match="unreachable from every source"):
        field.path(6)
    with pytest.raises(ValueError, match="edge 6 is out of range: the mesh has 6 edges"):
        field.wedges(6)
    with pytest.raises(ValueError, match="vertices 0 and 4 are not joined by an edge"):
        field.wedges((0, 4))
    with pytest.raises(ValueError, match="vertex 9 is out of range"):
        field.wedges((0, 9))
    with pytest.raises(ValueError, match="an edge is an edge index or a pair"):
        field.wedges("0-1")


def test_bad_matrix_arguments_are_refused():
    solver = eg.GeodesicSolver(SQUARE, TWO)
    with pytest.raises(ValueError, match="threads must be at least 1"):
        solver.distance_matrix([0], threads=0)
    with pytest.raises(ValueError, match="targets: vertex 4 is out of range"):
        solver.distance_matrix([0], targets=[4])
    with pytest.raises(ValueError, match="target_indices: vertex 4 is out of range"):
        eg.compute_gdist(SQUARE, TWO, [0], [4])
    with pytest.raises(ValueError, match="target_indices: vertex -1 is out of range"):
        eg.compute_gdist(SQUARE, TWO, [0], [-1])
    with pytest.raises(ValueError, match="target_indices must be integers"):
        eg.compute_gdist(SQUARE, TWO, [0], [1.0])
    with pytest.raises(ValueError, match="points: vertex 9 is out of range"):
        eg.distance_matrix_of_selected_points(SQUARE, TWO, [0, 9])
    with pytest.raises(ValueError, match="max_distance must be a non-negative number"):
        eg.local_gdist_matrix(SQUARE, TWO, -1.0)


def test_bad_mesh_sources_are_refused(tmp_path):
    with pytest.raises(ValueError, match="missing.obj"):
        eg.read_mesh(tmp_path / "missing.obj")
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")
    with pytest.raises(ValueError, match="bad.obj"):
        eg.read_mesh(bad)
    with pytest.raises(ValueError, match="unknown format|extension"):
        eg.read_mesh(tmp_path / "mesh.stl")
    with pytest.raises(ValueError):
        eg.generate_mesh("dodecahedron")
    with pytest.raises(ValueError):
        eg.generate_mesh("icosphere:99")


def test_a_non_manifold_edge_is_crossed_not_refused():
    """Three pages on the diagonal (0, 2) of the unit square, the third hanging below it: from
    vertex 1 the way to its tip crosses the spine at (0.5, 0.5, 0), where both feet are."""
    vertices = np.vstack([SQUARE, [[0.5, 0.5, -1]]])
    triangles = np.array([[0, 2, 1], [0, 2, 3], [0, 2, 4]])
    d = eg.compute_gdist(vertices, triangles, source_indices=np.array([1]))
    assert abs(d[3] - 2**0.5) < 1e-12
    assert abs(d[4] - (1 + 0.5**0.5)) < 1e-12
