//! The number types the engine runs on, in the style of CGAL's kernels: the engine asks a
//! [`Scalar`] for its constructions (`+ - * /`, square roots: the [`Field`] part) and for its
//! decisions (signs, comparisons, orientations, the roots of eq. (2) [LZT §2]) and never asks
//! which backend it runs on.
//!
//! How exact a decision is belongs to the backend:
//! - [`f64`] decides with the one documented tolerance policy in [`float`];
//! - [`Adaptive`] keeps `f64` values but decides every predicate exactly for those values
//!   (Shewchuk's orientation from `robust`, eq. (2) by an interval filter and exact rationals);
//! - [`Real`] is exact: rationals with exact square roots and certified signs.
//!
//! Backends that certify count their decisions ([`DecisionCounts`]) per thread; the engine
//! collects them per propagation through [`Scalar::take_counts`].

/// `Add<&T>`, `Sub<&T>`, `Mul<&T>`, `Div<&T>` for a `Copy` number type, by copying the operand.
macro_rules! ops_by_reference_for_copy {
    ($t:ty) => {
        ops_by_reference_for_copy!($t: Add add, Sub sub, Mul mul, Div div);
    };
    ($t:ty: $($tr:ident $f:ident),*) => {$(
        impl<'a> std::ops::$tr<&'a $t> for $t {
            type Output = $t;
            #[inline(always)]
            fn $f(self, o: &'a $t) -> $t {
                std::ops::$tr::$f(self, *o)
            }
        }
    )*};
}

/// The [`Scalar::Kept`] items of a number type that keeps no values: its values are numbers,
/// compared by value, and the engine's kept-value paths compile away.
macro_rules! keeps_no_values {
    () => {
        type Kept<T: Clone + std::fmt::Debug + Send + Sync> = ();

        #[inline(always)]
        fn keep<T: Clone + std::fmt::Debug + Send + Sync>(
            _make: impl FnOnce() -> T,
        ) -> Self::Kept<T> {
        }

        #[inline(always)]
        fn kept<T: Clone + std::fmt::Debug + Send + Sync>(_kept: &Self::Kept<T>) -> Option<T> {
            None
        }
    };
}
pub(crate) use keeps_no_values;

mod adaptive;
mod audit;
mod backend;
mod bignum;
mod bisector;
mod double_double;
mod error_bound;
pub mod exact;
pub mod float;
mod interval;
mod rational;
mod roots;

pub use adaptive::{Adaptive, Resolution};
pub use audit::{Certificate, DecisionCounts, DecisionSite, Site, Uncertainty, ZeroProof};
pub use backend::Backend;
pub use bisector::{Bisector, BisectorRoots, Eq2Case, Eq2Coefficients, Lower, SourceDistance};
pub use exact::Real;
pub use interval::Interval;

use std::cmp::Ordering;
use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// How far the front of a propagation must be beyond the largest distance a wedge gives on its
/// range before the wedge's edge may be given up ([`Scalar::front_passed`]): `2^-20` of it,
/// far above the rounding of the `f64` distances the float backends compare there (slivers
/// 1e8 long put float distances 1e-8 off) and above every backend's tie between distances, so
/// that a wedge arriving later is higher than the edge's wedges everywhere, by every backend's
/// decision. The wedges are held that much longer. The engine asks again once the front has
/// passed the `f64` value of that distance times this margin.
pub(crate) const FRONT_MARGIN: f64 = 1.0 + 1.0 / (1u64 << 20) as f64;

/// Sign of a number, as decided by its backend.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Sign {
    /// Less than zero.
    Negative,
    /// Zero.
    Zero,
    /// Greater than zero.
    Positive,
}

impl Sign {
    /// The sign of a product.
    #[inline]
    pub fn times(self, other: Sign) -> Sign {
        match (self, other) {
            (Sign::Zero, _) | (_, Sign::Zero) => Sign::Zero,
            (a, b) if a == b => Sign::Positive,
            _ => Sign::Negative,
        }
    }

    /// The ordering of `x` against zero, for a sign of `x`.
    #[inline]
    pub fn as_ordering(self) -> Ordering {
        match self {
            Sign::Negative => Ordering::Less,
            Sign::Zero => Ordering::Equal,
            Sign::Positive => Ordering::Greater,
        }
    }
}

/// Exact-valued arithmetic: `+ - * /` and the exact value of an `f64`. Enough to evaluate the
/// polynomials and rational functions whose signs the decisions need; exact rationals are rings
/// in this sense, and so is every [`Field`].
///
/// Values are `Clone`, not `Copy`, so that exact numbers (big rationals, expression DAGs) fit;
/// operators take their right operand by reference where a clone would otherwise be needed.
pub trait Ring:
    Clone
    + Debug
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
{
    /// The exact value of an `f64` (every finite `f64` is a binary rational).
    ///
    /// # Panics
    /// Backends whose values are exact ([`Real`]) panic on a NaN or infinite `x`, which has no
    /// exact value; backends with `f64` values ([`f64`], [`Adaptive`], [`Interval`]) keep it as
    /// it is. The engine passes only finite values: coordinates of a [`TriMesh`](crate::TriMesh)
    /// (checked by [`TriMesh::new`](crate::TriMesh::new)), validated parameters of surface
    /// points and constants.
    fn from_f64(x: f64) -> Self;
}

/// The constructions of a number type: a [`Ring`] (an ordered field, strictly) with square
/// roots of non-negative numbers. Shared by the engine's [`Scalar`]s and by the number types
/// that only filter or certify signs ([`Interval`]).
pub trait Field: Ring {
    /// The nearest `f64`, for output, priority keys and reports; never used for a decision.
    fn to_f64(&self) -> f64;

    /// The square root of `max(self, 0)`. Callers pass quantities that are non-negative in exact
    /// arithmetic (squared lengths, heights); a backend with rounding may see a tiny negative.
    fn sqrt(&self) -> Self;
}

/// A number type for the MMP engine: a [`Field`] plus the decisions MMP takes.
///
/// Decisions have no default bodies: a backend states how it takes each one. The bookkeeping
/// hooks ([`Scalar::locate`], [`Scalar::take_counts`]) default to nothing, which is what a
/// backend that does not certify wants (the `f64` engine pays nothing for them).
pub trait Scalar: Field {
    /// A value the engine keeps so that it can use the very same value again where it meets
    /// the same quantity a second time: `()` for number types whose values are numbers, the
    /// value itself for expression types, whose identities the engine's constructions then
    /// show by structure (a wedge's distance at a vertex, derived again by a descendant of the
    /// wedge that lit the vertex, is one and the same expression). `Send` and `Sync`, as the
    /// engines of a run's two sectors run on two threads.
    type Kept<T: Clone + std::fmt::Debug + Send + Sync>: Clone
        + Default
        + std::fmt::Debug
        + Send
        + Sync;

    /// Keeps the value `make` builds, if this number type keeps values (`make` is not called
    /// otherwise).
    fn keep<T: Clone + std::fmt::Debug + Send + Sync>(make: impl FnOnce() -> T) -> Self::Kept<T>;

    /// The kept value, if this number type keeps values.
    fn kept<T: Clone + std::fmt::Debug + Send + Sync>(kept: &Self::Kept<T>) -> Option<T>;

    /// The sign of `self`.
    fn sign(&self) -> Sign;

    /// Compares two positions or lengths.
    fn compare(&self, other: &Self) -> Ordering;

    /// Compares two geodesic distances; `Equal` means the backend cannot tell them apart, and
    /// the engine then keeps what it already has ([LZT §4] step 2.3.2: delete the newcomer).
    fn compare_distance(&self, other: &Self) -> Ordering;

    /// Whether `[lo, hi]` on an edge of length `scale` is long enough to be a wedge of its own.
    fn has_extent(lo: &Self, hi: &Self, scale: &Self) -> bool;

    /// Whether `[lo, hi]`, too short for its edge by [`Scalar::has_extent`], is still a wedge
    /// of its own because its pseudo-source, at `(x, y)` in the edge's frame, sees it under a
    /// wide angle: a number type that drops short ranges as numerically parallel rays says
    /// which are not. `false` for number types whose `has_extent` drops only empty ranges.
    fn fans_out(_lo: &Self, _hi: &Self, _x: &Self, _y: &Self) -> bool {
        false
    }

    /// Whether `x` lies in `[lo, hi]` (closed range), where `scale` gives the size of the
    /// offsets `x` and the range's ends are constructed from (an edge's length at most); only
    /// a number type that rounds those constructions evaluates it.
    fn within(x: &Self, lo: &Self, hi: &Self, scale: impl FnOnce() -> Self) -> bool;

    /// Whether the foot `x` of a pseudo-source's image counts as inside the range `[lo, hi]`
    /// (its ends included if `closed`) when the smallest distance a wedge gives there is sought
    /// [SSK+05 §4]: `sigma + y` if so, else the distance at the nearer end. With the foot at an
    /// end the two are one value, so either answer is right there, and a backend that could
    /// only tell `x = lo` from `x != lo` by a proof of zero answers `true` without one:
    /// `sigma + y` bounds the smallest distance from below wherever the foot lies.
    fn foot_within(x: &Self, lo: &Self, hi: &Self, closed: bool) -> bool {
        if closed {
            x.compare(lo) != Ordering::Less && x.compare(hi) != Ordering::Greater
        } else {
            x.compare(lo) == Ordering::Greater && x.compare(hi) == Ordering::Less
        }
    }

    /// Whether the point `(x, height)` in the frame of an edge of length `length`, its foot
    /// inside the edge (`0 < x < length`, `height >= 0`), lies on the edge's line: the middle
    /// corner of a degenerate face is then a point of its opposite edge \[MMP87\]. Exactly
    /// `height = 0` for number types whose constructions are exact. One that rounds them
    /// cannot tell a height at its resolution from zero (the rays through such a corner turn by
    /// that height over their length); taking the point onto the line moves the distances
    /// through it into the faces beyond by at most its height, and those to the edge's ends by
    /// about its square over twice the point's offset from the nearer end.
    fn on_line(height: &Self, x: &Self, length: &Self) -> bool;

    /// Whether two wedges have the same distance function on a range of length about `scale`:
    /// the case `A = B = C = 0` of eq. (2) with infinitely many solutions (Example 1 [LZT §3]).
    fn same_distance_function(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        scale: &Self,
    ) -> bool;

    /// Whether two distance functions are one image of one pseudo-source, reached by two ways
    /// across faces and so built by two chains of constructions (in a flat region, the wedges
    /// on the two sides of a vertex's shadow line), on a range of length about `scale`: then
    /// the two wedges are joined into one. [`Scalar::same_distance_function`] for number types
    /// whose constructions are exact; at the backend's resolution for those that round them,
    /// where the two chains give images that differ in their last bits.
    fn same_image(a: &SourceDistance<Self>, b: &SourceDistance<Self>, scale: &Self) -> bool;

    /// Whether two distance functions are proved the same, by signs the backend certifies (a
    /// sign it cannot certify is no decision and no tie): for a tie that provenance suggests
    /// ([`Scalar::Kept`]), checked where the suggestion may not hold; `false` for number types
    /// that keep no values.
    fn proved_same_distance_function(_a: &SourceDistance<Self>, _b: &SourceDistance<Self>) -> bool {
        false
    }

    /// Whether two points of a plane are proved one, as
    /// [`Scalar::proved_same_distance_function`]: `false` for number types that keep no values.
    fn proved_same_point(_p: [&Self; 2], _q: [&Self; 2]) -> bool {
        false
    }

    /// The order of two values where the backend proves it, else `None` and no decision: for a
    /// choice that the caller can make without it (by asking what it needs of both values).
    /// Number types that always answer give their comparison.
    #[inline(always)]
    fn proved_order(a: &Self, b: &Self) -> Option<Ordering> {
        Some(a.compare(b))
    }

    /// Roots of eq. (2) [LZT §2] that solve eq. (1), strictly inside `(lo, hi)`, in increasing
    /// order; by Property 1 there are none, one, two or infinitely many. The roots of
    /// [`Scalar::bisector`] without the ends' values.
    fn bisector_roots(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        lo: &Self,
        hi: &Self,
    ) -> BisectorRoots<Self> {
        Self::bisector(a, b, lo, hi, &[None, None]).roots
    }

    /// The meeting of two wedges on their shared range `[lo, hi]` [LZT §4]: the roots of eq. (2)
    /// that solve eq. (1) inside it, and which of `a`, `b` is lower on each stretch between
    /// them, in one decision (the engine gives each piece to the lower wedge and asks nothing
    /// again). `known[0]` (`[1]`) holds `[a, b]` at `lo` (`hi`) where the engine keeps those
    /// values ([`Scalar::Kept`]): a backend that proves equalities by structure uses them rather
    /// than decide the ends again (where they are equal, eq. (2) has a root at that end).
    fn bisector(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        lo: &Self,
        hi: &Self,
        known: &[Option<[Self; 2]>; 2],
    ) -> Bisector<Self>;

    /// [`Scalar::bisector`] of two wedges of which one is the wedge of a vertex that the
    /// other's image lit (the engine knows it by their paths): the vertex is seen straight
    /// from that image, and the two distance functions touch (the gap of the pseudo-sources,
    /// placed as the surface places them, is zero by structure). `opposite`: whether the two
    /// images lie on opposite sides of the edge's line in the surface. A backend that proves
    /// ties by structure takes that zero from the engine rather than decide it; the others
    /// meet the two wedges as any two.
    fn bisector_seen_straight(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        lo: &Self,
        hi: &Self,
        known: &[Option<[Self; 2]>; 2],
        _opposite: bool,
    ) -> Bisector<Self> {
        Self::bisector(a, b, lo, hi, known)
    }

    /// Whether two distance functions are equal at `t` to within the rounding of the
    /// constructions that gave them (their images unfolded across faces): which wedge the
    /// engine gives the point to is then a guess, so the other one is sent on as well.
    /// `false` for number types that construct exactly, whose ties are ties.
    #[inline(always)]
    fn near_tie(_a: &SourceDistance<Self>, _b: &SourceDistance<Self>, _t: &Self) -> bool {
        false
    }

    /// The orientation of the triangle `(p, q, r)`: the sign of `(q - p) x (r - p)`, positive
    /// when `r` lies to the left of the line from `p` to `q`.
    fn orientation(p: [&Self; 2], q: [&Self; 2], r: [&Self; 2]) -> Sign;

    /// `value`, raised to `bound` where it lies below it. The engine passes a wedge's distance at
    /// a vertex, constructed through a chain of unfoldings, with a lower bound computed from
    /// the inputs alone: the pseudo-source's sigma plus the straight line in space, which no
    /// geodesic beats and which it equals in the pseudo-source's own faces. A rounded number type
    /// repairs there the rounding that put the constructed value below (on a needle of 1e-12
    /// beside unit edges, that rounding is 1e-4 of the distance). The default, right for exact
    /// number types, returns `value` without evaluating `bound`.
    #[inline(always)]
    fn at_least(value: Self, _bound: impl FnOnce() -> Self) -> Self {
        value
    }

    /// Whether an edge far longer than its nearer end's distance from the sources has its frame
    /// start at that end rather than at its `vertices[0]`. A number type that rounds its
    /// constructions knows a position along an edge to ulps of its offset from the frame's
    /// origin: on an edge 1e8 long, a point one unit from the far end is known to 1e-8 only,
    /// and so is every distance unfolded through it, while the geodesics near the sources (the
    /// short distances, which need the finest resolution) pass near the nearer end. The default, right for exact number types,
    /// keeps the mesh's order, on which their kept expressions and flat regions are built.
    #[inline(always)]
    fn frames_from_nearer_end() -> bool {
        false
    }

    /// Whether the front of the propagation, at `front` (the `f64` key of the wedge popped last:
    /// every wedge reaching an edge later gives distances no nearer than it, up to the rounding
    /// of keys), lies beyond every distance the distance function `d` gives on `[lo, hi]`, by
    /// a margin that covers that rounding (`FRONT_MARGIN`): then a wedge arriving later
    /// loses every point of the range to this one, and the edge's wedges may be given up
    /// ([`propagate_vertices`](crate::propagate_vertices)). `false` is always safe (the wedges
    /// are kept), so a backend that cannot certify `true` answers `false`. `D` is convex on
    /// the range, so its largest value is at an end.
    fn front_passed(d: &SourceDistance<Self>, lo: &Self, hi: &Self, front: f64) -> bool;

    /// Whether this number type measures edges shorter than `2^-500` of the model's size
    /// ([`ValidationReport::float_unresolved_edges`](crate::ValidationReport)): their squared
    /// lengths, and eq. (2)'s coefficients on them, underflow in `f64`, and no one power of two
    /// brings both them and the model's largest coordinates into `f64`'s range. A number type
    /// that cannot is refused such a mesh ([`PointError::BeyondFloatRange`](crate::PointError)).
    fn measures_below_float_resolution() -> bool;

    /// Starts a propagation on this thread: a backend with a precision cap takes
    /// `precision_cap` as this thread's (if given), and resets what belongs to one run.
    #[inline(always)]
    fn begin_run(_precision_cap: Option<u32>) {}

    /// Tells the backend where the engine's next decisions are taken, so that a decision it
    /// cannot certify is reported with its place.
    #[inline(always)]
    fn locate(_site: Site) {}

    /// The decision counters of this thread since the last call, and resets them.
    #[inline(always)]
    fn take_counts() -> DecisionCounts {
        DecisionCounts::default()
    }

    /// Zero.
    #[inline]
    fn zero() -> Self {
        Self::from_f64(0.0)
    }

    /// The smaller of two positions.
    #[inline]
    fn min_of(a: &Self, b: &Self) -> Self {
        if a.compare(b) == Ordering::Greater {
            b.clone()
        } else {
            a.clone()
        }
    }

    /// The larger of two positions.
    #[inline]
    fn max_of(a: &Self, b: &Self) -> Self {
        if a.compare(b) == Ordering::Less {
            b.clone()
        } else {
            a.clone()
        }
    }
}
