//! The number types the engine runs on, in the style of CGAL's kernels: the engine asks a
//! [`Scalar`] for its constructions (`+ - * /`, square roots) and for its decisions (signs,
//! comparisons, the roots of eq. (2) [LZT §2]) and never asks which backend it runs on.
//!
//! How exact a decision is belongs to the backend: [`f64`] decides with the one documented
//! tolerance policy in [`float`]; exact backends decide with certified signs.

mod bisector;
pub mod float;

pub use bisector::{BisectorRoots, Eq2Case, Eq2Coefficients, SourceDistance};

use std::cmp::Ordering;
use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Sign of a number, as decided by its backend.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sign {
    /// Less than zero.
    Negative,
    /// Zero.
    Zero,
    /// Greater than zero.
    Positive,
}

/// A number type for the MMP engine: an ordered field with square roots of non-negative
/// numbers, plus the decisions MMP takes.
///
/// Values are `Clone`, not `Copy`, so that exact numbers (big rationals, expression DAGs) fit;
/// operators take their right operand by reference where a clone would otherwise be needed.
/// Decisions have no default bodies: a backend states how it takes each one.
pub trait Scalar:
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
    fn from_f64(x: f64) -> Self;

    /// The nearest `f64`, for output, priority keys and reports; never used for a decision.
    fn to_f64(&self) -> f64;

    /// The square root of `max(self, 0)`. Callers pass quantities that are non-negative in exact
    /// arithmetic (squared lengths, heights); a backend with rounding may see a tiny negative.
    fn sqrt(&self) -> Self;

    /// The sign of `self`.
    fn sign(&self) -> Sign;

    /// Compares two positions or lengths.
    fn compare(&self, other: &Self) -> Ordering;

    /// Compares two geodesic distances; `Equal` means the backend cannot tell them apart, and
    /// the engine then keeps what it already has ([LZT §4] step 2.3.2: delete the newcomer).
    fn compare_distance(&self, other: &Self) -> Ordering;

    /// Whether `[lo, hi]` on an edge of length `scale` is long enough to be a wedge of its own.
    fn has_extent(lo: &Self, hi: &Self, scale: &Self) -> bool;

    /// Whether `x` lies in `[lo, hi]` on an edge of length `scale` (closed range).
    fn within(x: &Self, lo: &Self, hi: &Self, scale: &Self) -> bool;

    /// Whether two wedges have the same distance function on a range of length about `scale`:
    /// the case `A = B = C = 0` of eq. (2) with infinitely many solutions (Example 1 [LZT §3]).
    fn same_distance_function(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        scale: &Self,
    ) -> bool;

    /// Roots of eq. (2) [LZT §2] that solve eq. (1), strictly inside `(lo, hi)`, in increasing
    /// order; by Property 1 there are none, one, two or infinitely many.
    fn bisector_roots(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        lo: &Self,
        hi: &Self,
    ) -> BisectorRoots<Self>;

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
