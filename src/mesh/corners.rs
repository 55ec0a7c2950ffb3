//! What the shapes of the faces say of their corners, in `f64` on the unit-scaled
//! coordinates: each vertex's angle sum, and whether it is a corner of a degenerate face or an
//! end of an edge far shorter than its face. Face by face, from positions alone, so that it
//! can be worked out beside the edges' numbering (`Topology::build`).

use super::vector::{angle_of_units, length, unit};
use super::FaceId;
use glam::DVec3;

/// An edge shorter than this fraction of its face's longest edge makes its ends pseudo-sources
/// (see `TriMesh::may_bend_geodesics`).
const SHORT_EDGE: f64 = 1e-8;

/// The corners' angle sums and degeneracies, summed over the faces counted.
pub(super) struct Corners {
    pub(super) angle_sum: Vec<f64>,
    /// Whether the vertex is a corner of a degenerate face or an end of an edge far shorter
    /// than its face: the float backends keep no window narrower than 1e-11 of an edge, so
    /// the rays through it would be lost.
    pub(super) on_degenerate_face: Vec<bool>,
    /// The degenerate faces ([`is_degenerate`]), in order.
    pub(super) zero_area_faces: Vec<FaceId>,
}

impl Corners {
    /// No face counted yet, on a mesh of `vertex_count` vertices.
    pub(super) fn new(vertex_count: usize) -> Corners {
        Corners {
            angle_sum: vec![0.0; vertex_count],
            on_degenerate_face: vec![false; vertex_count],
            zero_area_faces: Vec::new(),
        }
    }

    /// Counts the faces for which `counted` holds, with `scaled(v)` vertex `v`'s position
    /// times `unit_scale`: each face's angles are added to its corners' sums in the order of
    /// the faces. Allocates only for degenerate faces.
    pub(super) fn count(
        &mut self,
        faces: &[[u32; 3]],
        (scaled, unit_scale): (impl Fn(usize) -> DVec3, f64),
        counted: impl Fn(usize) -> bool,
    ) {
        for (fi, f) in faces.iter().enumerate().filter(|&(fi, _)| counted(fi)) {
            let p = f.map(|c| scaled(c as usize));
            // Side `k` joins corners `k` and `k + 1`; its length is its edge's (negating a
            // difference is exact).
            let sides = [p[1] - p[0], p[2] - p[1], p[0] - p[2]];
            let scaled_lengths = sides.map(length);
            let units = sides.map(unit);
            if is_degenerate(scaled_lengths, units) {
                self.zero_area_faces.push(FaceId(fi as u32));
                for &v in f {
                    self.on_degenerate_face[v as usize] = true;
                }
            }
            let lengths = scaled_lengths.map(|l| l / unit_scale);
            let longest = lengths.iter().fold(0.0f64, |m, &l| m.max(l));
            for (k, &l) in lengths.iter().enumerate() {
                if l < SHORT_EDGE * longest {
                    self.on_degenerate_face[f[k] as usize] = true;
                    self.on_degenerate_face[f[(k + 1) % 3] as usize] = true;
                }
            }
            // The angle at corner `k` lies between side `k` and side `k + 2` reversed.
            for k in 0..3 {
                self.angle_sum[f[k] as usize] += match (units[k], units[(k + 2) % 3]) {
                    (Some(u), Some(w)) => angle_of_units(u, -w),
                    _ => 0.0,
                };
            }
        }
    }
}

/// Whether a triangle (in unit-scaled coordinates; its sides' lengths and unit directions) is
/// degenerate for the f64 geometry: its corners collinear to within rounding, or two of them
/// coincident. The sine of its largest angle is then below a few ulps, and an unfolding
/// computed in f64 across it means little.
fn is_degenerate(lengths: [f64; 3], units: [Option<DVec3>; 3]) -> bool {
    /// Sines of the face's largest angle below this count as degenerate: well above the
    /// rounding of a cross product of unit vectors (a few ulps), far below any angle a
    /// modelled face has.
    const SINE: f64 = 64.0 * f64::EPSILON;
    // The largest angle is the one between the two shortest sides.
    let mut order = [0, 1, 2];
    order.sort_by(|&i, &j| lengths[i].total_cmp(&lengths[j]));
    match (units[order[0]], units[order[1]]) {
        (Some(u), Some(w)) => length(u.cross(w)) <= SINE,
        _ => true,
    }
}

#[cfg(test)]
mod tests {
    use super::super::topology::CONCURRENT_FACES;
    use crate::mesh::{shapes, FaceId, TriMesh, VertexId};
    use glam::DVec3;
    use std::f64::consts::{PI, TAU};

    /// A unit grid of `n` by `n` cells with copies of two of its faces (one reversed) and a
    /// collinear face on three new vertices: each corner's angles counted once, the collinear
    /// face degenerate and its corners bending geodesics.
    fn corners_of_a_grid_with_copies(n: usize) {
        let grid = shapes::grid(n, n, 1.0, 1.0);
        let mut positions = grid.positions().to_vec();
        let mut faces: Vec<[u32; 3]> = (0..grid.face_count() as u32)
            .map(|f| grid.face(FaceId(f)).map(|v| v.0))
            .collect();
        let [a, b, c] = faces[7];
        faces.extend([faces[0], [c, b, a]]);
        let next = positions.len() as u32;
        positions.extend([2.0, 3.0, 4.0].map(|x| DVec3::new(x, 0.0, 0.0)));
        faces.push([next, next + 1, next + 2]);
        let mesh = TriMesh::new(positions, faces).expect("a usable mesh");
        assert_eq!(mesh.validation().duplicate_faces.len(), 2);
        let interior = VertexId((n + 2) as u32);
        assert!((mesh.angle_sum(interior) - TAU).abs() < 1e-12);
        for v in 0..grid.vertex_count() as u32 {
            let v = VertexId(v);
            assert_eq!(mesh.angle_sum(v).to_bits(), grid.angle_sum(v).to_bits());
            assert!(!mesh.may_bend_geodesics(v) || grid.may_bend_geodesics(v));
        }
        // Every face of the grid adds pi to the sums (the collinear face pi as well).
        let total: f64 = (0..mesh.vertex_count() as u32)
            .map(|v| mesh.angle_sum(VertexId(v)))
            .sum();
        let expected = PI * (grid.face_count() + 1) as f64;
        assert!(
            (total - expected).abs() < 1e-9 * expected,
            "{total} {expected}"
        );
        let collinear = FaceId((grid.face_count() + 2) as u32);
        assert_eq!(mesh.validation().zero_area_faces, vec![collinear]);
        assert!((next..next + 3).all(|v| mesh.may_bend_geodesics(VertexId(v))));
    }

    #[test]
    fn corners_are_counted_once_on_a_small_mesh() {
        corners_of_a_grid_with_copies(4);
    }

    #[test]
    fn corners_are_counted_once_on_a_mesh_large_enough_for_a_thread() {
        let n = ((CONCURRENT_FACES / 2) as f64).sqrt().ceil() as usize;
        assert!(2 * n * n >= CONCURRENT_FACES);
        corners_of_a_grid_with_copies(n);
    }
}
