"""A geodesic distance matrix on a Dask cluster, written row block by row block to Zarr.

All-pairs matrices outgrow one machine: n vertices need n propagations and n * n * 8 bytes.
Here the source vertices are split into chunks; each chunk is one task on a
``dask.distributed`` cluster, which builds the solver from the mesh (sent once to every worker),
propagates from each of its sources (``GeodesicSolver.distance_matrix``) and writes its rows
into the Zarr array. Each task writes whole Zarr chunks of its own, so tasks never write the
same chunk and need no lock; a task that is retried rewrites the same rows.

Output: a Zarr array of shape (len(sources), n), float64, ``inf`` where unreachable, with the
source vertex of every row in its attributes (``sources``), the backend and ``max_distance``.

On one machine (a LocalCluster with one single-threaded worker per core)::

    python examples/dask_matrix.py gen:icosphere:3 matrix.zarr --chunk 64

On a real cluster:

1. Install the package on every worker and on the client, built from the same commit
   (``pip install ./python``); this script need not be installed: the client uploads it to
   the workers (``Client.upload_file``).
   Install zarr, and fsspec with the matching filesystem (``s3fs``, ``gcsfs``) for an object
   store.
2. Start a scheduler and workers, one thread per worker process (a propagation is
   single-threaded and holds no GIL, but one process per core keeps memory per task bounded)::

       dask scheduler                                   # on the scheduler host
       dask worker tcp://SCHEDULER:8786 --nworkers auto --nthreads 1   # on every worker host

3. Run the client with the mesh on the client's disk (it is read there and sent to the
   workers) and an output every worker can write to, a shared filesystem path or an object
   store URL::

       python dask_matrix.py bunny.obj s3://bucket/bunny-distances.zarr \\
           --scheduler tcp://SCHEDULER:8786 --chunk 128 --max-distance 0.1

A task's memory is about ``chunk * n * 8`` bytes of rows plus one propagation; pick ``--chunk``
so that a few hundred tasks keep every worker busy. ``--max-distance`` bounds each
propagation (the rows hold ``inf`` beyond it), which is what makes very large meshes feasible.
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np

import exact_geodesics as eg


def compute_rows(
    vertices: np.ndarray,
    triangles: np.ndarray,
    sources: np.ndarray,
    first_row: int,
    out: str,
    backend: str,
    max_distance: float | None,
) -> dict:
    """One task: the rows of ``sources`` (rows ``first_row`` onwards of ``out``)."""
    import zarr

    started = time.perf_counter()
    solver = eg.GeodesicSolver(vertices, triangles, backend=backend)
    rows = solver.distance_matrix(sources, max_distance=max_distance, threads=1)
    zarr.open_array(store=out, mode="r+")[first_row : first_row + len(sources), :] = rows
    return {
        "first_row": first_row,
        "rows": len(sources),
        "seconds": time.perf_counter() - started,
    }


def distance_matrix_to_zarr(
    client,
    vertices: np.ndarray,
    triangles: np.ndarray,
    out: str,
    sources: np.ndarray | None = None,
    chunk: int = 64,
    backend: str = "f64",
    max_distance: float | None = None,
):
    """Computes the rows of ``sources`` (default: every vertex) on the cluster of ``client``
    into a new Zarr array at ``out``; returns the array and one report per task."""
    import zarr
    from dask.distributed import as_completed

    n = len(vertices)
    sources = np.arange(n) if sources is None else np.asarray(sources)
    if chunk < 1:
        raise ValueError("chunk must be at least 1")
    # Check the mesh here, where an error is easy to read, before any task starts.
    eg.GeodesicSolver(vertices, triangles, backend=backend)
    matrix = zarr.open_array(
        store=out,
        mode="w",
        shape=(len(sources), n),
        chunks=(chunk, n),
        dtype="f8",
        fill_value=np.nan,
    )
    matrix.attrs.update(
        {
            "sources": [int(s) for s in sources],
            "backend": backend,
            # JSON has no infinity: no limit is null.
            "max_distance": max_distance if max_distance and np.isfinite(max_distance) else None,
        }
    )
    # Workers have exact_geodesics installed but not this file: send it, so that they can
    # import compute_rows (when this file runs as a script, tasks carry it by value anyway).
    client.upload_file(__file__)
    mesh = client.scatter([vertices, triangles], broadcast=True)
    tasks = [
        client.submit(
            compute_rows,
            *mesh,
            sources[start : start + chunk],
            start,
            out,
            backend,
            max_distance,
            pure=False,
        )
        for start in range(0, len(sources), chunk)
    ]
    reports = [task.result() for task in as_completed(tasks)]
    return zarr.open_array(store=out, mode="r"), sorted(reports, key=lambda r: r["first_row"])


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh", help="OBJ, OFF or PLY file, or gen:SHAPE (e.g. gen:icosphere:3)")
    parser.add_argument("out", help="output Zarr array: a path or a URL (s3://...)")
    parser.add_argument("--scheduler", help="address of a running scheduler (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, default=None, help="LocalCluster workers (default: one per core)")
    parser.add_argument("--chunk", type=int, default=64, help="sources per task (default 64)")
    parser.add_argument("--sources", type=int, default=None, help="the first N vertices only (default: all)")
    parser.add_argument("--backend", default="f64", choices=["f64", "adaptive", "exact"])
    parser.add_argument("--max-distance", type=float, default=None)
    args = parser.parse_args(argv)

    from dask.distributed import Client, LocalCluster

    if args.mesh.startswith("gen:"):
        vertices, triangles = eg.generate_mesh(args.mesh[4:])
    else:
        vertices, triangles = eg.read_mesh(args.mesh)
    sources = None if args.sources is None else np.arange(min(args.sources, len(vertices)))

    if args.scheduler:
        client = Client(args.scheduler)
    else:
        client = Client(LocalCluster(n_workers=args.workers, threads_per_worker=1))
    with client:
        started = time.perf_counter()
        matrix, reports = distance_matrix_to_zarr(
            client,
            vertices,
            triangles,
            args.out,
            sources=sources,
            chunk=args.chunk,
            backend=args.backend,
            max_distance=args.max_distance,
        )
        seconds = time.perf_counter() - started
    task_seconds = sum(r["seconds"] for r in reports)
    print(
        f"{matrix.shape[0]} x {matrix.shape[1]} distances in {len(reports)} tasks: "
        f"{seconds:.1f} s wall, {task_seconds:.1f} s in tasks -> {args.out}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
