"""Kirsanov's MMP (gdist) rows for Tables 1-2 of `exact-geodesics experiment`.

Runs inside the benchmark venv (see setup_venv.sh), after `experiment table1` and/or `table2`,
from the directory those ran in (their model paths are relative to it):

    .venv/bin/python examples/benchmark/gdist_tables.py DIR [--reference-backend f64]

For every model and source vertex of DIR/table1.json and DIR/table2.json, the model is
normalized into the unit cube exactly as the experiment normalizes it, gdist computes the
distances from the source to every vertex (`compute_gdist`, its own mesh construction included,
timed in wall-clock seconds as our `seconds` are, so that a busy machine slows both alike), and
our CLI's `distance` computes them on the same normalized mesh in the reference backend.
Writes DIR/table1_gdist.{csv,json} and DIR/table2_gdist.{csv,json}, one row per model and
source in the columns of section6_tables.py, which prints the tables merged. gdist gives distances only: its wedge columns are empty. `gen:` models are skipped
(this script reads OBJ files only). Exit status 1 if a model failed (the others still run).
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time
from importlib.metadata import version

import numpy as np

from common import BIN, write_rows
from gdist_scale import distances as gdist_distances
from gdist_scale import unit_cube
from gdist_worker import load_obj
from section6_tables import compare_distances, gdist_row, model_sources, read_rows


def write_obj(path, vertices, triangles):
    """An OBJ file holding `vertices` to the bit (shortest round-trip decimals)."""
    with open(path, "w") as f:
        f.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in vertices.tolist())
        f.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in triangles.tolist())


def our_distances(binary, mesh, source, backend):
    """Our distance from vertex `source` to every vertex of `mesh`, in vertex order."""
    out = subprocess.run(
        [binary, "distance", mesh, "--source", f"v:{source}", "--backend", backend],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.splitlines()
    return [float(line.split(",")[1]) for line in out[1:]]


def measure(binary, model, source, backend, scratch):
    """gdist's time and distances from `source` on `model` normalized, held to ours."""
    vertices, triangles = load_obj(model)
    unit = unit_cube(vertices, triangles)
    normalized = os.path.join(scratch, "unit.obj")
    write_obj(normalized, unit, triangles)
    start = time.perf_counter()
    theirs = gdist_distances(unit, triangles, source)
    seconds = time.perf_counter() - start
    ours = our_distances(binary, normalized, source, backend)
    return seconds, compare_distances(ours, theirs.tolist())


def report(model, source, measured):
    """One line of progress on stderr."""
    seconds, c = measured
    print(
        f"{model} v{source}: gdist {seconds:.3f} s, largest relative difference"
        f" {c['distance_max_relative_difference']}, {c['unreachable']} unreachable,"
        f" {c['reach_differs']} reached by one side only",
        file=sys.stderr,
    )


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", help="the --out DIR of `exact-geodesics experiment table1/table2`")
    parser.add_argument("--reference-backend", default="f64", choices=["f64", "adaptive", "exact"])
    parser.add_argument("--binary", default=BIN)
    args = parser.parse_args()
    print(f"gdist {version('gdist')}, numpy {np.__version__}", file=sys.stderr)
    # (model, source) -> (seconds, comparison), or None when it failed; table2 reuses table1's.
    measured = {}
    with tempfile.TemporaryDirectory() as scratch:
        for name in ("table1", "table2"):
            rows = read_rows(args.dir, name)
            gdist_rows = []
            for model, source in model_sources(rows):
                if model.startswith("gen:"):
                    continue
                if (model, source) not in measured:
                    try:
                        measured[model, source] = measure(
                            args.binary, model, source, args.reference_backend, scratch
                        )
                        report(model, source, measured[model, source])
                    except (OSError, ValueError, subprocess.CalledProcessError) as e:
                        print(f"{model} v{source}: failed: {e}", file=sys.stderr)
                        measured[model, source] = None
                if measured[model, source] is not None:
                    template = next(r for r in rows if r["model"] == model)
                    seconds, comparison = measured[model, source]
                    gdist_rows.append(
                        gdist_row(template, source, seconds, args.reference_backend, comparison)
                    )
            if rows:
                write_rows(args.dir, name + "_gdist", gdist_rows)
    return 1 if None in measured.values() else 0


if __name__ == "__main__":
    sys.exit(main())
