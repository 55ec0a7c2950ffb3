//! The engine is generic over its number type and never relies on `Copy`: a scalar that is only
//! `Clone` (as exact numbers will be) runs the same propagation and gets the same answers.

use exact_geodesics::mesh::shapes;
use exact_geodesics::scalar::{Bisector, Field, Ring, Scalar, Sign, SourceDistance};
use exact_geodesics::{propagate, PropagateOptions, SurfacePoint, TriMesh, VertexId};
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An `f64` that can only be cloned.
#[derive(Clone, Debug, PartialEq)]
struct CloneOnly(f64);

macro_rules! binary_op {
    ($trait:ident, $method:ident) => {
        impl $trait for CloneOnly {
            type Output = CloneOnly;
            fn $method(self, rhs: CloneOnly) -> CloneOnly {
                CloneOnly(self.0.$method(rhs.0))
            }
        }
        impl<'a> $trait<&'a CloneOnly> for CloneOnly {
            type Output = CloneOnly;
            fn $method(self, rhs: &'a CloneOnly) -> CloneOnly {
                CloneOnly(self.0.$method(rhs.0))
            }
        }
    };
}
binary_op!(Add, add);
binary_op!(Sub, sub);
binary_op!(Mul, mul);
binary_op!(Div, div);

impl Neg for CloneOnly {
    type Output = CloneOnly;
    fn neg(self) -> CloneOnly {
        CloneOnly(-self.0)
    }
}

fn raw(d: &SourceDistance<CloneOnly>) -> SourceDistance<f64> {
    SourceDistance {
        x: d.x.0,
        y: d.y.0,
        sigma: d.sigma.0,
    }
}

/// Every decision is delegated to the f64 backend, so the results must be identical.
impl Ring for CloneOnly {
    fn from_f64(x: f64) -> Self {
        CloneOnly(x)
    }
}

impl Field for CloneOnly {
    fn to_f64(&self) -> f64 {
        self.0
    }
    fn sqrt(&self) -> Self {
        CloneOnly(Field::sqrt(&self.0))
    }
}

impl Scalar for CloneOnly {
    // Keeps no values, as f64: the same constructions, so the same answers to the bit.
    type Kept<T: Clone + std::fmt::Debug + Send + Sync> = ();
    fn keep<T: Clone + std::fmt::Debug + Send + Sync>(_make: impl FnOnce() -> T) -> Self::Kept<T> {}
    fn kept<T: Clone + std::fmt::Debug + Send + Sync>(_kept: &Self::Kept<T>) -> Option<T> {
        None
    }
    fn orientation(p: [&Self; 2], q: [&Self; 2], r: [&Self; 2]) -> Sign {
        f64::orientation([&p[0].0, &p[1].0], [&q[0].0, &q[1].0], [&r[0].0, &r[1].0])
    }
    fn at_least(value: Self, bound: impl FnOnce() -> Self) -> Self {
        CloneOnly(f64::at_least(value.0, || bound().0))
    }
    fn frames_from_nearer_end() -> bool {
        f64::frames_from_nearer_end()
    }
    fn sign(&self) -> Sign {
        self.0.sign()
    }
    fn compare(&self, other: &Self) -> Ordering {
        self.0.compare(&other.0)
    }
    fn compare_distance(&self, other: &Self) -> Ordering {
        self.0.compare_distance(&other.0)
    }
    fn has_extent(lo: &Self, hi: &Self, scale: &Self) -> bool {
        f64::has_extent(&lo.0, &hi.0, &scale.0)
    }
    fn near_tie(a: &SourceDistance<Self>, b: &SourceDistance<Self>, t: &Self) -> bool {
        f64::near_tie(&raw(a), &raw(b), &t.0)
    }
    fn within(x: &Self, lo: &Self, hi: &Self, scale: impl FnOnce() -> Self) -> bool {
        f64::within(&x.0, &lo.0, &hi.0, || scale().0)
    }
    fn on_line(height: &Self, x: &Self, length: &Self) -> bool {
        f64::on_line(&height.0, &x.0, &length.0)
    }
    fn same_distance_function(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        scale: &Self,
    ) -> bool {
        f64::same_distance_function(&raw(a), &raw(b), &scale.0)
    }
    fn same_image(a: &SourceDistance<Self>, b: &SourceDistance<Self>, scale: &Self) -> bool {
        f64::same_image(&raw(a), &raw(b), &scale.0)
    }
    fn measures_below_float_resolution() -> bool {
        f64::measures_below_float_resolution()
    }
    fn front_passed(d: &SourceDistance<Self>, lo: &Self, hi: &Self, front: f64) -> bool {
        f64::front_passed(&raw(d), &lo.0, &hi.0, front)
    }
    fn bisector(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        lo: &Self,
        hi: &Self,
        _known: &[Option<[Self; 2]>; 2],
    ) -> Bisector<Self> {
        let b = f64::bisector(&raw(a), &raw(b), &lo.0, &hi.0, &[None, None]);
        Bisector {
            roots: b.roots.map(CloneOnly),
            lower: b.lower,
        }
    }
}

fn same_answers(mesh: &TriMesh, source: SurfacePoint) {
    let options = PropagateOptions::default();
    let plain = propagate::<f64>(mesh, &[source], &options).expect("valid source");
    let cloned = propagate::<CloneOnly>(mesh, &[source], &options).expect("valid source");
    assert_eq!(plain.vertex_distances(), cloned.vertex_distances());
    assert_eq!(plain.wedge_counts(), cloned.wedge_counts());
    assert_eq!(plain.stats().eq2, cloned.stats().eq2);
}

#[test]
fn clone_only_scalar_matches_f64_on_paper_example4() {
    same_answers(&shapes::paper_example4(), SurfacePoint::Vertex(VertexId(2)));
}

#[test]
fn clone_only_scalar_matches_f64_on_an_icosphere() {
    let mesh = shapes::icosphere(2);
    let face_point = SurfacePoint::Face {
        face: exact_geodesics::FaceId(7),
        bary: [0.2, 0.3, 0.5],
    };
    same_answers(&mesh, face_point);
}
