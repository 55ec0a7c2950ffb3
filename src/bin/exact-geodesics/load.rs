//! Loading the mesh a command runs on: a file, or a generated shape (`gen:NAME`).

use exact_geodesics::mesh::io::{read_path, ReadOptions};
use exact_geodesics::mesh::shapes;
use exact_geodesics::TriMesh;
use std::path::Path;

/// Loads `spec`: `gen:SHAPE` generates a mesh, anything else is a file path. Warnings about a
/// usable but unusual mesh go to stderr.
pub fn load_mesh(spec: &str, triangulate: bool) -> Result<TriMesh, String> {
    let mesh = if let Some(shape) = spec.strip_prefix("gen:") {
        shapes::parse_shape(shape).map_err(|e| e.to_string())?
    } else {
        read_path(Path::new(spec), &ReadOptions { triangulate }).map_err(|e| e.to_string())?
    };
    for warning in mesh.validation().warnings() {
        eprintln!("warning: {spec}: {warning}");
    }
    Ok(mesh)
}
