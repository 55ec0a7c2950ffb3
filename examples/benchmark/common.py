"""Writing a benchmark's rows: OUT/NAME.json and OUT/NAME.csv (the union of the rows' keys,
`mesh`/`model` first)."""

import csv
import json
import os


def write_rows(out, name, rows):
    """Writes `rows` (a list of dicts) to OUT/NAME.json and OUT/NAME.csv."""
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
