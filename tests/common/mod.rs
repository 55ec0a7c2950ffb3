//! Ground truths for the engine's tests, computed independently of the engine with plain f64
//! and the mesh's accessors only.
#![allow(dead_code)] // Each test binary uses a different part of this module.

#[cfg(feature = "cli")]
pub mod cli;
pub mod strategies;

use exact_geodesics::mesh::shapes::SplitMix64;
use exact_geodesics::scalar::{Adaptive, Real};
use exact_geodesics::{
    propagate, FaceId, PropagateOptions, Scalar, SurfacePoint, TriMesh, VertexId,
};
use std::collections::BinaryHeap;

#[derive(PartialEq)]
struct Entry(f64, usize);
impl Eq for Entry {}
impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Entry {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        other.0.total_cmp(&self.0)
    }
}

/// Dijkstra from `source` over a graph given by its weighted adjacency.
fn dijkstra(n: usize, source: usize, neighbours: impl Fn(usize) -> Vec<(usize, f64)>) -> Vec<f64> {
    let mut best = vec![f64::INFINITY; n];
    let mut heap = BinaryHeap::new();
    best[source] = 0.0;
    heap.push(Entry(0.0, source));
    while let Some(Entry(d, u)) = heap.pop() {
        if d > best[u] {
            continue;
        }
        for (v, w) in neighbours(u) {
            if d + w < best[v] {
                best[v] = d + w;
                heap.push(Entry(d + w, v));
            }
        }
    }
    best
}

/// Shortest paths along mesh edges from `source`: an upper bound of geodesic distance.
pub fn edge_graph_dijkstra(mesh: &TriMesh, source: usize) -> Vec<f64> {
    dijkstra(mesh.vertex_count(), source, |u| {
        let u = VertexId(u as u32);
        mesh.vertex_edges(u)
            .iter()
            .map(|&e| {
                let v = mesh.edge(e).other(u).expect("incident edge");
                (v.index(), mesh.position(u).distance(mesh.position(v)))
            })
            .collect()
    })
}

type P2 = [f64; 2];

fn cross(a: P2, b: P2) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

/// Places `c` in the plane given the placements `pa`, `pb` of `a`, `b`: on the left of the
/// line from `pa` to `pb` if `left`, else on its right. The foot and the height of `c` over
/// the edge are taken from the dot and cross products of the edge vectors in space, which keep
/// the height of a sliver to its relative precision (the law of cosines, `ac^2 - x^2`, left
/// heights of 1e-9 beside unit edges as noise of 1e-8, on either side of the edge).
fn unfold(mesh: &TriMesh, [a, b, c]: [usize; 3], [pa, pb]: [P2; 2], left: bool) -> P2 {
    let p = |v: usize| mesh.position(VertexId(v as u32));
    let (ab, ac) = (p(b) - p(a), p(c) - p(a));
    let l = ab.length();
    let (x, h) = (ac.dot(ab) / l, ac.cross(ab).length() / l);
    let placed = (pb[0] - pa[0]).hypot(pb[1] - pa[1]);
    let u = [(pb[0] - pa[0]) / placed, (pb[1] - pa[1]) / placed];
    let h = if left { h } else { -h };
    [pa[0] + x * u[0] - h * u[1], pa[1] + x * u[1] + h * u[0]]
}

/// Straight segments from vertex `u` to every vertex it sees within an unfolded strip of at most
/// `max_faces` faces: `(target, length)`.
///
/// Depth-first over strips, keeping the cone of directions from u that cross every edge so far
/// and stopping when it is empty. No slack: a vertex is seen only inside the cone or on its
/// boundary as computed, and a cone as thin as the rounding is followed (on slivers, geodesics
/// pass through windows 1e-13 wide). A segment that runs exactly through a vertex and is lost
/// to rounding is found as two segments joined at that vertex, of the same length; a slack
/// relative to the cone's far side admitted, beside a needle 1e-9 long, segments 1e-3 outside
/// it, shorter than the surface allows.
fn straight_segments(mesh: &TriMesh, u: usize, max_faces: usize) -> Vec<(usize, f64)> {
    let mut found = Vec::new();
    // A strip's last face: corners, their placements, the edge it was entered by, and the cone
    // of directions from u (at the origin) that cross every edge so far.
    struct State {
        face: usize,
        corners: [usize; 3],
        placed: [P2; 3],
        /// Whether `placed` runs counterclockwise, as built (each face of a strip is its
        /// predecessor's mirror image across their edge), not as computed.
        counterclockwise: bool,
        entry: Option<(usize, usize)>,
        cone: (P2, P2),
        depth: usize,
    }
    let mut stack = Vec::new();
    for &f in mesh.vertex_faces(VertexId(u as u32)) {
        let c = mesh.faces()[f.index()].map(|v| v as usize);
        let k = c.iter().position(|&v| v == u).expect("corner");
        let (a, b) = (c[(k + 1) % 3], c[(k + 2) % 3]);
        let pu = [0.0, 0.0];
        let pa = [
            mesh.position(VertexId(u as u32))
                .distance(mesh.position(VertexId(a as u32))),
            0.0,
        ];
        let pb = unfold(mesh, [u, a, b], [pu, pa], true);
        stack.push(State {
            face: f.index(),
            corners: [u, a, b],
            placed: [pu, pa, pb],
            counterclockwise: true,
            entry: None,
            cone: (pa, pb),
            depth: 1,
        });
    }
    while let Some(s) = stack.pop() {
        let (lo, hi) = s.cone;
        for i in 0..3 {
            let w = s.corners[i];
            let d = s.placed[i];
            let norm = (d[0] * d[0] + d[1] * d[1]).sqrt();
            if w != u && norm > 0.0 && cross(lo, d) >= 0.0 && cross(d, hi) >= 0.0 {
                found.push((w, norm));
            }
        }
        if s.depth == max_faces {
            continue;
        }
        for i in 0..3 {
            let (a, b) = (s.corners[i], s.corners[(i + 1) % 3]);
            // A shortest path from u never crosses an edge at u transversally (following the
            // edge to the crossing point would be no longer, and would make the path bend
            // inside an edge), so strips that come back around u can stop there.
            if a == u || b == u || s.entry == Some((a.min(b), a.max(b))) {
                continue;
            }
            let (mut pa, mut pb) = (s.placed[i], s.placed[(i + 1) % 3]);
            if cross(pa, pb) < 0.0 {
                std::mem::swap(&mut pa, &mut pb);
            }
            let new_lo = if cross(lo, pa) > 0.0 { pa } else { lo };
            let new_hi = if cross(pb, hi) > 0.0 { pb } else { hi };
            if cross(new_lo, new_hi) <= 0.0 {
                continue;
            }
            let edge = mesh
                .edge_between(VertexId(a as u32), VertexId(b as u32))
                .expect("face edge");
            let Some(next) = mesh
                .edge(edge)
                .faces()
                .into_iter()
                .flatten()
                .find(|f| f.index() != s.face)
            else {
                continue;
            };
            let c = mesh.faces()[next.index()].map(|v| v as usize);
            let apex = *c.iter().find(|&&v| v != a && v != b).expect("apex");
            // The face beyond lies on the other side of the edge: on the right of it in
            // a counterclockwise face.
            let (qa, qb) = (s.placed[i], s.placed[(i + 1) % 3]);
            let pc = unfold(mesh, [a, b, apex], [qa, qb], !s.counterclockwise);
            stack.push(State {
                face: next.index(),
                corners: [a, b, apex],
                placed: [qa, qb, pc],
                counterclockwise: !s.counterclockwise,
                entry: Some((a.min(b), a.max(b))),
                cone: (new_lo, new_hi),
                depth: s.depth + 1,
            });
        }
    }
    found
}

/// The exact geodesic distance between two vertices of a small mesh, by exhaustive search:
/// straight segments between vertices in every unfolding of up to `max_faces` faces (a geodesic
/// is such segments joined at vertices), then Dijkstra over them.
pub fn brute_force_vertex_distance(
    mesh: &TriMesh,
    source: usize,
    target: usize,
    max_faces: usize,
) -> f64 {
    brute_force_vertex_distances(mesh, source, max_faces)[target]
}

/// [`brute_force_vertex_distance`] from `source` to every vertex at once (the segment search is
/// the expensive part and does not depend on the target); `f64::INFINITY` when unreachable.
///
/// Exact (to the rounding of the unfoldings, ulps of the distances) as soon as `max_faces` is
/// at least the number of faces any straight piece of a geodesic crosses; with a smaller bound
/// it is still an upper bound (every path it finds lies on the surface), never below the true
/// distance. Slivers and needles are measured (`slivers_have_their_exact_distances_by_brute_force`
/// in `tests/shapes_and_oracles.rs`).
///
/// # Panics
/// On a mesh with an edge of length zero (coincident vertices), which has no unfolding.
pub fn brute_force_vertex_distances(mesh: &TriMesh, source: usize, max_faces: usize) -> Vec<f64> {
    for f in mesh.faces() {
        for k in 0..3 {
            let (a, b) = (VertexId(f[k]), VertexId(f[(k + 1) % 3]));
            assert!(
                mesh.position(a) != mesh.position(b),
                "the brute force unfolds no edge of length zero ({a:?}, {b:?})"
            );
        }
    }
    let segments: Vec<Vec<(usize, f64)>> = (0..mesh.vertex_count())
        .map(|u| straight_segments(mesh, u, max_faces))
        .collect();
    dijkstra(mesh.vertex_count(), source, |u| segments[u].clone())
}

/// The straight-line distance between two vertices: the geodesic distance on a planar convex
/// mesh, where the segment between any two points stays on the surface.
pub fn planar_straight_distance(mesh: &TriMesh, a: usize, b: usize) -> f64 {
    mesh.position(VertexId(a as u32))
        .distance(mesh.position(VertexId(b as u32)))
}

/// A uniformly random point of a uniformly random face.
pub fn random_face_point(mesh: &TriMesh, rng: &mut SplitMix64) -> SurfacePoint {
    let face = FaceId((rng.next_u64() % mesh.face_count() as u64) as u32);
    let (u, v) = (rng.next_f64(), rng.next_f64());
    let (u, v) = if u + v > 1.0 {
        (1.0 - u, 1.0 - v)
    } else {
        (u, v)
    };
    SurfacePoint::Face {
        face,
        bary: [1.0 - u - v, u, v],
    }
}

/// A mesh of `tests/data`, by file name.
pub fn data_mesh(name: &str) -> TriMesh {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name);
    exact_geodesics::mesh::io::read_path(&path, &Default::default()).expect("test mesh")
}

/// Two unit right triangles apart: vertices 3 to 5 are unreachable from 0 to 2.
pub fn two_triangles() -> TriMesh {
    TriMesh::new(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [5.0, 0.0, 0.0],
            [6.0, 0.0, 0.0],
            [5.0, 1.0, 0.0],
        ],
        vec![[0, 1, 2], [3, 4, 5]],
    )
    .expect("a usable mesh")
}

/// The vertex distances from the vertex `source` in the backend `S`.
pub fn distances<S: Scalar>(mesh: &TriMesh, source: u32) -> Vec<f64> {
    propagate::<S>(
        mesh,
        &[SurfacePoint::Vertex(VertexId(source))],
        &PropagateOptions::default(),
    )
    .expect("valid source")
    .vertex_distances()
}

/// The distances from `source` in all three backends, labelled.
pub fn every_backend(mesh: &TriMesh, source: u32) -> [(&'static str, Vec<f64>); 3] {
    [
        ("f64", distances::<f64>(mesh, source)),
        ("adaptive", distances::<Adaptive>(mesh, source)),
        ("exact", distances::<Real>(mesh, source)),
    ]
}

/// The straight-line distance between two vertices, without overflow or underflow at any
/// scale.
pub fn straight(mesh: &TriMesh, a: u32, b: u32) -> f64 {
    let (p, q) = (mesh.position(VertexId(a)), mesh.position(VertexId(b)));
    let d = [0, 1, 2].map(|i| q[i] - p[i]);
    let m = d.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    if m == 0.0 {
        return 0.0;
    }
    m * d.iter().map(|c| (c / m) * (c / m)).sum::<f64>().sqrt()
}
