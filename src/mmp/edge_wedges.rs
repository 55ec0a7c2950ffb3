//! The final wedges of a propagation, grouped by edge: one array, each edge's wedges a sorted
//! run of it, so that a field holds them without a vector per edge.

use super::wedge::Wedge;
use crate::mesh::EdgeId;

/// The final wedges of every edge, in edge order and sorted along each edge.
#[derive(Clone, Debug)]
pub(crate) struct EdgeWedges<S> {
    wedges: Vec<Wedge<S>>,
    /// Edge `e`'s wedges are `wedges[start[e]..start[e + 1]]`.
    start: Vec<u32>,
}

impl<S> EdgeWedges<S> {
    /// Groups `arena` in place: `lists[e]` holds, in order, the places in `arena` of edge `e`'s
    /// wedges; places that no list holds are dropped. In place, so that the propagation's
    /// wedges are not held twice at its end (the peak memory of a run).
    pub(crate) fn group(mut arena: Vec<Wedge<S>>, lists: &[Vec<u32>]) -> Self {
        let mut start = Vec::with_capacity(lists.len() + 1);
        start.push(0u32);
        let mut place = vec![u32::MAX; arena.len()];
        let mut next = 0u32;
        for list in lists {
            for &i in list {
                place[i as usize] = next;
                next += 1;
            }
            start.push(next);
        }
        let kept = next as usize;
        for p in place.iter_mut().filter(|p| **p == u32::MAX) {
            *p = next;
            next += 1;
        }
        // Follow each cycle of the permutation, putting one wedge in its place per swap.
        for i in 0..arena.len() {
            while place[i] as usize != i {
                let j = place[i] as usize;
                arena.swap(i, j);
                place.swap(i, j);
            }
        }
        arena.truncate(kept);
        EdgeWedges {
            wedges: arena,
            start,
        }
    }

    /// The wedges of edge `e`, sorted along it.
    #[inline]
    pub(crate) fn on(&self, e: EdgeId) -> &[Wedge<S>] {
        let i = e.index();
        &self.wedges[self.start[i] as usize..self.start[i + 1] as usize]
    }

    /// The wedges of every edge, in edge order.
    pub(crate) fn per_edge(&self) -> impl Iterator<Item = &[Wedge<S>]> {
        self.start
            .windows(2)
            .map(|w| &self.wedges[w[0] as usize..w[1] as usize])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{Side, SourceId};
    use crate::mmp::PseudoSource;

    /// A wedge told apart by its `b0`.
    fn wedge(b0: f64) -> Wedge<f64> {
        Wedge {
            edge: EdgeId(0),
            b0,
            b1: b0 + 1.0,
            source_x: 0.0,
            source_y: 1.0,
            sigma: 0.0,
            tau: Side::FIRST,
            pseudo_source: PseudoSource::Source(SourceId(0)),
            source: SourceId(0),
        }
    }

    #[test]
    fn grouping_keeps_each_list_in_order_and_drops_free_places() {
        let arena: Vec<Wedge<f64>> = (0..6).map(|i| wedge(f64::from(i))).collect();
        // Places 2 and 4 are free; edge 1 has no wedge.
        let lists = vec![vec![3, 1], vec![], vec![0, 5]];
        let grouped = EdgeWedges::group(arena, &lists);
        let b0s = |e: u32| -> Vec<f64> { grouped.on(EdgeId(e)).iter().map(|w| w.b0).collect() };
        assert_eq!(b0s(0), [3.0, 1.0]);
        assert!(b0s(1).is_empty());
        assert_eq!(b0s(2), [0.0, 5.0]);
        let counts: Vec<usize> = grouped.per_edge().map(<[Wedge<f64>]>::len).collect();
        assert_eq!(counts, [2, 0, 2]);
    }
}
