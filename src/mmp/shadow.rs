//! The shadow of a pseudo-source vertex [MMP87, SSK+05 §3]: a geodesic bends at a saddle
//! vertex only by leaving it at an angle of at least pi from the way it came, on both sides.
//! Around an interior vertex of angle sum `Theta`, the directions that a shortest path through
//! it can take on are those at least pi from its arrival either way round, a sector of
//! `Theta - 2 pi`; a point in any other direction has a shorter way that passes the vertex on
//! the side of the smaller angle, which the wedges passing the vertex carry. So the vertex
//! sends wedges only into the faces and along the edges that meet that sector. The arrival is
//! one of the shortest ways to the vertex (with several, the sector of any one will do: a way
//! bending by less than pi at the vertex is shortened, so a point outside the sector of one
//! is nearer by another way than through the vertex).
//!
//! The sector is measured in `f64` with a margin ([`MARGIN`]) far above the rounding of the
//! angles, so leaving a face out is never a decision on a rounded value: a face within the
//! margin of the sector gets its wedge. Vertices without a closed fan of faces around them
//! (boundary, bowtie, edges of more than two faces, twins), corners of degenerate faces and
//! ends of edges far shorter than their faces (whose angles mean little in `f64`: beside a
//! vertex 1.3e-13 from another, a sliver corpus mesh came out 7 % long), and vertices whose
//! arrival is not a straight way from a wedge, send wedges everywhere, as before.

use super::fan::{fan, Fan};
use super::unfold::Unfolding;
use super::wedge::Wedge;
use crate::mesh::vector::angle;
use crate::mesh::{EdgeId, FaceId, Side, TriMesh, VertexId};
use crate::scalar::Scalar;
use glam::DVec3;
use std::f64::consts::PI;

/// Radians added to the sector on both sides: far above the rounding of corner angles summed
/// around a vertex (about 1e-15 each) and of an arrival's direction from unfolded positions.
const MARGIN: f64 = 1e-6;

/// The straight way by which a wedge reached a vertex: the wedge's edge, side and pseudo-source
/// image in the edge's frame, in `f64` (directions only).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Arrival {
    edge: EdgeId,
    tau: Side,
    x: f64,
    y: f64,
}

impl Arrival {
    /// The way from `w`'s pseudo-source image straight to a vertex of its edge, or to the apex
    /// of a face beyond it.
    pub(crate) fn of<S: Scalar>(w: &Wedge<S>) -> Self {
        Arrival {
            edge: w.edge,
            tau: w.tau,
            x: w.source_x.to_f64(),
            y: w.source_y.to_f64(),
        }
    }
}

/// The sector of directions around a vertex into which it sends wedges.
pub(crate) struct Shadow {
    fan: Fan,
    /// The angle sum.
    total: f64,
    /// Where the sector starts, in `[0, total)`, and its width.
    start: f64,
    width: f64,
}

impl Shadow {
    /// The shadow of `v` reached by `arrival`, if `v` has a closed fan of faces around it.
    pub(crate) fn new<S: Scalar>(
        mesh: &TriMesh,
        unfolding: &Unfolding<S>,
        v: VertexId,
        arrival: &Arrival,
    ) -> Option<Self> {
        if mesh.is_boundary_vertex(v) || mesh.is_on_degenerate_face(v) || unfolding.has_twin(v) {
            return None;
        }
        let fan = fan(mesh, v)?;
        let (neighbours, faces) = (&fan.neighbours, &fan.faces);
        let (u, f, angle) = arrival_direction(mesh, unfolding, v, arrival)?;
        let i = neighbours.iter().position(|n| n.0 == u)?;
        let before = (i + faces.len() - 1) % faces.len();
        let (incoming, corner) = if faces[i].0 == f {
            (neighbours[i].1 + angle, faces[i].2)
        } else if faces[before].0 == f {
            (neighbours[i].1 - angle, faces[before].2)
        } else {
            return None;
        };
        // The way crossed `f` to the vertex, so it arrives within `f`'s corner; a way along an
        // edge's line from beyond the vertex (rounding) says nothing of the side.
        if angle.is_nan() || angle > corner + MARGIN {
            return None;
        }
        Self::around(fan, incoming)
    }

    /// The shadow in a fan ([`fan`]) of a way arriving from the direction at angle
    /// `incoming` (measured as the fan's angles are).
    fn around(fan: Fan, incoming: f64) -> Option<Self> {
        let total: f64 = fan.faces.iter().map(|x| x.2).sum();
        let width = total - 2.0 * PI + 2.0 * MARGIN;
        let start = (incoming + PI - MARGIN).rem_euclid(total);
        (width.is_finite() && start.is_finite()).then_some(Shadow {
            fan,
            total,
            start,
            width,
        })
    }

    /// Where the angle `a` lies after the sector's start, in `[0, total)`.
    fn offset(&self, a: f64) -> f64 {
        (a - self.start).rem_euclid(self.total)
    }

    /// Whether face `f` of the vertex meets the sector.
    pub(crate) fn meets_face(&self, f: FaceId) -> bool {
        self.fan.faces.iter().any(|&(g, at, corner)| {
            let o = self.offset(at);
            g == f && (o <= self.width || o + corner >= self.total)
        })
    }

    /// Whether the edge to neighbour `u` lies in the sector.
    pub(crate) fn meets_edge(&self, u: VertexId) -> bool {
        self.fan
            .neighbours
            .iter()
            .any(|&(n, at)| n == u && self.offset(at) <= self.width)
    }
}

/// The arrival at `v` as a neighbour `u`, a face `f` of the edge `(v, u)` and the angle from
/// that edge into `f` at which the way arrives (from the direction back to the pseudo-source).
fn arrival_direction<S: Scalar>(
    mesh: &TriMesh,
    unfolding: &Unfolding<S>,
    v: VertexId,
    a: &Arrival,
) -> Option<(VertexId, FaceId, f64)> {
    let [e0, e1] = unfolding.ends(mesh, a.edge);
    let length = unfolding.length(a.edge).to_f64();
    // At an end of the edge, from the face the wedge came through.
    if v == e0 || v == e1 {
        let face = mesh.wing(a.edge, a.tau)?.face;
        return Some(if v == e0 {
            (e1, face, a.y.atan2(a.x))
        } else {
            (e0, face, a.y.atan2(length - a.x))
        });
    }
    // The apex of a face beyond the edge, laid below its line (the pseudo-source above it):
    // the angle at the apex from its edge to `e0`.
    let side = mesh
        .sides(a.edge)
        .find(|&s| s != a.tau && mesh.wing(a.edge, s).is_some_and(|w| w.apex == v))?;
    let face = mesh.wing(a.edge, side)?.face;
    let apex = unfolding.apex(mesh, a.edge, side)?;
    let (ax, h) = (apex.x.to_f64(), apex.h.to_f64());
    let to_e0 = DVec3::new(-ax, h, 0.0);
    let to_source = DVec3::new(a.x - ax, a.y + h, 0.0);
    Some((e0, face, angle(to_e0, to_source)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// A saddle: six neighbours round the origin, at unit distance in the plane, raised and
    /// lowered by turns (an angle sum of about 2 pi + 1.1).
    fn monkey_saddle() -> TriMesh {
        let mut points = vec![DVec3::ZERO];
        for i in 0..6 {
            let a = i as f64 * std::f64::consts::FRAC_PI_3;
            let z = if i % 2 == 0 { 0.6 } else { -0.6 };
            points.push(DVec3::new(a.cos(), a.sin(), z));
        }
        let faces: Vec<[u32; 3]> = (0..6).map(|i| [0, 1 + i, 1 + (i + 1) % 6]).collect();
        TriMesh::new(points, faces).expect("a valid mesh")
    }

    #[test]
    fn a_saddle_s_shadow_faces_away_from_the_arrival() {
        let mesh = monkey_saddle();
        let v = VertexId(0);
        let fan = fan(&mesh, v).expect("a closed fan");
        let (neighbours, faces) = (fan.neighbours.clone(), fan.faces.clone());
        assert_eq!(faces.len(), 6);
        let total: f64 = faces.iter().map(|x| x.2).sum();
        assert!(total > 2.0 * PI + 0.5, "a saddle: {total}");
        // Arriving along the edge to the first neighbour: the sector of about 1.1 radians
        // round the opposite direction, total / 2 from it either way.
        let shadow = Shadow::around(fan, 0.0).expect("shadow");
        let half = total / 2.0;
        for &(f, at, corner) in &faces {
            let (from, to) = (at, at + corner);
            // Faces wholly within pi of the arrival either way round get no wedge.
            let near = to <= PI - 1e-3 || from >= total - PI + 1e-3;
            assert_eq!(shadow.meets_face(f), !near, "face {f} over [{from}, {to}]");
        }
        for &(u, at) in &neighbours {
            let inside = at >= PI + 1e-3 && at <= total - PI - 1e-3;
            let outside = at <= PI - 1e-3 || at >= total - PI + 1e-3;
            if inside || outside {
                assert_eq!(shadow.meets_edge(u), inside, "edge to {u} at {at}");
            }
        }
        // The edge straight across from the arrival lies in the sector.
        let across = neighbours
            .iter()
            .min_by(|a, b| (a.1 - half).abs().total_cmp(&(b.1 - half).abs()))
            .expect("neighbours");
        assert!(shadow.meets_edge(across.0));
    }

    #[test]
    fn a_vertex_without_a_closed_fan_has_no_shadow() {
        let mesh = monkey_saddle();
        // A neighbour on the boundary of the fan.
        assert!(fan(&mesh, VertexId(1)).is_none());
    }
}
