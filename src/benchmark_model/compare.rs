//! Comparing a traced geodesic with the ground-truth polyline.

use super::geometry::{distance_to_segment, Point};
use glam::DVec3;
use serde::{Deserialize, Serialize};

/// How far a traced path is from the ground-truth polyline in the plane.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PathDeviation {
    /// The largest distance from a traced point, projected to z = 0, to the ground truth.
    pub traced_to_truth: f64,
    /// The largest distance from a ground-truth corner to the projected traced polyline.
    pub truth_to_traced: f64,
    /// The largest |z| of a traced point: the geodesic should stay on the floor.
    pub max_height: f64,
}

impl PathDeviation {
    /// The largest of the three measures (NaN if any is NaN).
    pub fn max(&self) -> f64 {
        largest([self.traced_to_truth, self.truth_to_traced, self.max_height].into_iter())
    }
}

/// Compares a traced path (in space) with a ground-truth polyline (in the plane z = 0).
pub fn path_deviation(traced: &[DVec3], truth: &[Point]) -> PathDeviation {
    let planar: Vec<Point> = traced.iter().map(|x| x.truncate().to_array()).collect();
    PathDeviation {
        traced_to_truth: one_sided(&planar, truth),
        truth_to_traced: one_sided(truth, &planar),
        max_height: largest(traced.iter().map(|x| x.z.abs())),
    }
}

/// The largest distance from a point of `from` to the polyline `to`.
fn one_sided(from: &[Point], to: &[Point]) -> f64 {
    largest(from.iter().map(|&x| {
        match to {
            [] => f64::INFINITY,
            [only] => distance_to_segment(*only, *only, x),
            _ => to
                .windows(2)
                .map(|w| distance_to_segment(w[0], w[1], x))
                .fold(f64::INFINITY, f64::min),
        }
    }))
}

/// The largest of non-negative values, 0 for none; unlike `f64::max`, a NaN (a traced point
/// that is not a number) wins, so that it fails every tolerance.
fn largest(values: impl Iterator<Item = f64>) -> f64 {
    values.fold(0.0, |m, x| if x.is_nan() || x > m { x } else { m })
}
