"""examples/dask_matrix.py on a LocalCluster of two worker processes with a small mesh."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

import exact_geodesics as eg

distributed = pytest.importorskip("dask.distributed", reason="dask.distributed is not installed")
zarr = pytest.importorskip("zarr", reason="zarr is not installed")

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "dask_matrix.py"


@pytest.fixture(scope="module")
def example():
    spec = importlib.util.spec_from_file_location("dask_matrix", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    with cluster, distributed.Client(cluster) as client:
        yield client


def test_rows_written_by_the_cluster_are_the_solvers(example, client, tmp_path):
    vertices, triangles = eg.generate_mesh("icosphere:2")
    out = str(tmp_path / "matrix.zarr")
    sources = np.arange(0, 162, 3)
    matrix, reports = example.distance_matrix_to_zarr(
        client, vertices, triangles, out, sources=sources, chunk=10, max_distance=2.0
    )
    assert len(reports) == 6 and sum(r["rows"] for r in reports) == len(sources)
    assert matrix.shape == (len(sources), len(vertices))
    assert list(matrix.attrs["sources"]) == sources.tolist()
    expected = eg.GeodesicSolver(vertices, triangles).distance_matrix(sources, max_distance=2.0)
    np.testing.assert_array_equal(matrix[:], expected)
    assert np.isinf(matrix[:]).any() and not np.isnan(matrix[:]).any()


def test_command_line_on_a_local_cluster(example, tmp_path, capsys):
    out = str(tmp_path / "all.zarr")
    assert example.main(["gen:icosphere:1", out, "--workers", "2", "--chunk", "16"]) == 0
    assert "42 x 42 distances in 3 tasks" in capsys.readouterr().out
    matrix = zarr.open_array(store=out, mode="r")[:]
    np.testing.assert_allclose(matrix, matrix.T, rtol=1e-9)
    assert np.all(np.diag(matrix) == 0)
