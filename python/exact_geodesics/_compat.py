"""The functions of the ``gdist`` package (Kirsanov's MMP), with its arguments and results.

Differences from gdist, all deliberate: indices of any integer dtype; ``inf`` for every vertex
that is unreachable or farther than ``max_distance``; a point repeated in
``distance_matrix_of_selected_points`` counts once; the matrices are computed on every core.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse

from ._native import GeodesicSolver


def _solver(vertices, triangles, is_one_indexed: bool) -> GeodesicSolver:
    return GeodesicSolver(vertices, triangles, backend="f64", is_one_indexed=is_one_indexed)


def _max_distance(max_distance: float) -> float | None:
    # gdist's default is its own infinity, 1e100; both mean no limit.
    return None if max_distance >= 1e100 else max_distance


def compute_gdist(
    vertices,
    triangles,
    source_indices=None,
    target_indices=None,
    max_distance: float = np.inf,
    is_one_indexed: bool = False,
) -> np.ndarray:
    """Geodesic distance from the nearest of ``source_indices`` to each of ``target_indices``.

    Args:
        vertices: (n, 3) coordinates (converted to float64).
        triangles: (m, 3) vertex indices, any integer dtype (1-based if ``is_one_indexed``).
        source_indices: source vertices, any integer dtype; default ``[0]``.
        target_indices: target vertices, any integer dtype; default every vertex.
        max_distance: stop the propagation there; farther vertices are at ``inf``.
        is_one_indexed: whether ``triangles`` count vertices from 1 (sources and targets are
            0-based, as in gdist).

    Returns:
        float64 array of ``len(target_indices)`` distances (``n`` without targets), ``inf``
        where unreachable.

    Raises:
        ValueError: for a mesh the library refuses or an index out of range.
    """
    solver = _solver(vertices, triangles, is_one_indexed)
    sources = np.zeros(1, dtype=np.int64) if source_indices is None else source_indices
    distances, _ = solver.vertex_distances(sources, max_distance=_max_distance(max_distance))
    if target_indices is None:
        return distances
    return distances[_vertex_indices(target_indices, solver.vertex_count, "target_indices")]


def local_gdist_matrix(
    vertices,
    triangles,
    max_distance: float = np.inf,
    is_one_indexed: bool = False,
) -> scipy.sparse.csc_matrix:
    """Distances from every vertex to every vertex within ``max_distance`` of it.

    Returns:
        ``scipy.sparse.csc_matrix`` of shape (n, n): entry ``(i, j)`` is the distance from
        vertex ``i`` to vertex ``j``, stored where it is finite, non-zero and within
        ``max_distance``.
    """
    solver = _solver(vertices, triangles, is_one_indexed)
    data, rows, columns = solver.local_distances(_max_distance(max_distance))
    n = solver.vertex_count
    return scipy.sparse.csc_matrix((data, (rows, columns)), shape=(n, n))


def distance_matrix_of_selected_points(
    vertices,
    triangles,
    points,
    max_distance: float = np.inf,
    is_one_indexed: bool = False,
) -> scipy.sparse.csc_matrix:
    """Pairwise geodesic distances among the vertices ``points``.

    Returns:
        ``scipy.sparse.csc_matrix`` of shape (n, n) holding, for every pair of distinct points
        ``p`` before ``q`` in ``points``, the distance from ``p`` to ``q`` at ``(p, q)`` and at
        ``(q, p)`` (``inf`` if ``q`` is unreachable from ``p`` or farther than
        ``max_distance``).
    """
    solver = _solver(vertices, triangles, is_one_indexed)
    n = solver.vertex_count
    selected = _vertex_indices(points, n, "points")
    # A repeated point counts once, at its first place.
    _, first = np.unique(selected, return_index=True)
    selected = selected[np.sort(first)]
    k = len(selected)
    if k < 2:
        return scipy.sparse.csc_matrix((n, n), dtype=np.float64)
    matrix = solver.distance_matrix(
        selected[:-1], targets=selected, max_distance=_max_distance(max_distance)
    )
    # Row i (every point but the last) against the points after it.
    i, j = np.triu_indices(k - 1, 1, m=k)
    distances = matrix[i, j]
    rows = np.concatenate([selected[i], selected[j]])
    columns = np.concatenate([selected[j], selected[i]])
    return scipy.sparse.csc_matrix(
        (np.concatenate([distances, distances]), (rows, columns)), shape=(n, n)
    )


def _vertex_indices(indices, n: int, what: str) -> np.ndarray:
    """``indices`` as an int64 array of vertices of the mesh (any integer dtype)."""
    array = np.asarray(indices)
    if array.size == 0:
        return np.zeros(0, dtype=np.int64)
    if array.dtype.kind not in "iu":
        raise ValueError(f"{what} must be integers (any integer dtype), not {array.dtype}")
    bad = (array < 0) | (array >= n)
    if bad.any():
        raise ValueError(
            f"{what}: vertex {array[bad].flat[0]} is out of range: the mesh has {n} vertices"
        )
    return array.astype(np.int64).ravel()
