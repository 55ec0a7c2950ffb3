//! Wedge intersection [LZT §4, SSK+05 §4.2]: a new wedge meets the wedges already on its edge.
//!
//! On the range it shares with an existing wedge, eq. (2) gives the points where the two
//! distance functions cross (none, one, two or infinitely many: Property 1). Between consecutive
//! crossings one wedge is better throughout; each piece goes to the better one, and a tie keeps
//! the existing wedge (Section 4, step 2.3.2). The result covers the union of the ranges with
//! non-overlapping wedges (Property 2), splitting an existing wedge in two where the new one
//! wins only in its middle (Fig. 8c, Fig. 10).

use super::propagate::{EndValues, Engine, Slot, SlotState};
use super::stats::{Eq2Counts, Eq2Decision};
use super::wedge::Wedge;
use crate::scalar::{BisectorRoots, Eq2Case, Eq2Coefficients, Scalar, Site, SourceDistance};
use std::cmp::Ordering;

/// Who owns a piece of the edge after an intersection.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Owner {
    New,
    Old(u32),
}

pub(crate) struct Piece<S> {
    lo: S,
    hi: S,
    owner: Owner,
}

fn push_piece<S: Scalar>(pieces: &mut Vec<Piece<S>>, lo: S, hi: S, owner: Owner) {
    if let Some(last) = pieces.last_mut() {
        if last.owner == owner {
            last.hi = hi;
            return;
        }
    }
    pieces.push(Piece { lo, hi, owner });
}

/// Reusable buffers of the intersection, kept across insertions to avoid allocating.
pub(crate) struct Scratch<S> {
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

/// The smallest value of a distance function on `[lo, hi]` (it is convex, so the foot of the
/// pseudo-source if inside, else the nearer end).
fn min_on<S: Scalar>(d: &SourceDistance<S>, lo: &S, hi: &S, at_lo: &S, at_hi: &S) -> S {
    if d.x.compare(lo) == Ordering::Greater && d.x.compare(hi) == Ordering::Less {
        d.y.clone() + &d.sigma
    } else {
        S::min_of(at_lo, at_hi)
    }
}

/// Splits the range `[lo, hi]` shared by an existing wedge (`theirs`) and the new one
/// (`mine`) into pieces, each owned by the better wedge [LZT §4]. Coincident distance
/// functions keep the existing wedge (step 2.3.2). When one wedge is better at every point of
/// the range by the bounds of convexity, eq. (2) has no root there and is not solved;
/// otherwise its roots cut the range, and each piece goes to the wedge better at its middle
/// (pieces on both sides of a touching root, or of a crossing the backend placed where the
/// distances agree to its resolution, go to the same wedge and merge). The roots' positions
/// are constructions: rounded from the coefficients of eq. (2), a near-double root moves far
/// (1.3 units on an edge of 1e8 in a mixed-magnitude mesh), so owners are not inferred by
/// alternation from one piece, which would hand that whole stretch to the wrong wedge.
/// `at_vertices[0]` (`[1]`) holds both distances at `lo` (`hi`) when that end is a vertex of
/// the edge whose distances both wedges keep ([`EndValues`]): those, not values derived again,
/// are compared there, so that a tie the engine built is seen as one.
/// Returns the case and whether eq. (2) was solved.
fn split_shared_range<S: Scalar>(
    pieces: &mut Vec<Piece<S>>,
    theirs: &SourceDistance<S>,
    mine: &SourceDistance<S>,
    [lo, hi]: [S; 2],
    at_vertices: [Option<[S; 2]>; 2],
    id: u32,
) -> (Eq2Case, bool) {
    if S::same_distance_function(theirs, mine, &(hi.clone() - &lo)) {
        push_piece(pieces, lo, hi, Owner::Old(id));
        return (Eq2Case::Infinite, true);
    }
    let ties = at_vertices.each_ref().map(|v| {
        v.as_ref()
            .is_some_and(|[t, m]| t.compare_distance(m) == Ordering::Equal)
    });
    let [[their_lo, my_lo], [their_hi, my_hi]] = [(&lo, 0), (&hi, 1)].map(|(at, i)| {
        at_vertices[i]
            .clone()
            .unwrap_or_else(|| [theirs.at(at), mine.at(at)])
    });
    let their_max = S::max_of(&their_lo, &their_hi);
    if min_on(mine, &lo, &hi, &my_lo, &my_hi).compare_distance(&their_max) != Ordering::Less {
        push_piece(pieces, lo, hi, Owner::Old(id));
        return (Eq2Case::None, false);
    }
    let my_max = S::max_of(&my_lo, &my_hi);
    if my_max.compare_distance(&min_on(theirs, &lo, &hi, &their_lo, &their_hi)) == Ordering::Less {
        push_piece(pieces, lo, hi, Owner::New);
        return (Eq2Case::None, false);
    }
    let roots = S::bisector_roots_given_ties(theirs, mine, &lo, &hi, ties);
    let case = roots.case();
    let (first, second) = match roots {
        BisectorRoots::One(r) | BisectorRoots::Touch(r) => (Some(r), None),
        BisectorRoots::Two(r, s) => (Some(r), Some(s)),
        BisectorRoots::None | BisectorRoots::Infinite => (None, None),
    };
    let half = S::from_f64(0.5);
    let mut start = lo;
    for end in [first, second, Some(hi)].into_iter().flatten() {
        let mid = (start.clone() + &end) * &half;
        let owner = if mine.at(&mid).compare_distance(&theirs.at(&mid)) == Ordering::Less {
            Owner::New
        } else {
            Owner::Old(id)
        };
        push_piece(pieces, start, end.clone(), owner);
        start = end;
    }
    (case, true)
}

/// Cuts the union of the new wedge's range and the ranges of the wedges it overlaps (sorted,
/// disjoint, each with an id and its kept distances at the edge's ends) into pieces, each
/// owned by the better wedge there.
fn cut_into_pieces<'a, S: Scalar>(
    counts: &mut Eq2Counts,
    mut log: Option<&mut Vec<Eq2Decision>>,
    pieces: &mut Vec<Piece<S>>,
    overlapping: impl Iterator<Item = (u32, &'a Wedge<S>, &'a EndValues<S>)>,
    (w, at_ends): (&Wedge<S>, &EndValues<S>),
    length: &S,
) {
    let mine = w.distance_function();
    let mut cursor = w.b0.clone();
    let vertices = [S::zero(), length.clone()];
    for (id, old, old_ends) in overlapping {
        if cursor.compare(&old.b0) == Ordering::Less {
            push_piece(pieces, cursor.clone(), old.b0.clone(), Owner::New);
        }
        if old.b0.compare(&w.b0) == Ordering::Less {
            push_piece(pieces, old.b0.clone(), w.b0.clone(), Owner::Old(id));
        }
        let lo = S::max_of(&old.b0, &w.b0);
        let hi = S::min_of(&old.b1, &w.b1);
        let theirs = old.distance_function();
        let record = log.is_some().then(|| {
            let eq2 = Eq2Coefficients::new(&theirs, &mine, &lo);
            let range = [lo.to_f64(), hi.to_f64()];
            (range, [eq2.a, eq2.b, eq2.c].map(|c| c.to_f64()))
        });
        // Both distances at a shared end that is a vertex, if both wedges keep them.
        let at_vertices = [(&lo, 0), (&hi, 1)].map(|(end, i)| {
            let kept = [S::kept(&old_ends[i])?, S::kept(&at_ends[i])?];
            (end.compare(&vertices[i]) == Ordering::Equal).then_some(kept)
        });
        let range = [lo, hi.clone()];
        let (case, solved) = split_shared_range(pieces, &theirs, &mine, range, at_vertices, id);
        counts.count(case);
        if let (Some(log), Some((range, coefficients))) = (log.as_deref_mut(), record) {
            log.push(Eq2Decision {
                edge: w.edge.0,
                existing: old.pseudo_source,
                arriving: w.pseudo_source,
                range,
                case,
                solved,
                coefficients,
            });
        }
        if old.b1.compare(&w.b1) == Ordering::Greater {
            push_piece(pieces, w.b1.clone(), old.b1.clone(), Owner::Old(id));
        }
        cursor = hi;
    }
    if cursor.compare(&w.b1) == Ordering::Less {
        push_piece(pieces, cursor, w.b1.clone(), Owner::New);
    }
}

/// The wedges of an edge after a new wedge meets them [LZT §4], outside a propagation: the
/// Section 4 cases on hand-made wedges. `existing` are the edge's wedges, sorted and disjoint;
/// the result is sorted and disjoint too, with the eq.-(2) cases met.
pub fn intersect<S: Scalar>(
    edge_length: &S,
    existing: &[Wedge<S>],
    arriving: &Wedge<S>,
) -> (Vec<Wedge<S>>, Eq2Counts) {
    let mut counts = Eq2Counts::default();
    if !S::has_extent(&arriving.b0, &arriving.b1, edge_length) {
        return (existing.to_vec(), counts);
    }
    let overlaps = |old: &Wedge<S>| {
        old.b1.compare(&arriving.b0) == Ordering::Greater
            && old.b0.compare(&arriving.b1) == Ordering::Less
    };
    let mut pieces = Vec::new();
    let overlapping = existing
        .iter()
        .enumerate()
        .filter(|(_, old)| overlaps(old))
        .map(|(i, old)| (i as u32, old));
    let none = EndValues::<S>::default();
    let overlapping = overlapping.map(|(i, old)| (i, old, &none));
    let new = (arriving, &none);
    cut_into_pieces(
        &mut counts,
        None,
        &mut pieces,
        overlapping,
        new,
        edge_length,
    );
    let first = existing.iter().position(overlaps).unwrap_or(existing.len());
    let mut result: Vec<Wedge<S>> = existing[..first].to_vec();
    for piece in pieces {
        if !S::has_extent(&piece.lo, &piece.hi, edge_length) {
            continue;
        }
        let mut wedge = match piece.owner {
            Owner::New => arriving.clone(),
            Owner::Old(i) => existing[i as usize].clone(),
        };
        wedge.b0 = piece.lo;
        wedge.b1 = piece.hi;
        result.push(wedge);
    }
    result.extend(
        existing
            .iter()
            .skip(first)
            .filter(|w| !overlaps(w))
            .cloned(),
    );
    (result, counts)
}

impl<S: Scalar> Engine<'_, S> {
    /// Inserts a wedge on its edge, intersecting it with the wedges there.
    pub(crate) fn insert(&mut self, w: Wedge<S>, at_ends: EndValues<S>) {
        let e = w.edge;
        S::locate(Site {
            edge: Some(e.0),
            what: "wedge intersection (eq. 2)",
        });
        let length = self.unfolding.length(e).clone();
        if !S::has_extent(&w.b0, &w.b1, &length) {
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
        let log = self.record_decisions.then_some(&mut self.stats.decisions);
        let overlapping = self.lists[e.index()][first..end].iter().map(|&id| {
            let slot = &self.slots[id as usize];
            (id, &slot.wedge, &slot.at_ends)
        });
        let new = (&w, &at_ends);
        cut_into_pieces(
            &mut self.stats.eq2,
            log,
            &mut pieces,
            overlapping,
            new,
            &length,
        );
        if pieces.iter().any(|p| p.owner == Owner::New) {
            self.rebuild(&w, &at_ends, first, end, &mut pieces, &length);
        }
        self.scratch.pieces = pieces;
    }

    /// Replaces the wedges `first..end` of the new wedge's edge list by the pieces.
    fn rebuild(
        &mut self,
        w: &Wedge<S>,
        at_ends: &EndValues<S>,
        first: usize,
        end: usize,
        pieces: &mut Vec<Piece<S>>,
        length: &S,
    ) {
        let e = w.edge;
        let mut reused = std::mem::take(&mut self.scratch.reused);
        let mut ids = std::mem::take(&mut self.scratch.ids);
        reused.clear();
        ids.clear();
        let [v0, v1] = self.mesh.edge(e).vertices;
        let zero = S::zero();
        let mine = w.distance_function();
        for piece in pieces.drain(..) {
            if !S::has_extent(&piece.lo, &piece.hi, length) {
                continue;
            }
            match piece.owner {
                Owner::New => {
                    if S::within(&zero, &piece.lo, &piece.hi, length) {
                        let d = S::kept(&at_ends[0]).unwrap_or_else(|| mine.at(&zero));
                        self.improve_vertex(v0, d, w.source);
                    }
                    if S::within(length, &piece.lo, &piece.hi, length) {
                        let d = S::kept(&at_ends[1]).unwrap_or_else(|| mine.at(length));
                        self.improve_vertex(v1, d, w.source);
                    }
                    let mut wedge = w.clone();
                    wedge.b0 = piece.lo;
                    wedge.b1 = piece.hi;
                    let id = self.allocate(wedge, at_ends.clone(), SlotState::Queued);
                    self.push_wedge_event(id);
                    ids.push(id);
                }
                Owner::Old(id) => {
                    let slot = &self.slots[id as usize];
                    let unchanged = slot.wedge.b0.compare(&piece.lo) == Ordering::Equal
                        && slot.wedge.b1.compare(&piece.hi) == Ordering::Equal;
                    let state = slot.state;
                    let target = if reused.contains(&id) {
                        let mut wedge = slot.wedge.clone();
                        wedge.b0 = piece.lo;
                        wedge.b1 = piece.hi;
                        let kept = slot.at_ends.clone();
                        self.allocate(wedge, kept, state)
                    } else {
                        reused.push(id);
                        if !unchanged {
                            // A trimmed wedge keeps its queue event: trimming only raises its
                            // key, and the event is re-queued with the new key when it pops.
                            let slot = &mut self.slots[id as usize];
                            slot.wedge.b0 = piece.lo;
                            slot.wedge.b1 = piece.hi;
                        }
                        id
                    };
                    if state == SlotState::Queued && target != id {
                        self.push_wedge_event(target);
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
        self.stats.peak_wedge_bytes = self.stats.peak_wedge_bytes.max(bytes);
        self.scratch.reused = reused;
        self.scratch.ids = ids;
    }

    fn allocate(&mut self, wedge: Wedge<S>, at_ends: EndValues<S>, state: SlotState) -> u32 {
        self.stats.wedges_created += 1;
        if let Some(id) = self.free.pop() {
            let slot = &mut self.slots[id as usize];
            slot.wedge = wedge;
            slot.at_ends = at_ends;
            slot.state = state;
            slot.generation = slot.generation.wrapping_add(1);
            id
        } else {
            self.slots.push(Slot {
                wedge,
                at_ends,
                state,
                generation: 0,
            });
            (self.slots.len() - 1) as u32
        }
    }
}
