"""Time one `gdist.compute_gdist` call (Kirsanov's exact MMP) on an OBJ mesh.

Runs inside the benchmark venv (see setup_venv.sh), normally as a subprocess of
bench_vs_gdist.py, so that each measurement gets a fresh process. It loads the
mesh, then measures only the `compute_gdist` call, from one source vertex to all
vertices:

- ``seconds_cpu`` / ``seconds_wall``: ``time.process_time()`` /
  ``time.perf_counter()`` around the call. gdist builds its own mesh
  (adjacency) inside the call, so both include that construction.
- ``rss_before_bytes``: resident set size just before the call.
- ``peak_rss_bytes``: the peak RSS while the call ran, the interpreter, NumPy,
  SciPy and the mesh arrays included; ``rss_increase_bytes`` is that peak minus
  the RSS before the call. On Linux the kernel's high-water mark is reset just
  before the call (``peak_rss_reset``) and read back as ``VmHWM`` from
  /proc/self/status (``peak_rss_method`` says which): ``ru_maxrss`` would not
  do, since it never falls below the high-water mark of the process image
  replaced by exec, i.e. of the parent at the fork. Elsewhere it is
  ``ru_maxrss`` (the peak since the process started).

Unreachable vertices and vertices no face uses come back from gdist as its
``GEODESIC_INF`` (1e100) or as ``inf``; both are written as ``inf``. Distances
go to a text file (one per line, in vertex order, 17 significant digits); the
JSON report goes to stdout.
"""

import argparse
import json
import resource
import sys
import time
from importlib.metadata import version
from pathlib import Path

import gdist
import numpy as np

from common import read_obj

# gdist's GEODESIC_INF is 1e100; anything this large means "not reached".
UNREACHED_THRESHOLD = 1e99


def load_obj(path):
    """The vertices and triangles of an OBJ file (``common.read_obj``), as arrays
    ``(vertices float64 Nx3, triangles int32 Mx3)``; a face index out of range
    is an error."""
    vertices, triangles = read_obj(path)
    vertices = np.asarray(vertices, dtype=np.float64).reshape(-1, 3)
    triangles = np.asarray(triangles, dtype=np.int32).reshape(-1, 3)
    if triangles.size and (triangles.min() < 0 or triangles.max() >= len(vertices)):
        raise ValueError(f"{path}: face index out of range (1..{len(vertices)})")
    return vertices, triangles


def proc_status_bytes(field):
    """A size field of /proc/self/status (``VmRSS``, ``VmHWM``) in bytes; None elsewhere."""
    try:
        with open("/proc/self/status", encoding="ascii") as status:
            for line in status:
                if line.startswith(field + ":"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return None


def reset_peak_rss():
    """Reset the kernel's RSS high-water mark (Linux >= 4.0); True on success."""
    try:
        with open("/proc/self/clear_refs", "w", encoding="ascii") as clear_refs:
            clear_refs.write("5")
        return True
    except OSError:
        return False


def peak_rss(since_reset):
    """``(bytes, method)``: the peak RSS of this process, since the reset if there was one."""
    hwm = proc_status_bytes("VmHWM") if since_reset else None
    if hwm is not None:
        return hwm, "VmHWM"
    maxrss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    return (maxrss if sys.platform == "darwin" else maxrss * 1024), "ru_maxrss"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n", 1)[0])
    parser.add_argument("mesh", type=Path, help="OBJ file")
    parser.add_argument("--source", type=int, default=0, help="0-based source vertex (default 0)")
    parser.add_argument("--distances", type=Path, required=True, help="text file to write the distances to")
    args = parser.parse_args()

    vertices, triangles = load_obj(args.mesh)
    if not 0 <= args.source < len(vertices):
        parser.error(f"--source {args.source} out of range: the mesh has {len(vertices)} vertices")
    sources = np.array([args.source], dtype=np.int32)

    peak_reset = reset_peak_rss()
    rss_before = proc_status_bytes("VmRSS")
    cpu_start = time.process_time()
    wall_start = time.perf_counter()
    distances = gdist.compute_gdist(vertices, triangles, source_indices=sources)
    wall = time.perf_counter() - wall_start
    cpu = time.process_time() - cpu_start
    peak, peak_method = peak_rss(peak_reset)

    distances = np.asarray(distances, dtype=np.float64)
    distances[~(distances < UNREACHED_THRESHOLD)] = np.inf
    if distances.shape != (len(vertices),):
        raise RuntimeError(f"gdist returned {distances.shape} distances for {len(vertices)} vertices")
    args.distances.parent.mkdir(parents=True, exist_ok=True)
    np.savetxt(args.distances, distances, fmt="%.17g")

    report = {
        "mesh": str(args.mesh),
        "source": args.source,
        "vertices": len(vertices),
        "faces": len(triangles),
        "gdist_version": version("gdist"),
        "numpy_version": np.__version__,
        "seconds_cpu": cpu,
        "seconds_wall": wall,
        "rss_before_bytes": rss_before,
        "peak_rss_bytes": peak,
        "peak_rss_reset": peak_reset,
        "peak_rss_method": peak_method,
        "rss_increase_bytes": None if rss_before is None else max(0, peak - rss_before),
        "reached": int(np.isfinite(distances).sum()),
        "distances_path": str(args.distances),
    }
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
