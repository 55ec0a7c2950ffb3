"""What the benchmark scripts share: where the repository, the CLI and the shared models are,
the paper's Table 1 models, and how a benchmark's rows are written (OUT/NAME.json and
OUT/NAME.csv)."""

import csv
import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.path.join(ROOT, "target", "release", "exact-geodesics")
MODELS = os.path.join(ROOT, "..", "shared", "models")
# The paper's Table 1 models, non-uniform and uniform, under MODELS.
PAPER_TABLE1 = [
    f"paper-table1/{shape}_{kind}"
    for shape in ("sphere", "eight", "teapot")
    for kind in ("uniform", "nonuniform")
]


def write_rows(out, name, rows):
    """Writes `rows` (a list of dicts) to OUT/NAME.json and OUT/NAME.csv (the union of their
    keys, in order of first appearance)."""
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, name + ".json"), "w") as f:
        json.dump(rows, f, indent=2)
    fields = []
    for row in rows:
        fields += [k for k in row if k not in fields]
    with open(os.path.join(out, name + ".csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
