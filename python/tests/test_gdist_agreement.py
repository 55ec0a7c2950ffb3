"""Agreement with gdist (Kirsanov's MMP) to 1e-9 relative: on the shared models when they and
gdist are present, and on generated meshes whenever gdist is."""

from __future__ import annotations

import numpy as np
import pytest

import exact_geodesics as eg
from conftest import MODELS_DIR

gdist = pytest.importorskip(
    "gdist", reason="gdist is not installed: no comparison with Kirsanov's MMP"
)

RELATIVE = 1e-9
MODELS = sorted(MODELS_DIR.glob("*.obj")) if MODELS_DIR.is_dir() else []


def assert_agree(ours: np.ndarray, theirs: np.ndarray, same_reach: bool = True) -> None:
    if same_reach:
        np.testing.assert_array_equal(np.isfinite(ours), np.isfinite(theirs))
    both = np.isfinite(ours) & np.isfinite(theirs)
    scale = np.maximum(np.abs(theirs[both]), np.finfo(float).tiny)
    worst = np.max(np.abs(ours[both] - theirs[both]) / scale, initial=0.0)
    assert worst <= RELATIVE, f"largest relative difference {worst:.3e}"


@pytest.mark.skipif(not MODELS, reason=f"no shared models in {MODELS_DIR}: skipped")
@pytest.mark.parametrize("model", MODELS, ids=lambda p: p.stem)
def test_compute_gdist_agrees_on_the_shared_models(model):
    vertices, triangles = eg.read_mesh(model)
    bowties = any("bowtie" in w for w in eg.GeodesicSolver(vertices, triangles).warnings)
    n = len(vertices)
    for source in (0, n // 2):
        ours = eg.compute_gdist(vertices, triangles, np.array([source]))
        theirs = gdist.compute_gdist(
            vertices, triangles.astype(np.int32), np.array([source], dtype=np.int32)
        )
        if bowties:
            # gdist does not walk through a bowtie vertex; we do, so we reach at least as much
            # and never farther.
            assert np.all(np.isfinite(ours) | ~np.isfinite(theirs))
            reached = np.isfinite(theirs)
            assert np.all(ours[reached] <= theirs[reached] * (1 + RELATIVE))
        else:
            assert_agree(ours, theirs)


def test_compute_gdist_agrees_with_targets_and_several_sources(icosphere):
    vertices, triangles = icosphere
    sources, targets = np.array([0, 40, 99]), np.arange(0, 162, 7)
    ours = eg.compute_gdist(vertices, triangles, sources, targets)
    theirs = gdist.compute_gdist(
        vertices, triangles.astype(np.int32), sources.astype(np.int32), targets.astype(np.int32)
    )
    assert ours.shape == theirs.shape == targets.shape
    assert_agree(ours, theirs)


def test_compute_gdist_is_one_indexed_as_gdist(icosphere):
    vertices, triangles = icosphere
    ours = eg.compute_gdist(vertices, triangles + 1, np.array([3]), is_one_indexed=True)
    theirs = gdist.compute_gdist(
        vertices, (triangles + 1).astype(np.int32), np.array([3], np.int32), is_one_indexed=True
    )
    assert_agree(ours, theirs)


def test_local_gdist_matrix_agrees(icosphere):
    vertices, triangles = icosphere
    ours = eg.local_gdist_matrix(vertices, triangles, 0.5)
    theirs = gdist.local_gdist_matrix(vertices, triangles.astype(np.int32), 0.5)
    assert ours.format == "csc" and ours.shape == theirs.shape
    assert ours.nnz == theirs.nnz
    np.testing.assert_array_equal(ours.indices, theirs.indices)
    np.testing.assert_array_equal(ours.indptr, theirs.indptr)
    np.testing.assert_allclose(ours.data, theirs.data, rtol=RELATIVE, atol=0)


def test_distance_matrix_of_selected_points_agrees(icosphere):
    vertices, triangles = icosphere
    points = np.array([5, 17, 80, 161])
    ours = eg.distance_matrix_of_selected_points(vertices, triangles, points)
    theirs = gdist.distance_matrix_of_selected_points(
        vertices, triangles.astype(np.int32), points.astype(np.int32)
    )
    assert ours.format == "csc" and ours.nnz == theirs.nnz == 12
    np.testing.assert_allclose(ours.toarray(), theirs.toarray(), rtol=RELATIVE, atol=0)
