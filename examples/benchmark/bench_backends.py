#!/usr/bin/env python3
"""Benchmark the three backends (f64, adaptive, exact) of the exact-geodesics CLI.

Each (mesh, backend) pair runs ``exact-geodesics stats MESH --source v:0 --backend B`` in a
fresh process, REPEAT times, the backends taking turns so that a slow spell of a shared machine
hits them alike. It keeps the fastest ``propagation_seconds`` and its decision counters, and the
ratio to f64 both of the fastest runs and as the median over rounds of each round's ratio (the
steadier figure on a noisy machine). Meshes: the paper's Example 4 and a 1,012-face planar grid with exact symmetries
(generated, always present), and stanford_bunny, rocker_arm, fandisk and icosphere5 from
../shared/models when that folder exists (f64 and adaptive only: exact is not meant for 70k
faces).

Writes OUT/backends.json and OUT/backends.csv and prints a table; exit status 1 if a run fails.
Needs only the standard library; build the CLI first (cargo build --release).
"""

import argparse
import json
import os
import subprocess
import sys

from common import BIN, MODELS, ROOT, write_rows



def cases():
    yield "paper-example-4", "gen:paper-example-4", "v:2", ["f64", "adaptive", "exact"]
    yield "grid-22x23 (1012 faces)", "gen:grid:22,23", "v:0", ["f64", "adaptive", "exact"]
    for name in ["stanford_bunny", "rocker_arm", "fandisk", "icosphere5"]:
        path = os.path.join(MODELS, name + ".obj")
        if os.path.exists(path):
            yield name, path, "v:0", ["f64", "adaptive"]
        else:
            print(f"notice: {path} absent, skipped", file=sys.stderr)


def run(mesh, source, backend):
    out = subprocess.run(
        [BIN, "stats", mesh, "--source", source, "--backend", backend],
        capture_output=True,
        text=True,
        check=True,
    )
    return json.loads(out.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "bench-results"))
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows, failed = [], False
    for name, mesh, source, backends in cases():
        runs = {b: [] for b in backends}
        try:
            for _ in range(args.repeat):
                for backend in backends:
                    runs[backend].append(run(mesh, source, backend))
        except subprocess.CalledProcessError as e:
            print(f"{name}: failed: {e.stderr.strip()}", file=sys.stderr)
            failed = True
            continue
        base = min(r["propagation_seconds"] for r in runs["f64"])
        for backend in backends:
            best = min(runs[backend], key=lambda r: r["propagation_seconds"])
            seconds = best["propagation_seconds"]
            paired = sorted(
                r["propagation_seconds"] / f["propagation_seconds"]
                for r, f in zip(runs[backend], runs["f64"])
            )
            d = best["backend_decisions"]
            rows.append(
                {
                    "mesh": name,
                    "faces": best["faces"],
                    "backend": backend,
                    "propagation_seconds": seconds,
                    "ratio_to_f64": seconds / base,
                    "ratio_to_f64_median_of_rounds": paired[len(paired) // 2],
                    "wedges": best["wedges"],
                    "decisions": d["decisions"],
                    "by_filter": d["by_filter"],
                    "by_exact_stage": d["by_refinement"],
                    "certified_zeros": d["certified_zeros"],
                    "uncertified": d["uncertified"],
                }
            )
            r = rows[-1]
            print(
                f"{name:<26} {backend:<9} {seconds:>9.4f}s  x{r['ratio_to_f64']:<5.2f}"
                f" (rounds x{r['ratio_to_f64_median_of_rounds']:<5.2f}) wedges {r['wedges']:>8}"
                f"  filter {r['by_filter']:>8}  exact {r['by_exact_stage']:>7}"
                f"  zeros {r['certified_zeros']:>6}  uncertified {r['uncertified']}"
            )
    write_rows(args.out, "backends", rows)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
