//! Exact planar predicates (Shewchuk's adaptive orientation test) and the few f64 constructions
//! the benchmark model needs.

use glam::DVec2;
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
    let d = DVec2::from(a) - DVec2::from(b);
    d.x.hypot(d.y)
}

/// Distance from `x` to the closed segment `ab`.
pub(crate) fn distance_to_segment(a: Point, b: Point, x: Point) -> f64 {
    let (a, b, x) = (DVec2::from(a), DVec2::from(b), DVec2::from(x));
    let d = b - a;
    let len2 = d.length_squared();
    let t = if len2 > 0.0 {
        ((x - a).dot(d) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    distance((a + d * t).to_array(), x.to_array())
}

/// The smallest axis-parallel box holding the polygon: lower left, upper right.
pub(crate) fn bounding_box(polygon: &[Point]) -> [Point; 2] {
    let (lo, hi) = polygon
        .iter()
        .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(x.into()), hi.max(x.into()))
        });
    [lo.to_array(), hi.to_array()]
}
