//! Random scenes from a seed: convex polygons, star-shaped concave polygons, U shapes and hooks,
//! so that shortest paths wrap around obstacles and into pockets [LZT §5: "we use both convex
//! and concave polygon obstacles"].

use super::geometry::{distance, distance_to_segment, locate, Location, Point};
use super::scene::{Rectangle, Scene};
use crate::mesh::shapes::SplitMix64;
use glam::DVec2;
use std::f64::consts::TAU;

/// Half the side of a cell is 0.5; obstacles stay within this radius of the cell centre.
const OBSTACLE_RADIUS: f64 = 0.42;
/// p and q keep at least this distance from every obstacle.
const CLEARANCE: f64 = 0.03;

impl Scene {
    /// A random scene that depends on the seed only: `obstacles` obstacles in distinct unit cells
    /// of a square grid, each randomly rotated, cycling through convex, star-shaped, U-shaped and
    /// hook-shaped; p and q are random points at least `CLEARANCE` away from every obstacle and
    /// half the grid side apart, so they may sit in a pocket.
    pub fn random(seed: u64, obstacles: usize) -> Scene {
        let mut rng = SplitMix64::new(seed);
        let side = (obstacles as f64).sqrt().ceil() as usize + 1;
        let mut cells: Vec<usize> = (0..side * side).collect();
        for i in 0..obstacles {
            let j = i + below(&mut rng, cells.len() - i);
            cells.swap(i, j);
        }
        let first_kind = below(&mut rng, 4);
        let polygons: Vec<Vec<Point>> = cells[..obstacles]
            .iter()
            .enumerate()
            .map(|(i, &cell)| {
                let centre = DVec2::new((cell % side) as f64, (cell / side) as f64) + 0.5;
                place(template(&mut rng, (first_kind + i) % 4), centre, &mut rng)
            })
            .collect();
        let margin = 0.25;
        let rectangle = Rectangle {
            min: [-margin, -margin],
            max: [side as f64 + margin, side as f64 + margin],
        };
        let p = free_point(&mut rng, &rectangle, &polygons, None, side);
        let q = free_point(&mut rng, &rectangle, &polygons, Some(p), side);
        Scene {
            rectangle,
            obstacles: polygons,
            p,
            q,
        }
    }
}

/// A uniform integer in `0..n`.
fn below(rng: &mut SplitMix64, n: usize) -> usize {
    ((rng.next_f64() * n as f64) as usize).min(n - 1)
}

fn uniform(rng: &mut SplitMix64, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * rng.next_f64()
}

/// Corners of one kind of obstacle, in any frame and orientation; `place` normalises them.
fn template(rng: &mut SplitMix64, kind: usize) -> Vec<Point> {
    match kind {
        0 | 1 => {
            // Points by increasing angle: on a circle they are a convex polygon; with random
            // radii a star-shaped, generally concave one.
            let n = if kind == 0 {
                3 + below(rng, 6)
            } else {
                5 + below(rng, 6)
            };
            let gaps: Vec<f64> = (0..n).map(|_| uniform(rng, 0.5, 1.5)).collect();
            let total: f64 = gaps.iter().sum();
            let start = uniform(rng, 0.0, TAU);
            let mut angle = start;
            gaps.iter()
                .map(|gap| {
                    let r = if kind == 0 {
                        1.0
                    } else {
                        uniform(rng, 0.3, 1.0)
                    };
                    let x = r * DVec2::from_angle(angle);
                    angle += TAU * gap / total;
                    x.to_array()
                })
                .collect()
        }
        2 => {
            let (a, b) = (uniform(rng, 0.6, 1.1), uniform(rng, 0.6, 1.2));
            jitter(
                rng,
                &[
                    [0.0, 0.0],
                    [3.0, 0.0],
                    [3.0, 3.0],
                    [3.0 - a, 3.0],
                    [3.0 - a, b],
                    [a, b],
                    [a, 3.0],
                    [0.0, 3.0],
                ],
            )
        }
        _ => jitter(
            rng,
            &[
                [0.0, 0.0],
                [4.0, 0.0],
                [4.0, 3.0],
                [2.0, 3.0],
                [2.0, 2.0],
                [3.0, 2.0],
                [3.0, 1.0],
                [1.0, 1.0],
                [1.0, 4.0],
                [0.0, 4.0],
            ],
        ),
    }
}

/// Moves each corner by at most 0.12 in each coordinate: arms of width at least 0.6 stay apart.
fn jitter(rng: &mut SplitMix64, corners: &[Point]) -> Vec<Point> {
    corners
        .iter()
        .map(|&x| {
            let shift = DVec2::new(uniform(rng, -0.12, 0.12), uniform(rng, -0.12, 0.12));
            (DVec2::from(x) + shift).to_array()
        })
        .collect()
}

/// Centres, rotates and scales a template into the disk of radius `OBSTACLE_RADIUS` at `centre`.
fn place(corners: Vec<Point>, centre: DVec2, rng: &mut SplitMix64) -> Vec<Point> {
    let n = corners.len() as f64;
    let mean = corners
        .iter()
        .fold(DVec2::ZERO, |s, &x| s + DVec2::from(x) / n);
    let radius = corners
        .iter()
        .map(|&x| distance(x, mean.to_array()))
        .fold(0.0, f64::max);
    let rotation = DVec2::from_angle(uniform(rng, 0.0, TAU));
    let scale = OBSTACLE_RADIUS / radius;
    corners
        .iter()
        .map(|&x| (centre + scale * rotation.rotate(DVec2::from(x) - mean)).to_array())
        .collect()
}

/// A random point of the rectangle clear of every obstacle, and at least half the grid side
/// from `other`.
fn free_point(
    rng: &mut SplitMix64,
    rectangle: &Rectangle,
    obstacles: &[Vec<Point>],
    other: Option<Point>,
    side: usize,
) -> Point {
    let (min, max) = (DVec2::from(rectangle.min), DVec2::from(rectangle.max));
    loop {
        let x = DVec2::new(uniform(rng, min.x, max.x), uniform(rng, min.y, max.y));
        let clear = obstacles.iter().all(|o| {
            locate(o, x.to_array()) == Location::Outside
                && (0..o.len()).all(|i| {
                    distance_to_segment(o[i], o[(i + 1) % o.len()], x.to_array()) >= CLEARANCE
                })
        });
        let far = other.is_none_or(|y| distance(x.to_array(), y) >= 0.5 * side as f64);
        let inside = (min + CLEARANCE).cmplt(x).all() && x.cmplt(max - CLEARANCE).all();
        if clear && far && inside {
            return x.to_array();
        }
    }
}
