//! Creases: the unfolding of one flat region into the plane of another across the straight
//! line along which they meet.
//!
//! Two planes meet in one line, so every edge between two flat regions lies on it (on a CAD
//! model, a straight feature line of many edges). Unfolding across any of them is one and the
//! same isometry of the plane: it fixes that line point by point and puts the two regions on
//! opposite sides of it. Built from each edge's own frame, as a wedge crossing it would build
//! it, each edge gives that isometry its own expression, and the images of one pseudo-source
//! that cross the line at two edges and meet again in the next region are one point an exact
//! backend cannot prove equal. Built once per pair of regions, from one edge of the line, the
//! map gives them one expression: their equality is then proved by structure.

use crate::scalar::Scalar;

/// An edge's frame in a region's frame: the region point of the frame's start, the direction
/// to its other end, and whether the face of the region at the edge lies left of it.
pub(crate) type EdgeInRegion<'a, S> = (&'a [S; 2], [S; 2], bool);

/// The isometry from one region's frame to another's across their common line:
/// `q -> to + rotation (q - from)`.
#[derive(Clone, Debug)]
pub(crate) struct Crease<S> {
    from: [S; 2],
    to: [S; 2],
    rotation: [[S; 2]; 2],
}

impl<S: Scalar> Crease<S> {
    /// The unfolding across an edge, given its frame in the region left and in the region
    /// entered and its squared length: a point is placed in the edge's frame on the side away
    /// from the face entered, then in the entered region's frame, as `FlatRegions::to_edge`
    /// and `FlatRegions::entering` do for one wedge.
    pub(crate) fn new(
        (p0, d, left): EdgeInRegion<'_, S>,
        (q0, e, enters_left): EdgeInRegion<'_, S>,
        squared_length: &S,
    ) -> Self {
        // Along the edge a point keeps its offset; across it, its distance from the line,
        // on the side away from the face entered: the same side of the edge's direction in
        // both frames when the faces lie on opposite sides of it, else the other.
        let across = if left == enters_left { -1.0 } else { 1.0 };
        let s = [0, 1].map(|i| S::from_f64(across) * &d[i]);
        let entry = |a: S, b: S| (a + &b) / squared_length;
        let rotation = [
            [
                entry(d[0].clone() * &e[0], s[1].clone() * &e[1]),
                entry(d[1].clone() * &e[0], -(s[0].clone() * &e[1])),
            ],
            [
                entry(d[0].clone() * &e[1], -(s[1].clone() * &e[0])),
                entry(d[1].clone() * &e[1], s[0].clone() * &e[0]),
            ],
        ];
        Crease {
            from: p0.clone(),
            to: q0.clone(),
            rotation,
        }
    }

    /// A point of the frame of the region left in the frame of the region entered.
    pub(crate) fn apply(&self, q: &[S; 2]) -> [S; 2] {
        let r = [q[0].clone() - &self.from[0], q[1].clone() - &self.from[1]];
        [0, 1].map(|i| {
            let m = &self.rotation[i];
            self.to[i].clone() + &(m[0].clone() * &r[0] + &(m[1].clone() * &r[1]))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An edge from (1, 2) along (3, 4) in the frame of the region left, its face on the left;
    /// from (0, 0) along (0, 5) in the frame of the region entered. A point 2 along the edge
    /// and 1 from it on the side of the face left lies, unfolded, 2 along the edge and 1 from
    /// it on the side away from the face entered.
    #[test]
    fn a_point_keeps_its_offset_along_the_line_and_its_distance_from_it() {
        let (p0, q0) = ([1.0, 2.0], [0.0, 0.0]);
        let (d, e) = ([3.0, 4.0], [0.0, 5.0]);
        // 2 along (3, 4) / 5, then 1 along its left normal (-4, 3) / 5.
        let point = [1.0 + 1.2 - 0.8, 2.0 + 1.6 + 0.6];
        let on_line = [1.0 + 1.5, 2.0 + 2.0];
        for (enters_left, away) in [(true, 1.0), (false, -1.0)] {
            let crease = Crease::new((&p0, d, true), (&q0, e, enters_left), &25.0);
            let [x, y] = crease.apply(&point);
            assert!(
                (x - away).abs() < 1e-12 && (y - 2.0).abs() < 1e-12,
                "{x} {y}"
            );
            let [x, y] = crease.apply(&on_line);
            assert!(x.abs() < 1e-12 && (y - 2.5).abs() < 1e-12, "{x} {y}");
        }
        // The face left on the right of the edge's direction: a point on the left, across the
        // line from it, ends on the side of the face entered.
        let crease = Crease::new((&p0, d, false), (&q0, e, true), &25.0);
        let [x, y] = crease.apply(&point);
        assert!(
            (x + 1.0).abs() < 1e-12 && (y - 2.0).abs() < 1e-12,
            "{x} {y}"
        );
    }
}
