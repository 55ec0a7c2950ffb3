//! The adaptive-predicate backend: `f64` values and `f64` constructions, but every predicate is
//! exact for the `f64` values it is asked about, so decisions are consistent with each other
//! even where rounding has moved the geometry.
//!
//! - Orientation is Shewchuk's adaptive `orient2d` (the `robust` crate).
//! - Eq. (2) and the validity of its roots (Property 1) are signs of polynomials in the `f64`
//!   inputs (the `roots` module): decided by an `f64` filter with a running error bound, then by a
//!   double-double one, and only when neither can tell by the exact stage, exact rationals.
//!   The discriminant's sign is decided on its own, as the product of two source gaps
//!   ([`roots::source_gap`]), so that the near-tangencies MMP meets at every pseudo-source
//!   vertex do not send the whole decision to a finer stage.
//! - Comparisons and signs of stored values are exact as they stand.
//! - Three kinds of question are about *constructed* values, which rounding has already moved,
//!   so an exact answer would only tell how the rounding fell: whether two distances
//!   `sigma + |s - t|` are equal, whether a range between two constructed points (crossings,
//!   ray hits) has a length, and whether a point lies in such a range. They are answered at
//!   the resolution of the constructions ([`Resolution`]): closer than that is a tie, a tie
//!   keeps the wedge already on the edge, and a point that close to a range is in it.
//!
//! The filter and exact-stage counts of the predicates are reported per run; comparisons of
//! stored values are exact by themselves and not counted.

use super::audit::{self, Certificate, DecisionCounts};
use super::bisector::Eq2Terms;
use super::double_double::DoubleDouble;
use super::error_bound::ErrorBound;
use super::float;
use super::rational::Q;
use super::roots::{self, CertifiedSign};
use super::{Bisector, BisectorRoots, Field, Lower, Ring, Scalar, Sign, SourceDistance};
use crate::mesh::vector::normalizing_power;
use std::cell::Cell;
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The resolution of the adaptive backend's constructed values, relative to the quantity at
/// hand (a distance, an edge's length). Exact comparisons of rounded constructions
/// (a vertex's distance against the same distance recomputed through another edge, two rays
/// that should meet an edge at one point) leave ulp-wide wedges and gaps that carry nothing;
/// on stanford_bunny they made a quarter of all wedges.
pub struct Resolution;

impl Resolution {
    /// Two distances this close (relative, `2^-46`, about 1.4e-14) are a tie. A distance is
    /// `sigma + sqrt((t - x)^2 + y^2)`, a few roundings from `sigma`, which is itself rounded.
    pub const DISTANCE: f64 = 64.0 * f64::EPSILON;
    /// A range shorter than this fraction of its edge (`2^-40`, about 9.1e-13) is not a wedge
    /// of its own: its ends are constructions, and a crossing near a double root of eq. (2) is
    /// rounded far more than one ulp.
    pub const EXTENT: f64 = 4096.0 * f64::EPSILON;
    /// Slack, as a fraction of the edge's length (`2^-46`, about 1.4e-14), when asking
    /// whether a point lies in a range: the ends are rounded constructions, computed from the
    /// end of the edge nearer the sources ([`Scalar::frames_from_nearer_end`]). The coarser
    /// [`Resolution::EXTENT`] let wedges claim vertices beyond their ranges on edges 1e8 times
    /// longer than the distances at hand, 3e-6 of a distance short.
    pub const WITHIN: f64 = 64.0 * f64::EPSILON;
    /// A point lies on an edge's line ([`Scalar::on_line`]) if its height is at most this
    /// fraction (`2^-46`, as [`Resolution::WITHIN`]) of the edge's length and its square at
    /// most this fraction of the square of its offset from the nearer end: heights are rounded
    /// constructions, and the rays through a corner at such a height are rounding too.
    pub const ON_LINE: f64 = 64.0 * f64::EPSILON;
    /// Two images of one pseudo-source whose positions and sigmas agree to this fraction of
    /// the range's scale (or of their distance from the edge) are one image reached by two
    /// ways ([`Scalar::same_image`]): each way rounds its own chain of unfoldings, a few ulps
    /// per face, so this is the `f64` backend's `SAME_SOURCE`. Asked only of wedges of one
    /// pseudo-source whose ranges meet, to join them; never to decide eq. (2).
    pub const SAME_IMAGE: f64 = 1e-12;
}

/// An `f64` whose predicates are exact for its value.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd, Default)]
pub struct Adaptive(pub f64);

macro_rules! adaptive_ops {
    ($($tr:ident $f:ident),*) => {$(
        impl $tr for Adaptive {
            type Output = Adaptive;
            #[inline(always)]
            fn $f(self, o: Adaptive) -> Adaptive {
                Adaptive($tr::$f(self.0, o.0))
            }
        }
        impl<'a> $tr<&'a Adaptive> for Adaptive {
            type Output = Adaptive;
            #[inline(always)]
            fn $f(self, o: &'a Adaptive) -> Adaptive {
                Adaptive($tr::$f(self.0, o.0))
            }
        }
    )*};
}
adaptive_ops!(Add add, Sub sub, Mul mul, Div div);

impl Neg for Adaptive {
    type Output = Adaptive;
    #[inline(always)]
    fn neg(self) -> Adaptive {
        Adaptive(-self.0)
    }
}

impl Ring for Adaptive {
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        Adaptive(x)
    }
}

impl Field for Adaptive {
    #[inline(always)]
    fn to_f64(&self) -> f64 {
        self.0
    }

    #[inline(always)]
    fn sqrt(&self) -> Self {
        Adaptive(self.0.max(0.0).sqrt())
    }
}

/// A wedge's distance function with its `f64` inputs as another number type.
fn lift<T: Ring>(d: &SourceDistance<Adaptive>) -> SourceDistance<T> {
    SourceDistance {
        x: T::from_f64(d.x.0),
        y: T::from_f64(d.y.0),
        sigma: T::from_f64(d.sigma.0),
    }
}

/// The signs [`roots::crossings`] may ask apart from the rest when a filter cannot tell them,
/// each decided exactly (double-double, then exact rationals), and once for all stages.
struct Signs<'a> {
    a: &'a SourceDistance<Adaptive>,
    b: &'a SourceDistance<Adaptive>,
    ends: [f64; 2],
    /// The gaps (same side, mirrored), `P` at the start and at the end, then
    /// [`roots::excess_factor`].
    known: Cell<[Option<Sign>; 5]>,
}

impl Signs<'_> {
    fn decide<T: CertifiedSign>(&self, at: usize) -> Option<Sign> {
        let (a, b) = (lift::<T>(self.a), lift::<T>(self.b));
        match at {
            0 | 1 => roots::source_gap(&a, &b, at == 1),
            2 | 3 => roots::eq2_at(&a, &b, &T::from_f64(self.ends[at - 2])),
            _ => roots::excess_factor(&a, &b),
        }
        .certified_sign()
    }

    fn sign(&self, at: usize) -> Option<Sign> {
        let mut known = self.known.get();
        // Asked only once the `f64` filter of the meeting could not tell: start finer.
        let sign = *known[at].get_or_insert_with(|| {
            filtered(
                || self.decide::<DoubleDouble>(at),
                || None,
                || self.decide::<Q>(at),
            )
        });
        self.known.set(known);
        Some(sign)
    }
}

impl roots::InputSigns for Signs<'_> {
    fn gap(&self, mirror: bool) -> Option<Sign> {
        self.sign(mirror as usize)
    }

    fn at_end(&self, end: bool) -> Option<Sign> {
        self.sign(2 + end as usize)
    }

    fn excess_factor(&self) -> Option<Sign> {
        self.sign(4)
    }
}

/// Runs a predicate through the `f64` filter, then the double-double one, then, if neither can
/// tell, exactly.
fn filtered<R>(
    filter: impl FnOnce() -> Option<R>,
    finer: impl FnOnce() -> Option<R>,
    exact: impl FnOnce() -> Option<R>,
) -> R {
    if let Some(r) = filter().or_else(finer) {
        audit::record(Certificate::Filter, || [0.0; 2]);
        return r;
    }
    audit::record(Certificate::Refinement, || [0.0; 2]);
    exact().expect("exact rationals decide every sign")
}

/// The exact sign of an `f64`.
#[inline(always)]
fn sign_of(x: f64) -> Sign {
    if x > 0.0 {
        Sign::Positive
    } else if x < 0.0 {
        Sign::Negative
    } else {
        Sign::Zero
    }
}

/// Exact comparison of two `f64` values (`-0 = 0`; NaN, which the engine never produces,
/// compares equal).
#[inline(always)]
fn cmp(a: f64, b: f64) -> Ordering {
    a.partial_cmp(&b).unwrap_or(Ordering::Equal)
}

/// The `f64` positions of the crossings the filtered decision found, from values known to a
/// few ulps: eq. (2)'s coefficients and its discriminant `beta^2 G G'` ([`roots::source_gap`])
/// in double-double, or in exact rationals where that is not accurate, each rounded once; then
/// the cancellation-free formula. A position is then good to a few ulps of its distance from
/// the range's start, and it is kept inside the range, in order. The filter's own coefficients
/// carry errors that it bounds for their signs only: on a near-double root or a nearly
/// vanishing `A` they placed roots far outside the range, and the lower wedge, certain on each
/// stretch between the exact roots, went to the wrong places. Nor are they accurate enough
/// where they are certain: with their error bounds, the roots they give were known to about
/// `2^-24` of the range's width on icosphere5, never the few ulps asked for.
fn root_positions(
    a: &SourceDistance<Adaptive>,
    b: &SourceDistance<Adaptive>,
    crossings: roots::Crossings<f64>,
    [lo, hi]: [f64; 2],
) -> BisectorRoots<f64> {
    // Most meetings have no crossing inside the range: nothing to place.
    match crossings {
        roots::Crossings::None
        | roots::Crossings::Quadratic {
            smaller: false,
            larger: false,
            ..
        } => return BisectorRoots::None,
        roots::Crossings::Infinite => return BisectorRoots::Infinite,
        _ => {}
    }
    // In units where the offsets from the range's start are near 1 (a power of two, exact
    // unless it makes a value subnormal): eq. (2)'s coefficients are of degree up to 4 in
    // lengths, its discriminant 6, and would leave f64's range.
    let size = [a, b]
        .iter()
        .flat_map(|d| [d.x.0 - lo, d.y.0, d.sigma.0])
        .fold(hi - lo, |m, v| m.max(v.abs()));
    let unit = normalizing_power(size);
    let positions = |u: [f64; 2]| u.map(|u| (lo + u / unit).clamp(lo, hi));
    // Double-double values, known to within 2^-60 (of themselves, or absolutely below 1: the
    // inputs are of unit size here); exact rationals where they are not.
    let [r, s] = scaled_positions(a, b, &crossings, lo, unit, DoubleDouble::accurate_f64)
        .unwrap_or_else(|| {
            scaled_positions(a, b, &crossings, lo, unit, |q: Q| Some(q.to_f64()))
                .expect("exact rationals give every value")
        });
    let [r, s] = positions([r, s]);
    match crossings {
        roots::Crossings::None => BisectorRoots::None,
        roots::Crossings::Infinite => BisectorRoots::Infinite,
        roots::Crossings::At(_) => BisectorRoots::One(r),
        roots::Crossings::Touch(_) => BisectorRoots::Touch(r),
        roots::Crossings::Quadratic {
            smaller, larger, ..
        } => match (smaller, larger) {
            (true, true) => BisectorRoots::Two(r, s),
            (true, false) => BisectorRoots::One(r),
            (false, true) => BisectorRoots::One(s),
            (false, false) => BisectorRoots::None,
        },
    }
}

/// The crossings' offsets from `lo` in units of `1 / unit`, in increasing order (the first
/// alone for a single root), computed in `T` from the inputs multiplied by `unit`; `None` if
/// `accurate` cannot give a value to an ulp.
fn scaled_positions<T: CertifiedSign + Clone>(
    a: &SourceDistance<Adaptive>,
    b: &SourceDistance<Adaptive>,
    crossings: &roots::Crossings<f64>,
    lo: f64,
    unit: f64,
    accurate: fn(T) -> Option<f64>,
) -> Option<[f64; 2]> {
    let scaled = |d: &SourceDistance<Adaptive>| SourceDistance {
        x: T::from_f64(d.x.0 * unit),
        y: T::from_f64(d.y.0 * unit),
        sigma: T::from_f64(d.sigma.0 * unit),
    };
    let (ta, tb) = (scaled(a), scaled(b));
    let terms = Eq2Terms::new(&ta, &tb, &T::from_f64(lo * unit));
    let two = T::from_f64(2.0);
    // Only the coefficients a case's formula needs.
    Some(match crossings {
        roots::Crossings::None | roots::Crossings::Infinite => [0.0; 2],
        roots::Crossings::At(_) if terms.beta.certified_sign() == Some(Sign::Zero) => [
            accurate(-(terms.gamma.clone() / &(two * &terms.alpha)))?,
            0.0,
        ],
        roots::Crossings::At(_) => [accurate(-(terms.constant() / &terms.linear()))?, 0.0],
        roots::Crossings::Touch(_) => [
            accurate(-(terms.linear() / &(two * &terms.quadratic())))?,
            0.0,
        ],
        roots::Crossings::Quadratic { .. } => {
            let eq2 = terms.coefficients();
            // B^2 - 4AC = beta^2 G G' (the source gaps): no cancellation.
            let disc = accurate(
                terms.beta2.clone()
                    * &roots::source_gap(&ta, &tb, false)
                    * &roots::source_gap(&ta, &tb, true),
            )?;
            let (ca, cb, cc) = (accurate(eq2.a)?, accurate(eq2.b)?, accurate(eq2.c)?);
            let q = -0.5 * (cb + cb.signum() * disc.max(0.0).sqrt());
            let (r, s) = if q == 0.0 {
                (0.0, 0.0)
            } else {
                (q / ca, cc / q)
            };
            [r.min(s), r.max(s)]
        }
    })
}

impl Scalar for Adaptive {
    super::keeps_no_values!();

    #[inline(always)]
    fn at_least(value: Adaptive, bound: impl FnOnce() -> Adaptive) -> Adaptive {
        Adaptive(value.0.max(bound().0))
    }

    #[inline(always)]
    fn frames_from_nearer_end() -> bool {
        true
    }

    #[inline(always)]
    fn measures_below_float_resolution() -> bool {
        false
    }

    /// As the `f64` backend, on the `f64` values: the distances compared are constructions,
    /// rounded as that backend's, and the margin is what covers their rounding.
    #[inline(always)]
    fn front_passed(d: &SourceDistance<Self>, lo: &Self, hi: &Self, front: f64) -> bool {
        let d = SourceDistance {
            x: d.x.0,
            y: d.y.0,
            sigma: d.sigma.0,
        };
        f64::front_passed(&d, &lo.0, &hi.0, front)
    }

    #[inline(always)]
    fn sign(&self) -> Sign {
        sign_of(self.0)
    }

    #[inline(always)]
    fn compare(&self, other: &Self) -> Ordering {
        cmp(self.0, other.0)
    }

    #[inline(always)]
    fn compare_distance(&self, other: &Self) -> Ordering {
        float::compare_with_tie(self.0, other.0, Resolution::DISTANCE)
    }

    #[inline(always)]
    fn has_extent(lo: &Self, hi: &Self, scale: &Self) -> bool {
        hi.0 - lo.0 > Resolution::EXTENT * scale.0
    }

    /// As `f64` does (`float::fans_out`).
    #[inline(always)]
    fn fans_out(lo: &Self, hi: &Self, x: &Self, y: &Self) -> bool {
        float::fans_out(lo.0, hi.0, x.0, y.0)
    }

    /// At the resolution of the range's ends ([`Resolution::WITHIN`]): the ends are
    /// constructions, and two wedges whose ranges meet at a ray through a vertex (exactly, on
    /// the surface) meet with a gap or overlap of a few ulps once rounded; a vertex in such a
    /// gap must still be reached by both.
    #[inline(always)]
    fn within(x: &Self, lo: &Self, hi: &Self, scale: impl FnOnce() -> Self) -> bool {
        let slack = Resolution::WITHIN * scale().0;
        x.0 >= lo.0 - slack && x.0 <= hi.0 + slack
    }

    /// At the resolution of constructed heights ([`Resolution::ON_LINE`]).
    #[inline(always)]
    fn on_line(height: &Self, x: &Self, length: &Self) -> bool {
        let (h, offset) = (height.0, x.0.min(length.0 - x.0));
        h <= Resolution::ON_LINE * length.0 && h * h <= Resolution::ON_LINE * offset * offset
    }

    /// `A = B = C = 0` holds exactly when the two functions have equal `x`, `|y|` and `sigma`,
    /// or when both pseudo-sources lie on the edge's line with `x2 - x1 = +-(sigma2 - sigma1)`;
    /// for `f64` inputs the first is a comparison of bits, the second is left to the filter.
    fn same_distance_function(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        _scale: &Self,
    ) -> bool {
        if a.x == b.x && a.sigma == b.sigma && a.y.0.abs() == b.y.0.abs() {
            return true;
        }
        if a.y.0 != 0.0 || b.y.0 != 0.0 {
            return false;
        }
        filtered(
            || roots::same_distance_function::<ErrorBound>(&lift(a), &lift(b)),
            || roots::same_distance_function::<DoubleDouble>(&lift(a), &lift(b)),
            || roots::same_distance_function::<Q>(&lift(a), &lift(b)),
        )
    }

    /// At [`Resolution::SAME_IMAGE`]: the images are rounded constructions.
    fn same_image(a: &SourceDistance<Self>, b: &SourceDistance<Self>, scale: &Self) -> bool {
        let same = Resolution::SAME_IMAGE * scale.0.abs().max(a.y.0.abs()).max(b.y.0.abs());
        (a.x.0 - b.x.0).abs() <= same
            && (a.sigma.0 - b.sigma.0).abs() <= same
            && (a.y.0.abs() - b.y.0.abs()).abs() <= same
    }

    /// The crossings by exact signs of polynomials in the `f64` inputs (`roots::crossings`),
    /// placed from exact values (`root_positions`); on each stretch between them, the lower
    /// wedge by the sign of `D_a(t) - D_b(t)` at the stretch's middle or at an end of the range
    /// (`float::lower_on`), taken where the two differ by more than
    /// [`Resolution::DISTANCE`]: each distance is evaluated to within `4 eps` of itself, so
    /// that sign is certain. Closer than that everywhere asked is a tie (the existing wedge
    /// keeps the stretch): the sigmas are constructions, and a wedge better by less would only
    /// replace its neighbour by a copy of itself.
    fn bisector(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        lo: &Self,
        hi: &Self,
        _known: &[Option<[Self; 2]>; 2],
    ) -> Bisector<Self> {
        let signs = Signs {
            a,
            b,
            ends: [lo.0, hi.0],
            known: Cell::new([None; 5]),
        };
        let crossings = filtered(
            || {
                let (lo, hi) = (ErrorBound::from_f64(lo.0), ErrorBound::from_f64(hi.0));
                roots::crossings(&lift(a), &lift(b), &lo, &hi, &signs, [false; 2])
                    .map(|c| c.map(|x| x.to_f64()))
            },
            || {
                let (lo, hi) = (DoubleDouble::from_f64(lo.0), DoubleDouble::from_f64(hi.0));
                roots::crossings(&lift(a), &lift(b), &lo, &hi, &signs, [false; 2])
                    .map(|c| c.map(|x| x.to_f64()))
            },
            || {
                let (lo, hi) = (Q::from_f64(lo.0), Q::from_f64(hi.0));
                roots::crossings(&lift(a), &lift(b), &lo, &hi, &signs, [false; 2])
                    .map(|c| c.map(|x| x.to_f64()))
            },
        );
        let roots = root_positions(a, b, crossings, [lo.0, hi.0]);
        let (fa, fb) = (lift::<f64>(a), lift::<f64>(b));
        let cuts = match roots {
            BisectorRoots::One(r) | BisectorRoots::Touch(r) => [Some(r), None],
            BisectorRoots::Two(r, s) => [Some(r), Some(s)],
            BisectorRoots::None | BisectorRoots::Infinite => [None, None],
        };
        let mut lower = [Lower::Neither; 3];
        if roots != BisectorRoots::Infinite {
            let mut start = lo.0;
            let ends = cuts.into_iter().flatten().chain([hi.0]);
            for (i, end) in ends.enumerate() {
                let range = [lo.0, hi.0];
                lower[i] = float::lower_on(&fa, &fb, [start, end], range, Resolution::DISTANCE);
                start = end;
            }
        }
        Bisector {
            roots: roots.map(Adaptive),
            lower,
        }
    }

    #[inline]
    fn near_tie(a: &SourceDistance<Self>, b: &SourceDistance<Self>, t: &Self) -> bool {
        float::compare_with_tie(a.at(t).0, b.at(t).0, Resolution::DISTANCE) == Ordering::Equal
    }

    #[inline]
    fn orientation(p: [&Self; 2], q: [&Self; 2], r: [&Self; 2]) -> Sign {
        let c = |p: [&Self; 2]| robust::Coord {
            x: p[0].0,
            y: p[1].0,
        };
        sign_of(robust::orient2d(c(p), c(q), c(r)))
    }

    fn take_counts() -> DecisionCounts {
        audit::take()
    }
}
