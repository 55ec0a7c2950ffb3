//! The wedges of every edge while a propagation runs [SSK+05 §4.2, LZT §4]: an arena of slots
//! (each a wedge, what it keeps of its construction, and whether it waits in the queue), its
//! free list, and each edge's list of slot ids, sorted along the edge and disjoint. A wedge
//! arriving on an edge is cut into pieces with the wedges there by eq. (2)
//! ([`intersect`](super::intersect)), and the list is rebuilt from the pieces.

use super::edge_wedges::EdgeWedges;
use super::intersect::{cut_into_pieces, Owner, Piece};
use super::provenance::Provenance;
use super::stats::Stats;
use super::wedge::Wedge;
use crate::mesh::VertexId;
use crate::scalar::{Scalar, Site};
use std::cmp::Ordering;
use std::ops::Range;

/// Where a wedge of the arena is in its propagation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum SlotState {
    Queued,
    Propagated,
    Free,
}

/// A place of the arena: a wedge, or a free place waiting to be reused (a new generation each
/// time, so that an event of the queue knows whether its wedge is still there).
#[derive(Clone, Debug)]
struct Slot<S: Scalar> {
    wedge: Wedge<S>,
    kept: Provenance<S>,
    state: SlotState,
    generation: u32,
}

/// Reusable buffers of the intersection, kept across insertions to avoid allocating.
struct Scratch<S> {
    pieces: Vec<Piece<S>>,
    reused: Vec<u32>,
    ids: Vec<u32>,
}

impl<S> Default for Scratch<S> {
    fn default() -> Self {
        Scratch {
            pieces: Vec::new(),
            reused: Vec::new(),
            ids: Vec::new(),
        }
    }
}

/// What inserting a wedge tells the propagation: the wedges it queues and the vertices of the
/// edge the new wedge reaches.
pub(crate) trait Arrivals<S: Scalar> {
    /// The wedge in `slot`, of `generation`, waits to be propagated.
    fn queue(&mut self, slot: u32, generation: u32, wedge: &Wedge<S>);
    /// The wedge `w` reaches the vertex `v` of its edge at distance `d`.
    fn reach(&mut self, v: VertexId, d: S, w: &Wedge<S>);
}

/// Whether the wedge of a queue event is due ([`WedgeLists::due`]).
pub(crate) enum Due<S: Scalar> {
    /// Its slot was freed or reused, or the wedge already propagated.
    Stale,
    /// The wedge was trimmed since it was queued: its smallest distance is now this key.
    Later(f64),
    /// The wedge and what it keeps, now marked as propagated.
    Now(Wedge<S>, Provenance<S>),
}

/// The wedges of every edge of a running propagation.
pub(crate) struct WedgeLists<S: Scalar> {
    slots: Vec<Slot<S>>,
    free: Vec<u32>,
    lists: Vec<Vec<u32>>,
    list_entries: usize,
    /// Keep a log of every meeting of two wedges ([`Stats::decisions`]).
    record_decisions: bool,
    scratch: Scratch<S>,
}

impl<S: Scalar> WedgeLists<S> {
    /// No wedge yet on any of `edge_count` edges.
    pub(crate) fn new(edge_count: usize, record_decisions: bool) -> Self {
        WedgeLists {
            slots: Vec::new(),
            free: Vec::new(),
            lists: vec![Vec::new(); edge_count],
            list_entries: 0,
            record_decisions,
            scratch: Scratch::default(),
        }
    }

    /// The wedge of the queue event of `slot` and `generation` popped at `key`, if it is due.
    pub(crate) fn due(&mut self, slot: u32, generation: u32, key: f64) -> Due<S> {
        let s = &mut self.slots[slot as usize];
        if s.generation != generation || s.state != SlotState::Queued {
            return Due::Stale;
        }
        let now = s.wedge.min_distance().to_f64();
        if now > key {
            return Due::Later(now);
        }
        s.state = SlotState::Propagated;
        Due::Now(s.wedge.clone(), s.kept.clone())
    }

    /// The final wedges, out of their slots and grouped by edge in place: copies would double
    /// the peak memory.
    pub(crate) fn into_edge_wedges(self) -> EdgeWedges<S> {
        let arena = self.slots.into_iter().map(|s| s.wedge).collect();
        EdgeWedges::group(arena, &self.lists)
    }

    /// Inserts a wedge on its edge (of the given length and vertices), intersecting it with
    /// the wedges there.
    pub(crate) fn insert(
        &mut self,
        (w, kept): (Wedge<S>, Provenance<S>),
        (length, ends): (&S, [VertexId; 2]),
        stats: &mut Stats,
        arrivals: &mut impl Arrivals<S>,
    ) {
        let e = w.edge;
        S::locate(Site {
            edge: Some(e.0),
            what: "wedge intersection (eq. 2)",
        });
        if !S::has_extent(&w.b0, &w.b1, length) {
            return;
        }
        let list = &self.lists[e.index()];
        let first = list.partition_point(|&id| {
            self.slots[id as usize].wedge.b1.compare(&w.b0) != Ordering::Greater
        });
        let end = first
            + list[first..]
                .iter()
                .take_while(|&&id| {
                    self.slots[id as usize].wedge.b0.compare(&w.b1) == Ordering::Less
                })
                .count();
        let mut pieces = std::mem::take(&mut self.scratch.pieces);
        pieces.clear();
        let log = self.record_decisions.then_some(&mut stats.decisions);
        let overlapping = self.lists[e.index()][first..end].iter().map(|&id| {
            let slot = &self.slots[id as usize];
            (id, &slot.wedge, &slot.kept)
        });
        let new = (&w, &kept);
        cut_into_pieces(&mut stats.eq2, log, &mut pieces, overlapping, new, length);
        if pieces.iter().any(|p| p.owner == Owner::New) {
            let edge = (length, ends);
            self.rebuild((&w, &kept), first..end, &mut pieces, edge, stats, arrivals);
        }
        self.scratch.pieces = pieces;
    }

    /// Replaces the wedges `first..end` of the new wedge's edge list by the pieces.
    fn rebuild(
        &mut self,
        (w, kept): (&Wedge<S>, &Provenance<S>),
        Range { start: first, end }: Range<usize>,
        pieces: &mut Vec<Piece<S>>,
        (length, [v0, v1]): (&S, [VertexId; 2]),
        stats: &mut Stats,
        arrivals: &mut impl Arrivals<S>,
    ) {
        let e = w.edge;
        let mut reused = std::mem::take(&mut self.scratch.reused);
        let mut ids = std::mem::take(&mut self.scratch.ids);
        reused.clear();
        ids.clear();
        let zero = S::zero();
        let mine = w.distance_function();
        // Which range ends of a wedge a piece keeps (asked only where anchors depend on it).
        let anchored = |k: &Provenance<S>| k.anchor(0).is_some() || k.anchor(1).is_some();
        let keeps = |w: &Wedge<S>, lo: &S, hi: &S| {
            [
                w.b0.compare(lo) == Ordering::Equal,
                w.b1.compare(hi) == Ordering::Equal,
            ]
        };
        // A wedge that keeps two pieces (the new one won in its middle: three pieces at least)
        // is trimmed in place for the first: the second is cut from the wedge as it was, with
        // the anchor of its end (only anchors depend on it).
        let mut split: Vec<(u32, Wedge<S>, Provenance<S>)> = Vec::new();
        if pieces.len() >= 3 {
            for (i, p) in pieces.iter().enumerate() {
                let Owner::Old(id) = p.owner else { continue };
                let slot = &self.slots[id as usize];
                if anchored(&slot.kept) && pieces[i + 1..].iter().any(|q| q.owner == p.owner) {
                    split.push((id, slot.wedge.clone(), slot.kept.clone()));
                }
            }
        }
        for piece in pieces.drain(..) {
            if !S::has_extent(&piece.lo, &piece.hi, length) {
                continue;
            }
            match piece.owner {
                Owner::New => {
                    if S::within(&zero, &piece.lo, &piece.hi, length) {
                        let d = S::kept(&kept.at_ends[0]).unwrap_or_else(|| mine.at(&zero));
                        arrivals.reach(v0, d, w);
                    }
                    if S::within(length, &piece.lo, &piece.hi, length) {
                        let d = S::kept(&kept.at_ends[1]).unwrap_or_else(|| mine.at(length));
                        arrivals.reach(v1, d, w);
                    }
                    let piece_kept = if anchored(kept) {
                        kept.trimmed(keeps(w, &piece.lo, &piece.hi))
                    } else {
                        kept.clone()
                    };
                    let mut wedge = w.clone();
                    wedge.b0 = piece.lo;
                    wedge.b1 = piece.hi;
                    let id = self.allocate(wedge, piece_kept, SlotState::Queued, stats);
                    self.queue(id, arrivals);
                    ids.push(id);
                }
                Owner::Old(id) => {
                    let slot = &self.slots[id as usize];
                    let (original, original_kept) = split
                        .iter()
                        .find(|(i, ..)| *i == id)
                        .map_or((&slot.wedge, &slot.kept), |(_, w, k)| (w, k));
                    let kept_ends = keeps(original, &piece.lo, &piece.hi);
                    let unchanged = kept_ends == [true, true];
                    let state = slot.state;
                    let target = if reused.contains(&id) {
                        let mut wedge = original.clone();
                        wedge.b0 = piece.lo;
                        wedge.b1 = piece.hi;
                        let kept = original_kept.trimmed(kept_ends);
                        self.allocate(wedge, kept, state, stats)
                    } else {
                        reused.push(id);
                        if !unchanged {
                            // A trimmed wedge keeps its queue event: trimming only raises its
                            // key, and the event is re-queued with the new key when it pops.
                            let kept = original_kept.trimmed(kept_ends);
                            let slot = &mut self.slots[id as usize];
                            slot.wedge.b0 = piece.lo;
                            slot.wedge.b1 = piece.hi;
                            slot.kept = kept;
                        }
                        id
                    };
                    if state == SlotState::Queued && target != id {
                        self.queue(target, arrivals);
                    }
                    ids.push(target);
                }
            }
        }
        for i in first..end {
            let id = self.lists[e.index()][i];
            if !reused.contains(&id) {
                let slot = &mut self.slots[id as usize];
                slot.state = SlotState::Free;
                slot.generation = slot.generation.wrapping_add(1);
                self.free.push(id);
            }
        }
        self.list_entries = self.list_entries + ids.len() - (end - first);
        self.lists[e.index()].splice(first..end, ids.drain(..));
        let bytes = self.slots.len() * std::mem::size_of::<Slot<S>>()
            + self.list_entries * std::mem::size_of::<u32>()
            + self.lists.len() * std::mem::size_of::<Vec<u32>>();
        stats.peak_wedge_bytes = stats.peak_wedge_bytes.max(bytes);
        self.scratch.reused = reused;
        self.scratch.ids = ids;
    }

    /// Queues the wedge in `slot`.
    fn queue(&self, slot: u32, arrivals: &mut impl Arrivals<S>) {
        let s = &self.slots[slot as usize];
        arrivals.queue(slot, s.generation, &s.wedge);
    }

    /// A slot for a wedge: a free one, or a new one.
    fn allocate(
        &mut self,
        wedge: Wedge<S>,
        kept: Provenance<S>,
        state: SlotState,
        stats: &mut Stats,
    ) -> u32 {
        stats.wedges_created += 1;
        if let Some(id) = self.free.pop() {
            let slot = &mut self.slots[id as usize];
            slot.wedge = wedge;
            slot.kept = kept;
            slot.state = state;
            slot.generation = slot.generation.wrapping_add(1);
            id
        } else {
            self.slots.push(Slot {
                wedge,
                kept,
                state,
                generation: 0,
            });
            (self.slots.len() - 1) as u32
        }
    }
}
