"""Shared meshes and helpers of the Python test suite."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

import exact_geodesics as eg

#: The shared public models (never copied into the repository): ``$EXACT_GEODESICS_MODELS``,
#: or ``../shared/models`` from the repository root.
MODELS_DIR = Path(
    os.environ.get(
        "EXACT_GEODESICS_MODELS",
        Path(__file__).resolve().parents[2].parent / "shared" / "models",
    )
)


@pytest.fixture(scope="session")
def icosphere():
    """An icosphere of 162 vertices and 320 triangles."""
    return eg.generate_mesh("icosphere:2")


@pytest.fixture(scope="session")
def two_components():
    """Two separate triangles and a vertex no face uses (vertex 6)."""
    vertices = np.array(
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 5, 5], [6, 5, 5], [5, 6, 5], [9, 9, 9]],
        dtype=np.float64,
    )
    triangles = np.array([[0, 1, 2], [3, 4, 5]], dtype=np.int32)
    return vertices, triangles


def faces_of(solver: eg.GeodesicSolver, simplex) -> set[int]:
    """The faces containing a simplex ``(kind, index, parameters)``."""
    kind, index, _ = simplex
    triangles = solver.triangles
    if kind == "face":
        return {index}
    if kind == "vertex":
        return set(np.nonzero((triangles == index).any(axis=1))[0].tolist())
    a, b = solver.edges[index]
    return set(
        np.nonzero((triangles == a).any(axis=1) & (triangles == b).any(axis=1))[0].tolist()
    )


def position_of(solver: eg.GeodesicSolver, simplex) -> np.ndarray:
    """The point in space named by ``(kind, index, parameters)``."""
    kind, index, parameters = simplex
    vertices = solver.vertices
    if kind == "vertex":
        return vertices[index]
    if kind == "edge":
        a, b = solver.edges[index]
        (t,) = parameters
        return vertices[a] + t * (vertices[b] - vertices[a])
    corners = vertices[solver.triangles[index]]
    return np.asarray(parameters) @ corners
