//! Early stop at target points (`stop_points` in geometry-central and Kirsanov's MMP): the
//! propagation ends as soon as the distance of every stop point is final.
//!
//! A point's distance is at most `d(c) + |p - c|` for every corner `c` of the simplex holding it
//! whose distance is known (the straight segment from `c` to `p` stays in that simplex): that
//! is its *bound*. Continuous Dijkstra pops events in increasing distance, and nothing an event
//! makes is nearer to a source than the event itself, so once the front has passed a point's
//! bound, no later event can bring the point nearer: its distance is final.

use super::source::SurfacePoint;
use super::unfold::Unfolding;
use crate::mesh::{TriMesh, VertexId};
use crate::scalar::Scalar;
use std::cmp::Ordering;

/// A corner of a stop point's simplex and the point's distance from it.
struct Corner<S> {
    vertex: VertexId,
    offset: S,
    offset_approx: f64,
}

/// The stop points whose distances are not yet known to be final.
pub(crate) struct StopPoints<S> {
    pending: Vec<Vec<Corner<S>>>,
}

impl<S: Scalar> StopPoints<S> {
    /// The stop points (validated), in the engine's scaled units; `None` if there are none.
    pub(crate) fn new(
        mesh: &TriMesh,
        unfolding: &Unfolding<S>,
        points: &[SurfacePoint],
    ) -> Option<Self> {
        let pending: Vec<Vec<Corner<S>>> = points
            .iter()
            .map(|point| {
                let corners = match *point {
                    SurfacePoint::Vertex(v) => vec![v],
                    SurfacePoint::Edge { edge, .. } => mesh.edge(edge).vertices.to_vec(),
                    SurfacePoint::Face { face, .. } => mesh.face(face).to_vec(),
                };
                let p = unfolding.position(mesh, point);
                corners
                    .into_iter()
                    .map(|vertex| {
                        let offset = if *point == SurfacePoint::Vertex(vertex) {
                            S::zero()
                        } else {
                            let c = unfolding.position(mesh, &SurfacePoint::Vertex(vertex));
                            let squares = (0..3).fold(S::zero(), |sum, i| {
                                let d = p[i].clone() - &c[i];
                                sum + d.clone() * &d
                            });
                            squares.sqrt()
                        };
                        let offset_approx = offset.to_f64();
                        Corner {
                            vertex,
                            offset,
                            offset_approx,
                        }
                    })
                    .collect()
            })
            .collect();
        (!pending.is_empty()).then_some(StopPoints { pending })
    }

    /// Whether every stop point is final once the front has reached `key` (the smallest key
    /// left in the queue), given each vertex's known distance and its `f64` value. Points found
    /// final are dropped, so each is settled once.
    ///
    /// The `f64` values only filter: they can delay the stop, never cause it; a point is final
    /// when the backend finds one of its bounds smaller than `key`.
    pub(crate) fn all_final<'a>(
        &mut self,
        key: f64,
        known: impl Fn(VertexId) -> Option<(&'a S, f64)>,
    ) -> bool
    where
        S: 'a,
    {
        while let Some(corners) = self.pending.last() {
            let passed = |c: &&Corner<S>| {
                known(c.vertex).is_some_and(|(_, approx)| approx + c.offset_approx < key)
            };
            if !corners.iter().any(|c| passed(&c)) {
                return false;
            }
            let front = S::from_f64(key);
            let settled = corners.iter().filter(passed).any(|c| {
                let (d, _) = known(c.vertex).expect("a passed corner is reached");
                (d.clone() + &c.offset).compare_distance(&front) == Ordering::Less
            });
            if !settled {
                return false;
            }
            self.pending.pop();
        }
        true
    }
}
