//! The UV (latitude-longitude) sphere: the non-uniform counterpart of the icosphere, with
//! slivers at the poles, for the uniform / non-uniform pairs of [LZT §6] (Observation 2) when
//! the paper's models are not at hand.

use super::build;
use crate::mesh::TriMesh;
use glam::{DVec2, DVec3};
use std::f64::consts::PI;

/// The unit sphere cut into `slices` meridians and `stacks` parallels: the north pole
/// `(0, 0, 1)` is vertex 0, then the `stacks - 1` rings of `slices` vertices from north to south
/// (ring `k` at polar angle `pi k / stacks`, vertex `i` of a ring at longitude
/// `2 pi i / slices`), then the south pole. `2 + slices (stacks - 1)` vertices and
/// `2 slices (stacks - 1)` counter-clockwise faces: a fan at each pole, each band of quads split
/// along one diagonal. `slices` is at least 3 and `stacks` at least 2 (smaller values are
/// taken as those).
///
/// `uv_sphere(32, 21)` has as many vertices and faces as `icosphere(3)` (642 and 1280).
pub fn uv_sphere(slices: usize, stacks: usize) -> TriMesh {
    let (slices, stacks) = (slices.max(3), stacks.max(2));
    let mut positions = vec![DVec3::Z];
    for k in 1..stacks {
        let (sin_t, cos_t) = (PI * k as f64 / stacks as f64).sin_cos();
        for i in 0..slices {
            let longitude = DVec2::from_angle(2.0 * PI * i as f64 / slices as f64);
            positions.push((sin_t * longitude).extend(cos_t));
        }
    }
    positions.push(DVec3::NEG_Z);
    let south = (positions.len() - 1) as u32;
    // Vertex i of ring k (1-based from the north), i taken modulo slices.
    let ring = |k: usize, i: usize| (1 + (k - 1) * slices + i % slices) as u32;
    let mut faces = Vec::with_capacity(2 * slices * (stacks - 1));
    for i in 0..slices {
        faces.push([0, ring(1, i), ring(1, i + 1)]);
        for k in 1..stacks - 1 {
            let (a, b) = (ring(k, i), ring(k, i + 1));
            let (c, d) = (ring(k + 1, i), ring(k + 1, i + 1));
            faces.push([a, c, d]);
            faces.push([a, d, b]);
        }
        faces.push([ring(stacks - 1, i), south, ring(stacks - 1, i + 1)]);
    }
    build(positions, faces)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vertices_lie_on_the_unit_sphere_with_the_poles_first_and_last() {
        let mesh = uv_sphere(7, 4);
        let p = mesh.positions();
        assert_eq!((p[0], p[p.len() - 1]), (DVec3::Z, DVec3::NEG_Z));
        for q in p {
            assert!((q.length() - 1.0).abs() < 1e-15, "{q:?}");
        }
        // Ring 2 of 3 lies on the equator; its vertex 0 at longitude 0.
        assert!((p[1 + 7].x - 1.0).abs() < 1e-15 && p[1 + 7].y == 0.0);
    }
}
