"""pygeodesic's class on this library: the calls its users make, with answers derived by hand
on the unit cube (opposite corners sqrt 5 apart, over two faces unfolded into a 1 x 2 rectangle)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import exact_geodesics as eg
from exact_geodesics import geodesic


@pytest.fixture
def cube():
    return eg.generate_mesh("cube")


def far_corner(vertices, v):
    # The corner opposite v: every coordinate flipped.
    target = 1.0 - vertices[v]
    return int(np.flatnonzero(np.all(np.isclose(vertices, target), axis=1))[0])


def test_distance_and_path_between_opposite_corners(cube):
    vertices, faces = cube
    geoalg = geodesic.PyGeodesicAlgorithmExact(vertices, faces)
    target = far_corner(vertices, 0)
    distance, path = geoalg.geodesicDistance(0, target)
    assert math.isclose(distance, math.sqrt(5), rel_tol=1e-12)
    assert path.shape[1] == 3
    np.testing.assert_allclose(path[0], vertices[target])
    np.testing.assert_allclose(path[-1], vertices[0])
    length = np.linalg.norm(np.diff(path, axis=0), axis=1).sum()
    assert math.isclose(length, math.sqrt(5), rel_tol=1e-12)


def test_distances_from_two_sources_with_best_source(cube):
    vertices, faces = cube
    a = 0
    b = far_corner(vertices, a)
    geoalg = eg.PyGeodesicAlgorithmExact(vertices, faces.astype(np.int32))
    distances, best = geoalg.geodesicDistances(np.array([a, b], dtype=np.uint16))
    assert distances[a] == 0.0 and distances[b] == 0.0
    # Every other corner shares an edge with one of the two: distance 1.
    others = [v for v in range(8) if v not in (a, b)]
    np.testing.assert_allclose(distances[others], 1.0, rtol=1e-12)
    assert best[a] == 0 and best[b] == 1
    d, s = geoalg.geodesicDistances([a], target_indices=[b, a], max_distance=1e100)
    np.testing.assert_allclose(d, [math.sqrt(5), 0.0], rtol=1e-12)
    np.testing.assert_array_equal(s, [0, 0])
    d, s = geoalg.geodesicDistances([a], target_indices=[b], max_distance=1.5)
    assert np.isinf(d[0]) and s[0] == -1


def test_errors_raise_instead_of_returning_none(cube):
    vertices, faces = cube
    geoalg = geodesic.PyGeodesicAlgorithmExact(vertices, faces, backend="exact")
    with pytest.raises(ValueError):
        geoalg.geodesicDistance(0, 99)
    with pytest.raises(ValueError):
        geoalg.geodesicDistances([0], target_indices=[8])
