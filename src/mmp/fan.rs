//! The closed fan of faces round a vertex: its neighbours and faces in turn, with the angles
//! at which they lie, for the directions in which a vertex sends wedges (`shadow.rs`) and the
//! sectors into which a source's directions are split (`sectors.rs`).

use crate::mesh::vector::angle;
use crate::mesh::{FaceId, TriMesh, VertexId};
use std::f64::consts::PI;

/// Corners at a vertex this close to pi (relative) make it send wedges everywhere: a corner on
/// its opposite edge sends wedges through that edge into the faces beyond.
const STRAIGHT_CORNER: f64 = 1e-6;

/// A closed fan of faces round a vertex ([`fan`]).
pub(crate) struct Fan {
    /// The neighbours in turn, each at the angle of its edge (the first at 0).
    pub(crate) neighbours: Vec<(VertexId, f64)>,
    /// The faces in turn (the `i`-th from neighbour `i` to `i + 1`), each with the angle at
    /// which it starts and its corner angle.
    pub(crate) faces: Vec<(FaceId, f64, f64)>,
}

/// The neighbours of `v` in turn round a closed fan of its faces, each at the angle of its edge
/// (the first at 0), and the faces between them (the `i`-th from neighbour `i` to `i + 1`), with
/// their starting angles and corner angles; `None` unless every edge of `v` has two faces, they
/// close round `v` once, and no corner is degenerate or straight.
pub(crate) fn fan(mesh: &TriMesh, v: VertexId) -> Option<Fan> {
    let star = mesh.vertex_faces(v);
    let others = |f: FaceId| {
        let c = mesh.face(f);
        let k = c.iter().position(|&x| x == v)?;
        Some([c[(k + 1) % 3], c[(k + 2) % 3]])
    };
    let first = *star.first()?;
    let [u0, mut u] = others(first)?;
    let p = mesh.position(v);
    // On unit vectors: positions anywhere from 1e-300 to 1e300.
    let corner = |a: VertexId, b: VertexId| angle(mesh.position(a) - p, mesh.position(b) - p);
    let mut neighbours = vec![(u0, 0.0)];
    let mut faces = Vec::with_capacity(star.len());
    let mut at = 0.0;
    let (mut f, mut from) = (first, u0);
    for _ in 0..star.len() {
        let c = corner(from, u);
        if !(c > 0.0 && c < PI * (1.0 - STRAIGHT_CORNER)) {
            return None;
        }
        faces.push((f, at, c));
        at += c;
        let e = mesh.edge_between(v, u)?;
        if mesh.side_count(e) != 2 {
            return None;
        }
        let next = mesh.edge_faces(e).find(|&g| g != f)?;
        if next == first {
            return (u == u0 && faces.len() == star.len()).then_some(Fan { neighbours, faces });
        }
        neighbours.push((u, at));
        let [a, b] = others(next)?;
        from = u;
        u = if a == u {
            b
        } else if b == u {
            a
        } else {
            return None;
        };
        f = next;
    }
    None
}
