//! The 2D subdivision of a face induced by the final wedges on its edges (Property 4 and
//! Fig. 15 [LZT §3]), computed in f64 for drawing and inspection.
//!
//! Every final wedge on an edge of the face gives an unfolded image of its pseudo-source in the
//! face's plane and the part of the face its rays reach: beyond the edge for a wedge from outside,
//! between the image and the edge for one from inside, the whole face for a pseudo-source at a
//! corner. A point of the face belongs to the image that gives it the smallest distance
//! `|x - s| + sigma` among those reaching it. By Property 4 the regions cover the face and each is
//! star-shaped from its image, so a region is traced along rays from its image; its boundaries
//! with other regions are bisectors, lines (equal sigmas) or hyperbola branches (eq. (1)).

mod tolerance;

pub use tolerance::SubdivisionTolerance;

use crate::mesh::{FaceId, VertexId};
use crate::mmp::{GeodesicField, PseudoSource};
use crate::scalar::Scalar;
use glam::DVec2;
use serde::Serialize;

/// A point of the plane the face is unfolded into.
pub type Point2 = DVec2;

/// One region of a face's subdivision: the points closest to one image of one pseudo-source.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Region {
    /// The paper's name: the vertex index, bracketed by image number when the vertex has several
    /// images in the face (`6(1)`, `2(3)`), or `s0` for a source that is not a vertex.
    pub label: String,
    /// The pseudo-source.
    pub pseudo_source: PseudoSource,
    /// The mesh vertex the pseudo-source is, if it is one.
    pub vertex: Option<VertexId>,
    /// The unfolded image of the pseudo-source in the face's plane.
    pub image: Point2,
    /// Geodesic distance from the pseudo-source back to its source.
    pub sigma: f64,
    /// The region's boundary, counter-clockwise, with bisector arcs sampled.
    pub polygon: Vec<Point2>,
}

impl Region {
    /// The area enclosed by the polygon.
    pub fn area(&self) -> f64 {
        polygon_area(&self.polygon)
    }

    /// Whether the polygon contains `p` (even-odd rule).
    pub fn contains(&self, p: Point2) -> bool {
        let n = self.polygon.len();
        let mut inside = false;
        for i in 0..n {
            let (a, b) = (self.polygon[i], self.polygon[(i + 1) % n]);
            if (a.y > p.y) != (b.y > p.y) {
                let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
                if p.x < x {
                    inside = !inside;
                }
            }
        }
        inside
    }
}

/// The shape of a bisector `|x - s1| + sigma1 = |x - s2| + sigma2` (eq. (1) [LZT §2]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum BisectorKind {
    /// Equal sigmas: the perpendicular bisector of the two images.
    Line,
    /// Different sigmas: a branch of the hyperbola with the images as foci.
    Hyperbola,
}

/// The common boundary of two regions inside the face.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Bisector {
    /// Indices of the two regions.
    pub regions: [usize; 2],
    /// Line or hyperbola branch.
    pub kind: BisectorKind,
    /// Points along the arc, in order.
    pub points: Vec<Point2>,
}

/// The subdivision of one face [LZT Property 4, Fig. 15].
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FaceSubdivision {
    /// The face.
    pub face: FaceId,
    /// Its corners, in the face's order.
    pub corners: [VertexId; 3],
    /// The corners unfolded: the first at the origin, the second on the positive x axis, the
    /// third above it.
    pub layout: [Point2; 3],
    /// The regions with positive area.
    pub regions: Vec<Region>,
    /// The bisector arcs between regions.
    pub bisectors: Vec<Bisector>,
}

/// Which part of the face a wedge's rays reach.
#[derive(Clone, Copy, Debug)]
enum Reach {
    /// The whole face: the pseudo-source is one of its corners.
    Face,
    /// The rays from the image through the segment `[q0, q1]`, beyond it.
    Beyond(Point2, Point2),
    /// The rays from the image to the segment `[q0, q1]`, before it.
    Before(Point2, Point2),
}

/// One image of a pseudo-source with the parts of the face its wedges reach.
struct Image {
    pseudo_source: PseudoSource,
    vertex: Option<VertexId>,
    position: Point2,
    sigma: f64,
    reach: Vec<Reach>,
    /// Where its first wedge starts along the face's boundary: (edge index, position from the
    /// edge's first corner in the face's order).
    first: (usize, f64),
}

/// The length of `a` by `hypot`, which neither overflows nor underflows (unlike
/// [`DVec2::length`]).
fn norm(a: DVec2) -> f64 {
    a.x.hypot(a.y)
}

/// Shoelace area of a polygon (positive when counter-clockwise).
pub fn polygon_area(polygon: &[Point2]) -> f64 {
    let n = polygon.len();
    (0..n)
        .map(|i| polygon[i].perp_dot(polygon[(i + 1) % n]))
        .sum::<f64>()
        / 2.0
}

/// A traced region: its image's index and its polygon.
type Traced = (usize, Vec<Point2>);

type Tol = SubdivisionTolerance;

impl FaceSubdivision {
    /// The face's area.
    pub fn face_area(&self) -> f64 {
        polygon_area(&self.layout)
    }

    /// Whether `p` lies in the face, within `slack` (relative to the face's size).
    pub fn face_contains(&self, p: Point2, slack: f64) -> bool {
        let [a, b, c] = self.layout;
        let area2 = (b - a).perp_dot(c - a);
        let tol = -slack * area2;
        (b - a).perp_dot(p - a) >= tol
            && (c - b).perp_dot(p - b) >= tol
            && (a - c).perp_dot(p - c) >= tol
    }
}

/// The subdivision of `face` induced by the final wedges on its three edges [LZT Property 4].
///
/// # Panics
/// If `face` is not a face of the field's mesh.
pub fn face_subdivision<S: Scalar>(field: &GeodesicField<'_, S>, face: FaceId) -> FaceSubdivision {
    let mesh = field.mesh();
    let corners = mesh.face(face);
    let dist3 = |a: VertexId, b: VertexId| mesh.position(a).distance(mesh.position(b));
    let (l01, l02, l12) = (
        dist3(corners[0], corners[1]),
        dist3(corners[0], corners[2]),
        dist3(corners[1], corners[2]),
    );
    let x2 = (l01 * l01 + l02 * l02 - l12 * l12) / (2.0 * l01);
    let layout = [
        DVec2::ZERO,
        DVec2::new(l01, 0.0),
        DVec2::new(x2, (l02 * l02 - x2 * x2).max(0.0).sqrt()),
    ];
    let scale = l01.max(l02).max(l12);
    let tol = Tol::POINT * scale;
    let corner_of = |v: VertexId| corners.iter().position(|&c| c == v).map(|k| layout[k]);

    let mut images: Vec<Image> = Vec::new();
    for (i, e) in mesh.face_edges(face).into_iter().enumerate() {
        let edge = mesh.edge(e);
        let (p0, p1) = (
            corner_of(edge.vertices[0]).expect("edge of the face"),
            corner_of(edge.vertices[1]).expect("edge of the face"),
        );
        let length = norm(p1 - p0);
        let u = (p1 - p0) / length;
        let opposite = layout[(i + 2) % 3];
        let inward = if u.perp_dot(opposite - p0) > 0.0 {
            u.perp()
        } else {
            -u.perp()
        };
        for w in field.wedges(e) {
            let (x, y) = (w.source_x.to_f64(), w.source_y.to_f64());
            let inside = mesh.side_of(e, face) == Some(w.tau);
            let h = if inside { y } else { -y };
            let mut position = p0 + x * u + h * inward;
            let vertex = match w.pseudo_source {
                PseudoSource::Vertex(v) => Some(v),
                PseudoSource::Source(k) => match field.sources()[k.index()] {
                    super::SurfacePoint::Vertex(v) => Some(v),
                    _ => None,
                },
            };
            let at_corner = layout.iter().position(|&c| norm(c - position) < tol);
            let reach = if let Some(k) = at_corner {
                position = layout[k];
                Reach::Face
            } else if y <= tol {
                continue;
            } else {
                let (q0, q1) = (p0 + w.b0.to_f64() * u, p0 + w.b1.to_f64() * u);
                if inside {
                    Reach::Before(q0, q1)
                } else {
                    Reach::Beyond(q0, q1)
                }
            };
            let sigma = w.sigma.to_f64();
            let start = if edge.vertices[0] == corners[i] {
                w.b0.to_f64()
            } else {
                length - w.b1.to_f64()
            };
            match images.iter_mut().find(|m| {
                m.pseudo_source == w.pseudo_source
                    && norm(m.position - position) < tol
                    && (m.sigma - sigma).abs() < tol
            }) {
                Some(m) => {
                    m.reach.push(reach);
                    if (i, start) < m.first {
                        m.first = (i, start);
                    }
                }
                None => images.push(Image {
                    pseudo_source: w.pseudo_source,
                    vertex,
                    position,
                    sigma,
                    reach: vec![reach],
                    first: (i, start),
                }),
            }
        }
    }

    let mut sub_division = FaceSubdivision {
        face,
        corners,
        layout,
        regions: Vec::new(),
        bisectors: Vec::new(),
    };
    let nearest = |x: Point2| nearest_image(&images, x, tol);
    let mut traced: Vec<Traced> = Vec::new();
    for (k, image) in images.iter().enumerate() {
        for polygon in trace_region(&sub_division, image.position, k, &nearest) {
            traced.push((k, polygon));
        }
    }
    let labels = image_labels(&images, &traced);
    for (k, polygon) in &traced {
        let image = &images[*k];
        sub_division.regions.push(Region {
            label: labels[*k].clone(),
            pseudo_source: image.pseudo_source,
            vertex: image.vertex,
            image: image.position,
            sigma: image.sigma,
            polygon: polygon.clone(),
        });
    }
    sub_division.bisectors = bisectors(&images, &traced, &sub_division, &nearest);
    sub_division
}

/// The image nearest to `x` among those whose wedges reach it (ties to the lower index).
///
/// A tie goes to the smaller sigma: where a pseudo-source was reached straight from another
/// image, the two tie along the line behind it, and the region is the upstream image's.
fn nearest_image(images: &[Image], x: Point2, tol: f64) -> Option<usize> {
    let mut best: Option<(usize, f64)> = None;
    for (k, m) in images.iter().enumerate() {
        if m.reach.iter().any(|r| reaches(*r, m.position, x)) {
            let d = norm(x - m.position) + m.sigma;
            let better = best.is_none_or(|(j, b)| {
                d < b - tol * Tol::DISTANCE_TIE
                    || (d <= b + tol * Tol::DISTANCE_TIE && m.sigma < images[j].sigma)
            });
            if better {
                best = Some((k, d));
            }
        }
    }
    best.map(|(k, _)| k)
}

/// Whether the rays of `reach` from image `s` meet `x`, with an angular slack of
/// [`SubdivisionTolerance::ANGLE`].
fn reaches(reach: Reach, s: Point2, x: Point2) -> bool {
    let (q0, q1, beyond) = match reach {
        Reach::Face => return true,
        Reach::Beyond(q0, q1) => (q0, q1, true),
        Reach::Before(q0, q1) => (q0, q1, false),
    };
    let (a, b, d) = (q0 - s, q1 - s, x - s);
    let turn = a.perp_dot(b).signum();
    let within = turn * a.perp_dot(d) >= -Tol::ANGLE * norm(a) * norm(d)
        && turn * d.perp_dot(b) >= -Tol::ANGLE * norm(b) * norm(d);
    // Positive on the image's side of the segment's line.
    let e = q1 - q0;
    let side = e.perp_dot(x - q0) * e.perp_dot(s - q0).signum();
    let slack = Tol::ANGLE * norm(e) * norm(d);
    within
        && if beyond {
            side <= slack
        } else {
            side >= -slack
        }
}

/// Traces the region of image `k` along rays from `s`: the polygons of its angular runs.
fn trace_region(
    face: &FaceSubdivision,
    s: Point2,
    k: usize,
    nearest: &dyn Fn(Point2) -> Option<usize>,
) -> Vec<Vec<Point2>> {
    let [a, b, c] = face.layout;
    let centre = (a + b + c) / 3.0;
    let base = (centre - s).to_angle();
    let angle_of = |p: Point2| {
        let mut t = (p - s).to_angle() - base;
        while t > std::f64::consts::PI {
            t -= std::f64::consts::TAU;
        }
        while t < -std::f64::consts::PI {
            t += std::f64::consts::TAU;
        }
        t
    };
    let scale = norm(b - a).max(norm(c - a));
    let outside = !face.face_contains(s, Tol::IN_FACE)
        || face
            .layout
            .iter()
            .any(|&q| norm(q - s) < Tol::POINT * scale);
    let (lo, hi) = if outside {
        let angles: Vec<f64> = face
            .layout
            .iter()
            .filter(|&&q| norm(q - s) > Tol::POINT * scale)
            .map(|&q| angle_of(q))
            .collect();
        (
            angles.iter().copied().fold(f64::INFINITY, f64::min),
            angles.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        )
    } else {
        (-std::f64::consts::PI, std::f64::consts::PI)
    };
    let direction = |t: f64| DVec2::from_angle(base + t);
    // The part of the ray at angle t in image k's region: (near, far) parameters. By Property 4
    // it starts where the ray enters the face, if anywhere.
    let run = |t: f64| -> Option<(f64, f64, Point2)> {
        let d = direction(t);
        let (near, tb) = clip_ray(face, s, d)?;
        let inside = |u: f64| nearest(s + u * d) == Some(k);
        let step = (tb - near) / Tol::SAMPLES as f64;
        if !inside(near + Tol::FIRST_SAMPLE * (tb - near)) {
            return None;
        }
        let far = match (1..=Tol::SAMPLES).find(|&i| !inside(near + step * i as f64)) {
            None => tb,
            Some(i) => bisect(near + step * i as f64, near + step * (i - 1) as f64, inside),
        };
        Some((near, far, d))
    };
    let (lo, hi) = (lo + Tol::REACH_MARGIN, hi - Tol::REACH_MARGIN);
    let mut runs: Vec<Vec<f64>> = Vec::new();
    let mut current: Vec<f64> = Vec::new();
    let mut previous: Option<f64> = None;
    for i in 0..=Tol::RAYS {
        let t = lo + (hi - lo) * i as f64 / Tol::RAYS as f64;
        let present = run(t).is_some();
        // The limiting ray itself may be a tie along its whole length (a bisector through the
        // image): trace just inside it.
        let nudge = Tol::RAY_NUDGE * (hi - lo) / Tol::RAYS as f64;
        match (present, previous) {
            (true, None) if i > 0 => {
                let prev_t = lo + (hi - lo) * (i - 1) as f64 / Tol::RAYS as f64;
                current.push(bisect(prev_t, t, |u| run(u).is_some()) + nudge);
                current.push(t);
            }
            (true, _) => current.push(t),
            (false, Some(p)) => {
                current.push(bisect(t, p, |u| run(u).is_some()) - nudge);
                runs.push(std::mem::take(&mut current));
            }
            (false, None) => {}
        }
        previous = present.then_some(t);
    }
    if !current.is_empty() {
        runs.push(current);
    }
    runs.into_iter()
        .filter_map(|angles| {
            let rays: Vec<(f64, f64, Point2)> = angles.iter().filter_map(|&t| run(t)).collect();
            if rays.len() < 2 {
                return None;
            }
            let mut polygon: Vec<Point2> = rays.iter().map(|&(n, _, d)| s + n * d).collect();
            polygon.extend(rays.iter().rev().map(|&(_, f, d)| s + f * d));
            dedup(&mut polygon, Tol::DEDUP * scale);
            if polygon_area(&polygon) < 0.0 {
                polygon.reverse();
            }
            (polygon.len() >= 3 && polygon_area(&polygon) > Tol::AREA * scale * scale)
                .then_some(polygon)
        })
        .collect()
}

fn dedup(polygon: &mut Vec<Point2>, tol: f64) {
    polygon.dedup_by(|a, b| norm(*a - *b) <= tol);
    while polygon.len() > 1 && norm(polygon[0] - polygon[polygon.len() - 1]) <= tol {
        polygon.pop();
    }
}

/// The last parameter in `[good, bad]` where `keep` holds, by bisection (`keep(good)` holds,
/// `keep(bad)` does not).
fn bisect(mut bad: f64, mut good: f64, keep: impl Fn(f64) -> bool) -> f64 {
    for _ in 0..Tol::BISECTIONS {
        let mid = 0.5 * (bad + good);
        if keep(mid) {
            good = mid;
        } else {
            bad = mid;
        }
    }
    good
}

/// The parameters where the ray `s + t d` (t >= 0) enters and leaves the face, if it meets it.
fn clip_ray(face: &FaceSubdivision, s: Point2, d: Point2) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = (0.0f64, f64::INFINITY);
    let [a, b, c] = face.layout;
    for (p, q) in [(a, b), (b, c), (c, a)] {
        // Inside: (q - p) perp-dot (x - p) >= 0, linear in t.
        let e = q - p;
        let at0 = e.perp_dot(s - p);
        let slope = e.perp_dot(d);
        if slope.abs() < Tol::PARALLEL {
            if at0 < 0.0 {
                return None;
            }
        } else if slope > 0.0 {
            lo = lo.max(-at0 / slope);
        } else {
            hi = hi.min(-at0 / slope);
        }
    }
    (hi > lo).then_some((lo, hi))
}

/// Labels in the paper's bracket notation: a vertex with several images that have regions gets
/// them numbered `v(1), v(2), ...` in order of first appearance along the face's edges, taken in
/// the face's order; a vertex with one image gets its index alone [LZT Fig. 15].
fn image_labels(images: &[Image], traced: &[Traced]) -> Vec<String> {
    let present = |k: usize| traced.iter().any(|t| t.0 == k);
    images
        .iter()
        .enumerate()
        .map(|(k, m)| {
            let base = match (m.vertex, m.pseudo_source) {
                (Some(v), _) | (None, PseudoSource::Vertex(v)) => v.0.to_string(),
                (None, PseudoSource::Source(s)) => format!("s{s}"),
            };
            let mut same: Vec<usize> = (0..images.len())
                .filter(|&j| {
                    present(j)
                        && images[j].vertex == m.vertex
                        && images[j].pseudo_source == m.pseudo_source
                })
                .collect();
            if same.len() <= 1 {
                return base;
            }
            same.sort_by(|&i, &j| {
                let (a, b) = (images[i].first, images[j].first);
                a.0.cmp(&b.0).then(a.1.total_cmp(&b.1))
            });
            match same.iter().position(|&j| j == k) {
                Some(rank) => format!("{base}({})", rank + 1),
                None => base,
            }
        })
        .collect()
}

/// The bisector arcs: runs of a region's boundary along which the same other region lies just
/// outside. A bisector is a line when the sigmas are equal or differ by the images' distance
/// (the degenerate hyperbola behind a pseudo-source reached straight from the other image).
fn bisectors(
    images: &[Image],
    traced: &[Traced],
    face: &FaceSubdivision,
    nearest: &dyn Fn(Point2) -> Option<usize>,
) -> Vec<Bisector> {
    let [a, b, c] = face.layout;
    let scale = norm(b - a).max(norm(c - a));
    let probe = Tol::PROBE * scale;
    let mut out: Vec<Bisector> = Vec::new();
    for (r, (k, polygon)) in traced.iter().enumerate() {
        let n = polygon.len();
        // The region just outside each boundary edge (the polygon is counter-clockwise).
        let beyond: Vec<Option<usize>> = (0..n)
            .map(|i| {
                let (p, q) = (polygon[i], polygon[(i + 1) % n]);
                let e = q - p;
                let l = norm(e);
                if l == 0.0 {
                    return None;
                }
                // Right of the edge, outside the counter-clockwise polygon.
                let x = 0.5 * (p + q) - probe * e.perp() / l;
                face.face_contains(x, 0.0)
                    .then(|| nearest(x))
                    .flatten()
                    .filter(|j| j != k)
                    .and_then(|j| traced.iter().position(|t| t.0 == j))
            })
            .collect();
        // Start the walk where the neighbour changes, so that no arc wraps around.
        let start = (0..n)
            .find(|&i| beyond[i] != beyond[(i + n - 1) % n])
            .unwrap_or(0);
        let mut i = 0;
        while i < n {
            let first = (start + i) % n;
            let Some(j) = beyond[first] else {
                i += 1;
                continue;
            };
            let mut points = vec![polygon[first]];
            while i < n && beyond[(start + i) % n] == Some(j) {
                points.push(polygon[(start + i + 1) % n]);
                i += 1;
            }
            let (mi, mj) = (&images[*k], &images[traced[j].0]);
            let gap = (mi.sigma - mj.sigma).abs();
            let apart = norm(mi.position - mj.position);
            let kind = if gap <= Tol::POINT * scale || (gap - apart).abs() <= Tol::POINT * scale {
                BisectorKind::Line
            } else {
                BisectorKind::Hyperbola
            };
            let pair = [r.min(j), r.max(j)];
            match out.iter_mut().find(|b| b.regions == pair) {
                Some(b) if b.points.len() >= points.len() => {}
                Some(b) => b.points = points,
                None => out.push(Bisector {
                    regions: pair,
                    kind,
                    points,
                }),
            }
        }
    }
    out
}
