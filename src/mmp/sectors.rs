//! A source vertex's directions split into two sectors, each propagated by its own engine on
//! its own thread. Every geodesic leaves the source in one of them, so the shorter of the two
//! distances at a vertex is its distance; the engines share their vertices' distances
//! (`bounds.rs`) to give up the wedges that the other sector's paths beat, so that each
//! covers about its own part of the surface. How evenly the work divides rests on a proxy:
//! the directions in which the vertices lie, by discrete geodesic polar coordinates
//! ([`directions`]), halved so that the two hold as many vertices within every distance as can
//! be ([`balanced_sides`]). From v0 of stanford_bunny the busier engine propagates 51-55 % as
//! many wedges as a one-thread run (three runs; 55-60 % with the sides placed only by the
//! vertices' count), on icosphere5 50.4 %.
//!
//! A run takes as long as the busier engine's share. The engine that runs ahead goes on into
//! the other's ground before that one's paths there are published, but the other, whose paths
//! there are shorter, propagates that ground again: with the engines' fronts held together (a
//! scratch build in which an engine waited while ahead), rocker_arm from v0 created about as
//! many wedges in all as one thread (326k against 323k; 378k running free) in the same time.
//! The proxy errs first in the directions. Past a saddle vertex, geodesics leave the source
//! in that vertex's direction, so many vertices share a direction, which the polar coordinates
//! spread and shift: from v0 of rocker_arm the sides chosen gave the engines 62 % and 38 % of
//! the wedges (6,291 and 3,753 vertices), and moving one side by 0.15 of a face (3.3 to 3.45)
//! moved a quarter of them from one engine to the other; sides at 0.7 and 3.5 gave 48 and 52 %.
//! Then in the work: with each vertex's true direction (from the traced paths of a one-thread
//! run) and sides on whole cells of the fan, the vertices halve but the wedges do not
//! (fandisk from v0: 49 % of the vertices, 38 % of the wedges; stanford_bunny from v1000: 53
//! and 58 %). An engine's share is that of the final wedges on the edges of its vertices
//! (within 1 % on those runs), which the vertices' count does not foretell.

use super::fan::{fan, open_fan, Fan};
use crate::mesh::{FaceId, TriMesh, VertexId};
use glam::DVec3;
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// The directions of a source vertex that one sector's engine propagates. The two sectors
/// meet at their sides and share no directions: a margin of 0.3 faces of the fan that each
/// also propagated on either side (so that its wedges would trim, on the edges, the wedges the
/// sector's pseudo-sources near its sides sent across them) made each engine propagate 59 %
/// instead of 50 % of a one-thread run's wedges on icosphere5 and 65 % instead of 51 % on
/// unit_sphere (the busier engine, from v0, v1000, v2000, v3000); on the other shared models
/// as many within the runs' spread (teapot 72 % with them and 76 % without, from seven
/// vertices) or more (alligator 89 % against 68 %).
#[derive(Clone, Debug)]
pub(crate) struct Sector {
    /// Parts of faces: the face, its first neighbour in turn round the fan, and the part of its
    /// opposite edge as fractions from that neighbour.
    pieces: Vec<(FaceId, VertexId, [f64; 2])>,
    /// The neighbours along whose edges the sector sends wedges.
    edges: Vec<VertexId>,
}

impl Sector {
    /// The parts of face `f`'s opposite edge that the sector's wedges cover, as fractions of the
    /// edge from its end `first`.
    pub(crate) fn pieces_of(
        &self,
        f: FaceId,
        first: VertexId,
    ) -> impl Iterator<Item = [f64; 2]> + '_ {
        self.pieces
            .iter()
            .filter(move |p| p.0 == f)
            .map(move |&(_, from, [lo, hi])| {
                if from == first {
                    [lo, hi]
                } else {
                    [1.0 - hi, 1.0 - lo]
                }
            })
    }

    /// Whether the sector sends a wedge along the edge to neighbour `u`.
    pub(crate) fn sends_along(&self, u: VertexId) -> bool {
        self.edges.contains(&u)
    }
}

/// Two sectors of the fan of faces round `v` that together cover it, with about as many
/// vertices beyond each: round a closed fan between two sides ([`balanced_sides`]), across an
/// open one (a boundary vertex's) at one ([`halving_cut`]); `None` for a vertex with neither
/// ([`fan`], [`open_fan`]).
pub(crate) fn split(mesh: &TriMesh, v: VertexId) -> Option<[Sector; 2]> {
    let fan = fan(mesh, v).or_else(|| open_fan(mesh, v))?;
    let (n, closed) = (fan.faces.len(), fan.is_closed());
    if closed && n < 3 {
        return None;
    }
    let cells = n * CELLS_PER_FACE;
    let found: Vec<(f64, f64)> = directions(mesh, v, &fan).into_iter().flatten().collect();
    let farthest = found.iter().map(|&(_, d)| d).fold(0.0, f64::max);
    let mut rings = vec![[0.0; RINGS]; cells];
    for (x, d) in found {
        let cell = ((x * CELLS_PER_FACE as f64) as usize).min(cells - 1);
        let ring = match farthest > 0.0 {
            true => ((d / farthest * RINGS as f64) as usize).min(RINGS - 1),
            false => 0,
        };
        rings[cell][ring] += 1.0;
    }
    let n_f = n as f64;
    let spans = if closed {
        let (lo, hi) = balanced_sides(&rings)?;
        // An arc round the fan's circle, in spans within `[0, n]`.
        let arc = |from: f64, to: f64| {
            let from = from.rem_euclid(n_f);
            let to = from + (to - from).rem_euclid(n_f);
            if to <= n_f {
                vec![[from, to]]
            } else {
                vec![[from, n_f], [0.0, to - n_f]]
            }
        };
        [arc(lo, hi), arc(hi, lo + n_f)]
    } else {
        let x = halving_cut(&counts(&rings)).filter(|&x| x > 0.0 && x < n_f)?;
        [vec![[0.0, x]], vec![[x, n_f]]]
    };
    let [first, second] = spans;
    Some([sector(&fan, first), sector(&fan, second)])
}

/// The sector of a fan whose directions it takes in `spans` of positions (face `i` spans
/// `[i, i + 1]` from neighbour `i`).
fn sector(fan: &Fan, spans: Vec<[f64; 2]>) -> Sector {
    let neighbours: Vec<VertexId> = fan.neighbours.iter().map(|n| n.0).collect();
    let mut pieces = Vec::new();
    for (i, face) in fan.faces.iter().enumerate() {
        for &[a, b] in &spans {
            let (lo, hi) = (a.max(i as f64) - i as f64, b.min((i + 1) as f64) - i as f64);
            if hi > lo {
                pieces.push((face.0, neighbours[i], [lo, hi]));
            }
        }
    }
    // On a closed fan neighbour 0 lies at both 0 and n.
    let n_f = fan.faces.len() as f64;
    let edges = (0..neighbours.len())
        .filter(|&i| {
            let ends = if fan.is_closed() && i == 0 {
                vec![0.0, n_f]
            } else {
                vec![i as f64]
            };
            ends.into_iter()
                .any(|x| spans.iter().any(|&[a, b]| a <= x && x <= b))
        })
        .map(|i| neighbours[i])
        .collect();
    Sector { pieces, edges }
}

/// The position across an open fan (face `i` spans `[i, i + 1]`) that halves the vertices,
/// given how many vertices' directions lie in each of its cells ([`CELLS_PER_FACE`] per face).
fn halving_cut(vertices: &[f64]) -> Option<f64> {
    let half = vertices.iter().sum::<f64>() / 2.0;
    let mut inside = 0.0;
    for (c, &w) in vertices.iter().enumerate() {
        if w > 0.0 && inside + w >= half {
            return Some((c as f64 + (half - inside) / w) / CELLS_PER_FACE as f64);
        }
        inside += w;
    }
    None
}

/// Cells of the fan per face in which [`balanced_sides`] places the sectors' sides.
const CELLS_PER_FACE: usize = 16;

/// Rings of estimated distance from the source (up to the farthest vertex's) in which
/// [`balanced_sides`] weighs the two sectors against each other.
const RINGS: usize = 32;

/// The sides of the first sector as positions round a fan (face `i` spans `[i, i + 1]`, from
/// neighbour `i`), given how many vertices' directions lie in each of its cells
/// ([`CELLS_PER_FACE`] per face), ring by ring of distance ([`RINGS`]). The sides halve the
/// vertices; of all such halvings, the one whose sectors differ least in the vertices they hold
/// within any distance, and then the one with its sides nearest faces' middles. Each engine
/// takes its events in the order of their distances and gives up only what the other's
/// published paths beat: an engine whose ground lies nearer runs ahead into the other's
/// before those paths are there. Against halving where the fewest directions lie (so that
/// the sides' uncertain vertices were fewest), from twelve vertices of stanford_bunny (three
/// runs each) the busier engine propagated 5 % fewer wedges (913k -> 866k on average), both
/// together 4 % fewer, in 6 % less time (whole process, median 0.562 -> 0.528 s); from three
/// of the bunny subdivided once (278k faces) 8 % fewer (5.30 -> 4.87 s); rocker_arm 2 %
/// fewer in the same time, icosphere5 as many (each half already), fandisk on two threads 5 %
/// fewer (four vertices). On models below 15,000 faces, which `distance` runs on one thread,
/// the busier engine of cad_featuretype propagated 14 % more.
fn balanced_sides(rings: &[[f64; RINGS]]) -> Option<(f64, f64)> {
    let cells = rings.len();
    let n = (cells / CELLS_PER_FACE) as f64;
    let position = |c: f64| c / CELLS_PER_FACE as f64;
    let weights = counts(rings);
    let weight = |c: usize| weights[c % cells];
    let half = weights.iter().sum::<f64>() / 2.0;
    let mut all = [0.0; RINGS];
    for r in rings {
        add(&mut all, r, 1.0);
    }
    // The largest difference between the sector's vertices and the rest within a distance.
    let imbalance = |inside: &[f64; RINGS]| {
        let (mut mine, mut theirs, mut worst) = (0.0, 0.0, 0.0f64);
        for (a, b) in inside.iter().zip(&all) {
            mine += a;
            theirs += b - a;
            worst = worst.max((mine - theirs).abs());
        }
        worst
    };
    let off_middle = |x: f64| (x.fract() - 0.5).abs();
    let tie = 1e-9 * half;
    let (mut end, mut inside, mut ring) = (0, 0.0, [0.0; RINGS]);
    let mut best: Option<(f64, f64, f64)> = None;
    for start in 0..cells {
        if end <= start {
            (end, inside, ring) = (start, 0.0, [0.0; RINGS]);
        }
        while end < start + cells && inside + weight(end) < half {
            inside += weight(end);
            add(&mut ring, &rings[end % cells], 1.0);
            end += 1;
        }
        let w = weight(end);
        let part = if w > 0.0 { (half - inside) / w } else { 0.0 };
        let (lo, hi) = (position(start as f64), position(end as f64 + part));
        let mut sector = ring;
        add(&mut sector, &rings[end % cells], part);
        let cost = imbalance(&sector) + tie * (off_middle(lo) + off_middle(hi));
        if hi > lo && hi < lo + n && best.is_none_or(|b| cost < b.0) {
            best = Some((cost, lo, hi));
        }
        if end > start {
            inside -= weight(start);
            add(&mut ring, &rings[start % cells], -1.0);
        }
    }
    best.map(|(_, lo, hi)| (lo, hi))
}

/// The vertices of each cell, all rings together.
fn counts(rings: &[[f64; RINGS]]) -> Vec<f64> {
    rings.iter().map(|r| r.iter().sum()).collect()
}

/// `into += by * what`, ring by ring.
fn add(into: &mut [f64; RINGS], what: &[f64; RINGS], by: f64) {
    for (a, b) in into.iter_mut().zip(what) {
        *a += by * b;
    }
}

/// Each vertex's direction from `v` as a position round its fan: `i + t` where it crosses
/// the opposite edge of face `i` at the fraction `t` from neighbour `i`. By discrete geodesic
/// polar coordinates [MR12]: a front from `v` in the order of estimated distances, each vertex
/// reached across a face from two reached corners by the unfolded source that their distances
/// place, its angle interpolated between theirs, or else along an edge with its neighbour's
/// angle. A vertex is settled when the front passes it: estimates across faces are not a
/// metric's and could lower it again, but every face is then crossed once from each corner
/// instead of from every corner that the front lowers (a third fewer instructions, on
/// rocker_arm 41M -> 26M, where the sectors were the wait before the engines started).
/// Each with the distance the front gave it; `None` for the vertices the front does not reach.
///
/// [MR12]: E. L. Melvær, M. Reimers, Geodesic polar coordinates on polygonal meshes, Computer
/// Graphics Forum 31(8), 2012.
fn directions(mesh: &TriMesh, v: VertexId, fan: &Fan) -> Vec<Option<(f64, f64)>> {
    let count = mesh.vertex_count();
    let total: f64 = fan.faces.iter().map(|f| f.2).sum();
    // Angles round a closed fan start again at 0 after the angle sum.
    let wrap = fan.is_closed().then_some(total);
    let mut distance = vec![f64::INFINITY; count];
    let mut angle = vec![f64::NAN; count];
    let mut queue = BinaryHeap::new();
    let mut settled = vec![false; count];
    distance[v.index()] = 0.0;
    settled[v.index()] = true;
    for &(u, at) in &fan.neighbours {
        distance[u.index()] = mesh.position(u).distance(mesh.position(v));
        angle[u.index()] = at;
        queue.push((Reverse(distance[u.index()].to_bits()), u));
    }
    let p = |u: VertexId| mesh.position(u);
    // A vertex queued again at a lower distance is settled by that entry, which comes first.
    while let Some((_, j)) = queue.pop() {
        if settled[j.index()] {
            continue;
        }
        settled[j.index()] = true;
        for &f in mesh.vertex_faces(j) {
            let corners = mesh.face(f);
            for &i in corners.iter().filter(|&&i| !settled[i.index()]) {
                let k = *corners
                    .iter()
                    .find(|&&k| k != i && k != j)
                    .expect("a third corner");
                let (dj, aj) = (distance[j.index()], angle[j.index()]);
                let (dk, ak) = (distance[k.index()], angle[k.index()]);
                let crossing = across(p, (j, dj), (k, dk, ak), i);
                let d = match &crossing {
                    Some(c) => c.distance,
                    None => dj + p(i).distance(p(j)),
                };
                if d < distance[i.index()] {
                    distance[i.index()] = d;
                    angle[i.index()] = crossing.map_or(aj, |c| c.angle(aj, ak, wrap));
                    queue.push((Reverse(d.to_bits()), i));
                }
            }
        }
    }
    let n = fan.neighbours.len();
    let reach = |i: usize| mesh.position(fan.neighbours[i % n].0).distance(p(v));
    // Where the direction crosses its face's opposite edge, as a fraction from neighbour `i`
    // (the sectors' pieces are parts of those edges, not of the corner angles): by the law of
    // sines, `r_i sin t / (r_i sin t + r_{i+1} sin(c - t))` at angle `t` into a corner `c`.
    let position = |a: f64| {
        let a = match wrap {
            Some(total) => a.rem_euclid(total),
            None => a.clamp(0.0, total),
        };
        let (i, face) = fan.faces.iter().enumerate().rev().find(|(_, f)| f.1 <= a)?;
        let t = (a - face.1).clamp(0.0, face.2);
        let (near, far) = (reach(i) * t.sin(), reach(i + 1) * (face.2 - t).sin());
        let fraction = if near + far > 0.0 {
            near / (near + far)
        } else {
            0.0
        };
        Some(i as f64 + fraction)
    };
    angle
        .iter()
        .zip(&distance)
        .map(|(&a, &d)| match a.is_nan() {
            true => None,
            false => position(a).map(|x| (x, d)),
        })
        .collect()
}

/// Where the straight way to a face's third corner `i` from the source, unfolded by the
/// distances of corners `j` and `k`, crosses the edge `jk` ([`across`]): the way's length, and
/// the directions from the source to `j`, `k` and `i` in the unfolding (edge `jk` along the
/// first axis from `j`), from which [`Crossing::angle`] interpolates `i`'s angle.
struct Crossing {
    distance: f64,
    to_j: [f64; 2],
    to_k: [f64; 2],
    to_i: [f64; 2],
}

impl Crossing {
    /// The angle of corner `i`, given those of `j` and `k`, as far from `aj` towards `ak` as
    /// the angle at the source from `j` to `i` is a share of that from `j` to `k`: exact where
    /// the faces between lie in one plane. Asked only where the crossing lowers `i`'s distance
    /// (two arc tangents).
    fn angle(&self, aj: f64, ak: f64, wrap: Option<f64>) -> f64 {
        // Unwrapped across a closed fan's first neighbour, where angles start again at 0.
        let ak = match wrap {
            Some(total) if (ak - aj).abs() > total / 2.0 => ak - total * (ak - aj).signum(),
            _ => ak,
        };
        let between = |a: [f64; 2], b: [f64; 2]| {
            (a[0] * b[1] - a[1] * b[0])
                .atan2(a[0] * b[0] + a[1] * b[1])
                .abs()
        };
        let (alpha, beta) = (between(self.to_j, self.to_i), between(self.to_j, self.to_k));
        if beta > 0.0 {
            aj + (ak - aj) * (alpha / beta)
        } else {
            aj
        }
    }
}

/// The way to corner `i` of a face from the point that the distances of its corners `j` and
/// `k` place on the far side of the edge `jk` from `i` (the source, unfolded), where it crosses
/// that edge; `None` where it does not, or no such point is (or `k`, at distance `dk` and
/// angle `ak`, is not reached).
fn across(
    p: impl Fn(VertexId) -> DVec3,
    (j, dj): (VertexId, f64),
    (k, dk, ak): (VertexId, f64, f64),
    i: VertexId,
) -> Option<Crossing> {
    if !dk.is_finite() || ak.is_nan() {
        return None;
    }
    let (e, to_i) = (p(k) - p(j), p(i) - p(j));
    let length = e.length();
    let along = e / length;
    let (xi, yi) = (to_i.dot(along), to_i.cross(along).length());
    let xs = (dj * dj - dk * dk + length * length) / (2.0 * length);
    let ys = -(dj * dj - xs * xs).sqrt();
    if ys.is_nan() || yi <= 0.0 {
        return None;
    }
    // Where the way from the source to `i` crosses the edge's line.
    let t = xs + (xi - xs) * (-ys) / (yi - ys);
    if !(0.0..=length).contains(&t) {
        return None;
    }
    Some(Crossing {
        distance: ((xi - xs).powi(2) + (yi - ys).powi(2)).sqrt(),
        to_j: [-xs, -ys],
        to_k: [length - xs, -ys],
        to_i: [xi - xs, yi - ys],
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    /// On a plane, geodesic polar coordinates are the polar angles: from the middle vertex of
    /// a flat grid, every vertex's direction is where the straight line to it crosses the
    /// opposite edge of a face of the fan.
    #[test]
    fn directions_on_a_plane_are_the_polar_angles() {
        let mesh = shapes::grid(10, 10, 1.0, 1.0);
        let v = VertexId(5 * 11 + 5);
        let fan = fan(&mesh, v).expect("an interior vertex");
        let n = fan.neighbours.len();
        let at = |u: VertexId| mesh.position(u) - mesh.position(v);
        let cross = |a: glam::DVec3, b: glam::DVec3| a.x * b.y - a.y * b.x;
        let mut checked = 0;
        for (u, position) in directions(&mesh, v, &fan).into_iter().enumerate() {
            let Some((x, _)) = position else { continue };
            let p = at(VertexId(u as u32));
            // The ray from `v` through `p` meets `a + t (b - a)` at `t`, in front of `v`.
            let expected: Vec<f64> = (0..n)
                .filter_map(|i| {
                    let (a, b) = (at(fan.neighbours[i].0), at(fan.neighbours[(i + 1) % n].0));
                    let t = cross(p, a) / cross(b - a, p);
                    let ahead = (a + (b - a) * t).dot(p) > 0.0;
                    ((-1e-12..=1.0 + 1e-12).contains(&t) && ahead).then_some(i as f64 + t)
                })
                .collect();
            let off = |e: f64| {
                let d = (x - e).abs();
                d.min(n as f64 - d)
            };
            assert!(
                expected.iter().any(|&e| off(e) < 1e-9),
                "v{u}: {x} for {expected:?}"
            );
            checked += 1;
        }
        assert_eq!(checked, 120);
    }

    /// Evenly spread directions are halved at faces' middles. Where the near vertices lie in
    /// one half of the fan and the far ones in the other, the sides cut across both, so that
    /// each sector holds as many of each.
    #[test]
    fn sides_halve_the_directions_and_each_distance() {
        let faces = 6;
        let even = vec![[1.0; RINGS]; faces * CELLS_PER_FACE];
        let (lo, hi) = balanced_sides(&even).expect("sides");
        assert!((hi - lo - 3.0).abs() < 1e-12, "{lo} {hi}");
        assert!((lo.fract() - 0.5).abs() < 1e-12, "{lo}");
        // Faces 0 to 2: a vertex per cell in the nearest ring; faces 3 to 5: in the farthest.
        let mut apart = vec![[0.0; RINGS]; faces * CELLS_PER_FACE];
        for (c, cell) in apart.iter_mut().enumerate() {
            cell[if c < 3 * CELLS_PER_FACE { 0 } else { RINGS - 1 }] = 1.0;
        }
        let (lo, hi) = balanced_sides(&apart).expect("sides");
        assert!((hi - lo - 3.0).abs() < 1e-12, "{lo} {hi}");
        // Cell middles within the first sector, counted by ring.
        let within = |ring: usize| {
            (0..apart.len())
                .filter(|&c| {
                    let x = (c as f64 + 0.5) / CELLS_PER_FACE as f64;
                    (lo <= x && x <= hi) || (lo <= x + 6.0 && x + 6.0 <= hi)
                })
                .map(|c| apart[c][ring])
                .sum::<f64>()
        };
        let half_ring = 1.5 * CELLS_PER_FACE as f64;
        assert!(
            (within(0) - half_ring).abs() <= 1.0,
            "{lo} {hi}: {}",
            within(0)
        );
        assert!((within(RINGS - 1) - half_ring).abs() <= 1.0, "{lo} {hi}");
    }

    /// The two sectors' directions cover every face of the fan once, and one or both (at a
    /// side) send a wedge along each edge: round a closed fan and across open ones.
    #[test]
    fn the_sectors_own_every_direction_once() {
        let sphere = shapes::icosphere(2);
        owned_once(
            &sphere,
            VertexId(0),
            fan(&sphere, VertexId(0)).expect("a closed fan"),
        );
        let grid = shapes::grid(6, 5, 1.0, 1.0);
        for v in [0, 3, 6, 13, 41].map(VertexId) {
            owned_once(&grid, v, open_fan(&grid, v).expect("an open fan"));
        }
    }

    fn owned_once(mesh: &TriMesh, v: VertexId, fan: Fan) {
        let sectors = split(mesh, v).expect("two sectors");
        for &(f, ..) in &fan.faces {
            let first = mesh
                .face(f)
                .into_iter()
                .find(|&c| c != v)
                .expect("a corner");
            let owned: f64 = sectors
                .iter()
                .flat_map(|s| s.pieces_of(f, first))
                .map(|[lo, hi]| hi - lo)
                .sum();
            assert!((owned - 1.0).abs() < 1e-12, "{f:?}: {owned}");
        }
        for &(u, _) in &fan.neighbours {
            let own = sectors.iter().filter(|s| s.sends_along(u)).count();
            assert!((1..=2).contains(&own), "{u:?}");
        }
    }
}
