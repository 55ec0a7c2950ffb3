"""section6_tables: gdist rows and the merged Markdown tables, on rows made by hand."""

import csv
import math

from common import write_rows
from section6_tables import (
    compare_distances,
    gdist_row,
    model_sources,
    read_rows,
    table1_markdown,
    table2_markdown,
)

INF = math.inf


def table1_row(source, wedges_mean, wedges_max, seconds, backend="f64"):
    return {
        "model": "models/a.obj",
        "backend": backend,
        "source": source,
        "faces": 12,
        "edges": 18,
        "wedges_mean": wedges_mean,
        "wedges_std": 1.0,
        "wedges_max": wedges_max,
        "seconds": seconds,
        "wedges_skewness": 0.5,
        "wedges_total": 36,
        "edges_without_wedges": 0,
        "edges_holding_half": 0.25,
        "min_angle_max": 45.0,
        "min_angle_mean": 45.0,
        "min_angle_min": 45.0,
    }


def table2_row(source, ratio, seconds):
    return {
        "model": "models/a.obj",
        "backend": "f64",
        "source": source,
        "edge_length_mean": 0.5,
        "edge_length_std": 0.125,
        "edge_length_max": 0.75,
        "edge_length_min": 0.25,
        "wedges_per_unit_length": ratio,
        "wedges_mean": ratio / 2,
        "edges": 18,
        "seconds": seconds,
    }


def comparison(largest, mean, unreachable=0, reach_differs=0):
    return {
        "distance_max_relative_difference": largest,
        "distance_mean_relative_difference": mean,
        "unreachable": unreachable,
        "reach_differs": reach_differs,
    }


def test_relative_differences_skip_the_source_and_what_one_side_does_not_reach():
    ours = [0.0, 1.0, 2.0, INF, 4.0, INF]
    theirs = [0.0, 1.5, 2.0, INF, INF, 3.0]
    # Vertices 1 and 2 count: |1.5 - 1| / 1 = 0.5 and 0; 3 is unreached by both, 4 and 5 by one.
    assert compare_distances(ours, theirs) == comparison(0.5, 0.25, 2, 2)


def test_nothing_to_compare_gives_no_difference():
    assert compare_distances([0.0, INF], [0.0, INF]) == comparison(None, None, 1, 0)


def test_a_gdist_row_keeps_the_model_and_empties_the_wedges():
    ours = table1_row(7, 2.0, 5, 0.25)
    row = gdist_row(ours, 7, 0.125, "f64", comparison(1e-15, 5e-16))
    assert list(row) == list(ours) + [
        "reference_backend",
        "distance_max_relative_difference",
        "distance_mean_relative_difference",
        "unreachable",
        "reach_differs",
    ]
    assert (row["model"], row["faces"], row["edges"], row["min_angle_min"]) == (
        "models/a.obj",
        12,
        18,
        45.0,
    )
    assert (row["backend"], row["source"], row["seconds"]) == ("gdist", 7, 0.125)
    for column in ("wedges_mean", "wedges_std", "wedges_max", "wedges_total", "edges_holding_half"):
        assert row[column] is None
    assert (row["reference_backend"], row["distance_max_relative_difference"]) == ("f64", 1e-15)


def test_gdist_rows_are_written_with_empty_wedge_cells(tmp_path):
    rows = [gdist_row(table1_row(7, 2.0, 5, 0.25), 7, 0.125, "f64", comparison(None, None, 3))]
    write_rows(tmp_path, "table1_gdist", rows)
    with open(tmp_path / "table1_gdist.csv") as f:
        (record,) = csv.DictReader(f)
    assert (record["wedges_mean"], record["seconds"], record["unreachable"]) == ("", "0.125", "3")
    assert read_rows(tmp_path, "table1_gdist") == rows
    assert read_rows(tmp_path, "absent") == []


def test_model_sources_in_order_of_first_appearance():
    rows = [table1_row(3, 1, 1, 1), table1_row(1, 1, 1, 1), table1_row(3, 1, 1, 1, "adaptive")]
    assert model_sources(rows) == [("models/a.obj", 3), ("models/a.obj", 1)]


def test_table1_merges_gdist_after_our_backends():
    ours = [table1_row(1, 2.0, 5, 0.25), table1_row(2, 4.0, 7, 0.75)]
    theirs = [
        gdist_row(ours[0], 1, 0.5, "f64", comparison(4e-15, 1e-15, 0, 0)),
        gdist_row(ours[1], 2, 1.5, "f64", comparison(2e-15, 3e-15, 10, 4)),
    ]
    lines = table1_markdown(theirs[:1] + ours + theirs[1:]).splitlines()
    # Means 2 and 4: 3.00 ± 1.00 (population); std 1 at both; times 0.25, 0.75 and 0.5, 1.5.
    assert lines[2:] == [
        "| a | f64 | 12 | 18 | 45.0 / 45.0 / 45.0 | 3.00 ± 1.00 | 1.00 ± 0.00 | 5/7 | 0.500 |  |  |  |",
        "| a | gdist |  |  |  | - | - | - | 1.000 | 4.0e-15 / 2.0e-15 | 0/10 | 0/4 |",
    ]


def test_table2_shows_lengths_once_and_no_ratio_for_gdist():
    ours = [table2_row(1, 10.0, 0.25), table2_row(2, 14.0, 0.75)]
    theirs = [gdist_row(ours[0], 1, 0.5, "f64", comparison(None, None, 2, 2))]
    assert (theirs[0]["edge_length_min"], theirs[0]["wedges_per_unit_length"]) == (0.25, None)
    lines = table2_markdown(ours + theirs).splitlines()
    assert lines[2:] == [
        "| a | f64 | 0.5000 | 0.1250 | 0.7500 | 0.2500 | 12 ± 2 | 0.500 |  |  |  |",
        "| a | gdist |  |  |  |  | - | 0.500 | - | 2 | 2 |",
    ]
