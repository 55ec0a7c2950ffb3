#!/usr/bin/env python3
"""Benchmark the exact-geodesics CLI against gdist (Kirsanov's exact MMP).

For every model (an OBJ file in ../shared/models, relative to the repository,
and generated meshes written as OBJ files into OUT/generated: regular ones, and
shared models Loop-subdivided, ``loop:rocker_arm:1``) and one
source vertex, this runs fresh processes, taking turns --repeats times:

1. gdist_worker.py in the venv made by setup_venv.sh: one
   ``gdist.compute_gdist`` call, timed inside the worker;
2. ``exact-geodesics distance MODEL --source v:S --format csv [--threads T]``:
   the distance of every vertex, compared with gdist's (two threads split the
   source's directions into two sectors propagated at once; by default the
   command uses every core on meshes of 15,000 faces or more);
3. where ``build_kirsanov.sh`` built it (or ``--kirsanov-driver PATH``), the
   plain C++ driver around the same code as gdist's (``kirsanov_driver.cpp``):
   the whole process, timed as ours is (the targets compare whole processes);

then once ``exact-geodesics stats MODEL --source v:S``: a JSON object whose
``propagation_seconds``, ``wedges``, ``wedges_per_edge`` and
``wedge_memory_bytes`` are read.

The wall time of each child is measured here, and its peak RSS by GNU time
(``/usr/bin/time -f %M``) when it is installed, else with ``os.wait4``
(``ours_rss_method`` says which: ``gnu-time`` or ``wait4``); each figure of the
repeated runs is their median. On Linux a child's ``ru_maxrss`` never falls
below its parent's high-water mark at the fork (it survives exec), so
``os.wait4`` reports at least this harness's own RSS (about 19 MiB), while
GNU time's small process is all that the measured command inherits.
Results go to OUT/benchmark.json and OUT/benchmark.csv (rewritten after each
model), a table goes to stdout, progress to stderr. The exit status is 0 when
every run succeeded (whatever the timings and differences), 1 when some run
failed (the failures are recorded per model), 2 on a setup error. Without the
models folder the script says so and exits 0.

Runs under the system python3 or the venv's; needs only the standard library.
"""

import argparse
import concurrent.futures
import csv
import json
import math
import multiprocessing
import os
import platform
import statistics
import subprocess
import sys
from datetime import datetime, timezone
from pathlib import Path

from common import RSS_METHOD, RunError, read_obj, run_measured
from loop_subdivision import loop_subdivide, split_in_four

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
WORKER = HERE / "gdist_worker.py"
DEFAULT_MODELS_DIR = REPO.parent / "shared" / "models"
DEFAULT_BINARY = REPO / "target" / "release" / "exact-geodesics"
DEFAULT_VENV_PYTHON = REPO / ".venv" / "bin" / "python"
DEFAULT_OUT = REPO / "bench-results"
DEFAULT_KIRSANOV = DEFAULT_OUT / "kirsanov" / "kirsanov_driver"
MIB = 1024 * 1024

# Columns of benchmark.csv, in order; every per-model result has these keys.
CSV_COLUMNS = [
    "model",
    "vertices",
    "faces",
    "source",
    "threads",
    "repeats",
    "ours_propagation_seconds",
    "gdist_cpu_seconds",
    "gdist_wall_seconds",
    "ratio_ours_over_gdist",
    "ratio_ours_wall_over_gdist",
    "gdist_process_wall_seconds",
    "ours_wedges",
    "ours_wedges_per_edge_mean",
    "ours_wedges_per_edge_max",
    "ours_wedge_memory_bytes",
    "ours_stats_wall_seconds",
    "ours_stats_peak_rss_bytes",
    "ours_distance_wall_seconds",
    "ours_distance_peak_rss_bytes",
    "ours_rss_method",
    "gdist_peak_rss_bytes",
    "gdist_rss_before_bytes",
    "gdist_rss_increase_bytes",
    "gdist_rss_method",
    "ours_reached",
    "gdist_reached",
    "finite_in_both",
    "finite_ours_only",
    "finite_gdist_only",
    "max_abs_diff",
    "max_abs_diff_vertex",
    "max_rel_diff",
    "kirsanov_process_wall_seconds",
    "kirsanov_process_cpu_seconds",
    "kirsanov_peak_rss_bytes",
    "ratio_ours_wall_over_kirsanov",
    "ratio_ours_rss_over_kirsanov",
    "kirsanov_reached",
    "kirsanov_max_abs_diff",
    "errors",
]


class SetupError(Exception):
    """The benchmark cannot run at all (missing venv, binary, model...)."""


def log(message):
    """Print a progress line on stderr."""
    print(message, file=sys.stderr, flush=True)


def read_distances_text(path):
    """Read one float per line (``inf`` allowed), as written by gdist_worker.py."""
    with open(path, encoding="ascii") as lines:
        return [float(line) for line in lines if line.strip()]


def read_distances_csv(path, vertex_count):
    """Read the ``vertex,distance,source`` CSV of ``exact-geodesics distance``.

    Checks that there is one row per vertex, in vertex order (and that there
    are ``vertex_count`` rows, unless it is None).
    """
    with open(path, encoding="utf-8", newline="") as stream:
        rows = csv.reader(stream)
        header = next(rows, None)
        if header != ["vertex", "distance", "source"]:
            raise RunError(f"{path}: unexpected CSV header {header}")
        distances = []
        for expected, row in enumerate(rows):
            try:
                if int(row[0]) != expected:
                    raise ValueError(f"expected vertex {expected}")
                distances.append(float(row[1]))
            except (ValueError, IndexError) as exc:
                raise RunError(f"{path}: bad row {expected + 2} {row}: {exc}") from exc
    if vertex_count is not None and len(distances) != vertex_count:
        raise RunError(f"{path}: {len(distances)} rows for {vertex_count} vertices")
    return distances


def parse_stats(path):
    """Read the JSON of ``exact-geodesics stats`` and check the keys used here."""
    try:
        stats = json.loads(Path(path).read_text(encoding="utf-8"))
    except ValueError as exc:
        raise RunError(f"{path}: stats output is not JSON: {exc}") from exc
    expected = {"propagation_seconds": (int, float), "wedges": int, "wedge_memory_bytes": int}
    for key, kind in expected.items():
        if not isinstance(stats.get(key), kind) or isinstance(stats.get(key), bool):
            raise RunError(f"{path}: stats JSON lacks a numeric {key!r}")
    per_edge = stats.get("wedges_per_edge")
    if not isinstance(per_edge, dict) or not all(isinstance(per_edge.get(k), (int, float)) for k in ("mean", "max")):
        raise RunError(f"{path}: stats JSON lacks wedges_per_edge mean and max")
    return stats


def compare(ours, reference):
    """Compare two distance lists over the vertices finite in both.

    The relative difference is taken against the reference, over vertices where
    the reference distance is positive.
    """
    max_abs, max_abs_vertex, max_rel = 0.0, None, 0.0
    both = ours_only = reference_only = 0
    for vertex, (a, b) in enumerate(zip(ours, reference)):
        finite_a, finite_b = math.isfinite(a), math.isfinite(b)
        if finite_a and finite_b:
            both += 1
            diff = abs(a - b)
            if max_abs_vertex is None or diff > max_abs:
                max_abs, max_abs_vertex = diff, vertex
            if b > 0:
                max_rel = max(max_rel, diff / b)
        elif finite_a:
            ours_only += 1
        elif finite_b:
            reference_only += 1
    return {
        "finite_in_both": both,
        "finite_ours_only": ours_only,
        "finite_gdist_only": reference_only,
        "max_abs_diff": max_abs if both else None,
        "max_abs_diff_vertex": max_abs_vertex,
        "max_rel_diff": max_rel if both else None,
    }


def median(values):
    """The median of the figures of the repeated runs, None without any."""
    return statistics.median(values) if values else None


def run_gdist(mesh, args, raw_dir, name):
    """One gdist worker process: its report, with the whole process's wall time added."""
    report_path = raw_dir / f"{name}.gdist.json"
    distances_path = raw_dir / f"{name}.gdist.txt"
    cmd = [str(args.venv_python), str(WORKER), str(mesh), "--source", str(args.source),
           "--distances", str(distances_path)]
    wall = run_measured(cmd, report_path, args.timeout).wall_seconds
    report = json.loads(report_path.read_text(encoding="utf-8"))
    report["process_wall_seconds"] = wall
    return report, distances_path


def run_ours_distance(mesh, args, raw_dir, name):
    """One ``distance`` process: its wall time, peak RSS and the CSV it wrote."""
    csv_path = raw_dir / f"{name}.ours.csv"
    cmd = [str(args.binary), "distance", str(mesh), "--source", f"v:{args.source}", "--format", "csv"]
    if args.threads is not None:
        cmd += ["--threads", str(args.threads)]
    run = run_measured(cmd, csv_path, args.timeout)
    return run.wall_seconds, run.peak_rss_bytes, csv_path


def run_kirsanov(mesh, args, raw_dir, name):
    """One run of the C++ driver: its wall and CPU time, peak RSS and the distances it wrote."""
    distances_path = raw_dir / f"{name}.kirsanov.txt"
    cmd = [str(args.kirsanov_driver), str(mesh), str(args.source)]
    run = run_measured(cmd, distances_path, args.timeout)
    return run, distances_path


def in_fresh_process(function, *args):
    """``function(*args)`` in a fresh interpreter. On Linux a child's peak RSS includes its
    parent's high-water mark at the fork (it survives fork and exec), so whatever holds a
    mesh or its distances runs apart, and this harness stays small."""
    with concurrent.futures.ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as pool:
        return pool.submit(function, *args).result()


def compare_outputs(ours_csv, gdist_txt, vertex_count):
    """Our reach, and the comparison with gdist's distances if ``gdist_txt`` is not None."""
    ours = read_distances_csv(ours_csv, vertex_count)
    summary = {"vertices": len(ours), "ours_reached": sum(1 for d in ours if math.isfinite(d))}
    if gdist_txt is not None:
        summary.update(compare(ours, read_distances_text(gdist_txt)))
    return summary


def benchmark_model(name, mesh, args, raw_dir):
    """Run gdist and our ``distance`` in turns, then our ``stats``, on one model; return its
    result dict (medians of the repeated runs)."""
    result = dict.fromkeys(CSV_COLUMNS)
    result.update(model=name, source=args.source, threads=args.threads or "default", repeats=args.repeats, errors=[])
    gdist_txt = ours_csv = kirsanov_txt = None
    gdist_reports, ours_runs, kirsanov_runs = [], [], []

    for turn in range(1, args.repeats + 1):
        try:
            report, gdist_txt = run_gdist(mesh, args, raw_dir, name)
            gdist_reports.append(report)
            log(f"  [{turn}] gdist: {report['seconds_cpu']:.3f} s cpu, reached {report['reached']}/{report['vertices']}")
        except (RunError, ValueError, KeyError) as exc:
            result["errors"].append(f"gdist: {exc}")
            log(f"  [{turn}] gdist FAILED: {exc}")
        try:
            wall, peak, ours_csv = run_ours_distance(mesh, args, raw_dir, name)
            ours_runs.append((wall, peak))
            log(f"  [{turn}] ours distance: {wall:.3f} s wall, {peak / MIB:.1f} MiB")
        except RunError as exc:
            result["errors"].append(f"ours distance: {exc}")
            log(f"  [{turn}] ours distance FAILED: {exc}")
        if args.kirsanov_driver is not None:
            try:
                run, kirsanov_txt = run_kirsanov(mesh, args, raw_dir, name)
                kirsanov_runs.append(run)
                log(f"  [{turn}] kirsanov driver: {run.wall_seconds:.3f} s wall, {run.peak_rss_bytes / MIB:.1f} MiB")
            except RunError as exc:
                result["errors"].append(f"kirsanov driver: {exc}")
                log(f"  [{turn}] kirsanov driver FAILED: {exc}")

    if gdist_reports:
        last = gdist_reports[-1]
        result.update(
            vertices=last["vertices"],
            faces=last["faces"],
            gdist_cpu_seconds=median([r["seconds_cpu"] for r in gdist_reports]),
            gdist_wall_seconds=median([r["seconds_wall"] for r in gdist_reports]),
            gdist_process_wall_seconds=median([r["process_wall_seconds"] for r in gdist_reports]),
            gdist_peak_rss_bytes=median([r["peak_rss_bytes"] for r in gdist_reports]),
            gdist_rss_before_bytes=median([r["rss_before_bytes"] for r in gdist_reports if r["rss_before_bytes"] is not None]),
            gdist_rss_increase_bytes=median([r["rss_increase_bytes"] for r in gdist_reports if r["rss_increase_bytes"] is not None]),
            gdist_reached=last["reached"],
            gdist_rss_method=last.get("peak_rss_method"),
        )
        result["gdist"] = last
    if ours_runs:
        result.update(
            ours_distance_wall_seconds=median([wall for wall, _ in ours_runs]),
            ours_distance_peak_rss_bytes=median([peak for _, peak in ours_runs]),
            ours_rss_method=RSS_METHOD,
        )
        try:
            result.update(in_fresh_process(compare_outputs, ours_csv, gdist_txt, result["vertices"]))
            if kirsanov_txt is not None:
                against = in_fresh_process(compare_outputs, ours_csv, kirsanov_txt, result["vertices"])
                result["kirsanov_reached"] = against["finite_in_both"] + against["finite_gdist_only"]
                result["kirsanov_max_abs_diff"] = against["max_abs_diff"]
        except RunError as exc:
            result["errors"].append(f"ours distance: {exc}")
    if kirsanov_runs:
        result.update(
            kirsanov_process_wall_seconds=median([r.wall_seconds for r in kirsanov_runs]),
            kirsanov_process_cpu_seconds=median([r.user_seconds + r.system_seconds for r in kirsanov_runs]),
            kirsanov_peak_rss_bytes=median([r.peak_rss_bytes for r in kirsanov_runs]),
        )
        if ours_runs:
            result["ratio_ours_wall_over_kirsanov"] = (
                result["ours_distance_wall_seconds"] / result["kirsanov_process_wall_seconds"])
            result["ratio_ours_rss_over_kirsanov"] = (
                result["ours_distance_peak_rss_bytes"] / result["kirsanov_peak_rss_bytes"])

    try:
        stats_path = raw_dir / f"{name}.ours-stats.json"
        cmd = [str(args.binary), "stats", str(mesh), "--source", f"v:{args.source}"]
        run = run_measured(cmd, stats_path, args.timeout)
        wall, peak = run.wall_seconds, run.peak_rss_bytes
        stats = parse_stats(stats_path)
        result.update(
            ours_propagation_seconds=stats["propagation_seconds"],
            ours_wedges=stats["wedges"],
            ours_wedges_per_edge_mean=stats["wedges_per_edge"]["mean"],
            ours_wedges_per_edge_max=stats["wedges_per_edge"]["max"],
            ours_wedge_memory_bytes=stats["wedge_memory_bytes"],
            ours_stats_wall_seconds=wall,
            ours_stats_peak_rss_bytes=peak,
        )
        result["ours_stats"] = stats
        log(f"  ours stats: {stats['propagation_seconds']:.3f} s propagation, {stats['wedges']} wedges")
    except RunError as exc:
        result["errors"].append(f"ours stats: {exc}")
        log(f"  ours stats FAILED: {exc}")

    if result["gdist_cpu_seconds"]:
        if result["ours_propagation_seconds"] is not None:
            result["ratio_ours_over_gdist"] = result["ours_propagation_seconds"] / result["gdist_cpu_seconds"]
        if result["ours_distance_wall_seconds"] is not None:
            result["ratio_ours_wall_over_gdist"] = result["ours_distance_wall_seconds"] / result["gdist_cpu_seconds"]
    return result


def write_obj(path, vertices, triangles):
    """Write vertices and 0-based triangles as an OBJ file."""
    with open(path, "w", encoding="ascii") as out:
        out.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in vertices)
        out.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in triangles)


def grid_mesh(n):
    """The unit square in z = 0 as an n by n grid, each cell split along a diagonal."""
    vertices = [(i / n, j / n, 0.0) for j in range(n + 1) for i in range(n + 1)]
    at = lambda i, j: j * (n + 1) + i
    triangles = []
    for j in range(n):
        for i in range(n):
            triangles.append((at(i, j), at(i + 1, j), at(i + 1, j + 1)))
            triangles.append((at(i, j), at(i + 1, j + 1), at(i, j + 1)))
    return vertices, triangles


def icosphere_mesh(level):
    """The icosahedron subdivided ``level`` times at edge midpoints, on the unit sphere."""
    t = (1 + 5 ** 0.5) / 2
    corners = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
               (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    triangles = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
                 (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
                 (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]

    def unit(p):
        norm = math.sqrt(sum(c * c for c in p))
        return tuple(c / norm for c in p)

    vertices = [unit(p) for p in corners]
    for _ in range(level):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                middle[key] = len(vertices)
                vertices.append(unit(tuple((p + q) / 2 for p, q in zip(vertices[a], vertices[b]))))
            return middle[key]

        triangles = split_in_four(triangles, mid)
    return vertices, triangles


def write_generated(kind, size, path, model=None):
    """Write ``icosphere_mesh(size)``, ``grid_mesh(size)`` or, for ``loop``, the OBJ file
    ``model`` Loop-subdivided ``size`` times, to ``path``."""
    if kind == "loop":
        mesh = read_obj(model)
        for _ in range(size):
            mesh = loop_subdivide(*mesh)
    else:
        mesh = icosphere_mesh(size) if kind == "icosphere" else grid_mesh(size)
    write_obj(path, *mesh)


def generated_models(names, out_dir, models_dir):
    """Write each generated mesh (``icosphere:L``, ``grid:N``, or ``loop:MODEL:N``: the model
    of ``models_dir`` Loop-subdivided N times) as OBJ; map names to paths."""
    out_dir.mkdir(parents=True, exist_ok=True)
    models = {}
    for name in names:
        kind, _, size = name.partition(":")
        model = None
        if kind == "loop":
            stem, _, size = size.rpartition(":")
            if not models_dir.is_dir():
                log(f"models folder {models_dir} not found: {name} skipped")
                continue
            model = models_dir / f"{stem}.obj"
            if not model.is_file():
                raise SetupError(f"no model {stem!r} in {models_dir} to subdivide ({name!r})")
        if kind not in ("icosphere", "grid", "loop") or not size.isdigit():
            raise SetupError(f"unknown generated mesh {name!r} (icosphere:L, grid:N or loop:MODEL:N)")
        stem = f"{model.stem}_loop{size}" if model else f"{kind}{size}"
        path = out_dir / f"{stem}.obj"
        if not path.exists():
            log(f"writing {path}")
            in_fresh_process(write_generated, kind, int(size), path, model)
        models[stem] = path
    return models


def ensure_binary(binary, force_build):
    """Build the release CLI with cargo if it is missing (or if asked to)."""
    if force_build or not binary.exists():
        log(f"building {binary.name}: cargo build --release")
        try:
            build = subprocess.run(["cargo", "build", "--release"], cwd=REPO, stdout=sys.stderr)
        except OSError as exc:
            raise SetupError(f"cannot run cargo: {exc}") from exc
        if build.returncode != 0:
            raise SetupError("cargo build --release failed")
    if not binary.exists():
        raise SetupError(f"{binary} does not exist")


def ensure_venv(venv_python):
    """Check that the venv's python imports gdist."""
    hint = f"run {HERE.relative_to(REPO) / 'setup_venv.sh'} first"
    if not venv_python.exists():
        raise SetupError(f"{venv_python} does not exist: {hint}")
    probe = subprocess.run([str(venv_python), "-c", "import gdist"], capture_output=True, text=True)
    if probe.returncode != 0:
        raise SetupError(f"{venv_python} cannot import gdist: {hint}\n{probe.stderr.strip()}")


def select_models(models_dir, names):
    """Map model names (file stems) to OBJ paths; all OBJ files when ``names`` is None."""
    if names is None:
        return {path.stem: path for path in sorted(models_dir.glob("*.obj"))}
    selected = {}
    for name in names:
        path = models_dir / f"{name.removesuffix('.obj')}.obj"
        if not path.is_file():
            raise SetupError(f"no model {name!r} in {models_dir}")
        selected[path.stem] = path
    return selected


def git_commit():
    """The repository's HEAD commit, or None outside a git checkout."""
    try:
        probe = subprocess.run(["git", "rev-parse", "HEAD"], cwd=REPO, capture_output=True, text=True)
    except OSError:
        return None
    return probe.stdout.strip() if probe.returncode == 0 else None


def write_results(out_dir, meta, results):
    """Write benchmark.json (everything) and benchmark.csv (one row per model)."""
    (out_dir / "benchmark.json").write_text(
        json.dumps({"meta": meta, "results": results}, indent=2) + "\n", encoding="utf-8"
    )
    with open(out_dir / "benchmark.csv", "w", encoding="utf-8", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=CSV_COLUMNS, extrasaction="ignore")
        writer.writeheader()
        for result in results:
            writer.writerow({**result, "errors": "; ".join(result["errors"])})


def format_table(results):
    """A fixed-width text table of the main figures."""

    def num(value, fmt, scale=None):
        if value is None:
            return "-"
        return format(value if scale is None else value / scale, fmt)

    columns = [
        ("model", lambda r: r["model"]),
        ("V", lambda r: num(r["vertices"], "d")),
        ("ours s", lambda r: num(r["ours_propagation_seconds"], ".3f")),
        ("gdist s", lambda r: num(r["gdist_cpu_seconds"], ".3f")),
        ("ratio", lambda r: num(r["ratio_ours_over_gdist"], ".2f")),
        ("wall ratio", lambda r: num(r["ratio_ours_wall_over_gdist"], ".2f")),
        ("wedges", lambda r: num(r["ours_wedges"], "d")),
        ("w/edge", lambda r: num(r["ours_wedges_per_edge_mean"], ".2f")),
        ("wedge MiB", lambda r: num(r["ours_wedge_memory_bytes"], ".1f", MIB)),
        ("ours RSS MiB", lambda r: num(r["ours_distance_peak_rss_bytes"], ".1f", MIB)),
        ("gdist RSS MiB", lambda r: num(r["gdist_peak_rss_bytes"], ".1f", MIB)),
        ("gdist +MiB", lambda r: num(r["gdist_rss_increase_bytes"], ".1f", MIB)),
        ("max abs", lambda r: num(r["max_abs_diff"], ".1e")),
        ("max rel", lambda r: num(r["max_rel_diff"], ".1e")),
        ("ours only", lambda r: num(r["finite_ours_only"], "d")),
        ("gdist only", lambda r: num(r["finite_gdist_only"], "d")),
        ("ours wall s", lambda r: num(r["ours_distance_wall_seconds"], ".3f")),
        ("kirsanov wall s", lambda r: num(r["kirsanov_process_wall_seconds"], ".3f")),
        ("/kirsanov", lambda r: num(r["ratio_ours_wall_over_kirsanov"], ".2f")),
        ("kirsanov MiB", lambda r: num(r["kirsanov_peak_rss_bytes"], ".1f", MIB)),
        ("RSS /kirsanov", lambda r: num(r["ratio_ours_rss_over_kirsanov"], ".2f")),
    ]
    rows = [[title for title, _ in columns]]
    rows += [[cell(result) for _, cell in columns] for result in results]
    widths = [max(len(row[i]) for row in rows) for i in range(len(columns))]
    lines = []
    for index, row in enumerate(rows):
        cells = [row[0].ljust(widths[0])] + [c.rjust(w) for c, w in zip(row[1:], widths[1:])]
        lines.append("  ".join(cells))
        if index == 0:
            lines.append("  ".join("-" * w for w in widths))
    for result in results:
        for error in result["errors"]:
            lines.append(f"{result['model']}: {error}")
    return "\n".join(lines)


def parse_args():
    """Command-line options."""
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n", 1)[0],
        formatter_class=argparse.ArgumentDefaultsHelpFormatter,
    )
    parser.add_argument("--models", type=lambda s: [m for m in s.split(",") if m],
                        help="comma-separated model names (default: every OBJ file in --models-dir)")
    parser.add_argument("--models-dir", type=Path, default=DEFAULT_MODELS_DIR, help="folder of OBJ models")
    parser.add_argument("--source", type=int, default=0, help="0-based source vertex")
    parser.add_argument("--threads", type=int, default=None,
                        help="threads of our distance runs, passed as distance --threads (default: the command's "
                             "own, every core from 15,000 faces; 2 or more: two sectors of the source's directions "
                             "at once)")
    parser.add_argument("--binary", type=Path, default=DEFAULT_BINARY,
                        help="exact-geodesics executable (built with cargo build --release if missing)")
    parser.add_argument("--build", action="store_true",
                        help="run cargo build --release even if the binary exists")
    parser.add_argument("--venv-python", type=Path, default=DEFAULT_VENV_PYTHON,
                        help="python of the venv made by setup_venv.sh")
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, help="output folder")
    parser.add_argument("--timeout", type=float, default=600.0, help="seconds allowed to each run")
    parser.add_argument("--repeats", type=int, default=3,
                        help="runs of gdist and of ours, taking turns; medians are reported")
    parser.add_argument("--generated", type=lambda s: [m for m in s.split(",") if m],
                        default=["icosphere:6", "icosphere:7", "grid:300", "grid:1000",
                                 "loop:rocker_arm:1", "loop:stanford_bunny:1"],
                        help="generated meshes, written to OUT/generated ('' for none): icosphere:L, grid:N, or "
                             "loop:MODEL:N, a model of --models-dir Loop-subdivided N times (4^N times the faces, "
                             "smoothed a little, the same genus; v:S stays the same point)")
    parser.add_argument("--kirsanov-driver", type=Path, default=None,
                        help="the C++ driver built by build_kirsanov.sh, also timed in every turn "
                             f"(default: {DEFAULT_KIRSANOV.relative_to(REPO)} where it exists)")
    args = parser.parse_args()
    if args.kirsanov_driver is None and DEFAULT_KIRSANOV.exists():
        args.kirsanov_driver = DEFAULT_KIRSANOV
    return args


def main():
    args = parse_args()
    if args.repeats < 1:
        print("error: --repeats must be at least 1", file=sys.stderr)
        return 2
    if not args.models_dir.is_dir() and not args.generated:
        print(f"models folder {args.models_dir} not found: nothing to benchmark", file=sys.stderr)
        return 0
    try:
        models = select_models(args.models_dir, args.models) if args.models_dir.is_dir() else {}
        models.update(generated_models(args.generated, args.out / "generated", args.models_dir))
        ensure_venv(args.venv_python)
        ensure_binary(args.binary, args.build)
    except SetupError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2

    raw_dir = args.out / "raw"
    raw_dir.mkdir(parents=True, exist_ok=True)
    meta = {
        "date": datetime.now(timezone.utc).isoformat(timespec="seconds"),
        "git_commit": git_commit(),
        "binary": str(args.binary),
        "source": args.source,
        "repeats": args.repeats,
        "models_dir": str(args.models_dir),
        "machine": platform.machine(),
        "cpu_count": os.cpu_count(),
        "harness_python": platform.python_version(),
        "gdist_version": None,
        "kirsanov_driver": None if args.kirsanov_driver is None else str(args.kirsanov_driver),
    }
    results = []
    for index, (name, mesh) in enumerate(models.items(), start=1):
        log(f"[{index}/{len(models)}] {name}")
        result = benchmark_model(name, mesh, args, raw_dir)
        if "gdist" in result:
            meta["gdist_version"] = result["gdist"]["gdist_version"]
        results.append(result)
        write_results(args.out, meta, results)

    print(format_table(results))
    log(f"wrote {args.out / 'benchmark.json'} and {args.out / 'benchmark.csv'}")
    return 1 if any(result["errors"] for result in results) else 0


if __name__ == "__main__":
    sys.exit(main())
