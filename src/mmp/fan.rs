//! The fan of faces round a vertex, closed or (on the boundary) open: its neighbours and faces
//! in turn, with the angles at which they lie, for the directions in which a vertex sends
//! wedges (`shadow.rs`, closed fans) and the sectors into which a source's directions are split
//! (`sectors.rs`).

use crate::mesh::vector::angle;
use crate::mesh::{EdgeId, FaceId, TriMesh, VertexId};
use std::f64::consts::PI;

/// Corners at a vertex this close to pi (relative) make it send wedges everywhere: a corner on
/// its opposite edge sends wedges through that edge into the faces beyond.
const STRAIGHT_CORNER: f64 = 1e-6;

/// A fan of faces round a vertex, closed ([`fan`]) or open ([`open_fan`]).
pub(crate) struct Fan {
    /// The neighbours in turn, each at the angle of its edge (the first at 0); an open fan has
    /// one more than it has faces, the last at its angle sum.
    pub(crate) neighbours: Vec<(VertexId, f64)>,
    /// The faces in turn (the `i`-th from neighbour `i` to `i + 1`), each with the angle at
    /// which it starts and its corner angle.
    pub(crate) faces: Vec<(FaceId, f64, f64)>,
}

impl Fan {
    /// Whether the fan closes round its vertex (an open one has a neighbour more than faces).
    pub(crate) fn is_closed(&self) -> bool {
        self.neighbours.len() == self.faces.len()
    }
}

/// The neighbours of `v` in turn round a closed fan of its faces, each at the angle of its edge
/// (the first at 0), and the faces between them (the `i`-th from neighbour `i` to `i + 1`), with
/// their starting angles and corner angles; `None` unless every edge of `v` has two faces, they
/// close round `v` once, and no corner is degenerate or straight.
pub(crate) fn fan(mesh: &TriMesh, v: VertexId) -> Option<Fan> {
    let star = mesh.vertex_faces(v);
    let first = *star.first()?;
    let [u0, mut u] = others(mesh, v, first)?;
    let mut neighbours = vec![(u0, 0.0)];
    let mut faces = Vec::with_capacity(star.len());
    let mut at = 0.0;
    let (mut f, mut from) = (first, u0);
    for _ in 0..star.len() {
        let c = corner(mesh, v, from, u)?;
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
        (from, u) = (u, after(mesh, v, next, u)?);
        f = next;
    }
    None
}

/// The open fan of faces round a boundary vertex `v`, as [`fan`]'s closed one: from the face
/// of one of its two boundary edges round to the other, with the neighbour at the end of each;
/// `None` unless `v` has two boundary edges, its other edges two faces each, and its faces
/// form that one chain, with no corner degenerate or straight.
pub(crate) fn open_fan(mesh: &TriMesh, v: VertexId) -> Option<Fan> {
    let star = mesh.vertex_faces(v);
    let edges = mesh.vertex_edges(v);
    let face_count = |e: EdgeId| mesh.edge_faces(e).count();
    if edges.iter().any(|&e| face_count(e) > 2) {
        return None;
    }
    let mut boundary = edges.iter().filter(|&&e| face_count(e) == 1);
    let (Some(&start), Some(_), None) = (boundary.next(), boundary.next(), boundary.next()) else {
        return None;
    };
    let u0 = mesh.edge(start).other(v)?;
    let mut f = mesh.edge_faces(start).next()?;
    let mut neighbours = vec![(u0, 0.0)];
    let mut faces = Vec::with_capacity(star.len());
    let mut at = 0.0;
    let mut from = u0;
    for _ in 0..star.len() {
        let u = after(mesh, v, f, from)?;
        let c = corner(mesh, v, from, u)?;
        faces.push((f, at, c));
        at += c;
        neighbours.push((u, at));
        let e = mesh.edge_between(v, u)?;
        if face_count(e) == 1 {
            return (faces.len() == star.len()).then_some(Fan { neighbours, faces });
        }
        f = mesh.edge_faces(e).find(|&g| g != f)?;
        from = u;
    }
    None
}

/// The corners of face `f` after `v`, in the face's turn.
fn others(mesh: &TriMesh, v: VertexId, f: FaceId) -> Option<[VertexId; 2]> {
    let c = mesh.face(f);
    let k = c.iter().position(|&x| x == v)?;
    Some([c[(k + 1) % 3], c[(k + 2) % 3]])
}

/// The corner of face `f` that is neither `v` nor `u`, if `u` is one.
fn after(mesh: &TriMesh, v: VertexId, f: FaceId, u: VertexId) -> Option<VertexId> {
    match others(mesh, v, f)? {
        [a, b] if a == u => Some(b),
        [a, b] if b == u => Some(a),
        _ => None,
    }
}

/// The corner angle at `v` between its neighbours `a` and `b`, if neither degenerate nor
/// straight. On unit vectors: positions anywhere from 1e-300 to 1e300.
fn corner(mesh: &TriMesh, v: VertexId, a: VertexId, b: VertexId) -> Option<f64> {
    let p = mesh.position(v);
    let c = angle(mesh.position(a) - p, mesh.position(b) - p);
    (c > 0.0 && c < PI * (1.0 - STRAIGHT_CORNER)).then_some(c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;
    use std::f64::consts::FRAC_PI_2;

    /// Round the boundary vertices of a flat grid, open fans turn by the boundary's angle,
    /// from one boundary neighbour to the other; interior vertices have closed fans only, and
    /// a vertex where two fans meet has neither.
    #[test]
    fn open_fans_run_from_boundary_to_boundary() {
        let grid = shapes::grid(4, 3, 4.0, 3.0);
        let id = |i: u32, j: u32| VertexId(j * 5 + i);
        for (v, sum, faces) in [(id(0, 0), FRAC_PI_2, 2), (id(4, 0), FRAC_PI_2, 1)] {
            let fan = open_fan(&grid, v).expect("a corner");
            assert_eq!((fan.faces.len(), fan.neighbours.len()), (faces, faces + 1));
            assert!(!fan.is_closed());
            let last = fan.neighbours.last().expect("a neighbour").1;
            assert!((last - sum).abs() < 1e-12, "{v:?}: {last}");
            for end in [fan.neighbours[0].0, fan.neighbours[faces].0] {
                let e = grid.edge_between(v, end).expect("an edge");
                assert_eq!(grid.edge_faces(e).count(), 1, "{v:?}: {end:?}");
            }
        }
        let side = open_fan(&grid, id(2, 0)).expect("a side vertex");
        let last = side.neighbours.last().expect("a neighbour").1;
        assert!((last - 2.0 * FRAC_PI_2).abs() < 1e-12, "{last}");
        assert!(open_fan(&grid, id(2, 1)).is_none());
        assert!(fan(&grid, id(2, 1)).is_some_and(|f| f.is_closed()));
        let bowtie = shapes::bowtie();
        assert!(open_fan(&bowtie, VertexId(0)).is_none() && fan(&bowtie, VertexId(0)).is_none());
    }
}
