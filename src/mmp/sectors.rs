//! A source vertex's directions split into two sectors, each propagated by its own engine on
//! its own thread. Every geodesic leaves the source in one of them, so the shorter of the two
//! distances at a vertex is its distance; the engines share their vertices' distances
//! (`bounds.rs`) to give up the wedges that the other sector's paths beat, so that each
//! covers about its own part of the surface. How evenly the work divides rests on a proxy
//! (shortest paths along the edges, [`balanced_sides`]): from four vertices of stanford_bunny
//! the busier engine propagated 55 % to 63 % as many wedges as a one-thread run, both
//! together 109 % to 120 %.

use super::fan::fan;
use crate::mesh::{FaceId, SourceId, TriMesh, VertexId};
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// Which of a sector's directions a wedge of its source carries: the sector's own, or a
/// margin it shares with the other sector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Share {
    Own,
    Margin,
}

/// The source a sector's engine names for the wedges of its margins: the same point, listed
/// a second time.
pub(crate) const MARGIN_SOURCE: SourceId = SourceId(1);

/// Margins, in faces of the fan, shared with the other sector on either side of a sector.
const MARGIN_FACES: f64 = 0.3;

/// The directions of a source vertex that one sector's engine propagates: its own and, on
/// either side, a margin that the other sector owns. The margins' wedges trim, on the edges,
/// the wedges that the sector's pseudo-sources near its sides send across them; vertices
/// reached through a margin do not act as pseudo-sources (the other sector's engine has the
/// same paths to them).
#[derive(Clone, Debug)]
pub(crate) struct Sector {
    /// Parts of faces: the face, its first neighbour in turn round the fan, the part of its
    /// opposite edge as fractions from that neighbour, and whose directions those are.
    pieces: Vec<(FaceId, VertexId, [f64; 2], Share)>,
    /// The neighbours along whose edges the sector sends wedges, and whose directions those are.
    edges: Vec<(VertexId, Share)>,
}

impl Sector {
    /// The parts of face `f`'s opposite edge that the sector's wedges cover, as fractions of the
    /// edge from its end `first`.
    pub(crate) fn pieces_of(
        &self,
        f: FaceId,
        first: VertexId,
    ) -> impl Iterator<Item = ([f64; 2], Share)> + '_ {
        self.pieces
            .iter()
            .filter(move |p| p.0 == f)
            .map(move |&(_, from, [lo, hi], share)| {
                let range = if from == first {
                    [lo, hi]
                } else {
                    [1.0 - hi, 1.0 - lo]
                };
                (range, share)
            })
    }

    /// Whether the sector sends a wedge along the edge to neighbour `u`, and whose.
    pub(crate) fn edge_to(&self, u: VertexId) -> Option<Share> {
        self.edges.iter().find(|e| e.0 == u).map(|e| e.1)
    }
}

/// Two sectors of the closed fan of faces round `v` that together cover it, with about as
/// many vertices beyond each ([`balanced_sides`]); `None` for a vertex without a closed fan
/// ([`fan`]).
pub(crate) fn split(mesh: &TriMesh, v: VertexId) -> Option<[Sector; 2]> {
    let fan = fan(mesh, v)?;
    let neighbours: Vec<VertexId> = fan.neighbours.iter().map(|n| n.0).collect();
    let n = neighbours.len();
    if n < 3 {
        return None;
    }
    let beyond = vertices_beyond(mesh, v, &neighbours);
    let (lo, hi) = balanced_sides(&beyond)?;
    let m = MARGIN_FACES;
    let (n_f, fan) = (n as f64, &fan);
    // Directions as positions round the fan: face `i` spans `[i, i + 1]` from neighbour `i`; an
    // arc is taken round the fan's circle, in spans within `[0, n]`.
    let arc = |from: f64, to: f64| {
        let from = from.rem_euclid(n_f);
        let to = from + (to - from).rem_euclid(n_f);
        if to <= n_f {
            vec![[from, to]]
        } else {
            vec![[from, n_f], [0.0, to - n_f]]
        }
    };
    let sector = |own: [f64; 2], margins: [[f64; 2]; 2]| {
        let spans: Vec<([f64; 2], Share)> = arc(own[0], own[1])
            .into_iter()
            .map(|a| (a, Share::Own))
            .chain(
                margins
                    .iter()
                    .flat_map(|m| arc(m[0], m[1]))
                    .map(|a| (a, Share::Margin)),
            )
            .collect();
        let mut pieces = Vec::new();
        for (i, face) in fan.faces.iter().enumerate() {
            for &([a, b], share) in &spans {
                let (lo, hi) = (a.max(i as f64) - i as f64, b.min((i + 1) as f64) - i as f64);
                if hi > lo {
                    pieces.push((face.0, neighbours[i], [lo, hi], share));
                }
            }
        }
        // Neighbour 0 lies at both 0 and n; the sector's own directions come first.
        let edges = (0..n)
            .filter_map(|i| {
                let at = |x: f64| spans.iter().filter(move |([a, b], _)| *a <= x && x <= *b);
                let ends = if i == 0 {
                    vec![0.0, n_f]
                } else {
                    vec![i as f64]
                };
                let mut shares = ends.into_iter().flat_map(at).map(|s| s.1);
                let share = shares
                    .clone()
                    .find(|&s| s == Share::Own)
                    .or(shares.next())?;
                Some((neighbours[i], share))
            })
            .collect();
        Sector { pieces, edges }
    };
    Some([
        sector([lo, hi], [[hi, hi + m], [lo - m, lo]]),
        sector([hi, lo + n_f], [[hi - m, hi], [lo + n_f, lo + n_f + m]]),
    ])
}

/// Cells of the fan per face in which [`balanced_sides`] places the sectors' sides.
const CELLS_PER_FACE: usize = 16;

/// The sides of the first sector as positions round a fan (face `i` spans `[i, i + 1]`, from
/// neighbour `i`), given how many vertices lie beyond each neighbour (`beyond`), taken to leave
/// evenly in the directions within half a face of its edge. The sides halve the vertices,
/// each placed among the directions of as few vertices as can be (which side of a side such
/// a vertex's geodesic leaves on is the proxy's guess), and else nearest a face's middle.
fn balanced_sides(beyond: &[usize]) -> Option<(f64, f64)> {
    let n = beyond.len();
    let cells = n * CELLS_PER_FACE;
    let position = |c: f64| c / CELLS_PER_FACE as f64;
    // The neighbour whose directions hold position `x`, and the weight of cell `c`.
    let density = |x: f64| beyond[x.round() as usize % n] as f64;
    let weight = |c: usize| density(position((c % cells) as f64 + 0.5)) / CELLS_PER_FACE as f64;
    let half = (0..cells).map(weight).sum::<f64>() / 2.0;
    let largest = beyond.iter().copied().max().unwrap_or(0) as f64;
    let off_middle = |x: f64| (x.fract() - 0.5).abs();
    let cost = |lo: f64, hi: f64| {
        density(lo) + density(hi) + 1e-3 * largest * (off_middle(lo) + off_middle(hi))
    };
    let (mut end, mut inside) = (0, 0.0);
    let mut best: Option<(f64, f64, f64)> = None;
    for start in 0..cells {
        if end <= start {
            (end, inside) = (start, 0.0);
        }
        while end < start + cells && inside + weight(end) < half {
            inside += weight(end);
            end += 1;
        }
        let w = weight(end);
        let lo = position(start as f64);
        let hi = position(end as f64 + if w > 0.0 { (half - inside) / w } else { 0.0 });
        if hi > lo && hi < lo + n as f64 && best.is_none_or(|b| cost(lo, hi) < b.0) {
            best = Some((cost(lo, hi), lo, hi));
        }
        if end > start {
            inside -= weight(start);
        }
    }
    best.map(|(_, lo, hi)| (lo, hi))
}

/// For each neighbour of `v`, how many vertices are nearer to `v` along the edges through it
/// than through any other neighbour.
fn vertices_beyond(mesh: &TriMesh, v: VertexId, neighbours: &[VertexId]) -> Vec<usize> {
    let mut best = vec![f64::INFINITY; mesh.vertex_count()];
    let mut through = vec![usize::MAX; mesh.vertex_count()];
    let mut queue = BinaryHeap::new();
    best[v.index()] = 0.0;
    for (i, &u) in neighbours.iter().enumerate() {
        let d = mesh.position(u).distance(mesh.position(v));
        if d < best[u.index()] {
            best[u.index()] = d;
            through[u.index()] = i;
            queue.push((Reverse(d.to_bits()), u));
        }
    }
    while let Some((Reverse(bits), u)) = queue.pop() {
        let d = f64::from_bits(bits);
        if d > best[u.index()] {
            continue;
        }
        for &e in mesh.vertex_edges(u) {
            let Some(w) = mesh.edge(e).other(u) else {
                continue;
            };
            let dw = d + mesh.position(w).distance(mesh.position(u));
            if dw < best[w.index()] {
                best[w.index()] = dw;
                through[w.index()] = through[u.index()];
                queue.push((Reverse(dw.to_bits()), w));
            }
        }
    }
    let mut counts = vec![0; neighbours.len()];
    for &i in through.iter().filter(|&&i| i < neighbours.len()) {
        counts[i] += 1;
    }
    counts
}
