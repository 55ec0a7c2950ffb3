//! Reading distances at any surface point from the final wedges [LZT §2, step (1)]: the point
//! lies in the region of the wedge (on one of its face's edges) whose pseudo-source sees it
//! through the wedge's range and gives the smallest distance.

use super::field::GeodesicField;
use super::planar::Planar;
use super::rounded_gap::{distance_through, end_beside, gap_fraction};
use super::source::{PointError, SurfacePoint};
use super::wedge::Wedge;
use crate::mesh::{EdgeId, FaceId, SourceId, VertexId};
use crate::scalar::{Scalar, Sign};
use std::cmp::Ordering;

/// How the best path reaches a point.
#[derive(Clone, Debug)]
pub(crate) enum Via<S> {
    /// Straight from the pseudo-source of `wedge` on `edge`, seen from `face`, where the point
    /// has coordinates `at` in the edge's frame (y >= 0 towards `face`).
    Wedge {
        edge: EdgeId,
        wedge: usize,
        face: FaceId,
        at: Planar<S>,
    },
    /// Straight from a vertex of the face (or the point is that vertex).
    Vertex(VertexId),
}

#[derive(Clone, Debug)]
pub(crate) struct Best<S> {
    pub(crate) distance: S,
    pub(crate) via: Via<S>,
}

fn keep_better<S: Scalar>(best: &mut Option<Best<S>>, candidate: Best<S>) {
    let better = match best {
        None => true,
        Some(b) => candidate.distance.compare_distance(&b.distance) == Ordering::Less,
    };
    if better {
        *best = Some(candidate);
    }
}

impl<S: Scalar> GeodesicField<'_, S> {
    /// The geodesic distance from the nearest source to any surface point; `f64::INFINITY` if
    /// it cannot be reached.
    ///
    /// # Errors
    /// [`PointError`] if the point is not a point of the mesh.
    pub fn distance_at(&self, point: &SurfacePoint) -> Result<f64, PointError> {
        let point = point.validated(self.mesh())?;
        Ok(self
            .best_at(&point)
            .map_or(f64::INFINITY, |b| self.model_f64(&b.distance)))
    }

    /// [`distance_at`](Self::distance_at) in the backend's own number type (for the exact
    /// backend, the exact value); `None` if the point cannot be reached.
    ///
    /// # Errors
    /// [`PointError`] if the point is not a point of the mesh.
    pub fn distance_at_exact(&self, point: &SurfacePoint) -> Result<Option<S>, PointError> {
        let point = point.validated(self.mesh())?;
        Ok(self.best_at(&point).map(|b| self.to_model(&b.distance)))
    }

    /// Index (into [`sources`](Self::sources)) of the source nearest to any surface point;
    /// `None` if no source reaches it.
    ///
    /// # Errors
    /// [`PointError`] if the point is not a point of the mesh.
    pub fn nearest_source_at(&self, point: &SurfacePoint) -> Result<Option<SourceId>, PointError> {
        let point = point.validated(self.mesh())?;
        Ok(self.best_at(&point).and_then(|b| match b.via {
            Via::Wedge { edge, wedge, .. } => Some(self.wedges.on(edge)[wedge].source),
            Via::Vertex(v) => self.nearest_source(v),
        }))
    }

    /// The best way to reach a point in canonical form.
    pub(crate) fn best_at(&self, point: &SurfacePoint) -> Option<Best<S>> {
        if let SurfacePoint::Vertex(v) = *point {
            return self.vertices[v.index()].as_ref().map(|d| Best {
                distance: d.distance.clone(),
                via: Via::Vertex(v),
            });
        }
        let p = self.unfolding.position(self.mesh(), point);
        let mut best = None;
        for face in point.faces(self.mesh()) {
            for edge in self.mesh().face_edges(face) {
                let at = match *point {
                    // A point of the edge is on its line exactly, not at a rounded height.
                    SurfacePoint::Edge { edge: own, t }
                        if own == edge && !self.unfolding.is_zero_length(edge) =>
                    {
                        Some(Planar {
                            x: self.unfolding.at_fraction(edge, t),
                            y: S::zero(),
                        })
                    }
                    _ => self.unfolding.planar(self.mesh(), edge, &p),
                };
                let Some(at) = at else {
                    continue; // An edge of length zero carries no wedge.
                };
                if let Some(found) = self.best_through_edge(edge, face, &at, |_| true, true) {
                    keep_better(&mut best, found);
                }
            }
            for v in self.mesh().face(face) {
                if let Some(d) = &self.vertices[v.index()] {
                    let q = self
                        .unfolding
                        .position(self.mesh(), &SurfacePoint::Vertex(v));
                    let gap = [0, 1, 2].map(|i| q[i].clone() - &p[i]);
                    let len = (gap[0].clone() * &gap[0]
                        + gap[1].clone() * &gap[1]
                        + gap[2].clone() * &gap[2])
                        .sqrt();
                    keep_better(
                        &mut best,
                        Best {
                            distance: d.distance.clone() + &len,
                            via: Via::Vertex(v),
                        },
                    );
                }
            }
        }
        best
    }

    /// The best wedge on `edge`, among those `accept`ed, whose pseudo-source sees the point `at`
    /// (in the edge's frame, y >= 0 towards `face`) through the wedge's range; with `beside`,
    /// also the way through the end of a range beside which the point lies in a gap that
    /// rounding left (see `rounded_gap.rs`): to that end, then straight to the point, its `via`
    /// naming the wedge at the end, where the way back leaves the edge.
    pub(crate) fn best_through_edge(
        &self,
        edge: EdgeId,
        face: FaceId,
        at: &Planar<S>,
        accept: impl Fn(&Wedge<S>) -> bool,
        beside: bool,
    ) -> Option<Best<S>> {
        let side = self.mesh().side_of(edge, face)?;
        let length = self.unfolding.length(edge);
        let mut best = None;
        for (i, w) in self.wedges.on(edge).iter().enumerate() {
            if !accept(w) {
                continue;
            }
            let on_line = at.y.sign() == Sign::Zero;
            let same_side = w.tau == side;
            // Where the ray from the pseudo-source to the point crosses the edge; `None` for
            // the pseudo-source itself (a source inside a face or an edge), which every wedge
            // of it reaches at its sigma, whatever range the wedge kept.
            let crossing = if w.source_y.sign() == Sign::Zero {
                // A wedge along the edge's line reaches only points of the edge.
                if !on_line {
                    continue;
                }
                Some(at.x.clone())
            } else if on_line {
                Some(at.x.clone())
            } else if same_side {
                // The point must lie between the pseudo-source and the edge, or be it.
                match at.y.compare(&w.source_y) {
                    Ordering::Greater => continue,
                    Ordering::Equal if at.x.compare(&w.source_x) == Ordering::Equal => None,
                    Ordering::Equal => continue,
                    Ordering::Less => {
                        let depth = w.source_y.clone() - &at.y;
                        let run = (at.x.clone() - &w.source_x) * &w.source_y / depth;
                        Some(w.source_x.clone() + run)
                    }
                }
            } else {
                let depth = w.source_y.clone() + &at.y;
                Some(w.source_x.clone() + (at.x.clone() - &w.source_x) * &w.source_y / depth)
            };
            if let Some(c) = crossing.filter(|c| !S::within(c, &w.b0, &w.b1, || length.clone())) {
                // Outside the range: reached through its end only from a pseudo-source beyond
                // the edge, in a gap that rounding left beside the range (see `rounded_gap.rs`).
                if beside && !same_side && w.source_y.sign() != Sign::Zero {
                    if let Some(end) = end_beside(w, || c, length, gap_fraction(self.mesh())) {
                        let distance = distance_through(w, end, (&at.x, &at.y));
                        let at = Planar {
                            x: end.clone(),
                            y: S::zero(),
                        };
                        let via = Via::Wedge {
                            edge,
                            wedge: i,
                            face,
                            at,
                        };
                        keep_better(&mut best, Best { distance, via });
                    }
                }
                continue;
            }
            let dx = at.x.clone() - &w.source_x;
            let dy = if same_side {
                at.y.clone() - &w.source_y
            } else {
                at.y.clone() + &w.source_y
            };
            let distance = (dx.clone() * dx + dy.clone() * dy).sqrt() + &w.sigma;
            keep_better(
                &mut best,
                Best {
                    distance,
                    via: Via::Wedge {
                        edge,
                        wedge: i,
                        face,
                        at: at.clone(),
                    },
                },
            );
        }
        best
    }
}
