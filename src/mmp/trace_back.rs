//! The back-trace of Section 2 [LZT §2, steps (1)-(4)]: from a point, go straight towards the
//! unfolded pseudo-source of the region containing it, crossing faces, until the pseudo-source;
//! if that is a mesh vertex rather than the source, continue from it in the region that vertex
//! was reached from.

use super::field::GeodesicField;
use super::query::{Best, Via};
use super::source::{PointError, SurfacePoint};
use super::unfold::{FaceLayout, Planar};
use super::wedge::PseudoSource;
use crate::mesh::{EdgeId, FaceId, VertexId};
use crate::scalar::{Scalar, Sign};
use serde::Serialize;
use std::cmp::Ordering;
use thiserror::Error;

/// A shortest path from a point back to its nearest source.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GeodesicPath {
    /// The path's points, from the target to the source, in space.
    pub points: Vec<[f64; 3]>,
    /// The same points, named by the simplex containing each.
    pub simplices: Vec<SurfacePoint>,
    /// The geodesic distance of the target, as the field gives it.
    pub distance: f64,
    /// Index of the source the path ends at.
    pub source: usize,
}

impl GeodesicPath {
    /// The length of the polyline (equal to `distance` up to rounding).
    pub fn length(&self) -> f64 {
        self.points
            .windows(2)
            .map(|p| {
                let d = [0, 1, 2].map(|i| p[1][i] - p[0][i]);
                (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
            })
            .sum()
    }
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
}

/// The walk's state: inside `face`, at `r`, heading for `s`; both in the frame of `edge`, an
/// edge of `face`, with y positive towards `face`.
struct Walk<S> {
    edge: EdgeId,
    face: FaceId,
    r: Planar<S>,
    s: Planar<S>,
}

impl<S: Scalar> GeodesicField<'_, S> {
    /// The shortest path from `target` back to its nearest source [LZT §2].
    ///
    /// # Errors
    /// [`TraceError::Unreachable`] if no source reaches the target, [`TraceError::Point`] for an
    /// invalid target, [`TraceError::Lost`] if rounding sends the walk astray.
    pub fn trace_back(&self, target: &SurfacePoint) -> Result<GeodesicPath, TraceError> {
        let target = target.validated(self.mesh)?;
        let best = self.best_at(&target).ok_or(TraceError::Unreachable)?;
        let distance = best.distance.to_f64();
        let mut simplices = vec![target];
        let mut via = best.via;
        let budget = 4 * self.mesh.face_count() + 16;
        for _ in 0..budget {
            let pseudo_source = match via {
                Via::Vertex(v) => {
                    push_point(&mut simplices, SurfacePoint::Vertex(v));
                    if let Some(k) = self.source_at_vertex(v) {
                        return Ok(self.finish(simplices, distance, k));
                    }
                    via = self
                        .arrival_at_vertex(v)
                        .ok_or(TraceError::Unreachable)?
                        .via;
                    continue;
                }
                Via::Wedge {
                    edge,
                    wedge,
                    face,
                    at,
                } => {
                    let w = &self.wedges[edge.index()][wedge];
                    let walk = self.enter(edge, wedge, face, at, &mut simplices)?;
                    self.walk_to(walk, w.pseudo_source, &mut simplices, budget)?;
                    w.pseudo_source
                }
            };
            match pseudo_source {
                PseudoSource::Source(k) => {
                    push_point(&mut simplices, self.sources[k]);
                    return Ok(self.finish(simplices, distance, k));
                }
                PseudoSource::Vertex(v) => via = Via::Vertex(v),
            }
        }
        Err(TraceError::Lost {
            near: format!("{:?}", simplices.last()),
        })
    }

    fn finish(&self, simplices: Vec<SurfacePoint>, distance: f64, source: usize) -> GeodesicPath {
        GeodesicPath {
            points: simplices.iter().map(|p| p.position(self.mesh)).collect(),
            simplices,
            distance,
            source,
        }
    }

    fn source_at_vertex(&self, v: VertexId) -> Option<usize> {
        self.sources
            .iter()
            .position(|s| *s == SurfacePoint::Vertex(v))
    }

    /// How a vertex was reached, excluding the wedges it emitted itself: wedges along its edges
    /// that cover it, and wedges on the opposite edges of its faces that see it from beyond.
    pub(crate) fn arrival_at_vertex(&self, v: VertexId) -> Option<Best<S>> {
        let mut best: Option<Best<S>> = None;
        let mut consider = |found: Option<Best<S>>| {
            if let Some(found) = found {
                if best
                    .as_ref()
                    .is_none_or(|b| found.distance.compare_distance(&b.distance) == Ordering::Less)
                {
                    best = Some(found);
                }
            }
        };
        for &edge in self.mesh.vertex_edges(v) {
            let e = self.mesh.edge(edge);
            let x = if e.vertices[0] == v {
                S::zero()
            } else {
                self.unfolding.length(edge).clone()
            };
            let at = Planar { x, y: S::zero() };
            for face in e.faces.into_iter().flatten() {
                consider(self.best_through_edge_excluding(edge, face, &at, v));
            }
        }
        for &face in self.mesh.vertex_faces(v) {
            let corner = self.mesh.face(face).iter().position(|&c| c == v)?;
            let edge = self.mesh.face_edges(face)[(corner + 1) % 3];
            let side = self.mesh.edge(edge).side_of(face)?;
            let (x, y) = self.unfolding.apex(edge, side)?.clone();
            consider(self.best_through_edge_excluding(edge, face, &Planar { x, y }, v));
        }
        best
    }

    fn best_through_edge_excluding(
        &self,
        edge: EdgeId,
        face: FaceId,
        at: &Planar<S>,
        v: VertexId,
    ) -> Option<Best<S>> {
        let best = self.best_through_edge(edge, face, at)?;
        match &best.via {
            Via::Wedge { wedge, .. }
                if self.wedges[edge.index()][*wedge].pseudo_source == PseudoSource::Vertex(v) =>
            {
                None
            }
            _ => Some(best),
        }
    }

    /// Starts the walk towards a wedge's pseudo-source from a point of `face`; if the
    /// pseudo-source lies beyond the wedge's edge, first cross that edge.
    fn enter(
        &self,
        edge: EdgeId,
        wedge: usize,
        face: FaceId,
        at: Planar<S>,
        simplices: &mut Vec<SurfacePoint>,
    ) -> Result<Walk<S>, TraceError> {
        let w = &self.wedges[edge.index()][wedge];
        let e = self.mesh.edge(edge);
        let side = e.side_of(face).expect("face of the edge");
        let s = w.source_point();
        if w.tau.index() == side || w.source_y.sign() == Sign::Zero {
            return Ok(Walk {
                edge,
                face,
                r: at,
                s,
            });
        }
        let depth = s.y.clone() + &at.y;
        let x = s.x.clone() + (at.x.clone() - &s.x) * &s.y / depth;
        let length = self.unfolding.length(edge);
        push_point(simplices, edge_point(edge, &x, length));
        let beyond = e.faces[w.tau.index()].ok_or_else(|| TraceError::Lost {
            near: format!("{edge}"),
        })?;
        Ok(Walk {
            edge,
            face: beyond,
            r: Planar { x, y: S::zero() },
            s,
        })
    }

    /// Goes straight from the walk's point to the pseudo-source, face by face.
    fn walk_to(
        &self,
        mut walk: Walk<S>,
        target: PseudoSource,
        simplices: &mut Vec<SurfacePoint>,
        budget: usize,
    ) -> Result<(), TraceError> {
        for _ in 0..budget {
            if self.face_contains(walk.face, target) {
                return Ok(());
            }
            let side = self
                .mesh
                .edge(walk.edge)
                .side_of(walk.face)
                .expect("face of the edge");
            let lost = || TraceError::Lost {
                near: format!("{}", walk.face),
            };
            let layout =
                FaceLayout::new(self.mesh, &self.unfolding, walk.edge, side).ok_or_else(lost)?;
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
            let turn = cross(cx.clone() - &r.x, cy.clone() - &r.y);
            let zero = S::zero();
            let one = S::from_f64(1.0);
            let clamp = |t: S| S::max_of(&zero, &S::min_of(&one, &t));
            let (next_edge, position, along) = if turn.sign() == Sign::Positive {
                let t = cross(zero.clone() - &r.x, zero.clone() - &r.y) / cross(cx, cy);
                let t = clamp(-t);
                (
                    layout.wing.near,
                    layout.near_position(&t),
                    layout.to_near(&s),
                )
            } else {
                let ux = layout.length.clone() - &cx;
                let uy = zero.clone() - &cy;
                let u = cross(r.x.clone() - &cx, r.y.clone() - &cy) / cross(ux, uy);
                let u = clamp(u);
                (layout.wing.far, layout.far_position(&u), layout.to_far(&s))
            };
            push_point(
                simplices,
                edge_point(next_edge, &position, self.unfolding.length(next_edge)),
            );
            let e = self.mesh.edge(next_edge);
            let here = e.side_of(walk.face).expect("face of the edge");
            let next_face = e.faces[1 - here].ok_or_else(lost)?;
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
            };
        }
        Err(TraceError::Lost {
            near: format!("{}", walk.face),
        })
    }

    /// Whether the pseudo-source is a corner of the face, or the source lies in its closure.
    fn face_contains(&self, face: FaceId, target: PseudoSource) -> bool {
        let point = match target {
            PseudoSource::Vertex(v) => SurfacePoint::Vertex(v),
            PseudoSource::Source(k) => self.sources[k],
        };
        point.faces(self.mesh).contains(&face)
    }
}

fn edge_point<S: Scalar>(edge: EdgeId, x: &S, length: &S) -> SurfacePoint {
    let t = (x.clone() / length).to_f64().clamp(0.0, 1.0);
    SurfacePoint::Edge { edge, t }
}

fn push_point(simplices: &mut Vec<SurfacePoint>, p: SurfacePoint) {
    if simplices.last() != Some(&p) {
        simplices.push(p);
    }
}
