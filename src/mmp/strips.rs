//! Wedges offered again: one wedge per strip shape from a pseudo-source.
//!
//! A wedge is a pseudo-source's image seen through a chain of faces [SSK+05 §4.1]. Its image in
//! the edge's frame is fixed by the shape of that chain, its *strip*: the classes of its
//! triangles' sides by exact squared length, and how they are glued. So is each end of its
//! range that the strips can name ([`EndKey`]): a vertex of the edge; the ray through a named
//! end of the edge before, carried along the strip; or the crossing of its distance function
//! with another wedge's (a root of eq. (1), fixed by the two strips and by which of the two is
//! lower past it). On a mesh with exact symmetries, a wedge and its mirror image (from the
//! other side of an edge in the mirror plane), or the same wedge brought again by a congruent
//! chain, reach an edge with values built by other constructions, which an exact backend would
//! have to prove equal: zeros that no normal form reaches. Offering a wedge's distance function
//! on its range again cannot change an edge: each point keeps a wedge at least as low as the
//! first copy there (a tie keeps the existing wedge, Section 4 step 2.3.2). So a copy is known
//! by its strip's description and its ends' keys, and dropped, not intersected.
//!
//! [`OfferedWedges`] describes strips and range ends incrementally (interned, so that a wedge
//! keeps a few numbers, not a list of faces), in two readings: the first face's far corners
//! named either way round, the strip and its mirror image. Kept only by number types that keep
//! values, on the meshes where [`CongruentPaths`] describes strips (a chain of faces fixes its
//! strip there).

use super::paths::{CongruentPaths, Path};
use crate::mesh::{EdgeId, FaceId, SourceId, TriMesh, VertexId};
use crate::scalar::Scalar;
use std::collections::{HashMap, HashSet};

/// The strip a wedge is seen through, in both readings: the interned description from the
/// pseudo-source up to the wedge's edge, the edge's ends as it names them (`a` first), and
/// the keys of the range's ends (`b0`, `b1`), where the strips know them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Strip {
    ids: [u32; 2],
    a: [VertexId; 2],
    b: [VertexId; 2],
    ends: [Option<[u32; 2]>; 2],
}

impl Strip {
    /// The same strip with the range ends that `keep` says are still the wedge's own; a
    /// trimmed end (another wedge's end, or a crossing not yet named) is unknown.
    pub(crate) fn trimmed(mut self, keep: [bool; 2]) -> Strip {
        for (end, keep) in self.ends.iter_mut().zip(keep) {
            if !keep {
                *end = None;
            }
        }
        self
    }

    /// The same strip with its range end `i`, if not named, at range end `j` of the wedge
    /// seen through `other` on the same edge: that end's keys, read from the same ends of the
    /// edge.
    pub(crate) fn ending_at(mut self, i: usize, other: &Strip, j: usize) -> Strip {
        if self.ends[i].is_some() {
            return self;
        }
        self.ends[i] = other.ends[j].and_then(|keys| {
            let reading = |r: usize| (0..2).find(|&q| other.a[q] == self.a[r]);
            Some([keys[reading(0)?], keys[reading(1)?]])
        });
        self
    }

    /// The strip of a wedge joined from this strip's wedge and `next`'s (after it along the
    /// edge): one image, proved so, seen through two chains of faces. Either chain's shape
    /// fixes that image, so either describes the joined wedge; the one of the least
    /// description does, so that a mirror image or congruent copy of the joined wedge, joined
    /// from the corresponding pieces, is described alike. Its range ends keep their keys:
    /// `b0` this strip's, `b1` `next`'s.
    pub(crate) fn joined(&self, next: &Strip) -> Strip {
        let least = |s: &Strip| {
            let mut ids = s.ids;
            ids.sort_unstable();
            ids
        };
        let mut joined = if least(next) < least(self) {
            *next
        } else {
            *self
        };
        joined.ends = [None; 2];
        joined.ending_at(0, self, 0).ending_at(1, next, 1)
    }

    /// Whether range end `i` of this strip's wedge and range end `j` of `other`'s, on the same
    /// edge, are one point: both named, with equal keys read from the same end of the edge.
    pub(crate) fn same_end(&self, i: usize, other: &Strip, j: usize) -> bool {
        let (Some(mine), Some(theirs)) = (self.ends[i], other.ends[j]) else {
            return false;
        };
        (0..2).any(|r| (0..2).any(|q| self.a[r] == other.a[q] && mine[r] == theirs[q]))
    }

    /// Whether the strip is its own mirror image across the perpendicular bisector of its
    /// edge (read from either end of the edge, one shape): its image lies on the bisector.
    pub(crate) fn is_symmetric(&self) -> bool {
        self.ids[0] == self.ids[1]
    }

    /// Whether `other` is this strip's mirror image across the perpendicular bisector of the
    /// edge (each, read from one end, is the other read from the other end): two distance
    /// functions `sigma + |s - t|` with mirrored images and one `sigma` cross at the edge's
    /// midpoint only.
    pub(crate) fn reflects(&self, other: &Strip) -> bool {
        !self.is_symmetric()
            && (0..2)
                .all(|r| (0..2).any(|q| other.a[q] == self.a[r] && other.ids[q] == self.ids[1 - r]))
    }

    /// Whether the wedge's range is its own mirror image across the edge's perpendicular
    /// bisector, as the strip is: each range end, named from its own end of the edge, is the
    /// other. Its distance function is then one value at its two ends.
    pub(crate) fn has_mirrored_ends(&self) -> bool {
        self.is_symmetric()
            && match self.ends {
                [Some(b0), Some(b1)] => b0[0] == b1[1] && b0[1] == b1[0],
                _ => false,
            }
    }

    /// The same strip with its range ends swapped (the wedge laid out the other way).
    pub(crate) fn swapped(mut self) -> Strip {
        self.ends.swap(0, 1);
        self
    }
}

/// How a child's range end follows from its parent's, across a face (see
/// [`OfferedWedges::across`]).
#[derive(Clone, Copy, Debug)]
pub(crate) enum Through {
    /// A corner of the face, an end of the child's edge.
    Corner(VertexId),
    /// The ray from the pseudo-source's image through the parent's range end of that index.
    Ray(usize),
}

/// What a range end is, in one reading of its strip: the keys of equal points are equal.
/// A point of an edge so described is fixed by the shapes of the strips named, so two wedges
/// whose ends have one key have them at one place of their edge.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum EndKey {
    /// An end of the edge of strip `strip`: its `a` or its `b`.
    Corner { strip: u32, is_a: bool },
    /// The ray from the image through the point `origin` of the edge before, carried across
    /// the last face of strip `strip`.
    Carried { strip: u32, origin: u32 },
    /// The crossing of the distance functions seen through strips `low` and `high` (`low <
    /// high`, both read from the same end `a` of the edge): a root of eq. (1) past which,
    /// going from `a` to `b`, `low`'s wedge is the lower one (`low_beyond`) or `high`'s. The
    /// two functions differ in sign on either side of a simple root, so this names one root.
    Crossing {
        low: u32,
        high: u32,
        low_beyond: bool,
    },
}

/// The strips met in one run, and the wedges offered through them.
#[derive(Default)]
pub(crate) struct OfferedWedges {
    /// Interned descriptions: a strip's id from the id of the strip one face shorter (or
    /// [`FIRST_FACE`]) and the next face's description.
    strips: HashMap<(u32, [u32; 4]), u32>,
    /// Interned keys of the paths to pseudo-sources (see `paths.rs`).
    paths: HashMap<Vec<u32>, u32>,
    /// Interned keys of range ends.
    ends: HashMap<EndKey, u32>,
    /// The wedges offered: source, pseudo-source vertex, edge, strip and the keys of its range
    /// ends (in the least of the two readings), and whether the edge's frame starts at that
    /// reading's `a`.
    offered: HashSet<(SourceId, VertexId, EdgeId, [u32; 3], bool)>,
}

/// Marks a strip's first face, whose description follows the path to the pseudo-source.
const FIRST_FACE: u32 = u32::MAX;

/// Marks the strip of a wedge along an edge from one of its ends, the pseudo-source.
const ALONG: u32 = u32::MAX - 1;

impl OfferedWedges {
    fn intern(&mut self, before: u32, description: [u32; 4]) -> u32 {
        let next = self.strips.len() as u32;
        *self.strips.entry((before, description)).or_insert(next)
    }

    fn intern_end(&mut self, key: EndKey) -> u32 {
        let next = self.ends.len() as u32;
        *self.ends.entry(key).or_insert(next)
    }

    /// The strip of the wedge that pseudo-source `p`, reached along `path`, sends across face
    /// `f` to its opposite edge (whose frame runs from `first`), the range's ends its corners.
    pub(crate) fn first<S: Scalar>(
        &mut self,
        paths: &CongruentPaths<S>,
        mesh: &TriMesh,
        (p, path): (VertexId, &Path),
        (f, first): (FaceId, VertexId),
    ) -> Option<Strip> {
        let path = self.path_id(paths, mesh, path)?;
        let corners = mesh.face(f);
        let at = corners.iter().position(|&c| c == p)?;
        let (next, previous) = (corners[(at + 1) % 3], corners[(at + 2) % 3]);
        let mut read = |a: VertexId, b: VertexId| -> Option<u32> {
            let sides = [
                paths.class(mesh, p, a)?,
                paths.class(mesh, p, b)?,
                paths.class(mesh, a, b)?,
            ];
            Some(self.intern(FIRST_FACE, [path, sides[0], sides[1], sides[2]]))
        };
        let ids = [read(next, previous)?, read(previous, next)?];
        Some(self.spanning(ids, [next, previous], first))
    }

    /// The strip of the wedge that pseudo-source `p`, reached along `path`, sends along its
    /// edge `g` (whose frame runs from `first`): no face, the image at the edge's end `p`.
    pub(crate) fn along<S: Scalar>(
        &mut self,
        paths: &CongruentPaths<S>,
        mesh: &TriMesh,
        (p, path): (VertexId, &Path),
        (g, first): (EdgeId, VertexId),
    ) -> Option<Strip> {
        let path = self.path_id(paths, mesh, path)?;
        let [u, v] = mesh.edge(g).vertices;
        let other = if u == p { v } else { u };
        let side = paths.class(mesh, p, other)?;
        // Read from `p`, the image is at `a`; from the other end, at `b`.
        let ids = [0, 1].map(|at_b| self.intern(ALONG, [path, side, at_b, 0]));
        Some(self.spanning(ids, [p, other], first))
    }

    /// The strip of ids `ids` read from `a` and from `b`, over its whole edge (whose frame runs
    /// from `first`): the range's ends are the edge's.
    fn spanning(&mut self, ids: [u32; 2], [a, b]: [VertexId; 2], first: VertexId) -> Strip {
        let mut strip = Strip {
            ids,
            a: [a, b],
            b: [b, a],
            ends: [None; 2],
        };
        let last = if first == a { b } else { a };
        strip.ends = [first, last].map(|v| Some(self.corner(&strip, v)));
        strip
    }

    /// The interned key of the path to a pseudo-source (see `paths.rs`).
    fn path_id<S: Scalar>(
        &mut self,
        paths: &CongruentPaths<S>,
        mesh: &TriMesh,
        path: &Path,
    ) -> Option<u32> {
        let key = paths.key(mesh, path)?;
        let next = self.paths.len() as u32;
        Some(*self.paths.entry(key).or_insert(next))
    }

    /// The keys, in each reading, of the strip's edge's end `v`.
    fn corner(&mut self, strip: &Strip, v: VertexId) -> [u32; 2] {
        [0, 1].map(|r| {
            self.intern_end(EndKey::Corner {
                strip: strip.ids[r],
                is_a: v == strip.a[r],
            })
        })
    }

    /// The strip continued across `face` (beyond the strip's edge) to its edge `to`, with the
    /// child's range ends (`b0`, `b1` in the order the child is laid out) following from the
    /// parent's as `through` says.
    pub(crate) fn across<S: Scalar>(
        &mut self,
        paths: &CongruentPaths<S>,
        mesh: &TriMesh,
        strip: &Strip,
        (face, to): (FaceId, EdgeId),
        through: [Through; 2],
    ) -> Option<Strip> {
        let mut next = *strip;
        for reading in 0..2 {
            let (a, b) = (strip.a[reading], strip.b[reading]);
            let apex = *mesh.face(face).iter().find(|&&c| c != a && c != b)?;
            let sides = [paths.class(mesh, a, apex)?, paths.class(mesh, b, apex)?];
            let ends = mesh.edge(to).vertices;
            let (exit, labels) = if ends.contains(&a) && ends.contains(&apex) {
                (0, (a, apex))
            } else if ends.contains(&apex) && ends.contains(&b) {
                (1, (apex, b))
            } else {
                return None;
            };
            next.ids[reading] = self.intern(strip.ids[reading], [sides[0], sides[1], exit, 0]);
            (next.a[reading], next.b[reading]) = labels;
        }
        next.ends = through.map(|t| match t {
            Through::Corner(v) => Some(self.corner(&next, v)),
            Through::Ray(i) => strip.ends[i].map(|origin| {
                [0, 1].map(|r| {
                    self.intern_end(EndKey::Carried {
                        strip: next.ids[r],
                        origin: origin[r],
                    })
                })
            }),
        });
        Some(next)
    }

    /// The strip with its range end `i` at the crossing with the wedge seen through `other`
    /// (a root of eq. (1)), on an edge whose frame starts at `first`.
    pub(crate) fn crossed(
        &mut self,
        strip: &Strip,
        i: usize,
        other: &Strip,
        first: VertexId,
    ) -> Strip {
        let keys = [0, 1].map(|r| {
            let mine = strip.ids[r];
            let theirs = other.ids[(0..2).find(|&q| other.a[q] == strip.a[r])?];
            // Whether this wedge is lower just beyond the point, going from `a` to `b`.
            let beyond = (i == 0) == (first == strip.a[r]);
            let key = match mine.cmp(&theirs) {
                std::cmp::Ordering::Less => EndKey::Crossing {
                    low: mine,
                    high: theirs,
                    low_beyond: beyond,
                },
                std::cmp::Ordering::Greater => EndKey::Crossing {
                    low: theirs,
                    high: mine,
                    low_beyond: !beyond,
                },
                std::cmp::Ordering::Equal => return None,
            };
            Some(self.intern_end(key))
        });
        let mut next = *strip;
        next.ends[i] = match keys {
            [Some(k0), Some(k1)] => Some([k0, k1]),
            _ => None,
        };
        next
    }

    /// Whether the wedge on `edge` (whose frame starts at `first`) of pseudo-source vertex `p`
    /// (leading back to `source`) seen through `strip` was offered before, from either side
    /// of the edge; records it if not. Only a wedge whose range ends the strips know is known
    /// again: its distance function along the edge and its range are those of the copy first
    /// offered, as the two strips' layouts are congruent, name the edge's ends alike, and
    /// place the range's ends alike.
    pub(crate) fn offered_before(
        &mut self,
        strip: &Strip,
        (source, p): (SourceId, VertexId),
        (edge, first): (EdgeId, VertexId),
    ) -> bool {
        let [Some(b0), Some(b1)] = strip.ends else {
            return false;
        };
        let described = [0, 1].map(|r| ([strip.ids[r], b0[r], b1[r]], first == strip.a[r]));
        let (key, a_first) = described[0].min(described[1]);
        !self.offered.insert((source, p, edge, key, a_first))
    }
}
