//! The command line: its output contract and its errors (non-zero exit, a message naming the
//! file and line, never a panic).

// The command line is built with the `cli` feature only.
#![cfg(feature = "cli")]
mod common;

use common::cli::{fails_with, refuses, run, stdout, temp_file};

#[test]
fn distance_csv_has_one_row_per_vertex_with_nearest_source() {
    let text = stdout(&run(&[
        "distance", "gen:cube", "--source", "v:0", "--source", "v:6",
    ]));
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("vertex,distance,source"));
    let rows: Vec<Vec<String>> = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    assert_eq!(rows.len(), 8);
    assert_eq!(rows[0], ["0", "0", "0"]);
    assert_eq!(rows[6], ["6", "0", "1"]);
    // Vertex 2, (1, 1, 0), is sqrt(2) from vertex 0 and 1 from vertex 6, (1, 1, 1).
    let d2: f64 = rows[2][1].parse().expect("a number");
    assert!((d2 - 1.0).abs() < 1e-12);
    assert_eq!(rows[2][2], "1");
}

/// `--threads 2` (two sectors of the source's directions) gives the one-thread distances, and
/// `--threads 0` is refused.
#[test]
fn distance_on_two_threads_gives_the_one_thread_distances() {
    let column = |args: &[&str]| -> Vec<f64> {
        stdout(&run(args))
            .lines()
            .skip(1)
            .map(|l| {
                l.split(',')
                    .nth(1)
                    .expect("a distance")
                    .parse()
                    .expect("a number")
            })
            .collect()
    };
    let one = column(&["distance", "gen:icosphere:3", "--source", "v:7"]);
    let two = column(&[
        "distance",
        "gen:icosphere:3",
        "--source",
        "v:7",
        "--threads",
        "2",
    ]);
    assert_eq!(one.len(), 642);
    for (v, (a, b)) in one.iter().zip(&two).enumerate() {
        assert!((a - b).abs() <= 1e-12 * a.max(1.0), "v{v}: {a} and {b}");
    }
    refuses(
        &[
            "distance",
            "gen:icosphere:3",
            "--source",
            "v:7",
            "--threads",
            "0",
        ],
        &["--threads"],
    );
}

#[test]
fn unreachable_vertices_are_inf_with_empty_source() {
    // Two separate triangles and a vertex no face uses.
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nv 6 5 5\nv 5 6 5\nv 9 9 9\nf 1 2 3\nf 4 5 6\n";
    let path = temp_file("parts.obj", obj);
    let text = stdout(&run(&[
        "distance",
        path.to_str().expect("UTF-8 path"),
        "--source",
        "v:0",
    ]));
    let rows: Vec<&str> = text.lines().skip(1).collect();
    assert_eq!(rows.len(), 7);
    let d1: f64 = rows[1]
        .split(',')
        .nth(1)
        .expect("distance")
        .parse()
        .expect("a number");
    assert!(
        (d1 - 1.0).abs() < 1e-12 && rows[1].ends_with(",0"),
        "{}",
        rows[1]
    );
    for row in &rows[3..] {
        assert!(row.ends_with(",inf,"), "{row}");
    }
}

#[test]
fn max_distance_marks_farther_vertices_unreachable() {
    let text = stdout(&run(&[
        "distance",
        "gen:cube",
        "--source",
        "v:0",
        "--max-distance",
        "1.2",
    ]));
    let far: Vec<&str> = text.lines().filter(|l| l.contains(",inf,")).collect();
    assert_eq!(far.len(), 4, "{text}");
}

#[test]
fn path_json_length_equals_distance() {
    let text = stdout(&run(&[
        "path", "gen:cube", "--source", "v:0", "--target", "v:6",
    ]));
    let json: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let length = json["length"].as_f64().expect("length");
    let distance = json["distance"].as_f64().expect("distance");
    assert!((length - 5f64.sqrt()).abs() < 1e-12);
    assert!((distance - 5f64.sqrt()).abs() < 1e-12);
    assert_eq!(json["simplices"][0], "v:6");
    assert_eq!(
        json["simplices"]
            .as_array()
            .expect("list")
            .last()
            .expect("end"),
        "v:0"
    );
}

#[test]
fn path_obj_is_a_polyline() {
    let text = stdout(&run(&[
        "path",
        "gen:cube",
        "--source",
        "v:0",
        "--target",
        "f:4,0.2,0.3,0.5",
        "--format",
        "obj",
    ]));
    assert!(text.lines().any(|l| l.starts_with("l 1 2")));
}

#[test]
fn wedges_of_face_20_follow_the_paper_table_shape() {
    let text = stdout(&run(&[
        "wedges",
        "gen:paper-example-4",
        "--source",
        "v:2",
        "--face",
        "20",
    ]));
    assert!(
        text.contains("There are 2 wedges at edge (v5, v4):"),
        "{text}"
    );
    assert!(
        text.contains("There are 5 wedges at edge (v4, v13):"),
        "{text}"
    );
    assert!(
        text.contains("There are 3 wedges at edge (v13, v5):"),
        "{text}"
    );
    assert!(
        text.contains("(0.000, 0.976, 1.826, 2.799, true, v2, 0.000)"),
        "{text}"
    );
    assert!(
        text.contains("(0.000, 0.038, 0.000, 0.038, false, v4, 2.778)"),
        "{text}"
    );
}

#[test]
fn stats_json_reports_the_counters() {
    let text = stdout(&run(&["stats", "gen:icosphere:2", "--source", "v:0"]));
    let json: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    for key in [
        "vertices",
        "faces",
        "edges",
        "wedges",
        "wedges_per_edge",
        "edge_length",
        "eq2_cases",
        "propagation_seconds",
        "peak_queue",
        "wedge_memory_bytes",
    ] {
        assert!(!json[key].is_null(), "missing {key}");
    }
    assert_eq!(json["vertices"], 162);
    assert_eq!(json["coverage"]["has_overlaps"], false);
}

#[test]
fn missing_file_is_named() {
    fails_with(
        &["distance", "/nonexistent/mesh.obj", "--source", "v:0"],
        "/nonexistent/mesh.obj",
    );
}

#[test]
fn malformed_obj_names_file_and_line() {
    let path = temp_file("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n");
    fails_with(
        &["distance", path.to_str().expect("UTF-8"), "--source", "v:0"],
        "bad.obj:3",
    );
}

#[test]
fn nan_coordinate_names_the_line() {
    let path = temp_file("nan.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
    fails_with(
        &["distance", path.to_str().expect("UTF-8"), "--source", "v:0"],
        "nan.obj:2",
    );
}

#[test]
fn non_manifold_edge_is_named_in_a_warning_and_refused_when_strict() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
    let path = temp_file("fin.obj", obj);
    let p = path.to_str().expect("UTF-8");
    let out = run(&["distance", p, "--source", "v:2"]);
    let warnings = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(
        warnings.contains("1 edge(s) shared by more than two faces: (0, 1) with 3 faces"),
        "{warnings}"
    );
    // Three right isosceles pages with legs 1 along the spine (0, 1); unfolded flat, vertices
    // 3 and 4 lie at (0, -1) and vertex 2 at (0, 1): 2 apart, through vertex 0.
    let text = stdout(&out);
    let d: Vec<f64> = text
        .lines()
        .skip(1)
        .map(|l| {
            l.split(',')
                .nth(1)
                .expect("distance")
                .parse()
                .expect("number")
        })
        .collect();
    let root2 = 2f64.sqrt();
    for (got, want) in d.iter().zip([1.0, root2, 0.0, 2.0, 2.0]) {
        assert!((got - want).abs() < 1e-12, "{text}");
    }
    fails_with(&["distance", p, "--source", "v:0", "--strict"], "fin.obj:8");
}

#[test]
fn path_and_stats_cross_a_non_manifold_edge() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
    let path = temp_file("fin-path.obj", obj);
    let p = path.to_str().expect("UTF-8");
    // The point (0.6, 0, 0.2) of the standing page, turned flat, is (0.6, -0.2): the straight
    // line from vertex 2 at (0, 1) crosses the spine at x = 0.5, sqrt(1.8) long.
    let text = stdout(&run(&[
        "path",
        p,
        "--source",
        "v:2",
        "--target",
        "f:2,0.2,0.6,0.2",
        "--format",
        "csv",
    ]));
    let rows: Vec<&str> = text.lines().skip(1).collect();
    assert_eq!(rows.len(), 3, "{text}");
    let crossing: Vec<f64> = rows[1]
        .split(',')
        .skip(1)
        .take(3)
        .map(|c| c.parse().expect("number"))
        .collect();
    for (got, want) in crossing.iter().zip([0.5, 0.0, 0.0]) {
        assert!((got - want).abs() < 1e-12, "{text}");
    }
    let stats: serde_json::Value =
        serde_json::from_str(&stdout(&run(&["stats", p, "--source", "v:2"]))).expect("JSON");
    assert_eq!(stats["coverage"]["gaps_and_overlaps"], 0, "{stats}");
}

#[test]
fn quads_are_refused_unless_triangulated() {
    let obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    let path = temp_file("quad.obj", obj);
    let p = path.to_str().expect("UTF-8");
    fails_with(&["distance", p, "--source", "v:0"], "quad.obj:5");
    let text = stdout(&run(&["distance", p, "--source", "v:0", "--triangulate"]));
    assert_eq!(text.lines().count(), 5);
}

#[test]
fn out_of_range_and_malformed_sources_are_errors() {
    fails_with(
        &["distance", "gen:cube", "--source", "v:99"],
        "out of range",
    );
    fails_with(
        &["distance", "gen:cube", "--source", "f:0,0.5,0.5"],
        "bad point",
    );
    fails_with(
        &["distance", "gen:cube", "--source", "e:0,6,0.5"],
        "not joined",
    );
    fails_with(
        &["distance", "gen:cube", "--source", "e:0,1,1.5"],
        "not in [0, 1]",
    );
    fails_with(&["distance", "gen:cube", "--source", "q:1"], "bad point");
    fails_with(
        &["distance", "gen:no-such-shape", "--source", "v:0"],
        "unknown generated mesh",
    );
}

#[test]
fn every_backend_gives_the_same_distances_and_exact_reports_its_decisions() {
    let csv = |backend: &str| {
        stdout(&run(&[
            "distance",
            "gen:paper-example-4",
            "--source",
            "v:2",
            "--backend",
            backend,
        ]))
    };
    let parse = |text: String| -> Vec<f64> {
        text.lines()
            .skip(1)
            .map(|l| {
                l.split(',')
                    .nth(1)
                    .expect("distance")
                    .parse()
                    .expect("number")
            })
            .collect()
    };
    let f = parse(csv("f64"));
    for backend in ["adaptive", "exact"] {
        for (a, b) in parse(csv(backend)).iter().zip(&f) {
            assert!((a - b).abs() <= 1e-12 * b.max(1.0), "{backend}: {a} vs {b}");
        }
    }
    let stats = stdout(&run(&[
        "stats",
        "gen:paper-example-4",
        "--source",
        "v:2",
        "--backend",
        "exact",
    ]));
    let json: serde_json::Value = serde_json::from_str(&stats).expect("JSON");
    let decisions = &json["backend_decisions"];
    assert!(decisions["certified_zeros"].as_u64().expect("count") > 0);
    assert_eq!(decisions["uncertified"].as_u64(), Some(0));
    assert_eq!(
        decisions["decisions"].as_u64().expect("count"),
        [
            "by_filter",
            "by_refinement",
            "certified_zeros",
            "uncertified"
        ]
        .iter()
        .map(|k| decisions[*k].as_u64().expect("count"))
        .sum::<u64>()
    );
}

#[test]
fn compare_reports_example1_symmetric_wedges_case_by_case() {
    let text = stdout(&run(&["compare", "gen:paper-example-1", "--source", "v:0"]));
    for needle in [
        "vertex distances against exact",
        "edges whose final wedge counts differ",
        "wedge meetings decided differently from exact",
    ] {
        assert!(text.contains(needle), "{needle} in {text}");
    }
    let json = stdout(&run(&[
        "compare",
        "gen:paper-example-1",
        "--source",
        "v:0",
        "--format",
        "json",
    ]));
    let json: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let backends = json["backends"].as_array().expect("backends");
    assert_eq!(backends.len(), 3);
    // Example 1's w1 and w3 meet on e2 in f64 with infinitely many solutions (by its
    // tolerance). The exact backend knows w3 by its strip as w1 read the other way (the faces
    // between lie in the plane x = y) and drops the copy before eq. (2); it certifies every
    // decision, and its distances are f64's.
    assert_eq!(backends[0]["backend"], "f64");
    assert!(
        backends[0]["eq2_cases"]["infinite"]
            .as_u64()
            .expect("count")
            > 0
    );
    let exact = &backends[2];
    assert_eq!(exact["backend"], "exact");
    assert_eq!(exact["decisions"]["uncertified"].as_u64(), Some(0));
    for d in json["distance_vs_exact"].as_array().expect("differences") {
        assert!(d["max_relative"].as_f64().expect("number") < 1e-12);
    }
    // Every listed difference names the case exact chose and what f64 saw.
    for d in json["decisions_differ"].as_array().expect("list") {
        let f = &d["f64"];
        if !f.is_null() {
            assert_eq!(f["coefficients"].as_array().expect("A, B, C").len(), 3);
        }
    }
}

#[test]
fn distance_csv_writes_extreme_magnitudes_in_exponent_form() {
    // A right triangle with legs 1e-150: distances in shortest round-trip form, not 150 zeros.
    let obj = "v 0 0 0\nv 1e-150 0 0\nv 0 1e-150 0\nf 1 2 3\n";
    let path = temp_file("tiny.obj", obj);
    let text = stdout(&run(&[
        "distance",
        path.to_str().expect("utf-8"),
        "--source",
        "v:0",
    ]));
    let row = text.lines().nth(2).expect("vertex 1");
    let d: f64 = row
        .split(',')
        .nth(1)
        .expect("a distance")
        .parse()
        .expect("a number");
    assert!((d - 1e-150).abs() <= 1e-165, "{row}");
    assert!(row.len() < 40 && row.contains('e'), "{row}");
}
