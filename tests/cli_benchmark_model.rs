//! The `benchmark-model` and `verify` commands [LZT §5]: a model written to a directory and
//! checked by the engine, a user's scene file, and the failures they report.

// The command line is built with the `cli` feature only.
#![cfg(feature = "cli")]
mod common;

use common::cli::{fails_with, refuses, run, stdout};
use std::path::PathBuf;

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir()
        .join(format!("exact-geodesics-bm-{}", std::process::id()))
        .join(name);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn text(path: &std::path::Path) -> &str {
    path.to_str().expect("UTF-8 path")
}

#[test]
fn a_generated_model_verifies() {
    let dir = temp_dir("generated");
    let made = stdout(&run(&[
        "benchmark-model",
        "--seed",
        "4",
        "--obstacles",
        "6",
        "--min-angle",
        "25",
        "--max-area",
        "0.05",
        "--wall-rows",
        "2",
        "--out",
        text(&dir),
    ]));
    assert!(made.contains("ground-truth length"), "{made}");
    assert!(dir.join("scene.obj").is_file());
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("scene.json")).expect("scene.json"))
            .expect("JSON");
    assert_eq!(json["seed"], 4);
    assert_eq!(json["options"]["wall_rows"], 2);
    assert_eq!(json["scene"]["obstacles"].as_array().map(Vec::len), Some(6));
    let scene_json = dir.join("scene.json");
    let report = stdout(&run(&["verify", text(&scene_json), "--backend", "f64"]));
    assert!(report.contains("relative error"), "{report}");
}

#[test]
fn a_user_scene_builds_and_verifies_and_a_wrong_ground_truth_is_caught() {
    let dir = temp_dir("user");
    let scene = dir.join("user-scene.json");
    std::fs::write(
        &scene,
        r#"{"rectangle": {"min": [-1, -1], "max": [4, 4]},
            "obstacles": [[[0, 0], [3, 0], [3, 3], [2, 3], [2, 1], [1, 1], [1, 3], [0, 3]]],
            "p": [1.4, 2], "q": [1.5, -0.5]}"#,
    )
    .expect("scene file");
    let out = dir.join("model");
    stdout(&run(&[
        "benchmark-model",
        "--scene",
        text(&scene),
        "--out",
        text(&out),
    ]));
    let json_path = out.join("scene.json");
    stdout(&run(&["verify", text(&json_path)]));

    let mut json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json_path).expect("scene.json"))
            .expect("JSON");
    let length = json["ground_truth"]["length"].as_f64().expect("a length");
    json["ground_truth"]["length"] = serde_json::json!(length * 1.001);
    std::fs::write(&json_path, json.to_string()).expect("rewrite");
    fails_with(&["verify", text(&json_path)], "relative error of d(p, q)");
}

#[test]
fn bad_scenes_are_errors_naming_the_problem() {
    let dir = temp_dir("bad");
    let scene = dir.join("overlap.json");
    std::fs::write(
        &scene,
        r#"{"rectangle": {"min": [0, 0], "max": [5, 5]},
            "obstacles": [[[1, 1], [3, 1], [3, 3], [1, 3]], [[2, 2], [4, 2], [4, 4], [2, 4]]],
            "p": [0.5, 0.5], "q": [4.5, 0.5]}"#,
    )
    .expect("scene file");
    let out = dir.join("model");
    fails_with(
        &[
            "benchmark-model",
            "--scene",
            text(&scene),
            "--out",
            text(&out),
        ],
        "obstacles 0 and 1 overlap",
    );
    fails_with(&["verify", text(&dir.join("missing.json"))], "missing.json");
}

#[test]
fn absurd_obstacle_counts_and_wall_rows_are_refused_not_built() {
    let dir = temp_dir("absurd");
    // A million obstacles ran for minutes; 10^8 wall rows allocated until memory ran out.
    refuses(
        &[
            "benchmark-model",
            "--obstacles",
            "1000000",
            "--out",
            text(&dir),
        ],
        &["--obstacles", "1000000", "0..=10000"],
    );
    refuses(
        &[
            "benchmark-model",
            "--wall-rows",
            "100000000",
            "--out",
            text(&dir),
        ],
        &["wall_rows", "100000000 rows", "at most 4194304"],
    );
}
