//! The experiments of [LZT §6] (Tables 1-2): statistics against hand-computed values, the
//! `experiment` command's files and columns, and its agreement with `stats`.

mod common;

use common::cli::{fails_with, run, stdout};
use exact_geodesics::experiments::{
    count_wedges_in, min_angle_summary, normalize_to_unit_cube, random_sources, ModelShape,
    Summary, Table1Row, Table2Row,
};
use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::Backend;
use exact_geodesics::{propagate, PropagateOptions, SurfacePoint, TriMesh, VertexId};
use std::path::{Path, PathBuf};

const ALL_BACKENDS: [Backend; 3] = [Backend::F64, Backend::Adaptive, Backend::Exact];

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1.0)
}

fn out_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "exact-geodesics-experiments-{}-{name}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// The records of a CSV file without quoting (model names here have no commas).
fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).expect("the table was written");
    let mut lines = text.lines();
    let header = lines.next().expect("a header");
    let split = |l: &str| l.split(',').map(String::from).collect::<Vec<_>>();
    (split(header), lines.map(split).collect())
}

fn column(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}

#[test]
fn summary_of_hand_made_samples() {
    // 1..4: mean 5/2, population variance 5/4, symmetric.
    let s = Summary::of(&[4.0, 1.0, 3.0, 2.0]).expect("not empty");
    assert_eq!((s.count, s.mean, s.min, s.max), (4, 2.5, 1.0, 4.0));
    assert!(close(s.std, 1.25f64.sqrt()));
    assert_eq!(s.skewness, 0.0);
    // 0, 0, 0, 1: m2 = 3/16, m3 = 3/32, skewness 2/sqrt(3) (right tail).
    let s = Summary::of(&[0.0, 0.0, 0.0, 1.0]).expect("not empty");
    assert!(close(s.skewness, 2.0 / 3f64.sqrt()));
    assert!(close(s.std, (3.0f64 / 16.0).sqrt()));
}

#[test]
fn normalization_undoes_a_uniform_scale_and_translation() {
    let cube = shapes::cube();
    let moved: Vec<[f64; 3]> = cube
        .positions()
        .iter()
        .map(|p| [4.0 * p[0] - 3.0, 4.0 * p[1] + 0.5, 4.0 * p[2] + 8.0])
        .collect();
    let moved = TriMesh::new(moved, cube.faces().to_vec()).expect("valid");
    let unit = normalize_to_unit_cube(&moved).expect("has extent");
    assert_eq!(unit.positions(), cube.positions());
    assert_eq!(unit.faces(), cube.faces());
}

#[test]
fn normalization_scales_by_the_largest_side_only() {
    let cube = shapes::cube();
    let box_ = cube
        .positions()
        .iter()
        .map(|p| [2.0 * p[0], p[1], p[2]])
        .collect();
    let unit = normalize_to_unit_cube(&TriMesh::new(box_, cube.faces().to_vec()).expect("valid"))
        .expect("has extent");
    for (p, q) in unit.positions().iter().zip(cube.positions()) {
        assert_eq!(*p, [q[0], q[1] / 2.0, q[2] / 2.0]);
    }
}

#[test]
fn normalization_refuses_a_mesh_without_extent() {
    let flat = TriMesh::new(vec![[1.0, 2.0, 3.0]; 3], vec![[0, 1, 2]]).expect("valid");
    let err = normalize_to_unit_cube(&flat).expect_err("no extent");
    assert!(err.to_string().contains("no extent"), "{err}");
}

#[test]
fn table2_edge_lengths_of_the_unit_cube_by_hand() {
    // gen:cube is [0,1]^3 already: 12 sides of length 1 and 6 face diagonals of length sqrt 2.
    let shape = ModelShape::of(&normalize_to_unit_cube(&shapes::cube()).expect("has extent"));
    let r2 = 2f64.sqrt();
    let mean = (12.0 + 6.0 * r2) / 18.0;
    let std = ((12.0 + 6.0 * 2.0) / 18.0 - mean * mean).sqrt();
    // Third central moment: 12 (1 - mean)^3 + 6 (r2 - mean)^3, over 18.
    let m3 = (12.0 * (1.0 - mean).powi(3) + 6.0 * (r2 - mean).powi(3)) / 18.0;
    let l = shape.edge_length;
    assert_eq!((l.count, l.min, l.max), (18, 1.0, r2));
    assert!(close(l.mean, mean) && close(l.std, std));
    assert!(close(l.skewness, m3 / std.powi(3)));
    // Every face is a right isosceles triangle.
    assert!(close(shape.min_angle.max, 45.0) && close(shape.min_angle.min, 45.0));
}

#[test]
fn uniformity_of_the_icosahedron_is_sixty_degrees() {
    let s = min_angle_summary(&shapes::icosahedron());
    assert!(close(s.max, 60.0) && close(s.min, 60.0) && s.std < 1e-9);
}

#[test]
fn cube_from_corner_0_has_one_wedge_per_edge_but_two_on_the_mirror_diagonal() {
    // From v0 = (0,0,0) the cube has no pseudo-source (every corner is convex), so every edge
    // is covered by straight lines from v0 unfolded along one face sequence. The diagonal
    // v2-v7 of the face y = 1 lies on the mirror plane x = z through v0: its half near v2 is
    // reached over the bottom face z = 0, its half near v7 over the face x = 0, so it holds
    // two wedges that meet at its midpoint. 17 edges x 1 + 2 = 19.
    let cube = shapes::cube();
    let diagonal = cube
        .edge_between(VertexId(2), VertexId(7))
        .expect("the diagonal of face y = 1");
    for backend in ALL_BACKENDS {
        let counts = count_wedges_in(backend, &cube, VertexId(0), |_| {}).expect("a vertex");
        assert_eq!(counts.total, 19, "{backend:?}");
        assert_eq!(counts.edges_without_wedges, 0);
        // Half of 19 wedges: the diagonal's 2 and 8 single ones, 9 of the 18 edges.
        assert!(close(counts.edges_holding_half, 9.0 / 18.0), "{backend:?}");
        let w = counts.per_edge;
        assert_eq!((w.count, w.min, w.max), (18, 1.0, 2.0), "{backend:?}");
        assert!(close(w.mean, 19.0 / 18.0));
        // 17 values 1 and one 2: variance 17/18^2.
        assert!(close(w.std, 17f64.sqrt() / 18.0));
    }
    let field = propagate::<f64>(
        &cube,
        &[SurfacePoint::Vertex(VertexId(0))],
        &PropagateOptions::default(),
    )
    .expect("a vertex");
    let wedges = field.wedges(diagonal);
    assert_eq!(wedges.len(), 2);
    assert!(close(wedges[0].b1, 2f64.sqrt() / 2.0));
}

#[test]
fn random_sources_are_distinct_used_vertices_and_seeded() {
    let mesh = shapes::icosphere(2);
    let picked = random_sources(&mesh, 5, 42);
    assert_eq!(picked, random_sources(&mesh, 5, 42));
    assert_ne!(picked, random_sources(&mesh, 5, 43));
    let mut sorted = picked.clone();
    sorted.sort();
    sorted.dedup();
    assert_eq!(sorted.len(), 5);
    // A vertex no face uses is never drawn.
    let mut positions = shapes::cube().positions().to_vec();
    positions.push([9.0, 9.0, 9.0]);
    let loose = TriMesh::new(positions, shapes::cube().faces().to_vec()).expect("valid");
    let all = random_sources(&loose, 100, 1);
    assert_eq!(all.len(), 8);
    assert!(all.iter().all(|v| v.0 < 8));
}

#[test]
fn table_rows_carry_the_counts_and_the_ratio() {
    let unit = normalize_to_unit_cube(&shapes::icosphere(1)).expect("has extent");
    let shape = ModelShape::of(&unit);
    let counts = count_wedges_in(Backend::Adaptive, &unit, VertexId(3), |_| {}).expect("ok");
    let t1 = Table1Row::new("ico", Backend::Adaptive, &shape, &counts);
    let t2 = Table2Row::new("ico", Backend::Adaptive, &shape, &counts);
    assert_eq!((t1.source, t1.faces, t1.edges), (3, 80, 120));
    assert_eq!(t1.wedges_mean, t2.wedges_mean);
    assert!(close(
        t2.wedges_per_unit_length,
        t1.wedges_mean / t2.edge_length_mean
    ));
    assert!(t1.csv_record().starts_with("ico,adaptive,3,80,120,"));
    assert_eq!(
        t1.csv_record().split(',').count(),
        Table1Row::CSV_HEADER.split(',').count()
    );
    assert_eq!(
        t2.csv_record().split(',').count(),
        Table2Row::CSV_HEADER.split(',').count()
    );
}

const TABLE1_COLUMNS: [&str; 9] = [
    "model",
    "backend",
    "source",
    "faces",
    "edges",
    "wedges_mean",
    "wedges_std",
    "wedges_max",
    "seconds",
];
const TABLE2_COLUMNS: [&str; 8] = [
    "model",
    "backend",
    "source",
    "edge_length_mean",
    "edge_length_std",
    "edge_length_max",
    "edge_length_min",
    "wedges_per_unit_length",
];

#[test]
fn cli_table1_writes_csv_and_json_with_one_row_per_model_backend_and_source() {
    let dir = out_dir("t1");
    let d = dir.to_str().expect("UTF-8 path");
    stdout(&run(&[
        "experiment",
        "table1",
        "gen:cube",
        "gen:icosphere:2",
        "--backend",
        "f64,adaptive",
        "--sources",
        "3",
        "--seed",
        "5",
        "--out",
        d,
    ]));
    let (header, rows) = read_csv(&dir.join("table1.csv"));
    assert_eq!(header[..9], TABLE1_COLUMNS);
    assert_eq!(rows.len(), 2 * 2 * 3);
    let models: Vec<&str> = rows.iter().map(|r| r[0].as_str()).collect();
    assert_eq!(models[0], "gen:cube");
    assert_eq!(models[11], "gen:icosphere:2");
    assert_eq!(rows[3][1], "adaptive");
    assert_eq!(rows[6][3..5], ["320", "480"]);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("table1.json")).expect("written"))
            .expect("JSON");
    let json = json.as_array().expect("an array of rows");
    assert_eq!(json.len(), rows.len());
    for (value, row) in json.iter().zip(&rows) {
        assert_eq!(value["source"].to_string(), row[2]);
        assert_eq!(value["backend"], row[1].as_str());
        let mean: f64 = row[5].parse().expect("a number");
        assert_eq!(value["wedges_mean"].as_f64(), Some(mean));
    }
}

#[test]
fn cli_table2_ratio_is_mean_wedges_over_mean_length() {
    let dir = out_dir("t2");
    let d = dir.to_str().expect("UTF-8 path");
    stdout(&run(&[
        "experiment",
        "table2",
        "gen:icosphere:2",
        "--backend",
        "f64",
        "--backend",
        "adaptive",
        "--sources",
        "2",
        "--out",
        d,
    ]));
    let (header, rows) = read_csv(&dir.join("table2.csv"));
    assert_eq!(header[..8], TABLE2_COLUMNS);
    assert_eq!(rows.len(), 4);
    let (ratio, wedges, length) = (
        column(&header, "wedges_per_unit_length"),
        column(&header, "wedges_mean"),
        column(&header, "edge_length_mean"),
    );
    for row in &rows {
        let num = |i: usize| row[i].parse::<f64>().expect("a number");
        assert!(close(num(ratio), num(wedges) / num(length)));
        // The icosphere spans [-1, 1]: normalized, its lengths halve; all below 1.
        assert!(num(column(&header, "edge_length_max")) < 1.0);
    }
    assert!(dir.join("table2.json").is_file());
}

#[test]
fn cli_table1_agrees_with_stats_for_the_same_model_and_source() {
    // gen:cube is already in the unit cube, so normalization leaves it unchanged.
    let dir = out_dir("agree");
    let d = dir.to_str().expect("UTF-8 path");
    stdout(&run(&[
        "experiment",
        "table1",
        "gen:cube",
        "--sources",
        "4",
        "--out",
        d,
    ]));
    let (header, rows) = read_csv(&dir.join("table1.csv"));
    for row in rows {
        let source = &row[column(&header, "source")];
        let stats: serde_json::Value = serde_json::from_str(&stdout(&run(&[
            "stats",
            "gen:cube",
            "--source",
            &format!("v:{source}"),
        ])))
        .expect("JSON");
        let per_edge = &stats["wedges_per_edge"];
        for (col, key) in [
            ("wedges_mean", "mean"),
            ("wedges_std", "std"),
            ("wedges_max", "max"),
        ] {
            let ours: f64 = row[column(&header, col)].parse().expect("a number");
            assert_eq!(Some(ours), per_edge[key].as_f64(), "{col} from v{source}");
        }
        let total = &row[column(&header, "wedges_total")];
        assert_eq!(stats["wedges"].to_string(), *total);
    }
}

#[test]
fn cli_errors_name_the_file_and_exit_non_zero() {
    let dir = out_dir("err");
    fails_with(
        &[
            "experiment",
            "table1",
            "no-such-model.obj",
            "--out",
            dir.to_str().expect("UTF-8"),
        ],
        "no-such-model.obj",
    );
}

/// The shared Table 1 models, when this machine has them.
fn paper_table1_model(name: &str) -> Option<PathBuf> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/models/paper-table1")
        .join(name);
    if path.is_file() {
        Some(path)
    } else {
        eprintln!("skipped: {} is absent", path.display());
        None
    }
}

#[test]
fn paper_table1_sphere_uniform_edge_lengths_match_its_readme() {
    // README of ../shared/models/paper-table1: mean / std / min / max = 0.0620 / 0.0073 /
    // 0.0440 / 0.0847, computed there by other code (Python) on the same file.
    let Some(path) = paper_table1_model("sphere_uniform.obj") else {
        return;
    };
    let dir = out_dir("sphere");
    stdout(&run(&[
        "experiment",
        "table2",
        path.to_str().expect("UTF-8"),
        "--sources",
        "1",
        "--out",
        dir.to_str().expect("UTF-8"),
    ]));
    let (header, rows) = read_csv(&dir.join("table2.csv"));
    let num = |c: &str| {
        rows[0][column(&header, c)]
            .parse::<f64>()
            .expect("a number")
    };
    for (col, want) in [
        ("edge_length_mean", 0.0620),
        ("edge_length_std", 0.0073),
        ("edge_length_min", 0.0440),
        ("edge_length_max", 0.0847),
    ] {
        assert!((num(col) - want).abs() <= 0.00005, "{col}: {}", num(col));
    }
}
