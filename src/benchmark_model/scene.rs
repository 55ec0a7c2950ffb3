//! A scene of [LZT §5]: disjoint polygonal obstacles in a rectangle, and the two points p, q
//! whose shortest path is the ground truth.

use super::geometry::{bounding_box, locate, orient, segments_touch, Location, Point};
use super::BenchmarkError;
use serde::{Deserialize, Serialize};
use std::cmp::Ordering;

/// An axis-parallel rectangle, the outer boundary of the plane part of the model.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Rectangle {
    /// Lower left corner.
    pub min: Point,
    /// Upper right corner.
    pub max: Point,
}

impl Rectangle {
    /// The four corners, counter-clockwise from `min`.
    pub fn corners(&self) -> [Point; 4] {
        let (a, b) = (self.min, self.max);
        [a, [b[0], a[1]], b, [a[0], b[1]]]
    }

    fn contains_strictly(&self, x: Point) -> bool {
        (0..2).all(|i| self.min[i] < x[i] && x[i] < self.max[i])
    }
}

/// Disjoint simple polygons (convex or concave, either orientation) strictly inside a
/// rectangle, and two points p, q outside them [LZT §5, Fig. 16a].
///
/// Users may write scenes as JSON:
/// `{"rectangle": {"min": [0, 0], "max": [4, 4]}, "obstacles": [[[1, 1], [3, 1], [3, 3], [1, 3]]],
/// "p": [0.5, 2], "q": [3.5, 2.5]}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    /// The rectangle R bounding everything.
    pub rectangle: Rectangle,
    /// The obstacles, each a list of corners (no repeated closing corner).
    pub obstacles: Vec<Vec<Point>>,
    /// The source.
    pub p: Point,
    /// The target.
    pub q: Point,
}

impl Scene {
    /// Parses the JSON of a scene; call [`Scene::validate`] (or build the model) to check it.
    ///
    /// # Errors
    /// [`BenchmarkError::Json`] when the text is not a scene.
    pub fn from_json(text: &str) -> Result<Scene, BenchmarkError> {
        serde_json::from_str(text).map_err(|e| BenchmarkError::Json(e.to_string()))
    }

    /// The scene as pretty JSON; [`Scene::from_json`] reads back the same bits.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("JSON of plain numbers")
    }

    /// Checks that the scene is one [LZT §5] builds a model from.
    ///
    /// # Errors
    /// Non-finite coordinates, an empty rectangle, an obstacle that is not a simple polygon with
    /// non-degenerate corners strictly inside the rectangle, obstacles that share a point, p or q
    /// outside the rectangle or not strictly outside every obstacle, or p = q. Every decision
    /// is exact.
    pub fn validate(&self) -> Result<(), BenchmarkError> {
        self.counter_clockwise_obstacles().map(|_| ())
    }

    /// The obstacles of a valid scene, each counter-clockwise (interior on the left of its edges).
    pub(crate) fn counter_clockwise_obstacles(&self) -> Result<Vec<Vec<Point>>, BenchmarkError> {
        let finite = |x: &Point| x.iter().all(|c| c.is_finite());
        let non_finite = |what: String| Err(BenchmarkError::NonFinite { what });
        if !finite(&self.rectangle.min) || !finite(&self.rectangle.max) {
            return non_finite("the rectangle".into());
        }
        for (name, x) in [("p", self.p), ("q", self.q)] {
            if !finite(&x) {
                return non_finite(name.into());
            }
        }
        for (obstacle, corners) in self.obstacles.iter().enumerate() {
            if let Some(corner) = corners.iter().position(|x| !finite(x)) {
                return non_finite(format!("corner {corner} of obstacle {obstacle}"));
            }
        }
        let r = &self.rectangle;
        if !(r.min[0] < r.max[0] && r.min[1] < r.max[1]) {
            return Err(BenchmarkError::EmptyRectangle {
                min: r.min,
                max: r.max,
            });
        }
        if self.p == self.q {
            return Err(BenchmarkError::PointsCoincide);
        }
        for (point, x) in [("p", self.p), ("q", self.q)] {
            if !r.contains_strictly(x) {
                return Err(BenchmarkError::PointOutsideRectangle { point });
            }
        }
        let mut obstacles = Vec::with_capacity(self.obstacles.len());
        for (obstacle, corners) in self.obstacles.iter().enumerate() {
            check_polygon(obstacle, corners)?;
            if !corners.iter().all(|&x| r.contains_strictly(x)) {
                return Err(BenchmarkError::ObstacleOutsideRectangle { obstacle });
            }
            obstacles.push(counter_clockwise(corners));
        }
        let boxes: Vec<[Point; 2]> = obstacles.iter().map(|o| bounding_box(o)).collect();
        for first in 0..obstacles.len() {
            for second in first + 1..obstacles.len() {
                if boxes_meet(&boxes[first], &boxes[second])
                    && polygons_meet(&obstacles[first], &obstacles[second])
                {
                    return Err(BenchmarkError::ObstaclesOverlap { first, second });
                }
            }
        }
        for (point, x) in [("p", self.p), ("q", self.q)] {
            if let Some(obstacle) = obstacles
                .iter()
                .position(|o| locate(o, x) != Location::Outside)
            {
                return Err(BenchmarkError::PointInObstacle { point, obstacle });
            }
        }
        Ok(obstacles)
    }
}

/// At least three corners, none collinear with its neighbours, and no two edges meeting except
/// neighbours at their shared corner.
fn check_polygon(obstacle: usize, corners: &[Point]) -> Result<(), BenchmarkError> {
    let n = corners.len();
    if n < 3 {
        return Err(BenchmarkError::TooFewCorners { obstacle, count: n });
    }
    for corner in 0..n {
        if orient(
            corners[(corner + n - 1) % n],
            corners[corner],
            corners[(corner + 1) % n],
        ) == Ordering::Equal
        {
            return Err(BenchmarkError::DegenerateCorner { obstacle, corner });
        }
    }
    // Neighbouring edges are not collinear, so they meet only at their shared corner.
    for first in 0..n {
        for second in first + 2..n {
            if first == 0 && second == n - 1 {
                continue;
            }
            let (a, b) = (corners[first], corners[(first + 1) % n]);
            let (c, d) = (corners[second], corners[(second + 1) % n]);
            if segments_touch(a, b, c, d) {
                return Err(BenchmarkError::SelfIntersecting {
                    obstacle,
                    first,
                    second,
                });
            }
        }
    }
    Ok(())
}

/// The polygon, reversed if clockwise. The lowest-leftmost corner of a simple polygon is convex,
/// so the exact turn there is the orientation.
fn counter_clockwise(corners: &[Point]) -> Vec<Point> {
    let n = corners.len();
    let lowest = (0..n)
        .min_by(|&i, &j| corners[i].partial_cmp(&corners[j]).expect("finite"))
        .expect("at least three corners");
    let turn = orient(
        corners[(lowest + n - 1) % n],
        corners[lowest],
        corners[(lowest + 1) % n],
    );
    let mut out = corners.to_vec();
    if turn == Ordering::Less {
        out.reverse();
    }
    out
}

fn boxes_meet(a: &[Point; 2], b: &[Point; 2]) -> bool {
    (0..2).all(|i| a[0][i] <= b[1][i] && b[0][i] <= a[1][i])
}

/// Whether two simple polygons share a point: their boundaries meet, or one contains the other.
fn polygons_meet(a: &[Point], b: &[Point]) -> bool {
    let edges = |p: &[Point]| {
        (0..p.len())
            .map(|i| (p[i], p[(i + 1) % p.len()]))
            .collect::<Vec<_>>()
    };
    let (ea, eb) = (edges(a), edges(b));
    ea.iter()
        .any(|&(x, y)| eb.iter().any(|&(u, v)| segments_touch(x, y, u, v)))
        || locate(b, a[0]) != Location::Outside
        || locate(a, b[0]) != Location::Outside
}
