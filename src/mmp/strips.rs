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
//! named either way round, the strip and its mirror image. Through a flat region a strip is
//! described by its run there, not by the faces it crosses (see `region_runs.rs`), and a range
//! end carried along the run by the point its ray came through where it was last named. Kept
//! only by number types that keep values, on the meshes where [`CongruentPaths`] describes
//! strips (a chain of faces fixes its strip there).

use super::flat_region::FlatRegions;
use super::paths::{CongruentPaths, Path};
use super::region_runs::{Entry, RegionRuns, Run, RunKey};
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
    /// The run through a flat region the strip is in, if it is (see `region_runs.rs`).
    run: Option<Run>,
    /// For each range end the strips know, in each reading: the strip's id on the edge where
    /// the end was last named other than by a ray carried along a run, and its key there. A
    /// ray carried along a run is named from that point, not from the edges crossed since.
    bases: [Option<[(u32, u32); 2]>; 2],
}

impl Strip {
    /// Range end `i`'s key in each reading, with the strip's ids: where the end is named now.
    fn based(&self, i: usize) -> Option<[(u32, u32); 2]> {
        self.ends[i].map(|keys| [0, 1].map(|r| (self.ids[r], keys[r])))
    }

    /// The same strip with the range ends that `keep` says are still the wedge's own; a
    /// trimmed end (another wedge's end, or a crossing not yet named) is unknown.
    pub(crate) fn trimmed(mut self, keep: [bool; 2]) -> Strip {
        for (i, keep) in keep.into_iter().enumerate() {
            if !keep {
                self.ends[i] = None;
                self.bases[i] = None;
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
        self.bases[i] = self.based(i);
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
        joined.bases = [None; 2];
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
        self.bases.swap(0, 1);
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
    /// The ray from the image through the point `point` of the edge where the strip was
    /// `base`, carried along a run to the edge of strip `strip` (see `region_runs.rs`).
    Through { strip: u32, base: u32, point: u32 },
}

/// The strips met in one run, and the wedges offered through them.
#[derive(Default)]
pub(crate) struct OfferedWedges {
    /// Interned descriptions: a strip's id from the id of the strip one face shorter (or
    /// [`FIRST_FACE`]) and the next face's description.
    strips: HashMap<(u32, [u32; 4]), u32>,
    /// Interned descriptions in a run through a flat region: a strip's id from its run's
    /// prefix and its edge's description against the run's anchor (see `region_runs.rs`).
    runs: HashMap<(u32, RunKey), u32>,
    /// The flat regions, where the mesh has some.
    regions: Option<RegionRuns>,
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
    /// The table for a run on `mesh`, with the mesh's flat regions where it has some.
    pub(crate) fn new<S: Scalar>(mesh: &TriMesh, regions: Option<&FlatRegions<S>>) -> Self {
        OfferedWedges {
            regions: regions.map(|r| RegionRuns::new(mesh, r)),
            ..OfferedWedges::default()
        }
    }

    /// The next strip id: ids of both tables are counted together, so they never meet.
    fn next_id(&self) -> u32 {
        (self.strips.len() + self.runs.len()) as u32
    }

    fn intern(&mut self, before: u32, description: [u32; 4]) -> u32 {
        let next = self.next_id();
        *self.strips.entry((before, description)).or_insert(next)
    }

    fn intern_run(&mut self, prefix: u32, key: RunKey) -> u32 {
        let next = self.next_id();
        *self.runs.entry((prefix, key)).or_insert(next)
    }

    /// The id of edge `edge` in `run`'s reading `r`.
    fn run_id(&mut self, mesh: &TriMesh, run: &Run, r: usize, edge: [VertexId; 2]) -> Option<u32> {
        let key = self.regions.as_mut()?.key(mesh, run.anchor[r], edge)?;
        Some(self.intern_run(run.prefix[r], key))
    }

    /// The run a strip is in after crossing into face `f` (of far corner `apex`) across its
    /// edge, where `f` lies in a flat region: the strip's run where `f` continues it; one
    /// anchored on a crease line, described from the run left, where the strip crosses one;
    /// else one anchored on the edge it came in by.
    fn run_into(
        &mut self,
        mesh: &TriMesh,
        strip: &Strip,
        f: FaceId,
        apex: VertexId,
    ) -> Option<Option<Run>> {
        let names = [0, 1].map(|r| [strip.a[r], strip.b[r]]);
        let Some(entry) = self
            .regions
            .as_ref()
            .and_then(|r| r.entry(strip.run.as_ref(), f, names))
        else {
            return Some(None);
        };
        Some(Some(match entry {
            Entry::Continues(run) => run,
            Entry::Crease(left, region, anchor) => {
                let mut prefix = [0; 2];
                for r in 0..2 {
                    let [u, w, _] = anchor[r];
                    prefix[r] = self.run_id(mesh, &left, r, [u, w])?;
                }
                Run {
                    region,
                    anchor,
                    prefix,
                }
            }
            Entry::Fresh(region) => Run {
                region,
                anchor: names.map(|[a, b]| [a, b, apex]),
                prefix: strip.ids,
            },
        }))
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
        let region = self.regions.as_ref().and_then(|r| r.region(f));
        let Some(region) = region else {
            let mut read = |a: VertexId, b: VertexId| -> Option<u32> {
                let sides = [
                    paths.class(mesh, p, a)?,
                    paths.class(mesh, p, b)?,
                    paths.class(mesh, a, b)?,
                ];
                Some(self.intern(FIRST_FACE, [path, sides[0], sides[1], sides[2]]))
            };
            let ids = [read(next, previous)?, read(previous, next)?];
            return Some(self.spanning(ids, [next, previous], first, None));
        };
        // The pseudo-source lies in the region: the run's anchor.
        let prefix = self.intern(FIRST_FACE, [path, u32::MAX, u32::MAX, u32::MAX]);
        let run = Run {
            region,
            anchor: [[p; 3]; 2],
            prefix: [prefix; 2],
        };
        let ids = [
            self.run_id(mesh, &run, 0, [next, previous])?,
            self.run_id(mesh, &run, 1, [previous, next])?,
        ];
        Some(self.spanning(ids, [next, previous], first, Some(run)))
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
        Some(self.spanning(ids, [p, other], first, None))
    }

    /// The strip of ids `ids` read from `a` and from `b`, over its whole edge (whose frame runs
    /// from `first`), in `run`: the range's ends are the edge's.
    fn spanning(
        &mut self,
        ids: [u32; 2],
        [a, b]: [VertexId; 2],
        first: VertexId,
        run: Option<Run>,
    ) -> Strip {
        let mut strip = Strip {
            ids,
            a: [a, b],
            b: [b, a],
            ends: [None; 2],
            run,
            bases: [None; 2],
        };
        let last = if first == a { b } else { a };
        strip.ends = [first, last].map(|v| Some(self.corner(&strip, v)));
        strip.bases = [0, 1].map(|i| strip.based(i));
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
        let (a, b) = (strip.a[0], strip.b[0]);
        let apex = *mesh.face(face).iter().find(|&&c| c != a && c != b)?;
        let run = self.run_into(mesh, strip, face, apex)?;
        let mut next = *strip;
        next.run = run;
        for reading in 0..2 {
            let (a, b) = (strip.a[reading], strip.b[reading]);
            let ends = mesh.edge(to).vertices;
            let (exit, labels) = if ends.contains(&a) && ends.contains(&apex) {
                (0, (a, apex))
            } else if ends.contains(&apex) && ends.contains(&b) {
                (1, (apex, b))
            } else {
                return None;
            };
            next.ids[reading] = match &run {
                Some(run) => self.run_id(mesh, run, reading, [labels.0, labels.1])?,
                None => {
                    let sides = [paths.class(mesh, a, apex)?, paths.class(mesh, b, apex)?];
                    self.intern(strip.ids[reading], [sides[0], sides[1], exit, 0])
                }
            };
            (next.a[reading], next.b[reading]) = labels;
        }
        for (i, t) in through.into_iter().enumerate() {
            (next.ends[i], next.bases[i]) = match (t, &run) {
                (Through::Corner(v), _) => (Some(self.corner(&next, v)), None),
                // Along a run, the ray is named from where its end was last named.
                (Through::Ray(j), Some(_)) => {
                    let base = strip.bases[j];
                    let keys = base.map(|base| {
                        [0, 1].map(|r| {
                            self.intern_end(EndKey::Through {
                                strip: next.ids[r],
                                base: base[r].0,
                                point: base[r].1,
                            })
                        })
                    });
                    (keys, base)
                }
                (Through::Ray(j), None) => (
                    strip.ends[j].map(|origin| {
                        [0, 1].map(|r| {
                            self.intern_end(EndKey::Carried {
                                strip: next.ids[r],
                                origin: origin[r],
                            })
                        })
                    }),
                    None,
                ),
            };
            if next.bases[i].is_none() {
                next.bases[i] = next.based(i);
            }
        }
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
        next.bases[i] = next.based(i);
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

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::mmp::source::SurfacePoint;

    /// A fan of faces about `v` (the origin, lifted by `lift`; its other corners are `fan`, in
    /// counterclockwise order) and, beyond its corners on `x = -1`, faces with the corner `p`
    /// in the plane `z = -(x + 1)` (`beyond`).
    pub(crate) fn fan(lift: f64, fan: &[[f64; 2]], beyond: &[[u32; 3]]) -> TriMesh {
        let mut positions = vec![[0.0, 0.0, lift], [-2.0, 0.0, 1.0], [-2.0, -2.0, 1.0]];
        positions.extend(fan.iter().map(|&[x, y]| [x, y, 0.0]));
        let n = fan.len() as u32;
        let mut faces: Vec<[u32; 3]> = (0..n).map(|k| [0, 3 + k, 3 + (k + 1) % n]).collect();
        faces.extend(beyond);
        TriMesh::new(positions, faces).expect("a mesh")
    }

    /// The mesh's flat regions, as a run that keeps values finds them (`f64` decides exactly
    /// on these coordinates).
    pub(crate) fn flat_regions(mesh: &TriMesh) -> FlatRegions<f64> {
        FlatRegions::new(
            mesh,
            &mesh
                .positions()
                .iter()
                .map(|p| p.to_array())
                .collect::<Vec<_>>(),
            vec![false; mesh.edge_count()],
        )
    }

    /// The strips from `p` (v1) across face `start` (whose far edge's frame runs from
    /// `frame`), then through the fan's faces of `route` (each entered across the edge it
    /// shares with the one before) out across `exit`, their ends carried along the rays:
    /// described in one table.
    fn through_fan(mesh: &TriMesh, routes: [(u32, u32, &[u32]); 2], exit: [u32; 2]) -> [Strip; 2] {
        let regions = flat_regions(mesh);
        let p = VertexId(1);
        let paths = CongruentPaths::<f64>::new(mesh, &[SurfacePoint::Vertex(p)]).expect("paths");
        let mut offered = OfferedWedges::new(mesh, Some(&regions));
        let exit = mesh
            .edge_between(VertexId(exit[0]), VertexId(exit[1]))
            .expect("an edge");
        routes.map(|(start, frame, route)| {
            let from = (p, &Path::at_source(p));
            let mut strip = offered
                .first(&paths, mesh, from, (FaceId(start), VertexId(frame)))
                .expect("a strip");
            for (k, &f) in route.iter().enumerate() {
                let to = match route.get(k + 1) {
                    Some(&g) => {
                        let shared: Vec<VertexId> = mesh
                            .face(FaceId(f))
                            .into_iter()
                            .filter(|c| mesh.face(FaceId(g)).contains(c))
                            .collect();
                        mesh.edge_between(shared[0], shared[1]).expect("an edge")
                    }
                    None => exit,
                };
                let through = [Through::Ray(0), Through::Ray(1)];
                strip = offered
                    .across(&paths, mesh, &strip, (FaceId(f), to), through)
                    .expect("a strip");
            }
            strip
        })
    }

    /// Whether two strips on one edge have one id in each reading, each reading of the one
    /// matched with the reading of the other that names the edge's ends alike; and the same
    /// range ends' keys too if `ends`.
    fn described_alike(s: &Strip, t: &Strip, ends: bool) -> bool {
        (0..2).all(|r| {
            let q = (0..2).find(|&q| t.a[q] == s.a[r]).expect("one edge");
            s.ids[r] == t.ids[q]
                && (!ends || (0..2).all(|i| s.ends[i].map(|k| k[r]) == t.ends[i].map(|k| k[q])))
        })
    }

    /// Whether two strips on one edge have different ids in each reading, matched as above.
    fn described_apart(s: &Strip, t: &Strip) -> bool {
        (0..2).all(|r| {
            let q = (0..2).find(|&q| t.a[q] == s.a[r]).expect("one edge");
            s.ids[r] != t.ids[q]
        })
    }

    /// The fan's corners w1, w2 on `x = -1`, n, e2, e1 on `x = 1`, s.
    pub(crate) const SIX: [[f64; 2]; 6] = [
        [1.0, 1.0],
        [0.0, 1.0],
        [-1.0, 1.0],
        [-1.0, -1.0],
        [0.0, -1.0],
        [1.0, -1.0],
    ];

    #[test]
    fn strips_passing_a_vertex_on_either_side_are_described_alike_where_it_is_flat() {
        // From p across (w1 = v6, w2 = v5) into the fan, past v above it (through n) and below
        // it (through s), out across (e1 = v8, e2 = v3). In the flat fan, one unfolding, which
        // the runs see (entered across the crease line (w1, w2)); with v lifted out of the
        // plane, two unfoldings, which they must not confuse.
        let beyond = [[6, 5, 1], [6, 1, 2]];
        let routes: [(u32, u32, &[u32]); 2] = [(6, 6, &[2, 1, 0, 5]), (6, 6, &[2, 3, 4, 5])];
        let [above, below] = through_fan(&fan(0.0, &SIX, &beyond), routes, [8, 3]);
        assert!(described_alike(&above, &below, true));
        let [above, below] = through_fan(&fan(0.25, &SIX, &beyond), routes, [8, 3]);
        assert!(described_apart(&above, &below));
    }

    #[test]
    fn strips_crossing_one_crease_line_at_different_edges_are_described_alike() {
        // The fan's corner m = v6 on `x = -1` too, between w1 = v7 and w2 = v5: from p across
        // (w1, m) and on below v, or across (m, w2) and on above v, out across (e1 = v9,
        // e2 = v3). With the fan flat, the crease line w1 m w2 is straight: one unfolding
        // across it wherever it is crossed.
        let seven = [SIX[0], SIX[1], SIX[2], [-1.0, 0.0], SIX[3], SIX[4], SIX[5]];
        let beyond = [[7, 6, 1], [6, 5, 1]];
        let routes: [(u32, u32, &[u32]); 2] = [(7, 7, &[3, 4, 5, 6]), (8, 6, &[2, 1, 0, 6])];
        let [below, above] = through_fan(&fan(0.0, &seven, &beyond), routes, [9, 3]);
        assert!(described_alike(&below, &above, false));
        let [below, above] = through_fan(&fan(0.25, &seven, &beyond), routes, [9, 3]);
        assert!(described_apart(&below, &above));
    }
}
