//! Exact planar predicates (Shewchuk's adaptive orientation test) and the few f64 constructions
//! the benchmark model needs.

use robust::{orient2d, Coord};
use std::cmp::Ordering;

/// A point of the plane.
pub type Point = [f64; 2];

/// The side of `c` seen from `a` towards `b`: `Greater` on the left (counter-clockwise turn),
/// `Equal` on the line. Exact for every pair of finite f64 inputs.
pub(crate) fn orient(a: Point, b: Point, c: Point) -> Ordering {
    let coord = |p: Point| Coord { x: p[0], y: p[1] };
    orient2d(coord(a), coord(b), coord(c))
        .partial_cmp(&0.0)
        .unwrap_or(Ordering::Equal)
}

/// Whether `x` lies on the closed segment `ab`, exactly.
pub(crate) fn on_segment(a: Point, b: Point, x: Point) -> bool {
    orient(a, b, x) == Ordering::Equal && within_box(a, b, x)
}

/// Whether `x` lies strictly between `a` and `b` on the segment `ab`, exactly.
pub(crate) fn strictly_inside_segment(a: Point, b: Point, x: Point) -> bool {
    x != a && x != b && on_segment(a, b, x)
}

fn within_box(a: Point, b: Point, x: Point) -> bool {
    (0..2).all(|i| a[i].min(b[i]) <= x[i] && x[i] <= a[i].max(b[i]))
}

/// Whether the closed segments `ab` and `cd` share a point.
pub(crate) fn segments_touch(a: Point, b: Point, c: Point, d: Point) -> bool {
    segments_cross(a, b, c, d)
        || on_segment(a, b, c)
        || on_segment(a, b, d)
        || on_segment(c, d, a)
        || on_segment(c, d, b)
}

/// Whether the segments `ab` and `cd` cross at one point interior to both (a proper crossing).
pub(crate) fn segments_cross(a: Point, b: Point, c: Point, d: Point) -> bool {
    let opposite = |x: Ordering, y: Ordering| x != Ordering::Equal && x == y.reverse();
    opposite(orient(a, b, c), orient(a, b, d)) && opposite(orient(c, d, a), orient(c, d, b))
}

/// Where a point is with respect to a closed polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Location {
    Inside,
    Boundary,
    Outside,
}

/// Locates `x` in a simple polygon (either orientation) by the crossing number of the ray to +x,
/// each crossing decided exactly.
pub(crate) fn locate(polygon: &[Point], x: Point) -> Location {
    let mut inside = false;
    for (i, &a) in polygon.iter().enumerate() {
        let b = polygon[(i + 1) % polygon.len()];
        if on_segment(a, b, x) {
            return Location::Boundary;
        }
        if (a[1] > x[1]) != (b[1] > x[1]) {
            // The edge crosses the horizontal line through x; the crossing is right of x when x is
            // left of the edge directed upwards.
            let upwards = if a[1] < b[1] { (a, b) } else { (b, a) };
            if orient(upwards.0, upwards.1, x) == Ordering::Greater {
                inside = !inside;
            }
        }
    }
    if inside {
        Location::Inside
    } else {
        Location::Outside
    }
}

/// Euclidean distance.
pub(crate) fn distance(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Distance from `x` to the closed segment `ab`.
pub(crate) fn distance_to_segment(a: Point, b: Point, x: Point) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let t = if len2 > 0.0 {
        (((x[0] - a[0]) * d[0] + (x[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    distance([a[0] + t * d[0], a[1] + t * d[1]], x)
}

/// The smallest axis-parallel box holding the polygon: lower left, upper right.
pub(crate) fn bounding_box(polygon: &[Point]) -> [Point; 2] {
    polygon.iter().fold(
        [[f64::INFINITY; 2], [f64::NEG_INFINITY; 2]],
        |[lo, hi], x| {
            [
                [lo[0].min(x[0]), lo[1].min(x[1])],
                [hi[0].max(x[0]), hi[1].max(x[1])],
            ]
        },
    )
}
