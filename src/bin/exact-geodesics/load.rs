//! Loading the mesh a command runs on: a file, or a generated shape (`gen:NAME`).

use clap::Args;
use exact_geodesics::mesh::io::{read_path, ReadOptions};
use exact_geodesics::mesh::shapes;
use exact_geodesics::TriMesh;
use std::path::Path;

/// How a mesh file is read.
#[derive(Args)]
pub struct ReadArgs {
    /// Split polygons with more than three corners into triangles instead of refusing them.
    #[arg(long)]
    pub triangulate: bool,
    /// Refuse a mesh that is not a manifold along its edges (an edge shared by more than two
    /// faces, a face repeating another) instead of propagating on it.
    #[arg(long)]
    pub strict: bool,
}

impl ReadArgs {
    /// The reader's options.
    pub fn options(&self) -> ReadOptions {
        ReadOptions {
            triangulate: self.triangulate,
            strict: self.strict,
        }
    }
}

/// Loads `spec`: `gen:SHAPE` generates a mesh, anything else is a file path. Warnings about a
/// usable but unusual mesh go to stderr.
pub fn load_mesh(spec: &str, options: &ReadOptions) -> Result<TriMesh, String> {
    let mesh = if let Some(shape) = spec.strip_prefix("gen:") {
        let mesh = shapes::parse_shape(shape).map_err(|e| e.to_string())?;
        if options.strict {
            mesh.require_manifold()
                .map_err(|e| format!("{spec}: {e}"))?;
        }
        mesh
    } else {
        read_path(Path::new(spec), options).map_err(|e| e.to_string())?
    };
    for warning in mesh.validation().warnings() {
        eprintln!("warning: {spec}: {warning}");
    }
    Ok(mesh)
}
