//! Gaps that rounding leaves between the cones of two wedges meeting at a range end.
//!
//! Two wedges that meet on an edge, one beside the other, light the face beyond through rays
//! from their pseudo-sources through the point where they meet: in exact arithmetic those
//! rays cross or coincide beyond the edge, and every point there is lit. A number type that
//! rounds its constructions places that point a little off, most of all where eq. (2) nearly
//! has a double root (to about the square root of the rounding, 1.5e-8 of the scale), and the
//! rays may then part: a vertex between them is lit by neither wedge. On a tetrahedron and an
//! octahedron rounded to 8 decimals, vertices so missed came out 2 to 3 % long in both the
//! `f64` and the adaptive backend; on such solids split finer, from most sources, by up to 21 %.
//!
//! Such a vertex is reached by the path through the nearer end of a wedge's range, straight
//! across the face: a path on the surface however the end was rounded, so never shorter than
//! the geodesic, and the geodesic to within the rounding where the vertex lies in such a gap.
//! Number types that keep values construct exactly and leave no gaps.

use super::provenance::keeps_values;
use super::wedge::Wedge;
use crate::mesh::TriMesh;
use crate::scalar::Scalar;
use std::cmp::Ordering;

/// The widest gap that rounded crossings are taken to leave, as a fraction of the scale of the
/// meeting: the edge's length or, if larger, the image's offsets from the range's end. A
/// crossing near a double root is placed to about the square root of the rounding times the
/// size of the images' offsets (the gap that left a vertex of the tetrahedron unlit was 7e-9
/// of its edge). The path through a range end is a path whatever the gap, so this only bounds
/// the work of offering it to vertices that no rounding could have put there.
const ROUNDED_GAP: f64 = 1e-6;

/// On a mesh whose edge lengths span a wide factor, an image unfolded across long edges is
/// placed to about `f64::EPSILON` times that factor of the scale ([`ValidationReport`]'s
/// `edge_length_span`), and so is a shadow constructed from it: the gap is taken to be this
/// many times wider. On a corpus mesh with edges from 1e-5 to 3e8 (span 7e9), the shadow of a
/// vertex beside a range's end fell 492 beyond it (1.6e-6 of its scale 3e8), outside
/// [`ROUNDED_GAP`], and the vertex came out 2e4 long (6.7e-5 relative) by another way.
///
/// [`ValidationReport`]: crate::mesh::ValidationReport
const SPAN_GAPS: f64 = 16.0;

/// The widest gap, as a fraction of the meeting's scale, that rounding may leave on `mesh`.
pub(crate) fn gap_fraction(mesh: &TriMesh) -> f64 {
    ROUNDED_GAP.max(SPAN_GAPS * f64::EPSILON * mesh.validation().edge_length_span)
}

/// The end of the wedge's range (on an edge of the given length) beside which the `shadow` of
/// a point, where the ray from the pseudo-source to it crosses the edge's line, lies outside
/// the range in a gap that rounding may have left (`gap`, [`gap_fraction`] of the mesh);
/// `None` for number types that keep values, which do not construct the shadow. The others'
/// values are their `f64`s, so the gap is measured on them.
pub(crate) fn end_beside<'a, S: Scalar>(
    w: &'a Wedge<S>,
    shadow: impl FnOnce() -> S,
    length: &S,
    gap: f64,
) -> Option<&'a S> {
    if keeps_values::<S>() {
        return None;
    }
    let shadow = shadow();
    let end = if shadow.compare(&w.b0) == Ordering::Less {
        &w.b0
    } else if shadow.compare(&w.b1) == Ordering::Greater {
        &w.b1
    } else {
        return None;
    };
    let end_f64 = end.to_f64();
    let scale = [
        length.to_f64(),
        (w.source_x.to_f64() - end_f64).abs(),
        w.source_y.to_f64().abs(),
    ]
    .into_iter()
    .fold(0.0, f64::max);
    ((shadow.to_f64() - end_f64).abs() <= gap * scale).then_some(end)
}

/// The length of the path through the point `end` of the wedge's range to the point at
/// `(x, y)` in the edge's frame (on either side): the wedge's distance there and the segment.
pub(crate) fn distance_through<S: Scalar>(w: &Wedge<S>, end: &S, (x, y): (&S, &S)) -> S {
    let dx = x.clone() - end;
    w.distance_function().at(end) + &(dx.clone() * dx + y.clone() * y).sqrt()
}
