#!/usr/bin/env python3
"""Time `exact-geodesics matrix` on 1 and on N threads, taking turns, and check rows of the
matrix against single-source `exact-geodesics distance` runs, bit for bit.

    python3 examples/benchmark/bench_matrix.py [--model stanford_bunny] [--vertices 200]
        [--seed 1] [--threads 2] [--repeats 1] [--check-rows 4] [--binary PATH]
        [--timeout 3600] [--out bench-results]

Writes OUT/matrix_runs.{json,csv} (one row per run: threads, wall seconds, user and system CPU
seconds, peak RSS, by GNU time where it is installed: `rss_method`),
OUT/matrix_checks.{json,csv} (the rows checked) and OUT/matrix_summary.{json,csv} (the
speedup of the median wall times, whether the parallel matrix equals the serial one byte for
byte). Standard library only. Exit status 1 if a checked
row or the parallel matrix differs.
"""

import argparse
import os
import statistics
import struct
import subprocess
import sys
import tempfile

from common import BIN, MODELS, ROOT, RSS_METHOD, RunError, run_measured, write_rows


def read_npy(path):
    """A little-endian float64 .npy file (format 1.0): (rows, columns, values)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x93NUMPY\x01\x00":
        sys.exit(f"{path}: not an .npy file of format 1.0")
    (header_len,) = struct.unpack("<H", data[8:10])
    header = data[10 : 10 + header_len].decode("ascii")
    shape = header.split("'shape': (")[1].split(")")[0]
    rows, columns = (int(x) for x in shape.split(","))
    values = struct.unpack(f"<{rows * columns}d", data[10 + header_len :])
    return rows, columns, values


def single_source(binary, mesh, vertex):
    """Distances of every vertex from `vertex`, by `exact-geodesics distance`."""
    out = subprocess.run(
        [binary, "distance", mesh, "--source", f"v:{vertex}"], capture_output=True, text=True, check=True
    ).stdout
    return [float(line.split(",")[1]) for line in out.splitlines()[1:]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--model", default="stanford_bunny", help="a model of the shared folder, or gen:SHAPE")
    parser.add_argument("--vertices", type=int, default=200, help="random vertices selected")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--threads", type=int, default=2, help="threads of the parallel runs")
    parser.add_argument("--repeats", type=int, default=1, help="runs of each, taking turns")
    parser.add_argument("--check-rows", type=int, default=4, help="rows checked against single-source runs")
    parser.add_argument("--binary", default=BIN, help="the exact-geodesics executable")
    parser.add_argument("--timeout", type=float, default=3600, help="seconds a run may take")
    parser.add_argument("--out", default=os.path.join(ROOT, "bench-results"))
    args = parser.parse_args()
    mesh = args.model if args.model.startswith("gen:") else os.path.join(MODELS, args.model + ".obj")

    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        selection = os.path.join(tmp, "selection.txt")
        for turn in range(args.repeats):
            for threads in (1, args.threads):
                npy = os.path.join(tmp, f"matrix{threads}.npy")
                cmd = [args.binary, "matrix", mesh, "--random", str(args.vertices), "--seed", str(args.seed),
                       "--threads", str(threads), "--save-selection", selection, "--out", npy]
                try:
                    wall, user, system, rss = run_measured(cmd, os.devnull, args.timeout)
                except RunError as exc:
                    sys.exit(f"failed: {' '.join(cmd)}: {exc}")
                runs.append({"turn": turn, "threads": threads, "wall_seconds": wall, "user_seconds": user,
                             "system_seconds": system, "peak_rss_bytes": rss, "rss_method": RSS_METHOD})
                print(f"threads {threads}: {wall:.1f} s wall, {user:.1f} s user, {rss / 2**20:.0f} MiB",
                      file=sys.stderr)
        one = read_npy(os.path.join(tmp, "matrix1.npy"))
        parallel = read_npy(os.path.join(tmp, f"matrix{args.threads}.npy"))
        with open(selection) as f:
            vertices = [int(line.strip()[2:]) for line in f if line.strip()]
        checks = []
        n = one[0]
        for i in sorted({round(k * (n - 1) / max(1, args.check_rows - 1)) for k in range(args.check_rows)}):
            reference = single_source(args.binary, mesh, vertices[i])
            row = one[2][i * n : (i + 1) * n]
            equal = all(struct.pack("<d", row[j]) == struct.pack("<d", reference[v]) for j, v in enumerate(vertices))
            checks.append({"row": i, "vertex": vertices[i], "equals_single_source": equal})
            print(f"row {i} (v{vertices[i]}): {'equal' if equal else 'DIFFERS'}", file=sys.stderr)
        same = one[2] == parallel[2]

    median = {t: statistics.median(r["wall_seconds"] for r in runs if r["threads"] == t) for t in (1, args.threads)}
    summary = {"model": args.model, "vertices": args.vertices, "seed": args.seed, "threads": args.threads,
               "speedup": median[1] / median[args.threads], "parallel_equals_serial": same,
               "rows_checked": len(checks), "rows_equal": sum(c["equals_single_source"] for c in checks)}
    print(summary)
    write_rows(args.out, "matrix_runs", runs)
    write_rows(args.out, "matrix_checks", checks)
    write_rows(args.out, "matrix_summary", [summary])
    return 0 if same and all(c["equals_single_source"] for c in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
