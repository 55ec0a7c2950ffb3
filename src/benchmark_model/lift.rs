//! Lifting each obstacle as a closed polygonal cylinder sewn to the floor along the obstacle's
//! boundary [LZT §5, Fig. 16d].

use super::geometry::{orient, Point};
use super::triangulate::Floor;
use super::BenchmarkError;
use crate::TriMesh;
use glam::{DVec2, DVec3};
use std::cmp::Ordering;

/// The most wall triangles [`lift`] builds: `2 rows` per boundary edge of an obstacle. Beyond
/// this the mesh takes gigabytes and the engine hours, and far beyond it the vertex numbers of
/// the walls would not fit in `u32`.
pub(crate) const MAX_WALL_FACES: u64 = 1 << 22;

/// The floor at z = 0 and, on each obstacle, a wall of `rows` rows of quads (two triangles
/// each) from every boundary edge of the floor up to `height`, closed by a flat top cap.
///
/// Refuses ([`BenchmarkError::InvalidOption`] for `wall_rows`) walls of more than
/// [`MAX_WALL_FACES`] triangles, before building any.
///
/// All faces are counter-clockwise seen from the open space above the surface: the floor and
/// the caps from +z, the walls from outside their obstacle. A wall's bottom row uses the floor's boundary vertices, so
/// the cylinder is sewn to the floor edge by edge.
pub(crate) fn lift(
    floor: &Floor,
    obstacles: &[Vec<Point>],
    height: f64,
    rows: usize,
) -> Result<TriMesh, BenchmarkError> {
    let edges: u64 = floor.rings.iter().map(|r| r.vertices.len() as u64).sum();
    let wall_faces = edges.saturating_mul(rows as u64).saturating_mul(2);
    if wall_faces > MAX_WALL_FACES {
        return Err(BenchmarkError::InvalidOption {
            name: "wall_rows",
            reason: format!(
                "{rows} rows on {edges} obstacle boundary edges make {wall_faces} wall triangles; at most {MAX_WALL_FACES}"
            ),
        });
    }
    let at_height = |x: Point, z: f64| DVec2::from(x).extend(z);
    let mut positions: Vec<DVec3> = floor.positions.iter().map(|&x| at_height(x, 0.0)).collect();
    let mut faces = floor.triangles.clone();
    for (ring, corners) in floor.rings.iter().zip(obstacles) {
        let m = ring.vertices.len();
        let base = positions.len() as u32;
        for row in 1..=rows {
            let z = height * row as f64 / rows as f64;
            positions.extend(
                ring.vertices
                    .iter()
                    .map(|&v| at_height(floor.positions[v as usize], z)),
            );
        }
        // Vertex of the wall at ring position j and row r (row 0 is the floor's).
        let at = |j: usize, r: usize| {
            let j = j % m;
            if r == 0 {
                ring.vertices[j]
            } else {
                base + ((r - 1) * m + j) as u32
            }
        };
        for j in 0..m {
            for r in 0..rows {
                let (a0, b0, a1, b1) = (at(j, r), at(j + 1, r), at(j, r + 1), at(j + 1, r + 1));
                // The obstacle is left of a -> b, so this winding faces away from it.
                faces.push([a0, b0, b1]);
                faces.push([a0, b1, a1]);
            }
        }
        // The cap: a triangulation of the obstacle's corners; where a cap triangle has points
        // inserted on its polygon edges, it is fanned from its centroid over all of them.
        let n = corners.len();
        for [a, b, c] in ear_clip(corners)? {
            let mut cycle = Vec::new();
            for (s, t) in [(a, b), (b, c), (c, a)] {
                if t == (s + 1) % n {
                    let (from, to) = (ring.corners[s], ring.corners[t]);
                    let to = if to == 0 { m } else { to };
                    cycle.extend((from..to).map(|j| at(j, rows)));
                } else {
                    cycle.push(at(ring.corners[s], rows));
                }
            }
            if cycle.len() == 3 {
                faces.push([cycle[0], cycle[1], cycle[2]]);
            } else {
                let centre = positions.len() as u32;
                let [pa, pb, pc] = [a, b, c].map(|k| DVec2::from(corners[k]));
                positions.push(((pa + pb + pc) / 3.0).extend(height));
                for i in 0..cycle.len() {
                    faces.push([cycle[i], cycle[(i + 1) % cycle.len()], centre]);
                }
            }
        }
    }
    Ok(TriMesh::new(positions, faces)?)
}

/// Ear clipping of a counter-clockwise simple polygon into counter-clockwise triangles of
/// corner indices, with exact predicates: an ear is a strictly convex corner whose triangle
/// contains no other remaining corner, not even on its boundary.
fn ear_clip(polygon: &[Point]) -> Result<Vec<[usize; 3]>, BenchmarkError> {
    let mut remaining: Vec<usize> = (0..polygon.len()).collect();
    let mut triangles = Vec::with_capacity(polygon.len() - 2);
    let (mut i, mut misses) = (0, 0);
    while remaining.len() > 3 {
        let m = remaining.len();
        let [a, b, c] = [
            remaining[(i + m - 1) % m],
            remaining[i],
            remaining[(i + 1) % m],
        ];
        let [pa, pb, pc] = [a, b, c].map(|k| polygon[k]);
        let is_ear = orient(pa, pb, pc) == Ordering::Greater
            && remaining.iter().all(|&k| {
                k == a
                    || k == b
                    || k == c
                    || [(pa, pb), (pb, pc), (pc, pa)]
                        .iter()
                        .any(|&(u, v)| orient(u, v, polygon[k]) == Ordering::Less)
            });
        if is_ear {
            triangles.push([a, b, c]);
            remaining.remove(i);
            i %= remaining.len();
            misses = 0;
        } else {
            i = (i + 1) % m;
            misses += 1;
            if misses > m {
                return Err(BenchmarkError::Triangulation(
                    "no ear found in an obstacle's top cap".into(),
                ));
            }
        }
    }
    triangles.push([remaining[0], remaining[1], remaining[2]]);
    Ok(triangles)
}
