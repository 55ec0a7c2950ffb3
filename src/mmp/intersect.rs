//! Wedge intersection [LZT §4, SSK+05 §4.2]: a new wedge meets the wedges already on its edge.
//!
//! On the range it shares with an existing wedge, eq. (2) gives the points where the two
//! distance functions cross (none, one, two or infinitely many: Property 1). Between consecutive
//! crossings one wedge is better throughout; each piece goes to the better one, and a tie keeps
//! the existing wedge (Section 4, step 2.3.2). The result covers the union of the ranges with
//! non-overlapping wedges (Property 2), splitting an existing wedge in two where the new one
//! wins only in its middle (Fig. 8c, Fig. 10).

use super::propagate::{Engine, Slot, SlotState};
use super::wedge::Wedge;
use crate::scalar::Scalar;
use std::cmp::Ordering;

/// Who owns a piece of the edge after an intersection.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Owner {
    New,
    Old(u32),
}

struct Piece<S> {
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

impl<S: Scalar> Engine<'_, S> {
    /// Inserts a wedge on its edge, intersecting it with the wedges there.
    pub(crate) fn insert(&mut self, w: Wedge<S>) {
        let e = w.edge;
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
                .take_while(|&&id| self.slots[id as usize].wedge.b0.compare(&w.b1) == Ordering::Less)
                .count();
        let mine = w.distance_function();
        let mut pieces: Vec<Piece<S>> = Vec::new();
        let mut cursor = w.b0.clone();
        for &id in &list[first..end] {
            let old = &self.slots[id as usize].wedge;
            if cursor.compare(&old.b0) == Ordering::Less {
                push_piece(&mut pieces, cursor.clone(), old.b0.clone(), Owner::New);
            }
            if old.b0.compare(&w.b0) == Ordering::Less {
                push_piece(&mut pieces, old.b0.clone(), w.b0.clone(), Owner::Old(id));
            }
            let lo = S::max_of(&old.b0, &w.b0);
            let hi = S::min_of(&old.b1, &w.b1);
            let theirs = old.distance_function();
            let roots = S::bisector_roots(&theirs, &mine, &lo, &hi);
            self.stats.eq2.count(roots.case());
            let mut bounds = vec![lo];
            match roots {
                crate::scalar::BisectorRoots::One(r) => bounds.push(r),
                crate::scalar::BisectorRoots::Two(r, s) => bounds.extend([r, s]),
                _ => {}
            }
            bounds.push(hi.clone());
            let half = S::from_f64(0.5);
            for pair in bounds.windows(2) {
                let mid = (pair[0].clone() + &pair[1]) * &half;
                let owner = if mine.at(&mid).compare_distance(&theirs.at(&mid)) == Ordering::Less {
                    Owner::New
                } else {
                    Owner::Old(id)
                };
                push_piece(&mut pieces, pair[0].clone(), pair[1].clone(), owner);
            }
            if old.b1.compare(&w.b1) == Ordering::Greater {
                push_piece(&mut pieces, w.b1.clone(), old.b1.clone(), Owner::Old(id));
            }
            cursor = hi;
        }
        if cursor.compare(&w.b1) == Ordering::Less {
            push_piece(&mut pieces, cursor, w.b1.clone(), Owner::New);
        }
        if pieces.iter().all(|p| p.owner != Owner::New) {
            return;
        }
        self.rebuild(w, first, end, pieces, &length);
    }

    /// Replaces the wedges `first..end` of the new wedge's edge list by the pieces.
    fn rebuild(&mut self, w: Wedge<S>, first: usize, end: usize, pieces: Vec<Piece<S>>, length: &S) {
        let e = w.edge;
        let old_ids: Vec<u32> = self.lists[e.index()][first..end].to_vec();
        let mut reused: Vec<u32> = Vec::with_capacity(old_ids.len());
        let mut ids: Vec<u32> = Vec::with_capacity(pieces.len());
        let mut new_ends = Vec::new();
        for piece in pieces {
            if !S::has_extent(&piece.lo, &piece.hi, length) {
                continue;
            }
            match piece.owner {
                Owner::New => {
                    let mut wedge = w.clone();
                    wedge.b0 = piece.lo;
                    wedge.b1 = piece.hi;
                    new_ends.push((wedge.b0.clone(), wedge.b1.clone()));
                    let id = self.allocate(wedge, SlotState::Queued);
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
                        self.allocate(wedge, state)
                    } else {
                        reused.push(id);
                        if !unchanged {
                            let slot = &mut self.slots[id as usize];
                            slot.wedge.b0 = piece.lo;
                            slot.wedge.b1 = piece.hi;
                            slot.generation = slot.generation.wrapping_add(1);
                        }
                        id
                    };
                    if state == SlotState::Queued && (!unchanged || target != id) {
                        self.push_wedge_event(target);
                    }
                    ids.push(target);
                }
            }
        }
        for id in old_ids {
            if !reused.contains(&id) {
                let slot = &mut self.slots[id as usize];
                slot.state = SlotState::Free;
                slot.generation = slot.generation.wrapping_add(1);
                self.free.push(id);
            }
        }
        self.list_entries = self.list_entries + ids.len() - (end - first);
        self.lists[e.index()].splice(first..end, ids);
        let bytes = self.slots.len() * std::mem::size_of::<Slot<S>>()
            + self.list_entries * std::mem::size_of::<u32>()
            + self.lists.len() * std::mem::size_of::<Vec<u32>>();
        self.stats.peak_wedge_bytes = self.stats.peak_wedge_bytes.max(bytes);

        let [v0, v1] = self.mesh.edge(e).vertices;
        let d = w.distance_function();
        let zero = S::zero();
        for (lo, hi) in new_ends {
            if S::within(&zero, &lo, &hi, length) {
                self.improve_vertex(v0, d.at(&zero), w.source);
            }
            if S::within(length, &lo, &hi, length) {
                self.improve_vertex(v1, d.at(length), w.source);
            }
        }
    }

    fn allocate(&mut self, wedge: Wedge<S>, state: SlotState) -> u32 {
        self.stats.wedges_created += 1;
        if let Some(id) = self.free.pop() {
            let slot = &mut self.slots[id as usize];
            slot.wedge = wedge;
            slot.state = state;
            slot.generation = slot.generation.wrapping_add(1);
            id
        } else {
            self.slots.push(Slot {
                wedge,
                state,
                generation: 0,
            });
            (self.slots.len() - 1) as u32
        }
    }
}
