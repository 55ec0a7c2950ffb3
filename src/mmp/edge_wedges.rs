//! The final wedges of a propagation, grouped by edge: each edge's wedges in a [`ThinVec`] of
//! their own, exactly sized (a pointer per edge, and the length with the wedges: when only
//! vertex distances are asked for, most edges have none left).

use super::wedge::Wedge;
use crate::mesh::EdgeId;
use thin_vec::ThinVec;

/// The final wedges of every edge, in edge order and sorted along each edge.
#[derive(Clone, Debug)]
pub(crate) struct EdgeWedges<S> {
    lists: Vec<ThinVec<Wedge<S>>>,
}

impl<S> EdgeWedges<S> {
    /// The wedges of each edge, `lists[e]` sorted along edge `e` and exactly sized.
    pub(crate) fn new(lists: Vec<ThinVec<Wedge<S>>>) -> Self {
        EdgeWedges { lists }
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
