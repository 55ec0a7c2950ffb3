//! The wedge (Surazhsky's "window") of Definition 1 [LZT §2].

use super::planar::Planar;
use crate::mesh::{EdgeId, Side, SourceId, VertexId};
use crate::scalar::{Scalar, SourceDistance};
use serde::Serialize;

/// Where a wedge's geodesics come from: a source itself, or a mesh vertex that acts as a
/// pseudo-source (a saddle or boundary vertex \[MMP87\]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum PseudoSource {
    /// The source with this index in the list passed to the propagation.
    Source(SourceId),
    /// A mesh vertex.
    Vertex(VertexId),
}

/// A wedge on an edge: the 6-tuple `(b0, b1, d0, d1, sigma, tau)` of Definition 1 [LZT §2],
/// plus the identity of its pseudo-source and of the source it leads back to.
///
/// The pseudo-source is stored as its unfolded position `(source_x, source_y)` in the edge's
/// frame rather than as `(d0, d1)`; both distances follow from it ([`Wedge::d0`], [`Wedge::d1`]),
/// and keeping the position avoids re-deriving it (which exact backends would pay for).
#[derive(Clone, Debug, PartialEq)]
pub struct Wedge<S> {
    /// The edge the wedge lies on.
    pub edge: EdgeId,
    /// Start of the wedge's range, measured from the edge's `vertices[0]`.
    pub b0: S,
    /// End of the wedge's range (`b0 < b1`).
    pub b1: S,
    /// The pseudo-source's position along the edge.
    pub source_x: S,
    /// The pseudo-source's distance from the edge's line (`>= 0`, on side `tau`).
    pub source_y: S,
    /// Geodesic distance from the pseudo-source to the source.
    pub sigma: S,
    /// The side of the edge the pseudo-source lies on.
    pub tau: Side,
    /// The pseudo-source.
    pub pseudo_source: PseudoSource,
    /// Index of the source the wedge's geodesics lead back to.
    pub source: SourceId,
}

/// The fields of a wedge that the intersection reads ([`cut_into_pieces`]), read where they
/// are stored: an edge list keeps its wedges without their edge, and copying the overlapped
/// ones out into wedges cost more than the rest of placing a new wedge beside them.
///
/// [`cut_into_pieces`]: super::intersect::cut_into_pieces
pub(crate) trait WedgeFields<S> {
    /// Start of the range.
    fn b0(&self) -> &S;
    /// End of the range.
    fn b1(&self) -> &S;
    /// The pseudo-source's position along the edge.
    fn source_x(&self) -> &S;
    /// The pseudo-source's distance from the edge's line.
    fn source_y(&self) -> &S;
    /// Geodesic distance from the pseudo-source to the source.
    fn sigma(&self) -> &S;
    /// The pseudo-source.
    fn pseudo_source(&self) -> PseudoSource;

    /// The geodesic distance the wedge gives along its edge.
    #[inline]
    fn distance_function(&self) -> SourceDistance<S>
    where
        S: Clone,
    {
        SourceDistance {
            x: self.source_x().clone(),
            y: self.source_y().clone(),
            sigma: self.sigma().clone(),
        }
    }

    /// The smallest distance the wedge gives on its range (its priority [SSK+05 §4]): at the
    /// foot of the pseudo-source if inside, else at the nearer end (the distance is convex);
    /// `sigma + y`, at most below it by the backend's resolution, where the backend leaves the
    /// foot's side of an end open ([`Scalar::foot_within`]). Read as a key of the queue and
    /// against a maximum distance, where a lower value only keeps a wedge longer.
    fn min_distance(&self) -> S
    where
        S: Scalar,
    {
        let (x, b0, b1) = (self.source_x(), self.b0(), self.b1());
        if S::foot_within(x, b0, b1, true) {
            self.sigma().clone() + self.source_y()
        } else {
            let d = self.distance_function();
            S::min_of(&d.at(b0), &d.at(b1))
        }
    }

    /// Whether `[lo, hi]`, a stretch of this wedge's range on an edge of length `length`, is
    /// long enough to be a wedge of its own: by the edge's resolution
    /// ([`Scalar::has_extent`]), or because the pseudo-source sees it under a wide angle
    /// ([`Scalar::fans_out`]).
    #[inline]
    fn has_extent_on(&self, lo: &S, hi: &S, length: &S) -> bool
    where
        S: Scalar,
    {
        S::has_extent(lo, hi, length) || S::fans_out(lo, hi, self.source_x(), self.source_y())
    }
}

/// Implements [`WedgeFields`] for a type that stores the wedge's fields under their names.
macro_rules! wedge_fields {
    ($t:ident) => {
        impl<S: $crate::scalar::Scalar> $crate::mmp::wedge::WedgeFields<S> for $t<S> {
            #[inline(always)]
            fn b0(&self) -> &S {
                &self.b0
            }
            #[inline(always)]
            fn b1(&self) -> &S {
                &self.b1
            }
            #[inline(always)]
            fn source_x(&self) -> &S {
                &self.source_x
            }
            #[inline(always)]
            fn source_y(&self) -> &S {
                &self.source_y
            }
            #[inline(always)]
            fn sigma(&self) -> &S {
                &self.sigma
            }
            #[inline(always)]
            fn pseudo_source(&self) -> $crate::mmp::wedge::PseudoSource {
                self.pseudo_source
            }
        }
    };
}
pub(crate) use wedge_fields;

wedge_fields!(Wedge);

impl<S: Scalar> Wedge<S> {
    /// Distance from the pseudo-source to the point `b0` of the edge.
    pub fn d0(&self) -> S {
        self.distance_function().at(&self.b0) - &self.sigma
    }

    /// Distance from the pseudo-source to the point `b1` of the edge.
    pub fn d1(&self) -> S {
        self.distance_function().at(&self.b1) - &self.sigma
    }

    /// The geodesic distance this wedge gives along its edge, `D(t) = sigma + |s - t|`.
    #[inline]
    pub fn distance_function(&self) -> SourceDistance<S> {
        SourceDistance {
            x: self.source_x.clone(),
            y: self.source_y.clone(),
            sigma: self.sigma.clone(),
        }
    }

    /// The unfolded pseudo-source in the edge's frame (y >= 0 on side tau).
    #[inline]
    pub(crate) fn source_point(&self) -> Planar<S> {
        Planar {
            x: self.source_x.clone(),
            y: self.source_y.clone(),
        }
    }

    /// The same wedge with every length multiplied by `factor` (a change of units).
    pub(crate) fn scaled(&self, factor: &S) -> Wedge<S> {
        let times = |x: &S| x.clone() * factor;
        Wedge {
            b0: times(&self.b0),
            b1: times(&self.b1),
            source_x: times(&self.source_x),
            source_y: times(&self.source_y),
            sigma: times(&self.sigma),
            ..self.clone()
        }
    }

    /// The scale of the constructions that place points of the wedge's range on its edge (of
    /// length `length`): the edge's length or the pseudo-source's offsets from the edge's
    /// first vertex, whichever is larger. Rays from a pseudo-source many edge lengths away
    /// meet the edge at positions rounded to ulps of that distance, not of the edge.
    pub(crate) fn reach(&self, length: &S) -> S {
        S::max_of(length, &self.source_reach())
    }

    /// The pseudo-source's offsets from the edge's first vertex: the scale of the
    /// constructions that place points of the range near that vertex, where the edge's
    /// length does not enter them.
    pub(crate) fn source_reach(&self) -> S {
        let offset = S::max_of(&self.source_x, &-self.source_x.clone());
        S::max_of(&offset, &self.source_y)
    }

    /// The smallest distance the wedge gives on its range (its priority [SSK+05 §4]).
    pub fn min_distance(&self) -> S {
        WedgeFields::min_distance(self)
    }
}
