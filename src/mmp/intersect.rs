//! Wedge intersection [LZT §4, SSK+05 §4.2]: a new wedge meets the wedges already on its edge.
//!
//! On the range it shares with an existing wedge, eq. (2) gives the points where the two
//! distance functions cross (none, one, two or infinitely many: Property 1). Between consecutive
//! crossings one wedge is better throughout; each piece goes to the better one, and a tie keeps
//! the existing wedge (Section 4, step 2.3.2). The result covers the union of the ranges with
//! non-overlapping wedges (Property 2), splitting an existing wedge in two where the new one
//! wins only in its middle (Fig. 8c, Fig. 10).

use super::propagate::{Engine, Slot, SlotState};
use super::provenance::{Anchor, Provenance};
use super::stats::{Eq2Counts, Eq2Decision};
use super::unfold::Planar;
use super::wedge::{PseudoSource, Wedge};
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
/// `known[0]` (`[1]`) holds both distances at `lo` (`hi`) where a wedge keeps its distance
/// there ([`Provenance`]: at a vertex of the edge, or at a range end on a shadow line): those,
/// not values derived again, are compared there, so that a tie the engine built is seen as one.
/// `lower`: the wedge known to be lower on the whole range ([`lower_by_anchor`]).
/// Returns the case and whether eq. (2) was solved.
fn split_shared_range<S: Scalar>(
    pieces: &mut Vec<Piece<S>>,
    theirs: &SourceDistance<S>,
    mine: &SourceDistance<S>,
    [lo, hi]: [S; 2],
    (known, lower): ([Option<[S; 2]>; 2], Option<Owner>),
    id: u32,
) -> (Eq2Case, bool) {
    if let Some(owner) = lower {
        push_piece(pieces, lo, hi, owner);
        return (Eq2Case::None, false);
    }
    if S::same_distance_function(theirs, mine, &(hi.clone() - &lo)) {
        push_piece(pieces, lo, hi, Owner::Old(id));
        return (Eq2Case::Infinite, true);
    }
    let ties = known.each_ref().map(|v| {
        v.as_ref()
            .is_some_and(|[t, m]| t.compare_distance(m) == Ordering::Equal)
    });
    let [[their_lo, my_lo], [their_hi, my_hi]] = [(&lo, 0), (&hi, 1)].map(|(at, i)| {
        known[i]
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

/// Which of two wedges is lower on all the range they share, when one of them has a range end
/// anchored at the other's pseudo-source vertex, or keeps its distance at a vertex of the edge
/// that is the other's pseudo-source, with the other's image and distance there: the first
/// passes that vertex on a straight line, so by the triangle inequality it is nowhere higher
/// than the vertex's own wedge, which it touches on the shadow line or at the vertex
/// ([`Provenance`]). Asked only of pseudo-source wedges against wedges that keep values.
fn lower_by_anchor<S: Scalar>(
    (old, old_kept, id): (&Wedge<S>, &Provenance<S>, u32),
    (new, new_kept): (&Wedge<S>, &Provenance<S>),
    vertices: &[S; 2],
) -> Option<Owner> {
    let is_source_of = |a: &Anchor<S>, b: &Wedge<S>| {
        matches!(b.pseudo_source, PseudoSource::Vertex(_))
            && b.source_x.compare(&a.point.x) == Ordering::Equal
            && b.source_y.compare(&a.point.y) == Ordering::Equal
            && b.sigma.compare_distance(&a.distance) == Ordering::Equal
    };
    let at_vertex = |kept: &Provenance<S>, i: usize| {
        S::kept(&kept.at_ends[i]).map(|distance| Anchor {
            point: Planar {
                x: vertices[i].clone(),
                y: S::zero(),
            },
            distance,
        })
    };
    let anchored_below = |kept: &Provenance<S>, other: &Wedge<S>| {
        (0..2).any(|i| {
            [kept.anchor(i), at_vertex(kept, i)]
                .into_iter()
                .flatten()
                .any(|a| is_source_of(&a, other))
        })
    };
    if anchored_below(old_kept, new) {
        Some(Owner::Old(id))
    } else if anchored_below(new_kept, old) {
        Some(Owner::New)
    } else {
        None
    }
}

/// Cuts the union of the new wedge's range and the ranges of the wedges it overlaps (sorted,
/// disjoint, each with an id and what it keeps of its construction) into pieces, each owned by
/// the better wedge there.
fn cut_into_pieces<'a, S: Scalar>(
    counts: &mut Eq2Counts,
    mut log: Option<&mut Vec<Eq2Decision>>,
    pieces: &mut Vec<Piece<S>>,
    overlapping: impl Iterator<Item = (u32, &'a Wedge<S>, &'a Provenance<S>)>,
    (w, my_kept): (&Wedge<S>, &Provenance<S>),
    length: &S,
) {
    let mine = w.distance_function();
    let mut cursor = w.b0.clone();
    let vertices = [S::zero(), length.clone()];
    for (id, old, old_kept) in overlapping {
        if cursor.compare(&old.b0) == Ordering::Less {
            push_piece(pieces, cursor.clone(), old.b0.clone(), Owner::New);
        }
        if old.b0.compare(&w.b0) == Ordering::Less {
            push_piece(pieces, old.b0.clone(), w.b0.clone(), Owner::Old(id));
        }
        let (c0, c1) = (old.b0.compare(&w.b0), old.b1.compare(&w.b1));
        let lo = if c0 == Ordering::Less { &w.b0 } else { &old.b0 }.clone();
        let hi = if c1 == Ordering::Greater {
            &w.b1
        } else {
            &old.b1
        }
        .clone();
        // Whose own range end `lo` and `hi` are: [end][old, new].
        let owns = [
            [c0 != Ordering::Less, c0 != Ordering::Greater],
            [c1 != Ordering::Greater, c1 != Ordering::Less],
        ];
        let theirs = old.distance_function();
        let record = log.is_some().then(|| {
            let eq2 = Eq2Coefficients::new(&theirs, &mine, &lo);
            let range = [lo.to_f64(), hi.to_f64()];
            (range, [eq2.a, eq2.b, eq2.c].map(|c| c.to_f64()))
        });
        // Both distances at a shared end where either wedge keeps its own: at a vertex of the
        // edge, or at its range end on a shadow line (the other wedge's is derived there).
        let known = [(&lo, 0), (&hi, 1)].map(|(end, i)| {
            let kept = [old_kept, my_kept];
            let mut values = kept.map(|k| S::kept(&k.at_ends[i]));
            if values.iter().all(Option::is_none) || end.compare(&vertices[i]) != Ordering::Equal {
                values = [0, 1].map(|k| {
                    let anchor = owns[i][k].then(|| kept[k].anchor(i)).flatten();
                    anchor.map(|a| a.distance_function().at(end))
                });
            }
            if values.iter().all(Option::is_none) {
                return None;
            }
            let [t, m] = values;
            Some([
                t.unwrap_or_else(|| theirs.at(end)),
                m.unwrap_or_else(|| mine.at(end)),
            ])
        });
        let lower = lower_by_anchor((old, old_kept, id), (w, my_kept), &vertices);
        let range = [lo, hi.clone()];
        let (case, solved) = split_shared_range(pieces, &theirs, &mine, range, (known, lower), id);
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
///
/// Unstable: an entry to the engine's internals for reproducing [LZT §4] and for tests; its
/// signature may change with the engine.
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
    let none = Provenance::<S>::default();
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
    pub(crate) fn insert(&mut self, w: Wedge<S>, kept: Provenance<S>) {
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
            (id, &slot.wedge, &slot.kept)
        });
        let new = (&w, &kept);
        cut_into_pieces(
            &mut self.stats.eq2,
            log,
            &mut pieces,
            overlapping,
            new,
            &length,
        );
        if pieces.iter().any(|p| p.owner == Owner::New) {
            self.rebuild(&w, &kept, first, end, &mut pieces, &length);
        }
        self.scratch.pieces = pieces;
    }

    /// Replaces the wedges `first..end` of the new wedge's edge list by the pieces.
    fn rebuild(
        &mut self,
        w: &Wedge<S>,
        kept: &Provenance<S>,
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
        // Which range ends of a wedge a piece keeps (asked only where anchors depend on it).
        let anchored = |k: &Provenance<S>| k.anchor(0).is_some() || k.anchor(1).is_some();
        let keeps = |w: &Wedge<S>, lo: &S, hi: &S| {
            [
                w.b0.compare(lo) == Ordering::Equal,
                w.b1.compare(hi) == Ordering::Equal,
            ]
        };
        // A wedge that keeps two pieces (the new one won in its middle) is trimmed in place for
        // the first: the second is cut from the wedge as it was, with the anchor of its end.
        let split: Vec<(u32, Wedge<S>, Provenance<S>)> = pieces
            .iter()
            .enumerate()
            .filter_map(|(i, p)| match p.owner {
                Owner::Old(id) if pieces[i + 1..].iter().any(|q| q.owner == p.owner) => {
                    let slot = &self.slots[id as usize];
                    Some((id, slot.wedge.clone(), slot.kept.clone()))
                }
                _ => None,
            })
            .collect();
        for piece in pieces.drain(..) {
            if !S::has_extent(&piece.lo, &piece.hi, length) {
                continue;
            }
            match piece.owner {
                Owner::New => {
                    if S::within(&zero, &piece.lo, &piece.hi, length) {
                        let d = S::kept(&kept.at_ends[0]).unwrap_or_else(|| mine.at(&zero));
                        self.offer_vertex(v0, d, w);
                    }
                    if S::within(length, &piece.lo, &piece.hi, length) {
                        let d = S::kept(&kept.at_ends[1]).unwrap_or_else(|| mine.at(length));
                        self.offer_vertex(v1, d, w);
                    }
                    let piece_kept = if anchored(kept) {
                        kept.trimmed(keeps(w, &piece.lo, &piece.hi))
                    } else {
                        kept.clone()
                    };
                    let mut wedge = w.clone();
                    wedge.b0 = piece.lo;
                    wedge.b1 = piece.hi;
                    let id = self.allocate(wedge, piece_kept, SlotState::Queued);
                    self.push_wedge_event(id);
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
                        self.allocate(wedge, kept, state)
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

    fn allocate(&mut self, wedge: Wedge<S>, kept: Provenance<S>, state: SlotState) -> u32 {
        self.stats.wedges_created += 1;
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
