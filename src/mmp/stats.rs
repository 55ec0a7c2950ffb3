//! What happened during a propagation: counters that make every run explainable.

use super::wedge::PseudoSource;
use crate::scalar::{DecisionCounts, Eq2Case};
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
#[non_exhaustive]
pub struct Stats {
    /// Wedges created (emitted, propagated or split off), including those later trimmed away.
    pub wedges_created: u64,
    /// Wedges propagated across a face.
    pub wedges_propagated: u64,
    /// New wedges discarded because a vertex already reached their whole range more cheaply
    /// [SSK+05 §4.2].
    pub wedges_filtered: u64,
    /// Times a vertex's distance was lowered by the path through the end of a wedge's range,
    /// the vertex lying in a gap that rounding left beside the range (`mmp/rounded_gap.rs`;
    /// number types that keep values leave none). A later wedge may still lower it further.
    pub rounded_gap_offers: u64,
    /// Stretches of wedges propagated although the edge's wedge there kept them, the two
    /// distances being equal to within the backend's rounding ([`Scalar::near_tie`]; number
    /// types that construct exactly have none).
    ///
    /// [`Scalar::near_tie`]: crate::scalar::Scalar::near_tie
    pub tied_wedges_propagated: u64,
    /// Wedges joined to the wedge before them on their edge, which they continue: the same
    /// image of the same pseudo-source, with ranges that meet (in an exactly flat region, on
    /// the shadow line of a vertex).
    pub wedges_joined: u64,
    /// Wedges dropped because their edge was offered the same wedge before, through a strip of
    /// the same shape from the same pseudo-source (exact backend, see `mmp/strips.rs`).
    pub wedges_offered_again: u64,
    /// Times a vertex emitted wedges as a pseudo-source.
    pub pseudo_source_emissions: u64,
    /// Wedges and pseudo-sources given up because the other sector's engine had found a
    /// shorter path throughout, where two engines propagate a source's directions at once
    /// ([`PropagateOptions::threads`](super::PropagateOptions::threads)).
    pub pruned_by_other_sector: u64,
    /// Engines that propagated at once: 2 where a source vertex's directions were split into
    /// sectors ([`PropagateOptions::threads`](super::PropagateOptions::threads)), else 1.
    pub sectors: u32,
    /// Cases of eq. (2) met in wedge intersections.
    pub eq2: Eq2Counts,
    /// Largest number of events waiting in the priority queue.
    pub peak_queue: usize,
    /// Largest number of bytes held by wedge storage (wedges and per-edge lists).
    pub peak_wedge_bytes: usize,
    /// Whether the run stopped early because every stop point was final
    /// ([`PropagateOptions::stop_points`](super::PropagateOptions::stop_points)).
    pub stopped_at_stop_points: bool,
    /// Wall-clock seconds spent propagating.
    pub propagation_seconds: f64,
    /// How the backend settled its decisions (empty for `f64`, which does not certify).
    pub backend: DecisionCounts,
    /// Every meeting of two wedges on an edge, when [`PropagateOptions::record_decisions`]
    /// asks for it.
    ///
    /// [`PropagateOptions::record_decisions`]: super::PropagateOptions::record_decisions
    pub decisions: Vec<Eq2Decision>,
}

impl Stats {
    /// Adds the counts of a run that went on beside this one (the other sector's, see
    /// [`PropagateOptions::threads`](super::PropagateOptions::threads)); the larger peaks add
    /// up, both having been held at once.
    pub(crate) fn absorb(&mut self, other: Stats) {
        self.wedges_created += other.wedges_created;
        self.wedges_propagated += other.wedges_propagated;
        self.wedges_filtered += other.wedges_filtered;
        self.rounded_gap_offers += other.rounded_gap_offers;
        self.tied_wedges_propagated += other.tied_wedges_propagated;
        self.wedges_joined += other.wedges_joined;
        self.wedges_offered_again += other.wedges_offered_again;
        self.pseudo_source_emissions += other.pseudo_source_emissions;
        self.pruned_by_other_sector += other.pruned_by_other_sector;
        self.sectors += other.sectors;
        self.eq2.none += other.eq2.none;
        self.eq2.one += other.eq2.one;
        self.eq2.two += other.eq2.two;
        self.eq2.infinite += other.eq2.infinite;
        self.peak_queue += other.peak_queue;
        self.peak_wedge_bytes += other.peak_wedge_bytes;
        self.backend.absorb(other.backend);
        self.decisions.extend(other.decisions);
    }
}

/// One meeting of two wedges on a shared range of an edge [LZT §4], as the backend decided it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Eq2Decision {
    /// The edge (index).
    pub edge: u32,
    /// The pseudo-source of the wedge already on the edge.
    pub existing: PseudoSource,
    /// The pseudo-source of the arriving wedge.
    pub arriving: PseudoSource,
    /// The shared range, as `f64`.
    pub range: [f64; 2],
    /// The case the backend decided (`none` also when convexity bounds settled it).
    pub case: Eq2Case,
    /// Whether eq. (2) was solved (`false`: one wedge was better throughout by the bounds).
    pub solved: bool,
    /// `A`, `B`, `C` of eq. (2) with positions from the range's start, as the backend's values
    /// seen in `f64`.
    pub coefficients: [f64; 3],
}
