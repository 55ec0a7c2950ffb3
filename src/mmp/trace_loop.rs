//! Loops of the back-trace [LZT §2]: a shortest path passes each point of the surface once, so
//! a walk that comes round to a vertex it passed has taken, at some vertex of the loop, an
//! arrival that a tie decided at the backend's resolution (two vertices an ulp apart, each on
//! the other's rounded way to the sources). That arrival is refused and the walk taken up
//! again from its vertex.

use super::field::GeodesicField;
use super::source::SurfacePoint;
use super::wedge::Wedge;
use crate::mesh::VertexId;
use crate::scalar::Scalar;
use std::cmp::Ordering;

/// The vertex a walk last left, kept to come back to if the walk runs round to a vertex the
/// trail passed.
pub(super) struct Departure<'a, S> {
    /// The vertex left.
    pub(super) vertex: VertexId,
    /// The trail's length before the vertex.
    pub(super) trail_len: usize,
    /// The wedge of the arrival taken from the vertex.
    pub(super) chosen: &'a Wedge<S>,
    /// The wedges of arrivals refused there.
    pub(super) refused: Vec<&'a Wedge<S>>,
}

/// Which departure of a loop, among vertices at equal distances, has its arrival refused.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum LoopTie {
    /// The latest left.
    Latest,
    /// The first left.
    First,
}

impl<S: Scalar> GeodesicField<'_, S> {
    /// Of the departures from the loop that came round to `u` (from `u`'s own, or the first,
    /// on), the one from the vertex nearest the sources (of equals, as `tie` says): taken off
    /// `departures` with those after it.
    pub(super) fn loop_departure<'a>(
        &self,
        u: VertexId,
        departures: &mut Vec<Departure<'a, S>>,
        tie: LoopTie,
    ) -> Option<Departure<'a, S>> {
        let twins = self.twins(u);
        let first = departures
            .iter()
            .position(|d| twins.iter().any(|t| t.0 == d.vertex))
            .unwrap_or(0);
        let distance = |d: &Departure<'a, S>| {
            self.vertices[d.vertex.index()]
                .as_ref()
                .map(|x| x.distance.clone())
        };
        let mut nearest = departures.len().checked_sub(1)?;
        for k in (first..departures.len()).rev() {
            let nearer = match (distance(&departures[k]), distance(&departures[nearest])) {
                (Some(a), Some(b)) => match a.compare_distance(&b) {
                    Ordering::Less => true,
                    Ordering::Equal => tie == LoopTie::First,
                    Ordering::Greater => false,
                },
                _ => false,
            };
            if nearer {
                nearest = k;
            }
        }
        departures.truncate(nearest + 1);
        departures.pop()
    }

    /// Whether the trail's `points` already passed the vertex or one at its place.
    pub(super) fn was_passed(&self, v: VertexId, points: &[SurfacePoint]) -> bool {
        self.twins(v)
            .iter()
            .any(|&(u, _)| points.contains(&SurfacePoint::Vertex(u)))
    }
}
