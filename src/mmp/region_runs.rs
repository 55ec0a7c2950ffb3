//! A strip's runs through flat regions: one description however the region's faces are crossed.
//!
//! Inside a flat region unfolding is the identity (see `flat_region.rs`), so where a strip's
//! image stands against an edge of the region is fixed by where it stood against three points
//! of the region that the strip met first, its run's *anchor*, and by the distances from those
//! points to the edge's ends: exact squared distances between vertices of one plane (three
//! points not on one line fix a fourth by its distances to them). The faces crossed in between
//! do not matter. A strip that passes a vertex of the region on one side and a strip that
//! passes it on the other, or that cross the region's faces in another order, are then
//! described alike, as [`OfferedWedges`](super::strips::OfferedWedges) needs on meshes whose
//! flat faces were cut into many triangles (a subdivided polyhedron), where the straight lines
//! along a mirror plane meet the vertices on it.
//!
//! A run starts where the strip enters the region: the anchor is the edge it came in by and
//! the far corner of the first face, or the pseudo-source itself where the strip starts in the
//! region. Two regions meet along one line, the planes' intersection; a strip that crosses from
//! one region into the next across any edge on that line starts its next run from the line's
//! two end vertices and a corner beyond the first of them, described from the run it leaves:
//! strips that cross one crease at different edges are then described alike too.

use super::flat_region::FlatRegions;
use crate::mesh::{EdgeId, FaceId, TriMesh, VertexId};
use crate::scalar::exact::{squared_distance, Rational};
use crate::scalar::Scalar;
use std::collections::HashMap;

/// A strip's run through one flat region.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Run {
    /// The region.
    pub(crate) region: u32,
    /// The anchor in each reading of the strip: two corners `p`, `q` named as the reading
    /// names the edge the run came in by (or a crease's ends), and a corner `c` off their
    /// line; or the pseudo-source three times.
    pub(crate) anchor: [[VertexId; 3]; 2],
    /// The strip's description up to the anchor, in each reading.
    pub(crate) prefix: [u32; 2],
}

/// The description of an edge `(x, y)` against a run's anchor `[p, q, c]`: the classes of the
/// squared distances `pc, qc, px, qx, cx, py, qy, cy, xy`.
pub(crate) type RunKey = [u32; 9];

/// A line along which two regions meet: its vertices in order, and for each end of it, the far
/// corner of the face of the region entered on the line's edge at that end.
struct CreaseLine {
    vertices: Vec<VertexId>,
    corners: [VertexId; 2],
}

/// How a face continues a strip's run.
pub(crate) enum Entry {
    /// A face of the run's region.
    Continues(Run),
    /// A face of the region (the second) beyond a crease line: the new run's anchor (in each
    /// reading the line's end on the side of the edge's first corner, the other end, and the
    /// corner beyond the first), to be described from the run left (the first).
    Crease(Run, u32, [[VertexId; 3]; 2]),
    /// A face of a region entered otherwise: a run anchored on the edge entered by.
    Fresh(u32),
}

/// The flat regions of a mesh as strips' runs see them, and the classes of squared distances
/// between their vertices.
pub(crate) struct RegionRuns {
    face_region: Vec<Option<u32>>,
    /// The crease lines by the region left and the region entered.
    lines: HashMap<(u32, u32), CreaseLine>,
    /// The class of each pair of vertices met (the lesser first).
    pairs: HashMap<(VertexId, VertexId), u32>,
    /// The class of each exact squared distance met.
    squares: HashMap<Rational, u32>,
}

impl RegionRuns {
    /// The regions of `mesh`, and the lines between them that one unfolding crosses (those
    /// [`FlatRegions`] unfolds by one map) where they form one path of edges.
    pub(crate) fn new<S: Scalar>(mesh: &TriMesh, regions: &FlatRegions<S>) -> Self {
        let face_region: Vec<Option<u32>> = (0..mesh.face_count())
            .map(|f| regions.region(FaceId(f as u32)))
            .collect();
        let mut edges: HashMap<(u32, u32), Vec<EdgeId>> = HashMap::new();
        for e in 0..mesh.edge_count() {
            let e = EdgeId(e as u32);
            let faces: Vec<FaceId> = mesh.edge_faces(e).collect();
            let &[f, g] = faces.as_slice() else { continue };
            let (Some(rf), Some(rg)) = (face_region[f.index()], face_region[g.index()]) else {
                continue;
            };
            for (left, entered) in [(rf, rg), (rg, rf)] {
                if left != entered && regions.unfolds_along_crease_line(e, left) {
                    edges.entry((left, entered)).or_default().push(e);
                }
            }
        }
        let lines = edges
            .into_iter()
            .filter_map(|(pair, edges)| {
                Some((pair, crease_line(mesh, &face_region, pair.1, &edges)?))
            })
            .collect();
        RegionRuns {
            face_region,
            lines,
            pairs: HashMap::new(),
            squares: HashMap::new(),
        }
    }

    /// The region of a face, if it lies in one.
    pub(crate) fn region(&self, f: FaceId) -> Option<u32> {
        self.face_region[f.index()]
    }

    /// How face `f` continues a strip in `run` (if any) whose edge has corners `names` in each
    /// reading; `None` where `f` lies in no region.
    pub(crate) fn entry(
        &self,
        run: Option<&Run>,
        f: FaceId,
        names: [[VertexId; 2]; 2],
    ) -> Option<Entry> {
        let region = self.region(f)?;
        let Some(run) = run else {
            return Some(Entry::Fresh(region));
        };
        if run.region == region {
            return Some(Entry::Continues(*run));
        }
        let Some(line) = self.lines.get(&(run.region, region)) else {
            return Some(Entry::Fresh(region));
        };
        let at = |v: VertexId| line.vertices.iter().position(|&u| u == v);
        let anchor = names.map(|[a, b]| {
            let (i, j) = (at(a)?, at(b)?);
            (i.abs_diff(j) == 1).then(|| {
                let last = line.vertices.len() - 1;
                // The end on the side of `a`, the other, the corner beyond the first.
                let (first, other) = if i < j { (0, 1) } else { (1, 0) };
                let end = |k: usize| line.vertices[k * last];
                [end(first), end(other), line.corners[first]]
            })
        });
        match anchor {
            [Some(a0), Some(a1)] => Some(Entry::Crease(*run, region, [a0, a1])),
            _ => Some(Entry::Fresh(region)),
        }
    }

    /// The description of edge `(x, y)` against `anchor` ([`RunKey`]).
    pub(crate) fn key(
        &mut self,
        mesh: &TriMesh,
        [p, q, c]: [VertexId; 3],
        [x, y]: [VertexId; 2],
    ) -> Option<RunKey> {
        let pairs = [
            (p, c),
            (q, c),
            (p, x),
            (q, x),
            (c, x),
            (p, y),
            (q, y),
            (c, y),
            (x, y),
        ];
        let mut key = [0; 9];
        for (k, (u, v)) in key.iter_mut().zip(pairs) {
            *k = self.class(mesh, u, v)?;
        }
        Some(key)
    }

    /// The class of the exact squared distance between two vertices.
    fn class(&mut self, mesh: &TriMesh, u: VertexId, v: VertexId) -> Option<u32> {
        let pair = (u.min(v), u.max(v));
        if let Some(&class) = self.pairs.get(&pair) {
            return Some(class);
        }
        let [a, b] = [u, v].map(|w| mesh.position(w).to_array());
        let next = self.squares.len() as u32;
        let class = *self.squares.entry(squared_distance(a, b)?).or_insert(next);
        self.pairs.insert(pair, class);
        Some(class)
    }
}

/// The line of `edges` (between two regions, the second `entered`) in order, with the far
/// corners of the entered region's faces at its ends; `None` unless the edges form one path.
fn crease_line(
    mesh: &TriMesh,
    face_region: &[Option<u32>],
    entered: u32,
    edges: &[EdgeId],
) -> Option<CreaseLine> {
    let mut next: HashMap<VertexId, Vec<VertexId>> = HashMap::new();
    for &e in edges {
        let [a, b] = mesh.edge(e).vertices;
        next.entry(a).or_default().push(b);
        next.entry(b).or_default().push(a);
    }
    let mut ends = next.iter().filter(|(_, n)| n.len() == 1).map(|(&v, _)| v);
    let (Some(start), Some(_), None) = (ends.next(), ends.next(), ends.next()) else {
        return None;
    };
    if next.values().any(|n| n.len() > 2) {
        return None;
    }
    let mut vertices = vec![start];
    while let Some(&v) = next[vertices.last()?]
        .iter()
        .find(|&&v| vertices.len() < 2 || v != vertices[vertices.len() - 2])
    {
        if vertices.len() > edges.len() {
            return None;
        }
        vertices.push(v);
    }
    if vertices.len() != edges.len() + 1 {
        return None;
    }
    let corner = |a: VertexId, b: VertexId| -> Option<VertexId> {
        let e = mesh.edge_between(a, b)?;
        let f = mesh
            .edge_faces(e)
            .find(|f| face_region[f.index()] == Some(entered))?;
        mesh.face(f).into_iter().find(|&v| v != a && v != b)
    };
    let n = vertices.len();
    let corners = [
        corner(vertices[0], vertices[1])?,
        corner(vertices[n - 1], vertices[n - 2])?,
    ];
    Some(CreaseLine { vertices, corners })
}
