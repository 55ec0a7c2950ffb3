//! How uniform a model's triangles are. [LZT §6] judges uniformity "by the maximum of minimal
//! internal angles of all triangles in the model"; the whole distribution of the per-face
//! minimal angle separates uniform from non-uniform models better (its minimum and mean).

use super::Summary;
use crate::mesh::vector::angle;
use crate::{FaceId, TriMesh};

/// The smallest interior angle of every face, in degrees, in face order.
///
/// Angles are `atan2(|a x b|, a . b)` of the two edge vectors at a corner, so a corner with an
/// edge of length zero has angle 0 and a face of zero area has minimal angle 0.
///
/// # Example
/// ```
/// use exact_geodesics::{experiments::min_angles_degrees, mesh::shapes};
/// // Every face of the cube is a right isosceles triangle.
/// for angle in min_angles_degrees(&shapes::cube()) {
///     assert!((angle - 45.0).abs() < 1e-12);
/// }
/// ```
pub fn min_angles_degrees(mesh: &TriMesh) -> Vec<f64> {
    (0..mesh.face_count())
        .map(|f| {
            let corners = mesh.face(FaceId(f as u32)).map(|v| mesh.position(v));
            (0..3)
                .map(|i| {
                    let o = corners[i];
                    angle(corners[(i + 1) % 3] - o, corners[(i + 2) % 3] - o).to_degrees()
                })
                .fold(f64::INFINITY, f64::min)
        })
        .collect()
}

/// The distribution of [`min_angles_degrees`] over the faces; its `max` is the paper's
/// uniformity measure [LZT §6].
///
/// # Example
/// ```
/// use exact_geodesics::{experiments::min_angle_summary, mesh::shapes};
/// let s = min_angle_summary(&shapes::icosahedron());
/// assert!((s.max - 60.0).abs() < 1e-9 && (s.min - 60.0).abs() < 1e-9);
/// ```
pub fn min_angle_summary(mesh: &TriMesh) -> Summary {
    Summary::of(&min_angles_degrees(mesh)).expect("a TriMesh has at least one face")
}
