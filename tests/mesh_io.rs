//! Mesh files: exact round trips, each format's quirks, errors that name the file and line, and
//! no panic on any input.

use exact_geodesics::glam::DVec3;
use exact_geodesics::mesh::io::*;
use exact_geodesics::{MeshError, TriMesh};
use proptest::prelude::*;
use std::io::{BufReader, Read};
use std::path::{Path, PathBuf};

const FORMATS: [MeshFormat; 3] = [MeshFormat::Obj, MeshFormat::Off, MeshFormat::Ply];

fn read(text: impl AsRef<[u8]>, format: MeshFormat) -> Result<TriMesh, MeshIoError> {
    read_from(text.as_ref(), format, "m", &ReadOptions::default())
}

fn read_triangulated(text: impl AsRef<[u8]>, format: MeshFormat) -> Result<TriMesh, MeshIoError> {
    read_from(
        text.as_ref(),
        format,
        "m",
        &ReadOptions {
            triangulate: true,
            ..ReadOptions::default()
        },
    )
}

/// A closed tetrahedron with awkward coordinates (subnormal, huge, negative zero, thirds) and an
/// unreferenced vertex in the middle of the list, faces in no particular order.
fn awkward_mesh() -> TriMesh {
    let positions = vec![
        [0.1, -0.0, 1e-300],
        [1.0 / 3.0, 5e-324, 0.0],
        [7.0, 8.0, 9.0],
        [std::f64::consts::PI, 1e300, -2.5],
        [f64::MIN_POSITIVE, -1e-7, 123_456_789.123],
    ];
    let faces = vec![[3, 1, 0], [0, 1, 4], [1, 3, 4], [3, 0, 4]];
    TriMesh::new(positions, faces).expect("valid mesh")
}

fn assert_identical(a: &TriMesh, b: &TriMesh) {
    let bits = |m: &TriMesh| -> Vec<[u64; 3]> {
        m.positions()
            .iter()
            .map(|p| p.to_array().map(f64::to_bits))
            .collect()
    };
    assert_eq!(bits(a), bits(b));
    assert_eq!(a.faces(), b.faces());
}

fn written(mesh: &TriMesh, format: MeshFormat, ply: PlyEncoding) -> Vec<u8> {
    let mut bytes = Vec::new();
    write_to(mesh, &mut bytes, format, ply).expect("writing to memory");
    bytes
}

fn temp_path(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!(
        "exact_geodesics_mesh_io_{}_{name}",
        std::process::id()
    ))
}

/// Big-endian PLY bytes for `items`, each a number of the given PLY type.
enum Be {
    U8(u8),
    I8(i8),
    U16(u16),
    I32(i32),
    F32(f32),
    F64(f64),
}

fn big_endian(items: &[Be]) -> Vec<u8> {
    items
        .iter()
        .flat_map(|item| match *item {
            Be::U8(x) => x.to_be_bytes().to_vec(),
            Be::I8(x) => x.to_be_bytes().to_vec(),
            Be::U16(x) => x.to_be_bytes().to_vec(),
            Be::I32(x) => x.to_be_bytes().to_vec(),
            Be::F32(x) => x.to_be_bytes().to_vec(),
            Be::F64(x) => x.to_be_bytes().to_vec(),
        })
        .collect()
}

fn line_of(result: Result<TriMesh, MeshIoError>) -> (Option<usize>, MeshError) {
    match result {
        Err(MeshIoError::Mesh { line, source, .. }) => (line, source),
        other => panic!("expected a mesh error, got {other:?}"),
    }
}

fn parse_line(result: Result<TriMesh, MeshIoError>) -> usize {
    match result {
        Err(MeshIoError::Parse { line, .. }) => line,
        other => panic!("expected a parse error, got {other:?}"),
    }
}

const PLY_HEADER: &str = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n\
property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

#[test]
fn round_trips_are_bit_exact_in_every_format() {
    let mesh = awkward_mesh();
    for (format, ply) in [
        (MeshFormat::Obj, PlyEncoding::Ascii),
        (MeshFormat::Off, PlyEncoding::Ascii),
        (MeshFormat::Ply, PlyEncoding::Ascii),
        (MeshFormat::Ply, PlyEncoding::BinaryLittleEndian),
    ] {
        let back = read(written(&mesh, format, ply), format).expect("reads back");
        assert_identical(&mesh, &back);
        assert_eq!(back.validation().unreferenced_vertices.len(), 1);
    }
}

#[test]
fn round_trips_through_files_choose_the_format_by_extension() {
    let mesh = awkward_mesh();
    for name in ["a.obj", "b.off", "c.ply", "d.OBJ", "e.Ply"] {
        let path = temp_path(name);
        write_path(&mesh, &path).expect("write");
        let back = read_path(&path, &ReadOptions::default());
        std::fs::remove_file(&path).expect("remove temp file");
        assert_identical(&mesh, &back.expect("read"));
    }
}

#[test]
fn format_from_path_reads_the_extension_in_any_case() {
    let format = |p: &str| MeshFormat::from_path(Path::new(p));
    assert_eq!(format("bunny.obj"), Some(MeshFormat::Obj));
    assert_eq!(format("dir/BUNNY.OBJ"), Some(MeshFormat::Obj));
    assert_eq!(format("m.Off"), Some(MeshFormat::Off));
    assert_eq!(format("m.pLy"), Some(MeshFormat::Ply));
    assert_eq!(format("m.stl"), None);
    assert_eq!(format("obj"), None);
    assert_eq!(format("m.obj/inner"), None);
}

#[test]
fn unknown_extensions_and_missing_files_are_named() {
    let mesh = awkward_mesh();
    let options = ReadOptions::default();
    assert!(matches!(
        read_path(Path::new("mesh.stl"), &options),
        Err(MeshIoError::UnknownFormat { file }) if file == "mesh.stl"
    ));
    assert!(matches!(
        write_path(&mesh, Path::new("mesh.stl")),
        Err(MeshIoError::UnknownFormat { .. })
    ));
    let missing = temp_path("missing.obj");
    let error = read_path(&missing, &options).expect_err("no such file");
    assert!(matches!(&error, MeshIoError::Io { file, .. } if Path::new(file) == missing));
    assert!(error
        .to_string()
        .starts_with(&missing.display().to_string()));
}

#[test]
fn read_failures_are_io_errors() {
    struct Failing;
    impl Read for Failing {
        fn read(&mut self, _: &mut [u8]) -> std::io::Result<usize> {
            Err(std::io::Error::other("disk on fire"))
        }
    }
    for format in FORMATS {
        let result = read_from(
            BufReader::new(Failing),
            format,
            "f",
            &ReadOptions::default(),
        );
        assert!(matches!(result, Err(MeshIoError::Io { .. })), "{format:?}");
    }
}

#[test]
fn hand_made_big_endian_ply_skips_other_properties_and_elements() {
    let header = "ply\nformat binary_big_endian 1.0\ncomment hand-made\n\
        element vertex 5\nproperty uchar red\nproperty float z\nproperty double x\n\
        property int y\nproperty list uchar ushort extra\n\
        element edge 2\nproperty int vertex1\nproperty list int char flags\n\
        element face 2\nproperty int flags\nproperty list ushort int vertex_index\n\
        property float quality\nend_header\n";
    let mut bytes = header.as_bytes().to_vec();
    let corners = [
        (0.25, 0, 1.5),
        (1.0, 0, 0.0),
        (1.0, 1, 0.0),
        (0.0, 1, 0.0),
        (9.0, 9, 9.0),
    ];
    for (i, &(x, y, z)) in corners.iter().enumerate() {
        let extra: Vec<Be> = (0..i as u16).map(Be::U16).collect();
        bytes.extend(big_endian(&[
            Be::U8(200),
            Be::F32(z),
            Be::F64(x),
            Be::I32(y),
        ]));
        bytes.extend(big_endian(&[Be::U8(i as u8)]));
        bytes.extend(big_endian(&extra));
    }
    for flags in [vec![], vec![Be::I8(-1), Be::I8(7)]] {
        bytes.extend(big_endian(&[Be::I32(3), Be::I32(flags.len() as i32)]));
        bytes.extend(big_endian(&flags));
    }
    for face in [[0, 1, 2], [0, 2, 3]] {
        bytes.extend(big_endian(&[Be::I32(-5), Be::U16(3)]));
        bytes.extend(big_endian(&face.map(Be::I32)));
        bytes.extend(big_endian(&[Be::F32(0.5)]));
    }
    let mesh = read(&bytes, MeshFormat::Ply).expect("valid big-endian PLY");
    let expected: Vec<DVec3> = corners
        .iter()
        .map(|&(x, y, z)| DVec3::new(x, f64::from(y), f64::from(z)))
        .collect();
    assert_eq!(mesh.positions(), &expected[..]);
    assert_eq!(mesh.faces(), &[[0, 1, 2], [0, 2, 3]]);
}

#[test]
fn obj_quirks_are_read() {
    let mut obj = b"# exported\r\nmtllib m.mtl\no square\n".to_vec();
    obj.extend(b"# caf\xe9, not UTF-8 in a comment\n");
    obj.extend(b"v 0 0 0 1.0\nv 1 0 0 0.9 0.1 0.1\nv 1 1 0\r\nv 0 1 0\n");
    obj.extend(b"v 0.5 0.5 0 # centre\nv 7 7 7\nvt 0 0\nvn 0 0 1\n\n  \ng g1\ns off\nusemtl m\n");
    obj.extend(b"f 1 2 5\nf 2/1 3/1 5/1\nf 3/1/1 4/1/1 5/1/1\nf -3//1 -6//1 -2//1\n");
    let mesh = read(&obj, MeshFormat::Obj).expect("valid OBJ");
    assert_eq!(mesh.vertex_count(), 6);
    assert_eq!(mesh.positions()[4], DVec3::new(0.5, 0.5, 0.0));
    assert_eq!(mesh.faces(), &[[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]);
}

#[test]
fn obj_words_split_at_any_whitespace_and_end_at_comments() {
    // ASCII lines are split byte by byte, the others by characters: both as `split_whitespace`.
    let obj = "v 0\u{a0}0\u{3000}0\n\u{a0}\u{2003}\n v\t1\x0b0\x0c0#glued\nv 1 1 0 # caf\u{e9}\n\
        v 0 1 0\nf 1 2 3#glued\nf 0001/1/1 3//2 4\n";
    let mesh = read(obj, MeshFormat::Obj).expect("valid OBJ");
    let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
    let expected: Vec<DVec3> = corners
        .iter()
        .map(|&(x, y)| DVec3::new(x, y, 0.0))
        .collect();
    assert_eq!(mesh.positions(), &expected[..]);
    assert_eq!(mesh.faces(), &[[0, 1, 2], [0, 2, 3]]);
    for (text, at) in [
        ("\u{a0}\nv 0 0 x\n", 2),
        ("v 0 0 0\n\u{2003}\nf 1 1\u{a0}x\n", 3),
        ("v 0 0 0\nf 1 1 0000000000000000001x\n", 2),
    ] {
        assert_eq!(parse_line(read(text, MeshFormat::Obj)), at, "{text:?}");
    }
}

#[test]
fn obj_faces_may_come_before_their_vertices() {
    let mesh = read("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", MeshFormat::Obj).expect("valid");
    assert_eq!(mesh.faces(), &[[0, 1, 2]]);
}

#[test]
fn off_quirks_are_read() {
    let coff = "# a comment\n\nCOFF\n# counts\n4 2 5\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n\
        1 1 0 0 0 255 255 # blue\n0 1 0 1 1 1 1\n3 0 1 2 255 0 0\n3 0 2 3\n";
    let expected = [[0, 1, 2], [0, 2, 3]];
    assert_eq!(
        read(coff, MeshFormat::Off).expect("COFF").faces(),
        &expected
    );
    let noff = "NOFF 4 2 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n3 0 2 3\n";
    assert_eq!(
        read(noff, MeshFormat::Off).expect("NOFF").faces(),
        &expected
    );
    let headerless = "4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
    let mesh = read(headerless, MeshFormat::Off).expect("no header");
    assert_eq!(mesh.positions()[2], DVec3::new(1.0, 1.0, 0.0));
    for bad in ["4OFF\n", "nOFF\n", "XOFF\n", "OFF BINARY\n", "mesh\n"] {
        assert_eq!(parse_line(read(bad, MeshFormat::Off)), 1, "{bad:?}");
    }
}

#[test]
fn ply_ascii_quirks_are_read() {
    let ply = "ply\r\nformat ascii 1.0\r\ncomment any order, any type\nobj_info x\n\
        element vertex 4\nproperty double z\nproperty uchar red\nproperty int x\nproperty float32 y\n\
        element material 1\nproperty list uint8 float weights\nproperty short id\n\
        element face 2\nproperty list int uint32 vertex_index\nproperty uchar flag\n\
        element other 1000000\nend_header\n\
        0.5 1 0 0\n0 2 1 0\n\n0 3 1 1\n0 4 0 1\n2 0.5 0.25 7\n3 0 1 2 9\n3 0 2 3 9\n";
    let mesh = read(ply, MeshFormat::Ply).expect("valid ASCII PLY");
    assert_eq!(mesh.positions()[0], DVec3::new(0.0, 0.0, 0.5));
    assert_eq!(mesh.positions()[2], DVec3::new(1.0, 1.0, 0.0));
    assert_eq!(mesh.faces(), &[[0, 1, 2], [0, 2, 3]]);
}

#[test]
fn triangulation_fans_polygons_and_keeps_their_line() {
    let pentagon = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.5, 1.0, 0.0],
        [0.5, 2.0, 0.0],
        [-0.5, 1.0, 0.0],
    ];
    let fan = [[0, 1, 2], [0, 2, 3], [0, 3, 4]];
    let vertices: String = pentagon
        .iter()
        .map(|p| format!("{} {} {}\n", p[0], p[1], p[2]))
        .collect();
    let obj = format!(
        "{}f 1 2 3 4 5\n",
        vertices
            .lines()
            .map(|l| format!("v {l}\n"))
            .collect::<String>()
    );
    let off = format!("OFF\n5 1 0\n{vertices}5 0 1 2 3 4\n");
    let ply = PLY_HEADER.replace("vertex 4", "vertex 5") + &vertices + "5 0 1 2 3 4\n";
    for (text, format) in [
        (obj, MeshFormat::Obj),
        (off, MeshFormat::Off),
        (ply, MeshFormat::Ply),
    ] {
        let mesh = read_triangulated(&text, format).expect("triangulated");
        assert_eq!(mesh.faces(), &fan, "{format:?}");
        // The bad index is in the polygon's last triangle; the error names the polygon's line.
        let (head, _) = text.trim_end().rsplit_once(' ').expect("a last corner");
        let bad = format!("{head} 99\n");
        let line = text.lines().count();
        let (at, source) = line_of(read_triangulated(&bad, format));
        assert_eq!(at, Some(line), "{format:?}");
        assert!(
            matches!(source, MeshError::VertexIndexOutOfRange { face: 2, .. }),
            "{format:?}"
        );
    }
}

#[test]
fn polygons_are_refused_at_their_line_unless_triangulating() {
    let obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    let off = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
    let ply = format!("{PLY_HEADER}0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    for (text, format, at) in [
        (obj, MeshFormat::Obj, 5),
        (off, MeshFormat::Off, 7),
        (&ply[..], MeshFormat::Ply, 14),
    ] {
        let error = read(text, format).expect_err("a quad");
        assert!(
            matches!(error, MeshIoError::NotATriangle { line, corners: 4, .. } if line == at),
            "{format:?}: {error:?}"
        );
        assert_eq!(
            read_triangulated(text, format)
                .expect("two triangles")
                .face_count(),
            2
        );
    }
}

#[test]
fn faces_with_fewer_than_three_corners_are_refused_even_when_triangulating() {
    let cases = [
        ("v 0 0 0\nv 1 0 0\nf 1 2\n", MeshFormat::Obj, 3, 2),
        ("v 0 0 0\nf\n", MeshFormat::Obj, 2, 0),
        ("OFF\n2 1 0\n0 0 0\n1 0 0\n2 0 1\n", MeshFormat::Off, 5, 2),
        (
            &*format!("{PLY_HEADER}0 0 0\n1 0 0\n1 1 0\n0 1 0\n1 0\n"),
            MeshFormat::Ply,
            14,
            1,
        ),
    ];
    for (text, format, at, n) in cases {
        let error = read_triangulated(text, format).expect_err("degenerate face");
        assert!(
            matches!(error, MeshIoError::NotATriangle { line, corners, .. } if line == at && corners == n),
            "{format:?}: {error:?}"
        );
    }
}

#[test]
fn binary_ply_errors_name_the_element() {
    let mesh = TriMesh::new(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .expect("square");
    let bytes = written(&mesh, MeshFormat::Ply, PlyEncoding::BinaryLittleEndian);
    let data = bytes
        .windows(11)
        .position(|w| w == b"end_header\n")
        .expect("header")
        + 11;
    let binary_error = |bytes: &[u8]| match read(bytes, MeshFormat::Ply) {
        Err(MeshIoError::BinaryParse {
            element,
            index,
            message,
            ..
        }) => (element, index, message),
        other => panic!("expected a binary error, got {other:?}"),
    };
    // Cut inside vertex 2 (24 bytes each), then inside face 1 (13 bytes each).
    assert_eq!(binary_error(&bytes[..data + 2 * 24 + 5]).0, "vertex");
    assert_eq!(binary_error(&bytes[..data + 2 * 24 + 5]).1, 2);
    let (element, index, _) = binary_error(&bytes[..bytes.len() - 1]);
    assert_eq!((element.as_str(), index), ("face", 1));
    // The second face's corner count becomes 4.
    let mut quad = bytes.clone();
    quad[data + 4 * 24 + 13] = 4;
    let (element, index, message) = binary_error(&quad);
    assert_eq!((element.as_str(), index), ("face", 1));
    assert!(message.contains("4 corners"), "{message}");
    // A NaN coordinate has no line to name; TriMesh::new names the vertex.
    let mut nan = bytes.clone();
    nan[data + 24 + 8..data + 24 + 16].copy_from_slice(&f64::NAN.to_le_bytes());
    let (line, source) = line_of(read(&nan, MeshFormat::Ply));
    assert_eq!(line, None);
    assert!(matches!(
        source,
        MeshError::NonFiniteCoordinate { vertex: 1, .. }
    ));
}

#[test]
fn out_of_range_indices_name_their_line() {
    let cases = [
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 99\n",
            MeshFormat::Obj,
            5,
        ),
        (
            "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 7\n",
            MeshFormat::Off,
            7,
        ),
        (
            &*format!("{PLY_HEADER}0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 4\n"),
            MeshFormat::Ply,
            14,
        ),
    ];
    for (text, format, at) in cases {
        let (line, source) = line_of(read(text, format));
        assert_eq!(line, Some(at), "{format:?}");
        assert!(
            matches!(source, MeshError::VertexIndexOutOfRange { .. }),
            "{format:?}"
        );
    }
}

#[test]
fn non_finite_coordinates_name_their_line() {
    let cases = [
        ("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n", MeshFormat::Obj, 2),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n",
            MeshFormat::Off,
            5,
        ),
        (
            &*format!("{PLY_HEADER}0 0 0\n1 0 0\n0 1 0\n-inf 0 1\n3 0 1 2\n"),
            MeshFormat::Ply,
            13,
        ),
        (
            "v 0 0 0\nv 1 0 1e400\nv 0 1 0\nf 1 2 3\n",
            MeshFormat::Obj,
            2,
        ),
    ];
    for (text, format, at) in cases {
        let (line, source) = line_of(read(text, format));
        assert_eq!(line, Some(at), "{format:?}");
        assert!(
            matches!(source, MeshError::NonFiniteCoordinate { .. }),
            "{format:?}"
        );
    }
}

#[test]
fn a_third_face_on_an_edge_is_read_and_named_at_its_line_when_strict() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
    let mesh = read(obj, MeshFormat::Obj).expect("a non-manifold edge is usable");
    assert_eq!(mesh.validation().non_manifold_edges.len(), 1);
    let strict = ReadOptions {
        strict: true,
        ..ReadOptions::default()
    };
    let (line, source) = line_of(read_from(obj.as_bytes(), MeshFormat::Obj, "m", &strict));
    assert_eq!(line, Some(8));
    assert!(matches!(
        source,
        MeshError::NonManifoldEdge { face_count: 3, .. }
    ));
    let copy = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 1\n";
    let (line, source) = line_of(read_from(copy.as_bytes(), MeshFormat::Obj, "m", &strict));
    assert_eq!(line, Some(5));
    assert!(matches!(
        source,
        MeshError::DuplicateFace {
            face: 1,
            copy_of: 0
        }
    ));
}

#[test]
fn repeated_vertices_name_their_line() {
    let off = "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 2 1\n";
    let (line, source) = line_of(read(off, MeshFormat::Off));
    assert_eq!(line, Some(7));
    assert!(matches!(
        source,
        MeshError::RepeatedVertex { face: 1, vertex: 2 }
    ));
}

#[test]
fn malformed_text_is_a_parse_error_at_its_line() {
    let cases = [
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n",
            MeshFormat::Obj,
            3,
        ),
        ("v 0 0\n", MeshFormat::Obj, 1),
        ("v 0 0 0\nf 0 1 2\n", MeshFormat::Obj, 2),
        ("v 0 0 0\nf -2 1 1\n", MeshFormat::Obj, 2),
        ("v 0 0 0\nf 1 1 99999999999\n", MeshFormat::Obj, 2),
        ("v 0 0 0\nf 1 x 1\n", MeshFormat::Obj, 2),
        ("v 0 0 0\nbogus 1 2\n", MeshFormat::Obj, 2),
        ("OFF\n3 1\n0 0 0\n1 0\n", MeshFormat::Off, 4),
        (
            "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n",
            MeshFormat::Off,
            6,
        ),
        (
            "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n",
            MeshFormat::Off,
            6,
        ),
        ("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n", MeshFormat::Off, 5),
        ("OFF\n3 1\n0 0 0\n", MeshFormat::Off, 3),
        ("# only a comment\n", MeshFormat::Off, 1),
        (
            &*format!("{PLY_HEADER}0 0 0\n1 0 0\n1 1 0 5\n"),
            MeshFormat::Ply,
            12,
        ),
        (
            &*format!("{PLY_HEADER}0 0 0\n1 0 0\n1 1\n"),
            MeshFormat::Ply,
            12,
        ),
        (
            &*format!("{PLY_HEADER}0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 -2\n"),
            MeshFormat::Ply,
            14,
        ),
        (
            &*format!("{PLY_HEADER}0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1.5 2\n"),
            MeshFormat::Ply,
            14,
        ),
        (&*format!("{PLY_HEADER}0 0 0\n1 0 0\n"), MeshFormat::Ply, 11),
    ];
    for (text, format, at) in cases {
        assert_eq!(parse_line(read(text, format)), at, "{format:?} {text:?}");
    }
    let not_utf8 = b"v 0 0 0\nv 1 0 \xff\n";
    assert_eq!(parse_line(read(not_utf8, MeshFormat::Obj)), 2);
}

#[test]
fn ply_header_errors_name_their_line() {
    let header = |lines: &str| format!("ply\nformat ascii 1.0\n{lines}end_header\n");
    let cases = [
        ("PLY\n".to_owned(), 1),
        ("\n\nnot ply\n".to_owned(), 3),
        (String::new(), 1),
        (header("ply\n"), 3),
        ("ply\nelement vertex 0\nproperty float x\nend_header\n".to_owned(), 4),
        ("ply\nformat ascii 1.0\n".to_owned(), 2),
        ("ply\nformat utf8 1.0\n".to_owned(), 2),
        (header("property float x\n"), 3),
        (header("element vertex 1\nproperty float128 x\n"), 4),
        (header("element vertex -1\n"), 3),
        (header("element vertex 1\nproperty float x\nproperty float y\n"), 3),
        (header("element vertex 0\nproperty float x\nproperty float y\nproperty list uchar int z\n"), 3),
        (header("element vertex 0\nproperty float x\nproperty float y\nproperty float z\nelement face 0\n"), 7),
        (header("element vertex 0\nelement vertex 0\n"), 4),
        (header("element face 0\nproperty list uchar int vertex_indices\n"), 5),
        (header("bogus\n"), 3),
    ];
    for (text, at) in cases {
        assert_eq!(parse_line(read(&text, MeshFormat::Ply)), at, "{text:?}");
    }
}

#[test]
fn huge_counts_in_small_files_fail_without_allocating() {
    let ply = |format: &str| {
        format!("ply\nformat {format} 1.0\nelement vertex 1000000000000\nproperty float x\nproperty float y\nproperty float z\nelement face 18446744073709551615\nproperty list uint uint vertex_indices\nend_header\n0 0 0\n0 0 0\n")
    };
    assert_eq!(parse_line(read(ply("ascii"), MeshFormat::Ply)), 11);
    for endian in ["binary_little_endian", "binary_big_endian"] {
        assert!(matches!(
            read(ply(endian), MeshFormat::Ply),
            Err(MeshIoError::BinaryParse { index: 1, .. })
        ));
    }
    let off = "OFF\n1000000000000 1000000000000 0\n0 0 0\n";
    assert_eq!(parse_line(read(off, MeshFormat::Off)), 3);
    // A list claiming four billion corners in a few bytes.
    let mut lying = ply("binary_little_endian")
        .replace("vertex 1000000000000", "vertex 0")
        .into_bytes();
    lying.truncate(lying.len() - 12);
    lying.extend([0xff, 0xff, 0xff, 0xff, 1, 0, 0, 0]);
    let triangulating = read_triangulated(&lying, MeshFormat::Ply);
    assert!(
        matches!(
            triangulating,
            Err(MeshIoError::BinaryParse { index: 0, .. })
        ),
        "{triangulating:?}"
    );
}

#[test]
fn files_without_faces_are_refused_naming_the_file() {
    let ply = |vertices: &str, face: &str| {
        format!("ply\nformat ascii 1.0\nelement vertex {vertices}\nproperty float x\nproperty float y\nproperty float z\nelement {face} 0\nproperty list uchar int vertex_indices\nend_header\n")
    };
    let cases = [
        (String::new(), MeshFormat::Obj, 0),
        ("# only a comment\n".to_owned(), MeshFormat::Obj, 0),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\n".to_owned(), MeshFormat::Obj, 3),
        ("OFF\n0 0 0\n".to_owned(), MeshFormat::Off, 0),
        ("OFF\n1 0 0\n0 0 0\n".to_owned(), MeshFormat::Off, 1),
        (ply("0", "face"), MeshFormat::Ply, 0),
        // Faces under another element name are skipped like any unknown element.
        (
            ply("3", "faces").replace("0\nproperty list", "1\nproperty list")
                + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
            MeshFormat::Ply,
            3,
        ),
    ];
    for (text, format, vertices) in cases {
        let error = read_from(text.as_bytes(), format, "empty.x", &ReadOptions::default())
            .expect_err("no faces");
        assert!(
            matches!(
                &error,
                MeshIoError::Mesh { file, line: None, source: MeshError::NoFaces { vertices: v } }
                    if file == "empty.x" && *v == vertices
            ),
            "{format:?} {text:?}: {error:?}"
        );
        assert!(
            error
                .to_string()
                .starts_with("empty.x: the mesh has no faces"),
            "{error}"
        );
    }
}

#[test]
fn garbage_is_an_error_in_every_format() {
    let garbage: Vec<u8> = (0u32..4096)
        .map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8)
        .collect();
    for format in FORMATS {
        assert!(read(&garbage, format).is_err(), "{format:?}");
        assert!(read("\u{feff}\u{0}\u{7f}", format).is_err(), "{format:?}");
    }
}

#[test]
fn messages_start_with_file_and_line() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n";
    let error = read_from(
        obj.as_bytes(),
        MeshFormat::Obj,
        "bunny.obj",
        &ReadOptions::default(),
    )
    .expect_err("out of range");
    assert!(
        error
            .to_string()
            .starts_with("bunny.obj:4: face 0 refers to vertex 98"),
        "{error}"
    );
    let error = read_from(
        &b"v 0 0 zero\n"[..],
        MeshFormat::Obj,
        "b.obj",
        &ReadOptions::default(),
    )
    .expect_err("malformed");
    assert!(error.to_string().starts_with("b.obj:1: "), "{error}");
    let error = read_from(
        &b"f 1 2 3 4\n"[..],
        MeshFormat::Obj,
        "q.obj",
        &ReadOptions::default(),
    )
    .expect_err("quad");
    assert!(
        error
            .to_string()
            .starts_with("q.obj:1: a face with 4 corners"),
        "{error}"
    );
}

/// A valid file in each format and encoding, to mutate.
fn valid_files() -> Vec<(MeshFormat, Vec<u8>)> {
    let mesh = awkward_mesh();
    vec![
        (
            MeshFormat::Obj,
            written(&mesh, MeshFormat::Obj, PlyEncoding::Ascii),
        ),
        (
            MeshFormat::Off,
            written(&mesh, MeshFormat::Off, PlyEncoding::Ascii),
        ),
        (
            MeshFormat::Ply,
            written(&mesh, MeshFormat::Ply, PlyEncoding::Ascii),
        ),
        (
            MeshFormat::Ply,
            written(&mesh, MeshFormat::Ply, PlyEncoding::BinaryLittleEndian),
        ),
    ]
}

proptest! {
    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..512)) {
        for format in FORMATS {
            let _ = read(&bytes, format);
            let _ = read_triangulated(&bytes, format);
        }
    }

    #[test]
    fn random_text_never_panics(text in "[ -~\n]{0,300}", format in 0usize..3) {
        let prefix = ["v 1 2 3\nf ", "OFF\n", "ply\nformat ascii 1.0\nelement "][format];
        let _ = read_triangulated(format!("{prefix}{text}"), FORMATS[format]);
    }

    #[test]
    fn mutated_files_never_panic(
        file in 0usize..4,
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..4), 1..6),
        keep in any::<prop::sample::Index>(),
    ) {
        let (format, mut bytes) = valid_files().swap_remove(file);
        for (at, byte, kind) in edits {
            let i = at.index(bytes.len());
            match kind {
                0 => bytes[i] = byte,
                1 => bytes.insert(i, byte),
                2 => { bytes.remove(i); }
                _ => bytes[i] = bytes[i].wrapping_add(1),
            }
        }
        bytes.truncate(keep.index(bytes.len() + 1));
        let _ = read(&bytes, format);
        let _ = read_triangulated(&bytes, format);
    }
}
