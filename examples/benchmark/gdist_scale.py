"""Observation 3 for Kirsanov's MMP (gdist): do its distances change with the model's scale?

Runs inside the benchmark venv (see setup_venv.sh):

    .venv/bin/python examples/benchmark/gdist_scale.py [--models a,b] [--source V] [--out DIR]

Each model is normalized into the unit cube as `exact-geodesics experiment` does (uniform scale
by the largest side of its bounding box), then multiplied by 10^k for k = -12..12, and gdist
computes the distances from one source vertex at every scale. Each scale is compared with
k = 0 after dividing by 10^k: the largest relative difference, how many vertices differ by
more than 1e-9 relative, and how many become unreachable (gdist's 1e100). gdist gives
distances only (no window counts), so this is the part of Observation 3's scale test that
can be asked of it; `exact-geodesics experiment observation3` asks the rest of our backends.

Writes DIR/gdist_scale.csv and DIR/gdist_scale.json and prints a summary per model.
"""

import argparse
import os
import sys

import gdist
import numpy as np

from gdist_worker import UNREACHED_THRESHOLD, load_obj
from common import MODELS, PAPER_TABLE1, ROOT, write_rows

DEFAULT_MODELS = PAPER_TABLE1 + ["spot"]


def unit_cube(vertices, triangles):
    """The vertices translated and scaled as `exact_geodesics::experiments::normalize_to_unit_cube`
    does, to the same bits: the bounding box of the vertices that faces use starts at the
    origin, and every coordinate is divided by its largest side."""
    used = vertices[np.unique(triangles)]
    low = used.min(axis=0)
    side = (used.max(axis=0) - low).max()
    return (vertices - low) / side


def distances(vertices, triangles, source):
    d = gdist.compute_gdist(
        vertices, triangles, source_indices=np.array([source], dtype=np.int32)
    )
    return np.where(d >= UNREACHED_THRESHOLD, np.inf, d)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--models", default=",".join(DEFAULT_MODELS))
    parser.add_argument("--source", type=int, default=0)
    parser.add_argument("--out", default=os.path.join(ROOT, "bench-results"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for name in [m for m in args.models.split(",") if m]:
        path = os.path.join(MODELS, name + ".obj")
        if not os.path.exists(path):
            print(f"notice: {path} absent, skipped", file=sys.stderr)
            continue
        vertices, triangles = load_obj(path)
        unit = unit_cube(vertices, triangles)
        base = distances(unit, triangles, args.source)
        reached = np.isfinite(base) & (base > 0)
        for k in range(-12, 13):
            scale = 10.0**k
            d = distances(unit * scale, triangles, args.source) / scale
            both = reached & np.isfinite(d)
            relative = np.abs(d[both] - base[both]) / base[both]
            rows.append(
                {
                    "model": name,
                    "k": k,
                    "scale": scale,
                    "vertices": len(base),
                    "reached_at_unit_scale": int(np.isfinite(base).sum()),
                    "newly_unreachable": int((np.isfinite(base) & ~np.isfinite(d)).sum()),
                    "max_relative_difference": float(relative.max()) if both.any() else 0.0,
                    "vertices_off_by_1e-9": int((relative > 1e-9).sum()),
                }
            )
        worst = max((r for r in rows if r["model"] == name), key=lambda r: r["max_relative_difference"])
        print(
            f"{name:<34} worst at 10^{worst['k']:>3}: relative {worst['max_relative_difference']:.2e},"
            f" {worst['vertices_off_by_1e-9']} vertices off by 1e-9,"
            f" {worst['newly_unreachable']} unreachable"
        )
    write_rows(args.out, "gdist_scale", rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
