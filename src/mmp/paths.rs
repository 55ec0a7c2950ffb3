//! Ties proved by congruence: one expression for the lengths of congruent paths, and for the
//! images seen through congruent strips.
//!
//! A distance that a wedge gives a vertex is the length of a path of straight segments in
//! unfoldings: from the source through a chain of faces to the first pseudo-source, and on
//! through chains to the vertex [SSK+05 §4, LZT §2]. Each segment's length is fixed by the
//! shape of its *strip*, the chain of triangles laid out in the plane: the lengths of their
//! sides, which sides they share, and the corners the segment joins. The same strip read
//! backwards, or mirrored, gives the same length; so does any strip of congruent triangles
//! glued alike, wherever it lies on the mesh. Such segments come from different chains of
//! constructions, whose expressions no normal form relates: on an icosphere, the geodesics
//! from a vertex to its antipode through strips congruent under the sphere's symmetries (or
//! merely triangle by triangle) tie, and the exact backend could not prove it.
//!
//! [`CongruentPaths`] describes each segment's strip by the classes of its sides' exact squared
//! lengths, keys a vertex distance by its segments' least descriptions (forwards or backwards,
//! either way round), and hands out one expression per key, so that those ties are zeros by
//! structure. A path is a sum of its segments, so their order does not matter. The same keys
//! fix a wedge's image on its edge: the strips of its last segment to the edge's two ends give
//! the image's distances from them, so wedges whose pairs of keys agree share one image
//! ([`CongruentPaths::image_key`], [`CongruentPaths::image`]), as images brought round a vertex
//! both ways on a symmetric mesh do; a range end's shadow line is known by its anchor and the
//! key of the image that casts it (see `provenance.rs`). A segment's faces in one flat region
//! are described by the run through them, by where it came in (see `region_runs.rs`): paths
//! that cross a region by other faces, or cross the line between two regions at other edges,
//! have one key; so do chains that pass a vertex of angle sum exactly 2 pi off every region (on
//! a straight crease between two) on either side, once each goes round it the short way
//! ([`CongruentPaths::round_the_short_way`]). Kept only by number types that keep
//! values, on meshes where a chain of faces fixes its strip: every source a vertex, and no
//! degenerate faces or edges with more than two faces.

use super::flat_region::FlatRegions;
use super::planar::Planar;
use super::region_runs::{Entry, RegionRuns, Run};
use super::source::SurfacePoint;
use crate::mesh::{EdgeId, FaceId, TriMesh, VertexId};
use crate::scalar::exact::squared_distance;
use crate::scalar::Scalar;
use std::cell::{OnceCell, RefCell};
use std::collections::HashMap;
use std::sync::Arc;

/// A step of a path: a vertex it passes, a face it crosses, or an edge it runs along.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) enum Step {
    Vertex(u32),
    Face(u32),
    Edge(u32),
}

/// A path, shared between the wedges that continue it: its last step and what came before.
#[derive(Clone, Debug)]
pub(crate) struct Path(Arc<Link>);

#[derive(Debug)]
struct Link {
    step: Step,
    before: Option<Path>,
}

impl Drop for Link {
    /// Unlinks a long path iteratively: dropping it recursively could overflow the stack.
    fn drop(&mut self) {
        let mut next = self.before.take();
        while let Some(Path(link)) = next {
            next = Arc::try_unwrap(link).ok().and_then(|mut l| l.before.take());
        }
    }
}

impl Path {
    /// The path that starts at a source vertex.
    pub(crate) fn at_source(v: VertexId) -> Path {
        Path(Arc::new(Link {
            step: Step::Vertex(v.0),
            before: None,
        }))
    }

    /// The path continued by one step.
    pub(crate) fn then(&self, step: Step) -> Path {
        Path(Arc::new(Link {
            step,
            before: Some(self.clone()),
        }))
    }

    /// The path continued across a face.
    pub(crate) fn across(&self, f: FaceId) -> Path {
        self.then(Step::Face(f.0))
    }

    /// The path continued along an edge.
    pub(crate) fn along(&self, e: EdgeId) -> Path {
        self.then(Step::Edge(e.0))
    }

    /// The path ended at a vertex.
    pub(crate) fn to(&self, v: VertexId) -> Path {
        self.then(Step::Vertex(v.0))
    }

    /// Whether two handles name one path: one link, not merely equal steps.
    pub(crate) fn is(&self, other: &Path) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }

    /// The path up to the vertex it last passed (the pseudo-source of its last segment).
    fn to_pseudo_source(&self) -> &Path {
        let mut at = self;
        while let (Step::Face(_) | Step::Edge(_), Some(before)) = (at.0.step, &at.0.before) {
            at = before;
        }
        at
    }

    /// Where this path, a vertex's wedge's, starts at a vertex that the image of `lit` (the
    /// path of a wedge on the same edge) saw straight: the vertex reached across a face by
    /// that wedge's lineage, and `lit` the path of the wedge that crossed the face, or of a
    /// descendant carried on across faces around the vertex (unfolding about edges through the
    /// vertex keeps it where the image saw it). A vertex keeps the path of the distance it
    /// keeps, so its distance is that image's distance function at it. `same` tells whether
    /// two paths of that lineage unfold one image ([`Path::is`], or
    /// [`CongruentPaths::same_image`]). `Some(opposite)`: whether the two wedges came to their
    /// edge across different faces (their images on opposite sides of its line).
    pub(crate) fn seen_straight_from(
        &self,
        mesh: &TriMesh,
        lit: &Path,
        same: impl Fn(&Path, &Path) -> bool,
    ) -> Option<bool> {
        let (Step::Face(back), Some(Path(at))) = (self.0.step, &self.0.before) else {
            return None;
        };
        let (Step::Vertex(v), Some(reached)) = (at.step, &at.before) else {
            return None;
        };
        let Step::Face(_) = reached.0.step else {
            return None;
        };
        let Step::Face(last) = lit.0.step else {
            return None;
        };
        let opposite = last != back;
        if reached.0.before.as_ref().is_some_and(|p| same(p, lit)) {
            return Some(opposite);
        }
        let around = |f: u32| mesh.face(FaceId(f)).contains(&VertexId(v));
        let mut at = lit;
        // A fan around a vertex has as many faces as the vertex.
        for _ in 0..=mesh.vertex_faces(VertexId(v)).len() {
            if same(at, reached) {
                return Some(opposite);
            }
            match (at.0.step, &at.0.before) {
                (Step::Face(f), Some(before)) if around(f) => at = before,
                _ => return None,
            }
        }
        None
    }

    /// The steps since the path last passed a vertex (the pseudo-source of its last segment),
    /// that vertex first.
    fn last_segment(&self) -> Vec<Step> {
        let mut steps = Vec::new();
        let mut at = Some(self);
        while let Some(Path(link)) = at {
            steps.push(link.step);
            if let Step::Vertex(_) = link.step {
                break;
            }
            at = link.before.as_ref();
        }
        steps.reverse();
        steps
    }

    /// The steps, first to last.
    fn steps(&self) -> Vec<Step> {
        let mut steps = Vec::new();
        let mut at = Some(self);
        while let Some(Path(link)) = at {
            steps.push(link.step);
            at = link.before.as_ref();
        }
        steps.reverse();
        steps
    }
}

/// One expression for the length of every path congruent to one already met (see the
/// module's docs), for one run.
pub(crate) struct CongruentPaths<S> {
    /// The class of each edge: edges of one class have equal exact lengths.
    classes: Vec<u32>,
    lengths: HashMap<Vec<u32>, S>,
    /// The vertex distances measured in flat regions, by region and vertex: the image and
    /// sigma they were measured from, and the expression (see [`CongruentPaths::length_from`]).
    measured: HashMap<(u32, VertexId), Vec<Measured<S>>>,
    /// The key of each edge and pair of strip descriptions met (see
    /// [`CongruentPaths::image_key`]).
    image_keys: HashMap<(EdgeId, [Vec<u32>; 2]), u32>,
    /// One image per key (see [`CongruentPaths::image`]).
    images: HashMap<u32, Planar<S>>,
    /// The mesh's flat regions, where it has some: a strip's faces in one region are
    /// described by the run through them (see `region_runs.rs`).
    regions: Option<RefCell<RegionRuns>>,
    /// Whether each vertex is an interior vertex of angle sum exactly 2 pi, asked when a strip
    /// turns about it (see [`CongruentPaths::round_the_short_way`]).
    developable: Vec<OnceCell<bool>>,
}

/// A vertex distance measured in a flat region: the image in the region's frame, the sigma
/// added to the straight line, and the distance's expression.
type Measured<S> = ([S; 2], S, S);

/// Separates the segments of a key.
const SEGMENT_END: u32 = u32::MAX;

impl<S: Scalar> CongruentPaths<S> {
    /// The table for a run from `sources` on `mesh`, if a chain of faces fixes its strip there.
    pub(crate) fn new(mesh: &TriMesh, sources: &[SurfacePoint]) -> Option<Self> {
        let report = mesh.validation();
        let fixed = sources.iter().all(|s| matches!(s, SurfacePoint::Vertex(_)))
            && report.zero_area_faces.is_empty()
            && report.non_manifold_edges.is_empty()
            && report.duplicate_faces.is_empty()
            && report.float_unresolved_edges.is_empty();
        if !fixed {
            return None;
        }
        let mut ids = HashMap::new();
        let classes = mesh
            .edges()
            .iter()
            .map(|e| {
                let [a, b] = e.vertices.map(|v| mesh.position(v).to_array());
                let next = ids.len() as u32;
                Some(*ids.entry(squared_distance(a, b)?).or_insert(next))
            })
            .collect::<Option<_>>()?;
        Some(CongruentPaths {
            classes,
            lengths: HashMap::new(),
            measured: HashMap::new(),
            image_keys: HashMap::new(),
            images: HashMap::new(),
            regions: None,
            developable: vec![OnceCell::new(); mesh.vertex_count()],
        })
    }

    /// The same table describing the faces of a strip in one of `regions` by its run there.
    pub(crate) fn with_regions(mut self, mesh: &TriMesh, regions: Option<&FlatRegions<S>>) -> Self {
        self.regions = regions.map(|r| RefCell::new(RegionRuns::new(mesh, r)));
        self
    }

    /// The length of `path` (a vertex distance): the expression of a congruent path met
    /// before, or `length()` kept for those to come. A path whose strips it cannot describe
    /// keeps its own.
    pub(crate) fn length(&mut self, mesh: &TriMesh, path: &Path, length: impl FnOnce() -> S) -> S {
        match self.key(mesh, path) {
            Some(key) => self.lengths.entry(key).or_insert_with(length).clone(),
            None => length(),
        }
    }

    /// [`CongruentPaths::length`] of a path that ends with a straight line in a flat region,
    /// from the image `at` (in the frame of `region`) to its corner `v`, after `sigma`. That
    /// length is fixed by the image and `sigma` as well as by the path's strips: a path met
    /// before with the same key, or a distance measured before from the same image (proved the
    /// same point, with the same `sigma`), gives its expression, which both keep for those to
    /// come. Paths that reach the same image by routes of different strips (on either side of
    /// a vertex within the region, across a crease at two of its edges) then tie by structure,
    /// as their congruent copies do.
    pub(crate) fn length_from(
        &mut self,
        mesh: &TriMesh,
        path: &Path,
        (region, v, at, sigma): (u32, VertexId, &[S; 2], &S),
        length: impl FnOnce() -> S,
    ) -> S {
        let key = self.key(mesh, path);
        let by_key = key.as_ref().and_then(|k| self.lengths.get(k).cloned());
        let measured = self.measured.entry((region, v)).or_default();
        // Points far apart in `f64` are not compared exactly: sharing is never required.
        let near =
            |a: &S, b: &S| (a.to_f64() - b.to_f64()).abs() <= 1e-9 * (1.0 + a.to_f64().abs());
        let same = |a: &S, b: &S| near(a, b) && S::proved_same_point([a, a], [b, b]);
        let by_image = measured
            .iter()
            .find(|(p, s, _)| same(&p[0], &at[0]) && same(&p[1], &at[1]) && same(s, sigma))
            .map(|(_, _, d)| d.clone());
        let d = by_key.or_else(|| by_image.clone()).unwrap_or_else(length);
        if by_image.is_none() {
            measured.push((at.clone(), sigma.clone(), d.clone()));
        }
        if let Some(key) = key {
            self.lengths.entry(key).or_insert_with(|| d.clone());
        }
        d
    }

    /// The key of the image, in the frame of edge `e` (from its end `ends[0]` to `ends[1]`),
    /// of the pseudo-source that `path` last passed, seen through the faces the path crossed
    /// since: the descriptions of its strips to the edge's two ends, interned. The two strips
    /// fix the pseudo-source's distances from the edge's ends in the unfolding, so the image
    /// up to its mirror across the edge's line, which the frame does not tell (`y` is a
    /// distance from it): images of one key are one point of the frame, however they were
    /// built. `None` where the strips cannot be described.
    pub(crate) fn image_key(
        &mut self,
        mesh: &TriMesh,
        (e, ends): (EdgeId, [VertexId; 2]),
        path: &Path,
    ) -> Option<u32> {
        let steps = path.last_segment();
        let [a, b] = ends.map(|v| {
            let mut to = steps.clone();
            to.push(Step::Vertex(v.0));
            self.segment(mesh, &to)
        });
        let next = self.image_keys.len() as u32;
        Some(*self.image_keys.entry((e, [a?, b?])).or_insert(next))
    }

    /// The expression of an image of key `key` ([`CongruentPaths::image_key`]) met before, or
    /// `at`, kept for those to come. So an image brought round a vertex both ways on a mesh
    /// with a symmetry (the same corners in the opposite order) is one expression, a tie no
    /// normal form reaches.
    pub(crate) fn image(&mut self, key: u32, at: Planar<S>) -> Planar<S> {
        self.images.entry(key).or_insert(at).clone()
    }

    /// Whether two paths that end across one face unfold one image of one pseudo-source
    /// there, however they were built: one path (one link) to the pseudo-source they last
    /// passed, or one source vertex, so one distance there; and strips since then to each
    /// corner of the face of one description, so the image's distances from the three corners
    /// agree. Paths through a flat region by other faces unfold the region alike.
    pub(crate) fn same_image(&self, mesh: &TriMesh, a: &Path, b: &Path) -> bool {
        if a.is(b) {
            return true;
        }
        let (Step::Face(f), Step::Face(g)) = (a.0.step, b.0.step) else {
            return false;
        };
        let (p, q) = (a.to_pseudo_source(), b.to_pseudo_source());
        let one_source = p.0.before.is_none() && q.0.before.is_none() && p.0.step == q.0.step;
        if f != g || !(p.is(q) || one_source) {
            return false;
        }
        let (a, b) = (a.last_segment(), b.last_segment());
        mesh.face(FaceId(f)).iter().all(|c| {
            let to = |steps: &[Step]| {
                let mut to = steps.to_vec();
                to.push(Step::Vertex(c.0));
                self.segment(mesh, &to)
            };
            to(&a).is_some_and(|d| to(&b) == Some(d))
        })
    }

    /// The descriptions of the path's segments, sorted and joined.
    pub(crate) fn key(&self, mesh: &TriMesh, path: &Path) -> Option<Vec<u32>> {
        let steps = path.steps();
        let mut segments = Vec::new();
        let mut start = 0;
        for (i, step) in steps.iter().enumerate().skip(1) {
            if let Step::Vertex(_) = step {
                segments.push(self.segment(mesh, &steps[start..=i])?);
                start = i;
            }
        }
        segments.sort_unstable();
        let mut key = Vec::new();
        for segment in segments {
            key.extend(segment);
            key.push(SEGMENT_END);
        }
        Some(key)
    }

    /// The class of the edge between two vertices.
    pub(crate) fn class(&self, mesh: &TriMesh, a: VertexId, b: VertexId) -> Option<u32> {
        Some(self.classes[mesh.edge_between(a, b)?.index()])
    }

    /// The least description of a segment's strip: `steps` runs from one vertex through faces
    /// (or along one edge) to another.
    fn segment(&self, mesh: &TriMesh, steps: &[Step]) -> Option<Vec<u32>> {
        let (Step::Vertex(s), Step::Vertex(v)) = (*steps.first()?, *steps.last()?) else {
            return None;
        };
        let (s, v) = (VertexId(s), VertexId(v));
        let middle = &steps[1..steps.len() - 1];
        if let [Step::Edge(_)] = middle {
            return Some(vec![self.class(mesh, s, v)?]);
        }
        let mut faces: Vec<FaceId> = middle
            .iter()
            .map(|step| match step {
                Step::Face(f) => Some(FaceId(*f)),
                _ => None,
            })
            .collect::<Option<_>>()?;
        self.round_the_short_way(mesh, &mut faces, [s, v]);
        // The segment ends at the copy of its end that the last faces turn about: in the first
        // of the run of faces at the chain's end that have it as a corner (an earlier face
        // with that corner, before the chain left it, unfolds another copy of it).
        let has = |f: FaceId, u: VertexId| mesh.face(f).contains(&u);
        if !has(*faces.last()?, v) {
            return None;
        }
        let mut last = faces.len() - 1;
        while last > 0 && has(faces[last - 1], v) {
            last -= 1;
        }
        let faces = &faces[..=last];
        if last == 0 {
            return Some(vec![self.class(mesh, s, v)?]);
        }
        if !has(faces[0], s) || faces[1..].iter().any(|&f| has(f, s)) {
            return None;
        }
        let backwards: Vec<FaceId> = faces.iter().rev().copied().collect();
        [(s, faces, v), (v, &backwards[..], s)]
            .into_iter()
            .flat_map(|(from, chain, to)| {
                [false, true].map(|flip| self.strip(mesh, (from, chain, to), flip))
            })
            .collect::<Option<Vec<_>>>()?
            .into_iter()
            .min()
    }

    /// Rewrites a chain of faces so that where it turns about a vertex of angle sum exactly
    /// 2 pi (exactly flat, or on a straight crease), other than its ends, it goes the short way
    /// round (of two ways of one length, the one of lesser face ids): about such a vertex the
    /// faces unfold into a whole disc, so both ways lay the faces after the turn out alike,
    /// and two chains that pass it on either side describe one strip. Not where the other way
    /// passes another face of the chain's start: no chain from the start goes there, and
    /// [`segment`](Self::segment) describes none that does. A vertex on a crease lies in two
    /// planes, in no flat region, so this is not the runs' description (`region_runs.rs`).
    fn round_the_short_way(&self, mesh: &TriMesh, faces: &mut Vec<FaceId>, ends: [VertexId; 2]) {
        let developable = |c: VertexId| {
            *self.developable[c.index()].get_or_init(|| {
                !mesh.is_boundary_vertex(c) && (mesh.is_flat_vertex(c) || mesh.is_crease_vertex(c))
            })
        };
        let mut i = 0;
        // Each rewrite makes the chain shorter, or as long and of lesser ids from `i` on.
        while i + 2 < faces.len() {
            let rewritten = mesh.face(faces[i]).into_iter().find_map(|c| {
                if ends.contains(&c) || !developable(c) {
                    return None;
                }
                let turn = faces[i..]
                    .iter()
                    .take_while(|&&f| mesh.face(f).contains(&c))
                    .count();
                if turn < 3 {
                    return None;
                }
                let way = other_way_round(mesh, c, &faces[i..i + turn])?;
                // The turn's own faces may hold the start (the chain's first face does).
                let fresh = |f: &&FaceId| !faces[i..i + turn].contains(f);
                if way
                    .iter()
                    .filter(fresh)
                    .any(|&f| mesh.face(f).contains(&ends[0]))
                {
                    return None;
                }
                let shorter = (way.len(), &way[..]) < (turn, &faces[i..i + turn]);
                shorter.then_some((turn, way))
            });
            let Some((turn, way)) = rewritten else {
                i += 1;
                continue;
            };
            faces.splice(i..i + turn, way);
            // The face at `i` stays; a turn that reaches it, about one of its corners, may
            // now go on differently: the scan goes back to the first such turn's start.
            i = mesh
                .face(faces[i])
                .into_iter()
                .map(|c| {
                    let before = faces[..i].iter().rev();
                    i - before.take_while(|&&f| mesh.face(f).contains(&c)).count()
                })
                .min()
                .unwrap_or(i);
        }
    }

    /// A strip's description from `from` through `chain` (at least two faces) to `to`: the
    /// classes of the first face's sides, then of each next face's two new sides and which
    /// shared corner it keeps; `flip` names the first shared side's corners the other way
    /// round (the strip's mirror image). Faces that turn about one corner in a row (each
    /// keeps the corner the one before kept) are described as a [`Turn`], by their shapes in
    /// any order: the strip goes on from the last of them however they are ordered.
    fn strip(
        &self,
        mesh: &TriMesh,
        (from, chain, to): (VertexId, &[FaceId], VertexId),
        flip: bool,
    ) -> Option<Vec<u32>> {
        let shared = |f: FaceId, g: FaceId| -> Option<[VertexId; 2]> {
            let common: Vec<VertexId> = mesh
                .face(f)
                .into_iter()
                .filter(|c| mesh.face(g).contains(c))
                .collect();
            <[VertexId; 2]>::try_from(common).ok()
        };
        let [mut a, mut b] = shared(chain[0], chain[1])?;
        if flip {
            std::mem::swap(&mut a, &mut b);
        }
        let class = |x, y| self.class(mesh, x, y);
        // The run through a flat region the strip is in: its region and anchor, described
        // when the strip leaves it (see `region_runs.rs`).
        let region = |f: FaceId| self.regions.as_ref().and_then(|r| r.borrow().region(f));
        let describe_run = |description: &mut Vec<u32>, anchor, edge| -> Option<()> {
            let key = self
                .regions
                .as_ref()?
                .borrow_mut()
                .key(mesh, anchor, edge)?;
            description.push(RUN);
            description.extend(key);
            Some(())
        };
        let mut run = region(chain[0]).map(|r| (r, [from; 3]));
        let mut description = match run {
            Some(_) => Vec::new(),
            None => vec![class(from, a)?, class(from, b)?, class(a, b)?],
        };
        let mut turn = Turn::default();
        for (i, &f) in chain.iter().enumerate().skip(1) {
            let apex = *mesh.face(f).iter().find(|&&c| c != a && c != b)?;
            match (run, region(f)) {
                (Some((r, _)), Some(s)) if r == s => {}
                (Some((left, anchor)), here) => {
                    // Across a crease line, the next run is anchored on the line's ends.
                    let crease = self.regions.as_ref().and_then(|r| {
                        let run = Run {
                            region: left,
                            anchor: [anchor; 2],
                            prefix: [0; 2],
                        };
                        match r.borrow().entry(Some(&run), f, [[a, b], [b, a]])? {
                            Entry::Crease(_, s, [line, _]) => Some((s, line)),
                            _ => None,
                        }
                    });
                    let edge = crease.map_or([a, b], |(_, [u, w, _])| [u, w]);
                    describe_run(&mut description, anchor, edge)?;
                    run = crease.or(here.map(|s| (s, [a, b, apex])));
                }
                (None, Some(s)) => {
                    turn.describe(&mut description);
                    run = Some((s, [a, b, apex]));
                }
                (None, None) => {}
            }
            if i + 1 == chain.len() {
                match run {
                    Some((_, anchor)) => describe_run(&mut description, anchor, [to, to])?,
                    None => {
                        turn.describe(&mut description);
                        description.extend([class(a, apex)?, class(b, apex)?]);
                    }
                }
                return (apex == to).then_some(description);
            }
            let next = shared(f, chain[i + 1])?;
            let entry = class(a, b)?;
            let sides = [class(a, apex)?, class(b, apex)?];
            let kept = if next.contains(&a) && next.contains(&apex) {
                b = apex;
                0
            } else if next.contains(&apex) && next.contains(&b) {
                a = apex;
                1
            } else {
                return None;
            };
            if run.is_none() {
                turn.push(&mut description, kept, (entry, sides));
            }
        }
        None
    }
}

/// Marks the description of a run through a flat region in a strip's description: the
/// classes of its anchor's distances to the edge it left the region by, or to the segment's
/// end ([`RegionRuns::key`]).
const RUN: u32 = u32::MAX - 2;

/// Faces of a strip in a row that turn about one corner, the *pivot* (each keeps the corner of
/// the shared side the one before kept). Laid out in the plane, the last side of the row is
/// the pivot's side to the last apex, turned from the row's first side by the sum of the
/// faces' angles at the pivot: it is fixed by that side's length and the faces' shapes, in
/// any order and each either way round (a face's angle at the pivot is a function of its
/// three sides, the two at the pivot alike). The pivot's fan on a mesh with a symmetry broken
/// inside the fan alone (a pole's ring of vertices, one of them off its mirror image by a
/// rounding) gives the same strip read through its mirror image.
#[derive(Default)]
struct Turn {
    /// Which corner of the shared side the faces keep (0: the first, 1: the second).
    kept: u32,
    /// Each face's sides at the pivot (the lesser first) and its side opposite the pivot.
    faces: Vec<[u32; 3]>,
    /// The side from the pivot to the last face's apex.
    last: u32,
}

/// Marks a [`Turn`] of more than one face in a strip's description: its faces' count follows.
const TURN: u32 = u32::MAX - 1;

impl Turn {
    /// Adds the face entered over a side of class `entry`, with new sides `sides` (from the
    /// side's first and second corner to its apex), which keeps corner `kept` of that side;
    /// a face that keeps the other corner starts a new turn, the last one described first.
    fn push(&mut self, description: &mut Vec<u32>, kept: u32, (entry, sides): (u32, [u32; 2])) {
        if !self.faces.is_empty() && kept != self.kept {
            self.describe(description);
        }
        let (at_pivot, opposite) = if kept == 0 {
            (sides[0], sides[1])
        } else {
            (sides[1], sides[0])
        };
        self.kept = kept;
        self.faces
            .push([entry.min(at_pivot), entry.max(at_pivot), opposite]);
        self.last = at_pivot;
    }

    /// Appends the turn to `description` and empties it: a single face as it is met (its new
    /// sides, the corner kept), more as [`TURN`], their count, the corner kept, their shapes
    /// sorted and the last side.
    fn describe(&mut self, description: &mut Vec<u32>) {
        match self.faces[..] {
            [] => {}
            [[_, _, opposite]] => {
                let sides = if self.kept == 0 {
                    [self.last, opposite]
                } else {
                    [opposite, self.last]
                };
                description.extend(sides);
                description.push(self.kept);
            }
            _ => {
                self.faces.sort_unstable();
                description.extend([TURN, self.faces.len() as u32, self.kept]);
                description.extend(self.faces.iter().flatten());
                description.push(self.last);
            }
        }
        self.faces.clear();
    }
}

/// The faces about the interior vertex `c` from the first face of `turn` (consecutive faces
/// around `c`) to its last, the other way round; `None` where the faces about `c` do not close
/// into one fan.
fn other_way_round(mesh: &TriMesh, c: VertexId, turn: &[FaceId]) -> Option<Vec<FaceId>> {
    let (&first, &last) = (turn.first()?, turn.last()?);
    let fan = mesh.vertex_faces(c).len();
    let mut way = vec![first];
    let (mut previous, mut at) = (turn[1], first);
    while at != last {
        if way.len() > fan {
            return None;
        }
        // The face beyond `at`'s side through `c` that does not lead back.
        let next = mesh
            .face(at)
            .into_iter()
            .filter(|&u| u != c)
            .find_map(|u| {
                let side = mesh.edge_between(c, u)?;
                let mut beyond = mesh.edge_faces(side).filter(|&g| g != at);
                let g = beyond.next()?;
                (beyond.next().is_none() && g != previous).then_some(g)
            })?;
        (previous, at) = (at, next);
        way.push(at);
    }
    Some(way)
}

/// A kept path continued by `step`; nothing where no path is kept.
pub(crate) fn continued<S: Scalar>(
    path: &S::Kept<Path>,
    step: impl FnOnce(&Path) -> Path,
) -> S::Kept<Path> {
    S::kept(path).map_or_else(Default::default, |p| S::keep(|| step(&p)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;
    use std::collections::HashSet;

    /// The wedges that see straight a vertex that their lineage lit across a face: the wedge
    /// that crossed the face (on the face's other side), the one lit across it (on the same
    /// side), its descendants across faces around the vertex; not an equal path of another
    /// wedge, nor a descendant across a face off the vertex.
    #[test]
    fn a_vertex_is_seen_straight_from_the_lineage_that_lit_it() {
        // Faces around vertex 0 of the icosahedron, and one face off it.
        let mesh = shapes::icosahedron();
        let fan = mesh.vertex_faces(VertexId(0)).to_vec();
        let off = (0..mesh.face_count() as u32)
            .map(FaceId)
            .find(|&f| !mesh.face(f).contains(&VertexId(0)))
            .expect("a face off the vertex");
        let parent = Path::at_source(VertexId(9)).across(off);
        let lit = parent.across(fan[0]);
        let vertex = lit.to(VertexId(0));
        let back = vertex.across(fan[0]);
        assert_eq!(
            back.seen_straight_from(&mesh, &parent, Path::is),
            Some(true)
        );
        assert_eq!(back.seen_straight_from(&mesh, &lit, Path::is), Some(false));
        let around = vertex.across(fan[2]);
        let carried = lit.across(fan[1]).across(fan[2]);
        assert_eq!(
            around.seen_straight_from(&mesh, &carried, Path::is),
            Some(false)
        );
        assert_eq!(
            back.seen_straight_from(&mesh, &carried, Path::is),
            Some(true)
        );
        let alike = Path::at_source(VertexId(9)).across(off).across(fan[0]);
        assert_eq!(back.seen_straight_from(&mesh, &alike, Path::is), None);
        assert_eq!(
            around.seen_straight_from(&mesh, &lit.across(off), Path::is),
            None
        );
        assert_eq!(
            lit.across(fan[1]).seen_straight_from(&mesh, &lit, Path::is),
            None
        );
    }

    /// A 4 x 3 grid folded along the line x = 0 (flat on the left, rising on the right), its
    /// cells split so that the eight faces 0..8 turn about the vertex 5 at (0, 0) in that
    /// order; faces 8..12 fill the column on the right. `lift` raises the vertex 9 at (0, 1)
    /// off the fold line: 5 is then no longer on a straight crease.
    fn folded_grid(lift: f64) -> TriMesh {
        let mut positions = Vec::new();
        for y in -1..=1 {
            for x in -1..=2 {
                let (x, y) = (f64::from(x), f64::from(y));
                positions.push([x, y, 0.5 * x.max(0.0)]);
            }
        }
        positions[9][2] = lift;
        let fan = [[5, 6, 10], [5, 10, 9], [5, 9, 8], [5, 8, 4]];
        let fan_below = [[5, 4, 0], [5, 0, 1], [5, 1, 2], [5, 2, 6]];
        let right = [[2, 3, 7], [2, 7, 6], [6, 7, 11], [6, 11, 10]];
        let faces = [fan, fan_below, right].concat();
        TriMesh::new(positions, faces).expect("a mesh")
    }

    /// About a vertex of angle sum 2 pi on a straight crease, a chain of faces is rewritten
    /// to go the short way round (of two ways of one length, the one of lesser face ids), and
    /// two paths that pass it on either side unfold one image; about the same vertex off a
    /// straight crease, nothing is rewritten.
    #[test]
    fn a_turn_about_a_vertex_on_a_straight_crease_goes_the_short_way() {
        let ids = |faces: &[u32]| faces.iter().map(|&f| FaceId(f)).collect::<Vec<_>>();
        let ends = [VertexId(3), VertexId(9)];
        let rewritten = |mesh: &TriMesh, faces: &[u32]| {
            let table = CongruentPaths::<f64>::new(mesh, &[SurfacePoint::Vertex(ends[0])])
                .expect("a mesh whose chains fix their strips");
            let mut chain = ids(faces);
            table.round_the_short_way(mesh, &mut chain, ends);
            (table, chain)
        };
        let folded = folded_grid(0.0);
        assert!(folded.is_crease_vertex(VertexId(5)));
        let long = [7, 6, 5, 4, 3, 2];
        assert_eq!(rewritten(&folded, &long).1, ids(&[7, 0, 1, 2]));
        assert_eq!(
            rewritten(&folded, &[7, 6, 5, 4, 3]).1,
            ids(&[7, 0, 1, 2, 3])
        );
        assert_eq!(
            rewritten(&folded, &[7, 0, 1, 2, 3]).1,
            ids(&[7, 0, 1, 2, 3])
        );
        // From vertex 3 on the right across faces 8 and 9 to face 7, then round to face 2.
        let path = |faces: &[u32]| {
            [8, 9]
                .iter()
                .chain(faces)
                .fold(Path::at_source(ends[0]), |p, &f| p.across(FaceId(f)))
        };
        let (table, _) = rewritten(&folded, &[]);
        assert!(table.same_image(&folded, &path(&long), &path(&[7, 0, 1, 2])));
        assert!(!table.same_image(&folded, &path(&long), &path(&[7, 0, 1])));
        let bent = folded_grid(0.25);
        assert!(!bent.is_crease_vertex(VertexId(5)));
        assert_eq!(rewritten(&bent, &long).1, ids(&long));
        let (table, _) = rewritten(&bent, &[]);
        assert!(!table.same_image(&bent, &path(&long), &path(&[7, 0, 1, 2])));
    }

    /// A chain from vertex 4 turning about vertex 5 through faces 4, 5, 6, 7 to 0 is not
    /// rewritten the other way round (faces 4, 3, 2, 1, 0: as long, of lesser ids), which
    /// passes face 3, a second face of vertex 4; the chain keeps a key. From vertex 0, which
    /// the other way does not pass, the same turn is rewritten.
    #[test]
    fn a_turn_is_not_rewritten_past_the_start_again() {
        let ids = |faces: &[u32]| faces.iter().map(|&f| FaceId(f)).collect::<Vec<_>>();
        let mesh = folded_grid(0.0);
        let [start, end] = [VertexId(4), VertexId(10)];
        let table = CongruentPaths::<f64>::new(&mesh, &[SurfacePoint::Vertex(start)])
            .expect("a mesh whose chains fix their strips");
        let mut chain = ids(&[4, 5, 6, 7, 0]);
        table.round_the_short_way(&mesh, &mut chain, [start, end]);
        assert_eq!(chain, ids(&[4, 5, 6, 7, 0]));
        let path = [4, 5, 6, 7, 0]
            .iter()
            .fold(Path::at_source(start), |p, &f| p.across(FaceId(f)))
            .to(end);
        assert!(table.key(&mesh, &path).is_some());
        let mut chain = ids(&[4, 5, 6, 7, 0]);
        table.round_the_short_way(&mesh, &mut chain, [VertexId(0), end]);
        assert_eq!(chain, ids(&[4, 3, 2, 1, 0]));
    }

    /// The paths from a corner of each face across its edge to the far corner of the face
    /// beyond, with their keys.
    fn keys_across_edges(mesh: &TriMesh) -> Vec<(Vec<u32>, Vec<u32>)> {
        let table = CongruentPaths::<f64>::new(mesh, &[SurfacePoint::Vertex(VertexId(0))])
            .expect("a mesh whose chains fix their strips");
        let corner = |f: FaceId, a: VertexId, b: VertexId| {
            *mesh.face(f).iter().find(|&&c| c != a && c != b).unwrap()
        };
        let mut keys = Vec::new();
        for (e, edge) in mesh.edges().iter().enumerate() {
            let faces: Vec<FaceId> = mesh.edge_faces(EdgeId(e as u32)).collect();
            let [f, g] = faces[..] else { continue };
            let [a, b] = edge.vertices;
            let (s, v) = (corner(f, a, b), corner(g, a, b));
            let forwards = Path::at_source(s).across(f).across(g).to(v);
            let backwards = Path::at_source(v).across(g).across(f).to(s);
            keys.push((
                table.key(mesh, &forwards).expect("a described strip"),
                table.key(mesh, &backwards).expect("a described strip"),
            ));
        }
        keys
    }

    #[test]
    fn congruent_strips_have_one_key_read_either_way() {
        // A grid of unit squares split by diagonals: every two faces across an edge form one
        // of a few shapes, wherever they lie.
        let keys = keys_across_edges(&shapes::grid(4, 4, 1.0, 1.0));
        assert!(keys.len() > 30);
        assert!(keys
            .iter()
            .all(|(forwards, backwards)| forwards == backwards));
        let distinct: HashSet<&Vec<u32>> = keys.iter().map(|(k, _)| k).collect();
        assert!(distinct.len() <= 3, "{} shapes", distinct.len());
    }

    /// A strip that turns about a vertex w across two faces, from p's face to r3's: pieces of
    /// one flat mesh, each its own copy of p, w, r0, r2, r3 (integer coordinates, so that
    /// equal squared lengths are exactly equal), with the middle corner r1 of its own.
    fn turning_piece(r1: [f64; 2], r2: [f64; 2], r3: [f64; 2], dx: f64) -> Vec<[f64; 3]> {
        let corners = [[2.0, -3.0], [0.0, 0.0], [5.0, 0.0], r1, r2, r3];
        corners.iter().map(|&[x, y]| [x + dx, y, 0.0]).collect()
    }

    #[test]
    fn faces_turning_about_a_vertex_in_another_order_have_one_key() {
        // A turns from w r0 to w r2 across a face of sides^2 (25, 10 | 5) and one of
        // (10, 25 | 25); B across the same two shapes the other way round (the fans are
        // mirror images, the pieces are not: p's face and r3's differ); C turns further.
        let pieces = [
            turning_piece([3.0, 1.0], [0.0, 5.0], [-4.0, 1.0], 0.0),
            turning_piece([1.0, 3.0], [0.0, 5.0], [-4.0, 1.0], 100.0),
            turning_piece([3.0, 1.0], [-3.0, 4.0], [-5.0, 0.0], 200.0),
        ];
        let faces: Vec<[u32; 3]> = (0..3)
            .flat_map(|k| {
                [[0, 2, 1], [1, 2, 3], [1, 3, 4], [1, 4, 5]].map(|f| f.map(|c| c + 6 * k))
            })
            .collect();
        let positions: Vec<[f64; 3]> = pieces.concat();
        let mesh = TriMesh::new(positions.clone(), faces).expect("a mesh");
        let table = CongruentPaths::<f64>::new(&mesh, &[SurfacePoint::Vertex(VertexId(0))])
            .expect("a mesh whose chains fix their strips");
        let path = |k: u32, backwards: bool| {
            let (p, r3) = (VertexId(6 * k), VertexId(6 * k + 5));
            let faces = (0..4).map(|f| FaceId(4 * k + f));
            let key = if backwards {
                faces
                    .rev()
                    .fold(Path::at_source(r3), |path, f| path.across(f))
                    .to(p)
            } else {
                faces
                    .fold(Path::at_source(p), |path, f| path.across(f))
                    .to(r3)
            };
            table.key(&mesh, &key).expect("a described strip")
        };
        // The independent fact the keys must follow: in the plane, p to r3 is a straight line.
        let length = |k: usize| {
            let [p, r3] = [positions[6 * k], positions[6 * k + 5]];
            ((p[0] - r3[0]).powi(2) + (p[1] - r3[1]).powi(2)).sqrt()
        };
        assert_eq!(length(0), length(1));
        assert_ne!(length(0), length(2));
        assert_eq!(path(0, false), path(1, false));
        assert_eq!(path(0, false), path(1, true));
        assert_ne!(path(0, false), path(2, false));
    }

    /// The key of the path from p (v1) across `faces` to `to` on the fan of `strips.rs`'s tests
    /// (about v, lifted by `lift`, with `corners` and the faces `beyond` it).
    fn key_on_fan(
        (lift, corners, beyond): (f64, &[[f64; 2]], &[[u32; 3]]),
        faces: &[u32],
        to: u32,
    ) -> Vec<u32> {
        let mesh = crate::mmp::strips::tests::fan(lift, corners, beyond);
        let regions = crate::mmp::strips::tests::flat_regions(&mesh);
        let table = CongruentPaths::<f64>::new(&mesh, &[SurfacePoint::Vertex(VertexId(1))])
            .expect("a mesh whose chains fix their strips")
            .with_regions(&mesh, Some(&regions));
        let path = faces
            .iter()
            .fold(Path::at_source(VertexId(1)), |p, &f| p.across(FaceId(f)))
            .to(VertexId(to));
        table.key(&mesh, &path).expect("a described strip")
    }

    #[test]
    fn paths_through_a_flat_region_have_one_key_whatever_faces_they_cross() {
        // From p (v1) across (w1, w2) into the fan about v, past v above it (through n) or
        // below it (through s), to e1 (v8): in the flat fan one straight line, with v lifted
        // two.
        let six = &crate::mmp::strips::tests::SIX;
        let key = |lift, faces: &[u32]| key_on_fan((lift, six, &[[6, 5, 1], [6, 1, 2]]), faces, 8);
        let (above, below): (&[u32], &[u32]) = (&[6, 2, 1, 0, 5], &[6, 2, 3, 4]);
        assert_eq!(key(0.0, above), key(0.0, below));
        assert_ne!(key(0.25, above), key(0.25, below));
    }

    #[test]
    fn paths_crossing_one_crease_line_at_different_edges_have_one_key() {
        // The fan with a seventh corner m (v6) on `x = -1` between w1 (v7) and w2 (v5): from
        // p (v1) across (w1, m) and on below v, or across (m, w2) and on above v, to e1 (v9).
        // With the fan flat, the crease line w1 m w2 is straight: one unfolding across it.
        let six = crate::mmp::strips::tests::SIX;
        let seven = [six[0], six[1], six[2], [-1.0, 0.0], six[3], six[4], six[5]];
        let key =
            |lift, faces: &[u32]| key_on_fan((lift, &seven, &[[7, 6, 1], [6, 5, 1]]), faces, 9);
        let (below, above): (&[u32], &[u32]) = (&[7, 3, 4, 5], &[8, 2, 1, 0, 6]);
        assert_eq!(key(0.0, below), key(0.0, above));
        assert_ne!(key(0.25, below), key(0.25, above));
    }

    #[test]
    fn strips_of_different_shapes_have_different_keys() {
        // The same grid with every vertex moved by its own amount: no two strips congruent.
        let grid = shapes::grid(4, 4, 1.0, 1.0);
        let positions = grid
            .positions()
            .iter()
            .enumerate()
            .map(|(i, p)| p + glam::DVec3::new(0.01 * i as f64, 0.003 * (i * i) as f64, 0.0))
            .collect();
        let moved = TriMesh::new(positions, grid.faces().to_vec()).expect("a mesh");
        let keys = keys_across_edges(&moved);
        let distinct: HashSet<&Vec<u32>> = keys.iter().map(|(k, _)| k).collect();
        assert_eq!(distinct.len(), keys.len());
    }
}
