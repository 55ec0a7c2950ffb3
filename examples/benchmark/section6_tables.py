#!/usr/bin/env python3
"""Tables 1-2 of `exact-geodesics experiment` with Kirsanov's MMP (gdist) beside our backends.

`gdist_tables.py` measures gdist on the models and sources of an experiment directory and
writes its rows to DIR/table1_gdist.csv and DIR/table2_gdist.csv (and JSON twins), in the
columns of DIR/table1.csv and DIR/table2.csv: the model's own columns are copied, the wedge
columns are empty (gdist gives no window counts), `seconds` is gdist's time, and
GDIST_COLUMNS follow. This module builds those rows and prints both tables merged, one line per
model and backend (mean ± population spread over the sources), as Markdown:

    python3 examples/benchmark/section6_tables.py DIR

Standard library only.
"""

import argparse
import json
import math
import os
import statistics
import sys

# Columns that describe the model, the same in every row of one model whatever the backend and
# source; a gdist row copies them from our rows.
MODEL_COLUMNS = (
    "model",
    "faces",
    "edges",
    "min_angle_max",
    "min_angle_mean",
    "min_angle_min",
    "edge_length_mean",
    "edge_length_std",
    "edge_length_max",
    "edge_length_min",
)
# What a gdist row adds after the table's own columns.
GDIST_COLUMNS = (
    "reference_backend",
    "distance_max_relative_difference",
    "distance_mean_relative_difference",
    "unreachable",
    "reach_differs",
)


def model_sources(rows):
    """The distinct (model, source) pairs of `rows`, in order of first appearance."""
    return list(dict.fromkeys((r["model"], r["source"]) for r in rows))


def compare_distances(ours, theirs):
    """Their distances held to ours, vertex by vertex (`inf` = not reached).

    The relative difference |theirs - ours| / ours is taken where both are finite and ours is
    positive; `unreachable` counts their infinite distances, `reach_differs` the vertices
    exactly one side reaches. Max and mean are None when no vertex qualifies.
    """
    if len(ours) != len(theirs):
        raise ValueError(f"{len(ours)} distances against {len(theirs)}")
    relative = [
        abs(t - o) / o
        for o, t in zip(ours, theirs)
        if math.isfinite(o) and math.isfinite(t) and o > 0
    ]
    return {
        "distance_max_relative_difference": max(relative) if relative else None,
        "distance_mean_relative_difference": statistics.fmean(relative) if relative else None,
        "unreachable": sum(not math.isfinite(t) for t in theirs),
        "reach_differs": sum(math.isfinite(o) != math.isfinite(t) for o, t in zip(ours, theirs)),
    }


def gdist_row(template, source, seconds, reference_backend, comparison):
    """A gdist row shaped like `template` (one of our rows of the same model): the model's
    columns copied, the others empty, then gdist's time and its `comparison` with our
    `reference_backend` (a dict of GDIST_COLUMNS but the first)."""
    row = {k: (v if k in MODEL_COLUMNS else None) for k, v in template.items()}
    row.update(backend="gdist", source=source, seconds=seconds)
    row["reference_backend"] = reference_backend
    row.update({k: comparison[k] for k in GDIST_COLUMNS[1:]})
    return row


def by_model_and_backend(rows):
    """{(model, backend): [rows]}: models in order of first appearance, each with its backends
    together, ours in order of first appearance and gdist last."""
    models = list(dict.fromkeys(r["model"] for r in rows))
    groups = {}
    for row in sorted(rows, key=lambda r: (models.index(r["model"]), r["backend"] == "gdist")):
        groups.setdefault((row["model"], row["backend"]), []).append(row)
    return groups


def spread(rows, column, digits):
    """Mean ± population standard deviation of `column` over `rows`."""
    values = [r[column] for r in rows]
    return f"{statistics.fmean(values):.{digits}f} ± {statistics.pstdev(values):.{digits}f}"


def model_name(model):
    """A model's file stem, or its `gen:` spec."""
    return model if model.startswith("gen:") else os.path.splitext(os.path.basename(model))[0]


def gdist_cells(rows):
    """The comparison columns of gdist rows: the largest and the mean relative difference over
    the sources, the unreachable vertices and those only one side reaches, per source."""
    if rows[0]["backend"] != "gdist":
        return ["", "", ""]
    largest = [r["distance_max_relative_difference"] for r in rows]
    means = [r["distance_mean_relative_difference"] for r in rows]
    relative = (
        f"{max(x for x in largest if x is not None):.1e} / "
        f"{statistics.fmean(x for x in means if x is not None):.1e}"
        if any(x is not None for x in largest)
        else "-"
    )
    return [
        relative,
        "/".join(str(r["unreachable"]) for r in rows),
        "/".join(str(r["reach_differs"]) for r in rows),
    ]


def markdown(header, lines):
    """A Markdown table."""
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(cells) + " |" for cells in lines]
    return "\n".join(out)


def table1_markdown(rows):
    """Table 1 (our rows and gdist's), one line per model and backend."""
    header = [
        "model",
        "backend",
        "F",
        "E",
        "min angle: max / mean / min (°)",
        "mean w(e)",
        "std w(e)",
        "max w(e), per source",
        "seconds",
        "distance to ours: max / mean relative",
        "unreachable, per source",
        "reach differs, per source",
    ]
    lines, seen = [], set()
    for (model, backend), group in by_model_and_backend(rows).items():
        first = group[0]
        shape = ["", "", ""]
        if model not in seen:
            seen.add(model)
            angles = "{:.1f} / {:.1f} / {:.1f}".format(
                first["min_angle_max"], first["min_angle_mean"], first["min_angle_min"]
            )
            shape = [str(first["faces"]), str(first["edges"]), angles]
        if backend == "gdist":
            wedges = ["-", "-", "-"]
        else:
            maxima = "/".join(f"{r['wedges_max']:g}" for r in group)
            wedges = [spread(group, "wedges_mean", 2), spread(group, "wedges_std", 2), maxima]
        seconds = f"{statistics.fmean(r['seconds'] for r in group):.3f}"
        lines.append(
            [model_name(model), backend] + shape + wedges + [seconds] + gdist_cells(group)
        )
    return markdown(header, lines)


def table2_markdown(rows):
    """Table 2 (our rows and gdist's), one line per model and backend."""
    header = [
        "model",
        "backend",
        "mean l(e)",
        "std l(e)",
        "max l(e)",
        "min l(e)",
        "w/l",
        "seconds",
        "distance to ours: max / mean relative",
        "unreachable, per source",
        "reach differs, per source",
    ]
    lines, seen = [], set()
    for (model, backend), group in by_model_and_backend(rows).items():
        first = group[0]
        lengths = ["", "", "", ""]
        if model not in seen:
            seen.add(model)
            lengths = [f"{first['edge_length_' + k]:.4f}" for k in ("mean", "std", "max", "min")]
        ratio = "-" if backend == "gdist" else spread(group, "wedges_per_unit_length", 0)
        seconds = f"{statistics.fmean(r['seconds'] for r in group):.3f}"
        lines.append([model_name(model), backend] + lengths + [ratio, seconds] + gdist_cells(group))
    return markdown(header, lines)


def read_rows(directory, name):
    """The rows of DIR/NAME.json, or [] when it is absent."""
    path = os.path.join(directory, name + ".json")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return json.load(f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", help="the --out DIR of `exact-geodesics experiment table1/table2`")
    args = parser.parse_args()
    for name, table in (("table1", table1_markdown), ("table2", table2_markdown)):
        rows = read_rows(args.dir, name) + read_rows(args.dir, name + "_gdist")
        if rows:
            print(f"{name}\n\n{table(rows)}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
