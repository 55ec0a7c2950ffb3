//! The front of continuous Dijkstra [SSK+05 §4, LZT §2]: the priority queue of events (wedges
//! ordered by the smallest distance each gives, and vertices waiting to act as pseudo-sources)
//! and the best known distance of every vertex.

use super::bounds::SharedBounds;
use super::paths::Path;
use super::provenance::{keeps_values, Provenance};
use super::radix_queue::RadixQueue;
use super::shadow::Arrival;
use super::source::SurfacePoint;
use super::unfold::Unfolding;
use super::wedge::{Wedge, WedgeFields};
use super::wedge_lists::WedgeRef;
use crate::mesh::{EdgeId, SourceId, TriMesh, VertexId};
use crate::scalar::Scalar;
use std::cmp::Ordering;
use std::collections::BinaryHeap;
use std::sync::Arc;

/// The best known distance of a vertex: an upper bound during propagation, final after it.
#[derive(Clone, Debug)]
pub(crate) struct VertexDistance<S: Scalar> {
    pub(crate) distance: S,
    pub(crate) approx: f64,
    pub(crate) source: SourceId,
    /// The path whose length the distance is, where the run proves ties by symmetry.
    pub(crate) path: S::Kept<Path>,
    /// Whether the distance improved since the vertex last acted as a pseudo-source. Here,
    /// not in a table of its own: its spare values also tell `None` from a distance, so that
    /// `Option<VertexDistance>` takes 24 bytes in the `f64` engine, not 32 and the table's 1.
    pending_emission: bool,
}

/// What an event is about: a wedge of an edge list (as long as it is there), a vertex whose
/// distance may have improved, or a wedge tied on a stretch of its edge ([`Front::push_tied`]).
#[derive(Clone, Copy, Debug)]
pub(crate) enum EventKind {
    Wedge(WedgeRef),
    Vertex(VertexId),
    Tied(u32),
}

/// Something due when the front reaches a key, ordered reversed, so that `BinaryHeap` pops the
/// nearest first (equal keys compare equal: the heap's own order decides between them).
///
/// The key is kept as the integer that orders as [`f64::total_cmp`] orders keys: the heap
/// compares at every level of every pop, and an integer comparison is one instruction where
/// `total_cmp` first maps both keys to such integers. The order, and with it the order in
/// which events of equal keys leave the heap, is the same.
#[derive(Clone, Copy, Debug)]
pub(crate) struct AtKey<T> {
    order: i64,
    pub(crate) what: T,
}

/// The integer of `key`'s bits that orders as `f64::total_cmp` (the transformation std's
/// `total_cmp` applies to both sides): negative keys have every bit but the sign flipped. It
/// is its own inverse.
#[inline(always)]
fn total_order_bits(bits: i64) -> i64 {
    bits ^ ((((bits >> 63) as u64) >> 1) as i64)
}

impl<T> AtKey<T> {
    /// `what`, due at `key`.
    #[inline(always)]
    pub(crate) fn new(key: f64, what: T) -> Self {
        AtKey {
            order: total_order_bits(key.to_bits() as i64),
            what,
        }
    }

    /// The key it is due at.
    #[inline(always)]
    pub(crate) fn key(&self) -> f64 {
        f64::from_bits(total_order_bits(self.order) as u64)
    }
}

impl<T> PartialEq for AtKey<T> {
    fn eq(&self, other: &Self) -> bool {
        self.order == other.order
    }
}
impl<T> Eq for AtKey<T> {}
impl<T> PartialOrd for AtKey<T> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl<T> Ord for AtKey<T> {
    #[inline(always)]
    fn cmp(&self, other: &Self) -> Ordering {
        other.order.cmp(&self.order)
    }
}

/// An event of the queue, keyed by the `f64` value of its distance.
pub(crate) type Event = AtKey<EventKind>;

/// An edge whose wedges may no longer be needed once the front reaches `key`
/// ([`WedgeLists::close`](super::wedge_lists::WedgeLists::close)).
pub(crate) type Closing = AtKey<EdgeId>;

/// The queue of events and the vertices' distances.
pub(crate) struct Front<S: Scalar> {
    vertices: Vec<Option<VertexDistance<S>>>,
    /// The straight way by which each vertex that acts as a pseudo-source (the only ones that
    /// read theirs, when they emit) got its distance, where it came from a wedge: at
    /// `arrival_slot[v]`, a slot only for those vertices ([`NO_SLOT`] for the others; a slot
    /// takes 32 bytes in the `f64` engine, its number 4).
    arrivals: Vec<Option<Arrival>>,
    arrival_slot: Vec<u32>,
    queue: RadixQueue<EventKind>,
    /// The wedges of [`Front::push_tied`] until they are due.
    tied: Vec<Option<(Wedge<S>, Provenance<S>)>>,
    /// Edges to close, apart from the events so that they do not change the order in which
    /// events of equal keys leave `queue` (ties that the vertices' last bits depend on).
    closing: BinaryHeap<Closing>,
    /// Vertices with a distance.
    reached: usize,
    /// The longest the queue has been right after a wedge joined it.
    peak_queue: usize,
    /// Where every distance given to a vertex is published, when another engine propagates
    /// beside this one (see `sectors.rs`).
    published: Option<Arc<SharedBounds>>,
}

impl<S: Scalar> Front<S> {
    /// An empty queue and no vertex of `mesh` reached; the vertices' distances are published to
    /// `published`, if given.
    pub(crate) fn new(mesh: &TriMesh, published: Option<Arc<SharedBounds>>) -> Self {
        let vertex_count = mesh.vertex_count();
        let mut slots = 0;
        let arrival_slot = (0..vertex_count as u32)
            .map(|v| match acts_as_pseudo_source::<S>(mesh, VertexId(v)) {
                true => {
                    slots += 1;
                    slots - 1
                }
                false => NO_SLOT,
            })
            .collect();
        Front {
            vertices: vec![None; vertex_count],
            arrivals: vec![None; slots as usize],
            arrival_slot,
            queue: RadixQueue::new(),
            tied: Vec::new(),
            closing: BinaryHeap::new(),
            reached: 0,
            peak_queue: 0,
            published,
        }
    }

    /// The nearest event, taken from the queue.
    pub(crate) fn pop(&mut self) -> Option<Event> {
        self.queue.pop().map(|(key, what)| Event::new(key, what))
    }

    /// The next edge to close with the front at `key`: one asked for at `key` or before.
    pub(crate) fn pop_closing(&mut self, key: f64) -> Option<Closing> {
        if self.closing.peek()?.key() <= key {
            self.closing.pop()
        } else {
            None
        }
    }

    /// Puts a popped event back into the queue at a later key.
    pub(crate) fn requeue(&mut self, event: Event, key: f64) {
        self.queue.push(key, event.what);
    }

    /// Queues the wedge named `at` at the smallest distance it gives.
    pub(crate) fn push_wedge(&mut self, at: WedgeRef, wedge: &impl WedgeFields<S>) {
        let key = wedge.min_distance().to_f64();
        self.queue.push(key, EventKind::Wedge(at));
        self.peak_queue = self.peak_queue.max(self.queue.len());
    }

    /// Queues a stretch of a wedge that lost it to the edge's wedge there on a near-tie
    /// ([`Scalar::near_tie`]): the two images may see different faces beyond, and the rounding
    /// that chose one may have chosen the wrong one (on a mixed-magnitude mesh, a vertex came
    /// out 33 % long without the other's geodesics). Propagated as any wedge when due, but not
    /// kept on its edge, whose distances it does not lower.
    pub(crate) fn push_tied(&mut self, w: Wedge<S>, kept: Provenance<S>) {
        let key = w.min_distance().to_f64();
        self.queue
            .push(key, EventKind::Tied(self.tied.len() as u32));
        self.tied.push(Some((w, kept)));
    }

    /// The tied wedge of an event ([`Front::push_tied`]).
    pub(crate) fn take_tied(&mut self, i: u32) -> Option<(Wedge<S>, Provenance<S>)> {
        self.tied[i as usize].take()
    }

    /// Asks, once the front reaches `key`, whether the wedges of edge `e` are still needed.
    pub(crate) fn push_closing(&mut self, edge: EdgeId, key: f64) {
        self.closing.push(Closing::new(key, edge));
    }

    /// The longest the queue has been after a wedge joined it.
    pub(crate) fn peak_queue(&self) -> usize {
        self.peak_queue
    }

    /// Vertices with a distance so far.
    pub(crate) fn reached(&self) -> usize {
        self.reached
    }

    /// The best known distance of a vertex.
    pub(crate) fn vertex(&self, v: VertexId) -> Option<&VertexDistance<S>> {
        self.vertices[v.index()].as_ref()
    }

    /// The distance, source and path of a vertex whose distance improved since it last acted
    /// as a pseudo-source; the vertex is then no longer pending.
    pub(crate) fn take_emission(&mut self, v: VertexId) -> Option<(S, SourceId, S::Kept<Path>)> {
        let known = self.vertices[v.index()].as_mut()?;
        std::mem::take(&mut known.pending_emission)
            .then(|| (known.distance.clone(), known.source, known.path.clone()))
    }

    /// The straight way by which a vertex got its present distance from a wedge, if it did.
    pub(crate) fn arrival(&self, v: VertexId) -> Option<&Arrival> {
        let slot = self.arrival_slot[v.index()];
        self.arrivals.get(slot as usize)?.as_ref()
    }

    /// Sets the arrival of `v`, if it acts as a pseudo-source (else it is never read).
    fn set_arrival(&mut self, v: VertexId, arrival: Option<Arrival>) {
        if let Some(a) = self.arrivals.get_mut(self.arrival_slot[v.index()] as usize) {
            *a = arrival;
        }
    }

    /// Marks a vertex as having acted as a pseudo-source at its present distance.
    pub(crate) fn emitted(&mut self, v: VertexId) {
        if let Some(known) = &mut self.vertices[v.index()] {
            known.pending_emission = false;
        }
    }

    /// Lowers a vertex's distance if `distance` is better, and says whether it was; a vertex
    /// that may bend geodesics then waits in the queue to act as a pseudo-source. Its twins
    /// (ends of its edges of length zero, the same point of the surface) take the same
    /// distance as it is, not a rounded copy of it.
    pub(crate) fn improve_vertex(
        &mut self,
        (mesh, unfolding): (&TriMesh, &Unfolding<S>),
        v: VertexId,
        distance: S,
        (source, path): (SourceId, S::Kept<Path>),
    ) -> bool {
        match &self.vertices[v.index()] {
            Some(known) if distance.compare_distance(&known.distance) != Ordering::Less => {
                return false
            }
            Some(_) => {}
            None => self.reached += 1,
        }
        self.set_arrival(v, None);
        let approx = distance.to_f64();
        if let Some(published) = &self.published {
            published.lower(v, approx);
        }
        let twin_distance = unfolding.has_twin(v).then(|| distance.clone());
        let twin_path = twin_distance.as_ref().map(|_| path.clone());
        let pending_emission = self.arrival_slot[v.index()] != NO_SLOT;
        self.vertices[v.index()] = Some(VertexDistance {
            distance,
            approx,
            source,
            path,
            pending_emission,
        });
        if pending_emission {
            self.queue.push(approx, EventKind::Vertex(v));
        }
        if let (Some(distance), Some(path)) = (twin_distance, twin_path) {
            for &e in mesh.vertex_edges(v) {
                if unfolding.is_zero_length(e) {
                    let other = mesh.edge(e).other(v).expect("an edge of the vertex");
                    let reached = (source, path.clone());
                    self.improve_vertex((mesh, unfolding), other, distance.clone(), reached);
                }
            }
        }
        true
    }

    /// A wedge's distance `d` at the vertex `v`, offered to it: no lower than its pseudo-source's
    /// straight line to `v` in space, where the backend repairs rounding ([`Scalar::at_least`]).
    /// `path` is the path of the wedge's distance there, if kept; `straight`: whether the way
    /// is straight from the pseudo-source's image (else it bends at a range end, see
    /// `rounded_gap.rs`), and so is the vertex's [`Arrival`]. Whether it lowered the vertex's
    /// distance.
    pub(crate) fn offer_vertex(
        &mut self,
        (mesh, unfolding, sources): (&TriMesh, &Unfolding<S>, &[SurfacePoint]),
        v: VertexId,
        (d, path): (S, S::Kept<Path>),
        (w, straight): (&Wedge<S>, bool),
    ) -> bool {
        let d = S::at_least(d, || unfolding.straight_bound(mesh, w, v, sources));
        let improved = self.improve_vertex((mesh, unfolding), v, d, (w.source, path));
        if improved && straight {
            self.set_arrival(v, Some(Arrival::of(w)));
        }
        improved
    }

    /// Takes, at each vertex, the other front's distance where it is shorter (the distances of
    /// two engines that propagated different sectors of a source's directions).
    pub(crate) fn take_shorter(&mut self, other: Front<S>) {
        for (mine, theirs) in self.vertices.iter_mut().zip(other.vertices) {
            let Some(theirs) = theirs else { continue };
            match mine {
                Some(m) if m.distance.compare_distance(&theirs.distance) != Ordering::Greater => {}
                Some(_) => *mine = Some(theirs),
                None => {
                    self.reached += 1;
                    *mine = Some(theirs);
                }
            }
        }
    }

    /// The vertices' distances at the end of a run, those beyond `max` (the run's maximum
    /// distance) dropped as unreachable.
    pub(crate) fn into_vertices(self, max: f64) -> Vec<Option<VertexDistance<S>>> {
        let mut vertices = self.vertices;
        for v in vertices.iter_mut() {
            if v.as_ref().is_some_and(|d| d.approx > max) {
                *v = None;
            }
        }
        vertices
    }
}

/// No slot in [`Front`]'s arrivals: the vertex never acts as a pseudo-source.
const NO_SLOT: u32 = u32::MAX;

/// Whether vertex `v`, once reached, sends wedges of its own as a pseudo-source. A vertex on a
/// straight crease bends no geodesic (its angle sum is exactly 2 pi); number types that keep
/// values prove the ties of the images passing it on either side by structure (`crease.rs`)
/// rather than meeting its own wedges there. Rounding types keep it as a pseudo-source, which
/// covers the shadow line behind it whatever the images' rounding.
pub(crate) fn acts_as_pseudo_source<S: Scalar>(mesh: &TriMesh, v: VertexId) -> bool {
    mesh.may_bend_geodesics(v) && !(keeps_values::<S>() && mesh.is_crease_vertex(v))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    #[test]
    fn a_vertex_distance_of_the_f64_engine_takes_24_bytes_with_or_without_a_distance() {
        assert_eq!(std::mem::size_of::<Option<VertexDistance<f64>>>(), 24);
    }

    /// Only vertices that act as pseudo-sources have a slot for their arrival, and only they
    /// wait to emit once reached; the others' arrivals are dropped unread.
    #[test]
    fn arrivals_are_kept_for_the_vertices_that_act_as_pseudo_sources() {
        // A flat grid: its interior vertices are flat, its boundary ones bend geodesics.
        let mesh = shapes::grid(4, 4, 1.0, 1.0);
        let sources = [SurfacePoint::Vertex(VertexId(0))];
        let unfolding = Unfolding::<f64>::new(&mesh, &sources);
        let mut front = Front::<f64>::new(&mesh, None);
        let acting: Vec<bool> = (0..mesh.vertex_count() as u32)
            .map(|v| acts_as_pseudo_source::<f64>(&mesh, VertexId(v)))
            .collect();
        assert!(acting.contains(&true) && acting.contains(&false));
        assert_eq!(front.arrivals.len(), acting.iter().filter(|&&a| a).count());
        let w = Wedge {
            edge: EdgeId(0),
            b0: 0.0,
            b1: 1.0,
            source_x: 0.5,
            source_y: 2.0,
            sigma: 0.0,
            tau: crate::mesh::Side::FIRST,
            pseudo_source: crate::mmp::PseudoSource::Source(SourceId(0)),
            source: SourceId(0),
        };
        for v in 0..mesh.vertex_count() as u32 {
            let v = VertexId(v);
            let surface = (&mesh, &unfolding, &sources[..]);
            assert!(front.offer_vertex(surface, v, (10.0, ()), (&w, true)));
            assert_eq!(front.arrival(v).is_some(), acting[v.index()], "{v:?}");
            assert_eq!(front.take_emission(v).is_some(), acting[v.index()], "{v:?}");
            assert!(front.take_emission(v).is_none());
        }
    }

    /// The heap's integer order is `f64::total_cmp` reversed (the nearest first), and the key
    /// comes back bit for bit.
    #[test]
    fn keys_order_as_total_cmp_reversed_and_come_back_exactly() {
        let keys = [
            f64::NEG_INFINITY,
            -2.5,
            -f64::MIN_POSITIVE,
            -0.0,
            0.0,
            5e-324,
            1.0,
            1.0 + f64::EPSILON,
            f64::MAX,
            f64::INFINITY,
        ];
        for a in keys {
            let at = AtKey::new(a, ());
            assert_eq!(at.key().to_bits(), a.to_bits());
            for b in keys {
                assert_eq!(
                    at.cmp(&AtKey::new(b, ())),
                    b.total_cmp(&a),
                    "{a} against {b}"
                );
            }
        }
    }
}
