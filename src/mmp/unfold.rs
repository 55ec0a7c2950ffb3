//! Unfolding: the planar frames of edges and the maps between them [SSK+05 §3].
//!
//! Each edge has a frame: x runs along the edge from its first end, y is the distance from the
//! edge's line. The first end is the edge's `vertices[0]`, or, for number types that round
//! ([`Scalar::frames_from_nearer_end`]) and an edge more than `WIDE_SPAN` times longer than its
//! nearer end's distance from the sources, that end: positions are then known to ulps of their
//! offset from the end the short geodesics pass, not to ulps of the edge's length. A face on one side of an edge is laid out with its apex at `(apex_x, -apex_h)`:
//! below the line, as seen by a wedge whose pseudo-source is above it. The maps here carry a
//! point from an edge's frame into the frames of the face's two other edges.

use super::flat_region::FlatRegions;
use super::planar::{Apex, Planar};
use super::source::SurfacePoint;
use super::wedge::{PseudoSource, Wedge};
use crate::mesh::{
    normalizing_power, EdgeId, FaceId, Side, TriMesh, ValidationReport, VertexId, Wing,
};
use crate::scalar::{Scalar, Sign};
use glam::DVec3;
use std::cmp::Ordering;

/// Per-run geometry in the backend's number type: edge lengths and, for each side of each edge,
/// the apex of the face there. Computed once per propagation so that every wedge reuses the same
/// values (for exact backends: the same radicals).
///
/// Coordinates are multiplied by the mesh's [`unit_scale`](TriMesh::unit_scale) (a power of
/// two, exactly), so every length here is in scaled units; [`Unfolding::to_model`] and
/// [`Unfolding::scaled_from_model`] convert distances to and from the model's units.
#[derive(Clone, Debug)]
pub(crate) struct Unfolding<S> {
    edge_length: Vec<S>,
    /// Whether the edge has length zero (its ends coincide): no wedge lives on it, and no
    /// point is laid out in its frame.
    zero_length: Vec<bool>,
    /// Whether a vertex ends an edge of length zero (has a twin at its place).
    has_twin: Vec<bool>,
    /// The face on each side of each edge as a wedge crossing it reads it, at the side's
    /// [`TriMesh::side_slot`].
    sides: Vec<Option<FaceSide<S>>>,
    /// Whether the edge's frame starts at its `vertices[1]` (see the module docs).
    reversed: Vec<bool>,
    /// The flat regions, for number types that keep values (see `flat_region.rs`).
    flat: Option<FlatRegions<S>>,
    /// The mesh's unit scale.
    scale: f64,
}

fn sub<S: Scalar>(p: &[S; 3], q: &[S; 3]) -> [S; 3] {
    [0, 1, 2].map(|i| p[i].clone() - &q[i])
}

fn dot<S: Scalar>(a: &[S; 3], b: &[S; 3]) -> S {
    a[0].clone() * &b[0] + a[1].clone() * &b[1] + a[2].clone() * &b[2]
}

/// The frame of an edge: its start and its direction, the edge vector multiplied by a power
/// of two that brings its largest component near 1 (exactly), so that neither its squared
/// length nor its products with other vectors leave the range of `f64`, however short the
/// edge is against the model.
struct EdgeFrame<S> {
    origin: [S; 3],
    direction: [S; 3],
    /// `|direction|`.
    norm: S,
    /// The powers of two the edge vector was multiplied by (two where their product leaves
    /// `f64`'s range).
    power: [f64; 2],
}

impl<S: Scalar> EdgeFrame<S> {
    /// The frame of the edge from `v0` to `v1`; `None` if they coincide.
    fn new(mesh: &TriMesh, v0: VertexId, v1: VertexId) -> Option<Self> {
        let scale = mesh.unit_scale();
        let (p0, p1) = (mesh.position(v0), mesh.position(v1));
        if p0 == p1 {
            return None;
        }
        let largest = (0..3).fold(0.0f64, |m, i| m.max((p1[i] * scale - p0[i] * scale).abs()));
        // An edge whose scaled length is below `f64`'s normal range: only a number type that
        // measures such edges gets here (the others refuse the mesh), and its factor is taken
        // in two powers of two, from the edge's length in the model's units; in one, it would
        // overflow (an edge of 1e-113 in a model of 1e211).
        let power = if largest >= f64::MIN_POSITIVE {
            [normalizing_power(largest), 1.0]
        } else if S::measures_below_float_resolution() {
            let model = (0..3).fold(0.0f64, |m, i| m.max((p1[i] - p0[i]).abs()));
            [normalizing_power(model), scale.recip()]
        } else if largest == 0.0 {
            return None;
        } else {
            [normalizing_power(largest), 1.0]
        };
        let origin = vertex_point::<S>(mesh, v0);
        let factor = S::from_f64(power[0]) * &S::from_f64(power[1]);
        let direction = sub(&vertex_point::<S>(mesh, v1), &origin).map(|c: S| c * &factor);
        let norm = dot(&direction, &direction).sqrt();
        Some(EdgeFrame {
            origin,
            direction,
            norm,
            power,
        })
    }

    /// The edge's length (scaled coordinates).
    fn length(&self) -> S {
        self.norm.clone()
            * &S::from_f64(self.power[0].recip())
            * &S::from_f64(self.power[1].recip())
    }

    /// The coordinates of `p` in the frame: `x` along the edge, `y >= 0` its distance from
    /// the edge's line.
    fn planar(&self, p: &[S; 3]) -> Planar<S> {
        let (u, w) = (&self.direction, sub(p, &self.origin));
        let cross = [
            u[1].clone() * &w[2] - u[2].clone() * &w[1],
            u[2].clone() * &w[0] - u[0].clone() * &w[2],
            u[0].clone() * &w[1] - u[1].clone() * &w[0],
        ];
        Planar {
            x: dot(u, &w) / &self.norm,
            y: dot(&cross, &cross).sqrt() / &self.norm,
        }
    }
}

/// The apex `a` of a face in the frame of its edge, given the edge's frames from each end
/// (`frames[i]` starts at `ends[i]`).
fn apex<S: Scalar>(
    mesh: &TriMesh,
    frames: [&EdgeFrame<S>; 2],
    ends: [VertexId; 2],
    a: VertexId,
) -> Apex<S> {
    let [v0, v1] = ends;
    let p = vertex_point::<S>(mesh, a);
    let (near, far) = (frames[0].planar(&p), frames[1].planar(&p));
    // Which end is nearer is a choice of formula, not a decision: both heights are exact
    // in exact arithmetic.
    let span = |v: VertexId| {
        let (q, r) = (mesh.position(v), mesh.position(a));
        (0..3).fold(0.0f64, |m, i| m.max((q[i] - r[i]).abs()))
    };
    let h = if span(v0) <= span(v1) { near.y } else { far.y };
    Apex {
        x: near.x,
        far_x: far.x,
        h,
    }
}

/// The face on one side of an edge, as the propagation of a wedge across it reads it
/// ([`FaceLayout`]): everything in one record, where it was read from a dozen arrays indexed by
/// the edge and by the face's two other edges (a cache miss each, at every wedge). Not copied
/// here: the lengths of the face's other edges (read where a point is carried into an edge, not
/// at every wedge) and the face itself (in the edge's record, which the propagation reads
/// anyway). 40 bytes in the `f64` engine, for the largest table of a run (at 48 bytes, with the
/// face and a byte per flag, a third of the heap at its peak on stanford_bunny and fandisk).
#[derive(Clone, Debug)]
pub(crate) struct FaceSide<S> {
    /// The face's corner opposite the edge.
    apex_vertex: VertexId,
    /// The face's other edges, in the order of the edge's frame ([`Wing::near`], [`Wing::far`]).
    near: EdgeId,
    far: EdgeId,
    /// The apex in the edge's frame.
    apex: Apex<S>,
    flags: SideFlags,
}

/// The yes-or-no facts of a [`FaceSide`], a bit each: see [`FaceLayout::near_reversed`] and the
/// three fields after it; whether the near (far) edge has length zero; whether the edge has
/// more than two sides (more than two faces share it). One bit is always set, so that
/// `Option<FaceSide>` needs no room of its own for `None`.
#[derive(Clone, Copy, Debug)]
struct SideFlags(std::num::NonZeroU8);

impl SideFlags {
    const NEAR_REVERSED: u8 = 1;
    const FAR_REVERSED: u8 = 1 << 1;
    const NEAR_FROM_APEX: u8 = 1 << 2;
    const FAR_FROM_END: u8 = 1 << 3;
    const NEAR_ZERO_LENGTH: u8 = 1 << 4;
    const FAR_ZERO_LENGTH: u8 = 1 << 5;
    const MORE_SIDES: u8 = 1 << 6;
    /// No flag set: only the bit that is always set.
    const NONE: SideFlags = SideFlags(std::num::NonZeroU8::new(1 << 7).unwrap());

    /// These flags with `flag` set to `on`.
    fn with(self, flag: u8, on: bool) -> Self {
        SideFlags(match on {
            true => self.0 | flag,
            false => std::num::NonZeroU8::new(self.0.get() & !flag).expect("the bit always set"),
        })
    }

    #[inline]
    fn has(self, flag: u8) -> bool {
        self.0.get() & flag != 0
    }
}

/// The ends of `e` in the order of its frame.
#[inline]
fn frame_ends(mesh: &TriMesh, reversed: &[bool], e: EdgeId) -> [VertexId; 2] {
    let [v0, v1] = mesh.edge(e).vertices;
    if reversed[e.index()] {
        [v1, v0]
    } else {
        [v0, v1]
    }
}

/// The wing on `side` of `e` in the order of its frame.
#[inline]
fn frame_wing(mesh: &TriMesh, reversed: &[bool], e: EdgeId, side: Side) -> Option<Wing> {
    let wing = mesh.wing(e, side)?;
    Some(if reversed[e.index()] {
        Wing {
            near: wing.far,
            far: wing.near,
            ..wing
        }
    } else {
        wing
    })
}

/// The fractions `[0, 1]` of an edge's two ends along a hit parameter, `[1, 0]` where the
/// parameter runs from the other end.
fn end_fractions<S: Scalar>(reversed: bool) -> [S; 2] {
    let (zero, one) = (S::zero(), S::from_f64(1.0));
    if reversed {
        [one, zero]
    } else {
        [zero, one]
    }
}

/// A vertex's position in scaled coordinates, in the backend's number type.
pub(crate) fn vertex_point<S: Scalar>(mesh: &TriMesh, v: VertexId) -> [S; 3] {
    let scale = S::from_f64(mesh.unit_scale());
    mesh.position(v).to_array().map(|c| S::from_f64(c) * &scale)
}

/// For each edge, whether it is longer than [`ValidationReport::WIDE_SPAN`] times its nearer
/// end's distance from the sources (in space): ulps of its length would then exceed 1e-12 of
/// the distances near that end, so its frame starts there. Returns, per edge, whether that
/// end is its `vertices[1]` (the frame is reversed) and whether the edge is that long.
fn frames_near_sources(mesh: &TriMesh, sources: &[SurfacePoint]) -> (Vec<bool>, Vec<bool>) {
    // In scaled coordinates, where squared distances neither overflow nor underflow.
    let scale = mesh.unit_scale();
    let from: Vec<_> = sources.iter().map(|p| p.position(mesh) * scale).collect();
    let nearest = |v: VertexId| {
        let q = mesh.position(v) * scale;
        from.iter()
            .map(|p| p.distance_squared(q))
            .fold(f64::INFINITY, f64::min)
    };
    let near: Vec<f64> = (0..mesh.vertex_count())
        .map(|v| nearest(VertexId(v as u32)))
        .collect();
    let span = ValidationReport::WIDE_SPAN;
    mesh.edges()
        .iter()
        .map(|e| {
            let [d0, d1] = e.vertices.map(|v| near[v.index()]);
            let length = (mesh.position(e.vertices[1]) - mesh.position(e.vertices[0])) * scale;
            let long = length.length_squared() > span * span * d0.min(d1);
            (long && d1 < d0, long)
        })
        .unzip()
}

/// For each edge, whether its frame starts at its `vertices[1]`: at the end whose position,
/// seen from the centre of the mesh's bounding box, has the smaller absolute coordinates
/// (sorted, compared in turn). A mirror symmetry of the mesh in a coordinate plane through
/// that centre, or a swap of two axes, keeps these keys, so the frames of an edge and of its
/// mirror image start at mirror-image ends, and the constructions of a wedge and of its mirror
/// image are one expression (number types that keep values see their ties by structure). An
/// edge whose ends have equal keys, one the other's mirror image, keeps its `vertices[0]`.
fn symmetric_frames(mesh: &TriMesh) -> Vec<bool> {
    let (lo, hi) = mesh
        .positions()
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
    // Rounded alike for mirror-image positions: round to nearest is symmetric.
    let centre = lo * 0.5 + hi * 0.5;
    let key = |v: VertexId| {
        let mut k = (mesh.position(v) - centre).abs().to_array();
        k.sort_by(f64::total_cmp);
        k
    };
    mesh.edges()
        .iter()
        .map(|e| {
            let [k0, k1] = e.vertices.map(key);
            k1.iter()
                .zip(&k0)
                .map(|(a, b)| a.total_cmp(b))
                .find(|o| o.is_ne())
                == Some(Ordering::Less)
        })
        .collect()
}

impl<S: Scalar> Unfolding<S> {
    /// The unfolding of `mesh` for a propagation from `sources`.
    pub(crate) fn new(mesh: &TriMesh, sources: &[SurfacePoint]) -> Self {
        let edge_count = mesh.edge_count();
        let (reversed, anchored) = if S::frames_from_nearer_end() {
            frames_near_sources(mesh, sources)
        } else {
            (symmetric_frames(mesh), vec![false; edge_count])
        };
        let mut edge_length = Vec::with_capacity(edge_count);
        let mut zero_length = Vec::with_capacity(edge_count);
        let mut sides: Vec<Option<FaceSide<S>>> = vec![None; mesh.side_slot_count()];
        let mut has_twin = vec![false; mesh.vertex_count()];
        let flat = S::kept(&S::keep(|| {
            let points: Vec<[S; 3]> = (0..mesh.vertex_count())
                .map(|v| vertex_point(mesh, VertexId(v as u32)))
                .collect();
            FlatRegions::new(mesh, &points, reversed.clone())
        }));
        // Whether the points of every face's far edge are computed from its far end, as the
        // mirror image of the near edge's ([`FaceLayout::far_from_end`]): for number types
        // that keep values.
        let mirrored_far = flat.is_some();
        for i in 0..edge_count {
            let e = EdgeId(i as u32);
            let ends = frame_ends(mesh, &reversed, e);
            let frame = EdgeFrame::<S>::new(mesh, ends[0], ends[1]);
            if frame.is_none() {
                for v in ends {
                    has_twin[v.index()] = true;
                }
            }
            edge_length.push(frame.as_ref().map_or_else(S::zero, EdgeFrame::length));
            zero_length.push(frame.is_none());
            let Some(frame) = frame else {
                continue;
            };
            let backwards = EdgeFrame::<S>::new(mesh, ends[1], ends[0]);
            for side in mesh.sides(e) {
                let Some(wing) = frame_wing(mesh, &reversed, e, side) else {
                    continue;
                };
                let apex = match (flat.as_ref(), backwards.as_ref()) {
                    (Some(regions), _) if regions.region(wing.face).is_some() => {
                        regions.apex(mesh, (e, wing.face), &edge_length[i], wing.apex)
                    }
                    (_, Some(backwards)) => apex(mesh, [&frame, backwards], ends, wing.apex),
                    (_, None) => continue,
                };
                let near_reversed = frame_ends(mesh, &reversed, wing.near)[0] == wing.apex;
                let far_reversed = frame_ends(mesh, &reversed, wing.far)[0] != wing.apex;
                let (near, far) = (wing.near.index(), wing.far.index());
                // Whether the other two edges have length zero is set below, once every edge
                // is measured: a table of the apexes kept until then would take half as much
                // memory again as the sides.
                let flags = SideFlags::NONE
                    .with(SideFlags::NEAR_REVERSED, near_reversed)
                    .with(SideFlags::FAR_REVERSED, far_reversed)
                    .with(SideFlags::NEAR_FROM_APEX, near_reversed && anchored[near])
                    .with(
                        SideFlags::FAR_FROM_END,
                        (far_reversed && anchored[far]) || mirrored_far,
                    )
                    .with(SideFlags::MORE_SIDES, mesh.side_count(e) > 2);
                sides[mesh.side_slot(e, side)] = Some(FaceSide {
                    apex_vertex: wing.apex,
                    near: wing.near,
                    far: wing.far,
                    apex,
                    flags,
                });
            }
        }
        for face in sides.iter_mut().flatten() {
            face.flags = face
                .flags
                .with(SideFlags::NEAR_ZERO_LENGTH, zero_length[face.near.index()])
                .with(SideFlags::FAR_ZERO_LENGTH, zero_length[face.far.index()]);
        }
        Unfolding {
            edge_length,
            zero_length,
            has_twin,
            sides,
            reversed,
            flat,
            scale: mesh.unit_scale(),
        }
    }

    /// Whether the frame of `e` runs from its `vertices[1]`.
    #[inline]
    pub(crate) fn is_reversed(&self, e: EdgeId) -> bool {
        self.reversed[e.index()]
    }

    /// The ends of an edge in the order of its frame: x runs from the first to the second.
    #[inline]
    pub(crate) fn ends(&self, mesh: &TriMesh, e: EdgeId) -> [VertexId; 2] {
        frame_ends(mesh, &self.reversed, e)
    }

    /// The one side of `e` other than `tau` where the edge has two sides (all but edges shared
    /// by more than two faces), whether or not a face lies there: told by that side's record
    /// (an edge with an empty side has no more), so that a wedge crossing the edge does not
    /// read the edge's count of sides from an array of its own, a cache miss at every wedge.
    /// `None` where the edge may have more sides.
    #[inline]
    pub(crate) fn only_other_side(&self, mesh: &TriMesh, e: EdgeId, tau: Side) -> Option<Side> {
        if tau.index() >= 2 {
            return None;
        }
        let other = Side::from_index(1 - tau.index());
        match &self.sides[mesh.side_slot(e, other)] {
            Some(face) if face.flags.has(SideFlags::MORE_SIDES) => None,
            _ => Some(other),
        }
    }

    /// The position in the frame of `e` of the point at fraction `t` from its `vertices[0]`.
    pub(crate) fn at_fraction(&self, e: EdgeId, t: f64) -> S {
        match self.is_reversed(e) {
            false => S::from_f64(t) * self.length(e),
            true => S::from_f64(1.0 - t) * self.length(e),
        }
    }

    /// The position `x` in the frame of `e` as an offset from the edge's `vertices[0]`.
    pub(crate) fn offset_from_first_vertex(&self, e: EdgeId, x: &S) -> S {
        match self.is_reversed(e) {
            false => x.clone(),
            true => self.length(e).clone() - x,
        }
    }

    /// The point at position `x` in the frame of `e`, in space (the model's coordinates),
    /// placed from the nearer end: to ulps of its offset from that end, not of the edge's
    /// length. (An exact backend's frames keep the mesh's order: a point 1e-4 from the far end
    /// of an edge 1e8 long, placed from the first end, was 7e-8 off, and its path as much too
    /// long.)
    pub(crate) fn edge_position(&self, mesh: &TriMesh, e: EdgeId, x: &S) -> DVec3 {
        let [a, b] = self.ends(mesh, e).map(|v| mesh.position(v));
        let length = self.length(e);
        let t = (x.clone() / length).to_f64().clamp(0.0, 1.0);
        if t <= 0.5 {
            return a + t * (b - a);
        }
        let u = ((length.clone() - x) / length).to_f64().clamp(0.0, 1.0);
        b + u * (a - b)
    }

    /// The point at position `x` in the frame of `e`, named by its fraction from `vertices[0]`.
    pub(crate) fn edge_point(&self, e: EdgeId, x: &S) -> SurfacePoint {
        let t = (x.clone() / self.length(e)).to_f64().clamp(0.0, 1.0);
        let t = if self.is_reversed(e) { 1.0 - t } else { t };
        SurfacePoint::Edge { edge: e, t }
    }

    /// The flat regions, for number types that keep values.
    pub(crate) fn flat_regions(&self) -> Option<&FlatRegions<S>> {
        self.flat.as_ref()
    }

    /// The flat region of a face and the regions' frames, if the face lies in one and the
    /// number type keeps values.
    #[inline]
    pub(crate) fn flat_region(&self, f: FaceId) -> Option<(&FlatRegions<S>, u32)> {
        let regions = self.flat.as_ref()?;
        regions.region(f).map(|r| (regions, r))
    }

    #[inline]
    pub(crate) fn length(&self, e: EdgeId) -> &S {
        &self.edge_length[e.index()]
    }

    /// Whether the edge's ends coincide.
    #[inline]
    pub(crate) fn is_zero_length(&self, e: EdgeId) -> bool {
        self.zero_length[e.index()]
    }

    /// Whether the vertex ends an edge of length zero.
    #[inline]
    pub(crate) fn has_twin(&self, v: VertexId) -> bool {
        self.has_twin[v.index()]
    }

    /// The apex of the face on `side` of `e` (`None` without a face there, or on an edge of
    /// length zero).
    #[inline]
    pub(crate) fn apex(&self, mesh: &TriMesh, e: EdgeId, side: Side) -> Option<&Apex<S>> {
        self.sides[mesh.side_slot(e, side)]
            .as_ref()
            .map(|s| &s.apex)
    }

    /// The apex of the face on `side` of `e` as a point of the edge's frame, below the line
    /// (`y = h`, the side a pseudo-source on the other side looks at).
    pub(crate) fn apex_point(&self, mesh: &TriMesh, e: EdgeId, side: Side) -> Option<Planar<S>> {
        self.apex(mesh, e, side).map(|a| Planar {
            x: a.x.clone(),
            y: a.h.clone(),
        })
    }

    /// A point in space (scaled coordinates) in the frame of edge `e`; `None` for an edge of
    /// length zero, which has no frame.
    pub(crate) fn planar(&self, mesh: &TriMesh, e: EdgeId, p: &[S; 3]) -> Option<Planar<S>> {
        if self.is_zero_length(e) {
            return None;
        }
        let [v0, v1] = self.ends(mesh, e);
        EdgeFrame::new(mesh, v0, v1).map(|frame| frame.planar(p))
    }

    /// Whether a point (in the frame of edge `e`) lies on the edge strictly between its ends,
    /// on its line as the number type resolves heights ([`Scalar::on_line`]).
    pub(crate) fn is_inside(&self, e: EdgeId, at: &Planar<S>) -> bool {
        let length = self.length(e);
        at.x.sign() == Sign::Positive
            && at.x.compare(length) == Ordering::Less
            && S::on_line(&at.y, &at.x, length)
    }

    /// A surface point's position in space, in scaled coordinates.
    pub(crate) fn position(&self, mesh: &TriMesh, point: &SurfacePoint) -> [S; 3] {
        let p = |v: VertexId| vertex_point::<S>(mesh, v);
        match *point {
            SurfacePoint::Vertex(v) => p(v),
            SurfacePoint::Edge { edge, t } => {
                let [a, b] = mesh.edge(edge).vertices.map(p);
                let t = S::from_f64(t);
                [0, 1, 2].map(|i| a[i].clone() + (b[i].clone() - &a[i]) * &t)
            }
            SurfacePoint::Face { face, bary } => {
                let c = mesh.face(face).map(p);
                let w = bary.map(S::from_f64);
                [0, 1, 2].map(|i| {
                    c[0][i].clone() * &w[0] + c[1][i].clone() * &w[1] + c[2][i].clone() * &w[2]
                })
            }
        }
    }

    /// A lower bound on a wedge's distance at the vertex `v`: its sigma plus the straight line
    /// from its pseudo-source to `v` in space (see [`Scalar::at_least`]). `sources` are
    /// the propagation's sources.
    pub(crate) fn straight_bound(
        &self,
        mesh: &TriMesh,
        w: &Wedge<S>,
        v: VertexId,
        sources: &[SurfacePoint],
    ) -> S {
        let from = match w.pseudo_source {
            PseudoSource::Vertex(u) => vertex_point(mesh, u),
            PseudoSource::Source(k) => self.position(mesh, &sources[k.index()]),
        };
        let d = sub(&vertex_point(mesh, v), &from);
        w.sigma.clone() + &dot(&d, &d).sqrt()
    }

    /// A distance in scaled units, in the model's units (exact: a power of two; `inf` past
    /// `f64::MAX`).
    #[inline]
    pub(crate) fn to_model(&self, d: f64) -> f64 {
        d / self.scale
    }

    /// A distance in the model's units, in scaled units.
    #[inline]
    pub(crate) fn scaled_from_model(&self, d: f64) -> f64 {
        d * self.scale
    }
}

/// A face laid out below an edge's line, ready to carry points into its other two edges' frames.
pub(crate) struct FaceLayout<'a, S> {
    /// The face and its other edges, in the order of the edge's frame.
    pub wing: Wing,
    /// Length of the edge the layout hangs from.
    pub length: &'a S,
    /// Apex position along the edge.
    pub apex_x: &'a S,
    /// Apex position along the edge from the frame's second end backwards (`length - apex_x`,
    /// measured from that end).
    pub apex_far_x: &'a S,
    /// Apex depth below the edge's line.
    pub apex_h: &'a S,
    /// Length of the edge from the frame's first end to the apex.
    pub near_length: &'a S,
    /// Length of the edge from the apex to the frame's second end.
    pub far_length: &'a S,
    /// Whether the near edge runs from the apex (its frame's x is measured from the apex).
    pub near_reversed: bool,
    /// Whether the far edge runs towards the apex.
    pub far_reversed: bool,
    /// Whether points of the near edge are computed from the apex (its frame's first end) rather
    /// than from the edge's first end: where the near edge is long beside the apex's distance
    /// from the sources (see `frames_near_sources`), so that a point near the apex is not the
    /// small difference of two lengths of the near edge.
    pub near_from_apex: bool,
    /// Likewise, whether points of the far edge are computed from the edge's second end rather
    /// than from the apex: also for number types that keep values, whatever the far edge's
    /// frame, so that the far edge's points are the mirror image of the near edge's (measured
    /// from the edge's first end) and the mirror images of a wedge build one expression.
    pub far_from_end: bool,
    /// Whether the near edge has length zero (its ends coincide: it carries no wedge).
    pub near_zero_length: bool,
    /// Whether the far edge has length zero.
    pub far_zero_length: bool,
}

impl<'a, S: Scalar> FaceLayout<'a, S> {
    /// The layout of the face on `side` of `e`, if there is one.
    #[inline]
    pub(crate) fn new(
        mesh: &'a TriMesh,
        unfolding: &'a Unfolding<S>,
        e: EdgeId,
        side: Side,
    ) -> Option<Self> {
        let face = unfolding.sides[mesh.side_slot(e, side)].as_ref()?;
        let wing = Wing {
            face: mesh
                .face_on(e, side)
                .expect("a side with a layout has a face"),
            apex: face.apex_vertex,
            near: face.near,
            far: face.far,
        };
        let flag = |f: u8| face.flags.has(f);
        Some(FaceLayout {
            wing,
            length: unfolding.length(e),
            apex_x: &face.apex.x,
            apex_far_x: &face.apex.far_x,
            apex_h: &face.apex.h,
            near_length: unfolding.length(face.near),
            far_length: unfolding.length(face.far),
            near_reversed: flag(SideFlags::NEAR_REVERSED),
            far_reversed: flag(SideFlags::FAR_REVERSED),
            near_from_apex: flag(SideFlags::NEAR_FROM_APEX),
            far_from_end: flag(SideFlags::FAR_FROM_END),
            near_zero_length: flag(SideFlags::NEAR_ZERO_LENGTH),
            far_zero_length: flag(SideFlags::FAR_ZERO_LENGTH),
        })
    }

    /// The apex vertex.
    #[inline]
    pub(crate) fn apex_vertex(&self) -> VertexId {
        self.wing.apex
    }

    /// Where the line through `s` and `(b, 0)` meets the near edge, as a fraction (not
    /// clamped) from the frame's first end towards the apex, or from the apex backwards if
    /// the near edge's points are computed from it ([`FaceLayout::near_ends`]).
    #[inline]
    pub(crate) fn near_hit(&self, s: &Planar<S>, b: &S) -> S {
        // Solve cross(d, t C - s) = 0 with d = (b - sx, -sy), C = (cx, -h).
        let dx = b.clone() - &s.x;
        let den = s.y.clone() * self.apex_x - dx.clone() * self.apex_h;
        let num = if self.near_from_apex {
            // 1 - t, without the cancellation.
            s.y.clone() * &(self.apex_x.clone() - b) - dx * self.apex_h
        } else {
            b.clone() * &s.y
        };
        num / den
    }

    /// Where the line through `s` and `(b, 0)` meets the far edge, as a fraction (not clamped)
    /// from the apex towards the frame's second end, or from that end backwards if the far
    /// edge's points are computed from it ([`FaceLayout::far_ends`]).
    #[inline]
    pub(crate) fn far_hit(&self, s: &Planar<S>, b: &S) -> S {
        let dx = b.clone() - &s.x;
        let den = dx.clone() * self.apex_h + s.y.clone() * self.apex_far_x;
        let num = if self.far_from_end {
            // 1 - u, without the cancellation.
            s.y.clone() * &(self.length.clone() - b)
        } else {
            dx * &(s.y.clone() + self.apex_h) + s.y.clone() * &(s.x.clone() - self.apex_x)
        };
        num / den
    }

    /// The fractions of [`FaceLayout::near_hit`] at the near edge's two ends: the frame's
    /// first end and the apex.
    #[inline]
    pub(crate) fn near_ends(&self) -> [S; 2] {
        end_fractions(self.near_from_apex)
    }

    /// The fractions of [`FaceLayout::far_hit`] at the far edge's two ends: the apex and the
    /// frame's second end.
    #[inline]
    pub(crate) fn far_ends(&self) -> [S; 2] {
        end_fractions(self.far_from_end)
    }

    /// Where the ray from `s` (above the edge's line) through the point `b` of the edge passes
    /// the apex: `Less` if `b` lies left of the apex's shadow (the ray leaves the face by the
    /// near edge), `Greater` if right of it (by the far edge), `Equal` through the apex. The
    /// orientation of `(s, b, apex)` [SSK+05 §4.1], decided by the number type.
    #[inline]
    pub(crate) fn ray_side(&self, s: &Planar<S>, b: &S) -> Ordering {
        let zero = S::zero();
        // Mirrored across the edge's line (apex above it, s below), which keeps the apex's
        // coordinates as stored and reverses the orientation.
        let below = -s.y.clone();
        match S::orientation([&s.x, &below], [b, &zero], [self.apex_x, self.apex_h]) {
            Sign::Negative => Ordering::Less,
            Sign::Zero => Ordering::Equal,
            Sign::Positive => Ordering::Greater,
        }
    }

    /// Where the line from `s` through the apex meets the edge's line: rays through points left of
    /// it leave the face by the near edge, rays right of it by the far edge.
    #[inline]
    pub(crate) fn apex_shadow(&self, s: &Planar<S>) -> S {
        let depth = s.y.clone() + self.apex_h;
        s.x.clone() + (self.apex_x.clone() - &s.x) * &s.y / depth
    }

    /// The size of the offsets [`FaceLayout::apex_shadow`] builds the shadow of the apex from
    /// `s` with, and of the shadow itself: it is known to ulps of these, not of the edge's
    /// length. Near the frame's first end, where the vertices of short distances lie, that is
    /// far finer than the edge: on an edge of length 1.41 whose pseudo-source and apex lay
    /// 1e-16 from that end, a slack of ulps of the edge let the wedge claim the apex 1e-20
    /// beyond its range, by a straight line shorter than the geodesic round the range's end.
    pub(crate) fn shadow_reach(&self, s: &Planar<S>, shadow: &S) -> S {
        let size = |x: &S| S::max_of(x, &-x.clone());
        [size(&s.x), s.y.clone(), size(self.apex_x)]
            .iter()
            .fold(size(shadow), |m, c| S::max_of(&m, c))
    }

    /// Squared distance from `s` to the apex.
    #[inline]
    pub(crate) fn apex_distance(&self, s: &Planar<S>) -> S {
        let dx = self.apex_x.clone() - &s.x;
        let dy = s.y.clone() + self.apex_h;
        (dx.clone() * dx + dy.clone() * dy).sqrt()
    }

    /// `s` in the near edge's frame, y positive towards this face.
    #[inline]
    pub(crate) fn to_near(&self, s: &Planar<S>) -> Planar<S> {
        let a = self.near_length;
        let y = (self.apex_x.clone() * &s.y + self.apex_h.clone() * &s.x) / a;
        if self.near_from_apex {
            // Along the near edge from the apex: (s - C) . (-C) / a with C = (cx, -h).
            let from_apex = (s.y.clone() + self.apex_h) * self.apex_h
                - (s.x.clone() - self.apex_x) * self.apex_x;
            return Planar {
                x: from_apex / a,
                y,
            };
        }
        let x = (s.x.clone() * self.apex_x - s.y.clone() * self.apex_h) / a;
        if self.near_reversed {
            Planar {
                x: a.clone() - x,
                y,
            }
        } else {
            Planar { x, y }
        }
    }

    /// `s` in the far edge's frame, y positive towards this face.
    #[inline]
    pub(crate) fn to_far(&self, s: &Planar<S>) -> Planar<S> {
        let b = self.far_length;
        let ux = self.apex_far_x.clone();
        if self.far_from_end {
            // From the frame's second end E = (length, 0) rather than from the apex C, with
            // C - E = (-far_x, -h): along the edge (s - E) . (C - E) / b, across it
            // (E - C) x (s - E) / b.
            let back = self.length.clone() - &s.x;
            let x = (back.clone() * &ux - s.y.clone() * self.apex_h) / b;
            let y = (ux * &s.y + back * self.apex_h) / b;
            // The far edge's frame may start at the apex (number types that keep values).
            let x = if self.far_reversed { x } else { b.clone() - x };
            return Planar { x, y };
        }
        let sx = s.x.clone() - self.apex_x;
        let sy = s.y.clone() + self.apex_h;
        let x = (sx.clone() * &ux + sy.clone() * self.apex_h) / b;
        let y = (ux * &sy - self.apex_h.clone() * &sx) / b;
        if self.far_reversed {
            Planar {
                x: b.clone() - x,
                y,
            }
        } else {
            Planar { x, y }
        }
    }

    /// A fraction `t` along the near edge (as [`FaceLayout::near_hit`] measures it) as a
    /// position in the near edge's frame.
    #[inline]
    pub(crate) fn near_position(&self, t: &S) -> S {
        let x = t.clone() * self.near_length;
        if self.near_reversed && !self.near_from_apex {
            self.near_length.clone() - x
        } else {
            x
        }
    }

    /// A fraction `u` along the far edge (as [`FaceLayout::far_hit`] measures it) as a
    /// position in the far edge's frame.
    #[inline]
    pub(crate) fn far_position(&self, u: &S) -> S {
        let x = u.clone() * self.far_length;
        if self.far_reversed != self.far_from_end {
            self.far_length.clone() - x
        } else {
            x
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::{Adaptive, Real, Ring};

    #[test]
    fn a_side_of_the_f64_engine_takes_40_bytes_with_or_without_a_face() {
        assert_eq!(std::mem::size_of::<Option<FaceSide<f64>>>(), 40);
    }

    /// Each flag of a side reads back as it was set, whatever the others are.
    #[test]
    fn the_flags_of_a_side_are_independent() {
        let all = [
            SideFlags::NEAR_REVERSED,
            SideFlags::FAR_REVERSED,
            SideFlags::NEAR_FROM_APEX,
            SideFlags::FAR_FROM_END,
            SideFlags::NEAR_ZERO_LENGTH,
            SideFlags::FAR_ZERO_LENGTH,
            SideFlags::MORE_SIDES,
        ];
        for pattern in 0..1u32 << all.len() {
            let on = |i: usize| pattern & (1 << i) != 0;
            let flags = (0..all.len()).fold(SideFlags::NONE, |f, i| f.with(all[i], on(i)));
            for (i, &flag) in all.iter().enumerate() {
                assert_eq!(flags.has(flag), on(i), "pattern {pattern:b}, flag {i}");
                assert_eq!(flags.with(flag, !on(i)).has(flag), !on(i));
            }
        }
    }

    /// Rays from a pseudo-source straight above the apex's shadow pass it on the side of the
    /// point of the edge they go through, and through it exactly at the shadow.
    fn rays_pass_the_apex_on_their_side<S: Scalar>() {
        // A unit square split along its diagonal from v0 = (0, 0) to v3 = (1, 1); the face
        // below the diagonal has its apex at v1 = (1, 0).
        let mesh = crate::mesh::shapes::grid(1, 1, 1.0, 1.0);
        let unfolding = Unfolding::<S>::new(&mesh, &[]);
        let e = mesh
            .edge_between(VertexId(0), VertexId(3))
            .expect("the diagonal");
        let side = mesh
            .sides(e)
            .find(|&s| mesh.wing(e, s).is_some_and(|w| w.apex == VertexId(1)))
            .expect("the face with apex (1, 0)");
        let layout = FaceLayout::new(&mesh, &unfolding, e, side).expect("a face");
        // A pseudo-source straight above the apex casts its shadow at the apex's own x.
        let s = Planar {
            x: layout.apex_x.clone(),
            y: S::from_f64(3.0),
        };
        let quarter = unfolding.length(e).clone() * &S::from_f64(0.25);
        assert_eq!(layout.ray_side(&s, &quarter), Ordering::Less);
        assert_eq!(layout.ray_side(&s, layout.apex_x), Ordering::Equal);
        let three_quarters = unfolding.length(e).clone() * &S::from_f64(0.75);
        assert_eq!(layout.ray_side(&s, &three_quarters), Ordering::Greater);
    }

    #[test]
    fn ray_side_in_every_backend() {
        rays_pass_the_apex_on_their_side::<f64>();
        rays_pass_the_apex_on_their_side::<Adaptive>();
        rays_pass_the_apex_on_their_side::<Real>();
    }

    #[test]
    fn an_edge_of_length_zero_has_no_frame_and_no_apex() {
        let mesh = TriMesh::new(
            vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]],
            vec![[0, 1, 2]],
        )
        .expect("a degenerate face is a usable mesh");
        let unfolding = Unfolding::<Real>::new(&mesh, &[]);
        let e = mesh
            .edge_between(VertexId(0), VertexId(2))
            .expect("the zero-length edge");
        assert!(unfolding.is_zero_length(e));
        assert!(unfolding.has_twin(VertexId(0)) && unfolding.has_twin(VertexId(2)));
        assert!(!unfolding.has_twin(VertexId(1)));
        assert!(unfolding.apex(&mesh, e, Side::FIRST).is_none());
        let p = [
            Real::from_f64(0.5),
            Real::from_f64(0.0),
            Real::from_f64(0.0),
        ];
        assert!(unfolding.planar(&mesh, e, &p).is_none());
    }
}
