//! What a wedge keeps of how it was built, for number types that keep values
//! ([`Scalar::Kept`]): the engine then hands out one expression for one quantity, and an exact
//! backend proves the identities MMP creates by structure instead of by arithmetic.
//!
//! Two identities matter [SSK+05 §4, LZT §2]:
//! - a vertex lit by one construction across a face is reached again by its descendants (and
//!   from both sides of the vertex): they keep the distance at their edge's vertices;
//! - behind a vertex that acts as a pseudo-source, the wedges of the pseudo-source and the lit
//!   wedges that pass the vertex meet along the vertex's *shadow line*, the ray from the lit
//!   wedges' pseudo-source through the vertex: a lit wedge's range end on that line keeps the
//!   vertex's image as an [`Anchor`], computes where the line goes on from the anchor (as the
//!   pseudo-source's own wedges do from the same image), and gives its distance there as the
//!   pseudo-source's wedges do.

use super::flat_region::RegionImage;
use super::paths::Path;
use super::planar::Planar;
use super::strips::Strip;
use super::wedge::Wedge;
use crate::scalar::{Scalar, SourceDistance};
use std::cmp::Ordering;

/// A vertex on the ray through a wedge's range end from the wedge's pseudo-source: the end lies
/// on that vertex's shadow line.
#[derive(Clone, Debug)]
pub(crate) struct Anchor<S> {
    /// The vertex's image in the edge's frame (on the wedge's side of the line).
    pub(crate) point: Planar<S>,
    /// The wedge's distance at the vertex.
    pub(crate) distance: S,
    /// The vertex's image in the frame of the flat region the wedge lies in, if it does.
    pub(crate) image: Option<RegionImage<S>>,
    /// The image whose shadow line through the vertex the end lies on, where it is not the
    /// wedge's own: for a wedge of the vertex itself, cut where the wedges of that image end.
    pub(crate) light: Option<Light<S>>,
}

/// An image that casts a shadow line through an anchor, kept as an anchor is: in the edge's
/// frame and, in a flat region, in the region's frame.
#[derive(Clone, Debug)]
pub(crate) struct Light<S> {
    /// The image in the edge's frame.
    pub(crate) point: Planar<S>,
    /// The image in the frame of the flat region the wedge lies in, if it does.
    pub(crate) image: Option<RegionImage<S>>,
    /// The path that brought the image to the wedge's edge, where the run keeps paths: the
    /// path of the wedge it lit, continued across the faces this wedge crossed since.
    pub(crate) path: Option<Path>,
    /// The key of the image on the wedge's edge, if known
    /// ([`image_key`](super::paths::CongruentPaths::image_key)).
    pub(crate) key: Option<u32>,
}

impl<S: Scalar> Anchor<S> {
    /// The wedge's distance along the edge seen from the anchor: equal to the wedge's own on
    /// the shadow line, and built as a wedge of the vertex (a pseudo-source) builds its own.
    pub(crate) fn distance_function(&self) -> SourceDistance<S> {
        SourceDistance {
            x: self.point.x.clone(),
            y: self.point.y.clone(),
            sigma: self.distance.clone(),
        }
    }
}

/// What a wedge keeps of how it was built (nothing for number types that keep no values).
#[derive(Clone, Debug)]
pub(crate) struct Provenance<S: Scalar> {
    /// The wedge's distance function at its edge's `vertices[0]` and `vertices[1]`: every
    /// wedge born of one construction across a face, and all their descendants that keep a
    /// vertex of it as an end of their edge, give that vertex the very same value.
    pub(crate) at_ends: [S::Kept<S>; 2],
    /// The anchors of the range's ends `b0` and `b1`, where they lie on a shadow line.
    pub(crate) anchors: [S::Kept<Anchor<S>>; 2],
    /// The distance functions of the wedges whose crossings with this one (roots of eq. (1))
    /// are the range's ends `b0` and `b1`, where they are: the two are equal there.
    pub(crate) crossings: [S::Kept<SourceDistance<S>>; 2],
    /// The pseudo-source's image in the frame of the flat region the wedge lies in, if it does
    /// (see `flat_region.rs`).
    pub(crate) image: S::Kept<RegionImage<S>>,
    /// The path the wedge continues, up to the face it came across (or the edge it lies
    /// along), where the run proves ties by symmetry (see `paths.rs`).
    pub(crate) path: S::Kept<Path>,
    /// The strip the wedge is seen through, where the run knows wedges offered again (see
    /// `strips.rs`).
    pub(crate) strip: S::Kept<Strip>,
    /// The shadow lines the range's ends `b0` and `b1` lie on where they are another wedge's
    /// anchored ends but not on a ray of this wedge's: known on this edge only.
    pub(crate) shadows: [S::Kept<ShadowLine<S>>; 2],
    /// The key of the wedge's image on its edge, if known
    /// ([`image_key`](super::paths::CongruentPaths::image_key)).
    pub(crate) image_key: S::Kept<u32>,
}

/// A shadow line, by the anchor it passes and the image that casts it, in an edge's frame.
#[derive(Clone, Debug)]
pub(crate) struct ShadowLine<S> {
    /// The anchor.
    pub(crate) anchor: Planar<S>,
    /// The image.
    pub(crate) light: Planar<S>,
    /// The image in the frame of the flat region the wedge lies in, if it does.
    pub(crate) light_image: Option<RegionImage<S>>,
    /// The path that brought the image to the edge, and the image's key there, where known
    /// (as a [`Light`] keeps them).
    pub(crate) light_path: Option<Path>,
    pub(crate) light_key: Option<u32>,
}

impl<S: Scalar> Default for Provenance<S> {
    fn default() -> Self {
        Provenance {
            at_ends: Default::default(),
            anchors: Default::default(),
            crossings: Default::default(),
            image: Default::default(),
            path: Default::default(),
            strip: Default::default(),
            shadows: Default::default(),
            image_key: Default::default(),
        }
    }
}

impl<S: Scalar> Provenance<S> {
    /// The provenance of given distances at the edge's vertices and anchors of the range ends.
    pub(crate) fn new(at_ends: [S::Kept<S>; 2], anchors: [Option<Anchor<S>>; 2]) -> Self {
        // Element by element: `anchors.map` was called out of line even where nothing is kept.
        let keep = |a: Option<Anchor<S>>| a.map_or_else(Default::default, |a| S::keep(|| a));
        let [a0, a1] = anchors;
        Provenance {
            at_ends,
            anchors: [keep(a0), keep(a1)],
            crossings: Default::default(),
            image: Default::default(),
            path: Default::default(),
            strip: Default::default(),
            shadows: Default::default(),
            image_key: Default::default(),
        }
    }

    /// The same provenance with the pseudo-source's image in a flat region's frame.
    pub(crate) fn with_image(mut self, image: Option<RegionImage<S>>) -> Self {
        self.image = image.map_or_else(Default::default, |i| S::keep(|| i));
        self
    }

    /// The same provenance with the path the wedge continues.
    pub(crate) fn with_path(mut self, path: S::Kept<Path>) -> Self {
        self.path = path;
        self
    }

    /// The same provenance with the strip the wedge is seen through.
    pub(crate) fn with_strip(mut self, strip: Option<Strip>) -> Self {
        self.strip = strip.map_or_else(Default::default, |s| S::keep(|| s));
        self
    }

    /// Whether range end `i` of this wedge and range end `j` of `other`'s, on the same edge,
    /// are one point by their strips (see `strips.rs`): known without comparing the values.
    pub(crate) fn same_end(&self, i: usize, other: &Provenance<S>, j: usize) -> bool {
        match (S::kept(&self.strip), S::kept(&other.strip)) {
            (Some(a), Some(b)) => a.same_end(i, &b, j),
            _ => false,
        }
    }

    /// The anchor of range end `i` (0: `b0`, 1: `b1`), if kept.
    pub(crate) fn anchor(&self, i: usize) -> Option<Anchor<S>> {
        S::kept(&self.anchors[i])
    }

    /// The shadow line range end `i` lies on, if known: its anchor's, from the anchor's light
    /// or the wedge's image `own`, or the line it keeps on this edge.
    pub(crate) fn shadow_line(&self, i: usize, own: [&S; 2]) -> Option<ShadowLine<S>> {
        let Some(a) = self.anchor(i) else {
            return S::kept(&self.shadows[i]);
        };
        let (light, light_image, light_path, light_key) = match a.light {
            Some(l) => (l.point, l.image, l.path, l.key),
            None => {
                let [x, y] = own.map(S::clone);
                let (path, key) = (S::kept(&self.path), S::kept(&self.image_key));
                (Planar { x, y }, S::kept(&self.image), path, key)
            }
        };
        Some(ShadowLine {
            anchor: a.point,
            light,
            light_image,
            light_path,
            light_key,
        })
    }

    /// The same provenance with range end `i` at another wedge's range end `theirs` on the
    /// same edge: where that end lies on a shadow line, so does this one. Kept for this edge
    /// only, or, for a wedge of the anchor's vertex itself (`own`: its image and distance,
    /// where it is a vertex's wedge), whose rays leave the anchor, as an anchor lit by the
    /// other's light and carried on with the wedge: the ends carried on from both wedges are
    /// then one point by structure ([`one_end`]).
    pub(crate) fn ending_on(
        mut self,
        i: usize,
        (_, their_kept, j, theirs): RangeEnd<'_, S>,
        own: Option<([&S; 2], &S)>,
    ) -> Self {
        if self.anchor(i).is_some() {
            return self;
        }
        let Some(line) = their_kept.shadow_line(j, theirs) else {
            return self;
        };
        match own {
            Some((image, sigma))
                if S::proved_same_point(image, [&line.anchor.x, &line.anchor.y]) =>
            {
                let anchor = Anchor {
                    point: line.anchor,
                    distance: sigma.clone(),
                    image: S::kept(&self.image),
                    light: Some(Light {
                        point: line.light,
                        image: line.light_image,
                        path: line.light_path,
                        key: line.light_key,
                    }),
                };
                self.anchors[i] = S::keep(|| anchor);
            }
            _ => self.shadows[i] = S::keep(|| line),
        }
        self
    }

    /// The distance function of the wedge whose crossing with this one is range end `i`, if
    /// kept.
    pub(crate) fn crossing(&self, i: usize) -> Option<SourceDistance<S>> {
        S::kept(&self.crossings[i])
    }

    /// The same provenance with the anchors and crossings of the range ends that `keep` says
    /// are still the wedge's ends (a trimmed end is a new point, no longer on the shadow line).
    pub(crate) fn trimmed(&self, keep: [bool; 2]) -> Self {
        fn kept_ends<T: Clone + Default>(ends: &[T; 2], keep: [bool; 2]) -> [T; 2] {
            [0, 1].map(|i| {
                if keep[i] {
                    ends[i].clone()
                } else {
                    T::default()
                }
            })
        }
        Provenance {
            at_ends: self.at_ends.clone(),
            anchors: kept_ends(&self.anchors, keep),
            crossings: kept_ends(&self.crossings, keep),
            image: self.image.clone(),
            path: self.path.clone(),
            // A trimmed end is a crossing or another wedge's end: the strip does not fix it.
            strip: S::kept(&self.strip)
                .map_or_else(Default::default, |strip| S::keep(|| strip.trimmed(keep))),
            shadows: kept_ends(&self.shadows, keep),
            image_key: self.image_key.clone(),
        }
    }

    /// The same provenance with the crossings that are now its range ends: `crossed[i]` is the
    /// distance function of the wedge that crosses this one at end `i`.
    pub(crate) fn with_crossings(mut self, crossed: [Option<SourceDistance<S>>; 2]) -> Self {
        for (kept, crossed) in self.crossings.iter_mut().zip(crossed) {
            if let Some(f) = crossed {
                *kept = S::keep(|| f);
            }
        }
        self
    }

    /// The provenance of a wedge joined from two that continue one another, this one first
    /// and `next` after it along the edge, with the same distance function (as the backend
    /// decided): the anchor of each range end from the wedge that owned that end, the
    /// distances at the edge's vertices, the region image and the path from the first where
    /// it keeps them (the two give the same values there), and a strip that describes both
    /// ([`Strip::joined`]).
    pub(crate) fn joined(self, next: Self) -> Self {
        let either = |a: S::Kept<S>, b: S::Kept<S>| if S::kept(&a).is_some() { a } else { b };
        let [first_0, first_1] = self.at_ends;
        let [next_0, next_1] = next.at_ends;
        let [anchor_0, _] = self.anchors;
        let [_, anchor_1] = next.anchors;
        let [crossing_0, _] = self.crossings;
        let [_, crossing_1] = next.crossings;
        let [shadow_0, _] = self.shadows;
        let [_, shadow_1] = next.shadows;
        let image = if S::kept(&self.image).is_some() {
            self.image
        } else {
            next.image
        };
        let path = if S::kept(&self.path).is_some() {
            self.path
        } else {
            next.path
        };
        // One image, proved so: either key describes it.
        let image_key = if S::kept(&self.image_key).is_some() {
            self.image_key
        } else {
            next.image_key
        };
        Provenance {
            at_ends: [either(first_0, next_0), either(first_1, next_1)],
            anchors: [anchor_0, anchor_1],
            crossings: [crossing_0, crossing_1],
            image,
            path,
            strip: match (S::kept(&self.strip), S::kept(&next.strip)) {
                (Some(first), Some(next)) => S::keep(|| first.joined(&next)),
                _ => Default::default(),
            },
            shadows: [shadow_0, shadow_1],
            image_key,
        }
    }

    /// The same provenance with the keys of the images on the wedge's edge: its own, `own`,
    /// and its anchors' lights', by `key_of` their paths
    /// ([`image_key`](super::paths::CongruentPaths::image_key)).
    pub(crate) fn keyed(
        mut self,
        own: Option<u32>,
        mut key_of: impl FnMut(&Path) -> Option<u32>,
    ) -> Self {
        self.image_key = own.map_or_else(Default::default, |k| S::keep(|| k));
        for kept in &mut self.anchors {
            let Some(mut a) = S::kept(kept) else { continue };
            if let Some(light) = a.light.as_mut() {
                light.key = light.path.as_ref().and_then(&mut key_of);
                *kept = S::keep(|| a);
            }
        }
        self
    }
}

/// Whether the number type keeps values ([`Scalar::Kept`]), and wedges their provenance: a
/// constant of the number type, folded wherever it is asked.
#[inline(always)]
pub(crate) fn keeps_values<S: Scalar>() -> bool {
    S::kept(&S::keep(|| ())).is_some()
}

/// A range end of a wedge as [`compare_ends`] sees it: its value, what the wedge keeps, which
/// end (0: `b0`, 1: `b1`), and the wedge's image.
pub(crate) type RangeEnd<'a, S> = (&'a S, &'a Provenance<S>, usize, [&'a S; 2]);

/// Range end `i` (0: `b0`, 1: `b1`) of wedge `w`, which keeps `kept`, as [`compare_ends`]
/// sees it.
pub(crate) fn range_end<'a, S: Scalar>(
    w: &'a Wedge<S>,
    kept: &'a Provenance<S>,
    i: usize,
) -> RangeEnd<'a, S> {
    let value = if i == 0 { &w.b0 } else { &w.b1 };
    (value, kept, i, [&w.source_x, &w.source_y])
}

/// Whether two range ends on one edge are one point by structure: their strips name them
/// alike, or both lie on one shadow line, of one anchor from one image (the line meets the
/// edge once): the image proved one point, or of one key (the mirror images of a light brought
/// to the edge from its two sides, through mirror-image flat regions, are one point of the
/// edge's frame but two expressions no normal form relates). `false` says nothing.
pub(crate) fn one_end<S: Scalar>(
    (_, ka, i, sa): RangeEnd<'_, S>,
    (_, kb, j, sb): RangeEnd<'_, S>,
) -> bool {
    let same = |p: &Planar<S>, q: &Planar<S>| S::proved_same_point([&p.x, &p.y], [&q.x, &q.y]);
    let one_shadow = || match (ka.shadow_line(i, sa), kb.shadow_line(j, sb)) {
        (Some(p), Some(q)) => {
            let one_key = p.light_key.is_some() && p.light_key == q.light_key;
            same(&p.anchor, &q.anchor) && (one_key || same(&p.light, &q.light))
        }
        _ => false,
    };
    ka.same_end(i, kb, j) || one_shadow()
}

/// The order of two range ends on one edge: equal where they are one point by structure
/// ([`one_end`]), else the backend's comparison of the values.
pub(crate) fn compare_ends<S: Scalar>(a: RangeEnd<'_, S>, b: RangeEnd<'_, S>) -> Ordering {
    if one_end(a, b) {
        Ordering::Equal
    } else {
        a.0.compare(b.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::{Field, Real};

    fn real(n: i64) -> Real {
        Real::from_integer(n)
    }

    /// A range end on the shadow line of an anchor, from an image.
    fn anchored(anchor: [Real; 2]) -> Provenance<Real> {
        let [x, y] = anchor;
        let anchor = Anchor {
            point: Planar { x, y },
            distance: real(1),
            image: None,
            light: None,
        };
        Provenance::new([None, None], [None, Some(anchor)])
    }

    /// Two ends on the shadow line of one anchor from one image are one point, by structure
    /// (the anchor's and the image's values handed on from one construction, as the engine
    /// hands them to the wedges it cuts): their values are not compared, so values that only
    /// an unbounded refinement could tell equal are never asked. Another anchor, or another
    /// image, leaves the comparison to the values.
    #[test]
    fn ends_on_one_shadow_line_are_equal_without_comparing_their_values() {
        let root = real(2).sqrt();
        let image = [real(3), root.clone() + &real(1)];
        let same_image = image.clone();
        let vertex = [real(1), root.clone() / &real(4)];
        let a = anchored(vertex.clone());
        let b = anchored(vertex);
        let (lo, hi) = (real(1), real(2));
        let order = |kb: &Provenance<Real>, image_b: [&Real; 2]| {
            compare_ends((&lo, &a, 1, [&image[0], &image[1]]), (&hi, kb, 1, image_b))
        };
        assert_eq!(order(&b, [&same_image[0], &same_image[1]]), Ordering::Equal);
        let elsewhere = anchored([real(1), root / &real(5)]);
        assert_eq!(
            order(&elsewhere, [&same_image[0], &same_image[1]]),
            Ordering::Less
        );
        let other_image = [real(3), real(2)];
        assert_eq!(
            order(&b, [&other_image[0], &other_image[1]]),
            Ordering::Less
        );
    }
}
