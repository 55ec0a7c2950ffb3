//! The wedges of every edge while a propagation runs [SSK+05 §4.2, LZT §4]: each edge's list
//! of entries (a wedge, what it keeps of its construction, whether it waits in the queue),
//! sorted along the edge and disjoint. A list is one piece of memory, so that placing a new
//! wedge reads its edge's wedges and nothing else (on a shared arena, every step of that search
//! was a cache miss). A list is a [`ThinVec`]: one pointer per edge, its length and capacity
//! kept with its wedges (most edges have no wedge at any time, and a `Vec` costs three words).
//! A wedge arriving on an edge is cut into pieces with the wedges there by eq. (2)
//! ([`intersect`](super::intersect)), and the list is rebuilt from the pieces.

use super::edge_wedges::EdgeWedges;
use super::intersect::{cut_into_pieces, Owner, Piece};
use super::paths::CongruentPaths;
use super::provenance::{compare_ends, keeps_values, one_end, range_end, Provenance, RangeEnd};
use super::radix_queue::KEY_RESOLUTION;
use super::stats::Stats;
use super::strips::OfferedWedges;
use super::wedge::{wedge_fields, PseudoSource, Wedge, WedgeFields};
use crate::mesh::{EdgeId, Side, SourceId, TriMesh, VertexId};
use crate::scalar::float::farthest;
use crate::scalar::{Scalar, Site, SourceDistance, FRONT_MARGIN};
use std::cmp::Ordering;
use std::ops::Range;
use thin_vec::ThinVec;

/// A wedge of an edge list: the wedge's fields but its edge (the list's), so that the queue
/// state and the serial fit where the wedge has padding (64 bytes in the `f64` engine, not
/// 72), and what the wedge keeps of its construction.
#[derive(Clone, Debug)]
struct Entry<S: Scalar> {
    b0: S,
    b1: S,
    source_x: S,
    source_y: S,
    sigma: S,
    pseudo_source: PseudoSource,
    source: SourceId,
    tau: Side,
    /// Whether the wedge waits in the queue (else it was propagated).
    queued: bool,
    /// The wedge's number on its edge, which its queue event names: a new one for each wedge
    /// the edge receives (the numbers wrap around after 2^32 wedges on one edge).
    serial: u32,
    kept: Provenance<S>,
}

impl<S: Scalar> Entry<S> {
    /// Range end `i` (0: `b0`, 1: `b1`) as [`compare_ends`] sees it.
    fn range_end(&self, i: usize) -> RangeEnd<'_, S> {
        let value = if i == 0 { &self.b0 } else { &self.b1 };
        (value, &self.kept, i, [&self.source_x, &self.source_y])
    }

    /// A wedge waiting in the queue under `serial`.
    fn new(w: Wedge<S>, kept: Provenance<S>, serial: u32) -> Self {
        Entry {
            b0: w.b0,
            b1: w.b1,
            source_x: w.source_x,
            source_y: w.source_y,
            sigma: w.sigma,
            pseudo_source: w.pseudo_source,
            source: w.source,
            tau: w.tau,
            queued: true,
            serial,
            kept,
        }
    }

    /// Whether `next`, the following wedge along an edge of length `length`, continues this
    /// one: the same pseudo-source, source and side, ranges that meet (no extent between
    /// them), and the same distance function, as the backend decides it (eq. (2) with
    /// infinitely many solutions). Then the two are one wedge of one image of the
    /// pseudo-source, split only by the shadow line of a vertex whose faces lie in the plane
    /// of the unfolding: in an exactly flat region, a wedge per vertex behind the edge. Ends
    /// that are one point by structure ([`one_end`]: both on that vertex's shadow line) meet
    /// without comparing their values, which two chains of faces built apart.
    fn continued_by(&self, next: &Self, length: &S) -> bool {
        self.pseudo_source == next.pseudo_source
            && self.source == next.source
            && self.tau == next.tau
            && S::same_image(
                &self.distance_function(),
                &next.distance_function(),
                &(next.b1.clone() - &self.b0),
            )
            && (one_end(self.range_end(1), next.range_end(0))
                || !S::has_extent(&self.b1, &next.b0, length))
    }

    /// This wedge extended over `next`, which continues it ([`Entry::continued_by`]) and which
    /// the caller then drops: the range runs on to `next`'s end, with what `next` keeps of that
    /// end. The distance function is this wedge's (the backend found the two the same), and so
    /// are the serial and the queue state (the caller joins only wedges in the same state).
    fn join(&mut self, next: &mut Entry<S>) {
        self.b1 = next.b1.clone();
        self.kept = std::mem::take(&mut self.kept).joined(std::mem::take(&mut next.kept));
    }

    /// The largest distance the wedge gives on its range, in `f64` (at an end: the distance
    /// function is convex): when to ask whether the front has passed it, not the answer.
    fn farthest(&self) -> f64 {
        let d = SourceDistance {
            x: self.source_x.to_f64(),
            y: self.source_y.to_f64(),
            sigma: self.sigma.to_f64(),
        };
        farthest(&d, self.b0.to_f64(), self.b1.to_f64())
    }

    /// The wedge, on `edge`.
    fn wedge(&self, edge: EdgeId) -> Wedge<S> {
        Wedge {
            edge,
            b0: self.b0.clone(),
            b1: self.b1.clone(),
            source_x: self.source_x.clone(),
            source_y: self.source_y.clone(),
            sigma: self.sigma.clone(),
            tau: self.tau,
            pseudo_source: self.pseudo_source,
            source: self.source,
        }
    }
}

wedge_fields!(Entry);

/// Reusable buffers of the intersection, kept across insertions to avoid allocating.
struct Scratch<S: Scalar> {
    pieces: Vec<Piece<S>>,
    /// Whether a piece of each overlapped wedge took its serial (and so its queue event).
    named: Vec<bool>,
    /// The rebuilt stretch of the list, each entry with whether it needs a queue event.
    fresh: Vec<(Entry<S>, bool)>,
}

impl<S: Scalar> Default for Scratch<S> {
    fn default() -> Self {
        Scratch {
            pieces: Vec::new(),
            named: Vec::new(),
            fresh: Vec::new(),
        }
    }
}

/// How a queue event names its wedge: by its edge and serial, with the place it had in the
/// edge's list when it was queued, where the search for it starts.
#[derive(Clone, Copy, Debug)]
pub(crate) struct WedgeRef {
    edge: EdgeId,
    serial: u32,
    place: u32,
}

impl WedgeRef {
    /// The edge of the wedge.
    pub(crate) fn edge(&self) -> EdgeId {
        self.edge
    }
}

/// What inserting a wedge tells the propagation: the wedges it queues and the vertices of the
/// edge the new wedge reaches.
pub(crate) trait Arrivals<S: Scalar> {
    /// The wedge `wedge`, named `at`, waits to be propagated.
    fn queue(&mut self, at: WedgeRef, wedge: &impl WedgeFields<S>);
    /// A wedge, with what it keeps of its construction, reaches the vertex `v` of its
    /// edge at distance `d`.
    fn reach(&mut self, v: VertexId, d: S, wedge: (&Wedge<S>, &Provenance<S>));
    /// The stretch `[lo, hi]` of `wedge`'s range that the edge's wedge of distance function
    /// `other` kept: if the two are equal there to within the backend's rounding, the stretch
    /// of `wedge` is propagated as well (see `front.rs`).
    fn tied(
        &mut self,
        _wedge: (&Wedge<S>, &Provenance<S>),
        _stretch: [&S; 2],
        _other: &SourceDistance<S>,
    ) {
    }

    /// The mesh and the run's table of congruent paths, where the wedges' paths are read
    /// against them.
    fn congruence(&self) -> Option<(&TriMesh, &CongruentPaths<S>)> {
        None
    }
}

/// Whether the wedge of a queue event is due ([`WedgeLists::due`]).
pub(crate) enum Due<S: Scalar> {
    /// The wedge left its edge, or already propagated.
    Stale,
    /// The wedge was trimmed since it was queued: its smallest distance is now this key.
    Later(f64),
    /// The wedge and what it keeps, now marked as propagated.
    Now(Wedge<S>, Provenance<S>),
}

/// How far beyond the front, as a fraction of the front's distance, a wedge trimmed since it
/// was queued may lie and still be propagated when its event comes up, rather than queued
/// again at its new smallest distance: the queue's resolution ([`KEY_RESOLUTION`]), within
/// which it orders no keys anyway (and no less, or a wedge queued again within it would come
/// up again at once, for ever). Its children still give no distance nearer than the front
/// (they lie beyond the wedge's smallest distance), which is all that vertices being final,
/// stop points and giving up edges rest on. Trimming an end of a wedge mostly raises its
/// smallest distance by 1e-7 to 1e-4 of it: from v0 of icosphere5, 278k events came up before
/// their wedges (478k propagated) and were queued again, each costing a pop and a push; with
/// this slack 154 do, and the run takes 6.5 % fewer instructions (rocker_arm 43.8k requeues
/// -> 3.9k, 1.5 %; stanford_bunny 221k -> 14k, 1.7 %), the same wedges propagated within
/// 0.01 % (fewer created).
const EARLY: f64 = KEY_RESOLUTION;

/// The place of the wedge numbered `serial` in `list`, looking from `place` on, then back from
/// it: wedges inserted before it since it was queued there moved it to the right, and wedges
/// join a list far more often than they leave it (on the bunny, 990k events found their wedge
/// to the right of its place and 2k to the left; a search outwards both ways at once took
/// twice the probes, each a cache line).
fn find_near<S: Scalar>(list: &[Entry<S>], place: usize, serial: u32) -> Option<usize> {
    let (before, after) = list.split_at(place.min(list.len()));
    after
        .iter()
        .position(|x| x.serial == serial)
        .map(|i| before.len() + i)
        .or_else(|| before.iter().rposition(|x| x.serial == serial))
}

/// Inserts `entries` into `list` at `at`, moving its tail once: for the rare rebuild that
/// adds three entries or more (kept apart, so that `Vec::splice` does not weigh on the common
/// rebuild's code).
#[cold]
#[inline(never)]
fn insert_many<T>(list: &mut ThinVec<T>, at: usize, entries: impl Iterator<Item = T>) {
    list.splice(at..at, entries);
}

/// The wedges of every edge of a running propagation.
pub(crate) struct WedgeLists<S: Scalar> {
    lists: Vec<ThinVec<Entry<S>>>,
    /// When only vertex distances are asked for, whether each edge's wedges were given up
    /// ([`WedgeLists::close`]); `None`: every wedge is kept to the end.
    closed: Option<Vec<bool>>,
    /// The serial of each edge's next wedge.
    serials: Vec<u32>,
    /// Wedges in all lists.
    entries: usize,
    /// The most wedges an edge's list has had room for.
    longest: usize,
    /// Keep a log of every meeting of two wedges ([`Stats::decisions`]).
    record_decisions: bool,
    scratch: Scratch<S>,
}

impl<S: Scalar> WedgeLists<S> {
    /// No wedge yet on any of `edge_count` edges.
    /// `vertices_only`: only vertex distances are asked for, so the wedges of an edge may be
    /// given up once no later wedge can win a point of it ([`WedgeLists::close`]).
    pub(crate) fn new(edge_count: usize, record_decisions: bool, vertices_only: bool) -> Self {
        WedgeLists {
            lists: std::iter::repeat_with(ThinVec::new)
                .take(edge_count)
                .collect(),
            closed: vertices_only.then(|| vec![false; edge_count]),
            serials: vec![0; edge_count],
            entries: 0,
            longest: 0,
            record_decisions,
            scratch: Scratch::default(),
        }
    }

    /// The wedge of a queue event popped at `key`, if it is due: its smallest distance is
    /// within [`EARLY`] of `key`. A due wedge is marked as propagated and joined to the
    /// propagated wedges beside it that it continues ([`Entry::continued_by`]; `length`: its
    /// edge's length): their children and its own are the children of the joined wedge, so the
    /// edge keeps one wedge where the shadow lines of flat vertices would have cut many.
    pub(crate) fn due(&mut self, at: WedgeRef, key: f64, length: &S, stats: &mut Stats) -> Due<S> {
        let list = &mut self.lists[at.edge.index()];
        let Some(mut i) = find_near(list, at.place as usize, at.serial) else {
            return Due::Stale;
        };
        let entry = &mut list[i];
        if !entry.queued {
            return Due::Stale;
        }
        let now = entry.min_distance().to_f64();
        if now > key + key * EARLY {
            return Due::Later(now);
        }
        let wedge = entry.wedge(at.edge);
        entry.queued = false;
        let kept = entry.kept.clone();
        if i > 0 && !list[i - 1].queued && list[i - 1].continued_by(&list[i], length) {
            let mut next = list.remove(i);
            i -= 1;
            list[i].join(&mut next);
            self.entries -= 1;
            stats.wedges_joined += 1;
        }
        if i + 1 < list.len() && !list[i + 1].queued && list[i].continued_by(&list[i + 1], length) {
            let mut next = list.remove(i + 1);
            list[i].join(&mut next);
            self.entries -= 1;
            stats.wedges_joined += 1;
        }
        Due::Now(wedge, kept)
    }

    /// The most wedges an edge's list has had room for so far (at least its most wedges, and
    /// less than 1.5 times them).
    pub(crate) fn longest(&self) -> usize {
        self.longest
    }

    /// When only vertex distances are asked for and every wedge of edge `e` has been
    /// propagated: the front's key at which they may be given up ([`WedgeLists::close`]).
    pub(crate) fn closing_key(&self, e: EdgeId) -> Option<f64> {
        self.closed.as_ref()?;
        let list = &self.lists[e.index()];
        if list.is_empty() || list.iter().any(|x| x.queued) {
            return None;
        }
        Some(list.iter().map(Entry::farthest).fold(0.0, f64::max) * FRONT_MARGIN)
    }

    /// Gives up the wedges of edge `e` (of length `length`) if the front, at `key`, is beyond
    /// every distance they give, as the backend decides it ([`Scalar::front_passed`]), all of
    /// them have been propagated, and a wedge arriving later, no nearer than the front, would
    /// lose every point of the edge: to them, where they cover the edge without a gap that has
    /// extent, or else to a path of length `known()[i]` to the edge's end `i` continued along
    /// the whole edge, if the front is beyond that too (the vertex filter's reason to drop a
    /// wedge [SSK+05 §4.2]; in a run split into sectors, the edges the other sector's wedges
    /// win keep gaps). Such a wedge is dropped unseen, and the vertex distances are those of
    /// a run that keeps every wedge. What is given up is the distance field inside the faces,
    /// which vertex distances do not need. Whether the edge was closed.
    pub(crate) fn close(
        &mut self,
        e: EdgeId,
        key: f64,
        length: &S,
        known: impl FnOnce() -> [Option<S>; 2],
    ) -> bool {
        let Some(closed) = self.closed.as_mut() else {
            return false;
        };
        let list = &mut self.lists[e.index()];
        let (Some(first), Some(last)) = (list.first(), list.last()) else {
            return false;
        };
        let done = list.iter().all(|x| !x.queued)
            && list
                .iter()
                .all(|x| S::front_passed(&x.distance_function(), &x.b0, &x.b1, key));
        let covered = || {
            !S::has_extent(&S::zero(), &first.b0, length)
                && !S::has_extent(&last.b1, length, length)
                && list
                    .windows(2)
                    .all(|p| !S::has_extent(&p[0].b1, &p[1].b0, length))
        };
        // The path to an end continued along the edge: the distance function of a source at
        // that end, lit before the front by `known`.
        let beaten_from_ends = || {
            known()
                .into_iter()
                .zip([S::zero(), length.clone()])
                .any(|(d, x)| {
                    d.is_some_and(|sigma| {
                        let path = SourceDistance {
                            x,
                            y: S::zero(),
                            sigma,
                        };
                        S::front_passed(&path, &S::zero(), length, key)
                    })
                })
        };
        if done && (covered() || beaten_from_ends()) {
            self.entries -= list.len();
            *list = ThinVec::new();
            closed[e.index()] = true;
            return true;
        }
        false
    }

    /// The final wedges of every edge, each list exactly sized, moved out of their entries.
    /// The table of lists is reused in place (a new one, allocated while the unfolding is
    /// still held, made the run's peak).
    pub(crate) fn into_edge_wedges(self) -> EdgeWedges<S> {
        EdgeWedges::new(
            self.lists
                .into_iter()
                .enumerate()
                .map(|(e, list)| {
                    let e = EdgeId(e as u32);
                    let mut wedges = ThinVec::with_capacity(list.len());
                    wedges.extend(list.into_iter().map(|x| x.wedge(e)));
                    wedges
                })
                .collect(),
        )
    }

    /// Inserts a wedge on its edge (of the given length and vertices), intersecting it with
    /// the wedges there.
    pub(crate) fn insert(
        &mut self,
        (w, kept): (Wedge<S>, Provenance<S>),
        (length, ends): (&S, [VertexId; 2]),
        stats: &mut Stats,
        (arrivals, strips): (&mut impl Arrivals<S>, Option<&mut OfferedWedges>),
    ) {
        let e = w.edge;
        S::locate(Site {
            edge: Some(e.0),
            what: "wedge intersection (eq. 2)",
        });
        let closed = self.closed.as_ref().is_some_and(|c| c[e.index()]);
        if closed || !w.has_extent_on(&w.b0, &w.b1, length) {
            return;
        }
        let list = &self.lists[e.index()];
        let first = list.partition_point(|x| {
            compare_ends(x.range_end(1), range_end(&w, &kept, 0)) != Ordering::Greater
        });
        let end = first
            + list[first..]
                .iter()
                .take_while(|x| {
                    compare_ends(x.range_end(0), range_end(&w, &kept, 1)) == Ordering::Less
                })
                .count();
        let mut pieces = std::mem::take(&mut self.scratch.pieces);
        pieces.clear();
        let log = self.record_decisions.then_some(&mut stats.decisions);
        // An overlapped wedge is named by its place among the overlapped ones.
        let overlapping = (0..).zip(&list[first..end]).map(|(k, x)| (k, x, &x.kept));
        let new = (&w, &kept);
        let edge = (length, arrivals.congruence());
        cut_into_pieces(&mut stats.eq2, log, &mut pieces, overlapping, new, edge);
        // Stretches of the new range that an overlapped wedge kept, which a near-tie may have
        // decided (only number types that round their constructions have those).
        if !keeps_values::<S>() {
            for piece in &pieces {
                let Some(k) = piece.owner.old_id() else {
                    continue;
                };
                if piece.lo.compare(&w.b0) != Ordering::Less
                    && piece.hi.compare(&w.b1) != Ordering::Greater
                {
                    let other = list[first + k as usize].distance_function();
                    arrivals.tied((&w, &kept), [&piece.lo, &piece.hi], &other);
                }
            }
        }
        if pieces.iter().any(|p| p.owner == Owner::NEW) {
            let edge = (length, ends);
            let run = (stats, arrivals, strips);
            self.rebuild((&w, &kept), first..end, &mut pieces, edge, run);
        }
        self.scratch.pieces = pieces;
    }

    /// Replaces the wedges `first..end` of the new wedge's edge list by the pieces. The first
    /// piece of an existing wedge keeps its serial, and so its queue event (trimming only
    /// raises its key, and the event is re-queued with the new key when it pops, unless the
    /// rise is within [`EARLY`]); a second piece (the new wedge won in its middle) is a wedge
    /// of its own, cut from it as it was, with the anchor of its end. Waiting wedges that
    /// continue one another ([`Entry::continued_by`]), among the pieces and with the waiting
    /// wedges beside them, are joined into one, queued anew (the joined range may come nearer
    /// than the first one's key); a wedge beside a propagated one that it continues joins it
    /// once it is propagated itself ([`WedgeLists::due`]).
    fn rebuild(
        &mut self,
        (w, kept): (&Wedge<S>, &Provenance<S>),
        Range { start: first, end }: Range<usize>,
        pieces: &mut Vec<Piece<S>>,
        (length, [v0, v1]): (&S, [VertexId; 2]),
        (stats, arrivals, mut strips): (
            &mut Stats,
            &mut impl Arrivals<S>,
            Option<&mut OfferedWedges>,
        ),
    ) {
        let e = w.edge;
        let list = &mut self.lists[e.index()];
        let serial = &mut self.serials[e.index()];
        let mut next_serial = || {
            let s = *serial;
            *serial = s.wrapping_add(1);
            s
        };
        let Scratch { named, fresh, .. } = &mut self.scratch;
        named.clear();
        named.resize(end - first, false);
        fresh.clear();
        let zero = S::zero();
        let mine = w.distance_function();
        // Asked where it is used, not held in a variable: the closures below that captured it
        // saw a run-time flag, kept the branches for number types that keep values, and were
        // called out of line (8 % of the f64 engine's instructions on stanford_bunny).
        let keeps_values = keeps_values::<S>;
        // Which range ends of a wedge a piece keeps (asked only where anchors or a strip
        // depend on it).
        let anchored = |k: &Provenance<S>| {
            k.anchor(0).is_some() || k.anchor(1).is_some() || S::kept(&k.strip).is_some()
        };
        // `known`: where the pieces or the strips already say it (not compared then).
        let keeps = |[b0, b1]: [&S; 2], lo: &S, hi: &S, known: [Option<bool>; 2]| {
            [
                known[0].unwrap_or_else(|| b0.compare(lo) == Ordering::Equal),
                known[1].unwrap_or_else(|| b1.compare(hi) == Ordering::Equal),
            ]
        };
        // The strip of the new wedge or of an overlapped one, looked up only by number types
        // that keep values (for the others, not even the overlapped wedge is read).
        let strip_of = |owner: Owner| {
            keeps_values()
                .then(|| match owner.old_id() {
                    None => S::kept(&kept.strip),
                    Some(k) => S::kept(&list[first + k as usize].kept.strip),
                })
                .flatten()
        };
        let mut midpoint = None;
        for mut piece in pieces.drain(..) {
            // Kept only by number types that keep values: f64 builds none of it.
            let crossed = piece.cut.map(|other| {
                keeps_values().then(|| match other?.old_id() {
                    None => Some(mine.clone()),
                    Some(k) => Some(list[first + k as usize].wedge(e).distance_function()),
                })?
            });
            // The strips of the wedges whose crossings are the piece's ends.
            let partners = piece.cut.map(|other| strip_of(other?));
            // A crossing with the owner's mirror image across the edge's perpendicular
            // bisector is the edge's midpoint (see `strips.rs`): that one value, not a root
            // of eq. (2) equal to it.
            let owner = strip_of(piece.owner);
            for (i, partner) in partners.iter().enumerate() {
                if let (Some(owner), Some(partner)) = (&owner, partner) {
                    if owner.reflects(partner) {
                        let half = midpoint
                            .get_or_insert_with(|| length.clone() * S::from_f64(0.5))
                            .clone();
                        *if i == 0 { &mut piece.lo } else { &mut piece.hi } = half;
                    }
                }
            }
            let (lo, hi) = (&piece.lo, &piece.hi);
            // The owner is read only for a piece too short for the edge.
            let extent = S::has_extent(lo, hi, length)
                || match piece.owner.old_id() {
                    None => w.has_extent_on(lo, hi, length),
                    Some(k) => list[first + k as usize].has_extent_on(lo, hi, length),
                };
            if !extent {
                continue;
            }
            // The strips of the wedges whose own range ends are the piece's ends.
            let ended = piece.end_of.map(|end| {
                let (other, j) = end.filter(|(other, _)| *other != piece.owner)?;
                Some((strip_of(other)?, j))
            });
            // Whether each end of the piece is its owner's own range end: recorded by the
            // intersection, or another wedge's end that is one point with the owner's by
            // structure ([`one_end`]).
            let end_of_owner = |o: Owner, i: usize| match o.old_id() {
                None => range_end(w, kept, i),
                Some(k) => list[first + k as usize].range_end(i),
            };
            let own_end = [0, 1].map(|i| match piece.end_of[i] {
                Some((o, j)) if o == piece.owner && j == i => Some(true),
                Some((o, j))
                    if keeps_values()
                        && one_end(end_of_owner(piece.owner, i), end_of_owner(o, j)) =>
                {
                    Some(true)
                }
                _ => None,
            });
            // The keys of the piece's ends: a crossing's, or another wedge's end's.
            let mut named_ends = |piece_kept: Provenance<S>| match (
                strips.as_deref_mut(),
                S::kept(&piece_kept.strip),
            ) {
                (Some(strips), Some(mut strip)) => {
                    for i in 0..2 {
                        if let Some(partner) = &partners[i] {
                            strip = strips.crossed(&strip, i, partner, v0);
                        } else if let Some((other, j)) = &ended[i] {
                            strip = strip.ending_at(i, other, *j);
                        }
                    }
                    piece_kept.with_strip(Some(strip))
                }
                _ => piece_kept,
            };
            // A piece that ends at another wedge's end on a shadow line lies on that line.
            let lit_ends = |owner: &Wedge<S>, mut piece_kept: Provenance<S>| {
                if !keeps_values() {
                    return piece_kept;
                }
                let own = matches!(owner.pseudo_source, PseudoSource::Vertex(_))
                    .then(|| ([&owner.source_x, &owner.source_y], &owner.sigma));
                for i in 0..2 {
                    if let Some((other, j)) = piece.end_of[i].filter(|(o, _)| *o != piece.owner) {
                        piece_kept = piece_kept.ending_on(i, end_of_owner(other, j), own);
                    }
                }
                piece_kept
            };
            let (entry, event) = match piece.owner.old_id() {
                None => {
                    // The first vertex is reached at the scale of the offsets near it (a slack
                    // of ulps of the edge let a wedge claim it 2.6e-16 beyond its range, by a
                    // straight line shorter than the way round the range's end).
                    let near =
                        || S::max_of(&w.source_reach(), &S::max_of(&piece.lo, &-piece.lo.clone()));
                    if S::within(&zero, &piece.lo, &piece.hi, near) {
                        let d = S::kept(&kept.at_ends[0]).unwrap_or_else(|| mine.at(&zero));
                        arrivals.reach(v0, d, (w, kept));
                    }
                    if S::within(length, &piece.lo, &piece.hi, || w.reach(length)) {
                        let d = S::kept(&kept.at_ends[1]).unwrap_or_else(|| mine.at(length));
                        arrivals.reach(v1, d, (w, kept));
                    }
                    let piece_kept = if anchored(kept) {
                        kept.trimmed(keeps([&w.b0, &w.b1], &piece.lo, &piece.hi, own_end))
                    } else {
                        kept.clone()
                    }
                    .with_crossings(crossed);
                    let piece_kept = lit_ends(w, named_ends(piece_kept));
                    let mut wedge = w.clone();
                    wedge.b0 = piece.lo;
                    wedge.b1 = piece.hi;
                    stats.wedges_created += 1;
                    (Entry::new(wedge, piece_kept, next_serial()), true)
                }
                Some(k) => {
                    let k = k as usize;
                    let mut entry = list[first + k].clone();
                    let kept_ends = keeps([&entry.b0, &entry.b1], &piece.lo, &piece.hi, own_end);
                    if kept_ends != [true, true] {
                        let trimmed =
                            named_ends(entry.kept.trimmed(kept_ends).with_crossings(crossed));
                        entry.kept = lit_ends(&entry.wedge(e), trimmed);
                        entry.b0 = piece.lo;
                        entry.b1 = piece.hi;
                    }
                    let mut event = false;
                    if named[k] {
                        entry.serial = next_serial();
                        stats.wedges_created += 1;
                        event = entry.queued;
                    }
                    named[k] = true;
                    (entry, event)
                }
            };
            fresh.push((entry, event));
        }
        // Join waiting wedges that continue one another, among the pieces and with the
        // waiting wedges just before and after them.
        let joins = |a: &Entry<S>, b: &Entry<S>| a.queued && b.queued && a.continued_by(b, length);
        let mut start = first;
        if first > 0
            && fresh
                .first()
                .is_some_and(|(x, _)| joins(&list[first - 1], x))
        {
            fresh.insert(0, (list[first - 1].clone(), false));
            start -= 1;
        }
        let mut stop = end;
        if end < list.len() && fresh.last().is_some_and(|(x, _)| joins(x, &list[end])) {
            fresh.push((list[end].clone(), false));
            stop += 1;
        }
        // In place: each entry is joined to the last one kept if it continues it.
        fresh.dedup_by(|(entry, _), (last, event)| {
            let joined = joins(last, entry);
            if joined {
                last.join(entry);
                *event = true;
                stats.wedges_joined += 1;
            }
            joined
        });
        // A neighbour taken in but not joined to the chain (which keeps its first wedge's
        // function) needs no event, and stays as it was.
        if start < first && !fresh[0].1 {
            fresh.remove(0);
            start += 1;
        }
        if stop > end && !fresh.last().expect("a neighbour").1 {
            fresh.pop();
            stop -= 1;
        }
        for (i, (entry, event)) in fresh.iter().enumerate() {
            if *event {
                let at = WedgeRef {
                    edge: e,
                    serial: entry.serial,
                    place: (start + i) as u32,
                };
                arrivals.queue(at, entry);
            }
        }
        self.entries = self.entries + fresh.len() - (stop - start);
        // The stretch is overwritten in place as far as it goes, and the rest of the fresh
        // entries inserted after it, or the rest of the stretch removed. One or two entries
        // more (on the bunny 1.41 M of 1.64 M rebuilds; 3k add more) are inserted one by one,
        // each moving the list's tail once: `Vec::splice` cost more there.
        let (removed, added) = (stop - start, fresh.len());
        let common = removed.min(added);
        let mut fresh = fresh.drain(..).map(|(entry, _)| entry);
        for (old, new) in list[start..start + common].iter_mut().zip(fresh.by_ref()) {
            *old = new;
        }
        if added > removed {
            let needed = list.len() + added - removed;
            if needed > list.capacity() {
                // A run's memory is mostly these lists: they grow by a half, not double, and by
                // five wedges at least, so that short lists are not moved at every wedge (by a
                // quarter and three: 297k moves on the bunny, 2.3 % of its instructions; now
                // 1 % fewer instructions for 1 % more peak memory).
                let grown = (needed + needed / 2).max(needed + 5);
                list.reserve_exact(grown - list.len());
                self.longest = self.longest.max(grown);
            }
            let at = start + common;
            if added - removed <= 2 {
                for (at, new) in (at..).zip(fresh) {
                    list.insert(at, new);
                }
            } else {
                insert_many(list, at, fresh);
            }
        } else {
            list.drain(start + common..stop);
        }
        let bytes = self.entries * std::mem::size_of::<Entry<S>>()
            + self.lists.len()
                * (std::mem::size_of::<ThinVec<Entry<S>>>() + std::mem::size_of::<u32>());
        stats.peak_wedge_bytes = stats.peak_wedge_bytes.max(bytes);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{Side, SourceId};
    use crate::mmp::PseudoSource;

    /// Records the queue events and ignores the vertices reached.
    #[derive(Default)]
    struct Events(Vec<WedgeRef>);

    impl Arrivals<f64> for Events {
        fn queue(&mut self, at: WedgeRef, _wedge: &impl WedgeFields<f64>) {
            self.0.push(at);
        }
        fn reach(&mut self, _v: VertexId, _d: f64, _w: (&Wedge<f64>, &Provenance<f64>)) {}
    }

    /// A wedge on `[b0, b1]` of edge 0 (of length 1) from a pseudo-source above `x` at `sigma`.
    fn wedge([b0, b1]: [f64; 2], x: f64, sigma: f64) -> Wedge<f64> {
        Wedge {
            edge: EdgeId(0),
            b0,
            b1,
            source_x: x,
            source_y: 1.0,
            sigma,
            tau: Side::FIRST,
            pseudo_source: PseudoSource::Source(SourceId(0)),
            source: SourceId(0),
        }
    }

    /// Inserts `w` on its edge, of length 1 between vertices 0 and 1.
    fn insert(lists: &mut WedgeLists<f64>, w: Wedge<f64>, events: &mut Events) {
        let edge = (&1.0, [VertexId(0), VertexId(1)]);
        lists.insert(
            (w, Provenance::default()),
            edge,
            &mut Stats::default(),
            (events, None),
        );
    }

    /// An edge whose wedges leave a gap (in a run split into sectors, where the other
    /// sector's wedges won) is given up once the front is past them and past a known path to
    /// one of its ends continued along the whole edge; a covered edge once the front is past
    /// its wedges.
    #[test]
    fn edges_are_given_up_behind_the_front_with_a_gap_once_an_end_beats_later_wedges() {
        let mut lists = WedgeLists::<f64>::new(2, false, true);
        let mut events = Events::default();
        // Its farthest distance: sqrt(0.2^2 + 1) < 1.02, at both ends of [0, 0.4].
        insert(&mut lists, wedge([0.0, 0.4], 0.2, 0.0), &mut events);
        let mut covering = wedge([0.0, 1.0], 0.5, 0.0);
        covering.edge = EdgeId(1);
        insert(&mut lists, covering, &mut events);
        // Not before its wedge is propagated.
        assert!(!lists.close(EdgeId(0), 1.6, &1.0, || [Some(0.5), None]));
        for at in events.0.clone() {
            let due = lists.due(at, 1.0, &1.0, &mut Stats::default());
            assert!(matches!(due, Due::Now(..)));
        }
        assert!(!lists.close(EdgeId(0), 1.1, &1.0, || [None, None]));
        // The path to an end along the edge, 0.5 + 1, is not behind a front at 1.1.
        assert!(!lists.close(EdgeId(0), 1.1, &1.0, || [Some(0.5), None]));
        assert!(!lists.close(EdgeId(0), 1.6, &1.0, || [None, None]));
        assert!(lists.close(EdgeId(0), 1.6, &1.0, || [None, Some(0.5)]));
        // A wedge arriving later is dropped unseen.
        insert(&mut lists, wedge([0.5, 1.0], 0.8, 1.0), &mut events);
        assert!(lists.lists[0].is_empty());
        // A covered edge needs no known end: its farthest distance sqrt(0.5^2 + 1) < 1.12.
        assert!(!lists.close(EdgeId(1), 1.1, &1.0, || [None, None]));
        assert!(lists.close(EdgeId(1), 1.13, &1.0, || [None, None]));
    }

    /// A wedge trimmed after it was queued, so that its smallest distance rose, is due when
    /// its event comes up if the rise is within [`EARLY`] of the key, else queued again at its
    /// new smallest distance. The wedge from (0.5, 1) has its smallest distance 1 at its foot;
    /// a wedge from (0.7, 0.3) that meets it at `c` (its sigma chosen so) takes the range
    /// beyond `c`, leaving `[0, c]` with the smallest distance `sqrt((0.5 - c)^2 + 1)` at `c`.
    #[test]
    fn a_wedge_trimmed_by_less_than_the_slack_is_due_and_by_more_is_queued_again() {
        let at = |c: f64| {
            let mut lists = WedgeLists::<f64>::new(1, false, false);
            let mut events = Events::default();
            insert(&mut lists, wedge([0.0, 1.0], 0.5, 0.0), &mut events);
            let lowest = ((0.5 - c).powi(2) + 1.0).sqrt();
            let mut beyond = wedge([0.0, 1.0], 0.7, lowest - ((0.7 - c).powi(2) + 0.09).sqrt());
            beyond.source_y = 0.3;
            insert(&mut lists, beyond, &mut events);
            (
                lists.due(events.0[0], 1.0, &1.0, &mut Stats::default()),
                lowest,
            )
        };
        // A rise of 5e-5 of the key.
        match at(0.49) {
            (Due::Now(w, _), _) => assert!((w.b1 - 0.49).abs() < 1e-9, "{}", w.b1),
            _ => panic!("the wedge trimmed to [0, 0.49] is due"),
        }
        // A rise of 1.2e-3.
        match at(0.45) {
            (Due::Later(key), lowest) => assert!((key - lowest).abs() < 1e-12, "{key}"),
            _ => panic!("the wedge trimmed to [0, 0.45] waits"),
        }
    }

    #[test]
    fn an_entry_of_the_f64_engine_takes_64_bytes() {
        assert_eq!(std::mem::size_of::<Entry<f64>>(), 64);
    }

    #[test]
    fn an_event_finds_its_wedge_after_others_moved_it_and_is_stale_once_it_left() {
        let mut lists = WedgeLists::<f64>::new(1, false, false);
        let mut events = Events::default();
        insert(&mut lists, wedge([0.4, 0.6], 0.5, 0.0), &mut events);
        insert(&mut lists, wedge([0.6, 1.0], 0.8, 0.5), &mut events);
        // Two wedges before the first one move it two places to the right.
        insert(&mut lists, wedge([0.0, 0.2], 0.1, 0.0), &mut events);
        insert(&mut lists, wedge([0.2, 0.4], 0.3, 0.0), &mut events);
        // A wedge nearer than the second one everywhere takes its whole range.
        insert(&mut lists, wedge([0.6, 1.0], 0.8, 0.0), &mut events);
        let [first, second, ..] = events.0[..] else {
            panic!("five queue events, got {}", events.0.len());
        };
        match lists.due(first, 1.0, &1.0, &mut Stats::default()) {
            Due::Now(w, _) => assert_eq!([w.b0, w.b1], [0.4, 0.6]),
            _ => panic!("the first wedge is due"),
        }
        // Propagated once: its event is stale from then on, as is that of the wedge that left.
        assert!(matches!(
            lists.due(first, 1.0, &1.0, &mut Stats::default()),
            Due::Stale
        ));
        assert!(matches!(
            lists.due(second, 1.0, &1.0, &mut Stats::default()),
            Due::Stale
        ));
    }
}
