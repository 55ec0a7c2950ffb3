//! The back-trace of Section 2 [LZT §2, steps (1)-(4)]: from a point, go straight towards the
//! unfolded pseudo-source of the region containing it, crossing faces, until the pseudo-source;
//! if that is a mesh vertex rather than the source, continue from it in the region that vertex
//! was reached from.

use super::field::GeodesicField;
use super::planar::{Apex, Planar};
use super::query::{Best, Via};
use super::source::{PointError, SurfacePoint};
use super::trace_loop::{Departure, LoopTie};
use super::unfold::FaceLayout;
use super::wedge::{PseudoSource, Wedge};
use crate::mesh::{EdgeId, FaceId, SourceId, VertexId};
use crate::scalar::{Scalar, Sign};
use glam::DVec3;
use serde::Serialize;
use std::cmp::Ordering;
use thiserror::Error;

/// A shortest path from a point back to its nearest source.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GeodesicPath {
    /// The path's points, from the target to the source, in space.
    pub points: Vec<DVec3>,
    /// The same points, named by the simplex containing each.
    pub simplices: Vec<SurfacePoint>,
    /// The geodesic distance of the target, as the field gives it.
    pub distance: f64,
    /// Index of the source the path ends at.
    pub source: SourceId,
}

impl GeodesicPath {
    /// The length of the polyline (equal to `distance` up to rounding), without overflow or
    /// underflow at any scale.
    pub fn length(&self) -> f64 {
        self.points
            .windows(2)
            .map(|p| {
                let d = p[1] - p[0];
                d.x.hypot(d.y).hypot(d.z)
            })
            .fold(0.0, |sum, d| sum + d)
    }

    /// Whether the polyline's length equals `distance` within `relative` of the larger, plus
    /// what rounding the points to `f64` can move it by: each point is within half an ulp of
    /// the point the walk found and moves the two segments it ends by as much (a needle
    /// 1e-11 long at coordinates near 1 is measured to 1e-5 of its length at best).
    pub fn is_as_long_as_its_distance(&self, relative: f64) -> bool {
        let length = self.length();
        let resolution: f64 = self
            .points
            .iter()
            .map(|p| 2.0 * f64::EPSILON * p.abs().max_element())
            .sum();
        (length - self.distance).abs() <= relative * length.max(self.distance) + resolution
    }
}

/// How far a traced path's length may be from the target's distance, relative: a walk that
/// strays further (in a tie between arrivals that rounding decided) is an error, not a path.
const TRACE_LENGTH: f64 = 1e-9;

/// A shortest path with the backend's own numbers ([`GeodesicField::trace_back_exact`]).
#[derive(Clone, Debug)]
pub struct ExactPath<S> {
    /// The path in `f64`, as [`GeodesicField::trace_back`] gives it.
    pub path: GeodesicPath,
    /// For each of `path.simplices`: where it is a point the walk found inside an edge, its
    /// offset along the edge from the edge's `vertices[0]`, in the model's units; `None` for
    /// vertices, the target and the source.
    pub offsets: Vec<Option<S>>,
    /// The target's distance.
    pub distance: S,
}

/// Why a path could not be traced.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TraceError {
    /// The target is not a point of the mesh.
    #[error(transparent)]
    Point(#[from] PointError),
    /// No source reaches the target.
    #[error("the target is unreachable from every source")]
    Unreachable,
    /// The walk did not arrive at the pseudo-source (rounding in a degenerate configuration).
    #[error("the back-trace lost its way near {near}")]
    Lost {
        /// The last simplex the walk was in.
        near: String,
    },
    /// The walk arrived by a way whose length is not the target's distance (rounding in a
    /// degenerate configuration sent it through the wrong face): no path is given rather than
    /// a wrong one.
    #[error("the traced path is {length:e} long but the distance is {distance:e}")]
    NotShortest {
        /// The traced polyline's length.
        length: f64,
        /// The target's distance.
        distance: f64,
    },
}

/// The walk's state: inside `face`, at `r`, heading for `s`; both in the frame of `edge`, an
/// edge of `face`, with y positive towards `face`.
struct Walk<S> {
    edge: EdgeId,
    face: FaceId,
    r: Planar<S>,
    s: Planar<S>,
    /// The mesh vertex the walk starts from, if it starts at one.
    start: Option<VertexId>,
}

/// Where a walk goes next.
enum Step<S> {
    /// On through a face.
    Walk(Walk<S>),
    /// Through a mesh vertex, where the walk stops.
    Vertex(VertexId),
}

/// Where a walk stopped.
enum WalkEnd<S> {
    /// At the pseudo-source it was heading for.
    PseudoSource,
    /// At a mesh vertex on the straight way to it.
    Vertex(VertexId),
    /// At the point `x` of an edge shared by more than two faces, where the straight way goes
    /// on into the face its wedge there came through.
    Edge { edge: EdgeId, x: S },
}

impl<S: Scalar> GeodesicField<'_, S> {
    /// The shortest path from `target` back to its nearest source [LZT §2].
    ///
    /// # Errors
    /// [`TraceError::Unreachable`] if no source reaches the target, [`TraceError::Point`] for an
    /// invalid target, [`TraceError::Lost`] if rounding sends the walk astray, and
    /// [`TraceError::NotShortest`] if it sends the walk by a way longer or shorter than the
    /// distance by more than 1e-9 of it.
    pub fn trace_back(&self, target: &SurfacePoint) -> Result<GeodesicPath, TraceError> {
        self.checked_trace(target).map(|(path, ..)| path)
    }

    /// [`GeodesicField::trace_back`] with the backend's own numbers: where the path crosses an
    /// edge, its offset along the edge as the number type computed it (exactly, in the exact
    /// backend), and the target's distance in the number type.
    ///
    /// # Errors
    /// As [`GeodesicField::trace_back`].
    pub fn trace_back_exact(&self, target: &SurfacePoint) -> Result<ExactPath<S>, TraceError> {
        let (path, trail, distance) = self.checked_trace(target)?;
        let offsets = trail
            .points
            .iter()
            .zip(&trail.offsets)
            .map(|(p, x)| match (p, x) {
                (SurfacePoint::Edge { edge, .. }, Some(x)) => {
                    Some(self.to_model(&self.unfolding.offset_from_first_vertex(*edge, x)))
                }
                _ => None,
            })
            .collect();
        Ok(ExactPath {
            path,
            offsets,
            distance: self.to_model(&distance),
        })
    }

    /// The path, its trail and the target's distance (scaled units), checked against the
    /// distance. Where the walk came round to a vertex it passed, and the vertices on that loop
    /// tie at the backend's resolution, the arrival refused is that of the latest of them and,
    /// if the path is then lost or not as long as the distance, that of the first.
    fn checked_trace(
        &self,
        target: &SurfacePoint,
    ) -> Result<(GeodesicPath, Trail<S>, S), TraceError> {
        self.trace(target, LoopTie::Latest)
            .or_else(|error| match error {
                TraceError::Lost { .. } | TraceError::NotShortest { .. } => {
                    self.trace(target, LoopTie::First).map_err(|_| error)
                }
                _ => Err(error),
            })
    }

    /// The path, its trail and the target's distance (scaled units). A walk that rounding
    /// sends astray (lost, or by a way whose length is not the distance: a near tie with
    /// another way, decided at the backend's resolution) backs off to the vertex it last left,
    /// refuses the arrival taken there and takes the next best, backing off further where none
    /// is left; the first error is the answer if every way fails.
    fn trace(
        &self,
        target: &SurfacePoint,
        tie: LoopTie,
    ) -> Result<(GeodesicPath, Trail<S>, S), TraceError> {
        let target = target.validated(self.mesh())?;
        let best = self.best_at(&target).ok_or(TraceError::Unreachable)?;
        let distance = best.distance;
        let mut simplices = Trail::start(target);
        let mut via = best.via;
        let mut start = None;
        // The vertices the walk left, in order, and a vertex to leave again with the arrivals
        // refused there.
        let mut departures: Vec<Departure<'_, S>> = Vec::new();
        let mut retry: Retry<'_, S> = None;
        let mut first_error = None;
        let budget = 4 * self.mesh().face_count() + 16;
        for _ in 0..budget {
            let pseudo_source = match via {
                Via::Vertex(v) => {
                    let refused = match retry.take() {
                        Some((u, refused)) if u == v => refused,
                        _ => Vec::new(),
                    };
                    let trail_len = simplices.len();
                    simplices.push(SurfacePoint::Vertex(v));
                    // The path ends at the vertex if it is a source; it may hop at no cost to a
                    // vertex at the same place (across edges of length zero): to a source, or
                    // else to whichever was reached through a face that is not degenerate.
                    let twins = self.twins(v);
                    let hop = |simplices: &mut Trail<S>, mut at: usize| {
                        let mut chain = Vec::new();
                        while let Some(parent) = twins[at].1 {
                            chain.push(twins[at].0);
                            at = parent;
                        }
                        for u in chain.into_iter().rev() {
                            simplices.push(SurfacePoint::Vertex(u));
                        }
                    };
                    if let Some((i, k)) = twins
                        .iter()
                        .enumerate()
                        .find_map(|(i, &(u, _))| self.source_at_vertex(u).map(|k| (i, k)))
                    {
                        hop(&mut simplices, i);
                        match self.path_of(&simplices, &distance, k) {
                            Ok(path) => return Ok((path, simplices, distance)),
                            Err(error) => {
                                let back = (&mut departures, &mut first_error);
                                (via, retry) = back_off(back, &mut simplices, error)?;
                                continue;
                            }
                        }
                    }
                    let Some((i, arrival)) = twins
                        .iter()
                        .enumerate()
                        .filter_map(|(i, &(u, _))| {
                            self.arrival_at_vertex(u, &twins, &refused).map(|b| (i, b))
                        })
                        .min_by(|(_, a), (_, b)| self.better_arrival(a, b))
                    else {
                        if refused.is_empty() {
                            return Err(TraceError::Unreachable);
                        }
                        let lost = TraceError::Lost {
                            near: format!("{v}"),
                        };
                        let back = (&mut departures, &mut first_error);
                        (via, retry) = back_off(back, &mut simplices, lost)?;
                        continue;
                    };
                    hop(&mut simplices, i);
                    let u = twins[i].0;
                    if let Via::Wedge { edge, wedge, .. } = arrival.via {
                        departures.push(Departure {
                            vertex: v,
                            trail_len,
                            chosen: &self.wedges.on(edge)[wedge],
                            refused,
                        });
                    }
                    via = arrival.via;
                    start = Some(u);
                    continue;
                }
                Via::Wedge {
                    edge,
                    wedge,
                    face,
                    at,
                } => {
                    let w = &self.wedges.on(edge)[wedge];
                    let walked = self
                        .enter(edge, wedge, face, at, start, &mut simplices)
                        .and_then(|step| match step {
                            Step::Walk(walk) => {
                                self.walk_to(walk, w.pseudo_source, &mut simplices, budget)
                            }
                            Step::Vertex(v) => Ok(WalkEnd::Vertex(v)),
                        });
                    let end = match walked {
                        Ok(end) => end,
                        // Rounding sent the walk astray from the arrival taken at the vertex
                        // last left (a near tie with another way): that arrival is refused
                        // there and the next best taken; any way is still checked against
                        // the distance.
                        Err(lost @ TraceError::Lost { .. }) => {
                            let back = (&mut departures, &mut first_error);
                            (via, retry) = back_off(back, &mut simplices, lost)?;
                            continue;
                        }
                        Err(error) => return Err(error),
                    };
                    match end {
                        WalkEnd::PseudoSource => w.pseudo_source,
                        // The straight path runs through a mesh vertex: it goes on from there.
                        WalkEnd::Vertex(v) => PseudoSource::Vertex(v),
                        // The straight path crosses an edge shared by more than two faces:
                        // it goes on by the wedge there, into the face that wedge came through
                        // (a point of the edge is seen alike from each of its faces).
                        WalkEnd::Edge { edge, x } => {
                            let at = Planar { x, y: S::zero() };
                            let face = self.mesh().edge_faces(edge).next().expect("a face");
                            via = self
                                .best_through_edge(edge, face, &at, |_| true, false)
                                .ok_or_else(|| TraceError::Lost {
                                    near: format!("{edge}"),
                                })?
                                .via;
                            start = None;
                            continue;
                        }
                    }
                }
            };
            if let PseudoSource::Vertex(u) = pseudo_source {
                if self.was_passed(u, &simplices.points) {
                    // A shortest path passes a point once: the walk came round to a vertex it
                    // passed (vertices an ulp apart, each on the other's rounded way). On the
                    // loop, the arrival taken at the nearest vertex to the sources cannot be
                    // right (it goes by vertices no nearer): it is refused there, and the trail
                    // taken up again from that vertex.
                    let d = self
                        .loop_departure(u, &mut departures, tie)
                        .ok_or_else(|| TraceError::Lost {
                            near: format!("{u}"),
                        })?;
                    (via, retry) = refuse(d, &mut simplices);
                    continue;
                }
            }
            match pseudo_source {
                PseudoSource::Source(k) => {
                    simplices.push(self.sources[k.index()]);
                    match self.path_of(&simplices, &distance, k) {
                        Ok(path) => return Ok((path, simplices, distance)),
                        Err(error) => {
                            let back = (&mut departures, &mut first_error);
                            (via, retry) = back_off(back, &mut simplices, error)?;
                        }
                    }
                }
                PseudoSource::Vertex(v) => via = Via::Vertex(v),
            }
        }
        Err(first_error.unwrap_or_else(|| TraceError::Lost {
            near: format!("{:?}", simplices.points.last()),
        }))
    }

    /// The path of a trail in space, checked against the distance ([`TRACE_LENGTH`]).
    fn path_of(
        &self,
        trail: &Trail<S>,
        distance: &S,
        source: SourceId,
    ) -> Result<GeodesicPath, TraceError> {
        // A point the walk found inside an edge is placed from its offset in the edge's frame,
        // not from its fraction `t`, which on a long edge is known only to ulps of the length.
        let points = trail
            .points
            .iter()
            .zip(&trail.offsets)
            .map(|(p, x)| match (p, x) {
                (SurfacePoint::Edge { edge, .. }, Some(x)) => {
                    self.unfolding.edge_position(self.mesh(), *edge, x)
                }
                _ => p.position(self.mesh()),
            })
            .collect();
        let path = GeodesicPath {
            points,
            simplices: trail.points.clone(),
            distance: self.model_f64(distance),
            source,
        };
        if !path.is_as_long_as_its_distance(TRACE_LENGTH) {
            return Err(TraceError::NotShortest {
                length: path.length(),
                distance: path.distance,
            });
        }
        Ok(path)
    }

    /// The vertex and those at the same place, joined to it by edges of length zero, each
    /// with the index of the one it was found from (`None` for the vertex itself).
    pub(super) fn twins(&self, v: VertexId) -> Vec<(VertexId, Option<usize>)> {
        let mut group = vec![(v, None)];
        let mut next = 0;
        while next < group.len() {
            let w = group[next].0;
            for &e in self.mesh().vertex_edges(w) {
                if self.unfolding.is_zero_length(e) {
                    let u = self.mesh().edge(e).other(w).expect("an edge of the vertex");
                    if group.iter().all(|&(x, _)| x != u) {
                        group.push((u, Some(next)));
                    }
                }
            }
            next += 1;
        }
        group
    }

    /// Orders two arrivals at a vertex: the shorter first and, on a tie, the one not through
    /// a degenerate face (where a walk has no room to find its way).
    fn better_arrival(&self, a: &Best<S>, b: &Best<S>) -> Ordering {
        let degenerate = |x: &Best<S>| matches!(x.via, Via::Wedge { face, .. } if self.mesh().is_degenerate_face(face));
        a.distance
            .compare_distance(&b.distance)
            .then(degenerate(a).cmp(&degenerate(b)))
    }

    fn source_at_vertex(&self, v: VertexId) -> Option<SourceId> {
        self.sources
            .iter()
            .position(|s| *s == SurfacePoint::Vertex(v))
            .map(|k| SourceId(k as u32))
    }

    /// How a vertex was reached, excluding the wedges it (or a twin, in `twins`) emitted itself
    /// and those `refused` there: wedges on the opposite
    /// edges of its faces that see it from beyond, or, only where strictly better, wedges along
    /// its edges that cover it (a path arriving along an edge). The first kind is preferred on
    /// ties because the straight way back then starts inside a known face; a wedge along an edge
    /// may cover the vertex only with the boundary ray of its range.
    pub(crate) fn arrival_at_vertex(
        &self,
        v: VertexId,
        twins: &[(VertexId, Option<usize>)],
        refused: &[&Wedge<S>],
    ) -> Option<Best<S>> {
        // The wedges a vertex, or one at its place, emitted itself lead nowhere new. Wedges are
        // told apart by their place in the field's lists.
        let own = |w: &Wedge<S>| {
            matches!(w.pseudo_source, PseudoSource::Vertex(u) if twins.iter().any(|t| t.0 == u))
                || refused.iter().any(|r| std::ptr::eq(*r, w))
        };
        let mut best: Option<Best<S>> = None;
        let mut consider = |found: Option<Best<S>>| {
            if let Some(found) = found {
                if best
                    .as_ref()
                    .is_none_or(|b| self.better_arrival(&found, b) == Ordering::Less)
                {
                    best = Some(found);
                }
            }
        };
        for &face in self.mesh().vertex_faces(v) {
            let corner = self.mesh().face(face).iter().position(|&c| c == v)?;
            let edge = self.mesh().face_edges(face)[(corner + 1) % 3];
            let Some(side) = self.mesh().side_of(edge, face) else {
                continue;
            };
            // No apex on an opposite edge of length zero, which carries no wedge.
            let Some(at) = self.unfolding.apex_point(self.mesh(), edge, side) else {
                continue;
            };
            let beyond = |w: &Wedge<S>| !own(w) && w.tau != side;
            consider(self.best_through_edge(edge, face, &at, beyond, true));
        }
        for &edge in self.mesh().vertex_edges(v) {
            let (_, at) = self.end_of_edge(edge, v);
            let arrives = |w: &Wedge<S>| !own(w) && self.ray_enters_corner(w, &at);
            for face in self.mesh().edge_faces(edge) {
                consider(self.best_through_edge(edge, face, &at, arrives, false));
            }
        }
        best.or_else(|| self.arrival_near_vertex(v, &own))
    }

    /// The vertex `v`, an end of `edge`, in the edge's frame, and whether it is the frame's
    /// origin.
    fn end_of_edge(&self, edge: EdgeId, v: VertexId) -> (bool, Planar<S>) {
        let at_start = self.unfolding.ends(self.mesh(), edge)[0] == v;
        let x = if at_start {
            S::zero()
        } else {
            self.unfolding.length(edge).clone()
        };
        (at_start, Planar { x, y: S::zero() })
    }

    /// A way to a vertex that no wedge covers: leave along an edge of the vertex to the nearest
    /// range end of a wedge that would arrive there. In a float backend, a copy of a
    /// pseudo-source unfolded around the vertex ties with the wedge running straight along the
    /// edge from it, and a rounding its way took the end of that wedge's range at the vertex,
    /// though its own ray does not enter the vertex's corner; the vertex's distance is the
    /// same within that rounding.
    fn arrival_near_vertex(
        &self,
        v: VertexId,
        own: &impl Fn(&Wedge<S>) -> bool,
    ) -> Option<Best<S>> {
        let mut nearest: Option<(S, EdgeId, S)> = None;
        for &edge in self.mesh().vertex_edges(v) {
            let (at_start, at) = self.end_of_edge(edge, v);
            for w in self.wedges.on(edge) {
                if own(w) || !self.ray_enters_corner(w, &at) {
                    continue;
                }
                let end = if at_start { &w.b0 } else { &w.b1 };
                let gap = if at_start {
                    end.clone() - &at.x
                } else {
                    at.x.clone() - end
                };
                if nearest
                    .as_ref()
                    .is_none_or(|(g, _, _)| gap.compare(g) == Ordering::Less)
                {
                    nearest = Some((gap, edge, end.clone()));
                }
            }
        }
        let (_, edge, x) = nearest?;
        let at = Planar { x, y: S::zero() };
        let arrives = |w: &Wedge<S>| !own(w) && self.ray_enters_corner(w, &at);
        self.mesh()
            .edge_faces(edge)
            .filter_map(|face| self.best_through_edge(edge, face, &at, arrives, false))
            .min_by(|a, b| self.better_arrival(a, b))
    }

    /// For a wedge on an edge ending at the vertex `at`: whether the way from the vertex to the
    /// pseudo-source starts inside the face on the wedge's side (within its corner there). A
    /// wedge covers its edge's end vertices only with the boundary ray of its range, which may
    /// reach the vertex through another face. Wedges along the edge's line qualify when their
    /// pseudo-source lies on the edge's side of the vertex.
    fn ray_enters_corner(&self, w: &Wedge<S>, at: &Planar<S>) -> bool {
        if w.source_y.sign() == Sign::Zero {
            // Along the line, it arrives by the edge only from a pseudo-source on the edge's
            // side of the vertex; from beyond, its way passes through the vertex elsewhere.
            return if at.x.sign() == Sign::Zero {
                w.source_x.sign() != Sign::Negative
            } else {
                w.source_x.compare(&at.x) != Ordering::Greater
            };
        }
        let Some(Apex { x: cx, h, .. }) = self.unfolding.apex(self.mesh(), w.edge, w.tau) else {
            return false;
        };
        // u runs along the edge away from the vertex, c to the apex, d to the pseudo-source.
        // u is (+-1, 0), so the orientations of (u, c) and (u, d) are signs of heights.
        let along = if at.x.sign() == Sign::Zero {
            Sign::Positive
        } else {
            Sign::Negative
        };
        let zero = S::zero();
        let orientation = along.times(h.sign());
        let u_d = along.times(w.source_y.sign());
        let d_c = S::orientation([&at.x, &zero], [&w.source_x, &w.source_y], [cx, h]);
        [u_d, d_c]
            .iter()
            .all(|&s| s == orientation || s == Sign::Zero)
    }

    /// Starts the walk towards a wedge's pseudo-source from a point of `face`; if the
    /// pseudo-source lies beyond the wedge's edge, first cross that edge.
    fn enter(
        &self,
        edge: EdgeId,
        wedge: usize,
        face: FaceId,
        at: Planar<S>,
        start: Option<VertexId>,
        simplices: &mut Trail<S>,
    ) -> Result<Step<S>, TraceError> {
        let w = &self.wedges.on(edge)[wedge];
        let e = self.mesh().edge(edge);
        let side = self.mesh().side_of(edge, face).expect("face of the edge");
        let s = w.source_point();
        let lost = || TraceError::Lost {
            near: format!("{edge}"),
        };
        // The face the wedge came through.
        let wedge_face = || {
            self.mesh()
                .wing(edge, w.tau)
                .map(|wing| wing.face)
                .ok_or_else(lost)
        };
        if at.y.sign() == Sign::Zero {
            // On the edge itself: the way to the pseudo-source starts in the face on its side.
            let face = wedge_face()?;
            // A point on the edge but named otherwise (a vertex in the middle of a degenerate
            // face, a point of a degenerate face) is also that point of the edge, which the
            // face the walk starts in has in its closure.
            let named_on_edge = match simplices.points.last() {
                Some(SurfacePoint::Vertex(v)) => e.vertices.contains(v),
                Some(SurfacePoint::Edge { edge: on, .. }) => *on == edge,
                _ => false,
            };
            if !named_on_edge {
                simplices.push_edge(self.unfolding.edge_point(edge, &at.x), &at.x);
            }
            return Ok(Step::Walk(Walk {
                edge,
                face,
                r: at,
                s,
                start,
            }));
        }
        if w.tau == side || w.source_y.sign() == Sign::Zero {
            return Ok(Step::Walk(Walk {
                edge,
                face,
                r: at,
                s,
                start,
            }));
        }
        let depth = s.y.clone() + &at.y;
        let x = s.x.clone() + (at.x.clone() - &s.x) * &s.y / depth;
        let reach = (s.x.clone() - &x).to_f64().hypot(s.y.to_f64());
        if let Some(v) = self.end_vertex(edge, &x, reach) {
            return Ok(Step::Vertex(v));
        }
        simplices.push_edge(self.unfolding.edge_point(edge, &x), &x);
        let beyond = wedge_face()?;
        Ok(Step::Walk(Walk {
            edge,
            face: beyond,
            r: Planar { x, y: S::zero() },
            s,
            start: None,
        }))
    }

    /// The end of `edge` at position `x`, if the backend cannot tell `x` from it. `reach`,
    /// the point's distance from the pseudo-source, is the scale of the constructions that
    /// placed it: near the frame's first end, where positions are known to ulps of their own
    /// size, the point is told from the vertex at that scale, not at the edge's length (on an
    /// edge 1e8 long, a path 1e-4 from a vertex would otherwise pass through it).
    fn end_vertex(&self, edge: EdgeId, x: &S, reach: f64) -> Option<VertexId> {
        let length = self.unfolding.length(edge);
        let [v0, v1] = self.unfolding.ends(self.mesh(), edge);
        let near_first = S::from_f64(reach.min(length.to_f64()));
        if !S::has_extent(&S::zero(), x, &near_first) {
            Some(v0)
        } else if !S::has_extent(x, length, length) {
            Some(v1)
        } else {
            None
        }
    }

    /// Goes straight from the walk's point to the pseudo-source, face by face.
    fn walk_to(
        &self,
        mut walk: Walk<S>,
        target: PseudoSource,
        simplices: &mut Trail<S>,
        budget: usize,
    ) -> Result<WalkEnd<S>, TraceError> {
        for _ in 0..budget {
            if let Some(points) = self.closure_path(walk.face, target) {
                for (point, offset) in points {
                    simplices.push_at(point, offset);
                }
                return Ok(WalkEnd::PseudoSource);
            }
            let side = self
                .mesh()
                .side_of(walk.edge, walk.face)
                .expect("face of the edge");
            let lost = || TraceError::Lost {
                near: format!("{}", walk.face),
            };
            let layout =
                FaceLayout::new(self.mesh(), &self.unfolding, walk.edge, side).ok_or_else(lost)?;
            // The layout hangs the face below the edge's line: mirror the walk's points into it.
            let r = Planar {
                x: walk.r.x.clone(),
                y: -walk.r.y.clone(),
            };
            let s = Planar {
                x: walk.s.x.clone(),
                y: -walk.s.y.clone(),
            };
            let (dx, dy) = (s.x.clone() - &r.x, s.y.clone() - &r.y);
            let cross = |ax: S, ay: S| dx.clone() * &ay - dy.clone() * &ax;
            let (cx, cy) = (layout.apex_x.clone(), -layout.apex_h.clone());
            let zero = S::zero();
            let one = S::from_f64(1.0);
            let clamp = |t: S| S::max_of(&zero, &S::min_of(&one, &t));
            // Where the line from r to s leaves the face: by the near edge (from the edge's
            // vertices[0] to the apex) or by the far edge (from the apex to vertices[1]).
            let exit = |near: bool| {
                if near {
                    // From the edge's first end, or from the apex (see `FaceLayout::near_hit`).
                    let from = if layout.near_from_apex {
                        cross(cx.clone() - &r.x, cy.clone() - &r.y)
                    } else {
                        cross(r.x.clone(), r.y.clone())
                    };
                    let t = clamp(from / cross(cx.clone(), cy.clone()));
                    (
                        layout.wing.near,
                        layout.near_position(&t),
                        layout.to_near(&s),
                    )
                } else {
                    let (ux, uy) = (layout.apex_far_x.clone(), zero.clone() - &cy);
                    // From the apex, or from the edge's second end (see `FaceLayout::far_hit`).
                    let from = if layout.far_from_end {
                        cross(layout.length.clone() - &r.x, zero.clone() - &r.y)
                    } else {
                        cross(r.x.clone() - &cx, r.y.clone() - &cy)
                    };
                    let u = clamp(from / cross(ux, uy));
                    (layout.wing.far, layout.far_position(&u), layout.to_far(&s))
                }
            };
            // From a corner of the face the line leaves by the opposite side; from elsewhere,
            // by the side the apex is on.
            // A start at a vertex at the same place as a corner starts from that corner.
            let [p0, p1] = self.unfolding.ends(self.mesh(), walk.edge);
            let start = walk.start.map(|v| self.twins(v));
            let starts_at =
                |p: VertexId| start.as_ref().is_some_and(|g| g.iter().any(|t| t.0 == p));
            let near = match start {
                Some(_) if starts_at(p0) => false,
                Some(_) if starts_at(p1) => true,
                _ => S::orientation([&r.x, &r.y], [&s.x, &s.y], [&cx, &cy]) == Sign::Positive,
            };
            let chosen = exit(near);
            let end = self.end_vertex(chosen.0, &chosen.1, dx.to_f64().hypot(dy.to_f64()));
            let (next_edge, position, along) = chosen;
            if let Some(v) = end {
                return Ok(WalkEnd::Vertex(v));
            }
            simplices.push_edge(self.unfolding.edge_point(next_edge, &position), &position);
            if self.mesh().side_count(next_edge) > 2 {
                return Ok(WalkEnd::Edge {
                    edge: next_edge,
                    x: position,
                });
            }
            let e = self.mesh().edge(next_edge);
            let here = self
                .mesh()
                .side_of(next_edge, walk.face)
                .expect("face of the edge");
            let next_face = e.faces()[1 - here.index()].ok_or_else(lost)?;
            walk = Walk {
                edge: next_edge,
                face: next_face,
                r: Planar {
                    x: position,
                    y: S::zero(),
                },
                s: Planar {
                    x: along.x,
                    y: -along.y,
                },
                start: None,
            };
        }
        Err(TraceError::Lost {
            near: format!("{}", walk.face),
        })
    }

    /// Whether the pseudo-source lies in the closure of the face: a corner, the source's own
    /// face, or a point inside one of its edges (a vertex in the middle of a degenerate face).
    /// In the last case, the way on to a face of the pseudo-source's own (through the
    /// degenerate faces whose edges contain it, all at the same place) as edge points.
    fn closure_path(&self, face: FaceId, target: PseudoSource) -> Option<Vec<TrailPoint<S>>> {
        let point = match target {
            PseudoSource::Vertex(v) => SurfacePoint::Vertex(v),
            PseudoSource::Source(k) => self.sources[k.index()],
        };
        let own = point.faces(self.mesh());
        if own.contains(&face) {
            return Some(Vec::new());
        }
        // Only an edge of a degenerate face (as the mesh or the number type tells them) can
        // hold another face's vertex inside it.
        let beside_degenerate = |g: EdgeId| {
            self.mesh().edge_faces(g).any(|h| {
                self.mesh().is_degenerate_face(h)
                    || self.mesh().side_of(g, h).is_some_and(|side| {
                        self.unfolding
                            .apex_point(self.mesh(), g, side)
                            .is_some_and(|at| self.unfolding.is_inside(g, &at))
                    })
            })
        };
        if !self
            .mesh()
            .face_edges(face)
            .into_iter()
            .any(beside_degenerate)
        {
            return None;
        }
        let p = self.unfolding.position(self.mesh(), &point);
        // Breadth first over faces joined by edges that contain the point inside.
        // Each face reached, with the face it was reached from and the point crossed to it.
        let mut reached: Vec<(FaceId, Option<Crossed<S>>)> = vec![(face, None)];
        let mut next = 0;
        while next < reached.len() {
            let (f, _) = reached[next];
            if own.contains(&f) {
                let mut points = Vec::new();
                let mut at = next;
                while let (_, Some((parent, point))) = &reached[at] {
                    points.push(point.clone());
                    at = *parent;
                }
                points.reverse();
                return Some(points);
            }
            for g in self.mesh().face_edges(f) {
                if !beside_degenerate(g) {
                    continue;
                }
                let Some(on) = self.unfolding.planar(self.mesh(), g, &p) else {
                    continue;
                };
                if !self.unfolding.is_inside(g, &on) {
                    continue;
                }
                let here = (self.unfolding.edge_point(g, &on.x), Some(on.x.clone()));
                for beyond in self.mesh().edge_faces(g) {
                    if reached.iter().all(|(r, _)| *r != beyond) {
                        reached.push((beyond, Some((next, here.clone()))));
                    }
                }
            }
            next += 1;
        }
        None
    }
}

/// Takes the walk up again at the vertex of departure `d`, refusing the arrival chosen there:
/// the trail back to before the vertex, the way to go on by, and the vertex with the arrivals
/// refused at it.
fn refuse<'a, S: Scalar>(mut d: Departure<'a, S>, trail: &mut Trail<S>) -> (Via<S>, Retry<'a, S>) {
    trail.truncate(d.trail_len);
    d.refused.push(d.chosen);
    (Via::Vertex(d.vertex), Some((d.vertex, d.refused)))
}

/// Backs off from `error` to the latest of the `departures`, refusing the arrival taken there
/// ([`refuse`]); the first error met (kept in `first`) if none is left.
fn back_off<'a, S: Scalar>(
    (departures, first): (&mut Vec<Departure<'a, S>>, &mut Option<TraceError>),
    trail: &mut Trail<S>,
    error: TraceError,
) -> Result<(Via<S>, Retry<'a, S>), TraceError> {
    let first = first.get_or_insert(error);
    match departures.pop() {
        Some(d) => Ok(refuse(d, trail)),
        None => Err(first.clone()),
    }
}

/// A vertex to leave again, with the arrivals refused there.
type Retry<'a, S> = Option<(VertexId, Vec<&'a Wedge<S>>)>;

/// A point of a trail and, on an edge, its offset along the edge in the number type.
type TrailPoint<S> = (SurfacePoint, Option<S>);

/// A step of the search in `closure_path`: where it came from, and the point it crossed.
type Crossed<S> = (usize, TrailPoint<S>);

/// A path being traced: its points and, for each, its offset along its edge (scaled units) as
/// the number type computed it, where it is a point inside an edge the walk crossed.
struct Trail<S> {
    points: Vec<SurfacePoint>,
    offsets: Vec<Option<S>>,
}

impl<S: Scalar> Trail<S> {
    fn start(target: SurfacePoint) -> Self {
        Trail {
            points: vec![target],
            offsets: vec![None],
        }
    }

    fn len(&self) -> usize {
        self.points.len()
    }

    /// Drops the points after the first `len`.
    fn truncate(&mut self, len: usize) {
        self.points.truncate(len);
        self.offsets.truncate(len);
    }

    /// Appends a point, unless it repeats the last one.
    fn push(&mut self, p: SurfacePoint) {
        self.push_at(p, None);
    }

    /// Appends the point `p` of an edge, at position `x` in the edge's frame.
    fn push_edge(&mut self, p: SurfacePoint, x: &S) {
        self.push_at(p, Some(x.clone()));
    }

    fn push_at(&mut self, p: SurfacePoint, offset: Option<S>) {
        if self.points.last() != Some(&p) {
            self.points.push(p);
            self.offsets.push(offset);
        }
    }
}
