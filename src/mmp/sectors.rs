//! A source vertex's directions split into two sectors, each propagated by its own engine on
//! its own thread. Every geodesic leaves the source in one of them, so the shorter of the two
//! distances at a vertex is its distance; the engines share their vertices' distances
//! (`bounds.rs`) to give up the wedges that the other sector's paths beat, so that each
//! covers about its own part of the surface.

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

/// Parts of a face narrower than this fraction of its opposite edge go to the other sector:
/// a wedge of its own there would be a sliver.
const SMALLEST_PART: f64 = 0.05;

/// Two sectors of the closed fan of faces round `v` that together cover it, chosen so that
/// about as many vertices lie beyond each (by their shortest paths along the edges), the side
/// between them crossing a face where that balances them; `None` for a vertex without a
/// closed fan ([`fan`]).
pub(crate) fn split(mesh: &TriMesh, v: VertexId) -> Option<[Sector; 2]> {
    let fan = fan(mesh, v)?;
    let neighbours: Vec<VertexId> = fan.neighbours.iter().map(|n| n.0).collect();
    let n = neighbours.len();
    if n < 3 {
        return None;
    }
    let beyond = vertices_beyond(mesh, v, &neighbours);
    // Face `i` lies between neighbours `i` and `i + 1` and takes half of each one's vertices.
    let weight = |i: usize| (beyond[i] + beyond[(i + 1) % n]) as f64 / 2.0;
    let half = (0..n).map(weight).sum::<f64>() / 2.0;
    // Going round from neighbour 0, where half the weight is reached: face `j`, fraction `t`.
    let mut before = 0.0;
    let mut j = 0;
    while j + 1 < n && before + weight(j) < half {
        before += weight(j);
        j += 1;
    }
    let t = if weight(j) > 0.0 {
        (half - before) / weight(j)
    } else {
        0.5
    };
    let side = match t {
        t if t < SMALLEST_PART => j as f64,
        t if t > 1.0 - SMALLEST_PART => (j + 1) as f64,
        t => j as f64 + t,
    };
    // Each sector keeps at least a face and its margins.
    let n_f = n as f64;
    let side = side.clamp(1.0, n_f - 1.0);
    // Directions as positions round the fan: face `i` spans `[i, i + 1]`, from neighbour `i`.
    let sector = |own: [f64; 2], margins: [[f64; 2]; 2]| {
        let spans = std::iter::once((own, Share::Own))
            .chain(margins.into_iter().map(|m| (m, Share::Margin)));
        let spans: Vec<_> = spans.collect();
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
    let m = MARGIN_FACES;
    Some([
        sector([0.0, side], [[side, side + m], [n_f - m, n_f]]),
        sector([side, n_f], [[side - m, side], [0.0, m]]),
    ])
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
