//! Edge-face topology: undirected edges, the faces on each side, vertex stars.
//!
//! An edge has a side per face: two on a manifold edge (the second empty on the boundary),
//! more on an edge that three or more faces share. A face that repeats the corners of an
//! earlier one is a copy of it: it shares that face's edges but is none of their faces.

use super::corners::Corners;
use super::validation::{DuplicateFace, NonManifoldEdge};
use super::vector::{length, normalizing_power, TWO_TO_64};
use super::{EdgeId, FaceId, ValidationReport, VertexId};
use glam::DVec3;
use rustc_hash::FxHashMap;
use std::collections::hash_map::Entry;

/// An undirected edge: its two end vertices (`vertices[0] < vertices[1]`) and its first two
/// faces ([`Edge::faces`]). 16 bytes: a face is kept as its index, `NO_FACE` for none (an
/// `Option<FaceId>` takes 8 bytes, and the edges are a large table of every run).
#[derive(Clone, PartialEq)]
pub struct Edge {
    /// End vertices; the edge's local x axis runs from `vertices[0]` to `vertices[1]`.
    pub vertices: [VertexId; 2],
    faces: [u32; 2],
}

/// No face on that side of an edge: never a face's index ([`TriMesh::new`](super::TriMesh::new)
/// refuses meshes of that many faces).
const NO_FACE: u32 = u32::MAX;

impl std::fmt::Debug for Edge {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Edge")
            .field("vertices", &self.vertices)
            .field("faces", &self.faces())
            .finish()
    }
}

impl Edge {
    /// The faces on sides 0 and 1; `faces()[1]` is `None` on the boundary. An edge shared by
    /// more than two faces has more sides ([`TriMesh::edge_faces`](super::TriMesh::edge_faces)).
    #[inline]
    pub fn faces(&self) -> [Option<FaceId>; 2] {
        [self.face(0), self.face(1)]
    }

    /// The face on side 0 or 1.
    #[inline]
    fn face(&self, side: usize) -> Option<FaceId> {
        let f = self.faces[side];
        (f != NO_FACE).then_some(FaceId(f))
    }

    /// The end opposite to `v`, or `None` if `v` is not an end of this edge.
    pub fn other(&self, v: VertexId) -> Option<VertexId> {
        if self.vertices[0] == v {
            Some(self.vertices[1])
        } else if self.vertices[1] == v {
            Some(self.vertices[0])
        } else {
            None
        }
    }

    /// Whether the edge has a single face.
    pub fn is_boundary(&self) -> bool {
        self.faces[1] == NO_FACE
    }
}

/// A face seen from one of its edges: the apex (the corner opposite the edge) and the two other
/// edges, `near` joining `vertices[0]` of the edge to the apex and `far` joining the apex to
/// `vertices[1]`. This is the combinatorial half of unfolding a face across an edge [SSK+05 §3].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wing {
    /// The face.
    pub face: FaceId,
    /// The corner of the face opposite the edge.
    pub apex: VertexId,
    /// The face's edge from the edge's `vertices[0]` to the apex.
    pub near: EdgeId,
    /// The face's edge from the apex to the edge's `vertices[1]`.
    pub far: EdgeId,
}

#[derive(Debug, Clone)]
pub(super) struct Topology {
    pub(super) edges: Vec<Edge>,
    pub(super) face_edges: Vec<[EdgeId; 3]>,
    /// Faces beyond the first two of each edge: `extra_start[e]..extra_start[e + 1]` indexes
    /// `extra_faces`, and side `2 + i` of edge `e` is its `i`-th extra face. Both are empty on a
    /// mesh without such edges (most of them), which then pays nothing per edge for them.
    extra_start: Vec<u32>,
    extra_faces: Vec<FaceId>,
    pub(super) edge_length: Vec<f64>,
    pub(super) angle_sum: Vec<f64>,
    pub(super) boundary_vertex: Vec<bool>,
    pub(super) on_degenerate_face: Vec<bool>,
    /// Interior vertices whose faces lie exactly in one plane, once around (see
    /// `flat_star`).
    pub(super) flat_vertex: Vec<bool>,
    pub(super) unit_scale: f64,
    vertex_face_start: Vec<u32>,
    vertex_face_list: Vec<FaceId>,
    vertex_edge_start: Vec<u32>,
    vertex_edge_list: Vec<EdgeId>,
}

/// Edges shorter than this, against a model whose largest coordinate is scaled to about 1,
/// are beyond the float backends: their squared lengths underflow (`2^-1000` is near the
/// smallest normal `f64`). `2^-500`.
const FLOAT_RESOLUTION: f64 = 3.054936363499605e-151;

/// The power of two by which coordinates are multiplied for the mesh's own f64 geometry and
/// for the engine's number types: 1 for models whose largest coordinate lies within
/// `2^-64 ..= 2^64` (every model in ordinary units, computed exactly as given), otherwise the
/// one that brings the largest coordinate near 1. Multiplying by a power of two is exact
/// (below `2^-1022` it rounds to subnormals, which only a model spanning more than 300
/// orders of magnitude reaches).
fn unit_scale(positions: &[DVec3]) -> f64 {
    const COMFORTABLE: f64 = TWO_TO_64;
    let largest = positions
        .iter()
        .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    if largest == 0.0 || (COMFORTABLE.recip()..=COMFORTABLE).contains(&largest) {
        1.0
    } else {
        normalizing_power(largest)
    }
}

/// Whether the faces of the star of vertex `v` (each face's corners, in its order, and their
/// positions by `at`) lie exactly in the plane of the first, all turn the same way in it, and
/// lie on either side of each edge of `v` that two of them share, and the three points
/// `straight`, if given, lie on one line, decided exactly on the coordinates (Shewchuk's
/// orient3d and orient2d, as `robust` evaluates them). With an angle sum below 3 pi (once
/// around) an interior vertex is then exactly flat, and so is a boundary vertex with its
/// boundary neighbours on a line through it and an angle sum below 3 pi / 2 (exactly pi): no
/// geodesic bends there. The turns alone tell a face folded over onto its neighbour only where
/// the faces are oriented alike: a face flipped against its neighbour and folded onto it turns
/// as they do (a boundary vertex with its faces folded into 240 degrees, its boundary
/// neighbours at one point, was taken for flat and sent no wedge into its faces).
fn flat_star(
    v: usize,
    faces: &[[u32; 3]],
    at: impl Fn(usize) -> DVec3,
    straight: Option<[DVec3; 3]>,
) -> bool {
    let mut star = faces.iter().map(|f| f.map(|c| at(c as usize)));
    let Some([a, b, c]) = star.next() else {
        return false;
    };
    let c3 = |p: DVec3| robust::Coord3D {
        x: p.x,
        y: p.y,
        z: p.z,
    };
    let n = (b - a).cross(c - a).abs();
    // The coordinate plane the first face's plane projects onto without folding.
    let drop = if n.x >= n.y && n.x >= n.z {
        0
    } else if n.y >= n.z {
        1
    } else {
        2
    };
    let c2 = |p: DVec3| {
        let [u, v] = match drop {
            0 => [p.y, p.z],
            1 => [p.z, p.x],
            _ => [p.x, p.y],
        };
        robust::Coord { x: u, y: v }
    };
    // A first face with one coordinate the same at its three corners (not on one line, as
    // the first turn below checks) lies in the plane where that coordinate has that value: a
    // point is in it where its coordinate has the value. Flat parts of CAD models often lie
    // so, and orient3d tells a point in the plane only in its slow exact stage.
    let axis = (0..3).find(|&i| a[i] == b[i] && b[i] == c[i]);
    // A corner of the first face is in its plane, without asking orient3d either.
    let on_plane = |q: DVec3| match axis {
        Some(i) => q[i] == a[i],
        None => q == a || q == b || q == c || robust::orient3d(c3(a), c3(b), c3(c), c3(q)) == 0.0,
    };
    let turn = |[p, q, r]: [DVec3; 3]| robust::orient2d(c2(p), c2(q), c2(r)).signum();
    let first = turn([a, b, c]);
    if robust::orient2d(c2(a), c2(b), c2(c)) == 0.0 {
        return false;
    }
    if let Some([p, q, r]) = straight {
        let in_plane = [p, q, r].into_iter().all(on_plane);
        if !in_plane || robust::orient2d(c2(p), c2(q), c2(r)) != 0.0 {
            return false;
        }
    }
    let in_plane = star.all(|f| {
        f.into_iter().all(on_plane)
            && robust::orient2d(c2(f[0]), c2(f[1]), c2(f[2])) != 0.0
            && turn(f) == first
    });
    if !in_plane {
        return false;
    }
    // Each edge (v, w) of the star with the corner opposite it in each face that has it.
    let mut wings: Vec<(u32, u32)> = faces
        .iter()
        .flat_map(|f| {
            let k = f
                .iter()
                .position(|&c| c as usize == v)
                .expect("a corner of the star");
            let (p, q) = (f[(k + 1) % 3], f[(k + 2) % 3]);
            [(p, q), (q, p)]
        })
        .collect();
    wings.sort_unstable();
    let centre = c2(at(v));
    wings.windows(2).all(|pair| {
        let [(w, x), (u, y)] = [pair[0], pair[1]];
        let side = |o: u32| robust::orient2d(centre, c2(at(w as usize)), c2(at(o as usize)));
        w != u || side(x) * side(y) < 0.0
    })
}

/// Whether three points lie on one line: collinear in space is collinear in each coordinate
/// plane, decided exactly by orient2d.
pub(super) fn collinear([p, q, r]: [DVec3; 3]) -> bool {
    let c = |a: f64, b: f64| robust::Coord { x: a, y: b };
    [(0, 1), (1, 2), (2, 0)]
        .iter()
        .all(|&(i, j)| robust::orient2d(c(p[i], p[j]), c(q[i], q[j]), c(r[i], r[j])) == 0.0)
}

/// Whether interior vertex `v` lies on a straight crease: two neighbours `p`, `q` on one line
/// through it, `v` between them, and the faces of its star on each side of that line (`faces`,
/// its star) flat with the line as their straight boundary ([`flat_star`]). Each side then
/// spans an angle of exactly pi, the star 2 pi: the surface is intrinsically flat at `v`, and no
/// geodesic bends there. Decided exactly on the input coordinates: collinear in 3D is
/// collinear in each coordinate plane.
pub(super) fn straight_crease(v: usize, faces: &[[u32; 3]], at: impl Fn(usize) -> DVec3) -> bool {
    let mut neighbours: Vec<u32> = faces
        .iter()
        .flatten()
        .copied()
        .filter(|&c| c as usize != v)
        .collect();
    neighbours.sort_unstable();
    neighbours.dedup();
    let centre = at(v);
    let between = |p: DVec3, q: DVec3| {
        (0..3).any(|i| {
            (p[i] < centre[i] && centre[i] < q[i]) || (q[i] < centre[i] && centre[i] < p[i])
        })
    };
    for (k, &p) in neighbours.iter().enumerate() {
        for &q in &neighbours[k + 1..] {
            let (pp, qq) = (at(p as usize), at(q as usize));
            if !(collinear([pp, centre, qq]) && between(pp, qq)) {
                continue;
            }
            // The two sides: faces joined across the star's edges other than (v, p), (v, q).
            let mut sides = UnionFind::new(faces.len());
            for i in 0..faces.len() {
                for j in i + 1..faces.len() {
                    let shared = faces[i]
                        .iter()
                        .filter(|&&c| c as usize != v && c != p && c != q && faces[j].contains(&c))
                        .count();
                    if shared > 0 {
                        sides.union(i as u32, j as u32);
                    }
                }
            }
            let roots: Vec<u32> = (0..faces.len() as u32).map(|i| sides.find(i)).collect();
            let mut distinct = roots.clone();
            distinct.sort_unstable();
            distinct.dedup();
            if distinct.len() != 2 {
                continue;
            }
            let straight = Some([pp, centre, qq]);
            if distinct.iter().all(|&r| {
                let side: Vec<[u32; 3]> = (0..faces.len())
                    .filter(|&i| roots[i] == r)
                    .map(|i| faces[i])
                    .collect();
                flat_star(v, &side, &at, straight)
            }) {
                return true;
            }
        }
    }
    false
}

/// Faces from which [`Topology::build`] works out the corners' geometry on a thread of its own.
/// The thread needs the corners' tables allocated before the edges' numbering; so placed in the
/// heap, they made fandisk's peak (13k faces, one engine) 0.4-0.5 MiB (5 %) higher, with or
/// without the thread (a thread alone costs no measurable memory). From this size on the
/// build saves a third of its time (stanford_bunny, 69k faces: 32 -> 21-24 ms, medians of 21)
/// for a peak unchanged on two threads and 1 MiB (3 %) higher on one.
pub(super) const CONCURRENT_FACES: usize = 50_000;

/// Compressed adjacency lists: `start[v]..start[v + 1]` indexes `list`, each list in the
/// order of `pairs`. A counting sort (linear, and stable as a sort of the pairs by `v` is).
fn csr<T: Copy>(n: usize, pairs: impl Iterator<Item = (usize, T)> + Clone) -> (Vec<u32>, Vec<T>) {
    let mut start = vec![0u32; n + 1];
    for (v, _) in pairs.clone() {
        start[v + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    // Every slot is written below; the first pair's value only fills them until then.
    let Some((_, filler)) = pairs.clone().next() else {
        return (start, Vec::new());
    };
    let mut list = vec![filler; start[n] as usize];
    let mut next = start.clone();
    for (v, t) in pairs {
        list[next[v] as usize] = t;
        next[v] += 1;
    }
    (start, list)
}

/// No side: never a side's index ([`TriMesh::new`](super::TriMesh::new) refuses meshes of a
/// third that many faces).
const NO_SIDE: u32 = u32::MAX;

/// The undirected edges of the faces, numbered in order of first appearance (side `i` of face
/// `f` joins corners `i` and `i + 1`), and each face's three edges. Linear, without hashing:
/// the sides are bucketed by their lower end (a counting sort), and within a bucket each side
/// is matched to the first one to the same upper end by marking that end.
fn number_edges(nv: usize, faces: &[[u32; 3]]) -> (Vec<Edge>, Vec<[EdgeId; 3]>) {
    let ends = |f: &[u32; 3], i: usize| {
        let (a, b) = (f[i], f[(i + 1) % 3]);
        (a.min(b), a.max(b))
    };
    // The sides by lower end, each as its upper end and its index: a counting sort, written
    // out as loops over the faces, cheaper than through `csr`'s iterator.
    let mut start = vec![0u32; nv + 1];
    for f in faces {
        for i in 0..3 {
            start[ends(f, i).0 as usize + 1] += 1;
        }
    }
    for v in 0..nv {
        start[v + 1] += start[v];
    }
    let mut by_low = vec![[0u32; 2]; 3 * faces.len()];
    let mut next = start.clone();
    for (fi, f) in faces.iter().enumerate() {
        for i in 0..3 {
            let (low, high) = ends(f, i);
            let at = &mut next[low as usize];
            by_low[*at as usize] = [high, (3 * fi + i) as u32];
            *at += 1;
        }
    }
    // The first side of each side's edge, turned below into the edge's number.
    let mut first = vec![NO_SIDE; 3 * faces.len()];
    let mut first_to = vec![NO_SIDE; nv];
    let mut count = 0;
    for v in 0..nv {
        let bucket = &by_low[start[v] as usize..start[v + 1] as usize];
        for &[high, h] in bucket {
            let mark = &mut first_to[high as usize];
            if *mark == NO_SIDE {
                *mark = h;
                count += 1;
            }
            first[h as usize] = *mark;
        }
        for &[high, _] in bucket {
            first_to[high as usize] = NO_SIDE;
        }
    }
    let mut edges = Vec::with_capacity(count);
    for h in 0..first.len() {
        let f = first[h] as usize;
        first[h] = if f == h {
            let (low, high) = ends(&faces[h / 3], h % 3);
            edges.push(Edge {
                vertices: [VertexId(low), VertexId(high)],
                faces: [NO_FACE; 2],
            });
            (edges.len() - 1) as u32
        } else {
            first[f]
        };
    }
    let face_edges = first
        .chunks_exact(3)
        .map(|e| [e[0], e[1], e[2]].map(EdgeId))
        .collect();
    (edges, face_edges)
}

/// The earlier face with the corners of face `fi` (edges `fe`), if any, given the faces already
/// on the sides of `edges`. That face has the edge opposite the largest corner of `fi`, on
/// one of its first two sides or, if both were taken when it came, in `crowded` (the faces
/// that found that edge full, by sorted corners), rather than in a hash map of every face.
fn original(
    fi: usize,
    faces: &[[u32; 3]],
    fe: &[EdgeId; 3],
    edges: &[Edge],
    crowded: &mut FxHashMap<[u32; 3], u32>,
) -> Option<u32> {
    let sorted = |mut f: [u32; 3]| {
        f.sort_unstable();
        f
    };
    let corners = sorted(faces[fi]);
    let largest = faces[fi].iter().position(|&c| c == corners[2])?;
    let sides = edges[fe[(largest + 1) % 3].index()].faces;
    for g in sides.into_iter().take_while(|&g| g != NO_FACE) {
        if sorted(faces[g as usize]) == corners {
            return Some(g);
        }
    }
    if sides[1] == NO_FACE {
        return None;
    }
    match crowded.entry(corners) {
        Entry::Occupied(first) => Some(*first.get()),
        Entry::Vacant(slot) => {
            slot.insert(fi as u32);
            None
        }
    }
}

/// The faces of edge `ei` beyond its first two, from `Topology::extra_start` and
/// `Topology::extra_faces`.
fn extra_of<'a>(start: &[u32], faces: &'a [FaceId], ei: usize) -> &'a [FaceId] {
    if start.is_empty() {
        &[]
    } else {
        &faces[start[ei] as usize..start[ei + 1] as usize]
    }
}

struct UnionFind(Vec<u32>);
impl UnionFind {
    fn new(n: usize) -> Self {
        UnionFind((0..n as u32).collect())
    }
    /// `n` singletons again, in the room of the last sets.
    fn reset(&mut self, n: usize) {
        self.0.clear();
        self.0.extend(0..n as u32);
    }
    fn find(&mut self, mut x: u32) -> u32 {
        while self.0[x as usize] != x {
            let parent = self.0[self.0[x as usize] as usize];
            self.0[x as usize] = parent;
            x = parent;
        }
        x
    }
    fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.0[ra.max(rb) as usize] = ra.min(rb);
        }
    }
}

impl Topology {
    pub(super) fn build(positions: &[DVec3], faces: &[[u32; 3]]) -> (Topology, ValidationReport) {
        if faces.len() >= CONCURRENT_FACES {
            std::thread::scope(|scope| Self::build_in(Some(scope), positions, faces))
        } else {
            Self::build_in(None, positions, faces)
        }
    }

    /// [`Topology::build`], with the corners' geometry ([`Corners`]) worked out on a thread of
    /// `scope`, if given, beside the edges' numbering: mostly arc tangents.
    fn build_in<'s>(
        scope: Option<&'s std::thread::Scope<'s, '_>>,
        positions: &'s [DVec3],
        faces: &'s [[u32; 3]],
    ) -> (Topology, ValidationReport) {
        let nv = positions.len();
        // Geometry in coordinates scaled by a power of two (exact), so that squared lengths
        // neither overflow nor underflow whatever the model's units.
        let unit_scale = unit_scale(positions);
        let scaled = move |v: usize| positions[v] * unit_scale;
        let corners_of = move |mut corners: Corners, counted: &dyn Fn(usize) -> bool| {
            corners.count(faces, (scaled, unit_scale), counted);
            corners
        };
        let all_corners = scope.map(|scope| {
            // Allocated here: the tables outlive the thread.
            let corners = Corners::new(nv);
            scope.spawn(move || corners_of(corners, &|_| true))
        });
        let mut report = ValidationReport::default();
        let (mut edges, face_edges) = number_edges(nv, faces);
        let mut extra: Vec<(usize, FaceId)> = Vec::new();
        let mut crowded = FxHashMap::default();
        let mut is_copy = vec![false; faces.len()];
        let mut forward = vec![[false; 2]; edges.len()];
        for (fi, (f, fe)) in faces.iter().zip(&face_edges).enumerate() {
            if let Some(first) = original(fi, faces, fe, &edges, &mut crowded) {
                is_copy[fi] = true;
                report.duplicate_faces.push(DuplicateFace {
                    face: FaceId(fi as u32),
                    copy_of: FaceId(first),
                });
                continue;
            }
            for i in 0..3 {
                let id = fe[i].index();
                let edge = &mut edges[id];
                let slot = if edge.faces[0] == NO_FACE {
                    0
                } else if edge.faces[1] == NO_FACE {
                    1
                } else {
                    extra.push((id, FaceId(fi as u32)));
                    continue;
                };
                edge.faces[slot] = fi as u32;
                forward[id][slot] = f[i] < f[(i + 1) % 3];
            }
        }
        // Extra faces in input order on each edge (the sort is stable).
        let (extra_start, extra_faces) = match extra.is_empty() {
            true => (Vec::new(), Vec::new()),
            false => csr(edges.len(), extra.into_iter()),
        };
        let faces_of = |ei: usize| {
            let more = extra_of(&extra_start, &extra_faces, ei);
            edges[ei]
                .faces()
                .into_iter()
                .flatten()
                .chain(more.iter().copied())
        };
        for (ei, e) in edges.iter().enumerate() {
            let face_count = faces_of(ei).count();
            if face_count > 2 {
                report.non_manifold_edges.push(NonManifoldEdge {
                    edge: EdgeId(ei as u32),
                    vertices: e.vertices,
                    face_count,
                });
            }
        }

        let mut edge_length = Vec::with_capacity(edges.len());
        for (ei, e) in edges.iter().enumerate() {
            let [v0, v1] = e.vertices.map(|v| v.index());
            let scaled_length = length(scaled(v1) - scaled(v0));
            // Ends apart in the input, however short the scaled difference (it underflows to
            // zero for an edge of 1e-113 in a model of 1e211).
            if positions[v0] != positions[v1] && scaled_length < FLOAT_RESOLUTION {
                report.float_unresolved_edges.push(EdgeId(ei as u32));
            }
            edge_length.push(scaled_length / unit_scale);
        }
        let (shortest, longest) = edge_length
            .iter()
            .filter(|&&l| l > 0.0)
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), &l| {
                (lo.min(l), hi.max(l))
            });
        report.edge_length_span = if longest > 0.0 {
            longest / shortest
        } else {
            1.0
        };

        report.inconsistently_oriented_edges = edges
            .iter()
            .zip(&forward)
            .filter(|(e, f)| f[0] == f[1] && !e.is_boundary())
            .count();
        report.boundary_edges = edges.iter().filter(|e| e.is_boundary()).count();

        let (vertex_face_start, vertex_face_list) = csr(
            nv,
            faces
                .as_flattened()
                .iter()
                .enumerate()
                .filter(|&(h, _)| !is_copy[h / 3])
                .map(|(h, &v)| (v as usize, FaceId((h / 3) as u32))),
        );
        let (vertex_edge_start, vertex_edge_list) = csr(
            nv,
            (0..2 * edges.len())
                .map(|h| (edges[h / 2].vertices[h % 2].index(), EdgeId((h / 2) as u32))),
        );

        // A copy's angles are its original's: counted once. Copies are rare; the thread, if
        // any, counted every face.
        let counted = |fi: usize| !is_copy[fi];
        let Corners {
            angle_sum,
            on_degenerate_face,
            zero_area_faces,
        } = match all_corners {
            Some(all) if !is_copy.contains(&true) => all.join().expect("the corners' geometry"),
            _ => corners_of(Corners::new(nv), &counted),
        };
        report.zero_area_faces = zero_area_faces;

        // Geodesics may bend at the ends of boundary edges and of edges with more than two
        // faces (where a path may turn into any of them).
        let mut boundary_vertex = vec![false; nv];
        let non_manifold = report.non_manifold_edges.iter().map(|n| n.edge.index());
        for ei in (0..edges.len())
            .filter(|&ei| edges[ei].is_boundary())
            .chain(non_manifold)
        {
            for v in edges[ei].vertices {
                boundary_vertex[v.index()] = true;
            }
        }
        let mut fans = UnionFind::new(0);
        for v in 0..nv {
            let star =
                &vertex_face_list[vertex_face_start[v] as usize..vertex_face_start[v + 1] as usize];
            if star.is_empty() {
                report.unreferenced_vertices.push(VertexId(v as u32));
                continue;
            }
            fans.reset(star.len());
            for e in
                &vertex_edge_list[vertex_edge_start[v] as usize..vertex_edge_start[v + 1] as usize]
            {
                let mut around =
                    faces_of(e.index()).filter_map(|g| star.iter().position(|&f| f == g));
                if let Some(first) = around.next() {
                    for other in around {
                        fans.union(first as u32, other as u32);
                    }
                }
            }
            let fan_count = (0..star.len() as u32)
                .filter(|&i| fans.find(i) == i)
                .count();
            if fan_count > 1 {
                report.non_manifold_vertices.push(VertexId(v as u32));
                boundary_vertex[v] = true;
            }
        }

        // Vertices where the surface is not a manifold, whatever their stars look like.
        let mut not_manifold = vec![false; nv];
        for v in &report.non_manifold_vertices {
            not_manifold[v.index()] = true;
        }
        for n in &report.non_manifold_edges {
            for v in edges[n.edge.index()].vertices {
                not_manifold[v.index()] = true;
            }
        }
        // One buffer for the corners of every star.
        let mut corners = Vec::new();
        let flat_vertex = (0..nv)
            .map(|v| {
                if on_degenerate_face[v] || not_manifold[v] {
                    return false;
                }
                let star = &vertex_face_list
                    [vertex_face_start[v] as usize..vertex_face_start[v + 1] as usize];
                corners.clear();
                corners.extend(star.iter().map(|f| faces[f.index()]));
                if !boundary_vertex[v] {
                    return angle_sum[v] < 3.0 * std::f64::consts::PI
                        && flat_star(v, &corners, scaled, None);
                }
                // On the boundary: flat where the boundary runs straight through the vertex.
                let mut ends = vertex_edge_list
                    [vertex_edge_start[v] as usize..vertex_edge_start[v + 1] as usize]
                    .iter()
                    .map(|e| &edges[e.index()])
                    .filter(|e| e.is_boundary());
                let (Some(a), Some(b), None) = (ends.next(), ends.next(), ends.next()) else {
                    return false;
                };
                let far = |e: &Edge| {
                    let u = if e.vertices[0].index() == v {
                        e.vertices[1]
                    } else {
                        e.vertices[0]
                    };
                    scaled(u.index())
                };
                let straight = [far(a), scaled(v), far(b)];
                angle_sum[v] < 1.5 * std::f64::consts::PI
                    && flat_star(v, &corners, scaled, Some(straight))
            })
            .collect();

        let mut components = UnionFind::new(faces.len());
        for ei in 0..edges.len() {
            let mut around = faces_of(ei);
            if let Some(first) = around.next() {
                for other in around {
                    components.union(first.0, other.0);
                }
            }
        }
        report.components = (0..faces.len() as u32)
            .filter(|&f| !is_copy[f as usize] && components.find(f) == f)
            .count();

        (
            Topology {
                edges,
                face_edges,
                extra_start,
                extra_faces,
                edge_length,
                angle_sum,
                boundary_vertex,
                on_degenerate_face,
                flat_vertex,
                unit_scale,
                vertex_face_start,
                vertex_face_list,
                vertex_edge_start,
                vertex_edge_list,
            },
            report,
        )
    }

    /// The faces of edge `e` beyond its first two.
    #[inline]
    pub(super) fn extra_faces(&self, e: EdgeId) -> &[FaceId] {
        extra_of(&self.extra_start, &self.extra_faces, e.index())
    }

    /// The face on side `side` of edge `e`, if there is one.
    #[inline]
    pub(super) fn face_on(&self, e: EdgeId, side: usize) -> Option<FaceId> {
        match side {
            0 | 1 => self.edges[e.index()].face(side),
            _ => self.extra_faces(e).get(side - 2).copied(),
        }
    }

    /// The wing of side `side` of edge `e` (`faces`: the mesh's corners). Worked out on each
    /// call rather than stored: a table of them took 20 bytes per side, as much as the rest of
    /// the topology of a side, for what the face's corners and edges already say.
    pub(super) fn wing(&self, faces: &[[u32; 3]], e: EdgeId, side: usize) -> Option<Wing> {
        let face = self.face_on(e, side)?;
        let corners = faces[face.index()];
        let fe = self.face_edges[face.index()];
        let k = fe
            .iter()
            .position(|&x| x == e)
            .expect("edge belongs to face");
        let apex = VertexId(corners[(k + 2) % 3]);
        // The face's other two edges: k+1 goes from corner k+1 to the apex, k+2 from the apex to corner k.
        let (after, before) = (fe[(k + 1) % 3], fe[(k + 2) % 3]);
        let (near, far) = if VertexId(corners[k]) == self.edges[e.index()].vertices[0] {
            (before, after)
        } else {
            (after, before)
        };
        Some(Wing {
            face,
            apex,
            near,
            far,
        })
    }

    /// The number of sides of all edges: the length of per-side arrays ([`Topology::side_slot`]).
    pub(super) fn side_slot_count(&self) -> usize {
        2 * self.edges.len() + self.extra_faces.len()
    }

    /// Where the data of side `side` of edge `e` lives in per-side arrays.
    #[inline]
    pub(super) fn side_slot(&self, e: EdgeId, side: usize) -> usize {
        if side < 2 {
            2 * e.index() + side
        } else {
            2 * self.edges.len() + self.extra_start[e.index()] as usize + side - 2
        }
    }

    pub(super) fn vertex_faces(&self, v: VertexId) -> &[FaceId] {
        let i = v.index();
        &self.vertex_face_list
            [self.vertex_face_start[i] as usize..self.vertex_face_start[i + 1] as usize]
    }

    pub(super) fn vertex_edges(&self, v: VertexId) -> &[EdgeId] {
        let i = v.index();
        &self.vertex_edge_list
            [self.vertex_edge_start[i] as usize..self.vertex_edge_start[i + 1] as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_edge_takes_16_bytes_and_tells_its_faces() {
        assert_eq!(std::mem::size_of::<Edge>(), 16);
        let edge = Edge {
            vertices: [VertexId(0), VertexId(1)],
            faces: [3, NO_FACE],
        };
        assert_eq!(edge.faces(), [Some(FaceId(3)), None]);
        assert!(edge.is_boundary());
    }
}
