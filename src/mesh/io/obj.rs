//! Wavefront OBJ: `v` and `f` statements; everything about materials, normals, texture
//! coordinates, groups and free-form geometry is skipped.

use super::{parse_error, parse_xyz, write_xyz, MeshIoError, ReadOptions, Soup, TextLines};
use crate::mesh::TriMesh;
use std::io::{BufRead, Write};

/// Statements that carry nothing a triangle mesh needs. Anything else that is neither `v` nor
/// `f` is refused, so that a file in another format is not read as an empty mesh.
const SKIPPED: &[&str] = &[
    "vt",
    "vn",
    "vp",
    "l",
    "p",
    "g",
    "o",
    "s",
    "mg",
    "usemtl",
    "mtllib",
    "usemap",
    "maplib",
    "lod",
    "bevel",
    "c_interp",
    "d_interp",
    "shadow_obj",
    "trace_obj",
    "ctech",
    "stech",
    "cstype",
    "deg",
    "bmat",
    "step",
    "curv",
    "curv2",
    "surf",
    "parm",
    "trim",
    "hole",
    "scrv",
    "sp",
    "end",
    "con",
];

pub(super) fn read<R: BufRead>(
    reader: R,
    name: &str,
    options: &ReadOptions,
) -> Result<TriMesh, MeshIoError> {
    let mut lines = TextLines::new(reader, name);
    let mut soup = Soup::default();
    let mut corners = Vec::new();
    while let Some((number, line)) = lines.next_line()? {
        let mut tokens = Words::new(line);
        let Some(keyword) = tokens.next() else {
            continue;
        };
        match keyword {
            "v" => {
                let p = parse_xyz(tokens).map_err(|m| parse_error(name, number, m))?;
                soup.push_vertex(p, Some(number));
            }
            "f" => {
                corners.clear();
                for token in tokens {
                    let index = resolve(token, soup.positions.len())
                        .map_err(|m| parse_error(name, number, m))?;
                    corners.push(index);
                }
                soup.push_polygon(&corners, Some(number), options.triangulate)
                    .map_err(|corners| MeshIoError::NotATriangle {
                        file: name.to_owned(),
                        line: number,
                        corners,
                    })?;
            }
            _ if SKIPPED.contains(&keyword) => {}
            _ => {
                let message = format!("unknown OBJ statement `{keyword}`");
                return Err(parse_error(name, number, message));
            }
        }
    }
    soup.build(name, options)
}

/// The words of a line before any `#`, split at whitespace as [`str::split_whitespace`] splits.
/// ASCII lines, nearly all of them, are split byte by byte, which is faster than decoding them.
enum Words<'a> {
    /// The rest of the line, which may still hold a comment.
    Ascii(&'a str),
    Unicode(std::str::SplitWhitespace<'a>),
}

impl<'a> Words<'a> {
    fn new(line: &'a str) -> Words<'a> {
        match line.is_ascii() {
            true => Words::Ascii(line),
            false => {
                let data = line.split('#').next().unwrap_or_default();
                Words::Unicode(data.split_whitespace())
            }
        }
    }
}

impl<'a> Iterator for Words<'a> {
    type Item = &'a str;

    fn next(&mut self) -> Option<&'a str> {
        // The ASCII characters that `char::is_whitespace` accepts.
        let space = |b: u8| matches!(b, b' ' | b'\t'..=b'\r');
        match self {
            Words::Ascii(rest) => {
                let start = rest.bytes().position(|b| !space(b))?;
                let word = &rest[start..];
                let end = word
                    .bytes()
                    .position(|b| space(b) || b == b'#')
                    .unwrap_or(word.len());
                let (word, after) = word.split_at(end);
                *rest = match after.starts_with('#') {
                    true => "",
                    false => after,
                };
                (!word.is_empty()).then_some(word)
            }
            Words::Unicode(words) => words.next(),
        }
    }
}

/// The 0-based vertex of a face corner `v`, `v/vt`, `v/vt/vn` or `v//vn`. OBJ counts from 1,
/// and negative numbers count back from the last vertex read so far. An index past the end is
/// left for [`TriMesh::new`] to report, since OBJ allows faces before their vertices.
fn resolve(token: &str, vertices_so_far: usize) -> Result<u32, String> {
    let number = match plain_number(token) {
        Some(number) => number,
        None => token
            .split('/')
            .next()
            .unwrap_or_default()
            .parse()
            .map_err(|_| format!("`{token}` is not a vertex reference"))?,
    };
    let index = match number {
        0 => return Err("vertex references count from 1; 0 is not one".to_owned()),
        n if n > 0 => n - 1,
        n => i64::try_from(vertices_so_far).unwrap_or(i64::MAX) + n,
    };
    if index < 0 {
        return Err(format!(
            "relative vertex reference {number} reaches before the first vertex ({vertices_so_far} read so far)"
        ));
    }
    u32::try_from(index).map_err(|_| format!("vertex reference {number} is out of range"))
}

/// The number of a corner written as at most 18 digits (no `i64` overflow) up to the end or the
/// first `/`, read in one pass; `None` for any other form, which `str::parse` then reads or
/// refuses. Nearly every corner is written so; splitting at `/` and then parsing read the digits
/// twice.
fn plain_number(token: &str) -> Option<i64> {
    let mut number = 0;
    for (i, b) in token.bytes().enumerate() {
        match b {
            b'0'..=b'9' if i < 18 => number = 10 * number + i64::from(b - b'0'),
            b'/' if i > 0 => return Some(number),
            _ => return None,
        }
    }
    (!token.is_empty()).then_some(number)
}

pub(super) fn write(mesh: &TriMesh, out: &mut impl Write) -> std::io::Result<()> {
    writeln!(
        out,
        "# {} vertices, {} faces",
        mesh.vertex_count(),
        mesh.face_count()
    )?;
    for &p in mesh.positions() {
        write_xyz(out, "v ", p)?;
    }
    for f in mesh.faces() {
        writeln!(out, "f {} {} {}", f[0] + 1, f[1] + 1, f[2] + 1)?;
    }
    Ok(())
}
