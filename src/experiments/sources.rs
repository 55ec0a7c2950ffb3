//! Source vertices for the experiments. [LZT §6] does not say where its sources were; we draw
//! several seeded random vertices per model and report one row per source.

use crate::mesh::shapes::SplitMix64;
use crate::{TriMesh, VertexId};

/// `count` distinct vertices that some face uses, drawn by a seeded partial Fisher-Yates shuffle
/// (`SplitMix64`) of those vertices in index order: the same mesh, count and seed give the same
/// vertices on every platform. Fewer are returned if the mesh has fewer such vertices.
///
/// # Example
/// ```
/// use exact_geodesics::{experiments::random_sources, mesh::shapes};
/// let cube = shapes::cube();
/// let picked = random_sources(&cube, 3, 7);
/// assert_eq!(picked.len(), 3);
/// assert_eq!(picked, random_sources(&cube, 3, 7));
/// assert_eq!(random_sources(&cube, 100, 7).len(), 8);
/// ```
pub fn random_sources(mesh: &TriMesh, count: usize, seed: u64) -> Vec<VertexId> {
    let mut used: Vec<u32> = mesh.faces().iter().flatten().copied().collect();
    used.sort_unstable();
    used.dedup();
    let count = count.min(used.len());
    let mut rng = SplitMix64::new(seed);
    for i in 0..count {
        let j = i + (rng.next_u64() % (used.len() - i) as u64) as usize;
        used.swap(i, j);
    }
    used.truncate(count);
    used.into_iter().map(VertexId).collect()
}
