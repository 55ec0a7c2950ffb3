//! Errors raised while reading or writing a mesh file.

use crate::mesh::MeshError;
use thiserror::Error;

/// Why a mesh file could not be read or written.
///
/// Every variant names the file (as given to the reader); text positions are 1-based line
/// numbers, so that `FILE:LINE:` at the start of a message can be pasted into an editor.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum MeshIoError {
    /// The file could not be opened, read or written.
    #[error("{file}: {source}")]
    Io {
        /// The file.
        file: String,
        /// What the operating system said.
        source: std::io::Error,
    },
    /// A line of a text file (or of a PLY header) is malformed.
    #[error("{file}:{line}: {message}")]
    Parse {
        /// The file.
        file: String,
        /// The 1-based line.
        line: usize,
        /// What is wrong with it.
        message: String,
    },
    /// The binary data of a PLY file is malformed or ends early. Binary data has no lines, so
    /// the error names the element instead.
    #[error("{file}: binary {element} element {index} (0-based): {message}")]
    BinaryParse {
        /// The file.
        file: String,
        /// The element's name in the header, such as `vertex` or `face`.
        element: String,
        /// The 0-based index of the element among those with its name.
        index: usize,
        /// What is wrong with it.
        message: String,
    },
    /// A face of a text file has fewer than three corners, or more without
    /// [`ReadOptions::triangulate`](super::ReadOptions::triangulate). Binary PLY files report
    /// the same problem as [`MeshIoError::BinaryParse`].
    #[error("{file}:{line}: {}", corner_problem(*.corners))]
    NotATriangle {
        /// The file.
        file: String,
        /// The 1-based line of the face.
        line: usize,
        /// How many corners the face has.
        corners: usize,
    },
    /// The file's extension names none of the supported formats.
    #[error("{file}: unknown mesh format (expected the extension .obj, .off or .ply)")]
    UnknownFormat {
        /// The file.
        file: String,
    },
    /// The file parsed, but its vertices and faces are not a mesh (see [`MeshError`]).
    #[error("{}{source}", location(.file, *.line))]
    Mesh {
        /// The file.
        file: String,
        /// The 1-based line of the offending vertex or face; `None` in binary files and for
        /// errors about the mesh as a whole.
        line: Option<usize>,
        /// What [`TriMesh::new`](crate::TriMesh::new) refused.
        source: MeshError,
    },
}

/// `FILE:LINE: ` or `FILE: `.
fn location(file: &str, line: Option<usize>) -> String {
    match line {
        Some(line) => format!("{file}:{line}: "),
        None => format!("{file}: "),
    }
}

/// Explains a face that is not a triangle, and whether triangulating would help.
pub(super) fn corner_problem(corners: usize) -> String {
    if corners < 3 {
        format!("a face needs at least 3 corners, this one has {corners}")
    } else {
        format!("a face with {corners} corners is not a triangle (enable triangulation to split polygons)")
    }
}
