//! The bounds a geodesic distance must respect, computed without the engine: the straight line
//! in space (a lower bound) and the shortest path along mesh edges (an upper bound, by
//! Dijkstra on the edge graph), both free of overflow and underflow for coordinates from
//! `2^-600` to `2^600`.
//!
//! Lengths are scaled by a power of two before squaring, so they are exact in the exact backend
//! and correctly rounded up to a few ulps in `f64`.

use crate::mesh::vector::normalizing_power;
use crate::mesh::{TriMesh, VertexId};
use crate::scalar::Scalar;
use glam::DVec3;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// The length of `q - p` in `f64`, without overflow or underflow.
pub(crate) fn distance_f64(p: DVec3, q: DVec3) -> f64 {
    let d = q - p;
    d.x.hypot(d.y).hypot(d.z)
}

/// The length of `q - p` in `S`: the differences are scaled by a power of two near their
/// largest before squaring, so the value is exact in an exact backend and overflows in none.
pub(crate) fn distance_in<S: Scalar>(p: DVec3, q: DVec3) -> S {
    let largest = (q - p).abs().max_element();
    if largest == 0.0 {
        return S::zero();
    }
    let power = normalizing_power(largest);
    let down = S::from_f64(power);
    let squares = (0..3)
        .map(|i| {
            let d = (S::from_f64(q[i]) - S::from_f64(p[i])) * &down;
            d.clone() * d
        })
        .reduce(|sum, x| sum + x)
        .expect("three coordinates");
    squares.sqrt() * S::from_f64(power.recip())
}

/// A distance on the heap, smallest first.
struct Entry(f64, VertexId);

impl PartialEq for Entry {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Entry {}
impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Entry {
    fn cmp(&self, other: &Self) -> Ordering {
        other.0.total_cmp(&self.0).then(other.1.cmp(&self.1))
    }
}

/// Shortest paths along mesh edges from one vertex (Dijkstra in `f64`), with the path to every
/// vertex, so that its length can be summed again in any backend.
pub(crate) struct EdgePaths {
    distance: Vec<f64>,
    previous: Vec<Option<VertexId>>,
}

impl EdgePaths {
    /// Dijkstra from `source` over the edges of `mesh`.
    pub(crate) fn new(mesh: &TriMesh, source: VertexId) -> EdgePaths {
        let n = mesh.vertex_count();
        let mut distance = vec![f64::INFINITY; n];
        let mut previous = vec![None; n];
        let mut heap = BinaryHeap::new();
        distance[source.index()] = 0.0;
        heap.push(Entry(0.0, source));
        while let Some(Entry(d, u)) = heap.pop() {
            if d > distance[u.index()] {
                continue;
            }
            for &e in mesh.vertex_edges(u) {
                let v = mesh.edge(e).other(u).expect("an edge at u has u as an end");
                let through = d + distance_f64(mesh.position(u), mesh.position(v));
                if through < distance[v.index()] {
                    distance[v.index()] = through;
                    previous[v.index()] = Some(u);
                    heap.push(Entry(through, v));
                }
            }
        }
        EdgePaths { distance, previous }
    }

    /// Whether a path along edges joins the source to `v` (the source reaches itself).
    pub(crate) fn reaches(&self, v: VertexId) -> bool {
        self.distance[v.index()].is_finite()
    }

    /// The length of the path found to `v`, summed in `S` edge by edge: an upper bound of the
    /// geodesic distance in `S`'s own arithmetic. `None` if no path reaches `v`.
    pub(crate) fn length_in<S: Scalar>(&self, mesh: &TriMesh, v: VertexId) -> Option<S> {
        if !self.reaches(v) {
            return None;
        }
        let mut sum = S::zero();
        let mut at = v;
        while let Some(from) = self.previous[at.index()] {
            sum = sum + distance_in::<S>(mesh.position(from), mesh.position(at));
            at = from;
        }
        Some(sum)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;
    use crate::mesh::vector::power_of_two;
    use crate::scalar::{Real, Ring, Sign};

    #[test]
    fn distances_at_2_to_600_neither_overflow_nor_underflow() {
        for k in [-600, 0, 600] {
            let s = power_of_two(k);
            let (p, q) = (DVec3::new(s, 0.0, 0.0), DVec3::new(4.0 * s, 4.0 * s, 0.0));
            assert_eq!(distance_f64(p, q), 5.0 * s);
            assert_eq!(distance_in::<f64>(p, q), 5.0 * s);
        }
    }

    #[test]
    fn exact_distance_is_the_exact_square_root() {
        let d = distance_in::<Real>(DVec3::ZERO, DVec3::new(1.0, 1.0, 0.0));
        let two = d.clone() * d - Real::from_f64(2.0);
        assert_eq!(two.sign(), Sign::Zero);
    }

    #[test]
    fn edge_paths_sum_the_edges_of_the_path() {
        let mesh = shapes::grid(2, 1, 2.0, 1.0);
        let paths = EdgePaths::new(&mesh, VertexId(0));
        assert!(paths.reaches(VertexId(5)));
        // v0 -> v4 (diagonal, sqrt 2) -> v5 (1).
        let d: f64 = paths.length_in(&mesh, VertexId(5)).expect("reached");
        assert!((d - (1.0 + 2f64.sqrt())).abs() < 1e-15);
    }
}
