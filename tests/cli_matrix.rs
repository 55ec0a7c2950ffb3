//! `exact-geodesics matrix`: the files it writes parse back (small readers below) and hold the
//! distances that `exact-geodesics distance` gives from each source.

// The command line is built with the `cli` feature only.
#![cfg(feature = "cli")]
mod common;

use common::cli::{refuses, run, stdout, temp_file};
use std::path::Path;

const MESH: &str = "gen:icosphere:2";
const SOURCES: [u32; 6] = [0, 17, 5, 160, 42, 99];

fn sources_arg() -> String {
    SOURCES.map(|v| format!("v:{v}")).join(",")
}

/// The distances of every vertex from `source`, by the `distance` command.
fn single_source(source: u32) -> Vec<f64> {
    let text = stdout(&run(&[
        "distance",
        MESH,
        "--source",
        &format!("v:{source}"),
    ]));
    text.lines()
        .skip(1)
        .map(|line| line.split(',').nth(1).unwrap().parse().unwrap())
        .collect()
}

/// A NumPy `.npy` file of little-endian `f64`, format 1.0: its shape and values.
fn read_npy(path: &Path) -> ((usize, usize), Vec<f64>) {
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(&bytes[..8], b"\x93NUMPY\x01\x00");
    let header_len = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    let data_start = 10 + header_len;
    assert_eq!(data_start % 64, 0, "data aligned");
    let header = std::str::from_utf8(&bytes[10..data_start]).unwrap();
    assert!(header.contains("'descr': '<f8'") && header.contains("'fortran_order': False"));
    assert!(header.ends_with('\n'));
    let shape = header.split("'shape': (").nth(1).unwrap();
    let shape: Vec<usize> = shape
        .split(')')
        .next()
        .unwrap()
        .split(',')
        .map(|s| s.trim().parse().unwrap())
        .collect();
    let values: Vec<f64> = bytes[data_start..]
        .chunks(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
        .collect();
    assert_eq!(values.len(), shape[0] * shape[1]);
    ((shape[0], shape[1]), values)
}

/// An entry of a sparse matrix: row, column (0-based), value.
type Entry = (usize, usize, f64);

/// A Matrix Market coordinate file: its size and entries.
fn read_mtx(path: &Path) -> ((usize, usize), Vec<Entry>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("%%MatrixMarket matrix coordinate real general")
    );
    let mut lines = lines.filter(|l| !l.starts_with('%'));
    let size: Vec<usize> = lines
        .next()
        .unwrap()
        .split_whitespace()
        .map(|s| s.parse().unwrap())
        .collect();
    let entries: Vec<Entry> = lines
        .map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            (
                f[0].parse::<usize>().unwrap() - 1,
                f[1].parse::<usize>().unwrap() - 1,
                f[2].parse().unwrap(),
            )
        })
        .collect();
    assert_eq!(entries.len(), size[2], "the count of the size line");
    ((size[0], size[1]), entries)
}

#[test]
fn npy_rows_equal_single_source_runs_on_one_and_two_threads() {
    let one = temp_file("one.npy", "");
    let two = temp_file("two.npy", "");
    for (path, threads) in [(&one, "1"), (&two, "2")] {
        let args = [
            "matrix",
            MESH,
            "--sources",
            &sources_arg(),
            "--threads",
            threads,
        ];
        stdout(&run(
            &[&args[..], &["--out", path.to_str().unwrap()]].concat()
        ));
    }
    assert_eq!(std::fs::read(&one).unwrap(), std::fs::read(&two).unwrap());
    let ((rows, cols), values) = read_npy(&one);
    assert_eq!((rows, cols), (SOURCES.len(), SOURCES.len()));
    for (i, &s) in SOURCES.iter().enumerate() {
        let single = single_source(s);
        for (j, &t) in SOURCES.iter().enumerate() {
            assert_eq!(values[i * cols + j].to_bits(), single[t as usize].to_bits());
        }
    }
}

#[test]
fn mtx_holds_the_entries_within_the_radius() {
    let npy = temp_file("all.npy", "");
    let mtx = temp_file("near.mtx", "");
    let selection = ["--sources", &sources_arg()];
    stdout(&run(&[
        &["matrix", MESH][..],
        &selection,
        &["--out", npy.to_str().unwrap()],
    ]
    .concat()));
    let radius = "1.2";
    let near = ["--max-distance", radius, "--out", mtx.to_str().unwrap()];
    stdout(&run(&[&["matrix", MESH][..], &selection, &near].concat()));
    let ((_, n), dense) = read_npy(&npy);
    let ((rows, cols), mut entries) = read_mtx(&mtx);
    assert_eq!((rows, cols), (n, n));
    entries.sort_by_key(|&(i, j, _)| (i, j));
    let want: Vec<Entry> = (0..n * n)
        .filter(|k| dense[*k] <= 1.2)
        .map(|k| (k / n, k % n, dense[k]))
        .collect();
    assert!(want.len() > n && want.len() < n * n, "the radius cuts");
    assert_eq!(entries, want);
}

#[test]
fn csv_from_a_sources_file_is_symmetric_with_symmetrize_min() {
    let list = temp_file(
        "sources.txt",
        "# the selection\nv:0, 17\n5 v:160 # more\n42\n99\n",
    );
    let csv = temp_file("sym.csv", "");
    let args = [
        "matrix",
        MESH,
        "--sources-file",
        list.to_str().unwrap(),
        "--symmetrize",
        "min",
    ];
    stdout(&run(
        &[&args[..], &["--out", csv.to_str().unwrap()]].concat()
    ));
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let names = SOURCES.map(|v| format!("v{v}")).join(",");
    assert_eq!(lines.next().unwrap(), format!("source,{names}"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').skip(1).map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), SOURCES.len());
    for (i, &s) in SOURCES.iter().enumerate() {
        let single = single_source(s);
        for (j, &t) in SOURCES.iter().enumerate() {
            assert_eq!(rows[i][j], rows[j][i]);
            assert!(rows[i][j] <= single[t as usize]);
            assert!((rows[i][j] - single[t as usize]).abs() < 1e-12);
        }
    }
}

#[test]
fn a_saved_random_selection_reads_back_as_the_same_matrix() {
    let (saved, first, again) = (
        temp_file("random.txt", ""),
        temp_file("random.npy", ""),
        temp_file("again.npy", ""),
    );
    let random = ["--random", "7", "--seed", "3", "--save-selection"];
    let out = ["--out", first.to_str().unwrap()];
    stdout(&run(&[
        &["matrix", MESH][..],
        &random,
        &[saved.to_str().unwrap()],
        &out,
    ]
    .concat()));
    let text = std::fs::read_to_string(&saved).unwrap();
    assert_eq!(text.lines().count(), 7);
    assert!(text.lines().all(|l| l.starts_with("v:")));
    let from_file = [
        "--sources-file",
        saved.to_str().unwrap(),
        "--out",
        again.to_str().unwrap(),
    ];
    stdout(&run(&[&["matrix", MESH][..], &from_file].concat()));
    assert_eq!(
        std::fs::read(&first).unwrap(),
        std::fs::read(&again).unwrap()
    );
}

#[test]
fn bad_selections_and_outputs_are_named() {
    let out = temp_file("bad.npy", "");
    let out = out.to_str().unwrap();
    refuses(
        &["matrix", MESH, "--sources", "v:0,v:999", "--out", out],
        &["--sources", "vertex 999"],
    );
    let list = temp_file("bad_sources.txt", "0\n1 x:3\n");
    let list = list.to_str().unwrap();
    refuses(
        &["matrix", MESH, "--sources-file", list, "--out", out],
        &[&format!("{list}:2"), "'x:3'"],
    );
    refuses(
        &["matrix", MESH, "--all", "--out", "m.txt"],
        &["m.txt", ".npy"],
    );
    refuses(
        &["matrix", MESH, "--all", "--out", "/nonexistent/m.npy"],
        &["/nonexistent/m.npy"],
    );
    refuses(&["matrix", MESH, "--out", out], &["--sources"]);
    refuses(
        &["matrix", MESH, "--all", "--threads", "0", "--out", out],
        &["--threads"],
    );
}
