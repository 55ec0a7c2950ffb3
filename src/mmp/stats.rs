//! What happened during a propagation: counters that make every run explainable.

use crate::scalar::Eq2Case;
use serde::Serialize;

/// How often each case of Property 1 [LZT §3] arose when two wedges met on an edge.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Eq2Counts {
    /// Eq. (2) had no solution in the shared range.
    pub none: u64,
    /// One solution.
    pub one: u64,
    /// Two solutions.
    pub two: u64,
    /// Infinitely many solutions (coincident distance functions).
    pub infinite: u64,
}

impl Eq2Counts {
    pub(crate) fn count(&mut self, case: Eq2Case) {
        match case {
            Eq2Case::None => self.none += 1,
            Eq2Case::One => self.one += 1,
            Eq2Case::Two => self.two += 1,
            Eq2Case::Infinite => self.infinite += 1,
        }
    }
}

/// Counters of one propagation.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Stats {
    /// Wedges created (emitted, propagated or split off), including those later trimmed away.
    pub wedges_created: u64,
    /// Wedges propagated across a face.
    pub wedges_propagated: u64,
    /// New wedges discarded because a vertex already reached their whole range more cheaply
    /// [SSK+05 §4.2].
    pub wedges_filtered: u64,
    /// Times a vertex emitted wedges as a pseudo-source.
    pub pseudo_source_emissions: u64,
    /// Cases of eq. (2) met in wedge intersections.
    pub eq2: Eq2Counts,
    /// Largest number of events waiting in the priority queue.
    pub peak_queue: usize,
    /// Largest number of bytes held by wedge storage (wedges and per-edge lists).
    pub peak_wedge_bytes: usize,
    /// Wall-clock seconds spent propagating.
    pub propagation_seconds: f64,
}
