//! The kinds made by surgery on a bumpy grid: coincident vertices, zero-area faces, slivers,
//! extreme scales and mixed magnitudes (see [`DegenerateKind`](super::DegenerateKind)).

use super::draw::{bumpy_grid, chance, dyadic, grid_corners, index, int};
use super::measure::distance_f64;
use super::soup::Soup;
use crate::mesh::shapes::SplitMix64;
use crate::mesh::vector::power_of_two;
use glam::DVec3;

/// A random interior manifold vertex and its star size, if one is found in a few tries.
fn interior_vertex(rng: &mut SplitMix64, soup: &Soup) -> Option<(u32, usize)> {
    (0..32).find_map(|_| {
        let v = index(rng, soup.positions.len()) as u32;
        soup.star(v).map(|star| (v, star.len()))
    })
}

/// Splits a random interior vertex into two, the copy at `v`'s position moved by `offset`;
/// returns the focus vertices (the two, and the neighbours where the fans were cut).
fn split_random_vertex(
    rng: &mut SplitMix64,
    soup: &mut Soup,
    offset: DVec3,
    close: bool,
) -> Vec<u32> {
    let Some((v, k)) = interior_vertex(rng, soup) else {
        return Vec::new();
    };
    let star = soup.star(v).expect("interior vertex");
    let (first, span) = (index(rng, k), 1 + index(rng, k - 1));
    let at = soup.positions[v as usize] + offset;
    let copy = soup
        .split_vertex(v, at, first, span, close)
        .expect("interior vertex");
    vec![v, copy, star[first].0, star[(first + span) % k].0]
}

pub(super) fn coincident_vertices(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let splits = int(rng, 1, 3) as usize;
    let (mut soup, _, _) = bumpy_grid(rng, max_faces - 2 * splits);
    let mut focus = Vec::new();
    for _ in 0..splits {
        let close = chance(rng, 0.75);
        focus.extend(split_random_vertex(rng, &mut soup, DVec3::ZERO, close));
    }
    (soup, focus)
}

/// A random face and one of its edges (`(face, corner)`), on the boundary when asked and
/// possible.
fn random_edge(rng: &mut SplitMix64, soup: &Soup, boundary: bool) -> (usize, usize) {
    let on_boundary = if boundary {
        soup.boundary_edges()
    } else {
        Vec::new()
    };
    match on_boundary.is_empty() {
        false => on_boundary[index(rng, on_boundary.len())],
        true => (index(rng, soup.faces.len()), index(rng, 3)),
    }
}

pub(super) fn zero_area_faces(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let insertions = int(rng, 1, 3) as usize;
    let (mut soup, _, _) = bumpy_grid(rng, max_faces - 2 * insertions);
    let mut focus = Vec::new();
    for n in 0..insertions {
        let boundary = n == 0 && chance(rng, 0.5);
        let (face, corner) = random_edge(rng, &soup, boundary);
        let f = soup.faces[face];
        let (p, q) = (
            soup.positions[f[corner] as usize],
            soup.positions[f[(corner + 1) % 3] as usize],
        );
        let t = [0.25, 0.5, 0.75][index(rng, 3)];
        // Exact: p and q are dyadic with few bits, so t (q - p) and p + t (q - p) are too.
        let at = p + t * (q - p);
        let m = soup.insert_on_edge(face, corner, at);
        focus.extend([m, f[0], f[1], f[2]]);
    }
    (soup, focus)
}

/// A factor from `10^-12` to `10^-9`, log-uniform.
fn tiny(rng: &mut SplitMix64) -> f64 {
    10f64.powf(-9.0 - 3.0 * rng.next_f64())
}

pub(super) fn slivers(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let operations = int(rng, 1, 3) as usize;
    let (mut soup, _, _) = bumpy_grid(rng, max_faces - 2 * operations);
    let mut focus = Vec::new();
    for _ in 0..operations {
        if chance(rng, 0.5) {
            // A cap: a vertex within 1e-9 of the edge it is inserted on.
            let boundary = chance(rng, 0.3);
            let (face, corner) = random_edge(rng, &soup, boundary);
            let f = soup.faces[face];
            let (p, q) = (
                soup.positions[f[corner] as usize],
                soup.positions[f[(corner + 1) % 3] as usize],
            );
            let t = dyadic(0.25 + 0.5 * rng.next_f64());
            let d = q - p;
            let across = d.x.hypot(d.y);
            let direction = if chance(rng, 0.5) || across == 0.0 {
                DVec3::Z
            } else {
                (d.truncate().perp() / across).extend(0.0)
            };
            let h = distance_f64(p, q) * tiny(rng) * if chance(rng, 0.5) { 1.0 } else { -1.0 };
            let at = p + t * d + h * direction;
            let m = soup.insert_on_edge(face, corner, at);
            focus.extend([m, f[0], f[1], f[2]]);
        } else {
            // Needles: a vertex split into two a tiny distance apart.
            let u = DVec3::from([0; 3].map(|_| 2.0 * rng.next_f64() - 1.0));
            let norm = u.x.hypot(u.y).hypot(u.z).max(f64::MIN_POSITIVE);
            let eps = tiny(rng);
            focus.extend(split_random_vertex(rng, &mut soup, eps * u / norm, true));
        }
    }
    (soup, focus)
}

pub(super) fn scaled(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let (mut soup, nx, ny) = bumpy_grid(rng, max_faces);
    let scale = power_of_two(int(rng, -600, 600) as i32);
    for p in &mut soup.positions {
        *p *= scale;
    }
    (soup, grid_corners(nx, ny))
}

pub(super) fn mixed_magnitudes(rng: &mut SplitMix64, max_faces: usize) -> (Soup, Vec<u32>) {
    let (mut soup, nx, ny) = bumpy_grid(rng, max_faces);
    for p in &mut soup.positions {
        p.x = (p.x + 1.0) * 10f64.powi(int(rng, -8, 8) as i32);
    }
    (soup, grid_corners(nx, ny))
}
