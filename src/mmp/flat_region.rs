//! Flat regions: maximal sets of faces, joined across edges, that lie exactly in one plane with
//! one orientation, each with one planar frame of its own.
//!
//! Inside a flat region, unfolding is the identity, and one image of a pseudo-source reaches an
//! edge along many sequences of faces (around every vertex of the region, from either side).
//! Carried from frame to frame face by face, each sequence builds its own expression of the same
//! point, and an exact backend must then prove equal what the algorithm made equal: on CAD
//! meshes, thousands of times, mostly beyond its reach. Carried in the region's frame instead,
//! the image is one expression wherever it goes in the region, and so are the distances it
//! gives and the vertices it meets, and their equality is proved by structure.
//!
//! Only number types that keep values ([`Scalar::Kept`]) use regions: floats lose nothing to
//! the face-by-face expressions, and would lose accuracy in a frame far from the point at hand.

use super::crease::{Crease, EdgeInRegion};
use super::planar::{Apex, Planar};
use crate::mesh::{EdgeId, FaceId, TriMesh, VertexId};
use crate::scalar::{Scalar, Sign};
use std::collections::HashMap;
use std::sync::Arc;

/// The first edge (by id) between two regions, its faces in the region left and in the region
/// entered, and the unfolding across it.
type CreaseLine<S> = (EdgeId, [FaceId; 2], Crease<S>);

/// A point in a region's frame.
pub(crate) type RegionPoint<S> = [S; 2];

/// A pseudo-source's image in the frame of the flat region whose faces it lights.
#[derive(Clone, Debug)]
pub(crate) struct RegionImage<S> {
    /// The region.
    pub(crate) region: u32,
    /// The image in the region's frame.
    pub(crate) point: RegionPoint<S>,
    /// The image it was carried from across a crease, and the edge of the crease it crossed
    /// (see [`FlatRegions::distance`]).
    pub(crate) carried: Option<Arc<(EdgeId, RegionImage<S>)>>,
}

impl<S> RegionImage<S> {
    /// An image first placed in `region`'s frame.
    pub(crate) fn new(region: u32, point: RegionPoint<S>) -> Self {
        RegionImage {
            region,
            point,
            carried: None,
        }
    }
}

/// The flat regions of a mesh and the frame of each.
#[derive(Clone, Debug)]
pub(crate) struct FlatRegions<S> {
    /// The region of each face that shares its plane with a neighbour.
    face_region: Vec<Option<u32>>,
    /// The corners of each region's faces in the region's frame.
    corners: HashMap<(u32, VertexId), RegionPoint<S>>,
    /// Whether each edge's frame runs from its `vertices[1]` (see `unfold.rs`).
    reversed: Vec<bool>,
    /// The unfolding across each edge between two regions, by the edge and the region left,
    /// where it is the one built for the pair of regions (see `crease.rs`).
    creases: HashMap<(EdgeId, u32), Crease<S>>,
}

fn sub<S: Scalar>(p: &[S; 3], q: &[S; 3]) -> [S; 3] {
    [0, 1, 2].map(|i| p[i].clone() - &q[i])
}

fn dot<S: Scalar>(a: &[S; 3], b: &[S; 3]) -> S {
    a[0].clone() * &b[0] + a[1].clone() * &b[1] + a[2].clone() * &b[2]
}

fn cross<S: Scalar>(a: &[S; 3], b: &[S; 3]) -> [S; 3] {
    [
        a[1].clone() * &b[2] - a[2].clone() * &b[1],
        a[2].clone() * &b[0] - a[0].clone() * &b[2],
        a[0].clone() * &b[1] - a[1].clone() * &b[0],
    ]
}

/// Whether face `f`, read in its corners' order, runs along its edge `e` from the edge's first
/// vertex to its second.
fn runs_from_first_end(mesh: &TriMesh, e: EdgeId, f: FaceId) -> bool {
    let [v0, v1] = mesh.edge(e).vertices;
    let corners = mesh.face(f);
    let at = |v: VertexId| corners.iter().position(|&c| c == v).expect("a corner");
    (at(v0) + 1) % 3 == at(v1)
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

impl<S: Scalar> FlatRegions<S> {
    /// The regions of `mesh`, whose vertices are at `points` (scaled coordinates, exact in
    /// `S`). Two faces on a manifold edge join when the edge's four corners are coplanar and
    /// the faces' normals point the same way, both decided exactly on the input coordinates
    /// (polynomials in them, without square roots).
    pub(crate) fn new(mesh: &TriMesh, points: &[[S; 3]], reversed: Vec<bool>) -> Self {
        let normal = |f: FaceId| {
            let [a, b, c] = mesh.face(f).map(|v| &points[v.index()]);
            cross(&sub(b, a), &sub(c, a))
        };
        let mut parent: Vec<usize> = (0..mesh.face_count()).collect();
        for e in 0..mesh.edge_count() {
            let faces: Vec<FaceId> = mesh.edge_faces(EdgeId(e as u32)).collect();
            let &[f, g] = faces.as_slice() else { continue };
            // Normals pointing the same way put the faces on opposite sides of the edge only
            // when they run along it in opposite directions; running the same way (an edge
            // of inconsistent orientation), they lie folded onto each other, and the plane's
            // frame is no unfolding of the pair.
            if runs_from_first_end(mesh, EdgeId(e as u32), f)
                == runs_from_first_end(mesh, EdgeId(e as u32), g)
            {
                continue;
            }
            let (nf, ng) = (normal(f), normal(g));
            let parallel = cross(&nf, &ng).iter().all(|c| c.sign() == Sign::Zero);
            if parallel && dot(&nf, &ng).sign() == Sign::Positive {
                let (rf, rg) = (find(&mut parent, f.index()), find(&mut parent, g.index()));
                parent[rf] = rg;
            }
        }
        let mut members: HashMap<usize, Vec<FaceId>> = HashMap::new();
        for f in 0..mesh.face_count() {
            let root = find(&mut parent, f);
            members.entry(root).or_default().push(FaceId(f as u32));
        }
        let mut face_region = vec![None; mesh.face_count()];
        let mut corners = HashMap::new();
        let mut regions: Vec<Vec<FaceId>> = members.into_values().filter(|m| m.len() > 1).collect();
        regions.sort_by_key(|m| m[0]);
        for (r, faces) in regions.iter().enumerate() {
            for &f in faces {
                face_region[f.index()] = Some(r as u32);
            }
        }
        // Whether an edge joins a face of region `r` to a face of another region.
        let on_crease = |e: EdgeId, r: u32| {
            let mut sides = mesh.edge_faces(e).map(|f| face_region[f.index()]);
            match (sides.next(), sides.next(), sides.next()) {
                (Some(Some(a)), Some(Some(b)), None) => a != b && (a == r || b == r),
                _ => false,
            }
        };
        for (r, faces) in regions.iter().enumerate() {
            let r = r as u32;
            // The frame: x along the region's first edge (by id) on a crease, from its first
            // end, else along the first face's first edge; y turned from it about the face's
            // normal (so the faces run counterclockwise). On a band of strips between parallel
            // creases (an extrusion's walls, a cylinder's columns) every x axis then runs along
            // the creases: unfolding across one is a reflection and a shift by rational data,
            // and an image carried along the band keeps a coordinate that is a sum of the
            // strips' widths, whose square has a root in the tower.
            let crease = faces
                .iter()
                .flat_map(|&f| mesh.face_edges(f))
                .filter(|&e| on_crease(e, r))
                .min();
            let [a, b] = match crease {
                Some(e) => mesh.edge(e).vertices.map(|v| &points[v.index()]),
                None => {
                    let [a, b, _] = mesh.face(faces[0]).map(|v| &points[v.index()]);
                    [a, b]
                }
            };
            let (origin, u) = (a.clone(), sub(b, a));
            let w = cross(&normal(faces[0]), &u);
            let (u_norm, w_norm) = (dot(&u, &u).sqrt(), dot(&w, &w).sqrt());
            for &f in faces {
                for v in mesh.face(f) {
                    corners.entry((r, v)).or_insert_with(|| {
                        let d = sub(&points[v.index()], &origin);
                        [dot(&d, &u) / &u_norm, dot(&d, &w) / &w_norm]
                    });
                }
            }
        }
        let mut regions = FlatRegions {
            face_region,
            corners,
            reversed,
            creases: HashMap::new(),
        };
        regions.creases = regions.creases(mesh, points);
        regions
    }

    /// The unfolding across each edge between two regions that lies on the line of the first
    /// such edge of the pair (by id) with the faces on the same sides of it: there, one map
    /// built from that first edge (see `crease.rs`). Decided exactly on the input coordinates.
    fn creases(&self, mesh: &TriMesh, points: &[[S; 3]]) -> HashMap<(EdgeId, u32), Crease<S>> {
        let point = |v: VertexId| &points[v.index()];
        let apex = |e: EdgeId, f: FaceId| {
            let ends = mesh.edge(e).vertices;
            let corner = mesh.face(f).into_iter().find(|v| !ends.contains(v));
            point(corner.expect("a face has a corner off each of its edges"))
        };
        let mut first: HashMap<(u32, u32), CreaseLine<S>> = HashMap::new();
        let mut creases = HashMap::new();
        for e in 0..mesh.edge_count() {
            let e = EdgeId(e as u32);
            let faces: Vec<FaceId> = mesh.edge_faces(e).collect();
            let &[f, g] = faces.as_slice() else { continue };
            let (Some(rf), Some(rg)) = (self.region(f), self.region(g)) else {
                continue;
            };
            if rf == rg {
                continue;
            }
            for (left, entered, pair) in [(f, g, (rf, rg)), (g, f, (rg, rf))] {
                let (e0, [l0, n0], crease) = first.entry(pair).or_insert_with(|| {
                    let [a, b] = mesh.edge(e).vertices.map(point);
                    let d = sub(b, a);
                    let crease = Crease::new(
                        self.edge_in(mesh, e, left),
                        self.edge_in(mesh, e, entered),
                        &dot(&d, &d),
                    );
                    (e, [left, entered], crease)
                });
                let [a, b] = mesh.edge(*e0).vertices.map(point);
                let d = sub(b, a);
                let on_line =
                    |p: &[S; 3]| cross(&d, &sub(p, a)).iter().all(|c| c.sign() == Sign::Zero);
                let same_side = |f0: FaceId, f1: FaceId| {
                    let (n0, n1) = (
                        cross(&d, &sub(apex(*e0, f0), a)),
                        cross(&d, &sub(apex(e, f1), a)),
                    );
                    dot(&n0, &n1).sign() == Sign::Positive
                };
                let [p, q] = mesh.edge(e).vertices.map(point);
                if *e0 == e
                    || (on_line(p) && on_line(q) && same_side(*l0, left) && same_side(*n0, entered))
                {
                    creases.insert((e, pair.0), crease.clone());
                }
            }
        }
        creases
    }

    /// Whether the edge `e`, leaving region `left`, is unfolded by the one map built for its
    /// pair of regions (it lies on the line of the pair's first edge, faces on the same sides).
    pub(crate) fn unfolds_along_crease_line(&self, e: EdgeId, left: u32) -> bool {
        self.creases.contains_key(&(e, left))
    }

    /// The region of a face, if it has one.
    pub(crate) fn region(&self, f: FaceId) -> Option<u32> {
        self.face_region[f.index()]
    }

    /// A corner of a region's faces in the region's frame.
    pub(crate) fn corner(&self, region: u32, v: VertexId) -> &RegionPoint<S> {
        &self.corners[&(region, v)]
    }

    /// The frame of edge `e` seen from its face `f` (in a region): the region points of its
    /// ends in the order of the edge's frame, and `+1` or `-1` for the side of its line `f`
    /// lies on (`f` runs counterclockwise in the region's frame, so it lies left of the edge
    /// when the edge runs the way of `f`'s corners).
    fn edge_in(&self, mesh: &TriMesh, e: EdgeId, f: FaceId) -> EdgeInRegion<'_, S> {
        let region = self.face_region[f.index()].expect("a face of a region");
        let [first, second] = mesh.edge(e).vertices;
        let reversed = self.reversed[e.index()];
        let [v0, v1] = if reversed {
            [second, first]
        } else {
            [first, second]
        };
        let left = runs_from_first_end(mesh, e, f) != reversed;
        let (p0, p1) = (self.corner(region, v0), self.corner(region, v1));
        (p0, [p1[0].clone() - &p0[0], p1[1].clone() - &p0[1]], left)
    }

    /// The apex of face `f` (in a region) in the frame of its edge `e` (of length `length`),
    /// with its offset from each end of the edge, as [`Apex`] keeps it.
    pub(crate) fn apex(
        &self,
        mesh: &TriMesh,
        (e, f): (EdgeId, FaceId),
        length: &S,
        a: VertexId,
    ) -> Apex<S> {
        let region = self.face_region[f.index()].expect("a face of a region");
        let p = self.corner(region, a);
        let at = self.to_edge(mesh, (e, f), length, p);
        let (p0, d, _) = self.edge_in(mesh, e, f);
        let p1 = [p0[0].clone() + &d[0], p0[1].clone() + &d[1]];
        let back = [p1[0].clone() - &p[0], p1[1].clone() - &p[1]];
        Apex {
            x: at.x,
            far_x: (d[0].clone() * &back[0] + d[1].clone() * &back[1]) / length,
            h: at.y,
        }
    }

    /// A region point in the frame of edge `e` (of length `length`) as seen from its face `f`:
    /// `y >= 0` on `f`'s side.
    pub(crate) fn to_edge(
        &self,
        mesh: &TriMesh,
        (e, f): (EdgeId, FaceId),
        length: &S,
        p: &RegionPoint<S>,
    ) -> Planar<S> {
        let (p0, d, left) = self.edge_in(mesh, e, f);
        let q = [p[0].clone() - &p0[0], p[1].clone() - &p0[1]];
        let along = d[0].clone() * &q[0] + d[1].clone() * &q[1];
        let across = d[0].clone() * &q[1] - d[1].clone() * &q[0];
        Planar {
            x: along / length,
            y: if left { across } else { -across } / length,
        }
    }

    /// The image of a point entering face `f` across its edge `e` (of length `length`): `at`
    /// in the edge's frame, `at.y` measured on the side away from `f` (where the
    /// pseudo-sources of the wedges entering `f` across `e` lie), and `kept` the image in the
    /// frame of the region it comes from, if it does. The same point wherever it comes from
    /// in the region it is in, or across the line that region shares with `f`'s (see
    /// `crease.rs`), gets one expression.
    pub(crate) fn image_entering(
        &self,
        mesh: &TriMesh,
        (e, f): (EdgeId, FaceId),
        length: &S,
        at: &Planar<S>,
        kept: Option<&RegionImage<S>>,
    ) -> RegionImage<S> {
        let region = self.face_region[f.index()].expect("a face of a region");
        let crease = kept.and_then(|image| Some((image, self.creases.get(&(e, image.region))?)));
        match (kept, crease) {
            (Some(image), _) if image.region == region => image.clone(),
            (_, Some((image, crease))) => RegionImage {
                region,
                point: crease.apply(&image.point),
                carried: Some(Arc::new((e, image.clone()))),
            },
            _ => RegionImage::new(region, self.entering(mesh, (e, f), length, at)),
        }
    }

    /// The distance from an image to a corner `v` of its region. A crease fixes its line point
    /// by point, so where the image was carried across creases whose lines pass through `v`,
    /// the distance is the same in the regions it came from; it is measured in the first of
    /// them. The images of one point that reach `v` from either side of a crease through it
    /// (around a vertex on a CAD model's feature line) then give it one expression.
    pub(crate) fn distance(&self, mesh: &TriMesh, image: &RegionImage<S>, v: VertexId) -> S {
        let mut at = image;
        while let Some(carried) = &at.carried {
            let (e, before) = &**carried;
            let [a, b] = mesh.edge(*e).vertices;
            if !(self.corners.contains_key(&(before.region, v)) && mesh.are_collinear([a, b, v])) {
                break;
            }
            at = before;
        }
        let (p, q) = (&at.point, self.corner(at.region, v));
        let (dx, dy) = (q[0].clone() - &p[0], q[1].clone() - &p[1]);
        (dx.clone() * dx + dy.clone() * dy).sqrt()
    }

    /// The region point of a point in the frame of edge `e` (of length `length`), `at.y`
    /// measured on the side away from the region's face `f`.
    fn entering(
        &self,
        mesh: &TriMesh,
        (e, f): (EdgeId, FaceId),
        length: &S,
        at: &Planar<S>,
    ) -> RegionPoint<S> {
        let (p0, d, left) = self.edge_in(mesh, e, f);
        // Towards f is +perp(d) when f lies left; the point lies the other way.
        let away = if left { -at.y.clone() } else { at.y.clone() };
        [
            p0[0].clone() + &((at.x.clone() * &d[0] - away.clone() * &d[1]) / length),
            p0[1].clone() + &((at.x.clone() * &d[1] + away * &d[0]) / length),
        ]
    }
}
