//! Reading and writing OBJ, OFF and PLY (ASCII and binary) meshes.
//!
//! Readers keep the file's vertex order, including vertices that no face uses, and its face
//! order, so that vertex and face numbers mean the same thing in the file and in the [`TriMesh`].
//! Every error names the file and, for text, the line, including the errors that
//! [`TriMesh::new`] raises about a particular vertex or face.
//!
//! ```
//! use exact_geodesics::mesh::io::{read_from, MeshFormat, ReadOptions};
//! let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
//! let mesh = read_from(obj.as_bytes(), MeshFormat::Obj, "tri.obj", &ReadOptions::default())?;
//! assert_eq!(mesh.face_count(), 1);
//! # Ok::<(), exact_geodesics::mesh::io::MeshIoError>(())
//! ```

mod error;
mod obj;
mod off;
mod ply;

pub use error::MeshIoError;

use crate::mesh::{MeshError, TriMesh};
use glam::DVec3;
use std::fs::File;
use std::io::{BufRead, BufReader, BufWriter, Write};
use std::path::Path;

/// A mesh file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MeshFormat {
    /// Wavefront OBJ.
    Obj,
    /// Object File Format (Geomview, Princeton Shape Benchmark).
    Off,
    /// Polygon File Format (Stanford), ASCII or binary.
    Ply,
}

impl MeshFormat {
    /// The format named by a path's extension (`.obj`, `.off`, `.ply`, in any case).
    pub fn from_path(path: &Path) -> Option<MeshFormat> {
        let extension = path.extension()?.to_str()?;
        [
            ("obj", MeshFormat::Obj),
            ("off", MeshFormat::Off),
            ("ply", MeshFormat::Ply),
        ]
        .into_iter()
        .find(|(name, _)| extension.eq_ignore_ascii_case(name))
        .map(|(_, format)| format)
    }
}

/// How to read a mesh file.
#[derive(Default, Clone, Debug)]
pub struct ReadOptions {
    /// Split polygons with more than three corners into a fan of triangles around their first
    /// corner. Off by default because a fan is a choice the engine cannot undo: geodesics on the
    /// result depend on which diagonals were drawn, so the caller should opt in knowingly.
    pub triangulate: bool,
    /// Refuse a surface that is not a manifold along its edges ([`TriMesh::require_manifold`]:
    /// an edge shared by more than two faces, a face repeating another), naming the line of the
    /// face that made it so. Off by default: such meshes propagate.
    pub strict: bool,
}

/// How [`write_to`] encodes a PLY file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PlyEncoding {
    /// Text, one element per line.
    #[default]
    Ascii,
    /// `binary_little_endian`: smaller and faster, and still exact.
    BinaryLittleEndian,
}

/// Reads a mesh file, choosing the format by the extension.
///
/// # Errors
/// [`MeshIoError::UnknownFormat`] for an unknown extension, [`MeshIoError::Io`] if the file
/// cannot be read, and otherwise as [`read_from`].
pub fn read_path(path: &Path, options: &ReadOptions) -> Result<TriMesh, MeshIoError> {
    let name = path.display().to_string();
    let Some(format) = MeshFormat::from_path(path) else {
        return Err(MeshIoError::UnknownFormat { file: name });
    };
    let file = File::open(path).map_err(|source| MeshIoError::Io {
        file: name.clone(),
        source,
    })?;
    read_from(BufReader::new(file), format, &name, options)
}

/// Reads a mesh in the given format; `name` is what error messages call the file.
///
/// # Errors
/// [`MeshIoError::Parse`] or [`MeshIoError::BinaryParse`] for malformed input,
/// [`MeshIoError::NotATriangle`] for polygons, [`MeshIoError::Mesh`] when the vertices and faces
/// are not a valid mesh, [`MeshIoError::Io`] when reading fails.
pub fn read_from<R: BufRead>(
    reader: R,
    format: MeshFormat,
    name: &str,
    options: &ReadOptions,
) -> Result<TriMesh, MeshIoError> {
    match format {
        MeshFormat::Obj => obj::read(reader, name, options),
        MeshFormat::Off => off::read(reader, name, options),
        MeshFormat::Ply => ply::read(reader, name, options),
    }
}

/// Writes a mesh file, choosing the format by the extension (PLY as ASCII).
///
/// # Errors
/// [`MeshIoError::UnknownFormat`] for an unknown extension, [`MeshIoError::Io`] if the file
/// cannot be created or written.
pub fn write_path(mesh: &TriMesh, path: &Path) -> Result<(), MeshIoError> {
    let name = path.display().to_string();
    let Some(format) = MeshFormat::from_path(path) else {
        return Err(MeshIoError::UnknownFormat { file: name });
    };
    File::create(path)
        .and_then(|file| write_mesh(mesh, file, format, PlyEncoding::Ascii))
        .map_err(|source| MeshIoError::Io { file: name, source })
}

/// Writes a mesh in the given format (`ply` matters only for [`MeshFormat::Ply`]).
///
/// Coordinates are written so that reading the file back gives the same `f64` bits, and vertex
/// and face order are kept.
///
/// # Errors
/// [`MeshIoError::Io`], naming the file `<writer>`, if writing fails.
pub fn write_to<W: Write>(
    mesh: &TriMesh,
    writer: W,
    format: MeshFormat,
    ply: PlyEncoding,
) -> Result<(), MeshIoError> {
    write_mesh(mesh, writer, format, ply).map_err(|source| MeshIoError::Io {
        file: "<writer>".to_owned(),
        source,
    })
}

fn write_mesh<W: Write>(
    mesh: &TriMesh,
    writer: W,
    format: MeshFormat,
    ply: PlyEncoding,
) -> std::io::Result<()> {
    let mut out = BufWriter::new(writer);
    match format {
        MeshFormat::Obj => obj::write(mesh, &mut out)?,
        MeshFormat::Off => off::write(mesh, &mut out)?,
        MeshFormat::Ply => ply::write(mesh, &mut out, ply)?,
    }
    out.flush()
}

/// Counts from a file's header are untrusted: reserve at most this many elements up front and
/// let vectors grow with the data actually read.
const MAX_RESERVE: usize = 1 << 16;

/// Vertices and triangles as read, with the line each came from so that errors from
/// [`TriMesh::new`] can point into the file.
#[derive(Default)]
struct Soup {
    positions: Vec<DVec3>,
    faces: Vec<[u32; 3]>,
    /// Line of each vertex; empty for binary files.
    vertex_lines: Vec<usize>,
    /// Line of each triangle; a polygon's triangles share its line. Empty for binary files.
    face_lines: Vec<usize>,
}

impl Soup {
    fn with_capacity(vertices: usize, faces: usize) -> Soup {
        let (vertices, faces) = (vertices.min(MAX_RESERVE), faces.min(MAX_RESERVE));
        Soup {
            positions: Vec::with_capacity(vertices),
            faces: Vec::with_capacity(faces),
            vertex_lines: Vec::with_capacity(vertices),
            face_lines: Vec::with_capacity(faces),
        }
    }

    fn push_vertex(&mut self, position: DVec3, line: Option<usize>) {
        self.positions.push(position);
        self.vertex_lines.extend(line);
    }

    /// Whether a face with this many corners can be added.
    fn accepts(corners: usize, triangulate: bool) -> bool {
        corners == 3 || (corners > 3 && triangulate)
    }

    /// Adds a triangle, or a polygon as a fan around its first corner if `triangulate`.
    /// On refusal returns the corner count, for the caller to report where it can.
    fn push_polygon(
        &mut self,
        corners: &[u32],
        line: Option<usize>,
        triangulate: bool,
    ) -> Result<(), usize> {
        if !Soup::accepts(corners.len(), triangulate) {
            return Err(corners.len());
        }
        for pair in corners[1..].windows(2) {
            self.faces.push([corners[0], pair[0], pair[1]]);
            self.face_lines.extend(line);
        }
        Ok(())
    }

    fn build(self, file: &str, options: &ReadOptions) -> Result<TriMesh, MeshIoError> {
        let Soup {
            positions,
            faces,
            vertex_lines,
            face_lines,
        } = self;
        let strict = |mesh: TriMesh| match options.strict {
            true => mesh.require_manifold().map(|()| mesh),
            false => Ok(mesh),
        };
        TriMesh::new(positions, faces)
            .and_then(strict)
            .map_err(|source| {
                let line = match &source {
                    MeshError::NonFiniteCoordinate { vertex, .. } => vertex_lines.get(*vertex),
                    MeshError::VertexIndexOutOfRange { face, .. }
                    | MeshError::RepeatedVertex { face, .. }
                    | MeshError::DuplicateFace { face, .. } => face_lines.get(*face),
                    // The last listed face is the one that made the edge non-manifold.
                    MeshError::NonManifoldEdge { faces, .. } => {
                        faces.iter().max().and_then(|&f| face_lines.get(f))
                    }
                    _ => None,
                };
                MeshIoError::Mesh {
                    file: file.to_owned(),
                    line: line.copied(),
                    source,
                }
            })
    }
}

/// What UTF-8 makes of U+FEFF, the byte-order mark some Windows tools start a file with.
const BYTE_ORDER_MARK: &[u8] = "\u{feff}".as_bytes();

/// Numbered lines of a text file. Bytes that are not UTF-8 become U+FFFD, so they are harmless
/// in comments and fail as numbers, where the error can name the line.
struct TextLines<R> {
    reader: R,
    file: String,
    number: usize,
    bytes: Vec<u8>,
    /// The line when its bytes are not UTF-8.
    text: String,
}

impl<R: BufRead> TextLines<R> {
    fn new(reader: R, file: &str) -> TextLines<R> {
        TextLines {
            reader,
            file: file.to_owned(),
            number: 0,
            bytes: Vec::new(),
            text: String::new(),
        }
    }

    /// The next line that is not blank, without its line ending, and its 1-based number;
    /// `None` at the end. No format gives blank lines a meaning.
    fn next_line(&mut self) -> Result<Option<(usize, &str)>, MeshIoError> {
        // The line is returned after the loop: returning a borrow from inside it would keep
        // the buffers borrowed across iterations.
        loop {
            self.bytes.clear();
            let read = self
                .reader
                .read_until(b'\n', &mut self.bytes)
                .map_err(|source| MeshIoError::Io {
                    file: self.file.clone(),
                    source,
                })?;
            if read == 0 {
                return Ok(None);
            }
            self.number += 1;
            if self.number == 1 && self.bytes.starts_with(BYTE_ORDER_MARK) {
                self.bytes.drain(..BYTE_ORDER_MARK.len());
            }
            // Blank means only whitespace characters: the first byte that is not ASCII
            // whitespace settles it, unless it starts a longer character (U+00A0 is blank, the
            // U+FFFD that stands for a bad byte is not).
            let blank = match self.bytes.iter().find(|b| !b" \t\n\r\x0b\x0c".contains(b)) {
                None => true,
                Some(b) if b.is_ascii() => false,
                Some(_) => String::from_utf8_lossy(&self.bytes).trim().is_empty(),
            };
            if !blank {
                break;
            }
        }
        // Borrowing the bytes when they are UTF-8 saves copying every line.
        let text = match std::str::from_utf8(&self.bytes) {
            Ok(text) => text,
            Err(_) => {
                self.text.clear();
                self.text.push_str(&String::from_utf8_lossy(&self.bytes));
                &self.text
            }
        };
        Ok(Some((self.number, text.trim_end_matches(['\n', '\r']))))
    }

    /// The number of the last line read (0 before the first), where a truncated file ends.
    fn last_number(&self) -> usize {
        self.number
    }

    fn into_inner(self) -> R {
        self.reader
    }
}

fn parse_error(file: &str, line: usize, message: impl Into<String>) -> MeshIoError {
    MeshIoError::Parse {
        file: file.to_owned(),
        line,
        message: message.into(),
    }
}

/// Parses the first three tokens as a position. NaN and infinities parse, so that
/// [`TriMesh::new`] refuses them with a clearer message than a syntax error would give.
fn parse_xyz<'a>(mut tokens: impl Iterator<Item = &'a str>) -> Result<DVec3, String> {
    let mut p = [0.0; 3];
    for c in &mut p {
        let token = tokens.next().ok_or("a vertex needs x, y and z")?;
        *c = token
            .parse()
            .map_err(|_| format!("`{token}` is not a number"))?;
    }
    Ok(DVec3::from(p))
}

/// Writes `f64`s in Rust's shortest form that parses back to the same bits (`{:?}` rather than
/// `{}`, which spells 1e300 with 301 digits).
fn write_xyz(out: &mut impl Write, prefix: &str, p: DVec3) -> std::io::Result<()> {
    writeln!(out, "{prefix}{:?} {:?} {:?}", p.x, p.y, p.z)
}
