//! A corpus of degenerate meshes, for checking that a geodesic distance keeps its invariants
//! in every backend: no silently wrong answer on degenerate input.
//!
//! [`degenerate_case`] builds seeded meshes of ten [`DegenerateKind`]s (coincident vertices and
//! zero-length edges, zero-area faces, exactly flat grids and fans, slivers, symmetric
//! pyramids, scales from `2^-600` to `2^600`, mixed magnitudes, bowties, several components and
//! loose vertices).

mod bumpy;
mod draw;
mod figures;
mod generate;
mod measure;
mod soup;

pub use generate::{degenerate_case, degenerate_mesh, DegenerateCase, DegenerateKind, MeshSize};
