#!/usr/bin/env python3
"""Certification of the exact backend on float meshes (issue 11): for each mesh, one run of
``exact-geodesics stats MESH --source v:0 --backend exact`` on one core, with its time and how
every decision was settled (filter, refinement; zeros by structure, rational value, normal form,
separation bound; uncertified, with the places of the first of them).

Meshes: generated icospheres (levels 1-3, exact float symmetries) and the models of
../shared/models and ../shared/models/paper-table1 when present (a notice otherwise). A run past
--timeout is killed and reported as such. Writes OUT/exact.json and OUT/exact.csv and prints a
table; exit status 1 if a run failed (other than by the timeout). Needs only the standard
library; build the CLI first (cargo build --release).
"""

import argparse
import json
import os
import subprocess
import sys
import time

from common import BIN, MODELS, PAPER_TABLE1, ROOT, write_rows

DEFAULT_MODELS = ["unit_sphere", "spot", "teapot_welded", "cad_featuretype", "fandisk"]
DEFAULT_MODELS += PAPER_TABLE1


def cases(models):
    for level in (1, 2, 3):
        yield f"icosphere:{level}", f"gen:icosphere:{level}"
    for name in models:
        path = os.path.join(MODELS, name + ".obj")
        if os.path.exists(path):
            yield name, path
        else:
            print(f"notice: {path} absent, skipped", file=sys.stderr)


def run(mesh, timeout):
    """The stats JSON of one exact run, or None past the timeout."""
    # One core: the engine is sequential, and taskset keeps the OS from spreading it.
    command = [BIN, "stats", mesh, "--source", "v:0", "--backend", "exact"]
    if os.path.exists("/usr/bin/taskset"):
        command = ["taskset", "-c", "0"] + command
    try:
        out = subprocess.run(command, capture_output=True, text=True, timeout=timeout, check=True)
    except subprocess.TimeoutExpired:
        return None
    return json.loads(out.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "bench-results"))
    parser.add_argument("--timeout", type=float, default=600.0, help="seconds per run")
    parser.add_argument(
        "--models",
        default=",".join(DEFAULT_MODELS),
        help="model names under ../shared/models, comma-separated",
    )
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows, failed = [], False
    for name, mesh in cases([m for m in args.models.split(",") if m]):
        started = time.monotonic()
        try:
            stats = run(mesh, args.timeout)
        except (subprocess.CalledProcessError, json.JSONDecodeError) as e:
            print(f"{name}: failed: {getattr(e, 'stderr', e)}", file=sys.stderr)
            failed = True
            continue
        if stats is None:
            rows.append({"mesh": name, "timed_out_after_seconds": args.timeout})
            print(f"{name:<34} timed out after {args.timeout:.0f} s")
            continue
        d = stats["backend_decisions"]
        first = d["uncertified_sites"][0]["site"]["what"] if d["uncertified_sites"] else ""
        rows.append(
            {
                "mesh": name,
                "faces": stats["faces"],
                "propagation_seconds": stats["propagation_seconds"],
                "process_seconds": time.monotonic() - started,
                "pseudo_source_emissions": stats["pseudo_source_emissions"],
                "decisions": d["decisions"],
                "by_filter": d["by_filter"],
                "by_refinement": d["by_refinement"],
                "zeros_by_structure": d["zeros_by_structure"],
                "zeros_by_rational_value": d["zeros_by_rational_value"],
                "zeros_by_normal_form": d["zeros_by_normal_form"],
                "zeros_by_separation_bound": d["zeros_by_separation_bound"],
                "uncertified": d["uncertified"],
                "first_uncertified_site": first,
            }
        )
        r = rows[-1]
        print(
            f"{name:<34} {r['faces']:>6} faces {r['propagation_seconds']:>8.2f} s"
            f"  decisions {r['decisions']:>9}  structure {r['zeros_by_structure']:>7}"
            f"  normal form {r['zeros_by_normal_form']:>5}  uncertified {r['uncertified']}"
        )
    write_rows(args.out, "exact", rows)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
