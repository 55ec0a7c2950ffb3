//! Seeded random choices for the corpus, and the bumpy grid most kinds start from: every
//! draw goes through [`SplitMix64`], so a mesh depends on its kind and seed only.

use super::soup::{Diagonal, Soup};
use crate::mesh::shapes::SplitMix64;
use glam::DVec3;

/// A uniform integer in `lo..=hi`.
pub(crate) fn int(rng: &mut SplitMix64, lo: i64, hi: i64) -> i64 {
    lo + (rng.next_u64() % (hi - lo + 1).max(1) as u64) as i64
}

/// A uniform index below `n` (`n > 0`).
pub(crate) fn index(rng: &mut SplitMix64, n: usize) -> usize {
    (rng.next_u64() % n.max(1) as u64) as usize
}

/// True with probability `p`.
pub(crate) fn chance(rng: &mut SplitMix64, p: f64) -> bool {
    rng.next_f64() < p
}

/// `x` rounded to a multiple of `2^-12`: few bits, so sums and halves stay exact.
pub(crate) fn dyadic(x: f64) -> f64 {
    (x * 4096.0).round() / 4096.0
}

/// Rising, falling or random diagonals for an `nx` by `ny` grid.
pub(crate) fn diagonals(rng: &mut SplitMix64, nx: usize, ny: usize) -> Vec<Diagonal> {
    let mode = int(rng, 0, 2);
    (0..nx * ny)
        .map(|_| match mode {
            0 => Diagonal::Rising,
            1 => Diagonal::Falling,
            _ if chance(rng, 0.5) => Diagonal::Rising,
            _ => Diagonal::Falling,
        })
        .collect()
}

/// Grid dimensions with at most `max_faces` faces, each side from 2 (or 1 if that is all
/// there is room for) to 9 cells.
pub(crate) fn grid_size(rng: &mut SplitMix64, max_faces: usize) -> (usize, usize) {
    let cells = (max_faces / 2).max(1) as i64;
    let nx = int(rng, 2.min(cells), 9.min(cells / 2).max(1));
    let ny = int(rng, 2.min(cells / nx), 9.min(cells / nx).max(1));
    (nx as usize, ny as usize)
}

/// A grid over `[0, nx] x [0, ny]` with random dyadic heights (corner `(0, 0)` at height 0),
/// its size and the index of vertex `(i, j)` being `j * (nx + 1) + i`.
pub(crate) fn bumpy_grid(rng: &mut SplitMix64, max_faces: usize) -> (Soup, usize, usize) {
    let (nx, ny) = grid_size(rng, max_faces);
    let amplitude = 0.1 + 0.5 * rng.next_f64();
    let heights: Vec<f64> = (0..(nx + 1) * (ny + 1))
        .map(|k| match k {
            0 => 0.0,
            _ => dyadic(amplitude * (2.0 * rng.next_f64() - 1.0)),
        })
        .collect();
    let cut = diagonals(rng, nx, ny);
    let soup = Soup::grid(
        nx,
        ny,
        |i, j| DVec3::new(i as f64, j as f64, heights[j * (nx + 1) + i]),
        |i, j| cut[j * nx + i],
    );
    (soup, nx, ny)
}

/// The four corners of an `nx` by `ny` grid.
pub(crate) fn grid_corners(nx: usize, ny: usize) -> Vec<u32> {
    let id = |i: usize, j: usize| (j * (nx + 1) + i) as u32;
    vec![id(0, 0), id(nx, 0), id(nx, ny), id(0, ny)]
}
