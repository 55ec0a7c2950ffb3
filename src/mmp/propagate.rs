//! Continuous Dijkstra over wedges [SSK+05 §4, LZT §2]: the options and entry points of a
//! propagation, and the engine that emits the wedges of sources and pseudo-sources and
//! propagates each wedge across the face beyond its edge. The queue and the vertices' distances
//! are the [`front`](super::front); the wedges on the edges, intersected as they arrive, are the
//! [`wedge_lists`](super::wedge_lists).

use super::bounds::SharedBounds;
use super::field::GeodesicField;
use super::flat_region::RegionImage;
use super::front::{acts_as_pseudo_source, EventKind, Front};
use super::paths::{continued, CongruentPaths, Path};
use super::planar::Planar;
use super::provenance::{keeps_values, Anchor, Light, Provenance};
use super::rounded_gap::{distance_through, end_beside, gap_fraction};
use super::sectors::{split, Sector};
use super::shadow::Shadow;
use super::source::{PointError, SurfacePoint};
use super::stats::Stats;
use super::stop::StopPoints;
use super::strips::{OfferedWedges, Strip, Through};
use super::unfold::{FaceLayout, Unfolding};
use super::wedge::{PseudoSource, Wedge, WedgeFields};
use super::wedge_lists::{Arrivals, Due, WedgeLists, WedgeRef};
use crate::mesh::{EdgeId, FaceId, Side, SourceId, TriMesh, VertexId};
use crate::scalar::{Scalar, Sign, Site, SourceDistance, FRONT_MARGIN};
use std::cmp::Ordering;
use std::sync::Arc;
use std::time::Instant;

/// Options of a propagation.
#[derive(Clone, Debug, Default, PartialEq)]
#[non_exhaustive]
pub struct PropagateOptions {
    /// Stop once every point closer than this is final; farther points are reported as
    /// unreachable (+infinity). `None` propagates over the whole surface.
    pub max_distance: Option<f64>,
    /// Keep a log of every meeting of two wedges on an edge ([`Stats::decisions`]), for
    /// comparing backends decision by decision.
    pub record_decisions: bool,
    /// The exact backend's precision cap for this run, in bits (clamped into
    /// [`MIN_PRECISION_CAP`](crate::scalar::exact::MIN_PRECISION_CAP)`..=`
    /// [`MAX_PRECISION_CAP`](crate::scalar::exact::MAX_PRECISION_CAP)); it stays the running
    /// thread's cap after the run, for queries. `None` keeps the thread's cap
    /// ([`set_precision_cap`](crate::scalar::exact::set_precision_cap), by default
    /// [`DEFAULT_PRECISION_CAP`](crate::scalar::exact::DEFAULT_PRECISION_CAP)). Other backends
    /// ignore it.
    pub precision_cap: Option<u32>,
    /// Stop as soon as the distance of every one of these points is final (`stop_points` in
    /// geometry-central and Kirsanov's MMP). Then the distances of the stop points, and of every
    /// vertex no farther than the farthest of them, are those of the full run: for vertices
    /// the very same values, since the run is the full run's first events, in the same order;
    /// for points in faces or on edges the same up to the rounding of the query. A path traced
    /// back from a stop point ([`GeodesicField::trace_back`]) crosses only nearer wedges, final
    /// by then: from the same source, of the same length (`tests/stop_points.rs`: the very
    /// path of the full run on regular meshes, and one as long on degenerate ones). Other
    /// vertices hold an upper bound (the length of some path, not necessarily the shortest) or
    /// `f64::INFINITY`, and [`Stats::stopped_at_stop_points`] says that the run stopped early.
    /// A point is final once the front of the propagation (the smallest distance waiting in
    /// its queue) exceeds `d(c) + |p - c|` for a corner `c` of the simplex holding the point,
    /// as decided by the backend; the front is the queue's key, the `f64` value of a distance.
    /// A stop point that cannot be reached lets the run go on to its end. Empty: no early stop.
    pub stop_points: Vec<SurfacePoint>,
    /// Threads a run may use (0 and 1: the calling thread only). Two or more split the
    /// directions of a single source vertex into two sectors propagated at once, on two
    /// threads, where only vertex distances are wanted
    /// ([`propagate_vertices`](crate::propagate_vertices)) and there are no stop points; the
    /// distances are the shorter of the two sectors', equal to a one-thread run's up to the
    /// last bits where two geodesics from different sectors tie (see `sectors.rs`).
    pub threads: usize,
    /// Only vertex distances are wanted ([`propagate_vertices`](crate::propagate_vertices)):
    /// the wedges of an edge are given up as soon as no later wedge can win a point of it.
    pub(crate) vertices_only: bool,
}

impl PropagateOptions {
    /// Stops the propagation at the given distance.
    pub fn with_max_distance(mut self, d: f64) -> Self {
        self.max_distance = Some(d);
        self
    }

    /// Stops the propagation once the distances of these points are final (see
    /// [`stop_points`](Self::stop_points)).
    pub fn with_stop_points(mut self, points: impl IntoIterator<Item = SurfacePoint>) -> Self {
        self.stop_points = points.into_iter().collect();
        self
    }

    /// Keeps a log of every meeting of two wedges (see
    /// [`record_decisions`](Self::record_decisions)).
    pub fn with_recorded_decisions(mut self) -> Self {
        self.record_decisions = true;
        self
    }

    /// Sets the exact backend's precision cap for the run (see
    /// [`precision_cap`](Self::precision_cap)).
    pub fn with_precision_cap(mut self, bits: u32) -> Self {
        self.precision_cap = Some(bits);
        self
    }

    /// Lets the run use up to `threads` threads (see [`threads`](Self::threads)).
    pub fn with_threads(mut self, threads: usize) -> Self {
        self.threads = threads;
        self
    }
}

/// Progress of a running propagation, reported to the callback of [`propagate_with_progress`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Progress {
    /// Vertices with a finite distance so far.
    pub vertices_reached: usize,
    /// Vertices in the mesh.
    pub vertex_count: usize,
    /// Distance of the propagation front.
    pub front: f64,
}

/// Computes the geodesic distance field from `sources` by propagating wedges.
///
/// Every source and stop point is validated first ([`SurfacePoint::validated`]). The result answers distance,
/// nearest-source and back-trace queries; points that cannot be reached (another component, a
/// vertex no face uses, beyond `max_distance`) are at distance `f64::INFINITY`.
///
/// # Errors
/// [`PointError`] if there is no source, a source or stop point is not a point of the mesh,
/// the maximum distance is negative or NaN, or the mesh has edges shorter than `2^-500` of its
/// size and `S` cannot measure them ([`PointError::BeyondFloatRange`]: `f64` and
/// [`Adaptive`](crate::scalar::Adaptive); the exact backend can).
///
/// # Example
/// ```
/// use exact_geodesics::{mesh::shapes, propagate, PropagateOptions, SurfacePoint, VertexId};
/// let cube = shapes::cube();
/// let field = propagate::<f64>(&cube, &[SurfacePoint::Vertex(VertexId(0))], &PropagateOptions::default())?;
/// let opposite = (0..8).map(|v| field.vertex_distance(VertexId(v))).fold(0.0, f64::max);
/// assert!((opposite - 5f64.sqrt()).abs() < 1e-12);
/// # Ok::<(), exact_geodesics::PointError>(())
/// ```
pub fn propagate<'m, S: Scalar>(
    mesh: &'m TriMesh,
    sources: &[SurfacePoint],
    options: &PropagateOptions,
) -> Result<GeodesicField<'m, S>, PointError> {
    propagate_with_progress(mesh, sources, options, |_| {})
}

/// [`propagate`] on a shared mesh: the field holds the `Arc` instead of a borrow, so it can be
/// stored beside the mesh, cloned, sent to other threads and queried for as long as it lives.
///
/// # Errors
/// As [`propagate`].
///
/// # Example
/// ```
/// use exact_geodesics::{mesh::shapes, propagate_shared, PropagateOptions, SurfacePoint, VertexId};
/// use std::sync::Arc;
/// let cube = Arc::new(shapes::cube());
/// let field = propagate_shared::<f64>(&cube, &[SurfacePoint::Vertex(VertexId(0))], &PropagateOptions::default())?;
/// let worker = std::thread::spawn(move || field.vertex_distance(VertexId(6)));
/// assert!((worker.join().unwrap() - 5f64.sqrt()).abs() < 1e-12);
/// # Ok::<(), exact_geodesics::PointError>(())
/// ```
pub fn propagate_shared<S: Scalar>(
    mesh: &Arc<TriMesh>,
    sources: &[SurfacePoint],
    options: &PropagateOptions,
) -> Result<GeodesicField<'static, S>, PointError> {
    let field = propagate::<S>(mesh, sources, options)?;
    Ok(field
        .into_shared(Arc::clone(mesh))
        .expect("propagated on this mesh"))
}

/// [`propagate`], calling `progress` now and then with how far it got.
///
/// # Errors
/// As [`propagate`].
pub fn propagate_with_progress<'m, S: Scalar>(
    mesh: &'m TriMesh,
    sources: &[SurfacePoint],
    options: &PropagateOptions,
    mut progress: impl FnMut(&Progress),
) -> Result<GeodesicField<'m, S>, PointError> {
    if sources.is_empty() {
        return Err(PointError::NoSource);
    }
    if let Some(max_distance) = options.max_distance.filter(|d| d.is_nan() || *d < 0.0) {
        return Err(PointError::MaxDistance { max_distance });
    }
    let unresolved = &mesh.validation().float_unresolved_edges;
    if !unresolved.is_empty() && !S::measures_below_float_resolution() {
        return Err(PointError::BeyondFloatRange {
            edge: unresolved[0].0,
            count: unresolved.len(),
        });
    }
    let sources = sources
        .iter()
        .map(|p| p.validated(mesh))
        .collect::<Result<Vec<_>, _>>()?;
    let stop_points = options
        .stop_points
        .iter()
        .map(|p| p.validated(mesh))
        .collect::<Result<Vec<_>, _>>()?;
    let started = Instant::now();
    // Not where the run proves ties by congruent paths (`paths.rs`, `strips.rs`): those
    // proofs take every wedge of a source to be in the one run.
    let (sectors, unfolding) = match sources[..] {
        [SurfacePoint::Vertex(v)]
            if options.threads > 1
                && mesh.validation().edge_length_span <= SECTOR_SPAN
                && options.vertices_only
                && stop_points.is_empty()
                && !keeps_values::<S>() =>
        {
            std::thread::scope(|scope| {
                let sectors = scope.spawn(|| split(mesh, v));
                let unfolding = Unfolding::new(mesh, &sources);
                (sectors.join().expect("the sectors"), unfolding)
            })
        }
        _ => (None, Unfolding::new(mesh, &sources)),
    };
    let unfolding = Arc::new(unfolding);
    let sectors = sectors.and_then(|s| {
        let run = (sources.clone(), Arc::clone(&unfolding));
        propagate_sectors(mesh, options, run, s, SECTOR_LIST_LIMIT, &mut progress)
    });
    let engine = match sectors {
        Some(merged) => merged,
        None => {
            let mut engine = Engine::new(mesh, options, (sources, &stop_points), unfolding, None);
            engine.propagate(&mut progress);
            engine
        }
    };
    Ok(engine.finish(started))
}

/// The engines of two sectors of a source vertex's directions run at once, merged; `None` if
/// one gave up, an edge of its own holding more than `list_limit` wedges.
fn propagate_sectors<'m, S: Scalar>(
    mesh: &'m TriMesh,
    options: &PropagateOptions,
    (sources, unfolding): (Vec<SurfacePoint>, Arc<Unfolding<S>>),
    [first, second]: [Sector; 2],
    list_limit: usize,
    progress: &mut impl FnMut(&Progress),
) -> Option<Engine<'m, S>> {
    let extent = mesh
        .positions()
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max);
    let bounds = Arc::new(SharedBounds::new(
        mesh.vertex_count(),
        extent * mesh.unit_scale(),
    ));
    let engine = |sector| {
        let (unfolding, sector) = (Arc::clone(&unfolding), Some((sector, &bounds)));
        let mut engine = Engine::new(mesh, options, (sources.clone(), &[]), unfolding, sector);
        engine.list_limit = list_limit;
        engine
    };
    let (engine, other) = std::thread::scope(|scope| {
        let worker = scope.spawn(|| {
            let mut other = engine(second);
            other.propagate(&mut |_: &Progress| {});
            other
        });
        let mut mine = engine(first);
        mine.propagate(progress);
        (mine, worker.join().expect("the other sector's propagation"))
    });
    (!engine.gave_up && !other.gave_up).then(|| engine.merged(other))
}

/// The most wedges an edge's list may hold in a sector's engine: beyond, it gives up, and the
/// run starts again on one engine. The other sector's paths are known to it only at vertices
/// (`bounds.rs`), which on some meshes leaves images of the source going round and round
/// unbeaten, one more wedge on an edge each turn (see [`SECTOR_SPAN`]), where one engine trims
/// them on the edge at once. A guard for such runs on meshes within the span: without the
/// span's limit, the 98-face mesh that took 187 s gave up after 1.6 s. No run of the shared
/// models or of icosphere level 6 holds more than 182 wedges on an edge. Checked every 8,192
/// events, off the event loop's path.
const SECTOR_LIST_LIMIT: usize = 1 << 14;

/// The largest span of edge lengths (longest over shortest) on which a run splits into two
/// sectors. A sector's engine trims its wedges against the other's only by the vertices'
/// distances, not on the edges: along an edge 3e8 long, images of the source that wound round
/// a far vertex, each turn a fraction of a unit longer than the direct one, lost to no vertex
/// path and went round some 60k times (a 12-face mesh of the degeneracy corpus with a span of
/// 1.1e9: 61,705 wedges against 25 on one thread, and minutes on a 98-face one). On one
/// engine the direct image's wedge trims them on their edge at once. The shared models span
/// at most 3.6e3; no case of the corpus below this span is slow on two sectors.
const SECTOR_SPAN: f64 = (1u64 << 20) as f64;

/// What a wedge of a (pseudo-)source keeps, if given: its distances at its edge's vertices, its
/// pseudo-source in the frame of a flat region, and its path.
type SourceKept<S> = (
    Option<[<S as Scalar>::Kept<S>; 2]>,
    Option<RegionImage<S>>,
    <S as Scalar>::Kept<Path>,
    Option<Strip>,
);

/// A wedge about to be born on an edge: the edge, the ends of its range (unsorted), its
/// pseudo-source there, and what it keeps of its construction.
type Child<S> = (EdgeId, [S; 2], Planar<S>, Provenance<S>);

/// A running propagation: the wedges on the edges and the front of continuous Dijkstra.
struct Engine<'m, S: Scalar> {
    mesh: &'m TriMesh,
    /// The unfolding of the mesh, shared by the engines of a run's sectors.
    unfolding: Arc<Unfolding<S>>,
    sources: Vec<SurfacePoint>,
    wedges: WedgeLists<S>,
    front: Front<S>,
    max_distance: f64,
    /// The exact backend's precision cap asked for ([`PropagateOptions::precision_cap`]).
    precision_cap: Option<u32>,
    stop: Option<StopPoints<S>>,
    /// One expression per vertex distance of congruent paths, where the run proves ties by
    /// congruence (see `paths.rs`).
    paths: Option<CongruentPaths<S>>,
    /// The wedges offered through each strip, where the run keeps paths (see `strips.rs`).
    offered: Option<OfferedWedges>,
    /// The sector of the source's directions this engine propagates, and the distances the
    /// other sector's engine has found, where two propagate at once (see `sectors.rs`).
    sector: Option<(Sector, Arc<SharedBounds>)>,
    /// The most wedges an edge may hold before the engine gives up its sector (see
    /// [`SECTOR_LIST_LIMIT`]); whether it did.
    list_limit: usize,
    gave_up: bool,
    stats: Stats,
}

/// The front and what it needs of the mesh, told by the edge lists of the wedges they queue
/// and the vertices they reach.
struct Reach<'a, S: Scalar> {
    mesh: &'a TriMesh,
    unfolding: &'a Unfolding<S>,
    sources: &'a [SurfacePoint],
    front: &'a mut Front<S>,
    paths: Option<&'a CongruentPaths<S>>,
}

impl<S: Scalar> Arrivals<S> for Reach<'_, S> {
    fn queue(&mut self, at: WedgeRef, wedge: &impl WedgeFields<S>) {
        self.front.push_wedge(at, wedge);
    }

    fn reach(&mut self, v: VertexId, d: S, (w, kept): (&Wedge<S>, &Provenance<S>)) {
        let surface = (self.mesh, self.unfolding, self.sources);
        let path = continued::<S>(&kept.path, |p| p.to(v));
        self.front.offer_vertex(surface, v, (d, path), (w, true));
    }

    /// Only stretches wider than the gaps rounding leaves ([`gap_fraction`]): beside a
    /// crossing, two distances are within rounding of each other on a narrow stretch, through
    /// which the other image sees nothing that its neighbours do not (from v0 of
    /// stanford_bunny, f64 decided 212k stretches wider than the edge's resolution as ties;
    /// 3 stretches pass this test).
    fn tied(
        &mut self,
        (w, kept): (&Wedge<S>, &Provenance<S>),
        [lo, hi]: [&S; 2],
        other: &SourceDistance<S>,
    ) {
        let length = self.unfolding.length(w.edge).to_f64();
        if (hi.clone() - lo).to_f64() <= gap_fraction(self.mesh) * length {
            return;
        }
        let middle = (lo.clone() + hi) * S::from_f64(0.5);
        if S::near_tie(&w.distance_function(), other, &middle) {
            let mut tied = w.clone();
            tied.b0 = lo.clone();
            tied.b1 = hi.clone();
            self.front.push_tied(tied, kept.clone());
        }
    }

    fn congruence(&self) -> Option<(&TriMesh, &CongruentPaths<S>)> {
        Some((self.mesh, self.paths?))
    }
}

impl<'m, S: Scalar> Engine<'m, S> {
    fn new(
        mesh: &'m TriMesh,
        options: &PropagateOptions,
        (sources, stop_points): (Vec<SurfacePoint>, &[SurfacePoint]),
        unfolding: Arc<Unfolding<S>>,
        sector: Option<(Sector, &Arc<SharedBounds>)>,
    ) -> Self {
        let stop = StopPoints::new(mesh, &unfolding, stop_points);
        let max_distance = options
            .max_distance
            .map_or(f64::INFINITY, |d| unfolding.scaled_from_model(d));
        let paths = keeps_values::<S>()
            .then(|| {
                CongruentPaths::new(mesh, &sources)
                    .map(|paths| paths.with_regions(mesh, unfolding.flat_regions()))
            })
            .flatten();
        let offered = paths
            .as_ref()
            .map(|_| OfferedWedges::new(mesh, unfolding.flat_regions()));
        Engine {
            mesh,
            unfolding,
            sources,
            paths,
            offered,
            wedges: WedgeLists::new(
                mesh.edge_count(),
                options.record_decisions,
                options.vertices_only,
            ),
            front: Front::new(mesh, sector.as_ref().map(|s| Arc::clone(s.1))),
            max_distance,
            precision_cap: options.precision_cap,
            stop,
            list_limit: usize::MAX,
            gave_up: false,
            sector: sector.map(|(sector, bounds)| (sector, Arc::clone(bounds))),
            stats: Stats::default(),
        }
    }

    /// Emits the sources' wedges and propagates them to the end, on the calling thread, whose
    /// backend state (precision cap, decision counts) it sets.
    fn propagate(&mut self, progress: &mut impl FnMut(&Progress)) {
        S::begin_run(self.precision_cap);
        S::take_counts();
        for k in 0..self.sources.len() {
            let point = self.sources[k];
            self.emit_source(SourceId(k as u32), &point);
        }
        self.run(progress);
        self.stats.sectors = 1;
        self.stats.backend = S::take_counts();
        S::locate(Site::ANYWHERE);
    }

    /// Whether a length known of a path to `v` by the other sector's engine (see `bounds.rs`)
    /// beats `d` there.
    fn beaten_at_vertex(&self, v: VertexId, d: &S) -> bool {
        let bound = self.sector.as_ref().and_then(|(_, b)| b.beyond(v));
        bound.is_some_and(|b| S::from_f64(b).compare_distance(d) == Ordering::Less)
    }

    /// Gives up the wedges of edge `e` if the front, at `at`, is past them
    /// ([`WedgeLists::close`]); an edge left with a gap is asked again once the front is past
    /// its ends' paths along it. Out of line: inlined, it changed how the event loop around
    /// it was compiled (7 % more instructions on rocker_arm).
    #[inline(never)]
    fn close_edge(&mut self, e: EdgeId, at: f64) {
        let ends = self.unfolding.ends(self.mesh, e);
        let bounds = self.sector.as_ref().map(|(_, b)| &**b);
        let known = || ends.map(|v| known_at(&self.front, bounds, v));
        let length = self.unfolding.length(e);
        if self.wedges.close(e, at, length, known) {
            return;
        }
        let retry = known()
            .iter()
            .flatten()
            .map(|d| (d.to_f64() + length.to_f64()) * FRONT_MARGIN * FRONT_MARGIN)
            .fold(f64::INFINITY, f64::min);
        if retry > at && retry.is_finite() {
            self.front.push_closing(e, retry);
        }
    }

    /// Whether the other sector's paths to the ends of the wedge's edge beat it throughout
    /// ([`Self::beaten_from_ends`]).
    fn beaten_by_other_sector(&self, w: &Wedge<S>) -> bool {
        let Some((_, bounds)) = &self.sector else {
            return false;
        };
        self.beaten_from_ends(w, |v| bounds.beyond(v).map(S::from_f64))
    }

    fn run(&mut self, progress: &mut impl FnMut(&Progress)) {
        let mut events = 0u64;
        while let Some(event) = self.front.pop() {
            let key = event.key();
            while let Some(c) = self.front.pop_closing(key) {
                self.close_edge(c.what, c.key());
            }
            if key > self.max_distance {
                break;
            }
            if self.stop.is_some() && self.stops_here(key) {
                self.stats.stopped_at_stop_points = true;
                break;
            }
            events += 1;
            if events % 8192 == 0 {
                if self.wedges.longest() > self.list_limit {
                    self.gave_up = true;
                    break;
                }
                progress(&Progress {
                    vertices_reached: self.reached(),
                    vertex_count: self.mesh.vertex_count(),
                    front: self.unfolding.to_model(key),
                });
            }
            match event.what {
                EventKind::Wedge(at) => match self.wedges.due(
                    at,
                    key,
                    self.unfolding.length(at.edge()),
                    &mut self.stats,
                ) {
                    Due::Stale => {}
                    Due::Later(key) => self.front.requeue(event, key),
                    Due::Now(wedge, kept) => {
                        if self.beaten_by_other_sector(&wedge) {
                            self.stats.pruned_by_other_sector += 1;
                        } else {
                            self.stats.wedges_propagated += 1;
                            self.propagate_wedge(&wedge, &kept);
                        }
                        if let Some(key) = self.wedges.closing_key(at.edge()) {
                            self.front.push_closing(at.edge(), key);
                        }
                    }
                },
                EventKind::Tied(i) => {
                    if let Some((wedge, kept)) = self.front.take_tied(i) {
                        self.stats.tied_wedges_propagated += 1;
                        self.propagate_wedge(&wedge, &kept);
                    }
                }
                EventKind::Vertex(v) => {
                    if let Some((sigma, source, path)) = self.front.take_emission(v) {
                        if self.beaten_at_vertex(v, &sigma) {
                            self.stats.pruned_by_other_sector += 1;
                            continue;
                        }
                        self.stats.pseudo_source_emissions += 1;
                        let shadow = self
                            .front
                            .arrival(v)
                            .and_then(|a| Shadow::new(self.mesh, &self.unfolding, v, a));
                        let from = (PseudoSource::Vertex(v), source, shadow);
                        self.emit_from_vertex(v, (sigma, path), from);
                    }
                }
            }
        }
        progress(&Progress {
            vertices_reached: self.reached(),
            vertex_count: self.mesh.vertex_count(),
            front: self.unfolding.to_model(self.max_distance.min(f64::MAX)),
        });
    }

    /// Vertices with a distance so far, by this engine or the other sector's.
    fn reached(&self) -> usize {
        match &self.sector {
            Some((_, bounds)) => bounds.reached(),
            None => self.front.reached(),
        }
    }

    /// Whether every stop point is final with the front at `key`.
    #[inline]
    fn stops_here(&mut self, key: f64) -> bool {
        let front = &self.front;
        self.stop.as_mut().is_some_and(|stop| {
            stop.all_final(key, |v| front.vertex(v).map(|d| (&d.distance, d.approx)))
        })
    }

    /// This sector's engine with the other's results: at each vertex the shorter distance
    /// (this one's on a tie), and both engines' counts.
    fn merged(mut self, other: Self) -> Self {
        self.stats.absorb(other.stats);
        self.stats.peak_queue += other.front.peak_queue();
        self.front.take_shorter(other.front);
        self
    }

    fn finish(mut self, started: Instant) -> GeodesicField<'m, S> {
        self.stats.propagation_seconds = started.elapsed().as_secs_f64();
        self.stats.peak_queue += self.front.peak_queue();
        let vertices = self.front.into_vertices(self.max_distance);
        GeodesicField::new(
            self.mesh,
            self.unfolding,
            self.sources,
            self.wedges.into_edge_wedges(),
            vertices,
            self.stats,
        )
    }

    /// Inserts a wedge on its edge, intersecting it with the wedges there.
    fn insert(&mut self, mut w: Wedge<S>, mut kept: Provenance<S>) {
        let e = w.edge;
        // One expression for images through congruent strips (see `paths.rs`); in a flat
        // region the region's frame is the image's construction (see `flat_region.rs`). The
        // keys of the images that cast the shadow lines of the anchored ends, the wedge's and
        // its anchors' lights', tell those lines apart.
        if let (Some(paths), Some(path)) = (self.paths.as_mut(), S::kept(&kept.path)) {
            let (mesh, edge) = (self.mesh, (e, self.unfolding.ends(self.mesh, e)));
            let anchored = (0..2).any(|i| kept.anchor(i).is_some());
            let key = (anchored || S::kept(&kept.image).is_none())
                .then(|| paths.image_key(mesh, edge, &path))
                .flatten();
            if let (Some(key), None) = (key, S::kept(&kept.image)) {
                let at = Planar {
                    x: w.source_x,
                    y: w.source_y,
                };
                let image = paths.image(key, at);
                (w.source_x, w.source_y) = (image.x, image.y);
            }
            kept = kept.keyed(key, |p| paths.image_key(mesh, edge, p));
        }
        if let (Some(offered), Some(strip)) = (self.offered.as_mut(), S::kept(&kept.strip)) {
            let p = match w.pseudo_source {
                PseudoSource::Vertex(v) => Some(v),
                PseudoSource::Source(k) => match self.sources[k.index()] {
                    SurfacePoint::Vertex(v) => Some(v),
                    _ => None,
                },
            };
            let first = self.unfolding.ends(self.mesh, e)[0];
            if p.is_some_and(|p| offered.offered_before(&strip, (w.source, p), (e, first))) {
                self.stats.wedges_offered_again += 1;
                return;
            }
        }
        let edge = (self.unfolding.length(e), self.unfolding.ends(self.mesh, e));
        let mut reach = Reach {
            mesh: self.mesh,
            unfolding: &self.unfolding,
            sources: &self.sources,
            front: &mut self.front,
            paths: self.paths.as_ref(),
        };
        let run = (&mut reach, self.offered.as_mut());
        self.wedges.insert((w, kept), edge, &mut self.stats, run);
    }

    /// Lowers a vertex's distance if `distance` (the length of `path`, if kept) is better
    /// ([`Front::improve_vertex`]).
    fn improve_vertex(&mut self, v: VertexId, distance: S, reached: (SourceId, S::Kept<Path>)) {
        let surface = (self.mesh, &*self.unfolding);
        self.front.improve_vertex(surface, v, distance, reached);
    }

    /// A wedge's distance `d` at the vertex `v` (the length of `path`, if kept), offered to it
    /// ([`Front::offer_vertex`]; `straight`: whether the way is straight from the wedge's
    /// pseudo-source); whether it lowered the vertex's distance.
    fn offer_vertex(&mut self, v: VertexId, d: (S, S::Kept<Path>), w: (&Wedge<S>, bool)) -> bool {
        let surface = (self.mesh, &*self.unfolding, self.sources.as_slice());
        self.front.offer_vertex(surface, v, d, w)
    }

    /// The path that starts at source vertex `v`, where the run keeps paths.
    fn source_path(&self, v: VertexId) -> S::Kept<Path> {
        match self.paths {
            Some(_) => S::keep(|| Path::at_source(v)),
            None => Default::default(),
        }
    }

    /// The initial wedges of a source [SSK+05 §4]: on every edge of every face containing it.
    fn emit_source(&mut self, k: SourceId, point: &SurfacePoint) {
        let source = PseudoSource::Source(k);
        match *point {
            SurfacePoint::Vertex(v) => self.emit_source_vertex(v, k),
            // A point of an edge whose ends coincide is both of them.
            SurfacePoint::Edge { edge, .. } if self.unfolding.is_zero_length(edge) => {
                self.emit_source_vertex(self.mesh.edge(edge).vertices[0], k)
            }
            SurfacePoint::Edge { edge, t } => {
                let on_edge = Planar {
                    x: self.unfolding.at_fraction(edge, t),
                    y: S::zero(),
                };
                self.add_wedge(
                    edge,
                    on_edge,
                    Side::FIRST,
                    S::zero(),
                    (source, k),
                    (None, None, Default::default(), None),
                );
                let p = self.unfolding.position(self.mesh, point);
                let faces: Vec<FaceId> = self.mesh.edge_faces(edge).collect();
                self.emit_from_point(&p, faces, Vec::new(), S::zero(), source, k);
            }
            SurfacePoint::Face { face, .. } => {
                let p = self.unfolding.position(self.mesh, point);
                self.emit_from_point(&p, vec![face], Vec::new(), S::zero(), source, k);
            }
        }
    }

    fn emit_source_vertex(&mut self, v: VertexId, k: SourceId) {
        let path = self.source_path(v);
        self.improve_vertex(v, S::zero(), (k, path.clone()));
        self.emit_from_vertex(v, (S::zero(), path), (PseudoSource::Source(k), k, None));
        self.front.emitted(v);
    }

    /// Wedges at `sigma` from the point `p` onto every edge of `faces` (which contain it in
    /// their closure). Where `p` lies inside one of those edges (an edge through a degenerate
    /// face), the face beyond that edge contains it too and gets its wedges, and so on; faces
    /// in `done` are left out. A corner of those faces at `p` itself gets distance `sigma`.
    fn emit_from_point(
        &mut self,
        p: &[S; 3],
        mut faces: Vec<FaceId>,
        mut done: Vec<FaceId>,
        sigma: S,
        source: PseudoSource,
        k: SourceId,
    ) {
        let mesh = self.mesh;
        done.extend(faces.iter().copied());
        while let Some(f) = faces.pop() {
            // A corner at the point's very place (across degenerate faces, not joined to it
            // by an edge) is that point: its distance is sigma, not a rounded copy of it.
            for c in mesh.face(f) {
                let q = self.unfolding.position(mesh, &SurfacePoint::Vertex(c));
                if (0..3).all(|i| q[i].compare(&p[i]) == Ordering::Equal) {
                    self.improve_vertex(c, sigma.clone(), (k, Default::default()));
                }
            }
            for g in mesh.face_edges(f) {
                let side = mesh.side_of(g, f).expect("edge of the face");
                // An edge of length zero carries no wedge.
                let Some(at) = self.unfolding.planar(mesh, g, p) else {
                    continue;
                };
                if self.unfolding.is_inside(g, &at) {
                    for beyond in mesh.edge_faces(g) {
                        if !done.contains(&beyond) {
                            done.push(beyond);
                            faces.push(beyond);
                        }
                    }
                }
                let kept = (None, None, Default::default(), None);
                self.add_wedge(g, at, side, sigma.clone(), (source, k), kept);
            }
        }
    }

    /// The wedges of a vertex acting as a (pseudo-)source [MMP87, SSK+05 §4]: across the edge
    /// opposite it in each incident face, and along each incident edge. A vertex lying inside
    /// its opposite edge (the middle corner of a degenerate face) is a point of that edge as
    /// well, and sends wedges into the face beyond it as a source on an edge does.
    fn emit_from_vertex(
        &mut self,
        v: VertexId,
        (sigma, path): (S, S::Kept<Path>),
        (source, k, shadow): (PseudoSource, SourceId, Option<Shadow>),
    ) {
        let mesh = self.mesh;
        let mut beyond = Vec::new();
        // The distance through the vertex to each neighbour, one value for every wedge of the
        // vertex that reaches the neighbour (kept by number types that keep values), and one
        // for every congruent path where the run keeps paths.
        let (unfolding, paths) = (&self.unfolding, &mut self.paths);
        let through: Vec<(VertexId, S::Kept<S>)> = mesh
            .vertex_edges(v)
            .iter()
            .filter_map(|&g| {
                let other = mesh.edge(g).other(v)?;
                let length = || sigma.clone() + unfolding.length(g);
                let path = S::kept(&path).map(|p| p.along(g).to(other));
                Some((
                    other,
                    S::keep(|| match (paths.as_mut(), path) {
                        (Some(paths), Some(path)) => paths.length(mesh, &path, length),
                        _ => length(),
                    }),
                ))
            })
            .collect();
        let to = |u: VertexId| -> S::Kept<S> {
            if u == v {
                return S::keep(|| sigma.clone());
            }
            through
                .iter()
                .find(|(w, _)| *w == u)
                .map(|(_, d)| d.clone())
                .unwrap_or_default()
        };
        // An exactly flat vertex bends no geodesic ([`TriMesh::is_flat_vertex`]; only one on
        // the boundary acts as a pseudo-source): across its faces its wedges would only tie
        // with the wedges passing it, on its shadow lines, and leave slivers there. Along its
        // edges they carry its distance on the boundary line, where a float backend's rays
        // from farther back graze the boundary.
        let across = matches!(source, PseudoSource::Source(_)) || !mesh.is_flat_vertex(v);
        // Only into the vertex's shadow, where it has one (`shadow.rs`).
        let into_face = |f: FaceId| shadow.as_ref().is_none_or(|s| s.meets_face(f));
        let along_edge = |u: VertexId| shadow.as_ref().is_none_or(|s| s.meets_edge(u));
        // A source whose directions two engines split sends wedges only into its engine's
        // sector (see `sectors.rs`).
        let sector = match source {
            PseudoSource::Source(_) => self.sector.as_ref().map(|s| s.0.clone()),
            PseudoSource::Vertex(_) => None,
        };
        for &f in mesh
            .vertex_faces(v)
            .iter()
            .filter(|&&f| across && into_face(f))
        {
            let corner = mesh.face(f).iter().position(|&c| c == v).expect("corner");
            let g = mesh.face_edges(f)[(corner + 1) % 3];
            let side = mesh.side_of(g, f).expect("edge of the face");
            // None only for an opposite edge of length zero, which carries no wedge.
            let Some(at) = self.unfolding.apex_point(mesh, g, side) else {
                continue;
            };
            // A corner on its opposite edge (the middle corner of a degenerate face, as the
            // number type resolves heights) is a point of the edge: a window as narrow as its
            // height would be lost to a rounding backend's resolution, and with it every
            // geodesic through the corner into the faces beyond.
            if self.unfolding.is_inside(g, &at) {
                beyond.extend(mesh.edge_faces(g).filter(|&h| h != f));
            }
            let ends = self.unfolding.ends(mesh, g).map(to);
            // In a flat region, the vertex itself in the region's frame (see `flat_region.rs`).
            let image = self.unfolding.flat_region(f).map(|(regions, region)| {
                RegionImage::new(region, regions.corner(region, v).clone())
            });
            let across = continued::<S>(&path, |p| p.across(f));
            let strip = self.start_strip((v, &path), g, Some(f));
            let kept = (Some(ends), image, across, strip);
            let Some(sector) = &sector else {
                self.add_wedge(g, at, side, sigma.clone(), (source, k), kept);
                continue;
            };
            let first = self.unfolding.ends(mesh, g)[0];
            for [lo, hi] in sector.pieces_of(f, first) {
                let kept = kept.clone();
                let (mut w, kept) =
                    self.wedge_on(g, at.clone(), side, sigma.clone(), (source, k), kept);
                let length = self.unfolding.length(g);
                (w.b0, w.b1) = (S::from_f64(lo) * length, S::from_f64(hi) * length);
                self.insert(w, kept);
            }
        }
        for &g in mesh.vertex_edges(v) {
            let Some(other) = mesh.edge(g).other(v) else {
                continue;
            };
            if sector.as_ref().is_some_and(|s| !s.sends_along(other)) {
                continue;
            }
            if !along_edge(other) {
                continue;
            }
            let x = if self.unfolding.ends(mesh, g)[0] == v {
                S::zero()
            } else {
                self.unfolding.length(g).clone()
            };
            let at = Planar { x, y: S::zero() };
            let ends = self.unfolding.ends(mesh, g).map(to);
            let along = continued::<S>(&path, |p| p.along(g));
            let strip = self.start_strip((v, &path), g, None);
            self.add_wedge(
                g,
                at,
                Side::FIRST,
                sigma.clone(),
                (source, k),
                (Some(ends), None, along, strip),
            );
        }
        if !beyond.is_empty() {
            let p = self.unfolding.position(mesh, &SurfacePoint::Vertex(v));
            let own = mesh.vertex_faces(v).to_vec();
            self.emit_from_point(&p, beyond, own, sigma, source, k);
        }
    }

    /// Adds a wedge covering the whole edge `g` ([`Self::wedge_on`]).
    fn add_wedge(
        &mut self,
        g: EdgeId,
        at: Planar<S>,
        tau: Side,
        sigma: S,
        source: (PseudoSource, SourceId),
        kept: SourceKept<S>,
    ) {
        let (wedge, kept) = self.wedge_on(g, at, tau, sigma, source, kept);
        self.insert(wedge, kept);
    }

    /// A wedge covering the whole edge `g`, of pseudo-source `source` leading back to source
    /// `k`, with its distances at the edge's vertices if given (else its own).
    fn wedge_on(
        &self,
        g: EdgeId,
        at: Planar<S>,
        tau: Side,
        sigma: S,
        (source, k): (PseudoSource, SourceId),
        (at_ends, image, path, strip): SourceKept<S>,
    ) -> (Wedge<S>, Provenance<S>) {
        let at = self.image_on(g, at, strip);
        let wedge = Wedge {
            edge: g,
            b0: S::zero(),
            b1: self.unfolding.length(g).clone(),
            source_x: at.x,
            source_y: at.y,
            sigma,
            tau,
            pseudo_source: source,
            source: k,
        };
        let at_ends = at_ends.unwrap_or_else(|| {
            let d = wedge.distance_function();
            [S::keep(|| d.at(&wedge.b0)), S::keep(|| d.at(&wedge.b1))]
        });
        let kept = Provenance::new(at_ends, [None, None])
            .with_image(image)
            .with_path(path)
            .with_strip(strip);
        (wedge, kept)
    }

    /// Propagates a wedge across the face on the far side of its edge [SSK+05 §4.1, LZT Fig. 2c]:
    /// the rays from the pseudo-source through `b0` and `b1` cut the face's two other edges, and
    /// the pieces between them become new wedges with the same pseudo-source. On an edge shared
    /// by more than two faces, every face but the one the wedge came through is a far side, each
    /// laid out below the edge's line as the one face beyond a manifold edge is.
    fn propagate_wedge(&mut self, w: &Wedge<S>, kept: &Provenance<S>) {
        S::locate(Site {
            edge: Some(w.edge.0),
            what: "propagation across a face",
        });
        if w.source_y.sign() == Sign::Zero {
            return; // A wedge along its edge's line sees nothing beyond the line.
        }
        if let Some(side) = self.unfolding.only_other_side(self.mesh, w.edge, w.tau) {
            self.propagate_into(w, kept, side);
            return;
        }
        for side in self.mesh.sides(w.edge) {
            if side != w.tau {
                self.propagate_into(w, kept, side);
            }
        }
    }

    /// Propagates a wedge across the face on side `side` of its edge, if there is one.
    fn propagate_into(&mut self, w: &Wedge<S>, kept: &Provenance<S>, side: Side) {
        let mesh = self.mesh;
        let Some(layout) = FaceLayout::new(mesh, &self.unfolding, w.edge, side) else {
            return;
        };
        let face = layout.wing.face;
        let s = w.source_point();
        let length = layout.length;
        // In a flat region the image travels in the region's frame, one expression however it
        // crosses the region (see `flat_region.rs`); elsewhere from frame to frame.
        let flat = self.unfolding.flat_region(face);
        let image = flat.map(|(regions, _)| {
            let kept = S::kept(&kept.image);
            regions.image_entering(mesh, (w.edge, face), length, &s, kept.as_ref())
        });
        // The ray through a range end with an anchor starts at the anchor: the same line,
        // from the vertex whose wedges continue it on the other side (see `provenance.rs`).
        // An anchor on the edge's line (a vertex of a degenerate face) gives no direction.
        let anchors = [kept.anchor(0), kept.anchor(1)];
        let from = |i: usize| {
            anchors[i]
                .as_ref()
                .filter(|a| a.point.y.sign() == Sign::Positive)
                .map_or(&s, |a| &a.point)
        };
        // Which way the rays through the range's ends pass the apex decides which edges the
        // children lie on: asked of the number type on the stored values (an orientation),
        // never read off a constructed shadow. Whether the apex itself is reached is asked at
        // the backend's resolution, as for any point of a range.
        let (side0, side1) = (
            layout.ray_side(from(0), &w.b0),
            layout.ray_side(from(1), &w.b1),
        );
        // A range end at an end of the edge is that vertex, which lies on the near edge at
        // t = 0 (v0) or on the far edge at u = 1 (v1): exactly there, not at a constructed
        // quotient equal to it that an exact backend would have to prove equal.
        let at_v = [
            w.b0.sign() == Sign::Zero,
            w.b1.compare(length) == Ordering::Equal,
        ];
        // A range that reaches a vertex of the edge acting as a pseudo-source, with the ray
        // through that vertex passing the apex: the geodesic to the apex goes on straight from
        // the vertex along the face's edge between them, and its length is the vertex's
        // distance and that edge, the expression the vertex's own wedges give the apex (the
        // same path); not one straight line from the image, which no normal form relates to
        // theirs on deep images (a torus's meridians run along its edges through saddles).
        let (unfolding, paths) = (&self.unfolding, &mut self.paths);
        let ends = unfolding.ends(mesh, w.edge);
        let grazed = (0..2)
            .find(|&i| {
                keeps_values::<S>()
                    && at_v[i]
                    && [side0, side1][i] == Ordering::Equal
                    && anchors[i].is_none()
                    && acts_as_pseudo_source::<S>(mesh, ends[i])
            })
            .map(|i| {
                let g = [layout.wing.near, layout.wing.far][i];
                let at_vertex = || {
                    let end = [S::zero(), length.clone()];
                    S::kept(&kept.at_ends[i]).unwrap_or_else(|| w.distance_function().at(&end[i]))
                };
                // The vertex's distance as congruent paths to it have it.
                let to_vertex = continued::<S>(&kept.path, |p| p.to(ends[i]));
                let d = match (paths.as_mut(), S::kept(&to_vertex)) {
                    (Some(paths), Some(p)) => paths.length(mesh, &p, at_vertex),
                    _ => at_vertex(),
                };
                (d + unfolding.length(g), ends[i], g)
            });
        let apex_distance = || {
            if let Some((d, _, _)) = &grazed {
                return d.clone();
            }
            let straight = match (flat, &image) {
                (Some((regions, _)), Some(image)) => {
                    regions.distance(mesh, image, layout.apex_vertex())
                }
                _ => layout.apex_distance(&s),
            };
            straight + &w.sigma
        };
        // The distance at the apex is the length of the wedge's path on across the face; one
        // expression for congruent paths where the run keeps paths.
        let path = continued::<S>(&kept.path, |p| p.across(face));
        let apex_path = match &grazed {
            Some((_, vertex, g)) => continued::<S>(&kept.path, |p| {
                p.to(*vertex).along(*g).to(layout.apex_vertex())
            }),
            None => continued::<S>(&path, |p| p.to(layout.apex_vertex())),
        };
        let paths = &mut self.paths;
        let at_apex = S::keep(
            || match (paths.as_mut(), S::kept(&apex_path), flat, &image) {
                (Some(paths), Some(p), _, _) if grazed.is_some() => {
                    paths.length(mesh, &p, apex_distance)
                }
                (Some(paths), Some(p), Some((_, region)), Some(image)) => {
                    let from = (region, layout.apex_vertex(), &image.point, &w.sigma);
                    paths.length_from(mesh, &p, from, apex_distance)
                }
                (Some(paths), Some(p), _, _) => paths.length(mesh, &p, apex_distance),
                _ => apex_distance(),
            },
        );
        let [at_v0, at_v1] = at_v;
        // In a flat region, the apex whose shadow is a vertex of the edge (the image, that
        // vertex and the apex on one line, as vertices along a straight feature of a CAD model
        // are) is known by the orientation of the three points in the region's frame, not by
        // comparing a constructed shadow with the range's end.
        let shadow_at_vertex = |i: usize| match (flat, &image) {
            (Some((regions, region)), Some(image)) => {
                let p = &image.point;
                let v = regions.corner(region, ends[i]);
                let a = regions.corner(region, layout.apex_vertex());
                S::orientation([&p[0], &p[1]], [&v[0], &v[1]], [&a[0], &a[1]]) == Sign::Zero
            }
            _ => false,
        };
        let shadow = layout.apex_shadow(&s);
        let reach = || layout.shadow_reach(&s, &shadow);
        let apex_inside = (at_v0 && shadow_at_vertex(0))
            || (at_v1 && shadow_at_vertex(1))
            || S::within(&shadow, &w.b0, &w.b1, reach);
        let apex = apex_inside.then(|| {
            let d = S::kept(&at_apex).unwrap_or_else(apex_distance);
            (layout.apex_vertex(), d)
        });
        let zero = S::zero();
        let one = S::from_f64(1.0);
        let clamp = |t: S| S::max_of(&zero, &S::min_of(&one, &t));
        // The anchor of a child's end on the ray through range end `i`, in the frame of edge
        // `g`: the end's anchor carried along (`to`), or, where the ray passes a vertex end
        // of the edge into the face (that vertex's shadow line), the vertex: the apex of the
        // face seen from `g`, the very image its own wedges across `g` start from.
        let anchor_on = |g: EdgeId, i: usize, to: &dyn Fn(&Planar<S>) -> Planar<S>| {
            // Number types that keep no values keep no anchors: for them the anchors stay
            // empty, known so where the children's provenance is built.
            if !keeps_values::<S>() {
                return None;
            }
            // A point kept with the anchor, in `g`'s frame and the region's.
            let carry = |point: &Planar<S>, image: Option<&RegionImage<S>>| {
                let Some((regions, _)) = flat else {
                    return (to(point), None);
                };
                let image = regions.image_entering(mesh, (w.edge, face), length, point, image);
                let length_g = self.unfolding.length(g);
                let at = regions.to_edge(mesh, (g, face), length_g, &image.point);
                (at, Some(image))
            };
            if let Some(a) = &anchors[i] {
                let (point, image) = carry(&a.point, a.image.as_ref());
                let light = a.light.as_ref().map(|l| {
                    let (point, image) = carry(&l.point, l.image.as_ref());
                    let path = l.path.as_ref().map(|p| p.across(face));
                    let key = None;
                    Light {
                        point,
                        image,
                        path,
                        key,
                    }
                });
                return Some(Anchor {
                    point,
                    distance: a.distance.clone(),
                    image,
                    light,
                });
            }
            if !(if i == 0 { at_v0 } else { at_v1 }) {
                return None;
            }
            let distance = S::kept(&kept.at_ends[i])?;
            let point = self.unfolding.apex_point(mesh, g, mesh.side_of(g, face)?)?;
            let vertex = self.unfolding.ends(mesh, w.edge)[i];
            let image = flat.map(|(regions, region)| {
                RegionImage::new(region, regions.corner(region, vertex).clone())
            });
            Some(Anchor {
                point,
                distance,
                image,
                light: None,
            })
        };
        let (near, far) = (layout.wing.near, layout.wing.far);
        let to_near = |p: &Planar<S>| layout.to_near(p);
        let to_far = |p: &Planar<S>| layout.to_far(p);
        // The pseudo-source in the frame of a child's edge, and its image kept for the next face.
        let source_on = |g: EdgeId, to: &dyn Fn(&Planar<S>) -> Planar<S>| match (flat, &image) {
            (Some((regions, _)), Some(image)) => {
                let at = regions.to_edge(mesh, (g, face), self.unfolding.length(g), &image.point);
                (at, Some(image.clone()))
            }
            _ => (to(&s), None),
        };
        // The strip continued across the face to a child's edge. It fixes a child's range end
        // that is a vertex (the apex, or an end of this wedge's edge) or the ray through an end
        // it fixes.
        let strip = S::kept(&kept.strip);
        let (paths, offered) = (&self.paths, &mut self.offered);
        let mut strip_to =
            |g: EdgeId, through: [Through; 2]| match (paths, offered.as_mut(), &strip) {
                (Some(paths), Some(offered), Some(strip)) => {
                    offered.across(paths, mesh, strip, (face, g), through)
                }
                _ => None,
            };
        let [first, second] = self.unfolding.ends(mesh, w.edge);
        let apex_corner = Through::Corner(layout.apex_vertex());
        let mut children: [Option<Child<S>>; 2] = [None, None];
        // An edge of length zero (coincident corners) carries no wedge; its face passes rays
        // on to its other edge unchanged.
        if side0 == Ordering::Less && !layout.near_zero_length {
            let [at_first, at_apex_t] = layout.near_ends();
            let (t0, a0) = if at_v0 {
                (at_first, None)
            } else {
                let a0 = anchor_on(near, 0, &to_near);
                (clamp(layout.near_hit(from(0), &w.b0)), a0)
            };
            let (t1, a1) = if side1 == Ordering::Less {
                let a1 = anchor_on(near, 1, &to_near);
                (clamp(layout.near_hit(from(1), &w.b1)), a1)
            } else {
                (at_apex_t, None)
            };
            let positions = [layout.near_position(&t0), layout.near_position(&t1)];
            let ends = if layout.near_reversed {
                [at_apex.clone(), kept.at_ends[0].clone()]
            } else {
                [kept.at_ends[0].clone(), at_apex.clone()]
            };
            let (at, image) = source_on(near, &to_near);
            let through = [
                if at_v0 {
                    Through::Corner(first)
                } else {
                    Through::Ray(0)
                },
                if side1 != Ordering::Less {
                    apex_corner
                } else {
                    Through::Ray(1)
                },
            ];
            let kept = Provenance::new(ends, [a0, a1])
                .with_image(image)
                .with_path(path.clone())
                .with_strip(strip_to(near, through));
            children[0] = Some((near, positions, at, kept));
        }
        if side1 == Ordering::Greater && !layout.far_zero_length {
            let [at_apex_u, at_second] = layout.far_ends();
            let (u0, a0) = if side0 == Ordering::Greater {
                let a0 = anchor_on(far, 0, &to_far);
                (clamp(layout.far_hit(from(0), &w.b0)), a0)
            } else {
                (at_apex_u, None)
            };
            let (u1, a1) = if at_v1 {
                (at_second, None)
            } else {
                let a1 = anchor_on(far, 1, &to_far);
                (clamp(layout.far_hit(from(1), &w.b1)), a1)
            };
            let positions = [layout.far_position(&u0), layout.far_position(&u1)];
            let ends = if layout.far_reversed {
                [kept.at_ends[1].clone(), at_apex.clone()]
            } else {
                [at_apex.clone(), kept.at_ends[1].clone()]
            };
            let (at, image) = source_on(far, &to_far);
            let through = [
                if side0 != Ordering::Greater {
                    apex_corner
                } else {
                    Through::Ray(0)
                },
                if at_v1 {
                    Through::Corner(second)
                } else {
                    Through::Ray(1)
                },
            ];
            let kept = Provenance::new(ends, [a0, a1])
                .with_image(image)
                .with_path(path.clone())
                .with_strip(strip_to(far, through));
            children[1] = Some((far, positions, at, kept));
        }
        if let Some((v, d)) = apex {
            self.offer_vertex(v, (d, apex_path), (w, true));
        } else if let Some(end) = end_beside(w, || shadow.clone(), length, gap_fraction(mesh)) {
            // An apex in a gap that rounding left beside the range (see `rounded_gap.rs`).
            let d = distance_through(w, end, (layout.apex_x, layout.apex_h));
            if self.offer_vertex(layout.apex_vertex(), (d, apex_path), (w, false)) {
                self.stats.rounded_gap_offers += 1;
            }
        }
        for (g, [p0, p1], at, mut kept) in children.into_iter().flatten() {
            let (b0, b1) = if p0.compare(&p1) == Ordering::Greater {
                kept.anchors.swap(0, 1);
                let strip = S::kept(&kept.strip).map(Strip::swapped);
                kept = kept.with_strip(strip);
                (p1, p0)
            } else {
                (p0, p1)
            };
            let tau = mesh.side_of(g, face).expect("edge of the face");
            let at = self.image_on(g, at, S::kept(&kept.strip));
            let child = Wedge {
                edge: g,
                b0,
                b1,
                source_x: at.x,
                source_y: at.y,
                sigma: w.sigma.clone(),
                tau,
                pseudo_source: w.pseudo_source,
                source: w.source,
            };
            if self.is_dominated_by_vertices(&child) {
                self.stats.wedges_filtered += 1;
            } else if self.beaten_by_other_sector(&child) {
                self.stats.pruned_by_other_sector += 1;
            } else {
                self.insert(child, kept);
            }
        }
    }

    /// The strip of the wedge that vertex `v`, reached along `path`, sends onto edge `g`
    /// (across face `f`, or along `g`), where the run knows wedges offered again (see
    /// `strips.rs`).
    fn start_strip(
        &mut self,
        (v, path): (VertexId, &S::Kept<Path>),
        g: EdgeId,
        across: Option<FaceId>,
    ) -> Option<Strip> {
        let (Some(paths), Some(offered), Some(path)) =
            (&self.paths, self.offered.as_mut(), S::kept(path))
        else {
            return None;
        };
        let first = self.unfolding.ends(self.mesh, g)[0];
        match across {
            Some(f) => offered.first(paths, self.mesh, (v, &path), (f, first)),
            None => offered.along(paths, self.mesh, (v, &path), (g, first)),
        }
    }

    /// The pseudo-source's image `at` on edge `g` as its strip places it: on the edge's
    /// perpendicular bisector, at half the edge's length, where the strip is its own mirror
    /// image (see `strips.rs`), so that every wedge there has that one value.
    fn image_on(&self, g: EdgeId, at: Planar<S>, strip: Option<Strip>) -> Planar<S> {
        match strip {
            Some(strip) if strip.is_symmetric() => Planar {
                x: self.unfolding.length(g).clone() * S::from_f64(0.5),
                y: at.y,
            },
            _ => at,
        }
    }

    /// Whether the wedge lies beyond the maximum distance, or the distances of the ends of its
    /// edge beat it throughout ([`Self::beaten_from_ends`]).
    fn is_dominated_by_vertices(&self, w: &Wedge<S>) -> bool {
        // Without a maximum distance no wedge is beyond it (its smallest distance is not
        // computed for nothing: a square root for most wedges).
        if self.max_distance < f64::INFINITY && w.min_distance().to_f64() > self.max_distance {
            return true;
        }
        self.beaten_from_ends(w, |v| self.front.vertex(v).map(|k| k.distance.clone()))
    }

    /// Whether paths of lengths `known` to the ends of the wedge's edge, continued along the
    /// edge, beat the wedge throughout [SSK+05 §4.2]: along the edge, `d(v0) + t` grows at
    /// slope 1, at least as fast as the wedge's distance, so beating it at `b1` beats it
    /// everywhere (and symmetrically for `v1` at `b0`).
    fn beaten_from_ends(&self, w: &Wedge<S>, known: impl Fn(VertexId) -> Option<S>) -> bool {
        let [v0, v1] = self.unfolding.ends(self.mesh, w.edge);
        let d = w.distance_function();
        if let Some(known) = known(v0) {
            if (known + &w.b1).compare_distance(&d.at(&w.b1)) == Ordering::Less {
                return true;
            }
        }
        if let Some(known) = known(v1) {
            let via = known + &(self.unfolding.length(w.edge).clone() - &w.b0);
            if via.compare_distance(&d.at(&w.b0)) == Ordering::Less {
                return true;
            }
        }
        false
    }
}

/// The shortest length known of a path to `v`: its distance in `front`, or a length that the
/// other sector's engine published in `bounds`.
fn known_at<S: Scalar>(front: &Front<S>, bounds: Option<&SharedBounds>, v: VertexId) -> Option<S> {
    let own = front.vertex(v).map(|k| k.distance.clone());
    match (own, bounds.and_then(|b| b.beyond(v)).map(S::from_f64)) {
        (Some(a), Some(b)) if b.compare_distance(&a) == Ordering::Less => Some(b),
        (a, b) => a.or(b),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::io::{read_from, MeshFormat};
    use crate::mesh::shapes;

    /// Two sectors from vertex `v`, their engines giving up beyond `list_limit` wedges on an
    /// edge: the merged run's counters, or `None` if one gave up.
    fn sectors_from(mesh: &TriMesh, v: u32, list_limit: usize) -> Option<Stats> {
        let sources = vec![SurfacePoint::Vertex(VertexId(v))];
        let sectors = split(mesh, VertexId(v)).expect("two sectors");
        let unfolding = Arc::new(Unfolding::<f64>::new(mesh, &sources));
        let mut options = PropagateOptions::default().with_threads(2);
        options.vertices_only = true;
        let run = (sources, unfolding);
        let merged = propagate_sectors(mesh, &options, run, sectors, list_limit, &mut |_| {});
        merged.map(|engine| engine.stats)
    }

    /// Where images of the source wind round a far vertex unbeaten by the other sector's
    /// vertex distances (a mixed-magnitude mesh of the degeneracy corpus, whose span of edge
    /// lengths keeps it off two sectors otherwise), an edge's list grows past the limit and the
    /// sectors give up; on an icosphere they do not.
    #[test]
    fn sectors_give_up_where_an_edge_list_runs_away() {
        let obj = include_str!("../../tests/data/sector_winding_12.obj");
        let mesh = read_from(
            obj.as_bytes(),
            MeshFormat::Obj,
            "winding",
            &Default::default(),
        )
        .expect("a mesh");
        let unlimited = sectors_from(&mesh, 5, usize::MAX).expect("no limit to reach");
        assert!(
            unlimited.wedges_created > 10_000,
            "{}",
            unlimited.wedges_created
        );
        assert!(sectors_from(&mesh, 5, 1024).is_none());
        let sphere = shapes::icosphere(3);
        let stats = sectors_from(&sphere, 0, SECTOR_LIST_LIMIT).expect("within the limit");
        assert_eq!(stats.sectors, 2);
    }
}
