//! The corpus's whole figures: exactly flat grids and fans, symmetric pyramids and bipyramids,
//! bowties, books and fins, and multi-component meshes (the kinds that are not a bumpy grid with
//! one kind of surgery; those are in [`bumpy`](super::bumpy)).

use super::draw::{bumpy_grid, chance, diagonals, dyadic, grid_corners, index, int};
use super::soup::Soup;
use crate::mesh::shapes::SplitMix64;
use glam::DVec3;

/// One of four planes through the origin with integer normals, as a map of the plane's integer
/// coordinates: exact, so a flat figure stays exactly flat and straight lines stay straight.
fn embedding(rng: &mut SplitMix64) -> impl Fn(f64, f64) -> DVec3 {
    let plane = int(rng, 0, 3);
    move |x, y| match plane {
        0 => DVec3::new(x, y, 0.0),
        1 => DVec3::new(x, 0.0, y),
        2 => DVec3::new(x, y, x),
        _ => DVec3::new(y, x, x + y),
    }
}

pub(super) fn flat_grid(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let cells = (max_faces / 2) as i64;
    let nx = int(rng, 1, 9.min(cells));
    let ny = int(rng, 1, 9.min(cells / nx));
    let (nx, ny) = (nx as usize, ny as usize);
    let (w, h) = (int(rng, 1, 3) as f64, int(rng, 1, 3) as f64);
    let place = embedding(rng);
    let cut = diagonals(rng, nx, ny);
    let soup = Soup::grid(
        nx,
        ny,
        |i, j| place(w * i as f64, h * j as f64),
        |i, j| cut[j * nx + i],
    );
    let mut focus = grid_corners(nx, ny);
    focus.push(index(rng, soup.positions.len()) as u32);
    (soup, focus)
}

/// The `8 r` integer points on the square of radius `r` around the origin, counter-clockwise
/// from `(r, 0)`.
fn square_ring(r: i64) -> Vec<[i64; 2]> {
    let mut ring = vec![[r, 0]];
    let steps = [
        ([0, 1], r),
        ([-1, 0], 2 * r),
        ([0, -1], 2 * r),
        ([1, 0], 2 * r),
        ([0, 1], r - 1),
    ];
    for (step, count) in steps {
        for _ in 0..count {
            let [x, y] = *ring.last().expect("non-empty");
            ring.push([x + step[0], y + step[1]]);
        }
    }
    ring
}

pub(super) fn flat_fan(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let double = chance(rng, 0.5) && max_faces >= 32;
    let k = if double {
        int(rng, 1, (max_faces / 32) as i64)
    } else {
        int(rng, 1, 6.min(max_faces as i64 / 8))
    };
    let place = embedding(rng);
    let at = |p: [i64; 2]| place(p[0] as f64, p[1] as f64);
    let mut soup = Soup::default();
    let centre = soup.add_vertex(at([0, 0]));
    let inner = square_ring(k);
    let n = inner.len();
    let ring: Vec<u32> = inner.iter().map(|&p| soup.add_vertex(at(p))).collect();
    for i in 0..n {
        soup.faces.push([centre, ring[i], ring[(i + 1) % n]]);
    }
    let mut focus = vec![centre, ring[0], ring[n / 2], ring[index(rng, n)]];
    if double {
        // Ring 2k: q_2i = 2 p_i and q_2i+1 = p_i + p_i+1, in order.
        let outer: Vec<u32> = (0..2 * n)
            .map(|m| {
                let (p, q) = (inner[m / 2], inner[(m / 2 + m % 2) % n]);
                soup.add_vertex(at([p[0] + q[0], p[1] + q[1]]))
            })
            .collect();
        for i in 0..n {
            let (p, p_next) = (ring[i], ring[(i + 1) % n]);
            let (q0, q1, q2) = (outer[2 * i], outer[2 * i + 1], outer[(2 * i + 2) % (2 * n)]);
            soup.faces
                .extend([[p, q0, q1], [p, q1, p_next], [p_next, q1, q2]]);
        }
        focus.extend([outer[0], outer[n]]);
    }
    (soup, focus)
}

/// A regular `n`-gon of radius 1 in z = 0, counter-clockwise from `(1, 0)`, exactly symmetric
/// under `y -> -y` (and under `x -> -x` when 4 divides `n`), with exact points on the axes.
fn mirrored_polygon(n: usize) -> Vec<DVec3> {
    let mut points = vec![DVec3::ZERO; n];
    for k in 0..=n / 2 {
        let angle = std::f64::consts::TAU * k as f64 / n as f64;
        points[k] = if k == 0 {
            DVec3::X
        } else if 2 * k == n {
            DVec3::NEG_X
        } else if 4 * k == n {
            DVec3::Y
        } else if n % 4 == 0 && 4 * k > n {
            let p = points[n / 2 - k];
            DVec3::new(-p.x, p.y, 0.0)
        } else {
            DVec3::new(angle.cos(), angle.sin(), 0.0)
        };
    }
    for k in n / 2 + 1..n {
        let p = points[n - k];
        points[k] = DVec3::new(p.x, -p.y, 0.0);
    }
    points
}

/// The shape of a pyramid.
#[derive(Clone, Copy, PartialEq)]
enum PyramidShape {
    /// Sides only.
    Open,
    /// Sides and a base fanned from its centre.
    Closed,
    /// Two apexes, at heights `h` and `-depth`.
    Bipyramid { depth: f64 },
}

/// A pyramid over [`mirrored_polygon`] with apex `(0, 0, h)`; its focus: base vertices 0 and
/// `n / 2`, the apex, the base centre or lower apex.
fn pyramid_soup(n: usize, h: f64, shape: PyramidShape) -> (Soup, Vec<u32>) {
    let mut soup = Soup {
        positions: mirrored_polygon(n),
        faces: Vec::new(),
    };
    let apex = soup.add_vertex(DVec3::new(0.0, 0.0, h));
    let mut focus = vec![0, (n / 2) as u32, apex];
    for i in 0..n as u32 {
        soup.faces.push([i, (i + 1) % n as u32, apex]);
    }
    let below = match shape {
        PyramidShape::Open => None,
        PyramidShape::Closed => Some(soup.add_vertex(DVec3::ZERO)),
        PyramidShape::Bipyramid { depth } => Some(soup.add_vertex(DVec3::new(0.0, 0.0, -depth))),
    };
    if let Some(c) = below {
        for i in 0..n as u32 {
            soup.faces.push([(i + 1) % n as u32, i, c]);
        }
        focus.push(c);
    }
    (soup, focus)
}

pub(super) fn pyramid(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let n = int(rng, 3, 16.min(max_faces as i64 / 2)) as usize;
    let h = dyadic(0.25 + 1.75 * rng.next_f64());
    let shape = match int(rng, 0, 2) {
        0 => PyramidShape::Open,
        1 => PyramidShape::Closed,
        _ if chance(rng, 0.5) => PyramidShape::Bipyramid { depth: h },
        _ => PyramidShape::Bipyramid {
            depth: dyadic(0.25 + 1.75 * rng.next_f64()),
        },
    };
    let (mut soup, focus) = pyramid_soup(n, h, shape);
    // Midpoint subdivision keeps the mirror symmetry exact: halves of mirror images are
    // mirror images.
    for _ in 0..2 {
        if 4 * soup.faces.len() <= max_faces && chance(rng, 0.5) {
            soup = soup.subdivide();
        }
    }
    (soup, focus)
}

pub(super) fn bowtie(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    if chance(rng, 0.5) {
        two_grids_at_a_corner(rng, max_faces)
    } else {
        fans_at_a_vertex(rng, max_faces)
    }
}

/// Grid A over `[0, a] x [0, b]` and grid B in the third or fourth quadrant (possibly tilted),
/// sharing only the origin.
fn two_grids_at_a_corner(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let (mut soup, nx, ny) = bumpy_grid(rng, max_faces / 2);
    let (grid, mx, my) = bumpy_grid(rng, max_faces / 2);
    let slope = if chance(rng, 0.5) {
        dyadic(rng.next_f64())
    } else {
        0.0
    };
    let third_quadrant = chance(rng, 0.5);
    let mut other = grid.clone();
    for j in 0..=my {
        for i in 0..=mx {
            let p = &mut other.positions[j * (mx + 1) + i];
            let x = if third_quadrant {
                i as f64 - mx as f64
            } else {
                i as f64
            };
            let y = j as f64 - my as f64;
            *p = DVec3::new(x, y, p.z + slope * (x + y));
        }
    }
    let origin = if third_quadrant {
        my * (mx + 1) + mx
    } else {
        my * (mx + 1)
    } as u32;
    let map = soup.append(&other, &[(origin, 0)]);
    let mut focus = grid_corners(nx, ny);
    focus.extend(grid_corners(mx, my).iter().map(|&v| map[v as usize]));
    (soup, focus)
}

/// Two to four fans of one to four triangles around the origin, in disjoint sectors.
fn fans_at_a_vertex(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let fans = int(rng, 2, 4.min(max_faces as i64));
    let mut soup = Soup::default();
    let tip = soup.add_vertex(DVec3::ZERO);
    let mut focus = vec![tip];
    let sector = std::f64::consts::TAU / fans as f64;
    for f in 0..fans {
        let triangles = int(rng, 1, 4);
        let radius = dyadic(0.5 + 1.5 * rng.next_f64());
        let ring: Vec<u32> = (0..=triangles)
            .map(|t| {
                let angle = sector * (f as f64 + 0.8 * t as f64 / triangles as f64);
                let z = dyadic(rng.next_f64() - 0.5);
                soup.add_vertex(DVec3::new(radius * angle.cos(), radius * angle.sin(), z))
            })
            .collect();
        for pair in ring.windows(2) {
            soup.faces.push([tip, pair[0], pair[1]]);
        }
        focus.push(ring[0]);
    }
    (soup, focus)
}

pub(super) fn non_manifold(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let (mut soup, mut focus) = if chance(rng, 0.5) {
        book(rng, max_faces)
    } else {
        fins(rng, max_faces)
    };
    // Sometimes a copy of a face, the other way round, where there is room.
    if soup.faces.len() < max_faces && chance(rng, 0.5) {
        let [a, b, c] = soup.faces[index(rng, soup.faces.len())];
        soup.faces.push([c, b, a]);
        focus.extend([a, b, c]);
    }
    (soup, focus)
}

/// Three to five bumpy grids (pages) sharing their row `j = 0` (the spine, on the x axis, flat),
/// page `p` turned about the spine by about `p / pages` of a turn: every spine edge has a face
/// on each page.
fn book(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let pages = int(rng, 3, 5) as usize;
    let (mut page, nx, ny) = bumpy_grid(rng, max_faces / pages);
    for p in &mut page.positions[..=nx] {
        p.z = 0.0;
    }
    let mut soup = page.clone();
    let spine: Vec<(u32, u32)> = (0..=nx as u32).map(|i| (i, i)).collect();
    for p in 1..pages {
        let turn = std::f64::consts::TAU * (p as f64 + 0.4 * rng.next_f64()) / pages as f64;
        let (sin, cos) = turn.sin_cos();
        let mut turned = page.clone();
        for q in &mut turned.positions {
            *q = DVec3::new(q.x, q.y * cos - q.z * sin, q.y * sin + q.z * cos);
        }
        soup.append(&turned, &spine);
    }
    let mut focus = grid_corners(nx, ny);
    focus.push(index(rng, nx + 1) as u32);
    (soup, focus)
}

/// A bumpy grid with one to four fins: a triangle standing on an edge between two faces of the
/// grid (and so a third face on it; a fourth if two fins share the edge), its apex above the
/// edge's midpoint.
fn fins(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let fins = int(rng, 1, 4) as usize;
    let (mut soup, nx, ny) = bumpy_grid(rng, max_faces - fins);
    let mut focus = grid_corners(nx, ny);
    // The grid's faces come two by two, a cell's pair, which share its diagonal.
    let diagonals: Vec<[u32; 2]> = soup
        .faces
        .chunks(2)
        .map(|cell| {
            let mut shared = cell[0].into_iter().filter(|v| cell[1].contains(v));
            [0; 2].map(|_| shared.next().expect("a cell's faces share a diagonal"))
        })
        .collect();
    for _ in 0..fins {
        let [a, b] = diagonals[index(rng, diagonals.len())];
        let (p, q) = (soup.positions[a as usize], soup.positions[b as usize]);
        let lift = DVec3::new(
            dyadic(rng.next_f64() - 0.5),
            dyadic(rng.next_f64() - 0.5),
            dyadic(0.25 + rng.next_f64()),
        );
        let apex = soup.add_vertex(0.5 * (p + q) + lift);
        soup.faces.push([a, b, apex]);
        focus.extend([a, b, apex]);
    }
    (soup, focus)
}

pub(super) fn components(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let parts = int(rng, 2, 4) as usize;
    let budget = max_faces / parts;
    let mut soup = Soup::default();
    let mut focus = Vec::new();
    for _ in 0..parts {
        let part = match int(rng, 0, 2) {
            0 => bumpy_grid(rng, budget).0,
            1 => {
                let n = int(rng, 3, 6.min(budget as i64 / 2)) as usize;
                let depth = dyadic(0.25 + rng.next_f64());
                pyramid_soup(n, 1.0, PyramidShape::Bipyramid { depth }).0
            }
            _ => Soup {
                positions: vec![DVec3::ZERO, DVec3::X, DVec3::new(0.0, 1.0, 0.5)],
                faces: vec![[0, 1, 2]],
            },
        };
        let shift = DVec3::from([0; 3].map(|_| dyadic(8.0 * rng.next_f64() - 4.0)));
        let mut moved = part;
        for p in &mut moved.positions {
            *p += shift;
        }
        focus.push(soup.append(&moved, &[])[0]);
    }
    for _ in 0..int(rng, 1, 5) {
        let at = if chance(rng, 0.5) {
            soup.positions[index(rng, soup.positions.len())]
        } else {
            DVec3::from([0; 3].map(|_| dyadic(8.0 * rng.next_f64() - 4.0)))
        };
        focus.push(soup.add_vertex(at));
    }
    // Shuffle the vertex numbers (Fisher-Yates), so loose vertices are not all at the end.
    let mut order: Vec<u32> = (0..soup.positions.len() as u32).collect();
    for i in (1..order.len()).rev() {
        order.swap(i, index(rng, i + 1));
    }
    soup.renumber(&order);
    let focus = focus.into_iter().map(|v| order[v as usize]).collect();
    (soup, focus)
}
