//! The ground truth of [LZT §5]: the Euclidean shortest path from p to q among the obstacles,
//! by Dijkstra's algorithm on the visibility graph VG(S ∪ {p, q}) [LZT refs. 19-21].
//!
//! Every visibility decision is made with exact orientation predicates. A segment may touch an
//! obstacle's corners and run along its edges; it is blocked only where it enters an interior.

use super::geometry::{
    bounding_box, distance, orient, segments_cross, strictly_inside_segment, Point,
};
use super::scene::Scene;
use super::BenchmarkError;
use serde::{Deserialize, Serialize};
use std::cmp::Ordering;

/// A shortest path in the plane among the obstacles.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ShortestPath {
    /// Its length.
    pub length: f64,
    /// Its corners, from p to q: p, obstacle corners where it bends (or that it passes), q.
    pub points: Vec<Point>,
}

/// The shortest path from `scene.p` to `scene.q` among the obstacles.
///
/// # Errors
/// The scene's [`Scene::validate`] errors.
pub fn shortest_path(scene: &Scene) -> Result<ShortestPath, BenchmarkError> {
    let obstacles = scene.counter_clockwise_obstacles()?;
    Ok(shortest_path_among(&obstacles, scene.p, scene.q))
}

/// A* (Dijkstra guided by the straight distance to q, a consistent estimate) on the reduced
/// visibility graph: its nodes are p, q and the convex obstacle corners, since a shortest path
/// bends only at convex corners, and its edges are the visible segments that are tangent to the
/// obstacle at each corner they end at, since a shortest path wraps around the corners it
/// touches. `obstacles` are valid and counter-clockwise.
pub(crate) fn shortest_path_among(obstacles: &[Vec<Point>], p: Point, q: Point) -> ShortestPath {
    // Each node with the neighbouring corners of its obstacle, if it is a corner.
    let mut nodes: Vec<(Point, Option<[Point; 2]>)> = vec![(p, None), (q, None)];
    for polygon in obstacles {
        let n = polygon.len();
        nodes.extend((0..n).filter_map(|i| {
            let (prev, w, next) = (polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]);
            (orient(prev, w, next) == Ordering::Greater).then_some((w, Some([prev, next])))
        }));
    }
    let tangent = |(w, around): (Point, Option<[Point; 2]>), x: Point| {
        around.is_none_or(|[prev, next]| {
            let (a, b) = (orient(w, x, prev), orient(w, x, next));
            a == Ordering::Equal || a != b.reverse()
        })
    };
    let boxes: Vec<[Point; 2]> = obstacles.iter().map(|o| bounding_box(o)).collect();
    // Dense: the graph is complete up to visibility, so a heap would not help.
    let n = nodes.len();
    let mut best = vec![f64::INFINITY; n];
    let mut previous = vec![usize::MAX; n];
    let mut done = vec![false; n];
    let estimate: Vec<f64> = nodes.iter().map(|&(x, _)| distance(x, q)).collect();
    best[0] = 0.0;
    while let Some(u) = (0..n)
        .filter(|&i| !done[i] && best[i].is_finite())
        .min_by(|&i, &j| (best[i] + estimate[i]).total_cmp(&(best[j] + estimate[j])))
    {
        done[u] = true;
        if u == 1 {
            break;
        }
        for v in 0..n {
            if done[v] {
                continue;
            }
            let (from, to) = (nodes[u].0, nodes[v].0);
            let candidate = best[u] + distance(from, to);
            if candidate < best[v]
                && tangent(nodes[u], to)
                && tangent(nodes[v], from)
                && visible(obstacles, &boxes, from, to)
            {
                best[v] = candidate;
                previous[v] = u;
            }
        }
    }
    // Disjoint obstacles strictly inside the rectangle leave its free space connected, so q is
    // reached.
    assert!(done[1], "q is reachable from p");
    let mut points = vec![q];
    let mut at = 1;
    while at != 0 {
        at = previous[at];
        points.push(nodes[at].0);
    }
    points.reverse();
    let length = points.windows(2).map(|w| distance(w[0], w[1])).sum();
    ShortestPath { length, points }
}

/// Whether the closed segment `uv` avoids the interior of every obstacle, given with its
/// bounding box. `u` and `v` are p, q or obstacle corners.
fn visible(obstacles: &[Vec<Point>], boxes: &[[Point; 2]], u: Point, v: Point) -> bool {
    let segment = bounding_box(&[u, v]);
    obstacles.iter().zip(boxes).all(|(polygon, b)| {
        let apart = (0..2).any(|i| b[1][i] < segment[0][i] || segment[1][i] < b[0][i]);
        if apart {
            return true;
        }
        let n = polygon.len();
        (0..n).all(|i| {
            let (prev, w, next) = (polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]);
            // The segment meets the boundary at an edge's interior only by crossing it (p and
            // q are off the boundary, corners are not on other edges), or else at corners.
            if segments_cross(u, v, w, next) {
                return false;
            }
            let enters = |x: Point| enters_interior(prev, w, next, x);
            if w == u {
                !enters(v)
            } else if w == v {
                !enters(u)
            } else if strictly_inside_segment(u, v, w) {
                !enters(u) && !enters(v)
            } else {
                true
            }
        })
    })
}

/// Whether the direction from corner `w` towards `x` points strictly into the interior of a
/// counter-clockwise polygon whose neighbours of `w` are `prev` and `next`. The interior near
/// `w` is swept counter-clockwise from the direction of `next` to that of `prev`; directions
/// along the two edges are on the boundary, not inside.
fn enters_interior(prev: Point, w: Point, next: Point, x: Point) -> bool {
    use Ordering::{Greater, Less};
    if orient(prev, w, next) == Greater {
        // Convex corner: an interior angle below pi.
        orient(w, next, x) == Greater && orient(w, x, prev) == Greater
    } else {
        // Reflex corner: inside unless in the closed exterior cone, swept from prev to next.
        !(orient(w, prev, x) != Less && orient(w, x, next) != Less)
    }
}
