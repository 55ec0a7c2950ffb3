//! OFF: a header (`OFF`, `COFF`, `NOFF`, `STOFF`, ... or none), a counts line, then one vertex
//! per line and one face per line. Per-vertex colours, normals and texture coordinates follow the
//! position, and face colours follow the corners, so both are skipped by reading only the
//! leading values of each line.

use super::{parse_error, parse_xyz, write_xyz, MeshIoError, ReadOptions, Soup, TextLines};
use crate::mesh::TriMesh;
use std::io::{BufRead, Write};

pub(super) fn read<R: BufRead>(
    reader: R,
    name: &str,
    options: &ReadOptions,
) -> Result<TriMesh, MeshIoError> {
    let mut lines = TextLines::new(reader, name);
    let mut soup = Soup::default();
    let mut header_seen = false;
    let mut counts = None;
    let mut faces_read = 0;
    let mut corners = Vec::new();
    while let Some((number, line)) = lines.next_line()? {
        let data = line.split('#').next().unwrap_or_default();
        let mut tokens = data.split_whitespace().peekable();
        if tokens.peek().is_none() {
            continue;
        }
        let error = |message: String| parse_error(name, number, message);
        if !header_seen {
            header_seen = true;
            // Some files omit the header; their first line is the counts line.
            if let Some(prefix) = tokens.peek().and_then(|t| t.strip_suffix("OFF")) {
                check_header(prefix).map_err(error)?;
                tokens.next();
                if tokens.peek() == Some(&"BINARY") {
                    return Err(error("binary OFF is not supported".to_owned()));
                }
                if tokens.peek().is_none() {
                    continue;
                }
            }
        }
        match counts {
            None => {
                let (vertices, faces) = parse_counts(tokens).map_err(error)?;
                soup = Soup::with_capacity(vertices, faces);
                counts = Some((vertices, faces));
            }
            Some((vertices, _)) if soup.positions.len() < vertices => {
                let p = parse_xyz(tokens).map_err(error)?;
                soup.push_vertex(p, Some(number));
            }
            Some((_, faces)) if faces_read < faces => {
                parse_face(tokens, &mut corners).map_err(error)?;
                soup.push_polygon(&corners, Some(number), options.triangulate)
                    .map_err(|corners| MeshIoError::NotATriangle {
                        file: name.to_owned(),
                        line: number,
                        corners,
                    })?;
                faces_read += 1;
            }
            // Anything after the last face (edges, say) is not needed.
            Some(_) => break,
        }
    }
    let end = lines.last_number().max(1);
    match counts {
        None => Err(parse_error(name, end, "the file has no OFF counts line")),
        Some((vertices, _)) if soup.positions.len() < vertices => {
            let message = format!(
                "the file ends after {} of {vertices} vertices",
                soup.positions.len()
            );
            Err(parse_error(name, end, message))
        }
        Some((_, faces)) if faces_read < faces => {
            let message = format!("the file ends after {faces_read} of {faces} faces");
            Err(parse_error(name, end, message))
        }
        Some(_) => soup.build(name, options),
    }
}

/// Accepts the 3-D header variants: `ST` (texture), `C` (colour) and `N` (normal) prefixes.
fn check_header(prefix: &str) -> Result<(), String> {
    if prefix.contains(['4', 'n']) {
        Err(format!("`{prefix}OFF`: only 3-D OFF files are supported"))
    } else if prefix.chars().all(|c| "STCN".contains(c)) {
        Ok(())
    } else {
        Err(format!("`{prefix}OFF` is not an OFF header"))
    }
}

/// Vertex and face counts; the edge count that usually follows is not needed.
fn parse_counts<'a>(mut tokens: impl Iterator<Item = &'a str>) -> Result<(usize, usize), String> {
    let mut count = |what: &str| {
        let token = tokens
            .next()
            .ok_or_else(|| format!("expected the OFF header or the vertex and face counts, but the {what} count is missing"))?;
        token
            .parse::<usize>()
            .map_err(|_| format!("expected the OFF header or the {what} count, found `{token}`"))
    };
    Ok((count("vertex")?, count("face")?))
}

/// `n i_1 ... i_n`, 0-based, into `corners`; values after the corners (colours) are skipped.
fn parse_face<'a>(
    mut tokens: impl Iterator<Item = &'a str>,
    corners: &mut Vec<u32>,
) -> Result<(), String> {
    let count = tokens.next().unwrap_or_default();
    let count: usize = count
        .parse()
        .map_err(|_| format!("`{count}` is not a corner count"))?;
    corners.clear();
    for _ in 0..count {
        let token = tokens
            .next()
            .ok_or_else(|| format!("the face has fewer than the {count} corners it announces"))?;
        let index = token
            .parse()
            .map_err(|_| format!("`{token}` is not a vertex index (0 to 4294967295)"))?;
        corners.push(index);
    }
    Ok(())
}

pub(super) fn write(mesh: &TriMesh, out: &mut impl Write) -> std::io::Result<()> {
    writeln!(out, "OFF")?;
    writeln!(out, "{} {} 0", mesh.vertex_count(), mesh.face_count())?;
    for &p in mesh.positions() {
        write_xyz(out, "", p)?;
    }
    for f in mesh.faces() {
        writeln!(out, "3 {} {} {}", f[0], f[1], f[2])?;
    }
    Ok(())
}
