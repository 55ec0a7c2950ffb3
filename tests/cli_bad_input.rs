//! Bad input to the command line (issue 10): every malformed, out-of-range or absurd input gets
//! a message naming the file and line, or the value, and exit code 1 (2 for a malformed command
//! line); never a panic (101), a hang or a silently changed input.

// The command line is built with the `cli` feature only.
#![cfg(feature = "cli")]
mod common;

use common::cli::{refuses, run, stdout, temp_file};

#[test]
fn barycentric_coordinates_near_f64_max_are_refused_not_a_panic() {
    refuses(
        &["distance", "gen:cube", "--source", "f:0,1e308,1e308,0"],
        &[
            "f:0,1e308,1e308,0",
            "gen:cube",
            "must sum to 1",
            "sum to inf",
        ],
    );
}

#[test]
fn barycentric_coordinates_must_sum_to_one_on_the_command_line() {
    refuses(
        &["distance", "gen:cube", "--source", "f:0,0.2,0.2,0.2"],
        &[
            "f:0,0.2,0.2,0.2",
            "must sum to 1 (within 1e-9)",
            "sum to 0.6",
        ],
    );
    refuses(
        &[
            "path",
            "gen:cube",
            "--source",
            "v:0",
            "--target",
            "f:0,1,1,1",
        ],
        &["f:0,1,1,1", "sum to 3"],
    );
    // Within the tolerance, rounding in typed decimals is accepted.
    let text = stdout(&run(&[
        "distance",
        "gen:cube",
        "--source",
        "f:0,0.3333333333,0.3333333333,0.3333333334",
    ]));
    assert_eq!(text.lines().count(), 9);
}

#[test]
fn precision_cap_below_the_first_exact_precision_is_refused() {
    for cap in ["0", "127", "1048577"] {
        refuses(
            &[
                "distance",
                "gen:cube",
                "--source",
                "v:0",
                "--backend",
                "exact",
                "--precision-cap",
                cap,
            ],
            &["--precision-cap", cap, "128..=1048576"],
        );
    }
}

#[test]
fn empty_mesh_files_are_refused_naming_the_file() {
    let ply_header = "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n";
    for (name, text) in [
        ("empty.obj", ""),
        ("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
        ("empty.off", "OFF\n0 0 0\n"),
        ("empty.ply", ply_header),
    ] {
        let path = temp_file(name, text.as_bytes());
        refuses(
            &["distance", path.to_str().expect("UTF-8"), "--source", "v:0"],
            &[&format!("{name}: the mesh has no faces")],
        );
    }
}

#[test]
fn meshes_beyond_the_float_range_are_refused_by_the_float_backends() {
    let path = temp_file("z308.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 1e308\nf 1 2 3\n");
    let mesh = path.to_str().expect("UTF-8");
    for backend in ["f64", "adaptive"] {
        refuses(
            &["distance", mesh, "--source", "v:0", "--backend", backend],
            &["shorter than 2^-500", "use the exact backend"],
        );
    }
    let out = stdout(&run(&[
        "distance",
        mesh,
        "--source",
        "v:0",
        "--backend",
        "exact",
    ]));
    assert!(out.contains("\n1,1,0\n"), "{out}");
}

#[test]
fn generated_meshes_of_absurd_size_are_refused_before_building() {
    for (shape, needle) in [
        (
            "gen:grid:100000000,100000000",
            "NX = 100000000 is not in 1..=1048576",
        ),
        ("gen:grid:2000,2000", "would have 8000000 faces"),
        ("gen:icosphere:40", "K = 40 is not in 0..=8"),
        ("gen:grid:0,0", "NX = 0 is not in 1..=1048576"),
        // Were clamped or raised silently.
        (
            "gen:convex:1,3,1000000",
            "INTERIOR = 1000000 is not in 0..=10000",
        ),
        ("gen:convex:1,2,5", "BOUNDARY = 2 is not in 3..=10000"),
        ("gen:grid:-1,2", "expected `grid:NX,NY` (whole numbers)"),
    ] {
        refuses(&["distance", shape, "--source", "v:0"], &[needle]);
    }
}

#[test]
fn max_distance_must_be_a_non_negative_number() {
    for bad in ["nan", "-1", "-inf", "far"] {
        refuses(
            &[
                "distance",
                "gen:cube",
                "--source",
                "v:0",
                "--max-distance",
                bad,
            ],
            &["--max-distance", bad, "non-negative"],
        );
    }
    let text = stdout(&run(&[
        "distance",
        "gen:cube",
        "--source",
        "v:0",
        "--max-distance",
        "inf",
    ]));
    assert!(
        !text.contains("inf"),
        "no limit: every vertex reached\n{text}"
    );
}

#[test]
fn out_of_range_edges_faces_and_targets_name_the_value_and_the_mesh() {
    let cube = ["gen:cube", "--source", "v:0"];
    let with = |command: &str, extra: &[&'static str]| -> Vec<String> {
        let mut args = vec![command.to_owned()];
        args.extend(cube.iter().chain(extra).map(|s| s.to_string()));
        args
    };
    for (args, needles) in [
        (
            with("wedges", &["--edge", "0,999"]),
            vec!["--edge 0,999", "gen:cube"],
        ),
        (
            with("wedges", &["--edge", "0,6"]),
            vec!["--edge 0,6", "no edge"],
        ),
        (
            with("wedges", &["--face", "99"]),
            vec!["--face 99", "gen:cube has 12 faces"],
        ),
        (
            with("subdivision", &["--face", "99"]),
            vec!["--face 99", "12 faces"],
        ),
        (
            with("path", &["--target", "v:999"]),
            vec!["'v:999' on gen:cube", "out of range"],
        ),
        (
            with("path", &["--target", "f:99,1,0,0"]),
            vec!["'f:99,1,0,0'", "face 99"],
        ),
    ] {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        refuses(&args, &needles);
    }
}

/// Every bad input of issue 10, each refused with exit code 1 or 2 and a message naming the file
/// and line or the value; exit code 101 (a panic) fails the test.
#[test]
fn bad_input_is_refused_with_a_message_never_a_panic() {
    let file = |name: &str, text: &[u8]| -> String {
        let path = temp_file(name, text);
        path.to_str().expect("UTF-8").to_owned()
    };
    let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    let ply_header = |format: &str, vertices: &str| {
        format!("ply\nformat {format} 1.0\nelement vertex {vertices}\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n")
    };
    let mut cases: Vec<(String, String, Vec<String>)> = Vec::new();
    let mut mesh = |name: &str, text: &[u8], needles: &[&str]| {
        let path = file(name, text);
        let mut needles: Vec<String> = needles.iter().map(|s| s.to_string()).collect();
        needles.push(name.to_owned());
        cases.push((path, "v:0".to_owned(), needles));
    };
    mesh("empty.obj", b"", &["no faces"]);
    mesh("short-vertex.obj", b"v 0 0\n", &[":1:", "x, y and z"]);
    mesh(
        "two-corners.obj",
        format!("{tri}f 1 2\n").as_bytes(),
        &[":4:", "3 corners"],
    );
    mesh(
        "zero-index.obj",
        format!("{tri}f 0 1 2\n").as_bytes(),
        &[":4:"],
    );
    mesh(
        "negative-index.obj",
        format!("{tri}f -5 1 2\n").as_bytes(),
        &[":4:", "-5"],
    );
    mesh(
        "huge-index.obj",
        format!("{tri}f 99999999999 1 2\n").as_bytes(),
        &[":4:"],
    );
    mesh(
        "past-end.obj",
        format!("{tri}f 1 2 4\n").as_bytes(),
        &[":4:", "vertex 3"],
    );
    mesh(
        "nan.obj",
        b"v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        &[":1:", "non-finite"],
    );
    mesh(
        "inf.obj",
        b"v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n",
        &[":2:", "non-finite"],
    );
    mesh("empty.off", b"OFF\n0 0 0\n", &["no faces"]);
    mesh(
        "huge.off",
        b"OFF\n1000000000000 1000000000000 0\n0 0 0\n",
        &[":3:", "1000000000000"],
    );
    mesh("negative-count.off", b"OFF\n-3 1\n", &[":2:", "-3"]);
    mesh(
        "negative-index.off",
        b"OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n",
        &[":6:", "-2"],
    );
    mesh(
        "lying-corners.off",
        b"OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n4294967295 0 1 2\n",
        &[":6:"],
    );
    mesh(
        "huge.ply",
        ply_header("binary_little_endian", "1000000000000").as_bytes(),
        &["binary vertex element 0"],
    );
    mesh(
        "huge-ascii.ply",
        format!("{}0 0 0\n", ply_header("ascii", "1000000000000")).as_bytes(),
        &[":10:", "1000000000000"],
    );
    mesh(
        "negative-index.ply",
        format!(
            "{}0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n",
            ply_header("ascii", "3")
        )
        .as_bytes(),
        &[":13:", "-1"],
    );
    mesh(
        "nan.ply",
        format!(
            "{}0 nan 0\n1 0 0\n0 1 0\n3 0 1 2\n",
            ply_header("ascii", "3")
        )
        .as_bytes(),
        &[":10:", "non-finite"],
    );
    for (point, needles) in [
        ("f:0,1e308,1e308,0", &["sum to inf"][..]),
        ("f:0,0.2,0.2,0.2", &["sum to 0.6"]),
        ("v:999999", &["vertex 999999 is out of range", "gen:cube"]),
        ("e:0,1,2", &["edge parameter 2 is not in [0, 1]"]),
        ("e:0,1,nan", &["'nan' is not a finite number"]),
        ("e:0,6,0.5", &["not joined"]),
        ("e:0,99,0.5", &["vertex 99 is out of range"]),
        ("f:999,1,0,0", &["face 999 is out of range"]),
        ("f:0,-1,1,1", &["non-negative"]),
        ("f:0,nan,0.5,0.5", &["'nan' is not a finite number"]),
        ("f:0,0,0,0", &["not all zero"]),
        ("v:-1", &["'-1' is not an index"]),
        ("x:1", &["expected v:I"]),
    ] {
        let mut needles: Vec<String> = needles.iter().map(|s| s.to_string()).collect();
        needles.push(point.to_owned());
        cases.push(("gen:cube".to_owned(), point.to_owned(), needles));
    }
    for (mesh, source, needles) in &cases {
        let needles: Vec<&str> = needles.iter().map(String::as_str).collect();
        refuses(&["distance", mesh, "--source", source], &needles);
    }
}
