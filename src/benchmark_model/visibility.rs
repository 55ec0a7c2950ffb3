//! The ground truth of [LZT §5]: the Euclidean shortest path from p to q among the obstacles,
//! by Dijkstra's algorithm on the visibility graph VG(S ∪ {p, q}) [LZT refs. 19-21].
//!
//! Every visibility decision is made with exact orientation predicates. A segment may touch an
//! obstacle's corners and run along its edges; it is blocked only where it enters an interior.

use super::geometry::{distance, orient, segments_cross, strictly_inside_segment, Point};
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

/// Dijkstra on the visibility graph whose nodes are p, q and the convex obstacle corners: a
/// shortest path bends only at convex corners. `obstacles` are valid and counter-clockwise.
pub(crate) fn shortest_path_among(obstacles: &[Vec<Point>], p: Point, q: Point) -> ShortestPath {
    let mut nodes = vec![p, q];
    for polygon in obstacles {
        let n = polygon.len();
        nodes.extend((0..n).filter_map(|i| {
            let turn = orient(polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]);
            (turn == Ordering::Greater).then_some(polygon[i])
        }));
    }
    // Dense Dijkstra: the graph is complete up to visibility, so a heap would not help.
    let n = nodes.len();
    let mut best = vec![f64::INFINITY; n];
    let mut previous = vec![usize::MAX; n];
    let mut done = vec![false; n];
    best[0] = 0.0;
    while let Some(u) = (0..n)
        .filter(|&i| !done[i] && best[i].is_finite())
        .min_by(|&i, &j| best[i].total_cmp(&best[j]))
    {
        done[u] = true;
        if u == 1 {
            break;
        }
        for v in 0..n {
            if done[v] {
                continue;
            }
            let candidate = best[u] + distance(nodes[u], nodes[v]);
            if candidate < best[v] && visible(obstacles, nodes[u], nodes[v]) {
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
        points.push(nodes[at]);
    }
    points.reverse();
    let length = points.windows(2).map(|w| distance(w[0], w[1])).sum();
    ShortestPath { length, points }
}

/// Whether the closed segment `uv` avoids the interior of every obstacle. `u` and `v` are p, q
/// or obstacle corners.
pub(crate) fn visible(obstacles: &[Vec<Point>], u: Point, v: Point) -> bool {
    obstacles.iter().all(|polygon| {
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
