//! Meshes the program generates itself: for tests, examples and the README's first command.
//!
//! All generated meshes are consistently oriented (counter-clockwise seen from outside, or from
//! +z for planar ones), manifold, and free of zero-area faces.

mod spec;
mod uv_sphere;

pub use spec::{parse_shape, ShapeError, MAX_GENERATED_FACES, SHAPE_NAMES};
pub use uv_sphere::uv_sphere;

use super::TriMesh;
use glam::DVec3;

/// A small deterministic generator (SplitMix64), so that generated meshes depend on the seed
/// only, on every platform.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator started from `seed`.
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A uniform number in `[0, 1)`.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn build<P: Into<DVec3>>(positions: Vec<P>, faces: Vec<[u32; 3]>) -> TriMesh {
    TriMesh::new(positions, faces).expect("generated meshes are valid by construction")
}

/// A planar `nx` by `ny` grid of `width` by `height` in z = 0, vertices row by row from the origin,
/// each cell split along its diagonal from lower left to upper right.
///
/// `(nx + 1) * (ny + 1)` vertices (vertex `j * (nx + 1) + i` at column `i`, row `j`) and
/// `2 * nx * ny` counter-clockwise faces. A zero count is taken as one cell.
pub fn grid(nx: usize, ny: usize, width: f64, height: f64) -> TriMesh {
    let (nx, ny) = (nx.max(1), ny.max(1));
    let mut positions = Vec::with_capacity((nx + 1) * (ny + 1));
    for j in 0..=ny {
        for i in 0..=nx {
            positions.push(DVec3::new(
                width * i as f64 / nx as f64,
                height * j as f64 / ny as f64,
                0.0,
            ));
        }
    }
    let id = |i: usize, j: usize| (j * (nx + 1) + i) as u32;
    let mut faces = Vec::with_capacity(2 * nx * ny);
    for j in 0..ny {
        for i in 0..nx {
            faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    build(positions, faces)
}

/// A planar grid of unit cells over `[0, n]^2` scaled by `1 / n`, keeping only the cells that
/// `keep(i, j)` accepts, with unused vertices dropped.
fn grid_region(
    cells_x: usize,
    cells_y: usize,
    n: usize,
    keep: impl Fn(usize, usize) -> bool,
) -> TriMesh {
    let mut index = vec![u32::MAX; (cells_x + 1) * (cells_y + 1)];
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    let mut id = |i: usize, j: usize, positions: &mut Vec<DVec3>| {
        let k = j * (cells_x + 1) + i;
        if index[k] == u32::MAX {
            index[k] = positions.len() as u32;
            positions.push(DVec3::new(i as f64 / n as f64, j as f64 / n as f64, 0.0));
        }
        index[k]
    };
    for j in 0..cells_y {
        for i in 0..cells_x {
            if keep(i, j) {
                let c = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
                    .map(|(a, b)| id(a, b, &mut positions));
                faces.push([c[0], c[1], c[2]]);
                faces.push([c[0], c[2], c[3]]);
            }
        }
    }
    build(positions, faces)
}

/// The planar L-shaped domain `[0, 2]^2` without `(1, 2]^2`, in cells of size `1 / n`; its reflex
/// corner `(1, 1)` is a vertex.
pub fn l_shape(n: usize) -> TriMesh {
    let n = n.max(1);
    grid_region(2 * n, 2 * n, n, |i, j| i < n || j < n)
}

/// The planar square `[0, 3]^2` with the square hole `(1, 2)^2`, in cells of size `1 / n`.
pub fn square_with_hole(n: usize) -> TriMesh {
    let n = n.max(1);
    grid_region(3 * n, 3 * n, n, |i, j| {
        !((n..2 * n).contains(&i) && (n..2 * n).contains(&j))
    })
}

/// A random convex polygon in z = 0 (`boundary` corners on a jittered ellipse), fanned into
/// triangles, with `interior` random points each inserted by splitting the triangle containing
/// it into three. Points that would make a triangle too thin are skipped.
///
/// The boundary corners come first, counter-clockwise (at least 3: smaller counts are raised),
/// then the interior points in insertion order. Corners sit at sorted, jittered angles on an
/// ellipse, so the polygon stays strictly convex. A point is kept only if each of its barycentric
/// coordinates in the containing triangle exceeds 0.02; after `100 * (interior + 1)` draws the
/// generator gives up, so fewer than `interior` points may be placed (rare in practice).
pub fn random_convex_triangulation(seed: u64, boundary: usize, interior: usize) -> TriMesh {
    let mut rng = SplitMix64::new(seed);
    let boundary = boundary.max(3);
    let (ax, ay) = (1.0 + 0.5 * rng.next_f64(), 0.7 + 0.5 * rng.next_f64());
    let mut angles: Vec<f64> = (0..boundary)
        .map(|k| (k as f64 + 0.8 * rng.next_f64()) * std::f64::consts::TAU / boundary as f64)
        .collect();
    angles.sort_by(f64::total_cmp);
    let mut positions: Vec<DVec3> = angles
        .iter()
        .map(|a| DVec3::new(ax * a.cos(), ay * a.sin(), 0.0))
        .collect();
    let mut faces: Vec<[u32; 3]> = (1..boundary as u32 - 1).map(|k| [0, k, k + 1]).collect();
    let area2 = |a: DVec3, b: DVec3, c: DVec3| {
        let a = a.truncate();
        (b.truncate() - a).perp_dot(c.truncate() - a)
    };
    let mut placed = 0;
    let mut attempts = 0;
    while placed < interior && attempts < 100 * (interior + 1) {
        attempts += 1;
        let (r, t) = (
            rng.next_f64().sqrt(),
            rng.next_f64() * std::f64::consts::TAU,
        );
        let p = DVec3::new(0.95 * ax * r * t.cos(), 0.95 * ay * r * t.sin(), 0.0);
        let found = faces.iter().position(|f| {
            let c = f.map(|i| positions[i as usize]);
            let total = area2(c[0], c[1], c[2]);
            [
                area2(p, c[1], c[2]),
                area2(c[0], p, c[2]),
                area2(c[0], c[1], p),
            ]
            .iter()
            .all(|&w| w / total > 0.02)
        });
        if let Some(k) = found {
            let [a, b, c] = faces[k];
            let new = positions.len() as u32;
            positions.push(p);
            faces[k] = [a, b, new];
            faces.push([b, c, new]);
            faces.push([c, a, new]);
            placed += 1;
        }
    }
    build(positions, faces)
}

/// The regular tetrahedron with vertices at alternate corners of the cube `[-1, 1]^3`.
pub fn tetrahedron() -> TriMesh {
    build(
        vec![
            [1.0, 1.0, 1.0],
            [1.0, -1.0, -1.0],
            [-1.0, 1.0, -1.0],
            [-1.0, -1.0, 1.0],
        ],
        vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]],
    )
}

/// Two unit right triangles meeting only at vertex 0, their legs along the axes, one on either
/// side of it: the simplest vertex that is not a manifold's (a bowtie).
pub fn bowtie() -> TriMesh {
    build(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
        ],
        vec![[0, 1, 2], [0, 3, 4]],
    )
}

/// The unit cube `[0, 1]^3`, each square split into two triangles.
pub fn cube() -> TriMesh {
    build(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
            [0.0, 1.0, 1.0],
        ],
        vec![
            [0, 2, 1],
            [0, 3, 2],
            [4, 5, 6],
            [4, 6, 7],
            [0, 1, 5],
            [0, 5, 4],
            [1, 2, 6],
            [1, 6, 5],
            [2, 3, 7],
            [2, 7, 6],
            [3, 0, 4],
            [3, 4, 7],
        ],
    )
}

/// The regular octahedron with vertices at the unit points of the axes.
pub fn octahedron() -> TriMesh {
    build(
        vec![
            [1.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
        ],
        vec![
            [0, 2, 4],
            [2, 1, 4],
            [1, 3, 4],
            [3, 0, 4],
            [2, 0, 5],
            [1, 2, 5],
            [3, 1, 5],
            [0, 3, 5],
        ],
    )
}

fn icosahedron_data() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    let positions = vec![
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ];
    let faces = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    (positions, faces)
}

/// The regular icosahedron with vertices `(0, ±1, ±phi)` and their cyclic permutations.
pub fn icosahedron() -> TriMesh {
    let (positions, faces) = icosahedron_data();
    build(positions, faces)
}

/// The icosahedron subdivided `subdivisions` times (each triangle into four), with every vertex
/// on the unit sphere: `10 * 4^k + 2` vertices.
pub fn icosphere(subdivisions: u32) -> TriMesh {
    let (positions, mut faces) = icosahedron_data();
    let normalise = |p: DVec3| p / p.length();
    let mut positions: Vec<DVec3> = positions
        .into_iter()
        .map(|p| normalise(DVec3::from(p)))
        .collect();
    for _ in 0..subdivisions {
        faces = split_in_four(&mut positions, &faces, |p, q| normalise(p + q));
    }
    build(positions, faces)
}

/// The mesh with every face split into four at the midpoints of its edges (one new vertex per
/// edge, shared by its faces): the same surface with half the edge length. The new vertices
/// follow the old ones; faces and vertices no face uses are kept in order.
///
/// # Example
/// ```
/// use exact_geodesics::mesh::shapes::{cube, subdivide};
/// let fine = subdivide(&cube());
/// assert_eq!((fine.vertex_count(), fine.face_count()), (8 + 18, 48));
/// ```
pub fn subdivide(mesh: &TriMesh) -> TriMesh {
    let mut positions = mesh.positions().to_vec();
    let faces = split_in_four(&mut positions, mesh.faces(), |p, q| 0.5 * p + 0.5 * q);
    build(positions, faces)
}

/// Splits every face `[a, b, c]` into four at new vertices `between(p, q)` on its edges, one
/// per edge, appended to `positions`.
fn split_in_four(
    positions: &mut Vec<DVec3>,
    faces: &[[u32; 3]],
    between: impl Fn(DVec3, DVec3) -> DVec3,
) -> Vec<[u32; 3]> {
    let mut midpoint = std::collections::HashMap::new();
    let mut mid = |a: u32, b: u32, positions: &mut Vec<DVec3>| {
        *midpoint.entry((a.min(b), a.max(b))).or_insert_with(|| {
            let (p, q) = (positions[a as usize], positions[b as usize]);
            positions.push(between(p, q));
            (positions.len() - 1) as u32
        })
    };
    let mut next = Vec::with_capacity(4 * faces.len());
    for &[a, b, c] in faces {
        let (ab, bc, ca) = (
            mid(a, b, positions),
            mid(b, c, positions),
            mid(c, a, positions),
        );
        next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
    }
    next
}

/// The mesh of Example 1 [LZT §3]: a triangular prism over the right triangle `v1 v2 v3`
/// (`v6 v5 v4` below it) capped by pyramids with apexes `v0` on top and `v7` below, 8 vertices and
/// 12 faces. The paper gives the vertices and the eight faces its wedges cross; the other four
/// (the quad `v1 v3 v4 v6` split along `v1 v4`, the caps' third faces) lie in the plane `x = y`.
/// The surface is symmetric under `(x, y, z) -> (1 - y, 1 - x, z)`, which swaps `v1, v3` and
/// `v4, v6` and fixes the edge `e2 = (v5, v7)`.
pub fn paper_example1() -> TriMesh {
    build(
        vec![
            [0.5, 0.5, 1.5],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
            [1.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0],
            [0.5, 0.5, -0.5],
        ],
        vec![
            [0, 1, 2],
            [0, 2, 3],
            [0, 3, 1],
            [1, 6, 2],
            [2, 6, 5],
            [2, 4, 3],
            [2, 5, 4],
            [1, 3, 4],
            [1, 4, 6],
            [5, 6, 7],
            [4, 5, 7],
            [6, 4, 7],
        ],
    )
}

/// The mesh of Example 3 [LZT §3]: the unit cube `[0, 1]^3` with its top fanned around the centre
/// `v0`, 9 vertices and 14 faces. The paper gives the vertices and the faces its two wedges cross
/// (which fix the diagonals of the sides `y = 0`, `y = 1` and of the bottom, `e0 = (v5, v7)`); the
/// sides `x = 0` and `x = 1` are split along `v1 v8` and `v2 v7`.
pub fn paper_example3() -> TriMesh {
    build(
        vec![
            [0.5, 0.5, 1.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
            [0.0, 1.0, 1.0],
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ],
        vec![
            [0, 1, 2],
            [0, 2, 3],
            [0, 3, 4],
            [0, 4, 1],
            [1, 6, 2],
            [1, 5, 6],
            [3, 7, 4],
            [4, 7, 8],
            [5, 7, 6],
            [5, 8, 7],
            [2, 6, 7],
            [2, 7, 3],
            [1, 4, 8],
            [1, 8, 5],
        ],
    )
}

/// The mesh of Example 4 [LZT §3]: 14 vertices and 24 faces, in the paper's order.
pub fn paper_example4() -> TriMesh {
    build(
        vec![
            [0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 1.0, 1.0],
            [1.0, 1.0, 1.0],
            [1.0, 0.0, 1.0],
            [0.5, -1.8, 0.5],
            [-1.8, 0.5, 0.5],
            [0.8, 2.6, 0.8],
            [2.9, 0.2, 0.2],
            [0.1, 0.9, -1.5],
            [0.5, 0.5, 2.8],
        ],
        vec![
            [0, 3, 8],
            [3, 7, 8],
            [7, 4, 8],
            [4, 0, 8],
            [1, 0, 9],
            [5, 1, 9],
            [4, 5, 9],
            [0, 4, 9],
            [2, 1, 10],
            [6, 2, 10],
            [5, 6, 10],
            [1, 5, 10],
            [2, 6, 11],
            [6, 7, 11],
            [7, 3, 11],
            [3, 2, 11],
            [0, 1, 12],
            [1, 2, 12],
            [2, 3, 12],
            [3, 0, 12],
            [5, 4, 13],
            [6, 5, 13],
            [7, 6, 13],
            [4, 7, 13],
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn euler(mesh: &TriMesh) -> i64 {
        mesh.vertex_count() as i64 - mesh.edge_count() as i64 + mesh.face_count() as i64
    }

    fn assert_clean(mesh: &TriMesh) {
        let report = mesh.validation();
        assert!(report.zero_area_faces.is_empty());
        assert_eq!(report.inconsistently_oriented_edges, 0);
        assert!(report.unreferenced_vertices.is_empty());
        assert_eq!(report.components, 1);
    }

    #[test]
    fn closed_shapes_are_spheres() {
        for (mesh, v, f) in [
            (tetrahedron(), 4, 4),
            (cube(), 8, 12),
            (octahedron(), 6, 8),
            (icosahedron(), 12, 20),
            (icosphere(2), 162, 320),
            // The smallest UV sphere is a bipyramid over a triangle; 32 x 21 matches icosphere(3).
            (uv_sphere(3, 2), 5, 6),
            (uv_sphere(32, 21), 642, 1280),
            (paper_example1(), 8, 12),
            (paper_example3(), 9, 14),
            (paper_example4(), 14, 24),
        ] {
            assert_eq!((mesh.vertex_count(), mesh.face_count()), (v, f));
            assert_eq!(mesh.validation().boundary_edges, 0);
            assert_eq!(euler(&mesh), 2);
            assert_clean(&mesh);
        }
    }

    #[test]
    fn closed_shapes_face_outwards() {
        for mesh in [
            tetrahedron(),
            cube(),
            octahedron(),
            icosphere(1),
            uv_sphere(8, 5),
            paper_example1(),
            paper_example3(),
        ] {
            let centre = mesh.positions().iter().sum::<DVec3>() / mesh.vertex_count() as f64;
            for f in mesh.faces() {
                let [a, b, c] = corners(&mesh, f);
                assert!((b - a).cross(c - a).dot(a - centre) > 0.0);
            }
        }
    }

    #[test]
    fn planar_shapes_are_discs_or_annuli() {
        let g = grid(4, 3, 2.0, 1.0);
        assert_eq!(
            (
                g.vertex_count(),
                g.face_count(),
                g.validation().boundary_edges
            ),
            (20, 24, 14)
        );
        assert_eq!(euler(&g), 1);
        let l = l_shape(2);
        assert_eq!((l.vertex_count(), l.face_count()), (21, 24));
        assert_eq!(euler(&l), 1);
        let h = square_with_hole(1);
        assert_eq!((h.vertex_count(), h.face_count()), (16, 16));
        assert_eq!(euler(&h), 0);
        for mesh in [g, l, h, random_convex_triangulation(7, 9, 25)] {
            assert_clean(&mesh);
        }
    }

    #[test]
    fn random_convex_triangulation_places_its_points() {
        let mesh = random_convex_triangulation(3, 10, 30);
        assert_eq!(mesh.vertex_count(), 40);
        assert_eq!(mesh.face_count(), 8 + 2 * 30);
        assert_eq!(mesh.validation().boundary_edges, 10);
    }

    fn corners(mesh: &TriMesh, f: &[u32; 3]) -> [DVec3; 3] {
        f.map(|i| mesh.positions()[i as usize])
    }

    /// Six times the signed volume a closed mesh encloses: positive when its faces are
    /// counter-clockwise seen from outside, whatever its shape (the centroid test above needs
    /// star-shaped meshes).
    fn signed_volume6(mesh: &TriMesh) -> f64 {
        mesh.faces()
            .iter()
            .map(|f| {
                let [a, b, c] = corners(mesh, f);
                a.dot(b.cross(c))
            })
            .sum()
    }

    /// Twice the signed area of a face's projection on z = 0.
    fn planar_area2(mesh: &TriMesh, f: &[u32; 3]) -> f64 {
        let [a, b, c] = corners(mesh, f);
        (b - a).truncate().perp_dot((c - a).truncate())
    }

    #[test]
    fn closed_shapes_enclose_positive_volume() {
        for (mesh, volume) in [
            (tetrahedron(), 8.0 / 3.0),
            (cube(), 1.0),
            (octahedron(), 4.0 / 3.0),
            (paper_example1(), 2.0 / 3.0),
            (paper_example3(), 1.0),
            (paper_example4(), f64::NAN),
            (icosahedron(), f64::NAN),
            (icosphere(3), f64::NAN),
        ] {
            let v = signed_volume6(&mesh) / 6.0;
            assert!(v > 0.0, "{v}");
            if volume.is_finite() {
                assert!((v - volume).abs() < 1e-12, "{v} != {volume}");
            }
        }
        // The icosphere approaches the ball from inside.
        let v = signed_volume6(&icosphere(4)) / 6.0;
        let ball = 4.0 / 3.0 * std::f64::consts::PI;
        assert!(v < ball && v > 0.99 * ball, "{v}");
    }

    #[test]
    fn icospheres_are_closed_on_the_unit_sphere() {
        for k in 0..4u32 {
            let mesh = icosphere(k);
            let faces = 20 * 4usize.pow(k);
            assert_eq!(mesh.vertex_count(), faces / 2 + 2);
            assert_eq!(mesh.face_count(), faces);
            assert_eq!(mesh.edge_count(), 3 * faces / 2);
            assert_eq!(mesh.validation().boundary_edges, 0);
            assert_eq!(euler(&mesh), 2);
            assert_clean(&mesh);
            for p in mesh.positions() {
                let r = p.length();
                assert!((r - 1.0).abs() < 1e-14, "{r}");
            }
        }
        assert_eq!(icosphere(0).faces(), icosahedron().faces());
    }

    #[test]
    fn planar_shapes_have_their_boundaries() {
        // Boundary edges: perimeter in cells. The L has perimeter 8, the holed square 12 + 4.
        for (mesh, boundary) in [
            (grid(4, 3, 2.0, 1.0), 14),
            (grid(1, 1, 1.0, 1.0), 4),
            (l_shape(1), 8),
            (l_shape(3), 24),
            (square_with_hole(1), 16),
            (square_with_hole(2), 32),
            (random_convex_triangulation(1, 12, 40), 12),
        ] {
            assert_eq!(mesh.validation().boundary_edges, boundary);
            assert_clean(&mesh);
        }
        let h = square_with_hole(2);
        assert_eq!((h.vertex_count(), h.face_count()), (48, 64));
        assert_eq!(euler(&h), 0);
        let l = l_shape(3);
        assert_eq!((l.vertex_count(), l.face_count()), (40, 54));
        assert_eq!(euler(&l), 1);
    }

    #[test]
    fn planar_shapes_face_up_and_lie_in_z0() {
        for mesh in [
            grid(5, 2, 3.0, 0.5),
            l_shape(2),
            square_with_hole(2),
            random_convex_triangulation(5, 9, 30),
        ] {
            assert!(mesh.positions().iter().all(|p| p.z == 0.0));
            for f in mesh.faces() {
                assert!(planar_area2(&mesh, f) > 0.0);
            }
        }
        // The grid's corners and its row-major order.
        let g = grid(4, 3, 2.0, 1.5);
        assert_eq!(g.positions()[0], DVec3::new(0.0, 0.0, 0.0));
        assert_eq!(g.positions()[4], DVec3::new(2.0, 0.0, 0.0));
        assert_eq!(g.positions()[5], DVec3::new(0.0, 0.5, 0.0));
        assert_eq!(g.positions()[19], DVec3::new(2.0, 1.5, 0.0));
        // The reflex corner of the L and the hole's corners are vertices.
        let has = |mesh: &TriMesh, p: [f64; 3]| mesh.positions().contains(&p.into());
        assert!(has(&l_shape(3), [1.0, 1.0, 0.0]));
        assert!(!has(&l_shape(3), [2.0, 2.0, 0.0]));
        for p in [
            [1.0, 1.0, 0.0],
            [2.0, 1.0, 0.0],
            [1.0, 2.0, 0.0],
            [2.0, 2.0, 0.0],
        ] {
            assert!(has(&square_with_hole(2), p));
        }
        assert!(!has(&square_with_hole(2), [1.5, 1.5, 0.0]));
    }

    #[test]
    fn random_convex_polygons_are_convex_with_points_inside() {
        for seed in 0..20 {
            let (b, i) = (3 + seed as usize % 10, 15);
            let mesh = random_convex_triangulation(seed, b, i);
            let p = mesh.positions();
            // Every boundary corner turns left.
            for k in 0..b {
                let (a, c, d) = (p[k], p[(k + 1) % b], p[(k + 2) % b]);
                let turn = (c - a).truncate().perp_dot((d - a).truncate());
                assert!(turn > 0.0, "seed {seed}: corner {k}");
            }
            // Interior points are strictly inside: left of every boundary edge.
            for q in &p[b..] {
                for k in 0..b {
                    let (a, c) = (p[k], p[(k + 1) % b]);
                    let side = (c - a).truncate().perp_dot((*q - a).truncate());
                    assert!(side > 0.0, "seed {seed}");
                }
            }
            assert_eq!(mesh.face_count(), b - 2 + 2 * (mesh.vertex_count() - b));
            assert_eq!(mesh.validation().boundary_edges, b);
            assert_eq!(euler(&mesh), 1);
            assert_clean(&mesh);
        }
    }

    #[test]
    fn paper_example4_keeps_the_printed_order() {
        let mesh = paper_example4();
        assert_eq!(mesh.positions()[0], DVec3::new(0.0, 0.0, 0.0));
        assert_eq!(mesh.positions()[2], DVec3::new(1.0, 1.0, 0.0));
        assert_eq!(mesh.positions()[8], DVec3::new(0.5, -1.8, 0.5));
        assert_eq!(mesh.positions()[13], DVec3::new(0.5, 0.5, 2.8));
        assert_eq!(mesh.faces()[0], [0, 3, 8]);
        assert_eq!(mesh.faces()[4], [1, 0, 9]);
        assert_eq!(mesh.faces()[20], [5, 4, 13]);
        assert_eq!(mesh.faces()[23], [4, 7, 13]);
    }
}
