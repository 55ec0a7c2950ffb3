//! The experiments of [LZT §6] (Tables 1-2, Observations 1-3): statistics against
//! hand-computed values, the `experiment` command's files and columns, and its agreement with
//! `stats`.

mod common;

#[cfg(feature = "cli")]
use common::cli::{fails_with, run, stdout};
use exact_geodesics::experiments::{
    count_wedges_in, fit_resolution, measure_in, min_angle_summary, normalize_to_unit_cube,
    random_sources, scale_factor, scale_uniformly, ModelShape, ResolutionRow, ScaleRow, Summary,
    Table1Row, Table2Row,
};
use exact_geodesics::glam::DVec3;
use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::Backend;
use exact_geodesics::{propagate, PropagateOptions, SurfacePoint, TriMesh, VertexId};
#[cfg(feature = "cli")]
use std::path::{Path, PathBuf};

const ALL_BACKENDS: [Backend; 3] = [Backend::F64, Backend::Adaptive, Backend::Exact];

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1.0)
}

#[cfg(feature = "cli")]
fn out_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "exact-geodesics-experiments-{}-{name}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[cfg(feature = "cli")]
/// The records of a CSV file without quoting (model names here have no commas).
fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).expect("the table was written");
    let mut lines = text.lines();
    let header = lines.next().expect("a header");
    let split = |l: &str| l.split(',').map(String::from).collect::<Vec<_>>();
    (split(header), lines.map(split).collect())
}

#[cfg(feature = "cli")]
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
        .map(|&p| p * DVec3::new(2.0, 1.0, 1.0))
        .collect();
    let unit = normalize_to_unit_cube(&TriMesh::new(box_, cube.faces().to_vec()).expect("valid"))
        .expect("has extent");
    for (p, q) in unit.positions().iter().zip(cube.positions()) {
        assert_eq!(*p, *q / DVec3::new(1.0, 2.0, 2.0));
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
    positions.push(DVec3::splat(9.0));
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
    assert_eq!(t1.seconds, t2.seconds);
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

#[test]
fn observation3_a_power_of_two_scale_changes_nothing_in_any_backend() {
    // Multiplying every coordinate by 2^k is exact, and so is every sum, product, quotient and
    // square root the engine forms from them (up to the same power of two), as long as nothing
    // under- or overflows: a backend whose decisions were absolute (an epsilon in model units)
    // would change its wedges with k; ours must not. (The exact backend, slow, on the cube.)
    for backend in ALL_BACKENDS {
        let model = match backend {
            Backend::Exact => shapes::cube(),
            _ => shapes::icosphere(2),
        };
        let unit = normalize_to_unit_cube(&model).expect("has extent");
        let reference = measure_in(backend, &unit, VertexId(5), |_| {}).expect("a vertex");
        for k in [-30, 9, 40] {
            let mesh = scale_uniformly(&unit, scale_factor(2, k)).expect("in range");
            let scaled = measure_in(backend, &mesh, VertexId(5), |_| {}).expect("a vertex");
            let row = ScaleRow::new("ico", backend, 2, k, &reference, &scaled);
            assert_eq!(row.edges_changed, 0, "{backend:?} at 2^{k}");
            assert_eq!(scaled.eq2, reference.eq2, "{backend:?} at 2^{k}");
            assert_eq!(row.distance_max_difference, 0.0, "{backend:?} at 2^{k}");
            assert_eq!(row.wedges_total, reference.counts.total);
        }
    }
}

#[test]
fn observation3_scale_row_compares_distances_in_the_reference_units() {
    // Scaling the unit cube by 10 and comparing with itself: distances divided by 10 are the
    // reference's to rounding, and their sum from corner 0 is, by hand, 3 corners at 1, 3 at
    // sqrt 2 and the far one at sqrt 5 (over two faces).
    let cube = shapes::cube();
    let reference = measure_in(Backend::F64, &cube, VertexId(0), |_| {}).expect("a vertex");
    let ten = scale_uniformly(&cube, 10.0).expect("in range");
    let scaled = measure_in(Backend::F64, &ten, VertexId(0), |_| {}).expect("a vertex");
    let row = ScaleRow::new("cube", Backend::F64, 10, 1, &reference, &scaled);
    assert_eq!((row.scale, row.edges, row.wedges_total), (10.0, 18, 19));
    assert!(close(
        row.distance_sum,
        3.0 + 3.0 * 2f64.sqrt() + 5f64.sqrt()
    ));
    assert!(row.distance_max_difference < 1e-15);
    assert_eq!(
        row.csv_record().split(',').count(),
        ScaleRow::CSV_HEADER.split(',').count()
    );
    assert!(scale_uniformly(&cube, 0.0).is_err());
    assert!(scale_uniformly(&cube, f64::INFINITY).is_err());
}

#[test]
fn observation3_fit_averages_sources_then_fits_the_exponent() {
    // Two sources per level with w = 1/l and 3/l at l = 2^-k: the mean is w = 2/l, so
    // w/l = 2 l^-2: exponent -2 and intercept ln 2 (averaging logarithms would give ln sqrt 3).
    let rows: Vec<ResolutionRow> = (1..=4u32)
        .flat_map(|level| {
            let l = 0.5f64.powi(level as i32);
            [1.0, 3.0].map(|w| ResolutionRow {
                series: "s".into(),
                model: format!("m{level}"),
                level,
                backend: Backend::F64,
                source: w as u32,
                faces: 0,
                edges: 0,
                edge_length_mean: l,
                wedges_mean: w / l,
                wedges_per_unit_length: w / l / l,
                uncertified: 0,
            })
        })
        .collect();
    let fits = fit_resolution(&rows);
    assert_eq!(fits.len(), 1);
    assert_eq!(fits[0].points.len(), 4);
    assert_eq!(fits[0].points[0].wedges_mean, 4.0);
    let fit = fits[0].fit.expect("four levels");
    assert!((fit.slope + 2.0).abs() < 1e-12, "{}", fit.slope);
    assert!(
        (fit.intercept - 2f64.ln()).abs() < 1e-12,
        "{}",
        fit.intercept
    );
    assert!(fit.slope_std_error < 1e-12);
    assert!(fits[0].csv_record().starts_with("s,f64,4,"));
}

#[test]
fn observation3_refinement_keeps_the_surface() {
    // Midpoint subdivision adds flat vertices only: from corner 0 of the cube subdivided twice
    // the far corner is still at sqrt 5, and the centre (0.5, 0.5, 1) of the top face, with
    // the side y = 0 and the top unfolded into one plane, at |(0.5, 1.5)| = sqrt 2.5.
    let fine = shapes::subdivide(&shapes::subdivide(&shapes::cube()));
    assert_eq!((fine.face_count(), fine.vertex_count()), (192, 98));
    let field = propagate::<f64>(
        &fine,
        &[SurfacePoint::Vertex(VertexId(0))],
        &PropagateOptions::default(),
    )
    .expect("a vertex");
    assert!(close(field.vertex_distance(VertexId(6)), 5f64.sqrt()));
    let centre = (0..fine.vertex_count() as u32)
        .find(|&v| fine.positions()[v as usize] == DVec3::new(0.5, 0.5, 1.0))
        .expect("the centre of the top face is a vertex after two subdivisions");
    assert!(close(
        field.vertex_distance(VertexId(centre)),
        2.5f64.sqrt()
    ));
}

#[cfg(feature = "cli")]
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
#[cfg(feature = "cli")]
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
#[cfg(feature = "cli")]
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
    // Observations 1 and 2: a histogram per model and the distributions together (f64 only).
    for plot in [
        "table1_wedges_0_gen_cube.svg",
        "table1_wedges_1_gen_icosphere_2.svg",
        "table1_distributions.svg",
    ] {
        let svg = std::fs::read_to_string(dir.join(plot)).expect("the plot was written");
        assert!(svg.starts_with("<svg") && svg.contains("w(e)"), "{plot}");
    }
    assert!(!dir.join("table1_wedges_2_gen_cube.svg").exists());
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
#[cfg(feature = "cli")]
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
#[cfg(feature = "cli")]
fn cli_table1_agrees_with_stats_and_wedges_for_the_same_model_source_and_backend() {
    // Both models lie in the unit cube already, so normalization leaves them unchanged. The
    // cube has 19 wedges from a corner, up to 2 on an edge; the flat grid, one region lit by
    // one image of the source, has 1 on every edge it reaches (issue 13; up to 3 before).
    for (model, backend, most) in [("gen:cube", "f64", 2.0), ("gen:grid:8,8", "adaptive", 1.0)] {
        let dir = out_dir("agree");
        let d = dir.to_str().expect("UTF-8 path");
        stdout(&run(&[
            "experiment",
            "table1",
            model,
            "--backend",
            backend,
            "--sources",
            "4",
            "--out",
            d,
        ]));
        let json: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(dir.join("table1.json")).expect("written"),
        )
        .expect("JSON");
        let rows = json.as_array().expect("an array of rows");
        assert_eq!(rows.len(), 4);
        let mut largest = 0.0f64;
        for row in rows {
            let source = &row["source"];
            let stats: serde_json::Value = serde_json::from_str(&stdout(&run(&[
                "stats",
                model,
                "--backend",
                backend,
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
                let ours = row[col].as_f64();
                assert_eq!(ours, per_edge[key].as_f64(), "{model} {col} from v{source}");
            }
            assert_eq!(
                stats["wedges"], row["wedges_total"],
                "{model} from v{source}"
            );
            // The `wedges` command lists every edge's final wedges: w(e) counted by hand.
            let listed: serde_json::Value = serde_json::from_str(&stdout(&run(&[
                "wedges",
                model,
                "--backend",
                backend,
                "--source",
                &format!("v:{source}"),
                "--format",
                "json",
            ])))
            .expect("JSON");
            let w: Vec<usize> = listed
                .as_array()
                .expect("an array of edges")
                .iter()
                .map(|e| e["wedges"].as_array().expect("wedges").len())
                .filter(|&n| n > 0)
                .collect();
            let edges = row["edges"].as_u64().expect("a count") as usize;
            assert_eq!(row["wedges_total"], w.iter().sum::<usize>());
            assert_eq!(row["wedges_max"], *w.iter().max().expect("a wedge") as f64);
            assert_eq!(row["edges_without_wedges"], edges - w.len());
            largest = largest.max(row["wedges_max"].as_f64().expect("a number"));
        }
        assert_eq!(largest, most, "{model}");
    }
}

#[cfg(feature = "cli")]
const SCALE_COLUMNS: [&str; 6] = [
    "model",
    "backend",
    "source",
    "scale_exponent",
    "wedges_mean",
    "distance_max_difference",
];
#[cfg(feature = "cli")]
const RESOLUTION_COLUMNS: [&str; 6] = [
    "series",
    "model",
    "level",
    "edge_length_mean",
    "wedges_mean",
    "wedges_per_unit_length",
];

#[test]
#[cfg(feature = "cli")]
fn cli_observation3_writes_the_scale_and_resolution_series_and_the_fits() {
    let dir = out_dir("o3");
    let d = dir.to_str().expect("UTF-8 path");
    stdout(&run(&[
        "experiment",
        "observation3",
        "gen:cube",
        "--levels",
        "3",
        "--refinements",
        "2",
        "--scale-exponents=-3,0,3",
        "--scale-base",
        "2",
        "--sources",
        "1",
        "--backend",
        "f64,adaptive",
        "--out",
        d,
    ]));
    let (header, rows) = read_csv(&dir.join("observation3_scale.csv"));
    for c in SCALE_COLUMNS {
        column(&header, c);
    }
    // 3 powers of two x 2 backends x 1 source; exact scales change nothing.
    assert_eq!(rows.len(), 6);
    for row in &rows {
        assert_eq!(row[column(&header, "edges_changed")], "0");
        assert_eq!(row[column(&header, "distance_max_difference")], "0e0");
    }
    let (header, rows) = read_csv(&dir.join("observation3_resolution.csv"));
    for c in RESOLUTION_COLUMNS {
        column(&header, c);
    }
    // Icospheres 1..3 and grids 4, 8, 16 (quoted names: "gen:grid:4,4" has a comma, so count
    // lines by their series) and the cube refined 0..2 times, in 2 backends.
    let series = |name: &str| rows.iter().filter(|r| r[0] == name).count();
    assert_eq!(series("icosphere"), 3 * 2);
    assert_eq!(series("grid"), 3 * 2);
    assert_eq!(series("refined:gen:cube"), 3 * 2);
    let refined: Vec<&Vec<String>> = rows.iter().filter(|r| r[0] == "refined:gen:cube").collect();
    assert_eq!(refined[0][1], "gen:cube@0");
    let last = refined[5];
    assert_eq!((last[1].as_str(), last[2].as_str()), ("gen:cube@2", "2"));
    assert_eq!((last[3].as_str(), last[5].as_str()), ("adaptive", "192"));
    let (header, fits) = read_csv(&dir.join("observation3_fit.csv"));
    assert_eq!(fits.len(), 3 * 2);
    for fit in &fits {
        let num = |c: &str| {
            fit[column(&header, c)]
                .parse::<f64>()
                .expect("a fitted number")
        };
        assert_eq!(fit[column(&header, "levels")], "3");
        assert!(num("ci95_low") <= num("exponent") && num("exponent") <= num("ci95_high"));
    }
    let json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("observation3.json")).expect("written"),
    )
    .expect("JSON");
    assert_eq!(json["fits"].as_array().map(Vec::len), Some(6));
    for plot in ["observation3_scale.svg", "observation3_resolution.svg"] {
        let svg = std::fs::read_to_string(dir.join(plot)).expect("the plot was written");
        assert!(svg.starts_with("<svg"), "{plot}");
    }
    assert!(
        std::fs::read_to_string(dir.join("observation3_resolution.svg"))
            .expect("written")
            .contains("exponent")
    );
}

#[test]
#[cfg(feature = "cli")]
fn cli_observation3_runs_only_the_series_asked_for() {
    let dir = out_dir("o3-grid");
    stdout(&run(&[
        "experiment",
        "observation3",
        "gen:cube",
        "--series",
        "grid",
        "--levels",
        "3",
        "--scale-exponents",
        "0",
        "--sources",
        "1",
        "--out",
        dir.to_str().expect("UTF-8"),
    ]));
    let (_, fits) = read_csv(&dir.join("observation3_fit.csv"));
    assert_eq!(fits.len(), 1);
    assert_eq!(fits[0][..3], ["grid", "f64", "3"]);
}

#[test]
#[cfg(feature = "cli")]
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
#[cfg(feature = "cli")]
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
#[cfg(feature = "cli")]
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
