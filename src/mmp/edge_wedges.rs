//! The final wedges of a propagation, grouped by edge: each edge's wedges in a boxed slice of
//! their own, exactly sized (a pointer and a length per edge).

use super::wedge::Wedge;
use crate::mesh::EdgeId;

/// The final wedges of every edge, in edge order and sorted along each edge.
#[derive(Clone, Debug)]
pub(crate) struct EdgeWedges<S> {
    lists: Vec<Box<[Wedge<S>]>>,
}

impl<S> EdgeWedges<S> {
    /// The wedges of each edge, `lists[e]` sorted along edge `e`.
    pub(crate) fn new(lists: Vec<Vec<Wedge<S>>>) -> Self {
        EdgeWedges {
            lists: lists.into_iter().map(Vec::into_boxed_slice).collect(),
        }
    }

    /// The wedges of edge `e`, sorted along it.
    #[inline]
    pub(crate) fn on(&self, e: EdgeId) -> &[Wedge<S>] {
        &self.lists[e.index()]
    }

    /// The wedges of every edge, in edge order.
    pub(crate) fn per_edge(&self) -> impl Iterator<Item = &[Wedge<S>]> {
        self.lists.iter().map(|l| &**l)
    }
}
