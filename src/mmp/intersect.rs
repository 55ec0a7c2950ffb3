//! Wedge intersection [LZT §4, SSK+05 §4.2]: a new wedge meets the wedges already on its edge.
//!
//! On the range it shares with an existing wedge, eq. (2) gives the points where the two
//! distance functions cross (none, one, two or infinitely many: Property 1). Between consecutive
//! crossings one wedge is better throughout; each piece goes to the better one, and a tie keeps
//! the existing wedge (Section 4, step 2.3.2). The result covers the union of the ranges with
//! non-overlapping wedges (Property 2), splitting an existing wedge in two where the new one
//! wins only in its middle (Fig. 8c, Fig. 10).
//!
//! Pure functions on wedges: they cut the edge into pieces and name each piece's owner; the
//! engine's edge lists ([`wedge_lists`](super::wedge_lists)) store the pieces as wedges.

use super::paths::{CongruentPaths, Path};
use super::planar::Planar;
use super::provenance::{compare_ends, keeps_values, range_end, Anchor, Provenance, RangeEnd};
use super::stats::{Eq2Counts, Eq2Decision};
use super::wedge::{PseudoSource, Wedge, WedgeFields};
use crate::mesh::TriMesh;
use crate::scalar::{BisectorRoots, Eq2Case, Eq2Coefficients, Lower, Scalar, SourceDistance};
use std::cmp::Ordering;

/// Who owns a piece of the edge after an intersection: the arriving wedge
/// ([`Owner::NEW`]), or the existing wedge of an id ([`Owner::old`]). One number, so that
/// owners compare in one instruction (a two-variant enum, its variant compared first, cost
/// 4 % of a run's instructions on stanford_bunny).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Owner(u32);

impl Owner {
    /// The arriving wedge.
    pub(crate) const NEW: Owner = Owner(u32::MAX);

    /// The existing wedge `id` (its place among the overlapped wedges, below `u32::MAX`).
    #[inline(always)]
    pub(crate) fn old(id: u32) -> Owner {
        debug_assert!(id != u32::MAX, "an overlapped wedge's place");
        Owner(id)
    }

    /// The id of the existing wedge, `None` for the arriving one.
    #[inline(always)]
    pub(crate) fn old_id(self) -> Option<u32> {
        (self != Owner::NEW).then_some(self.0)
    }
}

/// A stretch `[lo, hi]` of the edge and the wedge that owns it.
pub(crate) struct Piece<S> {
    pub(crate) lo: S,
    pub(crate) hi: S,
    pub(crate) owner: Owner,
    /// For each end, the wedge whose crossing with the owner (a root of eq. (1)) it is: the
    /// two distance functions are equal there.
    pub(crate) cut: [Option<Owner>; 2],
    /// For each end, the wedge whose own range end it is, and which (0: `b0`, 1: `b1`).
    pub(crate) end_of: [Option<EndOf>; 2],
}

/// A wedge's own range end: the wedge, and `0` for its `b0` or `1` for its `b1`.
pub(crate) type EndOf = (Owner, usize);

fn push_piece<S: Scalar>(
    pieces: &mut Vec<Piece<S>>,
    [lo, hi]: [S; 2],
    owner: Owner,
    end_of: [Option<EndOf>; 2],
) {
    push_cut_piece(pieces, [lo, hi], owner, [None, None], end_of);
}

fn push_cut_piece<S: Scalar>(
    pieces: &mut Vec<Piece<S>>,
    [lo, hi]: [S; 2],
    owner: Owner,
    cut: [Option<Owner>; 2],
    end_of: [Option<EndOf>; 2],
) {
    if let Some(last) = pieces.last_mut() {
        if last.owner == owner {
            last.hi = hi;
            last.cut[1] = cut[1];
            last.end_of[1] = end_of[1];
            return;
        }
    }
    let piece = Piece {
        lo,
        hi,
        owner,
        cut,
        end_of,
    };
    pieces.push(piece);
}

/// The lower (or the higher) of a wedge's distances at the two ends of a range, as the bounds
/// below ask for it: one end where the backend proves their order, else both, not asked which
/// (the ends of a range mirrored about the foot tie by a symmetry of the mesh, and no normal
/// form may prove it). A bound that holds at the lower end (at least a value, below a value;
/// or, at the higher end, at most a value) holds at both.
fn end_values<'a, S: Scalar>(at_lo: &'a S, at_hi: &'a S, lower: bool) -> ([&'a S; 2], usize) {
    let other_end = if lower {
        Ordering::Greater
    } else {
        Ordering::Less
    };
    match S::proved_order(at_lo, at_hi) {
        Some(order) if order == other_end => ([at_hi, at_hi], 1),
        Some(_) => ([at_lo, at_lo], 1),
        None => ([at_lo, at_hi], 2),
    }
}

/// Where a distance function is lowest on `[lo, hi]`: it is convex, so at the foot of the
/// pseudo-source if inside (or `sigma + y` below it where the backend leaves open on which
/// side of an end the foot lies, [`Scalar::foot_within`]: the callers use it as a bound, which
/// a lower one keeps), else at the lower end ([`end_values`]).
enum Lowest<'a, S> {
    Foot(S),
    Ends([&'a S; 2], usize),
}

impl<'a, S: Scalar> Lowest<'a, S> {
    fn on(d: &SourceDistance<S>, lo: &S, hi: &S, [at_lo, at_hi]: [&'a S; 2]) -> Self {
        if S::foot_within(&d.x, lo, hi, false) {
            Lowest::Foot(d.y.clone() + &d.sigma)
        } else {
            let (ends, n) = end_values(at_lo, at_hi, true);
            Lowest::Ends(ends, n)
        }
    }

    /// Whether `holds` holds at the lowest value (at each candidate for it).
    fn all(&self, holds: impl Fn(&S) -> bool) -> bool {
        match self {
            Lowest::Foot(d) => holds(d),
            Lowest::Ends(ends, n) => ends[..*n].iter().all(|d| holds(d)),
        }
    }
}

/// Splits the range `[lo, hi]` shared by an existing wedge (`theirs`) and the new one
/// (`mine`) into pieces, each owned by the better wedge [LZT §4]. Coincident distance
/// functions keep the existing wedge (step 2.3.2). When one wedge is better at every point of
/// the range by the bounds of convexity, eq. (2) has no root there and is not solved;
/// otherwise the backend's one decision ([`Scalar::bisector`]) gives the roots that cut the
/// range and which wedge is lower on each piece (a tie keeps the existing wedge). The engine
/// asks nothing again at a constructed point: the roots' positions are constructions (a
/// near-double root rounded from eq. (2)'s coefficients moves far, 1.3 units on an edge of
/// 1e8 in a mixed-magnitude mesh), and a piece's middle, far along a long range, is where two
/// distances that differ throughout look like a tie.
/// `known[0]` (`[1]`) holds both distances at `lo` (`hi`) where a wedge keeps its distance
/// there ([`Provenance`]: at a vertex of the edge, or at a range end on a shadow line): those,
/// not values derived again, are the backend's there, so that a tie the engine built is seen as
/// one.
/// `lower`: the wedge known to be lower on the whole range ([`lower_by_anchor`]).
/// Returns the case and whether eq. (2) was solved.
fn split_shared_range<S: Scalar>(
    pieces: &mut Vec<Piece<S>>,
    theirs: &SourceDistance<S>,
    mine: &SourceDistance<S>,
    ([lo, hi], end_of): ([S; 2], [Option<EndOf>; 2]),
    (known, lower, seen): (
        [Option<[S; 2]>; 2],
        Option<Owner>,
        impl FnOnce() -> Option<bool>,
    ),
    id: u32,
) -> (Eq2Case, bool) {
    if let Some(owner) = lower {
        push_piece(pieces, [lo, hi], owner, end_of);
        return (Eq2Case::None, false);
    }
    if S::same_distance_function(theirs, mine, &(hi.clone() - &lo)) {
        push_piece(pieces, [lo, hi], Owner::old(id), end_of);
        return (Eq2Case::Infinite, true);
    }
    let [[their_lo, my_lo], [their_hi, my_hi]] = [(&lo, 0), (&hi, 1)].map(|(at, i)| {
        known[i]
            .clone()
            .unwrap_or_else(|| [theirs.at(at), mine.at(at)])
    });
    // One wedge's lowest value against the other's highest end value (at each candidate for
    // them, see `end_values`).
    let (their_max, n) = end_values(&their_lo, &their_hi, false);
    let my_lowest = Lowest::on(mine, &lo, &hi, [&my_lo, &my_hi]);
    if my_lowest.all(|m| {
        their_max[..n]
            .iter()
            .all(|t| m.compare_distance(t) != Ordering::Less)
    }) {
        push_piece(pieces, [lo, hi], Owner::old(id), end_of);
        return (Eq2Case::None, false);
    }
    let (my_max, n) = end_values(&my_lo, &my_hi, false);
    let their_lowest = Lowest::on(theirs, &lo, &hi, [&their_lo, &their_hi]);
    if my_max[..n]
        .iter()
        .all(|m| their_lowest.all(|t| m.compare_distance(t) == Ordering::Less))
    {
        push_piece(pieces, [lo, hi], Owner::NEW, end_of);
        return (Eq2Case::None, false);
    }
    let bisector = match seen() {
        Some(opposite) => S::bisector_seen_straight(theirs, mine, &lo, &hi, &known, opposite),
        None => S::bisector(theirs, mine, &lo, &hi, &known),
    };
    if matches!(bisector.roots, BisectorRoots::Infinite) {
        push_piece(pieces, [lo, hi], Owner::old(id), end_of);
        return (Eq2Case::Infinite, true);
    }
    // The owner of each stretch is the backend's answer; a tie keeps the existing wedge. The
    // case counted is what the pieces show: how often the owner changes in the range (a
    // crossing whose two sides both went to one wedge, on a tie, is no crossing), and a
    // touching root, which is one solution of eq. (1) where the owner does not change.
    let touching = matches!(bisector.roots, BisectorRoots::Touch(_));
    let mut changes = 0;
    let mut previous = None;
    let mut start = lo;
    for (end, lower) in bisector.stretches() {
        let (owner, other) = match lower {
            Lower::Second => (Owner::NEW, Owner::old(id)),
            Lower::First | Lower::Neither => (Owner::old(id), Owner::NEW),
        };
        changes += usize::from(previous.is_some_and(|p| p != owner));
        let cut = [
            previous.is_some().then_some(other),
            end.is_some().then_some(other),
        ];
        let ends_of = [
            if previous.is_none() { end_of[0] } else { None },
            if end.is_none() { end_of[1] } else { None },
        ];
        previous = Some(owner);
        let end = end.unwrap_or_else(|| hi.clone());
        push_cut_piece(pieces, [start, end.clone()], owner, cut, ends_of);
        start = end;
    }
    let case = match changes {
        0 if touching => Eq2Case::One,
        0 => Eq2Case::None,
        1 => Eq2Case::One,
        _ => Eq2Case::Two,
    };
    (case, true)
}

/// Which of two wedges is lower on all the range they share, when one of them has a range end
/// anchored at the other's pseudo-source vertex, or keeps its distance at a vertex of the edge
/// that is the other's pseudo-source, with the other's image and distance there: the first
/// passes that vertex on a straight line, so by the triangle inequality it is nowhere higher
/// than the vertex's own wedge, which it touches on the shadow line or at the vertex
/// ([`Provenance`]). Asked only of pseudo-source wedges against wedges that keep values.
fn lower_by_anchor<S: Scalar>(
    (old, old_kept, id): (&impl WedgeFields<S>, &Provenance<S>, u32),
    (new, new_kept): (&Wedge<S>, &Provenance<S>),
    vertices: &[S; 2],
) -> Option<Owner> {
    // Number types that keep no values keep neither anchors nor distances at vertices: the
    // pairs of empty anchors below were still built and dropped, out of line, for every
    // overlapped wedge (18.5 % of the f64 engine's instructions on stanford_bunny).
    if !keeps_values::<S>() {
        return None;
    }
    // A wedge's pseudo-source, its image and its distance.
    type Source<'a, S> = (PseudoSource, [&'a S; 3]);
    let old_source = (
        old.pseudo_source(),
        [old.source_x(), old.source_y(), old.sigma()],
    );
    let new_source = (
        new.pseudo_source,
        [&new.source_x, &new.source_y, &new.sigma],
    );
    let is_source_of = |a: &Anchor<S>, (pseudo_source, [x, y, sigma]): Source<'_, S>| {
        matches!(pseudo_source, PseudoSource::Vertex(_))
            && x.compare(&a.point.x) == Ordering::Equal
            && y.compare(&a.point.y) == Ordering::Equal
            && sigma.compare_distance(&a.distance) == Ordering::Equal
    };
    let at_vertex = |kept: &Provenance<S>, i: usize| {
        S::kept(&kept.at_ends[i]).map(|distance| Anchor {
            point: Planar {
                x: vertices[i].clone(),
                y: S::zero(),
            },
            distance,
            image: None,
            light: None,
        })
    };
    let anchored_below = |kept: &Provenance<S>, other: Source<'_, S>| {
        (0..2).any(|i| {
            [kept.anchor(i), at_vertex(kept, i)]
                .into_iter()
                .flatten()
                .any(|a| is_source_of(&a, other))
        })
    };
    if anchored_below(old_kept, new_source) {
        Some(Owner::old(id))
    } else if anchored_below(new_kept, old_source) {
        Some(Owner::NEW)
    } else {
        None
    }
}

/// Where one of two wedges on an edge is the wedge of a vertex that the other's image saw
/// straight ([`seen_straight_from`](super::paths::Path::seen_straight_from), the lineage's
/// paths compared by [`CongruentPaths::same_image`]): whether the two images lie on opposite
/// sides of the edge's line. Asked only of number types that keep paths.
fn seen_straight<S: Scalar>(
    congruence: Option<(&TriMesh, &CongruentPaths<S>)>,
    a: &Provenance<S>,
    b: &Provenance<S>,
) -> Option<bool> {
    if !keeps_values::<S>() {
        return None;
    }
    let ((mesh, paths), a, b) = (congruence?, S::kept(&a.path)?, S::kept(&b.path)?);
    let same = |p: &Path, q: &Path| paths.same_image(mesh, p, q);
    a.seen_straight_from(mesh, &b, same)
        .or_else(|| b.seen_straight_from(mesh, &a, same))
}

/// The distance at range end `end` (`i`: 0 for the shared range's `lo`, 1 for its `hi`) where
/// it is the crossing of the wedge that owns it with a wedge of the other one's distance
/// function: a tie known by structure, which eq. (2) would meet as a root exactly at the end.
fn crossed_at<S: Scalar>(
    end: &S,
    i: usize,
    owns: &[bool; 2],
    kept: [&Provenance<S>; 2],
    functions: [&SourceDistance<S>; 2],
) -> Option<S> {
    (0..2).find_map(|k| {
        let crossed = owns[k].then(|| kept[k].crossing(i)).flatten()?;
        S::proved_same_distance_function(&crossed, functions[1 - k]).then(|| crossed.at(end))
    })
}

/// Both distances at each end of the shared range `ends` (`[lo, hi]`) where either wedge keeps
/// its own there: at a vertex of the edge, or at its range end on a shadow line (the other
/// wedge's is derived there), or where the end is a crossing kept by its owner. `owns`: whose
/// own range end each end is, `[end][old, new]`; `kept` and `functions` are the existing
/// wedge's and the new one's.
fn known_at_ends<S: Scalar>(
    ends: [&S; 2],
    owns: &[[bool; 2]; 2],
    kept: [&Provenance<S>; 2],
    [theirs, mine]: [&SourceDistance<S>; 2],
    vertices: &[S; 2],
) -> [Option<[S; 2]>; 2] {
    // Number types that keep no values keep none of them (the pairs below, mapped out of
    // line, cost them 4.5 % of the f64 engine's instructions on stanford_bunny).
    if !keeps_values::<S>() {
        return [None, None];
    }
    let [lo, hi] = ends;
    let mut known = [(lo, 0), (hi, 1)].map(|(end, i)| {
        let mut values = kept.map(|k| S::kept(&k.at_ends[i]));
        if values.iter().all(Option::is_none) || end.compare(&vertices[i]) != Ordering::Equal {
            values = [0, 1].map(|k| {
                let anchor = owns[i][k].then(|| kept[k].anchor(i)).flatten();
                anchor.map(|a| a.distance_function().at(end))
            });
        }
        if values.iter().all(Option::is_none) {
            return crossed_at(end, i, &owns[i], kept, [theirs, mine]).map(|d| [d.clone(), d]);
        }
        let [t, m] = values;
        Some([
            t.unwrap_or_else(|| theirs.at(end)),
            m.unwrap_or_else(|| mine.at(end)),
        ])
    });
    // A wedge whose range is its own mirror image across the edge's bisector has one
    // distance at its two ends (see `strips.rs`): one expression for both.
    let mirrored = |k: &Provenance<S>| S::kept(&k.strip).is_some_and(|s| s.has_mirrored_ends());
    for (k, kept) in kept.into_iter().enumerate() {
        if owns[0][k] && owns[1][k] && mirrored(kept) {
            let function = [theirs, mine][k];
            let at_lo = known[0]
                .as_ref()
                .map_or_else(|| function.at(lo), |d| d[k].clone());
            let mut at_hi = known[1]
                .clone()
                .unwrap_or_else(|| [theirs.at(hi), mine.at(hi)]);
            at_hi[k] = at_lo;
            known[1] = Some(at_hi);
        }
    }
    known
}

/// The order of the cursor against a range end: by structure where the cursor is a wedge's own
/// range end (`at`), else by the values.
fn cursor_order<S: Scalar>(
    cursor: &S,
    at: Option<RangeEnd<'_, S>>,
    end: RangeEnd<'_, S>,
) -> Ordering {
    match at {
        Some(at) => compare_ends(at, end),
        None => cursor.compare(end.0),
    }
}

/// Cuts the union of the new wedge's range and the ranges of the wedges it overlaps (sorted,
/// disjoint, each with an id and what it keeps of its construction) into pieces, each owned by
/// the better wedge there.
pub(crate) fn cut_into_pieces<'a, S: Scalar, W: WedgeFields<S> + 'a>(
    counts: &mut Eq2Counts,
    mut log: Option<&mut Vec<Eq2Decision>>,
    pieces: &mut Vec<Piece<S>>,
    overlapping: impl Iterator<Item = (u32, &'a W, &'a Provenance<S>)>,
    (w, my_kept): (&Wedge<S>, &Provenance<S>),
    (length, congruence): (&S, Option<(&TriMesh, &CongruentPaths<S>)>),
) {
    let mine = w.distance_function();
    let mut cursor = w.b0.clone();
    let mut cursor_of = Some((Owner::NEW, 0));
    // The range end of a wedge that the cursor is, if it is one.
    let mut cursor_end = Some(range_end(w, my_kept, 0));
    let vertices = [S::zero(), length.clone()];
    for (id, old, old_kept) in overlapping {
        let old_image = [old.source_x(), old.source_y()];
        let (c0, c1) = (
            compare_ends((old.b0(), old_kept, 0, old_image), range_end(w, my_kept, 0)),
            compare_ends((old.b1(), old_kept, 1, old_image), range_end(w, my_kept, 1)),
        );
        let old_b0 = (old.b0(), old_kept, 0, old_image);
        if cursor_order(&cursor, cursor_end, old_b0) == Ordering::Less {
            let range = [cursor.clone(), old.b0().clone()];
            push_piece(
                pieces,
                range,
                Owner::NEW,
                [cursor_of, Some((Owner::old(id), 0))],
            );
        }
        if c0 == Ordering::Less {
            let range = [old.b0().clone(), w.b0.clone()];
            let end_of = [Some((Owner::old(id), 0)), Some((Owner::NEW, 0))];
            push_piece(pieces, range, Owner::old(id), end_of);
        }
        let lo = if c0 == Ordering::Less {
            &w.b0
        } else {
            old.b0()
        }
        .clone();
        let hi = if c1 == Ordering::Greater {
            &w.b1
        } else {
            old.b1()
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
        let kept = [old_kept, my_kept];
        let known = known_at_ends([&lo, &hi], &owns, kept, [&theirs, &mine], &vertices);
        let lower = lower_by_anchor((old, old_kept, id), (w, my_kept), &vertices);
        let seen = || seen_straight(congruence, old_kept, my_kept);
        // Whose own range end `lo` and `hi` are, the existing wedge's first.
        let end_of = [0, 1].map(|i| {
            let [old_owns, new_owns] = owns[i];
            (old_owns.then_some((Owner::old(id), i))).or(new_owns.then_some((Owner::NEW, i)))
        });
        let range = ([lo, hi.clone()], end_of);
        let structure = (known, lower, seen);
        let (case, solved) = split_shared_range(pieces, &theirs, &mine, range, structure, id);
        counts.count(case);
        if let (Some(log), Some((range, coefficients))) = (log.as_deref_mut(), record) {
            log.push(Eq2Decision {
                edge: w.edge.0,
                existing: old.pseudo_source(),
                arriving: w.pseudo_source,
                range,
                case,
                solved,
                coefficients,
            });
        }
        if c1 == Ordering::Greater {
            let range = [w.b1.clone(), old.b1().clone()];
            let end_of = [Some((Owner::NEW, 1)), Some((Owner::old(id), 1))];
            push_piece(pieces, range, Owner::old(id), end_of);
        }
        cursor_of = end_of[1];
        cursor_end = if owns[1][0] {
            Some((old.b1(), old_kept, 1, old_image))
        } else {
            owns[1][1].then_some(range_end(w, my_kept, 1))
        };
        cursor = hi;
    }
    let my_b1 = range_end(w, my_kept, 1);
    if cursor_order(&cursor, cursor_end, my_b1) == Ordering::Less {
        let end_of = [cursor_of, Some((Owner::NEW, 1))];
        push_piece(pieces, [cursor, w.b1.clone()], Owner::NEW, end_of);
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
    if !arriving.has_extent_on(&arriving.b0, &arriving.b1, edge_length) {
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
        (edge_length, None),
    );
    let first = existing.iter().position(overlaps).unwrap_or(existing.len());
    let mut result: Vec<Wedge<S>> = existing[..first].to_vec();
    for piece in pieces {
        let mut wedge = match piece.owner.old_id() {
            None => arriving.clone(),
            Some(i) => existing[i as usize].clone(),
        };
        if !wedge.has_extent_on(&piece.lo, &piece.hi, edge_length) {
            continue;
        }
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
