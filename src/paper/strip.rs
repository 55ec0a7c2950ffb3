//! A wedge unfolded by hand along a named sequence of faces, as the examples of [LZT §3] describe
//! their wedges ("w1 goes through ..."), and eq. (2) between two such wedges.
//!
//! Independent of the engine: the faces are laid out in one plane and the cone of rays from the
//! source that crosses every shared edge is kept, in the backend's number type `S`.

use crate::mesh::{FaceId, TriMesh, VertexId};
use crate::scalar::{BisectorRoots, Eq2Coefficients, Scalar, Sign, SourceDistance};

/// A point of the plane the faces are unfolded into.
type P2<S> = [S; 2];

fn sub<S: Scalar>(a: &P2<S>, b: &P2<S>) -> P2<S> {
    [a[0].clone() - &b[0], a[1].clone() - &b[1]]
}

fn cross<S: Scalar>(a: &P2<S>, b: &P2<S>) -> S {
    a[0].clone() * &b[1] - a[1].clone() * &b[0]
}

fn dot<S: Scalar>(a: &P2<S>, b: &P2<S>) -> S {
    a[0].clone() * &b[0] + a[1].clone() * &b[1]
}

fn length3<S: Scalar>(mesh: &TriMesh, a: VertexId, b: VertexId) -> S {
    let (p, q) = (mesh.position(a), mesh.position(b));
    let d = [0, 1, 2].map(|i| S::from_f64(p[i]) - S::from_f64(q[i]));
    (d[0].clone() * &d[0] + d[1].clone() * &d[1] + d[2].clone() * &d[2]).sqrt()
}

/// Places vertex `c` at its distances from the placed `a` and `b`, on the left of `a -> b` if
/// `left`, else on the right.
fn place<S: Scalar>(
    mesh: &TriMesh,
    (a, pa): (VertexId, &P2<S>),
    (b, pb): (VertexId, &P2<S>),
    c: VertexId,
    left: bool,
) -> P2<S> {
    let l = length3::<S>(mesh, a, b);
    let (ac, bc) = (length3::<S>(mesh, a, c), length3::<S>(mesh, b, c));
    let x = (l.clone() * &l + ac.clone() * &ac - bc.clone() * &bc) / (S::from_f64(2.0) * &l);
    let h = (ac.clone() * &ac - x.clone() * &x).sqrt();
    let h = if left { h } else { -h };
    let u = sub(pb, pa);
    [
        pa[0].clone() + (x.clone() * &u[0] - h.clone() * &u[1]) / &l,
        pa[1].clone() + (x * &u[1] + h * &u[0]) / &l,
    ]
}

/// A wedge reaching an edge through a named face sequence, in the edge's frame (Definition 1
/// [LZT §2]): x along the edge from its first named vertex, y the distance from its line.
#[derive(Clone, Debug, PartialEq)]
pub struct StripWedge<S> {
    /// Start of the range on the edge.
    pub b0: S,
    /// End of the range.
    pub b1: S,
    /// The unfolded (pseudo-)source: position along the edge.
    pub source_x: S,
    /// The unfolded (pseudo-)source: distance from the edge's line.
    pub source_y: S,
    /// Distance from the (pseudo-)source back to the source.
    pub sigma: S,
    /// The last face of the sequence: the side of the edge the wedge comes from (tau).
    pub face: FaceId,
}

impl<S: Scalar> StripWedge<S> {
    /// The wedge's distance function along its edge.
    pub fn distance_function(&self) -> SourceDistance<S> {
        SourceDistance {
            x: self.source_x.clone(),
            y: self.source_y.clone(),
            sigma: self.sigma.clone(),
        }
    }

    /// Distance from the pseudo-source to the point `b0`.
    pub fn d0(&self) -> S {
        self.distance_function().at(&self.b0) - &self.sigma
    }

    /// Distance from the pseudo-source to the point `b1`.
    pub fn d1(&self) -> S {
        self.distance_function().at(&self.b1) - &self.sigma
    }
}

/// The face with these three corners, in any order.
pub fn face_with_corners(mesh: &TriMesh, corners: [u32; 3]) -> Option<FaceId> {
    let mut want = corners;
    want.sort_unstable();
    mesh.faces()
        .iter()
        .position(|f| {
            let mut f = *f;
            f.sort_unstable();
            f == want
        })
        .map(|i| FaceId(i as u32))
}

/// The wedge of `source` (at distance `sigma` from the real source) that crosses `faces` in
/// order and arrives on the edge `edge = (a, b)` of the last face, or `None` if the faces are
/// not a strip from `source` or no ray from it crosses them all.
///
/// `faces[0]` must have `source` as a corner; consecutive faces share an edge, which the rays
/// cross. The range is clipped to the edge.
pub fn unfold_strip<S: Scalar>(
    mesh: &TriMesh,
    source: VertexId,
    sigma: S,
    faces: &[FaceId],
    edge: (VertexId, VertexId),
) -> Option<StripWedge<S>> {
    let first = mesh.face(*faces.first()?);
    let k = first.iter().position(|&c| c == source)?;
    let (a, b) = (first[(k + 1) % 3], first[(k + 2) % 3]);
    let origin: P2<S> = [S::zero(), S::zero()];
    let pa: P2<S> = [length3(mesh, source, a), S::zero()];
    let pb = place(mesh, (source, &origin), (a, &pa), b, true);
    let mut placed: Vec<(VertexId, P2<S>)> = vec![(source, origin.clone()), (a, pa), (b, pb)];
    let find = |placed: &[(VertexId, P2<S>)], v: VertexId| {
        placed
            .iter()
            .rev()
            .find(|(w, _)| *w == v)
            .map(|(_, p)| p.clone())
    };
    // The cone of directions from the source, counter-clockwise from `lo` to `hi`.
    let mut cone: Option<(P2<S>, P2<S>)> = None;
    let clip = |p: P2<S>, q: P2<S>, cone: &mut Option<(P2<S>, P2<S>)>| -> Option<()> {
        let (lo, hi) = match cross(&p, &q).sign() {
            Sign::Positive => (p, q),
            Sign::Negative => (q, p),
            Sign::Zero => return None,
        };
        let (lo, hi) = match cone.take() {
            None => (lo, hi),
            Some((clo, chi)) => (
                if cross(&clo, &lo).sign() == Sign::Positive {
                    lo
                } else {
                    clo
                },
                if cross(&chi, &hi).sign() == Sign::Negative {
                    hi
                } else {
                    chi
                },
            ),
        };
        (cross(&lo, &hi).sign() == Sign::Positive).then(|| *cone = Some((lo, hi)))
    };
    let mut previous = first;
    for &f in &faces[1..] {
        let corners = mesh.face(f);
        let shared: Vec<VertexId> = corners
            .iter()
            .copied()
            .filter(|c| previous.contains(c))
            .collect();
        let [p, q] = shared[..] else { return None };
        let apex = corners.into_iter().find(|c| !shared.contains(c))?;
        let behind = previous.into_iter().find(|c| !shared.contains(c))?;
        let (pp, pq, pbehind) = (find(&placed, p)?, find(&placed, q)?, find(&placed, behind)?);
        clip(pp.clone(), pq.clone(), &mut cone)?;
        let behind_left = cross(&sub(&pq, &pp), &sub(&pbehind, &pp)).sign() == Sign::Positive;
        let papex = place(mesh, (p, &pp), (q, &pq), apex, !behind_left);
        placed.push((apex, papex));
        previous = corners;
    }
    let (e0, e1) = (find(&placed, edge.0)?, find(&placed, edge.1)?);
    if !(previous.contains(&edge.0) && previous.contains(&edge.1)) {
        return None;
    }
    clip(e0.clone(), e1.clone(), &mut cone)?;
    let (lo, hi) = cone?;
    let u = sub(&e1, &e0);
    let length = dot(&u, &u).sqrt();
    let to_source = sub(&origin, &e0);
    // Where the ray in direction d meets the edge's line, as a position along the edge.
    let hit = |d: &P2<S>| cross(&to_source, d) / cross(&u, d) * &length;
    let (t_lo, t_hi) = (hit(&lo), hit(&hi));
    let (b0, b1) = if t_lo.compare(&t_hi).is_le() {
        (t_lo, t_hi)
    } else {
        (t_hi, t_lo)
    };
    let (b0, b1) = (S::max_of(&b0, &S::zero()), S::min_of(&b1, &length));
    let along = dot(&to_source, &u) / &length;
    let height = cross(&u, &to_source) / &length;
    let height = if height.sign() == Sign::Negative {
        -height
    } else {
        height
    };
    Some(StripWedge {
        b0,
        b1,
        source_x: along,
        source_y: height,
        sigma,
        face: *faces.last()?,
    })
}

/// Eq. (2) between two wedges on the same edge, over their shared range [LZT §2, Property 1].
#[derive(Clone, Debug, PartialEq)]
pub struct Eq2Pair<S> {
    /// The shared range `(lo, hi)`.
    pub range: (S, S),
    /// The coefficients `A, B, C`, positions measured from `lo`.
    pub coefficients: Eq2Coefficients<S>,
    /// The solutions of eq. (1) inside the shared range, as the backend decides them.
    pub roots: BisectorRoots<S>,
}

/// Eq. (2) for two wedges on the same edge, or `None` if their ranges do not overlap.
pub fn eq2_pair<S: Scalar>(w1: &StripWedge<S>, w2: &StripWedge<S>) -> Option<Eq2Pair<S>> {
    let lo = S::max_of(&w1.b0, &w2.b0);
    let hi = S::min_of(&w1.b1, &w2.b1);
    if lo.compare(&hi).is_ge() {
        return None;
    }
    let (f1, f2) = (w1.distance_function(), w2.distance_function());
    Some(Eq2Pair {
        coefficients: Eq2Coefficients::new(&f1, &f2, &lo),
        roots: S::bisector_roots(&f1, &f2, &lo, &hi),
        range: (lo, hi),
    })
}
